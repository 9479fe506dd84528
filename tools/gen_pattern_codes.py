#!/usr/bin/env python3
"""Write the code ``re`` compiles zero's patterns to, to ``src/zero/pattern_codes.py``, with the Python and
regular expression engine that compiled it: :func:`zero.patterns.compiled` then builds each pattern from its code
without importing ``re`` (issue 40: start-up).

The patterns are found in zero's source: every call ``compiled(SOURCE)`` or ``compiled(SOURCE, FLAGS)`` (also as
``patterns.compiled``) whose SOURCE is a string or bytes literal or the name of one assigned at the top of its
module, and whose FLAGS are :mod:`zero.patterns`' flag names joined by ``|`` (or an int); and the tokenizer's row
patterns (``zero.lists.tokenizer.row_source``, each variant: the one call marked ``# pattern computed:``). A
pattern not written (another source, another Python, or a table not regenerated after a pattern changed)
compiles with ``re`` at run time: slower, never different; a test fails while the table is stale.

Usage: python tools/gen_pattern_codes.py [--check]   (--check: exit 1 if the table is stale, write nothing)
"""

from __future__ import annotations

import ast
import itertools
import marshal
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from pydata import TYPING_FOR_CHECKERS

SRC = Path(__file__).resolve().parent.parent / "src" / "zero"
TARGET = SRC / "pattern_codes.py"

Key = tuple[str | bytes, int]
# Written on the line of a call whose pattern is computed, and written from where it is computed (patterns()).
_COMPUTED = "# pattern computed:"


def _constants(tree: ast.Module) -> dict[str, str | bytes]:
    """A module's top-level names bound to a string or bytes literal."""
    out: dict[str, str | bytes] = {}
    for node in tree.body:
        target, value = None, None
        if isinstance(node, ast.Assign) and len(node.targets) == 1:
            target, value = node.targets[0], node.value
        elif isinstance(node, ast.AnnAssign):
            target, value = node.target, node.value
        if isinstance(target, ast.Name) and isinstance(value, ast.Constant) and isinstance(value.value, (str, bytes)):
            out[target.id] = value.value
    return out


def _flags(node: ast.expr | None) -> int | None:
    """The value of a FLAGS argument, or None where it is not made of flag names and ints."""
    from zero import patterns

    if node is None:
        return 0
    if isinstance(node, ast.Constant) and isinstance(node.value, int):
        return node.value
    name = node.attr if isinstance(node, ast.Attribute) else node.id if isinstance(node, ast.Name) else None
    if name is not None:
        value = getattr(patterns, name, None)
        return value if isinstance(value, int) else None
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        left, right = _flags(node.left), _flags(node.right)
        return None if left is None or right is None else left | right
    return None


def found(path: Path) -> tuple[list[Key], list[str]]:
    """The patterns a module compiles through ``compiled``, and where it passes one that cannot be read."""
    text = path.read_text(encoding="utf-8")
    tree = ast.parse(text)
    lines = text.splitlines()
    names = _constants(tree)
    by_name = any(isinstance(node, ast.ImportFrom) and node.module == "zero.patterns"
                  and any(a.name == "compiled" and a.asname is None for a in node.names) for node in ast.walk(tree))
    keys: list[Key] = []
    unread: list[str] = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        ours = ((isinstance(func, ast.Attribute) and func.attr == "compiled" and isinstance(func.value, ast.Name)
                 and func.value.id == "patterns") or (by_name and isinstance(func, ast.Name) and func.id == "compiled"))
        if not ours or _COMPUTED in lines[node.lineno - 1]:
            continue
        arg = node.args[0]
        source = (arg.value if isinstance(arg, ast.Constant) and isinstance(arg.value, (str, bytes))
                  else names.get(arg.id) if isinstance(arg, ast.Name) else None)
        flags = _flags(node.args[1] if len(node.args) > 1 else None)
        if source is None or flags is None:
            unread.append(f"{path.relative_to(SRC.parent)}:{node.lineno}")
        else:
            keys.append((source, flags))
    return keys, unread


def patterns() -> tuple[list[Key], list[str]]:
    """Every pattern to write, in a stable order, and the calls whose pattern could not be read."""
    from zero.lists.tokenizer import row_source

    keys: list[Key] = []
    unread: list[str] = []
    for path in sorted(SRC.rglob("*.py")):
        got, missed = found(path)
        keys += got
        unread += missed
    keys += [(row_source(*variant), 0) for variant in itertools.product((False, True), repeat=3)]
    return list(dict.fromkeys(keys)), unread


def render() -> str:
    """The module's text, from the patterns as they are now and this Python's engine."""
    import _sre  # type: ignore[import-not-found]
    from re import _compiler, _parser  # type: ignore[attr-defined]

    lines = []
    for source, flags in patterns()[0]:
        parsed = _parser.parse(source, flags)
        code = tuple(int(c) for c in _compiler._code(parsed, flags))  # plain ints (the opcodes are named ints)
        groupindex = dict(parsed.state.groupdict)
        indexgroup: list[str | None] = [None] * parsed.state.groups
        for name, i in groupindex.items():
            indexgroup[i] = name
        # the code as marshal writes the tuple (format 2: no references, the same bytes from every run): a bytes
        # constant costs nothing to load, where thousands of ints each cost an object (issue 40: start-up)
        lines.append(f"    ({source!r}, {flags}): ({flags | parsed.state.flags}, {marshal.dumps(code, 2)!r}, "
                     f"{parsed.state.groups - 1}, {groupindex!r}, {tuple(indexgroup)!r}),")
    built = (*sys.version_info[:2], _sre.MAGIC, _sre.CODESIZE)
    return ('"""The code the regular expression engine compiles zero\'s patterns to, by (source, flags): (all flags,\n'
            "code (its tuple as marshal.dumps(code, 2) writes it), groups, group name -> index, index -> group name),\n"
            "written by tools/gen_pattern_codes.py with the Python (major, minor) and engine (MAGIC, CODESIZE) of\n"
            "BUILT, and read only by that one (:mod:`zero.patterns`).\n\n"
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n" + "\n".join(TYPING_FOR_CHECKERS) + "\n\n"
            f"BUILT: tuple[int, ...] = {built!r}\n"
            "CODES: dict[tuple[Any, int], Any] = {\n" + "\n".join(lines) + "\n}\n")


def files() -> dict[Path, str | None]:
    """The generated module's text; a call whose pattern cannot be read is said (it compiles with re)."""
    for where in patterns()[1]:
        print(f"{where}: compiled() of a pattern that is not a literal (or a module's literal name): not written")
    return {TARGET: render()}


if __name__ == "__main__":
    from _gen import run

    run("gen_pattern_codes.py", files)

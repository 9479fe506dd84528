#!/usr/bin/env python3
"""Write what declaring each record of zero takes, worked out ahead of time, to ``src/zero/record_inits.py``.

:func:`zero.records.record` works out a record's fields (annotations, defaults, factories, which show and
compare) and writes its ``__init__`` as Python text, compiled when the record is first instantiated: some
forty records in a ``zero lint`` of one list, most of the cost of declaring them (issue 40, start-up). The
table holds, by module and qualified name, what that gives for each record of zero with no record base (its
field names, those shown and compared, its ``__init__`` compiled with the table) together with what it was
worked out from (the class's own annotations, its flags, which fields have values and of which kind), which
:func:`zero.records._body` checks against the class before taking the rest. A record the table does not
describe (a test's, a record with a record base, or a table not regenerated after a record changed) is
worked out as before: slower, never wrong; a test fails while the table is stale. The ``__init__`` of a
record with a record base is kept by its text. Run it after adding, removing or changing a record.

Two tables: ``record_inits.py`` holds the records of the modules a list's lint loads (it is imported with
:mod:`zero.records`), ``record_inits_rest.py`` every other record's (imported at the first record it holds:
a list's lint never reads it).

Usage: python tools/gen_record_inits.py [--check]   (--check: exit 1 if a table is stale, write nothing)
"""

from __future__ import annotations

import importlib
import os
import pkgutil
import re
import subprocess
import sys
import tempfile
from pathlib import Path
from types import CodeType
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen

SRC = Path(__file__).resolve().parent.parent / "src" / "zero"
# Parameter defaults the text names from its scope; the table's functions get theirs from the record.
_DEFAULT = re.compile(r"=(?:__default_\w+|MISSING)(?=[,)])")
_OPTIONAL = ("zero.server",)  # modules that need an extra (pygls) are read only where it is installed
# The modules a list's lint loads: zero's console entry on a small axis list, with a finding and a fix.
_LINT = """
import sys
import zero.cli.lean as lean

def end(code):
    sys.stdout.write("\\nMODULES " + " ".join(sorted(sys.modules)) + "\\n")
    sys.stdout.flush()
    raise SystemExit(code)

lean.end = end
sys.argv = ["zero", "lint", sys.argv[1]]
lean.main()
"""
_LIST = "kenngr.achs_mode 1\nkenngr.no_such_key 1\nkenngr.swe_pos 10000 ( a comment )\nEnde\n"


def lint_modules() -> set[str]:
    """The zero modules a ``zero lint`` of one list loads, in a fresh interpreter: without the cache,
    and with it (a first run, then one the cache answers)."""
    loaded: set[str] = set()
    with tempfile.TemporaryDirectory() as folder:
        target = os.path.join(folder, "axis.lis")
        with open(target, "w", encoding="ascii") as f:
            f.write(_LIST)
        base = {**os.environ, "PYTHONPATH": str(SRC.parent), "ZERO_CACHE_DIR": os.path.join(folder, "cache")}
        base.pop("ZERO_NO_CACHE", None)
        for env in ({**base, "ZERO_NO_CACHE": "1"}, base, base):
            out = subprocess.run([sys.executable, "-c", _LINT, target], capture_output=True, text=True, env=env,
                                 cwd=folder, check=False)
            if "\nMODULES " not in out.stdout:
                raise SystemExit(f"the lint of a list failed: {out.stderr}")
            loaded |= {m for m in out.stdout.rpartition("\nMODULES ")[2].split() if m.startswith("zero")}
    return loaded


Declared = tuple[Any, dict[str, Any], bool, bool, bool]  # (records._Shell, the body made of it, flags)


def declared() -> list[Declared]:
    """Every record of every zero module as declared (what it is made from, the body worked out of it, its
    flags), each worked out the slow way (:func:`zero.records._body_slow`), whatever the tables hold."""
    import zero.records as records

    seen: list[Declared] = []

    def capture(shell: Any, frozen: bool, eq: bool, unsafe_hash: bool) -> tuple[dict[str, Any], list[type]]:
        body, owner = records._body_slow(shell, frozen, eq, unsafe_hash)
        seen.append((shell, body, frozen, eq, unsafe_hash))
        return body, owner

    body_of = records._body
    records._body = capture
    try:
        import zero

        for info in pkgutil.walk_packages(zero.__path__, "zero."):
            if info.name in sys.modules or info.name.endswith("__main__"):
                continue
            try:
                importlib.import_module(info.name)
            except ImportError:
                if not info.name.startswith(_OPTIONAL):
                    raise
    finally:
        records._body = body_of
    return seen


def _listable(shell: Any) -> bool:
    """Whether :func:`zero.records._body` can take a record from the table: no record base, declared once
    by its module (not in a function), annotations as text."""
    import zero.records as records

    annotations = shell.ns.get("__annotations__") or {}
    return (not any(records._FIELDS in base.__dict__ for base in shell.ancestors)
            and "<locals>" not in shell.qualname and all(isinstance(a, str) for a in annotations.values()))


def entry(shell: Any, body: dict[str, Any], frozen: bool, eq: bool,
          unsafe_hash: bool) -> tuple[str, tuple[object, ...]]:
    """A record's ``__init__`` text and its entry in the table but for the code (see
    :func:`zero.records._body`): what it is made from, the body worked out of it (the slow way), its flags."""
    import zero.records as records

    ns = shell.ns
    all_fields = body[records._FIELDS]
    post_init = "__post_init__" in ns or any(hasattr(b, "__post_init__") for b in shell.ancestors)
    valued = tuple(f.name for f in all_fields if f.name in ns)
    declared = tuple((at, (f.default is not records.MISSING, f.default_factory is not records.MISSING, f.repr,
                           f.compare))
                     for at, f in enumerate(f for f in all_fields if f.name in ns)
                     if ns[f.name].__class__ is records.Field)
    required = tuple(f.name for f in all_fields if f.name not in ns)
    names = tuple(f.name for f in all_fields)
    compared = tuple(f.name for f in all_fields if f.compare)
    source = records.init_source(all_fields, frozen, post_init)[0]
    return source, (ns.get("__annotations__"), (frozen, eq, unsafe_hash, post_init), valued, declared, required,
                    names, body["__record_shown__"], compared)


def code_of(source: str) -> CodeType:
    """The code of an ``__init__`` text as the table holds it: compiled with its defaults named ``None``."""
    head, _, body = source.partition("\n")
    compiled = compile(_DEFAULT.sub("=None", head) + "\n" + body, "<table>", "exec")
    return next(c for c in compiled.co_consts if isinstance(c, CodeType))


def _function(source: str) -> list[str]:
    head, _, body = source.partition("\n")
    return [_DEFAULT.sub("=None", head), body if body else "    pass"]


def render(found: list[Declared], which: str, rest_modules: list[str] | None) -> str:
    """A table's module text: the ``__init__`` code of its records, each distinct text once, the records
    :func:`zero.records._body` takes from it by module and qualified name, and by its text the ``__init__``
    of the others (a record with a record base)."""
    out = [f'"""The records {which}, worked out ahead of time: written by tools/gen_record_inits.py',
           "(see :func:`zero.records._body`).",
           "",
           "``RECORDS``: by module and qualified name, what declaring the record takes (its own annotations and",
           "flags, the fields with values, which of them are field()s and of which kind, the fields without: all",
           "checked; all names, those shown and compared; its ``__init__`` code). ``INITS``: by its text, the",
           "``__init__`` code of a record that is not in ``RECORDS``.",
           "",
           'Generated: do not edit."""',
           "",
           "# ruff: noqa",
           "# mypy: ignore-errors",
           "from __future__ import annotations",
           "",
           "from types import CodeType",
           "",
           "INITS: dict[str, CodeType] = {}",
           ""]
    codes: dict[str, str] = {}
    listed: dict[str, dict[str, str]] = {}
    by_text: list[str] = []
    for shell, body, frozen, eq, unsafe_hash in found:
        source, spec = entry(shell, body, frozen, eq, unsafe_hash)
        if not _listable(shell):
            if source not in by_text:
                by_text.append(source)
            continue
        if source not in codes:
            codes[source] = f"_{len(codes)}"
            out.extend(_function(source))
            out.append(f"{codes[source]} = __init__.__code__")
            out.append("")
        listed.setdefault(shell.module, {})[shell.qualname] = f"{repr(spec)[:-1]}, {codes[source]})"
    for source in sorted(by_text):
        out.extend(_function(source))
        out.append(f"INITS[{source!r}] = __init__.__code__")
        out.append("")
    out.append("RECORDS: dict[str, dict[str, tuple]] = {")
    for module in sorted(listed):
        out.append(f"    {module!r}: {{")
        for qualname in sorted(listed[module]):
            out.append(f"        {qualname!r}: {listed[module][qualname]},")
        out.append("    },")
    out.append("}")
    if rest_modules is not None:
        out.append("# the modules whose records are in record_inits_rest")
        out.append(f"REST_MODULES = frozenset({tuple(sorted(rest_modules))!r})")
    if codes or by_text:
        out.append("del __init__")
    return "\n".join(out) + "\n"


def tables() -> dict[Path, str]:
    """Each table's file and text."""
    hot = lint_modules()
    found = declared()
    first = [r for r in found if r[0].module in hot]
    rest = [r for r in found if r[0].module not in hot]
    rest_modules = sorted({r[0].module for r in rest})
    return {SRC / "record_inits.py": render(first, "of the modules a list's lint loads", rest_modules),
            SRC / "record_inits_rest.py": render(rest, "of the other modules", None)}


def files() -> dict[Path, str | None]:
    return dict(tables())  # the texts do not depend on the tables: they only serve them


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_record_inits.py", files, argv)


if __name__ == "__main__":
    main()

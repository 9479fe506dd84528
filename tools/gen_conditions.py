#!/usr/bin/env python3
"""Write the K rules' conditions (``src/zero/catalog/data/startup_errors.py``) as Python functions to
``startup_compiled_<kind>.py`` (one module per list kind, ``startup_compiled.py`` their index), and the prose
ranges' (``prose_ranges.py``) to ``prose_compiled.py``: read from
bytecode at start-up instead of parsed and compiled at each run (issue 40). A row whose condition text
differs from the one written here is compiled at run time, so a stale module is slower, never wrong; a
test fails while it is stale. tools/gen_startup.py runs it after writing the rows.

Usage: python tools/gen_conditions.py [--check]   (--check: exit 1 if a module is stale, write nothing)
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen

TYPE_CHECKING = False
if TYPE_CHECKING:
    from zero.catalog.conditions import Node

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def _functions(defs: list[str], name: str, condition: str, when: str) -> Node:
    """Append the functions of ``condition`` (as ``name``) and of its guard ``when`` (as ``name_when``, if
    any) to ``defs``; the condition's parsed node."""
    from zero.catalog.condition_source import source
    from zero.catalog.conditions import parse

    node = parse(condition)
    defs.append(source(name, node))
    if when:
        defs.append(source(f"{name}_when", parse(when)))
    return node


def render() -> dict[str, str]:
    """The modules' texts by file name, from the rows as they are now: one module per list kind
    (``startup_compiled_axis.py``: the K rules of that kind, imported at its first check; a lint of an axis
    list reads no channel rule: issue 40, start-up) and ``startup_compiled.py``, their index (the kinds, and
    COMPILED of every kind, built on first use, for tools and tests)."""
    from zero.catalog.condition_source import HELPERS
    from zero.catalog.conditions import ref_elements, refs
    from zero.catalog.data.startup_errors import ERRORS

    defs: dict[str, list[str]] = {}
    table: dict[str, list[str]] = {}
    for row in ERRORS:
        condition, when = str(row.get("condition", "")), str(row.get("when", ""))
        if not condition:
            continue
        code, kind = str(row["code"]), str(row["list"])
        node = _functions(defs.setdefault(kind, []), f"_{code}", condition, when)
        table.setdefault(kind, []).append(
            f"    {code!r}: ({condition!r}, {when!r}, _{code}, {f'_{code}_when' if when else 'None'},\n"
            f"             {tuple(refs(node))!r}, {tuple(ref_elements(node))!r}),")
    kinds = tuple(sorted(table))
    out = {"startup_compiled.py": (
        '"""The K rules\' conditions of startup_errors.toml as Python, written by tools/gen_conditions.py: each list\n'
        "kind's in a module of its own (``startup_compiled_axis.py``: COMPILED, code -> (condition, guard, the\n"
        "condition's function, the guard's or None, the parameters it reads, the elements it shows)), imported at\n"
        "the first check of that kind; here the kinds, and COMPILED of every kind (built on first use, for tools\n"
        "and tests).\n\n"
        'Generated: do not edit."""\n\n'
        "# ruff: noqa\n# mypy: ignore-errors\n"
        "import importlib\n\n"
        f"KINDS = {kinds!r}\n"
        "_COMPILED = {}\n\n\n"
        "def __getattr__(name):\n"
        "    if name != \"COMPILED\":\n"
        "        raise AttributeError(f\"module {__name__!r} has no attribute {name!r}\")\n"
        "    if not _COMPILED:\n"
        "        for kind in KINDS:\n"
        "            _COMPILED.update(importlib.import_module(f\"{__name__}_{kind.lower()}\").COMPILED)\n"
        "    return _COMPILED\n")}
    for kind in kinds:
        head = (f'"""The {kind} K rules\' conditions of startup_errors.toml as Python (see startup_compiled.py),\n'
                'written by tools/gen_conditions.py.\n\n'
                'Generated: do not edit."""\n\n'
                "# ruff: noqa\n# mypy: ignore-errors\n"
                f"from zero.catalog.condition_helpers import {', '.join(HELPERS)}\n\n\n")
        out[f"startup_compiled_{kind.lower()}.py"] = \
            head + "\n\n".join(defs[kind]) + "\n\nCOMPILED = {\n" + "\n".join(table[kind]) + "\n}\n"
    return out


def render_prose() -> str:
    """``prose_compiled.py``'s text: each prose range's condition (and guard) as a function, with the
    elements it reads, keyed by the parameter's ID, from the rows as they are now."""
    from zero.catalog.condition_source import HELPERS
    from zero.catalog.conditions import ref_elements
    from zero.catalog.data.prose_ranges import RANGES

    defs: list[str] = []
    table: list[str] = []
    for n, row in enumerate(RANGES):
        pid, condition, when = str(row["id"]), str(row["condition"]), str(row.get("when", ""))
        node = _functions(defs, f"_r{n}", condition, when)
        table.append(f"    {pid!r}: ({condition!r}, {when!r}, _r{n}, {f'_r{n}_when' if when else 'None'}, "
                     f"{tuple(ref_elements(node))!r},\n                     {str(row['prose'])!r}),")
    head = ('"""The prose ranges\' conditions of prose_ranges.toml as Python, written by tools/gen_conditions.py:\n'
            "ID -> (condition, guard, the condition's function, the guard's or None, the elements it reads, the\n"
            "catalogue's prose); ROWS_SIZE: the size of the prose_ranges.py they were written from (while it has it,\n"
            "a lint reads the prose ranges from here alone).\n\n"
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n# mypy: ignore-errors\n"
            f"from zero.catalog.condition_helpers import {', '.join(HELPERS)}\n\n"
            f"ROWS_SIZE = {(DATA / 'prose_ranges.py').stat().st_size}\n\n\n")
    return head + "\n\n".join(defs) + "\n\nCOMPILED = {\n" + "\n".join(table) + "\n}\n"


def files() -> dict[Path, str | None]:
    """The modules' texts, and ``None`` for the module of a kind that has no K rule any more."""
    texts: dict[Path, str | None] = {path: None for path in sorted(DATA.glob("startup_compiled_*.py"))}
    texts.update((DATA / name, text) for name, text in (*render().items(), ("prose_compiled.py", render_prose())))
    return texts


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_conditions.py", files, argv)


if __name__ == "__main__":
    main()

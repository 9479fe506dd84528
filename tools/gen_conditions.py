#!/usr/bin/env python3
"""Write the K rules' conditions (``src/zero/catalog/data/startup_errors.py``) as Python functions to
``startup_compiled.py``, and the prose ranges' (``prose_ranges.py``) to ``prose_compiled.py``: read from
bytecode at start-up instead of parsed and compiled at each run (issue 40). A row whose condition text
differs from the one written here is compiled at run time, so a stale module is slower, never wrong; a
test fails while it is stale. tools/gen_startup.py runs it after writing the rows.

Usage: python tools/gen_conditions.py
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

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


def render() -> str:
    """The module's text, from the rows as they are now."""
    from zero.catalog.condition_source import HELPERS
    from zero.catalog.conditions import ref_elements, refs
    from zero.catalog.data.startup_errors import ERRORS

    defs: list[str] = []
    table: list[str] = []
    for row in ERRORS:
        condition, when = str(row.get("condition", "")), str(row.get("when", ""))
        if not condition:
            continue
        code = str(row["code"])
        node = _functions(defs, f"_{code}", condition, when)
        table.append(f"    {code!r}: ({condition!r}, {when!r}, _{code}, {f'_{code}_when' if when else 'None'},\n"
                     f"             {tuple(refs(node))!r}, {tuple(ref_elements(node))!r}),")
    head = ('"""The K rules\' conditions of startup_errors.toml as Python, written by tools/gen_conditions.py.\n\n'
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n# mypy: ignore-errors\n"
            f"from zero.catalog.condition_helpers import {', '.join(HELPERS)}\n\n\n")
    return head + "\n\n".join(defs) + "\n\nCOMPILED = {\n" + "\n".join(table) + "\n}\n"


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


def main() -> None:
    for name, text in (("startup_compiled.py", render()), ("prose_compiled.py", render_prose())):
        target = DATA / name
        target.write_text(text, encoding="utf-8")
        print(f"wrote {target}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Write the ``__init__`` of every record zero declares, compiled ahead of time, to ``src/zero/record_inits.py``.

:func:`zero.records.record` writes each record's ``__init__`` as Python text and, without this table,
compiles it when the record is first instantiated: some forty compiles in a ``zero lint`` of one list,
5 ms of its 60 (issue 40, start-up). The table holds each distinct text's function, compiled with the
module, keyed by that text; records take its code with their own globals and defaults. A record whose
text is not in the table (a test's, or a table not regenerated after a record changed) compiles its own,
as before: slower, never wrong; a test fails while the table is stale. Run it after adding, removing or
changing a record's fields.

Usage: python tools/gen_record_inits.py [--check]   (--check: exit 1 if the table is stale, write nothing)
"""

from __future__ import annotations

import importlib
import pkgutil
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

SRC = Path(__file__).resolve().parent.parent / "src" / "zero"
# Parameter defaults the text names from its scope; the table's functions get theirs from the record.
_DEFAULT = re.compile(r"=(?:__default_\w+|MISSING)(?=[,)])")
_OPTIONAL = ("zero.server",)  # modules that need an extra (pygls) are read only where it is installed


def sources() -> list[str]:
    """The ``__init__`` text of every record of every zero module, sorted, each once."""
    import zero.records as records

    seen: set[str] = set()
    first_init = records._first_init

    def capture(all_fields: tuple[records.Field, ...], frozen: bool, post_init: bool,
                owner: list[type]) -> object:
        seen.add(records.init_source(all_fields, frozen, post_init)[0])
        return first_init(all_fields, frozen, post_init, owner)

    records._first_init = capture  # type: ignore[assignment]
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
        records._first_init = first_init
    return sorted(seen)


def render() -> str:
    """The module's text."""
    out = ['"""The ``__init__`` of every record zero declares, compiled with this module and keyed by its text:',
           "written by tools/gen_record_inits.py (see :func:`zero.records._compiled_init`).",
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
    for source in sources():
        head, _, body = source.partition("\n")
        out.append(_DEFAULT.sub("=None", head))
        out.append(body if body else "    pass")
        out.append(f"INITS[{source!r}] = __init__.__code__")
        out.append("")
    out.append("del __init__")
    return "\n".join(out) + "\n"


def main() -> None:
    target = SRC / "record_inits.py"
    if sys.argv[1:] == ["--check"]:  # the records are read with the table as it is: it only serves them
        fresh = render() == target.read_text(encoding="utf-8")
        print("record_inits.py is current" if fresh else "record_inits.py is stale: run tools/gen_record_inits.py")
        raise SystemExit(0 if fresh else 1)
    # A stale table must not decide which texts the records write: render from a clean slate.
    target.write_text('"""Placeholder: written by tools/gen_record_inits.py."""\n\nINITS: dict = {}\n',
                      encoding="utf-8")
    target.write_text(render(), encoding="utf-8")
    print(f"wrote {target}")


if __name__ == "__main__":
    main()

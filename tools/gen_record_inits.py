#!/usr/bin/env python3
"""Write the ``__init__`` of every record zero declares, compiled ahead of time, to ``src/zero/record_inits.py``.

:func:`zero.records.record` writes each record's ``__init__`` as Python text and, without this table,
compiles it when the record is first instantiated: some forty compiles in a ``zero lint`` of one list,
5 ms of its 60 (issue 40, start-up). The table holds each distinct text's function, compiled with the
module, keyed by that text; records take its code with their own globals and defaults. A record whose
text is not in the table (a test's, or a table not regenerated after a record changed) compiles its own,
as before: slower, never wrong; a test fails while the table is stale. Run it after adding, removing or
changing a record's fields.

Two tables: ``record_inits.py`` holds the records of the modules a list's lint loads (it is imported with
:mod:`zero.records`), ``record_inits_rest.py`` every other record's (imported at the first record it holds:
a list's lint never reads its 90 functions).

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

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

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


def sources() -> dict[str, str]:
    """The ``__init__`` text of every record of every zero module, each once, with the module it is in."""
    import zero.records as records

    seen: dict[str, str] = {}
    first_init = records._first_init

    def capture(all_fields: tuple[records.Field, ...], frozen: bool, post_init: bool,
                owner: list[type]) -> object:
        frame = sys._getframe(1)
        while frame.f_back is not None and frame.f_globals.get("__name__") == "zero.records":
            frame = frame.f_back
        module = frame.f_globals.get("__name__", "")  # the module that declares the record
        seen.setdefault(records.init_source(all_fields, frozen, post_init)[0], module)
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
    return seen


def render(texts: list[str], which: str) -> str:
    """A table's module text."""
    out = [f'"""The ``__init__`` of every record {which}, compiled with this module and keyed by its text:',
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
    for source in texts:
        head, _, body = source.partition("\n")
        out.append(_DEFAULT.sub("=None", head))
        out.append(body if body else "    pass")
        out.append(f"INITS[{source!r}] = __init__.__code__")
        out.append("")
    out.append("del __init__")
    return "\n".join(out) + "\n"


def tables() -> dict[Path, str]:
    """Each table's file and text."""
    hot = lint_modules()
    found = sources()
    first = sorted(text for text, module in found.items() if module in hot)
    rest = sorted(text for text, module in found.items() if module not in hot)
    return {SRC / "record_inits.py": render(first, "of the modules a list's lint loads"),
            SRC / "record_inits_rest.py": render(rest, "of the other modules")}


def main() -> None:
    if sys.argv[1:] == ["--check"]:  # the texts do not depend on the tables: they only serve them
        stale = [path.name for path, text in tables().items()
                 if not path.is_file() or path.read_text(encoding="utf-8") != text]
        print(f"{', '.join(stale)} stale: run tools/gen_record_inits.py" if stale else "the record tables are current")
        raise SystemExit(1 if stale else 0)
    for path, text in tables().items():
        path.write_text(text, encoding="utf-8")
        print(f"wrote {path}")


if __name__ == "__main__":
    main()

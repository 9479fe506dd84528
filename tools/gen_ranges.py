#!/usr/bin/env python3
"""Write the built-in catalogue's formal ranges, parsed, to ``src/zero/catalog/data/ranges_compiled_<kind>.py``
(one module per list kind, ``ranges_compiled.py`` their index):
read from bytecode at the first range a lint checks instead of parsed at each run (issue 40). Each is
written with its text; a range whose text differs from the one written here (a user's catalogue, or a
stale module) is parsed at run time, so a stale module is slower, never wrong; a test fails while it is
stale. Run it after tools/gen_registry.py and tools/gen_seeds.py.

Usage: python tools/gen_ranges.py [--check]   (--check: exit 1 if a module is stale, write nothing)
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def render() -> dict[str, str]:
    """The modules' texts by file name, from the built-in registry as it is now: ``ranges_compiled.py`` (the
    kinds that have ranges, and RANGES of every kind for tools and tests, built on first use) and one module
    per kind (``ranges_compiled_axis.py``), the one a lint imports at the first range of that kind (a lint of
    an axis list reads no channel range: issue 40, start-up)."""
    from zero.catalog.ranges import encode_range, parse_range
    from zero.catalog.registry import load_registry

    specs = load_registry().specs
    by_kind: dict[str, list[str]] = {}
    for pid in sorted(specs):
        text = specs[pid].range_text
        if text:
            by_kind.setdefault(pid[2:6], []).append(
                f"    {pid!r}: ({text!r}, {encode_range(parse_range(text, pid))!r}),")
    kinds = tuple(sorted(by_kind))
    out = {"ranges_compiled.py": (
        '"""The formal ranges of the built-in catalogue (table.py and seeds.py), parsed, written by\n'
        'tools/gen_ranges.py: each kind\'s in a module of its own (``ranges_compiled_axis.py``: RANGES, ID -> (range\n'
        'text, the range encoded by zero.catalog.ranges.encode_range)), imported at the first range of that kind;\n'
        'here the kinds that have one, and RANGES of every kind (built on first use, for tools and tests).\n\n'
        'Generated: do not edit."""\n\n'
        "# ruff: noqa\n"
        "from __future__ import annotations\n\n"
        "import importlib\n\n"
        "TYPE_CHECKING = False\n"
        "if TYPE_CHECKING:\n"
        "    from typing import Any\n\n"
        f"KINDS: tuple[str, ...] = {kinds!r}\n"
        "_RANGES: dict[str, tuple[str, Any]] = {}\n\n\n"
        "def __getattr__(name: str) -> dict[str, tuple[str, Any]]:\n"
        "    if name != \"RANGES\":\n"
        "        raise AttributeError(f\"module {__name__!r} has no attribute {name!r}\")\n"
        "    if not _RANGES:\n"
        "        for kind in KINDS:\n"
        "            _RANGES.update(importlib.import_module(f\"{__name__}_{kind.lower()}\").RANGES)\n"
        "    return _RANGES\n")}
    for kind in kinds:
        out[f"ranges_compiled_{kind.lower()}.py"] = (
            f'"""The formal ranges of the built-in catalogue\'s {kind} parameters, parsed (see ranges_compiled.py),\n'
            'written by tools/gen_ranges.py: ID -> (range text, the range encoded by\n'
            'zero.catalog.ranges.encode_range).\n\n'
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n\n"
            "RANGES = {\n" + "\n".join(by_kind[kind]) + "\n}\n")
    return out


def files() -> dict[Path, str | None]:
    """The modules' texts, and ``None`` for the module of a kind that has no range any more."""
    return _gen.in_folder(DATA, "ranges_compiled_*.py", render())


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_ranges.py", files, argv)


if __name__ == "__main__":
    main()

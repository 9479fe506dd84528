#!/usr/bin/env python3
"""Write the built-in catalogue's formal ranges, parsed, to ``src/zero/catalog/data/ranges_compiled.py``:
read from bytecode at the first range a lint checks instead of parsed at each run (issue 40). Each is
written with its text; a range whose text differs from the one written here (a user's catalogue, or a
stale module) is parsed at run time, so a stale module is slower, never wrong; a test fails while it is
stale. Run it after tools/gen_registry.py and tools/gen_seeds.py.

Usage: python tools/gen_ranges.py
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def render() -> str:
    """The module's text, from the built-in registry as it is now."""
    from zero.catalog.ranges import encode_range, parse_range
    from zero.catalog.registry import load_registry

    specs = load_registry().specs
    lines = []
    for pid in sorted(specs):
        text = specs[pid].range_text
        if text:
            lines.append(f"    {pid!r}: ({text!r}, {encode_range(parse_range(text, pid))!r}),")
    return ('"""The formal ranges of the built-in catalogue (table.py and seeds.py), parsed, written by\n'
            'tools/gen_ranges.py: ID -> (range text, the range encoded by zero.catalog.ranges.encode_range).\n\n'
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n\n"
            "RANGES = {\n" + "\n".join(lines) + "\n}\n")


def main() -> None:
    target = DATA / "ranges_compiled.py"
    target.write_text(render(), encoding="utf-8")
    print(f"wrote {target}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/startup_errors.toml`` (the kernel's documented start-up errors a
list can cause, edited by hand, each row with its source) to ``startup_errors.py``,
``drive_types.toml`` (the drive types each axis parameter is documented for) to ``drive_types.py``, and
``prose_ranges.toml`` (the catalogue's prose ranges written as conditions) to ``prose_ranges.py``,
and ``releases.toml`` (key renames and removals, each row checked to have a source) to
``releases_table.py``
(imported at run time: no TOML parser at start-up). Run it after every edit of either TOML; a test
fails while they differ.

Usage: python tools/gen_startup.py
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

from pydata import write_module

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def main() -> None:
    rows = tomllib.loads((DATA / "startup_errors.toml").read_text(encoding="utf-8"))["error"]
    write_module(DATA / "startup_errors.py", "The kernel's start-up errors of startup_errors.toml, compiled.",
                 {"ERRORS": rows}, rows_name="ERRORS")
    print(f"wrote {DATA / 'startup_errors.py'}: {len(rows)} errors")
    drives = tomllib.loads((DATA / "drive_types.toml").read_text(encoding="utf-8"))["drive"]
    write_module(DATA / "drive_types.py", "The drive types of each parameter, drive_types.toml compiled.",
                 {"DRIVE_TYPES": drives}, rows_name="DRIVE_TYPES")
    print(f"wrote {DATA / 'drive_types.py'}: {len(drives)} parameters")
    ranges = tomllib.loads((DATA / "prose_ranges.toml").read_text(encoding="utf-8"))["range"]
    write_module(DATA / "prose_ranges.py", "The prose ranges of prose_ranges.toml written as conditions, compiled.",
                 {"RANGES": ranges}, rows_name="RANGES")
    print(f"wrote {DATA / 'prose_ranges.py'}: {len(ranges)} ranges")
    from zero.catalog.releases import read_table  # the rows checked on the way (a row needs a source)

    t = read_table(DATA / "releases.toml")
    rows = {"RENAMES": t.renames, "REMOVALS": t.removals, "PREFIXES": t.prefixes}
    write_module(DATA / "releases_table.py", "The renames and removals of releases.toml, checked and compiled.",
                 {name: [{f: getattr(r, f) for f in ("old", "kind", "new", "id", "release", "source", "see")
                          if hasattr(r, f)} for r in rs] for name, rs in rows.items()})
    print(f"wrote {DATA / 'releases_table.py'}")
    import gen_conditions  # the K conditions as Python (issue 40: start-up), from the rows just written
    import gen_startup_rules  # and what each K rule declares, with the size of the rows' module

    gen_conditions.main()
    gen_startup_rules.main()


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/startup_errors.toml`` (the kernel's documented start-up errors a
list can cause, edited by hand, each row with its source) to ``startup_errors.py``,
``drive_types.toml`` (the drive types each axis parameter is documented for) to ``drive_types.py``, and
``prose_ranges.toml`` (the catalogue's prose ranges written as conditions) to ``prose_ranges.py``,
and ``releases.toml`` (key renames and removals, each row checked to have a source) to
``releases_table.py``
(imported at run time: no TOML parser at start-up). Run it after every edit of either TOML; a test
fails while they differ.

Usage: python tools/gen_startup.py [--check]   (--check: exit 1 if a module is stale, its own or those of
tools/gen_conditions.py and tools/gen_startup_rules.py, which it runs; write nothing)
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen
from pydata import module_text

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def files() -> dict[Path, str | None]:
    """The texts of the four modules compiled from the TOML (not those of the generators it runs)."""
    rows = tomllib.loads((DATA / "startup_errors.toml").read_text(encoding="utf-8"))["error"]
    drives = tomllib.loads((DATA / "drive_types.toml").read_text(encoding="utf-8"))["drive"]
    ranges = tomllib.loads((DATA / "prose_ranges.toml").read_text(encoding="utf-8"))["range"]
    from zero.catalog.releases import read_table  # the rows checked on the way (a row needs a source)

    t = read_table(DATA / "releases.toml")
    releases = {"RENAMES": t.renames, "REMOVALS": t.removals, "PREFIXES": t.prefixes}
    return {
        DATA / "startup_errors.py": module_text("The kernel's start-up errors of startup_errors.toml, compiled.",
                                                {"ERRORS": rows}, rows_name="ERRORS"),
        DATA / "drive_types.py": module_text("The drive types of each parameter, drive_types.toml compiled.",
                                             {"DRIVE_TYPES": drives}, rows_name="DRIVE_TYPES"),
        DATA / "prose_ranges.py": module_text(
            "The prose ranges of prose_ranges.toml written as conditions, compiled.", {"RANGES": ranges},
            rows_name="RANGES"),
        DATA / "releases_table.py": module_text(
            "The renames and removals of releases.toml, checked and compiled.",
            {name: [{f: getattr(r, f) for f in ("old", "kind", "new", "id", "release", "source", "see")
                     if hasattr(r, f)} for r in rs] for name, rs in releases.items()}),
    }


def main(argv: list[str] | None = None) -> None:
    check = _gen.checking(argv, "python tools/gen_startup.py")
    found = _gen.update("gen_startup.py", files(), check)
    import gen_conditions  # the K conditions as Python (issue 40: start-up), from the rows just written
    import gen_startup_rules  # and what each K rule declares, with the size of the rows' module

    found += _gen.update("gen_conditions.py", gen_conditions.files(), check)
    found += _gen.update("gen_startup_rules.py", gen_startup_rules.files(), check)
    _gen.done("gen_startup.py", found, check)


if __name__ == "__main__":
    main()

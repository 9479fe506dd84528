#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/startup_errors.toml`` (the kernel's documented start-up errors a
list can cause, edited by hand, each row with its source) to ``startup_errors.py`` (imported at run
time: no TOML parser at start-up). Run it after every edit of the TOML; a test fails while the two
differ.

Usage: python tools/gen_startup.py
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from pydata import write_module

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def main() -> None:
    rows = tomllib.loads((DATA / "startup_errors.toml").read_text(encoding="utf-8"))["error"]
    write_module(DATA / "startup_errors.py", "The kernel's start-up errors of startup_errors.toml, compiled.",
                 {"ERRORS": rows}, rows_name="ERRORS")
    print(f"wrote {DATA / 'startup_errors.py'}: {len(rows)} errors")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/seeds.toml`` (edited by hand) to ``seeds.py`` (imported at
run time, so that start-up needs no TOML parser). Run it after every edit of seeds.toml; a test
fails while the two differ.

Usage: python tools/gen_seeds.py
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from pydata import write_module

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def main() -> None:
    seeds = tomllib.loads((DATA / "seeds.toml").read_text(encoding="utf-8"))
    write_module(DATA / "seeds.py", "The parameters, aliases and vendor keys of seeds.toml, compiled.",
                 {"SEEDS": seeds})
    print(f"wrote {DATA / 'seeds.py'}")


if __name__ == "__main__":
    main()

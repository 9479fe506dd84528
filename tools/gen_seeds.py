#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/seeds.toml`` (edited by hand) to ``seeds.py`` (imported at
run time, so that start-up needs no TOML parser). Run it after every edit of seeds.toml; a test
fails while the two differ.

Usage: python tools/gen_seeds.py [--check]   (--check: exit 1 if seeds.py is stale, write nothing)
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _gen
from pydata import module_text

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def files() -> dict[Path, str | None]:
    seeds = tomllib.loads((DATA / "seeds.toml").read_text(encoding="utf-8"))
    return {DATA / "seeds.py": module_text("The parameters, aliases and vendor keys of seeds.toml, compiled.",
                                           {"SEEDS": seeds})}


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_seeds.py", files, argv)


if __name__ == "__main__":
    main()

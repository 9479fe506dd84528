#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/seeds.toml`` (edited by hand) to ``seeds.json`` (read at run
time, so that start-up needs no TOML parser). Run it after every edit of seeds.toml; a test
fails while the two differ.

Usage: python tools/gen_seeds.py
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def main() -> None:
    seeds = tomllib.loads((DATA / "seeds.toml").read_text(encoding="utf-8"))
    (DATA / "seeds.json").write_text(json.dumps(seeds, ensure_ascii=False, indent=1, sort_keys=True) + "\n",
                                     encoding="utf-8")
    print(f"wrote {DATA / 'seeds.json'}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/evidence.toml`` (what zero says the controller does, each claim with
its source) to ``evidence_table.py`` (imported at the first finding: no TOML parser at start-up). Run it
after every edit of the TOML; a test fails while they differ.

Usage: python tools/gen_evidence.py
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from pydata import write_module

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def main() -> None:
    evidence = tomllib.loads((DATA / "evidence.toml").read_text(encoding="utf-8"))
    write_module(DATA / "evidence_table.py",
                 "The claims of evidence.toml (what the controller does, and the source), compiled.",
                 {"CLAIMS": evidence["claim"], "RULES": evidence["rules"], "DRIVES": evidence.get("drive", [])},
                 rows_name="CLAIMS")
    print(f"wrote {DATA / 'evidence_table.py'}: {len(evidence['claim'])} claims")


if __name__ == "__main__":
    main()

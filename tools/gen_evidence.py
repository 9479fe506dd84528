#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/evidence.toml`` (what zero says the controller does, each claim with
its source) to ``evidence_table.py`` (imported at the first finding: no TOML parser at start-up), with
the drive-type facts of ``drive_types.toml`` (the one table of them) as its ``DRIVES``, each row by its
catalogue key. Run it after every edit of either TOML; a test fails while they differ.

Usage: python tools/gen_evidence.py [--check]   (--check: exit 1 if evidence_table.py is stale, write nothing)
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen
from pydata import module_text

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def drives(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The rows of drive_types.toml as the evidence table reads them: a key pattern (the catalogue's key
    of ``param``, or the row's ``key``, a subtree ending in ``.``), the drive types and the page."""
    from zero.catalog.registry import load_registry

    registry = load_registry()
    out = []
    for row in rows:
        spec = registry.get(row["param"]) if "param" in row else None
        key = row.get("key") or (spec.key if spec is not None else None)
        if not key:
            raise SystemExit(f"drive_types.toml: no key for {row}")
        out.append({"key": key, "types": row["types"], "source": row["source"]})
    return out


def files() -> dict[Path, str | None]:
    evidence = tomllib.loads((DATA / "evidence.toml").read_text(encoding="utf-8"))
    types = tomllib.loads((DATA / "drive_types.toml").read_text(encoding="utf-8"))["drive"]
    return {DATA / "evidence_table.py": module_text(
        "The claims of evidence.toml (what the controller does, and the source), compiled; DRIVES from "
        "drive_types.toml.",
        {"CLAIMS": evidence["claim"], "RULES": evidence["rules"], "DRIVES": drives(types)}, rows_name="CLAIMS")}


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_evidence.py", files, argv)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Compile ``src/zero/catalog/data/evidence.toml`` (what zero says the controller does, each claim with
its source) to ``evidence_table.py`` (imported at the first finding: no TOML parser at start-up), with
the drive-type facts of ``drive_types.toml`` (the one table of them) as its ``DRIVES``, each row by its
catalogue key. Run it after every edit of either TOML; a test fails while they differ.

The claims and the rules' claims are written as text, a row a line (:func:`lines`): a string constant
loads with the module as one block, where the rows as dictionaries were some 400 objects to unmarshal
and build before the first finding could say anything, and :mod:`zero.catalog.evidence` finds a claim's
lines when a finding first asks for it (issue 40: a lint of a list with a finding, 132.69 M -> 132.34 M
instructions).

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
# a claim's fields in the order of its line (zero.catalog.evidence reads them in this order)
FIELDS = ("name", "consequence", "severity", "says", "source", "releases", "kinds", "kernel_error")


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


def _field(row: dict[str, Any], name: str) -> str:
    """A claim's field as its line writes it: ``kinds`` joined by commas, no kernel error empty, no
    ``releases`` ``all`` (the defaults of :class:`zero.catalog.evidence.Claim`)."""
    value = row.get(name)
    if name == "kinds":
        if any("," in kind for kind in value or ()):
            raise SystemExit(f"evidence.toml: a kind with a comma in {row}")
        return ",".join(value or ())
    text = "all" if name == "releases" and value is None else str(value or "")
    if "\t" in text or "\n" in text:
        raise SystemExit(f"evidence.toml: a tab or a line break in the {name} of {row}")
    return text


def lines(rows: list[tuple[str, ...]]) -> str:
    """``rows`` (each a tuple of fields) as the text of a string constant: each row a line, its fields
    separated by tabs, the text beginning with a line break (every row's line then begins after one)."""
    return "(\n    \"\\n\"\n" + "".join(f"    {chr(9).join(row) + chr(10)!r}\n" for row in rows) + ")"


def claim_rows(claims: list[dict[str, Any]]) -> list[tuple[str, ...]]:
    """Each claim's rows, a claim's rows together in the order of its first (the order the table keeps)."""
    by_name: dict[str, list[tuple[str, ...]]] = {}
    for row in claims:
        by_name.setdefault(row["name"], []).append(tuple(_field(row, name) for name in FIELDS))
    return [row for rows in by_name.values() for row in rows]


def files() -> dict[Path, str | None]:
    evidence = tomllib.loads((DATA / "evidence.toml").read_text(encoding="utf-8"))
    types = tomllib.loads((DATA / "drive_types.toml").read_text(encoding="utf-8"))["drive"]
    text = module_text(
        "The claims of evidence.toml (what the controller does, and the source), compiled; DRIVES from "
        "drive_types.toml.\n\nCLAIMS: a line per row, a claim's rows together, its fields separated by tabs: "
        f"{', '.join(FIELDS)} (kinds separated by commas).\nRULES: a line per rule: its code, a tab, the name "
        "of its claim.",
        {"DRIVES": drives(types)})
    rules = [(str(code), str(name)) for code, name in evidence["rules"].items()]
    if any("\t" in cell or "\n" in cell for row in rules for cell in row):
        raise SystemExit("evidence.toml: a tab or a line break in [rules]")
    text += f"CLAIMS: str = {lines(claim_rows(evidence['claim']))}\nRULES: str = {lines(rules)}\n"
    return {DATA / "evidence_table.py": text}


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_evidence.py", files, argv)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Regenerate ``src/zero/catalog/data/table.py`` from a ``CncParaDesc.xml``.

Usage: python tools/gen_registry.py [PATH/TO/CncParaDesc.xml]

Only facts are written (IDs, keys, types, defaults, formal ranges, sizes,
symbols, units, restart flags); the vendor's description texts are not.
Without an argument it reads ../shared/corpus/isg-sdk/meta-data/CncParaDesc.xml.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

from pydata import write_module  # noqa: E402

from zero.catalog.paramdesc import read_param_desc  # noqa: E402

DEFAULT_XML = ROOT.parent / "shared" / "corpus" / "isg-sdk" / "meta-data" / "CncParaDesc.xml"
OUT = ROOT / "src" / "zero" / "catalog" / "data" / "table.py"


def compact(row: dict[str, object]) -> dict[str, object]:
    """Drop empty fields so the table stays small."""
    return {k: v for k, v in row.items() if not (v is None or v is False or v in ([], ""))}


def main(argv: list[str]) -> int:
    xml = Path(argv[1]) if len(argv) > 1 else DEFAULT_XML
    rows = [compact(r) for r in read_param_desc(xml)]
    for r in rows:
        r.pop("source", None)  # always the same; the loader fills it in
        if "default" not in r:
            r["default"] = ""
    rows.sort(key=lambda r: str(r["id"]))
    write_module(OUT, "The facts of every parameter of the vendor's CncParaDesc.xml (no description texts).",
                 {"GENERATED_FROM": "CncParaDesc.xml (ISG CNC Kernel SDK V1.5.0.0, kernel V4.13.0.0)",
                  "ROWS": rows}, rows_name="ROWS")
    print(f"wrote {len(rows)} parameters to {OUT.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))

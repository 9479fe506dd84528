"""Prose ranges as conditions (catalog/data/prose_ranges.toml): every row reads, names parameters of
its own list kind that exist, checks its own parameter, and holds for the catalogue's defaults."""

from __future__ import annotations

import re
import tomllib
from collections.abc import Iterator
from functools import cache
from pathlib import Path
from typing import Any

import pytest

from zero.catalog.conditions import Lookup, Node, evaluate, parse, refs
from zero.catalog.data.table import ROWS
from zero.catalog.registry import Registry, load_registry
from zero.catalog.values import ListValues, default_number
from zero.lists.tokenizer import tokenize

ROOT = Path(__file__).resolve().parents[2]
TABLE = ROOT / "src" / "zero" / "catalog" / "data" / "prose_ranges.toml"
FIXTURES = ROOT / "fixtures" / "prose"
REASONS = ("other list", "runtime", "string", "not expressible", "vague", "no relation")
_ID = re.compile(r"P-[A-Z]{4}-[0-9]{5}")


@cache
def table() -> dict[str, list[dict[str, Any]]]:
    with TABLE.open("rb") as f:
        return tomllib.load(f)


@cache
def registry() -> Registry:
    return load_registry()


def ranges() -> list[dict[str, Any]]:
    return table()["range"]


def row_id(row: dict[str, Any]) -> str:
    return str(row["id"])


def compiled(row: dict[str, Any]) -> tuple[Node, Node | None]:
    when = row.get("when", "")
    return parse(row["condition"]), (parse(when) if when else None)


def test_table_shape() -> None:
    t = table()
    assert set(t) == {"range", "left"}
    for row in t["range"]:
        assert set(row) <= {"id", "condition", "when", "prose", "note"}, row["id"]
        assert _ID.fullmatch(row["id"]) and row["condition"] and row["prose"]
    for row in t["left"]:
        assert set(row) == {"id", "prose", "why"}, row["id"]
        assert row["why"].split(":")[0] in REASONS, row["id"]
    ids = [r["id"] for r in t["range"]] + [r["id"] for r in t["left"]]
    assert len(ids) == len(set(ids)), "a parameter in two rows"


def test_every_row_is_a_prose_range_of_the_catalogue() -> None:
    """Only ranges zero cannot read formally belong here (a formal one is checked already)."""
    prose = {r["id"] for r in ROWS if r.get("range_prose")}
    for row in ranges() + table()["left"]:
        assert row["id"] in prose, row["id"]


@pytest.mark.parametrize("row", ranges(), ids=row_id)
def test_row_parses_and_names_its_own_kind(row: dict[str, Any]) -> None:
    condition, when = compiled(row)
    own = row["id"]
    spec = registry().get(own)
    assert spec is not None
    named = refs(condition) + (refs(when) if when is not None else [])
    assert own in refs(condition), "the checked parameter is not in its own condition"
    for pid in named:
        other = registry().get(pid)
        assert other is not None, f"{pid} is not in the catalogue"
        assert pid[2:6] == own[2:6] and other.kind == spec.kind, f"{pid} is of another list kind"


def _defaults(pid: str, index: int | None) -> float | int | None:
    spec = registry().get(pid)
    return default_number(spec) if spec is not None else None


@pytest.mark.parametrize("row", ranges(), ids=row_id)
def test_catalogue_defaults_satisfy_the_row(row: dict[str, Any]) -> None:
    condition, when = compiled(row)
    if when is not None and evaluate(when, _defaults) is False:
        return
    got = evaluate(condition, _defaults)
    assert got is not False, f"the catalogue's defaults fail {row['condition']}"
    if got is None:  # nothing said: only where a parameter it reads has no numeric default
        assert any(_defaults(pid, None) is None for pid in refs(condition)), row["id"]


def _elements(values: ListValues, pid: str) -> list[tuple[int, ...]]:
    written = sorted(values.ids_of(pid))
    return written or [()]


def _lookup(values: ListValues, checked: tuple[int, ...]) -> Lookup:
    """An ID without an index reads the checked element (paired arrays; a scalar ignores it)."""

    def look(pid: str, index: int | None) -> float | int | None:
        return values.number_of(pid, checked if index is None else (index,))

    return look


def failures(path: Path) -> Iterator[tuple[str, tuple[int, ...]]]:
    doc = tokenize(path.read_bytes(), str(path))
    values = ListValues.of(doc, registry(), "AXIS")
    for row in ranges():
        if not row["id"].startswith("P-AXIS-"):
            continue
        condition, when = compiled(row)
        for element in _elements(values, row["id"]):
            look = _lookup(values, element)
            if when is not None and evaluate(when, look) is False:
                continue
            if evaluate(condition, look) is False:
                yield row["id"], element


def test_a_list_within_every_range() -> None:
    assert list(failures(FIXTURES / "pass.lis")) == []


def test_a_list_outside_ranges_fails_where_it_is_outside() -> None:
    assert sorted(failures(FIXTURES / "fail.lis")) == [
        ("P-AXIS-00071", ()),
        ("P-AXIS-00126", (1,)),
        ("P-AXIS-00127", (1,)),
        ("P-AXIS-00152", (1,)),  # gear 0 (0) lies between the soft limits
        ("P-AXIS-00248", ()),  # v2 not written: its default 2000 (gear 0)
        ("P-AXIS-00293", (0,)),
        ("P-AXIS-00305", ()),
        ("P-AXIS-00395", (0,)),
        ("P-AXIS-00531", (1,)),
    ]

"""Prose ranges as conditions (catalog/data/prose_ranges.toml): every row reads, names parameters of
its own list kind that exist, checks its own parameter, and holds for the catalogue's defaults."""

from __future__ import annotations

import re
import tomllib
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

from zero.catalog.conditions import compile_condition, parse, refs
from zero.catalog.data.table import ROWS
from zero.catalog.registry import Registry, load_registry
from zero.catalog.values import default_number
from zero.engine.lint import lint_file

if TYPE_CHECKING:
    from zero.catalog.conditions import Node

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
    if when is not None and compile_condition(when)(_defaults) is not True:  # as zero lint: only then checked
        return
    got = compile_condition(condition)(_defaults)
    assert got is not False, f"the catalogue's defaults fail {row['condition']}"
    if got is None:  # nothing said: only where a parameter it reads has no numeric default
        assert any(_defaults(pid, None) is None for pid in refs(condition)), row["id"]


def failures(path: Path) -> list[tuple[str | None, int]]:
    """The prose-range findings `zero lint` gives on a list (R006 on a parameter with a prose range)."""
    prose = {row["id"] for row in ranges()}
    return [(d.param_id, d.span.line) for d in lint_file(path, registry()).diagnostics
            if d.code == "R006" and d.param_id in prose]


def test_a_list_within_every_range() -> None:
    assert list(failures(FIXTURES / "pass.lis")) == []


# Not 10: a reference point equal to swe_pos is one the axis may move to (the soft-limit documentation; issue 36);
# not 13: the inverted modulo limits are K032's (P-ERR-110052), one root cause, one finding (issue 36).
EXPECTED = [("P-AXIS-00071", 6), ("P-AXIS-00531", 22)]
SAID_BY_THE_KERNEL = [("K032", 12), ("K069", 17), ("K092", 19), ("K070", 24)]  # moduloo, tr_w_min, dead band, phasing


def test_a_list_outside_ranges_fails_where_it_is_outside() -> None:
    """Each violation at its line; where the kernel's own start-up error says the same of a line (its
    number, K rules), that is the one finding there (moduloo, tr_w_min, the dead band, the phasing)."""
    assert sorted(failures(FIXTURES / "fail.lis")) == sorted(EXPECTED)
    kernel = [(d.code, d.span.line) for d in lint_file(FIXTURES / "fail.lis", registry()).diagnostics
              if d.code.startswith("K")]
    assert kernel == SAID_BY_THE_KERNEL

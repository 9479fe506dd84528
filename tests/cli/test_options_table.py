"""One option table, two command lines: the lean ``zero lint`` parser and the typer
command accept exactly the same options and read the same values from them."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Any

import pytest
import typer.main
from hypothesis import given, settings
from hypothesis import strategies as st

try:  # typer bundles its own click from 0.2x on; before, it used the click package
    from typer._click.exceptions import ClickException  # type: ignore[import-not-found,unused-ignore]
except ImportError:  # pragma: no cover - older typer
    from click.exceptions import ClickException  # type: ignore[import-not-found,no-redef,unused-ignore]

from zero.cli.app import app
from zero.cli.options import LINT_OPTIONS, parse_lint_args

LINT = typer.main.get_command(app).commands["lint"]  # type: ignore[attr-defined]


MULTI = {o.dest for o in LINT_OPTIONS if o.kind == "multi"} | {"paths"}


def typer_params(args: list[str]) -> dict[str, Any] | None:
    """What the typer command reads from ``args``; ``None`` when it rejects them."""
    try:
        params = dict(LINT.make_context("lint", list(args)).params)
    except (ClickException, SystemExit):
        return None
    out: dict[str, Any] = {}
    for name, value in params.items():
        if isinstance(value, Enum):
            value = value.value
        if name in MULTI:
            value = list(value or [])
        # a file's name: the lean parser gives the text typer's Path prints (zero.files.path_str)
        out[name] = [str(v) if isinstance(v, Path) else v for v in value] if isinstance(value, list) else \
            str(value) if isinstance(value, Path) else value
    return out


def test_the_typer_command_has_exactly_the_options_of_the_table() -> None:
    typer_options = {p.name: (tuple(p.opts), tuple(p.secondary_opts), bool(p.multiple), bool(p.is_flag))
                     for p in LINT.params if p.name != "paths"}
    table = {o.dest: (o.flags, (o.negative,) if o.negative else (), o.kind == "multi", o.kind == "flag")
             for o in LINT_OPTIONS}
    assert typer_options == table


def test_both_read_the_same_values() -> None:
    args = ["a.lis", "-", "--select", "R,S", "--select=M", "--ignore", "R007", "--extend-select", "S012", "-j", "3",
            "--output-format=json",
            "--no-strict", "--strict", "-o", "out.json", "--config", "zero.toml", "--kind", "axis", "--fix",
            "--diff", "--unsafe-fixes", "--statistics", "--exit-zero", "--isolated", "--stdin-filename", "x.lis",
            "--machine", "h.lis", "--", "--not-an-option.lis"]
    lean = parse_lint_args(args)
    assert lean is not None
    assert lean == typer_params(args)
    assert lean["paths"] == ["a.lis", "-", "--not-an-option.lis"]
    assert lean["select"] == ["R,S", "M"] and lean["jobs"] == 3 and lean["strict"] is True


@pytest.mark.parametrize("args", [
    ["a.lis", "-j", "-1"],  # a negative number of processes: refused by both
    ["a.lis", "--jobs", "many"],
    ["a.lis", "--output-format", "xml"],
    ["a.lis", "--fix=yes"],
    ["a.lis", "--select"],
    ["a.lis", "--no-such-option"],
])
def test_what_typer_refuses_the_lean_parser_does_not_accept(args: list[str]) -> None:
    assert typer_params(args) is None
    assert parse_lint_args(args) is None


_NAMES = [name for o in LINT_OPTIONS for name in o.names]
_VALUES = st.sampled_from(["0", "1", "-1", "7", "x", "json", "text", "sarif", "R", "R005,M", "a.lis", "-", "",
                           "--fix", "=", "01"])
_TOKEN = st.one_of(st.sampled_from(_NAMES), _VALUES, st.builds(lambda n, v: f"{n}={v}", st.sampled_from(_NAMES),
                                                               _VALUES), st.just("--"))


@settings(max_examples=300, deadline=None)
@given(st.lists(_TOKEN, max_size=8))
def test_whatever_the_lean_parser_accepts_typer_reads_the_same(args: list[str]) -> None:
    lean = parse_lint_args(args)
    if lean is not None:
        assert typer_params(args) == lean, args

"""Tables at any width of 80 columns or more never cut a number."""

from __future__ import annotations

import re

import pytest

from conftest import FIXTURES, zero_cli

ANSI = re.compile(r"\x1b\[[0-9;]*m")


@pytest.mark.slow
@pytest.mark.parametrize("columns", [80, 100, 120])
def test_limits_never_cut_a_number(columns: int) -> None:
    run = zero_cli("limits", "--machine", str(FIXTURES / "machine" / "listen" / "hochlauf.lis"),
                   env={"COLUMNS": str(columns), "FORCE_COLOR": "1"})
    text = ANSI.sub("", run.stdout)
    assert "…" not in text
    plain = zero_cli("limits", "--machine", str(FIXTURES / "machine" / "listen" / "hochlauf.lis")).stdout
    numbers = set(re.findall(r"-?[0-9]+\.[0-9]{4}", plain))
    assert numbers and numbers <= set(re.findall(r"-?[0-9]+\.[0-9]{4}", text))


@pytest.mark.slow
@pytest.mark.parametrize("columns", [80, 110, 120])
def test_diff_never_cuts_a_value(columns: int, tmp_path: object) -> None:
    run = zero_cli("diff", str(FIXTURES / "diff" / "base.lis"), str(FIXTURES / "diff" / "changed.lis"),
                   env={"COLUMNS": str(columns), "FORCE_COLOR": "1"})
    text = ANSI.sub("", run.stdout)
    assert "…" not in text
    for value in ("110000", "+1.0000", "-40.0000", "12500"):
        assert value in text, (columns, value)

"""Every --help, as people read it: plain text, placeholders in words, nothing eaten (snapshots)."""

from __future__ import annotations

import pytest

from conftest import FIXTURES, zero_cli

COMMANDS = ["", "lint", "convert", "diff", "show", "explain", "schema", "limits", "format", "config", "rule", "param",
            "server"]


@pytest.mark.slow
@pytest.mark.parametrize("command", COMMANDS)
def test_help_snapshot(command: str, request: pytest.FixtureRequest) -> None:
    run = zero_cli(*([command] if command else []), "--help", env={"COLUMNS": "100", "NO_COLOR": "1"})
    assert run.code == 0
    text = run.stdout
    assert "<bool>" not in text and "<list[str]>" not in text.split("Options:", 1)[-1]
    snapshot = FIXTURES / "help" / f"{command or 'zero'}.txt"
    if request.config.getoption("--update-golden"):
        snapshot.write_text(text, encoding="utf-8")
    assert text == snapshot.read_text(encoding="utf-8")


def test_brackets_in_help_text_survive() -> None:
    run = zero_cli("config", "--help", env={"COLUMNS": "100"})
    assert "[tool.zero]" in run.stdout
    lint = zero_cli("lint", "--help", env={"COLUMNS": "100"}).stdout
    assert "default: all" in lint and "--select CODES" in lint and "-j, --jobs N" in lint

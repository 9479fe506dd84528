"""Every --help, as people read it, pinned at 80 columns: plain text, placeholders in words
(PATH, FILE, CODE), no Python types (``<list[Path]>``, ``<str>``) and no ``{A}`` in the usage
line, whatever typer/click version is installed (the help is written by zero.cli.app)."""

from __future__ import annotations

import re

import pytest
import typer.main

from conftest import FIXTURES, zero_cli
from zero.cli.app import app

COMMANDS = ["", "lint", "convert", "diff", "show", "explain", "schema", "limits", "report", "format", "config", "rule",
            "param", "server"]
TERMINAL = {"COLUMNS": "80", "NO_COLOR": "1", "TERM": "dumb"}
# what typer 0.29 printed: `PATH... <list[Path]>`, `<str>`, `<path>`, `{FILE...}...`, `{A}`, `[x>=0]`
LEAKS = re.compile(r"<(list\[|str>|path>|int>|bool>|float>|Path>)|\{[A-Z|.]+\}|\[x>=")


def _help(command: str, env: dict[str, str]) -> str:
    run = zero_cli(*([command] if command else []), "--help", env=env)
    assert run.code == 0, run.stderr
    return run.stdout


@pytest.mark.slow
@pytest.mark.parametrize("command", COMMANDS)
def test_help_snapshot(command: str, request: pytest.FixtureRequest) -> None:
    text = _help(command, TERMINAL)
    long = [line for line in text.splitlines() if len(line) > 80]
    assert not long, long
    assert not LEAKS.search(text), LEAKS.search(text)
    assert text.startswith(f"Usage: zero {command}".rstrip() + " [OPTIONS]")
    snapshot = FIXTURES / "help" / f"{command or 'zero'}.txt"
    if request.config.getoption("--update-golden"):
        snapshot.write_text(text, encoding="utf-8")
    assert text == snapshot.read_text(encoding="utf-8")


def test_every_command_is_pinned() -> None:
    group = typer.main.get_command(app)
    assert sorted(group.commands) == sorted(c for c in COMMANDS if c)  # type: ignore[attr-defined]


@pytest.mark.slow
def test_help_is_the_same_on_a_wide_terminal_and_follows_a_narrow_one() -> None:
    wide = _help("lint", {**TERMINAL, "COLUMNS": "200"})
    assert wide == (FIXTURES / "help" / "lint.txt").read_text(encoding="utf-8")
    narrow = _help("lint", {**TERMINAL, "COLUMNS": "60"})
    assert max(len(line) for line in narrow.splitlines()) <= 60
    assert " ".join(narrow.split()) == " ".join(wide.split())  # the same words, wrapped narrower


def test_brackets_in_help_text_survive() -> None:
    run = zero_cli("config", "--help", env=TERMINAL)
    assert "[tool.zero]" in run.stdout
    lint = zero_cli("lint", "--help", env=TERMINAL).stdout
    assert "default: all" in lint and "--select CODES" in lint and "-j, --jobs N" in lint
    assert "Usage: zero lint [OPTIONS] [PATH]..." in lint
    assert "[default: text; env var: ZERO_OUTPUT_FORMAT]" in " ".join(lint.split())


@pytest.mark.parametrize(("args", "message"), [
    (["lint", "a.lis", "--output-format", "xml"],
     "Invalid value for '--output-format': 'xml' is not one of text, full, concise, grouped, json, json-lines, "
     "github, gitlab, azure, junit, sarif, rdjson, pylint"),
    (["lint", "a.lis", "-j", "-1"], "Invalid value for '--jobs' / '-j': '-1' is not a whole number of at least 0"),
    (["lint", "a.lis", "--jobs", "many"], "'many' is not a whole number of at least 0"),
    (["convert", "a.lis", "--to", "foo"], "Invalid value for '--to': 'foo' is not one of lis, yaml, toml, json, xml"),
    (["diff", "a.lis", "b.lis", "--output-format", "jsn"], "'jsn' is not one of text, json, csv (did you mean json?)"),
    (["diff"], "Missing argument 'A'"),
])
def test_usage_errors_are_plain(args: list[str], message: str) -> None:
    run = zero_cli(*args, env=TERMINAL)
    assert run.code == 2
    assert message in run.stderr
    assert "Value error" not in run.stderr and "Input should" not in run.stderr
    assert not LEAKS.search(run.stderr), run.stderr
    assert run.stderr.startswith(f"zero {args[0]}: ") and run.stderr.endswith(f"; see 'zero {args[0]} --help'\n")
    assert len(run.stderr.splitlines()) == 1  # one line (issue 35), not click's Usage / Try / blank / Error

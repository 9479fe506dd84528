"""The common options (issue 39 A): every command that reads lists takes `--config`, `--isolated`,
`--param-desc` and `--kernel`, declared once (zero.cli.options.COMMON_OPTIONS), and honours them as
`zero lint` does. On the old main only lint, format and config had `--config`/`--isolated`, so
`zero report` showed a finding `zero lint --config ci.toml` hides, and show, explain, diff, limits
and convert could not be told which configuration to use."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli
from zero.cli.options import COMMON_OPTIONS, LINT_OPTIONS

pytestmark = pytest.mark.slow

LIST_COMMANDS = ("lint", "format", "show", "explain", "diff", "limits", "convert", "report", "config")
BROKEN = 'param-desc = "missing/CncParaDesc.xml"\n[machine]\nstartup = "listen/hochlauf.lis"\n'
GOOD = '[machine]\nstartup = "listen/hochlauf.lis"\n'
COMMANDS = [
    ("show", "listen/achse_x.lis"),
    ("show", "--machine", "listen/hochlauf.lis"),
    ("explain", "kenngr.swe_pos"),
    ("diff", "listen/achse_x.lis", "listen/achse_y.lis"),
    ("limits",),
    ("convert", "listen/achse_x.lis"),
    ("format", "--check", "listen/achse_x.lis"),
    ("report",),
]


def _machine(tmp_path: Path) -> Path:
    root = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine", root, ignore=shutil.ignore_patterns("*.json"))
    return root


def test_the_common_options_are_declared_once_and_lint_takes_them_from_there() -> None:
    assert [o.dest for o in COMMON_OPTIONS] == ["config", "isolated", "param_desc", "kernel"]
    assert all(any(o is c for o in LINT_OPTIONS) for c in COMMON_OPTIONS)


@pytest.mark.parametrize("command", LIST_COMMANDS)
def test_every_command_that_reads_lists_offers_them(command: str) -> None:
    run = zero_cli(command, "--help", env={"COLUMNS": "80"})
    flags = set(re.findall(r"--[a-z-]+", run.stdout))
    assert {"--config", "--isolated", "--param-desc", "--kernel"} <= flags, run.stdout


@pytest.mark.parametrize("command", COMMANDS, ids=" ".join)
def test_each_command_honours_config_and_isolated(tmp_path: Path, command: tuple[str, ...]) -> None:
    root = _machine(tmp_path)
    (root / "zero.toml").write_text(BROKEN)  # the configuration found: its catalogue cannot be read
    (root / "ci.toml").write_text(GOOD)
    found = zero_cli(*command, cwd=root)
    assert found.code == 2 and "CncParaDesc.xml" in found.stderr, found
    given = zero_cli(*command, "--config", "ci.toml", cwd=root)  # this one, for every file
    assert given.code in (0, 1), given
    if command[0] in ("limits", "explain", "report"):  # the machine comes from the configuration only
        isolated = zero_cli(*command, "--isolated", cwd=root)
        assert isolated.code == 2 and "--machine" in isolated.stderr, isolated
    else:
        isolated = zero_cli(*command, "--isolated", cwd=root)
        assert isolated.code in (0, 1), isolated


def test_report_hides_what_lint_config_hides(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    (root / "ci.toml").write_text('[tool.zero]\nignore = ["X005"]\n'
                                  '[tool.zero.machine]\nstartup = "listen/hochlauf.lis"\n')
    linted = zero_cli("lint", "--config", "ci.toml", "--machine", "listen/hochlauf.lis", "--output-format", "concise",
                      cwd=root)
    assert " X005 " not in linted.stdout and " X004 " in linted.stdout, linted
    plain = zero_cli("report", "--machine", "listen/hochlauf.lis", cwd=root)
    assert plain.code == 0 and 'class="finding" id="finding-' in plain.stdout and 'data-code="X005"' in plain.stdout
    report = zero_cli("report", "--config", "ci.toml", cwd=root)
    assert report.code == 0, report
    shown = set(re.findall(r'<li class="finding" id="finding-\d+" data-code="(\w+)"', report.stdout))
    assert "X004" in shown and "X005" not in shown, shown


def test_the_kernel_release_reaches_every_command(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    bad = zero_cli("show", "listen/achse_x.lis", "--kernel", "not-a-release", cwd=root)
    assert bad.code == 2 and "kernel" in bad.stderr, bad
    config = zero_cli("config", "--kernel", "V3.1.3079", "listen", cwd=root)
    assert 'kernel = "V3.1.3079"' in config.stdout, config

"""``zero diff --fleet`` on the lean path (no typer, no rich: issue 40, a warm fleet's start-up) gives
what the typer command line gives, and leaves everything else to it."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES
from zero.cli.options import parse_fleet_args

TYPER = "import sys; from zero.cli.app import main; sys.argv[0] = 'zero'; main()"
LEAN = "import sys; from zero.cli.lean import main; sys.argv[0] = 'zero'; main()"


def _fleet(tmp_path: Path) -> tuple[str, str]:
    golden = tmp_path / "golden"
    shutil.copytree(FIXTURES / "machine-clean", golden)
    for i in range(3):
        shutil.copytree(FIXTURES / "machine-clean" / "listen", tmp_path / "fleet" / f"m{i:02d}" / "listen")
    axis = next((tmp_path / "fleet" / "m01" / "listen").glob("achse_x*.lis"))
    text = axis.read_text(encoding="latin-1").replace("\nEnde", "\nkenngr.swe_pos 16000000\nEnde", 1)
    axis.write_text(text, encoding="latin-1")
    return str(golden / "listen" / "hochlauf.lis"), str(tmp_path / "fleet")


@pytest.mark.parametrize("options", [[], ["--output-format", "json"], ["--output-format", "csv", "-j", "1"],
                                     ["--isolated", "--jobs", "1"]])
def test_the_lean_path_gives_what_typer_gives(tmp_path: Path, options: list[str]) -> None:
    golden, fleet = _fleet(tmp_path)
    args = ["diff", "--fleet", golden, fleet, "--no-cache", *options]
    assert parse_fleet_args(args[1:]) is not None
    got = [subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, timeout=120,
                          cwd=tmp_path)
           for code in (LEAN, TYPER)]
    assert got[0].returncode == got[1].returncode == 1
    assert got[0].stdout == got[1].stdout and "swe_pos" in got[0].stdout
    assert got[0].stderr == got[1].stderr


def test_anything_else_is_typer_s() -> None:
    ok = ["--fleet", "g.lis", "m"]
    assert parse_fleet_args(ok) == {"golden": "g.lis", "machines": ["m"], "output_format": "text", "jobs": None,
                                    "no_cache": False, "config": [], "isolated": False, "param_desc": None}
    for args in (["--fleet", "g.lis"], ["m"], [*ok, "--help"], [*ok, "--output-format", "yaml"], [*ok, "-j", "x"],
                 [*ok, "--fleet", "h.lis"], [*ok, "--kernel", "V3"], [*ok, "--strict"], ["--fleet=g.lis", "m"],
                 [*ok, "--config"], [*ok, "--"], ["--fleet", "-", "m"], [*ok, "-j", "-1"]):
        assert parse_fleet_args(args) is None, args

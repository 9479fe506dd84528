"""The language server runs for hours: it gets Python's own cycle-collector thresholds back, not the
raised ones of the short commands (zero.cli.GC_THRESHOLDS), under which cycles would never be freed."""

from __future__ import annotations

import gc
import subprocess
import sys

import pytest
from typer.testing import CliRunner

import zero.server.lsp as lsp
from zero.cli import GC_THRESHOLDS, PYTHON_GC_THRESHOLDS
from zero.cli.app import app


def test_the_server_runs_with_pythons_thresholds(monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[tuple[int, ...]] = []
    monkeypatch.setattr(lsp, "serve", lambda *_args: seen.append(gc.get_threshold()))
    before = gc.get_threshold()
    try:
        result = CliRunner().invoke(app, ["server"])
    finally:
        gc.set_threshold(*before)
    assert result.exit_code == 0, result.output
    assert seen == [PYTHON_GC_THRESHOLDS]
    assert PYTHON_GC_THRESHOLDS != GC_THRESHOLDS


def test_pythons_thresholds_are_read_before_the_console_script_raises_them() -> None:
    code = ("import gc; d = gc.get_threshold(); import sys; sys.argv = ['zero', '--version']\n"
            "import zero.cli.lean as lean, zero.cli as c\n"
            "assert c.PYTHON_GC_THRESHOLDS == d, (c.PYTHON_GC_THRESHOLDS, d)\n"
            "print('ok')")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=False)
    assert run.stdout.strip() == "ok", run.stderr

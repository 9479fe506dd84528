"""A report of many files is written as the results come (text, json, concise, github) and keeps
none of them: it must say exactly what the report written from kept results says. An
``--output-file`` report keeps them, so it is the reference."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES


def _zero(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "NO_COLOR": "1"}
    return subprocess.run([sys.executable, "-m", "zero", *args], capture_output=True, text=True, timeout=120,
                          cwd=cwd, env=env, check=False)


@pytest.fixture(scope="module")
def tree(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The rule fixtures twice over (more files than one process takes alone), and a file that
    cannot be read (F001: exit 2 however the report is written)."""
    root = tmp_path_factory.mktemp("many")
    for copy in ("a", "b"):
        shutil.copytree(FIXTURES / "rules", root / copy)
    (root / "a" / "broken.lis").symlink_to(root / "nowhere.lis")
    return root


@pytest.mark.parametrize("jobs", ["1", "2"])
@pytest.mark.parametrize("fmt", ["text", "json", "concise", "github"])
def test_streamed_report_is_the_kept_report(tree: Path, fmt: str, jobs: str, tmp_path: Path) -> None:
    files = sorted(tree.rglob("*.lis"))
    assert len(files) >= 128  # -j 2 runs two processes from 64 files on
    streamed = _zero("lint", "--output-format", fmt, "-j", jobs, ".", cwd=tree)
    kept = _zero("lint", "--output-format", fmt, "-j", jobs, "--output-file", str(tmp_path / "r"), ".", cwd=tree)
    assert streamed.returncode == kept.returncode == 2  # the broken link
    assert streamed.stdout == (tmp_path / "r").read_text(encoding="utf-8")
    assert streamed.stderr == kept.stderr and "R001" in streamed.stdout  # the summary; the findings


def test_run_lint_streams_only_when_asked(tree: Path) -> None:
    """With ``stream`` the results are an iterator made as it is read; without, a list."""
    from zero.catalog.registry import load_registry
    from zero.engine.commands import Echo, LintRequest, run_lint

    registry = load_registry()
    echo = Echo(out=lambda _t: None, err=lambda _t: None, out_bytes=lambda _b: None)

    def run(stream: bool) -> object:
        return run_lint(LintRequest([str(tree / "a")], jobs=1, stream=stream), lambda _d: registry, echo,
                        lambda: b"").results

    lazy, kept = run(True), run(False)
    assert isinstance(kept, list) and not isinstance(lazy, list)
    assert [(r.path, r.diagnostics) for r in lazy] == [(r.path, r.diagnostics) for r in kept]  # type: ignore[attr-defined]


def test_the_command_line_knows_which_formats_stream() -> None:
    """The lean command line names them without importing the renderers (start-up)."""
    from zero.output import OUTPUT_FORMATS, STREAMED_FORMATS
    from zero.output.formats import RENDERERS, STREAMED

    assert set(STREAMED_FORMATS) == {"text", "full", *STREAMED}  # full: the text report
    assert set(OUTPUT_FORMATS) == {"text", "full", *RENDERERS}  # the formats are named once, in zero.output

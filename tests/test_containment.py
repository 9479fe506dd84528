"""Contained and bounded (issue 23): what a received repository, configuration or list can make
zero do. Each case broke a promise of the README's "Files: what zero guarantees" on the old main;
hostile inputs are made here, never committed."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import zero_cli

pytestmark = pytest.mark.slow
GIT = shutil.which("git")


@pytest.mark.skipif(GIT is None, reason="git is not installed")
def test_linting_an_untrusted_checkout_runs_none_of_its_code(tmp_path: Path) -> None:
    """README: "zero lint DIR runs nothing a repository configures": `core.fsmonitor` names a
    program that `git ls-files` runs; zero asks git with it switched off."""
    repo = tmp_path / "checkout"
    repo.mkdir()
    env = {**os.environ, "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1"}

    def git(*args: str) -> None:
        assert GIT is not None
        subprocess.run([GIT, *args], cwd=repo, env=env, check=True, capture_output=True)

    git("init", "-q")
    (repo / "a.lis").write_text("np_grp[1].achse[0].versch x\nEnde\n")
    (repo / "ignored.lis").write_text("np_grp[1].achse[0].versch x\nEnde\n")
    (repo / ".gitignore").write_text("ignored.lis\n")
    git("add", "a.lis", ".gitignore")
    git("-c", "user.email=t@example.invalid", "-c", "user.name=t", "commit", "-qm", "x")
    marker = tmp_path / "ran"
    hook = tmp_path / "hook.sh"
    hook.write_text(f"#!/bin/sh\ntouch {marker}\necho 0\n")
    hook.chmod(0o755)
    git("config", "core.fsmonitor", str(hook))
    git("config", "core.hooksPath", str(tmp_path))
    run = zero_cli("lint", str(repo), "--output-format", "concise", env=env)
    assert not marker.exists(), "zero ran a program the repository configured"
    assert "a.lis" in run.stdout and "ignored.lis" not in run.stdout  # .gitignore still applies

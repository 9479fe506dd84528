"""The pre-commit hook, run by the real pre-commit against this checkout."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT

PRE_COMMIT = shutil.which("pre-commit", path=str(Path(sys.executable).parent)) or shutil.which("pre-commit")


@pytest.mark.slow
@pytest.mark.skipif(PRE_COMMIT is None or shutil.which("git") is None,
                    reason="pre-commit or git not installed (pip install -e '.[test]')")
def test_hook_fails_on_the_bad_list_and_passes_the_good_one(tmp_path: Path) -> None:
    assert PRE_COMMIT is not None
    env = {**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@example.invalid",
           "GIT_COMMITTER_NAME": "t", "GIT_COMMITTER_EMAIL": "t@example.invalid",
           "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1", "NO_COLOR": "1",
           "PRE_COMMIT_HOME": str(tmp_path / "cache")}
    repo = tmp_path / "machine"
    repo.mkdir()

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(list(args), cwd=repo, env=env, capture_output=True, text=True, check=False,
                              timeout=600)

    run("git", "init", "-q")
    (repo / "good.lis").write_bytes((FIXTURES / "rules" / "M006" / "pass.lis").read_bytes())
    (repo / "bad.lis").write_bytes((FIXTURES / "seed" / "nullp_3achsen.lis").read_bytes())
    (repo / "notes.txt").write_text("not a list\n")
    run("git", "add", ".")
    both = run(PRE_COMMIT, "try-repo", str(ROOT), "zero-lint", "--all-files", "--verbose")
    assert both.returncode == 1, both.stdout + both.stderr
    assert "bad.lis:19:20: S004 error whitespace inside the key" in both.stdout
    assert "notes.txt" not in both.stdout
    # pre-commit names the files explicitly: an exclude in zero's configuration still applies
    (repo / "zero.toml").write_text('exclude = ["bad.lis"]\n')
    run("git", "add", ".")
    excluded = run(PRE_COMMIT, "try-repo", str(ROOT), "zero-lint", "--all-files", "--verbose")
    assert excluded.returncode == 0, excluded.stdout + excluded.stderr
    (repo / "zero.toml").unlink()
    run("git", "rm", "-q", "--cached", "bad.lis", "zero.toml")
    (repo / "bad.lis").unlink()
    good = run(PRE_COMMIT, "try-repo", str(ROOT), "zero-lint", "--all-files", "--verbose")
    assert good.returncode == 0, good.stdout + good.stderr
    assert "Passed" in good.stdout
    # the format hook rewrites a list that is not in canonical layout, then passes
    (repo / "good.lis").write_text("g53_verfuegbar 1\nEnde\n")
    run("git", "add", ".")
    fmt = run(PRE_COMMIT, "try-repo", str(ROOT), "zero-format", "--all-files")
    assert fmt.returncode == 1 and "files were modified by this hook" in fmt.stdout
    assert (repo / "good.lis").read_text() == "g53_verfuegbar".ljust(54) + "1\nEnde\n"


def _yaml_blocks(path: Path) -> list[str]:
    import re

    return re.findall(r"```yaml\n(.*?)```", path.read_text(encoding="utf-8"), re.S)


@pytest.mark.slow
@pytest.mark.skipif(PRE_COMMIT is None or shutil.which("git") is None,
                    reason="pre-commit or git not installed (pip install -e '.[test]')")
@pytest.mark.parametrize("page", ["README.md", "docs/ci.md"])
def test_the_documented_pre_commit_configuration_works_as_written(page: str, tmp_path: Path) -> None:
    """The README's and the CI page's .pre-commit-config.yaml, copied as written into a machine
    repository, with zero installed as the Quick start installs it: the hook fails the commit on
    the faulty list and passes once it is gone (issue 35: it named https://example.invalid/zero)."""
    assert PRE_COMMIT is not None
    config = next(b for b in _yaml_blocks(ROOT / page) if ".pre-commit-config.yaml" in b)
    assert "example.invalid" not in config
    bin_dir = str(Path(sys.executable).parent)  # where `pip install -e .` put the zero command
    env = {**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@example.invalid",
           "GIT_COMMITTER_NAME": "t", "GIT_COMMITTER_EMAIL": "t@example.invalid",
           "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1", "NO_COLOR": "1",
           "PRE_COMMIT_HOME": str(tmp_path / "cache"), "PATH": bin_dir + os.pathsep + os.environ.get("PATH", "")}
    repo = tmp_path / "machine"
    repo.mkdir()

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(list(args), cwd=repo, env=env, capture_output=True, text=True, check=False,
                              timeout=600)

    run("git", "init", "-q")
    (repo / ".pre-commit-config.yaml").write_text(config, encoding="utf-8")
    (repo / "bad.lis").write_bytes((FIXTURES / "rules" / "R001" / "fail.lis").read_bytes())  # R001: an error
    (repo / "notes.txt").write_text("not a list\n")
    run("git", "add", ".")
    failed = run(PRE_COMMIT, "run", "--all-files")
    assert failed.returncode == 1, failed.stdout + failed.stderr
    assert "bad.lis:3:1: R001 error" in failed.stdout and "notes.txt" not in failed.stdout
    run("git", "rm", "-q", "--cached", "bad.lis")
    (repo / "bad.lis").unlink()
    (repo / "good.lis").write_bytes((FIXTURES / "rules" / "M006" / "pass.lis").read_bytes())
    run("git", "add", ".")
    passed = run(PRE_COMMIT, "run", "zero-lint", "--all-files")
    assert passed.returncode == 0, passed.stdout + passed.stderr
    assert "zero lint" in passed.stdout and "Passed" in passed.stdout

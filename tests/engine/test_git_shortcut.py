"""A walk outside any repository does not start git (:func:`zero.engine.git.may_be_in_repository`),
and says what git would: no ignore rules, no note."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from zero.engine import git as zgit

GIT = shutil.which("git")


def test_no_repository_above_starts_no_git(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "m").mkdir()
    if zgit.may_be_in_repository(tmp_path / "m"):
        pytest.skip("the temporary folder lies in a repository")

    def refuse(*args: object, **kwargs: object) -> None:
        raise AssertionError("git started")

    monkeypatch.setattr(zgit, "run", refuse)
    assert zgit.visible_files(tmp_path / "m") == zgit.Visible(None)


@pytest.mark.skipif(GIT is None, reason="no git")
@pytest.mark.parametrize("layout", ["work tree", "bare", "inside bare", "gitfile"])
def test_a_repository_above_is_asked(tmp_path: Path, layout: str) -> None:
    if zgit.may_be_in_repository(tmp_path):
        pytest.skip("the temporary folder lies in a repository")
    assert GIT is not None
    repo = tmp_path / "r"
    if layout == "gitfile":
        subprocess.run([GIT, "init", "-q", "--separate-git-dir", str(tmp_path / "store"), str(repo)], check=True)
    else:
        subprocess.run([GIT, "init", "-q", *(["--bare"] if layout != "work tree" else []), str(repo)], check=True)
    folder = repo / "objects" if layout == "inside bare" else repo
    (folder / "sub").mkdir(exist_ok=True)
    assert zgit.may_be_in_repository(folder / "sub")
    assert not zgit.may_be_in_repository(tmp_path / "elsewhere")
    seen = zgit.visible_files(folder / "sub")
    assert (seen.files is not None) == (layout in ("work tree", "gitfile"))

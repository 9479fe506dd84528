"""A machine's reading resolves each list's folder once (machine.model._Realpaths): its answers are
``os.path.realpath``'s for every kind of path containment must judge (links to files and folders,
links out of the tree, dangling links, loops, ``.`` and ``..``, missing files, relative paths)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from zero.machine.model import _Realpaths


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    root = tmp_path / "m"
    (root / "listen" / "SoE").mkdir(parents=True)
    (tmp_path / "outside").mkdir()
    (tmp_path / "outside" / "secret.lis").write_text("x\n")
    for name in ("hochlauf.lis", "achsmds1.lis", "SoE/achsmds2.lis"):
        (root / "listen" / name).write_text("x\n")
    links = {
        "listen/to_file.lis": "achsmds1.lis",
        "listen/out.lis": "../../outside/secret.lis",
        "listen/dir_link": "SoE",
        "listen/out_dir": str(tmp_path / "outside"),
        "listen/dangling.lis": "nowhere.lis",
        "listen/loop_a": "loop_b",
        "listen/loop_b": "loop_a",
        "listen/chain.lis": "to_file.lis",
    }
    for name, target in links.items():
        os.symlink(target, root / name)
    return root


PATHS = [
    "listen/hochlauf.lis", "listen/achsmds1.lis", "listen/SoE/achsmds2.lis", "listen/to_file.lis",
    "listen/out.lis", "listen/dir_link/achsmds2.lis", "listen/out_dir/secret.lis", "listen/dangling.lis",
    "listen/loop_a", "listen/loop_a/x.lis", "listen/chain.lis", "listen/missing.lis", "listen/missing/x.lis",
    "listen/./achsmds1.lis", "listen/SoE/../achsmds1.lis", "listen/dir_link/../achsmds1.lis",
    "listen//achsmds1.lis", "listen/", "listen/..", "listen/.", "listen/out_dir/../m/listen/hochlauf.lis",
]


@pytest.mark.parametrize("relative", [False, True])
def test_every_answer_is_realpaths(tree: Path, relative: bool, monkeypatch: pytest.MonkeyPatch) -> None:
    if relative:
        monkeypatch.chdir(tree)
    resolve = _Realpaths()
    for raw in PATHS * 2:  # the second round answers from what the first resolved
        path = raw if relative else str(tree / raw)
        assert resolve(path) == os.path.realpath(path), raw
    assert resolve("/") == "/"


def test_a_folder_is_resolved_once_for_its_lists(tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    calls: list[str] = []
    real = os.path.realpath

    def counted(path: str) -> str:
        calls.append(path)
        return real(path)

    monkeypatch.setattr(os.path, "realpath", counted)
    resolve = _Realpaths()
    for name in ("hochlauf.lis", "achsmds1.lis", "SoE/achsmds2.lis", "to_file.lis"):
        resolve(str(tree / "listen" / name))
    assert len(calls) == 2  # the tree's top once, and the one link (to_file.lis) whole

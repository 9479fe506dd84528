"""The cache on the command line (issue 40): on by default for ``zero lint`` and ``zero diff --fleet``,
in ``.zero_cache/`` with its own ``.gitignore``, off with ``--no-cache`` or ``ZERO_NO_CACHE=1``, the
same report in every format with and without it, safe when two runs share it."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import zero_cli
from zero.output import OUTPUT_FORMATS

ROOT = Path(__file__).resolve().parent.parent.parent
MACHINE = ROOT / "fixtures" / "machine"
CLEAN = {"ZERO_NO_CACHE": "", "ZERO_CACHE_DIR": ""}


def settle(root: Path) -> None:
    old = time.time() - 60
    for d, _, files in os.walk(root):
        for name in files:
            os.utime(os.path.join(d, name), (old, old))
        os.utime(d, (old, old))


@pytest.fixture()
def lists(tmp_path: Path) -> Path:
    folder = tmp_path / "lists"
    shutil.copytree(MACHINE / "listen", folder)
    (folder / "extra.lis").write_bytes(b"kopf.achs_nr 1\nantr_simu.mode 1\nkenngr.swe_pos 1e99\nEnde\n")
    settle(folder)
    return folder


def test_lint_keeps_its_results_in_zero_cache_with_its_own_gitignore(lists: Path, tmp_path: Path) -> None:
    first = zero_cli("lint", "--output-format", "json", str(lists), cwd=tmp_path, env=CLEAN)
    folder = tmp_path / ".zero_cache"
    assert (folder / ".gitignore").read_text() == "# Automatically created by zero.\n*\n"
    assert (folder / "CACHEDIR.TAG").is_file()
    kept = [p for p in folder.rglob("*") if p.is_file() and p.parent != folder and not p.name.startswith("run-")]
    assert len(kept) == len(list(lists.iterdir()))
    again = zero_cli("lint", "--output-format", "json", str(lists), cwd=tmp_path, env=CLEAN)
    assert (again.code, again.out) == (first.code, first.out)


def test_no_cache_and_zero_no_cache(lists: Path, tmp_path: Path) -> None:
    zero_cli("lint", "--no-cache", str(lists), cwd=tmp_path, env=CLEAN)
    zero_cli("lint", str(lists), cwd=tmp_path, env={**CLEAN, "ZERO_NO_CACHE": "1"})
    zero_cli("diff", "--no-cache", "--fleet", str(lists / "hochlauf.lis"), str(lists / "hochlauf.lis"), cwd=tmp_path,
             env=CLEAN)
    assert not (tmp_path / ".zero_cache").exists()
    assert "--no-cache" in zero_cli("lint", "--help", env=CLEAN).stdout
    zero_cli("lint", str(lists), cwd=tmp_path, env={**CLEAN, "ZERO_CACHE_DIR": str(tmp_path / "elsewhere")})
    assert (tmp_path / "elsewhere" / ".gitignore").is_file() and not (tmp_path / ".zero_cache").exists()


@pytest.mark.parametrize("fmt", OUTPUT_FORMATS)
def test_every_format_is_the_same_from_the_cache(lists: Path, tmp_path: Path, fmt: str) -> None:
    for named in ([str(lists)], [str(lists / "extra.lis")]):  # many files, and one (its whole document)
        cold = zero_cli("lint", "--output-format", fmt, *named, cwd=tmp_path, env=CLEAN)
        warm = zero_cli("lint", "--output-format", fmt, *named, cwd=tmp_path, env=CLEAN)
        off = zero_cli("lint", "--no-cache", "--output-format", fmt, *named, cwd=tmp_path, env=CLEAN)
        assert cold.code == warm.code == off.code
        assert cold.out == warm.out == off.out, fmt
        assert cold.stderr == warm.stderr == off.stderr


def test_the_corpus_gives_the_same_json_with_and_without_the_cache(corpus: Path, tmp_path: Path) -> None:
    cold = zero_cli("lint", "--output-format", "json", str(corpus), cwd=tmp_path, env=CLEAN, timeout=300)
    warm = zero_cli("lint", "--output-format", "json", str(corpus), cwd=tmp_path, env=CLEAN, timeout=300)
    off = zero_cli("lint", "--no-cache", "--output-format", "json", str(corpus), cwd=tmp_path, env=CLEAN,
                   timeout=300)
    assert cold.out == warm.out == off.out and cold.code == warm.code == off.code
    assert any((tmp_path / ".zero_cache").rglob("*/*"))


def test_two_runs_at_once_share_the_cache(lists: Path, tmp_path: Path) -> None:
    """Two processes fill one empty cache at the same time: each reports what a run without the cache
    does, and what they leave is read back whole."""
    expected = zero_cli("lint", "--no-cache", "--output-format", "json", str(lists), cwd=tmp_path, env=CLEAN).out
    env = {**os.environ, **CLEAN}
    command = [sys.executable, "-m", "zero", "lint", "--output-format", "json", "-j", "1", str(lists)]
    for _ in range(3):
        shutil.rmtree(tmp_path / ".zero_cache", ignore_errors=True)
        runs = [subprocess.Popen(command, cwd=tmp_path, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
                for _ in range(2)]
        outs = [p.communicate(timeout=120) for p in runs]
        assert [o for o, _ in outs] == [expected, expected], [e for _, e in outs]
        assert all(b"Traceback" not in e for _, e in outs)
    again = zero_cli("lint", "--output-format", "json", str(lists), cwd=tmp_path, env=CLEAN)
    assert again.out == expected
    assert not [p for p in (tmp_path / ".zero_cache").rglob("*.tmp")]


def test_the_same_fleet_again_gives_the_same_report(tmp_path: Path) -> None:
    golden = tmp_path / "gold" / "listen"
    shutil.copytree(MACHINE / "listen", golden)
    for n in range(2):
        shutil.copytree(MACHINE / "listen", tmp_path / "fleet" / f"m{n}" / "listen")
    axis = tmp_path / "fleet" / "m1" / "listen" / "achse_x.lis"
    axis.write_text(axis.read_text().replace("kopf.achs_nr", "kenngr.vb_max 1234\nkopf.achs_nr", 1))
    settle(tmp_path)
    args = ("diff", "--fleet", str(golden / "hochlauf.lis"), str(tmp_path / "fleet"), "--output-format", "json")
    cold = zero_cli(*args, cwd=tmp_path, env=CLEAN)
    assert (tmp_path / ".zero_cache" / ".gitignore").is_file()
    warm = zero_cli(*args, cwd=tmp_path, env=CLEAN)
    off = zero_cli(*args, "--no-cache", cwd=tmp_path, env=CLEAN)
    assert cold.code == warm.code == off.code == 1
    assert cold.out == warm.out == off.out


def test_standard_input_and_fixes_are_never_kept(lists: Path, tmp_path: Path) -> None:
    data = (lists / "extra.lis").read_bytes()
    zero_cli("lint", "--stdin-filename", str(lists / "extra.lis"), "-", stdin=data, cwd=tmp_path, env=CLEAN)
    zero_cli("lint", "--diff", str(lists / "extra.lis"), cwd=tmp_path, env=CLEAN)
    zero_cli("lint", "--fix", str(lists / "extra.lis"), cwd=tmp_path, env=CLEAN)
    zero_cli("lint", "--add-noqa", str(lists / "extra.lis"), cwd=tmp_path, env=CLEAN)
    assert not (tmp_path / ".zero_cache").exists()

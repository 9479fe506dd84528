"""A run's index (zero.engine.cache.LintCache): the same files again are known by their stat, not read;
any change of the stat (size, modification time, change time, inode) reads the file again, and a
change the stat cannot show (within a tick of a coarse clock) is never recorded (the racy rule)."""

from __future__ import annotations

import os
import time
from pathlib import Path
from typing import Any

import pytest

import zero.engine.cache as cache_module
from conftest import count_lints
from zero.catalog.registry import Registry, load_registry
from zero.engine.commands import Echo, LintRequest, run_lint
from zero.engine.lint import LintOptions

LIST = b"kopf.achs_nr 1\nantr_simu.mode 1\nunknown_key 1\nkenngr.swe_pos 1e99\nEnde\n"
SAME_SIZE = b"kopf.achs_nr 2\nantr_simu.mode 1\nunknown_kez 1\nkenngr.swe_pos 1e99\nEnde\n"


class Run:
    """``zero lint`` with the cache on: which files were linted, and which were read by the cache."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch, folder: Path) -> None:
        self.linted: list[str] = []
        self.read: list[str] = []
        self.registries: dict[Path | None, Registry] = {}
        read = cache_module.read_file

        def counting_read(path: Any, limit: int | None = None) -> bytes:
            self.read.append(str(path))
            return read(path, limit)

        count_lints(monkeypatch, lambda path: self.linted.append(path))
        monkeypatch.setattr(cache_module, "read_file", counting_read)
        monkeypatch.setenv("ZERO_CACHE_DIR", str(folder))
        monkeypatch.delenv("ZERO_NO_CACHE", raising=False)
        # the files change just before each run here: their change time counts as settled
        monkeypatch.setattr(cache_module, "INDEX_RACY_NS", -10 * 10**9)

    def registry(self, desc: Path | None) -> Registry:
        if desc not in self.registries:
            self.registries[desc] = load_registry(desc)
        return self.registries[desc]

    def __call__(self, *paths: Path, **request: Any) -> list[dict[str, object]]:
        self.linted, self.read = [], []
        echo = Echo(out=lambda _t: None, err=lambda _t: None, out_bytes=lambda _b: None)
        run = run_lint(LintRequest([str(p) for p in paths], cache=True, **request), self.registry, echo, bytes)
        return [d.to_json() for r in run.results for d in r.diagnostics]


def old(path: Path, when: float | None = None) -> None:
    t = time.time() - 60 if when is None else when
    os.utime(path, (t, t))


@pytest.fixture()
def run(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Run:
    return Run(monkeypatch, tmp_path / "cache")


@pytest.fixture()
def lists(tmp_path: Path) -> Path:
    folder = tmp_path / "lists"
    folder.mkdir()
    for n in range(3):
        (folder / f"m{n}.lis").write_bytes(f"# machine {n}\n".encode() + LIST)  # not twins: each is linted
        old(folder / f"m{n}.lis")
    return folder


def index_files(tmp_path: Path) -> list[Path]:
    return [p for p in (tmp_path / "cache").rglob("run-*") if p.is_file()]


def test_the_same_files_again_are_not_read(run: Run, lists: Path, tmp_path: Path) -> None:
    first = run(lists)
    assert len(run.linted) == 3 and len(index_files(tmp_path)) == 1
    written = index_files(tmp_path)[0].stat().st_mtime_ns
    assert run(lists) == first and run.linted == [] and run.read == []
    assert index_files(tmp_path)[0].stat().st_mtime_ns == written  # nothing changed: not written again


def test_a_change_the_size_and_time_hide_is_seen_by_the_change_time(run: Run, lists: Path) -> None:
    run(lists)
    target = lists / "m1.lis"
    st = os.stat(target)
    time.sleep(0.05)  # past a tick of the coarsest clock Linux keeps change times with
    target.write_bytes(b"# machine 1\n" + SAME_SIZE)
    os.utime(target, ns=(st.st_atime_ns, st.st_mtime_ns))  # the same size and modification time
    assert os.stat(target).st_size == st.st_size and os.stat(target).st_ctime_ns != st.st_ctime_ns
    changed = run(lists)
    assert run.read == [str(target)] and run.linted == [str(target)]
    assert run(lists) == changed and run.read == []


def test_a_file_replaced_by_another_is_read(run: Run, lists: Path) -> None:
    first = run(lists)
    target = lists / "m2.lis"
    other = lists / "m2.new"
    other.write_bytes(SAME_SIZE)
    st = os.stat(target)
    os.utime(other, ns=(st.st_atime_ns, st.st_mtime_ns))
    os.replace(other, target)  # a new inode, of the same size and times
    changed = run(lists)
    assert run.read == [str(target)] and run.linted == [str(target)] and changed != first


def test_settings_changed_miss_whatever_the_index_says(run: Run, lists: Path) -> None:
    first = run(lists)
    narrowed = run(lists, select=("R001",))
    assert run.read == [] and len(run.linted) == 3 and narrowed != first  # known by stat, linted anew
    assert run(lists) == first and run.linted == []  # the entries of the first settings are still there


@pytest.mark.parametrize("changed", ["options", "catalogue", "machine"])
def test_a_record_whose_settings_part_differs_is_not_answered_by_the_index(
        run: Run, lists: Path, monkeypatch: pytest.MonkeyPatch, changed: str) -> None:
    """The index answers a file from its record only where today's settings give the part of the
    entry's name it recorded: each of the three differing alone makes the file's entry name anew."""
    run(lists)
    at = ["options", "catalogue", "machine"].index(changed)
    part = cache_module.LintCache._part

    def other(self: cache_module.LintCache, path: Any) -> tuple[Any, ...]:
        got = list(part(self, path))
        got[at] = ("other",) if at == 1 else "other"
        return tuple(got)

    monkeypatch.setattr(cache_module.LintCache, "_part", other)
    run(lists)
    assert run.read == [] and len(run.linted) == 3  # known by stat, but no entry holds the new names
    if changed != "machine":  # (a machine key with no machine behind it is never kept)
        run(lists)
        assert run.read == [] and run.linted == []  # recorded with the new part


def test_a_torn_index_is_a_miss_and_the_entries_answer(run: Run, lists: Path, tmp_path: Path) -> None:
    first = run(lists)
    (index,) = index_files(tmp_path)
    data = index.read_bytes()
    for broken in (data[: len(data) // 2], b"", b"garbage", data[:-1] + bytes([data[-1] ^ 1])):
        index.write_bytes(broken)
        assert run(lists) == first and run.linted == [] and len(run.read) == 3
        assert run(lists) == first and run.read == []  # written whole again


def test_a_file_changed_too_recently_is_not_in_the_index(run: Run, lists: Path, tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache_module, "INDEX_RACY_NS", cache_module.RACY_NS)  # the real rule: changed now
    run(lists)
    assert index_files(tmp_path) == []  # every file's change time is of now
    run(lists)
    assert len(run.read) == 3 and run.linted == []  # read, and answered by the entries


def test_a_file_over_the_size_limit_is_read_and_refused(run: Run, lists: Path, monkeypatch: pytest.MonkeyPatch
                                                        ) -> None:
    run(lists)
    monkeypatch.setenv("ZERO_MAX_FILE_SIZE", "10")
    refused = run(lists)
    assert {d["code"] for d in refused} == {"F001"} and len(run.read) == 3


def test_another_file_list_has_its_own_index(run: Run, lists: Path, tmp_path: Path) -> None:
    run(lists)
    run(lists / "m0.lis")
    assert len(index_files(tmp_path)) == 2
    run(lists)
    assert run.read == [] and run.linted == []


def test_the_entry_name_is_the_fingerprint_of_its_parts(lists: Path, tmp_path: Path,
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    """The name is made without walking its parts: the same as :func:`fingerprint` of them."""
    from zero.engine.project import Project

    monkeypatch.setenv("ZERO_CACHE_DIR", str(tmp_path / "cache"))
    project = Project(load_registry_cached, cli=LintOptions(select=("R0",)))
    cache = cache_module.open_lint_cache(project)
    assert cache is not None
    path = lists / "m0.lis"
    key, machine = cache.key(path, "ab" * 16)
    parts = (cache_module.generation(), "lint", str(path), "ab" * 16, cache_module.fingerprint(project.options(path)),
             cache_module.catalogue_id(project.param_desc(path)), machine)
    assert key == cache_module.fingerprint(parts) and machine is None
    assert cache.key(path, LIST) == (cache_module.fingerprint((*parts[:3], cache_module.digest(LIST).hex(),
                                                                *parts[4:])), None)


def load_registry_cached(desc: Path | None) -> Registry:
    return load_registry(desc)

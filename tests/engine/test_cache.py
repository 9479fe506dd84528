"""The cache of ``zero lint`` and ``zero diff --fleet`` (zero.engine.cache, issue 40).

Every key the cache depends on is changed here one at a time: the cache then misses (the file is
linted again) and the findings are those of a run without the cache. A run of files that changed
too recently to tell by their time is not kept (it is linted again next time), so the tests set the
files' times into the past (:func:`settle`) wherever they want a run kept.
"""

from __future__ import annotations

import json
import os
import shutil
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

import zero.engine.cache as cache_module
import zero.engine.parallel as parallel
from conftest import count_lints
from zero.catalog.registry import Registry, load_registry
from zero.diagnostics import Diagnostic, Edit, Fix, Related, Severity, Span
from zero.engine.cache import (
    FOLDER,
    Store,
    fingerprint,
    generation,
    pack_result,
    unpack_result,
)
from zero.engine.commands import Echo, LintRequest, run_lint
from zero.engine.fleet import fleet_drift
from zero.engine.lint import LintOptions, LintResult
from zero.engine.project import Project
from zero.lists.model import Document
from zero.output.fleet import fleet_json

ROOT = Path(__file__).resolve().parent.parent.parent
MACHINE = ROOT / "fixtures" / "machine"
LIST = "kopf.achs_nr 1\nantr_simu.mode 1\nunknown_key\xe4 1\nkenngr.zero_test_count 1.5\nEnde\n"
# A parameter description that knows `kenngr.zero_test_count` (as an integer: 1.5 is a finding)
DESC = """<?xml version="1.0" encoding="utf-8"?>
<Parameters xmlns="https://www.isg-stuttgart.de/kernel/CncParaDesc">
  <Parameter><Id>P-AXIS-09999</Id><Name>kenngr.zero_test_count</Name><Type>{type}</Type>
    <DefaultValue>0</DefaultValue></Parameter>
</Parameters>
"""


def settle(*paths: Path) -> None:
    """Every file and folder below ``paths`` last changed a minute ago (what the cache keeps)."""
    old = time.time() - 60
    for p in paths:
        for d, _, files in os.walk(p) if p.is_dir() else [(str(p.parent), [], [p.name])]:
            for name in files:
                os.utime(os.path.join(d, name), (old, old))
            if p.is_dir():
                os.utime(d, (old, old))


class Linter:
    """``zero lint`` as the library runs it with the cache on, counting the files it really lints."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch, folder: Path) -> None:
        self.linted: list[str] = []
        self.registries: dict[Path | None, Registry] = {}
        count_lints(monkeypatch, lambda path: self.linted.append(path))
        monkeypatch.setenv("ZERO_CACHE_DIR", str(folder))
        monkeypatch.delenv("ZERO_NO_CACHE", raising=False)

    def registry(self, desc: Path | None) -> Registry:
        if desc not in self.registries:
            self.registries[desc] = load_registry(desc)
        return self.registries[desc]

    def __call__(self, *paths: Path, cache: bool = True, **request: Any) -> list[dict[str, object]]:
        """The findings as ``--output-format json`` has them; :attr:`linted` says which files were linted."""
        self.linted = []
        echo = Echo(out=lambda _t: None, err=lambda _t: None, out_bytes=lambda _b: None)
        run = run_lint(LintRequest([str(p) for p in paths], cache=cache, **request), self.registry, echo, bytes)
        return [d.to_json() for r in run.results for d in r.diagnostics]


@pytest.fixture(params=["by content", "by stat"])
def linter(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Linter:
    """Each test twice: files known by their content (no file's stat is ever settled enough for the
    run's index), and known by their stat from the run's index (as they are when they changed well
    before the run: here they changed just now, but their change time counts as settled)."""
    monkeypatch.setattr(cache_module, "INDEX_RACY_NS", -10 * 10**9 if request.param == "by stat" else 10**18)
    return Linter(monkeypatch, tmp_path / "cache")


@pytest.fixture()
def axis(tmp_path: Path) -> Path:
    path = tmp_path / "project" / "achse.lis"
    path.parent.mkdir()
    path.write_bytes(LIST.encode("cp1252"))
    settle(path)
    return path


def test_a_second_run_is_answered_from_the_cache_with_the_same_findings(linter: Linter, axis: Path,
                                                                       tmp_path: Path) -> None:
    first = linter(axis)
    assert linter.linted == [str(axis)] and first
    again = linter(axis)
    assert linter.linted == [] and again == first
    assert linter(axis, cache=False) == first and linter.linted == [str(axis)]
    folder = tmp_path / "cache"
    assert (folder / ".gitignore").read_text() == "# Automatically created by zero.\n*\n"
    assert (folder / "CACHEDIR.TAG").read_bytes().startswith(b"Signature: 8a477f597d28d172789f06886806bc55\n")


def test_the_content_is_a_key(linter: Linter, axis: Path) -> None:
    first = linter(axis)
    axis.write_bytes(axis.read_bytes().replace(b"antr_simu.mode 1\n", b""))
    settle(axis)
    changed = linter(axis)
    assert linter.linted == [str(axis)] and changed != first and changed == linter(axis, cache=False)


def test_the_path_is_a_key(linter: Linter, axis: Path) -> None:
    first = linter(axis)
    other = axis.with_name("achse2.lis")
    shutil.copy2(axis, other)
    settle(other)
    moved = linter(other)
    assert linter.linted == [str(other)] and [d["path"] for d in moved] == [str(other)] * len(first)


def _config(axis: Path, text: str) -> None:
    (axis.parent / "zero.toml").write_text(text, encoding="utf-8")


# Each setting changed on its own: (name, configuration before, configuration after, command line after)
SETTINGS: list[tuple[str, str, str, dict[str, Any]]] = [
    ("select", "", "", {"select": ("R001",)}),
    ("select in the configuration", "", 'select = ["S"]\n', {}),
    ("extend-select", 'select = ["S"]\n', 'select = ["S"]\n', {"extend_select": ("R",)}),
    ("ignore", "", "", {"ignore": ("S001",)}),
    ("severity", "", '[severity]\nR001 = "info"\n', {}),
    ("per-file-ignores", "", '[per-file-ignores]\n"achse.lis" = ["R001"]\n', {}),
    ("kind", "", "", {"kind": "zero"}),
    ("kind in the configuration", "", '[kind]\n"achse.lis" = "channel"\n', {}),
    ("encoding", "", '[encoding]\n"*.lis" = "cp850"\n', {}),
    ("kernel release", "", 'kernel = "V3.01.3074"\n', {}),
    ("kernel release on the command line", "", "", {"config": ('kernel = "V3.01.3074"',)}),
    ("ignore-noqa", "", "", {"ignore_noqa": True}),
]


@pytest.mark.parametrize(("before", "config", "request_"), [(b, c, r) for _, b, c, r in SETTINGS],
                         ids=[name for name, _, _, _ in SETTINGS])
def test_each_setting_is_a_key(linter: Linter, axis: Path, before: str, config: str, request_: dict[str, Any]) -> None:
    if request_.get("ignore_noqa"):
        axis.write_bytes(axis.read_bytes().replace(b"antr_simu.mode 1\n", b"antr_simu.mode 1  # noqa: R001\n"))
    _config(axis, before)
    settle(axis.parent)
    first = linter(axis)
    assert linter(axis) == first and linter.linted == []
    _config(axis, config)
    settle(axis.parent)
    after = linter(axis, **request_)
    assert linter.linted == [str(axis)], "a changed setting must not be answered from the cache"
    assert after != first
    assert after == linter(axis, cache=False, **request_)
    assert linter(axis, **request_) == after and linter.linted == []  # and kept under the new settings


def test_the_catalogue_is_a_key(linter: Linter, axis: Path, tmp_path: Path) -> None:
    desc = tmp_path / "CncParaDesc.xml"
    desc.write_text(DESC.format(type="SGN32"), encoding="utf-8")
    builtin = linter(axis)
    own = linter(axis, param_desc=desc)
    assert linter.linted == [str(axis)] and own != builtin
    assert linter(axis, param_desc=desc) == own and linter.linted == []
    desc.write_text(DESC.format(type="REAL64"), encoding="utf-8")  # the description's content changed
    linter.registries.clear()
    changed = linter(axis, param_desc=desc)
    assert linter.linted == [str(axis)] and changed != own
    assert changed == linter(axis, cache=False, param_desc=desc)


def test_zero_itself_is_a_key(linter: Linter, axis: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    first = linter(axis)
    monkeypatch.setattr(cache_module, "_generation", ["another zero"])
    assert linter(axis) == first and linter.linted == [str(axis)]


def test_zero_s_version_and_source_make_the_generation(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    package = tmp_path / "zero"
    (package / "rules").mkdir(parents=True)
    rule = package / "rules" / "meaning.py"
    rule.write_text("CHECK = 1\n")
    (package / "__pycache__").mkdir()
    (package / "__pycache__" / "x.pyc").write_bytes(b"compiled")

    def made() -> str:
        monkeypatch.setattr(cache_module, "_generation", [])
        monkeypatch.setattr(cache_module, "__file__", str(package / "engine" / "cache.py"))
        return generation()

    first = made()
    assert made() == first
    (package / "__pycache__" / "x.pyc").write_bytes(b"compiled again")  # bytecode is not source
    assert made() == first
    rule.write_text("CHECK = 2\n")  # an edited rule
    os.utime(rule, ns=(1, 1))
    edited = made()
    assert edited != first
    monkeypatch.setattr(cache_module, "__version__", "9.9.9")
    assert made() != edited


def test_the_machine_s_lists_are_a_key(linter: Linter, tmp_path: Path) -> None:
    root = tmp_path / "project"
    shutil.copytree(MACHINE, root)
    (root / "zero.toml").write_text('[machine]\nstartup = "listen/hochlauf.lis"\n', encoding="utf-8")
    settle(root)
    axis = root / "listen" / "achse_y.lis"
    first = linter(axis)
    assert any(d["code"] == "X013" for d in first), first  # found across the machine's lists
    assert linter(axis) == first and linter.linted == []
    startup = root / "listen" / "hochlauf.lis"
    text = startup.read_text()  # the compensation list now feeds axis 2: X013 on it goes
    startup.write_text(text.replace("achs_kw_log_ax_nr[0]                                  9",
                                    "achs_kw_log_ax_nr[0]                                  2"))
    assert startup.read_text() != text
    settle(startup.parent)
    changed = linter(axis)
    assert linter.linted == [str(axis)], "another list of the machine changed"
    assert changed != first and changed == linter(axis, cache=False)
    assert linter(axis) == changed and linter.linted == []
    (root / "listen" / "achse_fehlt.lis").write_text("kopf.achs_nr 5\nEnde\n")  # a list that was missing
    settle(startup.parent)
    linter(axis)
    assert linter.linted == [str(axis)]


def test_a_list_changed_too_recently_to_tell_is_not_kept(linter: Linter, axis: Path) -> None:
    os.utime(axis)  # now: a change in this very tick would not change its time
    linter(axis)
    linter(axis)
    assert linter.linted == [str(axis)]


def test_no_cache_and_zero_no_cache_neither_read_nor_write(linter: Linter, axis: Path, tmp_path: Path,
                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    linter(axis, cache=False)
    assert not (tmp_path / "cache").exists()
    monkeypatch.setenv("ZERO_NO_CACHE", "1")
    linter(axis)
    assert not (tmp_path / "cache").exists()
    monkeypatch.setenv("ZERO_NO_CACHE", "0")  # as off as unset
    linter(axis)
    linter(axis)
    assert linter.linted == [] and (tmp_path / "cache").is_dir()
    monkeypatch.setenv("ZERO_NO_CACHE", "true")
    linter(axis)
    assert linter.linted == [str(axis)]


def test_a_run_that_fixes_or_writes_noqa_neither_reads_nor_writes_it(linter: Linter, axis: Path,
                                                                     tmp_path: Path) -> None:
    linter(axis, show_diff=True)
    linter(axis, add_noqa=True)
    assert not (tmp_path / "cache").exists()


def test_a_torn_or_garbage_entry_is_a_miss(linter: Linter, axis: Path, tmp_path: Path) -> None:
    """An entry torn or garbage, and with it the run's index (which holds the result too) where there
    is one (the index alone torn: test_cache_index.py)."""
    first = linter(axis)
    kept = [p for p in (tmp_path / "cache").rglob("*") if p.is_file() and p.parent.parent == tmp_path / "cache"]
    (entry,) = [p for p in kept if not p.name.startswith("run-")]
    index = [p for p in kept if p.name.startswith("run-")]
    assert len(index) == (1 if cache_module.INDEX_RACY_NS < 0 else 0)  # "by stat": the run's index
    data = entry.read_bytes()
    for broken in (data[: len(data) // 2], b"", b"garbage", data[:-1] + bytes([data[-1] ^ 1])):
        for p in (entry, *index):
            p.write_bytes(broken)
        assert linter(axis) == first and linter.linted == [str(axis)]
        assert linter(axis) == first and linter.linted == []  # written whole again


def test_an_unreadable_or_refused_file_is_never_kept(linter: Linter, tmp_path: Path) -> None:
    bad = tmp_path / "project" / "bad.xml"
    bad.parent.mkdir()
    bad.write_text("<AX_MDS><!DOCTYPE x>")
    settle(bad)
    refused = linter(bad)
    assert [d["code"] for d in refused] == ["S014"]
    linter(bad)
    assert linter.linted == [str(bad)]
    assert not list((tmp_path / "cache").rglob("*/*")) if (tmp_path / "cache").exists() else True


def test_a_folder_that_cannot_be_written_is_no_cache(linter: Linter, axis: Path, tmp_path: Path,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    blocked = tmp_path / "file"
    blocked.write_text("")
    monkeypatch.setenv("ZERO_CACHE_DIR", str(blocked / "cache"))
    first = linter(axis)
    assert linter(axis) == first and linter.linted == [str(axis)]


def test_the_folder_is_bounded(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache_module, "MAX_ENTRIES", 40)
    store = Store(tmp_path / "cache")
    for n in range(100):
        assert store.put(f"k{n:03d}", ("value", n))
        os.utime(store.path(f"k{n:03d}"), ns=(n * 10**9, n * 10**9))
    kept = sorted(p.name for p in Path(store.entries).iterdir())
    assert len(kept) <= 40 + 40 // 4  # pruned as it is written: at most a quarter beyond the bound
    assert kept[0] >= "k050" and kept[-1] == "k099"  # the oldest went first
    assert store.get("k099") == ("value", 99)
    for n in range(100, 105):
        store.put(f"k{n:03d}", ("value", n))
    store.prune()
    assert len(list(Path(store.entries).iterdir())) == 30
    monkeypatch.setattr(cache_module, "MAX_BYTES", 200)
    store.prune()
    assert sum(p.stat().st_size for p in Path(store.entries).iterdir()) <= 150


def test_older_generations_go(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for n in range(6):
        monkeypatch.setattr(cache_module, "_generation", [f"{n:020d}"])
        Store(tmp_path / "cache").put("k", n)
        time.sleep(0.01)
    left = sorted(p.name for p in (tmp_path / "cache").iterdir() if p.is_dir())
    assert left == [f"{n:020d}" for n in (2, 3, 4, 5)]


def test_a_stored_result_says_all_a_finding_says() -> None:
    edit = Edit(Span(2, 3, 2, 9), "new")
    d = Diagnostic("R005", Severity.WARNING, "a message", Span(2, 3, 3, 4), "a.lis", "P-AXIS-00001",
                   Fix("a fix", (edit, Edit(Span(3, 1, 3, 1), "x")), safe=False), "a hint",
                   (Related(Span(1, 1, 1, 5), "first here"), Related(Span(4, 1, 4, 2), "there", "b.lis")),
                   "P-ERR-1", "ignored", "https://example.org/page")
    doc = Document("a.lis", "cp1252", ["l1", "l2 ä", "l3", "l4"], ["\n"] * 4, [], bom=True, end_line=4)
    result = LintResult("a.lis", doc, "AXIS", [d], "a note")
    back = unpack_result(pack_result(result))
    assert back.diagnostics == [d]
    (b,) = back.diagnostics
    assert (b.hint, b.related, b.consequence, b.source, b.fix) == (d.hint, d.related, d.consequence, d.source, d.fix)
    assert (back.path, back.kind, back.note) == ("a.lis", "AXIS", "a note")
    assert [back.document.line_text(n) for n in (2, 3)] == ["l2 ä", "l3"]
    assert back.document.has_line(2) and back.document.has_line(3) and not back.document.has_line(1)
    assert (back.document.encoding, back.document.bom, back.document.end_line) == ("cp1252", True, 4)


def test_lists_of_equal_findings_pack_them_once_and_unpack_each_with_its_own_file() -> None:
    """Two files with the same findings pack one tuple of them (marshal then writes it once in an
    index); unpacked, each finding names its own file, a finding about another file keeps that file,
    and a related place without a file (this file) stays without one."""
    import marshal

    def result(path: str) -> LintResult:
        doc = Document(path, "ascii", ["l1", "l2"], ["\n"] * 2, [], end_line=2)
        return LintResult(path, doc, "AXIS", [
            Diagnostic("R001", Severity.ERROR, "same", Span(1, 1, 1, 3), path, related=(
                Related(Span(2, 1, 2, 2), "here"), Related(Span(2, 1, 2, 2), "own", path),
                Related(Span(1, 1, 1, 1), "other", "x.lis"))),
            Diagnostic("X001", Severity.WARNING, "elsewhere", Span(2, 1, 2, 2), "other.lis")])

    a, b = result("m1/a.lis"), result("m2/a.lis")
    shared: dict[Any, Any] = {}
    packed_a, packed_b = pack_result(a, shared), pack_result(b, shared)
    assert packed_a[4] is packed_b[4] and packed_a[3][4] is packed_b[3][4]
    assert pack_result(a)[4] is not pack_result(b)[4]  # without a run's memo: each its own
    assert len(marshal.dumps((packed_a, packed_b), 4)) < 1.5 * len(marshal.dumps(packed_a, 4))
    made: dict[int, tuple[object, Any]] = {}
    for original, packed in ((a, packed_a), (b, packed_b), (a, packed_a)):
        back = unpack_result(marshal.loads(marshal.dumps(packed, 4)), made)
        assert back.diagnostics == original.diagnostics
        assert [d.related for d in back.diagnostics] == [d.related for d in original.diagnostics]
    shared_a, shared_b = unpack_result(packed_a, made), unpack_result(packed_b, made)
    assert shared_a.diagnostics == a.diagnostics and shared_b.diagnostics == b.diagnostics
    assert shared_a.diagnostics[0].span is shared_b.diagnostics[0].span  # made once


def test_the_fingerprint_of_settings_is_deterministic() -> None:
    a = LintOptions(select=("R",), severity={"R001": Severity.INFO, "M002": Severity.ERROR})
    b = LintOptions(select=("R",), severity={"M002": Severity.ERROR, "R001": Severity.INFO})
    assert fingerprint(a) == fingerprint(b)
    assert fingerprint(a) != fingerprint(LintOptions(select=("R",), severity={"R001": Severity.WARNING}))
    assert fingerprint(LintOptions(kernel="V3")) != fingerprint(LintOptions())
    with pytest.raises(TypeError):
        fingerprint(object())


# ----------------------------------------------------------------------------- fleets


@pytest.fixture()
def fleet(tmp_path: Path) -> tuple[Path, Path]:
    golden = tmp_path / "gold" / "listen"
    shutil.copytree(MACHINE / "listen", golden)
    for n in range(3):
        shutil.copytree(MACHINE / "listen", tmp_path / "fleet" / f"m{n}" / "listen")
    axis = tmp_path / "fleet" / "m1" / "listen" / "achse_x.lis"
    axis.write_text(axis.read_text().replace("kopf.achs_nr", "kenngr.vb_max 1234\nkopf.achs_nr", 1))
    settle(tmp_path / "gold", tmp_path / "fleet")
    return golden / "hochlauf.lis", tmp_path / "fleet"


def _drift(golden: Path, fleet: Path, cache: bool = True, jobs: int = 1) -> tuple[dict[str, Any], int]:
    """The fleet's drift as JSON, and how many machines were read."""
    registry = load_registry()
    read: list[str] = []
    project = Project(lambda _d: registry, isolated=True)
    real = project.machine

    def counting(*args: Any, **kwargs: Any) -> Any:
        read.append(str(kwargs.get("startup") or args))
        return real(*args, **kwargs)

    project.machine = counting  # type: ignore[method-assign]
    return fleet_json(fleet_drift(golden, [fleet], project, jobs=jobs, cache=cache)), len(read)


def test_the_same_fleet_again_reads_no_machine(fleet: tuple[Path, Path], tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ZERO_CACHE_DIR", str(tmp_path / "cache"))
    golden, machines = fleet
    first, read = _drift(golden, machines)
    assert read == 4 and first["parameters"]
    again, read = _drift(golden, machines)
    assert read == 0 and again == first
    assert _drift(golden, machines, cache=False)[0] == first


def test_a_changed_machine_is_compared_again(fleet: tuple[Path, Path], tmp_path: Path,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ZERO_CACHE_DIR", str(tmp_path / "cache"))
    golden, machines = fleet
    first, _ = _drift(golden, machines)
    axis = machines / "m2" / "listen" / "achse_y.lis"
    axis.write_text(axis.read_text().replace("kopf.achs_nr", "kenngr.vb_max 999\nkopf.achs_nr", 1))
    settle(axis.parent)
    changed, read = _drift(golden, machines)
    assert read == 2, "only the changed machine is read again (and the golden machine to compare it with)"
    assert changed != first and changed == _drift(golden, machines, cache=False)[0]


def test_a_changed_golden_machine_compares_every_machine_again(fleet: tuple[Path, Path], tmp_path: Path,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ZERO_CACHE_DIR", str(tmp_path / "cache"))
    golden, machines = fleet
    first, _ = _drift(golden, machines)
    axis = golden.parent / "achse_c.lis"
    axis.write_text(axis.read_text().replace("kopf.achs_nr", "kenngr.vb_max 777\nkopf.achs_nr", 1))
    settle(golden.parent)
    changed, read = _drift(golden, machines)
    assert read == 4 and changed != first and changed == _drift(golden, machines, cache=False)[0]


def test_a_fleet_in_two_processes_keeps_the_same_drift(fleet: tuple[Path, Path], tmp_path: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ZERO_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr("zero.engine.fleet.PARALLEL_MIN_MACHINES", 1)
    golden, machines = fleet
    first, _ = _drift(golden, machines, jobs=2)
    again, read = _drift(golden, machines, jobs=2)
    assert read == 0 and again == first == _drift(golden, machines, cache=False)[0]


def entries(folder: Path) -> Iterator[Path]:
    return (p for p in folder.rglob("*") if p.is_file() and p.parent != folder)


def test_an_unreadable_machine_is_not_kept(fleet: tuple[Path, Path], tmp_path: Path,
                                           monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ZERO_CACHE_DIR", str(tmp_path / "cache"))
    golden, machines = fleet
    (machines / "m0" / "listen" / "hochlauf.lis").write_bytes(b"\x00" * 10)
    settle(machines)
    first, _ = _drift(golden, machines)
    assert first["unreadable"], first
    assert len(list(entries(tmp_path / "cache"))) == 3  # the golden machine and the two readable ones
    assert json.dumps(_drift(golden, machines)[0]) == json.dumps(first)


def test_the_cache_folder_is_at_the_project_root(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from zero.engine.cache import cache_folder

    monkeypatch.delenv("ZERO_CACHE_DIR", raising=False)
    (tmp_path / "zero.toml").write_text("")
    (tmp_path / "sub").mkdir()
    monkeypatch.chdir(tmp_path / "sub")
    assert cache_folder(Project(load_registry)) == str(tmp_path / FOLDER)
    monkeypatch.setenv("ZERO_CACHE_DIR", "elsewhere")
    assert cache_folder(Project(load_registry)) == str(tmp_path / "sub" / "elsewhere")


def test_a_result_of_many_files_keeps_the_line_a_finding_ends_on_too() -> None:
    """As the cache keeps it: rdjson counts the end column in the bytes of the end line, so a report
    of many files (each result slimmed) says what a report of one file says."""
    d = Diagnostic("S001", Severity.ERROR, "m", Span(2, 1, 3, 4), "a.lis")
    doc = Document("a.lis", "utf-8", ["l1", "l2", "ä3", "l4"], ["\n"] * 4, [])
    slim = parallel._slim(LintResult("a.lis", doc, None, [d]))
    assert [slim.document.has_line(n) for n in (1, 2, 3, 4)] == [False, True, True, False]
    assert slim.document.line_text(3) == "ä3"


def test_fingerprints_tell_equal_values_of_other_types_apart() -> None:
    """1, 1.0 and True are one key of a dictionary; as settings they are three."""
    assert len({fingerprint(v) for v in (1, 1.0, True, "True", "1", (1,), None)}) == 7
    assert fingerprint(LintOptions(ignore_noqa=True)) != fingerprint(LintOptions(ignore_noqa=False))

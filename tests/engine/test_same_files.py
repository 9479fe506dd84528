"""Files of one run with the same bytes are linted once (zero.engine.parallel.SameFiles, issue 40).

A fleet's machines share most of their lists byte for byte. The first of such twins is linted;
the others get its findings with their own path. What decides a list's findings besides its bytes
(its options: configuration, command line, per-file ignores; its registry; the kind its name
suggests) is part of the key, so twins under other settings are linted each on its own. Every
test compares with each file linted alone (:func:`zero.engine.lint.lint_file`).
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

import zero.engine.parallel as parallel
from conftest import count_lints
from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic, Related, Severity, Span
from zero.engine.lint import LintOptions, LintResult, lint_file
from zero.engine.parallel import SameFiles, iter_lint_many
from zero.lists.model import Excerpt

AXIS = b"kopf.achs_nr 1\nkopf.achs_nr 2\nkenngr.swe_pos 1e99\nunknown_key 1\nEnde\n"
OTHER = b"kopf.achs_nr 3\nantr_simu.mode 7\nEnde\n"


def alone(files: list[Path], registry: Registry, options: Any = None) -> list[dict[str, object]]:
    """The findings of each file linted on its own, as ``--output-format json`` has them."""
    opts = (lambda _p: options) if not callable(options) else options
    return [d.to_json() for f in files for d in lint_file(f, registry, opts(f)).diagnostics]


def together(files: list[Path], registry: Registry, options: Any = None, jobs: int = 1) -> list[dict[str, object]]:
    return [d.to_json() for r in iter_lint_many(files, registry, options, jobs) for d in r.diagnostics]


class Counted:
    """Which files were really linted (not shared from a twin)."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch) -> None:
        self.linted: list[str] = []
        count_lints(monkeypatch, lambda path: self.linted.append(path))


@pytest.fixture()
def counted(monkeypatch: pytest.MonkeyPatch) -> Counted:
    return Counted(monkeypatch)


def fleet(root: Path, machines: int, lists: dict[str, bytes]) -> list[Path]:
    files = []
    for m in range(machines):
        for name, data in lists.items():
            f = root / f"m{m:03d}" / name
            f.parent.mkdir(parents=True, exist_ok=True)
            f.write_bytes(data)
            files.append(f)
    return files


@pytest.mark.parametrize("jobs", [1, 2])
def test_twins_are_linted_once_and_found_as_if_each_were_linted(tmp_path: Path, registry: Registry,
                                                               counted: Counted, jobs: int) -> None:
    files = fleet(tmp_path, 40, {"achse_x.lis": AXIS, "achse_y.lis": OTHER, "achse_z.lis": AXIS})  # 120 files
    expected = alone(files, registry)
    counted.linted = []
    assert together(files, registry, jobs=jobs) == expected
    assert counted.linted == [str(files[0]), str(files[1])]  # one of each content; the rest shared
    assert {d["path"] for d in expected} == {str(f) for f in files}  # every file has its own findings


def test_many_distinct_files_are_linted_across_processes_and_their_twins_shared(tmp_path: Path,
                                                                               registry: Registry) -> None:
    lists = {f"achse_{n}.lis": f"# axis {n}\n".encode() + (AXIS if n % 2 else OTHER) for n in range(70)}
    files = fleet(tmp_path, 2, lists)  # 70 contents, each twice: the 70 firsts are linted by two workers
    assert together(files, registry, jobs=2) == alone(files, registry)


def test_a_file_changed_after_it_was_hashed_is_no_ones_twin(tmp_path: Path, registry: Registry, counted: Counted,
                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """Many files: the parent hashes them all first, then lints the first of each content again from
    the file. If that file changed in between, its findings are not its old twins'."""
    files = fleet(tmp_path, 70, {"achse_x.lis": AXIS})
    real = parallel._made

    def changing(todo: list[Path], *args: Any) -> Iterator[tuple[bytes | None, LintResult]]:
        files[0].write_bytes(OTHER)  # after the twins were told apart, before the first is linted
        return real(todo, *args)

    monkeypatch.setattr(parallel, "_made", changing)
    found = together(files, registry, jobs=2)
    assert found == alone(files, registry)  # files[0] now holds OTHER; the other 69 still AXIS
    assert len(counted.linted) == 70  # its twins were linted each (none could share a result now unknown)


def test_other_options_other_findings(tmp_path: Path, registry: Registry, counted: Counted) -> None:
    files = fleet(tmp_path, 3, {"achse_x.lis": AXIS})
    narrowed = LintOptions(select=("R0",))
    wide = LintOptions()

    def options(path: Path) -> LintOptions:
        return narrowed if path.parent.name == "m001" else wide

    assert together(files, registry, options) == alone(files, registry, options)
    assert counted.linted == [str(files[0]), str(files[1])]
    assert LintOptions(select=("R0",)) == narrowed  # equal options, but another object: not assumed the same
    fresh = [narrowed, LintOptions(select=("R0",)), narrowed]
    counted.linted = []
    together(files, registry, lambda p: fresh[int(p.parent.name[1:])])
    assert counted.linted == [str(files[0]), str(files[1])]


def test_the_name_that_breaks_a_kind_tie_is_part_of_the_key(tmp_path: Path, registry: Registry,
                                                            counted: Counted) -> None:
    """An empty list has no key to vote with: its kind is the one its name suggests."""
    empty = b"# nothing set\nEnde\n"
    files = fleet(tmp_path, 2, {"achsmds1.lis": empty, "werkz_d1.lis": empty, "notes.lis": empty})
    results = list(iter_lint_many(files, registry, jobs=1))
    assert [r.kind for r in results] == [lint_file(f, registry).kind for f in files]
    assert [r.kind for r in results[:3]] != [results[0].kind] * 3
    assert counted.linted == [str(f) for f in files[:3]]


def test_no_file_is_read_past_the_size_limit(tmp_path: Path, registry: Registry,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    files = fleet(tmp_path, 70, {"achse_x.lis": AXIS})
    monkeypatch.setenv("ZERO_MAX_FILE_SIZE", "10")
    for jobs in (1, 2):
        found = together(files, registry, jobs=jobs)
        assert {d["code"] for d in found} == {"F001"} and len(found) == 70


def test_a_big_file_is_linted_on_its_own(tmp_path: Path, registry: Registry, counted: Counted,
                                         monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(parallel, "SHARED_MAX_BYTES", 20)
    files = fleet(tmp_path, 3, {"achse_x.lis": AXIS})
    assert together(files, registry) == alone(files, registry)
    assert counted.linted == [str(f) for f in files]  # each linted by the run (`alone` is not counted)


def test_one_file_keeps_its_whole_document(tmp_path: Path, registry: Registry) -> None:
    (f,) = fleet(tmp_path, 1, {"achse_x.lis": AXIS})
    (result,) = iter_lint_many([f], registry)
    assert type(result.document) is not Excerpt and result.document.entries


def test_a_result_naming_its_file_is_not_shared() -> None:
    doc = Excerpt("a/x.lis", "latin-1", [], [], [], [], shown={1: "kopf.achs_nr 1"})

    def result(**fields: Any) -> LintResult:
        d = Diagnostic("R001", Severity.ERROR, fields.pop("message", "m"), Span(1, 1, 1, 2), "a/x.lis", **fields)
        return LintResult("a/x.lis", doc, "AXIS", [d])

    assert parallel._shareable(result())
    assert not parallel._shareable(result(message="the default list under a/x.lis"))
    assert not parallel._shareable(result(hint="see a/x.lis line 3"))
    assert not parallel._shareable(result(related=(Related(Span(2, 1, 2, 2), "there", "b/y.lis"),)))
    moved = parallel._moved(result(), "b/x.lis")
    assert moved.path == moved.document.path == moved.diagnostics[0].path == "b/x.lis"
    assert isinstance(moved.document, Excerpt) and moved.document.line_text(1) == "kopf.achs_nr 1"


def test_programs_structured_and_xml_files_are_not_keyed(tmp_path: Path, registry: Registry) -> None:
    for name, data in (("p.nc", b"N10 G01 X1\n"), ("a.yaml", b"kopf:\n  achs_nr: 1\n"),
                       ("a.lis", b"<?xml version='1.0'?><a/>")):
        (tmp_path / name).write_bytes(data)
        assert SameFiles.key(tmp_path / name, LintOptions(), registry) is None
    (tmp_path / "b.lis").write_bytes(AXIS)
    assert SameFiles.key(tmp_path / "b.lis", LintOptions(), registry) is not None


def test_the_corpus_twice_is_found_as_each_list_alone(tmp_path: Path, registry: Registry, corpus: Path) -> None:
    """Two machines holding every corpus list: the same findings as each list linted alone, in one
    process and in two."""
    source = corpus / "isg-sdk" / "listen"
    files: list[Path] = []
    for m in ("m0", "m1"):
        shutil.copytree(source, tmp_path / m)
        files += sorted(p for p in (tmp_path / m).rglob("*.lis"))
    files *= 2  # more than PARALLEL_MIN_FILES when the corpus is small
    expected = alone(files, registry)
    assert len(files) >= parallel.PARALLEL_MIN_FILES
    for jobs in (1, 2):
        assert json.dumps(together(files, registry, jobs=jobs)) == json.dumps(expected)

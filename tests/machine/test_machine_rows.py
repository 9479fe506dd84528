"""The machine model read from rows (issue 40): documented keys per row without building entries,
the entries of a list as :class:`~zero.catalog.rows.Rows`, ``diff_sides`` on them, and the
lists of a run shared by content (a fleet's machines are copies), each under its own path."""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import generated_lists
from zero.catalog.registry import Registry, load_registry
from zero.catalog.rows import Rows, own_entries, row_keys
from zero.catalog.values import ListValues, canonical_key
from zero.diff import DiffOptions, Side, diff_sides
from zero.engine.lint import lint_machine
from zero.lists.model import Entry
from zero.lists.tokenizer import tokenize
from zero.machine.effective import entries_of, scope_values
from zero.machine.model import SHARED, ListFile, Machine, load_machine

# lines a fleet's lists hold beside the usual: an alias, indices with a leading zero (first or later),
# keys zero cannot read, a later line setting an element again
_ODD = st.sampled_from([
    "kenngr.homing_type 3", "kenngr.homing.homing_type 4", "np_grp[01].achse[2].versch 7",
    "np_grp[1].achse[02].versch 8", "np_grp[1].achse[2].versch 9", "wz[0].name x", "wz[00].name y",
    "syn_chk.fehler_pro_zeile 2", "syn_chk.errors_per_block 3", "a-b 5", "k[x] 1", "kenngr.swe_pos 1",
    "gruppe[0].achse[01].bezeichnung Q", "gruppe[0].achse[1].bezeichnung R", "x[123456789012345678901].y 1",
])


@pytest.fixture(autouse=True)
def _no_shared_lists() -> Iterator[None]:
    SHARED.clear()
    yield
    SHARED.clear()


def _old_own(values: ListValues) -> dict[str, Entry]:
    """What ``own_entries`` gave before it read rows: every entry, by its canonical key."""
    return {canonical_key(values.registry, values.kind, e): e for e in values.doc.entries}


def _same(rows: Rows, old: dict[str, Entry]) -> None:
    assert list(rows) == list(old)  # the same keys in the same order
    assert rows.texts == {k: e.value for k, e in old.items()}
    for k, e in old.items():
        assert rows[k] is e and rows.get(k) is e and k in rows  # the very entry, built on demand
    assert rows.get("no.such.key") is None and "no.such.key" not in rows
    with pytest.raises(KeyError):
        rows["no.such.key"]


@settings(max_examples=150, deadline=None)
@given(generated_lists(), st.lists(_ODD, max_size=8), st.sampled_from(["AXIS", "ZERO", "CHAN", "TOOL"]))
def test_row_keys_are_the_canonical_keys_of_the_entries(data: bytes, odd: list[str], kind: str) -> None:
    registry = _registry()
    text = "\n".join(odd).encode() + b"\n" + data if odd else data
    values = ListValues.of(tokenize(text, "t.lis"), registry, kind)
    keys = row_keys(values)
    assert keys == [canonical_key(registry, kind, e) for e in values.doc.entries]
    _same(own_entries(values), _old_own(values))


def test_every_corpus_list_gives_the_entries_it_gave(corpus: Path, registry: Registry) -> None:
    paths = sorted(p for p in corpus.rglob("*.lis") if p.is_file())
    assert len(paths) > 20
    for p in paths:
        values = ListValues.of(tokenize(p.read_bytes(), str(p)), registry, None)
        _same(own_entries(values), _old_own(values))


def _layers(registry: Registry) -> tuple[ListValues, ListValues]:
    base = ListValues.of(tokenize(b"kenngr.swe_pos 5\nkenngr.swe_neg -5\nkenngr.homing_type 1\n", "d.lis"),
                         registry, "AXIS")
    own = ListValues.of(tokenize(b"kenngr.swe_neg -7\nkopf.achs_nr 2\nkenngr.homing.homing_type 2\n", "a.lis"),
                        registry, "AXIS")
    own.base = base
    return base, own


def test_a_list_over_its_default_list(registry: Registry) -> None:
    base, own = _layers(registry)
    found: dict[int, Rows] = {}
    rows = entries_of(own, found)
    old = {**_old_own(base), **_old_own(own)}
    _same(rows, old)
    assert rows["kenngr.swe_pos"].line == 1 and rows["kenngr.swe_neg"].value == "-7"
    assert rows["kenngr.homing.homing_type"].value == "2"  # the alias of the default list is the key it stands for
    assert entries_of(own, found) is rows and found[id(base)] is entries_of(base, found)


def _sides(registry: Registry, a: bytes, b: bytes, kind: str) -> tuple[tuple[Side, Side], tuple[Side, Side]]:
    va = ListValues.of(tokenize(a, "a.lis"), registry, kind)
    vb = ListValues.of(tokenize(b, "b.lis"), registry, kind)
    rows = (Side("a.lis", kind, own_entries(va)), Side("b.lis", kind, own_entries(vb)))
    plain = (Side("a.lis", kind, _old_own(va)), Side("b.lis", kind, _old_own(vb)))
    return rows, plain


@settings(max_examples=100, deadline=None)
@given(generated_lists(), generated_lists(), st.lists(_ODD, max_size=4), st.booleans(), st.booleans())
def test_diff_sides_on_rows_is_diff_sides_on_entries(a: bytes, b: bytes, odd: list[str], strict: bool,
                                                     comments: bool) -> None:
    registry = _registry()
    b = "\n".join(odd).encode() + b"\n" + b
    options = DiffOptions(strict=strict, comments=comments)
    for kind in ("AXIS", "ZERO"):
        rows, plain = _sides(registry, a, b, kind)
        assert [c.to_json() for c in diff_sides(*rows, registry, options)] == \
            [c.to_json() for c in diff_sides(*plain, registry, options)]
        under = Side("u.lis", kind, own_entries(ListValues.of(tokenize(a, "u.lis"), registry, kind)))
        assert [c.to_json() for c in diff_sides(*rows, registry, options, under)] == \
            [c.to_json() for c in diff_sides(*plain, registry, options, under)]


def test_diff_sides_of_equal_rows_builds_no_entry(registry: Registry) -> None:
    text = b"kenngr.swe_pos 5\nkenngr.achs_typ 1\nkenngr.swe_neg -5\n"
    va, vb = (ListValues.of(tokenize(text, p), registry, "AXIS") for p in ("a.lis", "b.lis"))
    assert diff_sides(Side("a", "AXIS", own_entries(va)), Side("b", "AXIS", own_entries(vb)), registry) == []
    assert not va.doc.columns.objects and not vb.doc.columns.objects
    changed = ListValues.of(tokenize(text.replace(b"-5", b"-6"), "c.lis"), registry, "AXIS")
    (c,) = diff_sides(Side("a", "AXIS", own_entries(va)), Side("c", "AXIS", own_entries(changed)), registry)
    assert (c.key, c.old, c.new) == ("kenngr.swe_neg", "-5", "-6")
    assert set(changed.doc.columns.objects) == {1, 2}  # the axis type (for the unit), and the changed row


_REGISTRY: list[Registry] = []


def _registry() -> Registry:
    if not _REGISTRY:
        from conftest import builtin_registry

        _REGISTRY.append(builtin_registry())
    return _REGISTRY[0]


# ----------------------------------------------------------------------------- lists shared by content


def _machines(tmp_path: Path, corpus: Path, n: int = 2) -> list[Path]:
    out = []
    for i in range(n):
        shutil.copytree(corpus / "isg-sdk" / "listen", tmp_path / f"m{i}" / "listen")
        out.append(tmp_path / f"m{i}" / "listen" / "hochlauf.lis")
    return out


def _docs(m: Machine) -> dict[str, ListFile]:
    return {lf.key: lf for lf in m.lists}


def test_a_copy_of_a_machine_shares_the_reading_under_its_own_paths(tmp_path: Path, corpus: Path,
                                                                     registry: Registry) -> None:
    first, second = _machines(tmp_path, corpus)
    (second.parent / "achsmds2.lis").write_bytes((second.parent / "achsmds2.lis").read_bytes() + b"\n")
    m1, m2 = load_machine(first, registry), load_machine(second, registry)
    one, two = _docs(m1), _docs(m2)
    assert one.keys() == two.keys()
    shared = 0
    for key, lf1 in one.items():
        lf2 = two[key]
        d1, d2 = lf1.values.doc, lf2.values.doc
        assert d2 is not d1 and d2.path == str(lf2.path) and os.path.dirname(d2.path) == str(second.parent)
        if key == "achs_mds[1]":  # a byte more: read on its own
            assert d2.columns is not d1.columns
        elif key != "start-up":
            assert d2.columns is d1.columns  # read once
            shared += 1
        assert [e.value for e in d2.entries] == [e.value for e in d1.entries]
    assert shared >= 10
    # each machine's lists lie over its own default list
    assert m2.axis_lists[0].values.base is m2.defaults["AXIS"].values
    assert m1.axis_lists[0].values.base is m1.defaults["AXIS"].values
    # origins, and findings, name the machine's own files
    values = scope_values("axis 1", m2.axis_lists[0], with_defaults=False).values
    assert values and all(os.path.dirname(v.origin.path or "") == str(second.parent) for v in values)
    for lint in (lint_machine(m2, registry), lint_machine(load_machine(second, registry), registry)):
        paths = {d.path for r in lint for d in r.diagnostics}
        assert paths and all(str(second.parent) in p for p in paths)


def test_what_decides_a_reading_keeps_lists_apart(tmp_path: Path, corpus: Path, registry: Registry) -> None:
    first, second = _machines(tmp_path, corpus)
    m1 = load_machine(first, registry)
    axis = m1.axis_lists[0].values.doc
    assert load_machine(second, registry).axis_lists[0].values.doc.columns is axis.columns
    # the same bytes as another kind of list, another registry, another declared code page: read again
    shutil.copy(second.parent / "achsmds1.lis", second.parent / "hand_mds.lis")
    hand = load_machine(second, registry).singles["hand_mds"].values
    assert hand.kind == "MANU" and hand.doc.text == axis.text and hand.doc.columns is not axis.columns
    other = load_registry()
    assert other is not registry
    assert load_machine(second, other).axis_lists[0].values.doc.columns is not axis.columns
    latin = load_machine(second, registry, encoding=lambda _p: "cp1252")
    assert latin.axis_lists[0].values.doc.columns is not axis.columns


def test_the_lists_kept_are_bounded(tmp_path: Path, corpus: Path, registry: Registry,
                                    monkeypatch: pytest.MonkeyPatch) -> None:
    import zero.machine.model as model

    (first,) = _machines(tmp_path, corpus, 1)
    monkeypatch.setattr(model, "SHARED_LISTS", 3)
    load_machine(first, registry)
    assert len(SHARED.kept) == 3
    monkeypatch.setattr(model, "SHARED_TOTAL_CHARS", 1)
    SHARED.clear()
    load_machine(first, registry)
    assert len(SHARED.kept) == 1  # the last one only
    monkeypatch.setattr(model, "SHARED_MAX_CHARS", 0)
    SHARED.clear()
    load_machine(first, registry)
    assert not SHARED.kept and SHARED.chars == 0


def test_the_row_keys_kept_are_those_of_small_lists(registry: Registry) -> None:
    from zero.catalog import rows

    rows._keyed.clear()
    small = ListValues.of(tokenize(b"kenngr.swe_pos 5\n", "s.lis"), registry, "AXIS")
    big = ListValues.of(tokenize(b"".join(b"wz[%d].laenge 1\n" % i for i in range(rows._KEYED_ROWS + 1)),
                                 "t.lis"), registry, "TOOL")
    assert own_entries(small).texts is own_entries(small).texts  # worked out once
    assert own_entries(big).texts is not own_entries(big).texts  # a big list's keys are not kept
    assert len(rows._keyed) == 1

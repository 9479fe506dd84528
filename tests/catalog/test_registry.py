"""The registry is data: complete, consistent, and looked up by ID and by key."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest

from conftest import ROOT
from zero.catalog.ranges import parse_range
from zero.catalog.registry import BUILTIN_SOURCE, KINDS, Registry, build_registry, load_registry
from zero.catalog.values import default_number


def test_all_parameters_of_fourteen_kinds(registry: Registry) -> None:
    reg = registry
    assert len(reg) == 1766
    assert set(Counter(s.kind for s in reg.specs.values())) == set(KINDS)


def test_ids_are_well_formed_and_unique(registry: Registry) -> None:
    reg = registry
    for pid, spec in reg.specs.items():
        assert re.fullmatch(r"P-[A-Z]{4}-[0-9]{5}", pid) and spec.id == pid
        assert spec.kind == pid[2:6]


def test_stored_ranges_are_formal(registry: Registry) -> None:
    reg = registry
    for spec in reg.specs.values():
        if spec.range_text:
            assert parse_range(spec.range_text, spec.id) is not None, spec.id


def test_seed_defaults_pass_their_own_ranges(registry: Registry) -> None:
    reg = registry
    for spec in reg.specs.values():
        if "manual" not in spec.source or not spec.range_text:
            continue
        rng = reg.range_of(spec)
        d = default_number(spec)
        assert rng is not None and d is not None
        if rng.allowed is not None:
            assert d in rng.allowed, spec.id
        else:
            b = rng.evaluate(lambda pid, idx: default_number(reg.get(pid)))  # type: ignore[arg-type]
            assert b.contains(d), spec.id


@pytest.mark.parametrize(
    ("pid", "key", "typ", "default"),
    [
        ("P-ZERO-00001", "g53_verfuegbar", "BOOLEAN", "0"),
        ("P-ZERO-00002", "default_index", "UNS16", "0"),
        ("P-ZERO-00003", "np_grp[].achse[].versch", "SGN32", "0"),
        ("P-ZERO-00004", "np_grp[].achse[].inaktiv", "BOOLEAN", "0"),
        ("P-AXIS-00137", "handbetrieb.offsetgrenze_neg", "SGN32", "-1000000"),
        ("P-AXIS-00138", "handbetrieb.offsetgrenze_pos", "SGN32", "1000000"),
        ("P-AXIS-00177", "kenngr.swe_neg", "SGN32", "-100000000"),
        ("P-AXIS-00178", "kenngr.swe_pos", "SGN32", "100000000"),
        ("P-AXIS-00179", "kenngr.swe_toleranz", "UNS32", "1000"),
        ("P-AXIS-00554", "kenngr.swe_behaviour", "STRING", "ERROR"),
        ("P-AXIS-00705", "kenngr.swe_check", "SGN08", "-1"),
        ("P-CHAN-00489", "display_pcs_limits", "BOOLEAN", "0"),
        ("P-CHAN-00498", "range_check_prog_soft_limits", "BOOLEAN", "0"),
        ("P-MANU-00014", "move_limit_warning", "BOOLEAN", "0"),
    ],
)
def test_seed_parameters(registry: Registry, pid: str, key: str, typ: str, default: str) -> None:
    spec = registry.get(pid)
    assert spec is not None
    assert (spec.key, spec.type, spec.default) == (key, typ, default)
    assert spec.description and "seed" in spec.source


def test_machine_data_keywords_have_meanings(registry: Registry) -> None:
    reg = registry
    for n in ("00001", "00008", "00209", "00212", "00414"):
        spec = reg.get(f"P-AXIS-{n}")
        assert spec is not None and spec.description


def test_lookup_by_concrete_key(registry: Registry) -> None:
    from zero.lists.model import parse_key

    reg = registry
    key = parse_key("np_grp[5].achse[2].versch")
    assert key is not None
    spec = reg.by_pattern(key.pattern, "ZERO")
    assert spec is not None and spec.id == "P-ZERO-00003" and key.indices == (5, 2)
    assert spec.dims == (97, 32)


def test_same_key_in_two_kinds(registry: Registry) -> None:
    reg = registry
    axis = reg.by_pattern("kopf.achs_nr", "AXIS")
    comp = reg.by_pattern("kopf.achs_nr", "COMP")
    assert axis is not None and comp is not None and axis.id != comp.id


def test_kind_detection(registry: Registry) -> None:
    reg = registry
    assert reg.detect_kind(["np_grp[].achse[].versch", "g53_verfuegbar"]) == "ZERO"
    assert reg.detect_kind(["kopf.achs_nr", "kenngr.swe_pos"]) == "AXIS"
    assert reg.detect_kind(["kopf.achs_nr"], "achskw1.lis") == "COMP"
    assert reg.detect_kind([], "nullp_d1.lis") == "ZERO"


def test_did_you_mean(registry: Registry) -> None:
    reg = registry
    assert reg.suggest("kenngr.swe_pso", "AXIS") == ["kenngr.swe_pos"]
    assert reg.suggest("kenngr.homing_type", "AXIS") == ["kenngr.homing.homing_type"]


def test_no_vendor_description_texts_committed() -> None:
    tables = sorted((ROOT / "src" / "zero" / "catalog" / "data").glob("table*.py"))
    assert len(tables) == 1 + len(KINDS)  # the index, and each kind's rows
    for table in tables:
        data = table.read_text(encoding="utf-8")
        assert "ShortDescription" not in data and "vendor_text" not in data
        assert "Negative software limit switch" not in data


def test_param_desc_from_user_file(corpus: Path) -> None:
    reg = load_registry(corpus / "isg-sdk" / "meta-data" / "CncParaDesc.xml")
    assert len(reg) == 1766
    spec = reg.get("P-AXIS-00016")
    assert spec is not None and spec.description  # the vendor's text, read at run time
    # the seeds still apply on top
    swe = reg.get("P-AXIS-00705")
    assert swe is not None and swe.range_text == "-1, 0, 1"


def test_generated_table_matches_the_xml(corpus: Path, registry: Registry) -> None:
    """tools/gen_registry.py output is what is committed."""
    from zero.catalog.paramdesc import read_param_desc

    rows = read_param_desc(corpus / "isg-sdk" / "meta-data" / "CncParaDesc.xml")
    fresh = build_registry(rows, "test")
    built_in = registry
    assert fresh.specs == built_in.specs


def test_bad_param_desc(tmp_path: Path) -> None:
    from zero.errors import ZeroError

    bad = tmp_path / "x.xml"
    bad.write_text("<nope/>")
    with pytest.raises(ZeroError):
        load_registry(bad)
    bad.write_text("<<<")
    with pytest.raises(ZeroError):
        load_registry(bad)


def test_building_registries_leaves_the_built_in_tables_as_they_were() -> None:
    """The tables are module constants shared by every registry of a process (the server and the
    tests build many): building specs, linting and reporting must never change them."""
    import copy

    from zero.catalog.data.seeds import SEEDS
    from zero.catalog.data.table import ROWS
    from zero.engine.lint import lint_file

    rows, seeds = copy.deepcopy(ROWS), copy.deepcopy(SEEDS)
    for _ in range(2):
        reg = load_registry()
        for pid in reg.specs:  # every spec built, ranges parsed
            spec = reg.get(pid)
            assert spec is not None
            reg.range_of(spec)
        linted = [lint_file(path, reg) for path in sorted((ROOT / "fixtures" / "rules").rglob("*.lis"))]
        assert len(linted) > 50 and any(r.diagnostics for r in linted)
    assert rows == ROWS and seeds == SEEDS


def test_the_tables_written_index_is_the_one_the_registry_builds_of_its_rows() -> None:
    """data/table.py's index (tools/gen_registry.py) answers as the dictionaries a registry builds of the rows
    itself: every (kind, key), every key's kinds, the counts, in the same order; a stale index fails here."""
    from zero.catalog.data.table import ROWS
    from zero.catalog.registry import KeyIndex, SortedIndex, SpecTable, TableRows

    built_in = load_registry()
    assert isinstance(built_in._by_key, KeyIndex) and isinstance(built_in._kinds_of, SortedIndex)
    assert isinstance(built_in.specs, SpecTable) and isinstance(built_in.specs._rows, TableRows)
    own = build_registry(ROWS, BUILTIN_SOURCE)  # the rows as dictionaries: indexed by the registry itself
    assert isinstance(own._by_key, dict) and isinstance(own._kinds_of, dict)
    assert list(built_in._by_key.items()) == list(own._by_key.items())
    assert len(built_in._by_key) == len(own._by_key)
    assert {k: list(v) for k, v in built_in._kinds_of.items()} == own._kinds_of
    assert built_in._counters() == own._counters()
    assert list(built_in.specs) == list(own.specs) and len(built_in.specs) == len(own.specs)
    assert all(built_in.specs[pid] == own.specs[pid] for pid in own.specs)


def test_a_sorted_index_answers_as_a_dictionary() -> None:
    from zero.catalog.registry import KeyIndex, SortedIndex

    plain = {"b": 2, "d": 4, "a": 1}
    idx = SortedIndex(("a", "b", "d"), (1, 2, 4))
    assert list(idx) == ["a", "b", "d"] and len(idx) == 3 and dict(idx) == plain
    assert all(idx[k] == v and k in idx for k, v in plain.items())
    assert idx.get("c") is None and "c" not in idx and 5 not in idx and idx.get(5, "no") == "no"
    with pytest.raises(KeyError):
        idx["c"]
    by_kind = {"AXIS": (("a.b", "c"), ("P-AXIS-00002", "P-AXIS-00001")), "ZERO": (("a.b",), ("P-ZERO-00001",))}
    keys = KeyIndex(by_kind, by_kind.__getitem__)
    assert list(keys.items()) == [(("AXIS", "c"), "P-AXIS-00001"), (("AXIS", "a.b"), "P-AXIS-00002"),
                                  (("ZERO", "a.b"), "P-ZERO-00001")]
    assert keys.get(("AXIS", "a.b")) == "P-AXIS-00002" and ("ZERO", "c") not in keys and ("TOOL", "c") not in keys
    assert keys.get(("AXIS",)) is None and keys.get(None) is None and len(keys) == 3  # type: ignore[arg-type]
    with pytest.raises(KeyError):
        keys[("ZERO", "x")]


def test_an_overlay_that_moves_a_key_is_indexed_from_the_rows(monkeypatch: pytest.MonkeyPatch) -> None:
    """A seed that gives a parameter another key (or a new parameter) makes the written index wrong: the
    registry then indexes the rows itself."""
    from zero.catalog import registry as catalog
    from zero.catalog.data.seeds import SEEDS

    seeds = {**SEEDS, "params": {**SEEDS["params"], "P-AXIS-00001": {"key": "moved.a_beschl"},
                                 "P-AXIS-99999": {"key": "brand.new", "type": "UNS16"}}}
    monkeypatch.setattr(catalog, "_overlay", lambda: seeds)
    reg = load_registry()
    assert isinstance(reg._by_key, dict)
    spec = reg.by_pattern("moved.a_beschl", "AXIS")
    assert spec is not None and spec.id == "P-AXIS-00001"
    assert reg.by_pattern("getriebe[].slope_profil.a_beschl", "AXIS") is None
    new = reg.by_pattern("brand.new", None)
    assert new is not None and new.id == "P-AXIS-99999" and reg.kinds_of("brand.new") == ["AXIS"]


@pytest.mark.parametrize("key", ["grp_anzahl", "gruppe[].achs_anzahl", "a.b_c_anzahl", "x[].grp_anzahl", "c[]_anzahl",
                                 "_anzahl", "a._anzahl", "Grp_anzahl", "grp_anzahl.x", "spdl_anzahl", "ä_anzahl",
                                 "a.b.hr_anzahl", "grp2_anzahl", "anzahl"])
def test_a_counts_stem_is_found_as_the_pattern_finds_it(key: str) -> None:
    from zero.catalog.registry import _count_stem

    m = re.search(r"(?:^|\.)([a-z]+)_anzahl$", key)
    assert _count_stem(key) == (m.start(1) if m is not None else -1)


def test_a_lint_reads_the_rows_of_its_lists_kind_only(tmp_path: Path) -> None:
    """Each kind's rows are a module of their own, read at the kind's first row (issue 40: start-up): a
    zero-offset list's lint reads no axis or channel row, and a registry whose every row is read has them all."""
    import subprocess
    import sys

    listing = tmp_path / "nullp.lis"
    listing.write_text("g53_verfuegbar 1\nnp_grp[0].achse[0].versch 100\nEnde\n", encoding="utf-8")
    code = ("import sys\nfrom zero.catalog.registry import load_registry\nfrom zero.engine.lint import lint_file\n"
            f"lint_file({str(listing)!r}, load_registry())\n"
            "print(sorted(m for m in sys.modules if m.startswith('zero.catalog.data.table')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "['zero.catalog.data.table', 'zero.catalog.data.table_zero']"
    reg = load_registry()
    assert len(reg.specs) == 1766 and len(list(reg.specs)) == 1766 and "P-AXIS-00001" in reg.specs
    assert "P-AXIS-99999" not in reg.specs and "P-NOPE-00001" not in reg.specs and reg.get("P-AXIS") is None


def test_sorted_index_get_each_is_get_of_each() -> None:
    from zero.catalog.registry import SortedIndex

    index = SortedIndex(("a", "c", "e"), (1, 2, 3))
    keys = ["c", "b", "a", "z", 5, "e", ""]
    assert index.get_each(keys, ()) == [index.get(k, ()) for k in keys]

"""The registry is data: complete, consistent, and looked up by ID and by key."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest

from conftest import ROOT
from zero.catalog.ranges import parse_range
from zero.catalog.registry import KINDS, Registry, build_registry, load_registry
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
    data = (ROOT / "src" / "zero" / "catalog" / "data" / "table.py").read_text(encoding="utf-8")
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

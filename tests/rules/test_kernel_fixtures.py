"""Lists of machines in the field (issue 25): every finding true of the catalogue, with exact places.

Each fixture pins one way the catalogue's data must be read before a value is called faulty:
bit-coded symbols combine (`vorsteuerung 7` = VEL|ACC|JERK), an element beyond its count is not
used (`spindel[0]` with `spdl_anzahl 0`), indices that mean different things are not paired
(`tipp.geschw[i]` against every gear), a range that excludes the catalogue's own default is a
contradiction (R011), a range in ° for a value of unknown unit is not an error (R012), and a
decimal in an integer says that nothing documents how it is read.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import FIXTURES, findings, golden
from zero.catalog.registry import Registry
from zero.engine.lint import lint_file

KERNEL = sorted((FIXTURES / "kernel").glob("*.lis"))


@pytest.mark.parametrize("path", KERNEL, ids=lambda p: p.stem)
def test_golden(path: Path, request: pytest.FixtureRequest, registry: Registry) -> None:
    actual = findings(lint_file(path, registry))
    expected = golden(path.with_suffix(".expected.json"), actual, request.config.getoption("--update-golden"))
    assert actual == expected


def test_what_the_fixtures_pin(registry: Registry) -> None:
    by_file = {p.stem: [(d.code, d.span.line) for d in lint_file(p, registry).diagnostics] for p in KERNEL}
    assert by_file == {
        "axis_field": [("R011", 13), ("R004", 15), ("R006", 17)],  # 7, tipp.geschw[1] and hb.vb_max pass
        "axis_flags": [],  # 0x7
        "axis_symbols": [],  # VEL | ACC
        "channel_no_spindle": [],
        "tool_tilt": [("R012", 2)],
    }
    messages = {d.code: d.message for p in KERNEL for d in lint_file(p, registry).diagnostics}
    assert "the catalogue contradicts itself" in messages["R011"]
    assert "neither the catalogue nor the manuals say how the controller reads a decimal" in messages["R004"]
    assert "for every element of `getriebe[].dynamik.vb_max`" in messages["R006"] and "= 1400000" in messages["R006"]
    assert "the catalogue gives no unit for the value itself" in messages["R012"]


def test_bit_coded_symbols_are_found_by_rule(registry: Registry) -> None:
    coded = sorted(s.key for s in registry.specs.values() if s.symbols and s.bit_coded and s.key)
    assert "vorsteuer.vorsteuerung" in coded and "h_synch[]" in coded
    assert "filter[].prototype" not in coded and "getriebe[].slep_ueberw_typ" not in coded  # enumerations
    assert len(coded) == 11


def test_counts_are_found_by_rule(registry: Registry) -> None:
    pairs = {registry.specs[pid].key: sorted(registry.specs[c].key or "" for c, _ in registry.counted_by(spec))
             for pid, spec in registry.specs.items() if registry.counted_by(spec)}
    assert pairs["spindel[].log_achs_nr"] == ["spdl_anzahl"]
    assert pairs["gruppe[].achse[].log_achs_nr"] == ["grp_anzahl", "gruppe[].achs_anzahl"]
    assert {c for counts in pairs.values() for c in counts} == {
        "spdl_anzahl", "gruppe[].achs_anzahl", "grp_anzahl", "hr_anzahl", "tasten_anzahl"}

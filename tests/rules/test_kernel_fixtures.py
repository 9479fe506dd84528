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
        # issue 26's planted start-up faults: modulo limits inverted (P-ERR-110052 only: one root cause, one
        # finding, the catalogue's prose range on the other limit is superseded, issue 36), the reference point
        # outside the soft limits (the prose range of P-AXIS-00152, a warning: no start-up check documented),
        # homing speeds above the limit of an axis not homed (P-ERR-110422, 110421) ...
        "planted_spindle": [("K032", 8), ("R006", 11), ("K075", 13), ("K074", 14)],
        # ... and a homing distance limit on a linear axis (P-ERR-110545): the documentation checks it on
        # linear axes only, and modulo and the non-homed limit on rotary axes and spindles only; both position
        # resolution settings at once (no documented error: M009)
        "planted_linear": [("K089", 4), ("M009", 6)],
    }
    messages = {d.code: d.message for p in KERNEL if not p.stem.startswith("planted")
                for d in lint_file(p, registry).diagnostics}
    assert "the catalogue contradicts itself" in messages["R011"]
    assert "neither the catalogue nor the manuals say how the controller reads a decimal" in messages["R004"]
    assert "for every element of `getriebe[].dynamik.vb_max`" in messages["R006"] and "= 1400000" in messages["R006"]
    assert "the catalogue gives no unit for the value itself" in messages["R012"]


def test_bit_coded_symbols_are_what_the_catalogue_says(registry: Registry) -> None:
    """`<Bitfield>` (29 parameters) or a description calling the value bit-coded (6): facts of the
    catalogue, carried into the built-in table; an axis type with values 1, 2, 4 is no bit field."""
    coded = sorted(s.key for s in registry.specs.values() if s.bits and s.key)
    assert "vorsteuer.vorsteuerung" in coded and "h_synch[]" in coded and "block_search_restart_mode" in coded
    assert "kenngr.achs_typ" not in coded and "filter[].prototype" not in coded
    assert len(coded) == 35


def test_counts_are_found_by_rule(registry: Registry) -> None:
    pairs = {registry.specs[pid].key: sorted(registry.specs[c].key or "" for c, _ in registry.counted_by(spec))
             for pid, spec in registry.specs.items() if registry.counted_by(spec)}
    assert pairs["spindel[].log_achs_nr"] == ["spdl_anzahl"]
    assert pairs["gruppe[].achse[].log_achs_nr"] == ["grp_anzahl", "gruppe[].achs_anzahl"]
    assert {c for counts in pairs.values() for c in counts} == {
        "spdl_anzahl", "gruppe[].achs_anzahl", "grp_anzahl", "hr_anzahl", "tasten_anzahl"}


def test_an_axis_list_of_an_older_kernel(registry: Registry) -> None:
    """fixtures/releases/old_axis.lis (its README says line by line what is right): renamed keys are
    R013 with today's key as an unsafe fix and their values checked as today's parameter, removed
    keys and (the header says V3.01.3074) keys this catalogue lacks are R013 warnings, never R001."""
    result = lint_file(FIXTURES / "releases" / "old_axis.lis", registry)
    assert [(d.code, d.span.line) for d in result.diagnostics] == [
        ("R013", 12), ("R013", 13), ("R013", 14), ("R013", 15), ("R013", 16), ("R008", 16), ("R013", 17),
        ("R013", 18), ("R013", 19), ("R013", 20), ("R013", 21), ("R013", 25), ("R013", 26), ("R013", 29),
        ("R013", 30), ("R013", 31), ("R013", 32), ("R013", 33), ("R013", 34), ("R013", 35)]
    renamed = next(d for d in result.diagnostics if d.span.line == 17)
    assert renamed.fix is not None and not renamed.fix.safe and renamed.fix.edits[0].replacement == "antr.simu.totzeit"
    assert renamed.param_id == "P-AXIS-00194"


def test_the_kernel_setting_says_what_an_unknown_key_may_be(tmp_path: Path) -> None:
    from conftest import zero_cli

    (tmp_path / "achse.lis").write_text("kopf.achs_nr 1\nkenngr.vendor_frei 7\nEnde\n")
    plain = zero_cli("lint", "achse.lis", "--output-format", "concise", cwd=tmp_path)
    assert " R001 " in plain.stdout and plain.code == 1
    (tmp_path / "zero.toml").write_text('kernel = "V3.1.3074"\n')
    older = zero_cli("lint", "achse.lis", "--output-format", "concise", cwd=tmp_path)
    assert " R013 " in older.stdout and " R001 " not in older.stdout and older.code == 0
    assert "the machine runs the older kernel V3.1.3074" in older.stdout
    (tmp_path / "zero.toml").write_text('kernel = "latest"\n')
    bad = zero_cli("lint", "achse.lis", cwd=tmp_path)
    assert bad.code == 2 and "kernel" in bad.stderr and "not a kernel release" in bad.stderr


@pytest.mark.parametrize(("value", "codes"), [("7", []), ("0x7", []), ("VEL | JERK", []), ("0x8", ["R005"]),
                                              ("9", ["R005"]), ("0x101", []), ("BRAKE", ["R005"])])
def test_a_bit_field_takes_its_bits_and_only_them(value: str, codes: list[str], registry: Registry) -> None:
    """`vorsteuer.vorsteuerung` (VEL=1, ACC=2, JERK=4, ADD_VEL=257 …): any combination of the symbols'
    bits, by number or by name; a bit no symbol names (8) is not one of its values."""
    from zero.engine.lint import lint_bytes

    data = f"kopf.achs_nr 1\nvorsteuer.vorsteuerung {value}\nEnde\n".encode()
    assert [d.code for d in lint_bytes(data, registry, "achse.lis").diagnostics] == codes

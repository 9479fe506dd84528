"""zero diff: how a value reads — a mask as the bits that changed, a symbol by name, a BOOLEAN as
off/on, a quantity with its delta — and the catalogue's restart flag on each changed line."""

from __future__ import annotations

import io
import json
import re
from collections import Counter

import pytest
from typer.testing import CliRunner

from conftest import FIXTURES, ROOT, golden
from zero.catalog.registry import ParamSpec, Registry
from zero.cli.app import app
from zero.diff import (
    Change,
    DiffOptions,
    Side,
    bits_criterion,
    default_name,
    diff_defaults,
    diff_sides,
    read_side,
)
from zero.output.tables import format_change, render_diff

runner = CliRunner()
V = FIXTURES / "diff" / "values"
REL = V.relative_to(ROOT)  # the headers name the files as the command line does

# (golden name, arguments): two lists, or one list against the catalogue's defaults
CASES = [
    ("axis", [f"{REL}/axis-old.lis", f"{REL}/axis-new.lis"]),
    ("chan", [f"{REL}/chan-old.lis", f"{REL}/chan-new.lis"]),
    ("comp", [f"{REL}/comp-old.lis", f"{REL}/comp-new.lis"]),
    ("axis-defaults", ["--defaults", f"{REL}/axis-new.lis"]),
    ("chan-defaults", ["--defaults", f"{REL}/chan-new.lis"]),
]


def side(name: str, registry: Registry) -> Side:
    return read_side((V / name).read_bytes(), "lis", name, registry)


def changes(old: str, new: str, registry: Registry) -> dict[str, Change]:
    return {c.key: c for c in diff_sides(side(old, registry), side(new, registry), registry)}


@pytest.mark.parametrize(("name", "args"), CASES, ids=[c[0] for c in CASES])
def test_text_golden(name: str, args: list[str], request: pytest.FixtureRequest,
                     monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    result = runner.invoke(app, ["diff", *args], env={"NO_COLOR": "1"})
    assert result.exit_code == 1, result.output
    path = V / f"{name}.expected.txt"
    if request.config.getoption("--update-golden"):
        path.write_text(result.output, encoding="utf-8")
    assert result.output == path.read_text(encoding="utf-8")


@pytest.mark.parametrize(("name", "args"), CASES, ids=[c[0] for c in CASES])
def test_json_golden(name: str, args: list[str], request: pytest.FixtureRequest,
                     monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    result = runner.invoke(app, ["diff", "--output-format", "json", *args])
    assert result.exit_code == 1, result.output
    actual = json.loads(result.output)
    assert actual == golden(V / f"{name}.expected.json", actual, request.config.getoption("--update-golden"))
    # the README's contract, additive: the old keys first, the new ones after them
    assert all(list(c)[:9] == ["key", "id", "kind", "old", "new", "unit", "delta", "group", "note"]
               and list(c)[9:] == ["restart", "coding", "old_name", "new_name", "bits"] for c in actual)


def test_a_mask_shows_the_bits_that_changed_by_name_else_by_number(registry: Registry) -> None:
    c = changes("axis-old.lis", "axis-new.lis", registry)
    pre = c["vorsteuer.vorsteuerung"]  # symbols NONE=0 VEL=1 ACC=2 JERK=4 ADD_VEL=257 ...
    assert (pre.delta, pre.coding, pre.bits) == (None, "bits", (("JERK",), ("ACC",)))
    assert (pre.old_name, pre.new_name, format_change(pre)) == ("VEL | ACC", "VEL | JERK", "+JERK -ACC")
    mode = c["kenngr.achs_mode"]  # no names: the catalogue writes its default and range in hex
    assert (mode.delta, mode.bits, format_change(mode)) == (None, ((), ("bit 22 (0x400000)",)), "-bit 22 (0x400000)")
    assert (mode.old_name, mode.new_name) == ("0x400001", "0x1")
    flags = c["lr_param.prog_movement_requires_compensations"]  # names without numbers, written `A | B`
    assert (flags.coding, flags.bits) == ("bits", (("LEAD",), ()))


def test_symbols_and_booleans_by_name_quantities_with_their_delta(registry: Registry) -> None:
    c = changes("axis-old.lis", "axis-new.lis", registry)
    flag = c["kenngr.abs_pos_gueltig"]  # 0 → TRUE
    assert (flag.delta, flag.coding, format_change(flag)) == (None, "boolean", "off → on")
    assert (c["kenngr.swe_behaviour"].coding, c["kenngr.swe_behaviour"].new_name) == ("symbol", "WARNING")
    assert (c["kenngr.antr_typ"].coding, c["kenngr.antr_typ"].delta) == ("symbol", None)  # listed values
    assert (c["antr.sercos.telegramm_typ"].coding, c["antr.sercos.telegramm_typ"].delta) == (None, None)  # no unit
    assert (c["kenngr.swe_pos"].delta, c["kenngr.swe_pos"].unit) == (50.0, "mm")
    synch = changes("chan-old.lis", "chan-new.lis", registry)
    assert (synch["m_synch[3]"].old_name, synch["m_synch[3]"].new_name) == ("MOS", "MVS_SVS")  # 0x2 by name
    added = synch["m_synch[10]"]
    assert (added.note, format_change(added)) == ("was the default NOT_VALID", "+MVS_SVS -NOT_VALID")


def test_the_restart_flag_on_each_changed_line(registry: Registry) -> None:
    c = changes("comp-old.lis", "comp-new.lis", registry)
    assert {k: x.restart for k, x in c.items()} == {"kw.crosstalk.mode": True, "kw.crosstalk.max_points": True}
    assert not any(x.restart for x in changes("axis-old.lis", "axis-new.lis", registry).values())
    [defaults] = [x for x in diff_defaults(side("comp-new.lis", registry), registry) if x.key == "kw.crosstalk.mode"]
    assert defaults.restart
    table = io.StringIO()  # the terminal table says it too
    render_diff(list(c.values()), "header", table, color=True)
    assert re.sub(r"\x1b\[[0-9;]*m", "", table.getvalue()).count("(restart)") == 2


def test_a_default_list_value_is_named_too(registry: Registry) -> None:
    under = read_side(b"kenngr.abs_pos_gueltig 1\nkenngr.swe_pos 0\nEnde\n", "lis", "vorgabe.lis", registry, "AXIS")
    a = read_side(b"kenngr.abs_pos_gueltig 0\nkenngr.swe_pos 5\nEnde\n", "lis", "a.lis", registry, "AXIS")
    b = read_side(b"Ende\n", "lis", "b.lis", registry, "AXIS")
    by_key = {c.key: c for c in diff_sides(a, b, registry, DiffOptions(), under)}
    assert by_key["kenngr.abs_pos_gueltig"].note == "now the default list's on (vorgabe.lis:1)"
    assert by_key["kenngr.swe_pos"].note == "now the default list's 0 (vorgabe.lis:2)"


def test_defaults_by_name(registry: Registry) -> None:
    def spec(pid: str) -> ParamSpec:
        s = registry.get(pid)
        assert s is not None
        return s

    assert default_name(spec("P-AXIS-00014")) == "off"  # BOOLEAN
    assert default_name(spec("P-CHAN-00041")) == "NOT_VALID"
    assert default_name(spec("P-AXIS-00223")) == "NONE"
    assert default_name(spec("P-AXIS-00015")) == "0x00000001"  # a mask without names: as written


def test_which_parameters_are_bits_decided_by_the_catalogue(registry: Registry) -> None:
    by = {pid: bits_criterion(registry.specs[pid]) for pid in registry.specs}
    bits = {registry.specs[p].key for p, c in by.items() if c}
    # which criterion holds may move (the catalogue's own bit-field flag first), that these are bits not
    assert {"vorsteuer.vorsteuerung", "h_synch[]", "m_synch[]", "lr_hw[].mask_mess_1"} <= bits
    assert {by[p] for p in ("P-AXIS-00015", "P-AXIS-00039")} == {"hex"}  # achs_mode, cam_mask: no symbols
    for numbering in ("kenngr.antr_typ", "filter[].prototype", "ext_var_struct_member_alignment",
                      "antr.sercos.telegramm_typ", "kenngr.swe_behaviour"):
        assert numbering not in bits, numbering
    # symbols are bits exactly where the rules combine them (`vorsteuerung 7` = VEL | ACC | JERK)
    assert all((by[p] is not None) == registry.specs[p].bits for p in registry.specs
               if registry.specs[p].symbols and registry.specs[p].type != "BOOLEAN")
    assert Counter(registry.specs[p].type for p, c in by.items() if c).get("BOOLEAN") is None


def test_listed_bits_with_labels_and_a_description_that_speaks_of_bits(registry: Registry) -> None:
    labelled = ParamSpec("P-AXIS-09991", "AXIS", "t.listed", "UNS16", default="0x0080", enum=(64, 128),
                         enum_flags=True, enum_labels=("probe 1", "probe 2"))
    described = ParamSpec("P-AXIS-09992", "AXIS", "t.described", "UNS32", default="0",
                          description="Bit 0: lock the axis, bit 1: keep the brake closed")
    plain = ParamSpec("P-AXIS-09993", "AXIS", "t.plain", "UNS32", default="0", description="Number of bits")
    assert [bits_criterion(s) for s in (labelled, described, plain)] == ["enum", "description", None]
    reg = Registry({s.id: s for s in (labelled, described, plain)})
    a = read_side(b"t.listed 0x0080\nt.described 1\nt.plain 4\n", "lis", "a", reg, "AXIS")
    b = read_side(b"t.listed 0x0040\nt.described 2\nt.plain 6\n", "lis", "b", reg, "AXIS")
    by_key = {c.key: c for c in diff_sides(a, b, reg)}
    assert format_change(by_key["t.listed"]) == "+probe 1 -probe 2"
    assert (by_key["t.listed"].old_name, by_key["t.listed"].new_name) == ("probe 2", "probe 1")
    assert format_change(by_key["t.described"]) == "+bit 1 (0x2) -bit 0 (0x1)"
    assert (by_key["t.plain"].coding, by_key["t.plain"].delta) == (None, None)  # a number without a unit


def test_listed_values_by_their_meaning(registry: Registry) -> None:
    spec = ParamSpec("P-AXIS-09994", "AXIS", "t.mode", "UNS16", default="0", enum=(0, 1, 2),
                     enum_labels=("off", "position", "velocity"))
    reg = Registry({spec.id: spec})
    a, b = (read_side(f"t.mode {v}\n".encode(), "lis", "a", reg, "AXIS") for v in (1, 2))
    [c] = diff_sides(a, b, reg)
    assert (c.coding, c.delta, format_change(c)) == ("symbol", None, "1 (position) → 2 (velocity)")

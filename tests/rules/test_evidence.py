"""Issue 36: every error true on a real machine. What zero says the controller does comes from the
vendor's documentation (zero.catalog.evidence), or zero says it does not know; severity follows the
evidence; nothing reasons on a value zero cannot read; one root cause, one finding; the vendor's own
spellings are information; a list is judged on the machine's layered values."""

from __future__ import annotations

import io
import json
import tomllib
from pathlib import Path

import pytest

from conftest import FIXTURES
from zero.catalog.data.evidence_table import DRIVES
from zero.catalog.evidence import CONSEQUENCES, DOCUMENTED, Claim, claim, claims, rule_claims
from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic, Severity
from zero.engine.lint import LintOptions, LintResult, lint_file, lint_machine
from zero.machine.model import load_machine
from zero.output.formats import render_json, render_sarif
from zero.rules import RULES as ALL_RULES
from zero.rules.lists import kernel_rules
from zero.rules.startup import CHECKS

EVIDENCE = FIXTURES / "evidence"
DATA = Path(__file__).resolve().parents[2] / "src" / "zero" / "catalog" / "data"


def _found(name: str, registry: Registry) -> list[Diagnostic]:
    return lint_file(EVIDENCE / name, registry).diagnostics


def _at(found: list[Diagnostic]) -> list[tuple[int, str, str]]:
    return [(d.span.line, d.code, d.severity.label) for d in found]


# ------------------------------------------------------------------------- the table itself

def test_the_compiled_table_is_the_toml() -> None:
    """tools/gen_evidence.py was run after the last edit of evidence.toml."""
    data = tomllib.loads((DATA / "evidence.toml").read_text(encoding="utf-8"))
    by_name: dict[str, list[Claim]] = {}  # a claim's rows together, in the order of its first
    for row in data["claim"]:
        by_name.setdefault(row["name"], []).append(Claim(
            row["name"], row["consequence"], Severity.parse(row["severity"]), row["says"], row["source"],
            row.get("releases", "all"), tuple(row.get("kinds", ())), row.get("kernel_error")))
    want = [c for rows in by_name.values() for c in rows]
    assert claims() == want and rule_claims() == data["rules"] and "drive" not in data and DRIVES  # drive_types


def test_an_error_needs_a_documented_consequence_and_its_page() -> None:
    for c in claims():
        assert c.consequence in CONSEQUENCES, c
        if c.severity is Severity.ERROR:
            assert c.consequence in DOCUMENTED | {"unchecked"}, c
            if c.consequence != "unchecked":
                assert c.source.startswith("https://") or "manual" in c.source, c
        assert (c.consequence in DOCUMENTED) <= (c.severity is Severity.ERROR), c  # documented: an error
        if c.consequence == "undocumented":
            assert c.severity is not Severity.ERROR and (" not " in c.says or " no " in c.says), c


def test_every_rule_has_its_claim() -> None:
    """Every rule was re-checked against the standard: each names the claim its findings carry. The K rules
    carry their own row of the start-up errors, the Z rules are about zero's own directives; X and N rules
    declared after issue 36 with a kernel number of their own (X015-, N005-) keep their declared severity
    until a row here says otherwise."""
    named = rule_claims()
    assert set(named) <= set(ALL_RULES), sorted(set(named) - set(ALL_RULES))
    wanted = {code for code in ALL_RULES if code[0] in "SRMUF"} | {f"X{n:03}" for n in range(1, 15)} | \
        {f"N{n:03}" for n in range(1, 5)}
    assert wanted <= set(named), sorted(wanted - set(named))
    for code, name in named.items():
        c = claim(name, "AXIS")
        assert c.name == name
        declared = ALL_RULES[code].severity if code in ALL_RULES else None
        if declared is not None and code[0] in "SRMU":  # the families this issue's rules live in
            worst = max(claim(name, kind).severity for kind in ("AXIS", "CHAN", "ZERO", None))
            assert declared == worst, (code, declared, worst)


def test_the_kind_decides_the_claim() -> None:
    assert claim("out-of-range", "AXIS").kernel_error == "P-ERR-1001138"
    assert claim("out-of-range", "AXIS").consequence == "limited"
    assert claim("out-of-range", "CHAN").severity is Severity.WARNING
    assert claim("unknown-element", "AXIS").kernel_error == "P-ERR-1001119"
    assert claim("unknown-element", "TOOL").kernel_error is None


# ------------------------------------------------------------------------- the classes of the issue

def test_nothing_reasons_on_a_value_zero_cannot_read(registry: Registry) -> None:
    """Class 3: `666666.667` in the UNS32 vb_max, six speeds ranged against it: one finding, R004, the one
    true error class of the 2021 machine (before: R004 and six R006 "above vb_max" on the default 200000)."""
    found = _found("decimal_speeds.lis", registry)
    assert _at(found) == [(4, "R004", "error")]
    [d] = found
    assert d.kernel_error == "P-ERR-1001138" and d.consequence == "zeroed"
    assert d.source == "https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/269276555.html"
    assert "zero checks nothing against this value" in d.message and "default" not in d.message


def test_a_reference_point_on_the_soft_limit_is_allowed(registry: Registry) -> None:
    """Class 2: `swe_neg < pos_refpkt < swe_pos` in prose; the axis may move to its soft limits, so the limit
    itself is allowed; beyond it, a warning that says no start-up check is documented (no invented default)."""
    found = _found("refpkt_on_limit.lis", registry)
    assert _at(found) == [(7, "R006", "warning")]
    assert "no start-up check" in found[0].message and "replaces" not in found[0].message
    assert "kenngr.swe_pos = 15000000 (line 5)" in found[0].message  # where the value it used is written


def test_the_consequence_of_a_value_out_of_range(registry: Registry) -> None:
    """Class 6 and 9: in an axis list the kernel limits a value to its range (P-ERR-1001138), ignores an
    unknown element (P-ERR-1001119); listed values are not a range (nothing documented); inverted modulo
    limits are K032 only; a SERCOS-only mask on a simulated drive is not used (class 4)."""
    found = _found("out_of_range.lis", registry)
    assert _at(found) == [(5, "R005", "warning"), (6, "R005", "error"), (7, "R001", "error"), (8, "R005", "info"),
                          (9, "K032", "error")]
    by_line = {d.span.line: d for d in found}
    assert "here the maximum 10" in by_line[6].message and by_line[6].kernel_error == "P-ERR-1001138"
    assert by_line[6].consequence == "limited"
    assert by_line[5].consequence == "undocumented" and by_line[5].kernel_error is None
    assert by_line[7].kernel_error == "P-ERR-1001119" and by_line[7].consequence == "ignored"
    assert by_line[8].consequence == "not-applicable" and "drive type 4 (line 4" in by_line[8].message
    assert by_line[9].source and by_line[9].source.startswith("https://") and by_line[9].consequence == "replaced"
    assert not any(d.code == "R006" for d in found)  # the modulo limits: one root cause, one finding
    assert not any("replaces it with the default" in d.message for d in found)


def test_an_application_specific_range_is_information(registry: Registry) -> None:
    """Class 4: "0 … 9 (application-specific)" while the vendor's own template ships 12."""
    [d] = _found("manual.lis", registry)
    assert (d.code, d.severity.label, d.consequence) == ("R005", "info", "undocumented")
    assert "application-specific" in d.message


def test_the_vendors_own_spellings_are_information(registry: Registry) -> None:
    """Class 5 and 7: keys and spellings the vendor's own templates and lists write."""
    axis = _found("spellings.lis", registry)
    assert _at(axis) == [(3, "R013", "info"), (4, "R013", "info"), (5, "R002", "info"), (6, "R001", "error")]
    assert "default_ax_mds.xml line 146" in axis[1].message and axis[1].param_id == "P-AXIS-00141"
    assert all(d.consequence == "vendor-writes" for d in axis[:3])
    chan = _found("spellings_chan.lis", registry)
    assert _at(chan) == [(2, "R002", "info"), (3, "R002", "info"), (4, "R001", "warning")]
    assert "ignores the entry" not in chan[0].message
    assert "no reaction" in chan[2].message and chan[2].kernel_error is None  # 1001119 is the axis list's


def test_a_list_is_judged_with_the_default_list_under_it(registry: Registry) -> None:
    """Class 8: a condition met only with the default list's value (gear 1's vb_max), one the default list
    undoes (gear 0's vb_max, the drive type SERCOS); alone, the list says which values it assumed."""
    machine = load_machine(EVIDENCE / "machine" / "hochlauf.lis", registry)
    results = {Path(r.path).name: r for r in lint_machine(machine, registry)}
    layered = results["achse_x.lis"].diagnostics
    assert _at(layered) == [(4, "R005", "warning"), (6, "R006", "warning")]
    assert "default_mds.lis line 4, the default list under this one" in layered[1].message
    assert results["default_mds.lis"].diagnostics == []
    alone = _found("machine/listen/achse_x.lis", registry)
    assert _at(alone) == [(4, "R005", "info"), (5, "R006", "warning")]
    assert "(the catalogue's default, P-AXIS-00020)" in alone[0].message
    assert "is not set, default 200000" in alone[1].message


def test_every_k_rule_supersedes_on_the_parameters_it_names() -> None:
    """The mechanism reads each K row: a new K rule gets it without code."""
    rules = kernel_rules()
    assert set(rules) == {err.code for err in CHECKS}
    for err in CHECKS:
        assert set(err.params) <= rules[err.code][0]
    assert {"P-AXIS-00126", "P-AXIS-00127"} <= rules["K032"][0]


# ------------------------------------------------------------------------- severity, outputs

def test_the_run_severity_wins_where_given(registry: Registry) -> None:
    path = EVIDENCE / "out_of_range.lis"
    lowered = lint_file(path, registry, LintOptions(severity={"R005": Severity.WARNING})).diagnostics
    assert {d.severity.label for d in lowered if d.code == "R005"} == {"warning"}
    raised = lint_file(EVIDENCE / "refpkt_on_limit.lis", registry,
                       LintOptions(severity={"R006": Severity.ERROR})).diagnostics
    assert _at(raised) == [(7, "R006", "error")]


@pytest.mark.parametrize("render", ["json", "sarif"])
def test_the_outputs_carry_the_consequence_and_its_source(registry: Registry, render: str) -> None:
    result: LintResult = lint_file(EVIDENCE / "decimal_speeds.lis", registry)
    out = io.StringIO()
    if render == "json":
        render_json([result], out)
        [item] = json.loads(out.getvalue())
        assert item["consequence"] == "zeroed" and item["kernel_error"] == "P-ERR-1001138"
        assert item["source"].endswith("269276555.html")
    else:
        render_sarif([result], out)
        [item] = json.loads(out.getvalue())["runs"][0]["results"]
        assert item["properties"]["consequence"] == "zeroed"
        assert item["properties"]["source"].endswith("269276555.html")
        assert item["properties"]["kernelError"] == "P-ERR-1001138"


def test_a_claim_is_built_at_its_first_use_and_each_row_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """A lint's findings ask for a few claims: only theirs become Claim objects (issue 40: start-up)."""
    from zero.catalog import evidence

    monkeypatch.setattr(evidence, "_built", {})
    monkeypatch.setattr(evidence, "_chosen", {})
    first = evidence.claim("style")
    assert list(evidence._built) == ["style"] and evidence.claim("style") is first
    every = evidence.claims()
    assert len(every) == evidence._load()[0].count("\n") - 1 and first in every  # a row a line, after a line break
    with pytest.raises(KeyError):
        evidence.claim("no-such-claim")

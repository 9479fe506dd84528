"""The real world: every vendor list reads cleanly, and its real faults are found."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from conftest import FIXTURES, corpus_dir, golden
from zero.catalog.registry import Registry
from zero.engine.lint import LintOptions, lint_file

LISTS = sorted((corpus_dir() / "isg-sdk" / "listen").rglob("*.lis"))
TEMPLATES = sorted((corpus_dir() / "isg-sdk" / "xml").rglob("*.xml"))


def _name(p: Path) -> str:
    return str(p.relative_to(corpus_dir() / "isg-sdk" / "listen"))


def test_corpus_has_lists(corpus: Path) -> None:
    assert len(LISTS) >= 21


@pytest.mark.parametrize("path", LISTS, ids=_name)
def test_no_syntax_error(registry: Registry, corpus: Path, path: Path) -> None:
    result = lint_file(path, registry)
    bad = [d for d in result.diagnostics if d.code.startswith("S") and d.severity.label == "error"]
    assert bad == []
    assert result.kind is not None


def test_unknown_keys_are_exactly_the_real_ones(registry: Registry, corpus: Path) -> None:
    found: Counter[tuple[str, str]] = Counter()
    for path in LISTS:
        result = lint_file(path, registry)
        for d in result.diagnostics:
            if d.code in ("R001", "R002", "R010"):
                line = result.document.line_text(d.span.line)
                found[(d.code, line.split()[0])] += 1
    keys = {k for _, k in found}
    assert {"syn_chk.fehler_pro_zeile", "kenngr.homing_type", "thread[0].cpu"} <= keys
    # the rest of the unknown keys, checked by hand against CncParaDesc.xml: absent there too
    assert keys == {
        "syn_chk.fehler_pro_zeile", "syn_chk.fehler_gesamt", "syn_chk.interaktiv",
        "kenngr.homing_type", "thread[0].cpu", "thread[1].cpu", "thread[2].cpu",
        "thread[3].cpu", "thread[4].cpu", "configuration.channel[0].interpolator.parameter",
        "number_used_variables",
    }


def test_duplicate_drive_type_in_sercos_lists(registry: Registry, corpus: Path) -> None:
    for n in range(1, 5):
        result = lint_file(corpus / "isg-sdk" / "listen" / "SoE" / f"achsmds{n}.lis", registry)
        dups = [d for d in result.diagnostics if d.code == "R007"]
        assert len(dups) == 1 and "kenngr.antr_typ" in dups[0].message
        assert "later value 2" in dups[0].message


def test_wrong_annotations_found(registry: Registry, corpus: Path) -> None:
    found = set()
    for path in LISTS:
        for d in lint_file(path, registry).diagnostics:
            if d.code == "R008":
                found.add((_name(path), d.span.line))
    names = {f for f, _ in found}
    assert "SoE/achsmds2.lis" in names  # P-AXIS-00536 on kenngr.antr_typ
    msgs = [d.message for d in lint_file(corpus / "isg-sdk/listen/SoE/achsmds2.lis", registry).diagnostics]
    assert any("P-AXIS-00536" in m and "kenngr.antr_typ" in m for m in msgs)
    assert len(found) >= 7


def test_latin1_axis_lists(registry: Registry, corpus: Path) -> None:
    result = lint_file(corpus / "isg-sdk" / "listen" / "achsmds1.lis", registry)
    assert result.document.encoding == "cp1252"
    assert any("µ" in line for line in result.document.lines)


def test_commented_out_parameters_are_opt_in_information(registry: Registry, corpus: Path) -> None:
    path = corpus / "isg-sdk" / "listen" / "sda_mds1.lis"
    assert not [d for d in lint_file(path, registry).diagnostics if d.code in ("S005", "S012")]
    result = lint_file(path, registry, LintOptions(extend_select=("S012",)))
    s012 = [d for d in result.diagnostics if d.code == "S012"]
    assert len(s012) > 50 and all(d.severity.label == "info" for d in s012)


def test_vendor_keys_are_information_and_unknown_keys_errors(registry: Registry, corpus: Path) -> None:
    codes = Counter(d.code for path in LISTS for d in lint_file(path, registry).diagnostics)
    assert codes["R001"] == 0 and codes["R010"] == 9 and codes["S005"] == 0


def _compact(path: Path, registry: Registry) -> list[str]:
    result = lint_file(path, registry, LintOptions(extend_select=("S012",)))
    return [f"{d.span.line}:{d.span.column}-{d.span.end_line}:{d.span.end_column} {d.code} "
            f"{d.severity.label} {d.param_id or ''}".rstrip() for d in result.diagnostics]


def test_every_finding_on_the_corpus_is_pinned(registry: Registry, corpus: Path,
                                              request: pytest.FixtureRequest) -> None:
    """Exactly the findings (location, code, severity, parameter) zero gave on every vendor list
    before its speed work: a faster path must not lose or add one. Opt-in S012 included."""
    actual = {_name(p): _compact(p, registry) for p in LISTS}
    expected = golden(FIXTURES / "corpus-findings.json", actual, request.config.getoption("--update-golden"))
    assert actual == expected


def test_every_error_on_the_vendors_lists_is_documented(registry: Registry, corpus: Path) -> None:
    """Issue 36: on the vendor's own lists, ASCII and XML, every error is one the vendor's documentation
    backs. The one left: the SDK's spindle template sets the fast homing speed (the catalogue's default
    83333) above the speed limit of a non-homed axis (30000): P-ERR-110421, "the value of P-AXIS-00219 is
    automatically set to the maximum permissible velocity P-AXIS-00268"
    (https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/263292555.html)."""
    errors = []
    for path in [*LISTS, *TEMPLATES]:
        for d in lint_file(path, registry).diagnostics:
            if d.severity.label == "error":
                errors.append((path.name, d.span.line, d.code, d.kernel_error))
                assert d.source is not None and d.source.startswith("https://"), d
    assert errors == [("ax_mds_6_spdl.xml", 189, "K074", "P-ERR-110421")]
    templates = Counter((d.code, d.severity.label) for p in TEMPLATES for d in lint_file(p, registry).diagnostics)
    # the SERCOS-only measuring mask of a simulated axis, the application-specific inching keys: information
    assert templates[("R005", "info")] == 2 and templates[("R005", "error")] == 0

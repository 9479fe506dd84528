"""The evidence table is written as text, a row a line (tools/gen_evidence.py), and a claim is built from
its lines at its first use, a rule's claim found at the rule's first finding: a lint that has a finding or
two no longer builds the whole table (issue 40: start-up)."""

from __future__ import annotations

import pytest

import zero.catalog.evidence as evidence
from zero.catalog.data.evidence_table import CLAIMS, RULES
from zero.catalog.evidence import claim, claims, rule_claim, rule_claims
from zero.diagnostics import Severity


@pytest.fixture
def fresh(monkeypatch: pytest.MonkeyPatch) -> None:
    """Nothing of the table read yet, as at a run's first finding."""
    monkeypatch.setattr(evidence, "_table", None)
    monkeypatch.setattr(evidence, "_built", {})
    monkeypatch.setattr(evidence, "_chosen", {})
    monkeypatch.setattr(evidence, "_named", {})


def test_the_text_is_a_row_a_line() -> None:
    for text, fields in ((CLAIMS, 8), (RULES, 2)):
        assert text.startswith("\n") and text.endswith("\n")  # every row's line begins after a line break
        rows = text[1:-1].split("\n")
        assert rows and all(row.count("\t") == fields - 1 for row in rows)
    names = [row.split("\t", 1)[0] for row in CLAIMS[1:-1].split("\n")]
    assert names == sorted(names, key=names.index)  # a claim's rows together: claim() reads them in one go


@pytest.mark.usefixtures("fresh")
def test_a_claim_is_built_at_its_first_use() -> None:
    c = rule_claim("R008", "AXIS")
    assert c is not None and rule_claims()["R008"] == c.name
    assert list(evidence._built) == [c.name] and evidence._named == {"R008": c.name}  # nothing else built
    assert rule_claim("R008", "AXIS") is c  # and taken as built after
    assert rule_claim("K001") is None and evidence._named["K001"] is None  # a rule without a claim (the K rules)
    with pytest.raises(KeyError):
        claim("no-such-claim")


@pytest.mark.usefixtures("fresh")
def test_a_claim_is_its_own_rows_alone() -> None:
    """A name that begins another (``style``, ``style-info``) and a claim's rows for each kind."""
    assert claim("style").severity is Severity.WARNING and claim("style-info").severity is Severity.INFO
    assert [c.name for c in evidence._claims("style")] == ["style"]
    rows = evidence._claims("unknown-element")
    assert [(c.kinds, c.consequence) for c in rows] == [(("ZERO",), "aborted"), (("AXIS",), "ignored"),
                                                        ((), "undocumented")]
    assert claim("unknown-element", "CHAN") is rows[2] and claim("unknown-element", None) is rows[2]
    assert rows[1].kernel_error == "P-ERR-1001119" and rows[2].kernel_error is None
    assert [c for c in claims() if c.name == "unknown-element"] == rows
    assert claims()[-1] == claim(claims()[-1].name)  # the last line too

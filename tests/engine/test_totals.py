"""Totals (zero.engine.results): what a report says at its end, counted as results pass, is what
counting every finding of every result afterwards gives."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from zero.diagnostics import Diagnostic, Severity, Span
from zero.engine.results import LintResult, Totals, is_unreadable
from zero.lists.model import Document

CODES = ("F001", "R001", "R005", "S014", "X002")


def result(findings: list[tuple[str, Severity]], note: str | None) -> LintResult:
    doc = Document("a.lis", "ascii", [], [], [])
    return LintResult("a.lis", doc, "AXIS", [Diagnostic(code, severity, "m", Span(1, 1, 1, 2), "a.lis")
                                              for code, severity in findings], note)


results = st.lists(st.builds(result, st.lists(st.tuples(st.sampled_from(CODES), st.sampled_from(list(Severity))),
                                              max_size=6),
                             st.sampled_from([None, "skipped"])), max_size=8)


@given(results)
def test_totals_are_the_findings_counted_afterwards(rs: list[LintResult]) -> None:
    totals = Totals()
    for r in rs:
        totals.add(r)
    counted = [r for r in rs if r.note is None or r.diagnostics]
    found = [d for r in counted for d in r.diagnostics]
    assert totals.files == len(counted)
    assert totals.clean == sum(1 for r in counted if not r.diagnostics)
    assert totals.unreadable == sum(1 for r in counted if is_unreadable(r))
    assert totals.by_severity == {s: n for s in Severity if (n := sum(1 for d in found if d.severity is s))}
    assert totals.by_code == {c: n for c in CODES if (n := sum(1 for d in found if d.code == c))}
    assert totals.worst == max((d.severity for d in found), default=None)

"""The one funnel every finding passes before it is reported.

Whatever made a finding (a list's S/R/M checks, the X rules of its machine, an NC program's
N checks, a file that could not be read), the same three steps decide what is reported, in
this order:

1. **selection**: only codes the run selected (``--select``, ``--ignore``, the configuration's
   ``select``/``ignore``/``per-file-ignores`` for *this* file: ``severities`` holds exactly the
   selected codes);
2. **severity**: each finding keeps the severity its evidence gives it (:mod:`zero.catalog.evidence`:
   an error only where the vendor documents that the controller rejects, changes or ignores the
   value or stops) unless the run gives its code another severity than the rule's default
   (``[tool.zero.severity]``): then that one, whatever the check assumed;
3. **suppression**: the directives written in the file (``noqa``, ``zero: ignore[…]``), with Z001
   and Z002 for directives that hide nothing or cannot be read.

The checks skip work for codes nobody selected, but what they return is never trusted to be
selected: a finding made for one file and attached to another (an X finding on the list it
concerns) is selected with the options of the file it lands in.
"""

from __future__ import annotations

from collections.abc import Sequence

from zero.diagnostics import Diagnostic, Severity
from zero.records import replace
from zero.rules.base import default_severity
from zero.rules.suppress import Bad, Directive, apply_directives


def select(found: Sequence[Diagnostic], severities: dict[str, Severity]) -> list[Diagnostic]:
    """Steps 1 and 2: the selected findings, each with its evidence's severity, or the run's where the
    run gives its code another severity than the rule's default."""
    out = []
    for d in found:
        severity = severities.get(d.code)
        if severity is None:
            continue
        if severity is d.severity or severity is default_severity(d.code):
            out.append(d)  # the evidence's severity (the run left the rule's default)
        else:
            out.append(replace(d, severity=severity))
    return out


def funnel(path: str, found: Sequence[Diagnostic], severities: dict[str, Severity],
           directives: tuple[list[Directive], list[Bad]] | None = None) -> list[Diagnostic]:
    """Selection, severity and suppression for the findings of one file, sorted."""
    kept = select(found, severities)
    kept.sort(key=Diagnostic.sort_key)
    if directives is None:
        return kept
    return apply_directives(path, directives[0], directives[1], kept, severities)


__all__ = ["funnel", "select"]

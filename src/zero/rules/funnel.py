"""The one funnel every finding passes before it is reported (flake8's ``StyleGuide.handle_error``).

Whatever made a finding (a list's S/R/M/U/K checks, the X rules of its machine, an NC program's
N checks, an update file checked against its machine, a file that could not be read or parsed),
and whoever asked (``zero lint`` of lists, XML, structured forms, programs and machines, the
language server, ``zero report``), :func:`funnel` decides what is reported, in this order and
nowhere else:

1. **selection**: only codes the run selected for *this* file. ``severities`` holds exactly
   them: ``--select``/``--ignore``/``--extend-select`` over the configuration's
   ``select``/``ignore``, less every code the file's ``per-file-ignores`` match, whatever
   selected it (as ruff: :func:`zero.engine.lint.layered_selection`);
2. **severity**: each finding keeps the severity its evidence gives it (:mod:`zero.catalog.evidence`:
   an error only where the vendor documents that the controller rejects, changes or ignores the
   value or stops) unless the run gives its code another severity than the rule's default
   (``[tool.zero.severity]``): then that one, whatever the check assumed;
3. **one root cause, one finding**: among the selected findings, what the checks' ``consolidate``
   step leaves (a K rule supersedes the generic findings on the parameters it names:
   :mod:`zero.rules.lists`);
4. **suppression**: the directives written in the file (``noqa``, ``zero: ignore[…]``,
   ``zero: noqa``), with Z001 and Z002 for directives that hide nothing or cannot be read
   (:mod:`zero.rules.suppress`); ``--ignore-noqa`` passes none.

The checks may skip work for codes nobody selected (:meth:`zero.rules.base.Check.wanted`: a
pre-filter for speed), but what they return is never trusted to be selected, nor to carry the
run's severity: a finding made for one file and attached to another (an X finding on the list
it concerns, an update's finding in the list it changes) is decided with the options and the
directives of the file it lands in. No caller filters, re-grades or suppresses findings itself.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from zero.diagnostics import Diagnostic, Severity
from zero.records import replace
from zero.rules.base import default_severity
from zero.rules.suppress import Bad, Directive, apply_directives

Directives = tuple[list[Directive], list[Bad]]
Consolidate = Callable[[list[Diagnostic]], list[Diagnostic]]


def _select(found: Sequence[Diagnostic], severities: dict[str, Severity]) -> list[Diagnostic]:
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
           directives: Directives | None = None, consolidate: Consolidate | None = None) -> list[Diagnostic]:
    """The findings of one file as they are reported: selected, graded, consolidated, suppressed, sorted.
    ``directives``: the file's suppression directives (``None``: a file without comments zero reads,
    or ``--ignore-noqa``)."""
    kept = _select(found, severities)
    if consolidate is not None and kept:
        kept = consolidate(kept)
    kept.sort(key=Diagnostic.sort_key)
    if directives is None:
        return kept
    return apply_directives(path, directives[0], directives[1], kept, severities)


__all__ = ["Consolidate", "Directives", "funnel"]

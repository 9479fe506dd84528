"""The list families together: one list checked by every selected S, R, M, U and K rule, its
findings (and those its machine or an update attach to it) decided by the one funnel
(:mod:`zero.rules.funnel`: selection, severity, one root cause, the suppressions written in it).
The engine lints a list through :func:`check_document`.

One root cause, one finding: a K rule (the kernel's own documented start-up check, with its
error number) supersedes the generic findings on the parameters it names (R005 out of range,
R006 a relation, R011, M001): the kernel's number and its documented reaction say it better. The
parameters a K rule names are read from its row of the start-up errors (``params`` and what its
condition reads), so a new K rule supersedes without a line of code here.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence

from zero.catalog.registry import Registry
from zero.catalog.values import ListValues
from zero.diagnostics import Diagnostic, Severity
from zero.lists.model import Document
from zero.records import replace
from zero.rules import startup, suppress, syntax
from zero.rules.base import Context, declared_codes, run_checks
from zero.rules.families import LIST_CHECKS as CHECKS
from zero.rules.funnel import funnel

# the generic findings a K rule on the same parameter supersedes
SUPERSEDED = frozenset({"R005", "R006", "R011", "M001"})
# a K row's documented correction → the consequence its findings carry (zero.catalog.evidence)
_CORRECTION = {"default": "replaced", "abort": "aborted", "none": "behaviour", "": "reported"}


@functools.cache
def kernel_rules() -> dict[str, tuple[frozenset[str], str, str]]:
    """K code → the parameters its row names (reported ones and those its condition reads), its
    consequence and its source."""
    out = {}
    for err in startup.CHECKS:
        covered = frozenset((*err.params, *startup.compiled(err).read))
        consequence = _CORRECTION.get(err.correction.strip(), "corrected")
        out[err.code] = (covered, consequence, err.source)
    return out


@functools.cache
def _kernel_codes() -> frozenset[str]:
    """The K codes (what :func:`kernel_rules` holds), without reading what each row's condition reads, nor
    making each row's check (``startup.CHECKS``)."""
    return startup.codes()


def _kernel_first(ctx: Context, kept: list[Diagnostic]) -> list[Diagnostic]:
    """``kept`` (the selected findings: the funnel's consolidation step) with the generic findings that
    a K finding on the same parameter (and the same element of an array) supersedes left out, and
    each K finding with its consequence and source."""
    codes = _kernel_codes()
    if not any(d.code in codes for d in kept):  # no K finding: nothing superseded, and no table to build
        return kept
    rules = kernel_rules()
    kernel = [d for d in kept if d.code in rules]
    if not kernel:
        return kept
    # the key indices of the lines the findings are on, read from the columns (no entry built)
    wanted = {d.span.line for d in kept}
    rows = [row for row, line in enumerate(ctx.doc.columns.line) if line in wanted]
    indices = dict(zip(map(ctx.doc.columns.line.__getitem__, rows), ctx.indices_at(rows), strict=True))
    covers = [(rules[d.code][0], indices.get(d.span.line, ())) for d in kernel]

    def superseded(d: Diagnostic) -> bool:
        if d.code not in SUPERSEDED or d.param_id is None:
            return False
        mine = indices.get(d.span.line, ())
        return any(d.param_id in ids and (not idx or not mine or idx[:1] == mine[:1]) for ids, idx in covers)

    out = []
    for d in kept:
        if d.code in rules:
            _, consequence, source = rules[d.code]
            out.append(replace(d, consequence=d.consequence or consequence, source=d.source or source))
        elif not superseded(d):
            out.append(d)
    return out


def check_document(doc: Document, registry: Registry, kind: str | None,
                   severities: dict[str, Severity],
                   extra: Sequence[Diagnostic] = (), kernel: str | None = None,
                   default_list: bool = False, base: ListValues | None = None,
                   noqa: bool = True) -> tuple[Context, list[Diagnostic]]:
    """The list's context (kind detected when ``None``) and its findings as the funnel reports them
    (:mod:`zero.rules.funnel`), sorted. ``extra``: findings about this list from elsewhere (the X rules
    of its machine, an update's findings in the list it changes), which pass the same funnel: this
    list's selection, severities and suppressions.
    ``kernel``: the kernel release the machine runs, where the configuration says it; ``default_list``:
    the machine reads this list as a default list (an XML list says so by its root element itself);
    ``base``: the default list the machine reads under this one (its values count where this list
    sets none, for every rule: the machine's layered values)."""
    ctx = Context.of(doc, registry, kind)
    ctx.severities = severities
    ctx.kernel = kernel
    ctx.default_list = default_list or (doc.origin is not None and doc.origin.default_list)
    if base is not None and base.kind == ctx.kind and base.doc is not doc:
        ctx.base = base
    if any(p.kind == "binary" for p in doc.problems):  # one root cause, one finding
        return ctx, funnel(doc.path, [d for d in syntax.check_problems(ctx) if d.code == "S013"], severities)
    found = run_checks(CHECKS, ctx)
    found.extend(extra)
    # --ignore-noqa: the suppression directives written in the list are not applied
    directives = suppress.parse_directives(doc, declared_codes()) if noqa else None
    return ctx, funnel(doc.path, found, severities, directives, functools.partial(_kernel_first, ctx))

"""The list families together: one list checked by every selected S, R and M rule, then
the suppressions written in it applied (Z). The engine lints a list through
:func:`check_document`; the N rules lint the key and value of an ``AXPARAM`` the same way.
"""

from __future__ import annotations

from collections.abc import Sequence

from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic, Severity
from zero.lists.model import Document
from zero.rules import elements, meaning, registry, startup, suppress, syntax, update
from zero.rules.base import Check, Context, declared_codes, run_checks
from zero.rules.funnel import funnel

FAMILIES = (syntax.FAMILY, registry.FAMILY, meaning.FAMILY, update.FAMILY, startup.FAMILY)
assert elements.FAMILY is syntax.FAMILY  # its checks are the syntax family's
CHECKS: list[Check[Context]] = [c for family in FAMILIES for c in family.checks]


def check_document(doc: Document, registry: Registry, kind: str | None,
                   severities: dict[str, Severity],
                   extra: Sequence[Diagnostic] = (), kernel: str | None = None,
                   default_list: bool = False, noqa: bool = True) -> tuple[Context, list[Diagnostic]]:
    """The list's context (kind detected when ``None``) and its findings, sorted, suppressions applied.
    ``extra``: findings about this list from elsewhere (the X rules of its machine), which pass the
    same funnel (:mod:`zero.rules.funnel`): this list's selection, severities and suppressions.
    ``kernel``: the kernel release the machine runs, where the configuration says it; ``default_list``:
    the machine reads this list as a default list (an XML list says so by its root element itself)."""
    ctx = Context.of(doc, registry, kind)
    ctx.severities = severities
    ctx.kernel = kernel
    ctx.default_list = default_list or (doc.origin is not None and doc.origin.default_list)
    if any(p.kind == "binary" for p in doc.problems):  # one root cause, one finding
        return ctx, funnel(doc.path, [d for d in syntax.check_problems(ctx) if d.code == "S013"], severities)
    found = run_checks(CHECKS, ctx)
    found.extend(extra)
    # noqa=False (--ignore-noqa): the suppression directives written in the list are not applied
    kept = funnel(doc.path, found, severities, suppress.parse_directives(doc, declared_codes()) if noqa else None)
    said = {(d.span.line, d.param_id) for d in kept if d.kernel_error is not None}
    if said:  # one root cause, one finding: the kernel's own start-up error (not suppressed) says it
        kept = [d for d in kept if d.code not in ("R005", "R006") or (d.span.line, d.param_id) not in said]
    return ctx, kept

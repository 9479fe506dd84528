"""N rules: NC programs (``zero lint program.nc``; N003/N004 with the machine they run on).

The program is read by :mod:`zero.nc.program`; these checks say what the controller
does with its ``#MACHINE DATA`` blocks and its programmed soft limits (G98/G99).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from zero.catalog.ids import LENGTH_UNIT, RANGE_CHECK_PROG_LIMITS, SWE_NEG, SWE_POS, fixed
from zero.diagnostics import Diagnostic, Severity, Span
from zero.lists.tokenizer import tokenize
from zero.rules import registry, syntax
from zero.rules.base import E, Family, ProgramContext, W

if TYPE_CHECKING:  # start-up: a list's lint does not load the machine model
    from zero.machine.model import Axis
from zero.rules.lists import check_document

FAMILY: Family[ProgramContext] = Family("N", "NC programs", "program")


def _span(line: int, start: int, end: int) -> Span:
    return Span.on_line(line, start, max(end, start + 1))


MACHINE_DATA_SYNTAX = FAMILY.rule(
    "N001", "machine-data-syntax", E, "A #MACHINE DATA block the controller rejects",
    """
What it checks: `#MACHINE DATA [SYN] [AX=<name> | AXNR=<n>  <P-AXIS-id>[.<idx>]=<value> |
AXPARAM="<key> <value>" [WAIT]]`: one axis (AX= or a positive AXNR=), a parameter ID that
#MACHINE DATA accepts as a keyword, an AXPARAM key and value valid for the axis list, WAIT only
with SYN.

Why it matters on the machine: the block is rejected at run time, in the middle of a program,
or (AXNR is not checked by the controller) writes the parameter of another axis.

Example: `#MACHINE DATA [AX=X P-AXIS-00209=80000 WAIT]` (WAIT without SYN)
Fix: write the block as in the manual's examples.
""")

# AXPARAM's key and value are checked like an entry of an axis list, by the S and R rules
# (not R007/R008, which need a whole list).
_AXPARAM_RULES = {code: rule.severity for family in (syntax.FAMILY, registry.FAMILY)
                  for code, rule in family.rules.items() if code not in ("R007", "R008")}


def check_axparam(text: str, ctx: ProgramContext) -> list[str]:
    """AXPARAM's ``"<key> <value>"``: the key known in the axis list, the value valid for it."""
    parts = text.split(None, 1)
    if len(parts) != 2:
        return [f"AXPARAM=\"{text}\" needs a key and a value (\"kenngr.swe_pos 15000000\")"]
    doc = tokenize(f"{parts[0]} {parts[1]}\n".encode("utf-8", "surrogateescape"), "axparam.lis")
    _, found = check_document(doc, ctx.registry, "AXIS", _AXPARAM_RULES)
    return [f"AXPARAM: {d.message}" for d in found if d.severity >= Severity.WARNING]


@FAMILY.check(MACHINE_DATA_SYNTAX)
def check_machine_data(ctx: ProgramContext) -> Iterator[Diagnostic]:
    """N001: the form of each #MACHINE DATA block, and the parameters it writes."""
    for md in ctx.program.machine_data:
        problems = [*md.problems, *((m, a, b) for text, a, b in md.axparams for m in check_axparam(text, ctx))]
        for message, a, b in problems:
            tail = "" if message.startswith(("AXPARAM:", "AXNR=")) else ": the controller rejects the block"
            yield ctx.report("N001", _span(md.line, a, b), f"#MACHINE DATA {message}{tail}")


MACHINE_DATA_AFTER_SOFT_LIMITS = FAMILY.rule(
    "N002", "machine-data-after-soft-limits", W, "#MACHINE DATA after G98/G99 discards them",
    """
What it checks: a #MACHINE DATA block after G98 or G99 in the same program.

Why it matters on the machine: writing any machine data reloads the whole axis list into the
channel; soft limits programmed with G98/G99 before are silently gone, and the axis runs with
the configured ones again.

Fix: program G98/G99 again after #MACHINE DATA, or write the machine data first.
""")


@FAMILY.check(MACHINE_DATA_AFTER_SOFT_LIMITS)
def check_machine_data_order(ctx: ProgramContext) -> Iterator[Diagnostic]:
    """N002: the first #MACHINE DATA after G98/G99."""
    limits = ctx.program.limits
    if not limits:
        return
    first = limits[0]
    for md in ctx.program.machine_data:
        if md.line > first.line:
            yield ctx.report("N002", _span(md.line, md.start, md.end),
                             f"#MACHINE DATA after G98/G99 (line {first.line}): writing machine data reloads "
                             "the whole axis list and silently discards the programmed soft limits")
            return


PROGRAMMED_LIMIT_WIDENS = FAMILY.rule(
    "N003", "programmed-limit-widens", W, "G98/G99 widen the soft limits while that is not allowed",
    """
What it checks: with `range_check_prog_soft_limits` 1 (P-CHAN-00498), a soft limit programmed with
G98 below `swe_neg` or with G99 above `swe_pos` (G90 absolute, G91 relative to the configured limit).

Why it matters on the machine: the controller warns (P-ERR-21648 / P-ERR-21650) and keeps the
configured limit: the program does not run in the range its author expected.

Fix: stay inside the configured limits, or allow widening (P-CHAN-00498 0) deliberately.
""")
PROGRAMMED_LIMITS_CROSSED = FAMILY.rule(
    "N004", "programmed-limits-crossed", E, "G98/G99 put the negative limit at or above the positive",
    """
What it checks: a negative soft limit programmed with G98 at or above the configured positive one,
or a positive one programmed with G99 at or below the configured negative one.

Why it matters on the machine: error P-ERR-21649 / P-ERR-21878: the value is not taken over and
the controller resets, stopping the program.

Fix: check sign and unit of the programmed value (G98 sets the negative, G99 the positive limit).
""")


@FAMILY.check(PROGRAMMED_LIMIT_WIDENS, PROGRAMMED_LIMITS_CROSSED)
def check_programmed_limits(ctx: ProgramContext) -> Iterator[Diagnostic]:
    """N003, N004: G98/G99 against the configured soft limits of each named axis."""
    machine = ctx.machine
    if machine is None:
        return
    by_name: dict[str, Axis] = {}
    axes = machine.axes()
    limited = False
    for ch in machine.channels:
        if ch.lists is not None:
            limited = limited or bool(ch.lists.number(RANGE_CHECK_PROG_LIMITS))
        for ca in ch.axes:
            ax = axes.get(ca.log_nr)
            if ax is not None:
                by_name.setdefault(ca.name.upper(), ax)
    for lim in ctx.program.limits:
        ax = by_name.get(lim.axis)
        if ax is None:
            continue
        base = ax.swe_pos if lim.positive else ax.swe_neg
        new = (base + lim.value * LENGTH_UNIT) if lim.relative else lim.value * LENGTH_UNIT
        u = ax.unit
        shown = fixed(new, u)
        span = _span(lim.line, lim.start, lim.end)
        if lim.positive and new <= ax.swe_neg:
            yield ctx.report("N004", span,
                             f"P-ERR-21878: G99 sets the positive soft limit of {lim.axis} to {shown}, not above "
                             f"the configured negative one ({fixed(ax.swe_neg, u)}): not taken over, the "
                             "controller resets", param_id=SWE_POS)
        elif lim.positive and limited and new > ax.swe_pos:
            yield ctx.report("N003", span,
                             f"P-ERR-21650: G99 widens the positive soft limit of {lim.axis} to {shown} beyond "
                             f"the configured {fixed(ax.swe_pos, u)} while range_check_prog_soft_limits is 1: "
                             "not taken over", param_id=SWE_POS)
        elif not lim.positive and new >= ax.swe_pos:
            yield ctx.report("N004", span,
                             f"P-ERR-21649: G98 sets the negative soft limit of {lim.axis} to {shown}, not below "
                             f"the configured positive one ({fixed(ax.swe_pos, u)}): not taken over, the "
                             "controller resets", param_id=SWE_NEG)
        elif not lim.positive and limited and new < ax.swe_neg:
            yield ctx.report("N003", span,
                             f"P-ERR-21648: G98 widens the negative soft limit of {lim.axis} to {shown} beyond "
                             f"the configured {fixed(ax.swe_neg, u)} while range_check_prog_soft_limits is 1: "
                             "not taken over", param_id=SWE_NEG)

"""N rules: NC programs (``zero lint program.nc``; with the machine they run on, N003–N006).

The program is read by :mod:`zero.nc.program` (``#MACHINE DATA``, G98/G99) and followed by
:mod:`zero.nc.motion` (its words, control structures, calls and moves); these checks say what
the controller does with them, and N010 says what zero could not follow.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from pathlib import Path

from zero.catalog.ids import (
    AXIS_TYPE,
    DEFAULT_INDEX,
    G53_AVAILABLE,
    INACTIVE,
    LENGTH_UNIT,
    OFFSET,
    RANGE_CHECK_PROG_LIMITS,
    SWE_BEHAVIOUR,
    SWE_CHECK,
    SWE_NEG,
    SWE_POS,
    fixed,
    g_code,
)
from zero.diagnostics import Diagnostic, Related, Severity, Span
from zero.errors import ZeroError
from zero.files import read_file
from zero.lists.encoding import decode
from zero.lists.tokenizer import tokenize
from zero.nc import language as lang
from zero.records import Record
from zero.rules import elements, registry, syntax
from zero.rules.base import INFO, Check, Context, E, Family, ProgramContext, W, run_checks

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: a list's lint does not load the machine model
    from typing import Any

    from zero.catalog.registry import Registry
    from zero.machine.model import Axis, Channel, Machine
    from zero.nc.program import Program

MOD_CALC = "P-AXIS-00121"  # kenngr.mod_rechng: the axis counts modulo
SOFT_LIMIT_WARNING_AXES = "P-CHAN-00147"  # soft_limit_warning_axes: bit j, channel axis j only warns
PROG_START_G = "P-CHAN-00063"  # prog_start.g_gruppe[i].nr: the G code of group i at program start
PROGRAM_PATH = "P-STUP-00018"  # pfad[].prg[]: the controller's program paths

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

# AXPARAM's key and value are checked like an entry of an axis list, by the S and R checks (not
# R007/R008, which need a whole list): what they say is this check's reading, its N001 the finding
assert elements.FAMILY is syntax.FAMILY  # the S rules on XML elements are the syntax family's
_AXPARAM_RULES = {code: rule.severity for family in (syntax.FAMILY, registry.FAMILY)
                  for code, rule in family.rules.items() if code not in ("R007", "R008")}
_AXPARAM_CHECKS: list[Check[Context]] = [*syntax.FAMILY.checks, *registry.FAMILY.checks]


def check_axparam(text: str, ctx: ProgramContext) -> list[str]:
    """AXPARAM's ``"<key> <value>"``: the key known in the axis list, the value valid for it."""
    parts = text.split(None, 1)
    if len(parts) != 2:
        return [f"AXPARAM=\"{text}\" needs a key and a value (\"kenngr.swe_pos 15000000\")"]
    doc = tokenize(f"{parts[0]} {parts[1]}\n".encode("utf-8", "surrogateescape"), "axparam.lis")
    entry = Context.of(doc, ctx.registry, "AXIS")
    entry.severities = _AXPARAM_RULES
    found = sorted((d for d in run_checks(_AXPARAM_CHECKS, entry) if d.code in _AXPARAM_RULES), key=Diagnostic.sort_key)
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
""", reads=("P-CHAN-00498", "P-AXIS-00177", "P-AXIS-00178", "P-CHAN-00006", "P-CHAN-00035", "P-AXIS-00016"))
PROGRAMMED_LIMITS_CROSSED = FAMILY.rule(
    "N004", "programmed-limits-crossed", E, "G98/G99 put the negative limit at or above the positive",
    """
What it checks: a negative soft limit programmed with G98 at or above the configured positive one,
or a positive one programmed with G99 at or below the configured negative one.

Why it matters on the machine: error P-ERR-21649 / P-ERR-21878: the value is not taken over and
the controller resets, stopping the program.

Fix: check sign and unit of the programmed value (G98 sets the negative, G99 the positive limit).
""", reads=("P-AXIS-00177", "P-AXIS-00178", "P-CHAN-00006", "P-CHAN-00035", "P-AXIS-00016"))


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


# --------------------------------------------------------------------------- the program's moves

SOFT_LIMIT_CROSSED = FAMILY.rule(
    "N005", "soft-limit-crossed", E, "A move beyond a soft limit the controller monitors",
    f"""
What it checks: with the machine the program runs on (`zero lint prog.nc --machine STARTUP`, or
`machine` in the configuration), zero follows the program's positions (G90/G91, G0-G3 end
points and the extent of arcs, G17/G18/G19, G70/G71, the work offsets G53-G59 and G159=n of
the zero-offset list with `g53_verfuegbar` and `inaktiv`, G98/G99, POS_LIMIT, and P-parameters
and V. variables with literal values) on the first channel's axes. A target whose position on
the axis (programmed position plus the active work offset) lies beyond `kenngr.swe_neg` or
`kenngr.swe_pos` (or a limit the program set) is reported at its line, with the programmed
and the machine position, the limit with its list line and the offset with its line.

Why it matters on the machine: the controller checks commanded positions against the soft
limits in path preparation. With `swe_behaviour` ERROR (the default) it does not execute the
block and aborts the program ({lang.SOFT_LIMIT_ERRORS}; {lang.SOFT_LIMIT_SOURCE}); with
ERROR_LR path preparation only warns and the position controller stops the axis with an
error. Monitoring applies once the axis is referenced (or has an absolute measuring system).
zero checks the programmed point: tool length and radius offsets are not added.

Example: `N30 G54 G1 X1600` with `kenngr.swe_pos 15000000` (1500 mm) on X.
Fix: correct the program or the work offset; the limits are the machine's.
""", reads=("P-AXIS-00177", "P-AXIS-00178", "P-AXIS-00554", "P-AXIS-00705", "P-ZERO-00003", "P-ZERO-00004",
           "P-ZERO-00001", "P-ZERO-00002", "P-CHAN-00006", "P-CHAN-00035", "P-AXIS-00016", "P-CHAN-00063",
           "P-CHAN-00498", "P-AXIS-00018"))
SOFT_LIMIT_UNMONITORED = FAMILY.rule(
    "N006", "soft-limit-unmonitored", W, "A move beyond a soft limit nobody monitors",
    """
What it checks: the moves N005 checks, on an axis whose soft limits the controller does not
enforce: `swe_check 0` (P-AXIS-00705), `swe_behaviour WARNING` (P-AXIS-00554), the axis's bit
in `soft_limit_warning_axes` (P-CHAN-00147), or `POS_LIMIT OFF` in the program. A modulo axis
(`kenngr.mod_rechng`, or a spindle) with `swe_check -1` turns without end: the controller does
not monitor its soft limits and zero reports no position of it.

Why it matters on the machine: the axis moves past its soft limit unchecked (or with a warning
only): towards the hardware limit switch or into the machine's structure.

Fix: correct the program or the work offset; switch monitoring on where the axis has limits.
""", reads=("P-AXIS-00705", "P-AXIS-00554", "P-CHAN-00147", "P-AXIS-00121", "P-AXIS-00018", "P-AXIS-00177",
           "P-AXIS-00178", "P-ZERO-00003", "P-ZERO-00004", "P-ZERO-00001", "P-ZERO-00002", "P-CHAN-00006",
           "P-CHAN-00035", "P-AXIS-00016"))
UNKNOWN_WORD = FAMILY.rule(
    "N007", "unknown-word", W, "A word the ISG NC language does not have",
    """
What it checks: every word of every block: address letters with a value (`X12.5`, `XP1`,
`X[P1+2]`, `S1=1000`), block numbers and labels, `$` control keywords, `#` commands, `V.`
variables, P-parameters, `L`/`LL` calls, strings and comments. What is none of these (a typo,
`test`, `.....`), an unknown `$` keyword or an unknown `#` command is reported. The words come
from the vendor's programming manual and the grammar of its VS Code extension.

Why it matters on the machine: the decoder has no meaning for the word; zero cannot say what
the controller does with the block and does not guess.

Fix: correct the spelling, or make the text a comment (`;` or `( … )`).
""")
UNBALANCED_CONTROL = FAMILY.rule(
    "N008", "unbalanced-control-structure", W, "$IF, $WHILE, $FOR, $SWITCH, $DO, $REPEAT without their end",
    """
What it checks: each `$IF` is closed by `$ENDIF` (with `$ELSEIF`/`$ELSE` only inside it),
`$WHILE` by `$ENDWHILE`, `$FOR` by `$ENDFOR`, `$SWITCH` by `$ENDSWITCH` (`$CASE`/`$DEFAULT`
inside), `$DO` by `$ENDDO`, `$REPEAT` by `$UNTIL`, within one program part (`%`); an end
without its opening is reported too. `$IF <condition> $GOTO <target>` is one block.

Why it matters on the machine: the programming manual pairs these keywords; a program that
does not is not the program its author meant. zero has no documented error number for it.

Fix: add the missing end (or remove the stray one).
""")
SUBPROGRAM_NOT_FOUND = FAMILY.rule(
    "N009", "subprogram-not-found", W, "A subprogram call zero cannot resolve",
    """
What it checks: `L name` (a global subprogram) is a file in the program's folder or in a
program path of the machine's start-up list (`pfad[].prg[]`), names compared as the
controller's file system would (without case); `LL name` is a local subprogram (`%L name`)
of the same file.

Why it matters on the machine: the controller aborts where it cannot find the subprogram;
zero can only say that it did not find it in the folders it searched (the controller's own
program paths may hold it).

Fix: correct the name, or keep the subprogram beside the program.
""", reads=("P-STUP-00018",))
MOVES_NOT_EVALUATED = FAMILY.rule(
    "N010", "moves-not-evaluated", INFO, "Moves zero did not check against the soft limits",
    """
What it checks: what zero could not follow, counted per reason with its first line:
computed positions, `#TRAFO`, `#CS`, `#ACS`, `#RTCP` and other transformations, mirroring,
moves after a subprogram call or a jump target until the program sets G90/G91 and the work
offset again, relative moves from an unknown position, G92 presets, diameter programming,
G codes zero does not follow, what a loop changes per iteration, local subprograms, calls of
subprograms (whose moves zero does not read), and moves when no machine is given.

Why it matters on the machine: a program with no finding is only known to stay inside the
soft limits where zero followed it; this finding says where it did not, so that "clean" is
never claimed for what was not checked.

Fix: nothing to fix in the program; give the machine, or check these moves another way.
""")

if TYPE_CHECKING:  # start-up: a list's lint does not load the program model
    from zero.nc.motion import Analysis, Crossing, Setup

MAX_CROSSINGS = 10  # findings per axis and side before one finding counts the rest


class _AxisFacts(Record):
    """What the messages say about one channel axis: its list lines and its monitoring."""

    name: str
    unit: str
    code: str  # N005 or N006
    behaviour: str  # what the controller does
    path: str
    neg: tuple[str, int | None]  # (key, line in the axis list)
    pos: tuple[str, int | None]
    kernel_error: str | None = None


def _setup(machine: Machine) -> tuple[Setup, list[_AxisFacts], Channel] | None:
    """The first channel with axes: its axes, limits, offsets and start state, for the follower."""
    from zero.nc.motion import AxisSetup, Setup  # start-up: programs only

    ch = next((c for c in machine.channels if c.axes), None)
    if ch is None:
        return None
    axes = machine.axes()
    zl = ch.zero
    g53 = bool(zl.number(G53_AVAILABLE)) if zl is not None else False
    default_group = int(zl.number(DEFAULT_INDEX) or 0) if zl is not None else 0
    warn_bits = int(ch.lists.number(SOFT_LIMIT_WARNING_AXES) or 0) if ch.lists is not None else 0
    out: list[AxisSetup] = []
    facts: list[_AxisFacts] = []
    for ca in ch.axes:
        ax = axes.get(ca.log_nr)
        if ax is None:
            out.append(AxisSetup(ca.name.upper(), -math.inf, math.inf))
            facts.append(_AxisFacts(ca.name, "mm", "N006", "", "", ("", None), ("", None)))
            continue
        lf = ax.list
        check = lf.number(SWE_CHECK)
        behaviour = (lf.text(SWE_BEHAVIOUR) or "ERROR").strip().upper()
        modulo = ax.rotary and (bool(lf.number(MOD_CALC)) or lf.number(AXIS_TYPE) == 4)
        where = f"{lf.path.name}"
        kernel: str | None = None
        if check == 0:
            code, what = "N006", f"the axis moves past its limit unchecked: `swe_check 0` switches its soft-limit " \
                                 f"monitoring off ({where})"
        elif behaviour == "WARNING":
            code, what = "N006", f"the axis moves past its limit: with `swe_behaviour WARNING` ({where}) the " \
                                 "controller only warns"
        elif warn_bits >> ca.index & 1:
            code, what = "N006", "the axis moves past its limit: its bit in `soft_limit_warning_axes` " \
                                 "(P-CHAN-00147) makes the controller only warn and go on machining"
        elif behaviour == "ERROR_LR":
            code, what = "N005", f"path preparation only warns (`swe_behaviour ERROR_LR`, {where}); the " \
                                 "position controller stops the axis with an error"
        else:
            code, what = "N005", f"the controller does not execute the block and aborts the program " \
                                 f"({lang.SOFT_LIMIT_ERRORS})"
            kernel = lang.SOFT_LIMIT_ERRORS
        neg_entry, pos_entry = lf.entry(SWE_NEG), lf.entry(SWE_POS)
        facts.append(_AxisFacts(ca.name, ax.unit, code, what, str(lf.path),
                                ("kenngr.swe_neg", neg_entry.line if neg_entry else None),
                                ("kenngr.swe_pos", pos_entry.line if pos_entry else None), kernel))
        if modulo and check != 1:  # it turns without end: its soft limits bound no travel
            out.append(AxisSetup(ca.name.upper(), -math.inf, math.inf, ax.rotary))
        else:
            out.append(AxisSetup(ca.name.upper(), ax.swe_neg / LENGTH_UNIT, ax.swe_pos / LENGTH_UNIT, ax.rotary))
    offsets: dict[int, tuple[float, ...]] = {}
    if zl is not None:
        groups = {ix[0] for ix in zl.values.by_id.get(OFFSET, {}) if ix}
        for g in groups:
            row = []
            for ca in ch.axes:
                raw = zl.number(OFFSET, (g, ca.index)) or 0
                masked = bool(zl.number(INACTIVE, (g, ca.index)))
                row.append(0.0 if masked or (g == 0 and not g53) else raw / LENGTH_UNIT)
            offsets[g] = tuple(row)

    def start(group: int, default: int) -> int:
        v = ch.lists.number(PROG_START_G, (group,)) if ch.lists is not None else None
        return int(v) if v is not None and v >= 0 else default

    setup = Setup(out, offsets, default_group, absolute=start(14, 90) != 91, plane=start(4, 17),
                  inch=start(12, 71) == 70, centre_absolute=start(23, 162) == 161, diameter=start(8, 52) == 51,
                  range_check=bool(ch.lists.number(RANGE_CHECK_PROG_LIMITS)) if ch.lists is not None else False)
    return setup, facts, ch


_last: list[Any] = []  # the last program followed: its checks share one analysis (program, machine, path, result)


def analysis(ctx: ProgramContext) -> tuple[Analysis, tuple[Setup, list[_AxisFacts], Channel] | None]:
    """The program followed once per context (against the machine when there is one)."""
    last = _last
    if last and last[0] is ctx.program and last[1] is ctx.machine and last[2] == ctx.path:
        return last[3]  # type: ignore[no-any-return]
    from zero.nc.motion import follow  # start-up: programs only

    built = _setup(ctx.machine) if ctx.machine is not None else None
    machine_data = {md.line: [(md.axis or "", text) for text, _, _ in md.axparams] for md in ctx.program.machine_data}
    result = (follow(ctx.program.doc.lines, built[0] if built else None, machine_data, _resolver(ctx)), built)
    _last[:] = [ctx.program, ctx.machine, ctx.path, result]
    return result


def program_travel(program: Program, registry: Registry, machine: Machine,
                   path: str) -> tuple[int, dict[int, tuple[float, float]]] | None:
    """Where the program takes each axis of the machine's first channel: the channel's index and, by
    channel axis index, the lowest and highest position on the axis (zero report --program)."""
    found, built = analysis(ProgramContext(program, registry, machine, {}, path))
    if built is None:
        return None
    ch = built[2]
    return ch.index, {ch.axes[i].index: (low, high) for i, (low, high) in found.travel.items() if i < len(ch.axes)}


def _offset_where(ch: Channel, group: int, index: int, g53: bool) -> str:
    zl = ch.zero
    code = g_code(group)
    if zl is None:
        return f"{code}: no zero-offset list"
    if group == 0 and not g53:
        return f"{code} applies no offset (g53_verfuegbar 0)"
    if zl.number(INACTIVE, (group, index)):
        return f"{code} masked for this axis (inaktiv 1)"
    entry = zl.entry(OFFSET, (group, index))
    key = f"np_grp[{group}].achse[{index}].versch"
    return f"{code} {key}, {zl.path.name}:{entry.line}" if entry is not None else f"{code} {key} not set (0)"


@FAMILY.check(SOFT_LIMIT_CROSSED, SOFT_LIMIT_UNMONITORED)
def check_moves(ctx: ProgramContext) -> Iterator[Diagnostic]:
    """N005, N006: targets beyond the soft limits, by what the controller does there."""
    if ctx.machine is None:
        return
    found, built = analysis(ctx)
    if built is None:
        return
    setup, facts, ch = built
    g53 = bool(ch.zero.number(G53_AVAILABLE)) if ch.zero is not None else False
    worst: dict[tuple[int, int, bool], Crossing] = {}
    for c in found.crossings:  # one finding per line, axis and side: the farthest point
        key = (c.line, c.axis, c.positive)
        old = worst.get(key)
        if old is None or abs(c.machine - c.limit) > abs(old.machine - old.limit):
            worst[key] = c
    counts: dict[tuple[int, bool], list[Crossing]] = {}
    for c in sorted(worst.values(), key=lambda c: (c.line, c.start)):
        counts.setdefault((c.axis, c.positive), []).append(c)
    for (axis, positive), crossings in counts.items():
        f = facts[axis]
        for c in crossings[:MAX_CROSSINGS]:
            yield _crossing(ctx, c, f, _offset_where(ch, c.group, axis, g53), setup)
        rest = crossings[MAX_CROSSINGS:]
        if rest:
            c = rest[0]
            side = "positive" if positive else "negative"
            code = "N006" if c.unmonitored else f.code
            yield ctx.report(code, _span(c.line, c.start, c.end),
                             f"{len(rest)} more moves of {f.name} beyond its {side} soft limit from here to line "
                             f"{rest[-1].line} (zero reports the first {MAX_CROSSINGS} of each axis and side)")


def _crossing(ctx: ProgramContext, c: Crossing, f: _AxisFacts, offset_where: str, setup: Setup) -> Diagnostic:
    u = f.unit
    side = "positive" if c.positive else "negative"
    key, line = f.pos if c.positive else f.neg
    if c.limit_from:
        limit_where = f"programmed with {c.limit_from}"
    elif line is not None:
        limit_where = f"{key}, {Path(f.path).name}:{line}"
    else:
        limit_where = f"{key} default"
    code, behaviour, kernel = f.code, f.behaviour, f.kernel_error
    if c.unmonitored:
        code, behaviour, kernel = "N006", f"the axis moves past its limit unchecked: {c.unmonitored}", None
    via = f"{c.via}: " if c.via else ""
    moved = f"the arc passes {f.name}" if c.arc else f"{f.name} goes to"
    message = (f"{via}{moved} {c.programmed:.3f} {u} in {g_code(c.group)}, {c.machine:.3f} {u} on the axis "
               f"(offset {c.offset:.3f} {u}: {offset_where}), beyond the {side} soft limit {c.limit:.3f} {u} "
               f"({limit_where}): {behaviour}")
    related: tuple[Related, ...] = ()
    if line is not None and not c.limit_from and f.path:
        related = (Related(Span.on_line(line, 0, 1), f"the {side} soft limit of {f.name}", f.path),)
    return ctx.report(code, _span(c.line, c.start, c.end), message, param_id=SWE_POS if c.positive else SWE_NEG,
                      related=related, kernel_error=kernel if code == "N005" else None)


@FAMILY.check(UNKNOWN_WORD, UNBALANCED_CONTROL)
def check_language(ctx: ProgramContext) -> Iterator[Diagnostic]:
    """N007, N008: words the language does not have, control structures without their end."""
    found, _ = analysis(ctx)
    lines = ctx.program.doc.lines
    for w in found.unknown:
        text = lines[w.line - 1][w.start:w.end] if w.line <= len(lines) else w.text
        if w.kind == "$":
            message = f"`{text}` is no control keyword of the ISG NC language ($IF, $WHILE, $FOR, $SWITCH, $GOTO, …)"
        elif w.kind == "#":
            message = f"`{text}` is no #-command of the ISG NC language as zero knows it (the vendor's programming " \
                      "manual and its VS Code grammar)"
        else:
            message = f"`{text}` is no word of the ISG NC language (an address letter with a value, a keyword, a " \
                      "variable or a call); zero cannot say what the controller does with the block"
        yield ctx.report("N007", _span(w.line, w.start, w.end), message)
    for line, start, end, message in found.structure:
        if line > len(lines):
            line, start, end = len(lines) or 1, 0, 1
        yield ctx.report("N008", _span(line, start, end), message)


@FAMILY.check(SUBPROGRAM_NOT_FOUND)
def check_calls(ctx: ProgramContext) -> Iterator[Diagnostic]:
    """N009: L calls not in the searched folders, LL calls of no local subprogram."""
    from zero.nc.motion import find_subprogram  # start-up: programs only

    found, _ = analysis(ctx)
    dirs = _search_dirs(ctx)
    for call in found.calls:
        if call.cycle or not call.name:
            continue
        if call.local:
            if call.name.upper() not in found.locals:
                yield ctx.report("N009", _span(call.line, call.start, call.end),
                                 f"LL {call.name}: no local subprogram `%L {call.name}` in this file")
            continue
        if not dirs or find_subprogram(call.name, dirs) is not None:
            continue
        shown = ", ".join(dirs[:3]) + (f" and {len(dirs) - 3} more" if len(dirs) > 3 else "")
        yield ctx.report("N009", _span(call.line, call.start, call.end),
                         f"L {call.name}: no such file in the folders zero searched ({shown}); the controller "
                         "aborts where its program paths do not hold it either")


def _resolver(ctx: ProgramContext) -> Callable[[str], list[str] | None]:
    """The lines of a called global subprogram, from the folders N009 searches."""
    from zero.nc.motion import find_subprogram  # start-up: programs only

    dirs = _search_dirs(ctx)

    def resolve(name: str) -> list[str] | None:
        path = find_subprogram(name, dirs) if dirs else None
        if path is None:
            return None
        try:
            data = read_file(Path(path))
        except ZeroError:
            return None
        return decode(data)[0].splitlines()

    return resolve


def _search_dirs(ctx: ProgramContext) -> list[str]:
    """The program's folder, then the program paths of the machine's start-up list."""
    if ctx.path in ("-", "") or ctx.path.startswith("<"):
        return []
    dirs = [str(Path(ctx.path).parent)]
    if ctx.machine is not None:
        st = ctx.machine.startup
        for _, res in sorted(st.values.by_id.get(PROGRAM_PATH, {}).items()):
            raw = res.value.text if res.value.text is not None else res.entry.value
            if raw:
                p = Path(raw)
                dirs.append(str(p if p.is_absolute() else ctx.machine.workdir / p))
    return dirs


@FAMILY.check(MOVES_NOT_EVALUATED)
def check_coverage(ctx: ProgramContext) -> Iterator[Diagnostic]:
    """N010: what zero did not follow, counted, at the first such line."""
    found, _ = analysis(ctx)
    parts: list[str] = []
    first: int | None = None
    n = found.not_evaluated
    if n:
        reasons = sorted(found.skipped.items(), key=lambda kv: kv[1][1])
        first = reasons[0][1][1]
        shown = [(reason if "line" in reason or reason.startswith("no machine") else f"{reason} (line {line} first)")
                 + (f": {count}" if len(reasons) > 1 else "")
                 for reason, (count, line) in reasons[:8]]
        if len(reasons) > 8:
            shown.append(f"{len(reasons) - 8} more reasons")
        what = "checked against soft limits" if not found.machine else "evaluated"
        total = f"{n} of {found.moves}" if n != found.moves else f"{n}"
        parts.append(f"{total} move{'s' if n != 1 else ''} not {what}: " + "; ".join(shown))
    calls = found.not_followed
    if calls:
        c = calls[0]
        call = f"{'LL' if c.local else 'L'} {'CYCLE ' if c.cycle else ''}{c.name}".rstrip()
        parts.append(f"{len(calls)} subprogram call{'s' if len(calls) != 1 else ''} not followed into ({call} at "
                     f"line {c.line} first: zero does not read cycles, nor files it did not find)")
        first = c.line if first is None else min(first, c.line)
    if found.unfollowed and found.machine:
        what, line = found.unfollowed[0]
        parts.append(f"{len(found.unfollowed)} G code{'s' if len(found.unfollowed) != 1 else ''} zero does not "
                     f"follow ({what} at line {line} first)")
        first = line if first is None else min(first, line)
    if not parts or first is None:
        return
    lines = ctx.program.doc.lines
    end = len(lines[first - 1].rstrip()) if 0 < first <= len(lines) else 1
    yield ctx.report("N010", _span(first, 0, end), "; ".join(parts))


# codes whose findings mean a program was not (fully) evaluated: the summary counts them apart from "clean"
NOT_EVALUATED = frozenset({"N010"})

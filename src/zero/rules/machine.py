"""X rules: what the lists of one machine mean together (``zero lint --machine``).

They read a :class:`~zero.machine.model.Machine` (start-up list, channel lists, axis
lists, zero-offset lists) and report on the line of the list that carries the fault.
"""

from __future__ import annotations

from collections.abc import Iterator

from zero.catalog.ids import AXIS_NAME, AXIS_NR, FULL_TURN, G53_AVAILABLE, INACTIVE, OFFSET, fixed, g_code
from zero.catalog.ranges import TYPE_LIMITS
from zero.diagnostics import Diagnostic, Span
from zero.machine.model import axis_of
from zero.rules.base import E, Family, MachineContext, W

FAMILY: Family[MachineContext] = Family("X", "machine (across lists, `zero lint --machine`)", "machine")
SGN32 = TYPE_LIMITS["SGN32"]

MISSING_LIST = FAMILY.rule(
    "X005", "missing-list", E, "The start-up list names a list that does not exist",
    """
What it checks: every `achs_mds[i]`, `sda_mds[c]` and `nullp_data[c]` of the start-up list names
an existing file (relative to the start-up list, its parent directory, or by file name).

Why it matters on the machine: the controller starts without that axis, channel or zero-offset
data, or refuses to start.

Fix: correct the path, or add the file.
""")


@FAMILY.check(MISSING_LIST)
def check_missing(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X005: every list the start-up list names exists."""
    startup = ctx.machine.startup
    for m in ctx.machine.missing:
        line = startup.values.doc.line_text(m.line)
        yield ctx.report("X005", Span.on_line(m.line, 0, len(line)),
                         f"`{m.key}` names `{m.raw}`, which does not exist (looked next to the start-up "
                         "list and in the directories above it): the controller starts without it",
                         path=str(startup.path))


DUPLICATE_AXIS = FAMILY.rule(
    "X004", "duplicate-axis", E, "Two axis lists claim the same logical axis",
    """
What it checks: `kopf.achs_nr` (and `kopf.log_achs_name`) differ between the axis lists of one
start-up list.

Why it matters on the machine: the controller maps a channel axis to one of them; the other
list's soft limits, gears and drive data are not the ones in effect.

Fix: give each axis list its own `kopf.achs_nr` and name.
""")
CHANNEL_AXIS_WITHOUT_LIST = FAMILY.rule(
    "X007", "channel-axis-without-list", E, "A channel axis whose axis list is missing",
    """
What it checks: every `gruppe[0].achse[j].log_achs_nr` of the channel list is the `kopf.achs_nr`
of one of the machine's axis lists.

Why it matters on the machine: the channel names an axis the controller has no data for; the
start-up fails or the axis is missing in the channel.

Fix: add the axis list to the start-up list (`achs_mds[i]`), or correct `log_achs_nr`.
""")


@FAMILY.check(DUPLICATE_AXIS, CHANNEL_AXIS_WITHOUT_LIST)
def check_axes(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X004, X007: one axis list per logical axis, and one for every channel axis."""
    machine = ctx.machine
    seen_nr: dict[int, str] = {}
    seen_name: dict[str, str] = {}
    for lf in machine.axis_lists:
        ax = axis_of(lf)
        if ax is None:
            continue
        e = lf.entry(AXIS_NR)
        span = Span.on_line(e.line, e.value_start, e.value_end) if e else Span(1, 1, 1, 1)
        if ax.nr in seen_nr:
            yield ctx.report("X004", span, f"logical axis number {ax.nr} is also claimed by "
                             f"{seen_nr[ax.nr]}: only one of the two lists is in effect", param_id=AXIS_NR,
                             path=str(lf.path))
        seen_nr.setdefault(ax.nr, str(lf.path))
        en = lf.entry(AXIS_NAME)
        if ax.name in seen_name and en is not None:
            yield ctx.report("X004", Span.on_line(en.line, en.value_start, en.value_end),
                             f"axis name `{ax.name}` is also used by {seen_name[ax.name]}", param_id=AXIS_NAME,
                             path=str(lf.path))
        seen_name.setdefault(ax.name, str(lf.path))
    axes = machine.axes()
    for ch in machine.channels:
        if ch.lists is None:
            continue
        for ca in ch.axes:
            if ca.log_nr not in axes and ca.entry is not None:
                e = ca.entry
                yield ctx.report("X007", Span.on_line(e.line, e.value_start, e.value_end),
                                 f"channel axis {ca.index} (`{ca.name}`) is logical axis {ca.log_nr}, but no "
                                 "axis list of the start-up list has that `kopf.achs_nr`", path=str(ch.lists.path))


OFFSET_OUTSIDE_SOFT_LIMITS = FAMILY.rule(
    "X001", "offset-outside-soft-limits", W, "A work offset lies outside its axis's soft limits",
    """
What it checks: an applied zero offset `np_grp[i].achse[j].versch` against the soft limits
`kenngr.swe_neg` / `kenngr.swe_pos` of the axis the channel list maps to axis j.

Why it matters on the machine: the zero point of that work offset (G54 X0, ...) lies where the
axis may not go. Every program that starts at or near the work zero stops with a soft-limit
error, or, with `swe_behaviour WARNING`, drives on.

Example: `np_grp[1].achse[0].versch 20000000` (2000 mm) with `swe_pos 15000000` (1500 mm)
Fix: correct the offset (often a sign or a factor of 10), or the soft limits.
""")
PCS_LIMIT_OVERFLOW = FAMILY.rule(
    "X002", "pcs-limit-overflow", E, "A work offset moves a soft limit beyond SGN32",
    """
What it checks: soft limit minus offset stays inside the SGN32 range the controller computes in.

Why it matters on the machine: the soft limit in the programming coordinate system cannot be
represented; the displayed limits (`display_pcs_limits`) and any check on them are wrong.

Fix: correct the offset; offsets of this size are always a data error.
""")
OFFSET_FOR_MISSING_AXIS = FAMILY.rule(
    "X003", "offset-for-missing-axis", W, "An offset for an axis the channel does not have",
    """
What it checks: a non-zero `np_grp[i].achse[j].versch` where the channel list maps no axis to j.

Why it matters on the machine: the offset is never applied; it usually belongs to another axis
index (the list was copied from another machine, or the axis order changed).

Fix: move the offset to the right axis index, or remove it.
""")
ROTARY_OFFSET_IN_MM = FAMILY.rule(
    "X006", "rotary-offset-in-mm", W, "A rotary axis with an offset that only makes sense in mm",
    """
What it checks: an applied offset of a rotary axis (`kenngr.achs_typ` rotary or spindle) larger
than a full turn (360° = 3600000 in 0.0001°).

Why it matters on the machine: the value was almost certainly written for a linear axis in
0.1 µm; on the rotary axis it turns the work zero by many revolutions.

Fix: check the axis index and the unit; a rotary offset is given in 0.0001°.
""")


@FAMILY.check(OFFSET_OUTSIDE_SOFT_LIMITS, PCS_LIMIT_OVERFLOW, OFFSET_FOR_MISSING_AXIS, ROTARY_OFFSET_IN_MM)
def check_offsets(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X001, X002, X003, X006: each applied work offset against the axis it moves."""
    machine = ctx.machine
    axes = machine.axes()
    for ch in machine.channels:
        zl = ch.zero
        if zl is None or ch.lists is None:
            continue
        path = str(zl.path)
        by_index = {ca.index: ca for ca in ch.axes}
        g53 = bool(zl.number(G53_AVAILABLE))
        for idx, res in sorted(zl.values.by_id.get(OFFSET, {}).items()):
            if len(idx) != 2 or res.value.number is None or res.value.problem is not None:
                continue
            group, j = idx
            v = res.value.number
            e = res.entry
            span = Span.on_line(e.line, e.value_start, e.value_end)
            where = f"{g_code(group)} (group {group})"
            ca = by_index.get(j)
            if ca is None:
                if v != 0:
                    yield ctx.report("X003", span, f"offset {where} for axis {j}, but the channel has no "
                                     f"axis {j}: the offset is never applied", param_id=OFFSET, path=path)
                continue
            ax = axes.get(ca.log_nr)
            masked = bool(zl.number(INACTIVE, idx))
            if ax is None or v == 0 or masked or (group == 0 and not g53):
                continue
            for side, limit in (("negative", ax.swe_neg), ("positive", ax.swe_pos)):
                pcs = limit - v
                if not SGN32[0] <= pcs <= SGN32[1]:
                    yield ctx.report("X002", span, f"offset {where} of axis `{ca.name}` moves the {side} "
                                     f"soft limit to {pcs} in the programming coordinate system, beyond SGN32",
                                     param_id=OFFSET, path=path)
            if not ax.swe_neg <= v <= ax.swe_pos:
                yield ctx.report("X001", span,
                                 f"the work zero of {where} on axis `{ca.name}` ({fixed(v, ax.unit)}) lies outside "
                                 f"its soft limits {fixed(ax.swe_neg, ax.unit)} .. {fixed(ax.swe_pos, ax.unit)} "
                                 f"({ax.list.path.name}): positions near the work zero cannot be reached",
                                 param_id=OFFSET, path=path)
            if ax.rotary and abs(v) > FULL_TURN:
                yield ctx.report("X006", span,
                                 f"offset {where} of rotary axis `{ca.name}` is {fixed(v)}° — more than "
                                 "a full turn: probably a length in 0.1 µm written for a linear axis",
                                 param_id=OFFSET, path=path)

"""X rules: what the lists of one machine mean together (``zero lint --machine``).

They need a :class:`zero.machine.Machine` (start-up list, channel list, axis lists,
zero-offset list) and report on the line that carries the fault.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from zero.diagnostics import Diagnostic, Severity, Span
from zero.ranges import TYPE_LIMITS
from zero.registry import LENGTH_UNIT as ZERO_UNIT
from zero.rules.base import Rule, rule

if TYPE_CHECKING:
    from zero.machine import Machine

OFFSET = "P-ZERO-00003"

E, W = Severity.ERROR, Severity.WARNING

RULES: dict[str, Rule] = {
    r.code: r
    for r in (
        rule("X001", "offset-outside-soft-limits", W, "A work offset lies outside its axis's soft limits",
             """
What it checks: an applied zero offset `np_grp[i].achse[j].versch` against the soft limits
`kenngr.swe_neg` / `kenngr.swe_pos` of the axis the channel list maps to axis j.

Why it matters on the machine: the zero point of that work offset (G54 X0, ...) lies where the
axis may not go. Every program that starts at or near the work zero stops with a soft-limit
error, or, with `swe_behaviour WARNING`, drives on.

Example: `np_grp[1].achse[0].versch 20000000` (2000 mm) with `swe_pos 15000000` (1500 mm)
Fix: correct the offset (often a sign or a factor of 10), or the soft limits.
"""),
        rule("X002", "pcs-limit-overflow", E, "A work offset moves a soft limit beyond SGN32",
             """
What it checks: soft limit minus offset stays inside the SGN32 range the controller computes in.

Why it matters on the machine: the soft limit in the programming coordinate system cannot be
represented; the displayed limits (`display_pcs_limits`) and any check on them are wrong.

Fix: correct the offset; offsets of this size are always a data error.
"""),
        rule("X003", "offset-for-missing-axis", W, "An offset for an axis the channel does not have",
             """
What it checks: a non-zero `np_grp[i].achse[j].versch` where the channel list maps no axis to j.

Why it matters on the machine: the offset is never applied; it usually belongs to another axis
index (the list was copied from another machine, or the axis order changed).

Fix: move the offset to the right axis index, or remove it.
"""),
        rule("X004", "duplicate-axis", E, "Two axis lists claim the same logical axis",
             """
What it checks: `kopf.achs_nr` (and `kopf.log_achs_name`) differ between the axis lists of one
start-up list.

Why it matters on the machine: the controller maps a channel axis to one of them; the other
list's soft limits, gears and drive data are not the ones in effect.

Fix: give each axis list its own `kopf.achs_nr` and name.
"""),
        rule("X005", "missing-list", E, "The start-up list names a list that does not exist",
             """
What it checks: every `achs_mds[i]`, `sda_mds[c]` and `nullp_data[c]` of the start-up list names
an existing file (relative to the start-up list, its parent directory, or by file name).

Why it matters on the machine: the controller starts without that axis, channel or zero-offset
data, or refuses to start.

Fix: correct the path, or add the file.
"""),
        rule("X006", "rotary-offset-in-mm", W, "A rotary axis with an offset that only makes sense in mm",
             """
What it checks: an applied offset of a rotary axis (`kenngr.achs_typ` rotary or spindle) larger
than a full turn (360° = 3600000 in 0.0001°).

Why it matters on the machine: the value was almost certainly written for a linear axis in
0.1 µm; on the rotary axis it turns the work zero by many revolutions.

Fix: check the axis index and the unit; a rotary offset is given in 0.0001°.
"""),
        rule("X007", "channel-axis-without-list", E, "A channel axis whose axis list is missing",
             """
What it checks: every `gruppe[0].achse[j].log_achs_nr` of the channel list is the `kopf.achs_nr`
of one of the machine's axis lists.

Why it matters on the machine: the channel names an axis the controller has no data for; the
start-up fails or the axis is missing in the channel.

Fix: add the axis list to the start-up list (`achs_mds[i]`), or correct `log_achs_nr`.
"""),
    )
}

SGN32 = TYPE_LIMITS["SGN32"]


def _fmt(v: float, unit: str) -> str:
    return f"{v / ZERO_UNIT:.4f} {unit}"


def check_machine(machine: Machine, severities: dict[str, Severity]) -> Iterator[Diagnostic]:
    """The X findings of a machine (each carries the path of the file it is about)."""
    from zero.machine import AXIS_NAME, AXIS_NR, axis_of, g_code
    def report(code: str, path: object, span: Span, message: str, param_id: str | None = None) -> Diagnostic:
        return Diagnostic(code, severities.get(code, RULES[code].severity), message, span, str(path), param_id)

    startup = machine.startup
    for m in machine.missing:
        if "X005" in severities:
            line = startup.result.document.line_text(m.line)
            yield report("X005", startup.path, Span.on_line(m.line, 0, len(line)),
                         f"`{m.key}` names `{m.raw}`, which does not exist (looked next to the start-up "
                         "list and in the directories above it): the controller starts without it")
    seen_nr: dict[int, str] = {}
    seen_name: dict[str, str] = {}
    for lf in machine.axis_lists:
        ax = axis_of(lf)
        if ax is None:
            continue
        e = lf.entry(AXIS_NR)
        span = Span.on_line(e.line, e.value_start, e.value_end) if e else Span(1, 1, 1, 1)
        if ax.nr in seen_nr and "X004" in severities:
            yield report("X004", lf.path, span, f"logical axis number {ax.nr} is also claimed by "
                         f"{seen_nr[ax.nr]}: only one of the two lists is in effect", AXIS_NR)
        seen_nr.setdefault(ax.nr, str(lf.path))
        en = lf.entry(AXIS_NAME)
        if ax.name in seen_name and en is not None and "X004" in severities:
            yield report("X004", lf.path, Span.on_line(en.line, en.value_start, en.value_end),
                         f"axis name `{ax.name}` is also used by {seen_name[ax.name]}", AXIS_NAME)
        seen_name.setdefault(ax.name, str(lf.path))
    axes = machine.axes()
    for ch in machine.channels:
        if ch.lists is not None:
            for ca in ch.axes:
                if ca.log_nr not in axes and "X007" in severities and ca.entry is not None:
                    e = ca.entry
                    yield report("X007", ch.lists.path, Span.on_line(e.line, e.value_start, e.value_end),
                                 f"channel axis {ca.index} (`{ca.name}`) is logical axis {ca.log_nr}, but no "
                                 "axis list of the start-up list has that `kopf.achs_nr`")
        zl = ch.zero
        if zl is None or ch.lists is None:
            continue
        by_index = {ca.index: ca for ca in ch.axes}
        g53 = bool(zl.number("P-ZERO-00001"))
        for idx, res in sorted(zl.ctx.by_id.get(OFFSET, {}).items()):
            if len(idx) != 2 or res.value.number is None or res.value.problem is not None:
                continue
            group, j = idx
            v = res.value.number
            e = res.entry
            span = Span.on_line(e.line, e.value_start, e.value_end)
            where = f"{g_code(group)} (group {group})"
            found = by_index.get(j)
            if found is None:
                if v != 0 and "X003" in severities:
                    yield report("X003", zl.path, span, f"offset {where} for axis {j}, but the channel has no "
                                 f"axis {j}: the offset is never applied", OFFSET)
                continue
            ca = found
            ax = axes.get(ca.log_nr)
            masked = bool(zl.number("P-ZERO-00004", idx))
            if ax is None or v == 0 or masked or (group == 0 and not g53):
                continue
            if "X002" in severities:
                for side, limit in (("negative", ax.swe_neg), ("positive", ax.swe_pos)):
                    pcs = limit - v
                    if not SGN32[0] <= pcs <= SGN32[1]:
                        yield report("X002", zl.path, span, f"offset {where} of axis `{ca.name}` moves the {side} "
                                     f"soft limit to {pcs} in the programming coordinate system, beyond SGN32",
                                     OFFSET)
            if not ax.swe_neg <= v <= ax.swe_pos and "X001" in severities:
                yield report("X001", zl.path, span,
                             f"the work zero of {where} on axis `{ca.name}` ({_fmt(v, ax.unit)}) lies outside "
                             f"its soft limits {_fmt(ax.swe_neg, ax.unit)} .. {_fmt(ax.swe_pos, ax.unit)} "
                             f"({ax.list.path.name}): positions near the work zero cannot be reached", OFFSET)
            if ax.rotary and abs(v) > 3_600_000 and "X006" in severities:
                yield report("X006", zl.path, span,
                             f"offset {where} of rotary axis `{ca.name}` is {v / ZERO_UNIT:.4f}° — more than "
                             "a full turn: probably a length in 0.1 µm written for a linear axis", OFFSET)

"""X rules: what the lists of one machine mean together (``zero lint --machine``).

They read a :class:`~zero.machine.model.Machine` (start-up list, channel lists, axis
lists, zero-offset lists) and report on the line of the list that carries the fault.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from zero.catalog.ids import (
    AXIS_LISTS,
    AXIS_NAME,
    AXIS_NR,
    COMP_AXIS,
    COMP_LIST_AXIS,
    COMP_LISTS,
    COMPENSATIONS,
    FULL_TURN,
    G53_AVAILABLE,
    INACTIVE,
    OFFSET,
    SOFT_LIMITS,
    SPINDLE_AXIS,
    fixed,
    g_code,
)
from zero.catalog.ranges import TYPE_LIMITS
from zero.diagnostics import Diagnostic, Related, Span
from zero.rules.base import INFO, E, Family, MachineContext, W

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: a list's lint does not load the machine model
    from zero.machine.model import Axis, ListFile

FAMILY: Family[MachineContext] = Family("X", "machine (across lists, `zero lint --machine`)", "machine")
SGN32 = TYPE_LIMITS["SGN32"]

MISSING_LIST = FAMILY.rule(
    "X005", "missing-list", E, "The start-up list names a list that cannot be read",
    """
What it checks: every list the start-up list names (`default_sda_mds`, `sda_mds[c]`,
`werkz_data[c]`, `nullp_data[c]`, `pzv_data[c]`, `ve_var[c]`, `hand_mds`, `rtconf_lis`,
`hw_configuration_list`, `default_achs_mds`, `achs_mds[i]`, `achs_kw[i]`) exists in the
controller's working directory and can be read. The working directory is found once (the
start-up list's directory or the ancestor where the named lists are); a list is never looked
for anywhere else.

Why it matters on the machine: what follows depends on the key, and zero says only what the
catalogue documents: for axis lists (P-STUP-00015) and compensation lists (P-STUP-00017)
start-up is aborted; for the other keys the catalogue does not say.

Fix: correct the path, or add the file.
""", reads=("P-STUP-00034", "P-STUP-00009", "P-STUP-00010", "P-STUP-00011", "P-STUP-00012", "P-STUP-00146",
           "P-STUP-00013", "P-STUP-00135", "P-STUP-00136", "P-STUP-00035", "P-STUP-00015", "P-STUP-00017",
           "P-STUP-00014", "P-STUP-00016"))


def _on_reference(ctx: MachineContext, code: str, line: int, message: str) -> Diagnostic:
    """A finding on the whole line of the start-up list that names a list."""
    startup = ctx.machine.startup
    return ctx.report(code, Span.on_line(line, 0, len(startup.values.doc.line_text(line))), message,
                      path=str(startup.path))


@FAMILY.check(MISSING_LIST)
def check_missing(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X005: every list the start-up list names can be read."""
    from zero.machine.model import COUNT_KEYS, REFERENCES  # start-up: only a machine's lint needs it

    machine = ctx.machine
    startup = machine.startup
    for m in machine.missing:
        yield _on_reference(ctx, "X005", m.line, f"`{m.key}` names `{m.raw}`, which {m.reason} (working directory "
                            f"{machine.workdir}): {m.consequence}")
    for ref in REFERENCES:  # a count larger than the lists named: the controller looks for the rest
        if ref.count not in (AXIS_LISTS, COMP_LISTS):
            continue
        entry = startup.entry(ref.count)
        count = startup.number(ref.count)
        named = {n.index for n in machine.named if n.reference is ref}
        absent = [i for i in range(int(count or 0)) if i not in named]
        if entry is not None and absent:
            keys = ", ".join(f"{ref.key[:-2]}[{i}]" for i in absent[:4]) + (" …" if len(absent) > 4 else "")
            yield ctx.report("X005", Span.on_line(entry.line, entry.value_start, entry.value_end),
                             f"`{COUNT_KEYS[ref.count]}` is {int(count or 0)}, but the start-up list names no "
                             f"{keys} (working directory {machine.workdir}): the controller looks for them, and "
                             f"{ref.missing}",
                             param_id=ref.count, path=str(startup.path))


BEYOND_COUNT = FAMILY.rule(
    "X008", "list-beyond-count", W, "A list the start-up list names beyond its count",
    """
What it checks: `achs_mds[i]` with i ≥ `zahl_mds` (P-STUP-00014), `achs_kw[i]` with i ≥
`zahl_kw` (P-STUP-00016), and channel lists (`sda_mds[c]`, `nullp_data[c]`, ...) with c ≥
`kanal_anzahl` (P-STUP-00001).

Why it matters on the machine: the catalogue says the controller reads only as many axis and
compensation lists as the count says and ignores the rest, and configures `kanal_anzahl`
channels; the list named beyond the count is not read, however carefully it was prepared.

Example: `zahl_mds 1` with `achs_mds[0]` and `achs_mds[1]`
Fix: raise the count, or remove the reference.
""", reads=("P-STUP-00014", "P-STUP-00016", "P-STUP-00001", "P-STUP-00034", "P-STUP-00009", "P-STUP-00010",
           "P-STUP-00011", "P-STUP-00012", "P-STUP-00146", "P-STUP-00013", "P-STUP-00135", "P-STUP-00136",
           "P-STUP-00035", "P-STUP-00015", "P-STUP-00017"))


@FAMILY.check(BEYOND_COUNT)
def check_counts(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X008: lists named beyond zahl_mds, zahl_kw or kanal_anzahl."""
    from zero.machine.model import COUNT_KEYS  # start-up: only a machine's lint needs it

    startup = ctx.machine.startup
    for n in ctx.machine.named:
        if n.status != "beyond-count" or n.reference.count is None:
            continue
        count_key = COUNT_KEYS[n.reference.count]
        value = startup.number(n.reference.count)
        shown = f"{int(value or 0)}" if startup.values.value_of(n.reference.count) is not None \
            else f"{int(value or 0)} (not set: the catalogue default)"
        what = ("the controller configures that many channels and does not read this list"
                if count_key == "kanal_anzahl" else "the controller does not read lists beyond it")
        line = startup.values.doc.line_text(n.line)
        yield ctx.report("X008", Span.on_line(n.line, 0, len(line)),
                         f"`{n.key}` is beyond `{count_key}` {shown} ({n.reference.count}): {what}",
                         param_id=n.reference.param_id, path=str(startup.path))


DUPLICATE_AXIS = FAMILY.rule(
    "X004", "duplicate-axis", E, "Two axis lists claim the same logical axis",
    """
What it checks: `kopf.achs_nr` (and `kopf.log_achs_name`) differ between the axis lists of one
start-up list.

Why it matters on the machine: the kernel reports error P-ERR-110064 at start-up and does not take
over the data of the second axis with the same logical axis number; P-ERR-1001121 (axis cannot be
configured) aborts the start-up. The other list's soft limits, gears and drive data are not the
ones in effect. Sources: https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/262200203.html
(110064), https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/269224331.html (1001121).

Fix: give each axis list its own `kopf.achs_nr` and name.
""", reads=("P-AXIS-00016", "P-AXIS-00297"))
CHANNEL_AXIS_WITHOUT_LIST = FAMILY.rule(
    "X007", "channel-axis-without-list", E, "A channel axis whose axis list is missing",
    """
What it checks: every `gruppe[0].achse[j].log_achs_nr` of the channel list is the `kopf.achs_nr`
of one of the machine's axis lists.

Why it matters on the machine: the channel names an axis the controller has no data for; the
start-up fails or the axis is missing in the channel.

Fix: add the axis list to the start-up list (`achs_mds[i]`), or correct `log_achs_nr`.
""", reads=("P-CHAN-00035", "P-AXIS-00016"))


@FAMILY.check(DUPLICATE_AXIS, CHANNEL_AXIS_WITHOUT_LIST)
def check_axes(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X004, X007: one axis list per logical axis, and one for every channel axis."""
    from zero.machine.model import axis_of  # start-up: only a machine's lint needs it

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
            yield ctx.report("X004", span, f"P-ERR-110064: logical axis number {ax.nr} is also claimed by "
                             f"{seen_nr[ax.nr]}: the controller reports error 110064 at start-up and does not "
                             "take over this axis's data (P-ERR-1001121: the axis cannot be configured and the "
                             "start-up is aborted)", param_id=AXIS_NR, path=str(lf.path),
                             kernel_error="P-ERR-110064")
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
            if ca.log_nr not in axes and ca.entry is not None and machine.complete_axes():
                e = ca.entry
                yield ctx.report("X007", Span.on_line(e.line, e.value_start, e.value_end),
                                 f"channel axis {ca.index} (`{ca.name}`) is logical axis {ca.log_nr}, but no "
                                 "axis list of the start-up list has that `kopf.achs_nr`",
                                 path=str(ca.source or ch.lists.path))


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
""", reads=("P-ZERO-00003", "P-ZERO-00004", "P-ZERO-00001", "P-CHAN-00035", "P-AXIS-00016", "P-AXIS-00177",
           "P-AXIS-00178"))
PCS_LIMIT_OVERFLOW = FAMILY.rule(
    "X002", "pcs-limit-overflow", W, "A work offset moves a soft limit beyond SGN32",
    """
What it checks: soft limit minus offset stays inside the SGN32 range the controller computes in.

Why it matters on the machine: the soft limit in the programming coordinate system cannot be
represented; the displayed limits (`display_pcs_limits`) and any check on them are wrong.

Fix: correct the offset; offsets of this size are always a data error.
""", reads=("P-ZERO-00003", "P-ZERO-00004", "P-ZERO-00001", "P-CHAN-00035", "P-AXIS-00016", "P-AXIS-00177",
           "P-AXIS-00178"))
OFFSET_FOR_MISSING_AXIS = FAMILY.rule(
    "X003", "offset-for-missing-axis", W, "An offset for an axis the channel does not have",
    """
What it checks: a non-zero `np_grp[i].achse[j].versch` where the channel list maps no axis to j.

Why it matters on the machine: the offset is never applied; it usually belongs to another axis
index (the list was copied from another machine, or the axis order changed).

Fix: move the offset to the right axis index, or remove it.
""", reads=("P-ZERO-00003", "P-CHAN-00035"))
ROTARY_OFFSET_IN_MM = FAMILY.rule(
    "X006", "rotary-offset-in-mm", W, "A rotary axis with an offset that only makes sense in mm",
    """
What it checks: an applied offset of a rotary axis (`kenngr.achs_typ` rotary or spindle) larger
than a full turn (360° = 3600000 in 0.0001°).

Why it matters on the machine: the value was almost certainly written for a linear axis in
0.1 µm; on the rotary axis it turns the work zero by many revolutions.

Fix: check the axis index and the unit; a rotary offset is given in 0.0001°.
""", reads=("P-ZERO-00003", "P-ZERO-00004", "P-ZERO-00001", "P-CHAN-00035", "P-AXIS-00016", "P-AXIS-00018"))


def _limit_entries(ax: Axis) -> tuple[Related, ...]:
    """The entries that set an axis's soft limits (in its list or the default list under it)."""
    out = []
    for pid in SOFT_LIMITS:
        res = ax.list.values.value_of(pid)
        layer = ax.list.values.layer_of(pid)
        if res is None or layer is None:  # the catalogue's default: no entry to point at
            continue
        e = res.entry
        out.append(Related(Span.on_line(e.line, e.value_start, e.value_end), f"{e.key_text} {e.value}",
                           layer.doc.path))
    return tuple(out)


def _limits_origin(ax: Axis) -> str:
    """Where an axis's soft limits come from, as `zero explain` says it: `achse_vorgabe.lis:3,4` for
    both from the default list, `achse_x.lis:7, catalogue default` for one from the catalogue."""
    by_file: dict[str, list[str]] = {}
    for pid in SOFT_LIMITS:
        layer = ax.list.values.layer_of(pid)
        entry = layer.entry_of(pid) if layer is not None else None
        if layer is None or entry is None:
            by_file.setdefault("catalogue default", [])
        else:
            by_file.setdefault(Path(layer.doc.path).name, []).append(str(entry.line))
    return ", ".join(f"{name}:{','.join(lines)}" if lines else name for name, lines in by_file.items())


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
                                     param_id=OFFSET, path=path, related=_limit_entries(ax))
            if not ax.swe_neg <= v <= ax.swe_pos:
                yield ctx.report("X001", span,
                                 f"the work zero of {where} on axis `{ca.name}` ({fixed(v, ax.unit)}) lies outside "
                                 f"its soft limits {fixed(ax.swe_neg, ax.unit)} .. {fixed(ax.swe_pos, ax.unit)} "
                                 f"({_limits_origin(ax)}): positions near the work zero cannot be reached",
                                 param_id=OFFSET, path=path, related=_limit_entries(ax))
            if ax.rotary and abs(v) > FULL_TURN:
                yield ctx.report("X006", span,
                                 f"offset {where} of rotary axis `{ca.name}` is {fixed(v)}° — more than "
                                 "a full turn: probably a length in 0.1 µm written for a linear axis",
                                 param_id=OFFSET, path=path)


COMPENSATION_AXIS_UNKNOWN = FAMILY.rule(
    "X009", "compensation-axis-unknown", W, "A compensation list assigned to an axis the machine does not have",
    """
What it checks: `achs_kw_log_ax_nr[i]` (P-STUP-00036) of each compensation list the controller
reads (`achs_kw[i]`, i < `zahl_kw`) is the `kopf.achs_nr` of one of the machine's axis lists.

Why it matters on the machine: the offset values of the list belong to no axis; the axis they
were measured for runs uncompensated.

Fix: set `achs_kw_log_ax_nr[i]` to the logical axis number of the axis the list was measured on.
""", reads=("P-STUP-00036", "P-STUP-00017", "P-STUP-00016", "P-AXIS-00016"))


@FAMILY.check(COMPENSATION_AXIS_UNKNOWN)
def check_compensation(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X009: the axis of each compensation list exists."""
    machine = ctx.machine
    axes = machine.axes()
    startup = machine.startup
    for i, _lf in machine.compensation:
        nr = startup.number(COMP_AXIS, (i,))
        e = startup.entry(COMP_AXIS, (i,))
        if nr is None or int(nr) in axes or not nr:
            continue  # 0 is outside the documented range: R005 says so on the start-up list
        span = Span.on_line(e.line, e.value_start, e.value_end) if e is not None else Span(1, 1, 1, 1)
        yield ctx.report("X009", span, f"`achs_kw_log_ax_nr[{i}]` is {int(nr)}, but no axis list of the start-up "
                         f"list has that `kopf.achs_nr`: the compensation values of `achs_kw[{i}]` apply to no axis",
                         param_id=COMP_AXIS, path=str(startup.path))


COMPENSATION_WITHOUT_TABLE = FAMILY.rule(
    "X013", "compensation-without-table", W, "A compensation switched on for an axis no compensation list feeds",
    """
What it checks: an axis list that switches on leadscrew error compensation (`lr_param.ssfk`,
P-AXIS-00175), cross compensation (`lr_param.crosscomp`, P-AXIS-00047) or plane compensation
(`lr_param.crosscomp2`, P-AXIS-00174), while no compensation list of the machine (`achs_kw[i]`,
assigned by `achs_kw_log_ax_nr[i]` or by its own `kopf.achs_nr`) is for that axis, or the one
that is holds no entry of that compensation's table (`kw.ssfk.table[]`, `kw.crosscomp.table[]`,
`kw.crosscomp2.table[][]`).

Why it matters on the machine: the compensation values come from the axis's compensation list;
with none, the axis is switched to a compensation that has nothing to apply, and the machine
runs with the error it was meant to correct. For plane compensation the vendor documents
P-ERR-70183 at start-up: the controller switches plane compensation off for the axis
(https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/260228747.html); for leadscrew and
cross compensation it documents no start-up message.
Not claimed while a compensation list the start-up list names is not read (X005, X012).

Fix: add the compensation list to the start-up list (`zahl_kw`, `achs_kw[i]`,
`achs_kw_log_ax_nr[i]`) with its table, or switch the compensation off.
""", reads=("P-AXIS-00175", "P-AXIS-00047", "P-AXIS-00174", "P-COMP-00023", "P-COMP-00024", "P-COMP-00025",
           "P-COMP-00006", "P-COMP-00007", "P-COMP-00016", "P-STUP-00036", "P-COMP-00001", "P-AXIS-00016"))
COMPENSATION_AXIS_MISMATCH = FAMILY.rule(
    "X014", "compensation-list-axis-mismatch", W,
    "A compensation list whose header names another axis than the start-up list assigns it to",
    """
What it checks: `kopf.achs_nr` (P-COMP-00001) of the list `achs_kw[i]` is the axis
`achs_kw_log_ax_nr[i]` (P-STUP-00036) assigns it to, where both are written.

Why it matters on the machine: the start-up list assigns the values to one axis while the list
says it was measured on another; one of them is wrong, and the documentation does not say
which of the two the controller follows.

Fix: make the two numbers agree (the axis the values were measured on).
""", reads=("P-COMP-00001", "P-STUP-00036"))


def _compensation_lists(ctx: MachineContext) -> dict[int, list[ListFile]] | None:
    """Axis number → the compensation lists for it (by the start-up list's assignment or their own
    header); ``None`` while a compensation list the start-up list names was not read."""
    machine = ctx.machine
    if any(n.reference.key == "achs_kw[]" and n.status in ("missing", "unreadable", "not-checked")
           for n in machine.named):
        return None
    out: dict[int, list[ListFile]] = {}
    for i, lf in machine.compensation:
        for nr in {machine.startup.number(COMP_AXIS, (i,)), lf.number(COMP_LIST_AXIS)}:
            if nr:
                out.setdefault(int(nr), []).append(lf)
    return out


@FAMILY.check(COMPENSATION_WITHOUT_TABLE, COMPENSATION_AXIS_MISMATCH)
def check_compensation_tables(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X013, X014: each compensation an axis switches on has a table; each compensation list's
    header names the axis the start-up list assigns it to."""
    machine = ctx.machine
    startup = machine.startup
    for i, lf in machine.compensation:
        assigned, own = startup.number(COMP_AXIS, (i,)), lf.number(COMP_LIST_AXIS)
        e = lf.entry(COMP_LIST_AXIS)
        if assigned and own and e is not None and int(assigned) != int(own):
            yield ctx.report("X014", Span.on_line(e.line, e.value_start, e.value_end),
                             f"`kopf.achs_nr` is {int(own)}, but the start-up list assigns this list to axis "
                             f"{int(assigned)} (`achs_kw_log_ax_nr[{i}]`): the documentation does not say which "
                             "of the two the controller follows", param_id=COMP_LIST_AXIS, path=str(lf.path))
    by_axis = _compensation_lists(ctx)
    if by_axis is None:
        return
    said: set[tuple[str, int]] = set()
    for nr, ax in sorted(machine.axes().items()):
        for pid, (what, table, ids) in COMPENSATIONS.items():
            res = ax.list.values.value_of(pid)
            if res is None or res.value.number != 1:
                continue
            layer = ax.list.values.layer_of(pid) or ax.list.values
            where = (layer.doc.path, res.entry.line)
            lists = by_axis.get(nr, [])
            if any(lf.values.ids_of(t) for lf in lists for t in ids) or where in said:
                continue
            said.add(where)
            why = (f"the compensation list of axis {nr} ({', '.join(f'`{lf.path}`' for lf in lists)}) has no "
                   f"`{table}` entry" if lists else
                   f"no compensation list of the machine is for axis {nr} (`achs_kw_log_ax_nr`, `kopf.achs_nr`)")
            plane = pid == "P-AXIS-00174"  # P-ERR-70183: the one compensation the kernel reports at start-up
            yield ctx.report("X013", Span.on_line(res.entry.line, res.entry.value_start, res.entry.value_end),
                             f"`{res.entry.key_text} 1` switches {what} on, but {why}: there are no values to "
                             "apply" + (", and the kernel reports P-ERR-70183 at start-up and switches plane "
                                        "compensation off for the axis" if plane else
                                        ", and the vendor documents no start-up message for this"),
                             param_id=pid, path=layer.doc.path, kernel_error="P-ERR-70183" if plane else None)


CHANNEL_AXIS_TWICE = FAMILY.rule(
    "X010", "channel-axis-twice", W, "One logical axis in two places of the channels",
    """
What it checks: every logical axis number appears once among the channel axes
(`gruppe[0].achse[j].log_achs_nr`) and spindles (`spindel[s].log_achs_nr`) of all channels.

Why it matters on the machine: one drive would be commanded by two channel axes (or an axis
and a spindle); the channel configuration is contradictory.

Fix: give each channel axis and spindle its own logical axis number.
""", reads=("P-CHAN-00035", "P-CHAN-00036"))
SPINDLE_WITHOUT_LIST = FAMILY.rule(
    "X011", "spindle-without-list", W, "A spindle whose axis list is missing",
    """
What it checks: every `spindel[s].log_achs_nr` (P-CHAN-00036) of a channel list is the
`kopf.achs_nr` of one of the machine's axis lists.

Why it matters on the machine: the channel names a spindle the controller has no axis data for.

Fix: add the spindle's axis list to the start-up list (`achs_mds[i]`), or correct `log_achs_nr`.
""", reads=("P-CHAN-00036", "P-AXIS-00016"))


@FAMILY.check(CHANNEL_AXIS_TWICE, SPINDLE_WITHOUT_LIST)
def check_channel_axes(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X010, X011: logical axis numbers of channel axes and spindles."""
    machine = ctx.machine
    axes = machine.axes()
    seen: dict[int, str] = {}
    path_axes: dict[int, int] = {}  # logical axis → the channel whose path axis it is first
    for ch in machine.channels:
        if ch.lists is None:
            continue
        users: list[tuple[int, str, Span, str]] = []
        for ca in ch.axes:
            if ca.entry is not None:
                e = ca.entry
                if path_axes.get(ca.log_nr) == ch.index:
                    continue  # two path axes of one channel list: K004 says it, with the kernel's number 20423
                path_axes.setdefault(ca.log_nr, ch.index)
                users.append((ca.log_nr, f"channel {ch.index} axis {ca.index} (`{ca.name}`)",
                              Span.on_line(e.line, e.value_start, e.value_end), str(ca.source or ch.lists.path)))
        for idx, res in sorted(ch.lists.values.ids_of(SPINDLE_AXIS).items()):
            nr = res.value.number
            if nr is None or res.value.problem is not None or not nr:
                continue
            layer = ch.lists.values.layer_of(SPINDLE_AXIS, idx)
            path = layer.doc.path if layer is not None else str(ch.lists.path)
            span = Span.on_line(res.entry.line, res.entry.value_start, res.entry.value_end)
            where = f"channel {ch.index} spindle {idx[0] if idx else 0}"
            users.append((int(nr), where, span, path))
            if int(nr) not in axes and machine.complete_axes():
                yield ctx.report("X011", span, f"{where} is logical axis {int(nr)}, but no axis list of the "
                                 "start-up list has that `kopf.achs_nr`", param_id=SPINDLE_AXIS, path=path)
        for nr, what, span, path in users:
            if nr in seen:
                yield ctx.report("X010", span, f"{what} is logical axis {nr}, which {seen[nr]} already is: one "
                                 "drive cannot be two channel axes", path=path)
            else:
                seen[nr] = what


LIST_NOT_CHECKED = FAMILY.rule(
    "X012", "list-not-checked", INFO, "A list zero does not follow: an absolute path, or outside the machine's folder",
    """
What it checks: every list the start-up list names is a path inside the machine's folder (the
controller's working directory, never above the project or git work tree that holds the
start-up list, never the file system's root). A reference with an absolute path (`/…`,
`C:\\…`) or one that climbs out of that folder (`../../…`) is not followed.

Why it matters on the machine: the controller opens the file on its own file system, so zero
cannot know what it holds there; and a start-up list you received must never make zero read,
and print, a file of your computer. The lists it names are not checked, and no "axis without
a list" is claimed while an axis list is not followed.

Fix: name the file where it lies in the repository with `[tool.zero.machine]`
(`"achs_mds[0]" = "listen/achse_x.lis"`), or write the path relative to the working directory.
""", reads=("P-STUP-00034", "P-STUP-00009", "P-STUP-00010", "P-STUP-00011", "P-STUP-00012", "P-STUP-00146",
           "P-STUP-00013", "P-STUP-00135", "P-STUP-00136", "P-STUP-00035", "P-STUP-00015", "P-STUP-00017"))


@FAMILY.check(LIST_NOT_CHECKED)
def check_unchecked(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X012: references zero does not follow."""
    for n in ctx.machine.unchecked:
        yield _on_reference(ctx, "X012", n.line, f"`{n.key}` names `{n.raw}`, which {n.reason}: zero does not read "
                            "it, so that list is not checked (`[tool.zero.machine]` can name where it lies in the "
                            "repository)")


PRE_OUTPUT_BELOW_CYCLE = FAMILY.rule(
    "X015", "pre-output-below-cycle", E, "P-ERR-21203: pre-output time of an MET_SVS M/H function below the cycle time",
    """
What it checks: an M or H function synchronised with MET_SVS (`m_synch[i]` P-CHAN-00041, `h_synch[i]`
P-CHAN-00027, bit 0x2000000) whose pre-output time (`m_pre_outp[i]` P-CHAN-00070, `h_pre_outp[i]`
P-CHAN-00107, µs) is shorter than the cycle time of the machine's real-time configuration
(`cycle_time`, P-RTCF-00002, µs, in the list `rtconf_lis` names). A value from another list: checked
with `zero lint --machine` only, and only where the machine's real-time configuration sets its cycle
time. The NC cycle is not shorter than that base cycle, so a pre-output time below it is below the NC
cycle time too; one between the two is not reported (the NC cycle itself is the real-time threads').

Why it matters on the machine: at start-up the kernel reports error P-ERR-21203 (class 1), sets the
pre-output time to the cycle time and continues the start-up. Source:
https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/253779083.html

Fix: give the function a pre-output time of at least one NC cycle.
""", reads=("P-CHAN-00041", "P-CHAN-00027", "P-CHAN-00070", "P-CHAN-00107", "P-RTCF-00002"))

_MET_SVS = 0x2000000
_PRE_OUTPUT = (("P-CHAN-00041", "P-CHAN-00070", "M"), ("P-CHAN-00027", "P-CHAN-00107", "H"))


@FAMILY.check(PRE_OUTPUT_BELOW_CYCLE)
def check_pre_output(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X015 (P-ERR-21203): MET_SVS pre-output times against the real-time configuration's cycle time."""
    rtconf = ctx.machine.singles.get("rtconf_lis")
    if rtconf is None or rtconf.entry("P-RTCF-00002") is None:
        return  # no real-time configuration, or it does not set the cycle time: nothing known
    cycle = rtconf.number("P-RTCF-00002")
    if cycle is None or cycle <= 0:
        return
    for ch in ctx.machine.channels:
        lf = ch.lists
        if lf is None:
            continue
        for synch, pre, letter in _PRE_OUTPUT:
            for idx in sorted(lf.values.ids_of(synch)):
                mode = lf.number(synch, idx)
                if mode is None or not int(mode) & _MET_SVS:
                    continue
                time = lf.number(pre, idx)
                if time is None or time >= cycle:
                    continue
                entry = lf.entry(pre, idx) or lf.entry(synch, idx)
                if entry is None:
                    continue
                yield ctx.report(
                    "X015", Span.on_line(entry.line, entry.value_start, entry.value_end),
                    f"P-ERR-21203: {letter}{idx[0]} is synchronised with MET_SVS, but its pre-output time is "
                    f"{int(time)} µs, shorter than the real-time configuration's cycle time {int(cycle)} µs "
                    f"(P-RTCF-00002 in {rtconf.path.name}): the controller reports error 21203 at start-up and sets "
                    "the pre-output time to the cycle time", param_id=pre, path=str(lf.path),
                    kernel_error="P-ERR-21203")


SPINDLE_NOT_A_SPINDLE = FAMILY.rule(
    "X016", "channel-spindle-not-spindle", E, "P-ERR-110304: a channel spindle whose axis list is no spindle",
    """
What it checks: every spindle of a channel list (`spindel[i].log_achs_nr`, P-CHAN-00036) names an axis
list whose axis type (`kenngr.achs_typ`, P-AXIS-00018) is a spindle (4). Values from two lists of the
machine: checked with `zero lint --machine`.

Why it matters on the machine: the kernel reports error P-ERR-110304 (class 2): the start-up continues,
but no axes are available in the channel where the spindle is configured. Source:
https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/262857355.html

Fix: give the axis list the spindle axis type, or name the spindle's own logical axis number.
""", reads=("P-CHAN-00036", "P-CHAN-00082", "P-AXIS-00018", "P-AXIS-00016"))
GANTRY_MODULO_DIFFERS = FAMILY.rule(
    "X017", "gantry-modulo-differs", E, "P-ERR-70202: gantry master and slave with different modulo limits",
    """
What it checks: a gantry slave axis (`kenngr.gantry_ax_nr`, P-AXIS-00070, names its master) has the
same modulo limits (`getriebe[0].moduloo` P-AXIS-00126, `getriebe[0].modulou` P-AXIS-00127) as the
axis list of its master. Values from two lists of the machine: checked with `zero lint --machine`.

Why it matters on the machine: the kernel warns with P-ERR-70202; the gantry manual says that at
start-up a warning is output and the master axis's values are adopted, so the slave's own limits
are not the ones in effect. Sources:
https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/260298379.html,
https://infosys.beckhoff.com/content/1033/tf5200_gantry_operation/285690635.html

Fix: give both axes the same modulo limits.
""", reads=("P-AXIS-00070", "P-AXIS-00126", "P-AXIS-00127", "P-AXIS-00016"))
GANTRY_MASTER_NOT_MASTER = FAMILY.rule(
    "X018", "gantry-master-not-master", W, "P-ERR-70124: a gantry slave's master axis is not marked gantry master",
    """
What it checks: the axis a gantry slave names as its master (`kenngr.gantry_ax_nr`, P-AXIS-00070) has
the gantry master bit 0x10000 in its axis mode (`kenngr.achs_mode`, P-AXIS-00015). Values from two
lists of the machine: checked with `zero lint --machine`, where the master's axis list is read.

Why it matters on the machine: the kernel warns with P-ERR-70124 (class 1, warning); the page documents
no other reaction. Source: https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/260115595.html

Fix: set the gantry master bit in the master axis's `kenngr.achs_mode`, or name the right master.
""", reads=("P-AXIS-00070", "P-AXIS-00015", "P-AXIS-00016"))
_SPINDLE_NR, _AXIS_TYPE, _GANTRY_MASTER_NR, _AXIS_MODE = "P-CHAN-00036", "P-AXIS-00018", "P-AXIS-00070", "P-AXIS-00015"
_MODULO = ("P-AXIS-00126", "P-AXIS-00127")


@FAMILY.check(SPINDLE_NOT_A_SPINDLE)
def check_channel_spindles(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X016 (P-ERR-110304): a channel's spindle names an axis list of another axis type."""
    axes = ctx.machine.axes()
    for ch in ctx.machine.channels:
        lf = ch.lists
        if lf is None:
            continue
        count = lf.number("P-CHAN-00082")  # spdl_anzahl: spindles beyond it are not configured
        for idx, res in sorted(lf.values.ids_of(_SPINDLE_NR).items()):
            nr = lf.number(_SPINDLE_NR, idx)
            if nr is None or nr == 0 or (count is not None and idx and idx[0] >= count):
                continue
            ax = axes.get(int(nr))
            kind = ax.list.number(_AXIS_TYPE) if ax is not None else None
            if ax is None or kind is None or int(kind) == 4:
                continue
            e = res.entry
            yield ctx.report(
                "X016", Span.on_line(e.line, e.value_start, e.value_end),
                f"P-ERR-110304: spindle {idx[0] if idx else 0} is logical axis {int(nr)}, whose axis list "
                f"({ax.list.path.name}) has axis type {int(kind)}, not 4 (spindle): the controller reports error "
                "110304 at start-up, continues the start-up, and no axes are available in this channel",
                param_id=_SPINDLE_NR, path=str((lf.values.layer_of(_SPINDLE_NR, idx) or lf.values).doc.path),
                kernel_error="P-ERR-110304")


@FAMILY.check(GANTRY_MODULO_DIFFERS, GANTRY_MASTER_NOT_MASTER)
def check_gantry(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X017 (P-ERR-70202), X018 (P-ERR-70124): a gantry slave against its master's axis list."""
    axes = ctx.machine.axes()
    for lf in ctx.machine.axis_lists:
        master_nr = lf.number(_GANTRY_MASTER_NR)
        entry = lf.entry(_GANTRY_MASTER_NR)
        if not master_nr or entry is None:
            continue  # not a slave, or its master is set in a default list (reported there)
        master = axes.get(int(master_nr))
        if master is None or master.list is lf:
            continue  # no such axis list (another rule's), or itself (the kernel's 110342 family)
        span = Span.on_line(entry.line, entry.value_start, entry.value_end)
        mode = master.list.number(_AXIS_MODE)
        if mode is not None and not int(mode) & 0x10000:
            yield ctx.report(
                "X018", span, f"P-ERR-70124: the gantry master of this axis is logical axis {int(master_nr)}, whose "
                f"axis mode ({master.list.path.name}: {hex(int(mode))}) lacks the gantry master bit 0x10000: the "
                "controller warns with 70124 at start-up", param_id=_GANTRY_MASTER_NR, path=str(lf.path),
                kernel_error="P-ERR-70124")
        own = [lf.number(pid, (0,)) for pid in _MODULO]
        theirs = [master.list.number(pid, (0,)) for pid in _MODULO]
        if None in own or None in theirs or own == theirs:
            continue
        yield ctx.report(
            "X017", span, f"P-ERR-70202: this gantry slave's modulo limits ({own[0]:g} / {own[1]:g}) differ from its "
            f"master's, logical axis {int(master_nr)} ({theirs[0]:g} / {theirs[1]:g}, {master.list.path.name}): the "
            "controller warns with 70202 at start-up and adopts the master axis's values",
            param_id="P-AXIS-00126", path=str(lf.path), kernel_error="P-ERR-70202")


CHANNEL_ID_TWICE = FAMILY.rule(
    "X019", "channel-id-twice", E, "P-ERR-1001850: one channel ID on two channels",
    """
What it checks: no two channel lists of the machine write the same non-zero channel ID
(`channel_id`, P-CHAN-00400). Values from two lists of the machine: checked with
`zero lint --machine`. An ID left at the catalogue's default 0 is not checked (the page does not say
whether two unset IDs collide).

Why it matters on the machine: the kernel reports P-ERR-1001850 at start-up (class 3) and numbers
all channels by default instead (channel ID = channel index + 1), so whatever addresses a channel by
its configured ID finds another one. Source:
https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/1000916363.html

Fix: give each channel its own `channel_id`.
""", reads=("P-CHAN-00400",))
_CHANNEL_ID = "P-CHAN-00400"


@FAMILY.check(CHANNEL_ID_TWICE)
def check_channel_ids(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X019 (P-ERR-1001850): a channel ID that an earlier channel list already writes."""
    seen: dict[int, tuple[int, str]] = {}
    for ch in ctx.machine.channels:
        lf = ch.lists
        entry = lf.entry(_CHANNEL_ID) if lf is not None else None
        value = lf.number(_CHANNEL_ID) if lf is not None else None
        if lf is None or entry is None or not value:
            continue  # unset, or set in a default list only (one list, not two)
        nr = int(value)
        if nr in seen:
            index, name = seen[nr]
            yield ctx.report(
                "X019", Span.on_line(entry.line, entry.value_start, entry.value_end),
                f"P-ERR-1001850: channel ID {nr} is also channel {index}'s ({name}): the controller reports error "
                "1001850 at start-up and numbers every channel by default (channel index + 1) instead",
                param_id=_CHANNEL_ID, path=str(lf.path), kernel_error="P-ERR-1001850")
            continue
        seen[nr] = (ch.index, lf.path.name)


PATH_AXIS_SAI_OR_SPINDLE = FAMILY.rule(
    "X020", "path-axis-sai-or-spindle", E,
    "P-ERR-21238: a path axis of the channel is a single axis (SAI) or a spindle",
    """
What it checks: the axis list of every path axis of a channel (`gruppe[0].achse[j].log_achs_nr`,
P-CHAN-00035) neither marks the axis as a single axis (`kenngr.configure_sai`, P-AXIS-00250) nor
makes it a spindle (`kenngr.achs_typ` 4, P-AXIS-00018). Values from two lists of the machine:
checked with `zero lint --machine`.

Why it matters on the machine: the kernel reports P-ERR-21238 (class 3) and aborts the start-up.
Source: https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/253892235.html

Fix: take the axis out of the channel's path axes, or switch its SAI property off (a spindle
belongs in `spindel[i]`).
""", reads=("P-CHAN-00035", "P-AXIS-00016", "P-AXIS-00250", "P-AXIS-00018"))
ALIAS_NAME_COLLISION = FAMILY.rule(
    "X021", "alias-name-collision", E,
    "P-ERR-22016: with alias names active, a channel axis named like its axis list's alias",
    """
What it checks: where a channel list activates the axis lists' alias names
(`use_alias_name_in_ax_list`, P-CHAN-00253), no path axis's name (`gruppe[0].achse[j].bezeichnung`,
P-CHAN-00006) is the alias name its axis list configures (`kopf.log_achs_name`, P-AXIS-00297).
Values from two lists of the machine: checked with `zero lint --machine`.

Why it matters on the machine: the kernel warns with P-ERR-22016 at start-up (class 1), sets
P-CHAN-00253 to 0 (the alias names are not used) and continues.
Source: https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/482411787.html

Fix: rename the channel axis, or leave P-CHAN-00253 at 0.
""", reads=("P-CHAN-00253", "P-CHAN-00006", "P-AXIS-00297", "P-CHAN-00035", "P-AXIS-00016"))
PATH_AXIS_GANTRY_SLAVE = FAMILY.rule(
    "X022", "path-axis-gantry-slave", E, "P-ERR-21020: a path axis of the channel is a gantry slave axis",
    """
What it checks: no path axis of a channel (`gruppe[0].achse[j].log_achs_nr`, P-CHAN-00035) is an
axis whose axis list names a gantry master (`kenngr.gantry_ax_nr`, P-AXIS-00070): a gantry slave
moves with its master and is not known in the channel. Values from two lists of the machine:
checked with `zero lint --machine`.

Why it matters on the machine: the kernel reports P-ERR-21020 (class 3, abort current job).
Source: https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/253230731.html

Fix: remove the slave axis from the channel's path axes (program its master).
""", reads=("P-CHAN-00035", "P-AXIS-00016", "P-AXIS-00070"))
_SAI, _USE_ALIAS, _ALIAS, _CHANNEL_AXIS_NAME = "P-AXIS-00250", "P-CHAN-00253", "P-AXIS-00297", "P-CHAN-00006"


@FAMILY.check(PATH_AXIS_SAI_OR_SPINDLE, ALIAS_NAME_COLLISION, PATH_AXIS_GANTRY_SLAVE)
def check_path_axes(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X020 (P-ERR-21238), X021 (P-ERR-22016), X022 (P-ERR-21020): a channel's path axes against their
    axis lists."""
    axes = ctx.machine.axes()
    for ch in ctx.machine.channels:
        lf = ch.lists
        if lf is None:
            continue
        use_alias = bool(lf.number(_USE_ALIAS))
        for ca in ch.axes:
            ax = axes.get(ca.log_nr)
            if ca.entry is None or ax is None:
                continue
            own = ca.source is None or str(lf.path).split("#")[0] == str(ca.source)  # a list inside a project too
            path = str(lf.path) if own else str(ca.source)
            e = ca.entry
            span = Span.on_line(e.line, e.value_start, e.value_end)
            sai, kind = ax.list.number(_SAI), ax.list.number(_AXIS_TYPE)
            if sai or (kind is not None and int(kind) == 4):
                what = "is marked a single axis (SAI, kenngr.configure_sai)" if sai else "has axis type 4 (spindle)"
                yield ctx.report(
                    "X020", span, f"P-ERR-21238: path axis {ca.index} (`{ca.name}`) is logical axis {ca.log_nr}, whose "
                    f"axis list ({ax.list.path.name}) {what}: the controller reports error 21238 and aborts the "
                    "start-up", param_id="P-CHAN-00035", path=path, kernel_error="P-ERR-21238")
            master = ax.list.number(_GANTRY_MASTER_NR)
            if master:
                yield ctx.report(
                    "X022", span, f"P-ERR-21020: path axis {ca.index} (`{ca.name}`) is logical axis {ca.log_nr}, a "
                    f"gantry slave of axis {int(master)} ({ax.list.path.name}: kenngr.gantry_ax_nr): the controller "
                    "reports error 21020 and aborts the current job", param_id="P-CHAN-00035", path=path,
                    kernel_error="P-ERR-21020")
            alias = ax.list.text(_ALIAS)
            if use_alias and alias and ax.list.entry(_ALIAS) is not None and alias == ca.name:
                yield ctx.report(
                    "X021", span, f"P-ERR-22016: with alias names active (use_alias_name_in_ax_list), path axis "
                    f"{ca.index} is named `{ca.name}`, the alias its axis list ({ax.list.path.name}) configures: the "
                    "controller warns with 22016 at start-up, sets use_alias_name_in_ax_list to 0 and continues",
                    param_id=_CHANNEL_AXIS_NAME, path=path, kernel_error="P-ERR-22016")


PLANE_MASTER_INVALID = FAMILY.rule(
    "X023", "plane-compensation-master-invalid", E,
    "P-ERR-70182: a master axis of a plane compensation is 0 or no axis of the machine",
    """
What it checks: for every axis whose axis list switches plane compensation on (`lr_param.crosscomp2`,
P-AXIS-00174), the compensation list for that axis (`achs_kw[i]`, assigned by `achs_kw_log_ax_nr[i]` or
its own `kopf.achs_nr`) that holds a plane compensation table (`kw.crosscomp2.table[][]`) names two
master axes (`kw.crosscomp2.master1_ax_nr` P-COMP-00014, `kw.crosscomp2.master2_ax_nr` P-COMP-00015)
that are not 0 and are logical axis numbers of the machine's axis lists. Values from two lists of the
machine: checked with `zero lint --machine`; "no axis of the machine" only where every axis list the
start-up list names was read.

Why it matters on the machine: the kernel reports P-ERR-70182 (class 7, error type 2): a closed-loop
controlled stop of the axis, and plane compensation is switched off for it, so the axis runs
uncompensated. Source: https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/260224395.html

Fix: give both master axes the logical axis numbers of the axes whose positions the table is measured
over.
""", reads=("P-AXIS-00174", "P-COMP-00014", "P-COMP-00015", "P-COMP-00016", "P-AXIS-00016"))
PLANE_MASTER_NOT_LINEAR = FAMILY.rule(
    "X024", "plane-compensation-master-not-linear", E,
    "P-ERR-70184: a master axis of a plane compensation is not a linear axis",
    """
What it checks: the master axes of a plane compensation (as X023 finds them) have the axis type
translatory (`kenngr.achs_typ` 1, P-AXIS-00018) in their axis lists. Values from the compensation list
and the master axes' axis lists: checked with `zero lint --machine`.

Why it matters on the machine: the plane compensation manual lists error P-ERR-70184 ("Axis type of a master
axis for plane compensation is invalid": a master axis does not have the required axis type
translatory); errors in the configuration of plane compensation deselect the function for the axis and
output an error message, so the axis runs uncompensated. Source:
https://infosys.beckhoff.com/content/1033/axiscompensation/15327294987.html

Fix: use linear axes as master axes (`kenngr.achs_typ 1`), or switch plane compensation off.
""", reads=("P-AXIS-00174", "P-COMP-00014", "P-COMP-00015", "P-COMP-00016", "P-AXIS-00018"))
_PLANE_ON, _PLANE_TABLE, _PLANE_MASTERS = "P-AXIS-00174", "P-COMP-00016", ("P-COMP-00014", "P-COMP-00015")


@FAMILY.check(PLANE_MASTER_INVALID, PLANE_MASTER_NOT_LINEAR)
def check_plane_compensation(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X023 (P-ERR-70182), X024 (P-ERR-70184): the master axes of each plane compensation an axis
    switches on, against the machine's axis lists."""
    machine = ctx.machine
    by_axis = _compensation_lists(ctx)
    if by_axis is None:
        return  # a compensation list was not read: nothing is known of its table
    axes = machine.axes()
    complete = machine.complete_axes()
    said: set[tuple[str, int, int]] = set()  # (list, line, master): a default list's line once
    for nr, ax in sorted(axes.items()):
        on = ax.list.values.value_of(_PLANE_ON)
        if on is None or on.value.number != 1:
            continue
        for lf in by_axis.get(nr, []):
            if not lf.values.ids_of(_PLANE_TABLE):
                continue  # no table: X013 says so
            for which, pid in enumerate(_PLANE_MASTERS, start=1):
                master = lf.number(pid)
                entry = lf.entry(pid)
                if entry is not None:
                    span, path, param = Span.on_line(entry.line, entry.value_start, entry.value_end), lf.path, pid
                else:  # not written (0): said on the line that switches plane compensation on
                    layer = ax.list.values.layer_of(_PLANE_ON) or ax.list.values
                    span = Span.on_line(on.entry.line, on.entry.value_start, on.entry.value_end)
                    path, param = Path(layer.doc.path), _PLANE_ON
                where = (str(path), span.line, which)
                if where in said:
                    continue
                target = axes.get(int(master)) if master else None
                if not master or (target is None and complete):
                    said.add(where)
                    what = "is 0 (not set)" if not master else \
                        f"is {int(master)}, which no axis list of the machine has"
                    yield ctx.report(
                        "X023", span, f"P-ERR-70182: master axis {which} of the plane compensation of axis {nr} "
                        f"(`kw.crosscomp2.master{which}_ax_nr` in {lf.path.name}) {what}: the controller reports "
                        "error 70182, stops the axis (closed-loop) and switches its plane compensation off",
                        param_id=param, path=str(path), kernel_error="P-ERR-70182")
                    continue
                kind = target.list.number(_AXIS_TYPE) if target is not None else None
                if target is not None and kind is not None and int(kind) != 1:
                    said.add(where)
                    yield ctx.report(
                        "X024", span, f"P-ERR-70184: master axis {which} of the plane compensation of axis {nr} is "
                        f"logical axis {int(master)}, whose axis list ({target.list.path.name}) has axis type "
                        f"{int(kind)}, not 1 (translatory): the controller reports error 70184 and deselects plane "
                        "compensation for the axis", param_id=param, path=str(path), kernel_error="P-ERR-70184")


FEEDFORWARD_DELAY_ACCELERATION = FAMILY.rule(
    "X025", "acceleration-feedforward-delay-cycle", E,
    "P-ERR-70348: delay time of the acceleration feedforward not below the interpolator cycle time",
    """
What it checks: the delay time of the acceleration feedforward (`vorsteuer.acceleration_delay_time`,
P-AXIS-00390, µs) an axis list writes is shorter than the interpolator's cycle time: the cycle
(`thread[i].cycle`, P-RTCF-00009, µs) of the real-time configuration's thread named `CNC_IPO`
(`thread[i].name`, P-RTCF-00008), in the list `rtconf_lis` names. Values from two lists of the machine:
checked with `zero lint --machine`, and only where the real-time configuration names that thread with
a cycle.

Why it matters on the machine: the kernel reports P-ERR-70348 when it takes over the list (class 1,
error type 2) and disables the delay (P-AXIS-00390 = 0). Source:
https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/260824971.html

Fix: give the delay a value below one interpolator cycle.
""", reads=("P-AXIS-00390", "P-RTCF-00008", "P-RTCF-00009"))
FEEDFORWARD_DELAY_VELOCITY = FAMILY.rule(
    "X026", "velocity-feedforward-delay-cycle", E,
    "P-ERR-70349: delay time of the velocity feedforward not below the interpolator cycle time",
    """
What it checks: the delay time of the velocity feedforward (`vorsteuer.velocity_delay_time`,
P-AXIS-00389, µs) an axis list writes is shorter than the interpolator's cycle time, found as for X025.
Values from two lists of the machine: checked with `zero lint --machine`.

Why it matters on the machine: the kernel reports P-ERR-70349 when it takes over the list (class 1,
error type 2) and disables the delay (P-AXIS-00389 = 0). Source:
https://infosys.beckhoff.com/content/1033/tf5200_diagnosis/260829323.html

Fix: give the delay a value below one interpolator cycle.
""", reads=("P-AXIS-00389", "P-RTCF-00008", "P-RTCF-00009"))
_IPO_THREAD = "CNC_IPO"  # the interpolator's thread of the vendor's real-time configuration
_FEEDFORWARD_DELAYS = (("X025", "P-AXIS-00390", "acceleration", 70348), ("X026", "P-AXIS-00389", "velocity", 70349))


def _interpolator_cycle(ctx: MachineContext) -> tuple[int, str] | None:
    """The cycle (µs) of the real-time configuration's interpolator thread, and the list's name; ``None``
    where the machine has no real-time configuration or it names no such thread with a cycle."""
    rtconf = ctx.machine.singles.get("rtconf_lis")
    if rtconf is None:
        return None
    for idx in sorted(rtconf.values.ids_of("P-RTCF-00008")):
        if rtconf.text("P-RTCF-00008", idx) == _IPO_THREAD:
            cycle = rtconf.number("P-RTCF-00009", idx)
            return (int(cycle), rtconf.path.name) if cycle else None
    return None


@FAMILY.check(FEEDFORWARD_DELAY_ACCELERATION, FEEDFORWARD_DELAY_VELOCITY)
def check_feedforward_delays(ctx: MachineContext) -> Iterator[Diagnostic]:
    """X025 (P-ERR-70348), X026 (P-ERR-70349): feedforward delay times against the interpolator cycle."""
    found = _interpolator_cycle(ctx)
    if found is None:
        return
    cycle, rtconf = found
    for lf in ctx.machine.axis_lists:
        for code, pid, what, number in _FEEDFORWARD_DELAYS:
            delay, entry = lf.number(pid), lf.entry(pid)
            if entry is None or delay is None or delay < cycle:
                continue  # not written here (a default list's is reported there), or below the cycle
            yield ctx.report(
                code, Span.on_line(entry.line, entry.value_start, entry.value_end),
                f"P-ERR-{number}: the delay time of the {what} feedforward is {int(delay)} µs, not below the "
                f"interpolator cycle time {cycle} µs (thread {_IPO_THREAD} in {rtconf}): the controller reports "
                f"error {number} when it takes over the list and disables the delay ({pid} = 0)",
                param_id=pid, path=str(lf.path), kernel_error=f"P-ERR-{number}")

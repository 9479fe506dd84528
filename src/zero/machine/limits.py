"""Soft limits in the programming coordinate system, and the IP247 rule (``zero limits``).

The controller checks positions against the soft limits of each axis (ACS). A work
offset shifts the programming coordinate system, so the limits a program sees are the
ACS limits minus the offset its group applies. IP247 (Siemens S5) bounds offsets, soft
limits and soft limits plus tool offsets to ±99.999999 m.
"""

from __future__ import annotations

import math

from zero.catalog.ids import (
    G53_AVAILABLE,
    INACTIVE,
    IP247_LIMIT,
    OFFSET,
    TOOL_AXIS_OFFSET,
    TOOL_LENGTH,
    TOOL_LENGTH_AXIS,
    Number,
    fixed,
    g_code,
    in_units,
)
from zero.machine.model import Machine
from zero.records import Record


class LimitRow(Record):
    channel: int
    group: int
    axis_index: int
    axis_name: str
    log_nr: int
    unit: str
    acs_neg: Number
    acs_pos: Number
    offset: Number  # applied offset (0 when masked or G53 without g53_verfuegbar)
    masked: bool
    pcs_neg: Number
    pcs_pos: Number
    note: str = ""

    def to_json(self) -> dict[str, object]:
        def u(x: Number) -> float | None:
            mm = in_units(x)
            return round(mm, 4) if math.isfinite(mm) else None  # beyond a float: no JSON number

        return {"channel": self.channel, "group": self.group, "g_code": g_code(self.group),
                "axis": self.axis_index, "name": self.axis_name, "log_nr": self.log_nr, "unit": self.unit,
                "acs_neg": u(self.acs_neg), "acs_pos": u(self.acs_pos), "offset": u(self.offset),
                "masked": self.masked, "pcs_neg": u(self.pcs_neg), "pcs_pos": u(self.pcs_pos),
                "note": self.note or None}


def pcs_limits(machine: Machine, all_groups: bool = False) -> list[LimitRow]:
    """Soft limits in the programming coordinate system, per work offset and channel axis:
    ACS limit minus the offset the group applies (masked axes and G53 without
    ``g53_verfuegbar`` apply none). Groups G53..G59 always, higher ones where the list
    sets them (or all 97 with ``all_groups``)."""
    axes = machine.axes()
    rows: list[LimitRow] = []
    for ch in machine.channels:
        zl = ch.zero
        g53 = bool(zl.number(G53_AVAILABLE)) if zl is not None else False
        groups = set(range(7))
        if zl is not None:
            groups |= {ix[0] for ix in zl.values.by_id.get(OFFSET, {}) if ix}
        if all_groups:
            groups = set(range(97))
        for g in sorted(groups):
            for ca in ch.axes:
                ax = axes.get(ca.log_nr)
                if ax is None:
                    continue
                raw = zl.number(OFFSET, (g, ca.index)) if zl is not None else 0
                masked = bool(zl.number(INACTIVE, (g, ca.index))) if zl is not None else False
                offset = raw or 0
                note = ""
                if masked:
                    note, offset = "masked (inaktiv 1)", 0
                elif g == 0 and not g53:
                    note, offset = "G53 deselects all offsets (g53_verfuegbar 0)", 0
                rows.append(LimitRow(ch.index, g, ca.index, ca.name, ca.log_nr, ax.unit, ax.swe_neg, ax.swe_pos,
                                     offset, masked, ax.swe_neg - offset, ax.swe_pos - offset, note))
    return rows


class Ip247Violation(Record):
    what: str
    value: Number
    where: str


def ip247(machine: Machine) -> list[Ip247Violation]:
    """The Siemens S5 IP247 rule: offsets, soft limits, and soft limits plus each tool's offset
    on that axis (``wz[t].ax_versatz[j]``, plus the length on the third channel axis) inside
    ±99.999999 m."""
    out: list[Ip247Violation] = []
    axes = machine.axes()
    for ch in machine.channels:
        if ch.tools is None:
            continue
        ctx = ch.tools.values
        numbers = {t[0] for t in (*ctx.by_id.get(TOOL_LENGTH, {}), *ctx.by_id.get(TOOL_AXIS_OFFSET, {})) if t}
        for tool in sorted(numbers):
            for ca in ch.axes:
                ax = axes.get(ca.log_nr)
                if ax is None:
                    continue
                off = ch.tools.number(TOOL_AXIS_OFFSET, (tool, ca.index)) or 0
                if ca.index == TOOL_LENGTH_AXIS:
                    off += ch.tools.number(TOOL_LENGTH, (tool,)) or 0
                if not off:
                    continue
                for what, limit in (("positive soft limit", ax.swe_pos), ("negative soft limit", ax.swe_neg)):
                    total = limit + abs(off) if limit >= 0 else limit - abs(off)
                    if abs(total) > IP247_LIMIT:
                        out.append(Ip247Violation(f"{what} of {ca.name} plus tool {tool}", total,
                                                  f"{ch.tools.path} (offset {fixed(off, 'mm')})"))
    for ax in machine.axes().values():
        for what, v in (("negative soft limit", ax.swe_neg), ("positive soft limit", ax.swe_pos)):
            if abs(v) > IP247_LIMIT:
                out.append(Ip247Violation(what, v, f"{ax.list.path} ({ax.name})"))
    for ch in machine.channels:
        if ch.zero is None:
            continue
        for idx, res in sorted(ch.zero.values.by_id.get(OFFSET, {}).items()):
            offset = res.value.number
            if offset is not None and abs(offset) > IP247_LIMIT:
                out.append(Ip247Violation(f"offset {g_code(idx[0])} axis {idx[1]}", offset,
                                          f"{ch.zero.path}:{res.entry.line}"))
    return out

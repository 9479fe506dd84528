"""Pictures of a machine's axes as SVG: the travel range of each axis (``zero report``,
``zero limits --output-format svg``).

A linear axis is a horizontal bar from its negative to its positive soft limit (``kenngr.swe_neg``,
``kenngr.swe_pos``) over the tolerance band around it (``kenngr.swe_toleranz``), the reference
point (``getriebe[0].pos_refpkt``) as a triangle, and one row per work offset group with its zero
point as a marker and the programmable range (the soft limits in the programming coordinate
system: :func:`zero.machine.limits.pcs_limits`) at the row's ends. A rotary axis is an arc from
its negative to its positive soft limit, or a circle marked "modulo" where it counts modulo
(``kenngr.mod_rechng``, every spindle). Every element carries its values as data attributes
(``data-swe-neg``, ``data-x``, …, in mm or degrees) so that a test can read the drawing back.

Nothing here reads a file: the pictures are made from the machine the resolver loaded.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from html import escape

from zero.catalog.ids import SWE_BEHAVIOUR, SWE_CHECK, SWE_TOL, Number, g_code, in_units
from zero.machine.limits import LimitRow, pcs_limits
from zero.machine.model import Axis, Machine
from zero.records import Record, field

MOD_CALC = "P-AXIS-00121"  # kenngr.mod_rechng: the axis counts modulo
REF_POINT = "P-AXIS-00152"  # getriebe[g].pos_refpkt: the reference point (gear 0 drawn)
MOD_LOW, MOD_HIGH = "P-AXIS-00127", "P-AXIS-00126"  # getriebe[g].modulou, getriebe[g].moduloo
SPINDLE_TYPE = 4  # kenngr.achs_typ of a spindle
WARNING_AXES = "P-CHAN-00147"  # soft_limit_warning_axes: bit j, channel axis j only warns (command side)

# What the soft-limit monitoring of an axis does (``AxisPicture.monitoring``), from the vendor's axis
# parameter pages: kenngr.swe_check 0 switches it off whatever the axis type and mode
# (https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117316107.html);
# kenngr.swe_behaviour WARNING only warns, ERROR_LR warns in path planning and stops in the position
# controller (https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/491520267.html); the
# channel's soft_limit_warning_axes bit j makes crossing on the command side only a warning for
# channel axis j (https://infosys.beckhoff.com/content/1031/tf5200_channel_parameter/149359243.html).
MONITORED, OFF, WARNS, WARNS_IN_PLANNING = "on", "off", "warning", "error-lr"
MONITORING_WORDS = {
    OFF: "soft-limit monitoring OFF",
    WARNS: "soft limits only WARN",
    WARNS_IN_PLANNING: "soft limits warn in path planning, stop in the position controller",
}

WIDTH = 760  # every picture is this wide
LEFT, RIGHT = 96, 40  # the label column and the right margin of a linear axis
ROW = 18  # one work offset group
BAR_TOP, BAR_HEIGHT = 46, 22
ROTARY_CENTRE = 110.0
REACH = 2.0  # zero points farther than this many travel lengths beyond the limits are drawn at the edge


def _mm(value: Number | None) -> float | None:
    if value is None:
        return None
    v = in_units(value)
    return v if math.isfinite(v) else None


def _num(value: float) -> str:
    """A value in mm or degrees for a data attribute and a label: up to four decimals."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


class ZeroPoint(Record):
    """One work offset group on one channel axis: where its zero lies (ACS) and what a program may
    reach (PCS)."""

    group: int
    offset: float  # mm or degrees; the zero point in machine coordinates
    pcs_neg: float | None
    pcs_pos: float | None
    note: str = ""

    @property
    def label(self) -> str:
        return g_code(self.group)


class AxisPicture(Record):
    """What is drawn for one axis (of a channel, where a channel maps it)."""

    name: str
    log_nr: int
    unit: str  # mm or °
    rotary: bool
    modulo: bool
    swe_neg: float
    swe_pos: float
    tolerance: float
    ref: float | None
    channel: int | None = None
    index: int | None = None  # j in the channel's gruppe[0].achse[j]
    zeros: list[ZeroPoint] = field(default_factory=list)
    modulo_range: tuple[float, float] | None = None
    old_neg: float | None = None  # the soft limits of the machine compared against, where they differ
    old_pos: float | None = None
    monitoring: str = MONITORED  # on, off (swe_check 0), warning (swe_behaviour WARNING), error-lr
    monitoring_why: str = ""  # the setting that decides it: "kenngr.swe_check = 0"
    travel: list[tuple[str, float, float]] = field(default_factory=list)  # (program, lowest, highest) on the axis

    @property
    def ident(self) -> str:
        where = f"c{self.channel}-a{self.index}" if self.channel is not None else "m"
        return f"axis-{where}-{self.log_nr}"

    @property
    def title(self) -> str:
        where = f"channel {self.channel} axis {self.index}, " if self.channel is not None else ""
        kind = ("rotary, modulo" if self.modulo else "rotary") if self.rotary else "linear"
        return f"{self.name} ({where}logical axis {self.log_nr}, {kind})"

    @property
    def changed(self) -> bool:
        return self.old_neg is not None or self.old_pos is not None

    @property
    def monitoring_said(self) -> str:
        """The mark drawn on an axis whose soft limits do not stop it: "" where they do."""
        words = MONITORING_WORDS.get(self.monitoring, "")
        return f"{words} ({self.monitoring_why})" if words and self.monitoring_why else words


def monitoring_of(ax: Axis) -> tuple[str, str]:
    """What the axis list says the soft-limit monitoring does, and the setting that says it:
    ``swe_check 0`` switches it off; ``swe_behaviour WARNING`` (or ``ERROR_LR``) makes it warn."""
    lf = ax.list
    check = lf.number(SWE_CHECK)
    if check is not None and check == 0:
        return OFF, "kenngr.swe_check = 0"
    behaviour = (lf.text(SWE_BEHAVIOUR) or "").strip().upper()
    if behaviour == "WARNING":
        return WARNS, "kenngr.swe_behaviour = WARNING"
    if behaviour == "ERROR_LR":
        return WARNS_IN_PLANNING, "kenngr.swe_behaviour = ERROR_LR"
    return MONITORED, ""


def _axis_facts(ax: Axis) -> dict[str, object]:
    lf = ax.list
    modulo = ax.rotary and (bool(lf.number(MOD_CALC)) or lf.number("P-AXIS-00018") == SPINDLE_TYPE)
    low, high = _mm(lf.number(MOD_LOW, (0,))), _mm(lf.number(MOD_HIGH, (0,)))
    monitoring, why = monitoring_of(ax)
    return {"name": ax.name, "log_nr": ax.nr, "unit": ax.unit, "rotary": ax.rotary, "modulo": modulo,
            "monitoring": monitoring, "monitoring_why": why,
            "swe_neg": _mm(ax.swe_neg) or 0.0, "swe_pos": _mm(ax.swe_pos) or 0.0,
            "tolerance": _mm(lf.number(SWE_TOL)) or 0.0, "ref": _mm(lf.number(REF_POINT, (0,))),
            "modulo_range": (low if low is not None else 0.0, high if high is not None else 360.0) if modulo
            else None}


def axis_pictures(machine: Machine, rows: Sequence[LimitRow] | None = None,
                  against: Machine | None = None) -> list[AxisPicture]:
    """One picture per channel axis (with that channel's work offsets), then one per axis no channel
    maps; ``rows`` the work offsets (:func:`pcs_limits`, computed when not given); ``against`` a
    machine whose soft limits are drawn under the changed ones."""
    rows = pcs_limits(machine) if rows is None else rows
    axes = machine.axes()
    old_axes = against.axes() if against is not None else {}
    out: list[AxisPicture] = []
    seen: set[int] = set()
    by_axis: dict[tuple[int, int], list[LimitRow]] = {}
    for r in rows:
        by_axis.setdefault((r.channel, r.axis_index), []).append(r)
    for ch in machine.channels:
        for ca in ch.axes:
            ax = axes.get(ca.log_nr)
            if ax is None:
                continue
            seen.add(ax.nr)
            pic = AxisPicture(**_axis_facts(ax), channel=ch.index, index=ca.index)  # type: ignore[arg-type]
            pic.name = ca.name
            mask = ch.lists.number(WARNING_AXES) if ch.lists is not None else None
            if pic.monitoring == MONITORED and mask and 0 <= ca.index < 64 and int(mask) >> ca.index & 1:
                pic.monitoring = WARNS_IN_PLANNING  # the command side only warns; the actual side still stops
                pic.monitoring_why = f"soft_limit_warning_axes bit {ca.index} of channel {ch.index}"
            for r in by_axis.get((ch.index, ca.index), []):
                pic.zeros.append(ZeroPoint(r.group, _mm(r.offset) or 0.0, _mm(r.pcs_neg), _mm(r.pcs_pos), r.note))
            out.append(pic)
    for nr, ax in sorted(axes.items()):
        if nr not in seen:
            out.append(AxisPicture(**_axis_facts(ax)))  # type: ignore[arg-type]
    for pic in out:
        old = old_axes.get(pic.log_nr)
        if old is not None:
            neg, pos = _mm(old.swe_neg) or 0.0, _mm(old.swe_pos) or 0.0
            if (neg, pos) != (pic.swe_neg, pic.swe_pos):
                pic.old_neg, pic.old_pos = neg, pos
    return out


# ------------------------------------------------------------------------- drawing


class Scale(Record):
    lo: float
    hi: float
    x0: float = LEFT
    x1: float = WIDTH - RIGHT

    def x(self, value: float) -> float:
        """The x position of ``value``, clamped to the drawing."""
        if self.hi == self.lo:
            return (self.x0 + self.x1) / 2
        t = (value - self.lo) / (self.hi - self.lo)
        return round(self.x0 + min(max(t, 0.0), 1.0) * (self.x1 - self.x0), 3)

    def inside(self, value: float) -> bool:
        return self.lo <= value <= self.hi


def scale_for(pic: AxisPicture) -> Scale:
    """The range drawn: the soft limits with their tolerance, the reference point, the old limits and
    every zero point within reach, with a margin."""
    lo, hi = pic.swe_neg - pic.tolerance, pic.swe_pos + pic.tolerance
    span = max(hi - lo, 1e-9)
    values = [v for v in (pic.ref, pic.old_neg, pic.old_pos) if v is not None]
    values += [z.offset for z in pic.zeros if pic.swe_neg - REACH * span <= z.offset <= pic.swe_pos + REACH * span]
    values += [v for _, low, high in pic.travel for v in (low, high)
               if pic.swe_neg - REACH * span <= v <= pic.swe_pos + REACH * span]
    lo, hi = min([lo, *values]), max([hi, *values])
    pad = (hi - lo) * 0.05 or 1.0
    return Scale(lo - pad, hi + pad)


def _ticks(scale: Scale, count: int = 6) -> list[float]:
    span = scale.hi - scale.lo
    if span <= 0:
        return [scale.lo]
    raw = span / count
    step = 10 ** math.floor(math.log10(raw))
    for m in (1, 2, 5, 10):
        if raw <= m * step:
            step *= m
            break
    first = math.ceil(scale.lo / step) * step
    return [first + i * step for i in range(int((scale.hi - first) / step) + 1)]


def _attrs(**values: object) -> str:
    parts = []
    for k, v in values.items():
        if v is None:
            continue
        if isinstance(v, float):
            v = _num(v)
        parts.append(f'{k.rstrip("_").replace("_", "-")}="{escape(str(v), quote=True)}"')
    return " ".join(parts)


def picture_height(pic: AxisPicture) -> int:
    if pic.rotary:
        return max(200, int(ROTARY_CENTRE + 14 * (len(pic.zeros) + 1) + 12))
    return BAR_TOP + BAR_HEIGHT + 34 + ROW * len(pic.zeros) + 8


def axis_group(pic: AxisPicture, y: float = 0) -> str:
    """One axis as an SVG group (``<g class="axis">``), placed ``y`` down."""
    return (_rotary if pic.rotary else _linear)(pic, y)


def _linear(pic: AxisPicture, y: float) -> str:
    s = scale_for(pic)
    u = pic.unit
    top, bottom = BAR_TOP, BAR_TOP + BAR_HEIGHT
    out = [f'<g class="axis linear{" changed" if pic.changed else ""}{_monitor_class(pic)}" id="{escape(pic.ident)}" '
           + _attrs(transform=f"translate(0,{y})" if y else None, data_axis=pic.name, data_log_nr=pic.log_nr,
                    data_monitoring=pic.monitoring,
                    data_unit=u, data_domain_lo=s.lo, data_domain_hi=s.hi, data_x0=s.x0, data_x1=s.x1,
                    data_swe_neg=pic.swe_neg, data_swe_pos=pic.swe_pos, data_tolerance=pic.tolerance) + ">",
           f'<title>{escape(pic.title)}</title>',
           f'<text class="axis-title" x="4" y="16">{escape(pic.title)}</text>']
    tn, tp = s.x(pic.swe_neg - pic.tolerance), s.x(pic.swe_pos + pic.tolerance)
    out.append(f'<rect class="tolerance" {_attrs(x=tn, y=top - 4, width=round(tp - tn, 3), height=BAR_HEIGHT + 8)} '
               f'{_attrs(data_tolerance=pic.tolerance)}><title>tolerance ±{_num(pic.tolerance)} {u}</title></rect>')
    if pic.changed and pic.old_neg is not None and pic.old_pos is not None:
        on, op = s.x(pic.old_neg), s.x(pic.old_pos)
        out.append(f'<rect class="old-range" {_attrs(x=on, y=top, width=round(op - on, 3), height=BAR_HEIGHT)} '
                   f'{_attrs(data_swe_neg=pic.old_neg, data_swe_pos=pic.old_pos, data_x_neg=on, data_x_pos=op)}>'
                   f'<title>before: {_num(pic.old_neg)} .. {_num(pic.old_pos)} {u}</title></rect>')
    xn, xp = s.x(pic.swe_neg), s.x(pic.swe_pos)
    out.append(f'<rect class="soft-range" {_attrs(x=xn, y=top, width=round(xp - xn, 3), height=BAR_HEIGHT)} '
               f'{_attrs(data_swe_neg=pic.swe_neg, data_swe_pos=pic.swe_pos, data_x_neg=xn, data_x_pos=xp)}>'
               f'<title>soft limits {_num(pic.swe_neg)} .. {_num(pic.swe_pos)} {u}'
               f'{escape("; " + pic.monitoring_said) if pic.monitoring_said else ""}</title></rect>')
    for k, (program, low, high) in enumerate(pic.travel):  # a program's travel (zero report --program)
        beyond = low < pic.swe_neg or high > pic.swe_pos
        xl, xh = s.x(low), s.x(high)
        said = f"{program}: {_num(low)} .. {_num(high)} {u} on the axis{'; beyond its soft limits' if beyond else ''}"
        out.append(f'<rect class="travel{" beyond" if beyond else ""}" '
                   f'{_attrs(x=xl, y=bottom - 5 - 5 * k, width=round(max(xh - xl, 1.0), 3), height=4)} '
                   f'{_attrs(data_program=program, data_low=low, data_high=high)}><title>{escape(said)}</title></rect>')
    out.append(_monitor_mark(pic, WIDTH - RIGHT, 16, "end"))
    for cls, value, x, anchor in (("swe-neg", pic.swe_neg, xn, "end"), ("swe-pos", pic.swe_pos, xp, "start")):
        out.append(f'<line class="limit {cls}" {_attrs(x1=x, x2=x, y1=top - 8, y2=bottom + 8)} '
                   f'{_attrs(data_value=value, data_x=x)}/>')
        dx = -3 if anchor == "end" else 3
        out.append(f'<text class="limit-label" {_attrs(x=round(x + dx, 3), y=top - 10, text_anchor=anchor)}>'
                   f'{escape(_num(value))} {escape(u)}</text>')
    if pic.ref is not None:
        xr = s.x(pic.ref)
        out.append(f'<path class="ref" d="M{_num(xr)},{bottom} l-5,8 h10 z" {_attrs(data_ref=pic.ref, data_x=xr)}>'
                   f'<title>reference point {_num(pic.ref)} {u}</title></path>')
    axis_y = bottom + 22
    out.append(f'<line class="scale" {_attrs(x1=s.x0, x2=s.x1, y1=axis_y, y2=axis_y)}/>')
    for t in _ticks(s):
        xt = s.x(t)
        out.append(f'<line class="tick" {_attrs(x1=xt, x2=xt, y1=axis_y, y2=axis_y + 4)}/>'
                   f'<text class="tick-label" {_attrs(x=xt, y=axis_y + 14, text_anchor="middle")}>'
                   f'{escape(_num(t))}</text>')
    row_y = axis_y + 22
    for z in pic.zeros:
        clipped = not s.inside(z.offset)
        outside = not (pic.swe_neg <= z.offset <= pic.swe_pos)
        xz = s.x(z.offset)
        cls = "zero" + (" outside" if outside else "") + (" clipped" if clipped else "") + \
            (" inactive" if z.note else "")
        out.append(f'<g class="{cls}" ' + _attrs(data_group=z.group, data_g_code=z.label, data_offset=z.offset,
                                                 data_x=xz, data_pcs_neg=z.pcs_neg, data_pcs_pos=z.pcs_pos,
                                                 data_clipped="true" if clipped else None) + ">")
        out.append(f'<title>{escape(z.label)}: zero point at {_num(z.offset)} {u}; programmable '
                   f'{_pcs(z.pcs_neg)} .. {_pcs(z.pcs_pos)} {u}{escape("; " + z.note) if z.note else ""}</title>')
        out.append(f'<text class="row-label" {_attrs(x=4, y=row_y + 4)}>{escape(z.label)}</text>')
        out.append(f'<line class="pcs-range" {_attrs(x1=xn, x2=xp, y1=row_y, y2=row_y)}/>')
        out.append(f'<text class="pcs-label" {_attrs(x=round(xn - 3, 3), y=row_y + 4, text_anchor="end")}>'
                   f'{_pcs(z.pcs_neg)}</text>')
        out.append(f'<text class="pcs-label" {_attrs(x=round(xp + 3, 3), y=row_y + 4)}>{_pcs(z.pcs_pos)}</text>')
        out.append(f'<line class="zero-tick" {_attrs(x1=xz, x2=xz, y1=bottom, y2=row_y)}/>')
        out.append(f'<circle class="zero-marker" {_attrs(cx=xz, cy=row_y, r=4)}/>')
        if clipped:
            right = xz > s.x0
            out.append('<text class="clip-label" '
                       + _attrs(x=round(xz + (-6 if right else 6), 3), y=row_y - 5,
                                text_anchor="end" if right else "start")
                       + f'>{"→" if right else "←"} {escape(_num(z.offset))} {escape(u)}</text>')
        out.append("</g>")
        row_y += ROW
    out.append("</g>")
    return "\n".join(out)


def _monitor_class(pic: AxisPicture) -> str:
    return f" monitoring-{pic.monitoring}" if pic.monitoring != MONITORED else ""


def _monitor_mark(pic: AxisPicture, x: float, y: float, anchor: str) -> str:
    """The red mark on an axis whose soft limits do not stop it ("" where they do)."""
    if not pic.monitoring_said:
        return ""
    return (f'<text class="monitor-mark" {_attrs(x=x, y=y, text_anchor=anchor)}>'
            f'⚠ {escape(pic.monitoring_said)}</text>')


def _pcs(value: float | None) -> str:
    return escape(_num(value)) if value is not None else "beyond a float"


def _polar(cx: float, cy: float, r: float, degrees: float) -> tuple[float, float]:
    """A point of the circle: 0° to the right, counter-clockwise as on a drawing of the machine."""
    a = math.radians(degrees)
    return round(cx + r * math.cos(a), 3), round(cy - r * math.sin(a), 3)


def _rotary(pic: AxisPicture, y: float) -> str:
    cx, cy, r = 110.0, ROTARY_CENTRE, 64.0
    u = pic.unit
    out = [f'<g class="axis rotary{" modulo" if pic.modulo else ""}{" changed" if pic.changed else ""}'
           f'{_monitor_class(pic)}" id="{escape(pic.ident)}" '
           + _attrs(transform=f"translate(0,{y})" if y else None, data_axis=pic.name, data_log_nr=pic.log_nr,
                    data_monitoring=pic.monitoring,
                    data_unit=u, data_swe_neg=pic.swe_neg, data_swe_pos=pic.swe_pos, data_tolerance=pic.tolerance,
                    data_modulo="true" if pic.modulo else "false", data_cx=cx, data_cy=cy, data_r=r) + ">",
           f'<title>{escape(pic.title)}</title>',
           f'<text class="axis-title" x="4" y="16">{escape(pic.title)}</text>',
           f'<circle class="dial" {_attrs(cx=cx, cy=cy, r=r)}/>', _monitor_mark(pic, WIDTH - RIGHT, 16, "end")]
    if pic.modulo:
        low, high = pic.modulo_range or (0.0, 360.0)
        out.append(f'<circle class="modulo-ring" {_attrs(cx=cx, cy=cy, r=r)}/>')
        out.append(f'<text class="modulo-label" {_attrs(x=cx, y=cy + 4, text_anchor="middle")}>modulo</text>')
        out.append(f'<text class="note" {_attrs(x=cx + r + 24, y=cy - 8)}>counts modulo {escape(_num(low))} .. '
                   f'{escape(_num(high))} {escape(u)}: no end of travel</text>')
    else:
        if pic.changed and pic.old_neg is not None and pic.old_pos is not None:
            out.append(_arc("old-range", cx, cy, r + 8, pic.old_neg, pic.old_pos))
        out.append(_arc("soft-range", cx, cy, r, pic.swe_neg, pic.swe_pos))
        for cls, value in (("swe-neg", pic.swe_neg), ("swe-pos", pic.swe_pos)):
            x1, y1 = _polar(cx, cy, r - 10, value)
            x2, y2 = _polar(cx, cy, r + 10, value)
            out.append(f'<line class="limit {cls}" {_attrs(x1=x1, y1=y1, x2=x2, y2=y2, data_value=value)}/>')
        turns = (pic.swe_pos - pic.swe_neg) / 360
        out.append(f'<text class="note" {_attrs(x=cx + r + 24, y=cy - 8)}>soft limits {escape(_num(pic.swe_neg))} .. '
                   f'{escape(_num(pic.swe_pos))} {escape(u)}'
                   + (f" ({escape(_num(round(turns, 2)))} turns)" if turns > 1 else "") + "</text>")
    if pic.ref is not None:
        xr, yr = _polar(cx, cy, r, pic.ref)
        out.append(f'<circle class="ref" {_attrs(cx=xr, cy=yr, r=4, data_ref=pic.ref)}>'
                   f'<title>reference point {_num(pic.ref)} {u}</title></circle>')
    ny = cy + 14
    for z in pic.zeros:
        xz, yz = _polar(cx, cy, r - 18, z.offset)
        outside = not pic.modulo and not (pic.swe_neg <= z.offset <= pic.swe_pos)
        out.append(f'<g class="zero{" outside" if outside else ""}" '
                   + _attrs(data_group=z.group, data_g_code=z.label, data_offset=z.offset,
                            data_pcs_neg=z.pcs_neg, data_pcs_pos=z.pcs_pos) + ">"
                   f'<circle class="zero-marker" {_attrs(cx=xz, cy=yz, r=3)}/>'
                   f'<text class="pcs-label" {_attrs(x=cx + r + 24, y=ny)}>{escape(z.label)}: zero at '
                   f'{escape(_num(z.offset))} {escape(u)}, programmable {_pcs(z.pcs_neg)} .. {_pcs(z.pcs_pos)}'
                   f'{escape(" (" + z.note + ")") if z.note else ""}</text></g>')
        ny += 14
    out.append("</g>")
    return "\n".join(out)


def _arc(cls: str, cx: float, cy: float, r: float, start: float, end: float) -> str:
    span = end - start
    attrs = _attrs(data_swe_neg=start, data_swe_pos=end)
    if span >= 360:
        return f'<circle class="{cls} full-turn" {_attrs(cx=cx, cy=cy, r=r)} {attrs}/>'
    x1, y1 = _polar(cx, cy, r, start)
    x2, y2 = _polar(cx, cy, r, end)
    large = 1 if span > 180 else 0
    d = f"M{_num(x1)},{_num(y1)} A{_num(r)},{_num(r)} 0 {large} 0 {_num(x2)},{_num(y2)}"
    return f'<path class="{cls}" d="{d}" {attrs}/>'


STYLE = """
.axis-title { font: bold 13px sans-serif; fill: #222; }
.tolerance { fill: #fde8c8; stroke: none; }
.soft-range { fill: #8fb8de; fill-opacity: 0.85; stroke: #2c5d8a; }
.old-range { fill: none; stroke: #c0392b; stroke-dasharray: 4 3; stroke-width: 2; }
.axis.changed .soft-range { fill: #f4b183; }
.travel { fill: #1f4e79; }
.travel.beyond { fill: #c00000; }
.limit { stroke: #1b3d5c; stroke-width: 2; }
.limit-label, .tick-label, .pcs-label, .row-label, .note, .clip-label, .modulo-label {
  font: 11px sans-serif; fill: #333; }
.scale, .tick { stroke: #777; }
.ref { fill: #2e7d32; }
.pcs-range { stroke: #9bb7d4; stroke-width: 3; }
.zero-tick { stroke: #555; stroke-dasharray: 2 2; }
.zero-marker { fill: #fff; stroke: #222; stroke-width: 1.5; }
.zero.outside .zero-marker { fill: #c0392b; stroke: #7b241c; }
.zero.outside .row-label, .clip-label { fill: #c0392b; }
.zero.inactive .zero-marker { stroke-dasharray: 2 1; fill: #ddd; }
.dial { fill: none; stroke: #ccc; stroke-width: 1; }
.rotary .soft-range { fill: none; stroke: #2c5d8a; stroke-width: 10; stroke-opacity: 0.7; }
.rotary .old-range { fill: none; }
.modulo-ring { fill: none; stroke: #7e57c2; stroke-width: 6; stroke-dasharray: 10 5; }
.monitor-mark { font: bold 12px sans-serif; fill: #b3261e; }
.axis.monitoring-off .soft-range, .axis.monitoring-warning .soft-range, .axis.monitoring-error-lr .soft-range {
  fill: #e8e8e8; stroke: #b3261e; stroke-width: 2; stroke-dasharray: 6 3; }
.axis.monitoring-off.rotary .soft-range, .axis.monitoring-warning.rotary .soft-range,
.axis.monitoring-error-lr.rotary .soft-range { fill: none; stroke: #bbb; }
.legend-label { font: 11px sans-serif; fill: #333; }
"""

# The legend of the stand-alone picture: what each mark means (the report's page has its own).
LEGEND = (
    ("soft-range", "soft limits (kenngr.swe_neg .. swe_pos)"),
    ("tolerance", "tolerance (kenngr.swe_toleranz)"),
    ("ref", "reference point (getriebe[0].pos_refpkt)"),
    ("zero-marker", "work zero; row: programmable range at its ends"),
    ("outside", "work zero outside the soft limits"),
    ("monitoring-off", "soft limits that do not stop the axis (swe_check 0, swe_behaviour WARNING/ERROR_LR)"),
)
LEGEND_ROW = 16


def legend_svg(y: float) -> tuple[str, int]:
    """The legend as an SVG group placed ``y`` down, and the height it takes."""
    out = [f'<g class="legend" transform="translate(0,{_num(y)})">']
    for i, (cls, text) in enumerate(LEGEND):
        row = i * LEGEND_ROW
        if cls == "soft-range":
            mark = f'<rect class="soft-range" x="8" y="{row}" width="22" height="10"/>'
        elif cls == "tolerance":
            mark = f'<rect class="tolerance" x="8" y="{row}" width="22" height="10"/>'
        elif cls == "ref":
            mark = f'<path class="ref" d="M19,{row} l-5,10 h10 z"/>'
        elif cls == "zero-marker":
            mark = f'<circle class="zero-marker" cx="19" cy="{row + 5}" r="4"/>'
        elif cls == "outside":
            mark = f'<g class="zero outside"><circle class="zero-marker" cx="19" cy="{row + 5}" r="4"/></g>'
        else:
            mark = (f'<g class="axis monitoring-off"><rect class="soft-range" x="8" y="{row}" width="22" '
                    f'height="10"/></g>')
        out.append(f'<g class="legend-item" data-mark="{cls}">{mark}'
                   f'<text class="legend-label" x="40" y="{row + 9}">{escape(text)}</text></g>')
    out.append("</g>")
    return "\n".join(out), len(LEGEND) * LEGEND_ROW + 8


def axes_svg(pictures: Sequence[AxisPicture], title: str = "") -> str:
    """All axes in one standalone SVG document (for a README or a ticket): one group per axis."""
    y = 28 if title else 4
    legend, height = legend_svg(y)
    groups = [legend]
    y += height
    for pic in pictures:
        groups.append(axis_group(pic, y))
        y += picture_height(pic) + 12
    head = f'<text class="axis-title" x="4" y="18">{escape(title)}</text>\n' if title else ""
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{y}" viewBox="0 0 {WIDTH} {y}" '
            f'font-family="sans-serif">\n<style>{STYLE}</style>\n'
            f'<rect width="100%" height="100%" fill="#fff"/>\n{head}' + "\n".join(groups) + "\n</svg>\n")


def axis_svg(pic: AxisPicture) -> str:
    """One axis as an inline ``<svg>`` element of the HTML report (styled by the report's CSS)."""
    h = picture_height(pic)
    return (f'<svg class="axis-picture" width="{WIDTH}" height="{h}" '
            f'viewBox="0 0 {WIDTH} {h}" role="img" aria-label="{escape(pic.title, quote=True)}">\n'
            + axis_group(pic) + "\n</svg>")


def limits_svg(machine: Machine, rows: Sequence[LimitRow]) -> str:
    """``zero limits --output-format svg``: every axis of the machine in one picture."""
    return axes_svg(axis_pictures(machine, rows), f"Soft limits and work offsets: {machine.startup.path}")

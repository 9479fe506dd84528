"""M rules: what the values of one list mean together, as the manuals define it."""

from __future__ import annotations

from collections.abc import Iterator

from zero.catalog.evidence import claim
from zero.catalog.ids import (
    DEFAULT_INDEX,
    FEED_DEN,
    FEED_NUM,
    G53_AVAILABLE,
    INACTIVE,
    OFFSET,
    OFFSET_NEG,
    OFFSET_POS,
    RES_DEN,
    RES_NUM,
    SWE_BEHAVIOUR,
    SWE_CHECK,
    SWE_NEG,
    SWE_POS,
    SWE_TOL,
    g_code,
    length_text,
)
from zero.catalog.ranges import TYPE_LIMITS
from zero.catalog.values import Resolved, rotary
from zero.diagnostics import Diagnostic, Span
from zero.rules.base import INFO, Context, Family, W

FAMILY: Family[Context] = Family("M", "meaning", "list")


def _rotary(ctx: Context) -> bool | None:
    return rotary(ctx)


def _span(res: Resolved) -> Span:
    e = res.entry
    return Span.on_line(e.line, e.value_start, e.value_end)


# ------------------------------------------------------- soft limits: M001, M005..M008

SOFT_LIMITS_INVERTED = FAMILY.rule(
    "M001", "soft-limits-inverted", W, "The negative soft limit is not below the positive one",
    """
What it checks: `kenngr.swe_neg` < `kenngr.swe_pos` (P-AXIS-00177 < P-AXIS-00178), with
the default for whichever of the two the list does not set.

Why it matters on the machine: the limits span no travel range. The kernel documents an error
for an empty range (equal limits: P-ERR-110110, which K042 reports with its number, and then
this finding is not made); what it does with inverted limits is not documented, so this is a
warning that says so.

Example: `kenngr.swe_neg 5000000` with `kenngr.swe_pos -5000000`
Fix: swap or correct the values.
""", reads=("P-AXIS-00177", "P-AXIS-00178"))
SOFT_LIMIT_CHECK_OFF = FAMILY.rule(
    "M005", "soft-limit-check-off", W, "Soft-limit monitoring switched off (`swe_check 0`)",
    """
What it checks: `kenngr.swe_check` (P-AXIS-00705) set to 0.

Why it matters on the machine: 0 switches soft-limit monitoring off whatever the axis
type and mode; the axis can travel into its hardware limits or into the machine.

Fix: use -1 (monitoring by axis type, the default) or 1.
""", reads=("P-AXIS-00705",))
SOFT_LIMIT_WARNING_ONLY = FAMILY.rule(
    "M006", "soft-limit-warning-only", W, "Overrunning a soft limit only warns (`swe_behaviour WARNING`)",
    """
What it checks: `kenngr.swe_behaviour` (P-AXIS-00554) set to WARNING.

Why it matters on the machine: path planning and the position controller then only warn
when a soft limit is overrun; the movement is not stopped by the monitoring.

Fix: use ERROR (default) or ERROR_LR.
""", reads=("P-AXIS-00554",))
MANUAL_OFFSET_CHECK_OFF = FAMILY.rule(
    "M007", "manual-offset-check-off", W, "Both manual-mode offset limits 0: monitoring off",
    """
What it checks: `handbetrieb.offsetgrenze_neg` and `handbetrieb.offsetgrenze_pos`
(P-AXIS-00137/00138) both 0.

Why it matters on the machine: with both at 0 the manual-mode offset monitoring is off;
for an axis that is not homed these limits are the only range limit in manual mode.

Fix: set real limits (defaults ±100 mm).
""", reads=("P-AXIS-00137", "P-AXIS-00138"))
SOFT_LIMIT_TOLERANCE_OVERFLOW = FAMILY.rule(
    "M008", "soft-limit-tolerance-overflow", W, "Soft limit plus tolerance leaves the SGN32 range",
    """
What it checks: `swe_pos + swe_toleranz` above MAX(SGN32), or `swe_neg - swe_toleranz`
below MIN(SGN32).

Why it matters on the machine: actual positions are monitored against the limits widened
by the tolerance; a sum that does not fit the position type makes that monitoring
meaningless or wraps around.

Fix: reduce the tolerance or move the limit inward.
""", reads=("P-AXIS-00177", "P-AXIS-00178", "P-AXIS-00179"))


@FAMILY.check(SOFT_LIMITS_INVERTED, SOFT_LIMIT_CHECK_OFF, SOFT_LIMIT_WARNING_ONLY, MANUAL_OFFSET_CHECK_OFF,
              SOFT_LIMIT_TOLERANCE_OVERFLOW)
def check_soft_limits(ctx: Context) -> Iterator[Diagnostic]:
    """M001, M005, M006, M007, M008."""
    neg, pos = ctx.value_of(SWE_NEG), ctx.value_of(SWE_POS)
    rotary = _rotary(ctx)
    if neg is not None or pos is not None:
        n, p = ctx.number_of(SWE_NEG), ctx.number_of(SWE_POS)
        if n is not None and p is not None and n >= p:
            at = max((r for r in (neg, pos) if r is not None), key=lambda r: r.entry.line)
            yield ctx.report(
                "M001",
                _span(at),
                f"negative soft limit {length_text(n, rotary)} is not below the positive "
                f"{length_text(p, rotary)}: the limits span no travel range; "
                f"{claim('empty-soft-limits', ctx.kind).says}",
                param_id=at.spec.id,
            )
        tol = ctx.number_of(SWE_TOL)
        lo, hi = TYPE_LIMITS["SGN32"]
        if tol is not None and p is not None and pos is not None and p + tol > hi:
            yield ctx.report(
                "M008", _span(pos),
                f"swe_pos + swe_toleranz = {p + tol} exceeds MAX(SGN32): the actual-position "
                "limit cannot be represented", param_id=SWE_POS,
            )
        if tol is not None and n is not None and neg is not None and n - tol < lo:
            yield ctx.report(
                "M008", _span(neg),
                f"swe_neg - swe_toleranz = {n - tol} is below MIN(SGN32): the actual-position "
                "limit cannot be represented", param_id=SWE_NEG,
            )
    check = ctx.value_of(SWE_CHECK)
    if check is not None and check.value.number == 0:
        yield ctx.report(
            "M005", _span(check),
            "`swe_check 0` switches soft-limit monitoring off for this axis, whatever its type",
            param_id=SWE_CHECK,
        )
    behaviour = ctx.value_of(SWE_BEHAVIOUR)
    if behaviour is not None and behaviour.value.text == "WARNING":
        yield ctx.report(
            "M006", _span(behaviour),
            "`swe_behaviour WARNING`: overrunning a soft limit only warns, the axis is not stopped",
            param_id=SWE_BEHAVIOUR,
        )
    oneg, opos = ctx.value_of(OFFSET_NEG), ctx.value_of(OFFSET_POS)
    if (oneg is not None and opos is not None
            and oneg.value.number == 0 and opos.value.number == 0):
        at = max(oneg, opos, key=lambda r: r.entry.line)
        yield ctx.report(
            "M007", _span(at),
            "both manual-mode offset limits are 0: the controller does not monitor the offset "
            "in manual mode",
            param_id=at.spec.id,
        )


# ------------------------------------------------------- zero offsets: M002, M003, M004

G53_OFFSET_NO_EFFECT = FAMILY.rule(
    "M002", "g53-offset-no-effect", W, "Offsets in group 0 while G53 cancels all offsets",
    """
What it checks: non-zero `np_grp[0].achse[j].versch` while `g53_verfuegbar` is 0 or absent.

Why it matters on the machine: with `g53_verfuegbar` 0, G53 (G159=0) deselects every zero
offset; the values of group 0 are never applied. Someone expecting G53 to shift the axis
will cut in the wrong place.

Fix: set `g53_verfuegbar 1` if group 0 is meant as a full offset set, or clear the values.
""", reads=("P-ZERO-00003", "P-ZERO-00001"))
MASKED_OFFSET = FAMILY.rule(
    "M003", "masked-offset", INFO, "A non-zero offset masked by `inaktiv 1`",
    """
What it checks: `np_grp[i].achse[j].versch` ≠ 0 while `np_grp[i].achse[j].inaktiv` is 1.

Why it matters on the machine: the offset is not applied when the group is selected.
That can be intended (the ZERO manual's own example masks offsets), so this is
information: make sure it is.

Fix: set `inaktiv 0` to apply the offset, or set the offset to 0.
""", reads=("P-ZERO-00003", "P-ZERO-00004"))
DEFAULT_INDEX_EMPTY = FAMILY.rule(
    "M004", "default-index-empty", W, "`default_index` selects a group the list does not fill",
    """
What it checks: `default_index` n > 0 while the list has no `np_grp[n]` entry.

Why it matters on the machine: group n is active after every program start (instead of
G53); with no data in the list it holds whatever the controller has, usually zeros —
probably not the offsets the engineer meant to activate.

Fix: point `default_index` at the intended group, or add its offsets.
""", reads=("P-ZERO-00002", "P-ZERO-00003", "P-ZERO-00004"))


@FAMILY.check(G53_OFFSET_NO_EFFECT, MASKED_OFFSET, DEFAULT_INDEX_EMPTY)
def check_zero_offsets(ctx: Context) -> Iterator[Diagnostic]:
    """M002, M003, M004."""
    offsets = ctx.by_id.get(OFFSET, {})
    if not offsets and ctx.value_of(DEFAULT_INDEX) is None:
        return
    g53 = ctx.number_of(G53_AVAILABLE)
    for idx, res in sorted(offsets.items(), key=lambda kv: kv[1].entry.line):
        value = res.value.number
        if not value:
            continue
        if idx[:1] == (0,) and not g53:
            yield ctx.report(
                "M002", _span(res),
                f"offset {length_text(value)} in group 0 has no effect: `g53_verfuegbar` is "
                f"{'0' if ctx.value_of(G53_AVAILABLE) else 'absent'}, so G53 cancels all offsets",
                param_id=OFFSET,
            )
        mask = ctx.value_of(INACTIVE, idx)
        if mask is not None and mask.value.number == 1:
            yield ctx.report(
                "M003", _span(res),
                f"offset {length_text(value)} of axis {idx[1] if len(idx) > 1 else '?'} in group "
                f"{idx[0]} is masked by `inaktiv 1` on line {mask.entry.line}: it is not applied",
                param_id=OFFSET,
            )
    default = ctx.value_of(DEFAULT_INDEX)
    if default is not None and default.value.number:
        group = int(default.value.number)
        has = any(i[:1] == (group,) for slot in (OFFSET, INACTIVE)
                  for i in ctx.by_id.get(slot, {}))
        if not has:
            gcode = g_code(group)
            yield ctx.report(
                "M004", _span(default),
                f"`default_index {group}` activates group {group} ({gcode}) after every program "
                "start, but this list has no entry for that group",
                param_id=DEFAULT_INDEX,
            )


# ------------------------------------------------------- position resolution: M009

TWO_RESOLUTIONS = FAMILY.rule(
    "M009", "two-resolution-settings", INFO, "Gear-stage resolution and feed constant both set: which formula applies",
    """
What it checks: an axis list that sets `getriebe[g].wegaufz`/`wegaufn` (P-AXIS-00234/00233)
to anything but 1 while `antr.feed_const_num` or `antr.feed_const_denom` (P-AXIS-00362/00363)
is not 1 either, in the one list.

Why it matters on the machine: a feed constant other than 1 has the controller compute the
resolution from the feed constant and the encoder increments per motor revolution (P-AXIS-00092)
with a gear ratio. The TwinCAT CNC axis documentation (the feed-constant section,
https://infosys.beckhoff.com/content/1033/tccncaxisparameter/15267153035.html) puts
`wegaufz`/`wegaufn` (P-AXIS-00234/00233) into that formula as the gear ratio, so on such a
kernel they are a real gear ratio, not a second resolution; the TF5200 documentation
(https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/131271307.html) names
`gear_fact_num`/`gear_fact_denom` (P-AXIS-00511/00512) for it. No start-up message is documented
for either. Information: check which of the two the machine's kernel uses.

Example: `getriebe[0].wegaufz 4` with `antr.feed_const_num 100000`
Fix: nothing where wegaufz/wegaufn are the gear ratio the kernel's documentation puts into the
feed-constant formula; on a kernel that uses P-AXIS-00511/00512 there, write the gear ratio there.
""", reads=("P-AXIS-00234", "P-AXIS-00233", "P-AXIS-00362", "P-AXIS-00363"))


@FAMILY.check(TWO_RESOLUTIONS)
def check_resolution(ctx: Context) -> Iterator[Diagnostic]:
    """M009: one finding per list, on the line of this list that completes the mix."""
    feed = [(pid, idx, res) for pid in (FEED_NUM, FEED_DEN) for idx, res in ctx.ids_of(pid).items()
            if res.value.number is not None and res.value.number != 1]
    if not feed:
        return
    gear = [(pid, idx, res) for pid in (RES_NUM, RES_DEN) for idx, res in ctx.ids_of(pid).items()
            if res.value.number is not None and res.value.number != 1]
    if not gear:
        return
    own = [t for t in feed + gear if ctx.layer_of(t[0], t[1]) is ctx]
    if not own:
        return  # both come from the default list: its own lint reports them
    pid, _idx, at = max(own, key=lambda t: t[2].entry.line)
    g = min(gear, key=lambda t: t[2].entry.line)[2]
    f = min(feed, key=lambda t: t[2].entry.line)[2]
    yield ctx.report(
        "M009", _span(at),
        f"`{f.entry.key_text} {f.entry.value}` is not 1, so the resolution is computed from the feed constant; "
        f"`{g.entry.key_text} {g.entry.value}` enters it as the gear ratio where the kernel follows the TwinCAT "
        "CNC axis documentation (P-AXIS-00234/00233 in the feed-constant formula), while the TF5200 "
        "documentation names P-AXIS-00511/00512 for the gear ratio: which one this kernel uses decides how far "
        "the axis moves",
        param_id=pid,
    )

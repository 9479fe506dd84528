"""R rules: each entry against the registry — key, index, type, range, references."""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Iterator

from zero.catalog.evidence import Claim, claim, drive_types
from zero.catalog.ids import SOFT_LIMITS
from zero.catalog.ranges import TYPE_LIMITS, Bounds, Number, Range, Ref, encoded_bounds, format_number
from zero.catalog.registry import BUILTIN_SOURCE, KINDS, ParamSpec, Registry, written_range
from zero.catalog.values import Resolved, Value, default_number, plain_number, take
from zero.diagnostics import Diagnostic, Edit, Fix, Related, Span
from zero.errors import ZeroError
from zero.lists.model import HUGE_INDEX, Entry, ValueKind, format_key
from zero.patterns import compiled
from zero.records import replace
from zero.rules.base import INFO, MAX_PER_CODE, Context, E, Family, W

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

    from zero.catalog.condition_helpers import Compiled

FAMILY: Family[Context] = Family("R", "registry", "list")

# ------------------------------------------------------------------ keys: R001, R002, R003

UNKNOWN_KEY = FAMILY.rule(
    "R001", "unknown-key", E, "A key the parameter description does not know",
    """
What it checks: every key (with its indices removed) must be a parameter of the list's
kind in the registry. zero says which list a key belongs to when it is valid elsewhere,
and proposes the closest known key (for the first 100 distinct unknown keys of a list:
a list with more is not a list of its kind, and spellings would not help).

Why it matters on the machine: in an axis parameter list the kernel ignores an element it
cannot interpret (P-ERR-1001119), so the parameter the engineer meant keeps the value it had; an
error. For the other list kinds the vendor documents no reaction: a warning that says so. A key
the vendor's own lists or templates write is R002, R010 or R013 instead (information).
In a zero-offset list the plausibility check reports an unknown or incorrectly written
parameter or an invalid value and the job is aborted (P-ERR-20407): an error there too.

Example: `kenngr.swe_pso 15000000`
Fix: correct the key (`kenngr.swe_pos`), or load the description of your kernel with
`--param-desc` if the key is newer than zero's table.
""")
ALIAS_KEY = FAMILY.rule(
    "R002", "alias-key", INFO, "An undocumented spelling of a documented key that the vendor's lists write",
    """
What it checks: keys that the vendor's own lists use but the parameter description
does not, and that stand for a documented parameter (German or older spellings such as
`syn_chk.fehler_pro_zeile` for `syn_chk.errors_per_block`). The value is checked
against the documented parameter.

Why it matters on the machine: the vendor's own lists write the spelling, which is evidence that
the kernel of their release accepts it; no documentation says a kernel ignores it. Information:
the documented key is the safer spelling.

Fix: use the documented key (an unsafe fix), or nothing.
""")
INDEX_OUT_OF_RANGE = FAMILY.rule(
    "R003", "index-out-of-range", E, "An array index beyond the array's size",
    """
What it checks: each index of a key against the array size in the registry
(`np_grp` 0..96, `achse` 0..31, `getriebe` 0..5, ...; the tool list `wz` counts from 1).

Why it matters on the machine: the element does not exist. In an axis parameter list the
kernel ignores an element it cannot interpret (P-ERR-1001119): an error; for the other list kinds
no reaction is documented: a warning that says so.
In a zero-offset list the plausibility check reports an unknown or incorrectly written
parameter or an invalid value and the job is aborted (P-ERR-20407): an error there too.

Example: `np_grp[97].achse[0].versch 100`
Fix: use an index inside the range.
""")

_KIND_NAMES = {k: v[1] for k, v in KINDS.items()}


def _key_span(e: Entry) -> Span:
    return Span.on_line(e.line, e.key_start, e.key_end)


def says(ctx: Context, name: str) -> str:
    """What the evidence table says the controller does (claim ``name``, for this list's kind)."""
    return claim(name, ctx.kind).says


VENDOR_KEY = FAMILY.rule(
    "R010", "vendor-key", INFO, "A key the vendor's own lists use that the catalogue does not document",
    """
What it checks: keys that are not in the parameter description but that the vendor's own
example lists use consistently (`thread[n].cpu` in the real-time configuration,
`number_used_variables` in the external variables list, ...). zero keeps a table of them,
each with the list it was found in, and names the documented parameter it probably stands
for where one fits.

Why it matters on the machine: the catalogue does not say what the controller does with such a
key; a kernel that does not know it leaves it unused. This is information, not an error: the
vendor ships it that way.

Fix: nothing, unless your kernel's parameter description documents another key for it.
""")


OTHER_RELEASE = FAMILY.rule(
    "R013", "key-of-another-release", W, "A key written for another kernel release",
    """
What it checks: a key zero's catalogue (kernel V4.13) does not have, where zero knows more than
"unknown": an older spelling of a key the catalogue has (`antr_simu.totzeit`, today
`antr.simu.totzeit`, P-AXIS-00194), from zero's table of renames between releases (each row with
its source) or from the line's own `( P-AXIS-nnnnn` annotation naming a parameter whose key
ends in the same member; a key that lists of an older release use and today's catalogue lacks
(`lr_hw[0].cntr_adr`); and, where the configuration says the machine runs an older kernel
(`kernel = "V3.1.3074"`, or a list's header says so), any key this catalogue does not know.

Why it matters on the machine: on the kernel the list was written for, the entry may be read as
intended; on a kernel of the catalogue's release the old spelling is unknown and not taken over.
zero cannot check such an entry, and says what it knows instead of calling it an error.

Example: `antr_simu.totzeit 10 ( P-AXIS-00194 : ...` in an axis list of a kernel V3.01 machine
Fix: on a newer kernel, use today's key (an unsafe fix proposes it); on the old kernel, set
`kernel` in the configuration.
""")


@FAMILY.check(UNKNOWN_KEY, ALIAS_KEY, INDEX_OUT_OF_RANGE, VENDOR_KEY, OTHER_RELEASE)
def check_keys(ctx: Context) -> Iterator[Diagnostic | str]:
    """R001, R002, R003: key known, spelling documented, indices inside the arrays."""
    reg = ctx.registry
    proposed: set[str] = set()  # unknown patterns a spelling was looked for (the first SUGGESTIONS)
    known: dict[str, Any] = {}  # per list: the catalogue said, the machine's release, rows by pattern
    # Per distinct pattern its parameter; per shape of key (`wz[].kinematic.param[3]`) the indices after
    # the first checked once, the first indices by their least and greatest. Only the entries of an
    # unknown pattern, or with an index outside its array, are visited (in order) for a finding.
    cols = ctx.doc.columns
    rows: list[int] = []  # rows to visit
    known_specs: dict[str, ParamSpec | None] = reg.memo.setdefault(f"key_specs:{ctx.kind}", {})
    shape_rows, shape_keys, bound = ctx.shape_rows, ctx.shape_keys, ctx.bound
    for pattern, shapes in ctx.pattern_shapes.items():
        spec = known_specs.get(pattern, _MISSING)  # not try/except: a list's first look-ups all miss
        if spec is _MISSING:
            hit = bound.get(pattern)  # bind's answer: by_pattern's where it is not an alias or another spelling
            spec = hit[0] if hit is not None and not hit[1] and hit[0].key == pattern else \
                reg.by_pattern(pattern, ctx.kind)
            if len(known_specs) < 65_536:
                known_specs[pattern] = spec
        if spec is None:
            for shape in shapes:
                rows.extend(shape_rows[shape])
            continue
        if "[" not in pattern:
            continue  # no index to check
        bounds = bounds_of(spec)
        if not bounds:
            continue
        for shape in shapes:
            _, indices, indexed = shape_keys[shape]
            group = shape_rows[shape]
            if indices and not _inside(bounds[1:] if indexed else bounds, indices):
                rows.extend(group)  # the indices after the first (a key without a first: all) outside
                continue
            if not indexed:
                continue
            low, end = bounds[0]
            if len(group) == 1:
                if not low <= cols.first[group[0]] < end:
                    rows.append(group[0])
                continue
            firsts = take(cols.first, group)
            if min(firsts) < low or max(firsts) >= end:
                rows.extend(r for r, first in zip(group, firsts, strict=True) if not low <= first < end)
    rows.sort()
    tally = ctx.tally
    # a pattern -> the code of its rows without a comment: decided by the pattern (and the list), so where that
    # code is past the cap (run_checks), such a row is counted by its code alone, without building its entry
    settled: dict[int, str] = {}
    comment_of, pattern_of = cols.comment, cols.pattern
    for row in rows:
        plain = comment_of[row] < 0
        if plain and tally is not None:
            code = settled.get(pattern_of[row])
            if code is not None and tally.get(code, 0) > MAX_PER_CODE:
                yield code
                continue
        d = _row_finding(ctx, ctx.entry_at(row), known_specs, known, proposed)
        if d is not None:
            if plain:
                settled[pattern_of[row]] = d.code
            yield d


def _row_finding(ctx: Context, e: Entry, known_specs: dict[str, ParamSpec | None], known: dict[str, Any],
                 proposed: set[str]) -> Diagnostic | None:
    """The finding of a row check_keys visits (its key unknown, or an index outside its array), if any."""
    reg = ctx.registry
    key = e.key
    assert key is not None  # a row of a group
    found = known_specs[key.pattern] if key.pattern in known_specs else reg.by_pattern(key.pattern, ctx.kind)
    if found is None:
        alias = reg.alias(key.pattern, ctx.kind)
        if alias is not None:
            return ctx.report(
                "R002",
                _key_span(e),
                f"`{e.key_text}` is not in the parameter description; it stands for "
                f"`{alias.key}` ({alias.id}), and the vendor's own lists write it: evidence that the kernel "
                "of their release accepts it (its value is checked as the documented parameter's)",
                param_id=alias.id,
                hint=f"use `{format_key(alias.key or '', key.indices)}`",
                fix=Fix(
                    f"Use the documented key `{alias.key}`",
                    (Edit(_key_span(e), format_key(alias.key or "", key.indices)),),
                    safe=False,
                ),
            )
        vendor = reg.vendor_keys.get((ctx.kind or "", key.pattern))
        if vendor is not None:
            return _vendor_key(ctx, e, *vendor)
        propose = key.pattern in proposed or len(proposed) < SUGGESTIONS
        if propose:
            proposed.add(key.pattern)
        release = _other_release(ctx, e, known, propose)
        return release if release is not None else _unknown_key(ctx, e, propose, known)
    where = found.index_outside(key.indices)
    if where is None:
        return None
    pos, idx = where
    members = key.members
    member = members[pos] if pos < len(members) else "?"
    name = key.pattern.split("[]")[pos].rsplit(".", 1)[-1] or member
    shown = str(idx) if idx < 10**18 else f"{str(idx)[:6]}…"
    return ctx.report(
        "R003",
        _key_span(e),
        f"index {shown} of `{name}` is outside {found.valid_indices(pos)}: the element does not exist; "
        f"{says(ctx, 'unknown-element')}",
        param_id=found.id,
    )


def _inside(bounds: tuple[tuple[int, int], ...], indices: tuple[int, ...]) -> bool:
    """Every index inside its array's bounds (as ``index_outside`` reads them; none outside: no call)."""
    return all(first <= idx < end for (first, end), idx in zip(bounds, indices, strict=False))


_LEADING_ZERO = r"\[0[0-9]"  # compiled at its first use (through re's own cache): few lists write `[01]`
_BOUNDS: dict[tuple[tuple[int, ...], int], tuple[tuple[int, int], ...]] = {}  # by (dims, index base)


def bounds_of(spec: ParamSpec) -> tuple[tuple[int, int], ...]:
    """:func:`_bounds`, once per shape of arrays (the lists of a fleet ask for the same few hundred)."""
    slot = (spec.dims, spec.index_base)
    got = _BOUNDS.get(slot)
    if got is None:
        got = _bounds(spec)
        if len(_BOUNDS) < 4096:
            _BOUNDS[slot] = got
    return got


def _bounds(spec: ParamSpec) -> tuple[tuple[int, int], ...]:
    """Each index slot's first index and the index past its last, as ``index_outside`` reads them."""
    out = []
    for pos, size in enumerate(spec.dims):
        first = spec.index_first(pos)
        out.append((first, size if first == 0 and size > 0 else 1 << 128))
    return tuple(out)


# The patterns below are compiled at their first use, through re's own cache: a finding's, not a start-up's
_ANNOTATED_ID = r"\(\s*(P-[A-Z]{4}-[0-9]{5})"
# `# … written for kernel V3.01.3074`, `# CNC V3.1.3074`: a kernel or CNC release with its `V` (a bare
# "Version 1.2" of the list itself is not one)
_HEADER_RELEASE = r"(?i)\b(?:kernel|cnc)\b[^\n]{0,24}?\b(V\d+\.\d+(?:\.\d+){0,2})\b"


def _kernel_of(ctx: Context) -> tuple[int, ...] | None:
    """The kernel release the machine runs: the configuration's `kernel`, else what the list's first
    comment lines say (`# CNC kernel V3.01.3074`), else ``None``."""
    from zero.catalog.releases import parse_release  # start-up: only for a key the catalogue lacks

    text = ctx.kernel
    if text is None:
        for item in ctx.doc.comments_in_head(40):
            m = compiled(_HEADER_RELEASE).search(ctx.doc.lines[item.line - 1])
            if m is not None:
                text = m.group(1)
                break
    try:
        return parse_release(text) if text else None
    except ZeroError:
        return None


def _other_release(ctx: Context, e: Entry, known: dict[str, Any], propose: bool = True) -> Diagnostic | None:
    """R013 for a key of another kernel release (see the rule), or ``None`` where zero knows nothing
    more than "unknown" (R001)."""
    from zero.catalog.releases import (  # start-up: as above
        CATALOGUE_RELEASE,
        UNKNOWN_RELEASE,
        format_release,
        removed,
        renamed,
    )

    assert e.key is not None
    builtin = ctx.registry.source == BUILTIN_SOURCE
    if "ours" not in known:  # once per list, not once per unknown key
        known["ours"] = _catalogue(ctx.registry)
        known["kernel"] = _kernel_of(ctx) if builtin else None  # a catalogue of the user's own is the machine's
    ours = known["ours"]
    rows = known.setdefault("rows", {})
    if e.key.pattern not in rows:
        rows[e.key.pattern] = (renamed(e.key.pattern, ctx.kind, ctx.registry), removed(e.key.pattern, ctx.kind))
    row, gone = rows[e.key.pattern]
    source = row.source if row is not None else ""
    if row is None and e.comment is not None:  # the line's own annotation names today's parameter
        m = compiled(_ANNOTATED_ID).match(e.comment.strip())
        spec = ctx.registry.get(m.group(1)) if m is not None else None
        last = e.key.pattern.rsplit(".", 1)[-1]
        if spec is not None and spec.key and spec.kind == (ctx.kind or spec.kind) and \
                spec.key.rsplit(".", 1)[-1] == last:
            from zero.catalog.releases import Rename  # start-up: as above

            row = Rename(e.key.pattern, spec.kind, spec.key, spec.id, UNKNOWN_RELEASE, "the line's own annotation")
            source = f"its own `( {spec.id}` annotation"
    if row is not None:
        new = row.new_key(e.key.indices)
        when = f" (seen in lists of kernel {row.release})" if row.release != UNKNOWN_RELEASE else ""
        checked = f" (its value is checked as {row.id}'s)" if not source.startswith("its own") else ""
        if row.vendor:  # the vendor's own lists or templates write it: evidence, not a fault
            where = row.source.split(" (")[0].removeprefix("isg-sdk ")
            return ctx.report("R013", _key_span(e), f"`{e.key_text}` is another spelling{when} of `{new}` ({row.id}), "
                              f"which the vendor's own SDK writes ({where}): evidence that the kernel of its release "
                              "accepts it" + checked,
                              param_id=row.id, claim="vendor-writes", hint=f"today: `{new}`",
                              fix=Fix(f"Use today's key `{new}`", (Edit(_key_span(e), new),), safe=False))
        return ctx.report("R013", _key_span(e), f"`{e.key_text}` is another spelling{when} of `{new}` ({row.id}), as "
                          f"{source if source.startswith('its own') else 'zero’s table of renames says'}: "
                          f"{ours} does not document it; whether the machine's kernel accepts it is not documented, "
                          "and the kernel it was written for may read it as intended" + checked,
                          param_id=row.id,
                          hint=f"today: `{new}`", fix=Fix(f"Use today's key `{new}`", (Edit(_key_span(e), new),),
                                                          safe=False))
    if gone is not None:
        when = f"kernel {gone.release}" if gone.release != UNKNOWN_RELEASE else "an older kernel"
        return ctx.report("R013", _key_span(e), f"`{e.key_text}` is not in {ours}; lists of {when} use it: what a "
                          "kernel of this release does with it, the catalogue does not say")
    kernel = known["kernel"]
    if kernel is not None and kernel < CATALOGUE_RELEASE:
        near = ctx.registry.suggest(e.key.pattern, ctx.kind) if propose else []
        hint = f"the nearest key zero knows: `{format_key(near[0], e.key.indices)}`" if near else None
        return ctx.report("R013", _key_span(e), f"`{e.key_text}` is not in {ours}, which zero checks with; the "
                          f"machine runs the older kernel {format_release(kernel)}, whose catalogue zero does not "
                          "have: whether it knows the key is not known", hint=hint)
    return None


def _catalogue(registry: Registry) -> str:
    """The catalogue said to people: zero's own (and its kernel release), or the user's file."""
    from zero.catalog.releases import CATALOGUE_RELEASE, format_release  # start-up: only for an unknown key

    if registry.source == BUILTIN_SOURCE:
        return f"zero's catalogue (kernel {format_release(CATALOGUE_RELEASE)})"
    return f"the catalogue {registry.source}"


def _vendor_key(ctx: Context, e: Entry, source: str, near: str) -> Diagnostic:
    spec = ctx.registry.get(near) if near else None
    hint = f"perhaps the documented `{spec.key}` ({spec.id})" if spec is not None and spec.key else None
    return ctx.report("R010", _key_span(e), f"`{e.key_text}` is not in the parameter description, but the "
                      f"vendor's own lists use it ({source}): the catalogue does not say what the controller "
                      "does with it", hint=hint)


# Did-you-mean costs a scan of every known key per distinct unknown one: proposed for this many
# distinct unknown keys of a list (a list of a million made-up keys must not take minutes).
SUGGESTIONS = 100


def _unknown_key(ctx: Context, e: Entry, propose: bool = True, known: dict[str, Any] | None = None) -> Diagnostic:
    assert e.key is not None
    reg = ctx.registry
    others: dict[str, list[str]] = known.setdefault("kinds", {}) if known is not None else {}
    other = others.get(e.key.pattern)
    if other is None:  # once per distinct key of the list (a list of made-up keys repeats them)
        other = others[e.key.pattern] = [k for k in reg.kinds_of(e.key.pattern) if k != ctx.kind]
    hint = None
    fix = None
    if other:
        where = _KIND_NAMES.get(other[0], other[0])
        spec = reg.by_pattern(e.key.pattern, other[0])
        pid = f" ({spec.id})" if spec else ""
        msg = (f"`{e.key_text}` belongs to the {where}{pid}, not to this "
               f"{_KIND_NAMES.get(ctx.kind or '', 'list')}: {says(ctx, 'unknown-element')}")
        hint = "check that this is the right file, or override the detection with --kind"
    else:
        ours = known["ours"] if known and "ours" in known else _catalogue(reg)
        msg = f"unknown key `{e.key_text}` (not in {ours}): {says(ctx, 'unknown-element')}"
        near = reg.suggest(e.key.pattern, ctx.kind) if propose else []
        if near:
            proposal = format_key(near[0], e.key.indices)
            hint = f"did you mean `{proposal}`?"
            fix = Fix(f"Replace with `{proposal}`", (Edit(_key_span(e), proposal),), safe=False)
    return ctx.report("R001", _key_span(e), msg, hint=hint, fix=fix)


# ------------------------------------------------------- values: R004, R005, R006, R009

WRONG_TYPE = FAMILY.rule(
    "R004", "wrong-type", E, "A value that is not of the parameter's type",
    """
What it checks: integers must be integers that fit the type (`12.5` or `abc` for an
SGN32 are wrong, `70000` does not fit UNS16), numbers must be numbers, strings must not
exceed their maximum length.

Why it matters on the machine: in an axis parameter list the kernel goes on with the list and
sets a value of an invalid number format to 0, or limits one beyond the type to the permissible
minimum or maximum (P-ERR-1001138): an error. For the other list kinds the vendor documents no
reaction: a warning that says so.
In a zero-offset list the plausibility check reports an unknown or incorrectly written
parameter or an invalid value and the job is aborted (P-ERR-20407): an error there too.
Where zero cannot read a value (`666666.667` for an integer), no other rule reasons on it: not
on the default, not on a guessed number.

Example: `kenngr.swe_pos 1500.5`
Fix: write the value in the parameter's unit as an integer (`kenngr.swe_pos 15005000`).
""")
OUT_OF_RANGE = FAMILY.rule(
    "R005", "out-of-range", E, "A value outside the parameter's range or allowed set",
    """
What it checks: the value against the range of the parameter description (for example
`MIN(SGN32) < x < MAX(SGN32)`, `0 ... 96`, `-1, 0, 1`), against the values the description
lists in its text, one per line (`1 : <meaning>` … `32 : <meaning>` for
`kenngr.antr_typ`; any combination where they are the bits of a mask), BOOLEAN values against
0/1 (or FALSE/TRUE), and symbolic values against the allowed symbols. Where the catalogue's
default lies outside its own range, the message says so instead of predicting the default.

Why it matters on the machine: in an axis parameter list the kernel goes on with the list and
limits a value beyond the permissible range to its minimum or maximum (P-ERR-1001138): an error
that names the bound. For the other list kinds, for values outside the values the catalogue
lists, and for ranges the documentation calls application-specific, no reaction is documented:
a warning (information for an application-specific range) that says so.
In a zero-offset list the plausibility check reports an unknown or incorrectly written
parameter or an invalid value and the job is aborted (P-ERR-20407): an error there too. A parameter the
documentation gives for other drive types than the axis has (P-AXIS-00020) is not used by the
kernel: information.

Example: `kenngr.swe_behaviour WARN`
Fix: use a value inside the range; `zero param KEY` shows it.
""")
RANGE_REFERENCE = FAMILY.rule(
    "R006", "range-reference", W, "A range over other parameters that the list violates",
    """
What it checks: ranges that name other parameters (`1 ≤ a_emergency ≤ 2*P-AXIS-00008`,
`P-AXIS-00201 ≤ tr_grenz`), evaluated with the values of the same list, or the other
parameter's default when the list does not set it. With a machine, the default list under the
list counts too, and the message says where each value comes from. A value zero cannot read
(R004) is never replaced by a default here: nothing is said about it.

Why it matters on the machine: the vendor documents no start-up check of such a relation (where
the kernel documents one, its K rule reports it with the kernel's number instead, and this
finding is not made): a warning that says so. A relation the catalogue writes in prose
(`swe_neg < pos_refpkt < swe_pos`) is checked with its bounds allowed, as the soft-limit
documentation lets an axis move to its soft-limit positions.

Fix: adjust either value; the message names both.
""")
UNKNOWN_REFERENCE = FAMILY.rule(
    "R009", "unknown-reference", W, "A parameter reference to an unknown ID",
    """
What it checks: values of the form `P-AXIS-00212.0` ("the value of that parameter,
element 0") must name a parameter the registry knows.

Why it matters on the machine: the catalogue has no such parameter; what the controller does
with the reference is not documented (a warning that says so).

Fix: correct the ID.
""")

CONTRADICTION = FAMILY.rule(
    "R011", "range-excludes-default", W, "A value outside a range that the catalogue's own default violates",
    """
What it checks: a value outside the parameter's range, where the catalogue's default lies
outside that range too (`kenngr.distc.min_pos`: range `0 ≤ x < MAX(SGN32)`, default −50000).
The catalogue contradicts itself there: the value may be what the kernel expects.

Why it matters on the machine: perhaps nothing, perhaps the value is replaced — the catalogue
does not say which. zero reports it at warning, once, and says so, instead of an error (R005)
that claims to know.

Example: `kenngr.distc.min_pos -40000`
Fix: check the parameter's documentation for the kernel release of the machine.
""")
UNIT_UNKNOWN = FAMILY.rule(
    "R012", "range-unit-unknown", INFO, "A range written in a physical unit for a value of unknown unit",
    """
What it checks: a value outside a range the catalogue writes in a physical unit (`-45° ≤ x ≤
45°`), where the catalogue gives no unit for the value itself: the value may be written in an
internal unit (0.0001°: 450000 is 45°). zero compares a range in a unit only in the value's
own unit; where that is unknown, it says so at info instead of an error.

Why it matters on the machine: perhaps nothing (450000 is 45° in 0.0001°), perhaps a value out
of range — the catalogue does not say which.

Example: `wz[1].grinding_disc_tilt_angle 450000`
Fix: check the parameter's unit in its documentation; write the value in it.
""")
_PHYSICAL_UNIT = r"°|\b(?:mm|µm|um|m/s|mm/s|mm/min|rpm)\b"  # compiled at its first use (a finding's)

_SIMPLE_PROBLEMS = {
    "type": ("R004", "`{value}` is not {what} ({type}) for `{key}`"),
    "overflow": ("R004", "{value} does not fit {type} for `{key}`"),
    "length": ("R004", "the string for `{key}` has {detail} characters, more than the {max_len} allowed"),
    "bool": ("R005", "`{value}` is not a BOOLEAN (0/1, FALSE/TRUE) for `{key}`"),
}


def _value_span(e: Entry) -> Span:
    if e.value_end > e.value_start:
        return Span.on_line(e.line, e.value_start, e.value_end)
    return Span.on_line(e.line, e.key_start, e.key_end)


DRIVE_TYPE = "P-AXIS-00020"  # kenngr.antr_typ: 1 conventional, 2 SERCOS, 4 simulation, ...
_APPLICATION_SPECIFIC = r"(?i)application[-. ]specific|applikationsspezifisch"  # compiled at its first use


def _range_claim(ctx: Context, e: Entry, spec: ParamSpec, name: str = "out-of-range") -> Claim:
    """The claim a value outside ``spec``'s range carries: the drive type it does not apply to, a range
    the documentation calls application-specific, else ``name`` for this list's kind."""
    kind = ctx.kind
    if kind == "AXIS" and e.key is not None:
        hit = drive_types(e.key.pattern)
        drive = ctx.number_of(DRIVE_TYPE) if hit is not None else None
        if hit is not None and drive is not None and drive not in hit[0]:
            where = ctx.value_of(DRIVE_TYPE)
            origin = _origin(ctx, DRIVE_TYPE, ()) if where is not None else "the catalogue's default"
            c = claim("drive-type", kind)
            types = ", ".join(str(t) for t in hit[0])
            return replace(c, source=hit[1], says=(
                f"the documentation gives `{e.key.pattern}` for drive type {types} only, and this axis has drive "
                f"type {format_number(drive)} ({origin}, P-AXIS-00020): the kernel does not use the value"))
    if spec.range_text and compiled(_APPLICATION_SPECIFIC).search(spec.range_text):
        return claim("application-specific", kind)
    return claim(name, kind)


def _limited(c: Claim, b: Bounds | None, number: Number) -> str:
    """The claim's words, with the bound a `limited` value goes to where the catalogue's range gives it."""
    if c.consequence != "limited" or b is None:
        return c.says
    bound = b.high if b.high is not None and number > b.high else b.low if b.low is not None and number < b.low \
        else None
    if bound is None:
        return c.says
    side = "maximum" if bound == b.high else "minimum"
    return f"{c.says}: here the {side} {format_number(bound)}, where the catalogue's range is the kernel's"


def _origin(ctx: Context, pid: str, idx: tuple[int, ...]) -> str:
    """Where the value the controller uses for ``pid[idx]`` is written: `line 12`, or the default list's
    `default_mds.lis line 40` under this list."""
    res = ctx.value_of(pid, idx)
    if res is None:
        return "not set: the catalogue's default"
    layer = ctx.layer_of(pid, idx)
    if layer is None or layer is ctx:
        return f"line {res.entry.line}"
    return f"{layer.doc.path} line {res.entry.line}, the default list under this one"


def _default_contradicts(spec: ParamSpec, registry: Registry) -> bool:
    """The catalogue's default lies outside the catalogue's own constant range or listed values."""
    dflt = _default_of(spec)
    if dflt is None:
        return False
    if spec.enum:
        return not (isinstance(dflt, int) and spec.enum_allows(dflt))
    rng = registry.range_of(spec)
    if rng is None or rng.refs:
        return False
    if rng.allowed is not None:
        return dflt not in rng.allowed
    return not rng.evaluate(lambda *_: None).contains(dflt)


@FAMILY.check(WRONG_TYPE, OUT_OF_RANGE, RANGE_REFERENCE, UNKNOWN_REFERENCE, CONTRADICTION, UNIT_UNKNOWN)
def check_values(ctx: Context) -> Iterator[Diagnostic]:
    """R004, R005, R006, R009, R011, R012: type, range, references."""
    # Whether a value passes depends only on (parameter, value text) unless its range refers to
    # other parameters (then on the entry's indices too) or the catalogue writes it in prose: such a
    # value is checked once per distinct value of a pattern, and where it passes (kept across lists),
    # none of its entries is visited; where it does not, each entry is, in order, for its own finding.
    registry = ctx.registry
    passed: dict[tuple[str, str], bool] = registry.memo.setdefault("passed", {})  # kept across lists
    verdicts: dict[tuple[str, str], bool] = {}  # this list's: (parameter, value) -> passes
    cols = ctx.doc.columns
    texts = cols.values
    rows: list[int] = []  # rows to visit
    judges: dict[str, Judge | None] = registry.memo.setdefault("judge", {})  # parameter -> how a value is judged
    read: dict[tuple[str, str], Value] = registry.memo.setdefault("values", {})  # ListValues.value_of_text's
    kinds = cols.kinds
    prose = _prose_rows()
    pattern_shapes, shape_rows, value, valueless = ctx.pattern_shapes, ctx.shape_rows, cols.value, ctx.valueless
    for pattern, hit in ctx.bound.items():
        if hit is None:
            continue
        spec = hit[0]
        # Whether the findings on a value of the parameter depend on the value alone (not on the entry's indices
        # or the list's other values; prose reads others): then a value is checked once, as ``judge`` says. Kept
        # per registry.
        judge = judges.get(spec.id, _MISSING)  # not try/except: a list's first look-ups all miss
        if judge is _MISSING:
            judge = judges[spec.id] = _judge(registry, spec, prose)
        if judge is None:  # each entry's own verdict (entry built if fails)
            plan = _ref_plan(registry, spec)
            if plan is None:
                rows.extend(r for r in ctx.value_rows(pattern) if not _passes(ctx, ctx.sketch_at(r), True))
            else:  # once per value and values referred to
                rows.extend(_ref_failures(ctx, spec, pattern, plan))
            continue
        for shape in pattern_shapes[pattern]:
            group = shape_rows[shape]
            if len(group) == 1:  # one entry (most patterns of a small list)
                vid = value[group[0]]
                if vid in valueless:
                    continue
                slot = (spec.id, texts[vid])
                verdict = passed.get(slot) or verdicts.get(slot)
                if verdict is None:  # _value_passes, inline
                    got = _judged(judge, read.get(slot) or ctx.value_of_text(spec, slot[1], kinds[vid]))
                    verdict = verdicts[slot] = _passes(ctx, ctx.sketch_at(group[0])) if got is None else got
                    if verdict and len(passed) < 65_536:
                        passed[slot] = True
                if not verdict:
                    rows.append(group[0])
                continue
            ids = ctx.value_ids_at(group)
            first: dict[int, int] | None = None
            failed: set[int] = set()  # the value ids whose entries are visited
            for vid in set(ids):  # each distinct value once (which first: no matter, a verdict is the value's)
                if vid in ctx.valueless:
                    continue
                slot = (spec.id, texts[vid])
                verdict = passed.get(slot) or verdicts.get(slot)
                if verdict is None:
                    # a plain number that passes: so judged without reading a Value (a tool list's 60,000 distinct
                    # values); any other value as read_text reads it
                    number = plain_number(spec.type, slot[1], kinds[vid])
                    if number is not None and (judge is _ANY or _number_passes(judge, number)):
                        verdict = verdicts[slot] = True
                    else:
                        if first is None:
                            first = dict(zip(reversed(ids), reversed(group), strict=True))  # each value's first row
                        verdict = verdicts[slot] = _value_passes(ctx, judge, read.get(slot) or ctx.value_of_text(
                            spec, slot[1], kinds[vid]), first[vid])
                    if verdict and len(passed) < 65_536:
                        passed[slot] = True
                if not verdict:
                    failed.add(vid)
            if failed:
                rows.extend(r for r, v in zip(group, ids, strict=True) if v in failed)
    rows.sort()
    for row in rows:
        res = ctx.resolved_at(row)
        if not not_configured(ctx, res):
            yield from _check_value(ctx, res)


# A range's references as check_values reads them: those read at the entry's element (or at the element
# they name), and those whose index means something else (`_check_range`'s unpaired: element 0 first).
RefPlan = tuple[tuple[tuple[str, int | None], ...], tuple[str, ...]]


def _ref_plan(registry: Registry, spec: ParamSpec) -> RefPlan | None:
    """How a value's verdict depends on other parameters, where it depends on nothing else than the
    value and their values (a formal range, no prose, no listed values): the references read at the
    entry's element, left to right, and the unpaired ones (:func:`_check_range` reads their element 0,
    then, where that refuses the value, their other elements). ``None``: each entry is judged on its
    own. Kept per registry."""
    memo: dict[str, RefPlan | None] = registry.memo.setdefault("ref_plan", {})
    got = memo.get(spec.id, _MISSING)  # not try/except: a list's first look-ups all miss
    if got is not _MISSING:
        return got  # type: ignore[no-any-return]
    plan = None
    if spec.id not in _prose_rows() and spec.range_text and not spec.enum:
        rng = registry.range_of(spec)
        refs = rng.refs if rng is not None and rng.allowed is None else None  # walked once
        if refs:
            unpaired = {r.id for r in refs if r.index is None and not _same_indices(registry, spec, r.id)}
            if not any(r.id in unpaired and r.index is not None for r in refs):  # else: as each entry
                plan = (tuple((r.id, r.index) for r in refs if r.id not in unpaired), tuple(sorted(unpaired)))
    memo[spec.id] = plan
    return plan


def _ref_failures(ctx: Context, spec: ParamSpec, pattern: str, plan: RefPlan) -> list[int]:
    """The rows of ``pattern`` whose value fails a range that refers to other parameters (``plan``):
    judged once per (value, the values the range reads at the row's element and at element 0 of the
    unpaired references, whether M001 explains the soft limits), what :func:`_check_range` reads first
    and nothing else; the verdicts kept across lists. A value element 0 refuses is a row to visit: the
    entry's own check tries the other elements (and may find nothing)."""
    verdicts: dict[tuple[str, str, bool, tuple[Number | None, ...], tuple[Number | None, ...]], bool] = \
        ctx.registry.memo.setdefault("ref_verdicts", {})
    skip = "M001" in ctx.severities and spec.id in SOFT_LIMITS  # the references not read (_check_range)
    paired, unpaired = plan
    cols = ctx.doc.columns
    texts, value, kinds, indices_of, number_of = cols.values, cols.value, cols.kinds, cols.indices, ctx.number_of
    ups = tuple(None if skip else number_of(rid, (0,)) for rid in unpaired)  # the same for every row
    pid = spec.id
    out = []
    for row in ctx.value_rows(pattern):
        if skip or not paired:
            refs: tuple[Number | None, ...] = ()
        else:
            indices = indices_of(row)
            refs = tuple(number_of(rid, (ridx,) if ridx is not None else indices) for rid, ridx in paired)
        text = texts[value[row]]
        slot = (pid, text, skip, refs, ups)
        verdict = verdicts.get(slot)
        if verdict is None:
            got = _range_verdict(ctx.registry, spec, ctx.value_of_text(spec, text, kinds[value[row]]),
                                 dict(zip(paired, refs, strict=True)) if refs else {},
                                 dict(zip(unpaired, ups, strict=True)))
            verdict = _passes(ctx, ctx.sketch_at(row)) if got is None else got
            if len(verdicts) < 65_536:
                verdicts[slot] = verdict
        if not verdict:
            out.append(row)
    return out


def _value_passes(ctx: Context, judge: Judge, v: Value, row: int) -> bool:
    """Whether value ``v`` (read at ``row``, the first of it) of a parameter judged by value alone passes:
    :func:`_judged` where it tells, else the entry's own verdict."""
    got = _judged(judge, v)
    return _passes(ctx, ctx.sketch_at(row)) if got is None else got


# How check_values judges a value of a parameter whose findings depend on the value alone (:func:`_judge`): _ANY
# (every number passes), else the parameter, the test and what the test reads: _BY_ENUM the parameter's listed
# values, _BY_ALLOWED the values the range allows, _BY_BOUNDS (low, low_strict, high, high_strict) as
# Bounds.contains reads them.
Judge = tuple["ParamSpec | None", int, "Any"]
_BY_ENUM, _BY_ALLOWED, _BY_BOUNDS = 1, 2, 3
_ANY: Judge = (None, 0, None)


def _judge(registry: Registry, spec: ParamSpec, prose: dict[str, Any]) -> Judge | None:
    """How :func:`_range_verdict` judges a value of ``spec`` where that depends on the value alone, found once
    per parameter; ``None`` where it depends on more: a range the catalogue writes in prose, or one that refers to
    other parameters. A range written at build time is read from its constants, neither decoded nor evaluated (a
    lint judges some two hundred parameters so: issue 40, axis.lis's checks 23.3 → 22.3 M instructions)."""
    if spec.id in prose:
        return None
    text = spec.range_text
    allowed = bounds = None
    if text:
        written = written_range(spec.id)
        if written is not None and written[0] == text:  # as registry.range_of reads it
            data = written[1]
            if data is not None:
                allowed = data[4]
                if allowed is None:
                    bounds = encoded_bounds(data)
                    if bounds is None:
                        return None  # refers to other parameters
        else:
            rng = registry.range_of(spec)
            if rng is not None:
                if rng.refs:
                    return None
                allowed = rng.allowed
                if allowed is None:
                    b = rng.evaluate(lambda *_: None)
                    bounds = (b.low, b.low_strict, b.high, b.high_strict)
    if spec.enum:
        return spec, _BY_ENUM, None
    if allowed is not None:
        return spec, _BY_ALLOWED, allowed
    return _ANY if bounds is None else (spec, _BY_BOUNDS, bounds)  # _ANY: no range (or one in prose, not parsed)


def _judged(judge: Judge, v: Value) -> bool | None:
    """What :func:`_range_verdict` says of value ``v`` of a parameter judged by value alone as ``judge`` says.
    The default (never faulty) is asked for only where the value fails the test: most pass it (140 defaults not
    made for axis.lis, 0.55 M instructions)."""
    if v.problem is not None or v.ref is not None:
        return None
    number = v.number
    if number is None or judge is _ANY:
        return True
    if _number_passes(judge, number):
        return True
    dflt = _default_of(judge[0])  # type: ignore[arg-type]
    return dflt is not None and number == dflt  # the default itself is never faulty


def _number_passes(judge: Judge, number: Number) -> bool:
    """Does ``number`` pass the test of ``judge`` (not _ANY), the default aside?"""
    spec, test, what = judge
    if test == _BY_BOUNDS:
        low, low_strict, high, high_strict = what  # Bounds.contains
        return not (low is not None and (number <= low if low_strict else number < low)) and \
            not (high is not None and (number >= high if high_strict else number > high))
    if test == _BY_ALLOWED:
        return number in what
    return isinstance(number, int) and spec.enum_allows(number)  # type: ignore[union-attr]


def _range_verdict(registry: Registry, spec: ParamSpec, v: Value,
                   read: dict[tuple[str, int | None], Number | None],
                   unpaired: dict[str, Number | None] | None = None) -> bool | None:
    """What :func:`_check_range` says of value ``v`` of ``spec`` (a range not written in prose, whose
    references pair with the entry's element): ``True`` no finding, ``False`` one; ``read``: the values
    of its references at the entry's element (missing: not known); ``unpaired``: the values of the
    references whose index means something else at their element 0 (``False`` there: their other
    elements are the entry's check to try). ``None`` for a value that is no number to range-check (a
    problem, a reference): :func:`_check_value` decides from the entry."""
    if v.problem is not None or v.ref is not None:
        return None
    number = v.number
    if number is None or (spec.range_text is None and not spec.enum):
        return True
    dflt = _default_of(spec)
    if dflt is not None and number == dflt:
        return True
    if spec.enum:
        return isinstance(number, int) and spec.enum_allows(number)
    rng = registry.range_of(spec)
    if rng is None:
        return True
    if rng.allowed is not None:
        return number in rng.allowed
    const = _constant_bounds(rng)
    if const is not None:  # no references
        return const.contains(number)
    if not unpaired:
        return rng.evaluate(lambda rid, ridx: read.get((rid, ridx))).contains(number)
    return rng.evaluate(lambda rid, ridx: unpaired[rid] if rid in unpaired else read.get((rid, ridx))).contains(number)


def _passes(ctx: Context, res: Resolved, configured: bool = False) -> bool:
    """Whether ``res``'s value passes (no finding; ``configured``: or its element is not configured);
    for a parameter judged by value alone (check_values), every entry of that value then passes."""
    if configured and not_configured(ctx, res):
        return True
    return next(iter(_check_value(ctx, res)), None) is None


def not_configured(ctx: Context, res: Resolved) -> bool:
    """An element beyond its count (`spindel[0]` with `spdl_anzahl 0`): the controller does not use it,
    so its value is not checked (X011 says what a channel's spindles are)."""
    key = res.entry.key
    if key is None:
        return False
    for count_id, level in ctx.registry.counted_by(res.spec):
        if len(key.indices) > level:
            n = ctx.number_of(count_id, key.indices[:level])
            if n is not None and key.indices[level] >= n:
                return True
    return False


def _check_value(ctx: Context, res: Resolved) -> Iterator[Diagnostic]:
    e, spec, v = res.entry, res.spec, res.value
    if e.value_kind is None:
        return
    if v.problem is None and v.ref is None:  # the common case: a number or text to range-check
        yield from _check_range(ctx, e, spec, v)
        return
    span = _value_span(e)
    if v.ref is not None:
        rid, _ = v.ref
        if ctx.registry.get(rid) is None:
            yield ctx.report(
                "R009",
                span,
                f"`{e.value}` refers to the unknown parameter {rid}, which the catalogue does not have: "
                f"{says(ctx, 'unknown-reference')}",
                param_id=spec.id, claim="unknown-reference",
            )
        return
    simple = _SIMPLE_PROBLEMS.get(v.problem or "")
    if simple is not None:
        code, template = simple
        what = {"integer": "an integer", "number": "a number"}.get(v.detail, v.detail)
        text = template.format(value=e.value, key=e.key_text, type=spec.type, what=what,
                               detail=v.detail, max_len=spec.max_len)
        if v.problem == "type" and e.value_kind is ValueKind.REAL:  # `666666.667` for an integer
            whole = e.value.split(".")[0].split("e")[0].split("E")[0] or "0"
            c = claim("number-format", ctx.kind)
            said = f"if the kernel takes it for an invalid number format, {c.says}" if c.consequence == "zeroed" \
                else c.says
            yield ctx.report(code, span, f"{text}: neither the catalogue nor the manuals say how the controller "
                             f"reads a decimal here (the digits before the point, {whole}, or something else); "
                             f"{said}. zero checks nothing against this value", param_id=spec.id, claim=c)
            return
        if v.problem == "overflow":
            c = _range_claim(ctx, e, spec)
            lo, hi = TYPE_LIMITS.get(spec.type, (None, None))
            limit = Bounds(lo, False, hi, False) if lo is not None or hi is not None else None
            said = _limited(c, limit, v.number) if v.number is not None else c.says
            yield ctx.report(code, span, f"{text}: {said}", param_id=spec.id, claim=c)
            return
        if v.problem == "bool" and v.number is not None:  # `2` for a BOOLEAN: a number outside 0..1
            c = _range_claim(ctx, e, spec)
            said = _limited(c, Bounds(0, False, 1, False), v.number)
            yield ctx.report(code, span, f"{text}: {said}", param_id=spec.id, claim=c)
            return
        name = "unreadable-entry" if v.problem == "length" else "number-format"
        yield ctx.report(code, span, f"{text}: {says(ctx, name)}", param_id=spec.id, claim=name)
        return
    if v.problem == "symbol":
        names = [s for s, _ in spec.symbols]
        from zero.nearest import close_matches  # start-up: only for a value that is not allowed

        near = close_matches(v.detail, names, n=1, cutoff=0.6)
        shown = ", ".join(names[:8]) + (", …" if len(names) > 8 else "")
        yield ctx.report(
            "R005",
            span,
            f"`{v.detail}` is not an allowed value of `{e.key_text}` ({shown}): "
            f"{says(ctx, 'number-format')}",
            param_id=spec.id, claim="number-format",
            hint=f"did you mean `{near[0]}`?" if near else None,
        )
        return


_defaults: dict[int, tuple[ParamSpec, Number | None]] = {}
_constant: dict[int, tuple[Range, Bounds | None]] = {}
_MISSING: Any = object()  # what a memo's .get gives for a key it does not hold


def _default_of(spec: ParamSpec) -> Number | None:
    """default_number(spec), computed once per spec object."""
    hit = _defaults.get(id(spec))
    if hit is None or hit[0] is not spec:
        hit = (spec, default_number(spec))
        _defaults[id(spec)] = hit
    return hit[1]


def _constant_bounds(rng: Range) -> Bounds | None:
    """The bounds of a range without references or listed values, evaluated once per range; ``None``
    for any other range."""
    hit = _constant.get(id(rng))
    if hit is None or hit[0] is not rng:
        const = rng.allowed is None and not rng.refs
        hit = (rng, rng.evaluate(lambda *_: None) if const else None)
        _constant[id(rng)] = hit
    return hit[1]


def _check_range(ctx: Context, e: Entry, spec: ParamSpec, v: Value) -> Iterator[Diagnostic]:
    if v.number is not None and spec.id in _prose_rows():
        yield from _check_prose(ctx, e, spec, v.number)
    if v.number is None or (spec.range_text is None and not spec.enum):
        return
    dflt = _default_of(spec)
    if dflt is not None and v.number == dflt:
        return  # the default itself is never faulty (some vendor ranges exclude it); no parse needed
    if spec.enum:
        yield from _check_enum(ctx, e, spec, v.number)
        return
    rng = ctx.registry.range_of(spec)
    if rng is None:
        return
    const = _constant_bounds(rng)
    if const is not None and const.contains(v.number):
        return
    span = _value_span(e)
    if rng.allowed is not None:
        if v.number not in rng.allowed:
            allowed = ", ".join(format_number(a) for a in rng.allowed)
            c = _range_claim(ctx, e, spec, "not-listed")
            yield ctx.report(
                "R005",
                span,
                f"{e.value} is not one of {allowed} for `{e.key_text}`: {c.says}",
                param_id=spec.id, claim=c,
            )
        return
    # The soft-limit pair (swe_neg < swe_pos) is explained by M001 when it is on;
    # here only the fixed sides of their ranges are checked then.
    skip_refs = "M001" in ctx.severities and spec.id in SOFT_LIMITS
    indices = e.key.indices if e.key else ()

    unpaired = {r.id for r in rng.refs if r.index is None and not _same_indices(ctx.registry, spec, r.id)}

    def resolve_at(k: int | None) -> Callable[[str, int | None], Number | None]:
        def resolve(pid: str, idx: int | None) -> Number | None:
            if skip_refs:
                return None
            if pid in unpaired:  # its index means something else: element k of its array
                return ctx.number_of(pid, (k or 0,))
            return ctx.number_of(pid, (idx,) if idx is not None else indices)
        return resolve

    bounds = rng.evaluate(resolve_at(None))
    if bounds.contains(v.number):
        return
    every = ""
    if unpaired:  # `tipp.geschw[i] ≤ P-AXIS-00212` (gear i?): faulty only against every element of it
        sizes = [d for pid in unpaired if (ref := ctx.registry.get(pid)) is not None for d in ref.dims[:1]]
        each = [rng.evaluate(resolve_at(k)) for k in range(min(sizes or [1]))]
        if any(b.contains(v.number) for b in each):
            return
        # said with the element that allows the most (the largest upper bound, else the lowest lower one)
        bounds = max(each, key=lambda b: (b.high if b.high is not None else float("inf"),
                                          -(b.low if b.low is not None else float("-inf"))))
        arrays = ", ".join(f"`{ctx.registry.specs[pid].key}`" for pid in sorted(unpaired))
        every = (f" for every element of {arrays} (its index means something else than the index of "
                 f"`{spec.key}`, so zero pairs none)")
    refs = [] if skip_refs else rng.refs
    text = _bounds_text(bounds, rng.low, rng.high)
    if refs and every:
        c = _range_claim(ctx, e, spec, "relation")
        yield ctx.report("R006", span, f"{e.value} violates {text} for `{e.key_text}`{every}: "
                         f"{c.says}", param_id=spec.id, claim=c)
    elif refs:
        yield ctx.report(
            "R006",
            span,
            f"{e.value} violates {text} for `{e.key_text}` ({_ref_values(ctx, refs, indices)}): "
            f"{_range_claim(ctx, e, spec, 'relation').says}",
            param_id=spec.id, claim=_range_claim(ctx, e, spec, "relation"),
        )
    elif spec.range_text and not spec.units and (unit := compiled(_PHYSICAL_UNIT).search(spec.range_text)):
        yield ctx.report("R012", span, f"{e.value} is outside {text} for `{e.key_text}` if it is in "
                         f"{unit.group()}, as the catalogue writes the range; the catalogue gives no unit for the "
                         "value itself, so whether it lies inside is not known", param_id=spec.id)
    elif _default_contradicts(spec, ctx.registry):
        yield ctx.report("R011", span, f"{e.value} is outside {text} for `{e.key_text}`, but so is the "
                         f"catalogue's own default {spec.default_display}: the catalogue contradicts itself, and "
                         "what the controller does with the value is not documented", param_id=spec.id,
                         claim="catalogue-contradiction")
    else:
        c = _range_claim(ctx, e, spec)
        yield ctx.report(
            "R005",
            span,
            f"{e.value} is outside {text} for `{e.key_text}`: {_limited(c, bounds, v.number)}",
            param_id=spec.id, claim=c,
        )


@functools.cache
def _prose_rows() -> dict[str, tuple[str, str, str]]:
    """The catalogue's prose ranges written as conditions (``catalog/data/prose_ranges.toml``) by ID: the
    condition, its guard ("": none) and the catalogue's prose. Read from ``prose_compiled.py`` (written at build
    time with them) while ``prose_ranges.py`` has the size it was written from, else from the rows."""
    from zero.catalog.data import prose_compiled  # start-up: at the first value checked

    try:
        size = os.stat(os.path.join(os.path.dirname(prose_compiled.__file__), "prose_ranges.py")).st_size
    except OSError:
        size = -1
    if size == getattr(prose_compiled, "ROWS_SIZE", None):
        return {pid: (pre[0], pre[1], pre[5]) for pid, pre in prose_compiled.COMPILED.items()}
    from zero.catalog.data.prose_ranges import RANGES  # start-up: only where the written module is stale

    return {row["id"]: (row["condition"], row.get("when") or "", row["prose"]) for row in RANGES}


@functools.cache
def _prose(pid: str) -> tuple[Compiled, Compiled | None, str, str, list[tuple[str, int | None]]]:
    """One prose range compiled, at its parameter's first value (an axis range is never compiled for a
    zero-offset list): written at build time (``tools/gen_conditions.py``), else (a row whose text differs
    from the one written: a stale module, slower, never wrong) compiled from its text here."""
    from zero.catalog.data.prose_compiled import COMPILED  # start-up: as above

    condition, guard, prose = _prose_rows()[pid]
    pre = COMPILED.get(pid)
    if pre is not None and pre[:2] == (condition, guard):
        return pre[2], pre[3], condition, prose, list(pre[4])
    from zero.catalog.conditions import compile_condition, parse, ref_elements  # start-up: a stale row only

    cond = parse(condition)
    when = compile_condition(parse(guard)) if guard else None
    return compile_condition(cond), when, condition, prose, ref_elements(cond)


def _check_prose(ctx: Context, e: Entry, spec: ParamSpec, number: Number) -> Iterator[Diagnostic]:
    """R006 for a range the catalogue writes in prose (`swe_neg < pos_refpkt < swe_pos`), where zero can
    write it as a condition: evaluated with this entry's value and the list's others (defaults where
    unset)."""
    condition, when, text, prose, shown = _prose(spec.id)
    indices = e.key.indices if e.key else ()

    def lookup(pid: str, index: int | None) -> Number | None:
        if pid == spec.id and index is None:
            return number
        return ctx.number_of(pid, (index,) if index is not None else indices)

    if when is not None and when(lookup) is not True:
        return
    if condition(lookup) is not False:
        return
    def origin(p: str, i: int | None) -> str:
        spec_p = ctx.registry.specs[p]
        idx = (i,) if i is not None else indices
        idx = (idx + (0,) * len(spec_p.dims))[: len(spec_p.dims)]
        return _origin(ctx, p, idx)

    values = ", ".join(f"{format_key(ctx.registry.specs[p].key or p, (i,) if i is not None else indices)} = "
                       f"{format_number(lookup(p, i))} ({origin(p, i)})" for p, i in shown if p != spec.id)
    c = _range_claim(ctx, e, spec, "relation")
    yield ctx.report("R006", _value_span(e), f"{e.value} violates the catalogue's range for `{e.key_text}`, which "
                     f"it writes in prose, {prose} ({values}): {c.says}",
                     hint=f"the range as zero evaluates it: {text}", param_id=spec.id, claim=c)


def _same_indices(registry: Registry, spec: ParamSpec, ref_id: str) -> bool:
    """Do the indices of ``spec`` and of the parameter its range refers to mean the same thing (the
    same array: `getriebe[i].a` and `getriebe[i].b`)? Not where the arrays differ
    (`handbetrieb.tipp.geschw[i]` numbers jog steps, `getriebe[i].dynamik.vb_max` gears), nor where
    only the referenced parameter is an array. Where it is no array, there is nothing to pair."""
    ref = registry.get(ref_id)
    if ref is None or not ref.dims or not ref.key:
        return True
    if not spec.dims or not spec.key:
        return False  # a single value against an array: no index to pair
    arrays = [m for m in spec.key.split(".") if m.endswith("[]")]
    others = [m for m in ref.key.split(".") if m.endswith("[]")]
    return arrays[: len(others)] == others


def _check_enum(ctx: Context, e: Entry, spec: ParamSpec, number: Number) -> Iterator[Diagnostic]:
    """R005 for a value the catalogue's listed values (or bits) do not allow."""
    if isinstance(number, int) and spec.enum_allows(number):
        return
    what = "any combination of the bits" if spec.enum_flags else "one of the values"
    c = _range_claim(ctx, e, spec, "not-listed")
    yield ctx.report(
        "R005", _value_span(e),
        f"{e.value} is not {what} the catalogue lists for `{e.key_text}` ({spec.enum_listed()}): {c.says}",
        param_id=spec.id, claim=c,
    )


def _bounds_text(b: Bounds, low: object, high: object) -> str:
    parts = []
    if b.low is not None:
        shown = format_number(b.low) if str(low) == format_number(b.low) else f"{low} = {format_number(b.low)}"
        parts.append(f"{shown} {'<' if b.low_strict else '≤'} ")
    parts.append("x")
    if b.high is not None:
        shown = format_number(b.high) if str(high) == format_number(b.high) else f"{high} = {format_number(b.high)}"
        parts.append(f" {'<' if b.high_strict else '≤'} {shown}")
    return "".join(parts)


def _ref_values(ctx: Context, refs: list[Ref], indices: tuple[int, ...]) -> str:
    out = []
    for r in refs:
        spec = ctx.registry.get(r.id)
        idx = (r.index,) if r.index is not None else indices
        if spec is None:
            continue
        dims = len(spec.dims)
        key = format_key(spec.key or r.id, (idx + (0,) * dims)[:dims])
        element = (idx + (0,) * dims)[:dims]
        where = ctx.value_of(r.id, element)
        if where is not None:
            out.append(f"{key} is {format_number(ctx.number_of(r.id, idx))} on {_origin(ctx, r.id, element)}")
        else:
            out.append(f"{key} is not set, default {format_number(ctx.number_of(r.id, idx))}")
    return "; ".join(out)


# ------------------------------------------------------------------ R007, R008

DUPLICATE_KEY = FAMILY.rule(
    "R007", "duplicate-key", W, "The same key twice in one list",
    """
What it checks: a key that appears more than once before `Ende`.

Why it matters on the machine: the controller reads the list top to bottom, so the later
value overwrites the earlier one. The earlier line has no effect, but whoever edits it
believes it does. (The vendor's own SERCOS axis lists set `kenngr.antr_typ` twice.)

Fix: delete one of the entries (unsafe fix: removes the earlier line).
""")


@FAMILY.check(DUPLICATE_KEY)
def check_duplicates(ctx: Context) -> Iterator[Diagnostic]:
    """R007: the later entry wins."""
    # An element is its pattern and indices (`np_grp[01]` is element 1, as `np_grp[1]` is, and every
    # index beyond the arrays one element): only a pattern whose entries write fewer distinct elements
    # than entries has a duplicate, and only its entries are visited. A pattern whose keys have one
    # shape each (`wz[].laenge`; `wz[].param[0]`, `wz[].param[1]`) is counted by its first indices.
    cols = ctx.doc.columns
    rows: list[int] = []
    for pattern, shapes in ctx.pattern_shapes.items():
        if len(shapes) == 1 and len(ctx.shape_rows[shapes[0]]) == 1:
            continue  # one entry (most patterns of a small list)
        kinds = [ctx.shape_keys[s] for s in shapes]
        if all(indexed for _, _, indexed in kinds) and len({indices for _, indices, _ in kinds}) == len(kinds):
            for shape in shapes:
                group = ctx.shape_rows[shape]
                if len(group) > 1 and len(set(take(cols.first, group))) < len(group):
                    rows.extend(group)
            continue
        group = ctx.rows_of(pattern)
        if len(group) > 1 and len(set(ctx.indices_at(group))) < len(group):
            rows.extend(group)
    rows.sort()
    seen: dict[str, Entry] = {}
    for row in rows:
        e = ctx.entry_at(row)
        key = e.key
        assert key is not None  # a row of a group
        # the element's key as written without leading zeros; most keys are written so already
        slot = key.text
        if ("[0" in slot and compiled(_LEADING_ZERO).search(slot)) or HUGE_INDEX in key.indices:
            slot = format_key(key.pattern, key.indices)
        first = seen.get(slot)
        if first is None:
            seen[slot] = e
            continue
        spec = ctx.registry.by_pattern(key.pattern, ctx.kind)
        yield ctx.report(
            "R007",
            _key_span(e),
            f"`{e.key_text}` is already set on line {first.line} ({first.value}); this later "
            f"value {e.value} overwrites it, so line {first.line} has no effect",
            param_id=spec.id if spec else None,
            fix=Fix(
                f"Delete the earlier entry on line {first.line}",
                (Edit(Span(first.line, 1, first.line + 1, 1), ""),),
                safe=False,
            ),
            related=(Related(_key_span(first), f"first set here to {first.value}, which this entry overwrites"),),
        )
        seen[slot] = e


ANNOTATION_MISMATCH = FAMILY.rule(
    "R008", "annotation-mismatch", W, "A `( P-XXXX-nnnnn` comment names another parameter",
    """
What it checks: vendor lists annotate entries with their ID in a comment
(`kenngr.swe_pos 15000000 ( P-AXIS-00178 : ...`). zero compares the ID with the key's.

Why it matters on the machine: nothing for the controller, which ignores comments; but
engineers look up parameters by these IDs, and a wrong one sends them to the wrong page
of the manual. Seven such annotations are in the vendor's SDK lists.

Fix: correct the ID in the comment (safe fix).
""")


@FAMILY.check(ANNOTATION_MISMATCH)
def check_annotations(ctx: Context) -> Iterator[Diagnostic]:
    """R008: `( P-XXXX-nnnnn` comment naming another parameter than the key."""
    cols = ctx.doc.columns
    if not any(cols.notes):
        return  # no comment of the list names a parameter
    notes = [*cols.notes, None]  # by comment id (-1: no comment)
    comment = cols.comment
    rows: list[int] = []  # the entries whose annotation names another parameter, visited in order
    for pattern, hit in ctx.bound.items():
        if hit is None or hit[1]:
            continue  # not bound, or by an alias (its annotation names the documented parameter)
        pid = hit[0].id
        for shape in ctx.pattern_shapes[pattern]:
            group = ctx.shape_rows[shape]
            if len(group) == 1:
                note = notes[comment[group[0]]]
                if note is not None and note != pid:
                    rows.append(group[0])
                continue
            cids = take(comment, group)
            naming = {cid for cid in set(cids) if notes[cid] is not None and notes[cid] != pid}
            if naming:  # comments that name another parameter
                rows.extend(r for r, cid in zip(group, cids, strict=True) if cid in naming)
    if ctx.valueless:  # what `resolved` holds: entries with a value
        rows = [r for r in rows if cols.value[r] not in ctx.valueless]
    rows.sort()
    for row in rows:
        res = ctx.resolved_at(row)
        e = res.entry
        other = ctx.registry.get(e.annotation or "")
        what = f" (that is `{other.key}`)" if other and other.key else ""
        span = Span.on_line(e.line, e.annotation_start, e.annotation_start + 12)
        fix = Fix(f"Write {res.spec.id} in the comment", (Edit(span, res.spec.id),))
        yield ctx.report(
            "R008",
            span,
            f"the comment names {e.annotation}{what}, but `{e.key_text}` is {res.spec.id}",
            param_id=res.spec.id,
            fix=fix,
            hint=fix.title,
        )

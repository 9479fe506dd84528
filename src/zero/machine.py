"""A machine: the lists its start-up list names, read together.

The controller's start-up list (``hochlauf.lis``) names the channel lists
(``sda_mds[c]``), the zero-offset lists (``nullp_data[c]``) and the axis lists
(``achs_mds[i]``). A channel list says which logical axis (``kopf.achs_nr`` of an
axis list) is the channel's axis j (``gruppe[0].achse[j].log_achs_nr``) and its NC
name. With that, zero can check a zero offset against the soft limits of *its*
axis (rules X001–X007 in :mod:`zero.rules.machine`) and compute the soft limits in
the programming coordinate system per work offset (:func:`pcs_limits`,
``zero limits``).

Paths in a start-up list are relative to the controller's working directory; zero
tries the start-up list's directory, then up to four of its ancestors, then the bare
file name next to the start-up list.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from zero.lint import LintOptions, LintResult, build_context, lint_bytes, read_file, selected_rules
from zero.model import Entry
from zero.ranges import Number
from zero.registry import LENGTH_UNIT, Registry, default_registry
from zero.rules.base import Context

SWE_NEG, SWE_POS = "P-AXIS-00177", "P-AXIS-00178"
AXIS_NR, AXIS_NAME, AXIS_TYPE = "P-AXIS-00016", "P-AXIS-00297", "P-AXIS-00018"
CH_LOG_NR, CH_NAME, CH_COUNT = "P-CHAN-00035", "P-CHAN-00006", "P-CHAN-00003"
G53_AVAILABLE, OFFSET, INACTIVE = "P-ZERO-00001", "P-ZERO-00003", "P-ZERO-00004"
ROTARY_TYPES = (2, 4)  # rotary axis, spindle


@dataclass(slots=True)
class ListFile:
    """One list of the machine, linted, with its evaluation context."""

    key: str  # the start-up entry that names it: achs_mds[0]
    path: Path
    result: LintResult
    ctx: Context
    line: int  # where the start-up list names it

    def number(self, pid: str, indices: tuple[int, ...] = ()) -> Number | None:
        return self.ctx.number_of(pid, indices)

    def text(self, pid: str, indices: tuple[int, ...] = ()) -> str | None:
        res = self.ctx.value_of(pid, indices)
        if res is not None:
            return res.value.text if res.value.text is not None else res.entry.value
        spec = self.ctx.registry.get(pid)
        return spec.default if spec is not None else None

    def entry(self, pid: str, indices: tuple[int, ...] = ()) -> Entry | None:
        res = self.ctx.value_of(pid, indices)
        return res.entry if res is not None else None


@dataclass(slots=True)
class Axis:
    nr: int  # logical axis number (kopf.achs_nr)
    name: str
    rotary: bool
    swe_neg: Number
    swe_pos: Number
    list: ListFile

    @property
    def unit(self) -> str:
        return "°" if self.rotary else "mm"


@dataclass(slots=True)
class ChannelAxis:
    index: int  # j in np_grp[i].achse[j]
    log_nr: int
    name: str
    entry: Entry | None


@dataclass(slots=True)
class Channel:
    index: int
    lists: ListFile | None  # the channel list
    zero: ListFile | None  # the zero-offset list
    axes: list[ChannelAxis] = field(default_factory=list)
    tools: ListFile | None = None  # the tool list (werkz_data[c])


@dataclass(slots=True)
class Missing:
    key: str
    raw: str  # the path as written
    line: int


@dataclass(slots=True)
class Machine:
    startup: ListFile
    axis_lists: list[ListFile] = field(default_factory=list)
    channels: list[Channel] = field(default_factory=list)
    missing: list[Missing] = field(default_factory=list)

    @property
    def lists(self) -> list[ListFile]:
        out = [self.startup, *self.axis_lists]
        for ch in self.channels:
            out.extend(x for x in (ch.lists, ch.zero, ch.tools) if x is not None)
        return out

    def axes(self) -> dict[int, Axis]:
        """Logical axis number → axis (the first list wins when two claim one number)."""
        out: dict[int, Axis] = {}
        for lf in self.axis_lists:
            ax = axis_of(lf)
            if ax is not None and ax.nr not in out:
                out[ax.nr] = ax
        return out


def axis_of(lf: ListFile) -> Axis | None:
    nr = lf.number(AXIS_NR)
    if nr is None:
        return None
    kind = lf.number(AXIS_TYPE)
    neg, pos = lf.number(SWE_NEG), lf.number(SWE_POS)
    return Axis(int(nr), lf.text(AXIS_NAME) or f"axis {nr}", kind in ROTARY_TYPES,
                neg if neg is not None else -100_000_000, pos if pos is not None else 100_000_000, lf)


def resolve(startup: Path, raw: str) -> Path | None:
    """Where a path named in a start-up list is (None when nowhere)."""
    text = raw.strip().strip('"')
    if not text:
        return None
    base = startup.parent
    # The controller's working directory is usually the parent of `listen/`: try the
    # start-up list's directory and its ancestors, then the bare name next to it.
    for d in [base, *list(base.parents)[:4]]:
        cand = d / text
        if cand.is_file():
            return cand
    cand = base / Path(text).name
    return cand if cand.is_file() else None


def _read(key: str, path: Path, line: int, registry: Registry, kind: str | None,
          options: LintOptions | None) -> ListFile:
    opts = options or LintOptions()
    if kind is not None and opts.kind is None:
        opts = LintOptions(opts.select, opts.ignore, kind, opts.severity)
    result = lint_bytes(read_file(path), str(path), registry, opts)
    ctx = build_context(result.document, registry, result.kind, selected_rules(opts))
    return ListFile(key, path, result, ctx, line)


def load_machine(startup_path: Path, registry: Registry | None = None,
                 options: LintOptions | None = None, overrides: dict[str, Path] | None = None) -> Machine:
    """Read a start-up list and every list it names (lint results included); ``overrides``
    (start-up key → path, from ``[tool.zero.machine]``) replace what the start-up list names."""
    registry = registry or default_registry()
    startup = _read("start-up list", startup_path, 0, registry, "STUP", options)
    machine = Machine(startup)
    named: dict[str, list[tuple[int, str, int]]] = {}
    for e in startup.result.document.entries:
        if e.key is None or not e.key.indices:
            continue
        first = e.key.pattern
        if first in ("achs_mds[]", "sda_mds[]", "nullp_data[]", "werkz_data[]"):
            named.setdefault(first, []).append((e.key.indices[0], e.value, e.line))

    def load(key: str, raw: str, line: int, kind: str) -> ListFile | None:
        override = (overrides or {}).get(key)
        path = override if override is not None and override.is_file() else resolve(startup_path, raw)
        if path is None:
            machine.missing.append(Missing(key, raw, line))
            return None
        return _read(key, path, line, registry, kind, options)

    for idx, raw, line in sorted(named.get("achs_mds[]", [])):
        lf = load(f"achs_mds[{idx}]", raw, line, "AXIS")
        if lf is not None:
            machine.axis_lists.append(lf)
    sda = {i: (raw, line) for i, raw, line in named.get("sda_mds[]", [])}
    zero = {i: (raw, line) for i, raw, line in named.get("nullp_data[]", [])}
    tools = {i: (raw, line) for i, raw, line in named.get("werkz_data[]", [])}
    for c in sorted(set(sda) | set(zero)):
        ch_list = load(f"sda_mds[{c}]", *sda[c], "CHAN") if c in sda else None
        zero_list = load(f"nullp_data[{c}]", *zero[c], "ZERO") if c in zero else None
        ch = Channel(c, ch_list, zero_list)
        if c in tools:
            ch.tools = load(f"werkz_data[{c}]", *tools[c], "TOOL")
        if ch_list is not None:
            count = ch_list.number(CH_COUNT, (0,))
            present = {ix[1] for ix in ch_list.ctx.by_id.get(CH_LOG_NR, {}) if len(ix) == 2 and ix[0] == 0}
            n = max(int(count or 0), max(present, default=-1) + 1)
            for j in range(min(n, 32)):
                nr = ch_list.number(CH_LOG_NR, (0, j))
                if nr is None:
                    continue
                name = ch_list.text(CH_NAME, (0, j)) or f"axis {j}"
                ch.axes.append(ChannelAxis(j, int(nr), name, ch_list.entry(CH_LOG_NR, (0, j))))
        machine.channels.append(ch)
    return machine


# ----------------------------------------------------------------- PCS limits

ZERO_UNIT = LENGTH_UNIT
IP247_LIMIT = 999_999_990  # ±99.999999 m in 0.1 µm (Siemens S5 IP247)


@dataclass(slots=True)
class LimitRow:
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
        def u(x: Number) -> float:
            return round(x / ZERO_UNIT, 4)

        return {"channel": self.channel, "group": self.group, "g_code": g_code(self.group),
                "axis": self.axis_index, "name": self.axis_name, "log_nr": self.log_nr, "unit": self.unit,
                "acs_neg": u(self.acs_neg), "acs_pos": u(self.acs_pos), "offset": u(self.offset),
                "masked": self.masked, "pcs_neg": u(self.pcs_neg), "pcs_pos": u(self.pcs_pos),
                "note": self.note or None}


def g_code(group: int) -> str:
    """The G code that selects zero-offset group ``group``: G53, G54..G59, else G159=n."""
    if group == 0:
        return "G53"
    if 1 <= group <= 6:
        return f"G{53 + group}"
    return f"G159={group}"


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
            groups |= {ix[0] for ix in zl.ctx.by_id.get(OFFSET, {}) if ix}
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


@dataclass(slots=True)
class Ip247Violation:
    what: str
    value: Number
    where: str


TOOL_LENGTH, TOOL_AXIS_OFFSET = "P-TOOL-00003", "P-TOOL-00006"
TOOL_LENGTH_AXIS = 2  # the tool length acts along the third channel axis (Z in G17)


def ip247(machine: Machine) -> list[Ip247Violation]:
    """The Siemens S5 IP247 rule: offsets, soft limits, and soft limits plus each tool's offset
    on that axis (``wz[t].ax_versatz[j]``, plus the length on the third channel axis) inside
    ±99.999999 m."""
    out: list[Ip247Violation] = []
    axes = machine.axes()
    for ch in machine.channels:
        if ch.tools is None:
            continue
        ctx = ch.tools.ctx
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
                                                  f"{ch.tools.path} (offset {off / ZERO_UNIT:.4f} mm)"))
    for ax in machine.axes().values():
        for what, v in (("negative soft limit", ax.swe_neg), ("positive soft limit", ax.swe_pos)):
            if abs(v) > IP247_LIMIT:
                out.append(Ip247Violation(what, v, f"{ax.list.path} ({ax.name})"))
    for ch in machine.channels:
        if ch.zero is None:
            continue
        for idx, res in sorted(ch.zero.ctx.by_id.get(OFFSET, {}).items()):
            offset = res.value.number
            if offset is not None and abs(offset) > IP247_LIMIT:
                out.append(Ip247Violation(f"offset {g_code(idx[0])} axis {idx[1]}", offset,
                                          f"{ch.zero.path}:{res.entry.line}"))
    return out


def lint_machine(startup_path: Path, registry: Registry | None = None,
                 options: LintOptions | None = None,
                 overrides: dict[str, Path] | None = None) -> tuple[Machine, list[LintResult]]:
    """Every list of the machine with its own findings, plus the X findings on the file they
    concern (the start-up list, a channel list, a zero-offset list or an axis list)."""
    from zero.diagnostics import Diagnostic
    from zero.rules.machine import check_machine

    registry = registry or default_registry()
    opts = options or LintOptions()
    machine = load_machine(startup_path, registry, opts, overrides)
    results: dict[str, LintResult] = {}
    for lf in machine.lists:
        results.setdefault(str(lf.path), lf.result)
    severities = selected_rules(opts)
    for d in check_machine(machine, severities):
        r = results.get(d.path)
        if r is not None:
            r.diagnostics.append(d)
    for r in results.values():
        r.diagnostics.sort(key=Diagnostic.sort_key)
    return machine, list(results.values())

"""A machine: the lists its start-up list names, read together.

The controller's start-up list (``hochlauf.lis``) names the channel lists
(``sda_mds[c]``), the zero-offset lists (``nullp_data[c]``) and the axis lists
(``achs_mds[i]``). A channel list says which logical axis (``kopf.achs_nr`` of an
axis list) is the channel's axis j (``gruppe[0].achse[j].log_achs_nr``) and its NC
name. With that, zero can check a zero offset against the soft limits of *its*
axis (rules X001–X007 in :mod:`zero.rules.machine`) and compute the soft limits in
the programming coordinate system per work offset (:mod:`zero.machine.limits`,
``zero limits``). Loading a machine reads and evaluates its lists; linting them is
the engine's work (:func:`zero.engine.lint.lint_machine`).

Paths in a start-up list are relative to the controller's working directory; zero
tries the start-up list's directory, then up to four of its ancestors, then the bare
file name next to the start-up list.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from zero.catalog.ids import (
    AXIS_NAME,
    AXIS_NR,
    AXIS_TYPE,
    CH_COUNT,
    CH_LOG_NR,
    CH_NAME,
    ROTARY_TYPES,
    SWE_NEG,
    SWE_POS,
    Number,
)
from zero.catalog.registry import Registry
from zero.catalog.values import ListValues
from zero.files import read_file
from zero.lists.model import Entry
from zero.lists.tokenizer import tokenize

# Soft limits the controller uses when an axis list sets none (±10 m, the catalogue default).
DEFAULT_SOFT_LIMIT = 100_000_000


@dataclass(slots=True)
class ListFile:
    """One list of the machine with the values the controller takes from it."""

    key: str  # the start-up entry that names it: achs_mds[0]
    path: Path
    values: ListValues
    line: int  # where the start-up list names it

    def number(self, pid: str, indices: tuple[int, ...] = ()) -> Number | None:
        return self.values.number_of(pid, indices)

    def text(self, pid: str, indices: tuple[int, ...] = ()) -> str | None:
        return self.values.text_of(pid, indices)

    def entry(self, pid: str, indices: tuple[int, ...] = ()) -> Entry | None:
        return self.values.entry_of(pid, indices)


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
                neg if neg is not None else -DEFAULT_SOFT_LIMIT, pos if pos is not None else DEFAULT_SOFT_LIMIT, lf)


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


def _read(key: str, path: Path, line: int, registry: Registry, kind: str) -> ListFile:
    doc = tokenize(read_file(path), str(path))
    return ListFile(key, path, ListValues.of(doc, registry, kind), line)


def load_machine(startup_path: Path, registry: Registry, forced_kind: str | None = None,
                 overrides: dict[str, Path] | None = None) -> Machine:
    """Read a start-up list and every list it names; ``overrides`` (start-up key → path, from
    ``[tool.zero.machine]``) replace what the start-up list names. Each list is read as the
    kind its start-up key says (``achs_mds`` an axis list, ...), or as ``forced_kind``."""
    startup = _read("start-up list", startup_path, 0, registry, forced_kind or "STUP")
    machine = Machine(startup)
    named: dict[str, list[tuple[int, str, int]]] = {}
    for e in startup.values.doc.entries:
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
        return _read(key, path, line, registry, forced_kind or kind)

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
            present = {ix[1] for ix in ch_list.values.by_id.get(CH_LOG_NR, {}) if len(ix) == 2 and ix[0] == 0}
            n = max(int(count or 0), max(present, default=-1) + 1)
            for j in range(min(n, 32)):
                nr = ch_list.number(CH_LOG_NR, (0, j))
                if nr is None:
                    continue
                name = ch_list.text(CH_NAME, (0, j)) or f"axis {j}"
                ch.axes.append(ChannelAxis(j, int(nr), name, ch_list.entry(CH_LOG_NR, (0, j))))
        machine.channels.append(ch)
    return machine

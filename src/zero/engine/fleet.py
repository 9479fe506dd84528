"""Fleet drift: every effective parameter that differs from a golden machine on any machine of a fleet.

``zero diff --fleet GOLDEN MACHINE...`` compares each machine with the golden machine exactly as
``zero diff --machine GOLDEN MACHINE`` does (the same effective values, a value a default list
supplies counting as the machine's; the same pairing of lists: by what they configure,
``axis 1 (achs_mds[0])``, ``channel 0 (sda_mds[0])``, ``start-up``, ...; the same notion of "equal":
``0x10`` is ``16``), and then turns it around: per parameter, which machines differ, with which
values, how many (``kenngr.vb_max of axis 1 differs on 2 of 30 machines``), next to the golden value.

What differs from ``zero diff --machine`` (where that one shows every parameter of a list as removed):

* a list the golden machine loads and a machine does not (missing, unreadable, not named) is one
  finding, :class:`ListDrift` ``missing`` with the reason, not every parameter of it;
* a *default list* a machine misses is reported the same way, and the machine's lists of its kind
  are compared as if the golden's default list lay under them (their own differences still show);
* a list that only a machine loads is :class:`ListDrift` ``extra``;
* a list whose scope name changed (an axis list that states another axis number) is paired by the
  start-up key that names it (``achs_mds[0]``), so that the one changed ``kopf.achs_nr`` shows;
* a machine that cannot be read at all is :attr:`FleetDrift.unreadable`, and the others go on.

**Machines.** Each path given is a start-up list, or a folder: below a folder, every folder (the
folder itself first, then its subfolders in name order, hidden ones skipped) that holds a file named
``hochlauf.lis`` or ``startup.xml`` (either case; ``hochlauf.lis`` first) is one machine with that
start-up list, and its subfolders are not searched further (they hold that machine's lists, and the
vendor's ``SoE/hochlauf.lis`` variants). The walk stays in the folder: symbolic links to folders
are not followed, nor start-up lists that link out of it. A machine given twice, or the golden machine itself, is
compared once, respectively not at all. Each machine is read through the resolver
(:meth:`Project.machine`) with the list overrides of its own configuration.

**Order.** Parameters in the order of the golden machine's lists (``zero diff --machine``'s order),
then by group and key; within a parameter the values by how many machines have them (most first),
then by the first machine that has them; machines in the order given (a folder's in name order).
The same whatever ``jobs``.
"""

from __future__ import annotations

import contextlib
import gc
import os
import re
from collections.abc import Callable, Hashable, Sequence
from pathlib import Path

from zero.catalog.registry import ParamSpec, Registry
from zero.catalog.rows import Rows, own_entries
from zero.diff import (
    ADDED,
    CHANGED,
    REMOVED,
    DiffOptions,
    Side,
    default_effective,
    default_name,
    diff_sides,
    group_order,
    key_order,
    spec_for,
)
from zero.diff import effective as value_of
from zero.engine.project import Project, Registries, common_of, open_project
from zero.errors import ZeroError
from zero.files import read_file, within
from zero.machine.effective import entries_of
from zero.machine.model import Machine
from zero.records import Record, field

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: the cache only when it is on; typing for type checkers only
    from typing import Any

    from zero.engine.cache import FleetCache

# The names of a start-up list, as a folder of machines is searched for them (lower case, in order).
STARTUP_NAMES = ("hochlauf.lis", "startup.xml")
# Below this many machines a second process costs more than it saves: a machine whose lists are copies
# of lists read before costs about 4 ms, starting the pool about 50 ms of the parent's time (measured
# on 30 machines: 105 ms of comparisons in one process; 100 ms parent + 2 x 52 ms children in two).
PARALLEL_MIN_MACHINES = 32
MISSING, EXTRA = "missing", "extra"  # ListDrift.status


# ----------------------------------------------------------------------------- results


class FleetValue(Record):
    """One value some machines have instead of the golden one."""

    value: str | None  # as the first machine with it writes it; None: not set there (the catalogue default)
    note: str = ""  # for a value not set: what it then is ("the default 1000")
    name: str | None = None  # its meaning where the catalogue names it (`on`, `SERCOS`, `VEL | ACC`)
    delta: float | int | None = None  # value − golden, for a quantity
    machines: list[str] = field(default_factory=list)

    @property
    def count(self) -> int:
        return len(self.machines)


class ParamDrift(Record):
    """One effective parameter of one list that differs from the golden machine on some machines."""

    scope: str  # the list, as zero diff --machine names it: axis 1 (achs_mds[0])
    key: str
    param_id: str | None
    group: str  # zero diff's group within the list (kenngr, np_grp, general, ...)
    golden: str | None  # as the golden machine writes it; None: not set there
    golden_note: str = ""  # for a golden value not set: what it then is ("the default 0")
    golden_name: str | None = None
    unit: str | None = None
    values: list[FleetValue] = field(default_factory=list)

    @property
    def count(self) -> int:
        """How many machines differ."""
        return sum(v.count for v in self.values)

    @property
    def machines(self) -> list[str]:
        return [m for v in self.values for m in v.machines]


class ListDrift(Record):
    """A list the golden machine loads and some machines do not (``missing``), or the reverse (``extra``)."""

    scope: str  # axis 2 (achs_mds[1]), or a default list by its start-up key (default_achs_mds)
    status: str  # missing, extra
    reason: str
    machines: list[str] = field(default_factory=list)

    @property
    def count(self) -> int:
        return len(self.machines)


class Unreadable(Record):
    machine: str
    error: str


class FleetDrift(Record):
    """What ``zero diff --fleet`` found."""

    golden: str
    machines: list[str]  # the machines compared (readable or not), in order
    params: list[ParamDrift] = field(default_factory=list)
    lists: list[ListDrift] = field(default_factory=list)
    unreadable: list[Unreadable] = field(default_factory=list)

    @property
    def compared(self) -> int:
        """The machines that could be read: the "of N" of every count."""
        return len(self.machines) - len(self.unreadable)

    @property
    def drifting(self) -> list[str]:
        """The machines that differ in anything (a parameter or a list), in order."""
        hit = {m for p in self.params for m in p.machines} | {m for ld in self.lists for m in ld.machines}
        return [m for m in self.machines if m in hit]

    @property
    def differs(self) -> bool:
        return bool(self.params or self.lists)


# ----------------------------------------------------------------------------- machines


MAX_DEPTH = 32  # folders of machines are a few levels deep; a deeper walk stops there


def _startup_in(folder: Path, top: Path) -> Path | None:
    try:  # names first: a folder of a machine's lists is not asked about each of them
        named = [folder / n for n in sorted(os.listdir(folder)) if n.lower() in STARTUP_NAMES]
        names = {p.name.lower(): p for p in named if p.is_file() and within(p, top)}
    except OSError:
        return None
    return next((names[n] for n in STARTUP_NAMES if n in names), None)


def find_startups(folder: Path) -> list[Path]:
    """The start-up lists of the machines below ``folder`` (see the module's rule). The walk stays in
    ``folder``: a symbolic link to a folder is not followed (one to `/` walked the whole disk), a
    start-up list that links out of it is not taken, and it goes at most :data:`MAX_DEPTH` deep."""
    found: list[Path] = []

    def walk(d: Path, depth: int) -> None:
        hit = _startup_in(d, folder)
        if hit is not None:
            found.append(hit)
            return
        if depth >= MAX_DEPTH:
            return
        try:
            subs = sorted(p for p in d.iterdir() if not p.name.startswith(".") and not p.is_symlink() and p.is_dir())
        except OSError:
            return
        for s in subs:
            walk(s, depth + 1)

    walk(folder, 0)
    return found


def machine_startups(paths: Sequence[str | Path], golden: str | Path | None = None) -> list[str]:
    """The start-up lists of the machines ``paths`` name (start-up lists, or folders of machines),
    each once, in order, without the golden machine's."""
    out: list[str] = []
    seen = {os.path.realpath(golden)} if golden is not None else set()
    for p in paths:
        path = Path(p)
        if path.is_dir():
            found = find_startups(path)
            if not found:
                raise ZeroError(f"no start-up list ({', '.join(STARTUP_NAMES)}) found in this folder or below it",
                                str(path))
            named = [str(f) for f in found]
        else:
            named = [str(p)]
        for s in named:
            real = os.path.realpath(s)
            if real not in seen:
                seen.add(real)
                out.append(s)
    return out


# ----------------------------------------------------------------------------- one machine


class _Found(Record):
    """One parameter of one machine that differs from the golden machine (what a worker sends back)."""

    scope: str
    key: str
    param_id: str | None
    group: str
    golden: str | None
    golden_note: str
    golden_name: str | None
    unit: str | None
    value: str | None
    note: str
    name: str | None
    delta: float | int | None
    same: Hashable  # the effective value: machines with equal ones are one value


class _MachineDrift(Record):
    machine: str
    found: list[_Found] = field(default_factory=list)
    lists: list[tuple[str, str, str]] = field(default_factory=list)  # scope, status, reason
    error: str | None = None
    deps: tuple[Any, ...] | None = None  # what the machine was read from, for the cache (None: not kept)


class _Scope(Record):
    name: str
    key: str  # the start-up key that names the list (achs_mds[0]); the scope name for the start-up list
    kind: str | None
    side: Side
    own: Rows  # the entries of the list itself (without its default list's), read from its rows
    based: bool  # a default list lies under it


class _Golden(Record):
    """The golden machine, as each comparison needs it (kept by the workers)."""

    project: Project
    registry: Registry
    options: DiffOptions
    scopes: dict[str, _Scope]
    defaults: dict[str, tuple[str, Rows]]  # kind → (start-up key, the default list's entries)
    keep: FleetCache | None = None  # the cache: each comparison then says what its machine was read from


_KEY_IN_NAME = re.compile(r"\(([^()]*)\)$")


def _scopes(project: Project, startup: str, fleet: bool) -> tuple[dict[str, _Scope], Machine]:
    """A machine's lists by scope name, read through the resolver (a fleet's machines without
    keeping each: the resolver keeps the last few)."""
    if fleet:
        m = project.machine(Path(startup), startup=startup, required=True, reader=read_file, reader_key="fleet")
    else:
        m = project.machine(Path(startup), startup=startup, required=True)
    assert m is not None
    out: dict[str, _Scope] = {}
    bases: dict[int, Rows] = {}  # a default list's entries, found once for all the lists over it
    for name, lf in m.scopes():
        hit = _KEY_IN_NAME.search(name)
        key = hit.group(1) if hit else (lf.key if name != "start-up" else name)
        values = lf.values
        own = own_entries(values)  # the one value model (zero.machine.effective): bound once, layered once
        entries = own.over(entries_of(values.base, bases)) if values.base is not None else own
        out[name] = _Scope(name, key, values.kind, Side(str(lf.path), values.kind, entries), own,
                           values.base is not None)
    return out, m


def _golden(project: Project, golden: str, options: DiffOptions, keep: FleetCache | None = None) -> _Golden:
    scopes, m = _scopes(project, golden, fleet=False)
    defaults = {kind: (lf.key, entries_of(lf.values)) for kind, lf in m.defaults.items()}
    if keep is not None:
        keep.put_golden(keep.deps(m), list(scopes), [key for key, _ in defaults.values()])
    return _Golden(project, project.settings(Path(golden)).registry, options, scopes, defaults, keep)


def _why(machine: Machine, key: str) -> str:
    """Why a machine has no list where the start-up key ``key`` names one on the golden machine."""
    named = next((n for n in machine.named if n.key == key), None)
    if named is None:
        return f"its start-up list names no {key}"
    if named.status in ("loaded", "overridden"):
        return f"{key} ({named.raw}) is read, but configures something else"
    if named.status == "beyond-count":
        return f"{key} ({named.raw}) lies beyond the count its start-up list sets"
    return f"{key} ({named.raw}) {named.reason or named.status}"


def _value_text(spec: ParamSpec | None) -> str:
    return f"the default {default_name(spec)}" if spec is not None and default_effective(spec) is not None \
        else "not set"


def compare_machine(golden: _Golden, startup: str) -> _MachineDrift:
    """One machine against the golden machine: its differing parameters and lists."""
    out = _MachineDrift(startup)
    try:
        scopes, m = _scopes(golden.project, startup, fleet=True)
    except ZeroError as exc:
        out.error = str(exc)
        return out
    if golden.keep is not None:
        out.deps = golden.keep.deps(m)
    registry = golden.registry
    missing_defaults: dict[str, Rows] = {}
    for kind, (key, entries) in golden.defaults.items():
        if kind not in m.defaults:
            out.lists.append((key, MISSING, _why(m, key)))
            missing_defaults[kind] = entries
    for kind, lf in m.defaults.items():
        if kind not in golden.defaults:
            out.lists.append((lf.key, EXTRA, f"{lf.key} ({lf.path.name}) is read only on this machine"))
    unpaired = {s.key: s for name, s in scopes.items() if name not in golden.scopes}
    paired: set[str] = set()
    for name, g in golden.scopes.items():
        s = scopes.get(name)
        if s is None:
            s = unpaired.get(g.key)  # the same list, configuring another axis: paired by its start-up key
        if s is None:
            out.lists.append((name, MISSING, _why(m, g.key)))
            continue
        paired.add(s.name)
        side = s.side
        if not s.based and s.kind in missing_defaults:  # compared as if the golden's default list lay under it
            side = Side(side.path, side.kind, s.own.over(missing_defaults[s.kind]))
        for c in diff_sides(g.side, side, registry, golden.options):
            if c.kind not in (ADDED, CHANGED, REMOVED):
                continue  # equal values written differently, comments: no drift
            spec = spec_for(c.key, side.kind or g.side.kind, registry)
            entry = side.entries.get(c.key)
            same: Hashable = value_of(entry, spec) if entry is not None else ("not set",)
            golden_note = _value_text(spec) if c.kind == ADDED else ""
            note = _value_text(spec) if c.kind == REMOVED else ""
            out.found.append(_Found(name, c.key, c.param_id, c.group, c.old, golden_note, c.old_name, c.unit,
                                    c.new, note, c.new_name, c.delta, same))
    for name, s in scopes.items():
        if name not in golden.scopes and name not in paired:
            out.lists.append((name, EXTRA, f"{s.key} ({Path(s.side.path).name}) is read only on this machine"))
    return out


# ----------------------------------------------------------------------------- the fleet

_worker_state: _Golden | None = None


def _in_worker(startup: str) -> _MachineDrift:
    assert _worker_state is not None
    return compare_machine(_worker_state, startup)


def _compare_all(golden: _Golden, machines: list[str], jobs: int | None,
                 progress: Callable[[int, int], None] | None) -> list[_MachineDrift]:
    global _worker_state
    cores = os.cpu_count() or 1
    jobs = cores if jobs is None or jobs <= 0 else jobs
    jobs = min(jobs, cores * 4, max(1, len(machines) // 4))
    out: list[_MachineDrift] = []
    if jobs <= 1 or len(machines) < PARALLEL_MIN_MACHINES:
        for n, s in enumerate(machines, 1):
            out.append(compare_machine(golden, s))
            if progress is not None:
                progress(n, len(machines))
        return out
    import multiprocessing as mp  # start-up: only for a fleet of many machines

    try:
        ctx = mp.get_context("fork")
    except ValueError:  # pragma: no cover - platforms without fork compare in one process
        return [compare_machine(golden, s) for s in machines]
    _worker_state = golden
    gc.freeze()  # the workers share the parent's objects: a collection in a worker would copy every page
    try:
        with ctx.Pool(jobs) as pool:
            chunk = max(1, min(16, len(machines) // (jobs * 8)))
            for n, r in enumerate(pool.imap(_in_worker, machines, chunksize=chunk), 1):
                out.append(r)
                if progress is not None:
                    progress(n, len(machines))
    finally:
        _worker_state = None
        gc.unfreeze()
    return out


def fleet_drift(golden: str | Path, machines: Sequence[str | Path], project: Project, *, jobs: int | None = None,
                progress: Callable[[int, int], None] | None = None, cache: bool = False) -> FleetDrift:
    """Every effective parameter (and list) that differs from the ``golden`` machine (its start-up
    list) on any of ``machines`` (start-up lists or folders of machines), compared in ``jobs``
    processes (default: all cores). Raises :class:`ZeroError` where the golden machine cannot be read
    or a folder holds no machine; a machine that cannot be read is :attr:`FleetDrift.unreadable`.

    ``cache``: keep each machine's comparison between runs (:mod:`zero.engine.cache`), and take it
    from there while neither the golden machine's files nor the machine's changed: a fleet compared
    again reads no list of an unchanged machine (nor of the golden machine when none changed)."""
    options = DiffOptions()
    keep = None
    if cache:
        from zero.engine.cache import open_fleet_cache  # start-up: only when the cache is on

        keep = open_fleet_cache(project, str(golden), options)
    order = keep.golden_order() if keep is not None else None
    g = _golden(project, str(golden), options, keep) if order is None else None
    startups = machine_startups(machines, golden)
    if not startups:
        raise ZeroError("no machine to compare with the golden machine (give start-up lists or folders)")
    kept: dict[str, _MachineDrift] = {}
    if keep is not None:
        for s in startups:
            packed = keep.machine(s)
            if packed is not None:
                with contextlib.suppress(TypeError, ValueError):
                    kept[s] = _unpack(s, packed)
    todo = [s for s in startups if s not in kept]
    if todo and g is None:
        g = _golden(project, str(golden), options, keep)
    made = _compare_all(g, todo, jobs, progress) if g is not None and todo else []
    if keep is not None:
        for r in made:
            if r.error is None:
                keep.put_machine(r.machine, _pack(r), r.deps)
    by_machine = {**kept, **{r.machine: r for r in made}}
    if g is not None:
        scopes, defaults = list(g.scopes), [key for key, _ in g.defaults.values()]
    else:
        assert order is not None
        scopes, defaults = order
    return _gather(str(golden), scopes, defaults, startups, [by_machine[s] for s in startups])


def _pack(r: _MachineDrift) -> tuple[Any, ...]:
    """A machine's comparison as plain tuples (what the cache keeps)."""
    found = tuple((f.scope, f.key, f.param_id, f.group, f.golden, f.golden_note, f.golden_name, f.unit, f.value,
                   f.note, f.name, f.delta, f.same) for f in r.found)
    return (found, tuple(r.lists))


def _unpack(machine: str, packed: tuple[Any, ...]) -> _MachineDrift:
    found, lists = packed
    return _MachineDrift(machine, [_Found(*f) for f in found], [tuple(x) for x in lists])


def _gather(golden: str, scopes: list[str], defaults: list[str], startups: list[str],
            results: list[_MachineDrift]) -> FleetDrift:
    drift = FleetDrift(golden, startups)
    params: dict[tuple[str, str], tuple[ParamDrift, dict[Hashable, FleetValue]]] = {}
    lists: dict[tuple[str, str, str], ListDrift] = {}
    for r in results:
        if r.error is not None:
            drift.unreadable.append(Unreadable(r.machine, r.error))
            continue
        for f in r.found:
            hit = params.get((f.scope, f.key))
            if hit is None:
                p = ParamDrift(f.scope, f.key, f.param_id, f.group, f.golden, f.golden_note, f.golden_name, f.unit)
                hit = params[(f.scope, f.key)] = (p, {})
            p, values = hit
            v = values.get(f.same)
            if v is None:
                v = values[f.same] = FleetValue(f.value, f.note, f.name, f.delta)
                p.values.append(v)
            v.machines.append(r.machine)
        for scope, status, reason in r.lists:
            ld = lists.get((scope, status, reason))
            if ld is None:
                ld = lists[(scope, status, reason)] = ListDrift(scope, status, reason)
            ld.machines.append(r.machine)
    rank = {name: n for n, name in enumerate(scopes)}
    order = {m: n for n, m in enumerate(startups)}
    for p, _ in params.values():
        p.values.sort(key=lambda v: (-v.count, order[v.machines[0]]))
    drift.params = sorted((p for p, _ in params.values()),
                          key=lambda p: (rank.get(p.scope, len(rank)), group_order(p.group), key_order(p.key)))
    drift.lists = sorted(lists.values(), key=lambda ld: (
        0 if ld.scope in defaults else 1, rank.get(ld.scope, len(rank)), ld.scope, ld.status,
        order[ld.machines[0]], ld.reason))
    return drift


# ----------------------------------------------------------------------------- the command


class FleetRequest(Record):
    """What ``zero diff --fleet`` was asked (option names as on the command line)."""

    golden: str
    machines: Sequence[str] = ()
    jobs: int | None = None
    param_desc: str | Path | None = None
    config: str | Path | Sequence[str] | None = None
    isolated: bool = False
    cache: bool = False  # keep each machine's comparison between runs (the command line's default, --no-cache)


def run_fleet(request: FleetRequest, registries: Registries,
              progress: Callable[[int, int], None] | None = None) -> FleetDrift:
    """``zero diff --fleet GOLDEN MACHINE...``: the fleet's drift from the golden machine."""
    if not request.machines:
        raise ZeroError("--fleet compares machines with the golden machine: give their start-up lists or a folder "
                        "of machines after it")
    project = open_project(registries, common_of(request.config, request.isolated, request.param_desc))
    return fleet_drift(request.golden, request.machines, project, jobs=request.jobs,
                       progress=progress, cache=request.cache)


__all__ = ["EXTRA", "MISSING", "STARTUP_NAMES", "FleetDrift", "FleetRequest", "FleetValue", "ListDrift",
           "ParamDrift", "Unreadable", "find_startups", "fleet_drift", "machine_startups", "run_fleet"]

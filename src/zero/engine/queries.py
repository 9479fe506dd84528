"""The commands that ask about lists and machines, as library functions: ``zero diff``,
``zero show``, ``zero limits``, ``zero show --machine`` and ``zero explain``.

Kept apart from :mod:`zero.engine.commands` (``lint``, ``format``), so that the pre-commit
path does not load what only these commands need.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path

from zero.catalog.registry import ParamSpec, Registry
from zero.catalog.values import bind
from zero.diff import Change, DiffOptions, Side, diff_defaults, diff_sides, read_side
from zero.engine.convert import source_format
from zero.engine.project import Project, configurations_only
from zero.errors import ZeroError
from zero.files import read_file
from zero.forms import split_part
from zero.lists.model import parse_key
from zero.machine.effective import Scope, effective, entries_of, summary
from zero.machine.limits import Ip247Violation, LimitRow, ip247, pcs_limits
from zero.machine.model import Machine
from zero.records import Record, field


def load_side(name: str, fmt: str | None, kind: str | None, registry: Registry,
              read_stdin: Callable[[], bytes], project: Project | None = None) -> Side:
    """One side of ``zero diff`` (or ``zero show``): a file in any format, or standard input. A list
    is read in the code page its configuration declares (``project``'s; by default the one found
    from the file's folder)."""
    src = source_format(fmt, name)
    data = read_stdin() if name == "-" else read_file(_file_of(name))
    encoding = None
    if name != "-" and src in ("lis", "xml"):
        encoding = (project or configurations_only()).settings(Path(name)).encoding
    return read_side(data, src, name, registry, kind, encoding)


def _file_of(name: str) -> str:
    """The file a name reads: ``X.tsproj#Kanal_1/SdaMds`` and ``channel_1.xml#SdaMds`` name a list inside
    a TwinCAT project or export (a file that is named so on disk is that file)."""
    file, part = split_part(name)
    return file if part is not None and not os.path.exists(name) else name


class DiffRun(Record):
    changes: list[Change]
    header: str


def _named(name: str) -> Path | None:
    return None if name == "-" else Path(name)


def run_diff(a: str, b: str | None, project: Project, read_stdin: Callable[[], bytes], *,
             defaults: bool = False, options: DiffOptions | None = None, fmt: str | None = None,
             kind: str | None = None, machine: bool = False, revert: str | None = None) -> DiffRun:
    """``zero diff A B``, ``zero diff --defaults A`` or ``zero diff --machine A B`` (two start-up lists).
    Both sides are read with the catalogue of A's configuration."""
    options = options or DiffOptions()
    registry = project.settings(_named(a)).registry
    if defaults:
        if b is not None:
            raise ZeroError("--defaults compares one file with the registry; give one file")
        side = load_side(a, fmt, kind, registry, read_stdin, project)
        changes = diff_defaults(side, registry, options)
        return DiffRun(changes, f"{a}: {len(changes)} parameters differ from the registry defaults")
    if b is None:
        raise ZeroError("give two files to compare (or one with --defaults)")
    if a == "-" and b == "-":
        raise ZeroError("only one side can be standard input")
    if machine:
        return _diff_machines(a, b, project, registry, options)
    side_a = load_side(a, fmt, kind, registry, read_stdin, project)
    side_b = load_side(b, fmt, kind or side_a.kind, registry, read_stdin, project)
    header = f"--- {a}\n+++ {b}"
    if revert is not None and not (side_b.update and not side_a.update):
        raise ZeroError("--revert checks an update and its revert file against a list: give the list as A and "
                        "the update file as B (an update file lies in an `Update` folder or is named `*-Update.xml`)")
    if side_b.update and not side_a.update:  # `zero diff LIST UPDATE`: what the update will change
        side_b = side_b.applied_to(side_a)
        header = f"--- {a}\n+++ {a} with {b} applied"
        if revert is not None:  # what the update changes and the revert does not put back
            side_r = load_side(revert, fmt, kind or side_a.kind, registry, read_stdin, project)
            side_b = side_r.applied_to(side_b)
            header = f"--- {a}\n+++ {a} with {b}, then {revert} applied"
    under = _default_list_side(_named(b) or _named(a), side_b.kind or side_a.kind, project)
    return DiffRun(diff_sides(side_a, side_b, registry, options, under), header)


def _default_list_side(path: Path | None, kind: str | None, project: Project) -> Side | None:
    """The default list that lies under lists of ``kind`` on the machine ``path`` belongs to
    (``[tool.zero.machine]``), if there is one."""
    if kind is None:
        return None
    try:
        machine = project.machine(path)
    except ZeroError:
        return None  # a machine that cannot be read: the catalogue's defaults, as without one
    lf = machine.defaults.get(kind) if machine is not None else None
    return Side(str(lf.path), kind, entries_of(lf.values)) if lf is not None else None


def _diff_machines(a: str, b: str, project: Project, registry: Registry, options: DiffOptions) -> DiffRun:
    """Two machines' effective configurations, each machine with the list overrides of its own
    configuration: :func:`machine_changes`."""
    def machine(startup: str) -> Machine:
        m = project.machine(Path(startup), startup=startup, required=True)
        assert m is not None
        return m

    return DiffRun(machine_changes(machine(a), machine(b), registry, options), f"--- {a} (machine)\n+++ {b} (machine)")


def machine_changes(old: Machine, new: Machine, registry: Registry, options: DiffOptions | None = None) -> list[Change]:
    """Two machines' effective configurations, list by list, as ``zero diff --machine OLD NEW`` gives
    them (a value a default list supplies counts as the machine's value; a removed one falls back
    to the catalogue default)."""
    def sides(m: Machine) -> dict[str, Side]:
        return {name: Side(str(lf.path), lf.values.kind, entries_of(lf.values)) for name, lf in m.scopes()}

    left, right = sides(old), sides(new)
    changes: list[Change] = []
    for name in [*left, *(n for n in right if n not in left)]:
        empty = Side("-", (left.get(name) or right[name]).kind, {})
        for c in diff_sides(left.get(name, empty), right.get(name, empty), registry, options or DiffOptions()):
            c.group = f"{name}: {c.group}"
            changes.append(c)
    return changes


# ---------------------------------------------------------------------------- param


class ParamLookup(Record):
    """What ``zero param NAME`` found: one parameter (with the indices the name gave), or the
    parameters whose key, ID or description contain the word."""

    spec: ParamSpec | None = None
    indices: tuple[int, ...] = ()
    matches: list[ParamSpec] = field(default_factory=list)
    searched: bool = False  # the one parameter a search found (not named by ID or key)


def find_param(registry: Registry, name: str, kind: str | None = None) -> ParamLookup:
    """A parameter by ID (``P-AXIS-00178``), key or alias (``kenngr.swe_pos``, ``np_grp[1]...``),
    else by a word of its key or description; :class:`ZeroError` when nothing matches."""
    text = name.strip()
    spec = registry.get(text.upper()) if text.upper().startswith("P-") else None
    if spec is not None:
        return ParamLookup(spec)
    key = parse_key(text)
    if key is not None:
        hit = bind(registry, key.pattern, kind)  # as every reader of values binds it: another release's spelling too
        if hit is not None:
            return ParamLookup(hit[0], key.indices)
    found = registry.search(name)
    if len(found) == 1:
        return ParamLookup(found[0], searched=True)
    if found:
        return ParamLookup(matches=list(found))
    near = registry.suggest(text, None)
    hint = f" (did you mean {near[0]}?)" if near else ""
    raise ZeroError(f"unknown parameter {name!r}{hint}; no key, ID or description contains it")


# ---------------------------------------------------------------------------- limits


class LimitsRun(Record):
    rows: list[LimitRow]
    violations: list[Ip247Violation] = field(default_factory=list)


PROFILES = ("ip247",)


def machine_of(project: Project) -> Machine:
    """The machine a command about a machine is asked about: ``--machine``, else the
    configuration's ``[tool.zero.machine]`` (of the current directory)."""
    m = project.machine(required=True)
    assert m is not None
    return m


def run_limits(project: Project, all_groups: bool = False, profile: str | None = None) -> LimitsRun:
    """``zero limits``: PCS soft limits of the machine (the configuration's when not named)."""
    if profile not in (None, *PROFILES):
        raise ZeroError(f"unknown profile {profile!r} (known: {', '.join(PROFILES)})")
    m = machine_of(project)
    if not m.axes():
        read = sum(1 for n in m.named if n.status in ("loaded", "overridden"))
        raise ZeroError(f"no axis list of the machine could be read ({read} of {len(m.named)} named lists read, "
                        f"working directory {m.workdir}): no soft limits to compute; `zero lint --machine` says why",
                        str(m.startup.path))
    return LimitsRun(pcs_limits(m, all_groups), ip247(m) if profile == "ip247" else [])


class EffectiveRun(Record):
    summary: dict[str, object]
    scopes: list[Scope]

    def to_json(self) -> dict[str, object]:
        return {**self.summary, "scopes": [s.to_json() for s in self.scopes]}


def run_effective(project: Project, keys: Sequence[str] = (), with_defaults: bool = False,
                  explain: bool = False) -> EffectiveRun:
    """``zero show --machine`` / ``zero explain``: effective values and where they come from."""
    m = machine_of(project)
    scopes = effective(m, keys, with_defaults, explain)
    if keys and not scopes:
        raise ZeroError(f"no list of the machine has or documents {', '.join(keys)}")
    return EffectiveRun(summary(m), scopes)


def program_travel_of(path: Path, machine: Machine,
                      registry: Registry) -> tuple[str, int, dict[int, tuple[float, float]]]:
    """Where an NC program takes each axis of the machine's first channel (``zero report --program``):
    its name, the line of its first move past a soft limit (-1: none) and each axis's lowest and
    highest position."""
    from zero.nc.program import read_program  # start-up: only a report with --program
    from zero.rules.program import program_travel  # start-up: as above

    found = program_travel(read_program(read_file(path), str(path), registry), registry, machine, str(path))
    return (path.name, *found) if found is not None else (path.name, -1, {})

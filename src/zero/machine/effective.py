"""Effective values with their origin: what the controller uses, and where it comes from.

For every list the machine loads, an element of a parameter (its ID and indices: `[01]` and
`[1]` are one element, an alias is the key it stands for) takes its value from the list itself,
else from the default list under it (``default_achs_mds`` under each axis list,
``default_sda_mds`` under each channel list), else from the catalogue's default. This is
``zero show --machine`` (one line per parameter, like ``git config --show-origin``) and
``zero explain KEY --machine`` (every layer for one key).
"""

from __future__ import annotations

import fnmatch
from collections.abc import Sequence

from zero.catalog.registry import NO_DEFAULT, ParamSpec
from zero.catalog.rows import Rows, own_entries
from zero.catalog.values import ListValues, Slot, bind, canonical_key, slot_of
from zero.lists.model import Entry, format_key, parse_key
from zero.machine.model import ListFile, Machine
from zero.records import Record, field, replace

LIST, DEFAULT_LIST, CATALOGUE, NOT_SET = "list", "default list", "catalogue default", "not set"


class Origin(Record, frozen=True):
    """Where a value comes from: a line of a list, or the catalogue."""

    source: str  # list, default list, catalogue default, not set
    path: str | None = None
    line: int | None = None

    def __str__(self) -> str:
        if self.path is not None:
            where = f"{self.path}:{self.line}"
            return where if self.source == LIST else f"{where} ({self.source})"
        return f"({self.source})"

    def to_json(self) -> dict[str, object]:
        return {"source": self.source, "path": self.path, "line": self.line}


class Value(Record, frozen=True):
    key: str
    param_id: str | None
    value: str | None  # as written in the list, or the catalogue's default
    origin: Origin
    layers: tuple[tuple[str | None, Origin], ...] = ()  # every layer that has a value (explain)

    def to_json(self) -> dict[str, object]:
        out: dict[str, object] = {"key": self.key, "id": self.param_id, "value": self.value,
                                  "origin": self.origin.to_json()}
        if self.layers:
            out["layers"] = [{"value": v, **o.to_json()} for v, o in self.layers]
        return out


class Scope(Record):
    """One list of the machine and its effective values."""

    name: str  # axis 1 (achs_mds[0])
    file: ListFile
    values: list[Value] = field(default_factory=list)

    @property
    def default_list(self) -> str | None:
        base = self.file.values.base
        return base.doc.path if base is not None else None

    def to_json(self) -> dict[str, object]:
        return {"scope": self.name, "path": str(self.file.path), "default_list": self.default_list,
                "values": [v.to_json() for v in self.values]}


def canonical(values: ListValues, entry: Entry) -> str:
    """The documented key an entry sets (an alias as the key it stands for, `[01]` as `[1]`)."""
    return canonical_key(values.registry, values.kind, entry)


class Setting(Record, frozen=True):
    """The entry that gives one element its value, in the list or a default list under it."""

    key: str  # the documented key, indices as numbers
    spec: ParamSpec | None
    entry: Entry
    origin: Origin


def settings(values: ListValues) -> dict[Slot, Setting]:
    """Element (parameter ID and indices) → the entry the controller uses: the default list's,
    then this list's over it (the later entry wins within a list)."""
    out: dict[Slot, Setting] = {}
    if values.base is not None:
        for slot, s in settings(values.base).items():
            out[slot] = replace(s, origin=Origin(DEFAULT_LIST, s.origin.path, s.origin.line))
    for e in values.doc.entries:
        slot, spec = slot_of(values.registry, values.kind, e)
        out[slot] = Setting(canonical_key(values.registry, values.kind, e), spec, e,
                            Origin(LIST, values.doc.path, values.doc.file_line(e.line)))
    return out


def _catalogue(spec: ParamSpec | None) -> str | None:
    if spec is None or (spec.default or "").strip() in NO_DEFAULT:
        return None
    return spec.default_display


def _bound(values: ListValues, w: str) -> tuple[str, tuple[int, ...] | None] | None:
    """The parameter ID a key as asked names (any spelling the binding knows: an alias, another
    release's), and its indices where it gives some."""
    given = parse_key(w)
    hit = bind(values.registry, given.pattern, values.kind) if given is not None else None
    if hit is None or given is None:
        return None
    return hit[0].id, given.indices or None


def _matches(key: str, spec: ParamSpec | None, wanted: Sequence[str], values: ListValues | None = None) -> bool:
    if not wanted:
        return True
    parsed = parse_key(key)
    pattern = parsed.pattern if parsed is not None else key
    for w in wanted:
        bound = _bound(values, w) if values is not None and spec is not None else None
        if bound is not None and spec is not None and bound[0] == spec.id and \
                (bound[1] is None or (parsed is not None and bound[1] == parsed.indices)):
            return True  # the key as any spelling binds it: `antr_simu.zeitkonstante_z` is P-AXIS-00239
        given = parse_key(w)
        # a key as written first: `[1]` is an index, not fnmatch's character class; `[01]` is `[1]`
        if w in (key, pattern) or (given is not None and parsed is not None and given.indices
                                   and (given.pattern, given.indices) == (parsed.pattern, parsed.indices)):
            return True
        if fnmatch.fnmatchcase(key, w) or (spec is not None and w.upper() == spec.id):
            return True
    return False


def _layers(values: ListValues, slot: Slot, spec: ParamSpec | None) -> tuple[tuple[str | None, Origin], ...]:
    out: list[tuple[str | None, Origin]] = []
    layer: ListValues | None = values
    source = LIST
    while layer is not None:
        hit = next((e for e in reversed(layer.doc.entries)
                    if slot_of(layer.registry, layer.kind, e)[0] == slot), None)
        out.append((hit.value, Origin(source, layer.doc.path, layer.doc.file_line(hit.line))) if hit is not None
                   else (None, Origin(NOT_SET, layer.doc.path)))
        layer, source = layer.base, DEFAULT_LIST
    out.append((_catalogue(spec), Origin(CATALOGUE)))
    return tuple(out)


def scope_values(name: str, lf: ListFile, keys: Sequence[str] = (), with_defaults: bool = False,
                 explain: bool = False) -> Scope:
    """The effective values of one list: every element it or its default list sets (matching ``keys``,
    IDs or key patterns); with ``with_defaults`` also the catalogue defaults of what neither sets;
    with ``explain`` every layer of each value."""
    scope = Scope(name, lf)
    values = lf.values
    seen: set[Slot] = set()
    for slot, s in sorted(settings(values).items(), key=lambda item: item[1].key):
        if not _matches(s.key, s.spec, keys, values):
            continue
        seen.add(slot)
        scope.values.append(Value(s.key, s.spec.id if s.spec else None, s.entry.value, s.origin,
                                  _layers(values, slot, s.spec) if explain else ()))
    if with_defaults or keys:
        registry = values.registry
        for spec in (registry.get(pid) for pid in registry.specs):
            if spec is None or spec.kind != values.kind or not spec.key:
                continue
            key = spec.key
            wanted = next((given for w in keys if (given := parse_key(w)) is not None
                           and (given.pattern == key or (_bound(values, w) or ("",))[0] == spec.id)), None)
            indices = wanted.indices if wanted is not None and wanted.indices else (0,) * key.count("[]")
            shown = format_key(key, indices)
            slot = (spec.id, indices)
            if slot in seen or (keys and not _matches(shown, spec, keys, values)) or (not keys and not with_defaults):
                continue
            if not keys and spec.dims:
                continue  # arrays: only the elements a list sets are shown
            scope.values.append(Value(shown, spec.id, _catalogue(spec), Origin(CATALOGUE),
                                      _layers(values, slot, spec) if explain else ()))
    return scope


def effective(machine: Machine, keys: Sequence[str] = (), with_defaults: bool = False,
              explain: bool = False) -> list[Scope]:
    """The effective values of every list of the machine (see :func:`scope_values`)."""
    scopes = [scope_values(name, lf, keys, with_defaults, explain) for name, lf in machine.scopes()]
    return [s for s in scopes if s.values or not keys]


def summary(machine: Machine) -> dict[str, object]:
    """The start-up list, the working directory and what became of every list it names; for a machine
    read from TwinCAT (a project or exports), what TwinCAT says of each list's item (``twincat``)."""
    out: dict[str, object] = {
        "startup": str(machine.startup.path),
        "working_directory": str(machine.workdir),
        "lists": [{"key": n.key, "path": n.raw, "resolved": str(n.path) if n.path else None,
                   "status": n.status, "reason": n.reason or None,
                   "line": machine.startup.values.doc.file_line(n.line)} for n in machine.named],
    }
    if any(n.path is not None and "#" in str(n.path) for n in machine.named):
        from zero.machine.tsproj import twincat_items  # start-up: only for a machine read from TwinCAT

        items = twincat_items(machine)
        if items:
            out["twincat"] = items
    return out


def entries_of(values: ListValues, found: dict[int, Rows] | None = None) -> Rows:
    """Documented key → the entry the controller uses: this list's over the default list's (the
    layering of :func:`settings`, by key, without the origins). ``found``: the default lists already
    layered (a fleet's machines share them), by identity."""
    if found is not None:
        hit = found.get(id(values))
        if hit is not None:
            return hit
    own = own_entries(values)
    out = own.over(entries_of(values.base, found)) if values.base is not None else own
    if found is not None:
        found[id(values)] = out
    return out

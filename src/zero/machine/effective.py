"""Effective values with their origin: what the controller uses, and where it comes from.

For every list the machine loads, a parameter's value comes from the list itself, else
from the default list under it (``default_achs_mds`` under each axis list,
``default_sda_mds`` under each channel list), else from the catalogue's default. This is
``zero show --machine`` (one line per parameter, like ``git config --show-origin``) and
``zero explain KEY --machine`` (every layer for one key).
"""

from __future__ import annotations

import fnmatch
from collections.abc import Sequence

from zero.catalog.registry import NO_DEFAULT, ParamSpec
from zero.catalog.values import ListValues
from zero.lists.model import Entry, format_key, parse_key
from zero.machine.model import ListFile, Machine
from zero.records import field, record

LIST, DEFAULT_LIST, CATALOGUE, NOT_SET = "list", "default list", "catalogue default", "not set"


@record(frozen=True)
class Origin:
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


@record(frozen=True)
class Value:
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


@record
class Scope:
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
    """The documented key an entry sets: an alias (`kenngr.homing_type`) counts as the key it
    stands for (`kenngr.homing.homing_type`), with the entry's indices."""
    if entry.key is None or values.registry.by_pattern(entry.key.pattern, values.kind) is not None:
        return entry.key_text
    spec = values.registry.alias(entry.key.pattern, values.kind)
    return format_key(spec.key, entry.key.indices) if spec is not None and spec.key else entry.key_text


def _entries(values: ListValues) -> dict[str, tuple[Entry, Origin]]:
    """Documented key → (entry that wins, its origin): the default list first, the list over it."""
    out: dict[str, tuple[Entry, Origin]] = {}
    if values.base is not None:
        out.update({k: (e, Origin(DEFAULT_LIST, o.path, o.line)) for k, (e, o) in _entries(values.base).items()})
    for e in values.doc.entries:
        out[canonical(values, e)] = (e, Origin(LIST, values.doc.path, e.line))
    return out


def _spec(values: ListValues, key: str) -> ParamSpec | None:
    parsed = parse_key(key)
    if parsed is None:
        return None
    return values.registry.by_pattern(parsed.pattern, values.kind) or values.registry.alias(parsed.pattern,
                                                                                             values.kind)


def _catalogue(spec: ParamSpec | None) -> str | None:
    if spec is None or (spec.default or "").strip() in NO_DEFAULT:
        return None
    return spec.default_display


def _matches(key: str, spec: ParamSpec | None, wanted: Sequence[str]) -> bool:
    if not wanted:
        return True
    pattern = parse_key(key).pattern if parse_key(key) is not None else key  # type: ignore[union-attr]
    # a key as written first: `[1]` is an index, not fnmatch's character class
    return any(w in (key, pattern) or fnmatch.fnmatchcase(key, w) or (spec is not None and w.upper() == spec.id)
               for w in wanted)


def _layers(values: ListValues, key: str, spec: ParamSpec | None) -> tuple[tuple[str | None, Origin], ...]:
    out: list[tuple[str | None, Origin]] = []
    layer: ListValues | None = values
    source = LIST
    while layer is not None:
        hit = next((e for e in reversed(layer.doc.entries) if canonical(layer, e) == key), None)
        out.append((hit.value, Origin(source, layer.doc.path, hit.line)) if hit is not None
                   else (None, Origin(NOT_SET, layer.doc.path)))
        layer, source = layer.base, DEFAULT_LIST
    out.append((_catalogue(spec), Origin(CATALOGUE)))
    return tuple(out)


def scope_values(name: str, lf: ListFile, keys: Sequence[str] = (), with_defaults: bool = False,
                 explain: bool = False) -> Scope:
    """The effective values of one list: every key it or its default list sets (matching ``keys``,
    IDs or key patterns); with ``with_defaults`` also the catalogue defaults of what neither sets;
    with ``explain`` every layer of each value."""
    scope = Scope(name, lf)
    values = lf.values
    seen: set[str] = set()
    for key, (entry, origin) in sorted(_entries(values).items()):
        spec = _spec(values, key)
        if not _matches(key, spec, keys):
            continue
        seen.add(key)
        scope.values.append(Value(key, spec.id if spec else None, entry.value, origin,
                                  _layers(values, key, spec) if explain else ()))
    if with_defaults or keys:
        registry = values.registry
        for spec in (registry.get(pid) for pid in registry.specs):
            if spec is None or spec.kind != values.kind or not spec.key:
                continue
            key = spec.key
            shown = key.replace("[]", "[0]") if not keys else next(
                (w for w in keys if parse_key(w) is not None and parse_key(w).pattern == key), key)  # type: ignore[union-attr]
            if shown in seen or (keys and not _matches(shown, spec, keys)) or (not keys and not with_defaults):
                continue
            if not keys and spec.dims:
                continue  # arrays: only the elements a list sets are shown
            scope.values.append(Value(shown, spec.id, _catalogue(spec), Origin(CATALOGUE),
                                      _layers(values, shown, spec) if explain else ()))
    return scope


def effective(machine: Machine, keys: Sequence[str] = (), with_defaults: bool = False,
              explain: bool = False) -> list[Scope]:
    """The effective values of every list of the machine (see :func:`scope_values`)."""
    scopes = [scope_values(name, lf, keys, with_defaults, explain) for name, lf in machine.scopes()]
    return [s for s in scopes if s.values or not keys]


def summary(machine: Machine) -> dict[str, object]:
    """The start-up list, the working directory and what became of every list it names."""
    return {
        "startup": str(machine.startup.path),
        "working_directory": str(machine.workdir),
        "lists": [{"key": n.key, "path": n.raw, "resolved": str(n.path) if n.path else None,
                   "status": n.status, "reason": n.reason or None, "line": n.line} for n in machine.named],
    }


def entries_of(values: ListValues) -> dict[str, Entry]:
    """Key → the entry the controller uses (this list's, else the default list's)."""
    return {key: entry for key, (entry, _) in _entries(values).items()}

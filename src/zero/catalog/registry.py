"""The parameter registry: one table of facts keyed by parameter ID.

The table is data (``data/table.py``, generated from the vendor's ``CncParaDesc.xml`` by
``tools/gen_registry.py``) plus ``data/seeds.toml`` (the parameters the manuals define, with
descriptions in our words; ``tools/gen_seeds.py`` compiles it to ``data/seeds.py``). Both are
Python modules so that they load from bytecode, not parsed at every start-up. Rules read a
:class:`ParamSpec` generically; adding a parameter never means adding code.

A :class:`Registry` is data that callers pass in: :func:`load_registry` builds one
(the built-in table, or a user's ``CncParaDesc.xml``); nothing below the command
line keeps a process-wide registry.
"""

from __future__ import annotations

import importlib
import marshal
from collections import Counter
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from operator import itemgetter

from zero import preload
from zero.catalog.ranges import Range, decode_range, encoded_refers, parse_range
from zero.forms import kind_hint
from zero.records import Record, field, fields

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from pathlib import Path
    from typing import Any

    from zero.lists.model import Document, Entry

NO_DEFAULT = ("", "-", "--", "----")  # how the catalogue writes "no default documented"
BUILTIN_SOURCE = "built-in (CncParaDesc.xml facts + seeds)"

# List kinds: the four letters of the ID, a short name and a file-name hint.
KINDS: dict[str, tuple[str, str]] = {
    "AXIS": ("axis", "axis parameter list"),
    "CHAN": ("channel", "channel parameter list"),
    "ZERO": ("zero", "zero-offset list"),
    "TOOL": ("tool", "tool list"),
    "COMP": ("compensation", "axis compensation list"),
    "CLMP": ("clamp", "clamping-position offset list"),
    "MANU": ("manual", "manual-mode list"),
    "EXTV": ("extvar", "external variables list"),
    "STUP": ("startup", "start-up list"),
    "RTCF": ("rtconf", "real-time configuration list"),
    "SECO": ("sercos", "SERCOS list"),
    "HWCF": ("hardware", "hardware configuration list"),
    "VOLC": ("volcomp", "volumetric compensation list"),
    "CMLD": ("cmld", "CMLD list"),
}
_NAME_TO_KIND = {name: code for code, (name, _) in KINDS.items()}

INTEGER_TYPES = frozenset(
    {"BOOLEAN", "SGN08", "UNS08", "SGN16", "UNS16", "SGN32", "UNS32", "SGN64", "UNS64",
     "ADDRESS", "CHAR"}
)


def kind_from_name(text: str) -> str | None:
    """``"zero"`` or ``"ZERO"`` → ``"ZERO"``; ``None`` when unknown."""
    t = text.strip()
    if t.upper() in KINDS:
        return t.upper()
    return _NAME_TO_KIND.get(t.lower())


class ParamSpec(Record):
    """Everything zero knows about one parameter."""

    id: str
    kind: str
    key: str | None
    type: str
    default: str | None = None
    range_text: str | None = None
    range_note: str | None = None
    dims: tuple[int, ...] = ()
    symbols: tuple[tuple[str, int | None], ...] = ()
    units: tuple[str, ...] = ()
    quantity: str | None = None
    max_len: int | None = None
    restart: bool = False
    description: str | None = None
    source: str = "CncParaDesc.xml"
    index_base: int = 0
    enum: tuple[int, ...] = ()  # allowed values the catalogue lists in prose
    enum_flags: bool = False  # the listed values are bits: any combination of them is allowed
    bits: bool = False  # its symbols are bits that combine: the catalogue's `<Bitfield>`, or "bit-coded"
    enum_labels: tuple[str, ...] = ()  # their meaning (only from a user's CncParaDesc.xml)

    def index_first(self, pos: int) -> int:
        """The first index of slot ``pos`` (the catalogue counts some arrays from 1)."""
        return self.index_base if pos == 0 else 0

    def valid_indices(self, pos: int) -> str:
        """The indices of slot ``pos`` as said to people: ``0..5``, or ``1..`` where the first slot
        counts from 1 (its end is then not documented)."""
        base = self.index_first(pos)
        size = self.dims[pos] if pos < len(self.dims) else 0
        return f"{base}.." if base else f"0..{size - 1}"

    def index_outside(self, indices: tuple[int, ...]) -> tuple[int, int] | None:
        """The first (slot, index) that lies outside its array (the element does not exist: R003)."""
        for pos, (idx, size) in enumerate(zip(indices, self.dims, strict=False)):
            base = self.index_first(pos)
            if idx < base or (base == 0 and size > 0 and idx >= size):
                return pos, idx
        return None

    def enum_items(self) -> tuple[tuple[int, str], ...]:
        """The listed values with their meaning ("" where the catalogue gives none, or gives a
        different number of meanings than values: then none is trusted)."""
        labels = self.enum_labels if len(self.enum_labels) == len(self.enum) else ("",) * len(self.enum)
        return tuple(zip(self.enum, labels, strict=True))

    def enum_listed(self) -> str:
        """The listed values as said to people: ``0 off, 1 on, 2``."""
        return ", ".join(f"{v} {label}".strip() for v, label in self.enum_items())

    def enum_allows(self, value: int) -> bool:
        if self.enum_flags:
            mask = 0
            for v in self.enum:
                mask |= v
            return value & ~mask == 0
        return value in self.enum

    def bits_allow(self, value: int) -> bool:
        """A value made of the symbols' bits (every set bit covered by a symbol inside the value)."""
        covered = 0
        for _, v in self.symbols:
            if v and v & ~value == 0:
                covered |= v
        return value >= 0 and covered == value

    @property
    def symbol_names(self) -> frozenset[str]:
        return frozenset(s for s, _ in self.symbols)

    def symbol_value(self, name: str) -> int | None:
        for s, v in self.symbols:
            if s == name:
                return v
        return None

    @property
    def is_length(self) -> bool:
        """Lengths/angles in 0.1 µm / 0.0001° (the zero-offset and soft-limit units)."""
        return "0.1um" in self.units

    @property
    def default_display(self) -> str:
        """The default as the controller would write it, e.g. ``0`` for ``FALSE``."""
        d = (self.default or "").strip()
        if d in NO_DEFAULT:
            return "(none documented)"
        v = self.symbol_value(d)
        if v is not None and self.type != "STRING":
            return f"{v} ({d})"
        if "e" in d.lower() and self.type != "STRING":  # `3.000000e+001` is 30
            try:
                return f"{float(d):g}"
            except ValueError:
                return d
        return d


class SortedIndex(Mapping["Any", "Any"]):
    """A read-only mapping over keys sorted at build time (the built-in table's index, ``data/table.py``),
    iterated in key order: its dictionary is made in one call in C at the first look-up (as cheap as bisecting
    for a list's few hundred look-ups, and no ``_bisect``, a shared library to load: issue 40)."""

    __slots__ = ("_by_key", "_keys", "_values")

    def __init__(self, keys: Sequence[Any], values: Sequence[Any]) -> None:
        self._keys, self._values = keys, values
        self._by_key: dict[Any, Any] | None = None

    def _dict(self) -> dict[Any, Any]:
        """Key → value, made at the first look-up."""
        got = self._by_key
        if got is None:
            got = self._by_key = dict(zip(self._keys, self._values, strict=True))
        return got

    def get(self, key: Any, default: Any = None) -> Any:
        try:
            return (self._by_key or self._dict()).get(key, default)
        except TypeError:  # a key that is no dictionary's key (a list): none of them
            return default

    def __getitem__(self, key: Any) -> Any:
        got = self.get(key, _ABSENT)
        if got is _ABSENT:
            raise KeyError(key)
        return got

    def get_each(self, keys: Iterable[Any], default: Any = None) -> list[Any]:
        """``[self.get(k, default) for k in keys]`` in one call (a list's kind detection asks for each pattern)."""
        got = (self._by_key or self._dict()).get
        out = []
        for key in keys:
            try:
                out.append(got(key, default))
            except TypeError:
                out.append(default)
        return out

    def __contains__(self, key: object) -> bool:
        return self.get(key, _ABSENT) is not _ABSENT

    def __iter__(self) -> Iterator[Any]:
        return iter(self._keys)

    def __len__(self) -> int:
        return len(self._keys)


class TableRows(Mapping[str, "tuple[Any, ...] | dict[str, Any]"]):
    """The built-in table's rows by ID (``data/table_axis.py``, ...: a kind's IDs sorted, and its rows), a
    kind's read at its first row asked for; ``seeds``: the seed overlay's facts of a parameter, its row
    (:func:`_seeded`, a dictionary) made at its first look-up, in the table row's place or after them."""

    __slots__ = ("_columns", "_kinds", "_seeded", "_seeds")

    def __init__(self, kinds: Mapping[str, int], columns: tuple[str, ...] = (),
                 seeds: Mapping[str, dict[str, Any]] | None = None) -> None:
        self._kinds = kinds  # the kinds that have rows (a kind's: _kind_table(kind).IDS, PACKED)
        self._columns = columns
        self._seeds = seeds or {}
        self._seeded: dict[str, dict[str, Any]] = {}

    def table_row(self, pid: object) -> tuple[Any, ...] | None:
        """The table's own row of ``pid`` (``None``: none), its kind's module read at the first, the row
        unmarshalled at its first look-up (``PACKED``: written so by tools/gen_registry.py) and kept."""
        if type(pid) is not str or pid[2:6] not in self._kinds:
            return None
        got = _TABLE_ROWS.get(pid)
        if got is None:  # _kind_table and the ID's position, inline (pid a str, as the IDs are)
            kind = pid[2:6]
            table = _KIND_TABLES.get(kind) or _kind_table(kind)
            at = (_ID_POSITIONS.get(kind) or _id_positions(kind)).get(pid)
            if at is None:
                return None
            got = _TABLE_ROWS[pid] = marshal.loads(table.PACKED[at])
        return got

    def get(self, pid: str, default: Any = None) -> Any:
        if pid in self._seeds:
            seeded = self._seeded.get(pid)
            if seeded is None:
                old = self.table_row(pid)
                given = None if old is None else \
                    {c: v for c, v in zip(self._columns, old, strict=True) if v is not None}  # dict(_fields(...))
                seeded = self._seeded[pid] = _seeded(pid, given, self._seeds[pid])
            return seeded
        # table_row, inline (a call per row costs as much as its work)
        if type(pid) is not str or pid[2:6] not in self._kinds:
            return default
        got = _TABLE_ROWS.get(pid)
        if got is None:
            kind = pid[2:6]
            table = _KIND_TABLES.get(kind) or _kind_table(kind)
            at = (_ID_POSITIONS.get(kind) or _id_positions(kind)).get(pid)
            if at is None:
                return default
            got = _TABLE_ROWS[pid] = marshal.loads(table.PACKED[at])
        return got

    def __getitem__(self, pid: str) -> tuple[Any, ...] | dict[str, Any]:
        got = self.get(pid)
        if got is None:
            raise KeyError(pid)
        return got  # type: ignore[no-any-return]

    def __contains__(self, pid: object) -> bool:
        return pid in self._seeds or self.table_row(pid) is not None

    def __iter__(self) -> Iterator[str]:
        for kind in self._kinds:
            yield from _kind_table(kind).IDS
        yield from (pid for pid in self._seeds if self.table_row(pid) is None)

    def __len__(self) -> int:
        return sum(len(_kind_table(k).IDS) for k in self._kinds) + \
            sum(1 for pid in self._seeds if self.table_row(pid) is None)


def _fields(columns: tuple[str, ...], row: tuple[Any, ...]) -> Iterator[tuple[str, Any]]:
    """A table row's given fields (name, value)."""
    return ((c, v) for c, v in zip(columns, row, strict=True) if v is not None)


def _seeded(pid: str, old: dict[str, Any] | None, extra: dict[str, Any]) -> dict[str, Any]:
    """The row of ``pid`` with the seed overlay's facts ``extra`` over its row ``old`` (a copy: the table's
    rows are shared, never changed; ``None``: a parameter the table does not have)."""
    row = dict(old or {"id": pid, "kind": pid[2:6], "type": "STRING"})
    if "description" in extra and row.get("vendor_text"):
        row["vendor_text"] = None
    row.update(extra)
    if "range" in extra:
        row.pop("range_note", None)
    return row


_ABSENT: Any = object()


class KeyIndex(Mapping[tuple[str, str], str]):
    """(kind, key) → ID over the built-in table's keys sorted per kind (``data/table_axis.py``, ...): a kind's
    dictionary made in one call at its first look-up (as :class:`SortedIndex`), none of the other kinds'.
    Iterated in the order of the IDs (the order of the rows, the first row of each key)."""

    __slots__ = ("_dicts", "_keys_of", "_kinds", "_order")

    def __init__(self, kinds: Mapping[str, Any], keys_of: Callable[[str], tuple[Sequence[str], Sequence[str]]]) -> None:
        self._kinds = kinds  # the kinds that have keys
        self._keys_of = keys_of  # a kind's keys sorted, and the ID of each
        self._order: list[tuple[str, str]] | None = None  # every pair in the IDs' order, once iterated
        self._dicts: dict[str, dict[str, str]] = {}  # a kind's keys → their IDs, made at its first look-up

    def get(self, pair: tuple[str, str], default: Any = None) -> Any:
        try:
            kind, key = pair
            table = self._dicts.get(kind)
            if table is None:
                if kind not in self._kinds:
                    return default
                table = self._dicts[kind] = dict(zip(*self._keys_of(kind), strict=True))
            return table.get(key, default)
        except (TypeError, ValueError):  # no (kind, key) pair
            return default

    def __getitem__(self, pair: tuple[str, str]) -> str:
        got = self.get(pair, _ABSENT)
        if got is _ABSENT:
            raise KeyError(pair)
        return str(got)

    def __contains__(self, pair: object) -> bool:
        return self.get(pair, _ABSENT) is not _ABSENT  # type: ignore[arg-type]

    def __iter__(self) -> Iterator[tuple[str, str]]:
        if self._order is None:  # did-you-mean scans every key, once per distinct unknown key
            pairs = [(pid, kind, key) for kind in self._kinds for key, pid in zip(*self._keys_of(kind), strict=True)]
            self._order = [(kind, key) for _, kind, key in sorted(pairs)]
        return iter(self._order)

    def __len__(self) -> int:
        return sum(len(self._keys_of(kind)[0]) for kind in self._kinds)

    def keys_of_kind(self, kind: str) -> Sequence[str]:
        """One kind's keys, sorted (its table's own tuple): did-you-mean in a list of a known kind read every
        kind's table and sorted all their keys by ID (with difflib's import, 44 M instructions of a lint with
        one typo; 9 M now)."""
        return self._keys_of(kind)[0] if kind in self._kinds else ()


class SpecTable(Mapping[str, "ParamSpec"]):
    """ID → :class:`ParamSpec`, each built from its table row on first use.

    A lint of one list touches a few hundred of the 1766 parameters; building only
    those keeps start-up short. Iterating builds them all.
    """

    def __init__(self, rows: Mapping[str, dict[str, Any] | tuple[Any, ...]], index_base: dict[str, int],
                 columns: tuple[str, ...] = (), counts: tuple[tuple[str, str, str], ...] | None = None,
                 seeds: Mapping[str, dict[str, Any]] | None = None) -> None:
        self._rows = rows  # a row: a dictionary, or a tuple of the built-in table (fields in ``columns``' order)
        self._index_base = index_base
        self._columns = columns
        self._built: dict[str, ParamSpec] = {}
        self._counts = counts  # (id, kind, key) of the count parameters (`…_anzahl`), where known already
        # a tuple row (and a None after it) -> its fields in _SPEC_FIELDS' order (None: not given), in C
        self._pick = itemgetter(*(columns.index(f) if f in columns else len(columns) for f in _SPEC_FIELDS))
        # the built-in table's rows with the seed overlay's facts (``seeds``: the overlay's parameters): their specs
        # as tools/gen_specs.py wrote them are read where they were written from these rows and facts
        self._seeds = seeds

    def __getitem__(self, param_id: str) -> ParamSpec:
        spec = self._built.get(param_id)
        if spec is None:
            fields = _written_spec(param_id, self._seeds, self._index_base) if self._seeds is not None else None
            spec = self._built[param_id] = ParamSpec(*fields) if fields is not None else self.build(param_id)
        return spec

    def build(self, param_id: str) -> ParamSpec:
        """The spec of ``param_id`` made of its row (and the seed overlay's facts), never the one written at build
        time (what tools/gen_specs.py writes); :class:`KeyError` where there is no such parameter."""
        row = self._rows.get(param_id)  # TableRows.get: not its __getitem__ over it
        if row is None:
            raise KeyError(param_id)
        if isinstance(row, tuple):
            return _spec_from_fields(self._pick((*row, None)), self._index_base)
        return _spec_from_row(row, self._index_base)

    def get(self, param_id: str, default: Any = None) -> Any:
        """As ``Mapping.get``, without its ``try``/``KeyError`` (a fleet asks 100,000 times)."""
        spec = self._built.get(param_id)
        if spec is not None:
            return spec
        return self[param_id] if param_id in self._rows else default

    def __contains__(self, param_id: object) -> bool:
        return param_id in self._rows

    def __iter__(self) -> Iterator[str]:
        return iter(self._rows)

    def __len__(self) -> int:
        return len(self._rows)

    def keys_by_kind(self) -> Iterator[tuple[str, str, str]]:
        """(id, kind, key) of every parameter that has a key, without building specs."""
        for pid, row in self._rows.items():
            if isinstance(row, tuple):  # the built-in table's (id, kind, key, …)
                if row[2]:
                    yield pid, row[1], row[2]
            elif row.get("key"):
                yield pid, row["kind"], row["key"]

    def count_triples(self) -> Iterable[tuple[str, str, str]]:
        """(id, kind, key) of the parameters whose key ends in ``_anzahl`` (the counts of arrays), in order."""
        if self._counts is not None:
            return self._counts
        return [t for t in self.keys_by_kind() if t[2].endswith("_anzahl")]


class Registry(Record):
    """Lookup by ID and by concrete key, per list kind."""

    specs: Mapping[str, ParamSpec]
    source: str = "built-in"
    # (kind, key) → ID; key → its kinds (the built-in table's: KeyIndex, SortedIndex)
    _by_key: Mapping[tuple[str, str], str] = field(default_factory=dict)
    _kinds_of: Mapping[str, Sequence[str]] = field(default_factory=dict)
    _ranges: dict[str, Range | None] = field(default_factory=dict)
    aliases: dict[tuple[str, str], str] = field(default_factory=dict)
    # (kind, pattern) → (where the vendor's lists use it, the ID it probably stands for or "")
    vendor_keys: dict[tuple[str, str], tuple[str, str]] = field(default_factory=dict)
    _suggestions: dict[tuple[str, str | None, int], list[str]] = field(default_factory=dict)
    _machine_data: frozenset[str] | None = None
    # (kind, pattern) → spec: a big list asks for a few dozen patterns a million times
    _pattern_specs: dict[tuple[str | None, str], ParamSpec | None] = field(default_factory=dict)
    # Caches of the layers above, kept with the registry their entries depend on (values read per
    # (ID, text), values that passed their range): a fleet of lists repeats them from file to file.
    memo: dict[str, dict[Any, Any]] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if isinstance(self._by_key, KeyIndex) or self._by_key:
            return  # given with its index (the built-in table's, written at build time)
        by_key: dict[tuple[str, str], str] = {}
        kinds_of: dict[str, list[str]] = {}
        self._by_key, self._kinds_of = by_key, kinds_of
        if isinstance(self.specs, SpecTable):
            triples: Iterable[tuple[str, str, str]] = self.specs.keys_by_kind()
        else:
            triples = ((s.id, s.kind, s.key) for s in self.specs.values() if s.key)
        for pid, kind, key in triples:
            if (kind, key) not in by_key:
                by_key[(kind, key)] = pid
            kinds_of.setdefault(key, []).append(kind)

    def __len__(self) -> int:
        return len(self.specs)

    def get(self, param_id: str) -> ParamSpec | None:
        return self.specs.get(param_id)

    def by_pattern(self, pattern: str, kind: str | None) -> ParamSpec | None:
        """The spec for a key pattern (``np_grp[].achse[].versch``) in a list kind."""
        slot = (kind, pattern)
        spec = self._pattern_specs.get(slot, _ABSENT)  # not try/except: a list's first look-ups all miss
        if spec is _ABSENT:
            if kind is not None:  # _by_pattern, inline for a known kind (a list's, each pattern once)
                pid = self._by_key.get((kind, pattern))
                spec = self.specs[pid] if pid is not None else None
            else:
                spec = self._by_pattern(pattern, kind)
            if len(self._pattern_specs) < 100_000:
                self._pattern_specs[slot] = spec
        return spec  # type: ignore[no-any-return]

    def _by_pattern(self, pattern: str, kind: str | None) -> ParamSpec | None:
        if kind is not None:
            pid = self._by_key.get((kind, pattern))
            return self.specs[pid] if pid is not None else None
        kinds = self._kinds_of.get(pattern)
        return self.specs[self._by_key[(kinds[0], pattern)]] if kinds else None

    def alias(self, pattern: str, kind: str | None) -> ParamSpec | None:
        """The documented parameter an undocumented spelling stands for, if known."""
        for (k, p), target in self.aliases.items():
            if p == pattern and (kind is None or k == kind):
                pid = self._by_key.get((k, target))
                return self.specs[pid] if pid is not None else None
        return None

    def counted_by(self, spec: ParamSpec) -> tuple[tuple[str, int], ...]:
        """The parameters that count the elements of ``spec``'s arrays, each with the index it counts:
        `spindel[i].…` by `spdl_anzahl`, `gruppe[g].achse[j].…` by `gruppe[g].achs_anzahl` (index 1).
        Found by rule from the catalogue's keys: an unsigned `STEM_anzahl` beside an array (same
        parent) whose name holds STEM's letters in order (`spdl` in `spindel`, `grp` in `gruppe`, `hr`
        in `hr_data`); empty where none counts them. Answered per parameter from the few counts of
        its kind (found once), not from a table of every pair of keys (issue 40: start-up)."""
        if not spec.dims or not spec.key:
            return ()  # no array, nothing to count
        memo: dict[str, tuple[tuple[str, int], ...]] = self.memo.setdefault("counted_by", {})
        got = memo.get(spec.id)
        if got is None:
            got = memo[spec.id] = _counted(spec.key, self._counters_of(spec.kind))
        return got

    def _counters(self) -> dict[str, list[tuple[str, str, str, int]]]:
        """Kind → its counts: (ID, stem, parent, the index it counts), found from the keys (every kind's)."""
        return {kind: got for kind in dict.fromkeys(k for _, k, _ in self._count_keys())
                if (got := self._counters_of(kind))}

    def _count_keys(self) -> Iterable[tuple[str, str, str]]:
        """(ID, kind, key) of the parameters whose key ends in ``_anzahl``."""
        specs = self.specs
        return specs.count_triples() if isinstance(specs, SpecTable) else \
            [t for t in _triples(specs) if t[2].endswith("_anzahl")]

    def _counters_of(self, kind: str) -> list[tuple[str, str, str, int]]:
        """The counts of one kind (see :meth:`_counters`), found once: only that kind's are built (an axis
        list's lint reads no channel parameter's row)."""
        memo: dict[str, list[tuple[str, str, str, int]]] = self.memo.setdefault("counters", {})
        got = memo.get(kind)
        if got is None:
            got = memo[kind] = []
            for count_id, count_kind, count_key in self._count_keys():
                start = _count_stem(count_key)
                if count_kind != kind or start < 0 or not self.specs[count_id].type.startswith("UNS"):
                    continue
                parent = count_key[:start]
                got.append((count_id, count_key[start:-len("_anzahl")], parent, parent.count("[]")))
        return got

    def machine_data_ids(self) -> frozenset[str]:
        """The IDs ``#MACHINE DATA`` accepts as keywords (the seed's entries), computed once."""
        if self._machine_data is None:
            self._machine_data = frozenset(pid for pid in self.specs
                                           if self.specs[pid].source.startswith("#MACHINE DATA"))
        return self._machine_data

    def kinds_of(self, pattern: str) -> list[str]:
        return list(self._kinds_of.get(pattern, ()))

    def range_of(self, spec: ParamSpec) -> Range | None:
        """The parsed formal range of a spec (parsed once, cached). The built-in catalogue's ranges
        are parsed at build time (``tools/gen_ranges.py``); a text that differs from the one parsed
        there (a user's catalogue, or a stale module) is parsed here."""
        rng = self._ranges.get(spec.id, _ABSENT)  # not try/except: a list's first look-ups all miss
        if rng is _ABSENT:
            text = spec.range_text
            if not text:
                rng = None
            else:
                written = written_range(spec.id)
                rng = decode_range(written[1]) if written is not None and written[0] == text else \
                    parse_range(text, spec.id)
            self._ranges[spec.id] = rng
        return rng  # type: ignore[no-any-return]

    def range_refers(self, spec: ParamSpec) -> bool:
        """Whether ``spec``'s formal range refers to other parameters (``range_of(spec).refs``), read from the
        range written at build time where it is not parsed yet (a lint asks this of every parameter it
        binds, and reads the range of half of them)."""
        rng = self._ranges.get(spec.id, _ABSENT)
        if rng is _ABSENT and spec.range_text:
            written = written_range(spec.id)
            if written is not None and written[0] == spec.range_text:
                return encoded_refers(written[1])
            rng = self.range_of(spec)
        return bool(rng is not None and rng is not _ABSENT and rng.refs)

    def kind_of(self, doc: Document, entries: Iterable[Entry] | None = None) -> str | None:
        """The list kind of a document, the one way every command tells it: what the document declares
        itself (an XML list's root element), else detected from the keys of its entries (``entries``,
        by default all before ``Ende``) with the file name breaking a tie (:meth:`detect_kind`)."""
        declared = doc.declared_kind()
        if declared is not None:
            return declared
        return self.detect_kind((e.key.pattern for e in (doc.entries if entries is None else entries) if e.key),
                                doc.path)

    def kind_of_counts(self, doc: Document, counts: Mapping[str, int]) -> str | None:
        """:meth:`kind_of` of a document whose entries' key patterns are counted already (pattern ->
        how many entries have it): the same answer, without an entry."""
        declared = doc.declared_kind()
        if declared is not None:
            return declared
        return self.detect_kind_counts(counts, doc.path)

    def detect_kind(self, patterns: Iterable[str], path: str = "") -> str | None:
        """The list kind whose keys match most of ``patterns``; file name breaks ties."""
        return self.detect_kind_counts(Counter(patterns), path)  # counted in C: a big list has few patterns

    def detect_kind_counts(self, counts: Mapping[str, int], path: str = "") -> str | None:
        """:meth:`detect_kind` of patterns counted already (pattern -> how many times). Answered once per
        (counts, the file name's hint) and registry: the lists of a fleet repeat their keys."""
        hint = kind_hint(path)
        memo: dict[tuple[str | None, tuple[tuple[str, int], ...]], str | None] = self.memo.setdefault("kinds", {})
        slot = (hint, tuple(counts.items()))
        got = memo.get(slot, _ABSENT)
        if got is not _ABSENT:
            return got  # type: ignore[no-any-return]
        votes: dict[str, int] = {}
        kinds_of = self._kinds_of
        each = kinds_of.get_each(counts, ()) if isinstance(kinds_of, SortedIndex) else \
            [kinds_of.get(p, ()) for p in counts]  # the built-in index: one call, not one per pattern
        for kinds, n in zip(each, counts.values(), strict=True):
            for k in kinds:
                votes[k] = votes.get(k, 0) + n
        got = self._leader(votes, hint)
        if len(memo) < 4096 and len(counts) <= 4096:
            memo[slot] = got
        return got

    @staticmethod
    def _leader(votes: dict[str, int], hint: str | None) -> str | None:
        """The kind with the most votes; the file name's hint breaks a tie, else the first by name."""
        if not votes:
            return hint
        best = max(votes.values())
        leaders = [k for k, v in votes.items() if v == best]
        if hint in leaders:
            return hint
        return sorted(leaders)[0]

    def search(self, text: str, limit: int = 20) -> list[ParamSpec]:
        """Parameters whose key, a member of the key, the ID or the description contains ``text``
        (case-insensitive); the closest first: whole members, then parts of keys, then descriptions."""
        needle = text.strip().lower().replace("[0]", "[]")
        if not needle:
            return []
        ranked: list[tuple[int, str, ParamSpec]] = []
        for pid in self.specs:
            spec = self.specs[pid]
            key = (spec.key or "").lower()
            members = key.replace("[]", "").split(".")
            if needle in members or key.endswith("." + needle):
                rank = 0
            elif needle in key or needle in pid.lower():
                rank = 1
            elif spec.description and needle in spec.description.lower():
                rank = 2
            else:
                continue
            ranked.append((rank, key or pid, spec))
        ranked.sort(key=lambda r: (r[0], r[1]))
        return [spec for _, _, spec in ranked[:limit]]

    def suggest(self, pattern: str, kind: str | None, n: int = 1) -> list[str]:
        """Known key patterns close to an unknown one (did-you-mean), memoised per pattern."""
        memo = self._suggestions.get((pattern, kind, n))
        if memo is None:
            memo = self._suggest(pattern, kind, n)
            if len(self._suggestions) < 10_000:
                self._suggestions[(pattern, kind, n)] = memo
        return list(memo)

    def _suggest(self, pattern: str, kind: str | None, n: int) -> list[str]:
        from zero.nearest import close_matches  # start-up: only when a key is unknown

        by_key = self._by_key
        # the keys to choose from: a kind's own (its table's, sorted: the order does not change what
        # close_matches answers), else every (kind, key) in the index's order
        table = by_key if kind is not None and isinstance(by_key, KeyIndex) else None
        of_kind = kind or ""
        pool: Sequence[str] = table.keys_of_kind(of_kind) if table is not None else \
            [k for (kd, k) in by_key if kind is None or kd == kind]
        out = close_matches(pattern, pool, n=n, cutoff=0.75)
        if not out:
            # A missing or extra member level: `kenngr.homing_type` vs `kenngr.homing.homing_type`.
            last = pattern.rsplit(".", 1)[-1]
            first = pattern.split(".", 1)[0]
            cands = [k for k in pool if last in k and first in k and k.rsplit(".", 1)[-1] == last and
                     k.split(".", 1)[0] == first]
            if table is not None:  # the shortest first, then in the IDs' order, as the index's order gives them
                cands.sort(key=lambda k: (len(k), table.get((of_kind, k)), k))
            else:
                cands.sort(key=len)
            out = cands[:n]
        return out


def _count_stem(key: str) -> int:
    r"""Where the stem of a count's key starts (`gruppe[].achs_anzahl`: 10, at `achs`): the letters a-z
    before ``_anzahl``, after the key's start or a dot (``(?:^|\.)([a-z]+)_anzahl$``); -1: no count's key."""
    if not key.endswith("_anzahl"):
        return -1
    head = key[:-len("_anzahl")]
    start = head.rfind(".") + 1
    stem = head[start:]
    return start if stem and stem.isascii() and stem.isalpha() and stem.islower() else -1


def _letters_in_order(stem: str, name: str) -> bool:
    it = iter(name)
    return all(c in it for c in stem)


def _triples(specs: Mapping[str, ParamSpec]) -> Iterable[tuple[str, str, str]]:
    """(ID, kind, key) of every parameter with a key (from a lazy table's rows: no parameter built)."""
    return specs.keys_by_kind() if isinstance(specs, SpecTable) else \
        [(s.id, s.kind, s.key) for s in specs.values() if s.key]


def _counted(key: str, counters: Iterable[tuple[str, str, str, int]]) -> tuple[tuple[str, int], ...]:
    """The counts (of its kind's ``counters``) that count the arrays of the parameter keyed ``key``."""
    out: tuple[tuple[str, int], ...] = ()
    for count_id, stem, parent, level in counters:
        if not key.startswith(parent):
            continue
        first = key[len(parent):].split(".")[0]
        if first.endswith("[]") and first[:-2] != stem and first[0] == stem[0] and \
                _letters_in_order(stem, first[:-2]):
            out = (*out, (count_id, level))
    return out


def _counts(registry: Registry) -> dict[str, tuple[tuple[str, int], ...]]:
    """Every counted parameter → its counts (ID, the index each counts); see ``counted_by``, which
    answers one parameter at a time. Read from the keys alone (a lazy table builds no parameter
    for it): only the few counts are built."""
    out: dict[str, tuple[tuple[str, int], ...]] = {"": ()}
    counters = registry._counters()
    for pid, kind, key in _triples(registry.specs):
        got = _counted(key, counters.get(kind, ()))
        if got:
            out[pid] = got
    return out


_COMPILED_RANGES: dict[str, dict[str, tuple[str, Any]]] = {}


def written_range(pid: str) -> tuple[str, Any] | None:
    """(range text, that text parsed, encoded by :func:`~zero.catalog.ranges.encode_range`) of ``pid`` in
    the built-in catalogue, written by ``tools/gen_ranges.py`` (``None``: none written): its kind's module
    (``data/ranges_compiled_axis.py``) imported at the kind's first range (an axis list's lint reads no
    channel range)."""
    kind = pid[2:6]
    got = _COMPILED_RANGES.get(kind)
    if got is None:
        try:  # start-up: written at build time, imported at the kind's first range
            got = importlib.import_module(f"zero.catalog.data.ranges_compiled_{kind.lower()}").RANGES \
                if kind.isascii() and kind.isalnum() else {}
        except ModuleNotFoundError:  # a kind without ranges
            got = {}
        _COMPILED_RANGES[kind] = got
    return got.get(pid)


# The fields of a row a ParamSpec is made of, in the order _spec_from_fields reads them.
_SPEC_FIELDS = ("id", "kind", "key", "type", "default", "range", "range_note", "dims", "symbols", "units",
                "quantity", "max_len", "restart", "description", "vendor_text", "source", "enum", "enum_flags", "bits",
                "enum_labels")


def _spec_from_fields(fields: tuple[Any, ...], index_base: dict[str, int]) -> ParamSpec:
    """:func:`_spec_from_row` of a row's fields in ``_SPEC_FIELDS``' order (``None``: not given), as a table
    row's tuple gives them (its arrays tuples already, written so by tools/gen_registry.py): no dictionary per
    row, the fields passed in ParamSpec's order."""
    (pid, kind, key, typ, default, range_text, range_note, dims, symbols, units, quantity, max_len, restart,
     description, vendor_text, source, enum, enum_flags, bits, enum_labels) = fields
    base = 0
    if key:
        first = key.split("[", 1)[0].split(".", 1)[0]
        base = index_base.get(f"{kind}:{first}", 0)
    return ParamSpec(pid, kind, key, "STRING" if typ is None else typ, default, range_text, range_note,
                     dims or (), symbols or (), units or (), quantity, max_len, bool(restart),
                     description or vendor_text, "CncParaDesc.xml" if source is None else source, base, enum or (),
                     bool(enum_flags), bool(bits), enum_labels or ())


def _spec_from_row(row: dict[str, Any], index_base: dict[str, int]) -> ParamSpec:
    key = row.get("key")
    base = 0
    if key:
        first = key.split("[", 1)[0].split(".", 1)[0]
        base = index_base.get(f"{row['kind']}:{first}", 0)
    get = row.get
    return ParamSpec(  # by position, in ParamSpec's order: id, kind, key, type, default, range_text, ...
        row["id"], row["kind"], key, get("type", "STRING"), get("default"), get("range"), get("range_note"),
        tuple(get("dims", ())), tuple([(s[0], s[1]) for s in get("symbols", ())]), tuple(get("units", ())),
        get("quantity"), get("max_len"), bool(get("restart", False)), get("description") or get("vendor_text"),
        get("source", "CncParaDesc.xml"), base, tuple(get("enum", ())), bool(get("enum_flags", False)),
        bool(get("bits", False)), tuple(get("enum_labels", ())),
    )


def _overlay() -> dict[str, Any]:
    """``data/seeds.toml`` as ``tools/gen_seeds.py`` compiled it (no TOML parser at start-up; a
    test holds the two equal)."""
    from zero.catalog.data.seeds import SEEDS  # start-up: only where the built-in overlay is used

    return SEEDS


def build_registry(rows: list[dict[str, Any]], source: str) -> Registry:
    """Combine table rows with the seed overlay into a :class:`Registry`."""
    by_id: dict[str, dict[str, Any] | tuple[Any, ...]] = {r["id"]: r for r in rows}
    return _built(by_id, source)


# The built-in table's index, written at build time (``data/table.py``): the kinds with rows (each kind's
# keys sorted, and the ID of each, read from its module at the kind's first look-up), the keys sorted and the
# kinds of each, and the count parameters' (ID, kind, key).
Index = tuple[Mapping[str, int], tuple[str, ...], tuple[tuple[str, ...], ...], tuple[tuple[str, str, str], ...]]


def _built(rows: Mapping[str, dict[str, Any] | tuple[Any, ...]], source: str, columns: tuple[str, ...] = (),
           index: Index | None = None, seeded_keys: Mapping[str, str | None] | None = None) -> Registry:
    """The registry of rows by ID (dictionaries, or the built-in table's :class:`TableRows`, tuples in
    ``columns``' order) with the seed overlay. The rows are shared, never changed: a row the overlay changes
    is copied. ``index``: the rows' index written at build time, used where the overlay changes no row's key
    or kind (else the registry indexes the rows itself); ``seeded_keys``: the table's key of the parameters
    the overlay names, written with it (a parameter not there is looked up in its kind's rows)."""
    overlay = _overlay()
    params: dict[str, dict[str, Any]] = overlay.get("params", {})
    if isinstance(rows, TableRows):
        for pid, extra in params.items():
            if index is not None and (extra.get("kind", pid[2:6]) != pid[2:6] or (
                    "key" in extra and extra["key"] != _table_key(rows, pid, seeded_keys))):
                index = None  # a new parameter with a key, or one the overlay gives another key or kind
        rows = TableRows(rows._kinds, columns, params)
    else:
        changed: dict[str, dict[str, Any] | tuple[Any, ...]] = {}
        for pid, extra in params.items():
            old = rows.get(pid)
            if isinstance(old, tuple):
                old = dict(_fields(columns, old))
            changed[pid] = _seeded(pid, old, extra)
        rows = {**rows, **changed}
        index = None  # rows of a user's catalogue: indexed by the registry
    index_base = overlay.get("index_base", {})
    specs = SpecTable(rows, index_base, columns, index[3] if index is not None else None,
                      params if isinstance(rows, TableRows) else None)
    aliases = {}
    for name, target in overlay.get("aliases", {}).items():
        kind, _, pattern = name.partition(":")
        aliases[(kind, pattern)] = target
    vendor_keys = {}
    for name, facts in overlay.get("vendor_keys", {}).items():
        kind, _, pattern = name.partition(":")
        vendor_keys[(kind, pattern)] = (facts["source"], facts.get("near", ""))
    if index is None:
        return Registry(specs, source, aliases=aliases, vendor_keys=vendor_keys)
    kinds, kinds_of_keys, kinds_of, _ = index
    return Registry(specs, source, _by_key=KeyIndex(kinds, _kind_keys), _kinds_of=SortedIndex(kinds_of_keys, kinds_of),
                    aliases=aliases, vendor_keys=vendor_keys)


def _table_key(rows: TableRows, pid: str, seeded_keys: Mapping[str, str | None] | None) -> str | None:
    """The built-in table's key of ``pid`` (``None``: no such parameter): as written with the table where it
    is (``SEEDED_KEYS``), else from its kind's rows."""
    if seeded_keys is not None and pid in seeded_keys:
        return seeded_keys[pid]
    row = rows.table_row(pid)
    return row[2] if row is not None else None


_KIND_TABLES: dict[str, Any] = {}
_TABLE_ROWS: dict[str, tuple[Any, ...]] = {}  # the built-in table's rows unmarshalled, by ID (shared, never changed)
_SPEC_TABLES: dict[str, Any] = {}
_ID_POSITIONS: dict[str, dict[str, int]] = {}  # kind -> each of its IDs' position in its table


def _id_positions(kind: str) -> dict[str, int]:
    """Each ID of a kind's table and its position in IDS (and PACKED, SPECS), made in one call at its first row."""
    ids = _kind_table(kind).IDS
    got = _ID_POSITIONS[kind] = dict(zip(ids, range(len(ids)), strict=True))
    return got  # kind -> its module of specs written at build time (None: none, or not usable)


def _written_spec(pid: str, seeds: Mapping[str, dict[str, Any]], index_base: dict[str, int]) -> tuple[Any, ...] | None:
    """The fields of the built-in parameter ``pid``'s :class:`ParamSpec`, in its order, as tools/gen_specs.py
    wrote them (``data/specs_axis.py``, ...: the seed overlay's facts each was made of beside it): ``None`` where
    none is written, or it was written from another table module, other facts of the overlay (``seeds``,
    ``index_base``) or other fields of ParamSpec (a stale module is slower, never wrong). Making the spec from the
    written fields skips the row's conversion: 2.4 M of a lint's 154 M instructions (issue 40: start-up)."""
    if type(pid) is not str:
        return None
    kind = pid[2:6]
    specs = _SPEC_TABLES.get(kind, _ABSENT)
    if specs is _ABSENT:
        specs = _SPEC_TABLES[kind] = _spec_table(kind, index_base)
    if specs is None:
        return None
    at = (_ID_POSITIONS.get(kind) or _id_positions(kind)).get(pid)
    if at is None:
        return None
    extra, fields = marshal.loads(specs[at])
    return fields if extra == seeds.get(pid) else None


def spec_fields() -> tuple[str, ...]:
    """The names of :class:`ParamSpec`'s fields, in order (what tools/gen_specs.py writes each spec's fields in)."""
    return tuple(f.name for f in fields(ParamSpec))


def _spec_table(kind: str, index_base: dict[str, int]) -> tuple[bytes, ...] | None:
    """One kind's specs written at build time (``SPECS``, in the order of its table's IDS), where they were
    written for its table module, ParamSpec's fields and the overlay's ``index_base`` as they are (else ``None``)."""
    # the kind's data modules at once, where their bundle is current (zero.bundles): at its first parameter,
    # not at its table, which a list's unknown keys look for in every kind's
    preload(f"kind-{kind.lower()}")
    try:  # start-up: written at build time, imported at the kind's first parameter
        got = importlib.import_module(f"zero.catalog.data.specs_{kind.lower()}")
    except ImportError:
        return None
    written_for = (got.TABLE, got.FIELDS, got.INDEX_BASE)
    if written_for != (getattr(_kind_table(kind), "DIGEST", None), spec_fields(), index_base):
        return None
    return got.SPECS  # type: ignore[no-any-return]


def _kind_table(kind: str) -> Any:
    """The module of one kind's rows of the built-in table (``data/table_axis.py``: IDS, PACKED, KEYS, KEY_IDS),
    imported at the kind's first row."""
    got = _KIND_TABLES.get(kind)
    if got is None:
        preload(f"table-{kind.lower()}")  # mapped from its bundle, where that is current (zero.bundles)
        got = _KIND_TABLES[kind] = importlib.import_module(f"zero.catalog.data.table_{kind.lower()}")
    return got


def _kind_keys(kind: str) -> tuple[Sequence[str], Sequence[str]]:
    """One kind's keys of the built-in table, sorted, and the ID of each."""
    table = _kind_table(kind)
    return table.KEYS, table.KEY_IDS


def load_table() -> list[dict[str, Any]]:
    """The committed table rows (generated facts, no vendor texts)."""
    from zero.catalog.data.table import ROWS  # start-up: the 1766 rows only for the built-in registry

    return ROWS


def load_registry(param_desc: str | Path | None = None) -> Registry:
    """A new registry: the built-in table, or one built from a user's ``CncParaDesc.xml``
    (:class:`~zero.errors.ZeroError` when that file cannot be read)."""
    if param_desc is None:
        from zero.catalog.data import table  # start-up: the 1766 rows only for the built-in registry

        assert table.COLUMNS[:3] == ("id", "kind", "key")  # what keys_by_kind reads of a tuple
        return _built(TableRows(table.SIZES), BUILTIN_SOURCE, table.COLUMNS,
                      (table.SIZES, table.KINDS_OF_KEYS, table.KINDS_OF, table.COUNTS), table.SEEDED_KEYS)
    from zero.catalog.paramdesc import read_param_desc  # start-up: XML parsing only when asked

    rows = read_param_desc(param_desc, with_text=True)
    return build_registry(rows, str(param_desc))

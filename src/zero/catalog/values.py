"""Values as the controller reads them: one entry for its parameter, and a whole list.

:func:`read_value` interprets an entry's text for its parameter's type, symbols and
length, and says why the controller would reject it (``Value.problem``).
:class:`ListValues` binds the entries of one list to their parameters and answers
"which value does the controller use for this parameter": the list's (the later entry
wins), else the default, following parameter references. The rules, the machine model
and ``zero diff`` all read values through this module.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator, Mapping, Sequence
from itertools import chain

from zero.catalog.ids import AXIS_TYPE, is_rotary
from zero.catalog.ranges import TYPE_LIMITS, Number
from zero.catalog.registry import INTEGER_TYPES, NO_DEFAULT, ParamSpec, Registry
from zero.hints import overload
from zero.lists.model import HUGE_INDEX, MAX_INDEX_DIGITS, Document, Entry, ValueKind, format_key, parse_key
from zero.patterns import compiled
from zero.records import Record, field

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any, TypeVar

__all__ = ["NO_DEFAULT", "ListValues", "Resolved", "Slot", "Value", "bind", "canonical_key", "default_number",
           "parse_int", "plain_number", "read_text", "read_value", "slot_of", "spec_of", "take"]

# One element of a parameter: its ID and indices (``("P-AXIS-00178", ())``); an entry whose key the
# catalogue does not know is its key pattern behind a `?` (``("?a.b[]", (1,))``). `[01]` and `[1]`
# are one element, and so are an alias and the key it stands for.
Slot = tuple[str, tuple[int, ...]]
_INFINITE = (float("inf"), float("-inf"))  # math.isinf, without importing math (an extension module: start-up)
_LEADING_ZERO = r"\[0[0-9]"  # `[01]`: an index written with a leading zero (compiled at its first use)


def _renamed(registry: Registry, pattern: str, kind: str | None) -> ParamSpec | None:
    """Today's parameter for a spelling of another kernel release (zero's table of renames), so that
    its value is checked as that parameter's (R013 says what the key is)."""
    from zero.catalog.releases import renamed  # start-up: only for a key the catalogue does not have

    row = renamed(pattern, kind, registry)
    return registry.get(row.id) if row is not None else None


def bind(registry: Registry, pattern: str, kind: str | None) -> tuple[ParamSpec, bool] | None:
    """The one binding of a key pattern to its parameter, and whether by an alias: the documented
    key, else an alias, else another kernel release's spelling (the release tables). Every reader of
    values binds through it: the rules, the machine's effective values, diff, the fleet, the report."""
    spec = registry.by_pattern(pattern, kind)
    if spec is not None:
        return spec, False
    spec = registry.alias(pattern, kind)
    if spec is not None:
        return spec, True
    spec = _renamed(registry, pattern, kind)  # its annotation still checked (R008)
    return (spec, False) if spec is not None else None


def spec_of(registry: Registry, key: str, kind: str | None) -> ParamSpec | None:
    """The parameter a key as written names (any spelling :func:`bind` knows), ``None``: none."""
    parsed = parse_key(key)
    hit = bind(registry, parsed.pattern, kind) if parsed is not None else None
    return hit[0] if hit is not None else None


def rotary(values: ListValues) -> bool | None:
    """Whether the lengths of a list are degrees: ``None`` for a list that is not an axis list, else
    from its axis type (``kenngr.achs_typ``: the list's, the default list's under it, else the
    catalogue's, linear)."""
    if values.kind != "AXIS":
        return None
    return is_rotary(values.number_of(AXIS_TYPE))


def slot_of(registry: Registry, kind: str | None, entry: Entry) -> tuple[Slot, ParamSpec | None]:
    """The element an entry sets, and its parameter where the catalogue knows it."""
    key = entry.key
    if key is None:
        return ("?" + entry.key_text, ()), None
    hit = bind(registry, key.pattern, kind)
    if hit is None:
        return ("?" + key.pattern, key.indices), None
    return (hit[0].id, key.indices), hit[0]


def canonical_key(registry: Registry, kind: str | None, entry: Entry) -> str:
    """The documented key of the element an entry sets, its indices as numbers: an alias
    (`kenngr.homing_type`) as the key it stands for (`kenngr.homing.homing_type`), `[01]` as `[1]`."""
    key = entry.key
    if key is None:
        return entry.key_text
    # each distinct pattern bound once (a diff of two tool lists asks for 228,000 entries' keys)
    patterns: dict[tuple[str | None, str], str] = registry.memo.setdefault("canonical_patterns", {})
    pattern = patterns.get((kind, key.pattern))
    if pattern is None:
        hit = bind(registry, key.pattern, kind)  # another release's spelling: today's key
        pattern = hit[0].key if hit is not None and hit[0].key else key.pattern
        if len(patterns) < 100_000:
            patterns[(kind, key.pattern)] = pattern
    if pattern == key.pattern and ("[0" not in key.text or compiled(_LEADING_ZERO).search(key.text) is None):
        return key.text  # written as documented (the usual case): as it is
    return format_key(pattern, key.indices)


class Value(Record):
    """An entry's value as the controller reads it for its parameter."""

    number: Number | None = None  # the numeric value, when there is one
    text: str | None = None  # the string value (quotes removed), for STRING
    ref: tuple[str, int | None] | None = None  # a parameter reference
    problem: str | None = None  # "type", "overflow", "symbol", "bool", "length": why it is rejected
    detail: str = ""


class Resolved:
    """An entry bound to its parameter. Bound from a row of a document's columns, its entry is built when
    first read (the value model reads ``value``; a finding reads ``entry``)."""

    __slots__ = ("_doc", "_entry", "_row", "spec", "value", "via_alias")

    def __init__(self, entry: Entry, spec: ParamSpec, value: Value, via_alias: bool = False) -> None:
        self._entry: Entry | None = entry
        self._doc: Document | None = None
        self._row = -1
        self.spec = spec
        self.value = value
        self.via_alias = via_alias

    @classmethod
    def at(cls, doc: Document, row: int, spec: ParamSpec, value: Value, via_alias: bool) -> Resolved:
        """The entry of ``row`` of ``doc``'s columns bound to ``spec``, the entry not built yet."""
        out = cls.__new__(cls)
        out._entry, out._doc, out._row = None, doc, row
        out.spec, out.value, out.via_alias = spec, value, via_alias
        return out

    @property
    def entry(self) -> Entry:
        got = self._entry
        if got is None:
            assert self._doc is not None
            got = self._entry = self._doc.entry_at(self._row)
        return got

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        assert isinstance(other, Resolved)
        return (self.entry is other.entry and self.spec == other.spec and self.value == other.value
                and self.via_alias == other.via_alias)

    __hash__ = None  # type: ignore[assignment]  # mutable, compared by value: as the record it was

    def __repr__(self) -> str:
        return f"Resolved(entry={self.entry!r}, spec={self.spec!r}, value={self.value!r}, via_alias={self.via_alias!r})"


REAL64_MAX = sys.float_info.max


def parse_int(text: str) -> int | None:
    """A decimal or hexadecimal integer as the controller reads it; ``None`` if it is none."""
    if text.isdigit() and text.isascii() and len(text) <= 40:
        return int(text)
    t = text.strip()
    sign = -1 if t.startswith("-") else 1
    body = t.lstrip("+-")
    try:
        if len(body) > 1000:  # beyond every type (reported as too large); shown as a number of its size
            return sign * 10**1000
        if "." in body:  # what int() refuses: said without raising its ValueError (a real's default, `0.5`)
            return None
        if body.lower().startswith("0x"):
            return sign * int(body, 16)
        return sign * int(body)
    except ValueError:
        return None


def default_number(spec: ParamSpec, values: ListValues | None = None, depth: int = 0) -> Number | None:
    """The default as a number (symbols mapped; references followed through ``values``)."""
    d = (spec.default or "").strip()
    if not d:
        return None
    v = spec.symbol_value(d)
    if v is not None:
        return v
    if d in ("TRUE", "FALSE") and spec.type == "BOOLEAN":
        return 1 if d == "TRUE" else 0
    n = int(d) if d.isdigit() and d.isascii() and len(d) <= 40 else parse_int(d)  # its first case inline
    if n is not None:
        return n
    if values is not None and d.startswith("P-") and len(d) >= 12:
        rid, _, ridx = d.partition(".")
        return values.number_of(rid, (int(ridx),) if ridx.isdigit() else (), depth + 1)
    try:
        return float(d)
    except ValueError:
        return None


def _has_number(symbols: tuple[tuple[str, int | None], ...], n: int) -> bool:
    """Whether a symbol's number is ``n`` (not any() over a generator: one it leaves unfinished is closed
    by raising GeneratorExit in it)."""
    return n in [val for _, val in symbols]


def _no_numbers(symbols: tuple[tuple[str, int | None], ...]) -> bool:
    """Whether no symbol has a number (not all() over a generator: see _has_number)."""
    return [val for _, val in symbols].count(None) == len(symbols)


def _symbol_number(spec: ParamSpec, word: str) -> tuple[bool, int | None]:
    """Is ``word`` an allowed symbol (or its number)? And its numeric value."""
    for name, val in spec.symbols:
        if name == word:
            return True, val
    n = parse_int(word)
    if n is not None and (_has_number(spec.symbols, n) or (spec.bits and spec.bits_allow(n))):
        return True, n  # a symbol's number, or (bit-coded symbols) a combination of their bits: 7 = VEL|ACC|JERK
    return False, None


def _symbols(spec: ParamSpec, parts: list[str], boolean: bool) -> Value | int | None:
    """The OR of symbolic parts, or the :class:`Value` that rejects the first bad one."""
    total: int | None = 0
    for part in parts:
        ok, val = _symbol_number(spec, part)
        if not ok and boolean and part in ("TRUE", "FALSE"):
            ok, val = True, int(part == "TRUE")
        if not ok:
            return Value(problem="bool" if boolean else "symbol", detail=part)
        total = None if val is None or total is None else total | val
    return total


def read_value(spec: ParamSpec, entry: Entry) -> Value:
    """Interpret an entry's value for its parameter's type, symbols and length."""
    return read_text(spec, entry.value, entry.value_kind)


def read_text(spec: ParamSpec, raw: str, kind: ValueKind | None) -> Value:
    """:func:`read_value` of a value's text and kind (a row of a document's columns)."""
    t = spec.type
    if kind is ValueKind.REF:
        rid, _, ridx = raw.partition(".")  # an index beyond every array is never converted (Python's int limit)
        return Value(ref=(rid, (int(ridx) if len(ridx) <= MAX_INDEX_DIGITS else HUGE_INDEX) if ridx else None))

    if t == "STRING":
        if kind is ValueKind.QUOTED:
            text = raw[1:-1] if len(raw) >= 2 and raw.endswith('"') else raw[1:]
            text = text.rstrip(" ")
        else:
            text = raw
        if spec.symbols and kind in (ValueKind.INT, ValueKind.HEX) and _no_numbers(spec.symbols):
            # A number for names whose numbers the catalogue does not give (the vendor writes
            # `0x00000000` for "none of them"): the catalogue is silent, nothing to say.
            return Value(number=parse_int(raw), text=text)
        if spec.symbols and kind is not ValueKind.QUOTED:
            parts = [p.strip() for p in text.split("|")] if kind is ValueKind.FLAGS else [text]
            got = _symbols(spec, parts, False)
            if isinstance(got, Value):
                got.text = text
                return got
            return Value(number=got, text=text)
        if spec.max_len and len(text) > spec.max_len:  # a length of 0: the catalogue gives none
            return Value(text=text, problem="length", detail=str(len(text)))
        return Value(text=text)

    if t in INTEGER_TYPES:
        if kind in (ValueKind.INT, ValueKind.HEX):
            # parse_int's first case inline (most values: plain digits)
            n = int(raw) if raw.isdigit() and raw.isascii() and len(raw) <= 40 else parse_int(raw)
            assert n is not None
            lo, hi = TYPE_LIMITS.get(t, (None, None))
            if t == "BOOLEAN" and n not in (0, 1):
                return Value(number=n, problem="bool")
            if lo is not None and hi is not None and not lo <= n <= hi:
                return Value(number=n, problem="overflow")
            return Value(number=n)
        if kind in (ValueKind.WORD, ValueKind.FLAGS) and (spec.symbols or t == "BOOLEAN"):
            parts = [p.strip() for p in raw.split("|")] if kind is ValueKind.FLAGS else [raw]
            got = _symbols(spec, parts, t == "BOOLEAN")
            return got if isinstance(got, Value) else Value(number=got)
        return Value(problem="type", detail="integer")

    if t == "REAL64":  # beyond a double's range: does not fit (no arithmetic on it overflows later)
        if kind in (ValueKind.INT, ValueKind.HEX):
            n = parse_int(raw)
            return Value(number=n, problem="overflow" if n is not None and abs(n) > REAL64_MAX else None)
        if kind is ValueKind.REAL:
            try:
                r = float(raw)
            except ValueError:
                return Value(problem="type", detail="number")
            return Value(number=r, problem="overflow" if r in _INFINITE else None)
        if spec.symbols and kind is ValueKind.WORD:
            ok, val = _symbol_number(spec, raw)
            return Value(number=val) if ok else Value(problem="symbol", detail=raw)
        return Value(problem="type", detail="number")

    return Value(text=raw)  # STRUCT and anything undocumented: not checked


def plain_number(t: str | None, raw: str, kind: ValueKind | None) -> Number | None:
    """The number :func:`read_text` reads, without a problem, from a plain value of a parameter of type ``t``: a
    real of a ``REAL64``, plain digits of an integer type or of a ``REAL64``; ``None`` for any other value (then
    :func:`read_text` says what it is). Without making a :class:`Value`: a big list judges each of its tens of
    thousands of distinct values by its number (held to read_text by tests/catalog/test_plain_numbers.py)."""
    if kind is ValueKind.REAL:
        if t != "REAL64":
            return None
        try:
            r = float(raw)
        except ValueError:
            return None
        return None if r in _INFINITE or r != r else r
    if kind is not ValueKind.INT or not (raw.isdigit() and raw.isascii() and len(raw) <= 40):
        return None
    n = int(raw)
    if t == "REAL64":
        return n if n <= REAL64_MAX else None
    if t not in INTEGER_TYPES or (t == "BOOLEAN" and n not in (0, 1)):
        return None
    lo, hi = TYPE_LIMITS.get(t, (None, None))
    return n if lo is None or hi is None or lo <= n <= hi else None


if TYPE_CHECKING:
    _V = TypeVar("_V", bound="ListValues")
_MISSING: Any = object()  # what a memo's .get gives for a key it does not hold


def _rows_by_shape(shape: Sequence[int], count: int) -> list[Sequence[int]]:
    """Shape id -> its rows, in order (``count`` shapes). One pass over the rows; a list that repeats one
    sequence of distinct shapes (a tool table: every tool writes its parameters in the same order) is
    recognised by comparing its arrays in C, and each shape's rows are a ``range`` (no int per row held)."""
    n = len(shape)
    if n >= 4096:  # a list's or an array's (the column of a big list): compared, sliced and repeated in C
        seq: Any = shape
        try:
            period = seq.index(seq[0], 1)
        except ValueError:
            period = 0
        head = seq[:period]
        whole = n - n % period if period else 0
        if period and len(set(head)) == period and seq[:whole] == head * (n // period) \
                and seq[whole:] == head[:n - whole]:
            ranges: list[Sequence[int]] = [[] for _ in range(count)]
            for at, sid in enumerate(head):
                ranges[sid] = range(at, n, period)
            return ranges
    out: list[list[int]] = [[] for _ in range(count)]
    for row, sid in enumerate(shape):  # the one pass over the rows
        out[sid].append(row)
    return list(out)


def take(column: Sequence[int], rows: Sequence[int]) -> Sequence[int]:
    """``column``'s values at ``rows`` (increasing), in order: a slice where the rows are evenly spaced (a
    shape's rows in a repeating table), taken in C; else one look-up per row."""
    if type(rows) is range:  # a column is a list or an array: sliced alike
        return column[rows.start:rows.stop:rows.step]
    n = len(rows)
    if n >= 64:
        start, stop = rows[0], rows[-1]
        step = rows[1] - start
        if step > 0 and stop == start + step * (n - 1) and rows == list(range(start, stop + 1, step)):
            return column[start:stop + 1:step]
    return list(map(column.__getitem__, rows))


def _group(shape_rows: list[Sequence[int]], shapes: list[int]) -> Sequence[int]:
    """The rows of a pattern whose keys have ``shapes`` (ids into ``shape_rows``), in order."""
    return shape_rows[shapes[0]] if len(shapes) == 1 else sorted(chain.from_iterable(map(shape_rows.__getitem__,
                                                                                          shapes)))


class ListValues(Record):
    """The entries of one list bound to their parameters, and the values the controller uses.

    Bound per distinct key pattern, over the document's columns (:attr:`Document.columns`): the rows
    are grouped by the shape of their key once (``shape_rows``), each pattern is bound once
    (``bound``), and the checks run over the groups (a value once per distinct value of a pattern).
    ``resolved`` and ``by_id`` are built on first use, ``by_id`` one parameter at a time, and an
    :class:`Entry` only for a row that is asked for: a clean list builds no per-entry object here."""

    doc: Document
    registry: Registry
    kind: str | None
    # the default list under this one (default_achs_mds under an axis list): its values apply
    # where this list sets none
    base: ListValues | None = None
    # shape id (``doc.columns.shapes``) -> its rows, in order; none for a shape of rows without a key
    shape_rows: list[Sequence[int]] = field(default_factory=list, repr=False, compare=False)
    # shape id -> its key pattern, indices (after the first index where ``indexed``, else all) and indexed
    shape_keys: list[tuple[str, tuple[int, ...], bool]] = field(default_factory=list, repr=False, compare=False)
    # key pattern -> the shapes of its rows (first seen first)
    pattern_shapes: dict[str, list[int]] = field(default_factory=dict, repr=False, compare=False)
    # key pattern -> its binding (:func:`bind`): the parameter, and whether by an alias; ``None``: none
    bound: dict[str, tuple[ParamSpec, bool] | None] = field(default_factory=dict, repr=False, compare=False)
    # the value ids (``doc.columns.values``) of values the controller does not read (``value_kind`` None)
    valueless: frozenset[int] = field(default=frozenset(), repr=False, compare=False)
    _groups: dict[str, Sequence[int]] | None = field(default=None, repr=False, compare=False)
    _entries: list[Entry] | None = field(default=None, repr=False, compare=False)
    _resolved: _Resolved | None = field(default=None, repr=False, compare=False)
    _by_id: Mapping[str, dict[tuple[int, ...], Resolved]] | None = field(default=None, repr=False, compare=False)

    @classmethod
    def of(cls: type[_V], doc: Document, registry: Registry, kind: str | None = None) -> _V:
        """Bind a document's entries (before ``Ende``); ``kind`` detected when ``None``."""
        cols = doc.columns
        shapes = cols.shapes
        shape_rows = _rows_by_shape(cols.shape, len(shapes))
        pattern_shapes: dict[str, list[int]] = {}
        counts: dict[str, int] = {}
        shape_keys: list[tuple[str, tuple[int, ...], bool]] = []
        patterns = cols.patterns
        for sh, rows in zip(shapes, shape_rows, strict=True):
            # A shape is a key's (Columns.shape_id): its pattern, and its indices after the first (all of them for a
            # key without a first index, or one read the careful way, `[01]`), as parse_key reads the key (held by
            # tests/catalog/test_shape_keys.py; no key parsed again here, a third of binding 300 keys' patterns)
            got = (patterns[sh.pattern], sh.indices, sh.indexed)
            shape_keys.append(got)
            if not rows:
                continue
            pattern = got[0]
            got_shapes = pattern_shapes.get(pattern)
            if got_shapes is None:
                pattern_shapes[pattern] = [len(shape_keys) - 1]
                counts[pattern] = len(rows)
            else:
                got_shapes.append(len(shape_keys) - 1)
                counts[pattern] += len(rows)
        if kind is None:  # from each pattern's count (what kind_of reads: the entries' key patterns)
            kind = registry.kind_of_counts(doc, counts)
        kinds = cols.kinds
        valueless = frozenset([v for v, k in enumerate(kinds) if k is None]) if None in kinds else frozenset()
        out = cls(doc, registry, kind, shape_rows=shape_rows, shape_keys=shape_keys, pattern_shapes=pattern_shapes,
                  valueless=valueless)
        # Bindings are kept per registry and kind: the lists of a fleet bind the same patterns.
        memo: dict[str, tuple[ParamSpec, bool] | None] = registry.memo.setdefault(f"bound:{kind}", {})
        bound = out.bound
        for pattern in pattern_shapes:
            hit = memo.get(pattern, _MISSING)  # not try/except: a list's first look-ups all miss
            if hit is _MISSING:
                spec = registry.by_pattern(pattern, kind)  # bind's first answer, without its call
                hit = (spec, False) if spec is not None else bind(registry, pattern, kind)
                if len(memo) < 65_536:
                    memo[pattern] = hit
            bound[pattern] = hit
        return out

    @property
    def entries(self) -> list[Entry]:
        """The document's entries (before ``Ende``); a row is a position in it. Built on first use:
        a check that can work on rows does not ask for it."""
        got = self._entries
        if got is None:
            got = self._entries = self.doc.entries
        return got

    def entry_at(self, row: int) -> Entry:
        """The entry of ``row`` (built when first asked for)."""
        return self.doc.entry_at(row)

    @property
    def groups(self) -> dict[str, Sequence[int]]:
        """Key pattern -> the rows of its entries, in order (the patterns first seen first)."""
        got = self._groups
        if got is None:
            rows = self.shape_rows
            got = self._groups = {p: _group(rows, ids) for p, ids in self.pattern_shapes.items()}
        return got

    def rows_of(self, pattern: str) -> Sequence[int]:
        """``groups[pattern]``, without making every pattern's group (a list's checks ask for a few dozen)."""
        got = self._groups
        if got is not None:
            return got[pattern]
        return _group(self.shape_rows, self.pattern_shapes[pattern])

    def value_rows(self, pattern: str) -> Sequence[int]:
        """The rows of ``pattern`` whose entries have a value the controller reads (what ``resolved``
        holds of it), in order."""
        rows = self.rows_of(pattern)
        if self.valueless:
            valueless, value = self.valueless, self.doc.columns.value
            rows = [r for r in rows if value[r] not in valueless]
        return rows

    def value_ids_at(self, rows: Sequence[int]) -> Sequence[int]:
        """The value ids (``doc.columns.values``, ``kinds``) of ``rows``, in order."""
        return take(self.doc.columns.value, rows)

    def indices_at(self, rows: Sequence[int]) -> list[tuple[int, ...]]:
        """The key indices of ``rows`` (rows of a key), in order."""
        cols, keys = self.doc.columns, self.shape_keys
        out = []
        for row in rows:
            _, indices, indexed = keys[cols.shape[row]]
            out.append((cols.first[row], *indices) if indexed else indices)
        return out

    def annotations_at(self, rows: Sequence[int]) -> list[str | None]:
        """The `( P-XXXX-nnnnn` annotations of ``rows`` (``None``: none), in order."""
        cols = self.doc.columns
        notes = [*cols.notes, None]  # comment id -1: no comment
        return list(map(notes.__getitem__, map(cols.comment.__getitem__, rows)))

    def value(self, spec: ParamSpec, e: Entry) -> Value:
        """``read_value(spec, e)``, once per (parameter, value text) and registry: a value is never
        changed after reading, so entries share it (the value kind follows from the text)."""
        return self.value_of_text(spec, e.value, e.value_kind)

    def value_of_text(self, spec: ParamSpec, text: str, kind: ValueKind | None) -> Value:
        """``read_text(spec, text, kind)``, once per (parameter, value text) and registry."""
        read: dict[tuple[str, str], Value] = self.registry.memo.setdefault("values", {})
        slot = (spec.id, text)
        got = read.get(slot)
        if got is None:
            got = read_text(spec, text, kind)
            if len(read) < 65_536:
                read[slot] = got
        return got

    def resolved_at(self, row: int) -> Resolved:
        """The entry of ``row`` (a row of a bound pattern, with a value) bound to its parameter; the entry
        itself built when first read."""
        hit, value = self._bound_at(row)
        return Resolved.at(self.doc, row, hit[0], value, hit[1])

    def _bound_at(self, row: int) -> tuple[tuple[ParamSpec, bool], Value]:
        """The binding of ``row`` (a row of a bound pattern, with a value) and its value as read for it."""
        cols = self.doc.columns
        hit = self.bound.get(self.shape_keys[cols.shape[row]][0])
        vid = cols.value[row]
        kind = cols.kinds[vid]
        if hit is None or kind is None:
            raise ValueError(f"row {row} is no entry bound to a parameter")
        return hit, self.value_of_text(hit[0], cols.values[vid], kind)

    def sketch_at(self, row: int) -> Resolved:
        """``resolved_at(row)`` for a verdict: its entry the row's own where one is built already, else a
        stand-in from the columns with the row's line, key, value and kind but no positions (nothing
        reported may be made from it; building the real entry reads its line again)."""
        cols = self.doc.columns
        e = cols.objects.get(row)
        if e is None:
            text = cols.key_text(row)
            vid = cols.value[row]
            e = Entry(cols.line[row], text, text, cols.key(row), 0, 0, cols.values[vid], cols.kinds[vid], 0, 0)
        hit = self.bound.get(e.key.pattern) if e.key is not None else None
        if hit is None or e.value_kind is None:
            raise ValueError(f"row {row} is no entry bound to a parameter")
        return Resolved(e, hit[0], self.value(hit[0], e), hit[1])

    @property
    def resolved(self) -> Sequence[Resolved]:
        """Every entry with a value bound to its parameter, in order (built on first use)."""
        got = self._resolved
        if got is None:
            got = self._resolved = _Resolved(self)
        return got

    @property
    def by_id(self) -> Mapping[str, dict[tuple[int, ...], Resolved]]:
        """Parameter ID -> indices -> the entry that wins (the last one); each parameter's elements
        built on first use."""
        got = self._by_id
        if got is None:
            # a small list: every parameter's elements at once, in a plain dict (the value model reads it often)
            got = self._by_id = self._every_id() if len(self.doc.columns) < 4096 else _ById(self)
        return got

    def _every_id(self) -> dict[str, dict[tuple[int, ...], Resolved]]:
        """``by_id`` built in one pass over the rows (what :meth:`resolved_at` makes of each, inline)."""
        cols, doc, bound = self.doc.columns, self.doc, self.bound
        first, kinds, texts, value = cols.first, cols.kinds, cols.values, cols.value
        read: dict[tuple[str, str], Value] = self.registry.memo.setdefault("values", {})
        # per shape: its parameter, whether by an alias, the parameter's ID, indices and indexed; None: unbound
        per_shape: list[tuple[ParamSpec, bool, str, tuple[int, ...], bool] | None] = []
        for pattern, indices, indexed in self.shape_keys:
            hit = bound.get(pattern)
            per_shape.append(None if hit is None else (hit[0], hit[1], hit[0].id, indices, indexed))
        out: dict[str, dict[tuple[int, ...], Resolved]] = {}
        new = Resolved.__new__
        for row, shape in enumerate(cols.shape):
            bound_shape = per_shape[shape]
            if bound_shape is None:
                continue
            vid = value[row]
            kind = kinds[vid]
            if kind is None:
                continue
            spec, via_alias, pid, indices, indexed = bound_shape
            slot = (pid, texts[vid])
            got = read.get(slot)
            if got is None:
                got = read_text(spec, slot[1], kind)
                if len(read) < 65_536:
                    read[slot] = got
            res = new(Resolved)
            res._entry, res._doc, res._row, res.spec, res.value, res.via_alias = None, doc, row, spec, got, via_alias
            elements = out.get(pid)
            if elements is None:
                elements = out[pid] = {}
            elements[(first[row], *indices) if indexed else indices] = res
        return out

    def value_of(self, param_id: str, indices: tuple[int, ...] = ()) -> Resolved | None:
        """The entry that sets ``param_id[indices]`` (the later one wins; this list before the
        default list under it), if any."""
        by_id = self._by_id
        slot = (by_id if by_id is not None else self.by_id).get(param_id)
        hit = slot.get(indices) if slot else None
        if hit is None and self.base is not None:
            return self.base.value_of(param_id, indices)
        return hit

    def layer_of(self, param_id: str, indices: tuple[int, ...] = ()) -> ListValues | None:
        """The list whose entry the controller uses for ``param_id[indices]`` (``None``: default)."""
        slot = self.by_id.get(param_id)
        if slot and indices in slot:
            return self
        return self.base.layer_of(param_id, indices) if self.base is not None else None

    def ids_of(self, param_id: str) -> dict[tuple[int, ...], Resolved]:
        """Every element of ``param_id`` this list or the default list under it sets."""
        own = self.by_id.get(param_id, {})
        if self.base is None:
            return own
        return {**self.base.ids_of(param_id), **own}

    def number_of(self, param_id: str, indices: tuple[int, ...] = (), _depth: int = 0) -> Number | None:
        """The numeric value the controller will use: the list's, else the default; ``None`` where it is
        not known (the list's value is one zero cannot read: not the default in its place)."""
        spec = self.registry.get(param_id)
        if spec is None or _depth > 6:
            return None
        indices = indices[: len(spec.dims)] if spec.dims else ()
        if spec.dims and len(indices) < len(spec.dims):
            indices = indices + (0,) * (len(spec.dims) - len(indices))
        value = self._value_of(param_id, indices)
        if value is not None and value.problem is not None:
            return None  # a value zero cannot read (R004/R005 say so): nothing reasons on a guessed one
        if value is not None:
            if value.number is not None:
                return value.number
            if value.ref is not None:
                rid, ridx = value.ref
                return self.number_of(rid, (ridx,) if ridx is not None else (), _depth + 1)
            return None
        return default_number(spec, self, _depth)

    def _value_of(self, param_id: str, indices: tuple[int, ...]) -> Value | None:
        """``value_of(param_id, indices).value``; of a big list without building the entries of the parameter
        (a tool list's 30,000 tools each read the length of their tool: issue 40)."""
        by_id = self._by_id
        if by_id is None:
            by_id = self.by_id
        if type(by_id) is _ById:
            got = by_id.value_at(param_id, indices)
        else:
            slot = by_id.get(param_id)
            hit = slot.get(indices) if slot else None
            got = hit.value if hit is not None else None
        if got is None and self.base is not None:
            return self.base._value_of(param_id, indices)
        return got

    def text_of(self, param_id: str, indices: tuple[int, ...] = ()) -> str | None:
        """The text the controller uses: the list's value (unquoted), else the default."""
        res = self.value_of(param_id, indices)
        if res is not None:
            return res.value.text if res.value.text is not None else res.entry.value
        spec = self.registry.get(param_id)
        return spec.default if spec is not None else None

    def entry_of(self, param_id: str, indices: tuple[int, ...] = ()) -> Entry | None:
        res = self.value_of(param_id, indices)
        return res.entry if res is not None else None


class _Resolved(Sequence[Resolved]):
    """``ListValues.resolved``: built on first use; whether it is empty answered without building it."""

    __slots__ = ("_all", "_values")

    def __init__(self, values: ListValues) -> None:
        self._values = values
        self._all: list[Resolved] | None = None

    def _built(self) -> list[Resolved]:
        got = self._all
        if got is None:
            values = self._values
            rows = sorted(chain.from_iterable(values.value_rows(p) for p, hit in values.bound.items()
                                              if hit is not None))
            got = self._all = [values.resolved_at(r) for r in rows]
        return got

    def __bool__(self) -> bool:
        if self._all is not None:
            return bool(self._all)
        values = self._values
        if not values.valueless:
            return any(hit is not None for hit in values.bound.values())
        return any(hit is not None and values.value_rows(p) for p, hit in values.bound.items())

    def __len__(self) -> int:
        return len(self._built())

    def __iter__(self) -> Iterator[Resolved]:
        return iter(self._built())

    @overload
    def __getitem__(self, i: int) -> Resolved: ...
    @overload
    def __getitem__(self, i: slice) -> Sequence[Resolved]: ...
    def __getitem__(self, i: int | slice) -> Resolved | Sequence[Resolved]:
        return self._built()[i]

    def __repr__(self) -> str:
        return repr(self._built())


class _ById(Mapping[str, dict[tuple[int, ...], Resolved]]):
    """``ListValues.by_id``: a parameter's elements bound on first use (the last entry of each wins,
    the elements in the order the list first sets them)."""

    __slots__ = ("_built", "_patterns", "_rows_at", "_values")

    def __init__(self, values: ListValues) -> None:
        self._values = values
        self._built: dict[str, dict[tuple[int, ...], Resolved]] = {}
        self._rows_at: dict[str, dict[tuple[int, ...], int]] = {}  # parameter ID -> indices -> the row that wins
        patterns: dict[str, list[str]] = {}  # parameter ID -> the patterns bound to it
        for pattern, hit in values.bound.items():
            if hit is not None:
                patterns.setdefault(hit[0].id, []).append(pattern)
        self._patterns = patterns

    def _rows(self, pid: str) -> Sequence[int]:
        values = self._values
        patterns = self._patterns.get(pid, ())
        if len(patterns) == 1:
            return values.value_rows(patterns[0])
        return sorted(chain.from_iterable(values.value_rows(p) for p in patterns))  # an alias and its key

    def _winners(self, pid: str) -> dict[tuple[int, ...], int]:
        """A bound parameter's elements: indices -> the row that sets them (the later entry wins), in the
        order the list first sets them."""
        got = self._rows_at.get(pid)
        if got is None:
            values = self._values
            rows = self._rows(pid)
            got = self._rows_at[pid] = dict(zip(values.indices_at(rows), rows, strict=True))
        return got

    def get(self, pid: str, default: Any = None) -> Any:
        got = self._built.get(pid)
        if got is None:
            if pid not in self._patterns:
                return default
            resolved_at = self._values.resolved_at
            got = self._built[pid] = {idx: resolved_at(r) for idx, r in self._winners(pid).items()}
        return got if got else default

    def value_at(self, pid: str, indices: tuple[int, ...]) -> Value | None:
        """The value of ``pid[indices]`` as :meth:`get` binds it, without building the parameter's entries."""
        built = self._built.get(pid)
        if built is not None:
            hit = built.get(indices)
            return hit.value if hit is not None else None
        if pid not in self._patterns:
            return None
        row = self._winners(pid).get(indices)
        return None if row is None else self._values._bound_at(row)[1]

    def __getitem__(self, pid: str) -> dict[tuple[int, ...], Resolved]:
        got: dict[tuple[int, ...], Resolved] | None = self.get(pid)
        if got is None:
            raise KeyError(pid)
        return got

    def __contains__(self, pid: object) -> bool:
        if not isinstance(pid, str) or pid not in self._patterns:
            return False
        built = self._built.get(pid)
        return bool(built) if built is not None else bool(self._rows(pid))

    def _ids(self) -> list[str]:
        firsts = {pid: rows[0] for pid in self._patterns if (rows := self._rows(pid))}
        return sorted(firsts, key=firsts.__getitem__)  # in the order the list first sets them

    def __iter__(self) -> Iterator[str]:
        return iter(self._ids())

    def __len__(self) -> int:
        return len(self._ids())

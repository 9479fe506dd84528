"""Values as the controller reads them: one entry for its parameter, and a whole list.

:func:`read_value` interprets an entry's text for its parameter's type, symbols and
length, and says why the controller would reject it (``Value.problem``).
:class:`ListValues` binds the entries of one list to their parameters and answers
"which value does the controller use for this parameter": the list's (the later entry
wins), else the default, following parameter references. The rules, the machine model
and ``zero diff`` all read values through this module.
"""

from __future__ import annotations

import math
import re
import sys
from typing import TypeVar

from zero.catalog.ids import AXIS_TYPE, is_rotary
from zero.catalog.ranges import TYPE_LIMITS, Number
from zero.catalog.registry import INTEGER_TYPES, NO_DEFAULT, ParamSpec, Registry
from zero.lists.model import HUGE_INDEX, MAX_INDEX_DIGITS, Document, Entry, ValueKind, format_key, parse_key
from zero.records import field, record

__all__ = ["NO_DEFAULT", "ListValues", "Resolved", "Slot", "Value", "bind", "canonical_key", "default_number",
           "parse_int", "read_value", "slot_of", "spec_of"]

# One element of a parameter: its ID and indices (``("P-AXIS-00178", ())``); an entry whose key the
# catalogue does not know is its key pattern behind a `?` (``("?a.b[]", (1,))``). `[01]` and `[1]`
# are one element, and so are an alias and the key it stands for.
Slot = tuple[str, tuple[int, ...]]
_LEADING_ZERO = re.compile(r"\[0[0-9]")  # `[01]`: an index written with a leading zero


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
    if pattern == key.pattern and ("[0" not in key.text or _LEADING_ZERO.search(key.text) is None):
        return key.text  # written as documented (the usual case): as it is
    return format_key(pattern, key.indices)


@record
class Value:
    """An entry's value as the controller reads it for its parameter."""

    number: Number | None = None  # the numeric value, when there is one
    text: str | None = None  # the string value (quotes removed), for STRING
    ref: tuple[str, int | None] | None = None  # a parameter reference
    problem: str | None = None  # "type", "overflow", "symbol", "bool", "length": why it is rejected
    detail: str = ""


@record
class Resolved:
    """An entry bound to its parameter."""

    entry: Entry
    spec: ParamSpec
    value: Value
    via_alias: bool = False


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
    n = parse_int(d)
    if n is not None:
        return n
    if values is not None and d.startswith("P-") and len(d) >= 12:
        rid, _, ridx = d.partition(".")
        return values.number_of(rid, (int(ridx),) if ridx.isdigit() else (), depth + 1)
    try:
        return float(d)
    except ValueError:
        return None


def _symbol_number(spec: ParamSpec, word: str) -> tuple[bool, int | None]:
    """Is ``word`` an allowed symbol (or its number)? And its numeric value."""
    for name, val in spec.symbols:
        if name == word:
            return True, val
    n = parse_int(word)
    if n is not None and (any(val == n for _, val in spec.symbols) or (spec.bits and spec.bits_allow(n))):
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
    kind = entry.value_kind
    raw = entry.value
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
        if spec.symbols and kind in (ValueKind.INT, ValueKind.HEX) and all(v is None for _, v in spec.symbols):
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
            n = parse_int(raw)
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
            return Value(number=r, problem="overflow" if math.isinf(r) else None)
        if spec.symbols and kind is ValueKind.WORD:
            ok, val = _symbol_number(spec, raw)
            return Value(number=val) if ok else Value(problem="symbol", detail=raw)
        return Value(problem="type", detail="number")

    return Value(text=raw)  # STRUCT and anything undocumented: not checked


_V = TypeVar("_V", bound="ListValues")


@record
class ListValues:
    """The entries of one list bound to their parameters, and the values the controller uses."""

    doc: Document
    registry: Registry
    kind: str | None
    entries: list[Entry] = field(default_factory=list)
    resolved: list[Resolved] = field(default_factory=list)
    # param ID -> indices -> the entry that wins (the last one)
    by_id: dict[str, dict[tuple[int, ...], Resolved]] = field(default_factory=dict)
    # the default list under this one (default_achs_mds under an axis list): its values apply
    # where this list sets none
    base: ListValues | None = None

    @classmethod
    def of(cls: type[_V], doc: Document, registry: Registry, kind: str | None = None) -> _V:
        """Bind a document's entries (before ``Ende``); ``kind`` detected when ``None``."""
        entries = doc.entries
        if kind is None:
            kind = registry.kind_of(doc, entries)
        out = cls(doc, registry, kind, entries)
        append = out.resolved.append
        by_id = out.by_id
        # A big list has few patterns and few distinct values: each pattern is bound, and each
        # (parameter, value) read, once. Values are never changed after reading, so are shared.
        # Bindings are kept per registry and kind: the lists of a fleet bind the same patterns.
        bound: dict[str, tuple[ParamSpec, bool] | None] = registry.memo.setdefault(f"bound:{kind}", {})
        read: dict[tuple[str, str], Value] = registry.memo.setdefault("values", {})  # kind follows from text
        for e in entries:
            key = e.key
            if key is None or e.value_kind is None:
                continue
            pattern = key.pattern
            try:
                hit = bound[pattern]
            except KeyError:
                hit = bind(registry, pattern, kind)
                if len(bound) < 65_536:
                    bound[pattern] = hit
            if hit is None:
                continue
            spec = hit[0]
            slot = (spec.id, e.value)
            value = read.get(slot)
            if value is None:
                value = read_value(spec, e)
                if len(read) < 65_536:
                    read[slot] = value
            res = Resolved(e, spec, value, hit[1])
            append(res)
            ids = by_id.get(spec.id)
            if ids is None:
                ids = by_id[spec.id] = {}
            ids[key.indices] = res
        return out

    def value_of(self, param_id: str, indices: tuple[int, ...] = ()) -> Resolved | None:
        """The entry that sets ``param_id[indices]`` (the later one wins; this list before the
        default list under it), if any."""
        slot = self.by_id.get(param_id)
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
        res = self.value_of(param_id, indices)
        if res is not None and res.value.problem is not None:
            return None  # a value zero cannot read (R004/R005 say so): nothing reasons on a guessed one
        if res is not None:
            if res.value.number is not None:
                return res.value.number
            if res.value.ref is not None:
                rid, ridx = res.value.ref
                return self.number_of(rid, (ridx,) if ridx is not None else (), _depth + 1)
            return None
        return default_number(spec, self, _depth)

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

"""``zero diff``: what changed, by parameter, in units an engineer reads.

Both sides are read into :class:`Side` (lists directly; YAML/TOML/JSON through
the list they convert to), so a list and its YAML compare equal. Values are
compared as the controller reads them (``0x10`` = ``16``, ``TRUE`` = ``1`` for
a BOOLEAN); a parameter set to its default on one side and absent on the other
has the same effective value and is shown only with ``strict``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Mapping
from pathlib import Path

from zero.catalog.ids import AXIS_TYPE, axis_unit, fixed, g_code_with_index, in_units
from zero.catalog.registry import INTEGER_TYPES, NO_DEFAULT, ParamSpec, Registry
from zero.catalog.rows import Rows, own_entries
from zero.catalog.values import ListValues, bind, canonical_key, default_number, parse_int, read_value
from zero.errors import ZeroError
from zero.lists.model import Comment, Document, Entry, Key, ValueKind, parse_key
from zero.lists.tokenizer import tokenize_text
from zero.markup import read_document
from zero.records import Record, field

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

ADDED, REMOVED, CHANGED, SAME, COMMENT = "added", "removed", "changed", "same", "comment"


class Side(Record):
    """One file as the controller reads it: effective entries by key."""

    path: str
    kind: str | None
    entries: Mapping[str, Entry]  # a dict, or the rows of a list (zero.machine.effective.Rows)
    comments: Mapping[str, tuple[str, ...]] = field(default_factory=dict)  # key → comments near it
    update: bool = False  # an update or revert file: what it changes on a running controller

    def applied_to(self, target: Side) -> Side:
        """``target`` as it is once this update is applied: its entries, with this file's over them."""
        return Side(self.path, target.kind or self.kind, {**target.entries, **self.entries},
                    {**target.comments, **self.comments})


class Change(Record):
    key: str
    param_id: str | None
    kind: str  # added, removed, changed, same (equal effective value, shown with strict), comment
    old: str | None
    new: str | None
    unit: str | None = None
    delta: float | int | None = None
    group: str = ""
    note: str = ""
    restart: bool = False  # the catalogue: a change takes effect only at a restart (ChangeRequiresRestart)
    coding: str | None = None  # bits, symbol, boolean (see coding()); None: a quantity, a number, a text
    old_name: str | None = None  # the values by name (`VEL | ACC`, `SERCOS`, `off`) where coding says one
    new_name: str | None = None
    # a mask's bits (by name, else `bit 22 (0x400000)`) set and cleared; None where not two masks
    bits: tuple[tuple[str, ...], tuple[str, ...]] | None = None

    def to_json(self) -> dict[str, Any]:
        return {"key": self.key, "id": self.param_id, "kind": self.kind, "old": self.old,
                "new": self.new, "unit": self.unit, "delta": self.delta, "group": self.group,
                "note": self.note or None, "restart": self.restart, "coding": self.coding,
                "old_name": self.old_name, "new_name": self.new_name,
                "bits": {"set": list(self.bits[0]), "cleared": list(self.bits[1])} if self.bits else None}


# ----------------------------------------------------------------- reading sides


def read_side(data: bytes, fmt: str, path: str, registry: Registry, kind: str | None = None,
              encoding: str | None = None) -> Side:
    """Read list/YAML/TOML/JSON bytes as the controller would see them; a list in the code page
    ``encoding`` when its configuration declares one."""
    update = False
    if fmt in ("lis", "xml"):
        doc = read_document(data, path, registry, encoding)  # an ASCII or an XML list (by its content)
        if doc.origin is not None:
            kind, update = kind or doc.origin.kind, doc.origin.update
        if any(p.kind == "binary" for p in doc.problems):
            raise ZeroError("not a text file: not a parameter list (zero lint says so as S013)", path)
    else:
        from zero.structured.formats import read_tree  # start-up: only for a YAML, TOML or JSON side
        from zero.structured.tree import to_list_text  # start-up: as read_tree

        tree = read_tree(data, fmt, registry, path, kind)
        # the text as the list it makes (in UTF-8: the encoding of its `_zero` record changes nothing read)
        doc = tokenize_text(to_list_text(tree).text, path)
        if kind is None and isinstance(tree.meta.get("kind"), str):
            kind = tree.meta["kind"]
    # the entries by documented key, read from the rows (an Entry built only where a change is shown);
    # the comments near each only when asked for (--comments)
    values = ListValues.of(doc, registry, kind)  # the kind detected where neither side nor file says it
    return Side(path, values.kind, own_entries(values), _Comments(doc, registry, values.kind), update)


class _Comments(Mapping[str, tuple[str, ...]]):
    """Key → the comments near its entry (the full-line comments above it, then its own; the later
    entry's where a key is set twice), built on first use."""

    __slots__ = ("_doc", "_got", "_kind", "_registry")

    def __init__(self, doc: Document, registry: Registry, kind: str | None) -> None:
        self._doc, self._registry, self._kind = doc, registry, kind
        self._got: dict[str, tuple[str, ...]] | None = None

    def _built(self) -> dict[str, tuple[str, ...]]:
        got = self._got
        if got is None:
            doc = self._doc
            got = self._got = {}
            pending: list[str] = []
            for item in doc.items:
                if type(item) is Comment:
                    pending.append(doc.lines[item.line - 1].strip())
                elif type(item) is Entry and not item.after_end:
                    key = canonical_key(self._registry, self._kind, item)  # `[01]` is `[1]`, an alias its key
                    got[key] = (*pending, item.comment.strip() if item.comment else "")
                    pending = []
        return got

    def __getitem__(self, key: str) -> tuple[str, ...]:
        return self._built()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._built())

    def __len__(self) -> int:
        return len(self._built())


# ----------------------------------------------------------------- values


def spec_for(key: str, kind: str | None, registry: Registry, parsed: Key | None = None) -> ParamSpec | None:
    """The parameter of a key (its entry's parsed key where given), bound as every reader of values
    binds it (:func:`zero.catalog.values.bind`: the documented key, an alias, another release's spelling)."""
    k = parsed or parse_key(key)
    if k is None:
        return None
    hit = bind(registry, k.pattern, kind)
    return hit[0] if hit is not None else None


def effective(entry: Entry, spec: ParamSpec | None) -> tuple[str, Any]:
    """The value as the controller reads it, comparable across spellings."""
    if spec is not None and entry.value_kind is not None:
        v = read_value(spec, entry)
        if v.ref is not None:
            return ("ref", v.ref)
        if v.problem is None and v.number is not None:
            return ("num", v.number)
        if v.problem is None and v.text is not None:
            if entry.value_kind is ValueKind.FLAGS:  # `REPORT | PRINT` = `PRINT|REPORT`: a set of flags
                return ("flags", tuple(sorted({p.strip() for p in v.text.split("|") if p.strip()})))
            return ("text", v.text)
    if entry.value_kind is not None and entry.value_kind.value in ("int", "hex"):
        n = parse_int(entry.value)
        if n is not None:
            return ("num", n)
    return ("raw", entry.value)


def default_effective(spec: ParamSpec | None) -> tuple[str, Any] | None:
    if spec is None:
        return None
    d = (spec.default or "").strip()
    if d in NO_DEFAULT:
        return None
    if spec.type == "STRING" and not spec.symbols:
        return ("text", d.strip('"'))
    n = default_number(spec)
    return ("num", n) if n is not None else None


# ----------------------------------------------------------------- units and groups

def side_unit(side: Side | None, registry: Registry) -> str | None:
    """mm or ° from the axis type where a list states it (``kenngr.achs_typ``, a number or a symbol);
    ``None`` where it does not (a single list does not know the default list under it)."""
    spec = registry.get(AXIS_TYPE)
    e = side.entries.get(spec.key) if side is not None and spec is not None and spec.key else None
    if e is None or spec is None:
        return None
    value = read_value(spec, e)
    return axis_unit(value.number) if value.problem is None and value.number is not None else None


def unit_and_delta(spec: ParamSpec | None, old: tuple[str, Any] | None, new: tuple[str, Any] | None,
                   length_unit: str | None) -> tuple[str | None, float | int | None]:
    """The unit and, for a quantity (the catalogue gives it a unit), the numeric delta. A number
    without a unit (a code, a count, a number of something: the catalogue does not say which) and
    a value that names something (:func:`coding`) get no arithmetic."""
    if spec is None:
        return None, None
    unit: str | None = (length_unit or "mm or °") if spec.is_length else (", ".join(spec.units) or None)
    if unit is None or old is None or new is None or old[0] != "num" or new[0] != "num":
        return unit, None
    raw = new[1] - old[1]
    if spec.is_length:
        if isinstance(raw, int) and abs(raw) > 2**53:  # a float would show it wrong: no delta at all
            return unit, None
        delta = in_units(raw)
        return unit, round(delta, 4) if math.isfinite(delta) else None
    return unit, raw


# ----------------------------------------------------------------- what a value means

BITS, SYMBOL, BOOLEAN = "bits", "symbol", "boolean"  # Change.coding; None: a quantity, a number or a text

_BIT_WORDS = re.compile(r"\bbits?\s*[0-9]|\bbit[- ]?(?:coded|mask|wise|field)|\bbitmask|bitcodiert|\bbitmaske",
                        re.IGNORECASE)


def _one_bit(v: int) -> bool:
    return v > 0 and v & (v - 1) == 0


def bits_criterion(spec: ParamSpec) -> str | None:
    """Why the catalogue's data make the parameter's values bits (``None``: they do not):
    ``bit_coded`` (:attr:`ParamSpec.bits`: the one decision the rules make too, that
    `VEL | ACC` combines), ``enum`` (values listed in prose that the catalogue reader marks as
    bits: ``ParamSpec.enum_flags``), ``hex`` (an unsigned integer without symbols or listed values
    whose default or range the catalogue writes in hex), ``description`` (no symbols or listed
    values, and a description that speaks of bits: `Bit 0`, bit-coded, bit mask)."""
    if spec.type == "BOOLEAN":
        return None
    if spec.bits:
        return "bit_coded"
    if spec.symbols:
        return None  # symbols that are no bits: by name
    if spec.enum:
        return "enum" if spec.enum_flags else None
    if spec.type.startswith("UNS") and any((t or "").strip().lower().startswith("0x")
                                           for t in (spec.default, spec.range_text)):
        return "hex"
    if spec.description and _BIT_WORDS.search(spec.description):
        return "description"
    return None


def _hex_written(*texts: str | None) -> bool:
    return any(t is not None and t.strip().lstrip("+-").lower().startswith("0x") for t in texts)


def coding(spec: ParamSpec | None, old: tuple[str, Any] | None, new: tuple[str, Any] | None,
           *texts: str | None) -> str | None:
    """How a change is shown: ``bits`` (the bits that changed), ``symbol`` (by name), ``boolean``
    (off/on) or ``None`` (a number, with its delta where it has a unit). Decided by the catalogue;
    a combination written `A | B` is a set of flags; a unit-less integer written in hex a mask."""
    if any(v is not None and v[0] == "flags" for v in (old, new)):
        return BITS
    if spec is None:
        return BITS if _hex_written(*texts) else None
    if spec.type == "BOOLEAN":
        return BOOLEAN
    if bits_criterion(spec) is not None:
        return BITS
    if spec.symbols or spec.enum:
        return SYMBOL
    if not spec.units and spec.type in INTEGER_TYPES and _hex_written(*texts):
        return BITS
    return None


def _bit_names(spec: ParamSpec | None) -> dict[int, str]:
    """The catalogue's name of each single bit (its symbols, or the labels of its listed bits)."""
    names: dict[int, str] = {}
    if spec is None:
        return names
    for name, v in spec.symbols:
        if v is not None and _one_bit(v):
            names.setdefault(v, name)
    for v, label in spec.enum_items():
        if label and _one_bit(v):
            names.setdefault(v, label)
    return names


def bit_label(bit: int, names: dict[int, str]) -> str:
    """A bit by its catalogue name, else by number and value: ``bit 22 (0x400000)``."""
    return names.get(bit) or f"bit {bit.bit_length() - 1} ({bit:#x})"


def _bits_of(n: int) -> list[int]:
    return [1 << i for i in range(n.bit_length()) if n >> i & 1]


def changed_bits(spec: ParamSpec | None, old: tuple[str, Any] | None,
                 new: tuple[str, Any] | None) -> tuple[tuple[str, ...], tuple[str, ...]] | None:
    """The bits (or flags) set and cleared from ``old`` to ``new``, in bit order; ``None`` where the
    two values are not both masks zero can read."""
    if old is None or new is None:
        return None
    flags = [_flag_set(spec, v) for v in (old, new)]
    if flags[0] is not None and flags[1] is not None:
        order = {name: i for i, (name, _) in enumerate(spec.symbols)} if spec is not None else {}

        def ranked(names: set[str]) -> tuple[str, ...]:
            return tuple(sorted(names, key=lambda x: (order.get(x, len(order)), x)))

        return ranked(flags[1] - flags[0]), ranked(flags[0] - flags[1])
    if old[0] != "num" or new[0] != "num" or not all(isinstance(v[1], int) and v[1] >= 0 for v in (old, new)):
        return None
    a, b = old[1], new[1]
    names = _bit_names(spec)
    return (tuple(bit_label(x, names) for x in _bits_of(b & ~a)),
            tuple(bit_label(x, names) for x in _bits_of(a & ~b)))


def _flag_set(spec: ParamSpec | None, value: tuple[str, Any]) -> set[str] | None:
    """Flags named without numbers (`FCT_A | FCT_B`) as a set; ``None`` for a value with numbers."""
    if value[0] == "flags":
        return set(value[1])
    if value[0] == "text":
        return {value[1]}
    if value[0] == "num" and value[1] == 0 and spec is not None and spec.symbols \
            and all(v is None for _, v in spec.symbols):
        return set()  # `0x00000000`: none of them
    return None


def value_name(spec: ParamSpec | None, how: str | None, value: tuple[str, Any] | None) -> str | None:
    """A value as its meaning: ``on``/``off``, a symbol's name (a listed value with its meaning:
    ``3 (Bessel)``), the names of a mask's bits (``VEL | ACC``; a mask without names in hex);
    ``None`` where the catalogue names nothing."""
    if value is None or how is None:
        return None
    kind, v = value
    if kind == "flags":
        return " | ".join(v)
    if kind == "text":
        return str(v)
    if kind != "num" or not isinstance(v, int):
        return None
    if how == BOOLEAN:
        return {0: "off", 1: "on"}.get(v)
    if how == SYMBOL:
        for name, n in spec.symbols if spec is not None else ():
            if n == v:
                return name
        labels = dict(spec.enum_items()) if spec is not None else {}
        return f"{v} ({labels[v]})" if labels.get(v) else None
    if v < 0:
        return str(v)
    named = [(n, name) for name, n in spec.symbols if n is not None] if spec is not None else []
    if not named and not _bit_names(spec):
        return f"{v:#x}"
    if v == 0:
        return next((name for n, name in named if n == 0), "0")
    parts: list[tuple[int, str]] = []
    rest = v
    for n, name in sorted(named, key=lambda x: -x[0].bit_count()):  # combinations first (`ADD_VEL`)
        if n > 0 and rest & n == n and not _one_bit(n):
            parts.append((n & -n, name))
            rest &= ~n
    names = _bit_names(spec)
    for bit in _bits_of(rest):
        parts.append((bit, names.get(bit) or f"{bit:#x}"))
    return " | ".join(name for _, name in sorted(parts))


def describe(c: Change, spec: ParamSpec | None, old: tuple[str, Any] | None, new: tuple[str, Any] | None,
             *texts: str | None) -> Change:
    """Fill in what ``c`` means (:func:`coding`, the names, the bits that changed, the restart
    flag); a value that names something gets no delta."""
    c.restart = bool(spec is not None and spec.restart)
    how = coding(spec, old, new, *texts)
    if how is None:
        return c
    c.coding, c.delta = how, None
    c.old_name, c.new_name = value_name(spec, how, old), value_name(spec, how, new)
    if how == BITS:
        c.bits = changed_bits(spec, old, new)
    return c


def _named(spec: ParamSpec | None, value: tuple[str, Any] | None, text: str) -> str:
    """A value a list writes, by name where the catalogue names it (else as the list writes it)."""
    how = coding(spec, value, None, text)
    if how == BOOLEAN or (how in (BITS, SYMBOL) and spec is not None
                          and (spec.symbols or _bit_names(spec) or any(lb for _, lb in spec.enum_items()))):
        return value_name(spec, how, value) or text
    return text


def default_name(spec: ParamSpec) -> str:
    """The catalogue's default as a note says it, by name: ``off``, ``NOT_VALID``, ``VEL | ACC``
    (a default the catalogue writes as a name, or a number without names, as it writes it)."""
    if spec.type != "BOOLEAN" and spec.symbol_value((spec.default or "").strip()) is not None:
        return spec.default_display
    return _named(spec, default_effective(spec), spec.default_display)


_INDEX_RE = re.compile(r"\[([0-9]+)\]")


def group_of(key: str, kind: str | None) -> str:
    """How engineers think of a key: offsets by G code and axis, others by family."""
    m = re.match(r"(np_grp|pzv_grp)\[([0-9]+)\]\.achse\[[0-9]+\]", key)
    if m:
        grp = int(m.group(2)) if len(m.group(2)) < 10 else 10**9
        return g_code_with_index(grp) if m.group(1) == "np_grp" else f"clamp group {grp}"
    if kind == "ZERO" and key in ("g53_verfuegbar", "default_index"):
        return "general"
    first = key.split(".", 1)[0]
    return first if "." in key else "general"


def key_order(key: str) -> tuple[Any, ...]:
    parts = re.split(r"(\[[0-9]+\])", key)
    return tuple((0, int(p[1:-1]), "") if p.startswith("[") and len(p) < 22 else (1, 0, p)
                 for p in parts if p)


# ----------------------------------------------------------------- the diff


class DiffOptions(Record):
    strict: bool = False  # also show default vs absent and respelled equal values
    comments: bool = False  # comment changes count


def _comment_text(lines: tuple[str, ...]) -> str:
    return " | ".join(x for x in lines if x) or "(no comment)"


def _text(value: tuple[str, Any] | None, entry: Entry | None) -> str | None:
    if entry is not None:
        return entry.value
    if value is None:
        return None
    return str(value[1])


def diff_sides(a: Side, b: Side, registry: Registry, options: DiffOptions | None = None,
               under: Side | None = None) -> list[Change]:
    """Changes from side ``a`` to side ``b``, grouped and in key order. ``under`` is the default
    list that lies under both on the machine: where it sets a parameter, that value (not the
    catalogue's) is what an absent entry means."""
    options = options or DiffOptions()
    kind = b.kind or a.kind
    out: list[Change] = []
    # Keys in plain order here (the changes are put in key order at the end): most keys of two
    # versions of a list are the same, with the same text, and cost nothing more.
    same_comments = not options.comments
    ta, tb = _value_texts(a.entries), _value_texts(b.entries)
    if ta is not None and tb is not None and same_comments:
        # rows: only the keys whose text differs (or that one side lacks) are
        # looked at, and only their entries built (a fleet's lists are mostly the golden's)
        if ta == tb:
            return out
        keys = sorted({key for key, _ in ta.items() ^ tb.items()})
    else:
        keys = sorted(set(a.entries) | set(b.entries))
    if not keys:
        return out
    unit_a, unit_b = side_unit(a, registry), side_unit(b, registry)
    length_unit = unit_b or unit_a
    for key in keys:
        ea, eb = a.entries.get(key), b.entries.get(key)
        if (ea is not None and eb is not None and ea.value == eb.value
                and (same_comments or a.comments.get(key) == b.comments.get(key))):
            continue  # the same text is the same value, whatever the parameter
        spec = spec_for(key, kind, registry, ea.key if ea is not None else eb.key if eb is not None else None)
        pid = spec.id if spec else None
        va = effective(ea, spec) if ea is not None else None
        vb = effective(eb, spec) if eb is not None else None
        group = group_of(key, kind)
        if ea is not None and eb is not None:
            if va == vb:
                if ea.value != eb.value and options.strict:
                    out.append(Change(key, pid, SAME, ea.value, eb.value, group=group,
                                      note="written differently, same value"))
                elif options.comments and a.comments.get(key) != b.comments.get(key):
                    out.append(Change(key, pid, COMMENT, _comment_text(a.comments.get(key, ())),
                                      _comment_text(b.comments.get(key, ())), group=group))
                continue
            unit, delta = unit_and_delta(spec, va, vb, length_unit)
            out.append(describe(Change(key, pid, CHANGED, ea.value, eb.value, unit, delta, group),
                                spec, va, vb, ea.value, eb.value))
            continue
        base = under.entries.get(key) if under is not None else None
        if base is not None:
            dflt: tuple[str, Any] | None = effective(base, spec)
            named = _named(spec, dflt, base.value)
            shown = f"the default list's {named} ({Path(under.path).name}:{base.line})"  # type: ignore[union-attr]
        else:
            dflt = default_effective(spec)
            shown = f"the default {default_name(spec)}" if spec is not None else ""
        present = va if ea is not None else vb
        if dflt is not None and present is not None and present == dflt:
            if options.strict:
                out.append(Change(key, pid, SAME, _text(va, ea), _text(vb, eb), group=group,
                                  note="set to its default on one side, absent on the other"))
            continue
        if ea is None:
            unit, delta = unit_and_delta(spec, dflt, vb, length_unit)
            out.append(describe(Change(key, pid, ADDED, None, eb.value if eb else None, unit, delta, group,
                                       note=f"was {shown}" if dflt and shown else ""),
                                spec, dflt, vb, eb.value if eb else None, base.value if base else None))
        else:
            unit, delta = unit_and_delta(spec, va, dflt, length_unit)
            out.append(describe(Change(key, pid, REMOVED, ea.value, None, unit, delta, group,
                                       note=f"now {shown}" if dflt and shown else ""),
                                spec, va, dflt, ea.value, base.value if base else None))
    return _grouped(out)


def _value_texts(entries: Mapping[str, Entry]) -> dict[str, str] | None:
    """Key → value text, where the entries are rows that hold them (:class:`Rows`); ``None`` otherwise."""
    return entries.texts if isinstance(entries, Rows) else None


def _grouped(changes: list[Change]) -> list[Change]:
    return sorted(changes, key=lambda c: (group_order(c.group), key_order(c.key)))


def diff_defaults(side: Side, registry: Registry, options: DiffOptions | None = None) -> list[Change]:
    """The parameters of one file that differ from the registry defaults."""
    options = options or DiffOptions()
    length_unit = side_unit(side, registry)
    out: list[Change] = []
    for key in sorted(side.entries, key=key_order):
        e = side.entries[key]
        spec = spec_for(key, side.kind, registry)
        dflt = default_effective(spec)
        value = effective(e, spec)
        group = group_of(key, side.kind)
        if spec is None:
            out.append(Change(key, None, CHANGED, None, e.value, group=group,
                              note="not in the registry"))
            continue
        if dflt is None:
            if options.strict:
                out.append(describe(Change(key, spec.id, CHANGED, None, e.value, group=group,
                                           note="no documented default"), spec, None, value, e.value))
            continue
        if value == dflt:
            continue
        unit, delta = unit_and_delta(spec, dflt, value, length_unit)
        out.append(describe(Change(key, spec.id, CHANGED, spec.default_display, e.value, unit, delta, group),
                            spec, dflt, value, e.value, spec.default))
    return _grouped(out)


def show_lines(side: Side, registry: Registry) -> list[str]:
    """A list as one line per parameter, grouped: the view ``git diff`` compares (textconv)."""
    length_unit = side_unit(side, registry)
    out: list[str] = [f"# zero: {side.path} ({side.kind or 'unknown kind'}), "
                      f"{len(side.entries)} parameters as the controller reads them"]
    current = None
    for key in sorted(side.entries, key=lambda k: (group_order(group_of(k, side.kind)), key_order(k))):
        group = group_of(key, side.kind)
        if group != current:
            out.append(f"[{group}]")
            current = group
        e = side.entries[key]
        spec = spec_for(key, side.kind, registry)
        extra = ""
        if spec is not None:
            extra = f"  ({spec.id}"
            v = effective(e, spec)
            if spec.is_length and v[0] == "num":
                extra += f", {fixed(v[1])} {length_unit or 'mm or °'}"
            extra += ")"
        out.append(f"{key} = {e.value}{extra}")
    return out


def group_order(group: str) -> tuple[Any, ...]:
    """General first, then G53, G54..G59, G159=7.., clamp groups, then families by name."""
    if group == "general":
        return (0, 0, "")
    m = re.match(r"G\d+ \(G159=(\d+)\)|G159=(\d+)", group)
    if m:
        return (1, int(m.group(1) if m.group(1) is not None else m.group(2)), "")
    m = re.match(r"clamp group (\d+)", group)
    if m:
        return (2, int(m.group(1)), "")
    return (3, 0, group)

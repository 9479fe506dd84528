"""Hover: what zero knows about the parameter under the cursor, and what the controller makes
of the value written there.

On a key or value of a list (or of its YAML/TOML form), on a ``P-XXXX-nnnnn`` ID anywhere
(a reference value, a ``( P-…`` annotation, ``#MACHINE DATA``) and on the key of an
``AXPARAM="key value"``: the parameter's facts as ``zero param`` prints them (ID, type,
range, default, unit, indices, symbols, meaning — the user's ``CncParaDesc.xml`` text with
``param-desc``), preceded by the value read for the parameter (in mm/° for a length or
angle, the meaning of a symbol or of an enumerated value), the range evaluated with the
values it refers to, and, on a machine, the effective value and where it comes from.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from lsprotocol import types

from zero.catalog.ids import length_text
from zero.catalog.ranges import Number, format_number
from zero.catalog.registry import KINDS, ParamSpec, Registry
from zero.catalog.values import ListValues, bind, read_value, rotary
from zero.forms import LIST, PROGRAM, STRUCTURED, format_of
from zero.lists.model import Comment, Entry, format_key, parse_key
from zero.machine.effective import Origin, canonical, scope_values
from zero.output.docs import param_text
from zero.records import Record, replace
from zero.server.documents import Analysis, file_position

_ID = re.compile(r"P-[A-Z]{4}-[0-9]{5}(?:\.([0-9]+))?")
_AXPARAM = re.compile(r'AXPARAM\s*+=?\s*+"([^"\s]*+)', re.IGNORECASE)
_MACHINE_DATA = re.compile(r"#\s*MACHINE\s+DATA\b", re.IGNORECASE)
MACHINE_DATA_TEXT = (
    "**#MACHINE DATA** — write axis parameters from the NC program\n\n"
    "```text\n#MACHINE DATA [SYN] [AX=<name> | AXNR=<n>  P-AXIS-<id>[.<i>]=<value> | "
    "AXPARAM=\"<key> <value>\" [WAIT]]\n```\n"
    "One axis (`AX=` or a positive `AXNR=`), a parameter ID `#MACHINE DATA` accepts as a keyword or an "
    "`AXPARAM` key and value valid for the axis list, `WAIT` only with `SYN` (rule N001).")


class Target(Record):
    """What the cursor is on: a parameter, as a key (with indices) and maybe an entry."""

    spec: ParamSpec
    key: str | None = None  # as written, with indices
    indices: tuple[int, ...] = ()
    entry: Entry | None = None
    alias: str | None = None  # the undocumented spelling written, where it is one
    start: int = 0  # 0-based columns of what is hovered
    end: int = 0
    values: ListValues | None = None  # the list the entry is in


def _id_at(line: str, col: int, registry: Registry) -> Target | None:
    for m in _ID.finditer(line):
        if m.start() <= col <= m.end():
            pid = m.group(0).split(".", 1)[0]
            spec = registry.get(pid)
            if spec is not None:
                index = (int(m.group(1)),) if m.group(1) else ()
                key = format_key(spec.key, index) if spec.key and index else spec.key
                return Target(spec, key, index, start=m.start(), end=m.end())
    return None


def _spec_of(registry: Registry, key: str, kind: str | None) -> tuple[ParamSpec | None, bool]:
    parsed = parse_key(key)  # bound as every reader of values binds it (an alias, another release's spelling)
    hit = bind(registry, parsed.pattern, kind) if parsed is not None else None
    return hit if hit is not None else (None, False)


def _entry_target(entry: Entry, registry: Registry, kind: str | None) -> Target | None:
    if entry.key is None:
        return None
    spec, via_alias = _spec_of(registry, entry.key_text, kind)
    if spec is None:
        return None
    return Target(spec, entry.key_text, entry.key.indices, entry, entry.key_text if via_alias else None,
                  entry.key_start, max(entry.value_end, entry.key_end))


def target_at(a: Analysis, line: int, col: int) -> Target | None:
    """The parameter at 0-based ``line`` and code-point ``col`` of the document."""
    text = a.text.line(line)
    place = a.place(line, col) if a.form == LIST else None
    if place is None or not place.element or place.column > 0:  # an XML element's name: the ID of its entry
        hit = _id_at(text, col, a.registry)
        if hit is not None:
            return hit
    if a.form == LIST:
        if place is None or place.line >= len(place.values.doc.items):
            return None
        values = place.values
        item = values.doc.items[place.line]
        if isinstance(item, Comment) and item.commented_out is not None:
            item = item.commented_out
        t = _entry_target(item, a.registry, values.kind) if isinstance(item, Entry) else None
        if t is None:
            return None
        _, start = file_position(values.doc, place.line, t.start)
        _, end = file_position(values.doc, place.line, t.end, end=True)
        return replace(t, start=start, end=max(start, end), values=values)
    if a.form == PROGRAM:
        for m in _AXPARAM.finditer(text):
            if m.start(1) <= col <= m.end(1) and m.group(1):
                spec, via_alias = _spec_of(a.registry, m.group(1), "AXIS")
                key = parse_key(m.group(1))
                if spec is not None and key is not None:
                    return Target(spec, m.group(1), key.indices, alias=m.group(1) if via_alias else None,
                                  start=m.start(1), end=m.end(1))
        return None
    if a.form == STRUCTURED and a.result is not None:
        return _structured_target(a, line)
    return None


def _structured_target(a: Analysis, line: int) -> Target | None:
    """The parameter on a line of a YAML/TOML form (the leaf read there)."""
    from zero.structured.formats import read_tree  # start-up: only for hovers in YAML/TOML

    fmt = format_of(a.name)
    if fmt is None:
        return None
    tree = read_tree(a.data, fmt, a.registry, a.name)
    leaf = next((x for x in tree.leaves if x.line == line + 1), None)
    if leaf is None:
        return None
    spec, via_alias = _spec_of(a.registry, leaf.key, a.result.kind if a.result else None)
    key = parse_key(leaf.key)
    if spec is None or key is None:
        return None
    col = (leaf.column or 1) - 1
    return Target(spec, leaf.key, key.indices, alias=leaf.key if via_alias else None, start=col,
                  end=col + len(str(leaf.value)))


def _rotary(values: ListValues | None) -> bool | None:
    """Whether lengths of this list are degrees: known in an axis list from `kenngr.achs_typ`."""
    return rotary(values) if values is not None else None


def _value_lines(t: Target, values: ListValues | None) -> list[str]:
    """What the controller reads from the value written."""
    e = t.entry
    if e is None or e.value_kind is None:
        return []
    spec = t.spec
    v = read_value(spec, e)
    out = [f"value `{e.value}`"]
    number = v.number
    if v.ref is not None and values is not None:
        rid, ridx = v.ref
        number = values.number_of(rid, (ridx,) if ridx is not None else ())
        out[0] += f": the value of {rid}{'' if ridx is None else f' element {ridx}'}"
        out[0] += f" = {format_number(number)}" if number is not None else " (not known here)"
    if v.problem is not None:
        out[0] += " — the controller does not take it (see the finding)"
        return out
    if number is not None and spec.is_length:
        out.append(f"= {length_text(number, _rotary(values))}")
    if number is not None and spec.symbols:
        names = [name for name, val in spec.symbols if val == number]
        if names and e.value not in names:
            out.append(f"= {' | '.join(names)}")
        elif e.value in spec.symbol_names and not e.value.lstrip("-").isdigit():
            out.append(f"= {format_number(number)}")
    if isinstance(number, int) and spec.enum:
        if spec.enum_flags:
            bits = [f"{v} {label}".strip() for v, label in spec.enum_items() if v and number & v]
            out.append("— bits set: " + (", ".join(bits) if bits else "none"))
        else:
            meaning = next((label for v, label in spec.enum_items() if v == number), None)
            if meaning:
                out.append(f"= {meaning}")
            elif meaning is None:
                out.append("— not one of the values the catalogue lists")
    return out


def _range_lines(t: Target, values: ListValues | None, registry: Registry) -> list[str]:
    """The range with the values it refers to, as they are in this list."""
    rng = registry.range_of(t.spec)
    if rng is None or not rng.refs or values is None:
        return []

    def resolve(pid: str, idx: int | None) -> Number | None:
        return values.number_of(pid, (idx,) if idx is not None else t.indices)

    bounds = rng.evaluate(resolve)
    parts = []
    if bounds.low is not None:
        parts.append(f"{format_number(bounds.low)} {'<' if bounds.low_strict else '≤'} ")
    parts.append("x")
    if bounds.high is not None:
        parts.append(f" {'<' if bounds.high_strict else '≤'} {format_number(bounds.high)}")
    out = [f"range here: `{''.join(parts)}` (`{rng}`)"]
    for r in rng.refs:
        spec = registry.get(r.id)
        if spec is None:
            continue
        dims = len(spec.dims)
        idx = ((r.index,) if r.index is not None else t.indices) + (0,) * dims
        key = format_key(spec.key or r.id, idx[:dims])
        where = values.value_of(r.id, idx[:dims])
        n = values.number_of(r.id, idx[:dims])
        shown = format_number(n) if n is not None else "unknown"
        layer = values.layer_of(r.id, idx[:dims])
        if where is None or layer is None:
            source = "not set: the catalogue default"
        else:
            line = file_position(layer.doc, where.entry.line - 1, 0)[0] + 1  # a TwinCAT export's own line
            source = f"line {line}" if layer is values else f"default list {Path(layer.doc.path).name}:{line}"
        out.append(f"- `{key}` = {shown} ({r.id}, {source})")
    return out


def machine_lines(a: Analysis, t: Target) -> list[str]:
    """The effective value on the machine and the layers under it (``zero explain``)."""
    lf = a.machine_list()
    if lf is None or t.entry is None or t.entry.key is None:
        return []
    key = canonical(lf.values, t.entry)
    escaped = key.replace("[", "[[]")  # the key as a literal pattern
    scope = scope_values(lf.key, lf, [escaped], explain=True)

    def where(origin: Origin) -> str:
        if origin.path is None:
            return origin.source
        if os.path.realpath(origin.path) == os.path.realpath(lf.path):
            return f"this list, line {origin.line}"
        return f"{origin.source} {Path(origin.path).name}:{origin.line}"

    out = []
    for v in scope.values:
        out.append(f"on the machine ({lf.key}): `{v.value}` from {where(v.origin)}")
        out.extend(f"- {where(o)}: `{val}`" for val, o in v.layers if val is not None and o != v.origin)
    return out


def hover_text(a: Analysis, t: Target) -> str:
    on_machine = a.machine_list()  # with the default list under this one, where the machine has one
    values = on_machine.values if on_machine is not None else (t.values or (a.values() if a.form == LIST else None))
    spec = t.spec
    kind = KINDS.get(spec.kind, (spec.kind, spec.kind))[1]
    head = f"**{t.key or spec.key or spec.id}** — {spec.id}, {kind}"
    lines = [head]
    if t.alias is not None:
        lines.append(f"`{t.alias}` is an undocumented spelling of `{spec.key}` (R002)")
    value = _value_lines(t, values)
    if value:
        lines.append(" ".join(value))
    for block in (_range_lines(t, values, a.registry), machine_lines(a, t)):
        if block:
            lines.append("\n".join(block))
    lines.append(f"```text\n{param_text(spec, a.registry)}```")
    return "\n\n".join(lines)


def hover(a: Analysis, line: int, character: int) -> types.Hover | None:
    col = a.text.column(line, character)
    text = a.text.line(line)
    if a.form == PROGRAM:
        m = _MACHINE_DATA.search(text)
        if m is not None and m.start() <= col <= m.end():
            return types.Hover(types.MarkupContent(types.MarkupKind.Markdown, MACHINE_DATA_TEXT))
    t = target_at(a, line, col)
    if t is None:
        return None
    rng = types.Range(types.Position(line, a.text.character(line, t.start)),
                      types.Position(line, a.text.character(line, t.end)))
    return types.Hover(types.MarkupContent(types.MarkupKind.Markdown, hover_text(a, t)), rng)

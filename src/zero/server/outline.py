"""Document symbols (the outline), folding ranges, document links and go to definition.

The outline groups a list's entries as its keys do: ``np_grp[1]`` (G54) → ``achse[0]`` →
``versch``, ``kenngr`` → ``swe_pos``, at most two levels of groups; a YAML/TOML form the
same by the keys of its leaves; an NC program lists its ``#MACHINE DATA`` blocks and
programmed soft limits (G98/G99).

Go to definition: on a start-up list's reference (``achs_mds[0]  ./listen/achse_x.lis``) the
list file, resolved as the controller resolves it (:data:`zero.machine.model.REFERENCES`,
the working directory, ``[tool.zero.machine]`` overrides); on a value that refers to another
parameter (``P-AXIS-00212.0``) the entry that sets it, in this list or the default list under it.

Document links: every list a start-up list names, on the path as written, to the file the
controller would open (resolved as for go to definition); a path whose file does not exist has
no link (X005 says so). Folding: a block of two or more consecutive ``#`` comment lines, and a
run of entries whose keys share their first member (``np_grp[1]``, ``kenngr``), within it a run
sharing the second (``np_grp[1].achse[0]``), as the outline groups them.
"""

from __future__ import annotations

from pathlib import Path

import attrs
from lsprotocol import types

from zero.catalog.ids import g_code_with_index
from zero.catalog.registry import KINDS
from zero.catalog.values import ListValues
from zero.errors import ZeroError
from zero.files import read_file
from zero.forms import LIST, PROGRAM, STRUCTURED, TWINCAT, format_of, is_project
from zero.lists.model import Entry, ValueKind, parse_key
from zero.machine.tsproj import project_blocks
from zero.markup.tsproj import VIRTUAL_RE
from zero.records import Record, field
from zero.server.documents import Analysis, file_position
from zero.server.findings import line_range
from zero.server.positions import uri_of

_KINDS = (types.SymbolKind.Namespace, types.SymbolKind.Object)


class _Group(Record):
    name: str
    detail: str | None
    level: int
    symbols: list[types.DocumentSymbol] = field(default_factory=list)
    groups: dict[str, _Group] = field(default_factory=dict)
    order: list[_Group | types.DocumentSymbol] = field(default_factory=list)
    first: int = 1 << 30
    last: int = -1


def _segments(key: str) -> list[str]:
    """``np_grp[1].achse[0].versch`` → ``["np_grp[1]", "achse[0]", "versch"]``."""
    return key.split(".")


def _detail(segment: str, kind: str | None, level: int) -> str | None:
    parsed = parse_key(segment)
    if kind == "ZERO" and level == 0 and parsed is not None and parsed.pattern == "np_grp[]" and parsed.indices:
        return g_code_with_index(parsed.indices[0])
    return None


def _build(group: _Group) -> list[types.DocumentSymbol]:
    out = []
    for item in group.order:
        if isinstance(item, types.DocumentSymbol):
            out.append(item)
            continue
        children = _build(item)
        start = min((c.range.start for c in children), key=lambda p: (p.line, p.character))
        end = max((c.range.end for c in children), key=lambda p: (p.line, p.character))
        rng = types.Range(start, end)
        out.append(types.DocumentSymbol(item.name, _KINDS[min(item.level, 1)], rng, children[0].selection_range,
                                        detail=item.detail, children=children))
    return out


def _outline(rows: list[tuple[str, str, types.Range, types.Range]], kind: str | None) -> list[types.DocumentSymbol]:
    """Symbols from (key, value, line range, key range) rows, grouped by the key's first members."""
    root = _Group("", None, -1)
    for key, value, rng, sel in rows:
        parts = _segments(key)
        group = root
        for level, segment in enumerate(parts[:-1][:2]):
            sub = group.groups.get(segment)
            if sub is None:
                sub = group.groups[segment] = _Group(segment, _detail(segment, kind, level), level)
                group.order.append(sub)
            group = sub
        name = ".".join(parts[min(len(parts) - 1, 2):])
        group.order.append(types.DocumentSymbol(name, types.SymbolKind.Property, rng, sel, detail=value))
    return _build(root)


def _list_rows(a: Analysis, values: ListValues) -> list[tuple[str, str, types.Range, types.Range]]:
    doc = values.doc
    rows = []
    for e in doc.entries:
        index, start, end = e.line - 1, e.key_start, e.key_end
        if doc.origin is not None:  # an XML list (the element's name) or a list in a TwinCAT export
            index, start = file_position(doc, index, start)
            end = max(start, file_position(doc, e.line - 1, end, end=True)[1])
        sel = types.Range(types.Position(index, a.text.character(index, start)),
                          types.Position(index, a.text.character(index, end)))
        rows.append((e.key_text, e.value, line_range(a.text, index), sel))
    return rows


def _structured_rows(a: Analysis) -> list[tuple[str, str, types.Range, types.Range]]:
    from zero.structured.formats import read_tree  # start-up: only for outlines of YAML/TOML

    fmt = format_of(a.name)
    if fmt is None or a.result is None:
        return []
    rows = []
    for leaf in read_tree(a.data, fmt, a.registry, a.name).leaves:
        if leaf.line is None:
            continue
        rng = line_range(a.text, leaf.line - 1)
        rows.append((leaf.key, str(leaf.value), rng, rng))
    return rows


def _program_symbols(a: Analysis) -> list[types.DocumentSymbol]:
    from zero.nc.program import read_program  # start-up: only for outlines of NC programs

    program = read_program(a.data, a.name, a.registry)
    out = []
    for md in program.machine_data:
        index = md.line - 1
        rng = line_range(a.text, index)
        sel = types.Range(types.Position(index, a.text.character(index, md.start)),
                          types.Position(index, a.text.character(index, md.end)))
        axis = f"AX={md.axis}" if md.axis else (f"AXNR={md.axnr}" if md.axnr else "no axis")
        writes = ", ".join(w for w, *_ in md.writes)
        out.append(types.DocumentSymbol(f"#MACHINE DATA {axis}", types.SymbolKind.Event, rng, sel, detail=writes))
    for limit in program.limits:
        index = limit.line - 1
        rng = line_range(a.text, index)
        sel = types.Range(types.Position(index, a.text.character(index, limit.start)),
                          types.Position(index, a.text.character(index, limit.end)))
        g = "G99" if limit.positive else "G98"
        out.append(types.DocumentSymbol(f"{g} {limit.axis}", types.SymbolKind.Constant, rng, sel,
                                        detail=f"{limit.value:g}" + (" (G91)" if limit.relative else "")))
    out.sort(key=lambda s: (s.range.start.line, s.range.start.character))
    return out


def document_symbols(a: Analysis) -> list[types.DocumentSymbol]:
    """The outline, once per version of the text (built without attrs' validation of each value:
    a 6,208-entry list makes 9,411 symbols of values made here, and the checks were half the time)."""
    hit = a.cache.get("symbols")
    if isinstance(hit, list):
        return hit
    with attrs.validators.disabled():
        symbols = _document_symbols(a)
    a.cache["symbols"] = symbols
    return symbols


def _document_symbols(a: Analysis) -> list[types.DocumentSymbol]:
    if a.form == LIST and a.markup == TWINCAT:  # a symbol for each list of the export, its entries below
        out = []
        for element, values in a.lists():
            children = _outline(_list_rows(a, values), values.kind)
            if children:
                start = min((c.range.start for c in children), key=lambda p: (p.line, p.character))
                end = max((c.range.end for c in children), key=lambda p: (p.line, p.character))
                detail = KINDS[values.kind][1] if values.kind in KINDS else None
                out.append(types.DocumentSymbol(element, types.SymbolKind.Module, types.Range(start, end),
                                                children[0].selection_range, detail=detail, children=children))
        return out
    if a.form == LIST:
        lists = a.lists()
        return _outline(_list_rows(a, lists[0][1]) if lists else [], a.result.kind if a.result is not None else None)
    if a.form == STRUCTURED:
        return _outline(_structured_rows(a), a.result.kind if a.result is not None else None)
    if a.form == PROGRAM:
        return _program_symbols(a)
    return []


def _reference_target(a: Analysis, entry: Entry) -> Path | None:
    """The list file a start-up list's entry names, where the controller would look for it (as the
    resolver resolves the machine: its working directory and list overrides)."""
    return a.references.get(entry.key_text)


def definition(a: Analysis, line: int, character: int) -> list[types.Location]:
    if a.form != LIST:
        return []
    place = a.place(line, a.text.column(line, character))
    if place is None or place.line >= len(place.values.doc.items):
        return []
    values = place.values
    entry = values.doc.items[place.line]
    if not isinstance(entry, Entry):
        return []
    col = place.column
    if entry.value_kind is ValueKind.REF and entry.value_start <= col <= entry.value_end:
        rid, _, ridx = entry.value.partition(".")
        on_machine = a.machine_list()
        layers = on_machine.values if on_machine is not None else values  # with the default list under it
        hit = layers.value_of(rid, (int(ridx),) if ridx.isdigit() else ())
        layer = layers.layer_of(rid, (int(ridx),) if ridx.isdigit() else ())
        if layer is layers:
            layer = values
        if hit is None or layer is None:
            return []
        path = Path(layer.doc.path)
        uri = a.uri if layer is values else uri_of(path)
        index = file_position(layer.doc, hit.entry.line - 1, 0)[0]  # the line of the XML file
        rng = types.Range(types.Position(index, 0), types.Position(index, 0)) if layer is not values else \
            line_range(a.text, index)
        return [types.Location(uri, rng)]
    target = _reference_target(a, entry)
    if target is None or not target.is_file():
        return []
    return [types.Location(uri_of(target), types.Range(types.Position(0, 0), types.Position(0, 0)))]


# ------------------------------------------------------------------ links, folding


def _virtual_links(a: Analysis) -> list[types.DocumentLink]:
    """In a TwinCAT project: each ``tc_virtual_N\\`` reference of its start-up list linked to the
    ``<Data … Offset="N">`` block it names (in the project or one of its independent project files),
    never to a path on disk; a reference no block or two blocks answer gets no link (X005 says why)."""
    if a.path is None or not is_project(a.path):
        return []
    me = a.path
    try:
        blocks, _ = project_blocks(me, lambda p: a.data if p == me else read_file(p))
    except ZeroError:
        return []
    by_offset: dict[int, list[tuple[Path, int]]] = {}
    for f in blocks:
        if f.block.offset is not None:
            by_offset.setdefault(f.block.offset, []).append((f.path, f.line))
    out = []
    for _, values in a.lists():
        doc = values.doc
        if doc.origin is None or doc.origin.kind != "STUP":
            continue
        for e in doc.entries:
            m = VIRTUAL_RE.match(e.value)
            hits = by_offset.get(int(m.group(1)), []) if m is not None else []
            if len(hits) != 1 or e.value_end <= e.value_start:
                continue
            path, target_line = hits[0]
            uri = a.uri if path == me else uri_of(path)
            line, start = file_position(doc, e.line - 1, e.value_start)
            end = max(start, file_position(doc, e.line - 1, e.value_end, end=True)[1])
            rng = types.Range(types.Position(line, a.text.character(line, start)),
                              types.Position(line, a.text.character(line, end)))
            out.append(types.DocumentLink(rng, target=f"{uri}#L{target_line}",
                                          tooltip=f"{e.key_text}: {path.name} line {target_line}"))
    return out


def document_links(a: Analysis) -> list[types.DocumentLink]:
    if a.form == LIST and a.path is not None and is_project(a.path):
        return _virtual_links(a)
    if a.form != LIST or not a.references:
        return []
    out = []
    for _, values in a.lists():
        doc = values.doc
        for e in doc.entries:
            target = a.references.get(e.key_text)
            if target is None or not target.is_file() or e.value_end <= e.value_start:
                continue
            line, start = file_position(doc, e.line - 1, e.value_start)
            end = max(start, file_position(doc, e.line - 1, e.value_end, end=True)[1])
            rng = types.Range(types.Position(line, a.text.character(line, start)),
                              types.Position(line, a.text.character(line, end)))
            out.append(types.DocumentLink(rng, target=uri_of(target), tooltip=f"{e.key_text}: {target}"))
    return out


def _comment_blocks(a: Analysis) -> list[types.FoldingRange]:
    out = []
    start: int | None = None
    lines = a.text.lines
    for i in range(len(lines) + 1):
        is_comment = i < len(lines) and a.text.line(i).lstrip().startswith("#")
        if is_comment and start is None:
            start = i
        elif not is_comment and start is not None:
            if i - 1 > start:
                out.append(types.FoldingRange(start, i - 1, kind=types.FoldingRangeKind.Comment))
            start = None
    return out


def _key_groups(rows: list[tuple[int, list[str]]], level: int) -> list[types.FoldingRange]:
    """Runs of rows (0-based line, key members) sharing member ``level``; then within each run the same
    one level down (two levels, as the outline)."""
    out: list[types.FoldingRange] = []
    i = 0
    while i < len(rows):
        j = i
        head = rows[i][1][level] if len(rows[i][1]) > level + 1 else None
        while head is not None and j + 1 < len(rows) and len(rows[j + 1][1]) > level + 1 \
                and rows[j + 1][1][level] == head:
            j += 1
        if head is not None and rows[j][0] > rows[i][0]:
            out.append(types.FoldingRange(rows[i][0], rows[j][0], kind=types.FoldingRangeKind.Region))
            if level == 0:
                inner = _key_groups(rows[i:j + 1], 1)
                out.extend(r for r in inner if (r.start_line, r.end_line) != (rows[i][0], rows[j][0]))
        i = j + 1
    return out


def folding_ranges(a: Analysis) -> list[types.FoldingRange]:
    if a.form != LIST:
        return []
    out = _comment_blocks(a) if a.markup is None else []
    for _, values in a.lists():
        doc = values.doc
        rows = []
        for e in doc.items:
            if isinstance(e, Entry) and e.key_text:
                line = file_position(doc, e.line - 1, e.key_start)[0]
                rows.append((line, e.key_text.split(".")))
        out.extend(_key_groups(rows, 0))
    out.sort(key=lambda r: (r.start_line, -r.end_line))
    return out

"""Completion and signature help.

In a list: the keys the catalogue documents for the list's kind, with their indices filled
from what is typed (``np_grp[1].achse[0].`` offers ``versch`` and ``inaktiv`` of that axis)
and otherwise from the entry above (so that ``inaktiv`` follows ``versch`` of the same
axis, and a key already set moves on to the next element); after a key, its symbols, the
values the catalogue lists (with their meaning from the user's ``CncParaDesc.xml``), 0/1
for a BOOLEAN and the default. In an NC program: the parts of ``#MACHINE DATA``, the
parameter IDs it accepts, the axis list's keys inside ``AXPARAM="…"``, and signature help
for the block. The structured forms are left to the YAML/TOML language servers with
``zero schema``.
"""

from __future__ import annotations

import re

from lsprotocol import types

from zero.catalog.registry import ParamSpec, Registry
from zero.catalog.values import ListValues, bind
from zero.forms import LIST, PROGRAM, XML_LIST, XML_ROOTS, root_of
from zero.lists.model import Entry, parse_key
from zero.markup.lists import escape, key_of
from zero.output.docs import param_text
from zero.server.documents import Analysis, Place

_KEY_TYPED = re.compile(r"([ \t]*)([A-Za-z0-9_\[\].]*)")
_VALUE_TYPED = re.compile(r"[ \t]*([A-Za-z_][A-Za-z0-9_\[\].]*)[ \t]+([^\s|]*)")
_INDEX = re.compile(r"\[([0-9]*)\]?")
_MACHINE_DATA = re.compile(r"#\s*MACHINE\s+DATA\b", re.IGNORECASE)
_HASH_TYPED = re.compile(r"(?:^|\s)#[A-Za-z ]*$")  # `#MA` typed, at the start or after `N10 `
_XML_NAME_TYPED = re.compile(r"<(P-[A-Z0-9.-]*)$")  # `<P-AX` typed in an XML list
_XML_VALUE_TYPED = re.compile(r'<(P-[A-Z]{4}-[0-9]{5})(?:\.[0-9]+)*\s+Value\s*=\s*"([^"]*)$')
_XML_NAME = re.compile(r"<(P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)*)[\s/>]")
_AXPARAM_OPEN = re.compile(r'AXPARAM\s*+=?\s*+"([^"\s]*+)$', re.IGNORECASE)
MACHINE_DATA_LABEL = ('#MACHINE DATA [SYN] [AX=<name> | AXNR=<n>  P-AXIS-<id>[.<i>]=<value> | '
                      'AXPARAM="<key> <value>" [WAIT]]')
_PARTS = ("SYN", "AX=<name> | AXNR=<n>", 'P-AXIS-<id>[.<i>]=<value> | AXPARAM="<key> <value>"', "WAIT")
TRIGGERS = [".", "[", "=", '"', " "]

_keys_cache: dict[tuple[int, str | None], list[ParamSpec]] = {}


def keys_of(registry: Registry, kind: str | None) -> list[ParamSpec]:
    """The parameters with a key in lists of ``kind`` (every kind for None), sorted by key."""
    hit = _keys_cache.get((id(registry), kind))
    if hit is None:
        specs = (registry.specs[pid] for pid in registry.specs)
        hit = sorted((s for s in specs if s.key and (kind is None or s.kind == kind)), key=lambda s: s.key or "")
        if len(_keys_cache) > 64:
            _keys_cache.clear()
        _keys_cache[(id(registry), kind)] = hit
    return hit


# Where a word starts for the common clients: after these characters, which are neither in Neovim's
# default 'iskeyword' nor Helix's word characters nor Emacs's word or symbol characters of a plain mode
# (fundamental-, text- or prog-mode). Emacs takes `-`, `+`, `=`, `<`, `>`, `/`, `*`, `&`, `|`, `$`, `%`
# into a symbol, so no word ends there: `P-AXIS-002` is one (Neovim, seeing `002`, starts at the
# edit's range all the same; Helix matches `002` within the label fuzzily).
_WORD_END = re.compile(r"""[\s!"#'(),.:;?@\[\\\]^`{}~]""")


class _Items:
    """Completion items replacing the text typed from ``start`` to the cursor.

    The clients complete the word before the cursor as they see it: Neovim's omnifunc (0.7 to 0.9)
    starts at the keyword before the cursor when an item has a ``filterText``, else at the start of
    the items' ``textEdit``, and keeps the items whose text starts with what is typed from there; eglot
    matches the symbol before the cursor against the label; Helix and VS Code filter with the word
    before the cursor. So an item starts where that word starts, after the last `.`, `[`, `]` (or `#`,
    `"`, blank) typed: after ``np_grp[1].achse[0].ve`` the item is ``versch``, its label, its text and
    its edit's range (from the `v`) alike, and no ``filterText`` (the label is). An item whose text
    does not continue what is typed before that word (``np_grp[]`` typed, ``np_grp[1]`` offered)
    replaces the whole of it instead."""

    def __init__(self, a: Analysis, line: int, start: int, end: int, snippets: bool) -> None:
        typed = a.text.line(line)[start:end]
        cut = max((m.end() for m in _WORD_END.finditer(typed)), default=0)
        self.prefix = typed[:cut].lower()
        self.range = types.Range(types.Position(line, a.text.character(line, start)),
                                 types.Position(line, a.text.character(line, end)))
        self.word = types.Range(types.Position(line, a.text.character(line, start + cut)), self.range.end)
        self.snippets = snippets
        self.items: list[types.CompletionItem] = []

    def add(self, label: str, kind: types.CompletionItemKind, detail: str | None = None, insert: str | None = None,
            sort: str | None = None, data: object = None, documentation: str | None = None,
            snippet: bool = False) -> None:
        snippet = snippet and self.snippets
        text = insert if insert is not None else label
        where = self.range
        n = len(self.prefix)
        if (n and len(label) > n and label[:n].lower() == self.prefix and text[:n].lower() == self.prefix
                and not (snippet and ("$" in text[:n] or "\\" in text[:n]))):
            label, text, where = label[n:], text[n:], self.word
        self.items.append(types.CompletionItem(
            label, kind=kind, detail=detail, sort_text=sort, data=data,
            documentation=types.MarkupContent(types.MarkupKind.Markdown, documentation) if documentation else None,
            insert_text_format=types.InsertTextFormat.Snippet if snippet else types.InsertTextFormat.PlainText,
            text_edit=types.TextEdit(where, text)))


def _fill(spec: ParamSpec, typed: list[int | None], previous: tuple[int, ...], taken: set[str],
          snippets: bool) -> tuple[str, str]:
    """The key of ``spec`` with its index slots filled (typed, else from the entry above, else the
    first index), moved on to the next element while that key is set already; and its snippet."""
    assert spec.key is not None
    slots = spec.key.count("[]")
    values: list[int] = []
    for i in range(slots):
        base = spec.index_first(i)
        given = typed[i] if i < len(typed) else None
        values.append(given if given is not None else (previous[i] if i < len(previous) else base))
    fixed = {i for i in range(slots) if i < len(typed) and typed[i] is not None}
    free = [i for i in range(slots) if i not in fixed]

    def text(vals: list[int], snippet: bool) -> str:
        parts = spec.key.split("[]")  # type: ignore[union-attr]
        out = [parts[0]]
        n = 0
        for i, rest in enumerate(parts[1:]):
            if snippet and i in free:
                n += 1
                out.append(f"[${{{n}:{vals[i]}}}]")
            else:
                out.append(f"[{vals[i]}]")
            out.append(rest)
        return "".join(out)

    if free:  # a key set already: the next element of the last slot not typed
        last = free[-1]
        size = spec.dims[last] if last < len(spec.dims) else 0
        end = size + spec.index_first(last)
        for _ in range(64):
            if text(values, False) not in taken or (size and values[last] + 1 >= end):
                break
            values[last] += 1
    key = text(values, False)
    return key, (text(values, True) if snippets and free else key)


def _typed_indices(typed: str) -> tuple[str, list[int | None]]:
    """The typed key with its indices as the registry spells keys (``np_grp[].achse[].``), and the
    indices typed (None for an empty ``[]``)."""
    indices: list[int | None] = [int(m.group(1)) if m.group(1) else None for m in _INDEX.finditer(typed)]
    return _INDEX.sub("[]", typed), indices


def _previous_entry(values: ListValues | None, index: int, first: str) -> Entry | None:
    """The last entry above 0-based line ``index`` of the list whose key starts with ``first``."""
    if values is None:
        return None
    for item in reversed(values.doc.items[: min(index, len(values.doc.items))]):
        if isinstance(item, Entry) and item.key is not None and item.key.members[0] == first:
            return item
    return None


def _key_items(a: Analysis, where: Place, line: int, start: int, col: int, typed: str,
               snippets: bool) -> list[types.CompletionItem]:
    values = where.values
    kind = values.kind
    if kind is None:
        kind = a.registry.detect_kind((), a.name)
    pattern, indices = _typed_indices(typed)
    cut = max(pattern.rfind("."), pattern.rfind("]"))
    complete = pattern[: cut + 1].lower()  # the members typed completely
    taken = {e.key_text for e in values.doc.entries}
    items = _Items(a, line, start, col, snippets)
    for spec in keys_of(a.registry, kind):
        assert spec.key is not None
        if not spec.key.lower().startswith(complete):
            continue
        first = spec.key.split("[", 1)[0].split(".", 1)[0]
        above = _previous_entry(values, where.line, first) if "[]" in spec.key else None
        previous = above.key.indices if above is not None and above.key is not None else ()
        key, insert = _fill(spec, indices, previous, taken, snippets)
        if key in taken and "[]" not in spec.key:
            continue  # a key set already (again would be R007)
        items.add(key, types.CompletionItemKind.Field, f"{spec.id} · {spec.type} · default {spec.default_display}",
                  insert, sort=("1" if key in taken else "0") + key, data={"id": spec.id},
                  snippet=insert != key)
    return items.items


def _value_items(a: Analysis, kind: str | None, line: int, start: int, col: int,
                 key: str) -> list[types.CompletionItem]:
    parsed = parse_key(key)
    if parsed is None:
        return []
    hit = bind(a.registry, parsed.pattern, kind)  # as every reader of values binds it: another release's spelling too
    if hit is None:
        return []
    spec = hit[0]
    items = _Items(a, line, start, col, False)
    _spec_values(items, spec, a.registry)
    return items.items


def _xml_items(a: Analysis, line: int, col: int, snippets: bool) -> list[types.CompletionItem]:
    """In an XML list: the IDs of the list's kind after ``<P-`` (the element names, with the first
    index of each array, moved on past the elements set already), the values after ``Value="``. Read
    from the text alone: what is being typed is seldom well-formed XML."""
    text = a.text.line(line)
    before = text[:col]
    m = _XML_VALUE_TYPED.search(before)
    if m is not None:
        spec = a.registry.get(m.group(1))
        if spec is None:
            return []
        items = _Items(a, line, m.start(2), col, False)
        _spec_values(items, spec, a.registry)
        return items.items
    m = _XML_NAME_TYPED.search(before)
    if m is None:
        return []
    kind = XML_ROOTS.get(root_of(a.data) or "")
    values = a.values()
    if values is not None:
        taken = {e.key_text for e in values.doc.entries}
    else:  # the text as typed is no XML (yet): the elements written, as keys
        names = set(_XML_NAME.findall(a.text.source))
        taken = {key for key in (key_of(name, a.registry)[0] for name in names) if key is not None}
    items = _Items(a, line, m.start(1), col, snippets)
    bare = not text[col:].strip()  # nothing after the name: the element is written whole
    for spec in keys_of(a.registry, kind):
        assert spec.key is not None
        key, _ = _fill(spec, [], (), taken, False)
        parsed = parse_key(key)
        name = spec.id + "".join(f".{i}" for i in (parsed.indices if parsed is not None else ()))
        if key in taken and "[]" not in spec.key:
            continue  # an element set already (again would be R007)
        default = escape((spec.default or "").strip())
        insert = name
        if bare:
            shown = re.sub(r"([$}\\])", r"\\\1", default)
            insert += f' Value="${{1:{shown}}}" />' if snippets else f' Value="{default}" />'
        items.add(name, types.CompletionItemKind.Field, f"{key} · {spec.type} · default {spec.default_display}",
                  insert, sort=("1" if key in taken else "0") + name, data={"id": spec.id}, snippet=bare)
    return items.items


def _spec_values(items: _Items, spec: ParamSpec, registry: Registry) -> None:
    seen: set[str] = set()

    def add(label: str, detail: str, sort: str) -> None:
        if label not in seen:
            seen.add(label)
            items.add(label, types.CompletionItemKind.EnumMember if sort < "2" else types.CompletionItemKind.Value,
                      detail, sort=sort + label)

    for name, value in spec.symbols:
        add(name, f"{spec.id}: symbol" + (f" = {value}" if value is not None else ""), "0")
    for value, label in spec.enum_items():
        add(str(value), f"{spec.id}: " + (label or "a value the catalogue lists")
            + (" (bits: any combination)" if spec.enum_flags else ""), "1")
    rng = registry.range_of(spec)
    for allowed in (rng.allowed or ()) if rng is not None else ():
        text = str(int(allowed)) if isinstance(allowed, float) and allowed.is_integer() else str(allowed)
        add(text, f"{spec.id}: a value of the range {spec.range_text}", "1")
    if spec.type == "BOOLEAN":
        add("0", f"{spec.id}: FALSE", "1")
        add("1", f"{spec.id}: TRUE", "1")
    default = (spec.default or "").strip()
    if default and spec.default_display != "(none documented)":
        add(default, f"{spec.id}: the default", "2")


def _program_items(a: Analysis, line: int, col: int, snippets: bool) -> list[types.CompletionItem]:
    text = a.text.line(line)
    before = text[:col]
    m = _AXPARAM_OPEN.search(before)
    if m is not None:  # the key of AXPARAM="key value": the axis list's keys
        items = _Items(a, line, m.start(1), col, False)
        for spec in keys_of(a.registry, "AXIS"):
            assert spec.key is not None
            key = spec.key.replace("[]", "[0]")
            if not key.lower().startswith(items.prefix):
                continue  # another member than the one typed
            items.add(key, types.CompletionItemKind.Field, f"{spec.id} · {spec.type}", sort=key, data={"id": spec.id})
        return items.items
    md = _MACHINE_DATA.search(before)
    if md is None:
        hash_typed = _HASH_TYPED.search(before)
        if before != "" and hash_typed is None:
            return []
        start = before.index("#", hash_typed.start()) if hash_typed is not None else col
        items = _Items(a, line, start, col, snippets)
        items.add("#MACHINE DATA", types.CompletionItemKind.Snippet, "write axis parameters from the program",
                  "#MACHINE DATA [AX=${1:X} ${2:P-AXIS-00209}=${3:0}]" if snippets else "#MACHINE DATA [",
                  snippet=True)
        return items.items
    word = re.search(r"(?<![A-Za-z0-9_#=.-])[A-Za-z0-9_#=.-]*$", before)  # a run's start only: linear
    items = _Items(a, line, word.start() if word else col, col, snippets)
    if "[" not in before[md.end():]:
        items.add("SYN", types.CompletionItemKind.Keyword, "synchronise with the program (allows WAIT)")
        return items.items
    items.add("AX=", types.CompletionItemKind.Keyword, "the axis by its name")
    items.add("AXNR=", types.CompletionItemKind.Keyword, "the axis by its logical number (from 1)")
    items.add('AXPARAM="', types.CompletionItemKind.Keyword, 'an axis list entry: AXPARAM="<key> <value>"')
    items.add("WAIT", types.CompletionItemKind.Keyword, "wait until written (only with SYN)")
    for pid in sorted(a.registry.machine_data_ids()):
        found = a.registry.get(pid)
        if found is not None:
            items.add(f"{pid}=", types.CompletionItemKind.Field, f"{found.key or pid} · {found.type}",
                      data={"id": pid})
    return items.items


def completion(a: Analysis, line: int, character: int, snippets: bool) -> types.CompletionList:
    col = a.text.column(line, character)
    text = a.text.line(line)
    before = text[:col]
    items: list[types.CompletionItem] = []
    if a.form == LIST and a.markup == XML_LIST:
        items = _xml_items(a, line, col, snippets)
    elif a.form == LIST and (where := a.place(line, col)) is not None:
        before = text[where.shift:col]  # a list inside a TwinCAT export starts further right on its first line
        key = _KEY_TYPED.fullmatch(before)
        value = _VALUE_TYPED.fullmatch(before)
        if key is not None:
            items = _key_items(a, where, line, where.shift + len(key.group(1)), col, key.group(2), snippets)
        elif value is not None:
            items = _value_items(a, where.values.kind, line, where.shift + value.start(2), col, value.group(1))
    elif a.form == PROGRAM:
        items = _program_items(a, line, col, snippets)
    return types.CompletionList(is_incomplete=False, items=items)


def resolve(item: types.CompletionItem, registry: Registry) -> types.CompletionItem:
    """The parameter's facts as documentation (asked for when an item is shown)."""
    data = item.data if isinstance(item.data, dict) else {}
    spec = registry.get(str(data.get("id", "")))
    if spec is not None and item.documentation is None:
        item.documentation = types.MarkupContent(types.MarkupKind.Markdown,
                                                 f"```text\n{param_text(spec, registry)}```")
    return item


def _active(inside: str) -> int:
    """Which part of ``#MACHINE DATA`` the text typed inside the brackets is at."""
    words = inside.split()
    if not words or inside.endswith((" ", "[")):
        done = {w.split("=", 1)[0].upper() for w in words}
        return 3 if done & {"AXPARAM"} or any(w.upper().startswith("P-") for w in words) else (
            2 if done & {"AX", "AXNR"} else 1)
    last = words[-1].upper()
    if last.startswith("AX=") or last.startswith("AXNR") or last in ("AX", "A"):
        return 1
    if last.startswith("W"):
        return 3
    return 2


def signature_help(a: Analysis, line: int, character: int) -> types.SignatureHelp | None:
    """Help for ``#MACHINE DATA`` while it is typed in an NC program."""
    if a.form != PROGRAM:
        return None
    col = a.text.column(line, character)
    before = a.text.line(line)[:col]
    md = _MACHINE_DATA.search(before)
    if md is None:
        return None
    rest = before[md.end():]
    active = _active(rest.split("[", 1)[1]) if "[" in rest else 0
    params = [types.ParameterInformation(label=p) for p in _PARTS]
    sig = types.SignatureInformation(MACHINE_DATA_LABEL, documentation=types.MarkupContent(
        types.MarkupKind.Markdown, "One axis (`AX=` or a positive `AXNR=`), a parameter `#MACHINE DATA` accepts by "
        "ID or an `AXPARAM` key and value valid for the axis list, `WAIT` only with `SYN` (zero rule N001)."),
        parameters=params, active_parameter=active)
    return types.SignatureHelp([sig], active_signature=0, active_parameter=active)


__all__ = ["TRIGGERS", "completion", "keys_of", "resolve", "signature_help"]

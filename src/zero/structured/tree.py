"""The structured form of a list: leaves with comments, plus the layout record.

``from_document`` turns a tokenized list into a :class:`Tree`; ``to_list_text``
writes a tree back as list text. The YAML, TOML and JSON readers and writers
(:mod:`zero.structured.yaml`, ``toml``, ``json``) only move trees in and out of
those formats.

A tree holds three kinds of information:

* **data** — one :class:`Leaf` per key (``np_grp[1].achse[0].versch``), its value
  and the comments a person sees next to it (full-line comments and blank lines
  before it, the trailing comment after it, with its style);
* **tail** — the comment lines between the last entry and ``Ende``;
* **meta** — the ``_zero`` record: encoding, line endings, the value and comment
  columns, the ``Ende`` line, and only where the file deviates from that simple
  layout the exact text needed to write it back byte for byte (``layout``,
  ``before``, ``order``, ``shadowed`` …). A tree without meta is written in the
  canonical layout.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from zero.diagnostics import Span
from zero.errors import ZeroError
from zero.lists.encoding import declarable
from zero.lists.model import Blank, Comment, Document, End, Entry, Invalid
from zero.records import Record, field

if TYPE_CHECKING:  # start-up: a configuration file's TOML is read without the catalogue
    from zero.catalog.registry import Registry

Scalar = int | float | str

META_KEY = "_zero"
FORMAT_VERSION = 1
DEFAULT_VALUE_COLUMN = 54
MAX_DEPTH = 32  # key levels; real keys have at most six
COMMENT_GAP = 2  # spaces before a comment when no comment column is known

_MEMBER_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_INDEX_RE = re.compile(r"[0-9]+")
_FRAGMENT_RE = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)((?:\[[0-9]+\])*)")
# Characters a list line cannot carry through YAML/TOML: C0/C1 controls other
# than tab, DEL, lone surrogates (undecodable bytes) and Unicode line breaks.
_UNCARRIABLE_RE = re.compile(r"[\x00-\x08\x0a-\x1f\x7f-\x9f\u2028\u2029\ud800-\udfff]")


class Leaf(Record, eq=False):
    """One parameter in the structured form."""

    key: str  # as the list spells it: np_grp[1].achse[0].versch
    path: tuple[str, ...]  # ("np_grp", "1", "achse", "0", "versch"); digits = index
    value: Scalar
    before: list[str] = field(default_factory=list)  # comment / blank lines before it
    after: str | None = None  # trailing comment as written ("( P-ZERO-00003 ...")
    line: int | None = None  # where it was read (1-based), when the reader knows
    column: int | None = None
    native: str = "str"  # the reader's own type: int, float, str ("plain": YAML text without quotes)
    # the text of its key where the reader knows it: line, column, end line, end column (1-based, end
    # exclusive; a quoted key's text inside its quotes): where a finding about the key points
    key_at: tuple[int, int, int, int] | None = None


class Tree(Record, eq=False):
    leaves: list[Leaf]
    meta: dict[str, Any] = field(default_factory=dict)
    tail: list[str] = field(default_factory=list)
    path: str = "-"
    notes: list[str] = field(default_factory=list)  # what the conversion could not keep
    _nested: tuple[dict[str, Any], list[Leaf]] | None = field(default=None, repr=False)

    def nested(self) -> tuple[dict[str, Any], list[Leaf]]:
        """:func:`nest` of the leaves, computed once."""
        if self._nested is None:
            self._nested = nest(self.leaves)
        return self._nested


def source_span(leaf: Leaf, written: Document, span: Span) -> Span:
    """Where a finding lies in the YAML/TOML/JSON file ``leaf`` was read from, given its ``span``
    in ``written``, the list text the tree was written as (and linted): a finding within the key of
    the leaf's line (R001, R002, R010, R013: the key rules) on the key's text, any other on the
    value."""
    line = leaf.line or 1
    column = leaf.column or 1
    if leaf.key_at is not None and span.line == span.end_line and 0 < span.line <= len(written.items):
        e = written.items[span.line - 1]  # one item per line
        if (type(e) is Entry and e.line == span.line and e.key_start < e.key_end
                and e.key_start <= span.column - 1 and span.end_column - 1 <= e.key_end):
            return Span(*leaf.key_at)
    return Span(line, column, line, column + len(str(leaf.value)))


# --------------------------------------------------------------------------- keys


_SPLIT_RE = re.compile(r"[.\[\]]+")
_PLAIN_KEY_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:\[[0-9]+\])*(?:\.[A-Za-z_][A-Za-z0-9_]*(?:\[[0-9]+\])*)*")


# A plain key split after its first index: ``wz[17]`` + ``.laenge``; the tails repeat (a few dozen in a
# tool list of 114,000 keys), so each is checked and split once.
_HEAD_RE = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\[([0-9]+)\]")
_TAIL_RE = re.compile(r"(?:\[[0-9]+\])*(?:\.[A-Za-z_][A-Za-z0-9_]*(?:\[[0-9]+\])*)*")
_tails: dict[str, tuple[str, ...] | None] = {}


def split_key(key: str) -> tuple[str, ...] | None:
    """``np_grp[1].achse[0].versch`` → ``("np_grp", "1", "achse", "0", "versch")``."""
    head = _HEAD_RE.match(key)
    if head is not None:
        tail = key[head.end():]
        if tail in _tails:
            rest = _tails[tail]
        else:
            rest = tuple(filter(None, _SPLIT_RE.split(tail))) if _TAIL_RE.fullmatch(tail) else None
            if len(_tails) < 100_000:
                _tails[tail] = rest
        if rest is not None:  # the whole key is plain: what splitting it whole gives
            return (head.group(1), head.group(2), *rest)
    if _PLAIN_KEY_RE.fullmatch(key):
        return tuple(filter(None, _SPLIT_RE.split(key)))
    out: list[str] = []
    for part in key.split("."):
        m = _FRAGMENT_RE.fullmatch(part)
        if m is None:
            return None
        out.append(m.group(1))
        if m.group(2):
            out.extend(m.group(2)[1:-1].split("]["))
    return tuple(out)


def join_path(path: tuple[str, ...] | list[str]) -> str:
    """The inverse of :func:`split_key`."""
    parts: list[str] = []
    for seg in path:
        if seg.isdigit() and seg.isascii():
            parts.append(f"[{seg}]")
        else:
            parts.append(f".{seg}" if parts else seg)
    return "".join(parts)


def is_index(segment: str) -> bool:
    return segment.isascii() and segment.isdigit()


_segment_cache: dict[str, tuple[str, ...]] = {}
_SIMPLE_VALUE_RE = re.compile(r"[A-Za-z0-9_+\-][^\s\"|]*")


def path_from_segments(segments: list[str], where: str) -> tuple[str, ...]:
    """Validate the mapping keys on the way to a leaf; a segment may hold a dotted key."""
    out: list[str] = []
    for seg in segments:
        parts = _segment_cache.get(seg)
        if parts is None:
            parts = (seg,) if is_index(seg) else split_key(seg)
            if parts is None or not parts:
                raise ZeroError(f"`{seg}` is not a key or part of a key (name[index].name...)", where)
            if len(_segment_cache) < 100_000:
                _segment_cache[seg] = parts
        if not out and is_index(parts[0]):
            raise ZeroError(f"`{seg}` at the top: a key starts with a name, not an index", where)
        out.extend(parts)
    if len(out) > MAX_DEPTH:
        raise ZeroError(f"key has {len(out)} levels; zero converts keys of up to {MAX_DEPTH}", where)
    return tuple(out)


def structured_path(path: tuple[str, ...]) -> str:
    """How a leaf is addressed in YAML/TOML/JSON: ``np_grp.1.achse.0.versch``."""
    return ".".join(path)


# ------------------------------------------------------------------ nesting order


class _Node(Record):
    children: dict[str, _Node | Leaf] = field(default_factory=dict)


def nest(leaves: list[Leaf]) -> tuple[dict[str, Any], list[Leaf]]:
    """Nest leaves into mappings; return ``(root, flat)``.

    ``root`` maps segment → sub-mapping or :class:`Leaf`, children in first
    appearance. A leaf below another leaf's key (``a.b`` when ``a`` holds a value)
    cannot nest: it goes to ``flat`` and is written under its whole key at the
    top level, whatever the order of the two.
    """
    root: dict[str, Any] = {}
    for leaf in leaves:  # fast path: no key lies below another key's value
        node = root
        for seg in leaf.path[:-1]:
            nxt = node.get(seg)
            if nxt is None:
                nxt = node[seg] = {}
            elif not isinstance(nxt, dict):
                return _nest_with_flat(leaves)
            node = nxt
        if leaf.path[-1] in node:
            return _nest_with_flat(leaves)
        node[leaf.path[-1]] = leaf
    return root, []


def _nest_with_flat(leaves: list[Leaf]) -> tuple[dict[str, Any], list[Leaf]]:
    values = {leaf.path for leaf in leaves}
    root: dict[str, Any] = {}
    flat: list[Leaf] = []
    for leaf in leaves:
        p = leaf.path
        if any(p[:i] in values for i in range(1, len(p))):
            flat.append(leaf)
            continue
        node = root
        for seg in p[:-1]:
            nxt = node.get(seg)
            if nxt is None:
                nxt = node[seg] = {}
            node = nxt
        node[p[-1]] = leaf
    return root, flat


def dfs(root: dict[str, Any]) -> Iterator[Leaf]:
    """Leaves of a nested mapping in document order (iterative: no recursion)."""
    stack: list[Iterator[Any]] = [iter(root.values())]
    while stack:
        for child in stack[-1]:
            if isinstance(child, dict):
                stack.append(iter(child.values()))
                break
            yield child
        else:
            stack.pop()


# ------------------------------------------------------------- list → tree


def _check_carriable(doc: Document) -> None:
    for number, text in enumerate(doc.lines, 1):
        m = _UNCARRIABLE_RE.search(text)
        if m:
            ch = m.group()
            code = ord(ch)
            what = (f"undecodable byte 0x{code - 0xDC00:02X}" if 0xDC80 <= code <= 0xDCFF
                    else f"control character U+{code:04X}")
            raise ZeroError(
                f"{what}: YAML, TOML and JSON text cannot carry it; fix the line first "
                "(`zero lint` shows it)", doc.path, number, m.start() + 1)


def canonical_line(key: str, value: str, comment: str | None, value_column: int,
                   comment_column: int | None) -> str:
    s = key + " " * max(value_column - len(key), 1) + value
    if comment is not None:
        gap = max(comment_column - len(s), 1) if comment_column is not None else COMMENT_GAP
        s += " " * gap + comment
    return s


def _template(doc: Document, e: Entry) -> str:
    """The exact line with the value and comment replaced by ``{v}`` and ``{c}``."""
    s = doc.lines[e.line - 1]
    head = s[: e.value_start] + "{v}"
    if e.comment is None:
        return head + s[e.value_end:]
    core = e.comment.rstrip(" \t")
    return head + s[e.value_end: e.comment_start] + "{c}" + e.comment[len(core):]


def normalized(line: str) -> str:
    """A comment or blank line as YAML/TOML show it: without surrounding whitespace."""
    return line.strip()


_scalars: dict[tuple[str, str | None], tuple[Scalar, str]] = {}


def _scalar_from_list(value: str, spec_type: str | None) -> tuple[Scalar, str]:
    """A list value as the structured form holds it: int where exact, else text (values repeat: each
    distinct one read once)."""
    got = _scalars.get((value, spec_type))
    if got is None:
        got = _scalar_uncached(value, spec_type)
        if len(_scalars) < 65_536 and len(value) < 256:
            _scalars[(value, spec_type)] = got
    return got


def _scalar_uncached(value: str, spec_type: str | None) -> tuple[Scalar, str]:
    if spec_type != "STRING" and value.isascii() and (
            value.isdigit() or (value[:1] == "-" and value[1:].isdigit())):
        n = int(value) if len(value) < 4000 else None
        if n is not None and str(n) == value:
            return n, "int"
    if spec_type in ("REAL64", "REAL32") and re.fullmatch(r"-?[0-9]+\.[0-9]+", value):
        f = float(value)
        if repr(f) == value:
            return f, "float"
    return value, "str"


def from_document(doc: Document, registry: Registry, kind: str | None = None) -> Tree:
    """A list document as a tree; :class:`ZeroError` for what cannot be carried.

    The registry detects the list kind (unless given) and tells which values are numbers."""
    _check_carriable(doc)
    entries_all = [i for i in doc.items if type(i) is Entry and not i.after_end]
    if kind is None:
        kind = registry.kind_of(doc, entries_all)

    meta: dict[str, Any] = {"zero": FORMAT_VERSION}
    if kind:
        meta["kind"] = kind
    if doc.encoding != "utf-8":
        meta["encoding"] = doc.encoding
    if doc.bom:
        meta["bom"] = True
    newline = doc.newline
    if newline != "\n":
        meta["newline"] = newline
    notes: list[str] = []
    if "\r\n" in doc.endings and "\n" in doc.endings:
        notes.append(f"mixed line endings: the list is written back with {newline!r} throughout")
    if doc.endings and doc.endings[-1] == "":
        meta["final_newline"] = False

    vcols = Counter(e.value_start for e in entries_all if e.value)
    value_column = vcols.most_common(1)[0][0] if vcols else DEFAULT_VALUE_COLUMN
    ccols = Counter(e.comment_start for e in entries_all if e.comment is not None)
    comment_column = ccols.most_common(1)[0][0] if ccols else None
    meta["value_column"] = value_column
    if comment_column is not None:
        meta["comment_column"] = comment_column

    sequence: list[Leaf] = []
    layout: dict[str, str] = {}
    exact_of: dict[int, list[str]] = {}  # id(leaf) → exact lines before it
    pending: list[str] = []
    end_text = ""
    for item in doc.items:
        t = type(item)
        if t is End:
            end_text = doc.lines[item.line - 1]
            break
        if t is Invalid:
            raise ZeroError("not an entry, comment or blank line; fix it first (`zero lint` shows why)",
                               doc.path, item.line, 1)
        if t is Comment or t is Blank:
            pending.append(doc.lines[item.line - 1])
            continue
        assert isinstance(item, Entry)
        path = split_key(item.key_text)
        if path is None:
            raise ZeroError(f"`{item.key_text}` cannot be split into names and indices",
                               doc.path, item.line, item.key_start + 1)
        if len(path) > MAX_DEPTH:
            raise ZeroError(f"key has {len(path)} levels; zero converts keys of up to {MAX_DEPTH}",
                               doc.path, item.line, item.key_start + 1)
        if path[0] == META_KEY:
            raise ZeroError(f"`{META_KEY}` is the name of zero's layout record in YAML/TOML/JSON; "
                               "a list key of that name cannot be converted", doc.path, item.line,
                               item.key_start + 1)
        spec = registry.by_pattern(item.key.pattern, kind) if item.key else None
        value, native = _scalar_from_list(item.value, spec.type if spec else None)
        after = item.comment.rstrip(" \t") if item.comment is not None else None
        leaf = Leaf(item.key_text, path, value, [normalized(x) for x in pending], after,
                    item.line, item.value_start + 1, native,
                    (item.line, item.key_start + 1, item.line, item.key_end + 1))
        if any(x != normalized(x) for x in pending):
            exact_of[id(leaf)] = pending
        pending = []
        text = doc.lines[item.line - 1]
        if text != canonical_line(item.key_text, item.value, after, value_column, comment_column):
            layout[item.key_text] = _template(doc, item)
        sequence.append(leaf)

    meta["end"] = end_text
    if doc.end_line is not None and doc.end_line < len(doc.lines):
        meta["after_end"] = doc.lines[doc.end_line:]
    tail = [normalized(x) for x in pending]
    if any(x != normalized(x) for x in pending):
        meta["tail"] = pending

    # Duplicates: the controller keeps the last value; earlier lines are kept verbatim.
    last: dict[str, Leaf] = {}
    for leaf in sequence:
        last[leaf.key] = leaf
    shadowed: dict[str, list[list[str]]] = {}
    for leaf in sequence:
        if last[leaf.key] is not leaf:
            lines = exact_of.get(id(leaf)) or list(leaf.before)
            assert leaf.line is not None
            shadowed.setdefault(leaf.key, []).append([*lines, doc.lines[leaf.line - 1]])
            notes.append(f"line {leaf.line}: `{leaf.key}` is set again later; the earlier value "
                         f"{leaf.value} is kept verbatim in {META_KEY}.shadowed (the controller ignores it)")
    effective = [leaf for leaf in sequence if last[leaf.key] is leaf]
    before_exact = {leaf.key: exact_of[id(leaf)] for leaf in effective if id(leaf) in exact_of}
    # layout entries of shadowed lines were measured on the effective line's key: recompute
    for key in shadowed:
        eff = last[key]
        assert eff.line is not None
        e = doc.items[eff.line - 1]  # one item per line: no scan per shadowed key
        assert isinstance(e, Entry)
        if doc.lines[e.line - 1] != canonical_line(e.key_text, e.value, eff.after, value_column,
                                                   comment_column):
            layout[key] = _template(doc, e)
        else:
            layout.pop(key, None)
    root, flat = nest(effective)
    ordered = [*flat, *dfs(root)]
    if shadowed or [x.key for x in ordered] != [x.key for x in sequence]:
        meta["order"] = [x.key for x in sequence]
    if shadowed:
        meta["shadowed"] = shadowed
    if layout:
        meta["layout"] = layout
    if before_exact:
        meta["before"] = before_exact
    tree = Tree(ordered, meta, tail, doc.path, notes)
    tree._nested = (root, flat)
    return tree


# ------------------------------------------------------------- tree → list


def _render_value(value: Scalar) -> str:
    if isinstance(value, bool):  # pragma: no cover - readers refuse booleans
        raise TypeError("boolean value")
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _apply_template(template: str, key: str, value: str, comment: str | None,
                    comment_column: int | None) -> str | None:
    head, sep, rest = template.partition("{v}")
    if not sep or "".join(head.split()) != key:
        return None
    if "{c}" in rest:
        gap, _, trailing = rest.partition("{c}")
        if comment is None:
            return head + value
        return head + value + gap + comment + trailing
    if comment is None:
        return head + value + rest
    s = head + value
    gap_n = max(comment_column - len(s), 1) if comment_column is not None else COMMENT_GAP
    return s + " " * gap_n + comment


def _exact(visible: list[str], exact: Any) -> list[str]:
    """The exact lines, when they still say what the visible ones say."""
    ok = isinstance(exact, list) and all(isinstance(x, str) for x in exact)
    return exact if ok and [normalized(x) for x in exact] == visible else visible


def _reordered(tree: Tree, order: list[Any]) -> bool:
    """Did the user reorder the keys since zero wrote the file? Then the visible order wins over
    the recorded one. zero writes the keys of a list in the order nesting them gives; if the keys
    (those in both) stand in another order now, a person moved them."""
    by_key = {leaf.key: leaf for leaf in tree.leaves}
    last = {k: i for i, k in enumerate(order) if isinstance(k, str)}  # a key set twice counts where it wins
    recorded = [by_key[k] for k in sorted(last, key=last.__getitem__) if k in by_key]
    root, flat = nest(recorded)
    written = [leaf.key for leaf in (*flat, *dfs(root))]
    known = set(written)
    visible = [leaf.key for leaf in tree.leaves if leaf.key in known]
    return visible != written


def list_sequence(tree: Tree) -> list[Leaf | list[str]]:
    """Leaves in the order the list holds them; shadowed lines as lists of text."""
    meta = tree.meta
    order = meta.get("order")
    if not isinstance(order, list) or _reordered(tree, order):
        return list(tree.leaves)
    raw_shadowed = meta.get("shadowed")
    shadowed: dict[str, Any] = raw_shadowed if isinstance(raw_shadowed, dict) else {}
    by_key = {leaf.key: leaf for leaf in tree.leaves}
    used: Counter[str] = Counter()
    placed: set[str] = set()
    seq: list[Leaf | list[str]] = []
    for key in order:
        if not isinstance(key, str) or key not in by_key:
            continue  # removed since the conversion
        earlier = shadowed.get(key) or []
        if used[key] < len(earlier) and key not in placed:
            lines = earlier[used[key]]
            used[key] += 1
            if isinstance(lines, list) and all(isinstance(x, str) for x in lines):
                seq.append(lines)
            continue
        if key not in placed:
            placed.add(key)
            seq.append(by_key[key])
    # Leaves added since the conversion follow their predecessor in the document.
    after: dict[str | None, list[Leaf]] = {}
    anchor: str | None = None
    for leaf in tree.leaves:
        if leaf.key in placed:
            anchor = leaf.key
        else:
            after.setdefault(anchor, []).append(leaf)
    if not after:
        return seq
    out: list[Leaf | list[str]] = list(after.get(None, []))
    for item in seq:
        out.append(item)
        if isinstance(item, Leaf):
            out.extend(after.get(item.key, []))
    return out


class ListText(Record):
    text: str
    lines_of: dict[int, Leaf]  # list line number → the leaf written there


def to_list_text(tree: Tree) -> ListText:
    """Write a tree as list text (before encoding), verifying every entry line."""
    meta = tree.meta
    vcol = meta.get("value_column", DEFAULT_VALUE_COLUMN)
    value_column = vcol if isinstance(vcol, int) and not isinstance(vcol, bool) and 0 <= vcol < 1000 \
        else DEFAULT_VALUE_COLUMN
    ccol = meta.get("comment_column")
    comment_column = ccol if isinstance(ccol, int) and not isinstance(ccol, bool) and 0 <= ccol < 10000 \
        else None
    raw_layout, raw_before = meta.get("layout"), meta.get("before")
    layout: dict[str, Any] = raw_layout if isinstance(raw_layout, dict) else {}
    before_exact: dict[str, Any] = raw_before if isinstance(raw_before, dict) else {}

    out: list[str] = []
    lines_of: dict[int, Leaf] = {}
    for item in list_sequence(tree):
        if isinstance(item, list):
            out.extend(item)
            continue
        leaf = item
        out.extend(_exact(leaf.before, before_exact.get(leaf.key)))
        value = _render_value(leaf.value)
        line: str | None = None
        template = layout.get(leaf.key)
        if isinstance(template, str):
            line = _apply_template(template, leaf.key, value, leaf.after, comment_column)
        if line is None:
            line = canonical_line(leaf.key, value, leaf.after, value_column, comment_column)
        _verify(line, leaf, value, tree.path)
        out.append(line)
        lines_of[len(out)] = leaf
    out.extend(_exact(tree.tail, meta.get("tail")))
    end = meta.get("end", "Ende")
    if isinstance(end, str) and end:
        out.append(end)
    after_end = meta.get("after_end")
    if isinstance(after_end, list):
        out.extend(x for x in after_end if isinstance(x, str))
    newline = meta.get("newline", "\n")
    if newline not in ("\n", "\r\n"):
        newline = "\n"
    text = newline.join(out)
    if out and meta.get("final_newline", True) is not False:
        text += newline
    return ListText(text, lines_of)


def _verify(line: str, leaf: Leaf, value: str, path: str) -> None:
    """Read the line back as the controller would; refuse what would not survive."""
    where = structured_path(leaf.path)
    m = _UNCARRIABLE_RE.search(line)
    if m:
        raise ZeroError(f"{where}: control character U+{ord(m.group()):04X} cannot go into a list line",
                           path, leaf.line, leaf.column)
    if not leaf.before and _SIMPLE_VALUE_RE.fullmatch(value) and (
            leaf.after is None or not leaf.after.startswith("|")) and line.startswith(leaf.key):
        return  # a plain token after a valid key reads back as written: no need to re-scan
    for x in leaf.before:
        if x and not x.startswith("#"):
            raise ZeroError(f"{where}: comment line {x!r} does not start with `#`", path, leaf.line)
    from zero.lists.tokenizer import scan_line  # start-up: only where a value must be read back

    got = scan_line(line, 1, [])
    ok = (type(got) is Entry and got.key_text == leaf.key and got.value == value
          and (got.comment.rstrip(" \t") if got.comment is not None else None) == leaf.after)
    if not ok:
        if value == "" or (any(c in value for c in " \t") and "|" not in value):
            why = "the value is empty or holds whitespace"
        else:
            why = "the controller would read the line differently"
        read = f"`{got.value}`" if type(got) is Entry else "no entry"
        raise ZeroError(f"{where}: value {value!r} cannot be written as a list line: {why} "
                           f"(it would read {read})", path, leaf.line, leaf.column)


def encode_list(tree: Tree, text: str) -> bytes:
    """Encode list text the way the original file was encoded."""
    name = tree.meta.get("encoding", "utf-8")
    try:  # UTF-8, or a code page that reads ASCII as ASCII (cp850, cp1252, latin-1 …)
        enc = declarable(name) if isinstance(name, str) else ""
    except ValueError as exc:
        raise ZeroError(f"{META_KEY}.encoding {name!r} is not one zero writes: {exc}", tree.path) from None
    if not enc:
        raise ZeroError(f"{META_KEY}.encoding {name!r} is not one zero writes (a codec name, e.g. cp850)", tree.path)
    try:
        data = text.encode(enc)
    except UnicodeEncodeError as exc:
        line = text.count("\n", 0, exc.start) + 1
        raise ZeroError(f"character {text[exc.start]!r} cannot be written in {enc}; "
                           f"change {META_KEY}.encoding to utf-8 or the text", tree.path, line) from None
    if tree.meta.get("bom") is True:
        data = b"\xef\xbb\xbf" + data
    return data

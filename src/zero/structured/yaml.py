"""The YAML form: a streaming writer, and a strict reader over PyYAML's event stream.

The writer is our own (PyYAML cannot write comments): nested mappings of scalars,
comment lines before a key and the trailing comment after its value, then the
``_zero`` record in block style. The reader works on events, so no constructor runs:
explicit tags, anchors and aliases are refused at the first one (an alias bomb never
expands); duplicate keys, sequences, nesting deeper than ``MAX_NESTING`` and several
documents are refused with their line. Plain scalars keep their text as written
(``0x1F``, ``010``, ``on`` stay what they are); comments are found by line.
"""

from __future__ import annotations

import json
import re
from typing import Any

from zero.errors import ZeroError
from zero.structured.common import (
    MAX_NESTING,
    comment_suffix,
    emit_items,
    finish,
    make_leaf,
    quote,
    strip_comment,
)
from zero.structured.tree import META_KEY, Leaf, Scalar, Tree, is_index, structured_path

_YAML_PLAIN_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_./-]*")
# Words YAML 1.1 reads as booleans or null; never written plain.
_YAML_WORDS = frozenset({"y", "yes", "n", "no", "true", "false", "on", "off", "null", "~"})
_YAML_FLOAT_RE = re.compile(r"-?[0-9]+\.[0-9]+")
_INDEX_PLAIN_RE = re.compile(r"0|[1-9][0-9]*")

# ------------------------------------------------------------------------- YAML


_yaml_key_cache: dict[str, str] = {}


def _yaml_key(seg: str) -> str:
    cached = _yaml_key_cache.get(seg)
    if cached is None:
        cached = _yaml_key_uncached(seg)
        if len(_yaml_key_cache) < 100_000:
            _yaml_key_cache[seg] = cached
    return cached


def _yaml_key_uncached(seg: str) -> str:
    if is_index(seg):
        return seg if _INDEX_PLAIN_RE.fullmatch(seg) else quote(seg)
    if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", seg) and seg.lower() not in _YAML_WORDS:
        return seg
    return quote(seg)


def yaml_scalar(value: Scalar) -> str:
    if isinstance(value, bool):  # pragma: no cover - readers refuse booleans
        raise TypeError("boolean")
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        r = repr(value)
        return r if _YAML_FLOAT_RE.fullmatch(r) else quote(r)
    if _YAML_PLAIN_RE.fullmatch(value) and value.lower() not in _YAML_WORDS:
        return value
    return quote(value)


def write_yaml(tree: Tree) -> str:
    out: list[str] = []
    append = out.append
    open_path: tuple[str, ...] = ()
    # a leaf's text after its key (`: value  # comment`): values and comments repeat, so each pair is
    # written once (114,000 tool entries hold a few thousand pairs)
    tails: dict[tuple[type, Scalar, str | None], str] = {}  # by type too: 1 and 1.0 are equal keys
    for segs, leaf in emit_items(tree):
        parents = segs[:-1]
        if parents == open_path:  # a sibling of the leaf before: the common case
            common = len(parents)
        else:
            common, most = 0, min(len(open_path), len(parents))
            while common < most and open_path[common] == parents[common]:
                common += 1
        if leaf.before:
            pad = "  " * common
            out.extend(pad + c if c else "" for c in leaf.before)
        for depth in range(common, len(parents)):
            append("  " * depth + _yaml_key(parents[depth]) + ":")
        value, after = leaf.value, leaf.after
        tail = tails.get((type(value), value, after))
        if tail is None:
            tail = ": " + yaml_scalar(value) + comment_suffix(after)
            if len(tails) < 65_536:
                tails[(type(value), value, after)] = tail
        append("  " * len(parents) + _yaml_key(segs[-1]) + tail)
        open_path = parents
    out.extend(tree.tail)
    out.append(META_KEY + ":")
    out.extend(_yaml_meta(tree.meta))
    return "\n".join(out) + "\n"


def _yaml_meta_scalar(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    return quote(str(value))


def _yaml_meta(meta: dict[str, Any]) -> list[str]:
    """The ``_zero`` record in block style: scalars, lists and mappings of those (two levels)."""
    out: list[str] = []
    for key, value in meta.items():
        k = _yaml_key(key)
        if isinstance(value, dict):
            if not value:
                out.append(f"  {k}: {{}}")
                continue
            out.append(f"  {k}:")
            for k2, v2 in value.items():
                if isinstance(v2, list):
                    out.append(f"    {quote(k2)}: {json.dumps(v2, ensure_ascii=False)}")
                else:
                    out.append(f"    {quote(k2)}: {_yaml_meta_scalar(v2)}")
        elif isinstance(value, list):
            if not value:
                out.append(f"  {k}: []")
                continue
            out.append(f"  {k}:")
            out.extend(f"  - {json.dumps(v, ensure_ascii=False)}" if isinstance(v, list)
                       else f"  - {_yaml_meta_scalar(v)}" for v in value)
        else:
            out.append(f"  {k}: {_yaml_meta_scalar(value)}")
    return out


# ------------------------------------------------------------------------- YAML


class _Frame:
    """One open mapping or sequence while streaming YAML events."""

    __slots__ = ("container", "is_map", "key", "key_at", "key_line", "keys", "meta", "segs")

    def __init__(self, is_map: bool, segs: list[str], meta: bool, container: Any = None) -> None:
        self.is_map = is_map
        self.segs = segs
        self.meta = meta
        self.container = container
        self.key: str | None = None
        self.key_line = 0
        self.key_at: tuple[int, int, int, int] | None = None  # the pending key's text
        self.keys: dict[str, int] = {}


_OTHER_INT_RE = re.compile(r"[+-]?(?:0[0-9_]|[0-9][0-9_]*[_:])")  # octal 010, 1_000, 1:30 (YAML 1.1)


def _refuse_reread(tag: str, text: str, where: str, path: str, line: int, column: int) -> None:
    """Refuse a plain scalar that YAML reads as one value and the list line would read as another."""
    if tag == "bool":
        raise ZeroError(f"{where}: `{text}` is a YAML boolean, but a list holds the text `{text}`; write 1 or 0, "
                        "or quote it (\"TRUE\") where the parameter takes a symbol", path, line, column)
    if tag == "int" and _OTHER_INT_RE.match(text):
        raise ZeroError(f"{where}: `{text}` is a YAML number in a form the controller reads differently "
                        "(underscores, a leading zero, a colon); write plain decimal digits or quote it",
                        path, line, column)
    if tag == "float" and ("_" in text or text.lower().lstrip("+-") in (".inf", ".nan")):
        raise ZeroError(f"{where}: `{text}` is a YAML number no list line holds as YAML reads it; write the "
                        "number plainly", path, line, column)


def _meta_scalar(value: str, tag: str) -> Any:
    if tag == "int":
        try:
            return int(value)
        except ValueError:
            return value
    if tag == "bool":
        return value.lower() in ("true", "yes", "on", "y")
    if tag == "null":
        return None
    return value


def _text_at(e: Any) -> tuple[int, int, int, int]:
    """Where a scalar's text runs (1-based, end exclusive; a quoted one's inside its quotes)."""
    start, end = e.start_mark, e.end_mark
    inside = 1 if e.style in ("'", '"') else 0
    return start.line + 1, start.column + 1 + inside, end.line + 1, end.column + 1 - inside


def _yaml_stream(text: str, path: str) -> tuple[list[tuple[int, int, int, Leaf]], Any, range]:
    """Stream PyYAML events into leaves; no constructor runs and nothing expands.

    Returns ``(spans, meta, meta_lines)``: per leaf its key line, value end line and
    column (0-based), the ``_zero`` record, and the lines that record occupies.
    """
    import yaml  # start-up: PyYAML only when YAML is read
    from yaml import events as ev  # start-up: as above

    loader_cls = getattr(yaml, "CSafeLoader", None) or yaml.SafeLoader
    loader = loader_cls(text)
    resolve = loader.resolve
    scalar_node = yaml.ScalarNode
    Scalar_, MapStart, SeqStart = ev.ScalarEvent, ev.MappingStartEvent, ev.SequenceStartEvent
    MapEnd, SeqEnd, Alias, DocStart = ev.MappingEndEvent, ev.SequenceEndEvent, ev.AliasEvent, \
        ev.DocumentStartEvent
    spans: list[tuple[int, int, int, Leaf]] = []
    stack: list[_Frame] = []
    meta: Any = None
    meta_start = meta_end = -1
    documents = 0
    seen_root = False

    def refuse(message: str, mark: Any) -> ZeroError:
        return ZeroError(message, path, mark.line + 1, mark.column + 1)

    try:
        while True:
            e = loader.get_event()
            if e is None:
                break
            t = type(e)
            if t is Scalar_ or t is MapStart or t is SeqStart:
                if e.anchor is not None:
                    raise refuse(f"anchor &{e.anchor} refused: a parameter list needs no anchors or "
                                 "aliases, and aliases can expand without bound", e.start_mark)
                if e.tag is not None and e.tag != "!":
                    raise refuse(f"tag {e.tag} refused: zero reads plain YAML data only", e.start_mark)
                if not stack:
                    if seen_root:
                        raise refuse("more than one YAML document; a list is one", e.start_mark)
                    seen_root = True
                    if t is not MapStart:
                        what = "sequence" if t is SeqStart else "single value"
                        raise refuse(f"the top level must be a mapping of keys (np_grp: …), not a {what}",
                                     e.start_mark)
                    stack.append(_Frame(True, [], False))
                    continue
                f = stack[-1]
                if f.is_map and f.key is None:
                    if t is not Scalar_:
                        raise refuse("a mapping key must be text", e.start_mark)
                    key = e.value
                    first = f.keys.get(key)
                    if first is not None:
                        raise refuse(f"duplicate key `{key}` (first at line {first}); YAML loaders "
                                     "keep only the last one silently", e.start_mark)
                    line = e.start_mark.line
                    f.keys[key] = line + 1
                    f.key = key
                    f.key_line = line
                    f.key_at = _text_at(e)
                    continue
                # a value: of the pending key, or an item of a (meta) sequence
                key = f.key
                f.key = None
                if f.meta:
                    if t is Scalar_:
                        tag = resolve(scalar_node, e.value, e.implicit).rsplit(":", 1)[-1] \
                            if not e.style else "str"
                        value = _meta_scalar(e.value, tag)
                        if f.is_map:
                            f.container[key] = value
                        else:
                            f.container.append(value)
                    else:
                        container: Any = {} if t is MapStart else []
                        if f.is_map:
                            f.container[key] = container
                        else:
                            f.container.append(container)
                        if len(stack) >= MAX_NESTING:
                            raise refuse(f"nested deeper than {MAX_NESTING} levels", e.start_mark)
                        stack.append(_Frame(t is MapStart, [], True, container))
                    continue
                assert key is not None
                if not f.segs and key == META_KEY:
                    meta_start = f.key_line
                    if t is Scalar_:
                        meta = e.value
                        meta_end = e.end_mark.line + 1
                    else:
                        meta = {} if t is MapStart else []
                        stack.append(_Frame(t is MapStart, [], True, meta))
                    continue
                here = [*f.segs, key]
                if t is MapStart:
                    if len(stack) >= MAX_NESTING:
                        raise refuse(f"nested deeper than {MAX_NESTING} levels", e.start_mark)
                    stack.append(_Frame(True, here, False))
                    continue
                where = structured_path(tuple(here))
                m = e.start_mark
                if t is SeqStart:
                    raise ZeroError(f"{where}: a sequence is not a parameter value; one key per "
                                       "element (`name: {0: …, 1: …}`)", path, m.line + 1, m.column + 1)
                if e.style:
                    native = "str"
                else:
                    tag = resolve(scalar_node, e.value, e.implicit).rsplit(":", 1)[-1]
                    if tag == "null":
                        raise ZeroError(f"{where}: no value (YAML reads it as null); give a value, "
                                           "or \"\" for an empty one", path, f.key_line + 1)
                    _refuse_reread(tag, e.value, where, path, f.key_line + 1, m.column + 1)
                    native = tag if tag in ("int", "float") else "plain"  # text written without quotes
                leaf = make_leaf(here, e.value, native, path, f.key_line + 1, m.column + 1)
                leaf.key_at = f.key_at
                spans.append((f.key_line, e.end_mark.line, e.end_mark.column, leaf))
            elif t is MapEnd or t is SeqEnd:
                f = stack.pop()
                if f.meta and meta_end < 0 and stack and not stack[-1].meta:
                    meta_end = e.end_mark.line + (1 if e.end_mark.column else 0)
            elif t is Alias:
                raise refuse("aliases (*name) are refused: a parameter list needs none, and they "
                             "can expand without bound", e.start_mark)
            elif t is DocStart:
                documents += 1
                if documents > 1:
                    raise refuse("more than one YAML document; a list is one", e.start_mark)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        problem = exc.problem or "not valid YAML"
        raise ZeroError(f"not valid YAML: {problem}", path,
                           mark.line + 1 if mark else None, mark.column + 1 if mark else None) from None
    except yaml.reader.ReaderError as exc:  # a character YAML does not allow, anywhere (comments too)
        at = int(exc.position)
        line = text.count("\n", 0, at) + 1
        column = at - (text.rfind("\n", 0, at) + 1) + 1
        code = exc.character if isinstance(exc.character, int) else ord(str(exc.character)[:1] or "?")
        raise ZeroError(f"not valid YAML: character U+{code:04X} is not allowed in YAML (not even in a comment)",
                        path, line, column) from None
    except yaml.YAMLError as exc:
        raise ZeroError(f"not valid YAML: {' '.join(str(exc).split())}", path) from None
    finally:
        loader.dispose()
    if not seen_root:
        raise ZeroError("empty YAML document: no parameters", path)
    if meta_start >= 0 and meta_end < 0:
        meta_end = len(text.split("\n"))
    return spans, meta, range(meta_start, meta_end) if meta_start >= 0 else range(0)


_OPENER_COMMENT_RE = re.compile(r"^\s*[^#\"'\s][^#\"']*:\s+(#.*)$")


def _scan_between(lines: list[str], start: int, stop: int, skip: range) -> list[str]:
    """Comment and blank lines in ``lines[start:stop]`` (0-based), outside ``skip``."""
    out: list[str] = []
    for i in range(max(start, 0), min(stop, len(lines))):
        if i in skip:
            continue
        s = lines[i].strip()
        if not s:
            out.append("")
        elif s.startswith("#"):
            out.append(s)
        elif s in ("---", "..."):
            continue
        else:
            m = _OPENER_COMMENT_RE.match(lines[i])
            if m:
                out.append(m.group(1).strip())
    return out


def read_yaml(text: str, path: str = "-") -> Tree:
    if re.search(r"\r(?!\n)|[\x85\u2028\u2029]", text):
        raise ZeroError("line breaks other than LF or CRLF (CR, NEL, U+2028) are not read", path)
    spans, meta, meta_span = _yaml_stream(text, path)
    lines = text.split("\n")
    prev_end = -1
    for key_line, end_line, end_col, leaf in spans:
        if key_line > prev_end + 1:
            leaf.before = _scan_between(lines, prev_end + 1, key_line, meta_span)
        if end_line < len(lines):
            rest = lines[end_line][end_col:]
            if "#" in rest:
                leaf.after = strip_comment(rest)
        prev_end = end_line
    tail_stop = meta_span.start if meta_span and meta_span.start > prev_end else len(lines)
    tail = _scan_between(lines, prev_end + 1, tail_stop, meta_span)
    if tail_stop == len(lines):  # blank lines closing the file are no part of the list
        while tail and tail[-1] == "":
            tail.pop()
    return finish([s[3] for s in spans], meta, tail, path)


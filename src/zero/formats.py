"""YAML, TOML and JSON in and out of the structured form (:mod:`zero.structured`).

Writers are our own for the body (PyYAML and tomli-w cannot write comments): a
streaming emitter for a fixed, simple shape — nested mappings of scalars with
comment lines before a key and a trailing comment after its value. The ``_zero``
record is written by PyYAML / tomli-w / json. Tests read every writer's output
back with ``yaml.safe_load``, ``tomllib`` and ``json`` and compare the data.

Readers are strict:

* YAML is read from PyYAML's event stream (no constructor runs): explicit tags,
  anchors and aliases are refused at the first one, so an alias bomb never
  expands; duplicate keys, sequences, nesting deeper than :data:`MAX_NESTING` and
  several documents are refused with their line. Plain scalars keep the text as
  written (``0x1F``, ``010``, ``on`` stay what they are).
* TOML is parsed by ``tomllib``; JSON by ``json`` with duplicate keys refused.
* Comments are taken from the YAML/TOML text next to each key (by line), or from
  ``_zero.comments`` in JSON, which has none.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

from zero.structured import (
    FORMAT_VERSION,
    META_KEY,
    ConvertError,
    Leaf,
    Scalar,
    Tree,
    dfs,
    is_index,
    join_path,
    path_from_segments,
    structured_path,
)

FORMATS = ("lis", "yaml", "toml", "json")
SUFFIXES = {".lis": "lis", ".lst": "lis", ".yaml": "yaml", ".yml": "yaml", ".toml": "toml",
            ".json": "json"}
EXTENSION = {"lis": ".lis", "yaml": ".yaml", "toml": ".toml", "json": ".json"}
MAX_NESTING = 64

_YAML_PLAIN_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_./-]*")
# Words YAML 1.1 reads as booleans or null; never written plain.
_YAML_WORDS = frozenset({"y", "yes", "n", "no", "true", "false", "on", "off", "null", "~"})
_YAML_FLOAT_RE = re.compile(r"-?[0-9]+\.[0-9]+")
_INDEX_PLAIN_RE = re.compile(r"0|[1-9][0-9]*")
_TOML_BARE_RE = re.compile(r"[A-Za-z0-9_-]+")


def format_of(name: str) -> str | None:
    """The format a file name implies (``None`` when the suffix says nothing)."""
    lower = name.lower()
    for suffix, fmt in SUFFIXES.items():
        if lower.endswith(suffix):
            return fmt
    return None


def _q(text: str) -> str:
    """A double-quoted string valid in YAML, TOML and JSON alike."""
    return json.dumps(text, ensure_ascii=False)


def _emit_items(tree: Tree) -> Iterator[tuple[tuple[str, ...], Leaf]]:
    """Leaves with the key segments to write them under: first the few that cannot
    nest (under their whole key, in the top-level table), then the nested ones."""
    root, flat = tree.nested()
    for leaf in flat:
        yield (leaf.key,), leaf
    for leaf in dfs(root):
        yield leaf.path, leaf


def _comment_suffix(after: str | None) -> str:
    return "" if after is None else "  # " + after


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
        return seg if _INDEX_PLAIN_RE.fullmatch(seg) else _q(seg)
    if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", seg) and seg.lower() not in _YAML_WORDS:
        return seg
    return _q(seg)


def yaml_scalar(value: Scalar) -> str:
    if isinstance(value, bool):  # pragma: no cover - readers refuse booleans
        raise TypeError("boolean")
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        r = repr(value)
        return r if _YAML_FLOAT_RE.fullmatch(r) else _q(r)
    if _YAML_PLAIN_RE.fullmatch(value) and value.lower() not in _YAML_WORDS:
        return value
    return _q(value)


def write_yaml(tree: Tree) -> str:
    out: list[str] = []
    open_path: tuple[str, ...] = ()
    for segs, leaf in _emit_items(tree):
        parents = segs[:-1]
        common = 0
        while common < min(len(open_path), len(parents)) and open_path[common] == parents[common]:
            common += 1
        pad = "  " * common
        out.extend(pad + c if c else "" for c in leaf.before)
        for depth in range(common, len(parents)):
            out.append("  " * depth + _yaml_key(parents[depth]) + ":")
        out.append("  " * len(parents) + _yaml_key(segs[-1]) + ": " + yaml_scalar(leaf.value)
                   + _comment_suffix(leaf.after))
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
    return _q(str(value))


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
                    out.append(f"    {_q(k2)}: {json.dumps(v2, ensure_ascii=False)}")
                else:
                    out.append(f"    {_q(k2)}: {_yaml_meta_scalar(v2)}")
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


# ------------------------------------------------------------------------- TOML


def _toml_key(seg: str) -> str:
    return seg if _TOML_BARE_RE.fullmatch(seg) else _q(seg)


def toml_scalar(value: Scalar) -> str:
    if isinstance(value, bool):  # pragma: no cover - readers refuse booleans
        raise TypeError("boolean")
    if isinstance(value, (int, float)):
        return repr(value) if isinstance(value, float) else str(value)
    return _q(value)


def _dotted_tables(root: dict[str, Any]) -> set[tuple[str, ...]]:
    """Mappings that have a value after a sub-mapping: written as dotted keys."""
    out: set[tuple[str, ...]] = set()
    stack: list[tuple[tuple[str, ...], dict[str, Any]]] = [((), root)]
    while stack:
        path, node = stack.pop()
        seen_table = False
        for k, v in node.items():
            if isinstance(v, dict):
                seen_table = True
                stack.append(((*path, k), v))
            elif seen_table:
                out.add(path)
    return out


def write_toml(tree: Tree) -> str:
    root, _ = tree.nested()
    dotted = _dotted_tables(root)
    out: list[str] = []
    table: tuple[str, ...] = ()
    for segs, leaf in _emit_items(tree):
        t: tuple[str, ...] = ()
        if len(segs) > 1:  # flat leaves (one quoted segment) stay in the root table
            while len(t) < len(segs) - 1 and t not in dotted:
                t = segs[: len(t) + 1]
        out.extend(leaf.before)
        if t != table:
            out.append("[" + ".".join(_toml_key(s) for s in t) + "]")
            table = t
        key = ".".join(_toml_key(s) for s in segs[len(t):])
        out.append(f"{key} = {toml_scalar(leaf.value)}{_comment_suffix(leaf.after)}")
    out.extend(tree.tail)
    text = "\n".join(out) + ("\n" if out else "")
    import tomli_w

    return text + tomli_w.dumps({META_KEY: tree.meta})


# ------------------------------------------------------------------------- JSON


def write_json(tree: Tree) -> str:
    body: dict[str, Any] = {}
    comments: dict[str, dict[str, Any]] = {}
    for segs, leaf in _emit_items(tree):
        node = body
        for seg in segs[:-1]:
            node = node.setdefault(seg, {})
        node[segs[-1]] = leaf.value
        c: dict[str, Any] = {}
        if leaf.before:
            c["before"] = leaf.before
        if leaf.after is not None:
            c["after"] = leaf.after
        if c:
            comments[leaf.key] = c
    meta = dict(tree.meta)
    if comments:
        meta["comments"] = comments
    if tree.tail:
        meta["tail_comments"] = tree.tail
    body[META_KEY] = meta
    return json.dumps(body, ensure_ascii=False, indent=2) + "\n"


WRITERS = {"yaml": write_yaml, "toml": write_toml, "json": write_json}


# ----------------------------------------------------------------- common reading


@dataclass(slots=True)
class _Found:
    """Comments and position of one leaf, as a text scanner saw them."""

    line: int
    column: int
    after: str | None = None
    before: list[str] = field(default_factory=list)


def _leaf(segments: list[str], value: Scalar, native: str, path: str, line: int | None,
          column: int | None) -> Leaf:
    where = structured_path(tuple(segments))
    try:
        p = path_from_segments(segments, path)
    except ConvertError as exc:
        raise ConvertError(f"{where}: {exc.message}", path, line, column) from None
    if isinstance(value, str) and _BAD_IN_LINE.search(value):
        raise ConvertError(f"{where}: the value holds a line break or control character; "
                           "a list value is one line of text", path, line, column)
    return Leaf(join_path(p), p, value, [], None, line, column, native)


def _strip_comment(text: str) -> str | None:
    """``# text`` after a value → ``text`` (the list comment as written)."""
    t = text.strip(" \t")
    if not t.startswith("#"):
        return None
    t = t[1:]
    if t.startswith(" "):
        t = t[1:]
    return t.rstrip(" \t") or None


def _finish(leaves: list[Leaf], meta: Any, tail: list[str], path: str) -> Tree:
    if meta is None:
        meta = {}
    if not isinstance(meta, dict):
        raise ConvertError(f"`{META_KEY}` must be a mapping (zero's record of the list layout)", path)
    version = meta.get("zero", FORMAT_VERSION)
    if not isinstance(version, int) or version > FORMAT_VERSION:
        raise ConvertError(f"`{META_KEY}.zero` is {version!r}: written by a newer zero "
                           f"(this one reads format {FORMAT_VERSION})", path)
    check_meta(meta, path)
    seen: dict[str, Leaf] = {}
    for leaf in leaves:
        prev = seen.get(leaf.key)
        if prev is not None:
            where = f" (first at line {prev.line})" if prev.line else ""
            raise ConvertError(f"`{leaf.key}` is given twice{where}; a list holds each key once",
                               path, leaf.line, leaf.column)
        seen[leaf.key] = leaf
    _check_types(leaves, meta, path)
    return Tree(leaves, meta, tail, path)


_LINE = "line"  # a string that becomes one list line: no line breaks or control characters
_META_SHAPES: dict[str, Any] = {
    "zero": int, "kind": str, "encoding": str, "bom": bool, "newline": str, "final_newline": bool,
    "value_column": int, "comment_column": int, "end": _LINE, "after_end": [_LINE], "tail": [_LINE],
    "order": [str], "shadowed": {str: [[_LINE]]}, "layout": {str: _LINE}, "before": {str: [_LINE]},
}
_BAD_IN_LINE = re.compile(r"[\x00-\x08\x0a-\x1f\x7f\u2028\u2029\ud800-\udfff]")


def _shape_ok(value: Any, shape: Any) -> bool:
    if shape is _LINE:
        return isinstance(value, str) and not _BAD_IN_LINE.search(value)
    if shape is int:
        return isinstance(value, int) and not isinstance(value, bool) and 0 <= value < 100_000
    if isinstance(shape, type):
        return isinstance(value, shape)
    if isinstance(shape, list):
        return isinstance(value, list) and all(_shape_ok(v, shape[0]) for v in value)
    (key_shape, value_shape), = shape.items()
    return isinstance(value, dict) and all(
        _shape_ok(k, key_shape) and _shape_ok(v, value_shape) for k, v in value.items())


def check_meta(meta: dict[str, Any], path: str) -> None:
    """The ``_zero`` record has the shape zero writes, or a clear refusal."""
    for key, value in meta.items():
        shape = _META_SHAPES.get(key)
        if shape is None:
            raise ConvertError(f"`{META_KEY}.{key}` is not part of zero's layout record "
                               f"(known: {', '.join(_META_SHAPES)})", path)
        if not _shape_ok(value, shape):
            raise ConvertError(f"`{META_KEY}.{key}` does not have the form zero writes; "
                               "restore it or delete it (the list is then written in the canonical "
                               "layout)", path)


def _check_types(leaves: list[Leaf], meta: dict[str, Any], path: str) -> None:
    """Refuse a number of the wrong kind that the format made (a float for an integer)."""
    floats = [leaf for leaf in leaves if leaf.native == "float"]
    if not floats:
        return
    from zero.model import parse_key
    from zero.registry import INTEGER_TYPES, default_registry, kind_from_name

    registry = default_registry()
    kind = meta.get("kind") if isinstance(meta.get("kind"), str) else None
    kind = kind_from_name(kind) if kind else None
    for leaf in floats:
        key = parse_key(leaf.key)
        spec = registry.by_pattern(key.pattern, kind) if key else None
        if spec is not None and spec.type in INTEGER_TYPES:
            raise ConvertError(
                f"{structured_path(leaf.path)}: {leaf.value} is a floating-point number but "
                f"{spec.id} is {spec.type}; the controller would not take it over — "
                "write an integer", path, leaf.line, leaf.column)


def _walk_mapping(data: dict[str, Any], path: str,
                  found: dict[tuple[str, ...], _Found] | None) -> tuple[list[Leaf], Any]:
    """Leaves of parsed TOML/JSON data (iterative, bounded depth)."""
    leaves: list[Leaf] = []
    meta: Any = None
    stack: list[tuple[list[str], Iterator[tuple[str, Any]]]] = [([], iter(data.items()))]
    while stack:
        segs, it = stack[-1]
        for k, v in it:
            if not segs and k == META_KEY:
                meta = v
                continue
            here = [*segs, k]
            where = structured_path(tuple(here))
            f = found.get(tuple(here)) if found else None
            line = f.line if f else None
            col = f.column if f else None
            if isinstance(v, dict):
                if len(here) >= MAX_NESTING:
                    raise ConvertError(f"{where}: nested deeper than {MAX_NESTING} levels", path, line)
                stack.append((here, iter(v.items())))
                break
            if isinstance(v, bool):
                raise ConvertError(f"{where}: a boolean; the controller knows 0/1 or symbols like "
                                   "\"TRUE\" — write one of those", path, line, col)
            if isinstance(v, int):
                leaf = _leaf(here, v, "int", path, line, col)
            elif isinstance(v, float):
                if not math.isfinite(v):
                    raise ConvertError(f"{where}: {v} is no value a list can hold", path, line, col)
                leaf = _leaf(here, v, "float", path, line, col)
            elif isinstance(v, str):
                leaf = _leaf(here, v, "str", path, line, col)
            elif v is None:
                raise ConvertError(f"{where}: null has no list form; give a value or remove the key",
                                   path, line, col)
            elif isinstance(v, list):
                raise ConvertError(f"{where}: a list/array is not a parameter value; one key per "
                                   "element (`name: {0: …, 1: …}`)", path, line, col)
            else:
                raise ConvertError(f"{where}: a {type(v).__name__} is not a parameter value",
                                   path, line, col)
            if f is not None:
                leaf.before = f.before
                leaf.after = f.after
            leaves.append(leaf)
        else:
            stack.pop()
    return leaves, meta


# ------------------------------------------------------------------------- YAML


class _Frame:
    """One open mapping or sequence while streaming YAML events."""

    __slots__ = ("container", "is_map", "key", "key_line", "keys", "meta", "segs")

    def __init__(self, is_map: bool, segs: list[str], meta: bool, container: Any = None) -> None:
        self.is_map = is_map
        self.segs = segs
        self.meta = meta
        self.container = container
        self.key: str | None = None
        self.key_line = 0
        self.keys: dict[str, int] = {}


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


def _yaml_stream(text: str, path: str) -> tuple[list[tuple[int, int, int, Leaf]], Any, range]:
    """Stream PyYAML events into leaves; no constructor runs and nothing expands.

    Returns ``(spans, meta, meta_lines)``: per leaf its key line, value end line and
    column (0-based), the ``_zero`` record, and the lines that record occupies.
    """
    import yaml
    from yaml import events as ev

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

    def refuse(message: str, mark: Any) -> ConvertError:
        return ConvertError(message, path, mark.line + 1, mark.column + 1)

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
                    raise ConvertError(f"{where}: a sequence is not a parameter value; one key per "
                                       "element (`name: {0: …, 1: …}`)", path, m.line + 1, m.column + 1)
                if e.style:
                    native = "str"
                else:
                    tag = resolve(scalar_node, e.value, e.implicit).rsplit(":", 1)[-1]
                    if tag == "null":
                        raise ConvertError(f"{where}: no value (YAML reads it as null); give a value, "
                                           "or \"\" for an empty one", path, f.key_line + 1)
                    native = tag if tag in ("int", "float") else "str"
                leaf = _leaf(here, e.value, native, path, f.key_line + 1, m.column + 1)
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
        raise ConvertError(f"not valid YAML: {problem}", path,
                           mark.line + 1 if mark else None, mark.column + 1 if mark else None) from None
    except yaml.YAMLError as exc:
        raise ConvertError(f"not valid YAML: {exc}", path) from None
    finally:
        loader.dispose()
    if not seen_root:
        raise ConvertError("empty YAML document: no parameters", path)
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
        raise ConvertError("line breaks other than LF or CRLF (CR, NEL, U+2028) are not read", path)
    spans, meta, meta_span = _yaml_stream(text, path)
    lines = text.split("\n")
    prev_end = -1
    for key_line, end_line, end_col, leaf in spans:
        if key_line > prev_end + 1:
            leaf.before = _scan_between(lines, prev_end + 1, key_line, meta_span)
        if end_line < len(lines):
            rest = lines[end_line][end_col:]
            if "#" in rest:
                leaf.after = _strip_comment(rest)
        prev_end = end_line
    tail_stop = meta_span.start if meta_span and meta_span.start > prev_end else len(lines)
    tail = _scan_between(lines, prev_end + 1, tail_stop, meta_span)
    if tail_stop == len(lines):  # blank lines closing the file are no part of the list
        while tail and tail[-1] == "":
            tail.pop()
    return _finish([s[3] for s in spans], meta, tail, path)


# ------------------------------------------------------------------------- TOML


def _toml_key_at(s: str, i: int) -> tuple[list[str], int] | None:
    """Parse a dotted TOML key at ``s[i:]``; return segments and the position after it."""
    segs: list[str] = []
    n = len(s)
    while True:
        while i < n and s[i] in " \t":
            i += 1
        if i < n and s[i] == '"':
            j = i + 1
            while j < n and s[j] != '"':
                j += 2 if s[j] == "\\" else 1
            if j >= n:
                return None
            try:
                segs.append(json.loads(s[i: j + 1]))
            except ValueError:
                return None
            i = j + 1
        elif i < n and s[i] == "'":
            j = s.find("'", i + 1)
            if j < 0:
                return None
            segs.append(s[i + 1: j])
            i = j + 1
        else:
            m = _TOML_BARE_RE.match(s, i)
            if not m:
                return None
            segs.append(m.group())
            i = m.end()
        while i < n and s[i] in " \t":
            i += 1
        if i < n and s[i] == ".":
            i += 1
            continue
        return segs, i


def _toml_value_end(s: str, i: int) -> int | None:
    """End of a one-line TOML value at ``s[i:]``; ``None`` when it continues on the next line."""
    n = len(s)
    if s.startswith('"""', i) or s.startswith("'''", i):
        q = s[i: i + 3]
        j = s.find(q, i + 3)
        return None if j < 0 else j + 3
    if i < n and s[i] == '"':
        j = i + 1
        while j < n and s[j] != '"':
            j += 2 if s[j] == "\\" else 1
        return j + 1 if j < n else None
    if i < n and s[i] == "'":
        j = s.find("'", i + 1)
        return None if j < 0 else j + 1
    if i < n and s[i] in "[{":
        depth = 0
        j = i
        while j < n:
            c = s[j]
            if c in "[{":
                depth += 1
            elif c in "]}":
                depth -= 1
                if depth == 0:
                    return j + 1
            elif c in "\"'":
                end = _toml_value_end(s, j)
                if end is None:
                    return None
                j = end
                continue
            elif c == "#":
                return None
            j += 1
        return None
    j = i
    while j < n and s[j] not in " \t#":
        j += 1
    return j


def _toml_scan(text: str) -> tuple[dict[tuple[str, ...], _Found], list[str]]:
    """Comments and line of every key/value line, by full key path."""
    found: dict[tuple[str, ...], _Found] = {}
    lines = text.split("\n")
    table: tuple[str, ...] = ()
    pending: list[str] = []
    tail: list[str] = []
    in_meta = False
    open_multiline: str | None = None
    for number, raw in enumerate(lines, 1):
        line = raw[:-1] if raw.endswith("\r") else raw
        if open_multiline is not None:
            if open_multiline in line:
                open_multiline = None
            continue
        s = line.strip()
        if not s:
            pending.append("")
            continue
        if s.startswith("#"):
            pending.append(s)
            continue
        if s.startswith("["):
            inner = 2 if s.startswith("[[") else 1
            parsed = _toml_key_at(s, inner)
            if parsed is None:
                continue
            table = tuple(parsed[0])
            if table[:1] == (META_KEY,):
                if not in_meta:
                    tail, pending = pending, []
                in_meta = True
            else:
                in_meta = False
            rest = s[parsed[1] + inner:]
            c = _strip_comment(rest)
            if c is not None and not in_meta:
                pending.append("# " + c)
            continue
        if in_meta:
            continue
        parsed = _toml_key_at(line, 0)
        if parsed is None:
            continue
        segs, i = parsed
        while i < len(line) and line[i] in " \t=":
            i += 1
        end = _toml_value_end(line, i)
        key = (*table, *segs)
        if end is None:
            q = line[i: i + 3]
            open_multiline = q if q in ('"""', "'''") else None
            found[key] = _Found(number, i + 1, None, pending)
        else:
            found[key] = _Found(number, i + 1, _strip_comment(line[end:]), pending)
        pending = []
        tail = []
    if not in_meta:
        tail = pending
        while tail and tail[-1] == "":
            tail.pop()
    return found, tail


def read_toml(text: str, path: str = "-") -> Tree:
    import tomllib

    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        reason = re.sub(r" ?\(at line.*", "", msg)
        raise ConvertError(f"not valid TOML: {reason}", path,
                           int(m.group(1)) if m else None, int(m.group(2)) if m else None) from None
    except RecursionError:
        raise ConvertError("not read: nested too deeply", path) from None
    found, tail = _toml_scan(text)
    leaves, meta = _walk_mapping(data, path, found)
    return _finish(leaves, meta, tail, path)


# ------------------------------------------------------------------------- JSON


def _no_duplicates(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for k, v in pairs:
        if k in out:
            raise ConvertError(f"duplicate key `{k}` in one object; JSON readers keep only the last")
        out[k] = v
    return out


def read_json(text: str, path: str = "-") -> Tree:
    try:
        data = json.loads(text, object_pairs_hook=_no_duplicates)
    except ConvertError as exc:
        raise ConvertError(exc.message, path) from None
    except json.JSONDecodeError as exc:
        raise ConvertError(f"not valid JSON: {exc.msg}", path, exc.lineno, exc.colno) from None
    except RecursionError:
        raise ConvertError("not read: nested too deeply", path) from None
    if not isinstance(data, dict):
        raise ConvertError("the top level must be an object of keys, not a "
                           + type(data).__name__, path)
    leaves, meta = _walk_mapping(data, path, None)
    tail: list[str] = []
    if isinstance(meta, dict):
        comments = meta.pop("comments", None)
        raw_tail = meta.pop("tail_comments", None)
        if isinstance(raw_tail, list):
            tail = [x for x in raw_tail if isinstance(x, str)]
        if isinstance(comments, dict):
            for leaf in leaves:
                c = comments.get(leaf.key)
                if isinstance(c, dict):
                    before = c.get("before")
                    if isinstance(before, list):
                        leaf.before = [x for x in before if isinstance(x, str)]
                    after = c.get("after")
                    if isinstance(after, str) and after.strip(" \t"):
                        leaf.after = after.rstrip(" \t")
    return _finish(leaves, meta, tail, path)


READERS = {"yaml": read_yaml, "toml": read_toml, "json": read_json}

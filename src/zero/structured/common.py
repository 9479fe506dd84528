"""What the YAML, TOML and JSON forms share: quoting, the order leaves are written in,
and the strict checks every reader applies (the ``_zero`` record's shape, duplicate
keys, values a list line can carry, nesting depth).
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator
from typing import Any

from zero.errors import ZeroError
from zero.records import Record, field
from zero.structured.tree import (
    FORMAT_VERSION,
    META_KEY,
    Leaf,
    Scalar,
    Tree,
    dfs,
    join_path,
    path_from_segments,
    structured_path,
)

MAX_NESTING = 64
MAX_INT_BITS = 128  # beyond every parameter type (the largest is 64 bits), far below Python's print limit
_LONG_NUMBER_RE = re.compile(r"[0-9][0-9_]{999,}")


def number_too_long(text: str, path: str) -> ZeroError:
    """The located refusal of a number longer than Python converts (or any parameter holds)."""
    m = _LONG_NUMBER_RE.search(text)
    if m is None:
        return ZeroError("a number too long to read: no parameter holds it", path)
    line = text.count("\n", 0, m.start()) + 1
    column = m.start() - (text.rfind("\n", 0, m.start()) + 1) + 1
    digits = sum(c.isdigit() for c in m.group())
    return ZeroError(f"a number of {digits} digits: no parameter holds it", path, line, column)


def quote(text: str) -> str:
    """A double-quoted string valid in YAML, TOML and JSON alike."""
    return json.dumps(text, ensure_ascii=False)


def emit_items(tree: Tree) -> Iterator[tuple[tuple[str, ...], Leaf]]:
    """Leaves with the key segments to write them under: first the few that cannot
    nest (under their whole key, in the top-level table), then the nested ones."""
    root, flat = tree.nested()
    for leaf in flat:
        yield (leaf.key,), leaf
    for leaf in dfs(root):
        yield leaf.path, leaf


def comment_suffix(after: str | None) -> str:
    return "" if after is None else "  # " + after




class Found(Record):
    """Comments and position of one leaf, as a text scanner saw them."""

    line: int
    column: int
    after: str | None = None
    before: list[str] = field(default_factory=list)
    key_at: tuple[int, int, int, int] | None = None  # its key's text, as :attr:`Leaf.key_at`


def make_leaf(segments: list[str], value: Scalar, native: str, path: str, line: int | None,
          column: int | None) -> Leaf:
    where = structured_path(tuple(segments))
    try:
        p = path_from_segments(segments, path)
    except ZeroError as exc:
        raise ZeroError(f"{where}: {exc.message}", path, line, column) from None
    if isinstance(value, str) and BAD_IN_LINE.search(value):
        raise ZeroError(f"{where}: the value holds a line break or control character; "
                           "a list value is one line of text", path, line, column)
    return Leaf(join_path(p), p, value, [], None, line, column, native)


def strip_comment(text: str) -> str | None:
    """``# text`` after a value → ``text`` (the list comment as written)."""
    t = text.strip(" \t")
    if not t.startswith("#"):
        return None
    t = t[1:]
    if t.startswith(" "):
        t = t[1:]
    return t.rstrip(" \t") or None


NO_RECORD = (f"no `{META_KEY}` record: the list is written in UTF-8 with LF line endings and the canonical "
             "layout (convert the original list again to keep its encoding and layout)")


def finish(leaves: list[Leaf], meta: Any, tail: list[str], path: str) -> Tree:
    notes = []
    if meta is None:
        meta = {}
        notes.append(NO_RECORD)
    if not isinstance(meta, dict):
        raise ZeroError(f"`{META_KEY}` must be a mapping (zero's record of the list layout)", path)
    version = meta.get("zero", FORMAT_VERSION)
    if not isinstance(version, int) or version > FORMAT_VERSION:
        raise ZeroError(f"`{META_KEY}.zero` is {version!r}: written by a newer zero "
                           f"(this one reads format {FORMAT_VERSION})", path)
    check_meta(meta, path)
    seen: dict[str, Leaf] = {}
    for leaf in leaves:
        prev = seen.get(leaf.key)
        if prev is not None:
            where = f" (first at line {prev.line})" if prev.line else ""
            raise ZeroError(f"`{leaf.key}` is given twice{where}; a list holds each key once",
                               path, leaf.line, leaf.column)
        seen[leaf.key] = leaf
    return Tree(leaves, meta, tail, path, notes)


_LINE = "line"  # a string that becomes one list line: no line breaks or control characters
_META_SHAPES: dict[str, Any] = {
    "zero": int, "kind": str, "encoding": str, "bom": bool, "newline": str, "final_newline": bool,
    "value_column": int, "comment_column": int, "end": _LINE, "after_end": [_LINE], "tail": [_LINE],
    "order": [str], "shadowed": {str: [[_LINE]]}, "layout": {str: _LINE}, "before": {str: [_LINE]},
}
BAD_IN_LINE = re.compile(r"[\x00-\x08\x0a-\x1f\x7f\u2028\u2029\ud800-\udfff]")


def _shape_ok(value: Any, shape: Any) -> bool:
    if shape is _LINE:
        return isinstance(value, str) and not BAD_IN_LINE.search(value)
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
            raise ZeroError(f"`{META_KEY}.{key}` is not part of zero's layout record "
                               f"(known: {', '.join(_META_SHAPES)})", path)
        if not _shape_ok(value, shape):
            raise ZeroError(f"`{META_KEY}.{key}` does not have the form zero writes; "
                               "restore it or delete it (the list is then written in the canonical "
                               "layout)", path)




def walk_mapping(data: dict[str, Any], path: str,
                  found: dict[tuple[str, ...], Found] | None) -> tuple[list[Leaf], Any]:
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
                    raise ZeroError(f"{where}: nested deeper than {MAX_NESTING} levels", path, line)
                stack.append((here, iter(v.items())))
                break
            if isinstance(v, bool):
                raise ZeroError(f"{where}: a boolean; the controller knows 0/1 or symbols like "
                                   "\"TRUE\" — write one of those", path, line, col)
            if isinstance(v, int):
                if v.bit_length() > MAX_INT_BITS:  # TOML hexadecimal of any length; Python prints 4,300 digits
                    raise ZeroError(f"{where}: a number of {v.bit_length()} bits: no parameter holds it (the "
                                    "widest parameter types hold 64)", path, line, col)
                leaf = make_leaf(here, v, "int", path, line, col)
            elif isinstance(v, float):
                if not math.isfinite(v):
                    raise ZeroError(f"{where}: {v} is no value a list can hold", path, line, col)
                leaf = make_leaf(here, v, "float", path, line, col)
            elif isinstance(v, str):
                leaf = make_leaf(here, v, "str", path, line, col)
            elif v is None:
                raise ZeroError(f"{where}: null has no list form; give a value or remove the key",
                                   path, line, col)
            elif isinstance(v, list):
                raise ZeroError(f"{where}: a list/array is not a parameter value; one key per "
                                   "element (`name: {0: …, 1: …}`)", path, line, col)
            else:
                raise ZeroError(f"{where}: a {type(v).__name__} is not a parameter value",
                                   path, line, col)
            if f is not None:
                leaf.before = f.before
                leaf.after = f.after
                leaf.key_at = f.key_at
            leaves.append(leaf)
        else:
            stack.pop()
    return leaves, meta


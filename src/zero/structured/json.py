"""The JSON form: ``json`` writes and reads the data; JSON has no comments, so they
travel in ``_zero.comments`` (by key) and ``_zero.tail_comments``. Duplicate keys in
one object are refused (JSON readers keep only the last).
"""

from __future__ import annotations

import bisect
import json
import re
from typing import Any

from zero.errors import ZeroError
from zero.structured.common import (
    Found,
    emit_items,
    finish,
    number_too_long,
    walk_mapping,
)
from zero.structured.tree import META_KEY, Tree, is_index, split_key

# ------------------------------------------------------------------------- JSON


def write_json(tree: Tree) -> str:
    body: dict[str, Any] = {}
    comments: dict[str, dict[str, Any]] = {}
    for segs, leaf in emit_items(tree):
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



# ------------------------------------------------------------------------- JSON


def _no_duplicates(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for k, v in pairs:
        if k in out:
            raise ZeroError(f"duplicate key `{k}` in one object; JSON readers keep only the last")
        out[k] = v
    return out


_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[{}\[\]:,]|[^\s{}\[\]:,"]+')


def scan_json(text: str) -> dict[tuple[str, ...], Found]:
    """The line and column (1-based; a string's first character after its quote) of every value,
    and the text of its key (inside the quotes), by its key path: JSON readers give none, and
    findings belong where the value (or the key) is written. For text ``json.loads`` has read (so
    its tokens are well formed). A pass over every token (as long as reading the file): only for a
    file that has findings to place."""
    found: dict[tuple[str, ...], Found] = {}
    newlines = [m.start() for m in re.finditer("\n", text)]

    def position(at: int) -> tuple[int, int]:
        line = bisect.bisect_left(newlines, at)
        return line + 1, at - (newlines[line - 1] + 1 if line else 0) + 1

    # each open container: [its path, "{" or "[", the key read and not yet given a value, next index,
    # that key's text (line, column, end line, end column)]
    frames: list[list[Any]] = []
    expect_key = False
    for m in _TOKEN.finditer(text):
        tok = m.group()
        top = frames[-1] if frames else None
        if tok in ",:":
            expect_key = tok == "," and top is not None and top[1] == "{"
            continue
        if tok in "}]":
            frames.pop()
            expect_key = False
            continue
        if top is not None and top[1] == "{" and expect_key:
            key = json.loads(tok)  # a key: its path segments, as the reader splits a dotted one
            top[2] = (key,) if is_index(key) else split_key(key) or (key,)
            top[4] = (*position(m.start() + 1), *position(m.end() - 1))
            expect_key = False
            continue
        if top is None:
            here: tuple[str, ...] = ()
        elif top[1] == "{":
            here = (*top[0], *top[2])
        else:
            here = (*top[0], str(top[3]))
            top[3] += 1
        if tok in "{[":
            frames.append([here, tok, None, 0, None])
            expect_key = tok == "{"
            continue
        line, column = position(m.start() + (tok[0] == '"'))
        found[here] = Found(line, column, key_at=top[4] if top is not None and top[1] == "{" else None)
    return found


def read_json(text: str, path: str = "-") -> Tree:
    try:
        data = json.loads(text, object_pairs_hook=_no_duplicates)
    except ZeroError as exc:
        raise ZeroError(exc.message, path) from None
    except json.JSONDecodeError as exc:
        raise ZeroError(f"not valid JSON: {exc.msg}", path, exc.lineno, exc.colno) from None
    except RecursionError:
        raise ZeroError("not read: nested too deeply", path) from None
    except ValueError:  # an integer beyond Python's conversion limit
        raise number_too_long(text, path) from None
    if not isinstance(data, dict):
        raise ZeroError("the top level must be an object of keys, not a "
                           + type(data).__name__, path)
    leaves, meta = walk_mapping(data, path, None)  # positions: scan_json, when a finding needs them
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
    return finish(leaves, meta, tail, path)



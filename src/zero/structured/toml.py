"""The TOML form: a writer (tables where they help, dotted keys where they must), and a
reader that parses with ``tomllib`` and finds each key's comments with a small line
scanner (:func:`scan_toml`, also used to locate keys of a configuration file).
"""

from __future__ import annotations

import json
import re
from typing import Any

from zero.errors import ZeroError
from zero.structured.common import (
    MAX_NESTING,
    Found,
    comment_suffix,
    emit_items,
    finish,
    number_too_long,
    quote,
    strip_comment,
    walk_mapping,
)
from zero.structured.tree import META_KEY, Scalar, Tree

_TOML_BARE_RE = re.compile(r"[A-Za-z0-9_-]+")


# ------------------------------------------------------------------------- TOML


def _toml_key(seg: str) -> str:
    return seg if _TOML_BARE_RE.fullmatch(seg) else quote(seg)


def toml_scalar(value: Scalar) -> str:
    if isinstance(value, bool):  # pragma: no cover - readers refuse booleans
        raise TypeError("boolean")
    if isinstance(value, (int, float)):
        return repr(value) if isinstance(value, float) else str(value)
    return quote(value)


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
    for segs, leaf in emit_items(tree):
        t: tuple[str, ...] = ()
        if len(segs) > 1:  # flat leaves (one quoted segment) stay in the root table
            while len(t) < len(segs) - 1 and t not in dotted:
                t = segs[: len(t) + 1]
        out.extend(leaf.before)
        if t != table:
            out.append("[" + ".".join(_toml_key(s) for s in t) + "]")
            table = t
        key = ".".join(_toml_key(s) for s in segs[len(t):])
        out.append(f"{key} = {toml_scalar(leaf.value)}{comment_suffix(leaf.after)}")
    out.extend(tree.tail)
    text = "\n".join(out) + ("\n" if out else "")
    import tomli_w  # start-up: only when TOML is written

    return text + tomli_w.dumps({META_KEY: tree.meta})



# ------------------------------------------------------------------------- TOML


def _toml_key_at(s: str, i: int) -> tuple[list[str], int, tuple[int, int]] | None:
    """Parse a dotted TOML key at ``s[i:]``; return segments, the position after it, and where its
    text runs (0-based, end exclusive: from its first segment to its last, inside their quotes)."""
    segs: list[str] = []
    n = len(s)
    first = -1
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
            text = (i + 1, j)
            i = j + 1
        elif i < n and s[i] == "'":
            j = s.find("'", i + 1)
            if j < 0:
                return None
            segs.append(s[i + 1: j])
            text = (i + 1, j)
            i = j + 1
        else:
            m = _TOML_BARE_RE.match(s, i)
            if not m:
                return None
            segs.append(m.group())
            text = m.span()
            i = m.end()
        if first < 0:
            first = text[0]
        while i < n and s[i] in " \t":
            i += 1
        if i < n and s[i] == ".":
            i += 1
            continue
        return segs, i, (first, text[1])


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


# A key of more dotted parts than this is refused before parsing: tomllib builds one table per
# part and copies the path for each, so memory grows with the square of such a key (64 KB: 4 GB).
# Linear in the text: each run of dotted parts is matched once, whole (possessive quantifiers
# never give back, and a bare part starts only where no bare character precedes it), then its
# parts counted. (A search for 64 parts in a row backtracked over every letter of a run of
# letters: an 80 KB run took 31-52 s.)
_DOTTED_PART = r"""(?:(?<![A-Za-z0-9_-])[A-Za-z0-9_-]++|"[^"\n]*+"|'[^'\n]*+')[ \t]*+\.[ \t]*+"""
_DOTTED_RUN = re.compile(f"(?:{_DOTTED_PART})++")
_DOTTED_ONE = re.compile(_DOTTED_PART)


def guard_toml(text: str, path: str = "-") -> None:
    """Refuse, before parsing, TOML whose parsing would not be bounded by its size: a key of more
    than ``MAX_NESTING`` dotted parts. (Brackets nested without end make tomllib recurse; its
    RecursionError is turned into a located refusal by the callers.)"""
    for m in _DOTTED_RUN.finditer(text):
        if m.end() - m.start() >= 2 * MAX_NESTING and \
                sum(1 for _ in _DOTTED_ONE.finditer(text, m.start(), m.end())) >= MAX_NESTING:
            line = text.count("\n", 0, m.start()) + 1
            column = m.start() - (text.rfind("\n", 0, m.start()) + 1) + 1
            raise ZeroError(f"not read: a key of more than {MAX_NESTING} dotted parts", path, line, column)


def scan_toml(text: str) -> tuple[dict[tuple[str, ...], Found], list[str]]:
    """Comments and line of every key/value line, by full key path."""
    found: dict[tuple[str, ...], Found] = {}
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
            c = strip_comment(rest)
            if c is not None and not in_meta:
                pending.append("# " + c)
            continue
        if in_meta:
            continue
        parsed = _toml_key_at(line, 0)
        if parsed is None:
            continue
        segs, i, (key_start, key_end) = parsed
        key_at = (number, key_start + 1, number, key_end + 1)
        while i < len(line) and line[i] in " \t=":
            i += 1
        end = _toml_value_end(line, i)
        key = (*table, *segs)
        if end is None:
            q = line[i: i + 3]
            open_multiline = q if q in ('"""', "'''") else None
            found[key] = Found(number, i + 1, None, pending, key_at)
        else:
            found[key] = Found(number, i + 1, strip_comment(line[end:]), pending, key_at)
        pending = []
        tail = []
    if not in_meta:
        tail = pending
        while tail and tail[-1] == "":
            tail.pop()
    return found, tail


def read_toml(text: str, path: str = "-") -> Tree:
    import tomllib  # start-up: only when TOML is read

    guard_toml(text, path)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
        reason = re.sub(r" ?\(at line.*", "", msg)
        raise ZeroError(f"not valid TOML: {reason}", path,
                           int(m.group(1)) if m else None, int(m.group(2)) if m else None) from None
    except RecursionError:
        raise ZeroError("not read: nested too deeply", path) from None
    except ValueError:  # an integer beyond Python's conversion limit
        raise number_too_long(text, path) from None
    found, tail = scan_toml(text)
    leaves, meta = walk_mapping(data, path, found)
    return finish(leaves, meta, tail, path)


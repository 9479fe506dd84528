"""Applying fixes (``zero lint --fix / --diff``) and ``zero format``.

Fixes edit the decoded lines of a list and write them back in the file's own
encoding, BOM and line endings, so every byte not touched by an edit survives.
Safe fixes keep what the controller reads; unsafe ones (``--unsafe-fixes``) change it.
``zero format`` rewrites the layout only: keys, values and comments stay, in their order.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass

from zero.diagnostics import Diagnostic, Edit
from zero.lint import LintOptions, LintResult, lint_document
from zero.model import Document
from zero.registry import Registry
from zero.tokenizer import tokenize

MAX_PASSES = 8
COMMENT_OFFSET = 15  # comments start this many columns after the value column


def document_bytes(doc: Document, lines: list[str] | None = None) -> bytes:
    """A document's text back to bytes: its encoding, BOM and per-line endings."""
    lines = doc.lines if lines is None else lines
    text = "".join(line + end for line, end in zip(lines, doc.endings, strict=True))
    data = text.encode(doc.encoding, "surrogateescape")
    return (b"\xef\xbb\xbf" + data) if doc.bom else data


def apply_edits(doc: Document, edits: list[Edit]) -> tuple[list[str], int]:
    """Apply non-overlapping single-line edits; return the new lines and how many applied."""
    lines = list(doc.lines)
    applied = 0
    taken: dict[int, list[tuple[int, int]]] = {}
    for e in sorted(edits, key=lambda e: (e.span.line, e.span.column, e.span.end_column)):
        s = e.span
        if s.line != s.end_line or not 1 <= s.line <= len(lines):
            continue
        start, end = s.column - 1, s.end_column - 1
        if any((start < b and a < end) or (start == end == a) for a, b in taken.get(s.line, [])):
            continue
        taken.setdefault(s.line, []).append((start, end))
    for line_no, spans in taken.items():
        text = lines[line_no - 1]
        for e in sorted((e for e in edits if e.span.line == line_no
                         and (e.span.column - 1, e.span.end_column - 1) in spans),
                        key=lambda e: -e.span.column):
            text = text[: e.span.column - 1] + e.replacement + text[e.span.end_column - 1:]
            applied += 1
        lines[line_no - 1] = text
    return lines, applied


def _fixable(diagnostics: list[Diagnostic], unsafe: bool) -> list[Edit]:
    return [e for d in diagnostics if d.fix is not None and (d.fix.safe or unsafe) for e in d.fix.edits]


@dataclass(slots=True)
class FixResult:
    original: bytes
    fixed: bytes
    applied: int
    result: LintResult  # the findings left after fixing


def fix_bytes(data: bytes, path: str, registry: Registry | None = None,
              options: LintOptions | None = None, unsafe: bool = False) -> FixResult:
    """Apply fixes until none is left (at most :data:`MAX_PASSES` rounds)."""
    current = data
    total = 0
    doc = tokenize(current, path)
    result = lint_document(doc, registry, options)
    for _ in range(MAX_PASSES):
        edits = _fixable(result.diagnostics, unsafe)
        if not edits:
            break
        lines, applied = apply_edits(doc, edits)
        if not applied:
            break
        total += applied
        current = document_bytes(doc, lines)
        doc = tokenize(current, path)
        result = lint_document(doc, registry, options)
    return FixResult(data, current, total, result)


def unified_diff(path: str, before: bytes, after: bytes, encoding: str = "utf-8") -> str:
    a = before.decode(encoding, "replace").splitlines(keepends=True)
    b = after.decode(encoding, "replace").splitlines(keepends=True)
    out = "".join(difflib.unified_diff(a, b, fromfile=f"a/{path}", tofile=f"b/{path}"))
    return out if out.endswith("\n") or not out else out + "\n\\ No newline at end of file\n"


def format_bytes(data: bytes, path: str, value_column: int | None = None) -> bytes:
    """The list in canonical layout: values aligned in one column (the vendor's column 55, or
    after the longest key), comments 15 columns after it (one space after a longer value), no
    trailing whitespace; order, values, comments, encoding and line endings kept. Earlier lines
    of a key set twice stay as written. Raises ConvertError for lines it cannot read."""
    from zero.structured import DEFAULT_VALUE_COLUMN, from_document, to_list_text

    doc = tokenize(data, path)
    tree = from_document(doc)
    meta = tree.meta
    # A key written with whitespace inside means something else to the controller (S004):
    # format keeps such a line as it is; `zero lint --fix` joins the key.
    layout = meta.pop("layout", {})
    kept = {k: t for k, t in layout.items() if any(c in t.partition("{v}")[0].strip() for c in " \t")}
    if kept:
        meta["layout"] = kept
    for key in ("before", "tail"):
        meta.pop(key, None)
    if isinstance(meta.get("end"), str) and meta["end"]:
        meta["end"] = meta["end"].strip()
    if isinstance(meta.get("after_end"), list):
        meta["after_end"] = [x.rstrip() for x in meta["after_end"]]
    widest = max((len(leaf.key) for leaf in tree.leaves), default=0)
    column = value_column if value_column is not None else DEFAULT_VALUE_COLUMN
    if widest >= column:
        column = widest + 1
    meta["value_column"] = column
    if any(leaf.after is not None for leaf in tree.leaves):
        meta["comment_column"] = column + COMMENT_OFFSET  # the vendor's 55 / 70
    else:
        meta.pop("comment_column", None)
    from zero.structured import encode_list

    text = to_list_text(tree).text
    return encode_list(tree, text)

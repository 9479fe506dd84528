"""``zero lint --add-noqa``: record today's findings as suppressions in the lists themselves.

Each entry line with findings gets a ``noqa`` with exactly its codes and a reason, written
in the list's own comment syntax: inside the line's trailing comment where it has one, else
as a new ``( noqa: CODES -- reason`` comment (``(`` is the one comment a string value
allows). Only the new findings of later edits are reported then; Z001 says when a recorded
one is gone. Findings on lines without an entry (a comment line, a file-wide finding) cannot
be suppressed on their line and are counted, not hidden.
"""

from __future__ import annotations

import re

from zero.engine.lint import LintResult
from zero.lists.encoding import document_bytes
from zero.lists.model import CommentStyle, Entry
from zero.records import Record

_NOQA_CODES = re.compile(r"noqa\s*:\s*([A-Z][0-9A-Z]*(?:[\s,]+[A-Z][0-9A-Z]*)*)", re.IGNORECASE)

NOT_RECORDED = ("Z001", "Z002")  # findings about suppressions themselves


class Baseline(Record):
    data: bytes
    added: int  # lines that got a directive
    unplaced: int  # findings on lines without an entry


def add_noqa(result: LintResult, reason: str = "baseline") -> Baseline:
    """The list of ``result`` with a ``noqa`` for each entry line's findings."""
    doc = result.document
    codes_by_line: dict[int, set[str]] = {}
    for d in result.diagnostics:
        if d.code not in NOT_RECORDED:
            codes_by_line.setdefault(d.span.line, set()).add(d.code)
    lines = list(doc.lines)
    added = unplaced = 0
    for line, codes in sorted(codes_by_line.items()):
        item = doc.items[line - 1] if line <= len(doc.items) else None
        if type(item) is not Entry:
            unplaced += len(codes)
            continue
        text = lines[line - 1].rstrip(" \t")
        existing = _NOQA_CODES.search(item.comment or "")
        if existing is not None:  # a noqa with codes already: it gets the new ones too
            have = {c for c in re.split(r"[,\s]+", existing.group(1)) if c}
            start = item.comment_start + existing.start(1)
            end = item.comment_start + existing.end(1)
            lines[line - 1] = text[:start] + ", ".join(sorted(have | codes)) + text[end:]
        elif item.comment is not None and "noqa" in item.comment.lower():
            continue  # a bare noqa already hides every code of the line
        elif item.comment is not None and item.comment_style is not CommentStyle.TEXT:
            lines[line - 1] = f"{text}  noqa: {', '.join(sorted(codes))} -- {reason}"
        else:  # no comment, or words after the value: open a `(` comment, the one a string allows
            lines[line - 1] = f"{text}  ( noqa: {', '.join(sorted(codes))} -- {reason}"
        added += 1
    return Baseline(document_bytes(doc, lines), added, unplaced)

"""``zero lint --add-noqa``: record today's findings as suppressions in the lists themselves.

Each entry line with findings gets a ``noqa`` with exactly its codes and a reason, written
in the list's own comment syntax: inside the line's trailing comment where it has one, else
as a new ``( noqa: CODES -- reason`` comment (``(`` is the one comment a string value
allows). Only the new findings of later edits are reported then; Z001 says when a recorded
one is gone. Findings on lines without an entry (a comment line, a file-wide finding) cannot
be suppressed on their line and are counted, not hidden.
"""

from __future__ import annotations

from dataclasses import dataclass

from zero.engine.lint import LintResult
from zero.lists.encoding import document_bytes
from zero.lists.model import Entry

NOT_RECORDED = ("Z001", "Z002")  # findings about suppressions themselves


@dataclass(slots=True)
class Baseline:
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
        if type(item) is not Entry or (item.comment and "noqa" in item.comment.lower()):
            unplaced += len(codes)
            continue
        directive = f"noqa: {', '.join(sorted(codes))} -- {reason}"
        text = lines[line - 1].rstrip(" \t")
        lines[line - 1] = f"{text}  {directive}" if item.comment is not None else f"{text}  ( {directive}"
        added += 1
    return Baseline(document_bytes(doc, lines), added, unplaced)

"""Applying fixes (``zero lint --fix / --diff``).

Fixes edit the decoded lines of a list and write them back in the file's own
encoding, BOM and line endings, so every byte not touched by an edit survives.
Safe fixes keep what the controller reads; unsafe ones (``--unsafe-fixes``) change it.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass

from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic, Edit
from zero.engine.lint import LintOptions, LintResult, lint_document
from zero.lists.encoding import document_bytes
from zero.lists.model import Document
from zero.lists.tokenizer import tokenize

MAX_PASSES = 8


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


def fix_bytes(data: bytes, path: str, registry: Registry,
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

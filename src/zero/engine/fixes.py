"""Applying fixes (``zero lint --fix / --diff``).

Fixes edit the decoded lines of a list and write them back in the file's own
encoding, BOM and line endings, so every byte not touched by an edit survives.
Safe fixes keep what the controller reads; unsafe ones (``--unsafe-fixes``) change it.
"""

from __future__ import annotations

import difflib
import os

from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic, Edit
from zero.engine.lint import LintOptions, LintResult, lint_document, lint_xml
from zero.errors import ZeroError
from zero.forms import is_xml
from zero.lists.encoding import document_bytes
from zero.lists.model import Document
from zero.lists.tokenizer import split_lines, tokenize
from zero.records import record

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


@record
class FixResult:
    fixed: bytes
    applied: int
    result: LintResult  # the findings left after fixing


def fix_bytes(data: bytes, path: str, registry: Registry,
              options: LintOptions | None = None, unsafe: bool = False) -> FixResult:
    """Apply fixes until none is left (at most :data:`MAX_PASSES` rounds); the list is read in the
    code page its options declare (``options.encoding``) and written back in it."""
    if is_xml(data):
        return _fix_xml(data, path, registry, options, unsafe)
    current = data
    total = 0
    encoding = options.encoding if options is not None else None
    doc = tokenize(current, path, encoding)
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
        doc = tokenize(current, path, encoding)
        result = lint_document(doc, registry, options)
    return FixResult(current, total, result)


def _fix_xml(data: bytes, path: str, registry: Registry, options: LintOptions | None,
             unsafe: bool) -> FixResult:
    """Fixes in an XML list (only edits inside a ``Value`` attribute, escaped) or in the lists of a
    TwinCAT export (inside their CDATA sections): every other byte of the file kept."""
    from zero.markup.safe import encoding_of  # start-up: only for XML

    current = data
    total = 0
    result = lint_xml(current, path, registry, options)
    for _ in range(MAX_PASSES):
        edits = _fixable(result.diagnostics, unsafe)
        if not edits:
            break
        try:
            codec, bom = encoding_of(current)
        except ZeroError:
            break
        lines, endings = split_lines((current[3:] if bom else current).decode(codec, "surrogateescape"))
        doc = Document(path, codec, lines, endings, [], bom=bom)  # the file's own lines, to edit
        lines, applied = apply_edits(doc, edits)
        if not applied:
            break
        total += applied
        current = document_bytes(doc, lines)
        result = lint_xml(current, path, registry, options)
    return FixResult(current, total, result)


def _lines(data: bytes) -> list[bytes]:
    """Lines split after each LF only (a CR stays part of its line, as in the file)."""
    parts = data.split(b"\n")
    out = [p + b"\n" for p in parts[:-1]]
    if parts[-1]:
        out.append(parts[-1])
    return out


def patch_path(path: str) -> str:
    """The path a patch names: relative to the working directory where the file lies below it."""
    if os.path.isabs(path):
        rel = os.path.relpath(path)
        if not rel.startswith(".."):
            path = rel
    return path.replace(os.sep, "/")


def unified_diff(path: str, before: bytes, after: bytes, context: int = 3) -> bytes:
    """A unified diff of two versions of a file, byte for byte in the file's own encoding and
    line endings, with ``a/``/``b/`` paths that ``git apply`` and ``patch -p1`` accept."""
    a, b = _lines(before), _lines(after)
    name = patch_path(path).encode("utf-8", "surrogateescape")
    out = [b"--- a/" + name + b"\n", b"+++ b/" + name + b"\n"]
    groups = list(difflib.SequenceMatcher(None, a, b, autojunk=False).get_grouped_opcodes(context))
    if not groups:
        return b""
    for group in groups:
        i1, i2, j1, j2 = group[0][1], group[-1][2], group[0][3], group[-1][4]
        out.append(f"@@ -{_range(i1, i2)} +{_range(j1, j2)} @@\n".encode())
        for tag, x1, x2, y1, y2 in group:
            if tag == "equal":
                out.extend(_hunk_line(b" ", line) for line in a[x1:x2])
                continue
            out.extend(_hunk_line(b"-", line) for line in a[x1:x2])
            out.extend(_hunk_line(b"+", line) for line in b[y1:y2])
    return b"".join(out)


def _range(start: int, stop: int) -> str:
    length = stop - start
    first = start + 1 if length else start
    return f"{first}" if length == 1 else f"{first},{length}"


def _hunk_line(mark: bytes, line: bytes) -> bytes:
    if line.endswith(b"\n"):
        return mark + line
    return mark + line + b"\n\\ No newline at end of file\n"

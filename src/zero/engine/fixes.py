"""Applying fixes (``zero lint --fix / --diff``).

Fixes edit the decoded lines of a list and write them back in the file's own
encoding, BOM and line endings, so every byte not touched by an edit survives.
Safe fixes keep what the controller reads; unsafe ones (``--unsafe-fixes``) change it.
"""

from __future__ import annotations

import bisect
import os
from collections.abc import Hashable, Sequence

from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic, Edit
from zero.engine.lint import LintOptions, LintResult, lint_document, lint_xml
from zero.errors import ZeroError
from zero.forms import is_xml
from zero.lists.encoding import document_bytes
from zero.lists.model import Document
from zero.lists.tokenizer import split_lines, tokenize
from zero.records import Record

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
            text = text[: e.span.column - 1] + e.replacement + _keep_column(text[e.span.end_column - 1:],
                                                                             e, len(e.replacement))
            applied += 1
        lines[line_no - 1] = text
    return lines, applied


def _keep_column(rest: str, edit: Edit, new_length: int) -> str:
    """What follows an edit, its blanks adjusted so that a value in an aligned column (two or more
    blanks before it) stays in its column when the edit changes the length before it (a key
    renamed by a fix); one blank at least. Anything else is kept as it is."""
    gap = len(rest) - len(rest.lstrip(" "))
    old_length = edit.span.end_column - edit.span.column
    if gap < 2 or gap == len(rest) or new_length == old_length or not edit.replacement:
        return rest
    return " " * max(gap + old_length - new_length, 1) + rest[gap:]


def _fixable(diagnostics: list[Diagnostic], unsafe: bool) -> list[Edit]:
    return [e for d in diagnostics if d.fix is not None and (d.fix.safe or unsafe) for e in d.fix.edits]


class FixResult(Record):
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
    groups = _grouped(line_opcodes(a, b), context)
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


Opcode = tuple[str, int, int, int, int]  # as difflib's: tag, a[i1:i2], b[j1:j2]
_SMALL = 2_500  # line pairs of a gap left to difflib (exact; quadratic or worse where lines repeat)


def line_opcodes(a: Sequence[Hashable], b: Sequence[Hashable]) -> list[Opcode]:
    """difflib-style opcodes that turn ``a`` into ``b``, in time about linear in the lines (difflib
    over a 40,000-line list took 100 s: its matcher is quadratic where lines repeat). The common
    start and end are cut; lines kept in place (``zero format`` keeps every line where it is) are
    compared pairwise; else lines that occur once on each side anchor the rest (the longest
    increasing run of them, as a patience diff), and difflib sees only what lies between two
    anchors, when that is small: a larger gap is one replacement (a correct patch, not the shortest)."""
    out: list[Opcode] = []
    _opcodes(a, b, 0, len(a), 0, len(b), out)
    merged: list[Opcode] = []
    for op in out:
        if op[1] == op[2] and op[3] == op[4]:
            continue
        if merged and (merged[-1][0] == "equal") == (op[0] == "equal"):  # one run of each kind
            tag = "equal" if op[0] == "equal" else "replace" if merged[-1][0] != op[0] else op[0]
            merged[-1] = (tag, merged[-1][1], op[2], merged[-1][3], op[4])
        else:
            merged.append(op)
    return merged


def _opcodes(a: Sequence[Hashable], b: Sequence[Hashable], i1: int, i2: int, j1: int, j2: int,
             out: list[Opcode]) -> None:
    """The opcodes of ``a[i1:i2]`` → ``b[j1:j2]``, appended to ``out``; a stack, not recursion (gaps
    between anchors hold anchors of their own, as deep as a file cares to nest them)."""
    work: list[tuple[bool, Opcode]] = [(True, ("", i1, i2, j1, j2))]
    while work:
        segment, op = work.pop()
        if not segment:
            out.append(op)
            continue
        _, i1, i2, j1, j2 = op
        head = 0
        while i1 + head < i2 and j1 + head < j2 and a[i1 + head] == b[j1 + head]:
            head += 1
        tail = 0
        while i2 - tail > i1 + head and j2 - tail > j1 + head and a[i2 - tail - 1] == b[j2 - tail - 1]:
            tail += 1
        out.append(("equal", i1, i1 + head, j1, j1 + head))
        x1, x2, y1, y2 = i1 + head, i2 - tail, j1 + head, j2 - tail
        later: list[tuple[bool, Opcode]] = [(False, ("equal", x2, i2, y2, j2))]  # in the order they come
        if x1 == x2 or y1 == y2:
            out.append(("delete" if y1 == y2 else "insert", x1, x2, y1, y2))
        elif x2 - x1 == y2 - y1:  # in place: pairwise
            i = x1
            while i < x2:
                j = i
                same = a[i] == b[y1 + i - x1]
                while j < x2 and (a[j] == b[y1 + j - x1]) == same:
                    j += 1
                out.append(("equal" if same else "replace", i, j, y1 + i - x1, y1 + j - x1))
                i = j
        elif (x2 - x1) * (y2 - y1) <= _SMALL:
            import difflib  # start-up: only for a small gap

            matcher = difflib.SequenceMatcher(None, a[x1:x2], b[y1:y2], autojunk=False)
            out.extend((tag, x1 + p1, x1 + p2, y1 + q1, y1 + q2) for tag, p1, p2, q1, q2 in matcher.get_opcodes())
        else:
            anchors = _anchors(a, b, x1, x2, y1, y2)
            if not anchors:
                out.append(("replace", x1, x2, y1, y2))
            else:
                pi, pj = x1, y1
                parts: list[tuple[bool, Opcode]] = []
                for i, j in anchors:
                    parts += [(True, ("", pi, i, pj, j)), (False, ("equal", i, i + 1, j, j + 1))]
                    pi, pj = i + 1, j + 1
                parts.append((True, ("", pi, x2, pj, y2)))
                later = parts + later
        work.extend(reversed(later))


def _anchors(a: Sequence[Hashable], b: Sequence[Hashable], x1: int, x2: int, y1: int,
             y2: int) -> list[tuple[int, int]]:
    """Lines that occur exactly once in ``a[x1:x2]`` and once in ``b[y1:y2]``, the longest run of them
    in the same order on both sides (patience sorting: n log n)."""
    count: dict[Hashable, list[int]] = {}
    for i in range(x1, x2):
        count.setdefault(a[i], [0, -1, 0, -1])
        c = count[a[i]]
        c[0] += 1
        c[1] = i
    for j in range(y1, y2):
        seen = count.get(b[j])
        if seen is not None:
            seen[2] += 1
            seen[3] = j
    pairs = sorted((c[1], c[3]) for c in count.values() if c[0] == 1 and c[2] == 1)
    tops: list[int] = []  # the smallest last j of an increasing run of each length
    links: list[int] = []  # per pair, the pair before it in its run
    ends: list[int] = []  # per length, the pair index that ends the best run
    for k, (_, j) in enumerate(pairs):
        at = bisect.bisect_left(tops, j)
        if at == len(tops):
            tops.append(j)
            ends.append(k)
        else:
            tops[at] = j
            ends[at] = k
        links.append(ends[at - 1] if at else -1)
    run: list[tuple[int, int]] = []
    k = ends[-1] if ends else -1
    while k >= 0:
        run.append(pairs[k])
        k = links[k]
    return run[::-1]


def _grouped(codes: list[Opcode], n: int) -> list[list[Opcode]]:
    """Opcodes in hunks with ``n`` lines of context (difflib's ``get_grouped_opcodes``)."""
    if not codes or (len(codes) == 1 and codes[0][0] == "equal"):
        return []
    codes = list(codes)
    if codes[0][0] == "equal":
        tag, i1, i2, j1, j2 = codes[0]
        codes[0] = tag, max(i1, i2 - n), i2, max(j1, j2 - n), j2
    if codes[-1][0] == "equal":
        tag, i1, i2, j1, j2 = codes[-1]
        codes[-1] = tag, i1, min(i2, i1 + n), j1, min(j2, j1 + n)
    nn = n + n
    groups: list[list[Opcode]] = []
    group: list[Opcode] = []
    for tag, i1, i2, j1, j2 in codes:
        if tag == "equal" and i2 - i1 > nn:
            group.append((tag, i1, min(i2, i1 + n), j1, min(j2, j1 + n)))
            groups.append(group)
            group = []
            i1, j1 = max(i1, i2 - n), max(j1, j2 - n)
        group.append((tag, i1, i2, j1, j2))
    if group and not (len(group) == 1 and group[0][0] == "equal"):
        groups.append(group)
    return groups


def _range(start: int, stop: int) -> str:
    length = stop - start
    first = start + 1 if length else start
    return f"{first}" if length == 1 else f"{first},{length}"


def _hunk_line(mark: bytes, line: bytes) -> bytes:
    if line.endswith(b"\n"):
        return mark + line
    return mark + line + b"\n\\ No newline at end of file\n"

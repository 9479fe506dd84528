"""Findings: severity, location, message and an optional fix.

This module imports nothing else from zero, so every other module can use it.
Lines and columns are 1-based; ``end_column`` is exclusive (one past the last
character), so a span of width zero marks a position between two characters.
"""

from __future__ import annotations

import enum

from zero.records import field, record


class Severity(enum.IntEnum):
    """How bad a finding is. Ordered so that ``max()`` gives the worst."""

    INFO = 1
    WARNING = 2
    ERROR = 3

    @property
    def label(self) -> str:
        return _LABELS[self]

    @classmethod
    def parse(cls, text: str) -> Severity:
        try:
            return cls[text.strip().upper()]
        except KeyError:
            raise ValueError(f"unknown severity {text!r} (use error, warning or info)") from None


_LABELS = {s: s.name.lower() for s in Severity}  # a report writes one per finding: `name` is slow to ask


@record(frozen=True)
class Span:
    """A region of a file: 1-based line and column, end column exclusive."""

    line: int
    column: int
    end_line: int
    end_column: int

    @classmethod
    def on_line(cls, line: int, start: int, end: int) -> Span:
        """A span on one line from 0-based character offsets ``start``..``end``."""
        return cls(line, start + 1, line, max(end, start) + 1)


@record(frozen=True)
class Edit:
    """Replace the text of ``span`` with ``replacement``."""

    span: Span
    replacement: str


@record(frozen=True)
class Fix:
    """A change that resolves a finding. ``safe`` fixes keep what the controller reads."""

    title: str
    edits: tuple[Edit, ...] = ()
    safe: bool = True

    def to_json(self) -> dict[str, object]:
        return {
            "title": self.title,
            "safe": self.safe,
            "edits": [
                {
                    "line": e.span.line,
                    "column": e.span.column,
                    "end_line": e.span.end_line,
                    "end_column": e.span.end_column,
                    "replacement": e.replacement,
                }
                for e in self.edits
            ],
        }


@record(frozen=True)
class Related:
    """Another place a finding is about, e.g. the earlier entry a duplicate overwrites; ``path``
    ``None`` is the finding's own file."""

    span: Span
    message: str
    path: str | None = None


@record(frozen=True)
class Diagnostic:
    """One finding. ``hint`` is a one-line suggestion shown under the source line."""

    code: str
    severity: Severity
    message: str
    span: Span
    path: str = "-"
    param_id: str | None = None
    fix: Fix | None = None
    hint: str | None = field(default=None, compare=False)
    related: tuple[Related, ...] = field(default=(), compare=False)
    kernel_error: str | None = None  # the number the kernel reports for it at start-up: P-ERR-110421
    # what the controller does (zero.catalog.evidence: ignored, limited, zeroed, undocumented, ...) and
    # the document that says so (a page's address, or why there is none)
    consequence: str | None = field(default=None, compare=False)
    source: str | None = field(default=None, compare=False)

    def sort_key(self) -> tuple[str, int, int, str]:
        return (self.path, self.span.line, self.span.column, self.code)

    def to_json(self) -> dict[str, object]:
        """The JSON contract of ``--output-format json``: exactly these keys."""
        return {
            "path": self.path,
            "line": self.span.line,
            "column": self.span.column,
            "end_line": self.span.end_line,
            "end_column": self.span.end_column,
            "code": self.code,
            "severity": self.severity.label,
            "message": self.message,
            "param_id": self.param_id,
            "kernel_error": self.kernel_error,
            "consequence": self.consequence,
            "source": self.source,
            "fix": self.fix.to_json() if self.fix is not None else None,
        }

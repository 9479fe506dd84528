"""``--output-format rdjson``: reviewdog's Diagnostic Format."""

from __future__ import annotations

import json
import urllib.parse
from collections.abc import Sequence

from zero.diagnostics import Severity, Span
from zero.engine.results import LintResult
from zero.output.formats import rule_docs_template
from zero.output.formats.common import repo_path
from zero.output.text import printable

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def _utf8_column(text: str | None, column: int) -> int:
    """A 1-based column in characters as reviewdog counts it: in UTF-8 bytes."""
    if text is None:
        return column
    return len(text[:column - 1].encode("utf-8", "surrogateescape")) + 1


def _rd_range(r: LintResult, span: Span) -> dict[str, dict[str, int]]:
    def position(line: int, column: int) -> dict[str, int]:
        text = r.document.line_text(line) if r.document.has_line(line) else None
        return {"line": line, "column": _utf8_column(text, column)}

    return {"start": position(span.line, span.column), "end": position(span.end_line, span.end_column)}


RDJSON_SEVERITY = {Severity.ERROR: "ERROR", Severity.WARNING: "WARNING", Severity.INFO: "INFO"}


def render_rdjson(results: Sequence[LintResult], stream: TextIO) -> None:
    """reviewdog's Diagnostic Format as one JSON document (``rdjson``, its ``DiagnosticResult``):
    each finding with its range (columns in UTF-8 bytes, the end exclusive, as the format has
    them), severity, code (and the rule page's address where zero knows it) and, for a safe fix,
    its edits as suggestions reviewdog can offer on a pull request."""
    docs = rule_docs_template()
    source = {"name": "zero"}
    diagnostics: list[dict[str, object]] = []
    for r in results:
        for d in r.diagnostics:
            code: dict[str, str] = {"value": d.code}
            if docs:
                code["url"] = docs.replace("{code}", urllib.parse.quote(d.code))
            item: dict[str, object] = {
                "message": printable(d.message),
                "location": {"path": repo_path(d.path), "range": _rd_range(r, d.span)},
                "severity": RDJSON_SEVERITY[d.severity], "source": source, "code": code}
            if d.fix is not None and d.fix.safe and d.fix.edits:
                item["suggestions"] = [{"range": _rd_range(r, e.span), "text": e.replacement} for e in d.fix.edits]
            diagnostics.append(item)
    stream.write(json.dumps({"source": source, "diagnostics": diagnostics}, indent=2, ensure_ascii=False) + "\n")

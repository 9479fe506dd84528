"""zero's findings as LSP diagnostics: severity, exact range, code with a link to the rule's
text, related locations.

The link (``codeDescription.href``) is, by default, a ``file:`` URI of the rule's text as
``zero rule CODE`` prints it, written once per zero version as Markdown below the user's
cache directory (``$XDG_CACHE_HOME/zero/<version>/rules/<CODE>.md``, else
``~/.cache/zero/…``; ``%LOCALAPPDATA%\\zero\\…`` on Windows); the setting ``ruleDocs``
(``"https://…/{code}"``) names a web page instead. Related locations are the lines a
message names (``already set on line 12``), the other lists of the machine it names, and for a
work offset outside its axis's soft limits (X001, X002) the entries that set those limits.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import attrs
from lsprotocol import types

from zero import __version__
from zero.diagnostics import Diagnostic, Severity, Span
from zero.errors import ZeroError
from zero.files import read_file, write_atomic
from zero.rules import RULES
from zero.server.documents import Analysis, Note
from zero.server.positions import Text, uri_of

SEVERITY = {Severity.ERROR: types.DiagnosticSeverity.Error, Severity.WARNING: types.DiagnosticSeverity.Warning,
            Severity.INFO: types.DiagnosticSeverity.Information}
_LINE = re.compile(r"(?<!list )\bline (\d+)\b")  # "(list line 5)" is the converted list's
UNNECESSARY = ("Z001",)  # an unused suppression: shown faded where the editor does


def cache_dir() -> Path:
    """Where the rendered rule texts go."""
    base = os.environ.get("XDG_CACHE_HOME") or (os.environ.get("LOCALAPPDATA") if os.name == "nt" else None)
    root = Path(base) if base else Path.home() / ".cache"
    return root / "zero" / __version__ / "rules"


def rule_markdown(code: str) -> str:
    rule = RULES[code]
    return f"# {code} {rule.name}\n\n```text\n{rule.render()}```\n"


class RuleDocs:
    """The link of each rule's text: a URL template, or the rendered files (written on first use)."""

    def __init__(self, template: str | None = None, directory: Path | None = None) -> None:
        self.template = template
        self.directory = directory
        self._written: bool | None = None
        self._hrefs: dict[str, str | None] = {}

    def href(self, code: str) -> str | None:
        if code not in self._hrefs:
            self._hrefs[code] = self._href(code)
        return self._hrefs[code]

    def _href(self, code: str) -> str | None:
        if code not in RULES:
            return None
        if self.template:
            return self.template.replace("{code}", code)
        directory = self.directory or cache_dir()
        if self._written is None:
            self._written = self._write(directory)
        return uri_of(directory / f"{code}.md") if self._written else None

    def _write(self, directory: Path) -> bool:
        """Every rule's text as a file; False when the directory cannot be written (no links then)."""
        try:
            directory.mkdir(parents=True, exist_ok=True)
            for code in RULES:
                target = directory / f"{code}.md"
                data = rule_markdown(code).encode("utf-8")
                if not _holds(target, data):
                    write_atomic(target, data, force=True)
        except (OSError, ZeroError):
            return False
        return True


def _holds(target: Path, data: bytes) -> bool:
    """Does the cached rule text hold exactly ``data``? (Its size first: a file of the cache
    directory replaced by something huge is never read whole.)"""
    try:
        return target.stat().st_size == len(data) and read_file(target, limit=len(data)) == data
    except (OSError, ZeroError):
        return False


def lsp_range(start: tuple[int, int], end: tuple[int, int]) -> types.Range:
    return types.Range(types.Position(*start), types.Position(*end))


def span_range(text: Text, span: Span) -> types.Range:
    """A zero span (1-based, end column exclusive) in the client's units."""
    return lsp_range(*text.span(span))


def line_range(text: Text, index: int) -> types.Range:
    """The whole of 0-based line ``index``."""
    return types.Range(types.Position(index, 0), types.Position(index, text.character(index, len(text.line(index)))))


def _related(a: Analysis, d: Diagnostic) -> list[types.DiagnosticRelatedInformation]:
    out: list[types.DiagnosticRelatedInformation] = []
    named: set[int] = set()  # lines the finding itself names as related (exact: no need to read the message)
    for r in d.related:
        if r.path is None or r.path == d.path:
            named.add(r.span.line)
            out.append(types.DiagnosticRelatedInformation(types.Location(a.uri, span_range(a.text, r.span)),
                                                          r.message))
        else:
            where = Path(r.path)
            out.append(types.DiagnosticRelatedInformation(
                types.Location(uri_of(where), lsp_range((r.span.line - 1, 0), (r.span.line - 1, 0))),
                f"{where.name}:{r.span.line}: {r.message}"))
    for m in _LINE.finditer(d.message):
        n = int(m.group(1))
        if n != d.span.line and n not in named and 1 <= n <= len(a.text.lines):
            shown = a.text.line(n - 1).strip()
            out.append(types.DiagnosticRelatedInformation(
                types.Location(a.uri, line_range(a.text, n - 1)),
                f"line {n}: {shown[:120]}" if shown else f"line {n}"))
    if a.machine is not None:
        for lf in a.machine.lists:
            if str(lf.path) in d.message and str(lf.path) != a.name:
                out.append(types.DiagnosticRelatedInformation(
                    types.Location(uri_of(lf.path), types.Range(types.Position(0, 0), types.Position(0, 0))),
                    f"{lf.key}: {lf.path.name}"))
    return out


def to_lsp(a: Analysis, d: Diagnostic, docs: RuleDocs) -> types.Diagnostic:
    """One finding as an LSP diagnostic."""
    href = docs.href(d.code)
    message = d.message if d.hint is None else f"{d.message}\nhint: {d.hint}"
    return types.Diagnostic(
        range=span_range(a.text, d.span),
        message=message,
        severity=SEVERITY[d.severity],
        code=d.code,
        code_description=types.CodeDescription(href) if href else None,
        source="zero",
        related_information=_related(a, d) or None,
        tags=[types.DiagnosticTag.Unnecessary] if d.code in UNNECESSARY else None,
        data={"param_id": d.param_id} if d.param_id else None,
    )


def note_to_lsp(a: Analysis, note: Note) -> types.Diagnostic:
    start = a.text.position(note.line, note.column)
    related = None
    if note.elsewhere is not None:  # e.g. the line of pyproject.toml that cannot be read: one click away
        path, line, column = note.elsewhere
        at = types.Position(max(0, line - 1), max(0, column - 1))
        related = [types.DiagnosticRelatedInformation(types.Location(uri_of(path), types.Range(at, at)),
                                                      f"{path.name}:{line}:{column}")]
    return types.Diagnostic(range=lsp_range(start, start), message=note.message,
                            severity=SEVERITY[note.severity], source="zero", related_information=related)


def diagnostics(a: Analysis, docs: RuleDocs, cap: int = 0) -> list[types.Diagnostic]:
    """Everything to publish for one document (built without attrs' validation of each value, which
    was half the time: a list with 100,000 findings took 6 s here). With a ``cap`` (the setting
    ``maxFindings``), the first ``cap`` of them and one finding saying how many more there are: a
    list with 50,000 findings made 32 MB of JSON per publish and locked the editor."""
    found = a.diagnostics
    notes = a.notes
    over = 0
    if cap > 0 and len(notes) + len(found) > cap:
        over = len(notes) + len(found) - cap
        notes = notes[:cap]
        found = found[:cap - len(notes)]
    with attrs.validators.disabled():
        out = [*(note_to_lsp(a, n) for n in notes), *(to_lsp(a, d, docs) for d in found)]
    if over:
        out.append(summary(a, over))
    return out


SUMMARY_CODE = "zero"


def summary(a: Analysis, more: int) -> types.Diagnostic:
    """The one finding that stands for those over the cap, at the start of the file."""
    name = Path(a.name).name if a.path is not None else a.name
    return types.Diagnostic(lsp_range((0, 0), (0, 0)),
                            f"{more} more findings not shown: run `zero lint {name}`",
                            severity=types.DiagnosticSeverity.Information, code=SUMMARY_CODE, source="zero")

"""The report for people: ruff-like findings with their source line, coloured with rich
on a terminal (rich is imported only then, so the pre-commit path stays lean), the
summary line, ``--statistics`` and the progress bar.
"""

from __future__ import annotations

import os
import sys
from collections import Counter
from collections.abc import Iterable

from zero.diagnostics import Diagnostic, Severity
from zero.engine.results import LintResult, Totals, tallied

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any, TextIO

Segment = tuple[str, str]  # (text, rich style)
MAX_SHOWN_PER_CODE = 50  # the text report shows this many findings of one code per file, then a count
_SEVERITY_STYLE = {Severity.ERROR: "bold red", Severity.WARNING: "bold yellow",
                   Severity.INFO: "bold blue"}
_SOURCE_WINDOW = 120


def use_color(stream: TextIO) -> bool:
    """Colour only on a terminal, and never with NO_COLOR set."""
    if os.environ.get("NO_COLOR"):
        return False
    if os.environ.get("FORCE_COLOR"):
        return True
    isatty = getattr(stream, "isatty", None)
    return bool(isatty and isatty())


def _window(text: str, start: int, end: int) -> tuple[str, int, int]:
    """Cut a long source line around the span; return text and new offsets."""
    text = text.replace("\t", " ")
    if len(text) <= _SOURCE_WINDOW:
        return text, start, end
    left = max(0, min(start - 20, len(text) - _SOURCE_WINDOW))
    cut = text[left : left + _SOURCE_WINDOW]
    prefix = "…" if left > 0 else ""
    suffix = "…" if left + _SOURCE_WINDOW < len(text) else ""
    shift = len(prefix) - left
    return prefix + cut + suffix, start + shift, min(end + shift, len(prefix) + len(cut))


_ESCAPES = {"\n": "\\n", "\r": "\\r"}


def _escaped(ch: str) -> str:
    """A control character or a lone surrogate as its escape: ``\\n``, ``\\r``, ``\\x1b``;
    an undecodable byte kept by ``surrogateescape`` as that byte, ``\\xff``."""
    code = ord(ch)
    if ch in _ESCAPES:
        return _ESCAPES[ch]
    if 0xDC80 <= code <= 0xDCFF:
        return f"\\x{code - 0xDC00:02x}"
    return f"\\x{code:02x}" if code <= 0xFF else f"\\u{code:04x}"


def printable(text: str, escape: bool = False) -> str:
    """Make control characters and stray bytes visible: each one character wide, as U+FFFD (the
    default: a source line keeps its columns under its caret), or as its escape (``escape``: a
    file name or a message on one line of a report, ``\\n``, ``\\r``, ``\\xff``)."""
    if text.replace("\t", " ").isprintable():  # nothing to replace (a printable character is never a control
        return text  # character nor a surrogate; a truncated line's `…` included): no loop per character
    return "".join(
        ch if ch == "\t" or (" " <= ch < "\x7f") or (ord(ch) > 0x9F and not 0xD800 <= ord(ch) <= 0xDFFF)
        else _escaped(ch) if escape else "\ufffd"
        for ch in text
    )


def diagnostic_lines(d: Diagnostic, source: str | None) -> list[list[Segment]]:
    head: list[Segment] = [
        (f"{d.path}:{d.span.line}:{d.span.column}: ", "bold"),
        (d.code, _SEVERITY_STYLE[d.severity]),
        (f" {d.severity.label} ", _SEVERITY_STYLE[d.severity]),
        (printable(d.message), ""),
    ]
    out = [head]
    if source is not None:
        start = d.span.column - 1
        end = d.span.end_column - 1 if d.span.end_line == d.span.line else len(source)
        text, s, e = _window(source, start, max(end, start))
        text = printable(text)
        num = str(d.span.line)
        pad = " " * len(num)
        out.append([(f" {pad} |", "blue")])
        out.append([(f" {num} | ", "blue"), (text, "")])
        out.append([(f" {pad} | ", "blue"), (" " * max(s, 0) + "^" * max(e - s, 1),
                                              _SEVERITY_STYLE[d.severity])])
    if d.hint:
        out.append([(f" {' ' * len(str(d.span.line))} = ", "blue"), ("hint: ", "bold"), (d.hint, "")])
    out.append([("", "")])
    return out


def summary_line(totals: Totals) -> str:
    def n(count: int, word: str) -> str:
        return f"{count} {word}{'' if count == 1 else 's'}"

    counts = totals.by_severity
    # a program zero did not (fully) follow is never clean: N010 says so, once per program
    unevaluated = 0
    if any(code.startswith("N") for code in totals.by_code):  # findings on a program: its rules are loaded
        from zero.rules.program import NOT_EVALUATED  # start-up: a list's lint does not load the program rules

        unevaluated = sum(totals.by_code.get(code, 0) for code in NOT_EVALUATED)
    clean = f"{totals.clean} clean" + (f", {unevaluated} not fully evaluated" if unevaluated else "")
    return (
        f"{n(totals.files, 'file')} checked ({clean}): {n(counts.get(Severity.ERROR, 0), 'error')}, "
        f"{n(counts.get(Severity.WARNING, 0), 'warning')}, {n(counts.get(Severity.INFO, 0), 'info')}"
    )


class TextWriter:
    """Writes segment lines plain, or through rich when colour is on."""

    def __init__(self, stream: TextIO, color: bool) -> None:
        self.stream = stream
        self.console = None
        if color:
            from rich.console import Console  # start-up: rich only when colour is on

            self.console = Console(file=stream, force_terminal=True, highlight=False,
                                   soft_wrap=True, emoji=False, markup=False)

    def line(self, segments: Iterable[Segment]) -> None:
        if self.console is None:
            self.stream.write("".join(t for t, _ in segments) + "\n")
            return
        from rich.text import Text  # start-up: rich only when colour is on

        self.console.print(Text.assemble(*[(t, s) if s else t for t, s in segments]))


def render_text(results: Iterable[LintResult], stream: TextIO | None = None,
                color: bool | None = None, summary: bool = True,
                summary_stream: TextIO | None = None, totals: Totals | None = None) -> None:
    """Findings with their source line; the summary line to ``summary_stream`` (default: the
    same stream; the CLI sends it to stderr so that standard output holds findings only).
    ``results`` is read once, in order: it may be a stream of results made as it is read. Each
    is counted into ``totals`` (the caller's, when it needs them afterwards)."""
    stream = stream or sys.stdout
    writer = TextWriter(stream, use_color(stream) if color is None else color)
    totals = Totals() if totals is None else totals
    for r in tallied(results, totals):
        shown: Counter[str] = Counter()
        for d in r.diagnostics:
            shown[d.code] += 1
            if shown[d.code] > MAX_SHOWN_PER_CODE:
                continue
            src = r.document.line_text(d.span.line) if r.document.has_line(d.span.line) else None
            for segs in diagnostic_lines(d, src):
                writer.line(segs)
        for code, n in sorted(shown.items()):
            if n > MAX_SHOWN_PER_CODE:
                writer.line([(f"{r.path}: … and {n - MAX_SHOWN_PER_CODE:,} more {code} findings in this file "
                              "(every one is in --output-format json or concise)", "bold")])
                writer.line([("", "")])
    if summary:
        worst = totals.worst
        style = _SEVERITY_STYLE[worst] if worst is not None else "bold green"
        target = writer
        if summary_stream is not None and summary_stream is not stream:
            target = TextWriter(summary_stream, use_color(summary_stream) if color is None else color)
        target.line([(summary_line(totals), style)])


def statistics(totals: Totals) -> str:
    """Counts per code, most frequent first (``--statistics``)."""
    from zero.rules import RULES  # start-up: the rules' names only for --statistics (a cached run imports no rule)

    counts = totals.by_code
    lines = [f"{n:>7}  {code}  {RULES[code].name if code in RULES else ''}"
             for code, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))]
    return "\n".join(lines) + ("\n" if lines else "")


def statistics_json(totals: Totals) -> str:
    """Counts per code, most frequent first, as a JSON array (``--statistics`` with a JSON format)."""
    import json  # start-up: only for --statistics with JSON

    from zero.rules import RULES  # start-up: as in statistics()

    rows = [{"code": c, "name": RULES[c].name if c in RULES else None, "count": n}
            for c, n in sorted(totals.by_code.items(), key=lambda kv: (-kv[1], kv[0]))]
    return json.dumps(rows, indent=2) + "\n"


PROGRESS_MIN_FILES = 200


class ProgressBar:
    """A progress bar on stderr (rich's), only on a terminal and only for long runs; gone when done."""

    def __init__(self, stream: TextIO | None = None) -> None:
        self.stream = stream or sys.stderr
        self.shown = False
        self._progress: Any = None
        self._task: Any = None

    def start(self, total: int) -> ProgressBar | None:
        if total < PROGRESS_MIN_FILES or not self.stream.isatty():
            return None
        from rich.console import Console  # start-up: only a long run on a terminal shows a bar
        from rich.progress import (  # start-up: as above
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeRemainingColumn,
        )

        self._progress = Progress(TextColumn("zero:"), BarColumn(), MofNCompleteColumn(), TextColumn("files"),
                                  TimeRemainingColumn(), console=Console(file=self.stream), transient=True)
        self._progress.start()
        self._task = self._progress.add_task("lint", total=total)
        self.shown = True
        return self

    def __call__(self, done: int, total: int) -> None:
        if self._progress is not None:
            self._progress.update(self._task, completed=done, total=total)

    def finish(self) -> None:
        if self._progress is not None:
            self._progress.stop()
            self._progress = None

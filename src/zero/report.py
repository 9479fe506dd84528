"""Render findings: ruff-like text (coloured with rich on a terminal) and JSON.

rich is imported only when colour is on, so the pre-commit path (not a
terminal) stays lean.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, TextIO

from zero.diagnostics import Diagnostic, Severity
from zero.lint import LintResult
from zero.registry import KINDS, ParamSpec, Registry
from zero.rules import RULES

if TYPE_CHECKING:
    from zero.diff import Change

Segment = tuple[str, str]  # (text, rich style)
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


def _printable(text: str) -> str:
    """Make control characters and stray bytes visible."""
    return "".join(
        ch if ch == "\t" or (" " <= ch < "\x7f") or (ord(ch) > 0x9F and not 0xD800 <= ord(ch) <= 0xDFFF)
        else "\ufffd"
        for ch in text
    )


def diagnostic_lines(d: Diagnostic, source: str | None) -> list[list[Segment]]:
    head: list[Segment] = [
        (f"{d.path}:{d.span.line}:{d.span.column}: ", "bold"),
        (d.code, _SEVERITY_STYLE[d.severity]),
        (f" {d.severity.label} ", _SEVERITY_STYLE[d.severity]),
        (_printable(d.message), ""),
    ]
    out = [head]
    if source is not None:
        start = d.span.column - 1
        end = d.span.end_column - 1 if d.span.end_line == d.span.line else len(source)
        text, s, e = _window(source, start, max(end, start))
        text = _printable(text)
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


def summary_line(results: Sequence[LintResult]) -> str:
    counts = {s: 0 for s in Severity}
    for r in results:
        for d in r.diagnostics:
            counts[d.severity] += 1
    files = len(results)
    clean = sum(1 for r in results if not r.diagnostics)

    def n(count: int, word: str) -> str:
        return f"{count} {word}{'' if count == 1 else 's'}"

    return (
        f"{n(files, 'file')} checked ({clean} clean): {n(counts[Severity.ERROR], 'error')}, "
        f"{n(counts[Severity.WARNING], 'warning')}, {n(counts[Severity.INFO], 'info')}"
    )


class TextWriter:
    """Writes segment lines plain, or through rich when colour is on."""

    def __init__(self, stream: TextIO, color: bool) -> None:
        self.stream = stream
        self.console = None
        if color:
            from rich.console import Console

            self.console = Console(file=stream, force_terminal=True, highlight=False,
                                   soft_wrap=True, emoji=False, markup=False)

    def line(self, segments: Iterable[Segment]) -> None:
        if self.console is None:
            self.stream.write("".join(t for t, _ in segments) + "\n")
            return
        from rich.text import Text

        self.console.print(Text.assemble(*[(t, s) if s else t for t, s in segments]))


def render_text(results: Sequence[LintResult], stream: TextIO | None = None,
                color: bool | None = None, summary: bool = True) -> None:
    stream = stream or sys.stdout
    writer = TextWriter(stream, use_color(stream) if color is None else color)
    for r in results:
        for d in r.diagnostics:
            src = r.document.line_text(d.span.line) if d.span.line <= len(r.document.lines) else None
            for segs in diagnostic_lines(d, src):
                writer.line(segs)
    if summary:
        worst = max((r.worst for r in results if r.worst is not None), default=None)
        style = _SEVERITY_STYLE[worst] if worst is not None else "bold green"
        writer.line([(summary_line(results), style)])


def render_json(results: Sequence[LintResult], stream: TextIO | None = None) -> None:
    stream = stream or sys.stdout
    data = [d.to_json() for r in results for d in r.diagnostics]
    stream.write(json.dumps(data, indent=2) + "\n")


def rule_text(code: str) -> str:
    r = RULES[code]
    return r.render()


def rules_overview() -> str:
    lines = []
    for code, r in RULES.items():
        lines.append(f"{code}  {r.severity.label:<7}  {r.name:<30} {r.summary}")
    return "\n".join(lines) + "\n"


def param_text(spec: ParamSpec, registry: Registry) -> str:
    rng = registry.range_of(spec)
    if rng is not None:
        range_text = f"{spec.range_text}  (checked)"
    elif spec.range_note:
        range_text = f"{spec.range_note}  (prose, not checked)"
    elif spec.type == "BOOLEAN":
        range_text = "0/1 (FALSE/TRUE)"
    else:
        range_text = "not stated formally (not checked)"
    dims = ""
    if spec.dims:
        names = spec.key.split("[]") if spec.key else []
        parts = []
        for i, size in enumerate(spec.dims):
            member = names[i].rsplit(".", 1)[-1] if i < len(names) else "?"
            base = spec.index_base if i == 0 else 0
            parts.append(f"{member}[{base}..]" if base else f"{member}[0..{size - 1}]")
        dims = ", ".join(parts)
    rows = [
        ("ID", spec.id),
        ("key", spec.key or "(no list key documented)"),
        ("list", KINDS.get(spec.kind, (spec.kind, spec.kind))[1]),
        ("type", spec.type + (f", at most {spec.max_len} characters" if spec.max_len else "")),
        ("range", range_text),
        ("default", spec.default_display),
        ("unit", " or ".join(spec.units) if spec.units else "–"),
    ]
    if dims:
        rows.append(("indices", dims))
    if spec.symbols:
        rows.append(("symbols", ", ".join(n if v is None else f"{n}={v}" for n, v in spec.symbols)))
    if spec.restart:
        rows.append(("restart", "a change takes effect only after a restart"))
    rows.append(("meaning", spec.description or "(no description; load your CncParaDesc.xml with --param-desc)"))
    rows.append(("source", spec.source))
    width = max(len(k) for k, _ in rows)
    return "\n".join(f"{k:<{width}}  {v}" for k, v in rows) + "\n"


def render_diff(changes: Sequence[Change], header: str, stream: TextIO | None = None,
                color: bool | None = None) -> None:
    """The changes of ``zero diff``: a rich table on a terminal, aligned text otherwise."""
    from zero.diff import render_plain, rows, summary

    stream = stream or sys.stdout
    if not (use_color(stream) if color is None else color):
        stream.write(render_plain(list(changes), header))
        stream.write(summary(list(changes)) + "\n")
        return
    from rich.console import Console
    from rich.table import Table

    console = Console(file=stream, force_terminal=True, highlight=False, emoji=False, markup=False)
    console.print(header, style="bold")
    styles = {"+": "green", "-": "red", "~": "yellow", "=": "dim", "#": "cyan"}
    for group, cells in rows(changes):
        table = Table(title=group, title_justify="left", title_style="bold", box=None, pad_edge=False)
        for name in ("", "key", "ID", "old → new", "delta", ""):
            table.add_column(name, no_wrap=name in ("key", "ID"))
        for r in cells:
            table.add_row(*r, style=styles.get(r[0], ""))
        console.print(table)
    console.print(summary(list(changes)), style="bold")

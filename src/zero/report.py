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
    from zero.machine import Ip247Violation, LimitRow

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
                color: bool | None = None, summary: bool = True,
                summary_stream: TextIO | None = None) -> None:
    """Findings with their source line; the summary line to ``summary_stream`` (default: the
    same stream; the CLI sends it to stderr so that standard output holds findings only)."""
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
        target = writer
        if summary_stream is not None and summary_stream is not stream:
            target = TextWriter(summary_stream, use_color(summary_stream) if color is None else color)
        target.line([(summary_line(results), style)])


def _all(results: Sequence[LintResult]) -> list[Diagnostic]:
    return [d for r in results for d in r.diagnostics]


def render_concise(results: Sequence[LintResult], stream: TextIO) -> None:
    """One line per finding: ``path:line:col: CODE severity message``."""
    for d in _all(results):
        stream.write(f"{d.path}:{d.span.line}:{d.span.column}: {d.code} {d.severity.label} "
                     f"{_printable(d.message)}\n")


def _gh_escape(text: str, prop: bool = False) -> str:
    text = text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")
    return text.replace(":", "%3A").replace(",", "%2C") if prop else text


def render_github(results: Sequence[LintResult], stream: TextIO) -> None:
    """GitHub Actions workflow commands: an annotation per finding."""
    level = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}
    for d in _all(results):
        props = (f"file={_gh_escape(d.path, True)},line={d.span.line},col={d.span.column},"
                 f"endLine={d.span.end_line},endColumn={d.span.end_column},"
                 f"title={_gh_escape(f'zero {d.code}', True)}")
        stream.write(f"::{level[d.severity]} {props}::{_gh_escape(f'{d.code} {d.message}')}\n")


def render_gitlab(results: Sequence[LintResult], stream: TextIO) -> None:
    """GitLab code quality report (a JSON array of issues)."""
    import hashlib

    severity = {Severity.ERROR: "major", Severity.WARNING: "minor", Severity.INFO: "info"}
    out = []
    for d in _all(results):
        fp = hashlib.sha256(f"{d.path}\0{d.code}\0{d.span.line}\0{d.message}".encode(
            "utf-8", "surrogateescape")).hexdigest()
        out.append({"description": f"{d.code} {d.message}", "check_name": d.code, "fingerprint": fp,
                    "severity": severity[d.severity],
                    "location": {"path": d.path, "lines": {"begin": d.span.line, "end": d.span.end_line}}})
    stream.write(json.dumps(out, indent=2) + "\n")


def render_junit(results: Sequence[LintResult], stream: TextIO) -> None:
    """JUnit XML: one test suite per file, one failing test case per finding."""
    import xml.etree.ElementTree as ET

    total = sum(len(r.diagnostics) for r in results)
    suites = ET.Element("testsuites", name="zero", tests=str(max(total, len(results))),
                        failures=str(total))
    for r in results:
        suite = ET.SubElement(suites, "testsuite", name=r.path, tests=str(max(len(r.diagnostics), 1)),
                              failures=str(len(r.diagnostics)))
        if not r.diagnostics:
            ET.SubElement(suite, "testcase", name=f"{r.path} clean", classname=r.path)
        for d in r.diagnostics:
            case = ET.SubElement(suite, "testcase", name=f"{d.code} line {d.span.line}",
                                 classname=r.path, file=r.path, line=str(d.span.line))
            failure = ET.SubElement(case, "failure", message=_printable(d.message), type=d.code)
            failure.text = (f"{d.path}:{d.span.line}:{d.span.column}: {d.code} {d.severity.label} "
                            f"{_printable(d.message)}")
    stream.write(ET.tostring(suites, encoding="unicode", xml_declaration=True) + "\n")


def render_sarif(results: Sequence[LintResult], stream: TextIO) -> None:
    """SARIF 2.1.0: the rules that fired and one result per finding."""
    from zero import __version__

    level = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}
    used = sorted({d.code for d in _all(results)})
    rules = [{"id": c, "name": RULES[c].name, "shortDescription": {"text": RULES[c].summary},
              "fullDescription": {"text": RULES[c].explanation.strip()},
              "defaultConfiguration": {"level": level[RULES[c].severity]},
              "help": {"text": RULES[c].explanation.strip()}} for c in used if c in RULES]
    index = {c: i for i, c in enumerate(used)}
    res = []
    for d in _all(results):
        item: dict[str, object] = {
            "ruleId": d.code, "ruleIndex": index[d.code], "level": level[d.severity],
            "message": {"text": _printable(d.message)},
            "locations": [{"physicalLocation": {
                "artifactLocation": {"uri": d.path.replace(os.sep, "/")},
                "region": {"startLine": d.span.line, "startColumn": d.span.column,
                           "endLine": d.span.end_line, "endColumn": d.span.end_column}}}],
        }
        if d.param_id:
            item["properties"] = {"parameterId": d.param_id}
        res.append(item)
    log = {"$schema": "https://json.schemastore.org/sarif-2.1.0.json", "version": "2.1.0",
           "runs": [{"tool": {"driver": {"name": "zero", "version": __version__,
                                         "informationUri": "https://zero.invalid/", "rules": rules}},
                     "results": res, "columnKind": "unicodeCodePoints"}]}
    stream.write(json.dumps(log, indent=2) + "\n")


def statistics(results: Sequence[LintResult]) -> str:
    """Counts per code, most frequent first (``--statistics``)."""
    from collections import Counter

    counts = Counter(d.code for d in _all(results))
    lines = [f"{n:>7}  {code}  {RULES[code].name if code in RULES else ''}"
             for code, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))]
    return "\n".join(lines) + ("\n" if lines else "")


RENDERERS = {"concise": render_concise, "github": render_github, "gitlab": render_gitlab,
             "junit": render_junit, "sarif": render_sarif}


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


def render_limits(rows: Sequence[LimitRow], violations: Sequence[Ip247Violation] = (),
                  stream: TextIO | None = None, color: bool | None = None) -> None:
    """``zero limits``: a rich table on a terminal, aligned text otherwise."""
    from zero.machine import ZERO_UNIT, g_code

    stream = stream or sys.stdout
    head = ("ch", "offset", "axis", "unit", "ACS min", "ACS max", "offset value", "PCS min", "PCS max", "")
    cells = [(str(r.channel), g_code(r.group), f"{r.axis_index} {r.axis_name}", r.unit,
              *(f"{v / ZERO_UNIT:.4f}" for v in (r.acs_neg, r.acs_pos, r.offset, r.pcs_neg, r.pcs_pos)),
              r.note) for r in rows]
    if use_color(stream) if color is None else color:
        from rich.console import Console
        from rich.table import Table

        table = Table(*head, title="soft limits in the programming coordinate system", title_justify="left")
        for c in cells:
            table.add_row(*c)
        console = Console(file=stream, force_terminal=True, highlight=False, emoji=False, markup=False)
        console.print(table)
        for v in violations:
            console.print(f"IP247: {v.what} {v.value / ZERO_UNIT:.4f} mm outside ±99999.999 mm ({v.where})",
                          style="bold red")
        return
    widths = [max(len(head[i]), *(len(c[i]) for c in cells)) if cells else len(head[i]) for i in range(10)]
    right = {4, 5, 6, 7, 8}
    for c in [head, *cells]:
        stream.write("  ".join(c[i].rjust(widths[i]) if i in right else c[i].ljust(widths[i])
                               for i in range(10)).rstrip() + "\n")
    for v in violations:
        stream.write(f"IP247: {v.what} {v.value / ZERO_UNIT:.4f} mm outside ±99999.999 mm ({v.where})\n")

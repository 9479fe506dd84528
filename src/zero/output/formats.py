"""Reports for machines: JSON (zero's stable contract), concise lines, GitHub annotations,
GitLab code quality, JUnit XML and SARIF 2.1.0.
"""

from __future__ import annotations

import hashlib
import json
import os
import urllib.parse
from collections.abc import Callable, Iterable, Iterator, Sequence
from pathlib import Path
from typing import Any, TextIO

from zero import __version__
from zero.diagnostics import Diagnostic, Severity
from zero.engine.lint import LintResult
from zero.output.text import printable
from zero.rules import RULES


def _each(results: Iterable[LintResult]) -> Iterator[Diagnostic]:
    """The findings of results read once, in order (they may be made as they are read)."""
    for r in results:
        yield from r.diagnostics


def indented_json(value: Any, level: int = 0) -> str:
    """``json.dumps(value, indent=2)``, byte for byte, at nesting ``level``. The standard library
    writes indented JSON through nested closures that call each other: every call leaves a
    reference cycle that only the cycle collector frees, and the report of a fleet made one per
    finding. Scalars still go through :func:`json.dumps`."""
    pad = "\n" + "  " * (level + 1)
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = (f"{json.dumps(k if isinstance(k, str) else json.dumps(k))}: {indented_json(v, level + 1)}"
                 for k, v in value.items())
        return "{" + pad + ("," + pad).join(items) + "\n" + "  " * level + "}"
    if isinstance(value, (list, tuple)):
        if not value:
            return "[]"
        return "[" + pad + ("," + pad).join(indented_json(v, level + 1) for v in value) + "\n" + "  " * level + "]"
    return json.dumps(value)


def render_json(results: Iterable[LintResult], stream: TextIO) -> None:
    """The JSON contract of ``--output-format json``: one object per finding. Written object by
    object (the bytes ``json.dumps(all, indent=2)`` gives, without holding them all: JSON escapes
    every newline inside a string, so each object's lines can be indented on their own)."""
    opened = False
    try:
        for d in _each(results):
            stream.write(",\n  " if opened else "[\n  ")
            stream.write(indented_json(d.to_json(), 1))
            opened = True
    finally:  # results made as they are read may stop with an error (exit 2): the JSON stays whole
        stream.write("\n]\n" if opened else "[]\n")


def render_concise(results: Iterable[LintResult], stream: TextIO) -> None:
    """One line per finding: ``path:line:col: CODE severity message``."""
    for d in _each(results):
        stream.write(f"{d.path}:{d.span.line}:{d.span.column}: {d.code} {d.severity.label} "
                     f"{printable(d.message)}\n")


def _gh_escape(text: str, prop: bool = False) -> str:
    text = text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")
    return text.replace(":", "%3A").replace(",", "%2C") if prop else text


def render_github(results: Iterable[LintResult], stream: TextIO) -> None:
    """GitHub Actions workflow commands: an annotation per finding."""
    level = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}
    for d in _each(results):
        props = (f"file={_gh_escape(d.path, True)},line={d.span.line},col={d.span.column},"
                 f"endLine={d.span.end_line},endColumn={d.span.end_column},"
                 f"title={_gh_escape(f'zero {d.code}', True)}")
        stream.write(f"::{level[d.severity]} {props}::{_gh_escape(f'{d.code} {d.message}')}\n")


def _subject(d: Diagnostic, r: LintResult) -> str:
    """What a finding is about, without its line: the key (or the line's text) it stands on."""
    text = r.document.line_text(d.span.line)
    return text.split(None, 1)[0] if text.strip() else ""


def render_gitlab(results: Sequence[LintResult], stream: TextIO) -> None:
    """GitLab code quality report (a JSON array of issues). The fingerprint stays the same when
    lines move: it is made of the path, the code, the key the finding stands on and which
    occurrence of that triple it is, not of the line number."""
    severity = {Severity.ERROR: "major", Severity.WARNING: "minor", Severity.INFO: "info"}
    out = []
    for r in results:
        seen: dict[tuple[str, str, str], int] = {}
        for d in r.diagnostics:
            ident = (d.path, d.code, d.param_id or _subject(d, r))
            seen[ident] = seen.get(ident, 0) + 1
            fp = hashlib.sha256("\0".join((*ident, str(seen[ident]))).encode("utf-8", "surrogateescape")).hexdigest()
            out.append({"description": f"{d.code} {d.message}", "check_name": d.code, "fingerprint": fp,
                        "severity": severity[d.severity],
                        "location": {"path": d.path, "lines": {"begin": d.span.line, "end": d.span.end_line}}})
    stream.write(json.dumps(out, indent=2) + "\n")


def render_junit(results: Sequence[LintResult], stream: TextIO) -> None:
    """JUnit XML: one test suite per file, one test case per finding. Errors are failures;
    warnings and infos are passing test cases that carry the finding in ``system-out``, so a CI
    job fails on what ``zero lint`` exits 1 for (without ``--strict``)."""
    import xml.etree.ElementTree as ET  # start-up: only for JUnit output

    def failing(r: LintResult) -> int:
        return sum(1 for d in r.diagnostics if d.severity >= Severity.ERROR)

    total = sum(len(r.diagnostics) for r in results)
    suites = ET.Element("testsuites", name="zero", tests=str(max(total, len(results))),
                        failures=str(sum(failing(r) for r in results)))
    for r in results:
        suite = ET.SubElement(suites, "testsuite", name=r.path, tests=str(max(len(r.diagnostics), 1)),
                              failures=str(failing(r)))
        if not r.diagnostics:
            ET.SubElement(suite, "testcase", name=f"{r.path} clean", classname=r.path)
        for d in r.diagnostics:
            case = ET.SubElement(suite, "testcase", name=f"{d.code} line {d.span.line}",
                                 classname=r.path, file=r.path, line=str(d.span.line))
            text = f"{d.path}:{d.span.line}:{d.span.column}: {d.code} {d.severity.label} {printable(d.message)}"
            if d.severity >= Severity.ERROR:
                failure = ET.SubElement(case, "failure", message=printable(d.message), type=d.code)
                failure.text = text
            else:
                ET.SubElement(case, "system-out").text = text
    stream.write(ET.tostring(suites, encoding="unicode", xml_declaration=True) + "\n")


def artifact_uri(path: str) -> dict[str, str]:
    """A SARIF artifact location: a percent-encoded URI reference, relative to ``%SRCROOT%`` (the
    working directory) where the file lies below it, else an absolute ``file:`` URI."""
    absolute = os.path.abspath(path)
    rel = os.path.relpath(absolute)
    if not rel.startswith(".."):
        return {"uri": urllib.parse.quote(rel.replace(os.sep, "/")), "uriBaseId": "%SRCROOT%"}
    return {"uri": Path(absolute).as_uri()}


def render_sarif(results: Sequence[LintResult], stream: TextIO) -> None:
    """SARIF 2.1.0: the rules that fired and one result per finding."""
    level = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}
    used = sorted({d.code for d in _each(results)})
    rules = [{"id": c, "name": RULES[c].name, "shortDescription": {"text": RULES[c].summary},
              "fullDescription": {"text": RULES[c].explanation.strip()},
              "defaultConfiguration": {"level": level[RULES[c].severity]},
              "help": {"text": RULES[c].explanation.strip()}} for c in used if c in RULES]
    index = {c: i for i, c in enumerate(used)}
    res = []
    for d in _each(results):
        item: dict[str, object] = {
            "ruleId": d.code, "ruleIndex": index[d.code], "level": level[d.severity],
            "message": {"text": printable(d.message)},
            "locations": [{"physicalLocation": {
                "artifactLocation": artifact_uri(d.path),
                "region": {"startLine": d.span.line, "startColumn": d.span.column,
                           "endLine": d.span.end_line, "endColumn": d.span.end_column}}}],
        }
        if d.related:
            item["relatedLocations"] = [
                {"id": n, "message": {"text": printable(r.message)}, "physicalLocation": {
                    "artifactLocation": artifact_uri(r.path or d.path),
                    "region": {"startLine": r.span.line, "startColumn": r.span.column,
                               "endLine": r.span.end_line, "endColumn": r.span.end_column}}}
                for n, r in enumerate(d.related)]
        properties = {k: v for k, v in (("parameterId", d.param_id), ("kernelError", d.kernel_error)) if v}
        if properties:
            item["properties"] = properties
        res.append(item)
    log = {"$schema": "https://json.schemastore.org/sarif-2.1.0.json", "version": "2.1.0",
           "runs": [{"originalUriBaseIds": {"%SRCROOT%": {"uri": Path.cwd().as_uri() + "/"}},
                     "tool": {"driver": {"name": "zero", "version": __version__,
                                         "informationUri": "https://zero.invalid/", "rules": rules}},
                     "results": res, "columnKind": "unicodeCodePoints"}]}
    stream.write(json.dumps(log, indent=2) + "\n")


# The formats written finding by finding as the results come: a report of many files in one of
# them (or in text) does not hold the files' results, so its memory does not grow with them.
STREAMED: dict[str, Callable[[Iterable[LintResult], TextIO], None]] = {
    "json": render_json, "concise": render_concise, "github": render_github}
RENDERERS: dict[str, Callable[[Sequence[LintResult], TextIO], None]] = {
    **STREAMED, "gitlab": render_gitlab, "junit": render_junit, "sarif": render_sarif}

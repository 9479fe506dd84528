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
from zero.diagnostics import Diagnostic, Severity, Span
from zero.engine.lint import LintResult, is_unreadable
from zero.output.text import printable
from zero.rules import RULES

# Where a rule's text is on the web, ``{code}`` replaced by its code: each SARIF rule's
# ``helpUri``. zero has no public home yet, so there is none by default (SARIF makes it
# optional; the rule's text is in the log itself, ``help``); whoever publishes the rule texts
# sets it here, or passes ``rule_docs`` to :func:`render_sarif`.
RULE_DOCS_URL: str | None = None
DOCS_URL_VARIABLE = "ZERO_DOCS_URL"  # the documentation site's address (`https://…`): rule pages below it


def rule_docs_template() -> str | None:
    """Where each rule's page is (``{code}`` for its code): :data:`RULE_DOCS_URL` where set, else
    below the documentation site ``$ZERO_DOCS_URL`` names (``<site>/rules/R006/``, the page the
    site's generator writes); ``None`` where zero knows no address (the rule's text then travels
    in the report itself)."""
    if RULE_DOCS_URL:
        return RULE_DOCS_URL
    site = os.environ.get(DOCS_URL_VARIABLE, "").strip()
    return f"{site.rstrip('/')}/rules/{{code}}/" if site.startswith(("https://", "http://")) else None
# The tool's home page (SARIF ``informationUri``); none by default, for the same reason: the
# documentation site's address ($ZERO_DOCS_URL) where it is set.
PROJECT_URL: str | None = None


def information_uri() -> str | None:
    """SARIF ``tool.driver.informationUri``: :data:`PROJECT_URL`, else the documentation site."""
    if PROJECT_URL:
        return PROJECT_URL
    site = os.environ.get(DOCS_URL_VARIABLE, "").strip()
    return site.rstrip("/") + "/" if site.startswith(("https://", "http://")) else None
# The name of zero's own fingerprint among a SARIF result's ``partialFingerprints``.
SARIF_FINGERPRINT = "zeroKeyHash/v1"


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
    """One line per finding: ``path:line:col: CODE severity message``. A control character or an
    undecodable byte in the path or the message is written as its escape (``\\n``, ``\\r``,
    ``\\xff``): one finding stays one line, and the name can still be told."""
    for d in _each(results):
        stream.write(f"{printable(d.path, escape=True)}:{d.span.line}:{d.span.column}: {d.code} "
                     f"{d.severity.label} {printable(d.message, escape=True)}\n")


def repo_path(path: str, root: str | None = None) -> str:
    """``path`` relative to ``root`` (by default the working directory, the repository's root in
    CI), with ``/`` between its parts, as GitLab and GitHub expect; as given where it lies outside
    (or is ``-``)."""
    if path == "-":
        return path
    try:
        rel = os.path.relpath(os.path.abspath(path), os.path.abspath(root) if root else None)
    except ValueError:  # another drive (Windows)
        return path
    if rel == os.pardir or rel.startswith(os.pardir + os.sep):
        return path
    return rel.replace(os.sep, "/")


def _gh_escape(text: str, prop: bool = False) -> str:
    text = text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")
    return text.replace(":", "%3A").replace(",", "%2C") if prop else text


def render_github(results: Iterable[LintResult], stream: TextIO) -> None:
    """GitHub Actions workflow commands: an annotation per finding."""
    level = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}
    for d in _each(results):
        props = (f"file={_gh_escape(repo_path(d.path), True)},line={d.span.line},col={d.span.column},"
                 f"endLine={d.span.end_line},endColumn={d.span.end_column},"
                 f"title={_gh_escape(f'zero {d.code}', True)}")
        stream.write(f"::{level[d.severity]} {props}::{_gh_escape(f'{d.code} {d.message}')}\n")


def _subject(d: Diagnostic, r: LintResult) -> str:
    """What a finding is about, without its line: the key as written on its line, indices and
    all (``np_grp[2].achse[0].versch``), or the line's first word."""
    text = r.document.line_text(d.span.line)
    return text.split(None, 1)[0] if text.strip() else ""


def fingerprints(r: LintResult, root: str | None = None) -> list[str]:
    """A fingerprint per finding of ``r``, in order, that stays the same when lines move or other
    findings come and go: made of the repository-relative path, the code, the key as written
    (with its indices: every index of a parameter shares its ID) and which occurrence of that
    triple it is (a key written twice), never of the line number."""
    seen: dict[tuple[str, str, str], int] = {}
    out = []
    for d in r.diagnostics:
        ident = (repo_path(d.path, root), d.code, _subject(d, r))
        seen[ident] = seen.get(ident, 0) + 1
        text = "\0".join((*ident, str(seen[ident])))
        out.append(hashlib.sha256(text.encode("utf-8", "surrogateescape")).hexdigest())
    return out


def render_gitlab(results: Sequence[LintResult], stream: TextIO) -> None:
    """GitLab code quality report (a JSON array of issues), paths relative to the repository:
    to ``$CI_PROJECT_DIR`` where GitLab sets it (a job run from a subfolder keeps the prefix),
    else to the working directory; the fingerprint is :func:`fingerprints`'."""
    severity = {Severity.ERROR: "major", Severity.WARNING: "minor", Severity.INFO: "info"}
    root = os.environ.get("CI_PROJECT_DIR") or None
    out = []
    for r in results:
        for d, fp in zip(r.diagnostics, fingerprints(r, root), strict=True):
            out.append({"description": f"{d.code} {d.message}", "check_name": d.code, "fingerprint": fp,
                        "severity": severity[d.severity],
                        "location": {"path": repo_path(d.path, root),
                                     "lines": {"begin": d.span.line, "end": d.span.end_line}}})
    stream.write(json.dumps(out, indent=2) + "\n")


def render_junit(results: Sequence[LintResult], stream: TextIO, fail_on: Severity = Severity.ERROR) -> None:
    """JUnit XML as Jenkins' ``junit-10.xsd`` has it: one test suite per file, one test case per
    finding (a clean file: one passing case). A finding of ``fail_on`` or worse is a failure
    (``Severity.WARNING`` under ``--strict``, as the exit code); a file that could not be read
    (F001) is an error; the others pass and carry the finding in ``system-out``. Where it is
    (``path:line:col``) is in each case's text: the schema has no attribute for it."""
    import xml.etree.ElementTree as ET  # start-up: only for JUnit output

    suites = ET.Element("testsuites", name="zero")
    counts = {"tests": 0, "failures": 0, "errors": 0}
    for r in results:
        shown = printable(r.path, escape=True)
        suite = ET.SubElement(suites, "testsuite", name=shown)
        tally = {"tests": max(len(r.diagnostics), 1), "failures": 0, "errors": 0}
        if not r.diagnostics:
            ET.SubElement(suite, "testcase", name=f"{shown} clean", classname=shown)
        for d in r.diagnostics:
            case = ET.SubElement(suite, "testcase", name=f"{d.code} line {d.span.line}", classname=shown)
            message = printable(d.message, escape=True)
            where = f"{printable(d.path, escape=True)}:{d.span.line}:{d.span.column}"
            text = f"{where}: {d.code} {d.severity.label} {message}"
            if d.code == "F001":
                ET.SubElement(case, "error", message=message, type=d.code).text = text
                tally["errors"] += 1
            elif d.severity >= fail_on:
                ET.SubElement(case, "failure", message=message, type=d.code).text = text
                tally["failures"] += 1
            else:
                ET.SubElement(case, "system-out").text = text
        for k, n in tally.items():
            suite.set(k, str(n))
            counts[k] += n
        suite.set("skipped", "0")
    for k, n in counts.items():
        suites.set(k, str(n))
    stream.write(ET.tostring(suites, encoding="unicode", xml_declaration=True) + "\n")


def artifact_uri(path: str) -> dict[str, str]:
    """A SARIF artifact location: a percent-encoded URI reference, relative to ``%SRCROOT%`` (the
    working directory) where the file lies below it, else an absolute ``file:`` URI."""
    absolute = os.path.abspath(path)
    rel = repo_path(absolute)
    if rel != absolute:
        return {"uri": urllib.parse.quote(rel, errors="surrogateescape"), "uriBaseId": "%SRCROOT%"}
    return {"uri": Path(absolute).as_uri()}


def _region(span: Span) -> dict[str, int]:
    return {"startLine": span.line, "startColumn": span.column,
            "endLine": span.end_line, "endColumn": span.end_column}


def render_sarif(results: Sequence[LintResult], stream: TextIO, rule_docs: str | None = None) -> None:
    """SARIF 2.1.0: the rules that fired (each with its ``helpUri`` where ``rule_docs``, else
    :data:`RULE_DOCS_URL`, says where the rules' texts are), one result per finding with its
    fingerprint (``partialFingerprints``: that of :func:`fingerprints`, so a result uploaded again
    is known again) and the invocation: not successful when a file could not be read (F001, the
    run exits 2), each such file a notification."""
    from zero.output.docs import explanation_markdown  # start-up: only for SARIF

    docs = rule_docs if rule_docs is not None else rule_docs_template()
    level = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}
    used = sorted({d.code for d in _each(results)})
    rules: list[dict[str, object]] = []
    for c in used:
        if c not in RULES:
            continue
        rule: dict[str, object] = {
            "id": c, "name": RULES[c].name, "shortDescription": {"text": RULES[c].summary},
            "fullDescription": {"text": RULES[c].explanation.strip()},
            "defaultConfiguration": {"level": level[RULES[c].severity]},
            "help": {"text": RULES[c].explanation.strip(), "markdown": explanation_markdown(RULES[c].explanation)}}
        if docs:
            rule["helpUri"] = docs.replace("{code}", urllib.parse.quote(c))
        rules.append(rule)
    index = {c: i for i, c in enumerate(used)}
    res = []
    notifications = []
    for r in results:
        for d, fp in zip(r.diagnostics, fingerprints(r), strict=True):
            location = {"physicalLocation": {"artifactLocation": artifact_uri(d.path), "region": _region(d.span)}}
            item: dict[str, object] = {
                "ruleId": d.code, "ruleIndex": index[d.code], "level": level[d.severity],
                "message": {"text": printable(d.message)},
                "locations": [location],
                "partialFingerprints": {SARIF_FINGERPRINT: fp},
            }
            if d.related:
                item["relatedLocations"] = [
                    {"id": n, "message": {"text": printable(rel.message)}, "physicalLocation": {
                        "artifactLocation": artifact_uri(rel.path or d.path), "region": _region(rel.span)}}
                    for n, rel in enumerate(d.related)]
            properties = {k: v for k, v in (("parameterId", d.param_id), ("kernelError", d.kernel_error),
                                            ("consequence", d.consequence), ("source", d.source)) if v}
            if properties:
                item["properties"] = properties
            res.append(item)
            if d.code == "F001":
                notifications.append({"level": "error", "message": {"text": printable(d.message)},
                                      "locations": [location], "descriptor": {"id": d.code}})
    invocation: dict[str, object] = {"executionSuccessful": not any(is_unreadable(r) for r in results)}
    if notifications:
        invocation["toolExecutionNotifications"] = notifications
    driver: dict[str, object] = {"name": "zero", "version": __version__}
    home = information_uri()
    if home:
        driver["informationUri"] = home
    driver["rules"] = rules
    log = {"$schema": "https://json.schemastore.org/sarif-2.1.0.json", "version": "2.1.0",
           "runs": [{"originalUriBaseIds": {"%SRCROOT%": {"uri": Path.cwd().as_uri() + "/"}},
                     "tool": {"driver": driver}, "invocations": [invocation],
                     "results": res, "columnKind": "unicodeCodePoints"}]}
    stream.write(json.dumps(log, indent=2) + "\n")


def render_json_lines(results: Iterable[LintResult], stream: TextIO) -> None:
    """JSON Lines (``json-lines``, as ruff's): each finding's JSON object of ``--output-format json``
    on a line of its own."""
    for d in _each(results):
        stream.write(json.dumps(d.to_json(), ensure_ascii=False) + "\n")


def render_pylint(results: Iterable[LintResult], stream: TextIO) -> None:
    """The pylint (flake8 ``pylint`` formatter) lines ruff's ``pylint`` format writes:
    ``path:line: [CODE] message``, read by tools made for pylint's parseable output."""
    for d in _each(results):
        stream.write(f"{printable(d.path, escape=True)}:{d.span.line}: [{d.code}] "
                     f"{printable(d.message, escape=True)}\n")


def _azure_data(text: str) -> str:
    """A logging command's message: the agent reads ``%AZP25`` as ``%``, ``%0D``/``%0A`` as line ends."""
    return text.replace("%", "%AZP25").replace("\r", "%0D").replace("\n", "%0A")


def _azure_property(text: str) -> str:
    """A logging command's property value: as its message, and ``;`` and ``]`` end a property."""
    return _azure_data(text).replace(";", "%3B").replace("]", "%5D")


def render_azure(results: Iterable[LintResult], stream: TextIO) -> None:
    """Azure Pipelines logging commands: ``##vso[task.logissue type=error;sourcepath=…;linenumber=…;
    columnnumber=…;code=…;]message``, one per finding (an information finding is a warning: the
    command knows only errors and warnings)."""
    for d in _each(results):
        kind = "error" if d.severity == Severity.ERROR else "warning"
        props = (f"type={kind};sourcepath={_azure_property(repo_path(d.path))};linenumber={d.span.line};"
                 f"columnnumber={d.span.column};code={_azure_property(d.code)};")
        stream.write(f"##vso[task.logissue {props}]{_azure_data(f'{d.code} {d.message}')}\n")


def render_grouped(results: Iterable[LintResult], stream: TextIO) -> None:
    """ruff's ``grouped`` format: each file's name, then its findings indented below it
    (``  line:col CODE message``, the positions aligned), a blank line between files."""
    for r in results:
        if not r.diagnostics:
            continue
        stream.write(f"{printable(r.path, escape=True)}:\n")
        where = [f"{d.span.line}:{d.span.column}" for d in r.diagnostics]
        width = max(len(w) for w in where)
        for d, w in zip(r.diagnostics, where, strict=True):
            stream.write(f"  {w:<{width}} {d.code} {d.severity.label} {printable(d.message, escape=True)}\n")
        stream.write("\n")


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


# The formats written finding by finding as the results come: a report of many files in one of
# them (or in text) does not hold the files' results, so its memory does not grow with them.
STREAMED: dict[str, Callable[[Iterable[LintResult], TextIO], None]] = {
    "json": render_json, "concise": render_concise, "github": render_github, "json-lines": render_json_lines,
    "pylint": render_pylint, "azure": render_azure, "grouped": render_grouped}
RENDERERS: dict[str, Callable[[Sequence[LintResult], TextIO], None]] = {
    **STREAMED, "gitlab": render_gitlab, "junit": render_junit, "sarif": render_sarif, "rdjson": render_rdjson}

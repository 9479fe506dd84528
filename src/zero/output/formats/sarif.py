"""``--output-format sarif``: SARIF 2.1.0 (GitHub code scanning and other SARIF consumers)."""

from __future__ import annotations

import json
import os
import urllib.parse
from collections.abc import Sequence
from pathlib import Path

from zero import __version__
from zero.diagnostics import Severity, Span
from zero.engine.results import LintResult, is_unreadable
from zero.output.formats import information_uri, rule_docs_template
from zero.output.formats.common import each, fingerprints, repo_path
from zero.output.text import printable
from zero.rules import RULES

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO

# The name of zero's own fingerprint among a SARIF result's ``partialFingerprints``.
SARIF_FINGERPRINT = "zeroKeyHash/v1"


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
    used = sorted({d.code for d in each(results)})
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

"""``--output-format junit``: JUnit XML as Jenkins reads it."""

from __future__ import annotations

from collections.abc import Sequence

from zero.diagnostics import Severity
from zero.engine.results import LintResult
from zero.output.text import printable

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


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

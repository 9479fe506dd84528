"""The reports CI systems read, checked the way their consumers read them: GitLab's code quality
fingerprints and paths, GitHub's ``file=``, a JUnit XML schema of Jenkins' ``junit-10.xsd``
constraints, SARIF 2.1.0 (``partialFingerprints``, ``helpUri``, ``invocations``) and the
concise lines."""

from __future__ import annotations

import io
import json
import os
from pathlib import Path
from typing import Any

import pytest

from conftest import FIXTURES, builtin_registry, lint_text
from zero.diagnostics import Severity
from zero.engine.lint import LintResult, lint_file
from zero.output import formats
from zero.output.formats import render_concise, render_github, render_gitlab, render_junit, render_sarif
from zero.records import replace

SEED = FIXTURES / "seed" / "nullp_3achsen.lis"
CLEAN = FIXTURES / "rules" / "M006" / "pass.lis"
FIRST_BAD = "np_grp[1].achse[0].versch abc\n"
SECOND_BAD = "np_grp[2].achse[0].versch xyz\n"
TWO_INDICES = FIRST_BAD + "np_grp[1].achse[0].inaktiv 0\n" + SECOND_BAD + "Ende\n"
WARNING_ONLY = "np_grp[1].achse[0].versch 1\nEnde\nnp_grp[1].achse[1].versch 2\n"  # S009, a warning


def gitlab(results: list[LintResult]) -> list[dict[str, Any]]:
    out = io.StringIO()
    render_gitlab(results, out)
    issues: list[dict[str, Any]] = json.loads(out.getvalue())
    return issues


def sarif(results: list[LintResult], **options: Any) -> dict[str, Any]:
    out = io.StringIO()
    render_sarif(results, out, **options)
    log: dict[str, Any] = json.loads(out.getvalue())
    return log


def from_file(path: Path) -> LintResult:
    return lint_file(path, builtin_registry())


# GitLab code quality and GitHub annotations


def test_gitlab_fingerprint_of_one_index_survives_fixing_another() -> None:
    """Both findings are on P-ZERO-00003 (every index shares the ID): fixing the first must not
    hand its fingerprint to the second, or GitLab reports the second fixed and the first new."""
    before = gitlab([lint_text(TWO_INDICES, "np.lis")])
    assert [(i["check_name"], i["location"]["lines"]["begin"]) for i in before] == [("R004", 1), ("R004", 3)]
    assert before[0]["fingerprint"] != before[1]["fingerprint"]
    after = gitlab([lint_text(TWO_INDICES.replace(FIRST_BAD, ""), "np.lis")])
    assert [(i["check_name"], i["location"]["lines"]["begin"]) for i in after] == [("R004", 2)]
    assert after[0]["fingerprint"] == before[1]["fingerprint"]
    # a true duplicate (the same key as written, twice) is told apart by its occurrence
    twice = [i["fingerprint"] for i in gitlab([lint_text(FIRST_BAD + FIRST_BAD + "Ende\n", "dup.lis")])
             if i["check_name"] == "R004"]
    assert len(twice) == 2 and len(set(twice)) == 2


def test_gitlab_and_github_paths_are_relative_to_the_repository(tmp_path: Path,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    """Relative to the working directory (the repository's root in CI) where the file lies below
    it, even when given absolute; as given where it lies outside."""
    (tmp_path / "repo").mkdir()
    monkeypatch.chdir(tmp_path / "repo")
    absolute = str(tmp_path / "repo" / "machine" / "np.lis")
    issues = gitlab([lint_text(TWO_INDICES, absolute)])
    assert {i["location"]["path"] for i in issues} == {"machine/np.lis"}
    # the fingerprint does not depend on how the path was given either
    relative = gitlab([lint_text(TWO_INDICES, "machine/np.lis")])
    assert [i["fingerprint"] for i in issues] == [i["fingerprint"] for i in relative]
    out = io.StringIO()
    render_github([lint_text(TWO_INDICES, absolute)], out)
    lines = out.getvalue().splitlines()
    assert len(lines) == 2 and all(x.startswith("::error file=machine/np.lis,line=") for x in lines)
    outside = str(tmp_path / "elsewhere" / "np.lis")
    assert {i["location"]["path"] for i in gitlab([lint_text(TWO_INDICES, outside)])} == {outside}
    out = io.StringIO()
    render_github([lint_text(TWO_INDICES, outside)], out)
    assert out.getvalue().startswith(f"::error file={outside.replace(':', '%3A')},line=1,")


# JUnit: Jenkins' junit-10.xsd

# No package on PyPI or npm ships Jenkins' junit-10.xsd (nor may this repository carry that
# third-party file), so this schema is written for these tests from what junit-10.xsd
# requires of a report: <testsuites> with the attributes name, time, tests, failures and
# errors only, holding <testsuite>s; a <testsuite> must have name, tests, failures and errors,
# may have group, time, skipped, timestamp, hostname, id, package, file, log and url, and holds
# test cases, properties, nested suites and system-out/-err; a <testcase> must have name, may
# have classname, time and group (no file, no line), and holds skipped, error, failure,
# system-out and system-err. Anything valid here is valid under junit-10.xsd.
JUNIT_SCHEMA = """<?xml version="1.0" encoding="UTF-8"?>
<xs:schema xmlns:xs="http://www.w3.org/2001/XMLSchema" elementFormDefault="unqualified">
  <xs:complexType name="outcome" mixed="true">
    <xs:attribute name="message" type="xs:string"/>
    <xs:attribute name="type" type="xs:string"/>
  </xs:complexType>
  <xs:complexType name="caseType">
    <xs:choice minOccurs="0" maxOccurs="unbounded">
      <xs:element name="skipped" type="outcome"/>
      <xs:element name="error" type="outcome"/>
      <xs:element name="failure" type="outcome"/>
      <xs:element name="system-out" type="xs:string"/>
      <xs:element name="system-err" type="xs:string"/>
    </xs:choice>
    <xs:attribute name="name" type="xs:string" use="required"/>
    <xs:attribute name="classname" type="xs:string"/>
    <xs:attribute name="time" type="xs:decimal"/>
    <xs:attribute name="group" type="xs:string"/>
  </xs:complexType>
  <xs:complexType name="propertyList">
    <xs:sequence>
      <xs:element name="property" minOccurs="0" maxOccurs="unbounded">
        <xs:complexType>
          <xs:attribute name="name" type="xs:string" use="required"/>
          <xs:attribute name="value" type="xs:string" use="required"/>
        </xs:complexType>
      </xs:element>
    </xs:sequence>
  </xs:complexType>
  <xs:complexType name="suiteType">
    <xs:choice minOccurs="0" maxOccurs="unbounded">
      <xs:element name="testsuite" type="suiteType"/>
      <xs:element name="properties" type="propertyList"/>
      <xs:element name="testcase" type="caseType"/>
      <xs:element name="system-out" type="xs:string"/>
      <xs:element name="system-err" type="xs:string"/>
    </xs:choice>
    <xs:attribute name="name" type="xs:string" use="required"/>
    <xs:attribute name="tests" type="xs:nonNegativeInteger" use="required"/>
    <xs:attribute name="failures" type="xs:nonNegativeInteger" use="required"/>
    <xs:attribute name="errors" type="xs:nonNegativeInteger" use="required"/>
    <xs:attribute name="skipped" type="xs:nonNegativeInteger"/>
    <xs:attribute name="time" type="xs:decimal"/>
    <xs:attribute name="group" type="xs:string"/>
    <xs:attribute name="timestamp" type="xs:string"/>
    <xs:attribute name="hostname" type="xs:string"/>
    <xs:attribute name="id" type="xs:string"/>
    <xs:attribute name="package" type="xs:string"/>
    <xs:attribute name="file" type="xs:string"/>
    <xs:attribute name="log" type="xs:string"/>
    <xs:attribute name="url" type="xs:string"/>
  </xs:complexType>
  <xs:element name="testsuites">
    <xs:complexType>
      <xs:sequence>
        <xs:element name="testsuite" type="suiteType" minOccurs="0" maxOccurs="unbounded"/>
      </xs:sequence>
      <xs:attribute name="name" type="xs:string"/>
      <xs:attribute name="time" type="xs:decimal"/>
      <xs:attribute name="tests" type="xs:nonNegativeInteger"/>
      <xs:attribute name="failures" type="xs:nonNegativeInteger"/>
      <xs:attribute name="errors" type="xs:nonNegativeInteger"/>
    </xs:complexType>
  </xs:element>
</xs:schema>
"""


def junit(results: list[LintResult], **options: Any) -> str:
    out = io.StringIO()
    render_junit(results, out, **options)
    return out.getvalue()


def junit_schema() -> Any:
    xmlschema = pytest.importorskip("xmlschema", reason="the JUnit schema check needs xmlschema: "
                                                        "pip install -e '.[test]'")
    return xmlschema.XMLSchema(JUNIT_SCHEMA)


def test_junit_validates_against_the_junit_10_constraints(tmp_path: Path) -> None:
    schema = junit_schema()
    # the schema is strict where junit-10.xsd is: a suite without errors, a case with a line
    assert schema.is_valid('<testsuites><testsuite name="a" tests="1" failures="0" errors="0">'
                           '<testcase name="t"/></testsuite></testsuites>')
    assert not schema.is_valid('<testsuites><testsuite name="a" tests="1" failures="0">'
                               '<testcase name="t"/></testsuite></testsuites>')
    assert not schema.is_valid('<testsuites><testsuite name="a" tests="1" failures="0" errors="0">'
                               '<testcase name="t" file="a" line="1"/></testsuite></testsuites>')
    results = [from_file(SEED), from_file(CLEAN), from_file(tmp_path / "gone.lis"),
               lint_text(WARNING_ONLY, "w.lis")]
    schema.validate(junit(results))
    schema.validate(junit(results, fail_on=Severity.WARNING))


def test_junit_testsuites_count_test_cases_not_files() -> None:
    import xml.etree.ElementTree as ET

    root = ET.fromstring(junit([from_file(SEED), from_file(CLEAN)]))
    cases = root.findall("testsuite/testcase")
    assert len(cases) == 8  # seven findings, one clean file
    assert root.get("tests") == "8" and root.get("failures") == "2" and root.get("errors") == "0"
    assert [s.get("errors") for s in root.findall("testsuite")] == ["0", "0"]
    # where each finding is stands in its text, since the schema has no attribute for it
    failure = root.find("testsuite/testcase/failure")
    assert failure is not None and failure.text is not None
    assert failure.text.startswith(f"{SEED}:19:20: S004 error ")


def test_junit_warnings_fail_under_strict() -> None:
    """``zero lint --strict`` exits 1 on a warning: the JUnit report must then fail as well."""
    import xml.etree.ElementTree as ET

    result = lint_text(WARNING_ONLY, "w.lis")
    assert [d.severity for d in result.diagnostics] == [Severity.WARNING]
    relaxed = ET.fromstring(junit([result]))
    assert relaxed.get("failures") == "0" and relaxed.find("testsuite/testcase/system-out") is not None
    strict = ET.fromstring(junit([result], fail_on=Severity.WARNING))
    assert strict.get("failures") == "1"
    assert strict.find("testsuite").get("failures") == "1"  # type: ignore[union-attr]
    failure = strict.find("testsuite/testcase/failure")
    assert failure is not None and failure.get("type") == "S009"


def test_an_unreadable_file_is_a_junit_error(tmp_path: Path) -> None:
    import xml.etree.ElementTree as ET

    root = ET.fromstring(junit([from_file(tmp_path / "gone.lis"), from_file(CLEAN)]))
    assert root.get("errors") == "1" and root.get("failures") == "0" and root.get("tests") == "2"
    error = root.find("testsuite/testcase/error")
    assert error is not None and error.get("type") == "F001"


# SARIF 2.1.0


def sarif_model(log: dict[str, Any]) -> Any:
    sarif_pydantic = pytest.importorskip("sarif_pydantic", reason="pip install -e '.[test]'")
    return sarif_pydantic.Sarif.model_validate(log)


def test_sarif_partial_fingerprints_survive_fixing_another_index() -> None:
    before = sarif([lint_text(TWO_INDICES, "np.lis")])
    after = sarif([lint_text(TWO_INDICES.replace(FIRST_BAD, ""), "np.lis")])
    model = sarif_model(before)
    prints = [r.partial_fingerprints for r in model.runs[0].results]
    assert len(prints) == 2 and all(p and set(p) == {formats.SARIF_FINGERPRINT} for p in prints)
    assert prints[0] != prints[1]
    (kept,) = sarif_model(after).runs[0].results
    assert kept.partial_fingerprints == prints[1]
    # the same fingerprint GitLab gets: one identity for a finding, whichever report carries it
    assert [p[formats.SARIF_FINGERPRINT] for p in prints] == [
        i["fingerprint"] for i in gitlab([lint_text(TWO_INDICES, "np.lis")])]


def test_sarif_rules_link_their_text_and_no_placeholder_is_left(monkeypatch: pytest.MonkeyPatch) -> None:
    results = [from_file(SEED)]
    plain = json.dumps(sarif(results))
    assert ".invalid" not in plain and "example." not in plain
    monkeypatch.setattr(formats, "RULE_DOCS_URL", "https://docs.test/zero/rules/{code}.md")
    rules = sarif_model(sarif(results)).runs[0].tool.driver.rules
    assert [(r.id, r.help_uri) for r in rules] == [("M003", "https://docs.test/zero/rules/M003.md"),
                                                   ("S004", "https://docs.test/zero/rules/S004.md")]
    given = sarif(results, rule_docs="https://wiki.test/{code}")
    assert [r["helpUri"] for r in given["runs"][0]["tool"]["driver"]["rules"]] == [
        "https://wiki.test/M003", "https://wiki.test/S004"]


def test_sarif_invocation_fails_when_a_file_could_not_be_read(tmp_path: Path) -> None:
    good = sarif_model(sarif([from_file(SEED), from_file(CLEAN)]))
    (invocation,) = good.runs[0].invocations
    assert invocation.execution_successful is True
    log = sarif([from_file(SEED), from_file(tmp_path / "gone.lis")])
    (invocation,) = sarif_model(log).runs[0].invocations
    assert invocation.execution_successful is False
    (note,) = log["runs"][0]["invocations"][0]["toolExecutionNotifications"]
    assert note["level"] == "error" and note["descriptor"] == {"id": "F001"}
    assert note["message"]["text"].startswith("no such file")


# Concise lines


def test_concise_escapes_control_characters_in_file_names() -> None:
    name = "odd\nname\rwith\udcffbyte.lis"  # \udcff: the byte 0xff of an undecodable name
    out = io.StringIO()
    render_concise([lint_text(TWO_INDICES, name)], out)
    lines = out.getvalue().split("\n")
    assert lines[-1] == "" and len(lines) == 3  # one line per finding, whatever the name holds
    assert all(x.startswith("odd\\nname\\rwith\\xffbyte.lis:") for x in lines[:2])
    assert "\r" not in out.getvalue() and "\ufffd" not in out.getvalue()
    out.getvalue().encode("utf-8")  # no lone surrogate left to fail the terminal's encoding


def test_concise_escapes_a_newline_in_the_message_of_an_unreadable_file(tmp_path: Path) -> None:
    gone = tmp_path / "a\nb.lis"
    out = io.StringIO()
    render_concise([from_file(gone)], out)
    (line,) = out.getvalue().splitlines()
    escaped = os.fspath(gone).replace("\n", "\\n")
    assert line.startswith(f"{escaped}:1:1: F001 error ")


def test_strict_makes_warnings_junit_failures_on_the_command_line(tmp_path: Path) -> None:
    """`zero lint --strict --output-format junit`: the run exits 1 on a warning, so the warning is a
    failing test case (it was a passing one, `failures="0"`)."""
    from conftest import FIXTURES, zero_cli

    warn = FIXTURES / "rules" / "M006" / "fail.lis"
    plain = zero_cli("lint", "--isolated", "--output-format", "junit", str(warn))
    strict = zero_cli("lint", "--isolated", "--strict", "--output-format", "junit", str(warn))
    assert plain.code == 0 and 'failures="0"' in plain.stdout
    assert strict.code == 1 and 'failures="1"' in strict.stdout and "<failure" in strict.stdout


def test_sarif_help_uri_points_at_the_documentation_site(monkeypatch: pytest.MonkeyPatch) -> None:
    """With the site's address in ZERO_DOCS_URL, each rule's helpUri is its generated page (the
    path the site's generator writes, with MkDocs' directory URLs); without one there is none."""
    from zero.output.docs import rule_page_path
    from zero.output.formats import rule_docs_template

    monkeypatch.delenv("ZERO_DOCS_URL", raising=False)
    assert rule_docs_template() is None
    monkeypatch.setenv("ZERO_DOCS_URL", "https://zero.example.org/docs/")
    template = rule_docs_template()
    assert template is not None
    assert template.format(code="R006") == "https://zero.example.org/docs/" + rule_page_path("R006")[:-3] + "/"


# ------------------------------------------------------------------ the formats of issue 35


def _render(name: str, results: list[LintResult]) -> str:
    out = io.StringIO()
    formats.RENDERERS[name](results, out)
    return out.getvalue()


def test_every_output_format_has_a_renderer() -> None:
    from zero.output import OUTPUT_FORMATS, STREAMED_FORMATS

    assert set(OUTPUT_FORMATS) - {"text", "full"} == set(formats.RENDERERS)
    assert set(STREAMED_FORMATS) - {"text", "full"} == set(formats.STREAMED)
    assert {"json-lines", "rdjson", "pylint", "azure", "full", "grouped"} <= set(OUTPUT_FORMATS)


def test_json_lines_is_the_json_report_one_finding_a_line() -> None:
    results = [from_file(SEED)]
    lines = _render("json-lines", results).splitlines()
    assert [json.loads(line) for line in lines] == json.loads(_render("json", results))
    assert len(lines) == 7


# reviewdog's Diagnostic Format (rdjson): no package ships its JSON schema, so the constraints of
# its DiagnosticResult (reviewdog's proto/rdf/jsonschema) are written here, in this test's words:
# an object with `diagnostics`, each with a string `message`, a `location` with a string `path`
# and a `range` of `start` and optional `end` positions (integer `line` and `column`), a
# `severity` of ERROR, WARNING, INFO (or UNKNOWN_SEVERITY), an optional `source` with a `name`,
# an optional `code` with a `value` (and `url`), and optional `suggestions` (a `range` and a `text`).
_POSITION = {"type": "object", "properties": {"line": {"type": "integer", "minimum": 1},
                                              "column": {"type": "integer", "minimum": 1}}, "required": ["line"]}
_RANGE = {"type": "object", "properties": {"start": _POSITION, "end": _POSITION}, "required": ["start"]}
_SOURCE = {"type": "object", "properties": {"name": {"type": "string"}, "url": {"type": "string"}},
           "required": ["name"]}
RDJSON_SCHEMA = {
    "$schema": "http://json-schema.org/draft-07/schema#",
    "type": "object",
    "properties": {
        "source": _SOURCE,
        "severity": {"enum": ["UNKNOWN_SEVERITY", "ERROR", "WARNING", "INFO"]},
        "diagnostics": {"type": "array", "items": {
            "type": "object", "required": ["message", "location"],
            "properties": {
                "message": {"type": "string"},
                "location": {"type": "object", "required": ["path"],
                             "properties": {"path": {"type": "string"}, "range": _RANGE}},
                "severity": {"enum": ["UNKNOWN_SEVERITY", "ERROR", "WARNING", "INFO"]},
                "source": _SOURCE,
                "code": {"type": "object", "required": ["value"],
                         "properties": {"value": {"type": "string"}, "url": {"type": "string"}}},
                "suggestions": {"type": "array", "items": {
                    "type": "object", "required": ["range", "text"],
                    "properties": {"range": _RANGE, "text": {"type": "string"}}}},
                "original_output": {"type": "string"}}}}},
    "required": ["diagnostics"],
}


def test_rdjson_validates_against_reviewdogs_format(monkeypatch: pytest.MonkeyPatch) -> None:
    import jsonschema

    monkeypatch.setenv(formats.DOCS_URL_VARIABLE, "https://docs.test/zero")
    doc = json.loads(_render("rdjson", [from_file(SEED)]))
    jsonschema.validate(doc, RDJSON_SCHEMA)
    first = doc["diagnostics"][0]
    assert first["location"] == {"path": "fixtures/seed/nullp_3achsen.lis",
                                 "range": {"start": {"line": 19, "column": 20}, "end": {"line": 19, "column": 21}}}
    assert first["code"] == {"value": "S004", "url": "https://docs.test/zero/rules/S004/"}
    # the safe fix as reviewdog's suggestion: delete the blank inside the key
    assert first["suggestions"] == [{"range": first["location"]["range"], "text": ""}]
    assert {d["severity"] for d in doc["diagnostics"]} <= {"ERROR", "WARNING", "INFO"}


def test_rdjson_columns_are_utf8_bytes() -> None:
    """reviewdog counts a column in UTF-8 bytes: an `ä` before the finding moves it by one more."""
    assert formats._utf8_column("äb x", 4) == 5 and formats._utf8_column("ab x", 4) == 4
    result = lint_text("# Achse ä\nnp_grp[1].achse[0].versch abc # äö\nEnde\n", "np.lis")
    doc = json.loads(_render("rdjson", [result]))
    d = next(d for d in doc["diagnostics"] if d["code"]["value"] == "R004")
    assert d["location"]["range"] == {"start": {"line": 2, "column": 27}, "end": {"line": 2, "column": 30}}


def test_pylint_azure_and_grouped_lines() -> None:
    results = [lint_text(TWO_INDICES, "machine/np.lis")]
    d = results[0].diagnostics[0]
    pylint = _render("pylint", results).splitlines()
    assert pylint[0] == f"machine/np.lis:{d.span.line}: [{d.code}] {d.message}"
    azure = _render("azure", results).splitlines()
    kind = "error" if d.severity == Severity.ERROR else "warning"
    assert azure[0].startswith(f"##vso[task.logissue type={kind};sourcepath=machine/np.lis;linenumber={d.span.line};"
                               f"columnnumber={d.span.column};code={d.code};]{d.code} ")
    grouped = _render("grouped", results)
    assert grouped.startswith(f"machine/np.lis:\n  {d.span.line}:{d.span.column} {d.code} {d.severity.label} ")
    assert grouped.endswith("\n\n") and grouped.count("\n  ") == len(results[0].diagnostics)


def test_azure_escapes_what_ends_a_property_or_a_line() -> None:
    d = lint_text(TWO_INDICES, "a;b]%.lis").diagnostics[0]
    out = io.StringIO()
    formats.render_azure([LintResult("a;b]%.lis", lint_text(TWO_INDICES).document, None,
                                     [replace(d, path="a;b]%.lis", message="x\nq; 5%")])], out)
    line = out.getvalue()
    assert line.count("\n") == 1
    assert "sourcepath=a%3Bb%5D%AZP25.lis;" in line and line.endswith("x%0Aq; 5%AZP25\n")


def test_full_is_the_text_report(tmp_path: Path) -> None:
    from conftest import zero_cli

    text = zero_cli("lint", str(SEED), "--output-format", "text", env={"NO_COLOR": "1"})
    full = zero_cli("lint", str(SEED), "--output-format", "full", env={"NO_COLOR": "1"})
    assert full.stdout == text.stdout and "   |" in full.stdout


def test_gitlab_paths_are_relative_to_ci_project_dir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A job that runs from a subfolder keeps the folder in each path (GitLab sets CI_PROJECT_DIR)."""
    (tmp_path / "machines" / "m1").mkdir(parents=True)
    monkeypatch.chdir(tmp_path / "machines")
    monkeypatch.setenv("CI_PROJECT_DIR", str(tmp_path))
    issues = gitlab([lint_text(TWO_INDICES, "m1/np.lis")])
    assert {i["location"]["path"] for i in issues} == {"machines/m1/np.lis"}
    monkeypatch.delenv("CI_PROJECT_DIR")
    assert {i["location"]["path"] for i in gitlab([lint_text(TWO_INDICES, "m1/np.lis")])} == {"m1/np.lis"}


def test_sarif_names_the_tools_home_and_gives_help_in_markdown(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(formats.DOCS_URL_VARIABLE, "https://docs.test/zero")
    log = sarif([from_file(SEED)])
    driver = log["runs"][0]["tool"]["driver"]
    assert driver["informationUri"] == "https://docs.test/zero/"
    assert all(r["help"]["markdown"].startswith("## What it checks") for r in driver["rules"])
    sarif_model(log)  # still a valid SARIF 2.1.0 log


def test_the_json_schemas_id_is_no_placeholder() -> None:
    from zero.structured.schema import build_schema

    for kind in (None, "ZERO"):
        ident = build_schema(builtin_registry(), kind)["$id"]
        assert ".invalid" not in ident and ident.startswith("urn:zero-lint:schema:")

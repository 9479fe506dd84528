"""Machine-readable outputs of zero lint, through typer's runner and the lean entry point."""

from __future__ import annotations

import io
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from conftest import FIXTURES
from zero.cli.app import app
from zero.diagnostics import Diagnostic, Edit, Fix, Severity, Span
from zero.engine.lint import LintResult
from zero.lists.model import Document
from zero.output.formats import indented_json, render_json

SEED = str(FIXTURES / "seed" / "nullp_3achsen.lis")
CLEAN = str(FIXTURES / "rules" / "M006" / "pass.lis")
runner = CliRunner()
# GitLab and GitHub get paths relative to the working directory (the repository in CI)
SEED_REL = SEED if os.path.relpath(SEED).startswith("..") else Path(os.path.relpath(SEED)).as_posix()


def run(*args: str) -> tuple[int, str, str]:
    """The real console entry (lean path) in a subprocess: exit code, stdout, stderr."""
    p = subprocess.run([sys.executable, "-m", "zero", "lint", *args], capture_output=True, text=True,
                       env={"NO_COLOR": "1", "PATH": ""}, check=False)
    return p.returncode, p.stdout, p.stderr


@pytest.mark.parametrize("via", ["subprocess", "runner"])
def test_concise_and_summary_on_stderr(via: str) -> None:
    if via == "runner":
        r = runner.invoke(app, ["lint", "--output-format", "concise", SEED])
        code, out, _err = r.exit_code, r.stdout, r.stderr
    else:
        code, out, _err = run("--output-format", "concise", SEED)
    assert code == 1
    lines = out.splitlines()
    assert len(lines) == 7
    assert lines[0] == (f"{SEED}:19:20: S004 error whitespace inside the key `np_grp[0].achse[1].inaktiv`: "
                        "read up to the blank, it is another, unknown key; the plausibility check of a zero-offset "
                        "list reports an unknown or incorrectly written parameter or an invalid value (P-ERR-20407), "
                        "and the kernel aborts the job")
    assert "checked" not in out


def test_text_summary_goes_to_stderr() -> None:
    code, out, err = run(SEED)
    assert code == 1
    assert "1 file checked (0 clean): 2 errors, 0 warnings, 5 infos" in err
    assert "checked" not in out and "S004" in out


def test_github_annotations() -> None:
    _code, out, _ = run("--output-format", "github", SEED)
    first = out.splitlines()[0]
    assert first.startswith(f"::error file={SEED_REL},line=19,col=20,endLine=19,endColumn=21,title=zero S004::S004 ")
    assert sum(1 for x in out.splitlines() if x.startswith("::notice ")) == 5


def test_gitlab_code_quality() -> None:
    _, out, _ = run("--output-format", "gitlab", SEED)
    issues = json.loads(out)
    assert len(issues) == 7
    assert {i["severity"] for i in issues} == {"major", "info"}
    assert len({i["fingerprint"] for i in issues}) == 7
    assert issues[0]["location"] == {"path": SEED_REL, "lines": {"begin": 19, "end": 19}}


def test_junit() -> None:
    _, out, _ = run("--output-format", "junit", SEED, CLEAN)
    root = ET.fromstring(out.split("\n", 1)[1] if out.startswith("<?xml") else out)
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == [SEED, CLEAN]
    # two errors fail; the five infos are passing test cases that carry the finding
    assert suites[0].get("failures") == "2" and suites[1].get("failures") == "0"
    assert suites[0].get("tests") == "7"
    assert len(suites[0].findall("testcase/system-out")) == 5
    assert suites[1].find("testcase") is not None


def test_sarif_structure() -> None:
    _, out, _ = run("--output-format", "sarif", SEED)
    log = json.loads(out)
    assert log["version"] == "2.1.0"
    run0 = log["runs"][0]
    rules = run0["tool"]["driver"]["rules"]
    assert [r["id"] for r in rules] == ["M003", "S004"]
    for res in run0["results"]:
        assert rules[res["ruleIndex"]]["id"] == res["ruleId"]
        region = res["locations"][0]["physicalLocation"]["region"]
        assert region["startLine"] >= 1 and region["endColumn"] >= region["startColumn"]
    assert len(run0["results"]) == 7
    assert {r["level"] for r in run0["results"]} == {"error", "note"}


def test_output_file_statistics_exit_zero(tmp_path: Path) -> None:
    target = tmp_path / "report.json"
    code, out, _ = run("--output-format", "json", "-o", str(target), SEED)
    assert code == 1 and out == ""
    assert len(json.loads(target.read_text())) == 7
    # --statistics: the counts instead of the findings (as ruff), into the report file where one is named
    _, out, err = run("--output-format", "json", "-o", str(target), "--statistics", SEED)
    assert out == "" and "np_grp" not in err
    assert json.loads(target.read_text()) == [{"code": "M003", "name": "masked-offset", "count": 5},
                                              {"code": "S004", "name": "key-whitespace", "count": 2}]
    _, out, _ = run("--statistics", SEED)
    assert out.startswith("      5  M003  masked-offset\n      2  S004  key-whitespace\n")
    code, _, _ = run("--exit-zero", SEED)
    assert code == 0
    r = runner.invoke(app, ["lint", "--exit-zero", "--output-format", "sarif", "-o", str(target), SEED])
    assert r.exit_code == 0 and json.loads(target.read_text())["version"] == "2.1.0"


def test_unknown_format_is_a_usage_error() -> None:
    code, _, err = run("--output-format", "xml", SEED)
    assert code == 2 and "xml" in err


def test_stdin_with_a_filename(tmp_path: Path) -> None:
    data = Path(SEED).read_bytes()
    p = subprocess.run([sys.executable, "-m", "zero", "lint", "--stdin-filename", "m/nullp.lis",
                        "--output-format", "concise"], input=data, capture_output=True, cwd=tmp_path,
                       check=False)
    assert p.returncode == 1 and p.stdout.startswith(b"m/nullp.lis:19:20: S004")
    (tmp_path / "zero.toml").write_text('exclude = ["m/**"]\n')
    p = subprocess.run([sys.executable, "-m", "zero", "lint", "--stdin-filename", "m/nullp.lis"],
                       input=data, capture_output=True, cwd=tmp_path, check=False)
    assert p.returncode == 0 and p.stdout == b""
    p = subprocess.run([sys.executable, "-m", "zero", "lint", "-", "--fix"], input=data,
                       capture_output=True, cwd=tmp_path, check=False)
    assert p.stdout == data.replace(b"]. inaktiv", b"].inaktiv") and b"M003" in p.stderr
    r = runner.invoke(app, ["lint", "--stdin-filename", "x.lis", "--output-format", "json"], input=data)
    assert r.exit_code == 1 and len(json.loads(r.stdout)) == 7


def test_sarif_validates_against_the_sarif_2_1_0_model() -> None:
    sarif_pydantic = pytest.importorskip("sarif_pydantic", reason="pip install -e '.[test]'")
    _, out, _ = run("--output-format", "sarif", SEED, CLEAN)
    log = sarif_pydantic.Sarif.model_validate(json.loads(out))
    assert log.version == "2.1.0" and len(log.runs[0].results) == 7
    broken = json.loads(out)
    broken["runs"][0]["results"][0]["level"] = "fatal"  # not a SARIF level: the model refuses it
    with pytest.raises(ValueError):
        sarif_pydantic.Sarif.model_validate(broken)


def test_sarif_related_locations_of_a_duplicate() -> None:
    """A duplicate (R007) points at the entry it overwrites: a SARIF related location, valid 2.1.0."""
    sarif_pydantic = pytest.importorskip("sarif_pydantic", reason="pip install -e '.[test]'")
    fail = str(FIXTURES / "rules" / "R007" / "fail.lis")
    _, out, _ = run("--output-format", "sarif", fail)
    log = json.loads(out)
    sarif_pydantic.Sarif.model_validate(log)
    (dup, *_) = [r for r in log["runs"][0]["results"] if r["ruleId"] == "R007"]
    (other,) = dup["relatedLocations"]
    first = other["physicalLocation"]["region"]["startLine"]
    assert first < dup["locations"][0]["physicalLocation"]["region"]["startLine"]
    assert other["message"]["text"].startswith("first set here to ")
    assert other["physicalLocation"]["artifactLocation"] == dup["locations"][0]["physicalLocation"]["artifactLocation"]
    assert f"line {first}" in dup["message"]["text"]


def test_gitlab_fingerprints_survive_moved_lines(tmp_path: Path) -> None:
    data = Path(SEED).read_bytes()
    first = tmp_path / "a.lis"
    first.write_bytes(data)
    _, out, _ = run("--output-format", "gitlab", str(first))
    before = [i["fingerprint"] for i in json.loads(out)]
    first.write_bytes(b"# a new comment line at the top\n" + data)
    _, out, _ = run("--output-format", "gitlab", str(first))
    after = json.loads(out)
    assert [i["fingerprint"] for i in after] == before
    assert after[0]["location"]["lines"]["begin"] == 20  # the line moved, the fingerprint did not


def test_sarif_uris_are_percent_encoded_and_relative_to_srcroot(tmp_path: Path) -> None:
    folder = tmp_path / "sub dir"
    folder.mkdir()
    odd = folder / "a b#ü.lis"
    odd.write_bytes(Path(SEED).read_bytes())
    proc = subprocess.run([sys.executable, "-m", "zero", "lint", "--output-format", "sarif", "sub dir/a b#ü.lis"],
                          cwd=tmp_path, capture_output=True, text=True, check=False)
    log = json.loads(proc.stdout)
    location = log["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]
    assert location == {"uri": "sub%20dir/a%20b%23%C3%BC.lis", "uriBaseId": "%SRCROOT%"}
    assert log["runs"][0]["originalUriBaseIds"]["%SRCROOT%"]["uri"] == tmp_path.as_uri() + "/"


_TEXT = st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)), max_size=30)


@given(st.lists(st.lists(st.tuples(_TEXT, st.integers(1, 10**6), st.sampled_from(list(Severity)),
                                   st.one_of(st.none(), _TEXT)), max_size=4), max_size=4))
@settings(max_examples=200, deadline=None)  # a full collection inside one example took 245 ms on a loaded machine
def test_json_written_object_by_object_is_json_dumps_of_all(files: list[list[tuple[str, int, Severity,
                                                                                      str | None]]]) -> None:
    """The streamed JSON report is byte for byte what one json.dumps of every finding gives."""
    results = []
    for n, found in enumerate(files):
        diags = [Diagnostic("R001", sev, msg, Span(line, 1, line, 2), f"f{n}.lis", None,
                            Fix(msg, (Edit(Span(line, 1, line, 2), fix_text),)) if fix_text is not None else None)
                 for msg, line, sev, fix_text in found]
        results.append(LintResult(f"f{n}.lis", Document(f"f{n}.lis", "utf-8", [], [], []), "AXIS", diags))
    out = io.StringIO()
    render_json(results, out)
    expected = json.dumps([d.to_json() for r in results for d in r.diagnostics], indent=2) + "\n"
    assert out.getvalue() == expected


_JSON = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(),
    lambda inner: st.lists(inner, max_size=4)
    | st.dictionaries(st.text() | st.integers() | st.booleans() | st.none(), inner, max_size=4),
    max_leaves=20)


@given(_JSON, st.integers(min_value=0, max_value=3))
def test_indented_json_is_what_json_dumps_writes(value: object, level: int) -> None:
    expected = json.dumps(value, indent=2).replace("\n", "\n" + "  " * level)
    assert indented_json(value, level) == expected


def test_the_json_report_leaves_no_reference_cycles() -> None:
    """A fleet's report writes one object per finding: none may leave garbage for the cycle
    collector (json.dumps(indent=2) left one cycle per call)."""
    import gc

    d = Diagnostic("R001", Severity.ERROR, "x", Span(1, 1, 1, 2), "a.lis",
                   fix=Fix("f", (Edit(Span(1, 1, 1, 2), "y"),)))
    results = [LintResult("a.lis", Document("a.lis", "utf-8", [], [], []), None, [d] * 50)]
    gc.collect()
    gc.disable()
    try:
        render_json(results, io.StringIO())
        assert gc.collect() == 0
    finally:
        gc.enable()

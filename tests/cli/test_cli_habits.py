"""The command-line habits of ruff users (issue 27): -q/--quiet, -s/--silent, --show-files,
--exit-non-zero-on-fix, ZERO_OUTPUT_FORMAT; did-you-mean only for close typos; standard input
read once; shell completion of kinds, rule codes and choices."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli
from zero.cli.app import choice, complete_codes, complete_kind
from zero.cli.options import SUGGEST_CUTOFF, close_matches, did_you_mean, parse_lint_args
from zero.cli.run import check_kind
from zero.errors import ZeroError

BAD = b"kopf.achs_nr 1\nkenngr.swe_pso 1500\nEnde\n"  # R001 in an axis list: an error (P-ERR-1001119)
SEED = (FIXTURES / "seed" / "nullp_3achsen.lis").read_bytes()  # two safe fixes; infos remain
SUMMARY = "file checked"
PLAIN = {"NO_COLOR": "1", "TERM": "dumb", "COLUMNS": "80"}


@pytest.fixture
def bad(tmp_path: Path) -> Path:
    (tmp_path / "bad.lis").write_bytes(BAD)
    return tmp_path


# --------------------------------------------------------------- -q, -s, --show-files


@pytest.mark.parametrize("quiet", ["-q", "--quiet", "-qq"])  # -qq: not the lean parser's, typer's
def test_quiet_prints_the_findings_only(bad: Path, quiet: str) -> None:
    loud = zero_cli("lint", "bad.lis", cwd=bad, env=PLAIN)
    run = zero_cli("lint", quiet, "bad.lis", cwd=bad, env=PLAIN)
    assert SUMMARY in loud.stderr
    assert run.code == loud.code == 1
    assert run.stdout == loud.stdout and "R001" in run.stdout
    assert run.stderr == ""


def test_quiet_leaves_out_the_fix_notes(tmp_path: Path) -> None:
    (tmp_path / "nullp.lis").write_bytes(SEED)
    run = zero_cli("lint", "-q", "--fix", "nullp.lis", cwd=tmp_path, env=PLAIN)
    assert run.code == 0 and run.stderr == "" and "M003" in run.stdout
    assert (tmp_path / "nullp.lis").read_bytes() != SEED  # fixed all the same


@pytest.mark.parametrize("silent", ["-s", "--silent"])
def test_silent_prints_nothing_but_keeps_the_exit_code(bad: Path, silent: str) -> None:
    run = zero_cli("lint", silent, "bad.lis", cwd=bad, env=PLAIN)
    assert (run.code, run.stdout, run.stderr) == (1, "", "")
    run = zero_cli("lint", silent, "--output-format", "json", "-o", "report.json", "bad.lis", cwd=bad, env=PLAIN)
    assert run.code == 1 and "R001" in (bad / "report.json").read_text()  # the report file is still written


def test_show_files_lists_what_would_be_checked(tmp_path: Path) -> None:
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "one.lis").write_bytes(BAD)
    (tmp_path / "a" / "old.lis").write_bytes(BAD)
    (tmp_path / "a" / "notes.txt").write_text("not a list")
    (tmp_path / "two.lis").write_bytes(BAD)
    (tmp_path / "zero.toml").write_text('exclude = ["a/old.lis"]\n')
    run = zero_cli("lint", "--show-files", "a", "two.lis", cwd=tmp_path, env=PLAIN)
    assert run.code == 0, run.stderr  # nothing is checked: the errors in them do not count
    assert run.stdout.splitlines() == [os.path.join("a", "one.lis"), "two.lis"]
    assert run.stderr == ""


# --------------------------------------------------------------- --exit-non-zero-on-fix


def test_exit_non_zero_on_fix(tmp_path: Path) -> None:
    target = tmp_path / "nullp.lis"
    target.write_bytes(SEED)
    run = zero_cli("lint", "--fix", "--exit-non-zero-on-fix", "nullp.lis", cwd=tmp_path, env=PLAIN)
    assert run.code == 1, run.stderr  # fixed; only infos remain
    assert "2 fixes applied" in run.stderr
    run = zero_cli("lint", "--fix", "--exit-non-zero-on-fix", "nullp.lis", cwd=tmp_path, env=PLAIN)
    assert run.code == 0  # nothing left to fix
    target.write_bytes(SEED)
    assert zero_cli("lint", "--fix", "nullp.lis", cwd=tmp_path, env=PLAIN).code == 0  # without it: as before
    target.write_bytes(SEED)
    run = zero_cli("lint", "--fix", "--exit-non-zero-on-fix", "--exit-zero", "nullp.lis", cwd=tmp_path, env=PLAIN)
    assert run.code == 0  # --exit-zero wins, as in ruff


def test_exit_non_zero_on_fix_of_standard_input() -> None:
    run = zero_cli("lint", "-", "--fix", "--exit-non-zero-on-fix", "--stdin-filename", "nullp.lis", stdin=SEED,
                   env=PLAIN)
    assert run.code == 1 and run.out == SEED.replace(b"]. inaktiv", b"].inaktiv")


# --------------------------------------------------------------- ZERO_OUTPUT_FORMAT


@pytest.mark.parametrize("extra", [[], ["-qq"]])  # the lean parser and typer
def test_output_format_from_the_environment(bad: Path, extra: list[str]) -> None:
    run = zero_cli("lint", *extra, "bad.lis", cwd=bad, env={**PLAIN, "ZERO_OUTPUT_FORMAT": "json"})
    assert run.code == 1
    assert json.loads(run.stdout)[0]["code"] == "R001"
    run = zero_cli("lint", *extra, "--output-format", "concise", "bad.lis", cwd=bad,
                   env={**PLAIN, "ZERO_OUTPUT_FORMAT": "json"})
    assert run.stdout.startswith("bad.lis:2:1: R001")  # the command line wins


def test_a_bad_output_format_in_the_environment_names_the_variable(bad: Path) -> None:
    run = zero_cli("lint", "bad.lis", cwd=bad, env={**PLAIN, "ZERO_OUTPUT_FORMAT": "xml"})
    assert run.code == 2
    assert "(from the environment variable ZERO_OUTPUT_FORMAT): 'xml' is not one of text, full, concise" in run.stderr


def test_the_lean_parser_reads_the_variable_as_typer_does() -> None:
    assert parse_lint_args(["a.lis"], environ={"ZERO_OUTPUT_FORMAT": "json"})["output_format"] == "json"  # type: ignore[index]
    given = parse_lint_args(["a.lis", "--output-format", "sarif"], environ={"ZERO_OUTPUT_FORMAT": "json"})
    assert given is not None and given["output_format"] == "sarif"
    assert parse_lint_args(["a.lis"], environ={"ZERO_OUTPUT_FORMAT": ""})["output_format"] == "text"  # type: ignore[index]
    assert parse_lint_args(["a.lis"], environ={"ZERO_OUTPUT_FORMAT": "xml"}) is None  # typer says what is wrong


# --------------------------------------------------------------- did you mean


def test_an_unknown_option_is_matched_only_to_a_close_one(bad: Path) -> None:
    run = zero_cli("lint", "bad.lis", "--bogus", cwd=bad, env=PLAIN)
    assert run.code == 2 and "No such option: --bogus" in run.stderr
    assert "--jobs" not in run.stderr and "Possible options" not in run.stderr
    run = zero_cli("lint", "bad.lis", "--jbos", "2", cwd=bad, env=PLAIN)
    assert "No such option: --jbos (did you mean --jobs?)" in run.stderr


def test_suggestions_need_a_close_word() -> None:
    keys = ("select", "extend-select", "ignore", "per-file-ignores", "severity", "kind", "include", "exclude",
            "param-desc", "machine", "encoding", "kernel")  # the configuration keys before respect-gitignore
    assert close_matches("respect-gitignore", keys) == []  # difflib's default cutoff (0.6) gave per-file-ignores
    assert close_matches("--bogus", ["--jobs", "--config", "--fix"]) == []
    assert close_matches("selct", keys)[0] == "select"
    assert close_matches("respect-gitignor", (*keys, "respect-gitignore")) == ["respect-gitignore"]
    assert did_you_mean("exclud", keys) == " (did you mean exclude?)" and did_you_mean("zzz", keys) == ""
    assert 0.6 < SUGGEST_CUTOFF < 0.75


def test_a_kind_typo_suggests_the_nearest_kind() -> None:
    with pytest.raises(ZeroError, match=r"unknown list kind 'axsi'; did you mean axis\? \(use one of: axis, "):
        check_kind("axsi")
    with pytest.raises(ZeroError, match=r"'chanel'; did you mean channel\?"):
        check_kind("chanel")
    with pytest.raises(ZeroError, match=r"unknown list kind 'qqq' \(use one of"):
        check_kind("qqq")
    assert check_kind("AXIS") == "AXIS" and check_kind("startup") == "startup" and check_kind(None) is None


@pytest.mark.parametrize("command", [["lint", "bad.lis"], ["show", "bad.lis"], ["param", "kenngr.swe_pos"]])
def test_a_kind_typo_on_the_command_line(bad: Path, command: list[str]) -> None:
    run = zero_cli(*command, "--kind", "axsi", cwd=bad, env=PLAIN)
    assert run.code == 2 and "zero: unknown list kind 'axsi'; did you mean axis?" in run.stderr


# --------------------------------------------------------------- standard input


@pytest.mark.parametrize(("args", "message"), [
    (["-", "-"], "standard input can be read only once"),
    (["-", "bad.lis"], "goes alone"),
])
def test_standard_input_is_read_once_and_alone(bad: Path, args: list[str], message: str) -> None:
    run = zero_cli("lint", *args, cwd=bad, stdin=BAD, env=PLAIN)
    assert run.code == 2 and message in run.stderr
    assert "no such file" not in run.stderr


# --------------------------------------------------------------- completion


def test_completion_of_kinds() -> None:
    assert [v for v, _ in complete_kind("ax")] == ["axis"]
    assert dict(complete_kind(""))["startup"] == "start-up list"
    assert complete_kind("nothing") == []


def test_completion_of_rule_codes_and_prefixes() -> None:
    values = [v for v, _ in complete_codes("R00")]
    assert "R001" in values and "R" not in values and all(v.startswith("R00") for v in values)
    assert {"R", "S", "M"} <= {v for v, _ in complete_codes("")}
    assert [v for v, _ in complete_codes("s00")][:1] == ["S001"]  # any case
    assert all(v.startswith("R001,S") for v, _ in complete_codes("R001,S"))  # after a comma
    assert all(what for _, what in complete_codes(""))  # each with what it is


def test_completion_of_choices() -> None:
    complete = choice(("text", "json", "junit"))["autocompletion"]
    assert complete("j") == ["json", "junit"] and complete("") == ["text", "json", "junit"]


@pytest.mark.parametrize(("words", "expected"), [
    ("zero lint --kind ax", ["axis"]),
    ("zero lint --select R00", ["R001", "R002"]),
    ("zero lint --ignore S00", ["S001"]),
    ("zero lint --extend-select S01", ["S012"]),
    ("zero rule M00", ["M001"]),
    ("zero lint --output-format j", ["json", "junit"]),
    ("zero diff --output-format j", ["json"]),
    ("zero convert --to y", ["yaml"]),
])
def test_completion_in_the_shell(words: str, expected: list[str]) -> None:
    run = zero_cli(env={"_ZERO_COMPLETE": "complete_bash", "COMP_WORDS": words,
                        "COMP_CWORD": str(len(words.split()) - 1)})
    assert run.code == 0, run.stderr
    offered = run.stdout.split()
    assert set(expected) <= set(offered), offered

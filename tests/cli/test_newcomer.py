"""A newcomer's first hour (issue 35): usage errors in one line, a gitignored folder that says why
it is empty, and the options a ruff user reaches for (--select ALL, --exclude, --extend-exclude,
--[no-]respect-gitignore, --[no-]force-exclude, --kernel, --statistics alone, --show-fixes,
--fix-only, --watch)."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT, zero_cli

PLAIN = {"NO_COLOR": "1", "TERM": "dumb", "COLUMNS": "80"}
SEED = (FIXTURES / "seed" / "nullp_3achsen.lis").read_bytes()  # two safe S004 fixes, five M003 infos
OPT_IN = (FIXTURES / "rules" / "S012" / "fail.lis").read_bytes()  # S012: off unless named
GIT = shutil.which("git")


# ------------------------------------------------------------------------- usage errors


@pytest.mark.parametrize(("args", "line"), [
    (["lint", "--bogus", "x.lis"], "zero lint: No such option: --bogus; see 'zero lint --help'"),  # lean → typer
    (["lint", "--jbos", "2", "x.lis"],
     "zero lint: No such option: --jbos (did you mean --jobs?); see 'zero lint --help'"),
    (["lint", "x.lis", "--output-format", "jsn"],
     "zero lint: Invalid value for '--output-format': 'jsn' is not one of "),
    (["diff", "--bogus"], "zero diff: No such option: --bogus; see 'zero diff --help'"),
    (["lnt"], "zero: No such command 'lnt'. Did you mean 'lint'?; see 'zero --help'"),
    (["convert"], "zero convert: Missing argument 'FILE'; see 'zero convert --help'"),
])
def test_a_usage_error_is_one_line_on_stderr(args: list[str], line: str) -> None:
    run = zero_cli(*args, env=PLAIN)
    assert run.code == 2
    assert run.stdout == ""
    assert len(run.stderr.splitlines()) == 1, run.stderr
    assert run.stderr.startswith(line), run.stderr
    assert "Usage:" not in run.stderr and "Try " not in run.stderr


def test_a_bad_format_suggests_the_close_one() -> None:
    run = zero_cli("lint", "x.lis", "--output-format", "jsn", env=PLAIN)
    assert "(did you mean json?)" in run.stderr and len(run.stderr.splitlines()) == 1


def test_zero_alone_still_shows_the_help() -> None:
    run = zero_cli(env=PLAIN)
    assert run.code == 2 and "Usage: zero [OPTIONS] COMMAND [ARGS]..." in run.stdout + run.stderr


def test_lint_help_names_every_kind_of_input() -> None:
    text = zero_cli("lint", "--help", env=PLAIN).stdout
    assert "PATH" in text and "*.xml" in text and "YAML/TOML/JSON" in text and "*.nc" in text


# --------------------------------------------------------------- a folder .gitignore hides


@pytest.fixture
def machine_repo(tmp_path: Path) -> Path:
    """A git work tree whose machine backups lie in a folder .gitignore names."""
    if GIT is None:
        pytest.skip("git is not installed")
    subprocess.run([GIT, "init", "-q", str(tmp_path)], check=True, env={**os.environ, "GIT_CONFIG_GLOBAL": os.devnull})
    (tmp_path / ".gitignore").write_text("backup/\n")
    (tmp_path / "backup").mkdir()
    for name in ("a.lis", "b.lis"):
        (tmp_path / "backup" / name).write_bytes(SEED)
    (tmp_path / "backup" / "notes.txt").write_text("not a list\n")
    return tmp_path


def test_a_gitignored_folder_says_what_was_skipped_and_how_to_include_it(machine_repo: Path) -> None:
    run = zero_cli("lint", "backup", cwd=machine_repo, env=PLAIN)
    assert run.code == 2
    assert "no list files or NC programs found" in run.stderr
    assert "2 files skipped by .gitignore (--no-respect-gitignore" in run.stderr, run.stderr
    included = zero_cli("lint", "backup", "--no-respect-gitignore", "--output-format", "concise", cwd=machine_repo,
                        env=PLAIN)
    assert included.stdout.count("S004") == 4


def test_an_excluded_folder_says_so(tmp_path: Path) -> None:
    (tmp_path / "old").mkdir()
    (tmp_path / "old" / "a.lis").write_bytes(SEED)
    (tmp_path / "zero.toml").write_text('exclude = ["old"]\n')
    run = zero_cli("lint", ".", cwd=tmp_path, env=PLAIN)
    assert run.code == 2 and "1 file skipped by exclude" in run.stderr, run.stderr


# ------------------------------------------------------------------------- ruff's options


def _codes(run_stdout: str) -> list[str]:
    return [line.split()[1] for line in run_stdout.splitlines() if line.strip()]


def test_select_all_enables_every_rule_and_ignore_still_wins(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(OPT_IN)
    default = zero_cli("lint", "a.lis", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    everything = zero_cli("lint", "a.lis", "--select", "ALL", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    assert "S012" not in _codes(default.stdout)
    assert "S012" in _codes(everything.stdout)
    less = zero_cli("lint", "a.lis", "--select", "ALL", "--ignore", "S", "--output-format", "concise",
                    cwd=tmp_path, env=PLAIN)
    assert not any(c.startswith("S") for c in _codes(less.stdout))
    (tmp_path / "zero.toml").write_text('select = ["ALL"]\n')
    configured = zero_cli("lint", "a.lis", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    assert "S012" in _codes(configured.stdout)


def test_exclude_and_extend_exclude_on_the_command_line(tmp_path: Path) -> None:
    for folder in ("old", "new", "keep"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "a.lis").write_bytes(SEED)
    (tmp_path / "zero.toml").write_text('exclude = ["keep"]\n')

    def files(*args: str) -> list[str]:
        run = zero_cli("lint", ".", "--show-files", *args, cwd=tmp_path, env=PLAIN)
        assert run.code == 0, run.stderr
        return sorted(run.stdout.split())

    assert files() == ["new/a.lis", "old/a.lis"]
    assert files("--exclude", "old") == ["keep/a.lis", "new/a.lis"]  # in place of the configuration's
    assert files("--extend-exclude", "old") == ["new/a.lis"]  # as well as the configuration's
    assert files("--extend-exclude", "old,new") == []


def test_force_exclude_and_its_opposite(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(SEED)
    (tmp_path / "zero.toml").write_text('exclude = ["a.lis"]\n')
    forced = zero_cli("lint", "a.lis", "--force-exclude", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    default = zero_cli("lint", "a.lis", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    named = zero_cli("lint", "a.lis", "--no-force-exclude", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    assert forced.stdout == default.stdout == ""
    assert "S004" in named.stdout


def test_respect_gitignore_on_the_command_line(machine_repo: Path) -> None:
    (machine_repo / "top.lis").write_bytes(SEED)
    (machine_repo / "zero.toml").write_text("respect-gitignore = false\n")
    walked = zero_cli("lint", ".", "--show-files", cwd=machine_repo, env=PLAIN)
    assert "backup/a.lis" in walked.stdout
    kept = zero_cli("lint", ".", "--show-files", "--respect-gitignore", cwd=machine_repo, env=PLAIN)
    assert kept.code == 0 and kept.stdout.split() == ["top.lis"], kept.stderr


def test_the_kernel_release_on_the_command_line(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(SEED)
    run = zero_cli("lint", "a.lis", "--kernel", "V3.1.3079", "--output-format", "json", cwd=tmp_path, env=PLAIN)
    assert run.code == 1 and run.stderr == "", run.stderr  # the seed list's two errors, the release accepted
    alias = zero_cli("lint", "a.lis", "--target-version", "V3.1.3079", "--output-format", "json", cwd=tmp_path,
                     env=PLAIN)
    assert alias.stdout == run.stdout
    bad = zero_cli("lint", "a.lis", "--kernel", "bogus", cwd=tmp_path, env=PLAIN)
    assert bad.code == 2 and "not a kernel release: 'bogus'" in bad.stderr and len(bad.stderr.splitlines()) == 1


def test_the_kernel_option_reaches_the_checks() -> None:
    from zero.cli.run import command_line_config
    from zero.engine.config import Config, inline_config

    cfg = Config()
    for text in command_line_config(["a,b"], ["c"], False, "V3.1.3079"):
        cfg = inline_config(text, cfg)
    assert cfg.kernel == "V3.1.3079" and cfg.exclude == ("a", "b") and cfg.respect_gitignore is False


def test_statistics_prints_the_counts_alone(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(SEED)
    run = zero_cli("lint", "a.lis", "--statistics", cwd=tmp_path, env=PLAIN)
    assert run.stdout.split("\n")[:2] == ["      5  M003  masked-offset", "      2  S004  key-whitespace"], run.stdout
    assert "np_grp" not in run.stdout + run.stderr
    as_json = zero_cli("lint", "a.lis", "--statistics", "--output-format", "json", cwd=tmp_path, env=PLAIN)
    assert json.loads(as_json.stdout) == [{"code": "M003", "name": "masked-offset", "count": 5},
                                          {"code": "S004", "name": "key-whitespace", "count": 2}]


def test_show_fixes_and_fix_only(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(SEED)
    available = zero_cli("lint", "a.lis", "--show-fixes", "-q", cwd=tmp_path, env=PLAIN)
    assert "2 findings can be fixed" in available.stderr and "2 × S004 (key-whitespace)" in available.stderr
    assert (tmp_path / "a.lis").read_bytes() == SEED  # shown, not applied
    only = zero_cli("lint", "a.lis", "--fix-only", "--show-fixes", cwd=tmp_path, env=PLAIN)
    assert only.code == 0 and only.stdout == ""
    assert "Fixed 2 findings:" in only.stderr and "- a.lis:" in only.stderr
    fixed = (tmp_path / "a.lis").read_bytes()
    assert fixed != SEED and b"]. inaktiv" not in fixed
    again = zero_cli("lint", "a.lis", "--fix-only", "--show-fixes", cwd=tmp_path, env=PLAIN)
    assert again.code == 0 and "No fixes applied." in again.stderr


@pytest.mark.slow
def test_watch_lints_again_when_a_file_changes(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(b"g53_verfuegbar 1\nEnde\n")
    proc = subprocess.Popen([sys.executable, "-m", "zero", "lint", "--watch", ".", "--output-format", "concise"],
                            cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env={**os.environ, **PLAIN})
    try:
        deadline = time.monotonic() + 120
        err = ""
        assert proc.stderr is not None
        while "watching 1 file" not in err:  # the first run is done
            assert time.monotonic() < deadline and proc.poll() is None, err
            err += proc.stderr.readline()
        (tmp_path / "a.lis").write_bytes(b"g53_verfuegbar 1\nzzz_unknown 1\nEnde\n")
        while err.count("watching 1 file") < 2:
            assert time.monotonic() < deadline and proc.poll() is None, err
            err += proc.stderr.readline()
        assert "a file changed: linting again" in err
    finally:
        proc.terminate()
        out, _ = proc.communicate(timeout=60)
    assert "a.lis:2:1: R001" in out


def test_watch_refuses_standard_input() -> None:
    run = zero_cli("lint", "--watch", "-", env=PLAIN)
    assert run.code == 2 and "--watch needs files or directories" in run.stderr


def test_the_new_options_are_in_the_readme_table_of_formats() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "reviewdog" in readme and "Azure" in readme and "--watch" in readme


def test_a_fix_that_renames_a_key_keeps_the_value_in_its_column(tmp_path: Path) -> None:
    """`kenngr.swe_po` → `kenngr.swe_pos` (R001's did-you-mean, an unsafe fix): the value stays in
    the column of the values around it, not one to the right."""
    aligned = "kenngr.swe_po                      1500\nkenngr.swe_neg                     -1500\nEnde\n"
    (tmp_path / "a.lis").write_text(aligned)
    run = zero_cli("lint", "a.lis", "--fix", "--unsafe-fixes", "-q", cwd=tmp_path, env=PLAIN)
    assert run.code in (0, 1)
    first, second = (tmp_path / "a.lis").read_text().splitlines()[:2]
    assert first == "kenngr.swe_pos                     1500"
    assert first.index("1500") == second.index("-1500") == 35


def test_keep_column_only_in_an_aligned_layout() -> None:
    from zero.diagnostics import Edit, Span
    from zero.engine.fixes import _keep_column

    rename = Edit(Span(1, 1, 1, 4), "abcde")  # three characters become five
    assert _keep_column("      7", rename, 5) == "    7"
    assert _keep_column("  7", rename, 5) == " 7"  # one blank at least
    assert _keep_column(" 7", rename, 5) == " 7"  # one blank: no column to keep
    assert _keep_column("   ", rename, 5) == "   "  # nothing after the blanks


def test_ignore_noqa_reports_what_the_suppressions_hide(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_text("kenngr.swe_pso 1500 # noqa: R001\nEnde\n")
    hidden = zero_cli("lint", "a.lis", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    shown = zero_cli("lint", "a.lis", "--ignore-noqa", "--output-format", "concise", cwd=tmp_path, env=PLAIN)
    assert "R001" not in hidden.stdout
    assert "a.lis:1:1: R001" in shown.stdout and "Z001" not in shown.stdout

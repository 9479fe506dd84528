"""The command line, through typer's runner and through a real process."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conftest import FIXTURES
from zero.cli.app import app
from zero.rules import RULES

runner = CliRunner()
SEED = str(FIXTURES / "seed" / "nullp_3achsen.lis")
CLEAN = str(FIXTURES / "rules" / "M006" / "pass.lis")
WARN_ONLY = str(FIXTURES / "rules" / "M006" / "fail.lis")

JSON_KEYS = {"path", "line", "column", "end_line", "end_column", "code", "severity", "message",
             "param_id", "kernel_error", "consequence", "source", "fix"}


def test_lint_text_report_and_exit_code() -> None:
    result = runner.invoke(app, ["lint", SEED])
    assert result.exit_code == 1, result.output
    assert f"{SEED}:19:20: S004 error whitespace inside the key" in result.output
    assert " 19 | np_grp[0].achse[1]. inaktiv 0" in result.output
    assert "= hint: Remove the whitespace inside the key" in result.output
    assert "1 file checked (0 clean): 2 errors, 0 warnings, 5 infos" in result.output
    assert "\x1b[" not in result.output  # not a terminal: no colour


def test_json_contract() -> None:
    result = runner.invoke(app, ["lint", "--output-format", "json", SEED])
    assert result.exit_code == 1
    data = json.loads(result.output)
    assert isinstance(data, list) and len(data) == 7
    for d in data:
        assert set(d) == JSON_KEYS
        assert d["severity"] in ("error", "warning", "info")
        assert d["fix"] is None or set(d["fix"]) == {"title", "safe", "edits"}
    first = data[0]
    assert (first["line"], first["column"], first["end_line"], first["end_column"]) == (19, 20, 19, 21)
    assert first["code"] == "S004" and first["param_id"] is None
    assert first["fix"]["edits"] == [
        {"line": 19, "column": 20, "end_line": 19, "end_column": 21, "replacement": ""}]
    m003 = data[2]
    assert m003["code"] == "M003" and m003["param_id"] == "P-ZERO-00003"


def test_exit_codes_clean_warning_strict() -> None:
    assert runner.invoke(app, ["lint", CLEAN]).exit_code == 0
    assert runner.invoke(app, ["lint", WARN_ONLY]).exit_code == 0
    assert runner.invoke(app, ["lint", "--strict", WARN_ONLY]).exit_code == 1


def test_select_and_ignore() -> None:
    result = runner.invoke(app, ["lint", "--output-format", "json", "--select", "M", SEED])
    assert {d["code"] for d in json.loads(result.output)} == {"M003"}
    assert result.exit_code == 0
    result = runner.invoke(app, ["lint", "--ignore", "S004,M", SEED])
    assert result.exit_code == 0 and "0 errors" in result.output
    result = runner.invoke(app, ["lint", "--select", "Q9", SEED])
    assert result.exit_code == 2


def test_kind_override() -> None:
    result = runner.invoke(app, ["lint", "--kind", "axis", "--output-format", "json", SEED])
    data = json.loads(result.output)
    assert any(d["code"] == "R001" and "belongs to the zero-offset list" in d["message"]
               for d in data)
    assert runner.invoke(app, ["lint", "--kind", "nonsense", SEED]).exit_code == 2


def test_directories_recurse(tmp_path: Path) -> None:
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "x.lis").write_text("g53_verfuegbar 1\n")
    (tmp_path / "a" / "y.lst").write_text("g53_verfuegbar 2\n")
    (tmp_path / "a" / "notes.txt").write_text("not a list\n")
    result = runner.invoke(app, ["lint", "--output-format", "json", str(tmp_path)])
    data = json.loads(result.output)
    assert [Path(str(d["path"])).name for d in data] == ["y.lst"]
    assert result.exit_code == 1


def test_io_errors_exit_2(tmp_path: Path) -> None:
    result = runner.invoke(app, ["lint", str(tmp_path / "missing.lis")])
    assert result.exit_code == 2 and "no such file" in result.output
    result = runner.invoke(app, ["lint", str(tmp_path)])  # empty directory
    assert result.exit_code == 2 and "no list files" in result.output
    assert "Traceback" not in result.output


def test_rule_and_param_commands() -> None:
    result = runner.invoke(app, ["rule", "S004"])
    assert result.exit_code == 0 and "Why it matters on the machine" in result.output
    result = runner.invoke(app, ["rule"])
    assert result.exit_code == 0 and "M008" in result.output
    result = runner.invoke(app, ["rule", "--all"])
    assert result.output.count("Why it matters on the machine") == len(RULES)
    assert runner.invoke(app, ["rule", "X999"]).exit_code == 2
    result = runner.invoke(app, ["param", "P-AXIS-00178"])
    assert result.exit_code == 0 and "kenngr.swe_pos" in result.output and "100000000" in result.output
    result = runner.invoke(app, ["param", "np_grp[5].achse[2].versch"])
    assert "P-ZERO-00003" in result.output and "np_grp[0..96], achse[0..31]" in result.output
    result = runner.invoke(app, ["param", "kenngr.swe_pso"])
    assert result.exit_code == 2 and "kenngr.swe_pos" in result.output


def test_param_desc_option(tmp_path: Path) -> None:
    bad = tmp_path / "bad.xml"
    bad.write_text("not xml")
    result = runner.invoke(app, ["--param-desc", str(bad), "lint", SEED])
    assert result.exit_code == 2 and "cannot read parameter description" in result.output


def test_version() -> None:
    result = runner.invoke(app, ["--version"])
    assert result.exit_code == 0 and result.output.startswith("zero ")


def _run(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "zero", *args], capture_output=True, text=True,
                          timeout=60, env={**os.environ, **(env or {})})


def test_subprocess_lint() -> None:
    proc = _run("lint", SEED, env={"NO_COLOR": "1"})
    assert proc.returncode == 1
    assert "S004 error" in proc.stdout and "checked" not in proc.stdout
    assert proc.stderr == "1 file checked (0 clean): 2 errors, 0 warnings, 5 infos\n"
    proc = _run("lint", "--output-format", "json", CLEAN)
    assert proc.returncode == 0 and json.loads(proc.stdout) == []


def test_subprocess_colour_only_when_forced() -> None:
    proc = _run("lint", SEED, env={"FORCE_COLOR": "1"})
    assert "\x1b[" in proc.stdout
    proc = _run("lint", SEED, env={"FORCE_COLOR": "1", "NO_COLOR": "1"})
    assert "\x1b[" not in proc.stdout


def test_subprocess_usage_error_is_one_line() -> None:
    proc = _run("lint", "/nonexistent/file.lis")
    assert proc.returncode == 2
    assert proc.stderr.strip().count("\n") == 0 and "Traceback" not in proc.stderr


def test_the_console_entry_ends_without_teardown_but_says_everything(tmp_path: Path) -> None:
    """``zero.cli.lean.end`` skips the interpreter's teardown: output far beyond a pipe's buffer
    still arrives whole, and exit codes and messages of both command lines are kept."""
    big = tmp_path / "unknown.lis"
    # an axis list: its unknown elements are errors (P-ERR-1001119), so every run ends with 1
    big.write_text("kopf.achs_nr 1\n" + "".join(f"made_up_key_{i} {i}\n" for i in range(3000)), encoding="utf-8")
    proc = _run("lint", "--output-format", "json", str(big))
    assert proc.returncode == 1 and len(json.loads(proc.stdout)) == 3000  # ~1 MB through the pipe
    proc = _run("lint", "--output-format", "concise", str(big), env={"NO_COLOR": "1"})
    assert proc.returncode == 1 and proc.stdout.count("R001") == 3000 and proc.stderr == ""
    proc = _run("lint", str(big), env={"NO_COLOR": "1"})
    assert proc.returncode == 1 and proc.stderr == "1 file checked (0 clean): 3000 errors, 0 warnings, 0 infos\n"
    a, b = tmp_path / "a.lis", tmp_path / "b.lis"
    a.write_text("kopf.achs_nr 1\n", encoding="utf-8")
    b.write_text("kopf.achs_nr 2\n", encoding="utf-8")
    proc = _run("diff", str(a), str(b))  # the typer command line
    assert proc.returncode == 1 and "kopf.achs_nr" in proc.stdout
    proc = _run("rule", "Q999")
    assert proc.returncode == 2 and "Q999" in proc.stderr


def test_end_flushes_what_is_buffered_and_keeps_the_code() -> None:
    code = "import sys; from zero.cli.lean import end; [sys.stdout.write('x' * 99) for _ in range(1000)]; end(3)"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}  # buffered, as users run it
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=False,
                          env=env)
    assert (proc.returncode, len(proc.stdout)) == (3, 99_000)


@pytest.mark.slow
def test_progress_bar_only_on_a_terminal(tmp_path: Path) -> None:
    import pty

    for i in range(250):
        (tmp_path / f"l{i:03d}.lis").write_text(f"np_grp[1].achse[0].versch {i}\nEnde\n")
    proc = _run("lint", "-j", "1", str(tmp_path))
    assert "files" not in proc.stderr.replace("250 files checked", "")  # not a terminal: no bar
    master, slave = pty.openpty()
    p = subprocess.run([sys.executable, "-m", "zero", "lint", "-j", "1", str(tmp_path)],
                       stdout=subprocess.DEVNULL, stderr=slave, check=False, env={**os.environ, "NO_COLOR": "1"})
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
    os.close(master)
    err = b"".join(chunks).decode()
    assert p.returncode == 0
    assert "250/250 files" in err and "250 files checked" in err


def test_shell_completion_script() -> None:
    # Typer takes the shell from the processes above it and ignores a name after the flag unless
    # its detection is off: without this, the test failed where no bash was among its ancestors.
    proc = _run("--show-completion", "bash", env={"_TYPER_COMPLETE_TEST_DISABLE_SHELL_DETECTION": "1"})
    assert proc.returncode == 0 and "zero_completion() {" in proc.stdout

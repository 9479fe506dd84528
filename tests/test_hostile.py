"""Hostile input: a finding or exit 2, never a traceback, in bounded time and memory."""

from __future__ import annotations

import io
import json
import random
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conftest import lint_text
from zero.cli import app
from zero.lint import LintResult
from zero.report import render_text

MiB = 1024 * 1024


def _bounded(data: bytes, seconds: float = 60.0, memory_mib: int = 1024) -> LintResult:
    """Lint in a child process capped at ``memory_mib`` of address space and ``seconds``.

    The child runs the real CLI (JSON output), so this also proves: no traceback, exit 1
    or 0 with findings, or 2 with a one-line message. The parent re-lints in-process
    (uncapped) to hand the result to the assertions.
    """
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "hostile.lis"
        path.write_bytes(data)
        limit = memory_mib * MiB

        def cap() -> None:
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

        t0 = time.perf_counter()
        proc = subprocess.run(
            [sys.executable, "-m", "zero", "lint", "--output-format", "json", str(path)],
            capture_output=True, timeout=seconds, preexec_fn=cap, check=False,
        )
        elapsed = time.perf_counter() - t0
    assert proc.returncode in (0, 1, 2), proc.stderr[-2000:]
    assert b"Traceback" not in proc.stderr
    assert elapsed < seconds
    if proc.returncode != 2:
        json.loads(proc.stdout)
    result = lint_text(data)
    render_text([result], io.StringIO(), color=False)
    for d in result.diagnostics:  # every span lies inside the file
        assert 1 <= d.span.line <= max(1, len(result.document.lines))
    return result


def test_random_binary() -> None:
    rng = random.Random(1234)
    data = bytes(rng.randrange(256) for _ in range(200_000))
    result = _bounded(data)
    assert result.diagnostics  # something is reported


def test_nul_bytes_everywhere() -> None:
    result = _bounded(b"\x00" * 100_000 + b"\nk\x00 1\n")
    assert "S008" in {d.code for d in result.diagnostics}


def test_utf16_file() -> None:
    result = _bounded("np_grp[1].achse[0].versch 5\n".encode("utf-16"))
    assert "S008" in {d.code for d in result.diagnostics}


def test_ten_megabyte_line() -> None:
    line = b"np_grp[1].achse[0].versch 5 ( " + b"x" * (10 * MiB) + b"\n"
    result = _bounded(line, memory_mib=768)
    assert result.diagnostics == []
    result = _bounded(b"a" * (10 * MiB) + b" 1\n", memory_mib=768)
    assert [d.code for d in result.diagnostics] == ["R001"]
    out = io.StringIO()
    render_text([result], out, color=False)
    assert max(len(x) for x in out.getvalue().splitlines()) < 400  # the source is cut


@pytest.mark.parametrize("digits", [20, 30, 5000])
def test_huge_indices(digits: int) -> None:
    result = _bounded(f"np_grp[{'9' * digits}].achse[0].versch 1\n".encode())
    assert [d.code for d in result.diagnostics] == ["R003"]


def test_huge_values() -> None:
    result = _bounded(f"g53_verfuegbar {'9' * 5000}\n".encode())
    assert [d.code for d in result.diagnostics] == ["R005"]
    result = _bounded(f"np_grp[1].achse[0].versch -{'9' * 100}\n".encode())
    assert [d.code for d in result.diagnostics] == ["R004"]


def test_twenty_thousand_nested_members() -> None:
    key = ".".join(["a"] * 20_000)
    result = _bounded(f"{key} 1\n{key}[1] 2\n".encode())
    assert [d.code for d in result.diagnostics] == ["R001", "R001"]


def test_unterminated_quote_and_empty_file() -> None:
    assert [d.code for d in _bounded(b'kopf.log_achs_name "abc\n').diagnostics] == ["S003"]
    assert _bounded(b"").diagnostics == []
    assert _bounded(b"\n\n\n").diagnostics == []


def test_many_lines() -> None:
    data = b"".join(b"np_grp[%d].achse[%d].versch %d\n" % (i % 97, i % 32, i) for i in range(100_000))
    result = _bounded(data)
    # duplicates (the later value wins) and group-0 offsets without g53_verfuegbar
    assert {d.code for d in result.diagnostics} == {"R007", "M002"}


def test_cli_on_binary_file(tmp_path: Path) -> None:
    f = tmp_path / "junk.lis"
    f.write_bytes(bytes(range(256)) * 50)
    result = CliRunner().invoke(app, ["lint", "--output-format", "json", str(f)])
    assert result.exit_code in (1, 2)
    assert "Traceback" not in result.output
    json.loads(result.output)

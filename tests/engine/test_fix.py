"""zero lint --fix / --diff / --unsafe-fixes and zero format."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from typer.testing import CliRunner

from conftest import FIXTURES, builtin_registry, generated_lists
from zero.catalog.registry import Registry
from zero.cli.app import app
from zero.diff import DiffOptions, diff_sides, read_side
from zero.engine.fixes import fix_bytes
from zero.engine.formatting import format_bytes
from zero.engine.lint import LintOptions
from zero.errors import ZeroError

runner = CliRunner()
SEED = (FIXTURES / "seed" / "nullp_3achsen.lis").read_bytes()


def zero(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "zero", *args], cwd=cwd, capture_output=True, text=True,
                          check=False)


def test_safe_fixes_touch_only_their_bytes(registry: Registry) -> None:
    data = SEED.replace(b"\n", b"\r\n") + b"#np_grp[3].achse[0].versch 5\r\n"
    result = fix_bytes(data, "seed.lis", registry, LintOptions(extend_select=("S012",)))
    assert result.applied == 3  # two keys with whitespace, one missing space after # (S012, opt-in)
    assert result.fixed == data.replace(b"]. inaktiv", b"].inaktiv").replace(b"#np_grp[3]", b"# np_grp[3]")
    assert {d.code for d in result.result.diagnostics} == {"M003"}


def test_unsafe_fixes_only_when_asked(registry: Registry) -> None:
    data = b"g53_verfuegbr 1\nEnde\n"
    assert fix_bytes(data, "n.lis", registry).fixed == data
    assert fix_bytes(data, "n.lis", registry, unsafe=True).fixed == b"g53_verfuegbar 1\nEnde\n"


def test_cli_diff_fix_and_encoding(tmp_path: Path) -> None:
    target = tmp_path / "nullp.lis"
    target.write_bytes(SEED)
    p = zero("lint", "--diff", "nullp.lis", cwd=tmp_path)
    assert p.returncode == 1
    assert "-np_grp[0].achse[1]. inaktiv 0" in p.stdout and "+np_grp[0].achse[1].inaktiv 0" in p.stdout
    assert target.read_bytes() == SEED  # --diff writes nothing
    p = zero("lint", "--fix", "nullp.lis", cwd=tmp_path)
    assert p.returncode == 0, p.stdout + p.stderr  # only infos are left
    assert "2 fixes applied" in p.stderr
    fixed = target.read_bytes()
    assert fixed == SEED.replace(b"]. inaktiv", b"].inaktiv")  # Latin-1 µ and ° untouched
    r = runner.invoke(app, ["lint", "--fix", str(target)])
    assert r.exit_code == 0 and target.read_bytes() == fixed  # nothing left to fix


def test_format_keeps_meaning_and_comments_and_is_idempotent(registry: Registry, corpus: Path) -> None:
    for path in [FIXTURES / "seed" / "nullp_3achsen.lis", *sorted((corpus / "isg-sdk" / "listen").rglob("*.lis"))]:
        data = path.read_bytes()
        formatted = format_bytes(data, str(path), registry)
        assert format_bytes(formatted, str(path), registry) == formatted, path
        a, b = read_side(data, "lis", "a", registry), read_side(formatted, "lis", "b", registry)
        assert diff_sides(a, b, registry, DiffOptions(strict=True, comments=True)) == [], path


@pytest.mark.slow
@settings(max_examples=100, deadline=None)
@given(generated_lists())
def test_format_is_idempotent_on_generated_lists(data: bytes) -> None:
    registry = builtin_registry()
    try:
        once = format_bytes(data, "g.lis", registry)
    except ZeroError:
        return
    assert format_bytes(once, "g.lis", registry) == once
    assert diff_sides(read_side(data, "lis", "a", registry), read_side(once, "lis", "b", registry),
                      registry, DiffOptions(strict=True, comments=True)) == []


@pytest.mark.slow
def test_format_command(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(b"kenngr.swe_pos 1  ( c\nkenngr.swe_neg -1\nEnde\n")
    (tmp_path / "bad.lis").write_bytes(b"k.a 1\n*****\n")
    p = zero("format", "--check", ".", cwd=tmp_path)
    assert p.returncode == 1 and "would reformat a.lis" in p.stdout and "bad.lis:2:1" in p.stderr
    p = zero("format", "--diff", "a.lis", cwd=tmp_path)
    assert p.returncode == 1 and p.stdout.startswith("--- a/a.lis")
    assert zero("format", "a.lis", cwd=tmp_path).returncode == 0
    assert (tmp_path / "a.lis").read_text() == (
        "kenngr.swe_pos".ljust(54) + "1".ljust(15) + "( c\n" + "kenngr.swe_neg".ljust(54) + "-1\nEnde\n")
    assert zero("format", "--check", "a.lis", cwd=tmp_path).returncode == 0

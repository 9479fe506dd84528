"""zero convert on the command line: outputs, overwrite rules, atomic writes, exit codes."""

from __future__ import annotations

import errno
import os
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conftest import FIXTURES
from zero.cli.app import app
from zero.errors import ZeroError
from zero.files import write_atomic

runner = CliRunner()
SEED = FIXTURES / "seed" / "nullp_3achsen.lis"


def invoke(*args: str, stdin: bytes | None = None) -> tuple[int, bytes, str]:
    result = runner.invoke(app, list(args), input=stdin)
    return result.exit_code, result.stdout_bytes, result.stderr


def test_to_stdout_and_back_through_files(tmp_path: Path) -> None:
    code, out, _ = invoke("convert", str(SEED))
    assert code == 0 and out.startswith(b"# *****")
    y = tmp_path / "n.yaml"
    assert invoke("convert", str(SEED), "-o", str(y))[0] == 0
    lis = tmp_path / "n.lis"
    code, _, err = invoke("convert", str(y), "-o", str(lis))
    assert code == 0
    assert "S004" in err  # the list still has the seed's whitespace fault: reported
    assert lis.read_bytes() == SEED.read_bytes()


def test_format_from_suffix_and_options(tmp_path: Path) -> None:
    t = tmp_path / "n.toml"
    assert invoke("convert", str(SEED), "-o", str(t))[0] == 0
    assert t.read_text().count("[np_grp.") > 10
    code, out, _ = invoke("convert", str(t), "--to", "json")
    assert code == 0 and out.lstrip().startswith(b"{")
    weird = tmp_path / "data.txt"
    weird.write_bytes(SEED.read_bytes())
    code, _, err = invoke("convert", str(weird))
    assert code == 2 and "--from" in err
    assert invoke("convert", str(weird), "--from", "lis")[0] == 0


def test_never_overwrites_without_force_and_never_the_input(tmp_path: Path) -> None:
    src = tmp_path / "a.lis"
    src.write_bytes(SEED.read_bytes())
    out = tmp_path / "a.yaml"
    out.write_text("precious")
    code, _, err = invoke("convert", str(src), "-o", str(out))
    assert code == 2 and "--force" in err and out.read_text() == "precious"
    assert invoke("convert", str(src), "-o", str(out), "--force")[0] == 0
    assert out.read_text().startswith("# *****")
    code, _, err = invoke("convert", str(src), "-o", str(src), "--force", "--to", "lis")
    assert code == 2 and "input" in err
    assert src.read_bytes() == SEED.read_bytes()


def test_several_inputs_need_out_dir_and_fail_as_a_whole(tmp_path: Path) -> None:
    good = tmp_path / "good.lis"
    good.write_bytes(SEED.read_bytes())
    bad = tmp_path / "bad.lis"
    bad.write_bytes(b"k.a 1\n*****\nEnde\n")
    assert invoke("convert", str(good), str(bad))[0] == 2
    out_dir = tmp_path / "out"
    code, _, err = invoke("convert", str(good), str(bad), "--out-dir", str(out_dir))
    assert code == 1 and "bad.lis:2:1" in err
    assert not out_dir.exists() or list(out_dir.iterdir()) == []
    bad.write_bytes(b"k.a 1\nEnde\n")
    assert invoke("convert", str(good), str(bad), "--out-dir", str(out_dir), "--to", "toml")[0] == 0
    assert sorted(p.name for p in out_dir.iterdir()) == ["bad.toml", "good.toml"]


def test_stdin_and_refusal_exit_1() -> None:
    code, out, _ = invoke("convert", "-", "--to", "json", stdin=b"k.a 1\nEnde\n")
    assert code == 0 and b'"k"' in out
    code, out, err = invoke("convert", "-", "--from", "yaml", stdin=b"a: !!python/object:os.system 1\n")
    assert code == 1 and out == b"" and "-:1:" in err and "tag" in err
    code, _, err = invoke("convert", "-", "--from", "toml", stdin=b"[np_grp.1.achse.0]\nversch = 1.5\n")
    assert code == 1 and "floating-point" in err


def test_strict_refuses_lists_with_errors(tmp_path: Path) -> None:
    y = tmp_path / "x.yaml"
    y.write_text("kopf:\n  achs_nr: 1\nkenngr:\n  swe_pso: 1500\n")  # R001 in an axis list: an error
    assert invoke("convert", str(y))[0] == 0
    code, out, err = invoke("convert", str(y), "--strict")
    assert code == 1 and out == b"" and "x.yaml:4:3: R001 error" in err


def test_lint_reads_yaml_toml_json(tmp_path: Path) -> None:
    for fmt in ("yaml", "toml", "json"):
        target = tmp_path / f"n.{fmt}"
        assert invoke("convert", str(SEED), "-o", str(target))[0] == 0
        code, out, _ = invoke("lint", "--strict", str(target))  # the seed's two S004: warnings (issue 36)
        assert code == 1, fmt
        assert b"S004" in out and b"np_grp.0.achse.1.inaktiv" in out
    broken = tmp_path / "b.yaml"
    broken.write_text("a: &x 1\n")
    code, out, _ = invoke("lint", str(broken))  # one S017 finding where the reader stopped; the run goes on
    assert code == 1 and b"b.yaml:1:4" in out and b"S017" in out


def test_write_atomic_leaves_nothing_behind_on_failure(tmp_path: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "out.yaml"
    target.write_bytes(b"old")

    def full_disk(fd: int) -> None:
        raise OSError(errno.ENOSPC, "No space left on device")

    with monkeypatch.context() as m:
        m.setattr(os, "fsync", full_disk)
        with pytest.raises(ZeroError, match="No space left"):
            write_atomic(target, b"new" * 1000, force=True)
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["out.yaml"]

    def rename_fails(a: object, b: object) -> None:
        raise OSError(errno.EXDEV, "rename failed")

    with monkeypatch.context() as m:
        m.setattr(os, "replace", rename_fails)
        with pytest.raises(ZeroError, match="rename failed"):
            write_atomic(target, b"new", force=True)
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["out.yaml"]

    write_atomic(target, b"new", force=True)
    assert target.read_bytes() == b"new"


def test_killed_writer_never_leaves_a_truncated_target(tmp_path: Path) -> None:
    """A process killed in the middle of writing leaves the old file (or none) in place."""
    target = tmp_path / "out.lis"
    target.write_bytes(b"old\n")
    script = (
        "import os, sys, time\n"
        "from pathlib import Path\n"
        "import zero.files as c\n"
        "real = os.fsync\n"
        "def slow(fd):\n"
        "    sys.stdout.write('writing\\n'); sys.stdout.flush(); time.sleep(30)\n"
        "os.fsync = slow\n"
        f"c.write_atomic(Path({str(target)!r}), b'x' * 10_000_000, force=True)\n"
    )
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE)
    assert proc.stdout is not None
    assert proc.stdout.readline() == b"writing\n"
    proc.kill()
    proc.wait()
    assert target.read_bytes() == b"old\n"
    leftovers = [p for p in tmp_path.iterdir() if p.name != "out.lis"]
    assert all(p.name.startswith(".out.lis.") for p in leftovers)  # a hidden temp file at most


@pytest.mark.slow
def test_subprocess_convert_round_trip(tmp_path: Path) -> None:
    y = tmp_path / "seed.yaml"
    run = subprocess.run([sys.executable, "-m", "zero", "convert", str(SEED), "-o", str(y)],
                         capture_output=True)
    assert run.returncode == 0, run.stderr
    back = subprocess.run([sys.executable, "-m", "zero", "convert", str(y), "--to", "lis"],
                          capture_output=True)
    assert back.returncode == 0
    assert back.stdout == SEED.read_bytes()

"""One project, one answer: every command asks the resolver (zero.engine.project) which
configuration, catalogue and machine apply to a file, and they agree.

Each case here was a wrong answer on the old main (issue 22), reproduced through the
command line in a child process."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli

pytestmark = pytest.mark.slow

LAYERED = FIXTURES / "machine-layered"
AXIS = "kopf.achs_nr 1\nkenngr.homing_type DRIVE_DEFAULT\nkenngr.achs_typ 7\nEnde\n"  # R002 line 2, R005 line 3


def concise(run_out: str) -> list[tuple[str, str]]:
    """(file name, code) of each concise finding line."""
    out = []
    for line in run_out.splitlines():
        parts = line.split(": ", 1)
        if len(parts) == 2 and line.count(":") >= 3:
            out.append((Path(line.split(":", 1)[0]).name, parts[1].split()[0]))
    return sorted(out)


def _tree(tmp_path: Path, root_select: str, sub_select: str) -> Path:
    (tmp_path / "pyproject.toml").write_text(f'[tool.zero]\nselect = ["{root_select}"]\n')
    (tmp_path / "m" / "a").mkdir(parents=True)
    (tmp_path / "m" / "a" / "zero.toml").write_text(f'select = ["{sub_select}"]\n')
    (tmp_path / "m" / "x.lis").write_text(AXIS)
    (tmp_path / "m" / "a" / "y.lis").write_text(AXIS)
    return tmp_path


@pytest.mark.parametrize(("root", "sub"), [("R005", "R002"), ("R002", "R005")])
def test_a_folder_walk_gives_each_file_its_own_configuration(tmp_path: Path, root: str, sub: str) -> None:
    _tree(tmp_path, root, sub)
    walk = zero_cli("lint", "m", "--output-format", "concise", cwd=tmp_path)
    assert concise(walk.stdout) == sorted([("x.lis", root), ("y.lis", sub)])
    one = zero_cli("lint", "m/x.lis", "--output-format", "concise", cwd=tmp_path)
    assert concise(one.stdout) == [("x.lis", root)]
    shown = zero_cli("config", "--show", "m/x.lis", cwd=tmp_path)
    assert f'select = ["{root}"]' in shown.stdout
    shown = zero_cli("config", "--show", "m/a", cwd=tmp_path)
    assert f'select = ["{sub}"]' in shown.stdout


def _machine(tmp_path: Path, config: str = "") -> Path:
    root = tmp_path / "m"
    shutil.copytree(LAYERED, root, ignore=shutil.ignore_patterns("*.json", "*.txt"))
    if config:
        (root / "zero.toml").write_text(config)
    return root


def test_lint_machine_applies_the_projects_selection(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    before = zero_cli("lint", "--machine", "listen/hochlauf.lis", "--output-format", "json", cwd=root)
    assert {d["code"][0] for d in json.loads(before.stdout)} >= {"X"}
    (root / "zero.toml").write_text('ignore = ["M", "X"]\n')
    after = zero_cli("lint", "--machine", "listen/hochlauf.lis", "--output-format", "json", cwd=root)
    assert [d["code"] for d in json.loads(after.stdout) if d["code"][0] in "MX"] == []
    # per-file ignores reach the X findings too: the one on the zero-offset list is ignored there only
    (root / "zero.toml").write_text('[per-file-ignores]\n"listen/nullp.lis" = ["X001"]\n')
    some = json.loads(zero_cli("lint", "--machine", "listen/hochlauf.lis", "--output-format", "json",
                               cwd=root).stdout)
    assert "X001" not in {d["code"] for d in some} and "X005" in {d["code"] for d in some}


@pytest.mark.parametrize("command", [
    ("lint", "listen/achse_x.lis"),
    ("lint", "--machine", "listen/hochlauf.lis"),
    ("limits",),
    ("show", "--machine", "listen/hochlauf.lis"),
    ("explain", "kenngr.swe_pos"),
    ("show", "listen/achse_x.lis"),
    ("diff", "listen/achse_x.lis", "listen/achse_y.lis"),
    ("diff", "--machine", "listen/hochlauf.lis", "listen/hochlauf.lis"),
    ("format", "--check", "listen/achse_x.lis"),
    ("convert", "listen/achse_x.lis"),
])
def test_every_command_reads_the_configured_catalogue(tmp_path: Path, command: tuple[str, ...]) -> None:
    root = _machine(tmp_path, 'param-desc = "missing/CncParaDesc.xml"\n[machine]\nstartup = "listen/hochlauf.lis"\n')
    run = zero_cli(*command, cwd=root)
    assert run.code == 2, run
    assert "CncParaDesc.xml" in run.stderr


def test_diff_machine_keeps_the_list_overrides(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    (root / "listen" / "achse_x2.lis").write_text("kopf.achs_nr 1\nkopf.log_achs_name X_Achse\n"
                                                  "kenngr.swe_pos 7000000\nEnde\n")
    plain = zero_cli("diff", "--machine", "listen/hochlauf.lis", "listen/hochlauf.lis", cwd=root)
    assert plain.code == 0
    (root / "zero.toml").write_text('[machine]\n"achs_mds[0]" = "listen/achse_x2.lis"\n')
    overridden = zero_cli("diff", "--machine", "--output-format", "json", str(LAYERED / "listen" / "hochlauf.lis"),
                          "listen/hochlauf.lis", cwd=root)
    assert overridden.code == 1, overridden
    changes = json.loads(overridden.stdout)
    assert any(c["key"] == "kenngr.swe_pos" and c["new"] == "7000000" for c in changes), changes


def test_one_element_whatever_its_index_is_written_like(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    default = root / "listen" / "achse_vorgabe.lis"
    default.write_text(default.read_text().replace("Ende", "getriebe[1].dynamik.a_emergency 500\nEnde"))
    axis = root / "listen" / "achse_x.lis"
    axis.write_text(axis.read_text().replace("Ende", "getriebe[01].dynamik.a_emergency 700\nEnde"))
    run = zero_cli("show", "--machine", "listen/hochlauf.lis", "--output-format", "json", cwd=root)
    scope = next(s for s in json.loads(run.stdout)["scopes"] if s["scope"].startswith("axis 1"))
    values = [v for v in scope["values"] if "a_emergency" in v["key"]]
    assert [(v["key"], v["value"], Path(v["origin"]["path"]).name, v["origin"]["source"]) for v in values] == [
        ("getriebe[1].dynamik.a_emergency", "700", "achse_x.lis", "list")]
    explained = zero_cli("explain", "getriebe[01].dynamik.a_emergency", "--machine", "listen/hochlauf.lis", cwd=root)
    assert "700" in explained.stdout and "achse_x.lis" in explained.stdout
    diff = zero_cli("diff", str(axis), "-", stdin=axis.read_bytes().replace(b"[01]", b"[1]"), cwd=root)
    assert diff.code == 0, diff.stdout


def test_the_working_directory_does_not_depend_on_how_the_start_up_list_is_typed(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    inside = zero_cli("lint", "--machine", "hochlauf.lis", "--output-format", "json", cwd=root / "listen")
    outside = zero_cli("lint", "--machine", "listen/hochlauf.lis", "--output-format", "json", cwd=root)
    absolute = zero_cli("lint", "--machine", str(root / "listen" / "hochlauf.lis"), "--output-format", "json")

    def x005(run_out: str) -> list[str]:
        return sorted(d["message"].split("`")[3] for d in json.loads(run_out) if d["code"] == "X005"
                      and "names `" in d["message"])

    assert x005(inside.stdout) == x005(outside.stdout) == x005(absolute.stdout) == [
        "./listen/SoE/achse_c.lis", "./listen/hand_mds.lis"]
    message = next(d["message"] for d in json.loads(inside.stdout) if d["code"] == "X005")
    assert f"(working directory {root})" in message  # above the current directory: said absolute
    shown = zero_cli("show", "--machine", "hochlauf.lis", cwd=root / "listen")
    assert f"working directory {root}, 6 of 9 named lists read" in shown.stdout


@pytest.mark.parametrize("content", [b"", b"\x00\x01\x02binary\xff", b"# only a comment\nEnde\n"])
def test_a_start_up_list_that_yields_no_machine_is_an_error(tmp_path: Path, content: bytes) -> None:
    startup = tmp_path / "hochlauf.lis"
    startup.write_bytes(content)
    for command in (("lint", "--machine", str(startup)), ("limits", "--machine", str(startup)),
                    ("show", "--machine", str(startup))):
        run = zero_cli(*command, cwd=tmp_path)
        assert run.code == 2, (command, run)
        assert "names no list" in run.stderr or "not a start-up list" in run.stderr, run.stderr


def test_limits_without_an_axis_is_an_error(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    for name in ("achse_x.lis", "achse_y.lis", "achse_z.lis", "achse_c.lis"):
        (root / "listen" / name).unlink()
    run = zero_cli("limits", "--machine", "listen/hochlauf.lis", cwd=root)
    assert run.code == 2 and "no axis list of the machine could be read" in run.stderr, run


def test_x001_names_the_list_that_sets_the_soft_limits(tmp_path: Path) -> None:
    root = _machine(tmp_path)
    run = zero_cli("lint", "--machine", "listen/hochlauf.lis", "--output-format", "json", cwd=root)
    x001 = next(d for d in json.loads(run.stdout) if d["code"] == "X001")
    assert "(achse_vorgabe.lis:3,4)" in x001["message"]
    explain = zero_cli("explain", "kenngr.swe_pos", "--machine", "listen/hochlauf.lis", cwd=root)
    assert "achse_vorgabe.lis:4" in explain.stdout


def test_lint_machine_and_the_default_lint_use_one_machine(tmp_path: Path) -> None:
    """A program linted on its own (machine from [tool.zero.machine]) and named beside --machine
    gets the same findings."""
    root = _machine(tmp_path, '[machine]\nstartup = "listen/hochlauf.lis"\n')
    shutil.copy(FIXTURES / "programs" / "bad.nc", root / "part.nc")
    alone = zero_cli("lint", "part.nc", "--output-format", "json", cwd=root)
    beside = zero_cli("lint", "--machine", "listen/hochlauf.lis", "part.nc", "--output-format", "json", cwd=root)
    assert [d for d in json.loads(beside.stdout) if d["path"] == "part.nc"] == json.loads(alone.stdout)
    assert os.path.exists(root / "part.nc")


def test_convert_gives_each_input_its_own_catalogue(tmp_path: Path) -> None:
    broken = _machine(tmp_path, 'param-desc = "missing/CncParaDesc.xml"\n')
    (tmp_path / "other").mkdir()
    shutil.copy(broken / "listen" / "achse_x.lis", tmp_path / "other" / "x.lis")
    run = zero_cli("convert", "other/x.lis", "m/listen/achse_y.lis", "--out-dir", "out", cwd=tmp_path)
    assert run.code == 2 and "CncParaDesc.xml" in run.stderr, run
    alone = zero_cli("convert", "other/x.lis", "--out-dir", "out", cwd=tmp_path)
    assert alone.code == 0, alone

"""Defects found by trying zero as a demanding user would (a black-box review), each pinned."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli

SEED = FIXTURES / "seed" / "nullp_3achsen.lis"
pytestmark = pytest.mark.slow


def test_a_report_never_replaces_an_input_or_a_list(tmp_path: Path) -> None:
    lis = tmp_path / "a.lis"
    lis.write_bytes(SEED.read_bytes())
    assert zero_cli("lint", str(lis), "-o", str(lis)).code == 2
    assert lis.read_bytes() == SEED.read_bytes()
    other = tmp_path / "b.lis"
    other.write_bytes(b"x\n")
    assert zero_cli("lint", str(lis), "-o", str(other)).code == 2 and other.read_bytes() == b"x\n"
    report = tmp_path / "report.txt"
    assert zero_cli("lint", "--strict", str(lis), "-o", str(report)).code == 1
    assert zero_cli("lint", "--strict", str(lis), "-o", str(report)).code == 1  # a previous report is replaced
    assert "S004" in report.read_text()


def test_configuration_and_parameter_description_are_read_safely(tmp_path: Path) -> None:
    fifo = tmp_path / "c.toml"
    os.mkfifo(fifo)
    for args in (["lint", "--config", str(fifo), str(SEED)], ["--param-desc", str(fifo), "param", "P-AXIS-00001"],
                 ["lint", "--config", "/dev/zero", str(SEED)]):
        run = zero_cli(*args, timeout=10, memory_mib=512)
        assert run.code == 2 and "not a regular file" in run.stderr, (args, run)
    discovered = tmp_path / "proj"
    discovered.mkdir()
    os.mkfifo(discovered / "zero.toml")
    (discovered / "a.lis").write_bytes(SEED.read_bytes())
    run = zero_cli("lint", str(discovered / "a.lis"), timeout=10)
    assert run.code == 2 and "cannot read the configuration" in run.stderr


def test_add_noqa_writes_and_so_refuses_fix_and_diff(tmp_path: Path) -> None:
    lis = tmp_path / "a.lis"
    lis.write_bytes(SEED.read_bytes())
    for extra in ("--diff", "--fix"):
        assert zero_cli("lint", "--add-noqa", extra, str(lis)).code == 2
    assert lis.read_bytes() == SEED.read_bytes()


def test_a_start_up_list_cannot_make_zero_read_files_outside_the_machine(tmp_path: Path) -> None:
    machine = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine-layered", machine)
    secret = tmp_path / "secret.env"
    secret.write_text("AWS_KEY abcdef123\n")
    startup = machine / "listen" / "hochlauf.lis"
    startup.write_text(startup.read_text().replace("./listen/hand_mds.lis", f"{secret}"))
    for command in (["lint", "--machine"], ["show", "--machine"]):
        run = zero_cli(*command, str(startup))
        assert "abcdef123" not in run.stdout + run.stderr
    run = zero_cli("lint", "--machine", str(startup), "--output-format", "concise")
    assert "X012 info `hand_mds` names" in run.stdout and "is an absolute path on the controller" in run.stdout


def test_a_start_up_count_larger_than_the_named_lists(tmp_path: Path) -> None:
    machine = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine-clean", machine)
    startup = machine / "listen" / "hochlauf.lis"
    startup.write_text(startup.read_text().replace("zahl_mds                                              3",
                                                   "zahl_mds                                              5"))
    run = zero_cli("lint", "--machine", str(startup), "--output-format", "concise")
    assert "X005 error `zahl_mds` is 5, but the start-up list names no achs_mds[3], achs_mds[4] (working directory" \
        in run.stdout  # every X005 says where the controller looks


def test_walks_match_a_link_by_its_own_name(tmp_path: Path) -> None:
    (tmp_path / "data").write_bytes(SEED.read_bytes())
    (tmp_path / "m.lis").symlink_to(tmp_path / "data")
    (tmp_path / "x.lis").symlink_to(tmp_path / "nowhere")
    run = zero_cli("lint", "--output-format", "concise", str(tmp_path))
    assert run.code == 2
    assert "m.lis:19:20: S004" in run.stdout and "x.lis:1:1: F001" in run.stdout


def test_format_goes_on_past_an_unreadable_file_and_leaves_programs_alone(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(b"np_grp[1].achse[0].versch   100\nEnde\n")
    (tmp_path / "loop.lis").symlink_to(tmp_path / "loop.lis")
    shutil.copy(FIXTURES / "programs" / "good.nc", tmp_path / "good.nc")
    run = zero_cli("format", str(tmp_path))
    assert run.code == 2 and "loop.lis: symbolic link loop" in run.stderr and "good.nc" not in run.stderr
    assert (tmp_path / "a.lis").read_bytes() != b"np_grp[1].achse[0].versch   100\nEnde\n"
    assert (tmp_path / "good.nc").read_bytes() == (FIXTURES / "programs" / "good.nc").read_bytes()


def test_an_index_with_a_leading_zero_is_the_same_element(tmp_path: Path) -> None:
    lis = tmp_path / "i.lis"
    lis.write_bytes(b"np_grp[01].achse[0].versch 5\nnp_grp[1].achse[0].versch 6\n")
    assert "R007" in zero_cli("lint", "--output-format", "concise", str(lis)).stdout


def test_flags_compare_as_sets_in_diff(tmp_path: Path) -> None:
    (tmp_path / "a.lis").write_bytes(b"error_protocol_mode REPORT|PRINT\n")
    (tmp_path / "b.lis").write_bytes(b"error_protocol_mode PRINT | REPORT\n")
    assert zero_cli("diff", "--kind", "startup", str(tmp_path / "a.lis"), str(tmp_path / "b.lis")).code == 0


def test_add_noqa_after_a_string_value_and_into_an_existing_noqa(tmp_path: Path) -> None:
    lis = tmp_path / "a.lis"
    lis.write_bytes(b"kenngr.swe_check 0 # noqa: M006\nkopf.log_achs_name X_Achse words\n")
    zero_cli("lint", "--kind", "axis", "--add-noqa", str(lis))
    assert lis.read_bytes() == (b"kenngr.swe_check 0 # noqa: M005, M006\n"
                                b"kopf.log_achs_name X_Achse words  ( noqa: S006 -- baseline\n")


def test_a_bad_size_limit_is_one_usage_error(tmp_path: Path) -> None:
    run = zero_cli("lint", str(SEED), str(FIXTURES / "diff" / "base.lis"), env={"ZERO_MAX_FILE_SIZE": "0"})
    assert run.code == 2 and run.stderr.count("is not a size") == 1 and run.stdout == ""


def test_show_and_diff_refuse_a_file_that_is_not_text(tmp_path: Path) -> None:
    binary = tmp_path / "b.lis"
    binary.write_bytes(bytes(range(256)) * 8)
    for command in (["show", str(binary)], ["diff", str(binary), str(SEED)]):
        run = zero_cli(*command)
        assert run.code == 2 and "not a text file" in run.stderr, command


def test_param_says_when_an_index_is_outside_its_array() -> None:
    run = zero_cli("param", "np_grp[97].achse[0].versch")
    assert run.code == 0 and "(index 97 is outside 0..96: no such element, R003)" in run.stdout

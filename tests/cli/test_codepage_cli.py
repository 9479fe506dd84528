"""`encoding` in the configuration on the real command line: a list written on a DOS tool (CP850)
is linted, fixed, formatted, converted, shown and read by its machine as the text it is, and
written back in its own bytes (issue 24)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli

# A list in CP850: umlauts in comments and (0x84 ä, 0x81 ü) in a string value.
OLD = (b"# Achsparameter f\x81r die alte Fr\x8ese (CP850)\n"
       b"kenngr.swe_pos   15000000    # Endschalter f\x81r X\n"
       b"kenngr.swe_neg   -15000000   ( negativer Endschalter, Gr\x94\xe1e\n"
       b"lr_hw[0].cntr_hw_id_string  Z\x84hler_\x81\n"
       b"Ende\n")
CONFIG = '[tool.zero]\nencoding = {"machines/old/**/*.lis" = "cp850"}\n'


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "zero.toml").write_text(CONFIG)
    for sub in ("machines/old/x", "machines/new"):
        (tmp_path / sub).mkdir(parents=True)
    (tmp_path / "machines/old/x/achse.lis").write_bytes(OLD)
    (tmp_path / "machines/new/achse.lis").write_bytes(OLD)  # the same bytes, not declared
    return tmp_path


def test_lint_reads_the_declared_code_page(project: Path) -> None:
    run = zero_cli("lint", "machines", cwd=project)
    old, new = "machines/old/x/achse.lis", "machines/new/achse.lis"
    assert run.code == 0, run
    assert old not in run.stdout  # declared: `Zähler_ü` is text, the comments are letters
    # not declared: read as Latin-1; the umlauts of the comments are no findings, those of the value are
    assert [line.split(" warning")[0] for line in run.stdout.splitlines() if "S010" in line] == [
        f"{new}:4:30: S010", f"{new}:4:36: S010"]
    named = zero_cli("lint", old, cwd=project)
    assert named.code == 0 and "S010" not in named.stdout
    piped = zero_cli("lint", "-", "--stdin-filename", old, cwd=project, stdin=OLD)
    assert piped.code == 0 and "S010" not in piped.stdout
    piped = zero_cli("lint", "-", "--stdin-filename", "machines/new/achse.lis", cwd=project, stdin=OLD)
    assert piped.stdout.count("S010") == 2


def test_format_keeps_the_code_page(project: Path) -> None:
    old = project / "machines/old/x/achse.lis"
    check = zero_cli("format", "--check", str(old), cwd=project)
    assert check.code == 1 and "would reformat" in check.stdout
    diff = zero_cli("format", "--diff", str(old), cwd=project)
    assert b"+kenngr.swe_pos" in diff.out and b"f\x81r X" in diff.out  # the patch is in the file's bytes
    assert zero_cli("format", str(old), cwd=project).code == 0
    text = old.read_bytes().decode("cp850")
    assert text.splitlines()[0] == "# Achsparameter für die alte FrÄse (CP850)"
    assert "# Endschalter für X" in text and "Größe" in text and "Zähler_ü" in text
    assert old.read_bytes() == text.encode("cp850")
    assert zero_cli("format", "--check", str(old), cwd=project).code == 0
    undeclared = zero_cli("format", "--check", "machines/new/achse.lis", cwd=project)
    assert undeclared.code == 1 and "byte 0x81 reads as control character U+0081 in latin-1" in undeclared.stderr
    assert 'encoding = {"old/**/*.lis" = "cp850"}' in undeclared.stderr


def test_fix_keeps_the_code_page(project: Path) -> None:
    old = project / "machines/old/x/achse.lis"
    old.write_bytes(b"#Gr\x94\xe1e der Achse\n" + OLD)  # S005: `#` glued to the comment
    run = zero_cli("lint", "--fix", str(old), cwd=project)
    assert run.code == 0 and "1 fix applied" in run.stderr
    assert old.read_bytes() == b"# Gr\x94\xe1e der Achse\n" + OLD


@pytest.mark.parametrize("fmt", ["yaml", "toml", "json"])
def test_convert_round_trip_is_byte_identical(project: Path, fmt: str) -> None:
    old = "machines/old/x/achse.lis"
    there = zero_cli("convert", old, "-o", f"achse.{fmt}", cwd=project)
    assert there.code == 0, there
    text = (project / f"achse.{fmt}").read_text(encoding="utf-8")
    assert "für X" in text and "Größe" in text and "Zähler_ü" in text and "cp850" in text
    back = zero_cli("convert", f"achse.{fmt}", "-o", "back.lis", cwd=project)
    assert back.code == 0, back
    assert (project / "back.lis").read_bytes() == OLD
    undeclared = zero_cli("convert", "machines/new/achse.lis", "--to", fmt, cwd=project)
    assert undeclared.code == 1 and "in latin-1: YAML, TOML and JSON text cannot carry it" in undeclared.stderr


def test_show_and_diff_read_the_declared_code_page(project: Path) -> None:
    old = "machines/old/x/achse.lis"
    show = zero_cli("show", old, cwd=project)
    assert show.code == 0 and "lr_hw[0].cntr_hw_id_string = Zähler_ü" in show.stdout
    assert zero_cli("convert", old, "-o", "achse.yaml", cwd=project).code == 0
    assert zero_cli("diff", "--strict", old, "achse.yaml", cwd=project).code == 0  # equal


def test_the_machine_reads_its_lists_in_the_declared_code_page(tmp_path: Path) -> None:
    root = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine-clean", root)
    axis = root / "listen" / "achse_x.lis"
    axis.write_bytes(axis.read_bytes().replace(b"Ende\n", b"lr_hw[0].cntr_hw_id_string  Z\x84hler_\x81\nEnde\n")
                     .replace(b"# axis list X_Achse", b"# Achsparameter f\x81r X"))
    before = zero_cli("lint", "--machine", "listen/hochlauf.lis", cwd=root)
    assert before.stdout.count("S010") == 2  # the value read as Latin-1; not the comment
    (root / "zero.toml").write_text('[tool.zero.encoding]\n"listen/achse_*.lis" = "cp850"\n')
    after = zero_cli("lint", "--machine", "listen/hochlauf.lis", cwd=root)
    assert after.code == 0 and after.stdout == "", after
    shown = zero_cli("show", "--machine", "listen/hochlauf.lis", "lr_hw[0].cntr_hw_id_string", cwd=root)
    assert "lr_hw[0].cntr_hw_id_string = Zähler_ü  P-AXIS-00042  listen/achse_x.lis:7" in shown.stdout


@pytest.mark.parametrize(("value", "words"), [
    ('"klingon"', "tool.zero.encoding.machines/**: 'klingon' is not a codec Python knows"),
    ('"utf-16"', "'utf-16' cannot hold a parameter list"),
    ('"utf-32-le"', "'utf-32-le' cannot hold a parameter list"),
    ("850", "850 is not the name of a codec"),
])
def test_a_codec_zero_cannot_read_is_a_located_configuration_error(tmp_path: Path, value: str, words: str) -> None:
    (tmp_path / "zero.toml").write_text(f'[tool.zero]\nselect = ["S"]\n[tool.zero.encoding]\n"machines/**" = {value}\n')
    (tmp_path / "a.lis").write_bytes(OLD)
    run = zero_cli("lint", "a.lis", cwd=tmp_path)
    assert run.code == 2 and words in run.stderr, run
    assert f"{tmp_path / 'zero.toml'}:4:" in run.stderr


def test_encoding_must_be_a_table(tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('encoding = "cp850"\n')
    (tmp_path / "a.lis").write_bytes(OLD)
    run = zero_cli("lint", "a.lis", cwd=tmp_path)
    assert run.code == 2 and "zero.toml:1:" in run.stderr and "expected a table of glob = codec" in run.stderr


def test_config_show_names_the_declared_code_pages(project: Path) -> None:
    run = zero_cli("config", "--show", "machines/old/x/achse.lis", cwd=project)
    assert run.code == 0 and '[encoding]\n"machines/old/**/*.lis" = "cp850"\n' in run.stdout


def test_lint_of_the_structured_form_of_a_declared_list(project: Path) -> None:
    assert zero_cli("convert", "machines/old/x/achse.lis", "-o", "achse.yaml", cwd=project).code == 0
    run = zero_cli("lint", "achse.yaml", cwd=project)
    assert run.code == 0, run

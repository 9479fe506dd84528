"""Every form through the command line: XML lists, update files, TwinCAT exports, Windows paths."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES
from zero.catalog.registry import Registry
from zero.diff import DiffOptions, diff_sides, read_side
from zero.engine.convert import convert
from zero.forms import format_of

pytestmark = pytest.mark.slow
ZERO = [sys.executable, "-m", "zero"]
TWINCAT = FIXTURES / "twincat"


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*ZERO, *args], capture_output=True, text=True, cwd=cwd, timeout=120, check=False)


def concise(*args: str, cwd: Path | None = None) -> list[str]:
    r = run("lint", "--isolated", "--output-format", "concise", *args, cwd=cwd)
    return [line.split(" ", 2)[0] + " " + line.split(" ", 2)[1] for line in r.stdout.splitlines() if line]


# ------------------------------------------------------------------------------- XML lists


def test_every_corpus_xml_list_converts_to_every_form_and_back_byte_for_byte(corpus: Path, registry: Registry) -> None:
    for path in sorted((corpus / "isg-sdk" / "xml").rglob("*.xml")):
        data = path.read_bytes()
        for fmt in ("lis", "yaml", "toml", "json"):
            there = convert(data, "xml", fmt, registry, str(path), check=False).output
            back = convert(there, fmt, "xml", registry, f"x.{fmt}", check=False).output
            assert back == data, (path.name, fmt)


def test_every_corpus_list_converted_to_xml_and_back_is_equal_strictly(corpus: Path, registry: Registry) -> None:
    for path in sorted((corpus / "isg-sdk" / "listen").rglob("*.lis")):
        data = path.read_bytes()
        xml = convert(data, "lis", "xml", registry, str(path), check=False).output
        back = convert(xml, "xml", "lis", registry, "x.xml", check=False).output
        a = read_side(data, "lis", str(path), registry)
        b = read_side(back, "lis", "back.lis", registry, a.kind)
        changes = diff_sides(a, b, registry, DiffOptions(strict=True))
        assert changes == [], (path.name, changes[:3])


def test_convert_cli_xml_to_list_and_back(corpus: Path, tmp_path: Path) -> None:
    src = corpus / "isg-sdk" / "xml" / "templates" / "zero_offset_1.xml"
    assert run("convert", str(src), "-o", str(tmp_path / "z.lis")).returncode == 0
    text = (tmp_path / "z.lis").read_text(encoding="utf-8-sig")
    assert "# <ZeroOffset>" in text and "np_grp[1].achse[0].versch" in text and text.rstrip().endswith("Ende")
    assert run("convert", str(tmp_path / "z.lis"), "-o", str(tmp_path / "z.xml")).returncode == 0
    assert (tmp_path / "z.xml").read_bytes() == src.read_bytes()
    assert format_of("a.XML") == "xml"


def test_a_new_xml_list_from_an_ascii_list_reads_back_with_its_annotations(corpus: Path, tmp_path: Path) -> None:
    src = corpus / "isg-sdk" / "listen" / "nullp_d1.lis"
    assert run("convert", str(src), "--to", "xml", "-o", str(tmp_path / "n.xml")).returncode == 0
    xml = (tmp_path / "n.xml").read_text()
    assert xml.startswith('<?xml version="1.0" encoding="utf-8"?>\n<ZeroOffset>\n  <Version Label="1">')
    assert '<P-ZERO-00003.1.0 Value="' in xml and "<!-- ( P-ZERO-00003" in xml
    assert run("diff", "--strict", str(src), str(tmp_path / "n.xml")).returncode == 0
    assert concise(str(tmp_path / "n.xml")) == concise(str(src)) == []


# ------------------------------------------------------------------------------- hostile XML


@pytest.mark.parametrize("name", ["billion_laughs.xml", "external_entity.xml", "dtd_only.xml", "malformed.xml",
                                  "unclosed_cdata.xml"])
def test_hostile_xml_exits_1_with_one_located_finding(name: str) -> None:
    r = run("lint", "--isolated", "--output-format", "json", str(FIXTURES / "xml" / "hostile" / name))
    assert r.returncode == 1, r.stderr
    [d] = json.loads(r.stdout)
    assert d["code"] == "S014" and d["line"] > 1
    assert "Traceback" not in r.stderr


def test_hostile_xml_golden_positions() -> None:
    got = {name: concise(str(FIXTURES / "xml" / "hostile" / name)) for name in
           ("billion_laughs.xml", "external_entity.xml", "malformed.xml", "unclosed_cdata.xml")}
    assert got == {
        "billion_laughs.xml": [f"{FIXTURES}/xml/hostile/billion_laughs.xml:2:1: S014"],
        "external_entity.xml": [f"{FIXTURES}/xml/hostile/external_entity.xml:2:1: S014"],
        "malformed.xml": [f"{FIXTURES}/xml/hostile/malformed.xml:11:5: S014"],
        "unclosed_cdata.xml": [f"{FIXTURES}/xml/hostile/unclosed_cdata.xml:14:10: S014"],
    }


def test_a_100_mb_attribute_is_refused_without_reading_it_whole(tmp_path: Path) -> None:
    huge = tmp_path / "huge.xml"
    subprocess.run([sys.executable, str(FIXTURES / "xml" / "hostile" / "make_huge.py"), str(huge)], check=True)
    r = run("lint", "--isolated", "--output-format", "json", str(huge))
    assert r.returncode == 2, r.stderr  # an input zero refuses to read (F001): exit 2
    [d] = json.loads(r.stdout)
    assert d["code"] == "F001" and "is longer than" in d["message"]


# ------------------------------------------------------------------------------- TwinCAT exports


def test_twincat_exports_lint_at_their_xml_positions() -> None:
    assert concise(str(TWINCAT / "axis_x.xml")) == [f"{TWINCAT}/axis_x.xml:28:8: S004",
                                                    f"{TWINCAT}/axis_x.xml:30:1: R001"]
    assert concise(str(TWINCAT / "channel_1.xml")) == [f"{TWINCAT}/channel_1.xml:40:55: R004"]
    assert concise(str(TWINCAT / "cnc_task.xml")) == []


def test_fix_rewrites_inside_the_cdata_only(tmp_path: Path) -> None:
    target = tmp_path / "axis_x.xml"
    shutil.copy(TWINCAT / "axis_x.xml", target)
    r = run("lint", "--isolated", "--fix", str(target))
    assert r.returncode == 1  # the unknown key is left
    before, after = (TWINCAT / "axis_x.xml").read_bytes().split(b"\n"), target.read_bytes().split(b"\n")
    assert [i + 1 for i, (a, b) in enumerate(zip(before, after, strict=True)) if a != b] == [28]
    assert after[27].startswith(b"kenngr.swe_pos ")


def test_convert_extracts_each_list_and_puts_one_back(tmp_path: Path) -> None:
    assert run("convert", str(TWINCAT / "channel_1.xml"), "--out-dir", str(tmp_path / "out")).returncode == 0
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [
        "channel_1.NullpD.lis", "channel_1.PzvD.lis", "channel_1.SdaMds.lis", "channel_1.VeD.lis",
        "channel_1.WerkzD.lis"]
    r = run("convert", str(TWINCAT / "channel_1.xml"), "-o", str(tmp_path / "x.lis"))
    assert r.returncode == 1 and "--item ELEMENT" in r.stderr and "channel_1.xml#SdaMds" in r.stderr
    zero_offsets = tmp_path / "n.lis"
    assert run("convert", str(TWINCAT / "channel_1.xml"), "--item", "NullpD", "-o", str(zero_offsets)).returncode == 0
    zero_offsets.write_text(zero_offsets.read_text().replace(" 1.5", " 15 "))
    export = tmp_path / "channel_1.xml"
    shutil.copy(TWINCAT / "channel_1.xml", export)
    assert run("convert", str(zero_offsets), "--into", str(export), "--item", "NullpD").returncode == 0
    old, new = (TWINCAT / "channel_1.xml").read_bytes(), export.read_bytes()
    assert new.replace(b" 15 ", b" 1.5") == old
    assert concise(str(export)) == []


def test_format_lays_out_the_embedded_lists_only(tmp_path: Path) -> None:
    export = tmp_path / "channel_1.xml"
    shutil.copy(TWINCAT / "channel_1.xml", export)
    assert run("format", str(export)).returncode == 0
    changed = [(a, b) for a, b in zip((TWINCAT / "channel_1.xml").read_text().splitlines(),
                                      export.read_text().splitlines(), strict=True) if a != b]
    assert changed and all(not a.lstrip().startswith("<") for a, _ in changed)
    assert run("format", "--check", str(export)).returncode == 0


# ------------------------------------------------------------------------------- machines


def test_startup_xml_with_the_templates_builds_a_machine(corpus: Path, tmp_path: Path) -> None:
    for f in (corpus / "isg-sdk" / "xml" / "templates").glob("*.xml"):
        shutil.copy(f, tmp_path / f.name)
    (tmp_path / "zero.toml").write_text('[machine]\nstartup = "startup.xml"\n'
                                        'roots = {"CncKernelRootDir/config" = "."}\n')
    r = run("show", "--machine", "startup.xml", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "# machine startup.xml: working directory ., 12 of 16 named lists read" in r.stdout
    assert "CncKernelRootDir/config/ax_mds_2.xml: missing: does not exist" in r.stdout
    codes = {line.split(" ")[1] for line in run("lint", "--machine", "startup.xml", "--output-format", "concise",
                                                 cwd=tmp_path).stdout.splitlines()}
    assert "X005" in codes and "X007" not in codes  # the missing axis lists, said once each


def test_a_twincat_startup_list_with_windows_paths(tmp_path: Path) -> None:
    """`.\\sda_mds1.lis`, `..\\listen\\nullp_d1.lis` (inside the project) and a drive-letter path mapped by
    `roots`: every list read, each resolved path shown."""
    shutil.copytree(TWINCAT / "machine", tmp_path / "machine")
    root = tmp_path / "machine"
    (root / ".git").mkdir()
    r = run("show", "--machine", "startup/hochlauf.lis", cwd=root)
    head = [line for line in r.stdout.splitlines() if line.startswith("#")]
    assert head[0] == "# machine startup/hochlauf.lis: working directory startup, 7 of 8 named lists read", head
    assert "C:\\TwinCAT\\3.1\\Components\\Mc\\CNC\\Config\\werkz_d1.lis: not-checked" in head[1], head
    (root / "zero.toml").write_text('[machine]\nstartup = "startup/hochlauf.lis"\n'
                                    'roots = {"C:/TwinCAT/3.1/Components/Mc/CNC" = "."}\n')
    r = run("show", "--machine", "startup/hochlauf.lis", "--output-format", "json", cwd=root)
    lists = {x["key"]: (x["status"], x["resolved"]) for x in json.loads(r.stdout)["lists"]}
    assert lists["werkz_data[0]"] == ("loaded", str(root / "Config" / "werkz_d1.lis")), lists
    assert lists["nullp_data[0]"] == ("loaded", "listen/nullp_d1.lis"), lists
    assert lists["sda_mds[0]"] == ("loaded", "startup/sda_mds1.lis"), lists
    assert run("lint", "--machine", "startup/hochlauf.lis", cwd=root).returncode == 0


# ------------------------------------------------------------------------------- updates


def test_an_update_shows_what_it_changes_and_its_revert_what_it_leaves(corpus: Path) -> None:
    lists = corpus / "isg-sdk"
    update = lists / "xml" / "Update" / "achsmds1-Update.xml"
    revert = lists / "xml" / "Update" / "achsmds1-Revert.xml"
    r = run("diff", str(lists / "listen" / "achsmds1.lis"), str(update))
    assert r.returncode == 1 and "kopf.log_achs_name  P-AXIS-00297  X_Achse → Name-Changed" in r.stdout
    assert "1 changed, 0 added, 0 removed" in r.stdout
    assert run("diff", str(lists / "listen" / "achsmds1.lis"), str(update), "--revert", str(revert)).returncode == 0
    r = run("diff", str(lists / "xml" / "templates" / "ax_mds_1.xml"), str(update), "--revert", str(revert))
    assert r.returncode == 1 and "A1 → X_Achse" in r.stdout  # the revert writes the ASCII list's name back


def test_a_revert_that_misses_a_parameter(corpus: Path) -> None:
    base = corpus / "isg-sdk" / "listen" / "achsmds1.lis"
    r = run("diff", "--output-format", "json", str(base), str(FIXTURES / "xml" / "Update" / "axis-Update.xml"),
            "--revert", str(FIXTURES / "xml" / "Update" / "axis-Revert.xml"))
    assert r.returncode == 1
    assert [(c["key"], c["id"]) for c in json.loads(r.stdout)] == [("kenngr.max_vb_override", "P-AXIS-00109")]


def test_update_files_are_checked_as_updates() -> None:
    assert concise(str(FIXTURES / "xml" / "Update")) == [
        f"{FIXTURES}/xml/Update/no_axis-Update.xml:5:6: U002"]


def test_a_folder_walk_lints_xml_lists_and_skips_other_xml(tmp_path: Path) -> None:
    shutil.copy(FIXTURES / "xml" / "lists" / "zero_offset_faults.xml", tmp_path / "nullp.xml")
    (tmp_path / "pom.xml").write_text('<?xml version="1.0"?>\n<project><name>x</name></project>\n')
    (tmp_path / "plc.tmc").write_text("<TcModuleClass/>\n")
    found = concise(str(tmp_path))
    assert [f.split(":")[0] for f in found] == [str(tmp_path / "nullp.xml")] * 3
    r = run("lint", "--isolated", str(tmp_path / "pom.xml"))
    assert r.returncode == 1 and "S014" in r.stdout and "root element `<project>`" in r.stdout


def test_an_update_checked_against_its_machine(tmp_path: Path) -> None:
    """`zero lint --machine STARTUP UPDATE...`: U003 for an axis the machine lacks; the update's values
    among the target list's other values (a soft limit below the list's negative one: M001)."""
    shutil.copytree(TWINCAT / "machine", tmp_path / "machine")
    root = tmp_path / "machine"
    (root / ".git").mkdir()
    updates = root / "Update"
    updates.mkdir()
    (updates / "bad_axis-Update.xml").write_text('<?xml version="1.0" encoding="utf-8"?>\n<AX_MDS>\n'
                                                 '    <P-AXIS-00016 Value="7" />\n'
                                                 '    <P-AXIS-00297 Value="X9" />\n</AX_MDS>\n')
    (updates / "limit-Update.xml").write_text('<?xml version="1.0" encoding="utf-8"?>\n<AX_MDS>\n'
                                              '    <P-AXIS-00016 Value="1" />\n'
                                              '    <P-AXIS-00178 Value="-99000000" />\n</AX_MDS>\n')
    r = run("lint", "--machine", "startup/hochlauf.lis", "Update", "--output-format", "concise", cwd=root)
    assert r.returncode == 1
    found = [line.split(" ", 2)[:2] for line in r.stdout.splitlines() if line.startswith("Update")]
    assert found == [["Update/bad_axis-Update.xml:3:26:", "U003"], ["Update/limit-Update.xml:4:26:", "M001"]], r.stdout
    assert "with the update applied to startup/achsmds1.lis" in r.stdout
    assert run("lint", "Update", "--output-format", "concise", cwd=root).stdout == ""  # alone: nothing to say


def test_a_folder_of_twincat_exports_assembles_a_machine(tmp_path: Path) -> None:
    """The CNC task's export names its lists as TwinCAT writes them (`.\\achsmds1.lis`); where no such
    file lies beside it, the channel's and the axes' exports in the folder hold them."""
    for f in TWINCAT.glob("*.xml"):
        shutil.copy(f, tmp_path / f.name)
    (tmp_path / ".git").mkdir()
    r = run("show", "--machine", "cnc_task.xml", "--output-format", "json", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    lists = {x["key"]: (x["status"], x["resolved"], x["line"]) for x in json.loads(r.stdout)["lists"]}
    assert lists["achs_mds[0]"] == ("loaded", "axis_x.xml#AchsMds", 29), lists
    assert lists["nullp_data[0]"][:2] == ("loaded", "channel_1.xml#NullpD"), lists
    assert lists["sda_mds[0]"][:2] == ("loaded", "channel_1.xml#SdaMds"), lists
    assert lists["achs_mds[1]"][0] == "missing"  # one axis export in the folder for three axis lists
    found = [line.split(" ", 2)[:2] for line in run("lint", "--machine", "cnc_task.xml", "--output-format",
                                                    "concise", cwd=tmp_path).stdout.splitlines()]
    assert found == [["cnc_task.xml:30:1:", "X005"], ["cnc_task.xml:31:1:", "X005"], ["axis_x.xml:28:8:", "S004"],
                     ["axis_x.xml:30:1:", "R001"], ["channel_1.xml:40:55:", "R004"]], found

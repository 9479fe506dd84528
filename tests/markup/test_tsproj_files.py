"""TwinCAT projects (`.tsproj`) and independent project files (`.xti`) as files that hold lists, and the
TwinCAT exports' `<Default>` element, exports without declaration or line breaks, exports that hold no list."""

from __future__ import annotations

import os
import re
import time
from pathlib import Path

import pytest

from conftest import FIXTURES
from twincat_projects import big_project
from zero.catalog.registry import Registry
from zero.engine.convert import source_format, write_into, xml_source
from zero.engine.discovery import collect_files
from zero.engine.lint import LintResult, Totals, lint_bytes, lint_data
from zero.errors import ZeroError
from zero.forms import is_project, split_part, xml_form
from zero.markup.documents import embedded_documents, pick, read_xml
from zero.markup.tsproj import REFERENCE_KINDS, read_project

TWINCAT = FIXTURES / "twincat"
PROJECT = TWINCAT / "project" / "Maschine.tsproj"
SPLIT = TWINCAT / "split"


def test_a_project_is_a_twincat_form_and_its_lists_have_addresses() -> None:
    data = PROJECT.read_bytes()
    assert xml_form(data) == "twincat" and is_project(PROJECT) and is_project(f"{PROJECT}#X_Achse/AchsMds")
    assert split_part("a/X.tsproj#Kanal_1/SdaMds") == ("a/X.tsproj", "Kanal_1/SdaMds")
    assert split_part("a/b#c.lis") == ("a/b#c.lis", None)
    _, lists = embedded_documents(data, str(PROJECT))
    assert [(x.element, x.kind, x.offset) for x in lists] == [
        ("CNC/Startup", "STUP", None),
        ("Kanal_1/SdaMds", "CHAN", 1), ("Kanal_1/NullpD", "ZERO", 2), ("Kanal_1/WerkzD", "TOOL", 3),
        ("Kanal_2/SdaMds", "CHAN", 4), ("Kanal_2/NullpD", "ZERO", 5), ("Kanal_2/WerkzD", "TOOL", 6),
        ("X_Achse/AchsMds", "AXIS", 11), ("Y_Achse/AchsMds", "AXIS", 12), ("Z_Achse/AchsMds", "AXIS", 13),
        ("C_Spindel/AchsMds", "AXIS", 14)]


def test_a_finding_in_a_project_is_the_finding_in_the_extracted_list_at_the_projects_line(registry: Registry) -> None:
    """Before: one S014 error (`<TcSmProject>` is not a list) and nothing checked."""
    data = PROJECT.read_bytes()
    result = lint_data(data, str(PROJECT), registry)
    alone = lint_bytes((TWINCAT / "project" / "achsmds2.lis").read_bytes(), registry, "achsmds2.lis")
    assert [d.code for d in result.diagnostics] == [d.code for d in alone.diagnostics] == ["R001"]
    got, want = result.diagnostics[0], alone.diagnostics[0]
    _, lists = embedded_documents(data, str(PROJECT))
    y = pick(lists, "Y_Achse/AchsMds", str(PROJECT))
    first = data[:data.index(b"# Axis list Y_Achse")].count(b"\n") + 1  # the project line of list line 1
    assert (got.span.line, got.span.column) == (first + want.span.line - 1, want.span.column) == (112, 1)
    assert got.message == want.message
    assert y.doc.lines[want.span.line - 1] == data.decode().split("\n")[got.span.line - 1]


def test_lists_are_addressed_by_item_offset_name(registry: Registry) -> None:
    data = PROJECT.read_bytes()
    _, lists = embedded_documents(data, str(PROJECT))
    assert pick(lists, "y_achse/achsmds", "p").offset == 12
    assert pick(lists, "tc_virtual_12", "p").element == "Y_Achse/AchsMds"
    assert pick(lists, "Y_Achse", "p").element == "Y_Achse/AchsMds"  # the tree item, one list
    assert pick(lists, "Startup", "p").kind == "STUP"
    with pytest.raises(ZeroError, match="holds no list `Achse_99`"):
        pick(lists, "Achse_99", "p")
    with pytest.raises(ZeroError, match="2 lists named `SdaMds`"):
        pick(lists, "SdaMds", "p")
    # read as one list without an address: its start-up list; with one: that list
    assert read_xml(data, str(PROJECT), registry).origin.kind == "STUP"  # type: ignore[union-attr]
    assert read_xml(data, f"{PROJECT}#Kanal_2/SdaMds", registry).lines[0].startswith("# Channel list of channel 2")
    assert source_format(None, f"{PROJECT}#Kanal_2/SdaMds") == "xml"
    text, _, kind = xml_source(data, str(PROJECT), registry, "X_Achse/AchsMds")
    assert kind == "AXIS" and text.startswith(b"# Axis list X_Achse")


def test_convert_into_a_project_changes_only_that_cdata(tmp_path: Path, registry: Registry) -> None:
    project = tmp_path / "M.tsproj"
    project.write_bytes(PROJECT.read_bytes())
    fixed = (TWINCAT / "project" / "achsmds2.lis").read_text().replace("max_vb_overide", "max_vb_override")
    lis = tmp_path / "y.lis"
    lis.write_text(fixed)
    old = project.read_bytes()
    new = write_into(str(lis), project, "Y_Achse/AchsMds", registry, lambda: b"")
    assert project.read_bytes() == new
    a, b = old.index(b"# Axis list Y_Achse"), old.index(b"]]>", old.index(b"# Axis list Y_Achse"))
    assert new == old[:a] + fixed.encode() + old[b:]
    assert lint_data(new, str(project), registry).diagnostics == []


def test_independent_project_files_hold_items(registry: Registry) -> None:
    xti = SPLIT / "_Config" / "CNC" / "Z_Achse.xti"
    _, lists = embedded_documents(xti.read_bytes(), str(xti))
    assert [(x.element, x.kind, x.offset) for x in lists] == [("Z_Achse/AchsMds", "AXIS", 13)]
    assert [(d.code, d.span.line) for d in lint_data(xti.read_bytes(), str(xti), registry).diagnostics] == [
        ("R001", 14)]
    assert read_project((SPLIT / "Split.tsproj").read_bytes(), "s").files[0][1] == "Kanal_1.xti"
    walked = {os.path.basename(p) for p in collect_files([SPLIT])}
    assert walked == {"Split.tsproj", "Kanal_1.xti", "Y_Achse.xti", "Z_Achse.xti"}


def test_the_reference_kinds_are_the_machines() -> None:
    from zero.machine.model import REFERENCES

    assert {r.key.removesuffix("[]"): r.kind for r in REFERENCES} == REFERENCE_KINDS


def _lint(path: Path, registry: Registry) -> LintResult:
    return lint_data(path.read_bytes(), str(path), registry)


def test_the_default_axis_list_of_an_axis_group_export_is_checked(registry: Registry) -> None:
    """Before: "1 file checked (1 clean)" while its CDATA holds a fault; show/convert refused it."""
    result = _lint(TWINCAT / "ai" / "axis_group.xml", registry)
    assert [(d.code, d.span.line, d.span.column) for d in result.diagnostics] == [("R001", 5, 1)]
    _, lists = embedded_documents((TWINCAT / "ai" / "axis_group.xml").read_bytes(), "g")
    assert lists[0].element == "Default" and lists[0].doc.origin.default_list  # type: ignore[union-attr]


def test_an_automation_interface_export_without_declaration_or_line_breaks(registry: Registry) -> None:
    path = TWINCAT / "ai" / "axis_ai.xml"
    data = path.read_bytes()
    assert b"\n<" not in data and not data.startswith(b"<?xml")
    result = _lint(path, registry)
    column = data.decode().split("\n")[7].index("kenngr.max_vb_overide") + 1
    assert [(d.code, d.span.line, d.span.column) for d in result.diagnostics] == [("R001", 8, column)]
    assert "axis_ai.xml" in {os.path.basename(p) for p in collect_files([TWINCAT])}


def test_a_form_zero_does_not_know_never_counts_as_checked_clean(registry: Registry) -> None:
    """Before: an export holding no list zero knows was "1 file checked (1 clean)"."""
    result = _lint(TWINCAT / "ai" / "no_list.xml", registry)
    assert result.diagnostics == [] and result.note is not None and "skipped" in result.note
    totals = Totals()
    totals.add(result)
    assert (totals.files, totals.clean) == (0, 0)
    plc = b'<?xml version="1.0"?>\n<TcSmProject><Project><Plc><Project Name="P"/></Plc></Project></TcSmProject>\n'
    assert lint_data(plc, "plc.tsproj", registry).note is not None


def test_hostile_projects_are_located_findings(registry: Registry) -> None:
    bomb = (b'<?xml version="1.0"?>\n<!DOCTYPE p [<!ENTITY a "aaaaaaaa">]>\n<TcSmProject>&a;</TcSmProject>\n')
    result = lint_data(bomb, "b.tsproj", registry)
    assert [(d.code, d.span.line) for d in result.diagnostics] == [("S014", 2)]
    cut = PROJECT.read_bytes()[:5000]
    assert [d.code for d in lint_data(cut, "c.tsproj", registry).diagnostics] == ["S014"]


def test_a_50_mb_project(tmp_path: Path, registry: Registry) -> None:
    path = tmp_path / "Big.tsproj"
    shift = big_project(path)
    assert path.stat().st_size >= 50 * 1024 * 1024
    data = path.read_bytes()
    started = time.perf_counter()
    result = lint_data(data, str(path), registry)
    took = time.perf_counter() - started
    assert [(d.code, d.span.line, d.span.column) for d in result.diagnostics] == [("R001", 112 + shift, 1)]
    assert took < 120, f"{took:.1f} s"
    _, lists = embedded_documents(data, str(path))
    assert len(lists) == 11 and not any(re.search("Term", x.element) for x in lists)


def test_format_and_out_dir_of_a_project(tmp_path: Path, registry: Registry) -> None:
    from zero.engine.convert import output_path
    from zero.engine.formatting import format_bytes

    data = PROJECT.read_bytes()
    assert format_bytes(data, str(PROJECT), registry) == data  # nothing to do: every byte kept
    crooked = data.replace(b"kenngr.swe_pos                                        12000000",
                           b"kenngr.swe_pos  12000000", 1)
    assert crooked != data and format_bytes(crooked, "M.tsproj", registry) == data  # only inside that CDATA
    assert output_path(PROJECT, "lis", tmp_path, "Kanal_1/SdaMds").name == "Maschine.Kanal_1.SdaMds.lis"


def test_an_axis_export_says_its_drive_type_spindle_and_feed_axis() -> None:
    _, lists = embedded_documents((TWINCAT / "ai" / "axis_ai.xml").read_bytes(), "a")
    assert (lists[0].item, lists[0].properties) == ("Achse_11", {"DriveType": "4", "Spindle": "0", "FeedAxis": "1"})


def test_fix_in_a_project_changes_only_inside_the_cdata(registry: Registry) -> None:
    from zero.engine.fixes import fix_bytes

    data = PROJECT.read_bytes()
    broken = data.replace(b"kenngr.swe_pos                                        12000000",
                          b"kenngr. swe_pos                                       12000000", 1)
    fixed = fix_bytes(broken, "M.tsproj", registry).fixed
    line = 95  # the one line changed: the space inside the key removed, nothing else
    assert fixed.split(b"\n")[line - 1] == b"kenngr.swe_pos                                       12000000"
    assert [a for a, b in zip(fixed.split(b"\n"), data.split(b"\n"), strict=True) if a != b] == [
        fixed.split(b"\n")[line - 1]]


def test_show_of_an_export_element(registry: Registry) -> None:
    """Before: `zero show kanal1.xml#SdaMds` was refused, and `zero show kanal1.xml` said to use --item,
    which show does not have."""
    from zero.engine.queries import load_side

    side = load_side(f"{TWINCAT / 'channel_1.xml'}#SdaMds", None, None, registry, lambda: b"")
    assert side.kind == "CHAN" and side.entries
    with pytest.raises(ZeroError, match=r"name one as `.*channel_1\.xml#SdaMds`"):
        load_side(str(TWINCAT / "channel_1.xml"), None, None, registry, lambda: b"")
    y = load_side(f"{PROJECT}#Y_Achse/AchsMds", None, None, registry, lambda: b"")
    assert y.kind == "AXIS" and "kenngr.max_vb_overide" in " ".join(y.entries)


def test_convert_into_names_the_list_with_the_file(tmp_path: Path, registry: Registry) -> None:
    project = tmp_path / "M.tsproj"
    project.write_bytes(PROJECT.read_bytes())
    lis = tmp_path / "z.lis"
    lis.write_bytes(xml_source(PROJECT.read_bytes(), str(PROJECT), registry, "Z_Achse/AchsMds")[0].replace(
        b"12000000", b"11000000"))
    new = write_into(str(lis), Path(f"{project}#tc_virtual_13"), None, registry, lambda: b"")
    assert new.count(b"11000000") == 1 and project.read_bytes() == new


def test_an_offset_written_in_hexadecimal() -> None:
    data = PROJECT.read_bytes().replace(b'Offset="12"', b'Offset="#x0C"')
    _, lists = embedded_documents(data, "h.tsproj")
    assert pick(lists, "tc_virtual_12", "h").element == "Y_Achse/AchsMds"

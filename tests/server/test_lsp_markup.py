"""The kernel's XML lists and TwinCAT exports in the editor, from the real server process: findings
where `zero lint` puts them, hover, completion, formatting, outline and go to definition, each as on
an ASCII list (an XML list's element is its entry: its name the key, its ``Value`` the value; a list
in a TwinCAT export's CDATA is a list, shifted to where it stands in the file)."""

from __future__ import annotations

import json
import shutil
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_asyncio
from lsp_support import apply_edits, at, change_document, close_document, doc, open_document, session
from lsprotocol import types
from pytest_lsp import LanguageClient

from conftest import FIXTURES, zero_cli

pytestmark = [pytest.mark.slow, pytest.mark.asyncio(loop_scope="module")]

TWINCAT = FIXTURES / "twincat"

STARTUP_XML = """\
<?xml version="1.0" encoding="utf-8"?>
<StartUp>
  <ConfigurationFiles>
    <ChannelParameter>
      <!-- Name of the parameter file for the manual operation parameters - 'hand_mds' -->
      <P-STUP-00013 Value="CncKernelRootDir/config/manual_mode.xml" />
    </ChannelParameter>
    <AxisParameter>
      <!-- Number of axis machine data records - 'zahl_mds' -->
      <P-STUP-00014 Value="1" />
      <!-- Name of the parameter file for the axis parameters - 'achs_mds' -->
      <P-STUP-00015.0 Value="CncKernelRootDir/config/ax_mds_1.xml" />
      <P-STUP-00015.1 Value="CncKernelRootDir/config/ax_mds_2.xml" />
    </AxisParameter>
  </ConfigurationFiles>
</StartUp>
"""
AXIS_XML = """\
<?xml version="1.0" encoding="utf-8"?>
<AX_MDS>
  <Head>
    <!-- Logical axis number - 'achs_nr' -->
    <P-AXIS-00016 Value="1" />
    <!-- Default name of an axis - 'log_achs_name' -->
    <P-AXIS-00297 Value="X" />
  </Head>
  <Limits>
    <P-AXIS-00177 Value="-1000000" />
    <P-AXIS-00178 Value="15000000" />
    <P-AXIS-00199.0 Value="P-AXIS-00178" />
  </Limits>
</AX_MDS>
"""
MANUAL_XML = """\
<?xml version="1.0" encoding="utf-8"?>
<ManualMode>
  <!-- Count of inching key pairs - 'tasten_anzahl' -->
  <P-MANU-00008 Value="12"/>
</ManualMode>
"""


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[LanguageClient]:
    async for c in session(tmp_path_factory.mktemp("cache")):
        yield c


def xml_machine(tmp_path: Path) -> Path:
    """A machine of the kernel's XML lists: startup.xml names its lists below `CncKernelRootDir/config`,
    which the project maps to its own folder (`roots`)."""
    root = tmp_path / "config"
    root.mkdir()
    (root / "startup.xml").write_text(STARTUP_XML)
    (root / "ax_mds_1.xml").write_text(AXIS_XML)
    (root / "manual_mode.xml").write_text(MANUAL_XML)
    (root / "pyproject.toml").write_text('[tool.zero.machine]\nstartup = "startup.xml"\n'
                                         'roots = { "CncKernelRootDir/config" = "." }\n')
    return root


def _cli(path: Path, *args: str) -> list[tuple[int, int, str]]:
    """(line, column, code) of what `zero lint` finds in the file (its project's configuration applied)."""
    run = zero_cli("lint", "--output-format", "json", *args, path.name, cwd=path.parent)
    return [(f["line"], f["column"], f["code"]) for f in json.loads(run.stdout)
            if Path(f["path"]).name == path.name]


def _served(found: list[types.Diagnostic]) -> list[tuple[int, int, str]]:
    return [(d.range.start.line + 1, d.range.start.character + 1, str(d.code)) for d in found]


async def hover_of(client: LanguageClient, path: Path, line: int, character: int) -> types.Hover:
    result = await client.text_document_hover_async(types.HoverParams(doc(path), at(line, character)))
    assert result is not None and isinstance(result.contents, types.MarkupContent)
    return result


def text_of(result: types.Hover) -> str:
    assert isinstance(result.contents, types.MarkupContent)
    return result.contents.value


async def labels(client: LanguageClient, path: Path, line: int, character: int) -> dict[str, types.CompletionItem]:
    result = await client.text_document_completion_async(types.CompletionParams(doc(path), at(line, character)))
    assert isinstance(result, types.CompletionList)
    return {item.label: item for item in result.items}


async def definition(client: LanguageClient, path: Path, line: int, character: int) -> list[str]:
    result = await client.text_document_definition_async(types.DefinitionParams(doc(path), at(line, character)))
    assert isinstance(result, list)
    return [x.uri for x in result if isinstance(x, types.Location)]


# ----------------------------------------------------------------------------- findings


async def test_twincat_exports_get_the_findings_of_zero_lint_at_their_xml_positions(client: LanguageClient,
                                                                                    tmp_path: Path) -> None:
    for name, expected in (("axis_x.xml", [(28, 8, "S004"), (30, 1, "R001")]),
                           ("channel_1.xml", [(40, 55, "R004")]), ("cnc_task.xml", [])):
        path = tmp_path / name
        shutil.copy(TWINCAT / name, path)
        found = await open_document(client, path)
        assert _served(found) == _cli(path) == expected, name
        close_document(client, path)
    path = tmp_path / "axis_x.xml"
    found = await open_document(client, path)
    s004 = next(d for d in found if d.code == "S004")  # the whitespace inside `kenngr. swe_pos`, in the CDATA
    assert s004.range == types.Range(start=at(27, 7), end=at(27, 8))
    close_document(client, path)


async def test_the_lists_of_an_xml_machine_get_the_findings_of_zero_lint(client: LanguageClient,
                                                                         tmp_path: Path) -> None:
    """A list of the machine is linted as `zero lint` lints it, and its own findings stay: before, an XML
    list of a machine lost them all (the server linted the XML file's lines, not the list they hold)."""
    root = xml_machine(tmp_path)
    for name, expected in (("manual_mode.xml", [(4, 24, "R005")]), ("startup.xml", [(13, 8, "X008")]),
                           ("ax_mds_1.xml", [])):
        path = root / name
        found = await open_document(client, path)
        assert _served(found) == _cli(path) == expected, name
        close_document(client, path)
    assert _cli(root / "startup.xml", "--machine") == [(13, 8, "X008")]


# ----------------------------------------------------------------------------- hover


async def test_hover_on_an_xml_element_is_the_hover_of_its_entry(client: LanguageClient, tmp_path: Path) -> None:
    xml = tmp_path / "ax_mds_1.xml"
    xml.write_text(AXIS_XML)
    ascii_list = tmp_path / "achse.lis"
    ascii_list.write_text("kopf.achs_nr 1\n")
    await open_document(client, xml)
    await open_document(client, ascii_list)
    line = AXIS_XML.splitlines()[4]  # `    <P-AXIS-00016 Value="1" />`
    on_id = await hover_of(client, xml, 4, line.index("P-AXIS") + 3)
    on_value = await hover_of(client, xml, 4, line.index('Value="') + 7)
    same = await hover_of(client, ascii_list, 0, 3)
    assert text_of(on_id) == text_of(on_value) == text_of(same)
    assert text_of(on_id).startswith("**kopf.achs_nr** — P-AXIS-00016, axis parameter list\n\nvalue `1`")
    name, value_end = line.index("P-AXIS"), line.index('" />')
    assert on_id.range == on_value.range == types.Range(start=at(4, name), end=at(4, value_end))
    # a range over another element: evaluated with it, on the XML line it is written
    swe_pos = text_of(await hover_of(client, xml, 10, 25))
    assert "value `15000000` = 1500 mm" in swe_pos
    assert "`kenngr.swe_neg` = -1000000 (P-AXIS-00177, line 10)" in swe_pos
    # a value that names another parameter: that parameter, as on an ASCII list; the element's name: its own
    assert text_of(await hover_of(client, xml, 11, 30)).startswith("**kenngr.swe_pos** — P-AXIS-00178")
    assert "value `P-AXIS-00178`: the value of P-AXIS-00178 = 15000000" in text_of(await hover_of(client, xml, 11, 8))
    # an element with two indices: the key with both
    zero = tmp_path / "zero_offset_1.xml"
    zero.write_text('<?xml version="1.0"?>\n<ZeroOffset>\n  <P-ZERO-00003.1.0 Value="100000" />\n</ZeroOffset>\n')
    await open_document(client, zero)
    assert text_of(await hover_of(client, zero, 2, 10)).startswith(
        "**np_grp[1].achse[0].versch** — P-ZERO-00003, zero-offset list\n\nvalue `100000` = 10 mm (or °)")
    for path in (xml, ascii_list, zero):
        close_document(client, path)


async def test_hover_in_a_twincat_export_is_the_hover_of_its_list(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "axis_x.xml"
    shutil.copy(TWINCAT / "axis_x.xml", path)
    await open_document(client, path)
    lines = path.read_text().splitlines()
    line = next(i for i, x in enumerate(lines) if x.startswith("kenngr.swe_neg"))
    result = await hover_of(client, path, line, 3)
    text = text_of(result)
    assert text.startswith("**kenngr.swe_neg** — P-AXIS-00177, axis parameter list\n\nvalue `-2000000` = -200 mm")
    assert "(P-AXIS-00178, line 28)" in text  # the line of the export, not of the list (12)
    assert result.range == types.Range(start=at(line, 0), end=at(line, len(lines[line])))
    # the first list line, on the line of `<AchsMds><![CDATA[`: shifted
    first = next(i for i, x in enumerate(lines) if x.startswith("<AchsMds>"))
    assert await client.text_document_hover_async(types.HoverParams(doc(path), at(first, 3))) is None
    assert await client.text_document_hover_async(types.HoverParams(doc(path), at(2, 3))) is None  # <ItemName>
    channel = tmp_path / "channel_1.xml"
    shutil.copy(TWINCAT / "channel_1.xml", channel)
    await open_document(client, channel)
    text = text_of(await hover_of(client, channel, 39, 60))  # NullpD: `np_grp[1].achse[0].versch 1.5`
    assert text.startswith("**np_grp[1].achse[0].versch** — P-ZERO-00003, zero-offset list\n\nvalue `1.5`")
    close_document(client, path)
    close_document(client, channel)


# ----------------------------------------------------------------------------- completion


async def test_completion_in_a_twincat_export_as_in_a_list(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "axis_x.xml"
    shutil.copy(TWINCAT / "axis_x.xml", path)
    lines = path.read_text().split("\n")
    await open_document(client, path)
    at_line = next(i for i, x in enumerate(lines) if x.startswith("kenngr.swe_neg")) + 1
    typed = [*lines[:at_line], "kenngr.sw", *lines[at_line:]]
    await change_document(client, path, "\n".join(typed), 2)
    found = await labels(client, path, at_line, 9)
    assert "swe_toleranz" not in found  # set already in this list
    item = found["swe_behaviour"]  # the word after the `.`
    assert isinstance(item.text_edit, types.TextEdit)
    assert item.text_edit.range == types.Range(start=at(at_line, 7), end=at(at_line, 9))
    typed[at_line] = "kenngr.achs_typ  "
    await change_document(client, path, "\n".join(typed), 3)
    assert {"ACHSTYP_TRANSLATOR", "ACHSTYP_ROTATOR"} <= set(await labels(client, path, at_line, 17))
    assert await labels(client, path, 2, 10) == {}  # `<ItemName>`: no list there
    channel = tmp_path / "channel_1.xml"
    shutil.copy(TWINCAT / "channel_1.xml", channel)
    text = channel.read_text().split("\n")
    text[34] = "np_grp[1].achse[0]."  # in `<NullpD>`: the keys of a zero-offset list
    await open_document(client, channel, "\n".join(text))
    assert {"versch", "inaktiv"} <= set(await labels(client, channel, 34, 19))
    close_document(client, path)
    close_document(client, channel)


async def test_completion_of_ids_and_values_in_an_xml_list(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "ax_mds_1.xml"
    lines = AXIS_XML.split("\n")
    lines.insert(8, "    <P-")
    path.write_text("\n".join(lines))
    await open_document(client, path)
    found = await labels(client, path, 8, 7)
    assert "P-AXIS-00016" not in found and "P-AXIS-00297" not in found  # set already
    assert "P-AXIS-00199.0" not in found and "P-AXIS-00199.1" in found  # the next element of the array
    item = found["P-AXIS-00018"]
    assert item.detail is not None and item.detail.startswith("kenngr.achs_typ · ")
    assert isinstance(item.text_edit, types.TextEdit)
    assert item.text_edit.range == types.Range(start=at(8, 5), end=at(8, 7))
    assert item.text_edit.new_text.startswith('P-AXIS-00018 Value="${1:') and item.text_edit.new_text.endswith('}" />')
    lines[8] = '    <P-AXIS-00018 Value="'
    await change_document(client, path, "\n".join(lines), 2)
    values = await labels(client, path, 8, len(lines[8]))
    assert {"ACHSTYP_TRANSLATOR", "ACHSTYP_ROTATOR"} <= set(values)
    close_document(client, path)


# ----------------------------------------------------------------------------- formatting


async def test_formatting_keeps_an_xml_list_and_formats_the_lists_of_an_export(client: LanguageClient,
                                                                               tmp_path: Path) -> None:
    xml = tmp_path / "ax_mds_1.xml"
    xml.write_text(AXIS_XML.replace('<P-AXIS-00297 Value="X" />', '<P-AXIS-00297   Value="X"/>'))
    await open_document(client, xml)
    options = types.FormattingOptions(tab_size=4, insert_spaces=True)
    assert not await client.text_document_formatting_async(types.DocumentFormattingParams(doc(xml), options))
    close_document(client, xml)
    channel = tmp_path / "channel_1.xml"
    shutil.copy(TWINCAT / "channel_1.xml", channel)
    text = channel.read_text()
    await open_document(client, channel)
    edits = await client.text_document_formatting_async(types.DocumentFormattingParams(doc(channel), options))
    assert edits and all(e.range.start.line >= 74 for e in edits)  # only in `<VeD>`, the one list not laid out
    expected = tmp_path / "expected.xml"
    shutil.copy(channel, expected)
    zero_cli("format", str(expected))
    assert apply_edits(text, list(edits)) == expected.read_text() != text
    close_document(client, channel)


# ----------------------------------------------------------------------------- outline


async def test_the_outline_of_an_xml_list_and_of_an_export(client: LanguageClient, tmp_path: Path) -> None:
    xml = tmp_path / "ax_mds_1.xml"
    xml.write_text(AXIS_XML)
    await open_document(client, xml)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(doc(xml)))
    assert symbols is not None
    kopf = next(s for s in symbols if isinstance(s, types.DocumentSymbol) and s.name == "kopf")
    achs_nr = (kopf.children or [])[0]
    assert achs_nr.name == "achs_nr" and achs_nr.detail == "1"
    assert achs_nr.selection_range == types.Range(start=at(4, 5), end=at(4, 17))  # the element's name
    close_document(client, xml)
    channel = tmp_path / "channel_1.xml"
    shutil.copy(TWINCAT / "channel_1.xml", channel)
    await open_document(client, channel)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(doc(channel)))
    assert symbols is not None
    assert [(s.name, s.detail) for s in symbols if isinstance(s, types.DocumentSymbol)] == [
        ("SdaMds", "channel parameter list"), ("NullpD", "zero-offset list"), ("WerkzD", "tool list"),
        ("PzvD", "clamping-position offset list"), ("VeD", "external variables list")]
    close_document(client, channel)


# ----------------------------------------------------------------------------- definition


async def test_definition_of_a_reference_in_startup_xml_is_the_list(client: LanguageClient, tmp_path: Path) -> None:
    root = xml_machine(tmp_path)
    startup = root / "startup.xml"
    await open_document(client, startup)
    lines = STARTUP_XML.splitlines()

    def line_of(text: str) -> int:
        return next(i for i, x in enumerate(lines) if text in x)

    axis = line_of("P-STUP-00015.0")
    assert await definition(client, startup, axis, lines[axis].index("ax_mds_1") + 2) == [
        (root / "ax_mds_1.xml").as_uri()]
    assert await definition(client, startup, axis, 8) == [(root / "ax_mds_1.xml").as_uri()]  # on the name
    manual = line_of("P-STUP-00013")
    assert await definition(client, startup, manual, 40) == [(root / "manual_mode.xml").as_uri()]
    assert await definition(client, startup, line_of("P-STUP-00015.1"), 40) == []  # ax_mds_2.xml is not there
    assert await definition(client, startup, line_of("zahl_mds"), 10) == []
    close_document(client, startup)
    axis_list = root / "ax_mds_1.xml"  # a value that names another element: that element
    await open_document(client, axis_list)
    result = await client.text_document_definition_async(types.DefinitionParams(doc(axis_list), at(11, 30)))
    assert isinstance(result, list) and len(result) == 1 and isinstance(result[0], types.Location)
    assert result[0].uri == axis_list.as_uri() and result[0].range.start.line == 10
    close_document(client, axis_list)


async def test_definition_of_a_reference_in_a_twincat_startup_is_the_list(client: LanguageClient,
                                                                          tmp_path: Path) -> None:
    shutil.copytree(TWINCAT / "machine", tmp_path / "machine")
    folder = tmp_path / "machine" / "startup"
    task = folder / "cnc_task.xml"
    await open_document(client, task)
    lines = task.read_text().splitlines()
    for key, target in (("sda_mds[0]", folder / "sda_mds1.lis"), ("achs_mds[2]", folder / "achsmds3.lis"),
                        ("pzv_data[0]", folder / "pzv_d1.lis")):
        line = next(i for i, x in enumerate(lines) if x.startswith(key))
        assert await definition(client, task, line, len(lines[line]) - 3) == [target.as_uri()], key
    close_document(client, task)

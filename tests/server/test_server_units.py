"""The server's pieces without the protocol (fast): positions in the client's units, settings, URIs,
the edits of fixes, noqa and formatting, the outline and completion as plain values."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import pytest
from lsp_support import apply_edits
from lsprotocol import types

from conftest import builtin_registry
from zero.diagnostics import Span
from zero.forms import LIST, PROGRAM, STRUCTURED, form_of
from zero.server import actions, completion, findings, hover, outline
from zero.server.documents import Analysis, Projects
from zero.server.positions import Text, encode_text, path_of, source_bytes, uri_of
from zero.server.settings import Settings


def projects() -> Projects:
    return Projects(lambda desc: builtin_registry())


def analyse(text: str, name: str = "nullp.lis", directory: Path | None = None) -> Analysis:
    uri = (directory / name).as_uri() if directory is not None else f"untitled:{name}"
    return projects().analyse(uri, 1, text)


def test_positions_in_utf16_utf8_and_utf32() -> None:
    line = "a😀b ( µ"
    for encoding, after_emoji in (("utf-16", 3), ("utf-8", 5), ("utf-32", 2)):
        text = Text(line + "\n", encoding)
        assert text.character(0, 2) == after_emoji
        assert text.column(0, after_emoji) == 2
        assert text.position(1, 3) == (0, after_emoji)  # zero's 1-based column 3
    ascii_text = Text("abc\n")
    assert ascii_text.character(0, 99) == 3 and ascii_text.column(0, 99) == 3
    bom = Text("\ufeffkey 1\n")
    assert bom.position(1, 1) == (0, 1)  # zero reads past the BOM
    assert Text("x\r\ny").lines == ["x", "y"] and Text("").end() == (0, 0)


def test_spans_become_ranges_in_the_clients_units() -> None:
    text = Text("# 😀 comment\nkey 😀 value\n")
    assert text.span(Span(2, 5, 2, 6)) == ((1, 4), (1, 6))
    assert text.span(Span(9, 1, 9, 1)) == ((2, 0), (2, 0))  # beyond the end: the last line


def test_settings_take_what_they_know() -> None:
    s = Settings()
    refused = s.update({"zero": {"debounce": 100, "ruleDocs": "https://wiki/{code}", "structured": "all",
                                 "machine": False, "path": ["zero"], "colour": 1}})
    assert (s.debounce, s.rule_docs, s.structured, s.machine) == (0.1, "https://wiki/{code}", "all", False)
    assert refused == ["colour"]
    assert s.update({"debounce": -5, "ruleDocs": "no placeholder", "structured": 3}) == [
        "debounce", "ruleDocs", "structured"]
    assert s.update(None) == [] and s.debounce == 0.1


def test_uris_and_forms() -> None:
    assert path_of("file:///tmp/a%20b/n.lis") == Path("/tmp/a b/n.lis")
    assert path_of("untitled:Untitled-1") is None
    assert uri_of(Path("/tmp/a b/n.lis")) == "file:///tmp/a%20b/n.lis"
    assert [form_of(n) for n in ("a.lis", "a.LST", "p.NC", "p.mpf", "n.yaml", "n.toml", "n.json", "x")] == [
        LIST, LIST, PROGRAM, PROGRAM, STRUCTURED, STRUCTURED, STRUCTURED, LIST]


def test_rule_links_are_files_or_the_template(tmp_path: Path) -> None:
    docs = findings.RuleDocs(directory=tmp_path / "rules")
    href = docs.href("R005")
    assert href == (tmp_path / "rules" / "R005.md").as_uri()
    assert (tmp_path / "rules" / "R005.md").read_text(encoding="utf-8").startswith("# R005 out-of-range")
    assert docs.href("XYZ") is None
    assert findings.RuleDocs("https://wiki.example/zero/{code}").href("S004") == "https://wiki.example/zero/S004"
    blocked = tmp_path / "file"
    blocked.write_text("")
    assert findings.RuleDocs(directory=blocked / "rules").href("R005") is None  # cannot write: no link


def test_the_noqa_edit_appends_after_an_astral_character(tmp_path: Path) -> None:
    text = "np_grp[1].achse[0].versch 99999999999 ( 😀\n"
    a = analyse(text, directory=tmp_path)
    assert [d.code for d in a.diagnostics] == ["R004"]
    acts = actions.code_actions(a, types.Range(start=types.Position(line=0, character=0),
                                               end=types.Position(line=0, character=0)), None,
                                findings.RuleDocs("x/{code}"))
    (noqa,) = [x for x in acts if x.title.startswith("Suppress")]
    assert noqa.edit is not None and noqa.edit.changes is not None
    fixed = apply_edits(text, list(noqa.edit.changes[a.uri]))
    assert fixed == "np_grp[1].achse[0].versch 99999999999 ( 😀  noqa: R004 -- reviewed\n"
    assert analyse(fixed, directory=tmp_path).diagnostics == []


def test_formatting_edits_touch_only_the_lines_that_change(tmp_path: Path) -> None:
    text = "# head\n" + "np_grp[1].achse[0].versch".ljust(54) + "1\n" + "np_grp[1].achse[1].versch 2\n"
    a = analyse(text, directory=tmp_path)
    edits = actions.formatting(a)
    assert len(edits) == 1 and edits[0].range.start.line == 2
    formatted = apply_edits(text, edits)
    assert formatted.splitlines()[2] == "np_grp[1].achse[1].versch".ljust(54) + "2"
    assert actions.formatting(analyse(formatted, directory=tmp_path)) == []


def test_line_edits_at_the_end_without_a_newline() -> None:
    text = Text("a 1\nb 2")
    (edit,) = actions.line_edits(text, "a 1\nb 3\n")
    assert edit.range.start == types.Position(line=1, character=0)
    assert edit.range.end == types.Position(line=1, character=3)
    assert apply_edits("a 1\nb 2", [edit]) == "a 1\nb 3\n"


def test_completion_fills_indices_from_the_entry_above(tmp_path: Path) -> None:
    a = analyse("np_grp[4].achse[7].versch 5\n\n", directory=tmp_path)
    labels = {i.label for i in completion.completion(a, 1, 0, False).items}
    assert {"np_grp[4].achse[7].inaktiv", "np_grp[4].achse[8].versch"} <= labels
    snippets = completion.completion(a, 1, 0, True).items
    versch = next(i for i in snippets if i.label == "np_grp[4].achse[8].versch")
    assert isinstance(versch.text_edit, types.TextEdit)
    assert versch.text_edit.new_text == "np_grp[${1:4}].achse[${2:8}].versch"


def test_hover_and_outline_of_an_untitled_list() -> None:
    a = analyse("g53_verfuegbar 1\nnp_grp[1].achse[0].versch -25000\n")
    h = hover.hover(a, 1, 3)
    assert h is not None and isinstance(h.contents, types.MarkupContent)
    assert "= -2.5 mm (or °)" in h.contents.value
    symbols = outline.document_symbols(a)
    assert [s.name for s in symbols] == ["g53_verfuegbar", "np_grp[1]"]
    assert outline.document_symbols(a) is symbols  # once per version of the text


def test_places_in_an_xml_list_and_a_twincat_export_are_places_in_their_list_text() -> None:
    xml = analyse('<?xml version="1.0"?>\n<AX_MDS>\n  <P-AXIS-00016 Value="12" />\n  <!-- x -->\n</AX_MDS>\n',
                  "ax_mds_1.xml")
    (_, values), = xml.lists()
    on_name, on_value, after = xml.place(2, 4), xml.place(2, 24), xml.place(2, 27)
    assert on_name is not None and on_value is not None and after is not None
    entry = values.doc.entries[0]
    assert (on_name.line, on_name.column, on_name.element) == (2, 0, True)  # the element's name: the key
    assert on_value.column == entry.value_start + 1 and after.column > entry.value_end
    comment = xml.place(3, 4)
    assert comment is not None and (comment.column, comment.shift) == (6, -2)  # the line as `# <!-- x -->`
    export = analyse("<?xml version=\"1.0\"?>\n<TreeItem>\n<IsgAxisDef>\n<AchsMds><![CDATA[kopf.achs_nr 1\n"
                     "kenngr.achs_typ 1\nEnde\n]]></AchsMds>\n</IsgAxisDef>\n</TreeItem>\n", "axis.xml")
    (element, axis), = export.lists()
    assert element == "AchsMds" and axis.kind == "AXIS"
    first = export.place(3, 20)
    assert first is not None and (first.values, first.line, first.column, first.shift) == (axis, 0, 2, 18)
    assert export.place(3, 5) is None and export.place(2, 0) is None  # `<AchsMds>`, `<IsgAxisDef>`: no list
    h = hover.hover(export, 4, 3)
    assert h is not None and isinstance(h.contents, types.MarkupContent)
    assert h.contents.value.startswith("**kenngr.achs_typ** — P-AXIS-00018")
    assert h.range == types.Range(types.Position(4, 0), types.Position(4, 17))


@pytest.mark.skipif(sys.platform == "win32", reason="FIFOs")
def test_an_open_fifo_is_never_read(tmp_path: Path) -> None:
    import os

    fifo = tmp_path / "n.lis"
    os.mkfifo(fifo)
    a = analyse("np_grp[1].achse[0].inaktiv 7\n", "n.lis", tmp_path)
    assert [d.code for d in a.diagnostics] == ["R005"]
    assert not a.saved


def test_a_machine_that_cannot_be_read_is_said_on_programs_and_the_start_up_list(tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('[machine]\nstartup = "listen/hochlauf.lis"\n')
    lint = analyse("np_grp[1].achse[0].inaktiv 7\n", "nullp.lis", tmp_path)
    assert [d.code for d in lint.diagnostics] == ["R005"] and lint.notes == []
    program = analyse("N10 G99 X1600\n", "part.nc", tmp_path)
    (note,) = program.notes
    assert "the machine of [tool.zero.machine] cannot be read" in note.message and "no such file" in note.message
    (tmp_path / "listen").mkdir()
    text = "kanal_anzahl 1\nzahl_mds 1\nachs_mds[0] ./achse.lis\n"
    startup = analyse(text, "listen/hochlauf.lis", tmp_path)  # not saved yet: the machine is read from disk
    assert len(startup.notes) == 1 and "no such file" in startup.notes[0].message
    (tmp_path / "listen" / "hochlauf.lis").write_text(text)
    startup = analyse(text, "listen/hochlauf.lis", tmp_path)
    assert startup.notes == [] and [(d.span.line, d.code) for d in startup.diagnostics] == [(3, "X005")]


def test_bytes_the_client_could_not_decode_are_linted_as_they_were(tmp_path: Path) -> None:
    """The editor's text with a byte kept as `\\udcb5` is the file's bytes again (it was made `?`, and
    formatting then wrote `?` into the list); any other lone surrogate is still `?`."""
    assert encode_text("( 0,1 \udcb5m \ud83d") == b"( 0,1 \xb5m ?"
    path = tmp_path / "n.lis"
    path.write_bytes(b"# \xc3\xa4\nnp_grp[1].achse[0].versch 1 ( \xb5m\n")
    assert source_bytes(path, "# \u00e4\nnp_grp[1].achse[0].versch 1 ( \udcb5m\n") == (path.read_bytes(), True)
    a = analyse("# \u00e4\nnp_grp[1].achse[0].versch 1 ( \udcb5m\n", "n.lis", tmp_path)
    assert [d.code for d in a.diagnostics] == ["S007"] and a.saved


def test_line_edits_make_the_new_text_whatever_changes() -> None:
    rng = random.Random(7)
    pieces = ["a\n", "b\n", "a\r\n", "µ 😀\n", "\n", "c"]
    for _ in range(300):
        old = "".join(rng.choice(pieces) for _ in range(rng.randrange(8)))
        new = "".join(rng.choice(pieces) for _ in range(rng.randrange(8)))
        assert apply_edits(old, actions.line_edits(Text(old), new)) == new, (old, new)


def test_line_edits_of_a_long_list_that_repeats_itself_need_no_diff(monkeypatch: pytest.MonkeyPatch) -> None:
    """Lines that repeat made difflib quadratic: 10,000 lines of one block took 18 s to format (a 10 MB
    list, 35 s). Formatting keeps the number of lines, so they are compared line by line: no diff."""
    import difflib

    def refuse(*_args: object, **_kwargs: object) -> None:
        raise AssertionError("difflib used although no line came or went")

    monkeypatch.setattr(difflib, "SequenceMatcher", refuse)
    block = "".join(f"np_grp[{i}].achse[0].versch {i}\n" for i in range(50))
    old = block * 100
    new = old.replace(" 7\n", "  7\n")
    edits = actions.line_edits(Text(old), new)
    assert len(edits) == 100 and apply_edits(old, edits) == new


def test_a_declared_code_page_is_read_and_written_in_the_editor(tmp_path: Path) -> None:
    """A CP850 list the editor shows right (`ü`): its saved bytes are linted as on the command line,
    its unsaved text is written in CP850 before it is read in CP850, and formatting keeps CP850."""
    (tmp_path / "zero.toml").write_text('[encoding]\n"*.lis" = "cp850"\n')
    text = "kopf.log_achs_name  X  ( Achse f\u00fcr den Tisch\nkenngr.swe_pos 100\nEnde\n"
    path = tmp_path / "achse.lis"
    path.write_bytes(text.encode("cp850"))
    assert source_bytes(path, text, "cp850") == (text.encode("cp850"), True)
    assert source_bytes(path, text.replace("100", "200"), "cp850")[0] == text.replace("100", "200").encode("cp850")
    assert encode_text("\u20ac", "cp850") == "\u20ac".encode()  # a character CP850 lacks: UTF-8, said as S007
    saved = projects().analyse(uri_of(path), 1, text)
    assert saved.saved and saved.diagnostics == []
    edited = projects().analyse(uri_of(path), 2, text.replace("100", "200"))
    assert edited.diagnostics == []
    formatted = actions.formatting(edited)
    assert formatted and all("\u00fc" in e.new_text or "f" not in e.new_text for e in formatted)


def test_an_xml_text_is_written_in_the_encoding_its_declaration_names() -> None:
    """An unsaved XML list in ISO-8859-1: its bytes are what expat reads as the same text (was UTF-8:
    `Kühlung` read as `KÃ¼hlung`, every column after it shifted)."""
    text = '<?xml version="1.0" encoding="ISO-8859-1"?>\n<AX_MDS>\n  <!-- K\u00fchlung -->\n</AX_MDS>\n'
    assert encode_text(text) == text.encode("latin-1")
    assert encode_text("kopf.achs_nr 1  # K\u00fchlung\n") == "kopf.achs_nr 1  # K\u00fchlung\n".encode()

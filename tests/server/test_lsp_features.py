"""Hover, completion, code actions, formatting, symbols, definition and signature help over the
protocol, from the real server process."""

from __future__ import annotations

import shutil
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_asyncio
from lsp_support import apply_edits, at, change_document, close_document, codes, doc, open_document, session
from lsprotocol import types
from pytest_lsp import LanguageClient

from conftest import FIXTURES

pytestmark = [pytest.mark.slow, pytest.mark.asyncio(loop_scope="module")]


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[LanguageClient]:
    async for c in session(tmp_path_factory.mktemp("cache")):
        yield c


async def hover_text(client: LanguageClient, path: Path, line: int, character: int) -> str:
    result = await client.text_document_hover_async(types.HoverParams(doc(path), at(line, character)))
    assert result is not None
    assert isinstance(result.contents, types.MarkupContent)
    return result.contents.value


# ------------------------------------------------------------------------------ hover


async def test_hover_on_a_key_gives_the_parameter_and_its_value(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    path.write_text("np_grp[1].achse[0].versch  100000  # G54 X\nnp_grp[1].achse[0].inaktiv 1\n")
    await open_document(client, path)
    text = await hover_text(client, path, 0, 5)
    assert "**np_grp[1].achse[0].versch** — P-ZERO-00003, zero-offset list" in text
    assert "value `100000`" in text and "= 10 mm (or °)" in text
    assert "type     SGN32" in text and "default  0" in text  # zero param's facts
    result = await client.text_document_hover_async(types.HoverParams(doc(path), at(0, 30)))
    assert result is not None and result.range == types.Range(start=at(0, 0), end=at(0, 33))
    close_document(client, path)


async def test_hover_evaluates_a_range_over_other_parameters(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "achse.lis"
    path.write_text("kenngr.swe_neg -1000000\nkenngr.swe_pos 15000000\nkenngr.achs_typ 2\n")
    await open_document(client, path)
    text = await hover_text(client, path, 1, 3)
    assert "range here: `-1000000 < x" in text
    assert "`kenngr.swe_neg` = -1000000 (P-AXIS-00177, line 1)" in text
    assert "= 1500 °" in text  # a rotary axis: the length in degrees
    close_document(client, path)


async def test_hover_on_a_symbol_and_an_id(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "achse.lis"
    path.write_text("kenngr.swe_behaviour WARNING ( P-AXIS-00554 soft limits\n")
    await open_document(client, path)
    text = await hover_text(client, path, 0, 23)
    assert "value `WARNING`" in text and "P-AXIS-00554" in text
    text = await hover_text(client, path, 0, 35)  # the annotation's ID
    assert text.startswith("**kenngr.swe_behaviour** — P-AXIS-00554")
    assert await client.text_document_hover_async(types.HoverParams(doc(path), at(5, 0))) is None
    close_document(client, path)


async def test_hover_on_a_machine_list_shows_where_the_value_comes_from(client: LanguageClient,
                                                                        tmp_path: Path) -> None:
    shutil.copytree(FIXTURES / "machine-layered", tmp_path / "m")
    (tmp_path / "m" / "zero.toml").write_text('[machine]\nstartup = "listen/hochlauf.lis"\n')
    path = tmp_path / "m" / "listen" / "achse_x.lis"
    lines = path.read_text().splitlines()
    await open_document(client, path)
    line = next(i for i, x in enumerate(lines) if x.startswith("kopf.achs_nr"))
    text = await hover_text(client, path, line, 2)
    assert "on the machine (achs_mds[0])" in text and "catalogue default" in text
    close_document(client, path)


async def test_hover_in_the_yaml_form_and_in_a_program(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "n.yaml"
    path.write_text("np_grp:\n  1:\n    achse:\n      0:\n        versch: 50000\n_zero:\n  kind: ZERO\n")
    await open_document(client, path)
    assert "P-ZERO-00003" in await hover_text(client, path, 4, 10)
    program = tmp_path / "p.nc"
    program.write_text('N10 #MACHINE DATA SYN [AX=X AXPARAM="kenngr.swe_pos 15000000"]\n')
    await open_document(client, program)
    assert "P-AXIS-00178" in await hover_text(client, program, 0, 38)
    assert "**#MACHINE DATA**" in await hover_text(client, program, 0, 8)
    close_document(client, path)
    close_document(client, program)


# ------------------------------------------------------------------------- completion


async def complete(client: LanguageClient, path: Path, line: int, character: int) -> list[types.CompletionItem]:
    result = await client.text_document_completion_async(types.CompletionParams(doc(path), at(line, character)))
    assert isinstance(result, types.CompletionList)
    return list(result.items)


async def test_completion_of_keys_keeps_the_indices_typed(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    text = "g53_verfuegbar 1\nnp_grp[3].achse[2].versch 100\nnp_grp[1].achse[0]."
    await open_document(client, path, text)
    items = await complete(client, path, 2, len("np_grp[1].achse[0]."))
    labels = {i.label for i in items}  # the word after the last `.`, as the clients see it (no doubled key)
    assert labels == {"versch", "inaktiv"}
    edit = items[0].text_edit
    assert isinstance(edit, types.TextEdit) and edit.range.start == at(2, len("np_grp[1].achse[0]."))
    assert edit.new_text == items[0].label and items[0].filter_text is None
    # a new line: the keys of the list's kind, indices from the entry above, set keys moved on
    text = "g53_verfuegbar 1\nnp_grp[3].achse[2].versch 100\n"
    await change_document(client, path, text, 2)
    items = await complete(client, path, 2, 0)
    labels = {i.label for i in items}
    assert "np_grp[3].achse[2].inaktiv" in labels and "np_grp[3].achse[3].versch" in labels
    assert "g53_verfuegbar" not in labels  # set already
    assert "default_index" in labels and not any(x.startswith("kenngr.") for x in labels)
    item = next(i for i in items if i.label == "default_index")
    resolved = await client.completion_item_resolve_async(item)
    assert isinstance(resolved.documentation, types.MarkupContent) and "P-ZERO-00002" in resolved.documentation.value
    close_document(client, path)


async def test_completion_of_values(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "achse.lis"
    await open_document(client, path, "kenngr.swe_behaviour ")
    labels = {i.label for i in await complete(client, path, 0, len("kenngr.swe_behaviour "))}
    assert {"ERROR", "WARNING"} <= labels
    await change_document(client, path, "kenngr.swe_check ", 2)
    labels = {i.label for i in await complete(client, path, 0, len("kenngr.swe_check "))}
    assert {"0", "1"} <= labels
    close_document(client, path)


async def test_completion_and_signature_help_in_machine_data(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "p.nc"
    line = "N10 #MACHINE DATA SYN [AX=X "
    await open_document(client, path, line)
    labels = {i.label for i in await complete(client, path, 0, len(line))}
    assert {"AXPARAM=\"", "WAIT", "P-AXIS-00209="} <= labels
    help_ = await client.text_document_signature_help_async(types.SignatureHelpParams(doc(path), at(0, len(line))))
    assert help_ is not None and help_.signatures[0].label.startswith("#MACHINE DATA [SYN]")
    assert help_.active_parameter == 2
    line = 'N10 #MACHINE DATA SYN [AX=X AXPARAM="kenngr.swe_'
    await change_document(client, path, line, 2)
    labels = {i.label for i in await complete(client, path, 0, len(line))}
    assert "swe_pos" in labels  # a member of `kenngr.`, the word after the `.`
    close_document(client, path)


# ---------------------------------------------------------------------- code actions


async def actions(client: LanguageClient, path: Path, diagnostics: list[types.Diagnostic], line: int,
                  only: list[str] | None = None) -> list[types.CodeAction]:
    result = await client.text_document_code_action_async(types.CodeActionParams(
        doc(path), types.Range(start=at(line, 0), end=at(line, 0)),
        types.CodeActionContext(diagnostics=[d for d in diagnostics if d.range.start.line == line], only=only)))
    assert result is not None
    return [a for a in result if isinstance(a, types.CodeAction)]


def edits_of(action: types.CodeAction, path: Path) -> list[types.TextEdit]:
    assert action.edit is not None and action.edit.changes is not None
    return list(action.edit.changes[path.as_uri()])


async def test_every_fix_is_a_code_action_and_unsafe_ones_say_so(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    text = path.read_text(encoding="utf-8")
    found = await open_document(client, path)
    (fix,) = [a for a in await actions(client, path, found, 18) if a.title.startswith("Remove")]
    assert fix.title == "Remove the whitespace inside the key (S004)" and fix.is_preferred
    assert fix.diagnostics and fix.diagnostics[0].code == "S004"
    fixed = apply_edits(text, edits_of(fix, path)).splitlines()[18]
    assert fixed == "np_grp[0].achse[1].inaktiv 0 # Verschiebung ist gueltig"
    alias = tmp_path / "achse.lis"
    found = await open_document(client, alias, "kenngr.swe_pso 100\n")
    (unsafe,) = [a for a in await actions(client, alias, found, 0, only=["quickfix"]) if "unsafe" in a.title]
    assert unsafe.title.startswith("Replace with `kenngr.swe_pos` (R001, unsafe")
    assert not unsafe.is_preferred
    close_document(client, path)
    close_document(client, alias)


async def test_suppress_with_noqa_in_the_lists_own_syntax(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "n.lis"
    text = "np_grp[1].achse[0].versch 99999999999 ( offset\n"
    found = await open_document(client, path, text)
    (noqa,) = [a for a in await actions(client, path, found, 0) if a.title.startswith("Suppress")]
    assert noqa.title == "Suppress R004 on this line (noqa)"
    fixed = apply_edits(text, edits_of(noqa, path))
    assert fixed.splitlines()[0] == "np_grp[1].achse[0].versch 99999999999 ( offset  noqa: R004 -- reviewed"
    assert await change_document(client, path, fixed, 2) == []
    yaml = tmp_path / "n.yaml"
    ytext = "np_grp:\n  1:\n    achse:\n      0:\n        versch: 99999999999\n_zero:\n  kind: ZERO\n"
    found = await open_document(client, yaml, ytext)
    (noqa,) = [a for a in await actions(client, yaml, found, 4) if a.title.startswith("Suppress")]
    fixed = apply_edits(ytext, edits_of(noqa, yaml))
    assert "versch: 99999999999  # ( noqa: R004 -- reviewed )" in fixed
    assert await change_document(client, yaml, fixed, 2) == []
    program = tmp_path / "p.nc"  # an NC program: in its own `( … )` comment, also after a `;`
    ptext = "N10 #MACHINE DATA [AX=X P-AXIS-00209=80000 WAIT] ; probing\n"
    found = await open_document(client, program, ptext)
    (noqa,) = [a for a in await actions(client, program, found, 0) if a.title.startswith("Suppress")]
    fixed = apply_edits(ptext, edits_of(noqa, program))
    assert fixed.splitlines()[0].endswith("; probing ( noqa: N001 -- reviewed )")
    assert await change_document(client, program, fixed, 2) == []
    close_document(client, path)
    close_document(client, yaml)
    close_document(client, program)


async def test_fix_all_is_zero_lint_fix(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    text = path.read_text(encoding="utf-8")
    found = await open_document(client, path)
    result = await actions(client, path, found, 0, only=["source.fixAll"])
    assert [a.kind for a in result] == ["source.fixAll.zero"]
    (fix_all,) = result
    if fix_all.edit is None:  # resolved lazily where the client can
        fix_all = await client.code_action_resolve_async(fix_all)
    fixed = apply_edits(text, edits_of(fix_all, path))
    assert "np_grp[0].achse[1]. inaktiv" not in fixed and "np_grp[0].achse[2].inaktiv 0" in fixed
    assert "S004" not in {c for _, c in codes(await change_document(client, path, fixed, 2))}
    close_document(client, path)


# ------------------------------------------------------------------ formatting, outline


async def test_formatting_is_zero_format(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    text = "g53_verfuegbar 1 ( on\nnp_grp[1].achse[0].versch   100   # G54\nEnde\n"
    await open_document(client, path, text)
    edits = await client.text_document_formatting_async(types.DocumentFormattingParams(
        doc(path), types.FormattingOptions(tab_size=4, insert_spaces=True)))
    assert edits
    formatted = apply_edits(text, edits)
    assert formatted.splitlines()[1] == "np_grp[1].achse[0].versch".ljust(54) + "100".ljust(15) + "# G54"
    program = tmp_path / "p.nc"
    await open_document(client, program, "N10 G0 X1\n")
    assert not await client.text_document_formatting_async(types.DocumentFormattingParams(
        doc(program), types.FormattingOptions(tab_size=4, insert_spaces=True)))
    close_document(client, path)
    close_document(client, program)


async def test_range_formatting_lays_out_only_the_lines_of_the_range(client: LanguageClient,
                                                                     tmp_path: Path) -> None:
    """The selection's lines get zero format's layout (columns of the whole list); the others stay."""
    path = tmp_path / "nullp.lis"
    text = "g53_verfuegbar 1 ( on\nnp_grp[1].achse[0].versch   100   # G54\nnp_grp[1].achse[1].versch 5\nEnde"
    await open_document(client, path, text)
    whole = apply_edits(text, await client.text_document_formatting_async(types.DocumentFormattingParams(
        doc(path), types.FormattingOptions(tab_size=4, insert_spaces=True))))
    assert whole.split("\n")[0] != text.split("\n")[0] and whole.split("\n")[2] != text.split("\n")[2]
    selected = types.Range(start=at(1, 4), end=at(2, 0))  # line 1 only (the end is the start of line 2)
    edits = await client.text_document_range_formatting_async(types.DocumentRangeFormattingParams(
        doc(path), selected, types.FormattingOptions(tab_size=4, insert_spaces=True)))
    assert edits and {e.range.start.line for e in edits} == {1}
    partly = apply_edits(text, edits).split("\n")
    assert partly[1] == whole.split("\n")[1] and partly[0] == text.split("\n")[0] and partly[2:] == text.split("\n")[2:]
    last = types.Range(start=at(3, 0), end=at(3, 4))  # `Ende` without a newline: nothing to lay out
    assert not await client.text_document_range_formatting_async(types.DocumentRangeFormattingParams(
        doc(path), last, types.FormattingOptions(tab_size=4, insert_spaces=True)))
    close_document(client, path)


async def test_the_outline_goes_by_group_and_axis(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    await open_document(client, path)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(doc(path)))
    assert symbols is not None
    top = [s for s in symbols if isinstance(s, types.DocumentSymbol)]
    assert [s.name for s in top[:3]] == ["g53_verfuegbar", "default_index", "np_grp[0]"]
    g54 = next(s for s in top if s.name == "np_grp[1]")
    assert g54.detail == "G54 (G159=1)" and g54.children is not None
    assert [c.name for c in g54.children] == ["achse[0]", "achse[1]", "achse[2]"]
    axis = g54.children[0]
    assert [(c.name, c.detail) for c in axis.children or []] == [("versch", "100000"), ("inaktiv", "0")]
    assert axis.range.start.line == 24 and axis.range.end.line == 25
    close_document(client, path)


# ------------------------------------------------------------------------ definition


async def test_definition_of_a_start_up_reference_is_the_list(client: LanguageClient, tmp_path: Path) -> None:
    shutil.copytree(FIXTURES / "machine-layered", tmp_path / "m")
    startup = tmp_path / "m" / "listen" / "hochlauf.lis"
    lines = startup.read_text().splitlines()
    await open_document(client, startup)
    line = next(i for i, x in enumerate(lines) if x.startswith("achs_mds[0]"))
    result = await client.text_document_definition_async(types.DefinitionParams(doc(startup), at(line, 60)))
    assert isinstance(result, list) and len(result) == 1
    location = result[0]
    assert isinstance(location, types.Location)
    assert location.uri == (tmp_path / "m" / "listen" / "achse_x.lis").as_uri()
    missing = next(i for i, x in enumerate(lines) if x.startswith("hand_mds"))  # the file is not there
    assert await client.text_document_definition_async(types.DefinitionParams(doc(startup), at(missing, 60))) == []
    close_document(client, startup)


async def test_definition_of_a_reference_value_is_the_entry(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "achse.lis"
    text = "kenngr.swe_pos 15000000\nkenngr.swe_neg -1000\ngetriebe[0].swe_pos P-AXIS-00178\n"
    await open_document(client, path, text)
    result = await client.text_document_definition_async(types.DefinitionParams(doc(path), at(2, 25)))
    assert isinstance(result, list) and len(result) == 1 and isinstance(result[0], types.Location)
    assert result[0].range.start.line == 0
    close_document(client, path)

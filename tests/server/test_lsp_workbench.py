"""The editor as a machine workbench (issue 29), from the real server process: the open lists of a
machine follow each other's unsaved text, a cap on the findings published per file, refused
requests said in one line, document links, folding ranges, commands, pull diagnostics."""

from __future__ import annotations

import asyncio
import json
import shutil
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

import pytest
import pytest_asyncio
from lsp_support import (
    SERVER,
    TIMEOUT,
    _record,
    _record_responses,
    apply_edits,
    close_document,
    codes,
    diagnostics_after,
    doc,
    open_document,
    session,
)
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

from conftest import FIXTURES, zero_cli

pytestmark = [pytest.mark.slow, pytest.mark.asyncio(loop_scope="module")]


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[LanguageClient]:
    async for c in session(tmp_path_factory.mktemp("cache")):
        _apply_edits_as_asked(c)
        yield c


def _apply_edits_as_asked(c: LanguageClient) -> None:
    """The client keeps the edits the server asks it to apply (and says they were applied)."""
    edits: list[types.ApplyWorkspaceEditParams] = []
    c.edits = edits  # type: ignore[attr-defined]

    @c.feature(types.WORKSPACE_APPLY_EDIT)
    def apply(params: types.ApplyWorkspaceEditParams) -> types.ApplyWorkspaceEditResult:
        edits.append(params)
        return types.ApplyWorkspaceEditResult(applied=True)


def _machine(tmp_path: Path) -> Path:
    """The clean fixture machine with G54 X at 2000 mm, outside axis X's +1500 mm (X001)."""
    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    (tmp_path / "m" / "zero.toml").write_text('[machine]\nstartup = "listen/hochlauf.lis"\n')
    listen = tmp_path / "m" / "listen"
    zero_list = listen / "nullp.lis"
    zero_list.write_text(zero_list.read_text().replace("versch                             100000\n",
                                                      "versch                             20000000\n"))
    return listen


def _published(client: LanguageClient, path: Path) -> int:
    return sum(1 for p in client.published if p.uri == path.as_uri())  # type: ignore[attr-defined]


def _set(text: str, key: str, value: str) -> str:
    """The list text with ``key`` set to ``value`` (the value column kept)."""
    out = []
    for line in text.split("\n"):
        if line.split(" ", 1)[0] == key:
            line = key.ljust(54) + value
        out.append(line)
    return "\n".join(out)


# ------------------------------------------------------------------ 1. the machine's open lists follow each other


async def test_an_unsaved_axis_list_relints_the_open_zero_offset_list(client: LanguageClient,
                                                                      tmp_path: Path) -> None:
    """Issue 29: the zero-offset list kept X001 until it was itself edited."""
    listen = _machine(tmp_path)
    zero_list, axis = listen / "nullp.lis", listen / "achse_x.lis"
    unrelated = tmp_path / "other" / "n.lis"
    unrelated.parent.mkdir()
    unrelated.write_text("np_grp[1].achse[0].versch 100\n")
    assert (4, "X001") in codes(await open_document(client, zero_list))
    await open_document(client, unrelated)
    saved = axis.read_text()
    assert codes(await open_document(client, axis)) == []
    before = _published(client, unrelated)
    # swe_pos raised to 3000 mm in the editor, not saved: the offset lies inside, X001 goes from nullp.lis
    found = await diagnostics_after(client, zero_list.as_uri(), lambda: client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(uri=axis.as_uri(), version=2),
                                          [types.TextDocumentContentChangeWholeDocument(
                                              _set(saved, "kenngr.swe_pos", "30000000"))])))
    assert "X001" not in {d.code for d in found}
    assert axis.read_text() == saved
    # and back: X001 again, named after the editor's text
    found = await diagnostics_after(client, zero_list.as_uri(), lambda: client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(uri=axis.as_uri(), version=3),
                                          [types.TextDocumentContentChangeWholeDocument(
                                              _set(saved, "kenngr.swe_pos", "16000000"))])))
    (x001,) = [d for d in found if d.code == "X001"]
    assert "1600.0000 mm" in x001.message
    await asyncio.sleep(0.3)
    assert _published(client, unrelated) == before  # a list of no machine is not linted again
    # closed without saving: its saved text counts again
    found = await diagnostics_after(client, zero_list.as_uri(), lambda: close_document(client, axis))
    (x001,) = [d for d in found if d.code == "X001"]
    assert "1500.0000 mm" in x001.message
    close_document(client, zero_list)
    close_document(client, unrelated)


async def test_a_changed_channel_axis_shows_in_the_other_open_lists(client: LanguageClient, tmp_path: Path) -> None:
    """A channel list's `log_achs_nr` and an axis list's `kopf.achs_nr`, changed unsaved, move the X
    findings of the other open lists at once."""
    listen = _machine(tmp_path)
    zero_list, channel, axis_c = listen / "nullp.lis", listen / "kanal.lis", listen / "achse_c.lis"
    assert (4, "X001") in codes(await open_document(client, zero_list))
    assert codes(await open_document(client, channel)) == []
    saved_c = axis_c.read_text()
    await open_document(client, axis_c)
    # axis C renumbered in its list: channel axis 2 names logical axis 3, which no list has (X007 in kanal.lis)
    found = await diagnostics_after(client, channel.as_uri(), lambda: client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(uri=axis_c.as_uri(), version=2),
                                          [types.TextDocumentContentChangeWholeDocument(
                                              _set(saved_c, "kopf.achs_nr", "4"))])))
    assert codes(found) == [(7, "X007")]
    found = await diagnostics_after(client, channel.as_uri(), lambda: close_document(client, axis_c))
    assert codes(found) == []
    # channel axis 0 mapped to logical axis 9 in the channel list: X007 there, and the zero-offset
    # list no longer measures G54 X against axis X's limits
    text = _set(channel.read_text(), "gruppe[0].achse[0].log_achs_nr", "9")
    found = await diagnostics_after(client, zero_list.as_uri(),
                                    lambda: client.text_document_did_change(types.DidChangeTextDocumentParams(
                                        types.VersionedTextDocumentIdentifier(uri=channel.as_uri(), version=2),
                                        [types.TextDocumentContentChangeWholeDocument(text)])))
    assert "X001" not in {d.code for d in found}
    assert codes(client.diagnostics[channel.as_uri()]) == [(3, "X007")]
    assert zero_cli("lint", "listen/kanal.lis", cwd=listen.parent).code == 0  # nothing saved
    close_document(client, channel)
    close_document(client, zero_list)


# ------------------------------------------------------------------ 2. a cap on the findings published


def _many(n: int) -> str:
    return "".join(f"np_grp[1].achse[{i}].inaktiv 7\n" for i in range(n))  # R005 each


async def test_findings_over_the_cap_are_one_summary(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "viele.lis"
    path.write_text(_many(20))
    assert len(await open_document(client, path)) == 20  # under the default cap (2000): all of them
    found = await diagnostics_after(client, path.as_uri(), lambda: client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams({"zero": {"maxFindings": 5}})))
    assert [d.code for d in found] == ["R005"] * 5 + ["zero"]
    assert [d.range.start.line for d in found[:5]] == [0, 1, 2, 3, 4]  # the first ones, in order
    summary = found[-1]
    assert summary.message == "15 more findings not shown: run `zero lint viele.lis`"
    assert summary.severity == types.DiagnosticSeverity.Information
    assert summary.range == types.Range(types.Position(0, 0), types.Position(0, 0))
    found = await diagnostics_after(client, path.as_uri(), lambda: client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams({"zero": {"maxFindings": 0}})))  # 0: no cap
    assert len(found) == 20
    found = await diagnostics_after(client, path.as_uri(), lambda: client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams({"zero": {"maxFindings": 2000}})))
    assert len(found) == 20
    close_document(client, path)


# ------------------------------------------------------------------ 3. refused requests in one line


def _message(body: dict[str, Any]) -> bytes:
    data = json.dumps(body).encode()
    return b"Content-Length: %d\r\n\r\n" % len(data) + data


async def test_a_request_with_bad_params_is_logged_in_one_line_not_a_traceback() -> None:
    """Issue 29: pygls wrote a 40-line traceback at ERROR level for a request it answered correctly."""
    uri = "file:///tmp/zero-bad-params/n.lis"
    opened = {"textDocument": {"uri": uri, "languageId": "plaintext", "version": 1,
                               "text": "np_grp[1].achse[0].versch 1\n"}}
    messages = [{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}},
                {"jsonrpc": "2.0", "method": "initialized", "params": {}},
                {"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": opened},
                {"jsonrpc": "2.0", "id": 2, "method": "textDocument/hover",
                 "params": {"textDocument": {"uri": uri}, "position": {"line": "x", "character": 2}}},
                {"jsonrpc": "2.0", "id": 3, "method": "workspace/executeCommand",
                 "params": {"command": "zero.showEffectiveValue", "arguments": [uri]}},
                {"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": 5}}},
                {"jsonrpc": "2.0", "id": 4, "method": "shutdown"}, {"jsonrpc": "2.0", "method": "exit"}]
    process = await asyncio.create_subprocess_exec(*SERVER, stdin=asyncio.subprocess.PIPE,
                                                   stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.PIPE)
    out, err = await asyncio.wait_for(process.communicate(b"".join(_message(m) for m in messages)), TIMEOUT)
    answers = [json.loads(part.split(b"\r\n\r\n", 1)[1]) for part in out.split(b"Content-Length: ")[1:]]
    by_id = {a["id"]: a for a in answers if "id" in a}
    assert by_id[2]["error"]["code"] == -32602
    assert by_id[2]["error"]["message"].endswith("$.params.position.line: invalid literal for int() with "
                                                 "base 10: 'x'")
    assert by_id[3]["error"]["code"] == -32602 and "[uri, {line, character}]" in by_id[3]["error"]["message"]
    assert by_id[4]["result"] is None and process.returncode == 0
    log = err.decode("utf-8", "replace")
    assert "Traceback" not in log and "ERROR" not in log, log
    lines = log.splitlines()
    assert len(lines) == 3, log  # one line each: two refused requests, one notification ignored
    assert "request 2 refused: textDocument/hover" in lines[0] and "WARNING" in lines[0]
    logged = [a["params"] for a in answers if a.get("method") == "window/logMessage"]
    assert not [m for m in logged if m["type"] == 1 or "Traceback" in m["message"]], logged


# ------------------------------------------------------------------ 4. links, folding, commands, pull


async def test_a_start_up_lists_paths_are_links(client: LanguageClient, tmp_path: Path) -> None:
    listen = _machine(tmp_path)
    startup = listen / "hochlauf.lis"
    await open_document(client, startup)
    found = await client.text_document_document_link_async(types.DocumentLinkParams(doc(startup)))
    assert found is not None
    lines = startup.read_text().split("\n")
    got = {lines[link.range.start.line][link.range.start.character:link.range.end.character]: link.target
           for link in found}
    assert got == {f"./listen/{name}.lis": (listen / f"{name}.lis").as_uri()
                   for name in ("kanal", "nullp", "achse_x", "achse_y", "achse_c")}
    close_document(client, startup)
    # a path whose file does not exist (X005) has no link; the others resolve as the machine does
    layered = tmp_path / "layered"
    shutil.copytree(FIXTURES / "machine-layered", layered)
    (layered / "zero.toml").write_text('[machine]\nstartup = "listen/hochlauf.lis"\n')
    startup = layered / "listen" / "hochlauf.lis"
    await open_document(client, startup)
    found = await client.text_document_document_link_async(types.DocumentLinkParams(doc(startup)))
    targets = {link.target.rsplit("/", 1)[-1] for link in found or []}
    assert "hand_mds.lis" not in targets and "achse_c.lis" not in targets
    assert {"kanal_vorgabe.lis", "kanal.lis", "nullp.lis", "achse_vorgabe.lis", "achse_x.lis"} <= targets
    close_document(client, startup)


async def test_folding_ranges_are_comment_blocks_and_key_groups(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    text = ("# zero offsets\n# of machine 2\n# checked 2024\n"
            "g53_verfuegbar 1\n"
            "np_grp[1].achse[0].versch 100\n"
            "np_grp[1].achse[1].versch 200\n"
            "# a note\n"
            "np_grp[1].achse[1].inaktiv 0\n"
            "np_grp[2].achse[0].versch 300\n"
            "Ende\n")
    await open_document(client, path, text)
    found = await client.text_document_folding_range_async(types.FoldingRangeParams(doc(path)))
    got = [(r.start_line, r.end_line, r.kind) for r in found or []]
    assert got == [(0, 2, types.FoldingRangeKind.Comment),  # the header
                   (4, 7, types.FoldingRangeKind.Region),  # np_grp[1] (G54), over its note
                   (5, 7, types.FoldingRangeKind.Region)]  # np_grp[1].achse[1]
    close_document(client, path)


async def test_the_commands_are_advertised(tmp_path: Path) -> None:
    client, result = await _start(tmp_path, client_capabilities("visual-studio-code"))
    try:
        provider = result.capabilities.execute_command_provider
        assert provider is not None and set(provider.commands) == {"zero.fixAll", "zero.showEffectiveValue"}
        assert result.capabilities.document_link_provider is not None
        assert result.capabilities.folding_range_provider
        assert result.capabilities.diagnostic_provider is None  # VS Code 1.65 does not pull: pushed
    finally:
        await client.shutdown_session()
        await client.stop()


async def test_fix_all_command_applies_zero_lint_fix(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    text = path.read_text(encoding="utf-8")
    await open_document(client, path)
    answer = await client.workspace_execute_command_async(types.ExecuteCommandParams(
        "zero.fixAll", [path.as_uri()]))
    assert answer["applied"] is True and answer["edits"] > 0
    edit = client.edits[-1].edit  # type: ignore[attr-defined]
    fixed = apply_edits(text, edit.changes[path.as_uri()])
    cli = tmp_path / "cli"
    cli.mkdir()
    shutil.copy(path, cli / "nullp.lis")
    zero_cli("lint", "--fix", "nullp.lis", cwd=cli)
    assert fixed == (cli / "nullp.lis").read_text(encoding="utf-8")
    assert path.read_text(encoding="utf-8") == text  # the editor applies it, not the server
    close_document(client, path)


async def test_show_effective_value_says_where_the_value_comes_from(client: LanguageClient, tmp_path: Path) -> None:
    layered = tmp_path / "layered"
    shutil.copytree(FIXTURES / "machine-layered", layered)
    (layered / "zero.toml").write_text('[machine]\nstartup = "listen/hochlauf.lis"\n')
    axis = layered / "listen" / "achse_y.lis"
    await open_document(client, axis)
    line = next(i for i, x in enumerate(axis.read_text().split("\n")) if x.startswith("kenngr.swe_pos"))
    answer = await client.workspace_execute_command_async(types.ExecuteCommandParams(
        "zero.showEffectiveValue", [axis.as_uri(), {"line": line, "character": 3}]))
    assert answer["key"] == "kenngr.swe_pos" and answer["id"] == "P-AXIS-00178"
    assert "`2000000` from this list, line 4" in answer["message"]
    assert "achse_vorgabe.lis:4: `1000000`" in answer["message"]  # the default list under it
    assert client.messages[-1].message == answer["message"]  # shown too (pytest-lsp keeps them)
    close_document(client, axis)


# ------------------------------------------------------------------ pull diagnostics


async def _start(tmp_path: Path, capabilities: types.ClientCapabilities,
                 cwd: Path | None = None) -> tuple[LanguageClient, types.InitializeResult]:
    import os

    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path / "cache")}
    client = await ClientServerConfig(server_command=SERVER, server_env=env).start()
    assert isinstance(client, LanguageClient)
    _record(client)
    _record_responses(client)
    result = await client.initialize_session(types.InitializeParams(
        capabilities=capabilities, root_uri=(cwd or Path.cwd()).as_uri(),
        initialization_options={"debounce": 20, "maxFindings": 3}))
    return client, result


async def test_a_client_that_pulls_gets_its_findings_pulled(tmp_path: Path) -> None:
    caps = client_capabilities("visual-studio-code")
    assert caps.text_document is not None and caps.workspace is not None
    caps.text_document.diagnostic = types.DiagnosticClientCapabilities(related_document_support=False)
    caps.workspace.diagnostics = types.DiagnosticWorkspaceClientCapabilities(refresh_support=True)
    client, result = await _start(tmp_path, caps)
    try:
        provider = result.capabilities.diagnostic_provider
        assert isinstance(provider, types.DiagnosticOptions) and provider.inter_file_dependencies
        listen = _machine(tmp_path)
        zero_list, axis = listen / "nullp.lis", listen / "achse_x.lis"
        for path in (zero_list, axis):
            client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(
                path.as_uri(), "plaintext", 1, path.read_text())))
        report = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(doc(zero_list)))
        assert isinstance(report, types.RelatedFullDocumentDiagnosticReport)
        assert (4, "X001") in codes(report.items)
        # a neighbour changed: the client is asked to pull again, and the pull follows the unsaved text
        client.text_document_did_change(types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=axis.as_uri(), version=2),
            [types.TextDocumentContentChangeWholeDocument(_set(axis.read_text(), "kenngr.swe_pos", "30000000"))]))
        loop = asyncio.get_running_loop()
        deadline = loop.time() + TIMEOUT
        while client.diagnostic_refresh_count == 0 and loop.time() < deadline:
            await asyncio.sleep(0.01)
        assert client.diagnostic_refresh_count >= 1  # pytest-lsp counts them
        report = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(doc(zero_list)))
        assert "X001" not in {d.code for d in report.items}
        # the cap holds for pulled findings too
        many = tmp_path / "viele.lis"
        many.write_text(_many(10))
        report = await client.text_document_diagnostic_async(types.DocumentDiagnosticParams(doc(many)))
        assert [d.code for d in report.items] == ["R005"] * 3 + ["zero"]
        assert not client.published  # type: ignore[attr-defined]  # nothing pushed
    finally:
        await client.shutdown_session()
        await client.stop()


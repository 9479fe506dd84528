"""The server never dies of what a client sends: malformed requests and notifications, bytes that
are no JSON, files that cannot be read, positions beyond the text. Each is answered (an LSP error
or an empty result) and the next request is served as usual."""

from __future__ import annotations

import asyncio
import json
import os
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

import pytest
import pytest_asyncio
from lsp_support import (
    SERVER,
    TIMEOUT,
    answer_of,
    close_document,
    codes,
    diagnostics_after,
    open_document,
    raw_request,
    send_raw,
    session,
)
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pytest_lsp import LanguageClient

pytestmark = [pytest.mark.slow, pytest.mark.asyncio(loop_scope="module")]


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[LanguageClient]:
    async for c in session(tmp_path_factory.mktemp("cache")):
        yield c


async def still_serving(client: LanguageClient, tmp_path: Path) -> None:
    """A document opened after the fault gets its findings and a hover."""
    path = tmp_path / "alive.lis"
    found = await open_document(client, path, "np_grp[1].achse[0].versch 99999999999\n")
    assert codes(found) == [(1, "R004")]
    result = await client.text_document_hover_async(types.HoverParams(
        types.TextDocumentIdentifier(uri=path.as_uri()), types.Position(line=0, character=3)))
    assert result is not None
    close_document(client, path)


async def test_a_request_with_malformed_parameters_is_answered_invalid_params(client: LanguageClient,
                                                                             tmp_path: Path) -> None:
    result, error = await raw_request(client, types.TEXT_DOCUMENT_HOVER,
                                      {"textDocument": {"uri": 5}, "position": {"line": "x"}}, "hover")
    assert result is None and error is not None
    assert error.code == -32602 and "textDocument/hover" in error.message
    result, error = await raw_request(client, types.TEXT_DOCUMENT_COMPLETION, None, "completion")
    assert error is not None and error.code == -32602
    result, error = await raw_request(client, "zero/noSuchMethod", {}, "unknown")
    assert error is not None and error.code == -32601
    await still_serving(client, tmp_path)


async def test_malformed_notifications_and_bytes_are_read_past(client: LanguageClient, tmp_path: Path) -> None:
    await send_raw(client, b'{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": 1}}')
    await send_raw(client, b'{"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": '
                           b'{"uri": "file:///never-opened.lis", "version": 2}, "contentChanges": [{"text": "x"}]}}')
    await send_raw(client, b"{not json")
    await send_raw(client, "\u00fc".encode("latin-1"))
    await still_serving(client, tmp_path)


async def test_a_file_that_cannot_be_read_is_a_request_failed(client: LanguageClient, tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.lis"
    os.mkfifo(fifo)
    missing = tmp_path / "missing.lis"
    for path, reason in ((fifo, "FIFO"), (missing, "no such file"), (tmp_path, "directory")):
        with pytest.raises(JsonRpcException) as caught:
            await client.text_document_document_symbol_async(types.DocumentSymbolParams(
                types.TextDocumentIdentifier(uri=path.as_uri())))
        assert caught.value.code == -32803, reason
        assert reason in caught.value.message.lower() or reason in caught.value.message
    with pytest.raises(JsonRpcException) as caught:
        await client.text_document_hover_async(types.HoverParams(
            types.TextDocumentIdentifier(uri="untitled:Untitled-1"), types.Position(line=0, character=0)))
    assert caught.value.code == -32803
    await still_serving(client, tmp_path)


async def test_an_open_document_on_a_fifo_is_linted_from_the_editor_text(client: LanguageClient,
                                                                        tmp_path: Path) -> None:
    fifo = tmp_path / "nullp.lis"
    os.mkfifo(fifo)  # reading it would block: zero never opens it for reading
    found = await open_document(client, fifo, "np_grp[1].achse[0].inaktiv 7\n")
    assert codes(found) == [(1, "R005")]
    close_document(client, fifo)


async def test_positions_beyond_the_text_get_empty_answers(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "n.lis"
    await open_document(client, path, "np_grp[1].achse[0].versch 1\n")
    ident = types.TextDocumentIdentifier(uri=path.as_uri())
    far = types.Position(line=1000, character=1000)
    assert await client.text_document_hover_async(types.HoverParams(ident, far)) is None
    assert await client.text_document_definition_async(types.DefinitionParams(ident, far)) == []
    completion = await client.text_document_completion_async(types.CompletionParams(ident, far))
    assert isinstance(completion, types.CompletionList)
    actions = await client.text_document_code_action_async(types.CodeActionParams(
        ident, types.Range(start=far, end=far), types.CodeActionContext(diagnostics=[])))
    assert not actions
    close_document(client, path)
    await still_serving(client, tmp_path)


async def test_an_untitled_document_is_linted_with_the_defaults(client: LanguageClient) -> None:
    uri = "untitled:Untitled-2"
    client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(
        uri=uri, language_id="plaintext", version=1, text="np_grp[1].achse[0].inaktiv 7\n")))
    found = await diagnostics_after(client, uri)
    assert codes(found) == [(1, "R005")]


async def test_formatting_a_list_it_cannot_read_is_a_request_failed(client: LanguageClient,
                                                                   tmp_path: Path) -> None:
    path = tmp_path / "n.lis"
    await open_document(client, path, "np_grp[1].achse[0].versch 1\n\"quoted key\" 1\n")
    with pytest.raises(JsonRpcException) as caught:
        await client.text_document_formatting_async(types.DocumentFormattingParams(
            types.TextDocumentIdentifier(uri=path.as_uri()), types.FormattingOptions(tab_size=4, insert_spaces=True)))
    assert caught.value.code == -32803 and "not formatted" in caught.value.message
    close_document(client, path)
    await still_serving(client, tmp_path)


async def test_a_message_that_is_not_utf8_is_read_with_its_bytes(client: LanguageClient, tmp_path: Path) -> None:
    """An editor that sends a buffer it could not decode (raw Latin-1 bytes in the JSON): the document is
    opened and the byte reported where it is (S007), a request is answered; pygls used to drop both."""
    path = tmp_path / "gemischt.lis"  # not on disk: the editor's bytes are linted
    uri = path.as_uri()
    body = (b'{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "'
            + uri.encode() + b'", "languageId": "plaintext", "version": 1, "text": '
            + b'"# Umlaut \xc3\xa4\\nnp_grp[1].achse[0].versch 1 ( 0,1 \xb5m\\n"}}}')
    found = await diagnostics_after(client, uri, lambda: asyncio.ensure_future(send_raw(client, body)))
    assert [(d.code, d.range.start.line, d.range.start.character) for d in found] == [("S007", 1, 34)]
    body = (b'{"jsonrpc": "2.0", "id": "raw-latin1", "method": "textDocument/hover", "params": {"textDocument": '
            b'{"uri": "' + uri.encode() + b'"}, "position": {"line": 1, "character": 3}}}')
    await send_raw(client, body)
    result, error = await answer_of(client, "raw-latin1")
    assert error is None and "P-ZERO-00003" in str(result)
    close_document(client, path)
    await still_serving(client, tmp_path)


def _message(body: dict[str, object]) -> bytes:
    data = json.dumps(body).encode()
    return b"Content-Length: %d\r\n\r\n" % len(data) + data


async def _run_server(*messages: dict[str, object]) -> tuple[int, list[dict[str, Any]]]:
    """A server process fed these messages and then the end of its input: its exit code and answers."""
    process = await asyncio.create_subprocess_exec(*SERVER, stdin=asyncio.subprocess.PIPE,
                                                   stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.PIPE)
    out, _ = await asyncio.wait_for(process.communicate(b"".join(_message(m) for m in messages)), TIMEOUT)
    answers = [json.loads(part.split(b"\r\n\r\n", 1)[1]) for part in out.split(b"Content-Length: ")[1:]]
    assert process.returncode is not None
    return process.returncode, answers


INITIALIZE = {"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"processId": None, "rootUri": None,
                                                                             "capabilities": {}}}


async def test_shutdown_then_exit_is_0_and_requests_after_shutdown_are_refused() -> None:
    """A request after shutdown is answered InvalidRequest, as the protocol says (pygls left it unanswered:
    the client waited); exit without shutdown, or the client gone, ends with 1 (it was 0)."""
    hover = {"textDocument": {"uri": "file:///x.lis"}, "position": {"line": 0, "character": 0}}
    code, answers = await _run_server(
        INITIALIZE, {"jsonrpc": "2.0", "method": "initialized", "params": {}},
        {"jsonrpc": "2.0", "id": 2, "method": "shutdown"},
        {"jsonrpc": "2.0", "id": 3, "method": "textDocument/hover", "params": hover},
        {"jsonrpc": "2.0", "method": "exit"})
    assert code == 0
    by_id = {a["id"]: a for a in answers if "id" in a}
    assert by_id[2]["result"] is None
    assert by_id[3]["error"]["code"] == -32600 and "shutting down" in by_id[3]["error"]["message"]
    code, _ = await _run_server(INITIALIZE, {"jsonrpc": "2.0", "method": "exit"})
    assert code == 1
    code, _ = await _run_server(INITIALIZE)
    assert code == 1


async def test_a_refused_formatting_is_answered_without_a_traceback_or_an_error_log() -> None:
    """A list `zero format` cannot read is refused with its reason (RequestFailed); pygls used to log
    a traceback on stderr and an error into the client's log for each such refusal."""
    uri = "file:///tmp/zero-refused/n.lis"
    opened = {"textDocument": {"uri": uri, "languageId": "plaintext", "version": 1,
                               "text": "np_grp[1].achse[0].versch 1\n\"quoted key\" 1\n"}}
    fmt = {"textDocument": {"uri": uri}, "options": {"tabSize": 4, "insertSpaces": True}}
    messages = [INITIALIZE, {"jsonrpc": "2.0", "method": "initialized", "params": {}},
                {"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": opened},
                {"jsonrpc": "2.0", "id": 2, "method": "textDocument/formatting", "params": fmt},
                {"jsonrpc": "2.0", "id": 3, "method": "shutdown"}, {"jsonrpc": "2.0", "method": "exit"}]
    process = await asyncio.create_subprocess_exec(*SERVER, stdin=asyncio.subprocess.PIPE,
                                                   stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.PIPE)
    out, err = await asyncio.wait_for(process.communicate(b"".join(_message(m) for m in messages)), TIMEOUT)
    answers = [json.loads(part.split(b"\r\n\r\n", 1)[1]) for part in out.split(b"Content-Length: ")[1:]]
    refused = next(a for a in answers if a.get("id") == 2)
    assert refused["error"]["code"] == -32803 and "not formatted" in refused["error"]["message"]
    assert b"Traceback" not in err and b"not formatted" not in err, err.decode("utf-8", "replace")
    logged = [a["params"]["message"] for a in answers if a.get("method") == "window/logMessage"]
    assert not [m for m in logged if "not formatted" in m]


async def _run_raw(data: bytes, timeout: float = TIMEOUT) -> tuple[int, list[dict[str, Any]], bytes]:
    """A server process fed raw bytes, then the end of its input."""
    process = await asyncio.create_subprocess_exec(*SERVER, stdin=asyncio.subprocess.PIPE,
                                                   stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.PIPE)
    out, err = await asyncio.wait_for(process.communicate(data), timeout)
    answers = [json.loads(part.split(b"\r\n\r\n", 1)[1]) for part in out.split(b"Content-Length: ")[1:]]
    assert process.returncode is not None
    assert b"Traceback" not in err, err.decode(errors="replace")
    return process.returncode, answers, err


SHUTDOWN = {"jsonrpc": "2.0", "id": 9, "method": "shutdown"}
EXIT = {"jsonrpc": "2.0", "method": "exit"}


@pytest.mark.parametrize("broken", [
    b"Content-Length: abc\r\n\r\n{\"jsonrpc\": \"2.0\", \"id\": 5, \"method\": \"shutdown\"}",
    b"\r\n\r\n{\"jsonrpc\": \"2.0\", \"id\": 5, \"method\": \"x\"}",  # no Content-Length
    b"Content-Type: application/vscode-jsonrpc\r\n\r\n{}",
    b"Content-Length: 10\r\n\r\n{\"jsonrpc\": \"2.0\", \"id\": 5, \"method\": \"shutdown\"}",  # too short
    b"Content-Length: 80\r\n\r\n{\"jsonrpc\": \"2.0\", \"id\": 5}",  # too long: it swallows the next header
    b"Content-Length: 99999999999\r\n\r\n{}",  # over the limit
    b"garbage without any header at all" * 400,
    b"X-Junk: 1\r\n\r\n",  # a header's end and no Content-Length: the reader looped on it (fuzzing found it)
])
async def test_broken_framing_is_answered_and_the_server_goes_on(broken: bytes) -> None:
    """README: "a broken or oversized message is skipped, answered with a parse error". pygls trusted the
    framing: a Content-Length that was not a number, missing or wrong left the server reading the
    next message as a body, and it never answered again, not even `shutdown`."""
    data = _message(INITIALIZE) + broken + _message(SHUTDOWN) + _message(EXIT)
    code, answers, err = await _run_raw(data, timeout=20)
    assert code == 0, err.decode(errors="replace")
    assert any(a.get("id") == 9 and "result" in a for a in answers), answers
    assert any(a.get("id") is None and a.get("error", {}).get("code") == -32700 for a in answers), answers


async def test_a_uri_with_a_nul_byte_is_checked_as_an_untitled_document(client: LanguageClient) -> None:
    uri = "file:///tmp/a%00b.lis"
    found = await diagnostics_after(client, uri, lambda: client.text_document_did_open(
        types.DidOpenTextDocumentParams(types.TextDocumentItem(uri, "plaintext", 1, "np_grp[1].achse[0].versch x\n"))))
    assert [str(d.code) for d in found] == ["R004"]
    _result, error = await raw_request(client, types.TEXT_DOCUMENT_HOVER,
                                      {"textDocument": {"uri": uri}, "position": {"line": 0, "character": 2}}, "h")
    assert error is None or "Traceback" not in (error.message + str(error.data or ""))
    client.text_document_did_close(types.DidCloseTextDocumentParams(types.TextDocumentIdentifier(uri)))


async def test_a_burst_of_changes_is_linted_once_not_once_each() -> None:
    """With debounce 0 a client that sends 2,000 changes at once (or is gone) does not leave the
    server linting each of them in turn: changes already waiting supersede each other."""
    uri = "file:///tmp/zero-burst/n.lis"
    text = "".join(f"np_grp[1].achse[0].versch {i}\n" for i in range(3000))
    messages = [{**INITIALIZE, "params": {**INITIALIZE["params"], "initializationOptions": {"debounce": 0}}},  # type: ignore[dict-item]
                {"jsonrpc": "2.0", "method": "initialized", "params": {}},
                {"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
                    "uri": uri, "languageId": "plaintext", "version": 1, "text": text}}}]
    for v in range(2, 2002):
        messages.append({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {
            "textDocument": {"uri": uri, "version": v}, "contentChanges": [{"text": text + f"a {v}\n"}]}})
    messages += [SHUTDOWN, EXIT]
    import time

    t0 = time.perf_counter()
    code, answers, _ = await _run_raw(b"".join(_message(m) for m in messages), timeout=120)
    published = [a for a in answers if a.get("method") == "textDocument/publishDiagnostics"]
    assert code == 0
    assert len(published) < 200, (len(published), time.perf_counter() - t0)

"""Helpers for the protocol tests: the real ``zero server`` process driven by pytest-lsp's client.

Each test module starts one server (module scope: the start-up, registry included, is paid
once) with its rule texts written below a temporary cache directory, and opens the documents
it needs with :func:`open_document`, which waits for their first findings.
"""

from __future__ import annotations

import asyncio
import os
import sys
from collections.abc import AsyncIterator
from pathlib import Path
from typing import Any

from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

SERVER = [sys.executable, "-m", "zero", "server"]
TIMEOUT = 30.0


async def start(cache: Path, options: dict[str, Any] | None = None, capabilities: str = "visual-studio-code",
                cwd: Path | None = None) -> LanguageClient:
    """A client connected to a new server process, initialised."""
    env = {**os.environ, "XDG_CACHE_HOME": str(cache)}
    config = ClientServerConfig(server_command=SERVER, server_env=env)
    client = await config.start()
    assert isinstance(client, LanguageClient)

    @client.feature(types.CLIENT_REGISTER_CAPABILITY)
    def register(params: types.RegistrationParams) -> None:
        client.registrations.extend(params.registrations)  # type: ignore[attr-defined]

    client.registrations = []  # type: ignore[attr-defined]
    _record(client)
    _record_responses(client)
    await client.initialize_session(types.InitializeParams(
        capabilities=client_capabilities(capabilities),
        root_uri=(cwd or Path.cwd()).as_uri(),
        initialization_options={"debounce": 20, **(options or {})}))
    return client


async def stop(client: LanguageClient) -> None:
    await client.shutdown_session()
    await client.stop()


async def session(cache: Path, **kwargs: Any) -> AsyncIterator[LanguageClient]:
    client = await start(cache, **kwargs)
    yield client
    await stop(client)


def language_of(path: Path) -> str:
    return {".nc": "gcode", ".yaml": "yaml", ".yml": "yaml", ".toml": "toml", ".json": "json"}.get(
        path.suffix.lower(), "plaintext")


def _record(client: LanguageClient) -> None:
    """Keep every published set of findings, in order (pytest-lsp keeps only the latest per URI)."""
    client.published = []  # type: ignore[attr-defined]
    handle = client.protocol._handle_notification

    def handle_and_record(method_name: str, params: Any) -> None:
        if method_name == types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS:
            client.published.append(params)  # type: ignore[attr-defined]
        handle(method_name, params)

    client.protocol._handle_notification = handle_and_record  # type: ignore[method-assign]


def _record_responses(client: LanguageClient) -> None:
    """Keep the answers to requests the client did not make itself (sent with :func:`send_raw`)."""
    client.raw_answers = {}  # type: ignore[attr-defined]
    handle = client.protocol._handle_response

    def handle_and_record(msg_id: Any, result: Any = None, error: Any = None) -> None:
        if isinstance(msg_id, str) and msg_id.startswith("raw-"):
            client.raw_answers[msg_id] = (result, error)  # type: ignore[attr-defined]
            return
        handle(msg_id, result, error)

    client.protocol._handle_response = handle_and_record  # type: ignore[method-assign]


async def send_raw(client: LanguageClient, body: bytes) -> None:
    """Bytes to the server as a message (``Content-Length`` header added), as no well-behaved client would."""
    server = client._server
    assert server is not None and server.stdin is not None
    server.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    await server.stdin.drain()


async def raw_request(client: LanguageClient, method: str, params: Any, msg_id: str) -> tuple[Any, Any]:
    """Send a request whatever its parameters; its (result, error) as the server answers it."""
    import json

    await send_raw(client, json.dumps({"jsonrpc": "2.0", "id": f"raw-{msg_id}", "method": method,
                                       "params": params}).encode())
    return await answer_of(client, f"raw-{msg_id}")


async def answer_of(client: LanguageClient, msg_id: str) -> tuple[Any, Any]:
    """The (result, error) of a request sent with :func:`send_raw` (its id starting with ``raw-``)."""
    loop = asyncio.get_running_loop()
    deadline = loop.time() + TIMEOUT
    answers: dict[str, tuple[Any, Any]] = client.raw_answers  # type: ignore[attr-defined]
    while msg_id not in answers:
        if loop.time() > deadline:
            raise TimeoutError(f"no answer to {msg_id}")
        await asyncio.sleep(0.005)
    return answers[msg_id]


async def diagnostics_after(client: LanguageClient, uri: str, action: Any = None) -> list[types.Diagnostic]:
    """The next findings published for ``uri`` (after ``action()``, if given)."""
    published: list[types.PublishDiagnosticsParams] = client.published  # type: ignore[attr-defined]
    seen = sum(1 for p in published if p.uri == uri)
    if action is not None:
        action()
    loop = asyncio.get_running_loop()
    deadline = loop.time() + TIMEOUT
    while loop.time() < deadline:
        mine = [p for p in published if p.uri == uri]
        if len(mine) > seen:
            return list(mine[seen].diagnostics)
        await asyncio.sleep(0.005)
    raise TimeoutError(f"no findings published for {uri}")


async def open_document(client: LanguageClient, path: Path, text: str | None = None,
                        version: int = 1) -> list[types.Diagnostic]:
    """Open a file (its text from disk unless given) and return its first findings."""
    uri = path.as_uri()
    body = text if text is not None else path.read_bytes().decode("utf-8", "replace")
    return await diagnostics_after(client, uri, lambda: client.text_document_did_open(
        types.DidOpenTextDocumentParams(types.TextDocumentItem(uri, language_of(path), version, body))))


async def change_document(client: LanguageClient, path: Path, text: str, version: int) -> list[types.Diagnostic]:
    uri = path.as_uri()
    return await diagnostics_after(client, uri, lambda: client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                                          [types.TextDocumentContentChangeWholeDocument(text)])))


def close_document(client: LanguageClient, path: Path) -> None:
    client.text_document_did_close(types.DidCloseTextDocumentParams(types.TextDocumentIdentifier(path.as_uri())))


def codes(diagnostics: list[types.Diagnostic]) -> list[tuple[int, str]]:
    """(1-based line, code) of each finding, as zero reports them."""
    return [(d.range.start.line + 1, str(d.code)) for d in diagnostics if d.code is not None]


def apply_edits(text: str, edits: list[types.TextEdit]) -> str:
    """The text with LSP edits applied (positions in UTF-16 units, lines split after LF)."""
    lines = text.split("\n")

    def offset(p: types.Position) -> int:
        if p.line >= len(lines):
            return len(text)
        before = sum(len(x) + 1 for x in lines[: p.line])
        units = 0
        col = 0
        for ch in lines[p.line]:
            if units >= p.character:
                break
            units += 2 if ord(ch) > 0xFFFF else 1
            col += 1
        return before + col

    for e in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        text = text[: offset(e.range.start)] + e.new_text + text[offset(e.range.end):]
        lines = text.split("\n")
    return text


def doc(path: Path) -> types.TextDocumentIdentifier:
    return types.TextDocumentIdentifier(uri=path.as_uri())


def at(line: int, character: int) -> types.Position:
    return types.Position(line=line, character=character)

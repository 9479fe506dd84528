"""Large files through the protocol: the 6,208-entry zero-offset list (97 groups x 32 axes x
versch/inaktiv, as ``benchmarks/workloads.py`` builds it) gets its findings on open and after an
edit, and every request answers on it. How long each takes is measured by
``benchmarks/bench_lsp.py`` (figures in the README), never asserted here.
"""

from __future__ import annotations

import sys
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_asyncio
from lsp_support import change_document, close_document, codes, open_document, session
from lsprotocol import types
from pytest_lsp import LanguageClient

from conftest import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))
from workloads import full_zero_list

pytestmark = [pytest.mark.slow, pytest.mark.asyncio(loop_scope="module")]


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[LanguageClient]:
    async for c in session(tmp_path_factory.mktemp("cache"), options={"debounce": 0}):
        yield c


async def test_the_6208_entry_zero_list_is_served(client: LanguageClient, tmp_path: Path) -> None:
    text = full_zero_list().decode()
    assert text.count(".versch ") + text.count(".inaktiv ") == 6208
    path = tmp_path / "nullp.lis"
    assert codes(await open_document(client, path, text)) == []
    lines = text.split("\n")
    target = next(i for i, x in enumerate(lines) if x.startswith("np_grp[50].achse[7].inaktiv"))
    lines[target] = lines[target].replace(" 0 ", " 7 ", 1)
    assert codes(await change_document(client, path, "\n".join(lines), 2)) == [(target + 1, "R005")]
    ident = types.TextDocumentIdentifier(uri=path.as_uri())
    at = types.Position(line=target, character=2)
    assert await client.text_document_hover_async(types.HoverParams(ident, at)) is not None
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(ident))
    assert symbols and len(symbols) >= 97
    close_document(client, path)


async def test_many_lists_opened_at_once_answer_a_request_before_linting_them(tmp_path: Path) -> None:
    """400 lists opened at once, then one saved (issue 43: with 5,000 the first answer came after
    354 s, none within 600 s after a save): the request is answered before the lints nobody waits
    for, which follow, each list once. Steps counted (publishes before the answer), not time: the
    server linted and published every list before answering, after the opens and after the save."""
    n = 400
    paths = []
    for i in range(n):
        path = tmp_path / f"nullp_{i}.lis"
        path.write_text(f"np_grp[1].achse[0].versch {i}\nEnde\n", encoding="utf-8")
        paths.append(path)
    async for c in session(tmp_path / "cache", options={"debounce": 0}):
        published: list[types.PublishDiagnosticsParams] = c.published  # type: ignore[attr-defined]
        first = types.TextDocumentIdentifier(uri=paths[0].as_uri())
        hover = types.HoverParams(first, types.Position(line=0, character=2))
        for path in paths:
            c.text_document_did_open(types.DidOpenTextDocumentParams(
                types.TextDocumentItem(path.as_uri(), "isg-list", 1, path.read_text(encoding="utf-8"))))
        assert await c.text_document_hover_async(hover) is not None
        assert len(published) < n // 2, len(published)
        await _every_list_published(published, 0, paths)
        since = len(published)
        c.text_document_did_save(types.DidSaveTextDocumentParams(first))
        assert await c.text_document_hover_async(hover) is not None
        assert len(published) - since < n // 2, len(published) - since
        await _every_list_published(published, since, paths)


async def _every_list_published(published: list[types.PublishDiagnosticsParams], since: int,
                                paths: list[Path]) -> None:
    import asyncio

    every = {p.as_uri() for p in paths}
    for _ in range(1200):
        if every <= {p.uri for p in published[since:]}:
            return
        await asyncio.sleep(0.05)
    raise AssertionError(f"{len(every - {p.uri for p in published[since:]})} lists never published")

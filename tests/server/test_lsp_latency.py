"""Large files stay responsive: the time from an edit to its findings, and of the requests, on the
6,208-entry zero-offset list (97 groups x 32 axes x versch/inaktiv, as ``benchmarks/workloads.py``
builds it) and on the vendor's axis list (from the corpus, skipped where it is absent).

The figures are printed (``pytest -s``) and kept in the test report; the bounds asserted are
generous (a slow CI machine must pass), the figures are what the README states.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import AsyncIterator, Awaitable, Callable
from pathlib import Path
from typing import Any

import pytest
import pytest_asyncio
from lsp_support import change_document, close_document, codes, open_document, session
from lsprotocol import types
from pytest_lsp import LanguageClient

from conftest import corpus_dir

pytestmark = [pytest.mark.slow, pytest.mark.asyncio(loop_scope="module")]
ROUNDS = 7


def full_zero_list() -> str:
    """97 groups x 32 axes x (versch, inaktiv) = 6,208 entries (+2), in the vendor's layout with every
    comment style: the list ``benchmarks/workloads.py`` builds for the benchmarks."""
    lines = ["# zero-offset list (generated)", "#", "g53_verfuegbar".ljust(54) + "1", "default_index".ljust(54) + "1"]
    for i in range(97):
        lines.append(f"# G159 = {i}")
        for j in range(32):
            lines.append(f"np_grp[{i}].achse[{j}].versch".ljust(54) + f"{i * 1000 + j}".ljust(14)
                         + "( P-ZERO-00003 : offset")
            style = ("# active", "/* 0 */ ( on", "( P-ZERO-00004")[j % 3]
            lines.append(f"np_grp[{i}].achse[{j}].inaktiv".ljust(54) + "0".ljust(14) + style)
    lines.append("Ende")
    return "\n".join(lines) + "\n"


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[LanguageClient]:
    async for c in session(tmp_path_factory.mktemp("cache"), options={"debounce": 0}):
        yield c


async def timed(step: Callable[[], Awaitable[Any]]) -> tuple[float, Any]:
    t0 = time.perf_counter()
    result = await step()
    return (time.perf_counter() - t0) * 1000, result


def report(name: str, figures: dict[str, list[float]]) -> dict[str, float]:
    medians = {k: statistics.median(v) for k, v in figures.items()}
    print(f"\n{name}: " + ", ".join(f"{k} {v:.0f} ms" for k, v in medians.items()))
    return medians


async def measure(client: LanguageClient, path: Path, text: str, line: int, edit: Callable[[str, int], str],
                  code: str) -> dict[str, float]:
    """Open, then edit (a fault in, a fault out) and ask every request once per round."""
    figures: dict[str, list[float]] = {}
    ms, found = await timed(lambda: open_document(client, path, text))
    figures["open → findings"] = [ms]
    ident = types.TextDocumentIdentifier(uri=path.as_uri())
    position = types.Position(line=line, character=2)
    version = 1
    for i in range(ROUNDS):
        version += 1
        changed = edit(text, i)
        ms, found = await timed(lambda v=version, t=changed: change_document(client, path, t, v))  # type: ignore[misc]
        assert code in {c for _, c in codes(found)}
        figures.setdefault("edit → findings", []).append(ms)
        version += 1
        ms, _ = await timed(lambda v=version: change_document(client, path, text, v))  # type: ignore[misc]
        figures.setdefault("edit back → findings", []).append(ms)
        for name, request in (
            ("hover", lambda: client.text_document_hover_async(types.HoverParams(ident, position))),
            ("completion", lambda: client.text_document_completion_async(types.CompletionParams(ident, position))),
            ("symbols", lambda: client.text_document_document_symbol_async(types.DocumentSymbolParams(ident))),
            ("code actions", lambda: client.text_document_code_action_async(types.CodeActionParams(
                ident, types.Range(start=position, end=position), types.CodeActionContext(diagnostics=[])))),
            ("formatting", lambda: client.text_document_formatting_async(types.DocumentFormattingParams(
                ident, types.FormattingOptions(tab_size=4, insert_spaces=True)))),
        ):
            ms, _ = await timed(request)
            figures.setdefault(name, []).append(ms)
    close_document(client, path)
    return report(path.name, figures)


async def test_the_6208_entry_zero_list_stays_responsive(client: LanguageClient, tmp_path: Path) -> None:
    text = full_zero_list()
    assert text.count(".versch ") + text.count(".inaktiv ") == 6208
    lines = text.split("\n")
    target = next(i for i, x in enumerate(lines) if x.startswith("np_grp[50].achse[7].inaktiv"))

    def edit(source: str, i: int) -> str:
        changed = list(lines)
        changed[target] = changed[target].replace(" 0 ", f" {7 + i} ", 1)
        return "\n".join(changed)

    figures = await measure(client, tmp_path / "nullp.lis", text, target, edit, "R005")
    assert figures["edit → findings"] < 2000


async def test_the_vendor_axis_list_stays_responsive(client: LanguageClient, tmp_path: Path) -> None:
    source = corpus_dir() / "isg-sdk" / "listen" / "achsmds1.lis"
    if not source.is_file():
        pytest.skip(f"corpus not found at {corpus_dir()} (set ZERO_CORPUS)")
    text = source.read_bytes().decode("cp1252")
    lines = text.split("\n")
    target = next(i for i, x in enumerate(lines) if x.startswith("kenngr.swe_pos"))

    def edit(source_text: str, i: int) -> str:
        changed = list(lines)
        changed[target] = "kenngr.swe_pos -99999999999"
        return "\n".join(changed)

    figures = await measure(client, tmp_path / "achsmds1.lis", text, target, edit, "R004")
    assert figures["edit → findings"] < 1000

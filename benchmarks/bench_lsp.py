#!/usr/bin/env python3
"""Latency of ``zero server`` through the protocol, whole process, as an editor sees it.

A real client (pytest-lsp's, so ``pip install -e '.[test]'``) starts ``python -m zero server``
with no debounce, opens a list, then ROUNDS times edits a fault in and out and asks hover,
completion, symbols, code actions and formatting once each; it prints the median of each step.
Lists: the 6,208-entry zero-offset list (97 groups x 32 axes x versch/inaktiv, as
``benchmarks/workloads.py`` builds it) and the vendor's axis list from ``../shared/corpus``
(skipped where absent). Prints figures; it passes or fails nothing.

Then a pathological list, 60,000 faulty entries (50,002 findings: zero reports at most 10,000 of
one code in one file, so five kinds of fault: R001, R004, R005, R007, S004), with the cap on the
findings published per file on (``maxFindings`` 2000, the default) and off (0): open and edit to
findings, and the size of one publish as JSON.

``--many N``: only N small lists opened at once, then one saved: the first answers after each.

usage: python benchmarks/bench_lsp.py [--rounds N] [--cap-only] [--many N]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import statistics
import sys
import tempfile
import time
from collections.abc import Awaitable, Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT / "tests" / "server")]  # the protocol helpers the tests use

from lsp_support import (  # noqa: E402
    change_document,
    close_document,
    codes,
    open_document,
    session,
)
from lsprotocol import types  # noqa: E402
from pytest_lsp import LanguageClient  # noqa: E402
from workloads import full_zero_list  # noqa: E402

CORPUS = ROOT.parent / "shared" / "corpus"
ROUNDS = 7


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
        if code not in {c for _, c in codes(found)}:
            raise SystemExit(f"{path.name}: the edit did not give {code}")
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




FAULTS = ("np_grp[1].achse[0].versch 100", "np_grp[1].achse[1].inaktiv 7", "np_grp[1].achse[2].versch x",
          "np_grp[1].achse[3]. versch 1", "np_grp[1].achse[4].fooo 1", "np_grp[1].achse[5].versch 99999999999")


def publish_bytes(client: LanguageClient, path: Path) -> int:
    """The size of the last publish for ``path`` as JSON (as the server wrote it, near enough)."""
    published: list[types.PublishDiagnosticsParams] = client.published  # type: ignore[attr-defined]
    last = next(p for p in reversed(published) if p.uri == path.as_uri())
    return len(json.dumps(client.protocol._converter.unstructure(last)).encode("utf-8"))


async def measure_cap(folder: Path, cap: int) -> dict[str, float]:
    """A list with 50,002 findings: open and edit to findings, with ``maxFindings`` ``cap``."""
    text = "".join(FAULTS[i % len(FAULTS)] + "\n" for i in range(60_000))
    path = folder / f"viele-{cap}.lis"
    figures: dict[str, list[float]] = {}
    async for client in session(folder / f"cache-{cap}", options={"debounce": 0, "maxFindings": cap}):
        ms, found = await timed(lambda c=client: open_document(c, path, text))  # type: ignore[misc]
        figures["open → findings"] = [ms]
        figures["published"] = [len(found)]
        figures["publish JSON MB"] = [publish_bytes(client, path) / 1e6]
        for v in range(2, 2 + ROUNDS):
            changed = text.replace(" 100\n", f" {v}00\n", 1)  # the first entry's value
            ms, found = await timed(lambda c=client, v=v, t=changed: change_document(c, path, t, v))  # type: ignore[misc]
            figures.setdefault("edit → findings", []).append(ms)
        close_document(client, path)
    medians = {k: statistics.median(v) for k, v in figures.items()}
    print(f"\n60,000 faulty entries (50,002 findings), maxFindings {cap or 'off (0)'}: open → findings "
          f"{medians['open → findings']:.0f} ms, edit → findings {medians['edit → findings']:.0f} ms, "
          f"{medians['published']:.0f} published, {medians['publish JSON MB']:.2f} MB of JSON per publish")
    return medians


async def measure_many(folder: Path, n: int) -> dict[str, float]:
    """``n`` lists opened at once (an editor restoring a session, a "open all" of a fleet's folder),
    then one saved (every open document is linted again): how long the first hover waits after the
    last open, and after the save (issue 43: 5,000 lists, 354 s to the first answer, none within
    600 s after a save)."""
    many = folder / "many"
    many.mkdir()
    paths = []
    for i in range(n):
        path = many / f"nullp_{i}.lis"
        path.write_text(f"np_grp[1].achse[0].versch {i}\nnp_grp[1].achse[1].inaktiv 7\nEnde\n", encoding="utf-8")
        paths.append(path)
    figures: dict[str, float] = {}
    async for client in session(folder / "cache-many", options={"debounce": 0}):
        first = types.TextDocumentIdentifier(uri=paths[0].as_uri())
        hover = types.HoverParams(first, types.Position(line=0, character=2))
        t0 = time.perf_counter()
        for path in paths:
            client.text_document_did_open(types.DidOpenTextDocumentParams(
                types.TextDocumentItem(path.as_uri(), "isg-list", 1, path.read_text(encoding="utf-8"))))
        ms, _ = await timed(lambda c=client, h=hover: c.text_document_hover_async(h))  # type: ignore[misc]
        figures["open all → first hover answered"] = (time.perf_counter() - t0) * 1000
        figures["hover after the opens"] = ms
        published: list[types.PublishDiagnosticsParams] = client.published  # type: ignore[attr-defined]
        since = len(published)
        client.text_document_did_save(types.DidSaveTextDocumentParams(first))
        ms, _ = await timed(lambda c=client, h=hover: c.text_document_hover_async(h))  # type: ignore[misc]
        figures["save → next hover answered"] = ms
        t0 = time.perf_counter()
        every = {p.as_uri() for p in paths}
        while not every <= {p.uri for p in published[since:]}:
            await asyncio.sleep(0.05)
        figures["… and every list linted again"] = (time.perf_counter() - t0) * 1000 + ms
    print(f"\n{n} lists open at once: " + ", ".join(f"{k} {v:.0f} ms" for k, v in figures.items()))
    return figures


async def main(rounds: int, cap_only: bool = False, many: int = 0) -> None:
    global ROUNDS
    ROUNDS = rounds
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        if many:
            await measure_many(folder, many)
            return
        await measure_cap(folder, 2000)
        await measure_cap(folder, 0)
        if cap_only:
            return
        async for client in session(folder / "cache", options={"debounce": 0}):
            text = full_zero_list().decode()
            lines = text.split("\n")
            target = next(i for i, x in enumerate(lines) if x.startswith("np_grp[50].achse[7].inaktiv"))

            def zero_edit(_source: str, i: int, lines: list[str] = lines, target: int = target) -> str:
                changed = list(lines)
                changed[target] = changed[target].replace(" 0 ", f" {7 + i} ", 1)
                return "\n".join(changed)

            await measure(client, folder / "nullp.lis", text, target, zero_edit, "R005")
            source = CORPUS / "isg-sdk" / "listen" / "achsmds1.lis"
            if not source.is_file():
                print(f"\n(the vendor's axis list is not at {source}: skipped)")
                continue
            axis = source.read_bytes().decode("cp1252")
            axis_lines = axis.split("\n")
            at = next(i for i, x in enumerate(axis_lines) if x.startswith("kenngr.swe_pos"))

            def axis_edit(_source: str, _i: int, axis_lines: list[str] = axis_lines, at: int = at) -> str:
                changed = list(axis_lines)
                changed[at] = "kenngr.swe_pos -99999999999"
                return "\n".join(changed)

            await measure(client, folder / "achsmds1.lis", axis, at, axis_edit, "R004")


if __name__ == "__main__":
    a = argparse.ArgumentParser()
    a.add_argument("--rounds", type=int, default=ROUNDS)
    a.add_argument("--cap-only", action="store_true", help="only the 50,000-finding list, cap on and off")
    a.add_argument("--many", type=int, default=0, metavar="N", help="only N lists open at once, then a save")
    args = a.parse_args()
    asyncio.run(main(args.rounds, args.cap_only, args.many))

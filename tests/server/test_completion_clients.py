"""Completion items as the common clients use them, each client's matching and insertion written
out from its source: Neovim's omnifunc (0.7 to 0.9), nvim-cmp, eglot (1.9 and Emacs 29), Helix and
VS Code. Each takes the items as sent (JSON), finds the word it completes, keeps the items that
match it and applies the one chosen; the line must read as the key, the value or the name, never
with the text typed twice. tests/server/test_nvim.py and test_emacs.py do the same in the real
editors where they are installed; Helix and VS Code are not installable here, so their set-up
(``editors/helix/languages.toml``) is checked by starting the server it names.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from lsprotocol.converters import get_converter

from conftest import ROOT, builtin_registry
from zero.server import completion
from zero.server.documents import Analysis, Projects

CONVERTER = get_converter()


def analyse(text: str, name: str) -> Analysis:
    return Projects(lambda desc: builtin_registry()).analyse(f"untitled:{name}", 1, text)


def items_at(text: str, name: str, typed: str) -> tuple[str, list[dict[str, Any]]]:
    """The line typed at the end of ``text`` and the items for the cursor after it, as JSON."""
    lines = text.split("\n")
    a = analyse("\n".join([*lines, typed]), name)
    result = completion.completion(a, len(lines), len(typed), snippets=False)
    sent = json.loads(json.dumps(CONVERTER.unstructure(result)))
    return typed, sent["items"]


def apply(line: str, item: dict[str, Any]) -> str:
    edit = item["textEdit"]
    start, end = edit["range"]["start"]["character"], edit["range"]["end"]["character"]
    return line[:start] + edit["newText"] + line[end:]


def word_start(line: str, cursor: int, chars: str) -> int:
    """Where the run of ``chars`` (a regex class) before the cursor starts."""
    m = re.search(f"[{chars}]*$", line[:cursor])
    assert m is not None
    return m.start()


# --------------------------------------------------------------------------- the clients


def neovim_omnifunc(line: str, items: list[dict[str, Any]]) -> dict[str, str]:
    """Neovim 0.7-0.9 ``vim.lsp.omnifunc``: the start is the items' common textEdit start where no item
    has a filterText, else the keyword before the cursor ('iskeyword' @,48-57,_,192-255); the word
    of an item is its textEdit's newText, kept if it (or its filterText) starts with the text from
    the start; ``complete()`` puts the word there."""
    cursor = len(line)
    starts = {i["textEdit"]["range"]["start"]["character"] for i in items
              if "filterText" not in i and "textEdit" in i}
    start = starts.pop() if len(starts) == 1 else word_start(line, cursor, r"A-Za-z0-9_\xc0-\xff")
    prefix = line[start:cursor]
    return {i["label"]: line[:start] + i["textEdit"]["newText"] for i in items
            if (i.get("filterText") or i["textEdit"]["newText"]).startswith(prefix)}


def nvim_cmp(line: str, items: list[dict[str, Any]]) -> dict[str, str]:
    """nvim-cmp's LSP source: the input runs from the textEdit's start (where it lies before the keyword),
    matched at its beginning against filterText or label; the textEdit is applied."""
    cursor = len(line)
    offset = word_start(line, cursor, r"A-Za-z0-9_")
    out = {}
    for i in items:
        start = min(offset, i["textEdit"]["range"]["start"]["character"])
        typed = line[start:cursor].lower()
        if (i.get("filterText") or i["label"]).lower().startswith(typed):
            out[i["label"]] = apply(line, i)
    return out


# Emacs's word and symbol characters of a plain mode (fundamental-, text-, prog-mode, zero.el's modes)
EMACS_SYMBOL = r"A-Za-z0-9_$%&*+\-/<=>|"


def eglot(line: str, items: list[dict[str, Any]]) -> dict[str, str]:
    """eglot 1.9 (Emacs 28) and 1.12 (Emacs 29): the symbol before point is matched, as a prefix, against
    each item's filterText or "proxy" (the label, or insertText where given); the chosen proxy is
    inserted, taken out again and the textEdit applied."""
    start = word_start(line, len(line), EMACS_SYMBOL)
    probe = line[start:]
    out = {}
    for i in items:
        proxy = i.get("insertText") or i["label"]
        if (i.get("filterText") or proxy).startswith(probe):
            out[i["label"]] = apply(line, i)
    return out


def fuzzy(word: str, text: str) -> bool:
    """The letters of ``word`` in ``text`` in order (Helix's and VS Code's matching, reduced)."""
    rest = iter(text.lower())
    return all(ch in rest for ch in word.lower())


def helix(line: str, items: list[dict[str, Any]]) -> dict[str, str]:
    """Helix: the word characters (letters, digits, `_`) before the cursor, matched fuzzily against
    filterText or label; the textEdit applied."""
    word = line[word_start(line, len(line), r"A-Za-z0-9_"):]
    return {i["label"]: apply(line, i) for i in items if fuzzy(word, i.get("filterText") or i["label"])}


def vscode(line: str, items: list[dict[str, Any]]) -> dict[str, str]:
    """VS Code: the text of the edit's range up to the cursor, matched against filterText or label
    (fuzzily, its first character at the start); the textEdit applied."""
    out = {}
    for i in items:
        typed = line[i["textEdit"]["range"]["start"]["character"]:]
        label = i.get("filterText") or i["label"]
        if not typed or (label[:1].lower() == typed[:1].lower() and fuzzy(typed, label)):
            out[i["label"]] = apply(line, i)
    return out


CLIENTS = {"neovim": neovim_omnifunc, "nvim-cmp": nvim_cmp, "eglot": eglot, "helix": helix, "vscode": vscode}


@dataclass
class Case:
    name: str
    text: str
    typed: str
    chosen: str  # the line after the item is taken
    clients: tuple[str, ...] = tuple(CLIENTS)


ZERO = "g53_verfuegbar 1\nnp_grp[1].achse[0].versch 100"
CASES = [
    Case("nullp.lis", ZERO, "np_grp[1].achse[0].ve", "np_grp[1].achse[0].versch"),
    Case("nullp.lis", ZERO, "np_grp[1].achse[0].", "np_grp[1].achse[0].inaktiv"),
    Case("nullp.lis", ZERO, "np_grp[1].achse[1].in", "np_grp[1].achse[1].inaktiv"),
    Case("nullp.lis", ZERO, "np_grp[2].ach", "np_grp[2].achse[0].versch"),
    Case("nullp.lis", ZERO, "default_i", "default_index"),
    Case("nullp.lis", ZERO, "", "default_index"),
    Case("achse.lis", "kenngr.achs_typ ACHSTYP_TRANSLATOR", "kenngr.swe_beh", "kenngr.swe_behaviour"),
    Case("achse.lis", "", "kenngr.swe_behaviour WAR", "kenngr.swe_behaviour WARNING"),
    Case("p.nc", "N10 G01 X1", "N20 #MA", "N20 #MACHINE DATA ["),
    Case("p.nc", "", "N10 #MACHINE DATA SYN [AX=X P-AXIS-0020", "N10 #MACHINE DATA SYN [AX=X P-AXIS-00209="),
    Case("p.nc", "", 'N10 #MACHINE DATA [AX=X AXPARAM="kenngr.swe_po',
         'N10 #MACHINE DATA [AX=X AXPARAM="kenngr.swe_pos'),
]


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c.name}:{c.typed or '(nothing)'}")
@pytest.mark.parametrize("client", list(CLIENTS))
def test_each_client_completes_without_doubling(case: Case, client: str) -> None:
    line, items = items_at(case.text, case.name, case.typed)
    assert items, "no items"
    assert all("filterText" not in i for i in items)  # the label is (Neovim 0.7 then starts at the edit)
    offered = CLIENTS[client](line, items)
    assert case.chosen in offered.values(), (client, sorted(offered.values())[:8], [i["label"] for i in items][:8])


def test_an_item_starts_at_the_word_the_clients_complete() -> None:
    _, items = items_at(ZERO, "nullp.lis", "np_grp[1].achse[0].ve")
    (versch,) = (i for i in items if i["label"] == "versch")
    assert versch["textEdit"] == {"range": {"start": {"line": 2, "character": 19}, "end": {"line": 2, "character": 21}},
                                  "newText": "versch"}
    # an index typed empty: the key offered fills it, so the item replaces all that is typed (which
    # Helix and VS Code take; the prefix-matching clients find nothing there, as the typed text is no
    # prefix of any key)
    line, items = items_at(ZERO, "nullp.lis", "np_grp[].achse[0].ve")
    assert items and all(i["textEdit"]["range"]["start"]["character"] == 0 and i["label"] == i["textEdit"]["newText"]
                         and i["label"].startswith("np_grp[") for i in items)
    assert "np_grp[2].achse[0].versch" in vscode(line, items).values()


# --------------------------------------------------------------------------------- Helix


def test_helix_languages_toml_starts_zero_for_lists_and_programs() -> None:
    config = tomllib.loads((ROOT / "editors" / "helix" / "languages.toml").read_text(encoding="utf-8"))
    server = config["language-server"]["zero"]
    assert server["command"] == "zero" and server["args"] == ["server"]
    languages = {lang["name"]: lang for lang in config["language"]}
    assert {"lis", "lst"} <= set(languages["isg-list"]["file-types"])
    assert {"nc", "mpf", "spf"} <= set(languages["isg-nc"]["file-types"])
    assert all("zero" in lang["language-servers"] for lang in languages.values())
    # the command as Helix runs it: the `zero` of this environment answers `initialize` with the settings
    exe = shutil.which(server["command"], path=str(Path(sys.executable).parent))
    if exe is None:
        pytest.skip("no `zero` script next to this Python (pip install -e .)")
    request = {"jsonrpc": "2.0", "id": 1, "method": "initialize",
               "params": {"processId": None, "rootUri": None, "capabilities": {},
                          "initializationOptions": server["config"]}}
    messages = [request, {"jsonrpc": "2.0", "id": 2, "method": "shutdown"}, {"jsonrpc": "2.0", "method": "exit"}]
    data = b"".join(b"Content-Length: %d\r\n\r\n%s" % (len(body), body)
                    for body in (json.dumps(m).encode() for m in messages))
    proc = subprocess.run([exe, *server["args"]], input=data, capture_output=True, timeout=60, check=False)
    header = rb"Content-Length: \d+\r\n(?:[^\r\n]+\r\n)*\r\n"
    bodies = [json.loads(b) for b in re.split(header, proc.stdout) if b.strip()]
    (init,) = (b for b in bodies if b.get("id") == 1)
    capabilities = init["result"]["capabilities"]
    assert capabilities["completionProvider"]["triggerCharacters"][:2] == [".", "["]
    assert "textDocumentSync" in capabilities

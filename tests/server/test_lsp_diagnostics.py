"""Findings over the protocol, from the real server process: lists, NC programs, the YAML form,
the project's configuration, the machine's X findings, links to the rules' texts."""

from __future__ import annotations

import json
import shutil
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_asyncio
from lsp_support import change_document, close_document, codes, diagnostics_after, open_document, session
from lsprotocol import types
from pytest_lsp import LanguageClient

from conftest import FIXTURES, zero_cli

pytestmark = [pytest.mark.slow, pytest.mark.asyncio(loop_scope="module")]


@pytest_asyncio.fixture(scope="module", loop_scope="module")
async def client(tmp_path_factory: pytest.TempPathFactory) -> AsyncIterator[LanguageClient]:
    async for c in session(tmp_path_factory.mktemp("cache")):
        yield c


def _cli(path: Path) -> list[tuple[int, str]]:
    """What `zero lint` finds in the file (run in the file's directory, its project's configuration applied)."""
    run = zero_cli("lint", "--output-format", "json", path.name, cwd=path.parent)
    return [(f["line"], f["code"]) for f in json.loads(run.stdout)]


async def test_a_list_gets_the_findings_of_zero_lint_with_exact_ranges(client: LanguageClient,
                                                                        tmp_path: Path) -> None:
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    found = await open_document(client, path)
    assert codes(found) == _cli(path)
    s004 = next(d for d in found if d.code == "S004")
    assert s004.range == types.Range(types.Position(18, 19), types.Position(18, 20))
    assert s004.severity == types.DiagnosticSeverity.Error and s004.source == "zero"
    assert "hint: Remove the whitespace inside the key" in s004.message
    close_document(client, path)


async def test_the_link_of_a_code_is_the_rule_text(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "n.lis"
    path.write_text("np_grp[1].achse[0].versch 99999999999\n")
    found = await open_document(client, path)
    (r004,) = found
    assert r004.code == "R004" and r004.code_description is not None
    href = r004.code_description.href
    assert href.startswith("file://") and href.endswith("/zero/0.1.0/rules/R004.md")
    text = Path(href.removeprefix("file://")).read_text(encoding="utf-8")
    assert text.startswith("# R004 wrong-type") and "What it checks" in text
    close_document(client, path)


async def test_a_duplicate_points_at_the_other_line(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "achse.lis"
    shutil.copy(FIXTURES / "rules" / "R007" / "fail.lis", path)
    found = await open_document(client, path)
    r007 = [d for d in found if d.code == "R007"]
    assert r007 and all(d.related_information for d in r007)
    (related,) = r007[0].related_information  # type: ignore[misc]  # exactly one: the finding's own
    assert related.location.uri == path.as_uri()
    assert related.location.range.start.line < r007[0].range.start.line
    assert related.location.range.start.character == 0 and related.location.range.end.character > 0  # the key
    assert related.message.startswith("first set here to ")
    close_document(client, path)


async def test_findings_follow_the_edits(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "edit.lis"
    path.write_text("np_grp[1].achse[0].versch 100\n")
    assert await open_document(client, path) == []
    found = await change_document(client, path, "np_grp[1].achse[0].versch 100\nnp_grp[1].achse[0].inaktiv 7\n", 2)
    assert codes(found) == [(2, "R005")]
    found = await change_document(client, path, "np_grp[1].achse[0].versch 100\n", 3)
    assert found == []
    close_document(client, path)


async def test_a_nc_program_is_checked(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "bad.nc"
    shutil.copy(FIXTURES / "programs" / "bad.nc", path)
    found = await open_document(client, path)
    assert codes(found) == _cli(path)
    assert {c for _, c in codes(found)} == {"N001", "N002"}
    close_document(client, path)


async def test_the_yaml_form_is_checked_where_zero_wrote_it(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "nullp.yaml"
    path.write_text("np_grp:\n  1:\n    achse:\n      0:\n        versch: 99999999999\n_zero:\n  kind: ZERO\n")
    found = await open_document(client, path)
    assert codes(found) == [(5, "R004")]
    assert found[0].range.start.character == 16
    other = tmp_path / "compose.yaml"  # any other YAML file is none of zero's business
    other.write_text("services:\n  - web\n")
    assert await open_document(client, other) == []
    close_document(client, path)
    close_document(client, other)


async def test_a_yaml_form_that_makes_no_list_is_said_where_it_breaks(client: LanguageClient,
                                                                      tmp_path: Path) -> None:
    path = tmp_path / "broken.yaml"
    path.write_text("np_grp:\n  1:\n    achse: [1, 2]\n_zero:\n  kind: ZERO\n")
    (note,) = await open_document(client, path)  # one S017 finding where the reader stopped, as `zero lint` gives
    assert note.code == "S017" and note.severity == types.DiagnosticSeverity.Error
    assert note.range.start.line == 2
    close_document(client, path)


async def test_the_project_configuration_applies(client: LanguageClient, tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('ignore = ["M003"]\nexclude = ["old/"]\n[severity]\nS004 = "warning"\n')
    path = tmp_path / "nullp.lis"
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", path)
    found = await open_document(client, path)
    assert "M003" not in {d.code for d in found}
    assert {d.severity for d in found if d.code == "S004"} == {types.DiagnosticSeverity.Warning}
    assert codes(found) == _cli(path)
    (tmp_path / "old").mkdir()
    old = tmp_path / "old" / "nullp.lis"
    shutil.copy(path, old)
    assert await open_document(client, old) == []  # excluded, as zero lint leaves it
    close_document(client, path)
    close_document(client, old)


async def test_noqa_in_the_list_hides_a_finding(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "n.lis"
    path.write_text("np_grp[1].achse[0].versch 99999999999  # noqa: R004 -- reviewed\n")
    assert await open_document(client, path) == []
    close_document(client, path)


async def test_a_broken_configuration_is_said_and_nothing_checked(client: LanguageClient, tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('ignroe = ["M003"]\n')
    path = tmp_path / "n.lis"
    path.write_text("np_grp[1].achse[0].versch 99999999999\n")
    (note,) = await open_document(client, path)
    assert "ignroe: unknown key (did you mean `ignore`?)" in note.message
    close_document(client, path)


def _machine(tmp_path: Path) -> Path:
    shutil.copytree(FIXTURES / "machine-layered", tmp_path / "m")
    (tmp_path / "m" / "zero.toml").write_text('[machine]\nstartup = "listen/hochlauf.lis"\n')
    return tmp_path / "m" / "listen"


async def test_the_machine_findings_follow_the_open_lists(client: LanguageClient, tmp_path: Path) -> None:
    listen = _machine(tmp_path)
    zero_list = listen / "nullp.lis"
    found = await open_document(client, zero_list)
    assert (2, "X001") in codes(found)  # G54 X at 500 mm, outside the default list's +-100 mm
    x001 = next(d for d in found if d.code == "X001")
    assert "(achse_vorgabe.lis:3,4)" in x001.message  # where the limits are set, as `zero explain` says
    related = {(r.location.uri.rsplit("/", 1)[-1], r.location.range.start.line) for r in x001.related_information or []}
    assert {name for name, _ in related} == {"achse_vorgabe.lis"}  # the soft limits come from the default list
    # the offset moved inside the limits in the editor, not saved: the finding goes
    text = zero_list.read_text().replace("5000000", "50000")
    found = await change_document(client, zero_list, text, 2)
    assert "X001" not in {d.code for d in found}
    # suppressed on its line, as `zero lint --machine` suppresses it: gone, and the noqa is used
    lines = zero_list.read_text().split("\n")
    lines[1] += "  ( noqa: X001 -- reviewed"
    found = await change_document(client, zero_list, "\n".join(lines), 3)
    assert not {"X001", "Z001"} & {d.code for d in found}
    close_document(client, zero_list)


async def test_the_start_up_list_being_edited_shapes_the_machine(client: LanguageClient, tmp_path: Path) -> None:
    """The start-up list's unsaved text is read as the machine's (X findings as you type in it), and
    so are the other lists the machine is then made of."""
    listen = _machine(tmp_path)
    startup = listen / "hochlauf.lis"
    saved = startup.read_text()
    found = codes(await open_document(client, startup))
    assert found == _cli_machine(listen.parent) == [(7, "X005"), (12, "X005"), (13, "X008")]
    text = saved.replace("./listen/SoE/achse_c.lis", "./listen/achse_z.lis").replace("zahl_mds" + " " * 46 + "3",
                                                                                    "zahl_mds" + " " * 46 + "4")
    text = text.replace("achs_mds[3]                                           ./listen/achse_z.lis",
                        "achs_mds[3]                                           ./listen/achse_q.lis")
    found = codes(await change_document(client, startup, text, 2))
    assert found == [(7, "X005"), (13, "X005")]  # achse_c fixed, the count raised, achse_q missing: unsaved
    assert startup.read_text() == saved
    close_document(client, startup)


def _cli_machine(root: Path) -> list[tuple[int, str]]:
    run = zero_cli("lint", "--output-format", "json", "--machine", "listen/hochlauf.lis", cwd=root)
    return [(f["line"], f["code"]) for f in json.loads(run.stdout) if f["path"].endswith("hochlauf.lis")]


async def test_an_nc_program_is_checked_against_the_machine(client: LanguageClient, tmp_path: Path) -> None:
    listen = _machine(tmp_path)
    program = listen.parent / "part.nc"
    program.write_text("N10 G99 X1600\nM30\n")
    found = await open_document(client, program)
    assert codes(found) == _cli(program)
    close_document(client, program)


async def test_closing_a_document_clears_its_findings(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "n.lis"
    path.write_text("np_grp[1].achse[0].versch 99999999999\n")
    assert await open_document(client, path)
    assert await diagnostics_after(client, path.as_uri(), lambda: close_document(client, path)) == []


async def test_a_file_whose_uri_is_percent_encoded_gets_its_findings(client: LanguageClient, tmp_path: Path) -> None:
    """pygls keeps documents by the decoded URI: a path with a space, `%` or `ä` (and every Windows path,
    `file:///c%3A/…`) was never found open, and got no findings."""
    folder = tmp_path / "Meine Listen %41 ä"
    folder.mkdir()
    path = folder / "nullp #1.lis"
    path.write_text("np_grp[1].achse[0].versch 99999999999\n")
    uri = path.as_uri()
    assert "%20" in uri and "%2541" in uri and "%23" in uri
    assert codes(await open_document(client, path)) == [(1, "R004")]
    assert [p.uri for p in client.published if p.uri.startswith(folder.as_uri())] == [uri]  # as the client wrote it
    hover = await client.text_document_hover_async(types.HoverParams(types.TextDocumentIdentifier(uri=uri),
                                                                     types.Position(line=0, character=3)))
    assert hover is not None
    assert codes(await change_document(client, path, "np_grp[1].achse[0].inaktiv 7\n", 2)) == [(1, "R005")]
    close_document(client, path)


async def test_a_broken_pyproject_points_at_its_line(client: LanguageClient, tmp_path: Path) -> None:
    """The note on the list links to the place in pyproject.toml (it said it only in words)."""
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "x"\n\n[tool.zero]\nselect = ["R"\nignore = 3\n')
    path = tmp_path / "n.lis"
    path.write_text("np_grp[1].achse[0].versch 99999999999\n")
    (note,) = await open_document(client, path)
    assert "pyproject.toml:6:1: not valid TOML" in note.message and note.severity == types.DiagnosticSeverity.Error
    (where,) = note.related_information or []
    assert where.location.uri == (tmp_path / "pyproject.toml").as_uri()
    assert where.location.range.start == types.Position(line=5, character=0)
    (tmp_path / "pyproject.toml").write_text('[tool.zero]\nselect = "R"\n')
    found = await diagnostics_after(client, path.as_uri(), lambda: client.text_document_did_save(
        types.DidSaveTextDocumentParams(types.TextDocumentIdentifier(uri=path.as_uri()))))
    (note,) = found
    assert "tool.zero.select" in note.message
    assert note.related_information and note.related_information[0].location.range.start.line == 1
    close_document(client, path)


async def test_the_server_and_the_command_line_give_identical_findings(client: LanguageClient,
                                                                       tmp_path: Path) -> None:
    """The same file, configuration and machine: the same findings from `zero lint FILE`, from
    `zero lint --machine` (for that list) and from the server: one resolver, one funnel."""
    root = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine-layered", root, ignore=shutil.ignore_patterns("*.json", "*.txt"))
    (root / "zero.toml").write_text('ignore = ["M004"]\nextend-select = ["S012"]\n'
                                    '[per-file-ignores]\n"listen/achse_y.lis" = ["X"]\n'
                                    '[severity]\nX001 = "error"\nR = "info"\n'
                                    '[machine]\nstartup = "listen/hochlauf.lis"\n')
    nullp = root / "listen" / "nullp.lis"
    added = "#np_grp[2].achse[0].versch 1\nnp_grp[3].achse[0].inaktiv 7\nEnde"  # S012, R005
    nullp.write_text(nullp.read_text().replace("Ende", added))
    machine = zero_cli("lint", "--machine", "listen/hochlauf.lis", "--output-format", "json", cwd=root)
    by_list: dict[str, list[tuple[int, str, str]]] = {}
    for f in json.loads(machine.stdout):
        by_list.setdefault(Path(f["path"]).name, []).append((f["line"], f["code"], f["severity"]))
    severities = {types.DiagnosticSeverity.Error: "error", types.DiagnosticSeverity.Warning: "warning",
                  types.DiagnosticSeverity.Information: "info"}
    seen = set()
    for path in sorted((root / "listen").glob("*.lis")):
        if path.name == "achse_c.lis":  # beside the start-up list, but not the file it names
            continue
        served = [(d.range.start.line + 1, str(d.code), severities[d.severity])  # type: ignore[index]
                  for d in await open_document(client, path)]
        close_document(client, path)
        alone = [(f["line"], f["code"], f["severity"]) for f in json.loads(
            zero_cli("lint", str(path.relative_to(root)), "--output-format", "json", cwd=root).stdout)]
        assert served == alone == by_list.get(path.name, []), path.name
        seen.update(code for _, code, _ in served)
    assert {"X001", "X005", "S012", "R005"} <= seen

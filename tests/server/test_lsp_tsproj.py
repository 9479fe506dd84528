"""The language server on a TwinCAT project: findings at the project's lines, links from each
`tc_virtual_N\\` reference to the block it names (in the project or an independent project file)."""

from __future__ import annotations

from conftest import FIXTURES, builtin_registry
from zero.server import outline
from zero.server.documents import Analysis, Projects

TWINCAT = FIXTURES / "twincat"


def analyse(path) -> Analysis:  # type: ignore[no-untyped-def]
    return Projects(lambda desc: builtin_registry()).analyse(path.resolve().as_uri(), 1, path.read_text())


def test_findings_in_an_open_project_at_the_projects_line() -> None:
    a = analyse(TWINCAT / "project" / "Maschine.tsproj")
    assert [(d.code, d.span.line, d.span.column) for d in a.diagnostics] == [("R001", 112, 1)]


def test_links_from_tc_virtual_references_to_their_blocks() -> None:
    """Before: no link (the references are no paths on disk)."""
    path = TWINCAT / "project" / "Maschine.tsproj"
    a = analyse(path)
    links = outline.document_links(a)
    lines = path.read_text().split("\n")
    got = {lines[link.range.start.line][link.range.start.character:link.range.end.character]: link.target
           for link in links}
    assert len(got) == 10
    target = got["tc_virtual_12\\achsmds2.lis"]
    assert target is not None and target.endswith("Maschine.tsproj#L105")
    assert '<Data Name="AchsMds" Offset="12">' in lines[104]


def test_links_into_independent_project_files() -> None:
    a = analyse(TWINCAT / "split" / "Split.tsproj")
    targets = sorted(str(link.target).rsplit("/", 1)[1] for link in outline.document_links(a))
    assert targets == ["Kanal_1.xti#L19", "Kanal_1.xti#L24", "Kanal_1.xti#L5", "Split.tsproj#L36", "Y_Achse.xti#L7",
                       "Z_Achse.xti#L7"]

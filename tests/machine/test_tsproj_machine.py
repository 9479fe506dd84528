"""A TwinCAT project as a machine: `tc_virtual_N\\` references resolved to the project's Offset blocks
(the project file and its independent project files), never to a path on disk; hostile variants."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from conftest import FIXTURES
from twincat_projects import big_project
from zero.catalog.registry import Registry
from zero.engine.lint import lint_machine
from zero.machine.model import load_machine
from zero.machine.tsproj import project_blocks

TWINCAT = FIXTURES / "twincat"
PROJECT = TWINCAT / "project" / "Maschine.tsproj"
SPLIT = TWINCAT / "split" / "Split.tsproj"


def found(machine_results: list, code: str | None = None) -> list[tuple[str, str, int, int]]:  # type: ignore[type-arg]
    return [(Path(r.path.split("#")[0]).name, d.code, d.span.line, d.span.column)
            for r in machine_results for d in r.diagnostics if code is None or d.code == code]


def test_a_project_assembles_completely(registry: Registry) -> None:
    """Before: the start-up list could not be read (`<TcSmProject>` is no list)."""
    m = load_machine(PROJECT, registry)
    assert [(n.key, n.status) for n in m.named if n.status != "loaded"] == []
    assert len(m.named) == 10
    assert sorted(m.axes()) == [1, 2, 3, 4]
    assert [len(ch.axes) for ch in m.channels] == [3, 1]
    assert str(m.axis_lists[1].path).endswith("Maschine.tsproj#Y_Achse/AchsMds")
    # channel 2's only path axis is logical axis 4, a spindle (achs_typ 4): the kernel's 21238 (X020)
    assert found(lint_machine(m, registry)) == [("Maschine.tsproj", "R001", 112, 1),
                                                ("Maschine.tsproj", "X020", 68, 55)]


def test_tc_virtual_never_reads_a_path_on_disk(tmp_path: Path, registry: Registry) -> None:
    shutil.copy(PROJECT, tmp_path / "M.tsproj")
    decoy = tmp_path / "tc_virtual_12"
    decoy.mkdir()
    (decoy / "achsmds2.lis").write_text("kopf.achs_nr 99\nEnde\n")
    m = load_machine(tmp_path / "M.tsproj", registry)
    assert sorted(m.axes()) == [1, 2, 3, 4]


def test_independent_project_files(registry: Registry) -> None:
    m = load_machine(SPLIT, registry)
    assert [(n.key, n.status) for n in m.named if n.status != "loaded"] == []
    assert sorted(m.axes()) == [1, 2, 3]
    assert [str(p.path).split("#")[1] for p in m.axis_lists] == [f"{a}_Achse/AchsMds" for a in "XYZ"]
    assert found(lint_machine(m, registry)) == [("Z_Achse.xti", "R001", 14, 1)]


def _variant(tmp_path: Path, old: str, new: str, count: int = 1) -> Path:
    text = PROJECT.read_text()
    assert text.count(old) >= count
    target = tmp_path / "V.tsproj"
    target.write_text(text.replace(old, new, count))
    return target


def test_a_reference_to_an_offset_no_block_has(tmp_path: Path, registry: Registry) -> None:
    path = _variant(tmp_path, "tc_virtual_13\\achsmds3.lis", "tc_virtual_99\\achsmds3.lis")
    m = load_machine(path, registry)
    bad = [n for n in m.named if n.status != "loaded"]
    assert [(n.key, n.status) for n in bad] == [("achs_mds[2]", "missing")]
    assert "none has Offset 99" in bad[0].reason
    assert ("V.tsproj", "X005", 30, 1) in found(lint_machine(m, registry), "X005")


def test_a_block_without_offset(tmp_path: Path, registry: Registry) -> None:
    path = _variant(tmp_path, '<Data Name="AchsMds" Offset="13">', '<Data Name="AchsMds">')
    m = load_machine(path, registry)
    assert [(n.key, n.status) for n in m.named if n.status != "loaded"] == [("achs_mds[2]", "missing")]
    assert sorted(m.axes()) == [1, 2, 4]


def test_two_blocks_with_one_offset(tmp_path: Path, registry: Registry) -> None:
    path = _variant(tmp_path, '<Data Name="AchsMds" Offset="13">', '<Data Name="AchsMds" Offset="12">')
    m = load_machine(path, registry)
    bad = [n for n in m.named if n.status != "loaded"]
    assert [(n.key, n.status) for n in bad] == [("achs_mds[1]", "unreadable"), ("achs_mds[2]", "missing")]
    assert "2 blocks" in bad[0].reason and "V.tsproj:105" in bad[0].reason and "V.tsproj:122" in bad[0].reason


def test_an_independent_project_file_that_is_not_there(tmp_path: Path, registry: Registry) -> None:
    shutil.copytree(SPLIT.parent, tmp_path / "s")
    (tmp_path / "s" / "_Config" / "CNC" / "Y_Achse.xti").unlink()
    _blocks, problems = project_blocks(tmp_path / "s" / "Split.tsproj", lambda p: p.read_bytes())
    assert len(problems) == 1 and "Y_Achse.xti" in problems[0]
    m = load_machine(tmp_path / "s" / "Split.tsproj", registry)
    assert [(n.key, n.status) for n in m.named if n.status != "loaded"] == [("achs_mds[1]", "missing")]


def test_a_50_mb_project_as_a_machine(tmp_path: Path, registry: Registry) -> None:
    path = tmp_path / "Big.tsproj"
    shift = big_project(path)
    m = load_machine(path, registry)
    assert sorted(m.axes()) == [1, 2, 3, 4]
    assert found(lint_machine(m, registry)) == [("Big.tsproj", "R001", 112 + shift, 1),
                                                ("Big.tsproj", "X020", 68 + shift, 55)]


def test_what_twincat_says_of_each_item_is_part_of_the_machine(registry: Registry) -> None:
    """DriveType, Spindle and the item names, shown by `zero show --machine` (summary["twincat"])."""
    import io

    from zero.machine.effective import summary
    from zero.output.tables import render_effective

    m = load_machine(PROJECT, registry)
    said = summary(m)
    items = said["twincat"]
    assert isinstance(items, dict)
    assert items["achs_mds[3]"] == {"item": "C_Spindel", "element": "C_Spindel/AchsMds", "DriveType": "4",
                                    "Spindle": "true"}
    assert items["sda_mds[1]"] == {"item": "Kanal_2", "element": "Kanal_2/SdaMds"}
    out = io.StringIO()
    render_effective(said, [], out)
    assert "#   achs_mds[3]: TwinCAT item C_Spindel (C_Spindel/AchsMds): DriveType 4, Spindle true\n" in out.getvalue()
    plain = summary(load_machine(FIXTURES / "twincat" / "machine" / "startup" / "hochlauf.lis", registry))
    assert "twincat" not in plain


def test_two_projects_compared_as_machines(tmp_path: Path, registry: Registry) -> None:
    from zero.engine.queries import machine_changes

    other = _variant(tmp_path, "kenngr.swe_pos                                        12000000",
                     "kenngr.swe_pos                                        13000000")
    changes = machine_changes(load_machine(PROJECT, registry), load_machine(other, registry), registry)
    assert [(c.group, c.key) for c in changes] == [("axis 1 (achs_mds[0]): kenngr", "kenngr.swe_pos")]


def test_git_diff_of_two_revisions_of_a_project_through_textconv(tmp_path: Path) -> None:
    """Issue 37: `git diff` of two revisions of a project, with `zero show --textconv --machine` as the
    textconv docs/machines.md gives, shows the one changed value and nothing of git's temporary
    folders (without --textconv every line named the temporary copy and differed)."""
    repo = tmp_path / "repo"
    repo.mkdir()
    shutil.copy(PROJECT, repo / "Maschine.tsproj")
    (repo / ".gitattributes").write_text("*.tsproj diff=zeromachine\n", encoding="utf-8")
    zero = f"{sys.executable} -m zero"
    env = {**os.environ, "GIT_CONFIG_NOSYSTEM": "1", "HOME": str(tmp_path), "GIT_AUTHOR_NAME": "t",
           "GIT_AUTHOR_EMAIL": "t@t", "GIT_COMMITTER_NAME": "t", "GIT_COMMITTER_EMAIL": "t@t"}

    def git(*args: str) -> str:
        return subprocess.run(["git", "-C", str(repo), *args], env=env, check=True, capture_output=True,
                              text=True, timeout=120).stdout

    git("init", "-q")
    git("config", "diff.zeromachine.textconv", f"{zero} show --textconv --machine")
    git("add", "-A")
    git("commit", "-qm", "one")
    text = (repo / "Maschine.tsproj").read_text(encoding="utf-8")
    lines = text.splitlines(keepends=True)
    assert "kenngr.swe_pos" in lines[110] and "12000000" in lines[110]
    lines[110] = lines[110].replace("12000000", "13000000")
    (repo / "Maschine.tsproj").write_text("".join(lines), encoding="utf-8")
    git("commit", "-qam", "two")
    out = git("diff", "HEAD~1", "HEAD")
    changed = [line for line in out.splitlines() if line[:1] in "+-" and line[:3] not in ("+++", "---")]
    assert [line.split()[:3] for line in changed] == [["-kenngr.swe_pos", "=", "12000000"],
                                                      ["+kenngr.swe_pos", "=", "13000000"]]
    assert all("Maschine.tsproj:111" in line for line in changed)

"""One finished Settings per file (issue 39 A): the resolver answers "what applies to this file"
once, with the command line laid over the configuration, and is made in one place.

Each case here was a wrong answer or a missing answer on the old main."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_cli
from zero.catalog.registry import Registry
from zero.engine.lint import LintOptions
from zero.engine.project import Common, Settings, open_project, shown_path

MACHINE = FIXTURES / "machine"






def test_settings_hold_every_answer_of_a_file(tmp_path: Path, registry: Registry) -> None:
    (tmp_path / "zero.toml").write_text('kernel = "V3.1.3074"\nencoding = {"old/*.lis" = "cp850"}\n'
                                        '[kind]\n"old/*.lis" = "axis"\n[per-file-ignores]\n"old/*.lis" = ["R"]\n'
                                        '[machine]\nstartup = "listen/hochlauf.lis"\n')
    project = open_project(lambda _d: registry, Common(param_desc=None, kernel="V3.1.3079"),
                           cli=LintOptions(select=("R005",)))
    s = project.settings(tmp_path / "old" / "a.lis")
    assert isinstance(s, Settings)
    assert (s.encoding, s.kind, s.release, s.root, s.registry) == ("cp850", "AXIS", "V3.1.3079", tmp_path, registry)
    assert s.config.path == str(tmp_path / "zero.toml")  # as a Path prints it (no pathlib on the lint path)
    assert s.options.select == ()  # `R` per-file ignore drops R005 though the command line selected it
    assert s.startup == tmp_path / "listen" / "hochlauf.lis"
    assert project.settings(tmp_path / "old" / "a.lis") is s  # resolved once
    other = project.settings(tmp_path / "b.lis")
    assert (other.encoding, other.kind, other.options.select) == (None, None, ("R005",))
    with pytest.raises(AttributeError):
        s.options = LintOptions()  # type: ignore[misc]


def test_forget_keeps_the_command_lines_configuration(tmp_path: Path, registry: Registry) -> None:
    """`--config KEY=VALUE` and `--kernel` stay over the configuration once its files are read again
    (the language server's forget() dropped them)."""
    (tmp_path / "zero.toml").write_text('select = ["R"]\n')
    project = open_project(lambda _d: registry, Common(config=('ignore = ["R002"]',), kernel="V3.1.3079"))
    before = project.settings(tmp_path / "a.lis")
    project.forget()
    after = project.settings(tmp_path / "a.lis")
    assert after is not before
    assert (after.release, after.options.ignore) == ("V3.1.3079", before.options.ignore)
    assert after.release == before.release == "V3.1.3079"


def test_paths_are_shown_relative_below_the_current_directory(tmp_path: Path) -> None:
    assert shown_path(tmp_path / "listen" / "x.lis", tmp_path) == Path("listen/x.lis")
    assert shown_path(tmp_path / "x.lis", tmp_path / "sub") == tmp_path / "x.lis"  # above it: absolute
    assert shown_path("listen/x.lis", None).is_absolute()  # the language server: absolute


# ------------------------------------------------------------------------------ the command line


def _machine(tmp_path: Path, config: str | None) -> Path:
    root = tmp_path / "m"
    shutil.copytree(MACHINE, root, ignore=shutil.ignore_patterns("*.json"))
    if config is not None:
        (root / "pyproject.toml").write_text(config)
    return root


@pytest.mark.slow
def test_a_machine_names_its_files_alike_from_the_configuration_or_the_command_line(tmp_path: Path) -> None:
    """Issue 39: with `[tool.zero.machine] startup` the messages named `/abs/.../listen/achse_y.lis`
    and `working directory /abs/...`; with `--machine listen/hochlauf.lis` `listen/achse_y.lis` and
    `working directory .`."""
    root = _machine(tmp_path, '[tool.zero.machine]\nstartup = "listen/hochlauf.lis"\n')

    def messages(*args: str) -> dict[tuple[str, str, int], str]:
        run = zero_cli("lint", *args, "--output-format", "json", cwd=root)
        return {(d["path"], d["code"], d["line"]): d["message"] for d in json.loads(run.stdout)
                if d["code"][0] == "X"}

    configured = messages("listen")
    named = messages("--machine", "listen/hochlauf.lis")
    shared = set(configured) & set(named)
    assert any(code == "X004" for _, code, _ in shared) and any(code == "X005" for _, code, _ in shared)
    assert {k: configured[k] for k in shared} == {k: named[k] for k in shared}
    assert not any(str(root) in m for m in configured.values()), configured
    for command in (("limits",), ("explain", "kenngr.swe_pos"), ("show", "--machine", "listen/hochlauf.lis")):
        run = zero_cli(*command, cwd=root)
        assert str(root) not in run.stdout + run.stderr, (command, run)
    explained = zero_cli("explain", "kenngr.swe_pos", cwd=root)
    assert explained.stdout.startswith("# machine listen/hochlauf.lis: working directory .,"), explained.stdout

"""Configuration parity with ruff, each test after ruff's documented behaviour (its settings
reference and "Rule selection"): which rules run for a file, from the configuration files, the
files they `extend`, inline `--config KEY=VALUE` and the command line."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from zero.engine.config import ConfigFinder, inline_config, is_inline, parse_config
from zero.engine.discovery import collect_files
from zero.engine.lint import LintOptions, layered_selection, selected_rules
from zero.errors import ZeroError
from zero.rules import RULES


def _codes(tmp_path: Path, toml: str, file: str = "a.lis", cli: LintOptions | None = None,
           overrides: tuple[str, ...] = ()) -> set[str]:
    (tmp_path / "zero.toml").write_text(toml)
    target = tmp_path / file
    target.parent.mkdir(parents=True, exist_ok=True)
    cfg = ConfigFinder(overrides=overrides).for_path(target, directory=False)
    return set(selected_rules(cfg.options_for(target, cli or LintOptions())))


def test_command_line_select_drops_the_configured_extend_select(tmp_path: Path) -> None:
    """ruff: "CLI options are given higher priority … Ruff uses the highest-priority select as the
    basis for the rule set": a configured extend-select does not survive --select."""
    codes = _codes(tmp_path, 'extend-select = ["S012"]\n', cli=LintOptions(select=("R",)))
    assert "S012" not in codes and codes == {c for c in RULES if c.startswith("R")}


def test_command_line_select_is_the_whole_selection(tmp_path: Path) -> None:
    """ruff's own example: select = ["E", "F"], ignore = ["F401"] in the file and `--select F401`
    on the command line enforce F401 and no other rule."""
    codes = _codes(tmp_path, 'select = ["R", "M"]\nignore = ["R005"]\n', cli=LintOptions(select=("R005",)))
    assert codes == {"R005"}


def test_a_per_file_ignore_of_a_prefix_beats_a_selected_full_code(tmp_path: Path) -> None:
    """per-file-ignores drop what they match whatever selected it (`"old/*.lis" = ["R"]` against
    `select = ["R005"]`)."""
    toml = 'select = ["R005"]\n[per-file-ignores]\n"old/*.lis" = ["R"]\n'
    assert _codes(tmp_path, toml, "old/a.lis") == set()
    assert _codes(tmp_path, toml, "new/a.lis") == {"R005"}


def test_extend_select_on_the_command_line_is_a_later_layer(tmp_path: Path) -> None:
    """A layer without select changes only what its selectors match: --extend-select M re-enables
    the M003 the file ignores (the command line is the later layer), --ignore adds to the file's."""
    toml = 'ignore = ["M003"]\n'
    assert "M003" not in _codes(tmp_path, toml)
    assert "M003" in _codes(tmp_path, toml, cli=LintOptions(extend_select=("M",)))
    assert not {"M003", "M001"} & _codes(tmp_path, toml, cli=LintOptions(ignore=("M001",)))


def test_within_a_layer_the_longer_prefix_wins_and_ignore_wins_ties() -> None:
    only_r005 = layered_selection([(("R",), (), ("R0",)), ((), ("R005",), ())])
    assert selected_rules(only_r005) == {"R005": RULES["R005"].severity}
    tie = layered_selection([(("R005",), (), ("R005",))])
    assert selected_rules(tie) == {}


def test_opt_in_rules_only_by_their_full_code() -> None:
    assert "S012" not in selected_rules(layered_selection([(("S",), (), ())]))
    assert "S012" in selected_rules(layered_selection([((), ("S012",), ())]))


def test_extend_ignore_is_ignore(tmp_path: Path) -> None:
    assert "M003" not in _codes(tmp_path, 'extend-ignore = ["M003"]\n')


def test_extend_inherits_and_lays_this_file_over_it(tmp_path: Path) -> None:
    """ruff's `extend`: the base file is read first and this file's settings are merged in; its
    selection is a layer under this file's; its patterns stay relative to its own folder."""
    (tmp_path / "base").mkdir()
    (tmp_path / "base" / "zero.toml").write_text(
        'select = ["R"]\nexclude = ["skip.lis"]\nkernel = "V3.1.3074"\n[per-file-ignores]\n"*.lis" = ["R007"]\n')
    project = tmp_path / "project"
    project.mkdir()
    (project / "zero.toml").write_text('extend = "../base/zero.toml"\nextend-select = ["M001"]\n'
                                       'extend-exclude = ["old/"]\n')
    cfg = ConfigFinder().for_path(project / "a.lis", directory=False)
    codes = set(selected_rules(cfg.options_for(project / "a.lis", LintOptions())))
    assert codes == {c for c in RULES if c.startswith("R") and c != "R007"} | {"M001"}
    assert cfg.kernel == "V3.1.3074"
    assert cfg.excluded(project / "skip.lis") and cfg.excluded(project / "old" / "b.lis")
    assert not cfg.excluded(project / "b.lis")


def test_extend_in_a_circle_is_an_error(tmp_path: Path) -> None:
    (tmp_path / "a.toml").write_text('extend = "b.toml"\n')
    (tmp_path / "b.toml").write_text('extend = "a.toml"\n')
    with pytest.raises(ZeroError, match="circle"):
        parse_config(tmp_path / "a.toml")


def test_extend_exclude_adds_to_exclude(tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('exclude = ["a/"]\nextend-exclude = ["b/"]\n')
    cfg = ConfigFinder().for_path(tmp_path / "x.lis", directory=False)
    assert cfg.excluded(tmp_path / "a" / "x.lis") and cfg.excluded(tmp_path / "b" / "x.lis")
    assert not cfg.excluded(tmp_path / "c" / "x.lis")


def test_inline_config_overrides_the_file(tmp_path: Path) -> None:
    """`--config 'select=["R005"]'`: a KEY = VALUE pair that takes precedence over every file."""
    assert is_inline('select=["R005"]') and not is_inline("zero.toml")
    codes = _codes(tmp_path, 'select = ["M"]\nextend-select = ["S012"]\n', overrides=('select=["R005"]',))
    assert codes == {"R005"}
    with pytest.raises(ZeroError, match="matches no rule code"):
        ConfigFinder(overrides=('select=["Q9"]',))
    with pytest.raises(ZeroError, match="unknown key"):
        inline_config("bogus = 1", parse_config(tmp_path / "zero.toml") or ConfigFinder()._default)


def test_inline_config_on_the_command_line(tmp_path: Path) -> None:
    from conftest import FIXTURES, zero_cli

    bad = FIXTURES / "rules" / "R005" / "fail.lis"
    run = zero_cli("lint", "--isolated", "--config", 'select=["R005"]', "--output-format", "concise", str(bad))
    assert run.stdout.strip() and all(" R005 " in line for line in run.stdout.splitlines()), run.stdout
    none = zero_cli("lint", "--isolated", "--config", 'ignore=["R"]', "--output-format", "concise", str(bad))
    assert " R005 " not in none.stdout
    warn = FIXTURES / "rules" / "M006" / "fail.lis"  # repeated, each a layer over the one before
    both = zero_cli("lint", "--isolated", "--config", 'select=["R005"]', "--config", 'extend-select=["M006"]',
                    "--output-format", "concise", str(bad), str(warn))
    assert {line.split(" ")[1] for line in both.stdout.splitlines()} == {"R005", "M006"}


def test_respect_gitignore_false_walks_ignored_files(tmp_path: Path) -> None:
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    (tmp_path / ".gitignore").write_text("ignored.lis\n")
    (tmp_path / "ignored.lis").write_text("Ende\n")
    (tmp_path / "kept.lis").write_text("Ende\n")
    assert [os.path.basename(p) for p in collect_files([tmp_path])] == ["kept.lis"]
    (tmp_path / "zero.toml").write_text("respect-gitignore = false\n")
    finder = ConfigFinder()
    names = [os.path.basename(p) for p in collect_files(
        [tmp_path], respect_gitignore=lambda d: finder.for_path(d, directory=True).respect_gitignore)]
    assert names == ["ignored.lis", "kept.lis"]

"""Configuration: discovery, precedence, globs, per-file ignores, severities, kinds, errors."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conftest import FIXTURES
from zero.cli.app import app
from zero.engine.config import ConfigFinder, parse_config
from zero.engine.config_file import patterns
from zero.errors import ZeroError

runner = CliRunner()
SEED = (FIXTURES / "seed" / "nullp_3achsen.lis").read_bytes()


def machine(tmp_path: Path, config: str, name: str = "zero.toml") -> Path:
    (tmp_path / "lists" / "old").mkdir(parents=True)
    (tmp_path / "lists" / "nullp.lis").write_bytes(SEED)
    (tmp_path / "lists" / "old" / "nullp.lis").write_bytes(SEED)
    (tmp_path / name).write_text(config)
    return tmp_path


def lint(*args: str, cwd: Path | None = None) -> tuple[int, str, str]:
    p = subprocess.run([sys.executable, "-m", "zero", "lint", "--output-format", "concise", *args],
                       capture_output=True, text=True, cwd=cwd, check=False)
    return p.returncode, p.stdout, p.stderr


def test_globs() -> None:
    assert patterns(("**/nullp*.lis",)).match_file("a/b/nullp_1.lis")
    assert patterns(("**/nullp*.lis",)).match_file("nullp.lis")
    assert patterns(("old/**",)).match_file("old/a/b.lis")


@pytest.mark.parametrize("pattern", ["old/[n]*.lis", "old/", "/old/**", "./old/**", "old", "old/*"])
def test_gitignore_patterns_exclude_a_folder(tmp_path: Path, pattern: str) -> None:
    (tmp_path / "zero.toml").write_text(f'exclude = ["{pattern}"]\n')
    finder = ConfigFinder()
    cfg = finder.for_path(tmp_path / "old" / "nullp.lis")
    assert cfg.excluded(tmp_path / "old" / "nullp.lis"), pattern
    assert not cfg.excluded(tmp_path / "new" / "nullp.lis"), pattern


def test_a_pattern_that_cannot_be_read_is_a_located_error(tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('include = ["*.lis"]\nexclude = ["old/[n*.lis"]\n')
    with pytest.raises(ZeroError, match=r"zero.toml:2: exclude: pattern 'old/\[n\*.lis': `\[` is not closed"):
        parse_config(tmp_path / "zero.toml")


def test_ignore_wins_over_select_at_equal_specificity() -> None:
    from zero.engine.lint import LintOptions, selected_rules

    chosen = selected_rules(LintOptions(select=("S", "R"), ignore=("R",)))
    assert not any(c.startswith("R") for c in chosen) and "S001" in chosen
    assert "R005" in selected_rules(LintOptions(select=("R005",), ignore=("R",)))  # more specific wins


def test_zero_toml_may_be_written_with_the_tool_zero_table(tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('[tool.zero]\nignore = ["M003"]\n')
    cfg = parse_config(tmp_path / "zero.toml")
    assert cfg is not None and cfg.ignore == ("M003",)
    shown = cfg.show()
    assert "[tool.zero]" not in shown and 'ignore = ["M003"]' in shown and str(tmp_path / "zero.toml") in shown


@pytest.mark.slow
def test_ignore_exclude_severity_and_per_file_ignores(tmp_path: Path) -> None:
    root = machine(tmp_path, """
[tool.zero]
ignore = ["M003"]
exclude = ["lists/old/**"]

[tool.zero.severity]
S004 = "info"
""", "pyproject.toml")
    code, out, err = lint(str(root / "lists"))
    assert code == 0, out + err  # S004 is only information now
    assert "old" not in out and out.count("S004 info") == 2 and "M003" not in out
    code, out, _ = lint(str(root / "lists" / "old" / "nullp.lis"))  # named, still excluded
    assert code == 0 and out == ""
    code, out, _ = lint("--isolated", str(root / "lists"))
    assert code == 1 and "old/nullp.lis" in out and "M003" in out
    code, out, _ = lint("--select", "M003", str(root / "lists" / "nullp.lis"))
    assert code == 0 and out.count("M003") == 5  # the command line's select wins
    (root / "zero.toml").write_text('[tool.zero.per-file-ignores]\n"lists/*.lis" = ["S004"]\n'
                                    .replace("[tool.zero.per-file-ignores]", "[per-file-ignores]"))
    code, out, _ = lint(str(root / "lists" / "nullp.lis"))  # zero.toml is closer than pyproject? same dir
    assert "S004" not in out


def test_closest_configuration_wins(tmp_path: Path) -> None:
    root = machine(tmp_path, 'ignore = ["M003"]\n')
    (root / "lists" / ".zero.toml").write_text('ignore = ["S004"]\n')
    _code, out, _ = lint(str(root / "lists" / "nullp.lis"))
    assert "S004" not in out and "M003" in out
    _code, out, _ = lint("--config", str(root / "zero.toml"), str(root / "lists" / "nullp.lis"))
    assert "S004" in out and "M003" not in out


def test_kind_by_glob(tmp_path: Path) -> None:
    root = machine(tmp_path, '[kind]\n"**/nullp*.lis" = "axis"\n')
    _code, out, _ = lint(str(root / "lists" / "nullp.lis"))
    assert "R001" in out  # zero-offset keys are unknown in an axis list


@pytest.mark.parametrize(("text", "line", "words"), [
    ('select = ["R005"]\nignroe = ["M003"]\n', 2, "tool.zero.ignroe: unknown key (did you mean `ignore`?)"),
    ('select = ["Q1"]\n', 1, "'Q1' matches no rule code"),
    ('select = "R005"\n', 1, "expected a list of rule codes"),
    ('[severity]\nR005 = "fatal"\n', 2, "'fatal' is not a severity"),
    ('[kind]\n"*.lis" = "lathe"\n', 2, "'lathe' is not a list kind"),
    ("select = [\n", None, "not valid TOML"),
])
def test_errors_name_file_line_and_key(tmp_path: Path, text: str, line: int | None, words: str) -> None:
    path = tmp_path / "pyproject.toml"
    path.write_text("[tool.zero]\n" + text.replace("[severity]", "[tool.zero.severity]")
                    .replace("[kind]", "[tool.zero.kind]"))
    with pytest.raises(ZeroError) as info:
        parse_config(path)
    assert words in str(info.value)
    if line is not None:
        assert str(info.value).startswith(f"{path}:{line + 1}:")
    code, _, err = lint(str(path.parent))
    assert code == 2 and words in err


def test_pyproject_without_tool_zero_is_skipped(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    (tmp_path / "sub").mkdir()
    assert parse_config(tmp_path / "pyproject.toml") is None
    assert ConfigFinder().for_path(tmp_path / "sub" / "a.lis").path is None or \
        ConfigFinder().for_path(tmp_path / "sub" / "a.lis").path != tmp_path / "pyproject.toml"


def test_config_show(tmp_path: Path) -> None:
    root = machine(tmp_path, 'ignore = ["M003"]\n[severity]\nR007 = "error"\n')
    result = runner.invoke(app, ["config", "--show", str(root / "lists" / "nullp.lis")])
    assert result.exit_code == 0
    assert f"# from {root / 'zero.toml'}" in result.output
    assert 'ignore = ["M003"]' in result.output and 'R007 = "error"' in result.output
    bad = runner.invoke(app, ["config", "--config", str(root / "nope.toml")])
    assert bad.exit_code == 2


def test_directory_walk_respects_gitignore(tmp_path: Path) -> None:
    import shutil

    if shutil.which("git") is None:
        pytest.skip("git not installed")
    root = machine(tmp_path, "")
    (root / ".gitignore").write_text("lists/old/\n")
    subprocess.run(["git", "init", "-q"], cwd=root, check=True)
    _code, out, _ = lint(str(root / "lists"))
    assert "old" not in out and "lists/nullp.lis" in out
    _code, out, _ = lint(str(root / "lists" / "old" / "nullp.lis"))  # named: linted
    assert "old/nullp.lis" in out


def test_a_toml_error_in_the_configuration_is_located(tmp_path: Path) -> None:
    """tomllib says where only in its message; zero's error carries the line and column."""
    path = tmp_path / "pyproject.toml"
    path.write_text('[tool.zero]\nselect = ["R0\nignore = 1\n')
    with pytest.raises(ZeroError) as caught:
        parse_config(path)
    assert (caught.value.line, caught.value.column) == (2, 14)
    assert str(caught.value).startswith(f"{path}:2:14: not valid TOML")

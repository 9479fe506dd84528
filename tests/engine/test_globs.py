"""zero's own gitignore-style matcher (zero.engine.globs) answers as pathspec's GitIgnoreSpec, for
generated patterns and paths and for the documented ones; what it leaves to pathspec is handed to it;
and a lint in a project whose zero.toml has patterns no longer imports pathspec (issue 40, start-up)."""

from __future__ import annotations

import json
import os
import re
import warnings
from pathlib import Path

import pathspec
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pathspec.patterns.gitignore.spec import GitIgnoreSpecPattern

from conftest import zero_modules
from zero.engine.config_file import patterns
from zero.engine.globs import GlobSpec, translate
from zero.errors import ZeroError

_TOKENS = ["*", "**", "?", "[a-c]", "[!x]", "[^b]", "[x-a]", "[]a]", "[", "]", "/", "!", "\\", ".", " ", "#",
           "a", "b", "x", "lis", ".lis", "-"]
_PATTERN = st.lists(st.sampled_from(_TOKENS), max_size=8).map("".join)
_SEGMENT = st.lists(st.sampled_from(["a", "b", "c", "x", "!", ".", "lis", ".lis", "*", "[", "]", "\\", " ", "#",
                                     "-"]), min_size=1, max_size=4).map("".join)
_PATH = st.tuples(st.sampled_from(["", "/", "./"]), st.lists(_SEGMENT, max_size=5).map("/".join),
                  st.sampled_from(["", "/"])).map("".join)


def _pathspec(lines: list[str]) -> pathspec.GitIgnoreSpec | None:
    """pathspec's spec, ``None`` where it rejects the patterns."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # re's FutureWarning on a class such as `[[a]`
            return pathspec.GitIgnoreSpec.from_lines(lines)
    except (ValueError, TypeError, re.error):  # a pattern it cannot read
        return None


def _unsure(line: str) -> bool:
    return translate(line) is None


@given(st.lists(_PATTERN, min_size=1, max_size=3), st.lists(_PATH, min_size=1, max_size=6))
@settings(max_examples=1500, deadline=None)
def test_generated_patterns_match_as_pathspec(lines: list[str], paths: list[str]) -> None:
    expected = _pathspec(lines)
    if expected is None:
        return
    for line in lines:  # the very regular expression pathspec makes, where it is translated
        if not _unsure(line):
            assert translate(line) == GitIgnoreSpecPattern.pattern_to_regex(line), line
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        spec = GlobSpec(lines)
    assert spec.fallback == any(_unsure(line) for line in lines)
    for path in paths:
        assert spec.match_file(path) == expected.match_file(path), (lines, path)


_SIMPLE = st.tuples(st.sampled_from(["", "!", "/", "!/"]),
                    st.lists(st.sampled_from(["*", "**", "a", "b", "/", ".lis", "?", "[ab]"]), min_size=1, max_size=4
                             ).map("".join)).map("".join)
_SIMPLE_PATH = st.lists(st.sampled_from(["a", "b", "a.lis", "b.lis", "ab"]), min_size=1, max_size=4).map("/".join)


@given(st.lists(_SIMPLE, min_size=2, max_size=5), st.lists(_SIMPLE_PATH, min_size=1, max_size=8))
@settings(max_examples=1500, deadline=None)
def test_which_pattern_wins_as_pathspec(lines: list[str], paths: list[str]) -> None:
    """Negations and folders in turn: the last pattern that matches a file itself decides, else the last
    that matches a folder above it."""
    expected = _pathspec(lines)
    if expected is None:
        return
    spec = GlobSpec(lines)
    assert not spec.fallback
    for path in paths:
        assert spec.match_file(path) == expected.match_file(path), (lines, path)


@given(st.lists(_PATTERN.filter(lambda p: "[" not in p), min_size=1, max_size=3))
@settings(max_examples=300, deadline=None)
def test_patterns_without_a_class_are_translated(lines: list[str]) -> None:
    """Only a bracket expression, or a pattern pathspec rejects, goes to pathspec."""
    if _pathspec(lines) is not None:
        assert not GlobSpec(lines).fallback


_PATHS = ["old", "old/a.lis", "old/a/b.lis", "x/old/a.lis", "x.lis", "a/x.lis", "a/b/x.lis", "a.lis", "b/a.lis",
          "dir", "dir/a.lis", "a/dir/b.lis", "keep.lis", "a/keep.lis", "keep.lisx", "a/b", "a/x/b", "a/x/y/b",
          "a/b/c", "b/a/b", "machines/m1/nullp.lis", "machines/nullp_1.lis", "nullp.lis", "n1.lis", "m1.lis",
          "tmp/a.lis", "machines/old/a/b.lis", "", ".", "/a.lis", "./a.lis", "dir/", "a b.lis"]


@pytest.mark.parametrize("lines", [
    ["old/**"], ["**/x.lis"], ["/a.lis"], ["dir/"], ["*.lis", "!keep.lis"], ["a/**/b"], ["tmp/"], ["old/", "old"],
    ["machines/**/nullp*.lis"], ["machines/old/**"], ["**/nullp*.lis"], ["machines/old/**/*.lis"], ["[n]*.lis"],
    ["/old/**"], ["*.lis", "*.lst", "*.nc", "*.xml"], ["*"], ["**"], ["*/"], ["**/"], ["/"], ["#x"], ["\\#x"],
    ["a\\ b.lis"], ["a\\ "], [" a.lis"], ["a.lis  "], ["!old/", "old/**"], ["old/**", "!old/a.lis"],
    ["a/", "!a/b"], ["*.li?"], ["*.[lL]is"], ["[!a]*.lis"], ["[a-c]/*"],
])
def test_documented_patterns_match_as_pathspec(lines: list[str]) -> None:
    spec = GlobSpec(lines)
    expected = pathspec.GitIgnoreSpec.from_lines(lines)
    assert not spec.fallback
    assert [spec.match_file(p) for p in _PATHS] == [expected.match_file(p) for p in _PATHS]


@pytest.mark.parametrize("lines", [["[]a]"], ["]a["], ["[[:alpha:]]"], ["[a-c-e]"], ["[\\]]"], ["*.lis", "[z-a]"]])
def test_other_classes_go_to_pathspec(lines: list[str]) -> None:
    expected = _pathspec(lines)
    if expected is None:  # `[z-a]`: pathspec cannot read it either, and says so
        with pytest.raises(re.error):  # as pathspec raises it
            GlobSpec(lines)
        return
    spec = GlobSpec(lines)
    assert spec.fallback
    assert [spec.match_file(p) for p in _PATHS] == [expected.match_file(p) for p in _PATHS]


def test_what_cannot_be_read_is_refused_as_before() -> None:
    with pytest.raises(ZeroError, match=r"`\[` is not closed"):
        patterns(("[a",))
    with pytest.raises(ZeroError, match=r"a pattern cannot be read: Invalid git pattern: 'a\\\\'"):
        patterns(("a\\",))
    with pytest.raises(ZeroError, match="a pattern cannot be read: Invalid git pattern: '!'"):
        patterns(("!",))
    with pytest.raises(ZeroError, match="too complex"):
        patterns(("*a*b*c*d",))
    assert patterns(("./old/**",)).match_file("old/a.lis")
    assert not patterns(("./old/**",)).fallback


def test_a_lint_with_patterns_imports_no_pathspec(tmp_path: Path) -> None:
    """A zero.toml's exclude and per-file-ignores are matched without pathspec (119 M instructions of
    imports: typing, dataclasses, inspect; tomllib, which reads the file, still imports typing)."""
    for folder in ("lists", "old"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "achse.lis").write_text("kopf.achs_nr 1\nkenngr.swe_pos 5000000000\nEnde\n",
                                                     encoding="utf-8")
    (tmp_path / "zero.toml").write_text('exclude = ["old/**"]\nper-file-ignores = {"lists/*.lis" = ["R001"]}\n',
                                        encoding="utf-8")
    env = {**os.environ, "ZERO_NO_CACHE": "1"}
    for named in (os.path.join("lists", "achse.lis"), "."):
        report, modules, _ = zero_modules("lint", "--exit-zero", "--output-format", "json", named, cwd=tmp_path,
                                          env=env)
        assert [(d["path"], d["code"]) for d in json.loads(report)] == [(os.path.join("lists", "achse.lis"), "R004")]
        assert "zero.engine.globs" in modules
        assert not {"pathspec", "dataclasses", "inspect", "zero.structured.toml"} & modules
    (tmp_path / "zero.toml").write_text('exclude = ["old/**"]\nper-file-ignores = {"lists/*.lis" = ["R004"]}\n',
                                        encoding="utf-8")
    report, modules, _ = zero_modules("lint", "--exit-zero", "--output-format", "json", ".", cwd=tmp_path, env=env)
    assert json.loads(report) == []
    assert "pathspec" not in modules

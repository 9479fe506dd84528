"""zero.files.path_str: the text ``str(Path(p))`` gives, without importing pathlib (issue 40: pathlib
with urllib.parse and ipaddress is 7% of one list's lint at start-up). zero names files as a Path
prints them; the lint path keeps them as strings, so this one helper must agree with pathlib on any text."""

from __future__ import annotations

import os
from pathlib import Path, PurePosixPath

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.files import path_str

posix = pytest.mark.skipif(os.sep != "/", reason="Windows paths are pathlib's own (path_str asks it there)")


@posix
@pytest.mark.parametrize("text", ["", ".", "./", "/", "//", "///", "////a", "//a", "//a//", "a", "a/", "a//b",
                                  "a/./b", "./a.lis", "././a", "../a", "a/..", "a/../b", "/..", "..", ".../a",
                                  ".a", "a.", "a/.b/", "/./", "/.", "./..", "a /b", " ", "a\\b", "C:/x", "~/a"])
def test_the_text_of_a_path_is_pathlibs(text: str) -> None:
    assert path_str(text) == str(Path(text)) == str(PurePosixPath(text))


@posix
@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(["/", ".", "a", "b", "..", " ", "\\", "é", "\udcff", "\0"]), max_size=14).map("".join))
@example("")
@example("//.")
def test_any_text_of_slashes_and_dots(text: str) -> None:
    assert path_str(text) == str(Path(text))


@posix
@settings(max_examples=500, deadline=None)
@given(st.text(max_size=20))
def test_any_text(text: str) -> None:
    assert path_str(text) == str(Path(text))


def test_a_path_object_is_its_own_text() -> None:
    assert path_str(Path("a") / "b.lis") == str(Path("a") / "b.lis")
    assert path_str(path_str("./x//y/")) == path_str("./x//y/")

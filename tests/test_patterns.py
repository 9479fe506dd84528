"""Patterns built from the code written at build time (tools/gen_pattern_codes.py, issue 40: start-up) are the
patterns ``re`` compiles: equal code, flags, groups and group names, and they match alike; a pattern not written,
or a table written by another Python, compiles with ``re``."""

from __future__ import annotations

import itertools
import re
import sys
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from conftest import script_module
from zero import pattern_codes, patterns
from zero.lists.tokenizer import row_source

ROOT = Path(__file__).resolve().parents[1]
GEN = script_module(ROOT / "tools" / "gen_pattern_codes.py")


def _fresh(source: str | bytes, flags: int = 0) -> re.Pattern[str] | re.Pattern[bytes] | None:
    """The pattern :mod:`zero.patterns` builds from the written code, not from its memo."""
    return patterns._from_written(source, flags)


def test_the_generated_module_is_up_to_date() -> None:
    """Run ``python tools/gen_pattern_codes.py`` after adding or changing a pattern (or the Python zero runs on)."""
    written = (ROOT / "src" / "zero" / "pattern_codes.py").read_text(encoding="utf-8")
    assert written == GEN.render()


def test_every_call_in_zero_passes_a_pattern_the_generator_reads() -> None:
    assert GEN.patterns()[1] == []  # else that pattern compiles with re at run time: name it a module literal


def test_flags_are_those_of_re() -> None:
    assert (patterns.IGNORECASE, patterns.MULTILINE, patterns.DOTALL, patterns.VERBOSE, patterns.ASCII) == \
        (re.IGNORECASE, re.MULTILINE, re.DOTALL, re.VERBOSE, re.ASCII)


@pytest.mark.parametrize(("source", "flags"), list(pattern_codes.CODES), ids=lambda v: repr(v)[:40])
def test_each_written_pattern_is_the_one_re_compiles(source: str | bytes, flags: int) -> None:
    written, expected = _fresh(source, flags), re.compile(source, flags)
    assert written is not None and written == expected  # a pattern's == compares its flags and code
    assert (written.pattern, written.flags, written.groups, written.groupindex) == \
        (expected.pattern, expected.flags, expected.groups, expected.groupindex)


def test_the_row_patterns_and_some_of_each_module_are_written() -> None:
    for variant in itertools.product((False, True), repeat=3):
        assert patterns.written(row_source(*variant))
    assert len(pattern_codes.CODES) > 40


_SAMPLE = [(s, f) for s, f in pattern_codes.CODES if isinstance(s, str)][:40]


@given(st.sampled_from(_SAMPLE), st.text(alphabet="P-AXIS0123456789_.[] \t#()=:\"'<>/xyz\n", max_size=40))
def test_written_patterns_match_as_re_does(pattern: tuple[str, int], text: str) -> None:
    source, flags = pattern
    ours, theirs = patterns.compiled(source, flags), re.compile(source, flags)
    assert [m.span() for m in ours.finditer(text)] == [m.span() for m in theirs.finditer(text)]
    assert ours.split(text) == theirs.split(text)


def test_another_python_or_source_compiles_with_re(monkeypatch: pytest.MonkeyPatch) -> None:
    source = row_source(True, False, True)
    assert _fresh(source + b"x") is None  # not written: re compiles it
    assert patterns.compiled("(?P<a>x)y+") == re.compile("(?P<a>x)y+")
    monkeypatch.setattr(patterns, "_written", None)
    monkeypatch.setattr(pattern_codes, "BUILT", (sys.version_info[0], sys.version_info[1] + 1, 0, 0))
    assert _fresh(source) is None
    assert not patterns.written(source)

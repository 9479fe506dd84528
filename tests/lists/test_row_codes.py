"""The row patterns' code written at build time (tools/gen_row_codes.py, issue 40: start-up) is the code ``re``
compiles them to: the same patterns, while the module is up to date and read by the Python that wrote it."""

from __future__ import annotations

import itertools
import re
import sys
from pathlib import Path

import pytest

from conftest import script_module
from zero.lists import row_codes
from zero.lists.tokenizer import _written_pattern, row_source

ROOT = Path(__file__).resolve().parents[2]


def test_the_generated_module_is_up_to_date() -> None:
    """Run ``python tools/gen_row_codes.py`` after changing a row pattern (or the Python the project runs on)."""
    written = (ROOT / "src" / "zero" / "lists" / "row_codes.py").read_text(encoding="utf-8")
    assert written == script_module(ROOT / "tools" / "gen_row_codes.py").render()  # type: ignore[attr-defined]


def test_each_written_pattern_is_the_one_re_compiles() -> None:
    for binary, crlf, widths in itertools.product((False, True), repeat=3):
        source = row_source(binary, crlf, widths)
        written, compiled = _written_pattern(source), re.compile(source)
        assert written is not None and written == compiled  # a pattern's == compares its code
        assert (written.pattern, written.flags, written.groups, written.groupindex) == \
            (compiled.pattern, compiled.flags, compiled.groups, compiled.groupindex)


def test_another_python_or_source_compiles_the_pattern(monkeypatch: pytest.MonkeyPatch) -> None:
    source = row_source(True, False, True)
    assert _written_pattern(source + b"x") is None  # not written: compiled by the caller
    monkeypatch.setattr(row_codes, "BUILT", (sys.version_info[0], sys.version_info[1] + 1, 0, 0))
    assert _written_pattern(source) is None

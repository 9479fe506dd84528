"""The row patterns the columnar reader splits a text with (issue 40) read every line alike: for a text
or its ASCII bytes, with or without the CR variant, with or without the whitespace widths."""

from __future__ import annotations

from typing import Any

from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.lists.tokenizer import _ROW_AT_GROUPS, _ROW_GROUPS, _row_pattern

_PARTS = st.sampled_from([
    "wz", "[", "]", "0", "01", "17", "9" * 20, ".", "a", "_b", "Ende", " ", "  ", "\t", "\n", "|", '"', "#", "(",
    "x|y", ".5", ".m", "\x0c", "\x0b", "\x1c", "\x1f", "-3", "0x1F", "P-AXIS-00001", "\xa0", "\x85", "\x00",
])


def _rows(text: Any, binary: bool, crlf: bool, widths: bool) -> list[tuple[Any, ...]]:
    """Each line's groups (None for a part it lacks); the comment's gap only where it has a comment."""
    step = (_ROW_AT_GROUPS if widths else _ROW_GROUPS) + 1
    got = _row_pattern(binary, crlf, widths).split(text)
    assert not any(got[0::step]), "every line is one match: nothing between two"
    del got[-step:]
    rows = [tuple(got[at:at + step - 1]) for at in range(1, len(got), step)]
    if widths:  # as _ROW's groups, and the whitespace the widths keep
        return [(r[1], r[2], r[3], r[5], r[7], r[8], r[0], r[4], r[6] if r[7] is not None else None) for r in rows]
    return [(*r, None, None, None) for r in rows]


@settings(max_examples=300, deadline=None)
@given(st.lists(_PARTS, max_size=40).map("".join))
@example("wz[1].x 5 ( c\nk v\n#\n\nwz[01].y 1\na .b 1\nk 1 |B\nk 1\x0cc")
def test_each_row_pattern_reads_lines_alike(text: str) -> None:
    want = _rows(text, False, True, True)
    assert len(want) == (text.count("\n") + (not text.endswith("\n")) if text else 0)
    for binary in (False, True) if text.isascii() else (False,):
        for crlf in (False, True):
            for widths in (False, True):
                got = _rows(text.encode("ascii") if binary else text, binary, crlf, widths)
                if binary:
                    got = [tuple(g.decode("ascii") if g is not None else None for g in row) for row in got]
                parts = 9 if widths else 6
                assert [row[:parts] for row in got] == [row[:parts] for row in want], (binary, crlf, widths)

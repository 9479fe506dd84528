"""Property tests (bounded so CI stays fast)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import lint_text
from zero.model import Blank, Comment, End, Entry, Invalid
from zero.tokenizer import decode, tokenize

LINE_PARTS = st.sampled_from([
    "np_grp[1].achse[2].versch", "kenngr.swe_pos", "g53_verfuegbar", "#", "# c", "#key 1",
    " ", "\t", "1", "-5", "0x1F", "P-AXIS-00212.0", "A | B", '"q s"', '"open', "( c", "/* x */",
    "Ende", "[", "]", ".", "µ", "ä", "\x00", "\r", "99999999999999999999999",
])


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=2000))
def test_tokenizer_never_raises_and_is_lossless(data: bytes) -> None:
    doc = tokenize(data)
    text, encoding, bom = decode(data)
    rebuilt = "".join(line + end for line, end in zip(doc.lines, doc.endings, strict=True))
    assert rebuilt == text
    assert (b"\xef\xbb\xbf" if bom else b"") + rebuilt.encode(encoding, "surrogateescape") == data
    assert len(doc.items) == len(doc.lines)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.lists(LINE_PARTS, max_size=6).map(" ".join), max_size=30)
       .map("\n".join))
def test_spans_inside_file_and_lint_deterministic(text: str) -> None:
    first = lint_text(text)
    second = lint_text(text)
    assert first.diagnostics == second.diagnostics
    lines = first.document.lines
    for d in first.diagnostics:
        assert 1 <= d.span.line <= d.span.end_line <= max(len(lines), 1) + 1
        if d.span.line == d.span.end_line and d.span.line <= len(lines):
            assert 1 <= d.span.column <= d.span.end_column <= len(lines[d.span.line - 1]) + 1


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 96), st.integers(0, 31), st.integers(-(2**31) + 1, 2**31 - 2)),
                max_size=40))
def test_valid_offsets_give_no_errors(rows: list[tuple[int, int, int]]) -> None:
    text = "g53_verfuegbar 1\n" + "".join(
        f"np_grp[{i}].achse[{j}].versch {v}\n" for i, j, v in rows)
    result = lint_text(text)
    assert all(d.severity.label != "error" for d in result.diagnostics)
    assert {d.code for d in result.diagnostics} <= {"R007"}


@settings(max_examples=200, deadline=None)
@given(st.binary(max_size=500))
def test_every_line_is_one_item(data: bytes) -> None:
    doc = tokenize(data)
    for n, item in enumerate(doc.items, 1):
        assert isinstance(item, Entry | Comment | Blank | End | Invalid) and item.line == n

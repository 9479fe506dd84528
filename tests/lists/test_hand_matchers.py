"""The hand-written matchers of the lists (start-up: no pattern compiled for them) answer as the patterns
they stand for: a value's lexical kind, a comment's annotation, a key's form and its indices."""

from __future__ import annotations

import re

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.lists.model import MAX_INDEX_DIGITS, Columns, ValueKind, _indices, _part, is_key, key_form
from zero.lists.tokenizer import (
    _KIND_OF,
    _TABLE_LIMIT,
    _annotation_re,
    _comment_parts,
    _comment_table,
    _comments_parts,
    _kind_re,
    _kinds,
    _shape_info,
    _shape_of,
    _shapes_of,
    _value_kinds,
    annotation_at,
    value_kind,
)

_VALUE_CHARS = "0123456789+-.eExXaAfFgP_-Z |\n\u0661\u00b2 "
_KEY_CHARS = "ab_9.[]0123 \u0661x"
_COMMENT_CHARS = "( \t\u00a0\u2003P-AXISTOL0123456789#x)"

_VALUES = ["0", "-1", "+7", "12", "0x1F", "-0X1e5", "0x", "0xg", "1.", ".5", "+.5", "1.5e3", "1e5", "1E-5",
           "1e", "e5", ".", "+", "-", "", "1.2.3", "1e5e3", ".5e", "1.e5", "P-AXIS-00016", "P-AXIS-00016.2",
           "P-AXIS-00016.", "P-AXIS-0001", "P-AxIS-00016", "-P-AXIS-00016", "P-AXIS-000161", "\u0661", "1\u00b2",
           "1_000", "1\n", "ABSOLUT", "./listen/x.lis", "REPORT|MOS", "2e+5", "2e-", "0x1.5"]


def _kind_by_pattern(value: str) -> ValueKind:
    m = _kind_re().fullmatch(value)
    return _KIND_OF[m.lastgroup] if m is not None and m.lastgroup else ValueKind.WORD


@pytest.mark.parametrize("value", _VALUES)
def test_value_kind_as_the_pattern(value: str) -> None:
    assert value_kind(value) is _kind_by_pattern(value)


@settings(max_examples=400, deadline=None)
@given(st.text(_VALUE_CHARS, max_size=14))
@example("P-CHAN-00001.12")
def test_value_kind_as_the_pattern_any(value: str) -> None:
    assert value_kind(value) is _kind_by_pattern(value)


def _annotation_by_pattern(comment: str) -> int:
    m = _annotation_re().search(comment)
    return m.start(1) if m is not None else -1


@pytest.mark.parametrize("comment", ["( P-AXIS-00016 : logical", "(P-AXIS-00016", "(  \tP-TOOL-00005 x",
                                     "# ( P-AXIS-0016 ( P-AXIS-00017", "(\u2003P-CHAN-00001", "( P-AXIs-00016",
                                     "P-AXIS-00016", "((P-AXIS-00016", "( (P-AXIS-00016", "(", ""])
def test_annotation_as_the_pattern(comment: str) -> None:
    assert annotation_at(comment) == _annotation_by_pattern(comment)


@settings(max_examples=400, deadline=None)
@given(st.text(_COMMENT_CHARS, max_size=30))
def test_annotation_as_the_pattern_any(comment: str) -> None:
    assert annotation_at(comment) == _annotation_by_pattern(comment)


@settings(max_examples=400, deadline=None)
@given(st.text(_COMMENT_CHARS, min_size=1, max_size=30))
@example("( P-AXIS-00016 : logical")
@example("( P-AXIs-00016 ( P-AXIS-00017")
@example("( P-AXIS-0016")
def test_comment_parts_annotation_as_the_pattern(comment: str) -> None:
    """_comment_parts' own reading of the usual `( P-XXXX-nnnnn` gives what the pattern finds."""
    _comment_table.pop(comment, None)
    at = _annotation_by_pattern(comment)
    assert _comment_parts(comment)[1:] == ((comment[at:at + 12], at) if at >= 0 else (None, -1))


@pytest.mark.parametrize("key", ["a", "a.b", "a[1]", "a[1][2].b[3]", "a[]", "a[1]b", "a[1]]", "a.", ".a", "",
                                 "a..b", "a[1].[2]", "a[\u0661]", "a\n", "a[1", "[1]", "wz[01].x"])
def test_key_form_as_the_pattern(key: str) -> None:
    assert is_key(key) is (key_form().fullmatch(key) is not None)


@settings(max_examples=400, deadline=None)
@given(st.text(_KEY_CHARS, max_size=16))
def test_key_form_as_the_pattern_any(key: str) -> None:
    assert is_key(key) is (key_form().fullmatch(key) is not None)


def _part_by_pattern(text: str) -> tuple[str, tuple[int, ...]]:
    digits = re.findall(r"\[([0-9]+)\]", text)
    return (re.sub(r"\[([0-9]+)\]", "[]", text),
            tuple(int(d) if len(d) <= MAX_INDEX_DIGITS else 10**MAX_INDEX_DIGITS for d in digits))


@settings(max_examples=400, deadline=None)
@given(st.text(_KEY_CHARS, max_size=16))
@example("a[[12]]")
@example("a[1234567890123456789]")
def test_indices_as_the_pattern_any(text: str) -> None:
    assert [text[s:e] for s, e in _indices(text)] == re.findall(r"\[([0-9]+)\]", text)
    assert _part(text) == _part_by_pattern(text)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.text(_COMMENT_CHARS + "/*", min_size=1, max_size=30), max_size=6, unique=True), st.booleans())
@example(["( P-AXIS-00016 : a", "( P-AXIS-00017 : b"], False)
@example(["/* c */", "plain", "# c", "( P-AXIs-00016 ( P-AXIS-00017"], True)
def test_comments_parts_as_one_at_a_time(comments: list[str], seen: bool) -> None:
    """The comments a list reads are told in one step (the run's first list: none seen before) as one at a time;
    ``seen``: some of them seen before."""
    for c in comments:
        _comment_table.pop(c, None)
    alone = [_comment_parts(c) for c in comments]
    for c in comments[1 if seen else 0:]:
        _comment_table.pop(c, None)
    styles, notes, note_at = _comments_parts(comments)
    assert list(zip(styles, notes, note_at, strict=True)) == alone
    assert [_comment_table.get(c) for c in comments] == alone  # kept for the run's next lists


_NAMES = st.text("ab_9.", min_size=1, max_size=8).filter(lambda s: s[0] not in "9.") | st.just("Ende")
_TAILS = st.none() | st.just("") | st.text("a_9.[]0", max_size=10).map(lambda s: "]" + s)  # None: no index


@settings(max_examples=400, deadline=None)
@given(st.lists(st.tuples(_NAMES, _TAILS), max_size=6, unique=True))
@example([("a.b", None), ("a..b", ""), ("a.", ""), ("Ende", ""), ("w", "]"), ("w", "].x.y"), ("w", "]x"), ("w", "].x."),
          ("w", "]..x"), ("w", "][2].x"), ("w", "].x[3]"), ("w", "].x]"), ("w", "]."), ("w.", "].x")])
def test_shapes_of_as_one_at_a_time(keys: list[tuple[str, str | None]]) -> None:
    """The key shapes a list reads, told in one step as one at a time (what the row pattern gives: names, then
    the rest of the key from its first index's `]`, or nothing)."""
    alone = [_shape_of(k) for k in keys]
    assert _shapes_of(keys) == alone
    assert [_shape_info[k] for k in keys] == alone
    for key, info in zip(keys, alone, strict=True):
        name, tail = key
        assert (info is not None) is (is_key(f"{name}[0{tail}") if tail else is_key(name) and name != "Ende")


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(_NAMES, _TAILS), max_size=6, unique_by=lambda k: (k[0], k[1] or None)), st.booleans())
def test_shapes_added_at_once_as_one_at_a_time(keys: list[tuple[str, str | None]], one_before: bool) -> None:
    """Columns.add_shapes adds shapes at once (each a key, none added before, distinct: a missing rest, None, and an
    empty one are the same shape) as one at a time."""
    infos = [_shape_of(k) for k in keys]
    at_once, alone = Columns(), Columns()
    if one_before:  # a shape added before (what add_entry adds): one at a time
        for cols in (at_once, alone):
            cols.shape_id("a", True, ".b")
    ids = at_once.add_shapes(infos)
    assert ids == [-1 if info is None else alone.add_shape(*info) for info in infos]
    fields = [[(s.head, s.tail, s.pattern, s.indices, s.indexed) for s in cols.shapes] for cols in (at_once, alone)]
    assert fields[0] == fields[1] and at_once.patterns == alone.patterns
    assert at_once._shape_ids == alone._shape_ids and at_once._pattern_ids == alone._pattern_ids


@settings(max_examples=300, deadline=None)
@given(st.lists(st.text(_VALUE_CHARS + "AbZ_\u00e4", max_size=10), max_size=8, unique=True), st.booleans())
@example(["1", "X_Achse", "0x400001", "P-AXIS-00008.0", "e5", "E", "_1", "\u00e4", "1e5", "\u0661", "-1"], False)
def test_value_kinds_as_one_at_a_time(values: list[str], seen: bool) -> None:
    """The values a list reads are told in one step (none seen before: ints and names in C) as one at a time;
    ``seen``: one of them seen before."""
    if len(_kinds) > _TABLE_LIMIT - 16:  # the run's table full (a whole suite's values): no room to keep these
        _kinds.clear()
    for v in values:
        _kinds.pop(v, None)
    if seen and values:
        _value_kinds(values[:1])
    assert _value_kinds(values) == [value_kind(v) for v in values]
    assert [_kinds.get(v) for v in values] == [value_kind(v) for v in values]

"""Steps of reading a list into columns that take a short way for the usual list (issue 40: start-up): each
gives what the general way gives."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.lists import model, tokenizer
from zero.lists.model import CommentStyle, Entry
from zero.lists.tokenizer import annotation_at, comment_style, tokenize, tokenize_text
from zero.records import fields


def _fields(obj: Any) -> dict[str, Any]:
    return {k: _fields(v) if isinstance(v, Entry) else v for k in obj.__slots__ for v in [getattr(obj, k)]}


def _items(text: str) -> list[tuple[type, dict[str, Any]]]:
    return [(type(i), _fields(i)) for i in tokenize_text(text).items]


# --- the lines after `Ende`, split off from the end of the text
_TAILS = ["", "\n", "\n\n", "a 1\n", "a 1", "# c\n", "  \n", "b 2\n# c\nd 4", "Ende\n", "\r\n", "x\r\ny 1\r\n", "\r"]


@pytest.mark.parametrize("tail", _TAILS)
@pytest.mark.parametrize("head", ["", "k 1\n", "# h\nk 1\n\n", "k 1\r\nq 2\r\n"])
@pytest.mark.parametrize("ende", ["Ende", "Ende\r", "  Ende  ", "Ende # stop"])
def test_the_lines_after_ende_as_the_careful_scanner_reads_them(head: str, ende: str, tail: str) -> None:
    text = f"{head}{ende}\n{tail}" if tail else f"{head}{ende}"
    careful = tokenize_text(text, use_fast=False)
    assert _items(text) == [(type(i), _fields(i)) for i in careful.items]
    assert tokenize_text(text).problems == careful.problems
    doc = tokenize_text(text)
    assert [doc.line_text(n) for n in range(1, doc.line_count + 1)] == careful.lines


def test_the_lines_after_ende_of_a_list_read_as_its_bytes(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(tokenizer, "_BYTES_FROM", -1)
    text = "k 1\n# h\nEnde\nafter 2\n\n# c\r\nz 3"
    doc = tokenize(text.encode("ascii"))
    assert isinstance(doc._text, bytes)
    careful = tokenize_text(text, use_fast=False)
    assert [(type(i), _fields(i)) for i in doc.items] == [(type(i), _fields(i)) for i in careful.items]
    assert doc.problems == careful.problems


# --- comments that each start `( P-XXXX-00000`, told at once
_COMMENT_PARTS = st.sampled_from([
    "( P-AXIS-00016", "( P-AXIS-0001", "(  P-AXIS-00016", "(P-AXIS-00016", "( P-axis-00016", "( P-ÄXIS-00016",
    "( P-AXIS-000167", " : x", " ( P-TOOL-00005 ", "µ", "#", "(", "|", "\x85", "\u2028", "\t", "( ", "P-",
])
_COMMENTS = st.lists(st.lists(_COMMENT_PARTS, min_size=1, max_size=4).map("".join)
                     .filter(lambda c: not c[0].isspace()), min_size=1, max_size=12, unique=True)


def _told(comments: list[str]) -> tuple[list[CommentStyle], list[str | None], list[int]]:
    """What _comments_parts must give: each comment's style, annotation and its column, one at a time."""
    at = [annotation_at(c) for c in comments]
    notes = [c[a:a + 12] if a >= 0 else None for c, a in zip(comments, at, strict=True)]
    return [comment_style(c) for c in comments], notes, at


@settings(max_examples=300, deadline=None)
@given(_COMMENTS)
@example(["( P-AXIS-00016 : a", "( P-AXIS-00017 : b"])
@example(["( P-AXIS-00016 : a", "( P-AXIS-0017 : b"])
@example(["( P-AXIS-00016 : a", "(  P-AXIS-00017"])
@example(["( P-AXIS-00016 : a", "# c ( P-AXIS-00017"])
@example(["( P-AXIS-00016 ( P-TOOL-00001", "( P-AXIS-00017"])
def test_comments_told_at_once_as_one_at_a_time(comments: list[str]) -> None:
    saved = dict(tokenizer._comment_table)
    tokenizer._comment_table.clear()  # none seen before: the run's first list
    try:
        styles, notes, note_at = tokenizer._comments_parts(comments)
        assert (styles, notes, note_at) == _told(comments)
        assert all(s is t for s, t in zip(styles, _told(comments)[0], strict=True))
        # and kept for the next list, as one at a time would keep them
        assert [tokenizer._comment_table[c] for c in comments] == list(zip(styles, notes, note_at, strict=True))
    finally:
        tokenizer._comment_table.clear()
        tokenizer._comment_table.update(saved)


def test_a_list_whose_comments_all_hold_a_leading_note() -> None:
    tokenizer._comment_table.pop("( P-AXIS-00016 : number", None)
    tokenizer._comment_table.pop("( P-AXIS-00110 : ident (x)", None)
    doc = tokenize_text("a 1 ( P-AXIS-00016 : number\nb 2 ( P-AXIS-00110 : ident (x)\n")
    assert [(e.comment_style, e.annotation, e.annotation_start) for e in doc.entries] == [
        (CommentStyle.PAREN, "P-AXIS-00016", 6), (CommentStyle.PAREN, "P-AXIS-00110", 6)]


# --- the shapes a reader makes in bulk
def test_shapes_made_in_bulk_are_the_records_init_makes() -> None:
    heads, tails, patterns = ["wz", "kenngr.swe_pos", "a"], [".laenge", "", ".b[3]"], [0, 1, 2]
    indices, indexed = [(), (), (3,)], [True, False, True]
    made = model._made_shapes(heads, tails, patterns, indices, indexed)
    expected = list(map(model.Shape, heads, tails, patterns, indices, indexed))
    assert [type(s) for s in made] == [model.Shape] * 3
    assert [_fields(s) for s in made] == [_fields(s) for s in expected]
    # every field is set there: a field the record gains (with a default, or a __post_init__) fails here first
    assert [f.name for f in fields(model.Shape)] == ["head", "tail", "pattern", "indices", "indexed"]
    assert not hasattr(model.Shape, "__post_init__")
    assert model._made_shapes([], [], [], [], []) == []


# --- the tables of a small list, kept without a copy
_SMALL = "# head\na 1 # x\nwz[1].l 2\n\nb P-AXIS-00001 ( P-TOOL-00005 n\n"


def test_tables_kept_uncopied_give_the_items_they_held(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(tokenizer, "_small_tables", {})
    # the careful lines (a quoted value, an odd key) add to the first list's tables after they were kept
    first = tokenize_text(_SMALL + 'q "s t"\nk[1 2\nr "u" ( P-AXIS-00002 z\n')
    second = tokenize_text(_SMALL)  # the same distinct shapes, values and comments: the tables loaded
    careful = tokenize_text(_SMALL, use_fast=False)
    cols = second.columns
    assert cols.shapes[0] is first.columns.shapes[0]  # loaded, not made again
    assert len(first.columns.values) > len(cols.values) and '"s t"' not in cols.values
    assert [(c, cols.kinds[v]) for c, v in zip(cols.values, range(len(cols.values)), strict=True)] == [
        (c, k) for c, k in zip(first.columns.values, first.columns.kinds, strict=False)][:len(cols.values)]
    assert [_fields(e) for e in second.entries] == [_fields(e) for e in careful.entries]
    assert set(cols._value_ids) == set(cols.values) and len(cols._shape_ids) == len(cols.shapes)
    assert len(cols._comment_ids) == len(cols.comments) and len(cols._pattern_ids) == len(cols.patterns)
    # a loaded document's tables are its own: a third list loads them as they were kept
    cols.values.append("changed")
    cols._value_ids["changed"] = len(cols.values) - 1
    third = tokenize_text(_SMALL).columns
    assert "changed" not in third.values and "changed" not in third._value_ids
    assert third.values == cols.values[:-1]


# --- a small list's rows in lists, told from the lines the pattern split (no count of the line feeds first)
@pytest.mark.parametrize("widths", [False, True])
@pytest.mark.parametrize("text", ["a 1\nb 2", "a 1\nb 2\n", "a 1\nb 2\nc 3", "a 1\nb 2\nc 3\n", "a 1\n# c\n\nd 4\n",
                                  "a 1\r\nb 2\r\nc 3\r\n", "", "\n\n\n", "a 1\nEnde\nb 2\n"])
def test_rows_in_lists_below_so_many_line_feeds(monkeypatch: pytest.MonkeyPatch, text: str, widths: bool) -> None:
    monkeypatch.setattr(tokenizer, "_SMALL_LIST", 3)
    doc = tokenize_text(text, widths=widths)
    cols = doc.columns
    small = text.count("\n") < 3  # what the reader counted before it read
    for name in ("line", "shape", "first", "pattern", "value", "comment"):
        assert (type(getattr(cols, name)) is list) is small, name
    if widths:
        assert cols.widths is not None and all((type(w) is list) is small for w in cols.widths)
        assert [len(w) for w in cols.widths] == [len(cols)] * 3
    careful = tokenize_text(text, use_fast=False)
    assert [_fields(e) for e in doc.entries] == [_fields(e) for e in careful.entries]
    assert [(type(i), _fields(i)) for i in tokenize_text(text, widths=widths).items] == [
        (type(i), _fields(i)) for i in careful.items]


# --- the first part's new shapes and comments, found without an id per line first
@pytest.mark.parametrize("text", ["", "# c\n\n", "a 1\nb 2\na 3\n", "a 1 # x\nb 2\n# y\nc 3 # x\n", "Ende\n",
                                  "a[1].b 1 ( P-AXIS-00001\na[2].b 2\n\na[1].b 3 ( P-AXIS-00001\n", "k[1 2\nq \"s\"\n"])
def test_a_first_part_has_the_ids_of_the_careful_scanner(text: str) -> None:
    doc = tokenize_text(text)
    cols = doc.columns
    careful = tokenize_text(text, use_fast=False)
    assert [cols.key_text(r) for r in range(len(cols))] == [e.key_text for e in careful.entries]
    assert [cols.comment_text(r) for r in range(len(cols))] == [e.comment for e in careful.entries]
    assert len(cols.shapes) == len({e.key_text.split("[")[0] + e.key_text.partition("]")[2]
                                    for e in careful.entries})
    assert len(cols.comments) == len({e.comment for e in careful.entries} - {None})
    assert sorted(set(cols.shape)) == list(range(len(cols.shapes)))
    assert [(type(i), _fields(i)) for i in doc.items] == [(type(i), _fields(i)) for i in careful.items]

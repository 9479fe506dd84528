"""The columnar document (issue 40): the columns the tokenizer writes agree with the entries the careful
scanner builds, entries are built on demand and kept, and what reads the columns finds what it found
on the objects."""

from __future__ import annotations

from array import array
from pathlib import Path
from typing import Any

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.lists import model, tokenizer
from zero.lists.model import Columns, Document, Entry
from zero.lists.tokenizer import tokenize, tokenize_text
from zero.rules.suppress import parse_directives

_KEYS = ["wz[1].laenge", "wz[17].kinematic.param[3]", "kenngr.swe_pos", "a", "a[0]", "a[1][2].b[3]", "q[007].r",
         "x[00].y", "np_grp[1].achse[2].versch", "Ende", "5abc", "a..b", "a.", "a[1]x", "a]", "k[1", f"w[{'9' * 19}].x",
         "np_grp[0].achse[1]. inaktiv", "#kenngr.x", "# zero: ignore[R005]", "# zero: noqa: S", "# zero: ignore R5"]
_VALUES = ["1", "-5", "2\x1f", "0x1F", "1.5", "1e3", "P-AXIS-00212.0", "A|B", "A | B", '"q s"', '"open', "WORD",
           "./x.lis", "../y", ".5", ".x", ".", ".[1]", ""]
_COMMENTS = ["", "( P-TOOL-00005 : x", "# c", "/* c */", "plain words", "# noqa", "( noqa: R005 )", "# noqa: Q9",
             "(P-AXIS-00001", "# c\r", "( a | b"]
_GAPS = [" ", "\t", "   ", " \t "]


@st.composite
def _line(draw: st.DrawFn) -> str:
    choice = draw(st.integers(0, 9))
    if choice == 0:
        return draw(st.sampled_from(["", "  ", "#", "# comment", "Ende", "#a 1", "*****", "\x0c", "µ ä"]))
    lead = draw(st.sampled_from(["", "", " ", "\t"]))
    parts = [lead + draw(st.sampled_from(_KEYS))]
    value = draw(st.sampled_from(_VALUES))
    if value:
        parts += [draw(st.sampled_from(_GAPS)), value]
        comment = draw(st.sampled_from(_COMMENTS))
        if comment:
            parts += [draw(st.sampled_from(_GAPS)), comment]
    parts.append(draw(st.sampled_from(["", "", " "])))
    return "".join(parts)


_TEXTS = st.tuples(st.lists(_line(), max_size=25), st.sampled_from(["\n", "\r\n", "mixed"]),
                   st.booleans()).map(
    lambda t: "".join(s + ("\r\n" if t[1] == "\r\n" or (t[1] == "mixed" and n % 3 == 0) else "\n")
                      for n, s in enumerate(t[0]))[: None if t[2] else -1])


def _fields(obj: Any) -> dict[str, Any]:
    return {k: _fields(v) if isinstance(v, Entry) else v for k in obj.__slots__ for v in [getattr(obj, k)]}


def _check(text: str) -> None:
    for widths in (False, True):
        _check_read(text, widths)
    careful_first = tokenizer._CAREFUL_FIRST
    tokenizer._CAREFUL_FIRST = 0  # every line the columns do not take tried with the common line's pattern first
    try:
        _check_read(text, False)
    finally:
        tokenizer._CAREFUL_FIRST = careful_first
    if text.isascii() and "\x00" not in text:  # a big ASCII list: read as its bytes
        bytes_from = tokenizer._BYTES_FROM
        tokenizer._BYTES_FROM = -1
        try:
            for widths in (False, True):
                _check_read(text, widths, True)
        finally:
            tokenizer._BYTES_FROM = bytes_from


def _read(text: str, widths: bool, binary: bool) -> Document:
    if not binary:
        return tokenize_text(text, widths=widths)
    doc = tokenize(text.encode("ascii"), widths=widths)
    assert isinstance(doc._text, bytes) and doc.encoding == "utf-8" and doc.text == text
    assert doc.text_size == len(text)
    return doc


def _check_read(text: str, widths: bool, binary: bool = False) -> None:
    """The columns, the entries built of them (``widths``: from the widths the columns keep, else by
    reading each line again), lines and items agree with the careful scanner's objects; ``binary``: of
    a document read from the bytes of an ASCII text (never decoded as a whole)."""
    careful = tokenize_text(text, use_fast=False)
    doc = _read(text, widths, binary)
    cols = doc.columns
    assert (cols.widths is not None) is widths
    if cols.widths is not None:
        assert [len(w) for w in cols.widths] == [len(cols)] * 3
    entries = careful.entries
    assert len(cols) == len(entries)
    # the columns, row by row, before any object is built
    for row, e in enumerate(entries):
        assert e.key is not None
        assert cols.line[row] == e.line
        assert cols.key_text(row) == e.key_text
        assert cols.indices(row) == e.key.indices
        assert cols.patterns[cols.pattern[row]] == e.key.pattern
        assert cols.patterns[cols.shapes[cols.shape[row]].pattern] == e.key.pattern
        assert cols.key(row) == e.key
        assert cols.value_text(row) == e.value and cols.value_kind(row) is e.value_kind
        assert cols.comment_text(row) == e.comment
        cid = cols.comment[row]
        if cid >= 0:
            assert cols.styles[cid] is e.comment_style and cols.notes[cid] == e.annotation
            assert cols.note_at[cid] == (e.annotation_start - e.comment_start if e.annotation_start >= 0 else -1)
    # the text, without building lines or items
    fresh = _read(text, widths, binary)
    assert fresh.line_count == len(careful.lines)
    assert [fresh.line_text(n) for n in range(0, len(careful.lines) + 2)] == ["", *careful.lines, ""]
    assert fresh.newline == careful.newline and fresh.declared_kind() == careful.declared_kind()
    assert [fresh.item_at(n) is not None for n in range(1, len(careful.lines) + 1)] == [True] * len(careful.lines)
    # nothing above built the items (control characters do: where they are is told line by line)
    assert fresh._items is None or tokenizer._control_count(text) > text.count("\r\n")
    assert doc.problems == careful.problems
    # an entry of a row is the careful scanner's, field by field (asked for one by one, and all at once)
    built = [doc.entry_at(row) for row in range(len(cols))]
    assert [_fields(e) for e in built] == [_fields(e) for e in entries]
    assert [_fields(e) for e in _read(text, widths, binary).entries] == [_fields(e) for e in entries]
    first = _read(text, widths, binary)
    moved = first.moved("elsewhere")
    assert moved.path == "elsewhere" and first.path == "-" and moved.problems is first.problems
    assert moved.columns is first.columns and moved.lines == careful.lines
    assert [e.key_text for e in moved.entries] == [e.key_text for e in entries]
    assert first.items is not None and first.lines is not None
    again = first.moved("third")  # built parts shared too
    assert again.items is first.items and again.lines is first.lines
    # then lines, endings and items as the careful scanner's, holding the same entry objects
    assert doc.lines == careful.lines and doc.endings == careful.endings
    assert [(type(i), _fields(i)) for i in doc.items] == [(type(i), _fields(i)) for i in careful.items]
    assert all(a is b for a, b in zip(doc.entries, built, strict=True))
    assert [doc.item_at(n) for n in range(1, len(careful.lines) + 1)] == doc.items
    # columns built from objects (a document of another form) agree as well
    other = Columns.of_entries(entries)
    assert [other.key_text(r) for r in range(len(other))] == [cols.key_text(r) for r in range(len(cols))]
    assert [other.patterns[p] for p in other.pattern] == [cols.patterns[p] for p in cols.pattern]
    assert [other.indices(r) for r in range(len(other))] == [cols.indices(r) for r in range(len(cols))]


def _directives(doc: Document) -> tuple[list[Any], list[Any]]:
    found, bad = parse_directives(doc, {"R005", "S001", "S005", "M003"})
    return [(d.line, d.start, d.end, d.codes, d.scope, d.target) for d in found], bad


@settings(max_examples=400, deadline=None)
@given(_TEXTS)
@example("wz[1].x 1\nwz[2].x 2 ( P-TOOL-00005 : a\n")
@example("a 1\r\nb[01] 2\r\nEnde\r\nc 3 # noqa\r\n# zero: ignore[R005]\r\nd 4")
@example("k 1\r")
@example("")
def test_columns_agree_with_the_careful_scanner(text: str) -> None:
    _check(text)


@settings(max_examples=200, deadline=None)
@given(_TEXTS)
@example("# zero: ignore[R005]\n# zero: noqa: S\na 1 # noqa\nEnde\nb 2 ( noqa: R005 )\n# zero: ignore[S001]\n")
def test_directives_are_found_as_on_the_objects(text: str) -> None:
    careful = tokenize_text(text, use_fast=False)
    objects = Document("-", "utf-8", careful.lines, careful.endings, careful.items, careful.problems)
    doc = tokenize_text(text)
    assert _directives(doc) == _directives(objects)
    assert doc._items is None or tokenizer._control_count(text) > text.count("\r\n")  # without the items


def test_many_parts_of_a_big_text_read_as_one(monkeypatch: pytest.MonkeyPatch) -> None:
    """The pattern reads the text in parts: lines across part boundaries, and parts with lines the
    columns do not take (a comment, `Ende`), read as in one."""
    lines = [f"wz[{n}].x{n % 3} {n} ( P-TOOL-00005 : c{n % 2}" for n in range(300)]
    lines[37] = "# a comment"
    lines[120] = "a b c | d"
    lines[250] = "Ende"
    text = "\r\n".join(lines)
    monkeypatch.setattr(tokenizer, "_CHUNK", 40)
    monkeypatch.setattr(model, "_STARTS_STEP", 50)  # the index of line starts, split in parts as well
    _check(text)
    doc = tokenize_text(text)
    assert len(doc.columns) == 249 and doc.end_line == 251  # a comment and `Ende` are no rows


@pytest.mark.parametrize("other", [None, 700])
def test_a_big_part_read_as_the_careful_scanner(other: int | None) -> None:
    """Many rows in one part go into the columns packed in C (the rows of a part in one go, or between a
    comment and the part's ends)."""
    lines = [f"wz[{n}].x{n % 3}  {n * 7}\t( P-TOOL-00005 : c{n % 2}" for n in range(1200)]
    if other is not None:
        lines[other] = "# a comment"
    _check("\n".join(lines) + "\n")


def test_an_entry_is_built_from_the_widths_without_its_line() -> None:
    """With widths kept, an entry's positions come from the columns: its line is not read again."""
    text = "  wz[3].x\t\t12   ( P-TOOL-00005 : c\nb 2\n"
    doc = tokenize_text(text, widths=True)
    assert doc.columns.widths is not None
    assert [list(w) for w in doc.columns.widths] == [[2, 0], [2, 1], [3, 0]]
    doc._text = None  # the text gone: a line read again would be empty, and match no entry
    e = doc.entry_at(0)
    assert (e.key_text, e.key_start, e.key_end, e.value, e.value_start, e.value_end) == ("wz[3].x", 2, 9, "12", 11, 13)
    assert (e.comment_start, e.annotation, e.annotation_start) == (16, "P-TOOL-00005", 18)
    assert [(x.key_text, x.value_start) for x in doc.entries] == [("wz[3].x", 11), ("b", 2)]


def test_an_entry_is_built_once_and_kept() -> None:
    doc = tokenize_text("a 1\nb[2].c 3 # x\n# c\nd 4\n")
    first = doc.entry_at(1)
    assert doc.entry_at(1) is first and doc._items is None
    first.value = "changed"  # code that changes an entry sees its change in items and entries
    assert doc.items[1] is first and doc.entries[1] is first and doc.item_at(2) is first
    assert isinstance(doc.items[2], type(doc.other_items()[0]))
    assert [e.line for e in doc.entries] == list(doc.columns.line) == [1, 2, 4]


def test_a_document_built_from_items_has_columns() -> None:
    careful = tokenize_text("a 1\n# c\nb[3] x # noqa\n", use_fast=False)
    doc = Document("-", "utf-8", careful.lines, careful.endings, careful.items)
    assert len(doc.columns) == 2 and doc.entry_at(1) is careful.items[2]
    assert isinstance(doc.entry_at(0), Entry) and doc.columns.key_text(1) == "b[3]"
    doc.items = careful.items[:1]  # new items: the columns follow
    assert len(doc.columns) == 1


# A small list like one read before copies its tables: the rows must still be this list's.
_SMALL_A = "# head\na 1 # x\nwz[1].l 2\n\nb P-AXIS-00001 ( P-TOOL-00005 n\n"
_SMALL_B = "#\na 1 # x\nwz[7].l 2\n\n  \nwz[3].l 2\nb P-AXIS-00001 ( P-TOOL-00005 n\na 1 # x\n"


def test_a_small_list_like_one_read_before_has_its_own_rows(monkeypatch: pytest.MonkeyPatch) -> None:
    # the run's tables of small lists are bounded: lists other tests read before may have filled them
    monkeypatch.setattr(tokenizer, "_small_tables", {})
    _check(_SMALL_A)
    _check(_SMALL_B)  # the same distinct shapes, values and comments in the same order: the tables copied
    _check(_SMALL_A)
    a, b = tokenize_text(_SMALL_A).columns, tokenize_text(_SMALL_B).columns
    assert b.shapes[0] is a.shapes[0]  # copied, not made again
    assert b.shapes == a.shapes and b.comments == a.comments and b.values == a.values
    assert list(b.line) == [2, 3, 6, 7, 8] and list(b.first) == [-1, 7, 3, -1, -1]
    b.values.append("changed")  # a document's tables are its own
    assert "changed" not in tokenize_text(_SMALL_A).columns.values


_ROW_COLUMNS = ("line", "shape", "first", "pattern", "value", "comment")


@pytest.mark.parametrize("widths", [False, True])
def test_a_small_list_has_list_columns_alike_arrays(monkeypatch: pytest.MonkeyPatch, widths: bool) -> None:
    """A small list keeps its rows in lists, a big one in arrays: the same rows, tables and entries."""
    text = "# head\na 1 # x\nwz[1].l 2\n\nb P-AXIS-00001 ( P-TOOL-00005 n\nq \"s\"\nwz[12].l 2\nEnde\nc 1\n"
    small = tokenize_text(text, widths=widths)
    monkeypatch.setattr(tokenizer, "_SMALL_LIST", 0)  # every list read as a big one
    big = tokenize_text(text, widths=widths)
    for name in _ROW_COLUMNS:
        assert type(getattr(small.columns, name)) is list and type(getattr(big.columns, name)) is array
        assert list(getattr(small.columns, name)) == list(getattr(big.columns, name)), name
    if widths:
        assert small.columns.widths is not None and big.columns.widths is not None
        assert all(type(w) is list for w in small.columns.widths)
        assert [list(w) for w in small.columns.widths] == [list(w) for w in big.columns.widths]
    assert [_fields(e) for e in small.entries] == [_fields(e) for e in big.entries]
    assert [(type(i), _fields(i)) for i in small.items] == [(type(i), _fields(i)) for i in big.items]
    assert small.problems == big.problems
    _check(text)


@pytest.mark.parametrize("text", [
    # comments and blank lines between rows, lines read the careful way, `Ende` in the middle, CRLF
    "# c\r\na 1\r\n\r\nx \"q\"\r\nb 2\r\n#\tt\r\nEnde\r\nc 3\r\n# after\r\n\r\nd ./p\r\n",
    "a 1\n# c\nv ./listen/x\nb 2\n\nc 3\nEnde\n# c\ne 5\n  \n#\r",  # last line without newline, its \r kept
    "a 1\n\nb 2\n   \t\nc 3\n\x0b\n#x\n# y\n" + "".join(f"w[{n}] {n}\n" for n in range(40)),
])
def test_parts_with_other_lines_read_like_the_careful_scanner(text: str) -> None:
    _check(text)


@pytest.mark.parametrize("text", ["a 1\n", "ä\x85 \x01\x9f\n", "€ \x02\udc85\x7f", "\x80" * 10, ""])
def test_control_count_as_the_pattern(text: str) -> None:
    assert tokenizer._control_count(text) == len(tokenizer._control_re().findall(text))


def _same_objects(text: str) -> None:
    """``objects=True`` (what a diff or a conversion asks for: every item, built while reading) gives the
    objects and problems the columns give."""
    columnar = tokenize_text(text)
    objects = tokenize_text(text, objects=True)
    assert objects.lines == columnar.lines and objects.endings == columnar.endings
    assert objects.problems == columnar.problems and objects.end_line == columnar.end_line
    assert [(type(i), _fields(i)) for i in objects.items] == [(type(i), _fields(i)) for i in columnar.items]
    cols, other = columnar.columns, objects.columns
    assert [other.key_text(r) for r in range(len(other))] == [cols.key_text(r) for r in range(len(cols))]
    assert [other.value_text(r) for r in range(len(other))] == [cols.value_text(r) for r in range(len(cols))]


@settings(max_examples=150, deadline=None)
@given(_TEXTS)
def test_objects_read_as_the_columns_give_them(text: str) -> None:
    _same_objects(text)


def test_objects_of_vendor_lists_as_the_columns_give_them(corpus: Path) -> None:
    paths = sorted(corpus.rglob("*.lis"))
    assert paths
    for path in paths:
        data = path.read_bytes()
        a, b = tokenize(data, str(path)), tokenize(data, str(path), objects=True)
        assert [(type(i), _fields(i)) for i in a.items] == [(type(i), _fields(i)) for i in b.items], path
        assert a.problems == b.problems and a.encoding == b.encoding, path

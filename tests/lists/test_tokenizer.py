"""Every form of SPEC §1 and of the corpus, read exactly."""

from __future__ import annotations

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.lists.encoding import decode
from zero.lists.model import (
    HUGE_INDEX,
    Blank,
    Comment,
    CommentStyle,
    End,
    Entry,
    Invalid,
    Problem,
    ValueKind,
    parse_key,
)
from zero.lists.tokenizer import scan_entry, scan_line, tokenize


def one(line: str) -> Entry:
    doc = tokenize(line.encode())
    item = doc.items[0]
    assert isinstance(item, Entry), item
    return item


def kinds(text: str) -> list[str]:
    return [p.kind for p in tokenize(text.encode()).problems]


@pytest.mark.parametrize(
    ("line", "value", "kind"),
    [
        ("a 12", "12", ValueKind.INT),
        ("a -12", "-12", ValueKind.INT),
        ("a +7", "+7", ValueKind.INT),
        ("kenngr.achs_mode 0x400001 ( mode", "0x400001", ValueKind.HEX),
        ("a 12.5", "12.5", ValueKind.REAL),
        ("a 1e-6", "1e-6", ValueKind.REAL),
        ("a P-AXIS-00212.0", "P-AXIS-00212.0", ValueKind.REF),
        ("a P-AXIS-00376   ( P-AXIS-00377 :", "P-AXIS-00376", ValueKind.REF),
        ("a MOS", "MOS", ValueKind.WORD),
        ("a PLC_INFO | MOS", "PLC_INFO | MOS", ValueKind.FLAGS),
        ("a REPORT | REPORT_EXTENDED |PRINT | LOG", "REPORT | REPORT_EXTENDED |PRINT | LOG",
         ValueKind.FLAGS),
        ("a ./listen/achsmds1.lis", "./listen/achsmds1.lis", ValueKind.WORD),
        ("a 20804,20805", "20804,20805", ValueKind.WORD),
        ("a cnc_ve_%s_[%d]_r", "cnc_ve_%s_[%d]_r", ValueKind.WORD),
        ('a "STRING_WITH_COMMENT( # /*)_CHARACTERS"', '"STRING_WITH_COMMENT( # /*)_CHARACTERS"',
         ValueKind.QUOTED),
        ("a STRING_WITH_STANDARD_CHARACTERS!", "STRING_WITH_STANDARD_CHARACTERS!", ValueKind.WORD),
    ],
)
def test_values(line: str, value: str, kind: ValueKind) -> None:
    e = one(line)
    assert (e.value, e.value_kind) == (value, kind)
    assert line[e.value_start : e.value_end] == value


@pytest.mark.parametrize(
    ("line", "comment", "style"),
    [
        ("dummy[1] 1 Kommentar", "Kommentar", CommentStyle.TEXT),
        ("dummy[2] 1 # Kommentar", "# Kommentar", CommentStyle.HASH),
        ("dummy[3] 1 ( Kommentar", "( Kommentar", CommentStyle.PAREN),
        ("dummy[4] 1 /* Kommentar", "/* Kommentar", CommentStyle.BLOCK),
        ("t[0].pos  0  /* 20 */    ( P-COMP-00023 : value", "/* 20 */    ( P-COMP-00023 : value",
         CommentStyle.BLOCK),
        ("k 1 ( a ( nested (programmed stop) # and 'quotes' : x", None, CommentStyle.PAREN),
    ],
)
def test_comments(line: str, comment: str | None, style: CommentStyle) -> None:
    e = one(line)
    assert e.comment_style is style
    assert e.comment == (comment if comment is not None else line[line.index("("):])


def test_annotation_found_after_block_comment() -> None:
    e = one("kw.ssfk.table[1].pos   0  /* 20 */    ( P-COMP-00023 : Compensation")
    assert e.annotation == "P-COMP-00023"
    assert e.annotation_start == e.comment_start + e.comment.index("P-COMP")  # type: ignore[union-attr]


def test_quoted_string_with_paren_comment() -> None:
    e = one('beispiel[1].bezeichnung "STRING_(2)" (Kommentar')
    assert e.value == '"STRING_(2)"' and e.comment == "(Kommentar"


def test_full_line_comments_and_blanks() -> None:
    doc = tokenize(b"# text\n#\n#\ttab\n\t\t\t \n\n   \n")
    assert [type(i) for i in doc.items] == [Comment, Comment, Comment, Blank, Blank, Blank]
    assert doc.problems == []


def test_commented_out_parameter_stays_recognisable() -> None:
    doc = tokenize(b"#m_default_outp_ax_name[0]   X   ( P-CHAN-00039 : name\n")
    c = doc.items[0]
    assert isinstance(c, Comment) and c.commented_out is not None
    assert c.commented_out.key_text == "m_default_outp_ax_name[0]"
    assert c.commented_out.value == "X"
    assert [p.kind for p in doc.problems] == ["hash-no-space"]


def test_key_with_whitespace_inside_is_joined_and_reported() -> None:
    doc = tokenize(b"np_grp[0].achse[1]. inaktiv 0 # Verschiebung ist gueltig\n")
    e = doc.items[0]
    assert isinstance(e, Entry)
    assert e.key_text == "np_grp[0].achse[1].inaktiv" and e.value == "0"
    assert e.key_raw == "np_grp[0].achse[1]. inaktiv"
    (p,) = doc.problems
    assert (p.kind, p.start, p.end) == ("key-whitespace", 19, 20)


def test_value_starting_with_dot_is_not_joined_to_the_key() -> None:
    e = one("achs_mds[0] ./listen/achsmds1.lis")
    assert e.key_text == "achs_mds[0]" and e.value == "./listen/achsmds1.lis"


def test_key_without_value() -> None:
    assert kinds("kenngr.swe_pos\n") == ["missing-value"]
    assert kinds("kenngr.swe_pos   \t\n") == ["missing-value"]


def test_unterminated_quote() -> None:
    assert kinds('a "abc ( def\n') == ["unterminated-quote"]


def test_malformed_lines() -> None:
    doc = tokenize(b"*****\nnp_grp[1.achse 5\n[0] 1\n")
    assert all(isinstance(i, Invalid) for i in doc.items)
    assert kinds("*****\nnp_grp[1.achse 5\n") == ["malformed-line", "malformed-line"]


def test_ende_and_what_follows() -> None:
    doc = tokenize(b"a 1\nEnde   \n\n")
    assert isinstance(doc.items[1], End) and doc.end_line == 2 and doc.problems == []
    doc = tokenize(b"a 1\nEnde")  # no final newline
    assert doc.end_line == 2 and doc.endings == ["\n", ""]
    doc = tokenize(b"a 1\nEnde\n# fine\nb 2\nc 3\n")
    assert [p.kind for p in doc.problems] == ["after-end"]
    assert [e.key_text for e in doc.entries] == ["a"]


def test_line_endings_are_recorded() -> None:
    doc = tokenize(b"a 1\r\nb 2\nc 3")
    assert doc.lines == ["a 1", "b 2", "c 3"]
    assert doc.endings == ["\r\n", "\n", ""]
    assert [p.kind for p in doc.problems] == ["mixed-endings"]
    assert tokenize(b"a 1\r\nb 2\r\n").newline == "\r\n"


def test_tabs_alignment_and_trailing_whitespace() -> None:
    e = one("kenngr.swe_pos\t\t  15000000   \t")
    assert e.value == "15000000" and e.comment is None


@pytest.mark.parametrize(
    ("data", "encoding", "bom"),
    [
        ("µ ä".encode(), "utf-8", False),
        (b"\xef\xbb\xbfa 1\n", "utf-8", True),
        (b"# \xb5m\n", "cp1252", False),
        (b"# \x81\n", "latin-1", False),
    ],
)
def test_encodings(data: bytes, encoding: str, bom: bool) -> None:
    text, enc, has_bom = decode(data)
    assert (enc, has_bom) == (encoding, bom)
    # lossless: encoding the text again gives the bytes back
    body = data[3:] if bom else data
    assert text.encode(enc, "surrogateescape") == body


def test_latin1_micro_sign_decoded() -> None:
    doc = tokenize(b"k 1 ( [0.1\xb5m]\n")
    assert doc.encoding == "cp1252" and "µ" in doc.lines[0] and doc.problems == []


def test_mixed_encoding_is_reported_with_location() -> None:
    doc = tokenize("# ä\n".encode() + b"k 1 ( \xb5\n")
    (p,) = doc.problems
    assert (p.kind, p.line, p.start, p.detail) == ("undecodable", 2, 6, "0xB5")


def test_nul_and_control_characters() -> None:
    doc = tokenize(b"a 1\x00\nb 2\x07\nc 3\rx\n")
    assert [(p.kind, p.line) for p in doc.problems] == [
        ("nul-byte", 1), ("control-char", 2), ("control-char", 3)]


def test_keys() -> None:
    k = parse_key("np_grp[5].achse[2].versch")
    assert k is not None and k.pattern == "np_grp[].achse[].versch" and k.indices == (5, 2)
    k = parse_key("trafo[1].linkage[2][3]")
    assert k is not None and k.pattern == "trafo[].linkage[][]" and k.indices == (1, 2, 3)
    assert parse_key("coordinate_system.2nd_path_on_actual_1st_path") is not None
    assert parse_key("np_grp[x]") is None and parse_key("a..b") is None
    huge = parse_key("np_grp[99999999999999999999].achse[0].versch")
    assert huge is not None and any(i >= HUGE_INDEX for i in huge.indices)


def test_tool_list_indices_from_one() -> None:
    e = one("wz[1].gueltig 1 ( P-TOOL-00005 : Validity")
    assert e.key is not None and e.key.indices == (1,)


def test_a_short_crlf_list_is_text_not_binary() -> None:
    """The \\r of CRLF endings are not control characters: a list of short CRLF lines was taken
    for a binary file (S013, nothing else checked) because each ending counted as one."""
    data = b"kenngr.swe_pos 0\r\n" * 12 + b"Ende\r\n"
    doc = tokenize(data)
    assert [p.kind for p in doc.problems] == []
    assert len(doc.entries) == 12
    assert set(doc.endings) == {"\r\n"}
    stray = tokenize(b"a 1\r\n" + b"b\x01 1\r\n" * 10)
    assert "binary" in [p.kind for p in stray.problems]  # real control characters still count
    one = tokenize(b"a 1\r\nb 1 # x\x01y\r\n" + b"kenngr.swe_pos 0\r\n" * 10)
    assert [p.kind for p in one.problems] == ["control-char"]


_COMMENTED = st.one_of(
    st.text(alphabet="#*-=_aZ9 .[]\t|ä", max_size=12),
    st.tuples(st.sampled_from(["a", "wz[1].x", "k[01]", "Ende", "a.b[2][3]", "_x", "9z", "a]"]),
              st.sampled_from([" ", "\t", "  "]),
              st.sampled_from(["1", "-2", "0x1F", "1.5", "./p", ".5", ".x", "A | B", "A|B", '"q s"', "W", ""]),
              st.sampled_from(["", " # c", "  ( P-TOOL-00005 : x", " plain", " |x"])).map("".join))


def _fields(obj: object) -> dict[str, object]:
    return {k: getattr(obj, k) for k in obj.__slots__}  # type: ignore[attr-defined]


@settings(max_examples=400, deadline=None)
@given(_COMMENTED)
@example("#****")
@example("#* .x 1")
@example("#-a 1")
@example("wz[1].x  5 ( P-TOOL-00005 : x")
def test_a_hash_comment_reads_as_its_entry_would(rest: str) -> None:
    """`#` and then no key (`#****`) is a comment without an entry, read at once; `#key value` holds the
    entry that scanning the rest as an entry finds."""
    s = "#" + rest
    problems: list[Problem] = []
    item = scan_line(s, 3, problems)
    if rest[:1] in ("", " ", "\t"):
        return
    inner = scan_entry(s, 1, 3, None)  # the careful reading of what follows the `#`
    commented = inner if type(inner) is Entry and inner.value else None
    assert type(item) is Comment and item.text == s
    assert (item.commented_out is None) == (commented is None)
    if commented is not None:
        assert item.commented_out is not None and _fields(item.commented_out) == _fields(commented)
    assert problems == [Problem("hash-no-space", 3, 0, 1, "entry" if commented is not None else "")]

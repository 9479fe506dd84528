"""Property tests of the tokenizer (bounded so CI stays fast)."""

from __future__ import annotations

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.lists.encoding import decode
from zero.lists.model import Blank, Comment, End, Entry, Invalid
from zero.lists.tokenizer import _ascii_controls, _control_count, _control_re, tokenize, tokenize_text


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=2000))
def test_tokenizer_never_raises_and_is_lossless(data: bytes) -> None:
    doc = tokenize(data)
    text, encoding, bom = decode(data)
    rebuilt = "".join(line + end for line, end in zip(doc.lines, doc.endings, strict=True))
    assert rebuilt == text
    assert (b"\xef\xbb\xbf" if bom else b"") + rebuilt.encode(encoding, "surrogateescape") == data
    assert len(doc.items) == len(doc.lines)


@settings(max_examples=200, deadline=None)
@given(st.binary(max_size=500))
def test_every_line_is_one_item(data: bytes) -> None:
    doc = tokenize(data)
    for n, item in enumerate(doc.items, 1):
        assert isinstance(item, Entry | Comment | Blank | End | Invalid) and item.line == n


_FAST_PARTS = st.sampled_from([
    "np_grp[1].achse[2].versch", "kenngr.swe_pos", "a", "Ende", "5abc", "x.0y", " ", "\t", "  ",
    "1", "-5", "+7", "0x1F", "1.5", "1e3", ".5", "[3]", "]", ".m", "P-AXIS-00212.0", "A|B", "|",
    "A", "|B", '"q s"', '"', "( c", "/* x */", "# h", "#", "plain", "\xa0", "\x0c", "\r", "µ", "ä",
    "#\t", "\x00", "\x0b", "\u2028",
])


@pytest.mark.slow
@settings(max_examples=500, deadline=None)
@given(st.lists(st.lists(_FAST_PARTS, max_size=6).map("".join), max_size=12).map("\n".join))
@example("Ende 5\na 1\nEnde")
@example("a .b 1\na [1] 2\na 1 |B\na 1| B\nk \"q s\" c\nk\xa0v 1\nk v\xa0c")
def test_fast_path_reads_exactly_like_the_careful_scanner(text: str) -> None:
    def shape(doc):  # type: ignore[no-untyped-def]
        out = []
        for item in doc.items:
            fields = {k: getattr(item, k) for k in getattr(item, "__slots__", ())}
            if "commented_out" in fields and fields["commented_out"] is not None:
                co = fields["commented_out"]
                fields["commented_out"] = {k: getattr(co, k) for k in co.__slots__}
            out.append((type(item).__name__, fields))
        return out, doc.problems

    assert shape(tokenize_text(text)) == shape(tokenize_text(text, use_fast=False))


@given(st.lists(st.sampled_from([b"a", b"\xb5", b"\xc2\xb5", b"\xe2\x82\xac", b"\xff", b"\n", b"\xed\xb2\x80"]),
                max_size=40).map(b"".join))
@settings(max_examples=300)
def test_mixed_encoding_is_told_from_stray_bytes(data: bytes) -> None:
    """UTF-8 with stray bytes stays UTF-8 only when it also holds real multi-byte characters
    (the one-regex test equals the per-character definition)."""
    text, encoding, _ = decode(data)
    assert text.encode(encoding, "surrogateescape") == data
    try:
        data.decode("utf-8")
        return
    except UnicodeDecodeError:
        pass
    escaped = data.decode("utf-8", "surrogateescape")
    real = any(ord(ch) > 0x7F and not 0xDC80 <= ord(ch) <= 0xDCFF for ch in escaped)
    assert (encoding == "utf-8") == real


@given(st.text(alphabet=st.characters(codec="utf-8") | st.sampled_from("\x00\x07\t\n\r\x1b\x7f\x85 a#"), max_size=300))
@example("a\r\nb\x00\x7f")
@example("\x80\x9f\udc80")
@example("a\r\nb\r")
@example("a\x1f")
def test_control_characters_are_counted_as_the_regex_counts_them(text: str) -> None:
    """The ASCII shortcut counts exactly what the regex finds."""
    assert _control_count(text) == len(_control_re().findall(text))
    plain = text.encode("ascii", "ignore")
    assert _control_count(plain.decode("ascii")) == len(_control_re().findall(plain.decode("ascii")))
    assert _ascii_controls(plain) == len(_control_re().findall(plain.decode("ascii")))  # a big list's bytes


_CODE_PAGE_BYTES = [b"a", b"\n", b"\xe4", b"\xfc", b"\xa0", b"\x80", b"\x81", b"\x93", b"\x9f", b"\xc3\xa4"]


@given(st.lists(st.sampled_from(_CODE_PAGE_BYTES), max_size=40).map(b"".join))
@example(b"\xe4\n")
@example(b"\x81")
def test_a_list_that_is_no_utf8_reads_as_cp1252_else_latin1(data: bytes) -> None:
    """The built-in Latin-1 codec reads a list without the bytes where CP1252 differs: the text is CP1252's."""
    text, encoding, _ = decode(data)
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        pass
    else:
        assert encoding == "utf-8"
        return
    if encoding == "utf-8":  # real UTF-8 sequences among stray bytes
        return
    try:
        want = (data.decode("cp1252"), "cp1252")
    except UnicodeDecodeError:
        want = (data.decode("latin-1"), "latin-1")
    assert (text, encoding) == want

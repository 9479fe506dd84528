"""Lists written in another code page (CP850 from DOS tools): umlauts in comments are no control
characters, and a declared code page reads, and writes back, the list as it is (issue 24)."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import FIXTURES, builtin_registry, golden
from zero.engine.fixes import fix_bytes
from zero.engine.formatting import format_bytes
from zero.engine.lint import LintOptions, lint_bytes, lint_file
from zero.errors import ZeroError
from zero.lists.encoding import declarable, decode, document_bytes, encode_text
from zero.lists.model import Comment, Entry
from zero.lists.tokenizer import tokenize

CP850 = FIXTURES / "codepage" / "cp850_comments.lis"


def _findings(path: Path, options: LintOptions | None = None) -> list[dict[str, object]]:
    out = []
    for d in lint_file(path, builtin_registry(), options).diagnostics:
        j = d.to_json()
        j["path"] = path.name
        out.append(j)
    return out


def test_cp850_comments_undeclared(request: pytest.FixtureRequest) -> None:
    """Read as Latin-1 (0x81 is undefined in Windows-1252): the C1 controls in every kind of comment
    (full line, commented-out entry, `#`, `(`, `/* */`, the `Ende` line, after it) are letters of a
    comment; what stays is the C1 control in a value and the C0 control (BEL) in a comment."""
    actual = _findings(CP850)
    expected = golden(FIXTURES / "codepage" / "cp850_comments.expected.json", actual,
                      request.config.getoption("--update-golden"))
    assert actual == expected
    assert [(d["line"], d["code"], d["message"]) for d in actual] == [
        (6, "S010", "control character U+0081: invisible, but part of what the controller reads"),
        (7, "S010", "control character U+0007: invisible, but part of what the controller reads"),
    ]


def test_cp850_comments_declared(request: pytest.FixtureRequest) -> None:
    """Declared as CP850: the value `Xü` is text, only the BEL in the comment is left."""
    actual = _findings(CP850, LintOptions(encoding="cp850"))
    expected = golden(FIXTURES / "codepage" / "cp850_comments.cp850.expected.json", actual,
                      request.config.getoption("--update-golden"))
    assert actual == expected
    assert [(d["line"], d["code"]) for d in actual] == [(7, "S010")]


def test_declared_code_page_reads_the_letters_and_writes_the_bytes() -> None:
    data = CP850.read_bytes()
    doc = tokenize(data, str(CP850), "cp850")
    assert doc.encoding == "cp850" and not doc.bom
    assert doc.lines[0] == "# Achsparameter für die alte Fräse, geschrieben unter DOS (CP850)"
    assert doc.lines[4].endswith("/* ÄNDERUNG ÖL ÜBERLAUF */")
    item = doc.items[3]
    assert isinstance(item, Entry) and item.comment == "( negativer Endschalter, Änderung: Größe"
    assert isinstance(doc.items[1], Comment) and doc.items[1].commented_out is not None
    assert document_bytes(doc) == data
    assert tokenize(data, "x.lis").encoding == "latin-1"  # not declared: detected as before


@pytest.mark.parametrize("comment", [
    b"# Gr\x94\x81e", b"( Gr\x94\x81e", b"/* Gr\x94\x81e */", b"#\tGr\x94\x81e",
])
def test_c1_in_a_trailing_comment_is_not_s010(comment: bytes) -> None:
    kinds = [p.kind for p in tokenize(b"kenngr.swe_pos 1 " + comment + b"\n").problems]
    assert "control-char" not in kinds


@pytest.mark.parametrize(("line", "column"), [
    (b"kenngr.name X\x81Y # ok\n", 13),  # in the value
    (b"kenngr.name \"a\x81 b\" ( ok\n", 14),  # in a quoted value
    (b"kenngr.swe_pos 1 plain words \x81\n", 29),  # plain words: after a string the controller reads them
])
def test_c1_in_what_the_controller_reads_is_still_s010(line: bytes, column: int) -> None:
    problems = [p for p in tokenize(line).problems if p.kind == "control-char"]
    assert [(p.start, p.detail) for p in problems] == [(column, "U+0081")]


@pytest.mark.parametrize("control", [b"\x01", b"\x1b", b"\x7f", b"\r"])
def test_c0_controls_and_del_in_a_comment_are_still_s010(control: bytes) -> None:
    doc = tokenize(b"kenngr.swe_pos 1 # a" + control + b"b\n# c" + control + b"d\n")
    assert [p.kind for p in doc.problems] == ["control-char", "control-char"]


def test_c1_in_comments_is_no_binary_file() -> None:
    """Ten umlauts in a short list: not "not a text file" (S013) any more."""
    data = (b"# Achsparameter f\x81r die alte Maschine\n"
            b"kenngr.swe_pos   15000000   # Endschalter f\x81r X\n"
            b"kenngr.swe_neg   -15000000  ( negativer Endschalter, gepr\x81ft \x84nderung \x94l\n"
            b"# Gr\x94\xe1e und L\x84nge: \x8e \x99 \x9a\n"
            b"Ende\n")
    assert tokenize(data).problems == []
    binary = bytes(range(0x80, 0xA0)) * 4 + b"\n"  # C1 controls outside any comment: still binary
    assert "binary" in [p.kind for p in tokenize(binary).problems]


def test_a_byte_the_declared_code_page_lacks_is_kept_and_said() -> None:
    data = b"kenngr.swe_pos 1 # \x81\n"  # 0x81 is undefined in Windows-1252
    doc = tokenize(data, "a.lis", "cp1252")
    assert document_bytes(doc) == data
    result = lint_bytes(data, builtin_registry(), "a.lis", LintOptions(encoding="cp1252"))
    assert [(d.code, d.message) for d in result.diagnostics] == [
        ("S007", "byte 0x81 is not defined in cp1252, the encoding the configuration declares; what the controller "
         "does with these bytes is not documented")]


@pytest.mark.parametrize(("name", "canonical"), [
    ("cp850", "cp850"), ("CP850", "cp850"), ("IBM850", "cp850"), ("latin1", "latin-1"), ("utf8", "utf-8"),
    ("utf-8-sig", "utf-8"), ("cp1252", "cp1252"), ("iso8859-15", "iso8859-15"), ("cp437", "cp437"),
])
def test_declarable_codecs(name: str, canonical: str) -> None:
    assert declarable(name) == canonical


@pytest.mark.parametrize("name", ["utf-16", "utf-16-le", "utf-32", "utf-7", "shift_jis", "cp037", "base64",
                                  "rot13", "unicode_escape", "raw_unicode_escape", "iso2022_jp", "klingon"])
def test_codecs_that_cannot_hold_a_list_are_refused(name: str) -> None:
    with pytest.raises(ValueError, match=r"not a codec Python knows|cannot hold a parameter list"):
        declarable(name)


def test_decode_with_a_declared_utf8_keeps_the_bom() -> None:
    assert decode(b"\xef\xbb\xbfa 1\n", "utf-8") == ("a 1\n", "utf-8", True)
    assert decode(b"a \x84\n", "cp850") == ("a ä\n", "cp850", False)
    assert encode_text("a ä\n", "cp850", True) == b"\xef\xbb\xbfa \x84\n"
    with pytest.raises(ZeroError, match="cannot be written in cp850"):
        encode_text("a €\n", "cp850")


def test_format_and_fix_keep_a_declared_code_page() -> None:
    data = b"kenngr.swe_pos 15000000 # f\x81r X\n# Gr\x94\xe1e\nkenngr.swe_neg -15000000\n"
    formatted = format_bytes(data, "a.lis", builtin_registry(), encoding="cp850")
    assert formatted.decode("cp850").splitlines()[1] == "# Größe"
    assert b"f\x81r X" in formatted and b"Gr\x94\xe1e" in formatted
    glued = b"#Gr\x94\xe1e\nkenngr.swe_pos 15000000 # f\x81r X\n"
    fixed = fix_bytes(glued, "a.lis", builtin_registry(), LintOptions(encoding="cp850"))
    assert fixed.fixed == b"# Gr\x94\xe1e\nkenngr.swe_pos 15000000 # f\x81r X\n"


def test_format_of_an_undeclared_code_page_says_how_to_declare_it() -> None:
    with pytest.raises(ZeroError, match=r"byte 0x81 reads as control character U\+0081 in latin-1.*encoding = "):
        format_bytes(b"kenngr.swe_pos 1 # f\x81r X\n", "a.lis", builtin_registry())


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=400), st.sampled_from(["cp850", "cp437", "cp1252", "latin-1", "iso8859-15", "mac-roman",
                                                 "koi8-r", "ascii", "utf-8"]))
def test_any_bytes_in_a_declared_code_page_come_back_as_they_were(data: bytes, codec: str) -> None:
    doc = tokenize(data, "x.lis", codec)
    assert document_bytes(doc) == data


def _decode_whole(data: bytes) -> tuple[str, str, bool]:
    """What decode gives, the whole text decoded at each step (as it did before it decoded from the first stray
    byte on)."""
    try:
        return data.decode("utf-8"), "utf-8", False
    except UnicodeDecodeError:
        pass
    text = data.decode("utf-8", "surrogateescape")
    if len(text) < len(data):
        return text, "utf-8", False
    if not any(0x80 <= b < 0xA0 for b in data):
        return data.decode("latin-1"), "cp1252", False
    try:
        return data.decode("cp1252"), "cp1252", False
    except UnicodeDecodeError:
        return data.decode("latin-1"), "latin-1", False


_PIECES = [b"a 1\n", b"# \xc3\xa4\n", b"\xb5", b"\xe2\x82\xac", b"\x81", b"\x9f", b"\xc3", b"\xa4", b"\xf0\x9f\x98\x80",
           b"\xed\xa0\x80", b"x", b"\xef\xbb\xbf"]


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(_PIECES), max_size=12).map(b"".join))
def test_decode_as_the_whole_text_decoded(data: bytes) -> None:
    """Real UTF-8 before or after the first stray byte, C1 bytes before or after it: decoded as before."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = b"x" + data
    assert decode(data) == _decode_whole(data)

"""Property tests (bounded so CI stays fast)."""

from __future__ import annotations

from hypothesis import example, given, settings
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


# --------------------------------------------------------------- convert round trips

_KEYS = st.one_of(
    st.builds("np_grp[{}].achse[{}].versch".format, st.integers(0, 96), st.integers(0, 31)),
    st.builds("np_grp[{}].achse[{}].inaktiv".format, st.integers(0, 96), st.integers(0, 31)),
    st.sampled_from(["kenngr.swe_pos", "kenngr.achs_mode", "g53_verfuegbar", "default_index",
                     "lr_param.kv", "a", "a.b"]),
    st.builds("wz[{}].name".format, st.integers(1, 10**30)),
    st.builds("getriebe[{}].dynamik.vb_max".format, st.integers(0, 4_000_000_000)),
)
_VALUES = st.one_of(
    st.integers(-(2**31), 2**32 - 1).map(str),
    st.sampled_from(["-2147483648", "4294967295", "0", "-0", "010", "+7", "0x400001", "0X1f", "1.5",
                     "1e3", "1.50", "TRUE", "FALSE", "ERROR", "on", "no", "yes", "null", "~",
                     "PLC_INFO | MOS", "REPORT | REPORT_EXTENDED |PRINT", "P-AXIS-00212.0",
                     "P-AXIS-00376", '"text with ( # spaces"', '"a:b"', "X_Achse",
                     "./listen/achsmds1.lis", "20804,20805", "cnc_ve_%s_[%d]_r", "µm", "'q'"]),
)
_COMMENTS = st.one_of(
    st.none(),
    st.sampled_from(["# hash note", "#", "( P-ZERO-00003 : offset", "( unclosed ( nested)",
                     "/* 20 */ ( second", "plain words", "( with # and \"quotes\" : colon",
                     "( Maße in µm", "#x 5"]),
)
_GAP = st.sampled_from([" ", "  ", "\t", " \t ", "      "])
_FULL_LINES = st.sampled_from(["# comment", "#", "#\ttab", "#key 5", "#np_grp[0].achse[0].versch 1",
                               "", "\t", "   ", "  # indented", "# ä µ €"])


@st.composite
def _lists(draw: st.DrawFn) -> bytes:
    canonical = draw(st.booleans())
    lines: list[str] = []
    for _ in range(draw(st.integers(0, 25))):
        for _ in range(draw(st.integers(0, 2))):
            lines.append(draw(_FULL_LINES))
        key, value, comment = draw(_KEYS), draw(_VALUES), draw(_COMMENTS)
        if canonical:
            from zero.structured import canonical_line

            lines.append(canonical_line(key, value, comment, 54, 70))
        else:
            line = key + draw(_GAP) + value
            if comment is not None:
                line += draw(_GAP) + comment
            lines.append(line + draw(st.sampled_from(["", " ", "\t"])))
    lines.extend(draw(st.lists(_FULL_LINES, max_size=2)))
    end = draw(st.sampled_from(["Ende", "Ende  ", None]))
    if end is not None:
        lines.append(end)
        lines.extend(draw(st.lists(st.sampled_from(["", " "]), max_size=2)))
    newline = draw(st.sampled_from(["\n", "\r\n"]))
    text = newline.join(lines) + (newline if lines and draw(st.booleans()) else "")
    encoding = draw(st.sampled_from(["utf-8", "cp1252"]))
    return text.encode(encoding)


@settings(max_examples=150, deadline=None)
@given(_lists(), st.sampled_from(["yaml", "toml", "json"]))
def test_list_to_structured_to_list_is_the_identity(data: bytes, fmt: str) -> None:
    import json
    import tomllib

    import yaml

    from zero.convert import convert, read_tree
    from zero.structured import nest

    structured = convert(data, "lis", fmt, "gen.lis").output
    assert convert(structured, fmt, "lis", "gen." + fmt, check=False).output == data
    # the standard loaders read the same data zero holds
    if fmt == "yaml":
        loaded = yaml.safe_load(structured)
    elif fmt == "toml":
        loaded = tomllib.loads(structured.decode())
    else:
        loaded = json.loads(structured)
    loaded.pop("_zero")
    root, flat = nest(read_tree(data, "lis", "gen.lis").leaves)

    def plain(node: dict[str, object]) -> dict[str, object]:
        return {k: plain(v) if isinstance(v, dict) else v.value  # type: ignore[attr-defined]
                for k, v in node.items()}

    def str_keys(x: object) -> object:
        return {str(k): str_keys(v) for k, v in x.items()} if isinstance(x, dict) else x

    expected = plain(root)
    expected.update({leaf.key: leaf.value for leaf in flat})
    assert str_keys(loaded) == str_keys(expected)


_FAST_PARTS = st.sampled_from([
    "np_grp[1].achse[2].versch", "kenngr.swe_pos", "a", "Ende", "5abc", "x.0y", " ", "\t", "  ",
    "1", "-5", "+7", "0x1F", "1.5", "1e3", ".5", "[3]", "]", ".m", "P-AXIS-00212.0", "A|B", "|",
    "A", "|B", '"q s"', '"', "( c", "/* x */", "# h", "#", "plain", "\xa0", "\x0c", "\r", "µ", "ä",
])


@settings(max_examples=500, deadline=None)
@given(st.lists(st.lists(_FAST_PARTS, max_size=6).map("".join), max_size=12).map("\n".join))
@example("Ende 5\na 1\nEnde")
@example("a .b 1\na [1] 2\na 1 |B\na 1| B\nk \"q s\" c\nk\xa0v 1\nk v\xa0c")
def test_fast_path_reads_exactly_like_the_careful_scanner(text: str) -> None:
    from zero.tokenizer import tokenize_text

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

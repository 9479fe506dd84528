"""Property tests across the packages: lint and convert on generated lists (bounded so CI
stays fast). The tokenizer's own properties are in tests/lists/test_tokenizer_properties.py."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import builtin_registry, generated_lists, lint_text

LINE_PARTS = st.sampled_from([
    "np_grp[1].achse[2].versch", "kenngr.swe_pos", "g53_verfuegbar", "#", "# c", "#key 1",
    " ", "\t", "1", "-5", "0x1F", "P-AXIS-00212.0", "A | B", '"q s"', '"open', "( c", "/* x */",
    "Ende", "[", "]", ".", "µ", "ä", "\x00", "\r", "99999999999999999999999",
])


@pytest.mark.slow
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


@pytest.mark.slow
@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 96), st.integers(0, 31), st.integers(-(2**31) + 1, 2**31 - 2)),
                max_size=40))
def test_valid_offsets_give_no_errors(rows: list[tuple[int, int, int]]) -> None:
    text = "g53_verfuegbar 1\n" + "".join(
        f"np_grp[{i}].achse[{j}].versch {v}\n" for i, j, v in rows)
    result = lint_text(text)
    assert all(d.severity.label != "error" for d in result.diagnostics)
    assert {d.code for d in result.diagnostics} <= {"R007"}


# --------------------------------------------------------------- convert round trips


@pytest.mark.slow
@settings(max_examples=150, deadline=None)
@given(generated_lists(), st.sampled_from(["yaml", "toml", "json"]))
def test_list_to_structured_to_list_is_the_identity(data: bytes, fmt: str) -> None:
    import json
    import tomllib

    import yaml

    from zero.engine.convert import convert
    from zero.structured.formats import read_tree
    from zero.structured.tree import nest

    registry = builtin_registry()
    structured = convert(data, "lis", fmt, registry, "gen.lis").output
    assert convert(structured, fmt, "lis", registry, "gen." + fmt, check=False).output == data
    # the standard loaders read the same data zero holds
    if fmt == "yaml":
        loaded = yaml.safe_load(structured)
    elif fmt == "toml":
        loaded = tomllib.loads(structured.decode())
    else:
        loaded = json.loads(structured)
    loaded.pop("_zero")
    root, flat = nest(read_tree(data, "lis", registry, "gen.lis").leaves)

    def plain(node: dict[str, object]) -> dict[str, object]:
        return {k: plain(v) if isinstance(v, dict) else v.value  # type: ignore[attr-defined]
                for k, v in node.items()}

    def str_keys(x: object) -> object:
        return {str(k): str_keys(v) for k, v in x.items()} if isinstance(x, dict) else x

    expected = plain(root)
    expected.update({leaf.key: leaf.value for leaf in flat})
    assert str_keys(loaded) == str_keys(expected)


_DIFF_LINES = st.lists(st.sampled_from([b"a\n", b"b\n", b"c\n", b"\n", b"k 1\n", b"k 1  \n", b"x\r\n", b"end"]),
                       max_size=60)


def _patched(before: bytes, patch: bytes) -> bytes:
    """``patch`` (a unified diff zero wrote) applied to ``before``: each hunk's - and context lines
    must be where it says, in order."""
    old = before.split(b"\n")
    old_lines = [x + b"\n" for x in old[:-1]] + ([old[-1]] if old[-1] else [])
    out: list[bytes] = []
    at = 0
    rows = patch.split(b"\n")[2:]
    k = 0
    while k < len(rows) and rows[k].startswith(b"@@"):
        start = int(rows[k].split(b" ")[1][1:].split(b",")[0])
        length = rows[k].split(b" ")[1][1:].split(b",")
        first = start - 1 if len(length) == 1 or int(length[1]) else start
        out += old_lines[at:first]
        at = first
        k += 1
        while k < len(rows) and rows[k][:1] in (b" ", b"-", b"+"):
            text = rows[k][1:]
            ends = not (k + 1 < len(rows) and rows[k + 1] == b"\\ No newline at end of file")
            line = text + b"\n" if ends else text
            k += 1 if ends else 2
            if rows[k - (1 if ends else 2)][:1] in (b" ", b"-"):
                assert old_lines[at] == line, (old_lines[at], line)
                at += 1
            if rows[k - (1 if ends else 2)][:1] in (b" ", b"+"):
                out.append(line)
    return b"".join(out + old_lines[at:])


@settings(max_examples=400, deadline=None)
@given(_DIFF_LINES, _DIFF_LINES, st.sampled_from([0, 2_500]))
def test_unified_diff_turns_before_into_after(a: list[bytes], b: list[bytes], small: int) -> None:
    """zero's line diff (issue 43: linear-ish, difflib only for small gaps) is a correct patch:
    with difflib for small gaps and with anchors only (``small`` 0)."""
    import zero.engine.fixes as fixes

    if a and a[-1] != b"end":
        a = [x if x != b"end" else b"e\n" for x in a]
    b = [x if x != b"end" else b"e\n" for x in b[:-1]] + b[-1:]
    a = [x if x != b"end" else b"e\n" for x in a[:-1]] + a[-1:]
    before, after = b"".join(a), b"".join(b)
    kept = fixes._SMALL
    fixes._SMALL = small
    try:
        patch = fixes.unified_diff("f.lis", before, after)
    finally:
        fixes._SMALL = kept
    assert (patch == b"") == (before == after)
    if patch:
        assert _patched(before, patch) == after

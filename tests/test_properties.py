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

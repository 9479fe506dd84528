"""The value model binds each shape of key by the pattern and indices the tokenizer gave it (issue 40: no key
parsed again): for every shape a document's columns hold, they are what ``parse_key`` reads of its key."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from zero.catalog.registry import load_registry
from zero.catalog.values import ListValues
from zero.lists.model import parse_key
from zero.lists.tokenizer import tokenize

_NAMES = st.sampled_from(["a", "b_c", "wz", "x1", "_u", "kenngr", "achs_nr"])
_INDICES = st.sampled_from(["0", "1", "01", "007", "12", "99999999999999999999999"])
_PART = st.one_of(_NAMES.map(lambda n: "." + n), _INDICES.map(lambda i: f"[{i}]"),
                  st.sampled_from(["..", ".", "[", "]", "[]", "[a]"]))
_KEYS = st.tuples(_NAMES, st.lists(_PART, max_size=4)).map(lambda t: t[0] + "".join(t[1]))
_LINES = st.tuples(_KEYS, st.sampled_from([" ", "\t", "   "]), st.sampled_from(["1", "x", "0x1", '"s"']),
                   st.sampled_from(["", " # c", "  ( P-AXIS-00001 : t"])).map("".join)
_REGISTRY = load_registry()


def _assert_shapes_are_their_keys(text: bytes) -> int:
    doc = tokenize(text, "t.lis")
    cols = doc.columns
    bound = ListValues.of(doc, _REGISTRY, "AXIS")
    for sid, sh in enumerate(cols.shapes):
        key = parse_key(sh.head + ("[0]" if sh.indexed else "") + sh.tail)
        assert key is not None, sh
        indices = key.indices[1:] if sh.indexed else key.indices
        assert (key.pattern, indices) == (cols.patterns[sh.pattern], sh.indices)
        assert bound.shape_keys[sid] == (key.pattern, indices, sh.indexed)
    for row in range(len(cols)):  # each row's key is its shape's with its first index
        key = parse_key(cols.key_text(row))
        assert key is not None and cols.key(row) == key
    return len(cols.shapes)


@settings(max_examples=300, deadline=None)
@given(st.lists(_LINES, min_size=1, max_size=8))
def test_each_shape_is_bound_as_its_key_reads(lines: list[str]) -> None:
    _assert_shapes_are_their_keys("".join(f"{line}\n" for line in lines).encode())


def test_the_careful_way_and_huge_indices() -> None:
    text = b"a[01].b 1\nwz[007].x[99999999999999999999999] 2\nkenngr.swe_pos 3\na[1].b 4\nx1[2][3] 5\n"
    assert _assert_shapes_are_their_keys(text) >= 4

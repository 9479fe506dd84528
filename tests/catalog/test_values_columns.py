"""ListValues binds per distinct key pattern over the document's columns (issue 40) and answers as a
binding of every entry did: ``resolved`` in order, ``by_id`` with the later entry winning, each element
in the order the list first sets it, an alias and its documented key as one parameter."""

from __future__ import annotations

from hypothesis import example, given, settings
from hypothesis import strategies as st

from conftest import bound_one_by_one, builtin_registry, generated_lists
from zero.catalog.values import ListValues, Resolved
from zero.lists.tokenizer import tokenize


def _values(text: str, kind: str | None = None) -> ListValues:
    return ListValues.of(tokenize(text.encode("utf-8"), "t.lis"), builtin_registry(), kind)


def _reference(values: ListValues) -> tuple[list[Resolved], dict[str, dict[tuple[int, ...], Resolved]]]:
    """Every entry bound on its own, as ListValues.of did before it worked per pattern."""
    resolved = bound_one_by_one(values.doc, values.registry, values.kind)
    by_id: dict[str, dict[tuple[int, ...], Resolved]] = {}
    for res in resolved:
        assert res.entry.key is not None
        by_id.setdefault(res.spec.id, {})[res.entry.key.indices] = res
    return resolved, by_id


def _same(values: ListValues) -> None:
    resolved, by_id = _reference(values)
    assert bool(values.resolved) == bool(resolved)  # answered before it is built
    assert list(values.resolved) == resolved
    assert list(values.by_id) == list(by_id)  # the parameters in the order the list first sets them
    for pid, elements in by_id.items():
        assert pid in values.by_id
        got = values.by_id.get(pid)
        assert got == elements and list(got) == list(elements)
    assert "P-NONE-00000" not in values.by_id and values.by_id.get("P-NONE-00000", {}) == {}
    assert len(values.by_id) == len(by_id)


def test_an_alias_and_its_key_are_one_parameter_and_the_later_entry_wins() -> None:
    values = _values("kenngr.homing.homing_type CNC_CONTROLLED\nkopf.achs_nr 1\n"
                     "kenngr.homing_type DRIVE_CONTROLLED\n", "AXIS")
    _same(values)
    (res,) = values.by_id["P-AXIS-00299"].values()
    assert res.entry.line == 3 and res.via_alias


def test_leading_zeros_and_keys_of_several_shapes_are_one_element() -> None:
    values = _values("np_grp[1].achse[2].versch 1\nnp_grp[01].achse[2].versch 2\nnp_grp[1].achse[02].versch 3\n"
                     "np_grp[2].achse[2].versch 4\nnp_grp[1].achse[2].inaktiv 1\n", "ZERO")
    _same(values)
    offsets = values.by_id["P-ZERO-00003"]
    assert list(offsets) == [(1, 2), (2, 2)] and offsets[(1, 2)].entry.line == 3
    assert values.number_of("P-ZERO-00003", (1, 2)) == 3


def test_a_list_without_a_bound_key_has_no_values() -> None:
    values = _values("a.b 1\nunknown_key 2\n")
    assert not values.resolved and list(values.resolved) == [] and len(values.by_id) == 0


def test_groups_hold_every_keyed_row_by_pattern_in_order() -> None:
    values = _values("wz[1].laenge 5\nwz[1].radius 2\nwz[2].laenge 6\nbad key here\nwz[3].laenge 7\n", "TOOL")
    assert values.groups == {"wz[].laenge": [0, 2, 4], "wz[].radius": [1], "bad": [3]}
    assert list(values.groups) == ["wz[].laenge", "wz[].radius", "bad"]  # first written first
    assert [values.entry_at(r).line for r in values.groups["wz[].laenge"]] == [1, 3, 5]


@settings(max_examples=150, deadline=None)
@given(generated_lists())
def test_generated_lists_bind_as_entry_by_entry(data: bytes) -> None:
    doc = tokenize(data, "t.lis")
    _same(ListValues.of(doc, builtin_registry()))
    _same(ListValues.of(tokenize(data, "t.lis"), builtin_registry(), "ZERO"))


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(0, 7), min_size=1, max_size=9), st.integers(4096, 4300), st.lists(
    st.tuples(st.integers(0, 5000), st.integers(0, 9)), max_size=2))
def test_rows_by_shape_of_a_repeating_table_are_those_of_one_pass(period: list[int], n: int,
                                                                 changes: list[tuple[int, int]]) -> None:
    """A big list repeating one sequence of shapes (a tool table) gets each shape's rows as ranges; the
    same rows as one pass over them, also where the sequence repeats a shape or one row breaks it."""
    from array import array

    from zero.catalog.values import _rows_by_shape

    shape = array("i", (period * (n // len(period) + 1))[:n])
    for at, sid in changes:
        if at < n:
            shape[at] = sid
    expected: list[list[int]] = [[] for _ in range(10)]
    for row, sid in enumerate(shape):
        expected[sid].append(row)
    assert [list(rows) for rows in _rows_by_shape(shape, 10)] == expected


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 50), st.integers(1, 7), st.integers(0, 200), st.sets(st.integers(0, 2000), max_size=3),
       st.sets(st.integers(1, 198), max_size=2))
@example(0, 2, 100, {51}, {30})  # one row moved: as many rows, the same ends, not evenly spaced
def test_a_column_taken_at_evenly_spaced_rows_is_the_rows_values(start: int, step: int, n: int,
                                                                  extra: set[int], dropped: set[int]) -> None:
    """take: a slice where the rows are evenly spaced, the values of exactly those rows either way (rows
    added between them, or a gap, break the spacing)."""
    from array import array

    from zero.catalog.values import take

    column = array("i", range(3000, 0, -1))
    spaced = range(start, start + step * n, step)
    rows = sorted({*(r for i, r in enumerate(spaced) if i not in dropped), *extra})
    assert list(take(column, rows)) == [column[r] for r in rows]


@settings(max_examples=150, deadline=None)
@given(generated_lists(), st.booleans())
def test_a_big_lists_numbers_are_read_without_its_entries_as_a_small_lists(data: bytes, built_first: bool) -> None:
    """``number_of`` of a big list (``by_id`` a lazy :class:`_ById`: the values read from the columns, no
    entry built) answers as that of a small one (every parameter's entries built at once), for every element
    the list sets, one it does not set, and before or after the parameter's entries are built."""
    from zero.catalog.values import _ById

    small = ListValues.of(tokenize(data, "t.lis"), builtin_registry(), "AXIS")
    big = ListValues.of(tokenize(data, "t.lis"), builtin_registry(), "AXIS")
    big._by_id = _ById(big)
    assert type(small.by_id) is dict
    for pid, elements in small.by_id.items():
        if built_first:
            big.by_id.get(pid)
        for indices in [*elements, (99,), ()]:
            assert big.number_of(pid, indices) == small.number_of(pid, indices), (pid, indices)
            assert big._value_of(pid, indices) == small._value_of(pid, indices)
    assert big.number_of("P-AXIS-00001", ()) == small.number_of("P-AXIS-00001", ())

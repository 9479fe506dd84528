"""The condition language of the kernel's start-up checks and the prose ranges: closed, and exact."""

from __future__ import annotations

import pytest

from zero.catalog.conditions import DEFAULT_LIST, compile_condition, parse, ref_elements, refs


def run(text: str, values: dict[str, float | int | None]) -> object:
    return compile_condition(parse(text))(lambda pid, index: values.get(pid if index is None else f"{pid}.{index}"))


def test_bits_bind_tighter_than_comparisons_and_arithmetic_as_usual() -> None:
    assert run("P-AXIS-00015 & 0x4 != 0", {"P-AXIS-00015": 0x400004}) is True  # (a & 4) != 0, not a & (4 != 0)
    assert run("P-AXIS-00015 & 0x4 != 0", {"P-AXIS-00015": 0x1}) is False
    assert run("P-AXIS-00126 - P-AXIS-00127 > 2 * 3", {"P-AXIS-00126": 10, "P-AXIS-00127": 3}) is True
    assert run("not P-AXIS-00001 == 1 or abs(-2) == 2", {"P-AXIS-00001": 1}) is True


def test_an_unknown_value_says_nothing_unless_the_other_side_decides() -> None:
    assert run("P-AXIS-00219 <= P-AXIS-00268", {"P-AXIS-00219": 5}) is None
    assert run("P-AXIS-00018 == 1 and P-AXIS-00412 == 0", {"P-AXIS-00018": 4}) is False
    assert run("P-AXIS-00018 == 4 or P-AXIS-00250 != 0", {"P-AXIS-00018": 4}) is True
    assert run("P-AXIS-00018 == 1 and P-AXIS-00412 == 0", {"P-AXIS-00018": 1}) is None
    assert run("P-AXIS-00212 / P-AXIS-00001 > 1", {"P-AXIS-00212": 5, "P-AXIS-00001": 0}) is None  # no division by 0


def test_elements_and_the_list_fact() -> None:
    node = parse("P-AXIS-00305 <= P-AXIS-00212.0 / 2 and DEFAULT_LIST == 0")
    assert refs(node) == ["P-AXIS-00305", "P-AXIS-00212"]
    assert ref_elements(node) == [("P-AXIS-00305", None), ("P-AXIS-00212", 0)]
    assert run("P-AXIS-00212.0 > P-AXIS-00212", {"P-AXIS-00212.0": 3, "P-AXIS-00212": 2}) is True
    assert run(f"{DEFAULT_LIST} == 1", {DEFAULT_LIST: 1}) is True


@pytest.mark.parametrize("text", ["__import__('os')", "P-AXIS-00016 ==", "P-AXIS-00016 = 1", "x < 1",
                                  "(P-AXIS-00016 < 1", "P-AXIS-00016 < 1)", "len(P-AXIS-00016)"])
def test_anything_else_is_refused(text: str) -> None:
    with pytest.raises(ValueError):
        parse(text)

"""Formal ranges: parsed once, evaluated against other values."""

from __future__ import annotations

import pytest

from zero.catalog.ranges import Bounds, parse_range


def bounds(text: str, own: str = "P-TEST-00001", **refs: float) -> Bounds:
    r = parse_range(text, own)
    assert r is not None, text
    return r.evaluate(lambda pid, idx: refs.get(pid.replace("-", "_")))


@pytest.mark.parametrize(
    ("text", "inside", "outside"),
    [
        ("MIN(SGN32) < versch < MAX(SGN32)", [0, -(2**31) + 1, 2**31 - 2], [-(2**31), 2**31 - 1]),
        ("0 ... 96 (number of zero offset groups: 97, application-specific)", [0, 96], [-1, 97]),
        ("0x00000001 - 0x10000000", [1, 0x400001], [0, 0x10000001]),
        ("-1 … MAX(SGN16)", [-1, 32767], [-2]),
        ("MAX(UNS32) ≥ eigenfrequenz_n ≥ 1", [1], [0]),
        ("1 - 12", [1, 12], [0, 13]),
        ("0 ... 250 (25%)", [250], [251]),
        ("0 <= x", [0], [-1]),
        ("> 0", [1], [0]),
        ("-45°≤ grinding_tilt_angle ≤ 45°", [-45, 45], [46]),
    ],
)
def test_formal_ranges(text: str, inside: list[int], outside: list[int]) -> None:
    b = bounds(text)
    assert all(b.contains(x) for x in inside)
    assert not any(b.contains(x) for x in outside)


def test_references_and_products() -> None:
    b = bounds("1 ≤ a_emergency ≤ 2*P-AXIS-00008", P_AXIS_00008=2000)
    assert b.contains(4000) and not b.contains(4001)
    b = bounds("P-AXIS-00177 < swe_pos < MAX(SGN32)", own="P-AXIS-00178", P_AXIS_00177=-5)
    assert b.contains(-4) and not b.contains(-5)
    # own ID as the variable
    b = bounds("0 ≤ P-AXIS-00214 ≤ P-AXIS-00212", own="P-AXIS-00214", P_AXIS_00212=10)
    assert b.contains(10) and not b.contains(11)


def test_unresolved_reference_leaves_side_open() -> None:
    b = bounds("1 ≤ a ≤ P-AXIS-00008")
    assert b.high is None and b.contains(10**12) and not b.contains(0)


def test_explicit_sets() -> None:
    r = parse_range("0/1")
    assert r is not None and r.allowed == (0, 1)
    r = parse_range("-1, 0, 1")
    assert r is not None and r.allowed == (-1, 0, 1)


@pytest.mark.parametrize(
    "text",
    [
        "Maximum 16 characters",
        "swe_neg < pos_refpkt < swe_pos",
        "700 ≤ slep_dyn ≤ 10240 ≤ slep_dyn ≤ 1024",
        "0 ≤ pos_einschw_zeit ≤ MAX(UNS32)/1000",
        "MAX(SGN32) > slep_max > 10* position lag at P-AXIS-00212",
        "0: off\r\n1: on",
        "----",
        "",
    ],
)
def test_prose_is_rejected(text: str) -> None:
    assert parse_range(text) is None


def test_refs_left_to_right_and_no_cycle_left_behind() -> None:
    """``refs`` is asked for every value whose range names another parameter: it must leave no
    reference cycle (garbage only the cycle collector frees; a fleet's lint grew by megabytes)."""
    import gc

    r = parse_range("-P-AXIS-00001 < x < P-AXIS-00003 + P-AXIS-00004", "P-AXIS-00009")  # Neg, BinOp, Ref
    assert r is not None
    assert [ref.id for ref in r.refs] == ["P-AXIS-00001", "P-AXIS-00003", "P-AXIS-00004"]
    gc.collect()
    gc.disable()
    try:
        for _ in range(100):
            r.refs  # noqa: B018 - asked for its side effects on the heap
        assert gc.collect() == 0
    finally:
        gc.enable()

"""The built-in catalogue's ranges parsed at build time (tools/gen_ranges.py, issue 40: start-up)."""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from conftest import script_module
from zero.catalog.data.ranges_compiled import RANGES
from zero.catalog.ranges import decode_range, encode_range, parse_range
from zero.catalog.registry import ParamSpec, load_registry

ROOT = Path(__file__).resolve().parents[2]


def _generator() -> ModuleType:
    return script_module(ROOT / "tools" / "gen_ranges.py")


def test_the_generated_modules_are_up_to_date() -> None:
    """Run ``python tools/gen_ranges.py`` after regenerating table.py or seeds.py."""
    data = ROOT / "src" / "zero" / "catalog" / "data"
    rendered = _generator().render()  # type: ignore[attr-defined]
    assert sorted(rendered) == sorted(p.name for p in data.glob("ranges_compiled*.py"))
    for name, text in rendered.items():
        assert (data / name).read_text(encoding="utf-8") == text, name


def test_a_lint_reads_the_ranges_of_its_kind_alone() -> None:
    """Each kind's ranges in a module of their own (issue 40: start-up): a kind without ranges, or an ID that
    names no kind, has none written; every written range is in its kind's module."""
    import importlib

    from zero.catalog.data import ranges_compiled
    from zero.catalog.registry import written_range

    assert written_range("P-HWCF-00001") is None and written_range("P-a.b-00001") is None
    for pid, written in RANGES.items():
        assert pid[2:6] in ranges_compiled.KINDS and written_range(pid) == written
        module = importlib.import_module(f"zero.catalog.data.ranges_compiled_{pid[2:6].lower()}")
        assert all(p[2:6] == pid[2:6] for p in module.RANGES)


def test_each_written_range_is_what_its_text_parses_to() -> None:
    assert len(RANGES) > 500
    for pid, (text, data) in RANGES.items():
        parsed, written = parse_range(text, pid), decode_range(data)
        assert written == parsed and repr(written) == repr(parsed), pid  # 1 and 1.0 are not the same here
        assert encode_range(parsed) == data


def test_the_registry_reads_the_written_range_and_parses_a_text_it_does_not_have() -> None:
    registry = load_registry()
    pid = next(p for p, (_, data) in RANGES.items() if data is not None)
    assert registry.range_of(registry.specs[pid]) == decode_range(RANGES[pid][1])
    # the same ID with another text (a user's catalogue, a stale module): parsed, never the written one
    other = ParamSpec(id=pid, kind=pid[2:6], key="x", type="SGN32", range_text="0 ≤ x ≤ 7")
    fresh = load_registry()
    rng = fresh.range_of(other)
    assert rng == parse_range("0 ≤ x ≤ 7", pid) and rng != decode_range(RANGES[pid][1])


def test_whether_a_range_refers_is_read_from_the_written_one_as_the_range_says() -> None:
    from zero.catalog.ranges import encoded_refers

    for pid, (_, data) in RANGES.items():
        rng = decode_range(data)
        assert encoded_refers(data) == bool(rng is not None and rng.refs), pid
    registry, parsed = load_registry(), load_registry()
    for pid in registry.specs:
        spec = registry.specs[pid]
        rng = parsed.range_of(parsed.specs[pid])
        assert registry.range_refers(spec) == bool(rng is not None and rng.refs), pid
    assert not registry._ranges  # answered from the written ranges: none decoded, none parsed
    other = ParamSpec(id="P-AXIS-00001", kind="AXIS", key="x", type="SGN32", range_text="0 ≤ x ≤ P-AXIS-00008")
    assert load_registry().range_refers(other)  # a text not written: parsed


def test_the_bounds_read_from_a_written_range_are_the_bounds_it_evaluates_to() -> None:
    """encoded_bounds (check_values' judge of a value alone, issue 40) gives what the decoded range evaluates to,
    number for number (1 and 1.0 are not the same here), and ``None`` for a range that refers to a parameter."""
    from zero.catalog.ranges import encoded_bounds, encoded_refers

    seen = 0
    for pid, (_, data) in RANGES.items():
        if data is None or data[4] is not None:
            continue
        if encoded_refers(data):
            assert encoded_bounds(data) is None, pid
            continue
        b = decode_range(data).evaluate(lambda *_: None)  # type: ignore[union-attr]
        want = (b.low, b.low_strict, b.high, b.high_strict)
        assert repr(encoded_bounds(data)) == repr(want), pid
        seen += 1
    assert seen > 300
    # expressions the catalogue writes seldom: a limit of an unknown type, a negation, arithmetic, an overflow
    assert encoded_bounds((("N", ("L", "MAX", "UNS16")), True, ("B", "*", 2, ("L", "MAX", "SGN32")), False, None)) \
        == (-65535, True, 2 * (2**31 - 1), False)
    assert encoded_bounds((("L", "MIN", "NOPE"), False, ("B", "+", 10**400, 1.5), False, None)) == \
        (None, False, None, False)
    assert encoded_bounds((0, False, ("N", ("B", "-", 5, ("R", "P-AXIS-00008", None))), False, None)) is None

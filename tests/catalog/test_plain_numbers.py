"""A plain number is read without a Value (zero.catalog.values.plain_number) exactly as read_text reads it, and a
big list's values judged through it get the verdicts of the Value path (zero.rules.registry.check_values)."""

from __future__ import annotations

from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.catalog.registry import INTEGER_TYPES, ParamSpec
from zero.catalog.values import plain_number, read_text
from zero.lists.model import ValueKind
from zero.lists.tokenizer import value_kind

_KINDS = [None, ValueKind.INT, ValueKind.HEX, ValueKind.REAL, ValueKind.REF, ValueKind.FLAGS, ValueKind.WORD,
          ValueKind.QUOTED]
_NUMBERISH = st.one_of(
    st.integers(-(10**45), 10**45).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.from_regex(r"\A[+-]?[0-9]{0,45}(\.[0-9]{0,5})?([eE][+-]?[0-9]{1,4})?\Z"),
    st.sampled_from(["0x1F", "1e999", "-1e999", "nan", "inf", "TRUE", "FALSE", "0", "1", "2", "00", "007", "٣",
                     "1_000", " 1", "1.", ".5", "P-AXIS-00001.0", "255", "256", "-129", "65535", "65536"]),
)


@given(_NUMBERISH, st.sampled_from(sorted(INTEGER_TYPES | {"REAL64", "STRING", "STRUCT"})),
       st.sampled_from(_KINDS))
@example("1e999", "REAL64", ValueKind.REAL)
@example("2", "BOOLEAN", ValueKind.INT)
@example("65536", "UNS16", ValueKind.INT)
@settings(max_examples=1500, deadline=None)
def test_a_plain_number_is_what_read_text_reads_without_a_problem(raw: str, t: str, kind: ValueKind | None) -> None:
    spec = ParamSpec(id="P-TEST-00001", kind="AXIS", key="t", type=t)
    for k in (kind, value_kind(raw)):
        got = plain_number(t, raw, k)
        if got is None:
            continue
        value = read_text(spec, raw, k)
        assert value.problem is None and value.ref is None, (raw, t, k, value)
        assert value.number == got and type(value.number) is type(got), (raw, t, k, value)


_FIELDS = ["gueltig", "typ", "mass_einheit", "laenge", "radius", "ax_versatz[0]", "kinematic.param[1]", "kin_id",
           "param[3]", "vb_min", "vb_max", "a_max", "grinding_disc_tilt_angle", "log_ax_nr_spdl", "tool_fixed"]
_VALUES = st.one_of(st.integers(-(2**40), 2**40).map(str), st.sampled_from(
    ["0", "1", "2", "-1", "1.5", "-0.25", "1e999", "nan", "0x10", "4294967296", "99999999999", "ABC", "1e5", "007"]))


@given(st.lists(st.tuples(st.sampled_from(_FIELDS), _VALUES), min_size=2, max_size=60), st.integers(2, 6))
@settings(max_examples=60, deadline=None)
def test_a_tool_lists_values_judged_by_their_numbers_find_what_their_values_find(
        fields: list[tuple[str, str]], tools: int) -> None:
    """The findings of a tool list whose tools repeat fields (each field's values a group: check_values' path
    for many entries of one pattern) are the same with plain numbers judged without a Value and with every
    value read as a Value."""
    import zero.rules.registry as rules_registry
    from zero.catalog.registry import load_registry
    from zero.engine.lint import lint_bytes

    text = "".join(f"wz[{t}].{field} {value}\n" for t in range(1, tools + 1) for field, value in fields)
    data = (text + "Ende\n").encode("ascii")

    def findings() -> list[dict[str, object]]:
        registry = load_registry(None)
        registry.memo.clear()  # no verdict kept from another list
        return [d.to_json() for d in lint_bytes(data, registry, "werkz.lis").diagnostics]

    fast = findings()
    original = rules_registry.plain_number
    rules_registry.plain_number = lambda *_: None  # type: ignore[assignment]
    try:
        slow = findings()
    finally:
        rules_registry.plain_number = original
    assert fast == slow

"""The shortcuts of a small list's lint (issue 40, session 4) answer what the loops over every entry
answered: the value verdicts kept across the lists of a run (by value, and by value and the values a
range refers to), the list kind from the counted key patterns, and the K rules' consolidation read
from the columns. Each is compared here with the per-entry way, on generated lists and on the
start-up fixtures; the verdicts with a registry warmed by other lists and with a fresh one."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import FIXTURES, bound_one_by_one, builtin_registry, generated_lists
from zero.catalog.registry import Registry, load_registry
from zero.catalog.values import ListValues
from zero.diagnostics import Diagnostic
from zero.lists.tokenizer import tokenize
from zero.records import replace
from zero.rules import lists as L
from zero.rules import registry as R
from zero.rules.base import Context, declared_codes, default_severity, run_checks

KEYS = st.sampled_from([
    "wz[{i}].vb_min", "wz[{i}].vb_max", "wz[{i}].laenge", "getriebe[{i}].dynamik.vb_max",
    "getriebe[{i}].dynamik.a_max", "getriebe[{i}].dynamik.vb_min", "kenngr.swe_pos", "kenngr.swe_neg",
    "kenngr.achs_typ", "kenngr.vb_refmax", "handbetrieb.tipp.geschw[{i}]", "spindel[{i}].name",
    "np_grp[{i}].achse[{j}].versch", "np_grp[0{i}].achse[{j}].inaktiv", "kenngr.homing_type", "kenngr.vb_messen",
    "handbetrieb.jog.geschw[{i}]", "handbetrieb.hb.vb_max", "getriebe[{i}].pos_refpkt",
])
VALUES = st.sampled_from(["0", "1", "5", "-7", "1.5", "100", "400000", "99999999999", "P-AXIS-00212.0",
                          "P-AXIS-99999", "0x10", "WARN", "TRUE", '"x"', "-2000000"])
ROWS = st.lists(st.tuples(KEYS, st.integers(0, 4), st.integers(0, 3), VALUES), max_size=40)


def _text(rows: list[tuple[str, int, int, str]]) -> str:
    return "".join(f"{key.format(i=i, j=j)} {value}\n" for key, i, j, value in rows)


def _context(text: str, registry: Registry, kind: str | None, m001: bool) -> Context:
    ctx = Context.of(tokenize(text.encode("utf-8"), "t.lis"), registry, kind)
    ctx.severities = {c: s for c in declared_codes() if (s := default_severity(c)) is not None}
    if m001:
        ctx.severities["M001"] = ctx.severities.get("M001") or default_severity("R005")  # type: ignore[assignment]
    else:
        ctx.severities.pop("M001", None)
    return ctx


def _reference_values(ctx: Context) -> list[Diagnostic]:
    """check_values as the loop over every entry, each bound and judged on its own (no memo)."""
    out = []
    for res in bound_one_by_one(ctx.doc, ctx.registry, ctx.kind):
        if not R.not_configured(ctx, res):
            out.extend(R._check_value(ctx, res))
    return out


@settings(max_examples=120, deadline=None)
@given(ROWS, ROWS, st.sampled_from([None, "AXIS", "TOOL"]), st.booleans(), st.booleans())
def test_verdicts_kept_across_lists_give_the_findings_of_a_fresh_registry(
        first: list[tuple[str, int, int, str]], second: list[tuple[str, int, int, str]], kind: str | None,
        m001_first: bool, m001_second: bool) -> None:
    """A list checked after another one (the run's verdicts filled by it, with M001 on or off) has the
    findings of the per-entry loop, and those it has with a registry that checked nothing yet."""
    shared = builtin_registry()
    list(R.check_values(_context(_text(first), shared, kind, m001_first)))
    got = list(R.check_values(_context(_text(second), shared, kind, m001_second)))
    assert got == _reference_values(_context(_text(second), shared, kind, m001_second))
    fresh = load_registry()
    assert got == list(R.check_values(_context(_text(second), fresh, kind, m001_second)))


def test_a_range_against_another_parameter_is_judged_per_element_across_lists() -> None:
    """`wz[].vb_min ≤ vb_max` of its tool: the same value and the same bound share a verdict, another
    bound does not, in the same list or the next one."""
    registry = builtin_registry()
    first = _context("wz[1].vb_max 100\nwz[2].vb_max 10\nwz[1].vb_min 50\nwz[2].vb_min 50\n", registry, "TOOL", True)
    assert [d.span.line for d in R.check_values(first)] == [4]
    second = _context("wz[7].vb_max 10\nwz[8].vb_max 100\nwz[7].vb_min 50\nwz[8].vb_min 50\n", registry, "TOOL", True)
    found = list(R.check_values(second))
    assert [(d.code, d.span.line) for d in found] == [("R006", 3)] and "wz[7].vb_min" in found[0].message


@settings(max_examples=150, deadline=None)
@given(generated_lists())
def test_the_kind_from_counted_patterns_is_the_kind_of_the_entries(data: bytes) -> None:
    registry = builtin_registry()
    doc = tokenize(data, "achsmds1.lis")
    patterns = [e.key.pattern for e in tokenize(data, "achsmds1.lis").entries if e.key]
    assert ListValues.of(doc, registry).kind == registry.kind_of(tokenize(data, "achsmds1.lis"))
    assert registry.detect_kind_counts(Counter(patterns), "x.lis") == registry.detect_kind(patterns, "x.lis")


def _reference_kernel_first(ctx: Context, kept: list[Diagnostic]) -> list[Diagnostic]:
    """lists._kernel_first as it was: the indices of every entry's line, from the entries."""
    rules = L.kernel_rules()
    kernel = [d for d in kept if d.code in rules]
    if not kernel:
        return kept
    indices = {e.line: e.key.indices for e in ctx.doc.entries if e.key is not None}
    covers = [(rules[d.code][0], indices.get(d.span.line, ())) for d in kernel]

    def superseded(d: Diagnostic) -> bool:
        if d.code not in L.SUPERSEDED or d.param_id is None:
            return False
        mine = indices.get(d.span.line, ())
        return any(d.param_id in ids and (not idx or not mine or idx[:1] == mine[:1]) for ids, idx in covers)

    out = []
    for d in kept:
        if d.code in rules:
            _, consequence, source = rules[d.code]
            out.append(replace(d, consequence=d.consequence or consequence, source=d.source or source))
        elif not superseded(d):
            out.append(d)
    return out


def test_k_findings_supersede_what_they_did_with_every_entry_read() -> None:
    """On every start-up fixture that fails (and a few lists with arrays written with leading zeros),
    the consolidation read from the columns keeps and drops the findings the entry loop did."""
    registry = builtin_registry()
    paths = sorted((FIXTURES / "startup").glob("*/fail.lis"))
    assert paths
    # K037 on gear 0's velocity of 0 supersedes its R005, not gear 1's (above its `≤ 2000000000` too)
    extra = ["getriebe[0].dynamik.vb_max 0\ngetriebe[1].dynamik.vb_max 3000000000\ngetriebe[00].dynamik.vb_min 5\n"
             "kenngr.swe_pos -5\nkenngr.swe_neg 5\n# getriebe[2].dynamik.vb_max 7\nbad line here\n"]
    dropped = 0
    for name, data in [(str(p), p.read_bytes()) for p in paths] + [("x.lis", t.encode()) for t in extra]:
        ctx = Context.of(tokenize(data, Path(name).name), registry, None)
        ctx.severities = {c: s for c in declared_codes() if (s := default_severity(c)) is not None}
        found = run_checks(L.CHECKS, ctx)
        got = L._kernel_first(ctx, list(found))
        assert got == _reference_kernel_first(ctx, list(found)), name
        dropped += len(found) - len(got)
    assert dropped > 0  # some generic finding was superseded: the comparison saw both ways act


def test_a_range_against_an_array_of_another_meaning_tries_each_of_its_elements() -> None:
    """`kenngr.vb_messen ≤ P-AXIS-00212` (the six gears' `vb_max`, default 200000): allowed by gear 1 when
    gear 0 refuses it, refused when no gear allows it; the same value with other gears judged again."""
    registry = builtin_registry()
    found = []
    for gears, value in [((100, 1000), 500), ((100, 200), 500), ((100, 1000), 500), ((600, 50), 500)]:
        text = "".join(f"getriebe[{g}].dynamik.vb_max {gears[min(g, 1)] if g < 2 else 100}\n" for g in range(6))
        text += f"kenngr.vb_messen {value}\n"
        got = list(R.check_values(_context(text, registry, "AXIS", True)))
        assert got == _reference_values(_context(text, registry, "AXIS", True))
        found.append([d.span.line for d in got])
    assert found == [[], [7], [], []]


def test_a_value_judged_alone_is_judged_as_the_range_verdict_judges_it() -> None:
    """check_values' judge of a parameter whose findings depend on the value alone (issue 40: read from the range
    written at build time, the default asked for only where a value fails) says what _range_verdict says: for
    every parameter of the catalogue, with numbers at its bounds, its default and its listed values; ``None`` (the
    entry decides) for a value that is no number; and for a range the registry parses (a text not written)."""
    from zero.catalog.registry import ParamSpec
    from zero.catalog.values import Value

    builtin = load_registry()
    prose = R._prose_rows()
    other = ParamSpec(id="P-AXIS-00001", kind="AXIS", key="x", type="SGN32", range_text="-3 < x ≤ 7", default="9")
    refers = ParamSpec(id="P-AXIS-00001", kind="AXIS", key="x", type="SGN32", range_text="0 ≤ x ≤ P-AXIS-00008")
    judged = 0
    # (the two made-up ones each with a registry of its own: a registry keeps one parsed range per ID)
    for registry, spec in [*((builtin, s) for s in builtin.specs.values()), (load_registry(), other),
                           (load_registry(), refers)]:
        judge = R._judge(registry, spec, prose)
        assert (judge is not None) == (spec.id not in prose and not registry.range_refers(spec)), spec.id
        if judge is None:
            continue
        numbers: set[int | float] = {0, 1, -1, 0.5, 2**31, -(2**31), 10**20, *spec.enum}
        dflt = R._default_of(spec)
        if dflt is not None:
            numbers |= {dflt, dflt + 1, dflt - 1}
        rng = registry.range_of(spec)
        if rng is not None and not rng.refs:
            b = rng.evaluate(lambda *_: None)
            numbers |= {x + d for x in (b.low, b.high) if x is not None for d in (-1, 0, 1)}
            numbers |= set(rng.allowed or ())
        for n in numbers:
            v = Value(number=n)
            assert R._judged(judge, v) == R._range_verdict(registry, spec, v, {}), (spec.id, n)
        for v in (Value(text="x"), Value(number=1, problem="type"), Value(ref=("P-AXIS-00008", None))):
            assert R._judged(judge, v) == R._range_verdict(registry, spec, v, {}), (spec.id, v)
        judged += 1
    assert judged > 1000
    assert R._judge(load_registry(), refers, prose) is None
    judge = R._judge(load_registry(), other, prose)
    assert judge is not None and judge[2] == (-3, True, 7, False)  # parsed, not the written range of its ID
    assert R._judged(judge, Value(number=9)) is True  # its default, outside its range
    assert R._judged(judge, Value(number=8)) is False

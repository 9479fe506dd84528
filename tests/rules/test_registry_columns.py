"""The R checks as passes over distinct patterns and values (issue 40) report what a loop over every
entry reported: the same findings, in the same order, with each entry's own span, message and fix.

The reference below is that loop, as it was before the passes (one entry at a time, each bound on its
own); generated lists and hand-written cases compare the two."""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import bound_one_by_one, builtin_registry, generated_lists, lint_text
from zero.catalog.values import Resolved
from zero.diagnostics import Diagnostic, Edit, Fix, Related, Span
from zero.lists.model import HUGE_INDEX, format_key
from zero.lists.tokenizer import tokenize
from zero.rules import registry as R
from zero.rules.base import MAX_PER_CODE, Context, declared_codes, default_severity


def _context(text: str, kind: str | None = None) -> Context:
    doc = tokenize(text.encode("utf-8"), "t.lis")
    ctx = Context.of(doc, builtin_registry(), kind)
    ctx.severities = {c: s for c in declared_codes() if (s := default_severity(c)) is not None}
    return ctx


def _resolved(ctx: Context) -> list[Resolved]:
    return bound_one_by_one(ctx.doc, ctx.registry, ctx.kind)


def _reference_keys(ctx: Context) -> Iterator[Diagnostic]:
    reg = ctx.registry
    proposed: set[str] = set()
    known: dict[str, Any] = {}
    for e in ctx.doc.entries:
        key = e.key
        if key is None:
            continue
        spec = reg.by_pattern(key.pattern, ctx.kind)
        if spec is None:
            alias = reg.alias(key.pattern, ctx.kind)
            if alias is not None:
                span = Span.on_line(e.line, e.key_start, e.key_end)
                yield ctx.report(
                    "R002", span,
                    f"`{e.key_text}` is not in the parameter description; it stands for "
                    f"`{alias.key}` ({alias.id}), and the vendor's own lists write it: evidence that the kernel "
                    "of their release accepts it (its value is checked as the documented parameter's)",
                    param_id=alias.id, hint=f"use `{format_key(alias.key or '', key.indices)}`",
                    fix=Fix(f"Use the documented key `{alias.key}`",
                            (Edit(span, format_key(alias.key or "", key.indices)),), safe=False))
                continue
            vendor = reg.vendor_keys.get((ctx.kind or "", key.pattern))
            if vendor is not None:
                yield R._vendor_key(ctx, e, *vendor)
                continue
            propose = key.pattern in proposed or len(proposed) < R.SUGGESTIONS
            if propose:
                proposed.add(key.pattern)
            release = R._other_release(ctx, e, known, propose)
            yield release if release is not None else R._unknown_key(ctx, e, propose, known)
            continue
        outside = spec.index_outside(key.indices) if key.indices else None
        if outside is not None:
            pos, idx = outside
            members = key.members
            name = key.pattern.split("[]")[pos].rsplit(".", 1)[-1] or (members[pos] if pos < len(members) else "?")
            shown = str(idx) if idx < 10**18 else f"{str(idx)[:6]}…"
            yield ctx.report("R003", Span.on_line(e.line, e.key_start, e.key_end),
                             f"index {shown} of `{name}` is outside {spec.valid_indices(pos)}: the element does not "
                             f"exist; {R.says(ctx, 'unknown-element')}", param_id=spec.id)


def _reference_duplicates(ctx: Context) -> Iterator[Diagnostic]:
    seen: dict[str, Any] = {}
    for e in ctx.doc.entries:
        key = e.key
        if key is None:
            continue
        slot = key.text
        if ("[0" in slot and re.search(R._LEADING_ZERO, slot)) or HUGE_INDEX in key.indices:
            slot = format_key(key.pattern, key.indices)
        first = seen.get(slot)
        seen[slot] = e
        if first is None:
            continue
        spec = ctx.registry.by_pattern(key.pattern, ctx.kind)
        yield ctx.report(
            "R007", Span.on_line(e.line, e.key_start, e.key_end),
            f"`{e.key_text}` is already set on line {first.line} ({first.value}); this later "
            f"value {e.value} overwrites it, so line {first.line} has no effect",
            param_id=spec.id if spec else None,
            fix=Fix(f"Delete the earlier entry on line {first.line}",
                    (Edit(Span(first.line, 1, first.line + 1, 1), ""),), safe=False),
            related=(Related(Span.on_line(first.line, first.key_start, first.key_end),
                             f"first set here to {first.value}, which this entry overwrites"),))


def _reference_values(ctx: Context) -> Iterator[Diagnostic]:
    for res in _resolved(ctx):  # every entry checked (no memo at all)
        if not R.not_configured(ctx, res):
            yield from R._check_value(ctx, res)


def _reference_annotations(ctx: Context) -> Iterator[Diagnostic]:
    for res in _resolved(ctx):
        e = res.entry
        if e.annotation is None or e.annotation == res.spec.id or res.via_alias:
            continue
        other = ctx.registry.get(e.annotation)
        what = f" (that is `{other.key}`)" if other and other.key else ""
        span = Span.on_line(e.line, e.annotation_start, e.annotation_start + 12)
        fix = Fix(f"Write {res.spec.id} in the comment", (Edit(span, res.spec.id),))
        yield ctx.report("R008", span, f"the comment names {e.annotation}{what}, but `{e.key_text}` is {res.spec.id}",
                         param_id=res.spec.id, fix=fix, hint=fix.title)


PAIRS = [(R.check_keys, _reference_keys), (R.check_duplicates, _reference_duplicates),
         (R.check_values, _reference_values), (R.check_annotations, _reference_annotations)]


def _same(text: str, kind: str | None = None) -> list[Diagnostic]:
    """Each check's findings equal the reference's (fresh contexts: the reference shares no state);
    all of them, in order."""
    out = []
    for check, reference in PAIRS:
        got = list(check(_context(text, kind)))
        assert got == list(reference(_context(text, kind))), check.__name__
        out.extend(got)
    return out


@pytest.mark.slow
@settings(max_examples=150, deadline=None)
@given(generated_lists())
def test_generated_lists_give_the_findings_of_the_per_entry_loop(data: bytes) -> None:
    text = data.decode("utf-8", "replace")
    _same(text)
    _same(text, "ZERO")


KEYS = st.sampled_from([
    "np_grp[{i}].achse[{j}].versch", "np_grp[0{i}].achse[{j}].versch", "np_grp[{i}].achse[0{j}].inaktiv",
    "getriebe[{i}].dynamik.vb_max", "getriebe[{i}].dynamik.a_max", "kenngr.swe_pos", "kenngr.swe_neg",
    "kenngr.homing_type", "kenngr.achs_typ", "kenngr.antr_typ", "kenngr.swe_pso", "antr_simu.totzeit",
    "wz[{i}].laenge", "wz[{i}].vb_min", "wz[{i}].vb_max", "handbetrieb.tipp.geschw[{i}]", "lr_hw[{i}].cntr_adr",
    "spindel[{i}].name", "a[{i}].b",
])
VALUES = st.sampled_from(["0", "1", "5", "-7", "1.5", "99999999999", "400000", "P-AXIS-00212.0", "P-AXIS-99999",
                          "WARN", "CNC_CONTROLLED", "TRUE", "2", "0x10", '"x"'])
NOTES = st.sampled_from(["", "", "  ( P-AXIS-00178 : x", "  ( P-AXIS-00008 : y", "  # c"])


@settings(max_examples=120, deadline=None)
@given(st.lists(st.tuples(KEYS, st.integers(0, 120), st.integers(0, 40), VALUES, NOTES), max_size=60),
       st.sampled_from([None, "AXIS", "TOOL"]))
def test_keys_values_and_notes_of_every_kind_are_found_as_entry_by_entry(
        rows: list[tuple[str, int, int, str, str]], kind: str | None) -> None:
    text = "".join(f"{key.format(i=i, j=j)} {value}{note}\n" for key, i, j, value, note in rows)
    _same(text, kind)


def test_one_value_at_two_elements_gives_two_findings_each_with_its_own_span_and_key() -> None:
    text = "np_grp[1].achse[0].inaktiv 7\nnp_grp[2].achse[3].inaktiv 7\nnp_grp[3].achse[1].inaktiv 1\n"
    found = [d for d in _same(text, "ZERO") if d.code in ("R004", "R005")]
    assert [(d.span.line, d.span.column) for d in found] == [(1, 28), (2, 28)]
    assert "np_grp[1].achse[0].inaktiv" in found[0].message and "np_grp[2].achse[3].inaktiv" in found[1].message


def test_a_value_against_a_reference_is_checked_at_each_entry() -> None:
    """`wz[].vb_min` is bounded by the same tool's `vb_max`: one value, passing at one tool and not at
    the other."""
    text = "wz[1].vb_max 100\nwz[2].vb_max 10\nwz[1].vb_min 50\nwz[2].vb_min 50\n"
    found = [d for d in _same(text, "TOOL") if d.code.startswith("R")]
    assert [(d.code, d.span.line) for d in found] == [("R006", 4)]
    assert "wz[2].vb_min" in found[0].message


def test_duplicates_written_with_and_without_leading_zeros_and_in_another_shape() -> None:
    text = ("np_grp[1].achse[2].versch 1\nnp_grp[01].achse[2].versch 2\nnp_grp[1].achse[02].versch 3\n"
            "np_grp[2].achse[2].versch 4\nwz[1].laenge 5\nwz[1].laenge 6\n")
    found = [d for d in _same(text) if d.code == "R007"]
    assert [d.span.line for d in found] == [2, 3, 6]
    assert "already set on line 2" in found[1].message


def test_indices_outside_the_array_first_or_later_are_found_entry_by_entry() -> None:
    text = "np_grp[97].achse[0].versch 1\nnp_grp[1].achse[32].versch 1\nnp_grp[96].achse[31].versch 1\n"
    found = [d for d in _same(text, "ZERO") if d.code == "R003"]
    assert [d.span.line for d in found] == [1, 2]


def test_a_huge_list_of_one_repeated_finding_is_reported_entry_by_entry_and_bounded() -> None:
    n = MAX_PER_CODE + 500
    text = "".join(f"np_grp[{i % 96}].achse[{i // 96 % 32}].inaktiv 7\n" for i in range(n))
    result = lint_text(text, "nullp.lis", select=("R005",))
    found = [d for d in result.diagnostics if d.code == "R005"]
    assert len(found) == MAX_PER_CODE + 1  # the first ones, then one that counts the rest
    assert [d.span.line for d in found[:3]] == [1, 2, 3]
    assert found[-1].message.startswith("500 more R005 findings")


def test_a_clean_list_builds_no_entry_in_the_r_checks() -> None:
    text = "".join(f"wz[{t}].laenge {t * 10}\nwz[{t}].radius 5\n" for t in range(1, 400))
    ctx = _context(text, "TOOL")
    built = len(ctx.doc.columns.objects)
    for check, _ in PAIRS:
        assert list(check(ctx)) == []
    assert len(ctx.doc.columns.objects) - built <= 2  # a value's verdict needs no entry either


def _past_the_cap_list(pid: str) -> str:
    """MAX_PER_CODE + 700 rows: made-up keys of 13 patterns without a comment (R001), and among them made-up
    keys with a comment (R001 too, their comment read), a key an annotation names today's parameter of (R013)
    and the same key without the annotation (R001)."""
    rows = []
    for i in range(MAX_PER_CODE + 700):
        if i % 50 == 7:
            rows.append(f"alt.swe_pos {i} ( {pid} : the software limit\n")
        elif i % 50 == 8:  # the annotated rows' pattern without a comment: R001 (the comment decides)
            rows.append(f"alt.swe_pos {i}\n")
        elif i % 50 == 9:
            rows.append(f"unknown_thing[{i}] 1 ( a comment\n")
        else:
            rows.append(f"unknown_key_{i % 13}.member[{i}] 1\n")
    return "".join(rows)


def test_past_the_cap_a_key_finding_is_counted_by_its_code_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    """A list of a million made-up keys built a million entries and findings to show ten thousand and count
    the rest. A row without a comment whose pattern's code is past the cap is now counted by its code alone:
    the findings, and the one that counts the rest, are those of the whole path, and those rows build no entry."""
    from zero.rules.base import run_checks
    from zero.rules.lists import CHECKS

    pid = builtin_registry().by_pattern("kenngr.swe_pos", "AXIS").id  # type: ignore[union-attr]
    text = _past_the_cap_list(pid)
    ctx = _context(text, "AXIS")
    visited: list[int] = []
    finding = R._row_finding

    def counted(*args: Any) -> Diagnostic | None:
        visited.append(args[1].line)
        return finding(*args)

    with monkeypatch.context() as m:
        m.setattr(R, "_row_finding", counted)
        found = run_checks(CHECKS, ctx)
    assert ctx.tally is None  # the counts are run_checks's while it runs: a check called after yields findings
    assert all(isinstance(d, Diagnostic) for d in R.check_keys(ctx))
    with monkeypatch.context() as m:  # the whole path: no tally, so every row is built and reported
        m.setattr(Context, "tally", property(lambda self: None, lambda self, value: None))
        whole = _context(text, "AXIS")
        reference = run_checks(CHECKS, whole)
        assert len(whole.doc.columns.objects) == MAX_PER_CODE + 700
    assert found == reference
    codes = [d.code for d in found]
    assert codes.count("R013") == (MAX_PER_CODE + 700) // 50
    assert codes.count("R001") == MAX_PER_CODE + 1
    more = [d for d in found if d.message.startswith(f"{MAX_PER_CODE + 700 - codes.count('R013') - MAX_PER_CODE} "
                                                      "more R001 findings")]
    assert len(more) == 1
    # the rows past the cap without a comment: neither an entry nor a finding made (those with one: read)
    commented = sum(1 for line in visited if (line - 1) % 50 in (7, 9))
    assert commented == 2 * (MAX_PER_CODE + 700) // 50
    plain = len(visited) - commented  # up to the 10,001st R001, the commented ones among them counted too
    assert MAX_PER_CODE + 1 - commented // 2 <= plain <= MAX_PER_CODE + 1

"""The default selection (no selector, or every rule that is not opt-in by its full code: what a lint without
a configuration that selects asks) is worked out once per rule table, not tried code by code (issue 40:
start-up); it gives what the general way gives, for every selection and every table."""

from __future__ import annotations

from collections.abc import Sequence

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import zero.engine.selection as selection
from zero.diagnostics import Severity
from zero.engine.lint import ALL, LintOptions, _selected_rules, layered_selection
from zero.engine.selection import Layer, _layered_selection
from zero.rules import RULES

_CODES = sorted(RULES)
_OPT_IN = [c for c in _CODES if RULES[c].opt_in]
_DEFAULT = tuple(c for c in _CODES if not RULES[c].opt_in)
_SELECTORS = st.sampled_from([*_CODES, *{c[:2] for c in _CODES}, *{c[:1] for c in _CODES}, ALL, "R00", "K1", "Q"])
_SELECTION = st.one_of(st.just(()), st.just(_DEFAULT), st.lists(_SELECTORS, max_size=5).map(tuple))
_SEVERITIES = st.dictionaries(st.sampled_from([*_CODES, "Q1"]), st.sampled_from(list(Severity)), max_size=4)
_LAYER = st.tuples(_SELECTION, st.lists(_SELECTORS, max_size=3).map(tuple), st.lists(_SELECTORS, max_size=3).map(tuple))


def _match(prefixes: Sequence[str], code: str) -> int:
    return max((0 if p == ALL else len(p) for p in prefixes if p == ALL or code.startswith(p)), default=-1)


def _reference(options: LintOptions, table: dict[str, tuple[Severity, bool]]) -> dict[str, Severity]:
    """The selection as the rule states it, one code and one prefix at a time."""
    out: dict[str, Severity] = {}
    for code, (severity, opt_in) in table.items():
        sel, ext, ign = (_match(options.select, code), _match(options.extend_select, code),
                         _match(options.ignore, code))
        if opt_in and not any(code in s or ALL in s for s in (options.select, options.extend_select)):
            continue
        if options.select and sel < 0 and ext < 0:
            continue
        if ign >= 0 and ign >= max(sel, ext):
            continue
        out[code] = options.severity.get(code, severity)
    return out


def _layered_reference(layers: Sequence[Layer], dropped: Sequence[str],
                       table: dict[str, tuple[Severity, bool]]) -> tuple[str, ...]:
    """What a layered selection selects, from every rule that is not opt-in, a layer at a time."""
    enabled = {code for code, (_, opt_in) in table.items() if not opt_in}
    for select, extend, ignore in layers:
        if not (select or extend or ignore):
            continue
        for code, (_, opt_in) in table.items():
            on, off = _match((*select, *extend), code), _match(ignore, code)
            if opt_in and not any(code in s or ALL in s for s in (select, extend)):
                on = -1
            if not select and on < 0 and off < 0:
                continue
            if on > off:
                enabled.add(code)
            else:
                enabled.discard(code)
    return tuple(sorted(c for c in enabled if not any(c.startswith(p) for p in dropped)))


@pytest.mark.slow
@given(_SELECTION, _SELECTION, _SELECTION, _SEVERITIES)
@example((), (), (), {})  # zero lint with no option at all
@example(_DEFAULT, (), (), {})  # what a lint asks: layered_selection with no selector
@example(_DEFAULT, (), (), {"R002": Severity.ERROR, "Q1": Severity.INFO})  # a configuration's severities
@example(_DEFAULT[1:], (), (), {})  # one rule less: not the default
@example((*_DEFAULT, *_OPT_IN), (), (), {})  # the opt-in rules too
@example((), _DEFAULT, (), {})  # the default codes as extend-select: the opt-in rules stay off
@settings(max_examples=400, deadline=None)
def test_every_selection_is_the_reference(select: tuple[str, ...], ignore: tuple[str, ...],
                                          extend: tuple[str, ...], severity: dict[str, Severity]) -> None:
    options = LintOptions(select=select, ignore=ignore, extend_select=extend, severity=severity)
    got = _selected_rules(options)
    want = _reference(options, selection.rule_table())
    assert list(got.items()) == list(want.items())  # the table's order too


@pytest.mark.slow
@given(st.lists(_LAYER, max_size=3), st.lists(_SELECTORS, max_size=2))
@example([], [])
@example([((), (), ()), ((), (), ())], [])  # zero lint with a configuration that selects nothing
@example([((), (), ())], ["R"])  # per-file ignores alone
@settings(max_examples=300, deadline=None)
def test_every_layered_selection_is_the_reference(layers: list[Layer], dropped: list[str]) -> None:
    got = _layered_selection(layers, dropped)
    kept = _layered_reference(layers, dropped, selection.rule_table())
    assert got == (LintOptions(select=kept) if kept else LintOptions(ignore=("",)))


def test_the_default_is_what_no_layer_selects() -> None:
    options = layered_selection([((), (), ()), ((), (), ())])
    assert options.select == _DEFAULT and not options.ignore
    got = _selected_rules(options)
    assert list(got) == [c for c in RULES if not RULES[c].opt_in]  # the registry's order, no opt-in rule
    assert got == _selected_rules(LintOptions())
    assert got is not _selected_rules(options)  # each its own dictionary: a caller's change stays its own


def test_the_default_is_the_table_s(monkeypatch: pytest.MonkeyPatch) -> None:
    """Another table (a stale written one, or a test's) has its own default, worked out as it is first asked."""
    error, info = Severity.ERROR, Severity.INFO
    first = selection._default(selection.rule_table())
    table = {"S002": (error, False), "S001": (info, False), "S0010": (error, True), "S0011": (info, False)}
    monkeypatch.setattr(selection, "_TABLE", table)
    assert selection._default(table) is not first
    assert _layered_selection([((), (), ())]).select == ("S001", "S0011", "S002")
    for options in (LintOptions(), LintOptions(select=("S001", "S0011", "S002")),
                    LintOptions(select=("S001", "S0011", "S002"), severity={"S0011": error, "S0010": info}),
                    LintOptions(select=("S001",)), LintOptions(select=("S0010",)), LintOptions(ignore=("S001",))):
        assert list(_selected_rules(options).items()) == list(_reference(options, table).items()), options
    monkeypatch.undo()
    assert selection._default(selection.rule_table()).codes == _DEFAULT

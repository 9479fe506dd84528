"""Rule selection by sets of full codes gives what trying each prefix gave (issue 40: start-up)."""

from __future__ import annotations

import random

import pytest

from zero.engine.lint import ALL, LintOptions, _selected_rules, layered_selection
from zero.rules import RULES


def _reference(options: LintOptions) -> dict[str, object]:
    """The selection as the rule states it, one prefix at a time."""
    def match(prefixes: tuple[str, ...], code: str) -> int:
        return max((0 if p == ALL else len(p) for p in prefixes if p == ALL or code.startswith(p)), default=-1)

    out: dict[str, object] = {}
    for code, r in RULES.items():
        sel, ext, ign = (match(options.select, code), match(options.extend_select, code),
                         match(options.ignore, code))
        if r.opt_in and not any(code in s or ALL in s for s in (options.select, options.extend_select)):
            continue
        if options.select and sel < 0 and ext < 0:
            continue
        if ign >= 0 and ign >= max(sel, ext):
            continue
        out[code] = options.severity.get(code, r.severity)
    return out


def test_a_layered_selection_of_every_code_selects_what_prefixes_select() -> None:
    options = layered_selection([((), (), ())])
    assert len(options.select) > 100  # every enabled rule by its full code
    assert _selected_rules(options) == _reference(options)


def test_mixed_codes_and_prefixes_select_as_before() -> None:
    rnd = random.Random(40)
    codes = sorted(RULES)
    pool = [*codes, *{c[:2] for c in codes}, *{c[:1] for c in codes}, ALL, "R00", "K1"]
    for _ in range(300):
        pick = lambda: tuple(rnd.sample(pool, rnd.randint(0, 6)))  # noqa: E731
        options = LintOptions(select=pick(), ignore=pick(), extend_select=pick())
        assert _selected_rules(options) == _reference(options), options


def test_full_codes_alone_select_as_before() -> None:
    """What every lint asks (the fast way): only full codes selected, opt-in ones and severities included."""
    rnd = random.Random(41)
    codes = sorted(RULES)
    opt_in = [c for c in codes if RULES[c].opt_in]
    assert opt_in  # the case the fast way must keep: an opt-in rule named by its full code is enabled
    for _ in range(200):
        chosen = tuple(rnd.sample(codes, rnd.randint(1, len(codes))))
        severity = {c: RULES["S001"].severity for c in rnd.sample(codes, rnd.randint(0, 5))}
        options = LintOptions(select=chosen, severity=severity)
        assert _selected_rules(options) == _reference(options), options
    options = LintOptions(select=(*opt_in, "S001"))
    assert set(_selected_rules(options)) == {*opt_in, "S001"}


def test_a_code_that_begins_another_matches_both(monkeypatch: pytest.MonkeyPatch) -> None:
    """Were a code a prefix of another, a selector naming it matches both: the fast way is then not taken."""
    import zero.engine.selection as selection

    severity = RULES["S001"].severity
    monkeypatch.setattr(selection, "_TABLE", {"S001": (severity, False), "S0010": (severity, False)})
    monkeypatch.setattr(selection, "_PREFIX_FREE", [])
    assert _selected_rules(LintOptions(select=("S001",))) == {"S001": severity, "S0010": severity}

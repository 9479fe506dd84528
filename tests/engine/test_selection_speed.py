"""Rule selection by sets of full codes gives what trying each prefix gave (issue 40: start-up)."""

from __future__ import annotations

import random

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

"""Rule selection reads every rule's code, severity and opt-in flag from a table written by
tools/gen_rule_codes.py (issue 40: a cached run imports no rule module), and from the registry while
that table is stale."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import script_module
from zero.catalog.data.rule_codes import SOURCES
from zero.engine import selection
from zero.engine.lint import LintOptions, layered_selection, selected_rules
from zero.rules import RULES

ROOT = Path(__file__).resolve().parents[2]


def test_the_written_table_is_up_to_date() -> None:
    """Run ``python tools/gen_rule_codes.py`` after adding, removing or re-grading a rule."""
    written = (ROOT / "src" / "zero" / "catalog" / "data" / "rule_codes.py").read_text(encoding="utf-8")
    assert written == script_module(ROOT / "tools" / "gen_rule_codes.py").render()  # type: ignore[attr-defined]


def test_the_written_table_is_the_registry_in_its_order() -> None:
    written = selection._written()
    assert written is not None  # written from the rule modules as they are: the rules are not imported for it
    assert list(written.items()) == [(code, (r.severity, r.opt_in)) for code, r in RULES.items()]
    assert list(selection.rule_table()) == list(RULES)


def test_a_stale_table_is_not_read(monkeypatch: pytest.MonkeyPatch) -> None:
    changed = tuple((name, size + 1 if name == "syntax.py" else size) for name, size in SOURCES)
    monkeypatch.setattr(selection, "rule_sources", lambda: changed)
    assert selection._written() is None
    monkeypatch.setattr(selection, "_TABLE", {})
    assert list(selection.rule_table().items()) == list(selection._imported().items())


def test_a_table_that_cannot_be_checked_is_not_read(monkeypatch: pytest.MonkeyPatch) -> None:
    def missing() -> tuple[tuple[str, int], ...]:
        raise FileNotFoundError("rules")

    monkeypatch.setattr(selection, "rule_sources", missing)
    assert selection._written() is None


def test_selection_over_the_table_is_selection_over_the_registry() -> None:
    every = [code for code, r in RULES.items() if not r.opt_in]
    assert list(selected_rules(LintOptions())) == every
    assert layered_selection(()).select == tuple(sorted(every))
    opt_in = next(code for code, r in RULES.items() if r.opt_in)
    assert opt_in in selected_rules(LintOptions(extend_select=(opt_in,)))
    assert opt_in not in selected_rules(LintOptions(select=(opt_in[0],)))
    assert selection.known_code("ALL") and selection.known_code(every[0][:1]) and not selection.known_code("Q9")

"""What each K rule declares, written at build time (tools/gen_startup_rules.py, issue 40: start-up)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

from conftest import script_module
from zero.catalog.data import startup_facts, startup_rules
from zero.catalog.data.startup_errors import ERRORS
from zero.catalog.data.startup_rules import DECLARED
from zero.records import replace
from zero.rules import startup

ROOT = Path(__file__).resolve().parents[2]


def _generator() -> ModuleType:
    return script_module(ROOT / "tools" / "gen_startup_rules.py")


def test_the_generated_module_is_up_to_date() -> None:
    """Run ``python tools/gen_startup_rules.py`` after tools/gen_startup.py or a change to ``said``."""
    written = (ROOT / "src" / "zero" / "catalog" / "data" / "startup_rules.py").read_text(encoding="utf-8")
    assert written == _generator().render()  # type: ignore[attr-defined]
    facts = (ROOT / "src" / "zero" / "catalog" / "data" / "startup_facts.py").read_text(encoding="utf-8")
    assert facts == _generator().render_facts()  # type: ignore[attr-defined]


def test_each_rule_is_declared_as_its_row_says() -> None:
    rows = [r for r in ERRORS if r.get("condition")]
    assert len(rows) == len(startup.CHECKS) == len(DECLARED) > 100
    for row, err in zip(rows, startup.CHECKS, strict=True):
        f = startup.facts(row)
        letter, name, summary, explanation, reads = startup.said(f)
        rule = startup.FAMILY.rules[err.code]
        assert (rule.name, rule.summary, rule.explanation, rule.reads) == (name, summary, explanation, reads)
        assert rule.severity.label.startswith({"W": "warning", "E": "error"}[letter])
        assert (err.code, err.number, err.condition_text, err.when_text) == (f[0], f[1], f[4], f[5])


def test_a_row_whose_facts_differ_from_the_written_ones_is_declared_from_its_own() -> None:
    row = dict(next(r for r in ERRORS if r.get("condition") and r.get("correction") != "none"))
    f = startup.facts(row)
    assert DECLARED[f[0]] == (f, startup.said(f))
    row["title"], row["correction"] = "Another title", "none"
    changed = startup.facts(row)
    assert changed != DECLARED[f[0]][0]  # not the written facts: declared by said(), a warning now
    letter, _, summary, explanation, _ = startup.said(changed)
    assert letter == "W" and "Another title" in summary and "Another title" in explanation


def test_the_written_rules_are_taken_without_the_rows_while_the_rows_module_has_its_size() -> None:
    rows_module = ROOT / "src" / "zero" / "catalog" / "data" / "startup_errors.py"
    assert rows_module.stat().st_size == startup_rules.ERRORS_SIZE == startup_facts.ERRORS_SIZE
    assert list(startup._declared()) == list(DECLARED.values())
    assert list(startup._facts_declared()) == [f for f, _ in DECLARED.values()]
    code = ("import sys, zero.rules; print('zero.catalog.data.startup_errors' in sys.modules,"
            " 'zero.catalog.data.startup_rules' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False False"  # a lint's start-up reads the written facts only, no rule's texts


def test_a_kernel_rules_texts_are_read_at_their_first_use() -> None:
    """A K rule is declared without its summary, explanation and what it reads; each reads its row's (and
    replace() makes a rule of every field, as a record)."""
    code = ("from zero.rules.startup import FAMILY, _SLOTS\n"
            "r = FAMILY.rules['K037']\n"
            "def unset(name):\n"
            "    try:\n"
            "        _SLOTS[name].__get__(r)\n"
            "    except AttributeError:\n"
            "        return True\n"
            "    return False\n"
            "print(sorted(n for n in _SLOTS if unset(n)), r.reads, r.summary)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    _, said = DECLARED["K037"]
    assert out.strip() == f"['explanation', 'reads', 'summary'] {said[4]!r} {said[2]}"
    rule = startup.FAMILY.rules["K037"]
    assert (rule.name, rule.summary, rule.explanation, rule.reads) == said[1:]
    changed = replace(rule, explanation="another")
    assert (changed.explanation, changed.summary, changed == rule) == ("another", said[2], False)
    assert replace(rule) == rule and hash(replace(rule)) == hash(rule)


def test_a_rows_module_of_another_size_is_declared_from_its_rows(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(startup_facts, "ERRORS_SIZE", -2)
    rows = [r for r in ERRORS if r.get("condition")]
    declared = list(startup._declared())
    assert declared == list(DECLARED.values())  # the same, from the rows (facts(), and said() where they differ)
    assert [f for f, _ in declared] == [startup.facts(r) for r in rows]


def test_a_rows_check_is_made_where_a_list_needs_it() -> None:
    """Importing the K rules makes no :class:`StartupError` (``CHECKS`` is made at its first use); a list's
    lint makes those whose condition fails only (none without a K finding: a row is checked from its facts and
    its written condition), and ``CHECKS`` then holds every row's, in the rules' order."""
    code = ("from zero.catalog.registry import load_registry\n"
            "from zero.lists.tokenizer import tokenize_text\n"
            "from zero.rules import check_document, startup\n"
            "from zero.rules.families import RULES\n"
            "made = 'CHECKS' in vars(startup) or bool(startup._ERRORS)\n"
            "doc = tokenize_text('getriebe[0].dynamik.vb_max 1000\\n')\n"
            "found = check_document(doc, load_registry(), 'AXIS', {'K037': RULES['K037'].severity})[1]\n"
            "kinds = sorted({e.code for e in startup._ERRORS.values()}), found\n"
            "codes = [e.code for e in startup.CHECKS]\n"
            "print(made, kinds, codes == [c for c in RULES if c.startswith('K')])\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False ([], []) True"  # K037 (P-AXIS-00212 != 0) checked, and holds: none made
    assert [e.code for e in startup.CHECKS] == [f[0] for f, _ in DECLARED.values()]

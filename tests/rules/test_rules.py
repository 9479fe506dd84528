"""Every rule has a failing and a passing fixture with exactly known findings."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import FIXTURES, findings, golden
from zero.catalog.registry import Registry
from zero.engine.lint import LintOptions, lint_bytes, lint_file
from zero.rules import RULES
from zero.rules.registry import SUGGESTIONS

RULE_DIRS = sorted(p for p in (FIXTURES / "rules").iterdir() if p.is_dir())


def _fixture(rule_dir: Path, name: str) -> Path:
    """``fail.lis`` / ``pass.lis``; the rules on XML elements have ``.xml`` fixtures (the same list
    model, read from XML), the U rules update files (``fail-Update.xml``: known by the name), S017 a
    YAML list form (``fail.yaml``)."""
    for candidate in (f"{name}.xml", f"{name}-Update.xml", f"{name}.yaml"):
        if (rule_dir / candidate).exists():
            return rule_dir / candidate
    return rule_dir / f"{name}.lis"


def test_every_rule_has_fixtures() -> None:
    assert RULE_DIRS, "no rule fixtures found"
    # X rules need a whole machine: fixtures/machine (failing) and fixtures/machine-clean
    # (tests/machine/test_machine.py)
    # N rules read NC programs: fixtures/programs (tests/nc/test_program.py)
    # F rules are about files that cannot be read: made in the fault suite (tests/test_files.py)
    # U003 checks an update file against a machine: tests/markup/test_forms_cli.py
    # K rules (the kernel's start-up errors) have theirs by error number: tests/rules/test_startup.py
    assert {p.name for p in RULE_DIRS} == {c for c in RULES if not c.startswith(("X", "N", "F", "K")) and c != "U003"}


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=lambda p: p.name)
def test_failing_fixture(rule_dir: Path, request: pytest.FixtureRequest, registry: Registry) -> None:
    # selected by its code, so that opt-in rules (S012) run as well
    result = lint_file(_fixture(rule_dir, "fail"), registry, LintOptions(extend_select=(rule_dir.name,)))
    actual = findings(result)
    expected = golden(rule_dir / "fail.expected.json", actual,
                      request.config.getoption("--update-golden"))
    assert actual == expected
    assert rule_dir.name in [d["code"] for d in actual]


@pytest.mark.parametrize("rule_dir", RULE_DIRS, ids=lambda p: p.name)
def test_passing_fixture(rule_dir: Path, registry: Registry) -> None:
    result = lint_file(_fixture(rule_dir, "pass"), registry, LintOptions(extend_select=(rule_dir.name,)))
    assert result.diagnostics == []


@pytest.mark.parametrize("code", sorted(RULES))
def test_rule_metadata(code: str) -> None:
    r = RULES[code]
    assert r.code == code and code[0] in "SRMUKZXNF" and len(code) == 4
    assert r.summary and "Why it matters on the machine" in r.explanation
    assert "Fix" in r.explanation


def test_rule_names_unique() -> None:
    names = [r.name for r in RULES.values()]
    assert len(names) == len(set(names))


def test_disabled_rule_reports_nothing(registry: Registry) -> None:
    from zero.engine.lint import LintOptions

    result = lint_file(FIXTURES / "rules" / "M003" / "fail.lis", registry, options=LintOptions(ignore=("M",)))
    assert result.diagnostics == []
    result = lint_file(FIXTURES / "rules" / "R004" / "fail.lis", registry,
                       options=LintOptions(select=("R",), ignore=("R004",)))
    assert result.diagnostics == []


def test_m001_replaces_generic_range_reference(registry: Registry) -> None:
    """With M001 on, an inverted soft-limit pair is one M001, not R006 twice."""
    from zero.engine.lint import LintOptions

    path = FIXTURES / "rules" / "M001" / "fail.lis"
    assert [d.code for d in lint_file(path, registry).diagnostics] == ["M001"]
    generic = lint_file(path, registry, options=LintOptions(ignore=("M001",)))
    assert [d.code for d in generic.diagnostics] == ["R006", "R006"]


def test_opt_in_rules_run_only_when_named() -> None:
    from zero.engine.lint import selected_rules

    opt_in = {c for c, r in RULES.items() if r.opt_in}
    assert opt_in == {"S012"}
    assert not opt_in & set(selected_rules(LintOptions()))
    assert not opt_in & set(selected_rules(LintOptions(select=("S",))))
    assert "S012" in selected_rules(LintOptions(extend_select=("S012",)))
    assert "S012" in selected_rules(LintOptions(select=("S012",)))
    assert set(selected_rules(LintOptions(extend_select=("S012",)))) == set(selected_rules(LintOptions())) | {"S012"}


def test_spellings_are_proposed_for_the_first_hundred_unknown_keys(registry: Registry) -> None:
    """Did-you-mean scans every known key: a list of made-up keys gets it for its first 100
    distinct unknown keys, and every entry is still reported."""
    lines = [f"kenngr.swe_pos{i:03d} 1\n" for i in range(SUGGESTIONS + 20)]
    lines += ["kenngr.swe_pos000 2\n"]  # an unknown key seen before keeps its proposal
    result = lint_bytes("".join(lines).encode(), registry, "achse.lis", LintOptions(kind="AXIS"))
    r001 = [d for d in result.diagnostics if d.code == "R001"]
    assert len(r001) == SUGGESTIONS + 21
    hinted = [d.span.line for d in r001 if d.hint and "did you mean" in d.hint]
    assert hinted == [*range(1, SUGGESTIONS + 1), SUGGESTIONS + 21]

"""The rule families are listed once (issue 39, part C): :mod:`zero.rules.families` is the registry
that lint, the funnel, rule selection, ``zero rule``, the docs and the language server read; no
family is found by importing a module for its side effect, and no other module lists them."""

from __future__ import annotations

import ast
import subprocess
import sys

import pytest

from conftest import ROOT
from zero.diagnostics import Severity
from zero.rules import FAMILIES, RULES
from zero.rules import families as registry_of_families
from zero.rules.base import Family, Rule, declared_codes, default_severity

RULES_DIR = ROOT / "src" / "zero" / "rules"


def _declares_a_family(path: str) -> bool:
    tree = ast.parse((RULES_DIR / path).read_text(encoding="utf-8"))
    return any(isinstance(n, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "FAMILY" for t in n.targets)
               for n in tree.body)


def test_every_family_module_is_listed_once() -> None:
    modules = {m.__name__.rsplit(".", 1)[1] for m in registry_of_families.MODULES}
    declaring = {p.stem for p in RULES_DIR.glob("*.py") if _declares_a_family(p.name)}
    assert declaring <= modules, declaring - modules
    assert len(registry_of_families.MODULES) == len(modules)
    listed = {id(f) for f in registry_of_families.FAMILIES}
    assert all(id(m.FAMILY) in listed for m in registry_of_families.MODULES)
    assert len(listed) == len(registry_of_families.FAMILIES)


def test_the_registry_is_what_everything_reads() -> None:
    every = {code for f in registry_of_families.FAMILIES for code in f.rules}
    assert set(RULES) == every == declared_codes()
    assert all(default_severity(c) is RULES[c].severity for c in RULES)
    assert {f.letter: f.title for f in registry_of_families.FAMILIES} == FAMILIES
    assert {c.codes for c in registry_of_families.LIST_CHECKS} == \
        {c.codes for f in registry_of_families.LIST_FAMILIES for c in f.checks}
    assert {"S014", "S015", "S016"} <= set(RULES)  # declared by elements, for the syntax family


def test_no_other_module_lists_the_families() -> None:
    """Only the registry names the family objects together (a family module may use its own, and the
    N rules read the S and R checks for AXPARAM)."""
    src = ROOT / "src" / "zero"
    for path in src.rglob("*.py"):
        rel = path.relative_to(src).as_posix()
        if rel in ("rules/families.py", "rules/program.py"):
            continue
        text = path.read_text(encoding="utf-8")
        assert ".FAMILY" not in text.replace("FAMILY.rule", "").replace("FAMILY.check", ""), rel


def test_a_fresh_process_finds_every_rule_whatever_it_imports_first() -> None:
    """Importing one family module first (as a test or a tool may) still gives the whole registry:
    declared severities come from the registry, not from the order modules were imported in."""
    code = ("import zero.rules.syntax, zero.rules.base as b; "
            "from zero.rules import RULES; assert b.declared_codes() == set(RULES), 'partial'; print(len(RULES))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True)
    assert int(out.stdout) == len(RULES)


def test_a_family_declares_only_its_own_codes() -> None:
    f: Family = Family("Q", "test", "list")  # type: ignore[type-arg]
    f.rule("Q001", "q", RULES["S001"].severity, "s", "e")
    try:
        f.rule("Q001", "q", RULES["S001"].severity, "s", "e")
    except ValueError:
        pass
    else:
        raise AssertionError("a code declared twice")
    assert "Q001" not in declared_codes()  # declaring is not registering: only the registry registers


def test_rules_declared_later_are_made_at_the_first_look() -> None:
    made: list[int] = []

    def make() -> list[Rule]:
        made.append(1)
        return [Rule("Q002", "later", Severity.INFO, "s", "e", "list")]

    f: Family = Family("Q", "test", "list")  # type: ignore[type-arg]
    f.rule("Q001", "q", Severity.ERROR, "s", "e")
    f.declare_later(make, {"Q002": Severity.INFO})
    assert f.severities() == {"Q001": Severity.ERROR, "Q002": Severity.INFO} and made == []
    assert list(f.rules) == ["Q001", "Q002"] and made == [1]
    assert f.rules["Q002"].name == "later" and made == [1]  # once
    assert f.severities() == {"Q001": Severity.ERROR, "Q002": Severity.INFO}


@pytest.mark.parametrize("made", [[], [("Q002", Severity.ERROR)], [("Q002", Severity.INFO), ("Q003", Severity.INFO)]])
def test_rules_made_later_must_be_the_ones_declared(made: list[tuple[str, Severity]]) -> None:
    f: Family = Family("Q", "test", "list")  # type: ignore[type-arg]
    f.declare_later(lambda: [Rule(code, "r", sev, "s", "e", "list") for code, sev in made], {"Q002": Severity.INFO})
    with pytest.raises(ValueError, match="not the ones it declared"):
        _ = f.rules


def test_a_family_declares_later_only_its_own_new_codes() -> None:
    f: Family = Family("Q", "test", "list")  # type: ignore[type-arg]
    f.rule("Q001", "q", Severity.ERROR, "s", "e")
    for codes in ({"Q001": Severity.ERROR}, {"P001": Severity.ERROR}):
        with pytest.raises(ValueError, match="does not belong to family Q or is declared twice"):
            f.declare_later(list, codes)


def test_the_funnel_declares_every_rule_of_the_registry() -> None:
    assert declared_codes() == set(RULES)
    assert all(default_severity(code) == rule.severity for code, rule in RULES.items())

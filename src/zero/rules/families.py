"""Every rule family zero has, listed once: the explicit registry of rules (as yamllint's
``rules/__init__.py``, a plain table; no rule is found by importing a module for its side effect).

A family module declares its rules and the checks that report them on its :class:`Family`; this
module lists the families, in the order zero runs and documents them, and everything that asks
"which rules are there" asks here (through :mod:`zero.rules`): lint (the checks of a list, a
machine, a program), the funnel (each rule's declared severity, the codes a directive may name),
rule selection and the configuration's code check, ``zero rule``, the docs site, SARIF's rule
table, the HTML report and the language server.

The S family is declared in two modules: :mod:`~zero.rules.syntax` (the lines of a list) and
:mod:`~zero.rules.elements` (XML parameter elements that did not become entries, S014–S016), which
adds its rules and checks to the syntax family; both are listed in :data:`MODULES`.
"""

from __future__ import annotations

from zero.diagnostics import Severity
from zero.rules import elements, files, machine, meaning, program, registry, startup, suppress, syntax, update
from zero.rules.base import Check, Context, Family, MachineContext, ProgramContext, Rule, declare

# the family modules, each once (elements: the S family's rules on XML elements)
MODULES = (syntax, elements, registry, meaning, update, startup, suppress, machine, program, files)
# the families checked on one list, in the order they run (zero.rules.lists)
LIST_FAMILIES: tuple[Family[Context], ...] = (syntax.FAMILY, registry.FAMILY, meaning.FAMILY, update.FAMILY,
                                              startup.FAMILY)
FAMILIES: tuple[Family[Context] | Family[MachineContext] | Family[ProgramContext], ...] = (
    *LIST_FAMILIES, suppress.FAMILY, machine.FAMILY, program.FAMILY, files.FAMILY)

LIST_CHECKS: list[Check[Context]] = [c for family in LIST_FAMILIES for c in family.checks]
MACHINE_CHECKS: list[Check[MachineContext]] = machine.FAMILY.checks
PROGRAM_CHECKS: list[Check[ProgramContext]] = program.FAMILY.checks


def _rules() -> dict[str, Rule]:
    out: dict[str, Rule] = {}
    for family in FAMILIES:
        for code in sorted(family.rules):
            if code in out:
                raise ValueError(f"rule {code} is declared by two families")
            out[code] = family.rules[code]
    return out


RULES: dict[str, Rule] = _rules()  # code → rule, family by family
TITLES: dict[str, str] = {f.letter: f.title for f in FAMILIES}  # letter → the family's title
declare({code: r.severity for code, r in RULES.items()})  # the declared severities the funnel grades against


def severity_of(code: str) -> Severity | None:
    """The severity ``code`` is declared with (``None``: no such rule)."""
    r = RULES.get(code)
    return r.severity if r is not None else None


__all__ = ["FAMILIES", "LIST_CHECKS", "LIST_FAMILIES", "MACHINE_CHECKS", "MODULES", "PROGRAM_CHECKS", "RULES", "TITLES",
           "severity_of"]

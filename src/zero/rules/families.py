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

The X (a machine's lists) and N (NC programs) families are loaded on demand (:data:`ON_DEMAND`): a
list's lint imports neither module (nor the machine and program models they read). Their rules are
in the registry all the same, as their modules declare them, written by ``tools/gen_rules.py``
(:mod:`zero.catalog.data.rules_declared`: codes and severities; their names and texts in
:mod:`~zero.catalog.data.rules_texts`, read where the rules are first looked at); their checks
(:data:`MACHINE_CHECKS`, :data:`PROGRAM_CHECKS`) import the module at their first use.
"""

from __future__ import annotations

import importlib
import os
from collections.abc import Iterator, Sequence
from types import ModuleType

from zero.catalog.data.rules_declared import DECLARED
from zero.diagnostics import Severity
from zero.hints import overload
from zero.rules import elements, files, meaning, registry, startup, suppress, syntax, update
from zero.rules.base import C, Check, Context, Family, MachineContext, ProgramContext, Rule, declare, default_severity

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

# the families loaded on demand, by module name (zero.rules.<name>)
ON_DEMAND = ("machine", "program")


def _written(name: str) -> Family[MachineContext] | Family[ProgramContext] | None:
    """The family of module ``name`` as tools/gen_rules.py wrote it (its rules, no checks); ``None``
    where its source is not the one written from (or not there to tell): then the module is imported."""
    written = DECLARED.get(name)
    if written is None:
        return None
    letter, title, scope, size, codes = written
    if any(len(row) != 2 for row in codes):  # written in another form (by an older gen_rules.py)
        return None
    try:
        if os.stat(os.path.join(os.path.dirname(__file__), f"{name}.py")).st_size != size:
            return None
    except OSError:
        return None
    family: Family[Any] = Family(letter, title, scope)
    by_name = {s.name: s for s in Severity}

    def make() -> list[Rule]:  # at the first look at the family's rules (a list's lint reads only the severities)
        from zero.catalog.data.rules_texts import TEXTS  # start-up: the rules' names and texts where first looked at

        return [Rule(code, rule_name, by_name[severity], summary, explanation, scope, opt_in, tuple(reads))
                for code, rule_name, severity, summary, explanation, opt_in, reads in TEXTS[name]]

    family.declare_later(make, {code: by_name[severity] for code, severity in codes})
    return family


def module(name: str) -> ModuleType:
    """The family module ``zero.rules.<name>`` (imported at the first use of one loaded on demand)."""
    return importlib.import_module(f"zero.rules.{name}")


_machine = _written("machine") or module("machine").FAMILY
_program = _written("program") or module("program").FAMILY


class OnDemand(Sequence[Check[C]]):
    """The checks of a family loaded on demand: its module is imported at their first use."""

    def __init__(self, name: str) -> None:
        self.name = name
        self._checks: list[Check[C]] | None = None

    def _loaded(self) -> list[Check[C]]:
        if self._checks is None:
            self._checks = module(self.name).FAMILY.checks
        return self._checks

    @overload
    def __getitem__(self, index: int) -> Check[C]: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[Check[C]]: ...
    def __getitem__(self, index: int | slice) -> Check[C] | Sequence[Check[C]]:
        return self._loaded()[index]

    def __len__(self) -> int:
        return len(self._loaded())

    def __iter__(self) -> Iterator[Check[C]]:
        return iter(self._loaded())


# the family modules loaded with this one, each once (elements: the S family's rules on XML elements)
MODULES = (syntax, elements, registry, meaning, update, startup, suppress, files)
# the families checked on one list, in the order they run (zero.rules.lists)
LIST_FAMILIES: tuple[Family[Context], ...] = (syntax.FAMILY, registry.FAMILY, meaning.FAMILY, update.FAMILY,
                                              startup.FAMILY)
FAMILIES: tuple[Family[Context] | Family[MachineContext] | Family[ProgramContext], ...] = (
    *LIST_FAMILIES, suppress.FAMILY, _machine, _program, files.FAMILY)

LIST_CHECKS: list[Check[Context]] = [c for family in LIST_FAMILIES for c in family.checks]
MACHINE_CHECKS: Sequence[Check[MachineContext]] = OnDemand("machine")
PROGRAM_CHECKS: Sequence[Check[ProgramContext]] = OnDemand("program")


def _rules() -> dict[str, Rule]:
    out: dict[str, Rule] = {}
    for family in FAMILIES:
        for code in sorted(family.rules):
            if code in out:
                raise ValueError(f"rule {code} is declared by two families")
            out[code] = family.rules[code]
    return out


RULES: dict[str, Rule]  # code → rule, family by family: made at the first use (__getattr__ below)
TITLES: dict[str, str] = {f.letter: f.title for f in FAMILIES}  # letter → the family's title
# the declared severities the funnel grades against: from each family's codes, without making the rules it
# declares later (the K, X and N rules: a list's lint reads none of them; issue 40, start-up)
declare({code: severity for family in FAMILIES for code, severity in family.severities().items()})


def __getattr__(name: str) -> dict[str, Rule]:
    """``RULES``, made at its first use (``zero rule``, the docs, SARIF's rule table, the server)."""
    if name != "RULES":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    rules = _rules()
    globals()["RULES"] = rules
    return rules


def severity_of(code: str) -> Severity | None:
    """The severity ``code`` is declared with (``None``: no such rule)."""
    return default_severity(code)


__all__ = ["FAMILIES", "LIST_CHECKS", "LIST_FAMILIES", "MACHINE_CHECKS", "MODULES", "ON_DEMAND", "PROGRAM_CHECKS",
           "RULES", "TITLES", "severity_of"]

"""Every rule zero has, by code, and the checks that implement them.

Code families: S syntax, R registry, M meaning within one list, Z suppression directives
(applied after the checks by :mod:`zero.rules.suppress`), X across the lists of one machine
(:mod:`zero.rules.machine`, run by ``zero lint --machine``), N NC programs
(:mod:`zero.program`). A code is never reused.
"""

from __future__ import annotations

from zero.rules import machine, meaning, params, program, suppress, syntax
from zero.rules.base import Check, Context, Rule

RULES: dict[str, Rule] = {**syntax.RULES, **params.RULES, **meaning.RULES, **suppress.RULES,
                          **machine.RULES, **program.RULES}
CHECKS: tuple[Check, ...] = (*syntax.CHECKS, *params.CHECKS, *meaning.CHECKS)
FAMILIES = {"S": "syntax", "R": "registry", "M": "meaning", "Z": "suppressions",
            "X": "machine (across lists, `zero lint --machine`)", "N": "NC programs"}

__all__ = ["CHECKS", "FAMILIES", "RULES", "Context", "Rule"]

"""Every rule zero has, by code, and the checks that implement them.

Code families: S syntax, R registry, M meaning within one list, Z suppression directives
(applied after the checks by :mod:`zero.rules.suppress`). X (across the lists of one
machine) and N (NC programs) are reserved. A code is never reused.
"""

from __future__ import annotations

from zero.rules import meaning, params, suppress, syntax
from zero.rules.base import Check, Context, Rule

RULES: dict[str, Rule] = {**syntax.RULES, **params.RULES, **meaning.RULES, **suppress.RULES}
CHECKS: tuple[Check, ...] = (*syntax.CHECKS, *params.CHECKS, *meaning.CHECKS)
FAMILIES = {"S": "syntax", "R": "registry", "M": "meaning", "Z": "suppressions"}

__all__ = ["CHECKS", "FAMILIES", "RULES", "Context", "Rule"]

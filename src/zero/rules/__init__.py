"""Every rule zero has, by code, and the checks that implement them.

Code families: S syntax, R registry, M meaning within one list. X (across the lists
of one machine) and N (NC programs) are reserved. A code is never reused.
"""

from __future__ import annotations

from zero.rules import meaning, params, syntax
from zero.rules.base import Check, Context, Rule

RULES: dict[str, Rule] = {**syntax.RULES, **params.RULES, **meaning.RULES}
CHECKS: tuple[Check, ...] = (*syntax.CHECKS, *params.CHECKS, *meaning.CHECKS)
FAMILIES = {"S": "syntax", "R": "registry", "M": "meaning"}

__all__ = ["CHECKS", "FAMILIES", "RULES", "Context", "Rule"]

"""Every rule zero has, by code, and the checks that implement them.

One module per family, each rule's metadata beside the check that reports it:
S syntax (:mod:`~zero.rules.syntax`), R registry (:mod:`~zero.rules.registry`),
M meaning within one list (:mod:`~zero.rules.meaning`), Z suppression directives
(:mod:`~zero.rules.suppress`, applied after the checks), X across the lists of one
machine (:mod:`~zero.rules.machine`, ``zero lint --machine``), N NC programs
(:mod:`~zero.rules.program`), U update and revert files
(:mod:`~zero.rules.update`), K the kernel's start-up checks
(:mod:`~zero.rules.startup`), F files that could not be read (:mod:`~zero.rules.files`,
reported by the engine). A code is never reused. The S rules on XML parameter elements that
did not become entries live in :mod:`~zero.rules.elements`. The families are listed once, in
:mod:`~zero.rules.families` (the registry every command, the docs and the server read).
"""

from __future__ import annotations

from zero.rules.base import Context, MachineContext, ProgramContext, Rule, run_checks
from zero.rules.families import MACHINE_CHECKS, PROGRAM_CHECKS
from zero.rules.families import TITLES as FAMILIES  # letter → title
from zero.rules.lists import check_document

__all__ = ["FAMILIES", "MACHINE_CHECKS", "PROGRAM_CHECKS", "RULES", "Context", "MachineContext",
           "ProgramContext", "Rule", "check_document", "run_checks"]

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from zero.rules.families import RULES
else:
    def __getattr__(name: str) -> object:
        """``RULES`` (:mod:`zero.rules.families`), made at its first use: a list's lint reads none of it."""
        if name != "RULES":
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
        from zero.rules import families  # start-up: made at the first use

        return families.RULES

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
did not become entries live in :mod:`~zero.rules.elements`.
"""

from __future__ import annotations

from zero.rules import elements as elements  # its S rules join the syntax family on import
from zero.rules import files, machine, meaning, program, registry, startup, suppress, syntax, update
from zero.rules.base import Context, Family, MachineContext, ProgramContext, Rule, run_checks
from zero.rules.lists import check_document

_FAMILIES: tuple[Family[Context] | Family[MachineContext] | Family[ProgramContext], ...] = (
    syntax.FAMILY, registry.FAMILY, meaning.FAMILY, update.FAMILY, startup.FAMILY, suppress.FAMILY, machine.FAMILY,
    program.FAMILY, files.FAMILY)
RULES: dict[str, Rule] = {code: f.rules[code] for f in _FAMILIES for code in sorted(f.rules)}
FAMILIES = {f.letter: f.title for f in _FAMILIES}
MACHINE_CHECKS = machine.FAMILY.checks
PROGRAM_CHECKS = program.FAMILY.checks

__all__ = ["FAMILIES", "MACHINE_CHECKS", "PROGRAM_CHECKS", "RULES", "Context", "MachineContext",
           "ProgramContext", "Rule", "check_document", "run_checks"]

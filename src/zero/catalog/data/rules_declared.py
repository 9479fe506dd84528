"""The rules of the families zero loads on demand, as their modules declare them, written by
tools/gen_rules.py: module -> (letter, title, scope, the size of its source, its rules: (code,
severity) in the order declared). Their names and texts are in rules_texts.py, read where the rules
are first looked at (a list's lint reads none of them).

Generated: do not edit."""

# ruff: noqa
from __future__ import annotations

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (zero.hints)
if TYPE_CHECKING:
    from typing import Any

DECLARED: dict[str, Any] = {
    'machine': ('X', 'machine (across lists, `zero lint --machine`)', 'machine', 55156, (
        ('X005', 'ERROR'),
        ('X008', 'WARNING'),
        ('X004', 'ERROR'),
        ('X007', 'ERROR'),
        ('X001', 'WARNING'),
        ('X002', 'WARNING'),
        ('X003', 'WARNING'),
        ('X006', 'WARNING'),
        ('X009', 'WARNING'),
        ('X013', 'WARNING'),
        ('X014', 'WARNING'),
        ('X010', 'WARNING'),
        ('X011', 'WARNING'),
        ('X012', 'INFO'),
        ('X015', 'ERROR'),
        ('X016', 'ERROR'),
        ('X017', 'ERROR'),
        ('X018', 'WARNING'),
        ('X019', 'ERROR'),
        ('X020', 'ERROR'),
        ('X021', 'ERROR'),
        ('X022', 'ERROR'),
        ('X023', 'ERROR'),
        ('X024', 'ERROR'),
        ('X025', 'ERROR'),
        ('X026', 'ERROR'),
    )),
    'program': ('N', 'NC programs', 'program', 31485, (
        ('N001', 'ERROR'),
        ('N002', 'WARNING'),
        ('N003', 'WARNING'),
        ('N004', 'ERROR'),
        ('N005', 'ERROR'),
        ('N006', 'WARNING'),
        ('N007', 'WARNING'),
        ('N008', 'WARNING'),
        ('N009', 'WARNING'),
        ('N010', 'INFO'),
    )),
}

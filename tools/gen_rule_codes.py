#!/usr/bin/env python3
"""Write every rule's code, declared severity and opt-in flag to ``src/zero/catalog/data/rule_codes.py``, in the
order of the registry (``zero.rules.RULES``): rule selection (the configuration's layers, ``--select``,
the cache's key of a file's options) reads them there, so that a run whose every result comes from the
cache imports no rule module (issue 40: the same fleet again). The table is written with the name and
size of every module of ``src/zero/rules/``; while one differs, :func:`zero.engine.selection.rule_table`
imports the rules instead (a stale table: slower, never wrong), and a test fails. Run it after adding,
removing or re-grading a rule.

Usage: python tools/gen_rule_codes.py [--check]   (--check: exit 1 if the table is stale, write nothing)
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen

SRC = Path(__file__).resolve().parent.parent / "src" / "zero"


def render() -> str:
    """The module's text, from the registry and the rule modules as they are now."""
    from zero.engine.selection import rule_sources
    from zero.rules import RULES

    sources = "".join(f"\n    ({name!r}, {size!r})," for name, size in rule_sources())
    codes = "".join(f"\n    ({code!r}, {r.severity.name!r}, {r.opt_in!r})," for code, r in RULES.items())
    return ('"""Every rule\'s code, declared severity and opt-in flag, in the registry\'s order, and the size of\n'
            "each module of zero/rules/ they were read from: written by tools/gen_rule_codes.py.\n\n"
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n"
            "from __future__ import annotations\n\n"
            f"SOURCES: tuple[tuple[str, int], ...] = ({sources}\n)\n\n"
            f"CODES: tuple[tuple[str, str, bool], ...] = ({codes}\n)\n")


def files() -> dict[Path, str | None]:
    return {SRC / "catalog" / "data" / "rule_codes.py": render()}


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_rule_codes.py", files, argv)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Write what each K rule declares (its severity, name, summary, explanation and the parameters it reads)
to ``src/zero/catalog/data/startup_rules.py``, each with the facts of its row of startup_errors.toml (and the
facts alone to ``startup_facts.py``: a start-up declares the rules from them, the texts read at first use): read
from bytecode at start-up instead of written out at each run (issue 40). With them the size of the
``startup_errors.py`` they were written from: while that file has it, a start-up declares the rules from
this module alone (without importing the rows); else each row whose facts differ from the ones written
here is declared from its own, so a stale module is slower, never wrong; a test fails while it is stale.
Run it after tools/gen_startup.py (and after changing how ``zero.rules.startup.said`` words a rule).

Usage: python tools/gen_startup_rules.py [--check]   (--check: exit 1 if a module is stale, write nothing)
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen
from pydata import TYPING_FOR_CHECKERS

DATA = Path(__file__).resolve().parent.parent / "src" / "zero" / "catalog" / "data"


def render() -> str:
    """The module's text, from the rows and the wording as they are now."""
    from zero.catalog.data.startup_errors import ERRORS
    from zero.rules.startup import facts, said

    lines = []
    for row in ERRORS:
        if row.get("condition"):
            f = facts(row)
            lines.append(f"    {f[0]!r}: ({f!r},\n             {said(f)!r}),")
    return ('"""What each K rule declares, with the facts of its row of startup_errors.toml it is declared from,\n'
            'written by tools/gen_startup_rules.py: code -> (facts, (severity letter, name, summary, explanation,\n'
            'the parameters it reads)); ERRORS_SIZE: the size of the startup_errors.py written from.\n\n'
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n"
            + "\n".join(TYPING_FOR_CHECKERS) + "\n\n"
            f"ERRORS_SIZE: int = {(DATA / 'startup_errors.py').stat().st_size}\n"
            "DECLARED: dict[str, Any] = {\n" + "\n".join(lines) + "\n}\n")


def render_facts() -> str:
    """``startup_facts.py``: each rule's facts alone (what a start-up declares the K rules from; their
    texts, in ``startup_rules.py``, are imported where something reads them), with the same size."""
    from zero.catalog.data.startup_errors import ERRORS
    from zero.rules.startup import facts

    lines = [f"    {f[0]!r}: {f!r}," for f in (facts(row) for row in ERRORS if row.get("condition"))]
    return ('"""The facts of each K rule\'s row of startup_errors.toml, written by tools/gen_startup_rules.py:\n'
            'code -> facts (what the K rules are declared from at start-up; what each declares, its texts, is in\n'
            'startup_rules.py); ERRORS_SIZE: the size of the startup_errors.py written from.\n\n'
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n"
            + "\n".join(TYPING_FOR_CHECKERS) + "\n\n"
            f"ERRORS_SIZE: int = {(DATA / 'startup_errors.py').stat().st_size}\n"
            "FACTS: dict[str, Any] = {\n" + "\n".join(lines) + "\n}\n")


def files() -> dict[Path, str | None]:
    return {DATA / "startup_rules.py": render(), DATA / "startup_facts.py": render_facts()}


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_startup_rules.py", files, argv)


if __name__ == "__main__":
    main()

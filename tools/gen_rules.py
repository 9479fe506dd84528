#!/usr/bin/env python3
"""Write the rules of the families loaded on demand (X: a machine's lists, N: NC programs) to
``src/zero/catalog/data/rules_declared.py``, as their modules declare them: the registry (``zero.rules.RULES``: codes,
names, severities, texts) stays complete while a list's lint imports neither module nor what they import
(issue 40: start-up). Each family is written with the size of its module's source; a module whose size
differs is imported (a stale module: slower, never wrong in that case), and a test fails while the written
rules differ from the declared ones. Run it after changing a rule of rules/machine.py or rules/program.py.

Usage: python tools/gen_rules.py [--check]   (--check: exit 1 if the module is stale, write nothing)
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

import _gen
from pydata import TYPING_FOR_CHECKERS

RULES_DIR = Path(__file__).resolve().parent.parent / "src" / "zero" / "rules"


# the rest of both modules' head: the docstring's end, and the names their annotations use
_HEAD = 'Generated: do not edit."""\n\n# ruff: noqa\n' + "\n".join(TYPING_FOR_CHECKERS) + "\n\n"


def _families() -> list[tuple[str, object, int]]:
    import importlib

    from zero.rules.families import ON_DEMAND

    return [(name, importlib.import_module(f"zero.rules.{name}").FAMILY, (RULES_DIR / f"{name}.py").stat().st_size)
            for name in ON_DEMAND]


def render() -> str:
    """``rules_declared.py``, from the family modules as they are now: each family and its rules' codes and
    severities (what a start-up declares them with)."""
    out = []
    for name, family, size in _families():
        rules = "".join(f"\n        ({r.code!r}, {r.severity.name!r})," for r in family.rules.values())  # type: ignore[attr-defined]
        out.append(f"    {name!r}: ({family.letter!r}, {family.title!r}, {family.scope!r}, {size!r}, ({rules}\n    )),")  # type: ignore[attr-defined]
    return ('"""The rules of the families zero loads on demand, as their modules declare them, written by\n'
            'tools/gen_rules.py: module -> (letter, title, scope, the size of its source, its rules: (code,\n'
            'severity) in the order declared). Their names and texts are in rules_texts.py, read where the rules\n'
            'are first looked at (a list\'s lint reads none of them).\n\n'
            + _HEAD + "DECLARED: dict[str, Any] = {\n" + "\n".join(out) + "\n}\n")


def render_texts() -> str:
    """``rules_texts.py``: each family's rules in full (code, name, severity, summary, explanation, opt_in,
    reads), in the order declared."""
    out = []
    for name, family, _ in _families():
        rules = "".join(f"\n        ({r.code!r}, {r.name!r}, {r.severity.name!r}, {r.summary!r},\n"
                        f"         {r.explanation!r},\n         {r.opt_in!r}, {r.reads!r}),"
                        for r in family.rules.values())  # type: ignore[attr-defined]
        out.append(f"    {name!r}: ({rules}\n    ),")
    return ('"""The rules of the families zero loads on demand in full, as their modules declare them, written by\n'
            'tools/gen_rules.py: module -> its rules: (code, name, severity, summary, explanation, opt_in, reads)\n'
            'in the order declared (their codes and severities: rules_declared.py).\n\n'
            + _HEAD + "TEXTS: dict[str, Any] = {\n" + "\n".join(out) + "\n}\n")


def files() -> dict[Path, str | None]:
    data = RULES_DIR.parent / "catalog" / "data"
    return {data / "rules_declared.py": render(), data / "rules_texts.py": render_texts()}


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_rules.py", files, argv)


if __name__ == "__main__":
    main()

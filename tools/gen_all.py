#!/usr/bin/env python3
"""Run every generator of ``tools/``, each after the ones whose output it reads (or, with ``--check``, check
them all and name every stale file: exit 1, nothing written).

zero takes what these generators write (the catalogue's tables, the rule codes, the record inits, the
patterns' code, ...) only while it is current: a stale table is not wrong, it sends every run down the slow
way (an edit of a rule module makes the rule-code table stale, and each lint then imports and makes every
rule). ``tests/test_generators.py`` fails on a stale one; run this after an edit, or ``--check`` in a hook.

Usage: python tools/gen_all.py [--check]
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _gen

TOOLS = Path(__file__).resolve().parent
# Each after what it reads: the rows before the ranges, conditions and K declarations made of them; the
# rule modules' declarations before the codes; every module (their records), then what a lint imports, last.
ORDER = ("gen_registry.py", "gen_seeds.py", "gen_specs.py", "gen_evidence.py", "gen_config.py", "gen_ranges.py",
         "gen_startup.py", "gen_startup_rules.py", "gen_conditions.py", "gen_rules.py", "gen_rule_codes.py",
         "gen_pattern_codes.py", "gen_record_inits.py", "gen_bundled_modules.py")


def main(argv: list[str] | None = None) -> None:
    check = _gen.checking(argv, "python tools/gen_all.py")
    failed = []
    for name in ORDER:
        done = subprocess.run([sys.executable, str(TOOLS / name), *(["--check"] if check else [])], check=False,
                              capture_output=True, text=True)
        sys.stdout.write(done.stdout)
        sys.stderr.write(done.stderr)
        if done.returncode != 0:
            failed.append(name)
    if failed:
        print(f"{'stale' if check else 'failed'}: {', '.join(failed)}", file=sys.stderr)
        raise SystemExit(1)


if __name__ == "__main__":
    main()

"""The X and N families are loaded on demand (issue 40: start-up): their rules are in the registry as
their modules declare them (written by tools/gen_rules.py), their checks import the module at first use."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from types import ModuleType

from conftest import script_module
from zero.rules import MACHINE_CHECKS, PROGRAM_CHECKS, RULES
from zero.rules import families as registry_of_families

ROOT = Path(__file__).resolve().parents[2]


def _generator() -> ModuleType:
    return script_module(ROOT / "tools" / "gen_rules.py")


def test_the_generated_module_is_up_to_date() -> None:
    """Run ``python tools/gen_rules.py`` after changing a rule of rules/machine.py or rules/program.py."""
    data = ROOT / "src" / "zero" / "catalog" / "data"
    assert (data / "rules_declared.py").read_text(encoding="utf-8") == _generator().render()  # type: ignore[attr-defined]
    assert (data / "rules_texts.py").read_text(encoding="utf-8") == _generator().render_texts()  # type: ignore[attr-defined]


def test_the_written_families_are_the_declared_ones() -> None:
    listed = {f.letter: f for f in registry_of_families.FAMILIES}
    for name in registry_of_families.ON_DEMAND:
        written = registry_of_families._written(name)
        declared = registry_of_families.module(name).FAMILY
        assert written is not None  # the source it was written from: not imported for its rules
        assert (written.letter, written.title, written.scope) == (declared.letter, declared.title, declared.scope)
        assert written.rules == declared.rules and list(written.rules) == list(declared.rules)
        assert listed[declared.letter].rules == declared.rules
        assert all(RULES[code] == rule for code, rule in declared.rules.items())


def test_their_checks_are_the_modules_checks() -> None:
    assert list(MACHINE_CHECKS) == registry_of_families.module("machine").FAMILY.checks
    assert list(PROGRAM_CHECKS) == registry_of_families.module("program").FAMILY.checks
    assert len(MACHINE_CHECKS) > 5 and MACHINE_CHECKS[0] == next(iter(MACHINE_CHECKS))


def test_every_family_module_is_listed() -> None:
    rules_dir = ROOT / "src" / "zero" / "rules"
    declaring = {p.stem for p in rules_dir.glob("*.py") if "\nFAMILY" in p.read_text(encoding="utf-8")}
    listed = {m.__name__.rsplit(".", 1)[1] for m in registry_of_families.MODULES} | set(registry_of_families.ON_DEMAND)
    assert declaring <= listed and set(registry_of_families.ON_DEMAND) <= declaring, declaring ^ listed


def test_a_list_s_lint_loads_neither_the_machine_nor_the_program_rules(tmp_path: Path) -> None:
    lis = tmp_path / "a.lis"
    lis.write_text("kopf.achs_nr 1\nEnde\n", encoding="utf-8")
    code = ("import sys; from zero.cli.run import lint; from zero.rules import RULES; "
            f"lint(paths=[{str(lis)!r}], output_format='json', no_cache=True); "
            "print(sorted(m for m in sys.modules if m.startswith(('zero.rules.machine', 'zero.rules.program', "
            "'zero.machine', 'zero.nc'))), len(RULES), any(c.startswith('N') for c in RULES))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.stdout.strip().splitlines()[-1] == f"[] {len(RULES)} True", out.stderr

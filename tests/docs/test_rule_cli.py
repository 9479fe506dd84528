"""``zero rule Kxxx`` in the terminal says what its documentation page says about why it matters: the
specific consequence of the kernel's documented correction, not one sentence shared by every K rule."""

from __future__ import annotations

import subprocess
import sys

from conftest import ROOT
from zero.catalog.registry import Registry
from zero.output import docs
from zero.rules.startup import CHECKS


def _zero(*args: str) -> str:
    run = subprocess.run([sys.executable, "-m", "zero", *args], capture_output=True, text=True, timeout=120,
                         cwd=ROOT, env={"PATH": "/usr/bin:/bin", "COLUMNS": "200", "NO_COLOR": "1"})
    assert run.returncode == 0, run.stderr
    return run.stdout


def test_zero_rule_prints_a_kernel_rules_specific_consequence(registry: Registry) -> None:
    out = _zero("rule", "K093")
    why = out.split("Why it matters on the machine: ", 1)[1].split("\n\n", 1)[0]
    assert why == ("when the controller starts with such a list it reports error P-ERR-110580 (Gear factor "
                   "denominator is zero) and sets `getriebe[].gear_fact_denom` (P-AXIS-00512) to `1`: the machine "
                   "runs with that value, not with the one the list writes, and nothing in the list shows it.")
    err = next(c for c in CHECKS if c.code == "K093")
    page = docs.kernel_consequence(err, registry)
    assert why == page[:1].lower() + page[1:]  # the docs site's sentence
    assert "the message appears when the controller starts" not in out  # the generic sentence is gone
    assert out.count("Why it matters on the machine") == 1 and "Fix: change the values" in out


def test_zero_rule_all_has_no_generic_kernel_sentence() -> None:
    out = _zero("rule", "--all")
    assert "the message appears when the controller starts" not in out
    assert out.count("Why it matters on the machine") >= len(CHECKS)


def test_zero_rule_says_which_parameters_the_rule_reads() -> None:
    assert "\nReads: P-AXIS-00177 (kenngr.swe_neg), P-AXIS-00178 (kenngr.swe_pos).\n" in _zero("rule", "M001")
    assert "\nReads: P-AXIS-00512 (getriebe[].gear_fact_denom).\n" in _zero("rule", "K093")
    assert "\nReads: no particular parameter; it reads the list's text" in _zero("rule", "S001")

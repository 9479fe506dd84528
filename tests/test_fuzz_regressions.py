"""Every input the fuzzer (fuzz/fuzz_zero.py) ever crashed on, replayed without atheris."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT

sys.path.insert(0, str(ROOT / "fuzz"))
from targets import one_input

CASES = sorted((FIXTURES / "fuzz").glob("*.bin"))
SEEDS = sorted((ROOT / "fuzz" / "seeds").iterdir())


@pytest.mark.parametrize("case", CASES + SEEDS, ids=[c.name for c in CASES + SEEDS])
def test_fuzz_input_stays_fixed(case: Path) -> None:
    one_input(case.read_bytes())


def test_there_are_regression_cases() -> None:
    assert CASES

"""The K conditions written as Python at build time give what the compiled closures give (issue 40)."""

from __future__ import annotations

import itertools
import random
import sys
from pathlib import Path

import pytest

from conftest import script_module
from zero.catalog.condition_source import source
from zero.catalog.conditions import compile_condition, parse, ref_elements, refs
from zero.catalog.data.startup_compiled import COMPILED
from zero.rules import startup

ROOT = Path(__file__).resolve().parents[2]
CHOICES: list[object] = [None, 0, 1, -1, 2, 3, 0.5, 7, 64, 100, 10**30, 1e300, "", "X", "S", "AB_1", "Q-", "0"]


def _generator() -> object:
    return script_module(ROOT / "tools" / "gen_conditions.py")


def test_the_generated_module_is_up_to_date() -> None:
    """Run ``python tools/gen_conditions.py`` after editing startup_errors.toml (and gen_startup.py)."""
    written = (ROOT / "src" / "zero" / "catalog" / "data" / "startup_compiled.py").read_text(encoding="utf-8")
    assert written == _generator().render()  # type: ignore[attr-defined]


@pytest.mark.parametrize("err", startup.CHECKS, ids=lambda e: e.code)
def test_each_written_condition_gives_what_its_closure_gives(err: startup.StartupError) -> None:
    rnd = random.Random(err.code)
    for text, written in ((err.condition_text, COMPILED[err.code][2]), (err.when_text, COMPILED[err.code][3])):
        if not text:
            assert written is None
            continue
        closure = compile_condition(parse(text))
        for _ in range(400):
            values: dict[tuple[str, int | None], object] = {}

            def lookup(pid: str, index: int | None, values: dict[tuple[str, int | None], object] = values) -> object:
                if (pid, index) not in values:
                    values[(pid, index)] = rnd.choice(CHOICES)
                return values[(pid, index)]

            want = closure(lookup)  # type: ignore[arg-type]
            assert written(lookup) == want and type(written(lookup)) is type(want), (text, values)


def test_compiled_takes_the_written_function_and_its_reads() -> None:
    err = next(e for e in startup.CHECKS if e.when_text)
    got = startup.compiled(err)
    node = parse(err.condition_text)
    assert got.condition is COMPILED[err.code][2]
    assert got.read == tuple(refs(node)) and got.shown == tuple(ref_elements(node))


def test_a_stale_row_is_compiled_from_its_text(monkeypatch: pytest.MonkeyPatch) -> None:
    err = startup.CHECKS[0]
    monkeypatch.setitem(sys.modules["zero.catalog.data.startup_compiled"].COMPILED, err.code,
                        ("something else", "", lambda _lookup: True, None, (), ()))
    monkeypatch.setattr(startup, "_compiled", {})
    got = startup.compiled(err)
    assert got.read == tuple(refs(parse(err.condition_text)))


def test_and_or_decide_without_the_unknown_side() -> None:
    namespace: dict[str, object] = {}
    exec("from zero.catalog.condition_source import *\n"
         "from zero.catalog.condition_source import _both, _binary\n"
         + source("f", parse("P-AXIS-00001 > 0 and P-AXIS-00002 > 0"))
         + source("g", parse("P-AXIS-00001 > 0 or P-AXIS-00002 > 0")), namespace)
    f, g = namespace["f"], namespace["g"]
    for a, b in itertools.product((None, 0, 1), repeat=2):
        values = {"P-AXIS-00001": a, "P-AXIS-00002": b}
        look = lambda pid, _i, values=values: values[pid]  # noqa: E731
        assert f(look) == compile_condition(parse("P-AXIS-00001 > 0 and P-AXIS-00002 > 0"))(look)  # type: ignore[operator]
        assert g(look) == compile_condition(parse("P-AXIS-00001 > 0 or P-AXIS-00002 > 0"))(look)  # type: ignore[operator]

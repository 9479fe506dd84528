"""The K conditions and the prose ranges' written as Python at build time give what the compiled closures
give (issue 40)."""

from __future__ import annotations

import itertools
import random
import sys
from pathlib import Path

import pytest

from conftest import script_module
from zero.catalog.condition_source import source
from zero.catalog.conditions import compile_condition, parse, ref_elements, refs
from zero.catalog.data.prose_compiled import COMPILED as PROSE_COMPILED
from zero.catalog.data.prose_ranges import RANGES
from zero.catalog.data.startup_compiled import COMPILED
from zero.rules import registry as rules_registry
from zero.rules import startup

ROOT = Path(__file__).resolve().parents[2]
CHOICES: list[object] = [None, 0, 1, -1, 2, 3, 0.5, 7, 64, 100, 10**30, 1e300, "", "X", "S", "AB_1", "Q-", "0"]


def _generator() -> object:
    return script_module(ROOT / "tools" / "gen_conditions.py")


def test_the_generated_modules_are_up_to_date() -> None:
    """Run ``python tools/gen_conditions.py`` after editing startup_errors.toml (and gen_startup.py)."""
    data = ROOT / "src" / "zero" / "catalog" / "data"
    rendered = _generator().render()  # type: ignore[attr-defined]
    assert sorted(rendered) == sorted(p.name for p in data.glob("startup_compiled*.py"))
    for name, text in rendered.items():
        assert (data / name).read_text(encoding="utf-8") == text, name


def test_each_kind_reads_its_own_written_conditions() -> None:
    """Each kind's K conditions in a module of their own (issue 40: start-up): every check's is in its
    kind's, and a kind without any has none."""
    for err in startup.CHECKS:
        assert startup._written_of(err.kind).get(err.code) is COMPILED[err.code]
    assert startup._written_of("HWCF") == {} and startup._written_of("a.b") == {}


def test_the_generated_prose_module_is_up_to_date() -> None:
    """Run ``python tools/gen_conditions.py`` (tools/gen_startup.py runs it) after editing prose_ranges.toml."""
    written = (ROOT / "src" / "zero" / "catalog" / "data" / "prose_compiled.py").read_text(encoding="utf-8")
    assert written == _generator().render_prose()  # type: ignore[attr-defined]


def _same_as_closures(seed: str, pairs: tuple[tuple[str, object], ...]) -> None:
    """Each written function gives what the closure compiled from its text gives, on random values."""
    rnd = random.Random(seed)
    for text, written in pairs:
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
            got = written(lookup)  # type: ignore[operator]
            assert got == want and type(got) is type(want), (text, values)


@pytest.mark.parametrize("err", startup.CHECKS, ids=lambda e: e.code)
def test_each_written_condition_gives_what_its_closure_gives(err: startup.StartupError) -> None:
    _same_as_closures(err.code, ((err.condition_text, COMPILED[err.code][2]), (err.when_text, COMPILED[err.code][3])))


@pytest.mark.parametrize("row", RANGES, ids=lambda r: str(r["id"]))
def test_each_written_prose_range_gives_what_its_closure_gives(row: dict[str, object]) -> None:
    pre = PROSE_COMPILED[str(row["id"])]
    assert pre[:2] == (row["condition"], row.get("when") or "")
    assert pre[4] == tuple(ref_elements(parse(str(row["condition"]))))
    _same_as_closures(str(row["id"]), ((str(row["condition"]), pre[2]), (str(row.get("when") or ""), pre[3])))


def test_a_prose_range_takes_its_written_function_unless_its_row_is_stale(monkeypatch: pytest.MonkeyPatch) -> None:
    pid = str(next(r for r in RANGES if r.get("when"))["id"])
    rules_registry._prose.cache_clear()
    try:
        got = rules_registry._prose(pid)
        assert got[0] is PROSE_COMPILED[pid][2] and got[1] is PROSE_COMPILED[pid][3]
        assert got[4] == list(PROSE_COMPILED[pid][4])
        rules_registry._prose.cache_clear()
        monkeypatch.setitem(PROSE_COMPILED, pid, ("something else", "", lambda _lookup: True, None, ()))
        stale = rules_registry._prose(pid)
        assert stale[0] is not PROSE_COMPILED[pid][2] and stale[1] is not None
        assert stale[4] == ref_elements(parse(stale[2]))
    finally:
        rules_registry._prose.cache_clear()


def test_compiled_takes_the_written_function_and_its_reads() -> None:
    err = next(e for e in startup.CHECKS if e.when_text)
    got = startup.compiled(err)
    node = parse(err.condition_text)
    assert got.condition is COMPILED[err.code][2]
    assert got.read == tuple(refs(node)) and got.shown == tuple(ref_elements(node))


def test_a_stale_row_is_compiled_from_its_text(monkeypatch: pytest.MonkeyPatch) -> None:
    err = startup.CHECKS[0]
    monkeypatch.setitem(startup._written_of(err.kind), err.code,
                        ("something else", "", lambda _lookup: True, None, (), ()))
    monkeypatch.setattr(startup, "_compiled", {})
    got = startup.compiled(err)
    assert got.read == tuple(refs(parse(err.condition_text)))


def test_and_or_decide_without_the_unknown_side() -> None:
    namespace: dict[str, object] = {}
    exec("from zero.catalog.condition_helpers import _both, _binary\n"
         + source("f", parse("P-AXIS-00001 > 0 and P-AXIS-00002 > 0"))
         + source("g", parse("P-AXIS-00001 > 0 or P-AXIS-00002 > 0")), namespace)
    f, g = namespace["f"], namespace["g"]
    for a, b in itertools.product((None, 0, 1), repeat=2):
        values = {"P-AXIS-00001": a, "P-AXIS-00002": b}
        look = lambda pid, _i, values=values: values[pid]  # noqa: E731
        assert f(look) == compile_condition(parse("P-AXIS-00001 > 0 and P-AXIS-00002 > 0"))(look)  # type: ignore[operator]
        assert g(look) == compile_condition(parse("P-AXIS-00001 > 0 or P-AXIS-00002 > 0"))(look)  # type: ignore[operator]


def test_the_prose_rows_are_read_from_the_written_module_while_their_module_has_its_size(
        monkeypatch: pytest.MonkeyPatch) -> None:
    import subprocess

    from zero.catalog.data import prose_compiled

    rows = {str(r["id"]): (str(r["condition"]), str(r.get("when") or ""), str(r["prose"])) for r in RANGES}
    rows_module = ROOT / "src" / "zero" / "catalog" / "data" / "prose_ranges.py"
    assert rows_module.stat().st_size == prose_compiled.ROWS_SIZE
    rules_registry._prose_rows.cache_clear()
    try:
        assert rules_registry._prose_rows() == rows
        monkeypatch.setattr(prose_compiled, "ROWS_SIZE", -2)  # another size: read from the rows, the same
        rules_registry._prose_rows.cache_clear()
        assert rules_registry._prose_rows() == rows
    finally:
        rules_registry._prose_rows.cache_clear()
    code = ("import sys\nfrom zero.rules.registry import _prose, _prose_rows\n_prose(next(iter(_prose_rows())))\n"
            "print('zero.catalog.data.prose_ranges' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


def test_a_lint_imports_no_condition_parser(tmp_path: Path) -> None:
    """The written K conditions and prose ranges need the helpers only (catalog/condition_helpers.py): the
    parser and the writer are imported for a stale row or a tool (issue 40: start-up)."""
    import subprocess

    listing = tmp_path / "achse.lis"
    listing.write_text("kenngr.swe_pos 100000\nkenngr.swe_neg -100000\ngetriebe[0].dynamik.vb_max 0\nEnde\n",
                       encoding="utf-8")
    code = ("import sys\nfrom zero.catalog.registry import load_registry\nfrom zero.engine.lint import lint_file\n"
            f"print(len(lint_file({str(listing)!r}, load_registry()).diagnostics) > 0, "
            "'zero.catalog.conditions' in sys.modules, 'zero.catalog.condition_source' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["True", "False", "False"]

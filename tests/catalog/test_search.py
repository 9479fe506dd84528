"""`zero param` finds parameters by a member of the key, a part of it, the ID or the description."""

from __future__ import annotations

from typer.testing import CliRunner

from zero.catalog.registry import Registry
from zero.cli.app import app

runner = CliRunner()


def test_search_ranks_whole_members_first(registry: Registry) -> None:
    assert [s.id for s in registry.search("swe_pos")][:1] == ["P-AXIS-00178"]
    assert [s.key for s in registry.search("homing_type")] == ["kenngr.homing.homing_type"]
    assert registry.search("xyzzy") == []
    assert len(registry.search("swe")) > 3


def test_param_command_shows_the_one_match_or_lists_several() -> None:
    one = runner.invoke(app, ["param", "swe_pos"])
    assert one.exit_code == 0 and "P-AXIS-00178" in one.output and "kenngr.swe_pos" in one.output
    several = runner.invoke(app, ["param", "swe"])
    assert several.exit_code == 0 and "parameters match 'swe'" in several.output
    assert "P-AXIS-00177  kenngr.swe_neg  (axis parameter list)" in several.output
    none = runner.invoke(app, ["param", "xyzzy"])
    assert none.exit_code == 2


def test_the_compiled_seeds_match_the_toml_source() -> None:
    import tomllib

    from conftest import ROOT
    from zero.catalog.data.seeds import SEEDS

    data = ROOT / "src" / "zero" / "catalog" / "data"
    assert tomllib.loads((data / "seeds.toml").read_text(encoding="utf-8")) == SEEDS, "run tools/gen_seeds.py"

"""The generators of ``tools/``: each one's ``--check`` passes on the tree (no generated file is stale),
fails on a stale file without writing, and they share one command line (``tools/_gen.py``)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

from conftest import ROOT, script_module

# gen_record_inits.py --check runs in tests/test_records.py (test_the_ahead_of_time_inits_are_current)
GENERATORS = ["gen_bundled_modules.py", "gen_conditions.py", "gen_config.py", "gen_evidence.py", "gen_ranges.py",
              "gen_registry.py", "gen_pattern_codes.py", "gen_rule_codes.py", "gen_rules.py", "gen_seeds.py",
              "gen_specs.py", "gen_startup.py", "gen_startup_rules.py"]
PARAM_DESC = ROOT.parent / "shared" / "corpus" / "isg-sdk" / "meta-data" / "CncParaDesc.xml"  # gen_registry's


def _check(tool: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, str(tool), *args, "--check"], capture_output=True, text=True,
                          check=False)


def test_every_generator_is_checked() -> None:
    """A new generator joins GENERATORS (or test_records.py's check), and gen_all.py's order."""
    found = {p.name for p in (ROOT / "tools").glob("gen_*.py")} - {"gen_record_inits.py", "gen_all.py"}
    assert found <= set(GENERATORS)
    gen_all = script_module(ROOT / "tools" / "gen_all.py")
    assert sorted(gen_all.ORDER) == sorted([*found, "gen_record_inits.py"])  # type: ignore[attr-defined]
    # the records read every module; the bundles' modules are what a lint imports once every table is current
    assert gen_all.ORDER[-2:] == ("gen_record_inits.py", "gen_bundled_modules.py")  # type: ignore[attr-defined]


@pytest.mark.parametrize("name", GENERATORS)
def test_no_generated_file_is_stale(name: str) -> None:
    """Run ``python tools/<name>`` after changing what it reads (its docstring says when)."""
    if name == "gen_registry.py" and not PARAM_DESC.is_file():
        pytest.skip("the vendor's CncParaDesc.xml is not here")
    done = _check(ROOT / "tools" / name)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "every file is current" in done.stdout


def test_a_stale_file_fails_the_check_and_is_left_as_it_is(tmp_path: Path) -> None:
    """gen_seeds.py on a copy of what it reads and writes: ``--check`` names the stale file, exits 1 and
    writes nothing; without it the file is written again."""
    shutil.copytree(ROOT / "tools", tmp_path / "tools", ignore=shutil.ignore_patterns("__pycache__"))
    data = tmp_path / "src" / "zero" / "catalog" / "data"
    data.mkdir(parents=True)
    for name in ("seeds.toml", "seeds.py"):
        shutil.copy(ROOT / "src" / "zero" / "catalog" / "data" / name, data / name)
    tool = tmp_path / "tools" / "gen_seeds.py"
    assert _check(tool).returncode == 0
    current = (data / "seeds.py").read_bytes()
    (data / "seeds.py").write_bytes(current + b"# edited\n")
    done = _check(tool)
    assert done.returncode == 1
    assert "src/zero/catalog/data/seeds.py is stale: run python tools/gen_seeds.py" in done.stdout
    assert (data / "seeds.py").read_bytes() == current + b"# edited\n"
    subprocess.run([sys.executable, str(tool)], capture_output=True, check=True)
    assert (data / "seeds.py").read_bytes() == current


def _gen() -> ModuleType:
    return script_module(ROOT / "tools" / "_gen.py")


def test_update_checks_writes_and_removes(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    gen = _gen()
    same, other, gone, absent = (tmp_path / n for n in ("same.py", "other.py", "gone.py", "absent.py"))
    same.write_text("x = 1\n")
    other.write_text("x = 1\r\n")  # a line end alone makes a file stale
    gone.write_text("")
    files = {same: "x = 1\n", other: "x = 1\n", gone: None, absent: "y = 2\n"}
    assert gen.update("gen_x.py", files, True) == [other, gone, absent]
    assert (other.read_bytes(), gone.exists(), absent.exists()) == (b"x = 1\r\n", True, False)
    said = capsys.readouterr().out
    assert f"{gone} is no longer generated: run python tools/gen_x.py" in said
    assert f"{absent} is stale: run python tools/gen_x.py" in said
    assert gen.update("gen_x.py", files, False) == []
    assert gen.stale(files) == []
    assert (other.read_bytes(), gone.exists(), absent.read_text()) == (b"x = 1\n", False, "y = 2\n")


def test_the_command_line_is_check_or_nothing() -> None:
    gen = _gen()
    assert gen.checking([]) is False
    assert gen.checking(["--check"]) is True
    for wrong in (["--chek"], ["--check", "--check"], ["x"]):
        with pytest.raises(SystemExit) as stop:
            gen.checking(wrong, "python tools/gen_x.py")
        assert stop.value.code == 2
    with pytest.raises(SystemExit) as stop:
        gen.done("gen_x.py", [Path("a.py")], True)
    assert stop.value.code == 1


def test_gen_all_checks_every_generator() -> None:
    """``python tools/gen_all.py --check``: what a hook runs after an edit (each generator in its order)."""
    if not PARAM_DESC.is_file():
        pytest.skip("the vendor's CncParaDesc.xml is not here")
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "gen_all.py"), "--check"], capture_output=True,
                          text=True, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    gen_all = script_module(ROOT / "tools" / "gen_all.py")
    assert done.stdout.count("every file is current") == len(gen_all.ORDER)  # type: ignore[attr-defined]
    bad = subprocess.run([sys.executable, str(ROOT / "tools" / "gen_all.py"), "--write"], capture_output=True,
                         text=True, check=False)
    assert bad.returncode == 2 and "usage" in bad.stderr

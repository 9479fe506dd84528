"""The registry a command is given is the one every layer uses (no process-wide default)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from zero.catalog.registry import load_registry
from zero.engine.convert import convert
from zero.errors import ZeroError

# A parameter description of one parameter that the built-in table does not have.
XML = """<?xml version="1.0" encoding="utf-8"?>
<Parameters xmlns="https://www.isg-stuttgart.de/kernel/CncParaDesc">
  <Parameter><Id>P-AXIS-09999</Id><Name>kenngr.zero_test_count</Name><Type>SGN32</Type>
    <DefaultValue>0</DefaultValue></Parameter>
</Parameters>
"""
YAML = b"kenngr:\n  zero_test_count: 1.5\n_zero:\n  kind: AXIS\n"


@pytest.fixture()
def desc(tmp_path: Path) -> Path:
    path = tmp_path / "CncParaDesc.xml"
    path.write_text(XML, encoding="utf-8")
    return path


def test_convert_types_numbers_with_the_registry_it_is_given(desc: Path) -> None:
    own = load_registry(desc)
    with pytest.raises(ZeroError, match="floating-point number but P-AXIS-09999 is SGN32"):
        convert(YAML, "yaml", "lis", own, "t.yaml", check=False)
    # the built-in table does not know the key: the value is carried as written
    assert b"kenngr.zero_test_count" in convert(YAML, "yaml", "lis", load_registry(), "t.yaml",
                                                check=False).output


@pytest.mark.slow
def test_param_desc_reaches_convert_on_the_command_line(desc: Path, tmp_path: Path) -> None:
    src = tmp_path / "t.yaml"
    src.write_bytes(YAML)
    run = subprocess.run([sys.executable, "-m", "zero", "--param-desc", str(desc), "convert", str(src), "--to", "lis"],
                         capture_output=True, text=True, check=False)
    assert run.returncode == 1, run.stderr
    assert "P-AXIS-09999 is SGN32" in run.stderr
    plain = subprocess.run([sys.executable, "-m", "zero", "convert", str(src), "--to", "lis"],
                           capture_output=True, text=True, check=False)
    assert plain.returncode == 0, plain.stderr


@pytest.mark.slow
def test_severity_overrides_apply_to_structured_files(tmp_path: Path) -> None:
    """A YAML file that names its kind keeps the configuration's severity overrides."""
    (tmp_path / "pyproject.toml").write_text('[tool.zero]\n[tool.zero.severity]\nR005 = "warning"\n')
    (tmp_path / "a.yaml").write_text("kenngr.swe_behaviour: WARN\n_zero:\n  kind: AXIS\n")
    run = subprocess.run([sys.executable, "-m", "zero", "lint", "a.yaml"], cwd=tmp_path,
                         capture_output=True, text=True, check=False)
    assert "R005 warning" in run.stdout
    assert run.returncode == 0

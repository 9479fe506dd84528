"""The resolver answers "which code page" too: `Project.encoding` and `Project.options` give the
codec the configuration declares, and a machine is read again when that changes (issue 24)."""

from __future__ import annotations

import shutil
from pathlib import Path

import zero.engine.config as config
import zero.engine.config_file as config_file
from conftest import FIXTURES, builtin_registry
from zero.engine.project import Project


def test_the_declared_codec_reaches_options_and_the_machine(tmp_path: Path) -> None:
    root = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine-clean", root)
    axis = root / "listen" / "achse_x.lis"
    axis.write_bytes(axis.read_bytes().replace(b"# axis list X_Achse", b"# Achse f\x81r X"))
    project = Project(lambda _desc: builtin_registry())
    assert project.encoding(axis) is None and project.options(axis).encoding is None
    machine = project.machine(axis, startup=root / "listen" / "hochlauf.lis")
    assert machine is not None
    assert next(lf.values.doc for lf in machine.lists if lf.path == axis).encoding == "latin-1"

    (root / "zero.toml").write_text('encoding = {"listen/achse_*.lis" = "CP850"}\n')
    project.forget()  # the configuration changed (the language server says so): asked again
    assert project.encoding(axis) == "cp850" and project.options(axis).encoding == "cp850"
    assert project.encoding(root / "listen" / "kanal.lis") is None
    assert project.encoding(None) is None  # standard input without a name
    again = project.machine(axis, startup=root / "listen" / "hochlauf.lis")
    assert again is not None and again is not machine
    doc = next(lf.values.doc for lf in again.lists if lf.path == axis)
    assert (doc.encoding, doc.lines[0]) == ("cp850", "# Achse für X")
    assert project.machine(axis, startup=root / "listen" / "hochlauf.lis") is again  # cached


def test_the_configuration_modules_example_declares_a_code_page(tmp_path: Path) -> None:
    """The example in zero.engine.config_file's documentation (the options' declarations) reads, `encoding`
    among its keys."""
    doc = config_file.__doc__ or ""
    example = doc.split("```toml\n", 1)[1].split("```", 1)[0]
    (tmp_path / "pyproject.toml").write_text(example)
    cfg = config.parse_config(tmp_path / "pyproject.toml")
    assert cfg is not None and cfg.encoding == (("machines/old/**/*.lis", "cp850"),)
    assert cfg.encoding_for(tmp_path / "machines" / "old" / "a" / "x.lis") == "cp850"
    assert cfg.encoding_for(tmp_path / "machines" / "new" / "x.lis") is None

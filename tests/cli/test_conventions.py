"""Conventions through the real command line: discovery of NC programs, commands that need a
start-up list, the pre-commit hooks for every form zero reads."""

from __future__ import annotations

import shutil
from pathlib import Path

import yaml

from conftest import FIXTURES, ROOT, zero_cli


def test_a_folder_of_nc_programs_is_linted(tmp_path: Path) -> None:
    for program in (FIXTURES / "programs").glob("*.nc"):
        shutil.copy(program, tmp_path / program.name)
    run = zero_cli("lint", "--output-format", "concise", str(tmp_path))
    assert run.code == 1, run
    assert "bad.nc:" in run.stdout and "N001" in run.stdout
    empty = tmp_path / "empty"
    empty.mkdir()
    run = zero_cli("lint", str(empty))
    assert run.code == 2 and "no list files or NC programs found" in run.stderr


def test_a_machine_command_refuses_a_list_that_is_not_a_start_up_list() -> None:
    zero_list = FIXTURES / "machine" / "listen" / "nullp.lis"
    for command in (["limits", "--machine"], ["lint", "--machine"], ["show", "--machine"]):
        run = zero_cli(*command, str(zero_list))
        assert run.code == 2, (command, run)
        assert "not a start-up list: it reads as a zero-offset list" in run.stderr


def test_pre_commit_hooks_cover_lists_programs_and_structured_forms() -> None:
    hooks = {h["id"]: h for h in yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())}
    assert set(hooks) == {"zero-lint", "zero-lint-structured", "zero-format"}
    import re

    assert re.search(hooks["zero-lint"]["files"], "listen/achsmds1.lis")
    assert re.search(hooks["zero-lint"]["files"], "prog/part.nc")
    assert re.search(hooks["zero-lint-structured"]["files"], "machines/nullp.yaml")
    assert re.search(hooks["zero-lint-structured"]["exclude"], ".pre-commit-config.yaml")


def test_param_desc_after_the_command_as_before_it(corpus: Path) -> None:
    xml = str(corpus / "isg-sdk" / "meta-data" / "CncParaDesc.xml")
    before = zero_cli("--param-desc", xml, "param", "kenngr.antr_typ")
    after = zero_cli("param", "kenngr.antr_typ", "--param-desc", xml)
    assert before.code == after.code == 0 and before.stdout == after.stdout
    from zero.catalog.registry import load_registry

    label = load_registry(xml).get("P-AXIS-00020").enum_labels[0]  # type: ignore[union-attr]
    assert f"1 {label}" in after.stdout  # the meaning read from the user's file, not from zero
    lean = zero_cli("lint", "--param-desc", "/no/such.xml", str(FIXTURES / "seed"))
    assert lean.code == 2 and "cannot read parameter description /no/such.xml" in lean.stderr


def test_severity_accepts_prefixes(tmp_path: Path) -> None:
    (tmp_path / "zero.toml").write_text('[severity]\nM = "error"\nM003 = "warning"\n')
    shutil.copy(FIXTURES / "seed" / "nullp_3achsen.lis", tmp_path / "n.lis")
    run = zero_cli("lint", "--output-format", "concise", str(tmp_path / "n.lis"))
    assert "M003 warning" in run.stdout  # the longer prefix (the full code) wins

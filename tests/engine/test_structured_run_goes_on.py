"""A YAML/TOML/JSON file that is no list form is skipped with a note, one that does not read is
one S017 finding, and the run goes on with the other files (as ruff's does); the structured
hook's default pattern leaves out the files the README tells users to create."""

from __future__ import annotations

import json
import re
from pathlib import Path

import yaml

from conftest import FIXTURES, ROOT, zero_cli
from zero.catalog.registry import Registry
from zero.engine.lint import lint_data, list_form
from zero.structured.formats import read_tree

NOT_FORMS = {
    "package.json": '{"name": "plant", "version": "1.0.0", "scripts": {"test": "x"}}\n',
    ".vscode/settings.json": '{"files.associations": {"*.lis": "isg-list"}, "editor.formatOnSave": true}\n',
    ".zero/zero.schema.json": '{"$schema": "https://json-schema.org/draft/2020-12/schema", "type": "object"}\n',
    ".taplo.toml": 'include = ["**/*.toml"]\n[[rule]]\ninclude = ["machines/**/*.toml"]\n',
    ".github/workflows/zero.yml": "name: zero\non: push\njobs:\n  lint:\n    runs-on: ubuntu-latest\n",
}


def test_files_that_are_no_list_form_are_skipped_with_a_note_or_one_finding(registry: Registry) -> None:
    """What reads but is no list form is skipped with a note; what does not even read as keys
    (`runs-on`, an array) is one S017 finding: never a stop, never one finding per key."""
    skipped = {"package.json"}
    for name, text in NOT_FORMS.items():
        result = lint_data(text.encode(), name, registry)
        if name in skipped:
            assert result.diagnostics == [] and result.note is not None and "skipped" in result.note, name
        else:
            assert [d.code for d in result.diagnostics] == ["S017"] and result.note is None, name


def test_a_hand_written_form_with_a_typo_is_still_a_list_form(registry: Registry) -> None:
    text = b"kopf:\n  achs_nr: 1\nkenngr:\n  swe_pos: 5\nkengr:\n  swe_neg: -5\n"
    assert list_form(read_tree(text, "yaml", registry), registry) is True
    assert [d.code for d in lint_data(text, "axis.yaml", registry).diagnostics] == ["R001"]


def test_one_bad_form_does_not_stop_the_run(tmp_path: Path) -> None:
    """Old main: `zero lint` exited 2 at the first structured file it could not read, with no
    finding for the others and an empty SARIF log."""
    for name, text in NOT_FORMS.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    (tmp_path / "broken.yaml").write_bytes((FIXTURES / "rules" / "S017" / "fail.yaml").read_bytes())
    (tmp_path / "bad.lis").write_bytes((FIXTURES / "rules" / "R005" / "fail.lis").read_bytes())
    names = [*NOT_FORMS, "broken.yaml", "bad.lis"]
    run = zero_cli("lint", "--isolated", "--output-format", "sarif", *names, cwd=tmp_path)
    assert run.code == 1, run.stderr
    results = json.loads(run.stdout)["runs"][0]["results"]
    assert {r["ruleId"] for r in results} == {"S017", "R005"}
    refused = {r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
               for r in results if r["ruleId"] == "S017"}
    assert refused == {"broken.yaml", *NOT_FORMS} - {"package.json"}


def test_the_structured_hook_leaves_out_what_is_no_list_form() -> None:
    """pre-commit matches `files` and `exclude` with Python's re.search on the repository path."""
    hooks = {h["id"]: h for h in yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())}
    hook = hooks["zero-lint-structured"]

    def picked(path: str) -> bool:
        return re.search(hook["files"], path) is not None and re.search(hook["exclude"], path) is None

    for name in (*NOT_FORMS, "pyproject.toml", "zero.toml", ".pre-commit-config.yaml", "sub/package.json",
                 ".gitlab-ci.yml", "schemas/axis.schema.json"):
        assert not picked(name), name
    for name in ("machines/m1/achse_x.yaml", "nullp.toml", "lists/kanal.json", "config/axis.yml"):
        assert picked(name), name


def test_the_note_of_a_skipped_file_is_said_on_stderr(tmp_path: Path) -> None:
    (tmp_path / "package.json").write_text(NOT_FORMS["package.json"])
    (tmp_path / "good.lis").write_bytes((FIXTURES / "rules" / "M006" / "pass.lis").read_bytes())
    run = zero_cli("lint", "--isolated", "package.json", "good.lis", cwd=tmp_path)
    assert run.code == 0
    assert "zero: package.json: not a JSON list form" in run.stderr and "skipped" in run.stderr
    quiet = zero_cli("lint", "--isolated", "-q", "package.json", "good.lis", cwd=tmp_path)
    assert quiet.code == 0 and "package.json" not in quiet.stderr

"""Each thing declared once (issue 39): configuration options, output formats, file suffixes, list
kinds and exit codes each have one home, and what is made from them (the parser, ``zero config
--show``, the docs page, the JSON Schema, the command line's choices) is held to it here."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path
from typing import Any

import jsonschema
import pytest

from conftest import ROOT
from zero.engine.config import BY_KEY, OPTIONS, config_schema, options_example, parse_config
from zero.errors import ZeroError

SRC = ROOT / "src" / "zero"


def _gen_config() -> Any:
    import importlib.util

    spec = importlib.util.spec_from_file_location("gen_config", ROOT / "tools" / "gen_config.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# ------------------------------------------------------------------------------ configuration


def test_the_docs_option_reference_is_generated_from_the_declaration() -> None:
    gen = _gen_config()
    page = (ROOT / "docs" / "configuration.md").read_text(encoding="utf-8")
    assert gen.BEGIN in page and gen.END in page
    assert page == gen.page_text(page), "run python tools/gen_config.py"
    for o in OPTIONS:  # every option has its entry
        assert f"#### `{o.key}`" in page


def test_the_shipped_schema_is_the_declaration_s() -> None:
    gen = _gen_config()
    assert (ROOT / "zero.schema.json").read_text(encoding="utf-8") == gen.schema_text(), \
        "run python tools/gen_config.py"
    assert set(config_schema()["$defs"]["zero"]["properties"]) == set(BY_KEY)


def _project(tmp_path: Path) -> Path:
    root = tmp_path / "p"
    (root / ".git").mkdir(parents=True)
    (root / "base.toml").write_text('ignore = ["M003"]\n')
    return root


def _example(o: Any) -> str:
    return f"[tool.zero]\n{o.example}\n" if not o.table else f"[tool.zero.{o.key}]\n{o.example}\n"


@pytest.mark.parametrize("key", list(BY_KEY))
def test_each_option_s_example_is_read_and_valid(tmp_path: Path, key: str) -> None:
    """An option's example is what the parser accepts and the schema admits."""
    o = BY_KEY[key]
    root = _project(tmp_path)
    text = _example(o).replace("../zero.toml", "base.toml")
    (root / "pyproject.toml").write_text(text)
    assert parse_config(root / "pyproject.toml") is not None
    jsonschema.validate(tomllib.loads(text)["tool"]["zero"], config_schema())
    (root / "zero.toml").write_text(text)  # a zero.toml written as pyproject.toml is: the same schema
    jsonschema.validate(tomllib.loads(text), config_schema())


def _docs_configurations() -> list[str]:
    """Every TOML block of the docs that configures zero (``[tool.zero]``)."""
    out = []
    for page in sorted((ROOT / "docs").rglob("*.md")):
        for block in re.findall(r"```toml\n(.*?)```", page.read_text(encoding="utf-8"), re.S):
            if block.lstrip().startswith("[tool.zero"):
                out.append(block)
    return out


def test_the_docs_configurations_and_the_schema_agree_with_the_parser(tmp_path: Path) -> None:
    blocks = _docs_configurations()
    assert len(blocks) > len(OPTIONS)
    assert "[tool.zero]\n" + options_example().split("\n", 1)[1] + "\n" in blocks
    root = _project(tmp_path)
    for block in blocks:
        (root / "pyproject.toml").write_text(block.replace("../zero.toml", "base.toml"))
        assert parse_config(root / "pyproject.toml") is not None, block
        jsonschema.validate(tomllib.loads(block)["tool"]["zero"], config_schema())


@pytest.mark.parametrize(("text", "words"), [
    ('ignroe = ["M003"]\n', "unknown key"),
    ('select = "R005"\n', "expected a list of rule codes"),
    ("respect-gitignore = 1\n", "expected true or false"),
    ('[tool.zero.severity]\nR005 = "fatal"\n', "'fatal' is not a severity"),
    ('[tool.zero.kind]\n"*.lis" = "lathe"\n', "'lathe' is not a list kind"),
    ('param-desc = ""\n', "expected the path of a CncParaDesc.xml"),
    ("[tool.zero.machine]\nstartup = 1\n", "expected a path"),
])
def test_what_the_parser_refuses_the_schema_refuses(tmp_path: Path, text: str, words: str) -> None:
    path = tmp_path / "pyproject.toml"
    path.write_text("[tool.zero]\n" + text)
    with pytest.raises(ZeroError, match=words):
        parse_config(path)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(tomllib.loads(path.read_text())["tool"]["zero"], config_schema())


def test_config_show_prints_every_option_it_holds_and_reads_back_the_same(tmp_path: Path) -> None:
    """``zero config --show`` is made from each option's declaration: what it prints is read back
    as the same configuration, every option included (extend-per-file-ignores was not shown)."""
    root = _project(tmp_path)
    (root / "zero.toml").write_text(options_example().replace("[tool.zero.", "[").replace("[tool.zero]\n", ""))
    first = parse_config(root / "zero.toml")
    assert first is not None and first.extend_per_file_ignores
    shown = first.show()
    (root / "again.toml").write_text(shown)
    again = parse_config(root / "again.toml")
    assert again is not None
    keep = ("select", "extend_select", "ignore", "per_file_ignores", "extend_per_file_ignores", "severity", "kind",
            "encoding", "include", "exclude", "extend_exclude", "respect_gitignore", "param_desc", "kernel",
            "machine", "machine_lists", "machine_workdir", "machine_roots")
    assert {k: getattr(again, k) for k in keep} == {k: getattr(first, k) for k in keep}
    assert 'extend-per-file-ignores]\n"machines/old/**" = ["R"]' in shown


def test_every_option_is_declared_with_its_parts() -> None:
    sections = {o.section for o in OPTIONS}
    assert sections == {"rules", "files", "machine", "general"}
    for o in OPTIONS:
        assert o.description.strip() and o.type and o.example and o.schema, o.key
    assert not re.search(r'key == "|elif key ==', (SRC / "engine" / "config.py").read_text(encoding="utf-8"))


def test_the_schema_is_json() -> None:
    json.loads((ROOT / "zero.schema.json").read_text(encoding="utf-8"))

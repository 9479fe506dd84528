"""Each thing declared once (issue 39): configuration options, output formats, file suffixes, list
kinds and exit codes each have one home, and what is made from them (the parser, ``zero config
--show``, the docs page, the JSON Schema, the command line's choices) is held to it here."""

from __future__ import annotations

import ast
import json
import re
import subprocess
import sys
import tomllib
from pathlib import Path
from typing import Any

import jsonschema  # type: ignore[import-untyped]
import pytest

from conftest import ROOT, script_module
from zero.engine.config import parse_config
from zero.engine.config_file import BY_KEY, OPTIONS, config_schema, options_example
from zero.errors import ZeroError

SRC = ROOT / "src" / "zero"


def _gen_config() -> Any:
    return script_module(ROOT / "tools" / "gen_config.py")


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


def test_zero_config_schema_prints_the_shipped_schema() -> None:
    from typer.testing import CliRunner

    from zero.cli.app import app

    result = CliRunner().invoke(app, ["config", "--schema"])
    assert result.exit_code == 0 and result.output == (ROOT / "zero.schema.json").read_text(encoding="utf-8")


def test_the_schema_is_json_and_a_valid_schema() -> None:
    jsonschema.Draft202012Validator.check_schema(json.loads((ROOT / "zero.schema.json").read_text(encoding="utf-8")))


# ------------------------------------------------------------------------------ output formats

FORMATS_PACKAGE = SRC / "output" / "formats"


def test_one_module_per_format_and_one_registry() -> None:
    from zero.cli.options import LINT_OPTIONS
    from zero.output import OUTPUT_FORMATS as REEXPORTED
    from zero.output.formats import FORMATS, OUTPUT_FORMATS, emitter, help_text

    modules = {p.stem for p in FORMATS_PACKAGE.glob("*.py")} - {"__init__", "common"}
    declared = {f.module for f in FORMATS.values() if f.module is not None}
    assert modules == declared  # every module is a format's, every format has its module
    for name, f in FORMATS.items():
        if f.module is not None:
            assert callable(emitter(name)), name
    option = next(o for o in LINT_OPTIONS if o.dest == "output_format")
    assert option.choices == OUTPUT_FORMATS == REEXPORTED == tuple(FORMATS)
    assert option.help == help_text()
    assert all(name in option.help for name in FORMATS)


def test_every_format_is_documented_for_its_consumers() -> None:
    """docs/ci.md says who reads each format: a format added to the registry needs its line there."""
    from zero.output.formats import FORMATS

    page = (ROOT / "docs" / "ci.md").read_text(encoding="utf-8")
    missing = [name for name in FORMATS if f"`{name}`" not in page and f"--output-format {name}" not in page]
    assert missing == []


_FORMAT_NAMES = {"concise", "grouped", "json-lines", "github", "gitlab", "azure", "junit", "sarif", "rdjson",
                 "pylint"}  # the names only zero lint's formats have (fleet and tables also say text and json)


def _format_lists(path: Path) -> list[int]:
    """The lines where a module lists two or more of zero lint's format names in one literal
    (tuple, list, set, or the keys of a dict)."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if not isinstance(node, (ast.Dict, ast.Tuple, ast.List, ast.Set)):
            continue
        items = node.keys if isinstance(node, ast.Dict) else node.elts
        names = {i.value for i in items if isinstance(i, ast.Constant) and isinstance(i.value, str)}
        if len(names & _FORMAT_NAMES) >= 2:
            out.append(node.lineno)
    return out


def test_no_list_of_output_formats_outside_the_registry() -> None:
    wrong = [f"{p.relative_to(SRC)}:{line}" for p in sorted(SRC.rglob("*.py"))
             if p != FORMATS_PACKAGE / "__init__.py" for line in _format_lists(p)]
    assert wrong == []


def test_the_format_list_check_sees_a_list(tmp_path: Path) -> None:
    bad = tmp_path / "bad.py"
    bad.write_text('STREAMED = {"json": 1, "concise": 2, "github": 3}\nFORMATS = ("text", "sarif", "junit")\n')
    assert _format_lists(bad) == [1, 2]


def _emitters_loaded(output_format: str) -> list[str]:
    """The modules of zero.output.formats a `zero lint` run in ``output_format`` imports."""
    code = ("import sys\nfrom zero.cli.run import lint\n"
            f"lint([{str(ROOT / 'fixtures' / 'seed' / 'nullp_3achsen.lis')!r}], output_format={output_format!r}, "
            "quiet=True)\n"
            "sys.stderr.write(' '.join(sorted(m for m in sys.modules if m.startswith('zero.output.formats'))))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False, cwd=ROOT)
    return run.stderr.split()


@pytest.mark.slow
def test_the_text_report_imports_no_emitter_and_a_format_only_its_own() -> None:
    assert _emitters_loaded("text") == ["zero.output.formats"]
    assert _emitters_loaded("sarif") == ["zero.output.formats", "zero.output.formats.common",
                                         "zero.output.formats.sarif"]


# ------------------------------------------------------------------------------ file suffixes

FORMS = SRC / "forms.py"
SUFFIXES = {".lis", ".lst", ".nc", ".mpf", ".spf", ".xml", ".yaml", ".yml", ".toml", ".json", ".tsproj", ".xti"}


def _suffix_literals(path: Path) -> list[str]:
    """A file suffix written as a literal (``".lis"``, ``"*.xml"``, the ``.nc`` of ``f"{name}.nc"``),
    docstrings aside: only zero.forms knows the suffixes."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docs = {id(n.value) for n in ast.walk(tree) if isinstance(n, ast.Expr) and isinstance(n.value, ast.Constant)}
    out = []
    for n in ast.walk(tree):
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docs:
            text = n.value.lower()
            if text in SUFFIXES or text.removeprefix("*") in SUFFIXES or (
                    text.startswith("-") and text[text.find("."):] in SUFFIXES and len(text) < 12):
                out.append(f"{n.lineno}: {n.value!r}")
    return out


def test_file_suffixes_are_written_only_in_forms() -> None:
    wrong = [f"{p.relative_to(SRC)}:{hit}" for p in sorted(SRC.rglob("*.py")) if p != FORMS
             for hit in _suffix_literals(p)]
    assert wrong == []
    assert _suffix_literals(FORMS)  # the check reads literals at all


def test_the_suffix_check_sees_a_suffix(tmp_path: Path) -> None:
    bad = tmp_path / "bad.py"
    bad.write_text('"""A list (.lis)."""\nX = (".lis", "*.xml")\ny = name.endswith(".xti")\nz = f"{n}.nc"\n'
                   'names = ("hochlauf.lis", "CncParaDesc.xml")\n')
    assert _suffix_literals(bad) == ["2: '.lis'", "2: '*.xml'", "3: '.xti'", "4: '.nc'"]


# ------------------------------------------------------------------------------ list kinds

def test_a_document_s_list_kind_is_told_in_one_place() -> None:
    """Declared by the document, else detected from its keys: Registry.kind_of, nowhere else
    (it was written out four times)."""
    wrong = [f"{p.relative_to(SRC)}" for p in sorted(SRC.rglob("*.py")) if p != SRC / "catalog" / "registry.py"
             and re.search(r"declared_kind\(\) or \w+\.detect_kind", p.read_text(encoding="utf-8"))]
    assert wrong == []
    callers = sorted(str(p.relative_to(SRC)) for p in SRC.rglob("*.py") if "detect_kind(" in p.read_text("utf-8"))
    assert callers == ["catalog/registry.py", "server/completion.py"]  # completion: by the name alone


def test_a_list_kind_by_name_is_parsed_in_one_place() -> None:
    """`zero`, `ZERO`, `Axis`: zero.catalog.registry.kind_from_name; the lists of kind names for
    messages come from KINDS."""
    from zero.catalog.registry import KINDS, kind_from_name
    from zero.cli.run import check_kind
    from zero.engine.commands import parse_kind

    assert all(kind_from_name(name) == code and kind_from_name(code.lower()) == code
               for code, (name, _) in KINDS.items())
    messages = []
    for check in (parse_kind, check_kind):  # the engine and the command line refuse a kind alike
        with pytest.raises(ZeroError) as caught:
            check("axsi")
        messages.append(str(caught.value))
    assert messages[0] == messages[1] and "did you mean axis?" in messages[0]


def test_a_list_kind_by_file_name_is_told_in_forms() -> None:
    from zero.forms import kind_hint

    assert (kind_hint("listen/nullp_d1.lis"), kind_hint("achskw1.lis"), kind_hint("ACHSMDS2.LIS"),
            kind_hint("x.lis")) == ("ZERO", "COMP", "AXIS", None)
    assert "_FILE_HINTS" not in (SRC / "catalog" / "registry.py").read_text(encoding="utf-8")


# ------------------------------------------------------------------------------ exit codes

EXITS = SRC / "cli" / "exits.py"
# The language server's exit code is the protocol's (1 after `exit` without `shutdown`), and the
# server may not import the command line.
EXIT_ALLOWED = {"server/lsp.py"}
_EXIT_NAMES = {"OK", "FOUND", "FINDINGS", "USAGE", "UNREAD", "INTERRUPTED", "BROKEN_PIPE"}


def _exit_literals(path: Path, in_cli: bool) -> list[int]:
    """Lines where an exit code is written as a number: ``SystemExit(1)``, ``sys.exit(2)``,
    ``typer.Exit(code=1)``, ``os._exit(0)``, a constant named like an exit code, and in the command
    line a ``return 1`` / ``code = 1`` (zero.cli.exits names them all)."""
    out = []

    def number(node: ast.AST | None) -> bool:
        if isinstance(node, ast.IfExp):
            return number(node.body) or number(node.orelse)
        return isinstance(node, ast.Constant) and type(node.value) is int

    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call):
            name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            if name in ("SystemExit", "exit", "_exit", "Exit") and (
                    any(number(a) for a in node.args) or any(number(k.value) for k in node.keywords)):
                out.append(node.lineno)
        elif isinstance(node, ast.Assign):
            names = [t.id for t in node.targets if isinstance(t, ast.Name)] + [
                e.id for t in node.targets if isinstance(t, ast.Tuple) for e in t.elts if isinstance(e, ast.Name)]
            values = node.value.elts if isinstance(node.value, ast.Tuple) else [node.value]
            if any(number(v) for v in values) and (set(names) & _EXIT_NAMES or (in_cli and "code" in names)):
                out.append(node.lineno)
        elif isinstance(node, ast.Return) and in_cli and number(node.value):
            out.append(node.lineno)
    return sorted(out)


def test_exit_codes_are_numbers_only_in_exits() -> None:
    wrong = [f"{p.relative_to(SRC)}:{line}" for p in sorted(SRC.rglob("*.py"))
             if p != EXITS and str(p.relative_to(SRC)) not in EXIT_ALLOWED
             for line in _exit_literals(p, p.parent.name == "cli")]
    assert wrong == []
    assert _exit_literals(EXITS, True)  # the check reads the home's numbers


def test_the_exit_code_check_sees_a_number(tmp_path: Path) -> None:
    bad = tmp_path / "bad.py"
    bad.write_text("OK, FOUND, UNREAD = 0, 1, 2\nraise SystemExit(1)\ndef f() -> int:\n    return 0 if x else 1\n"
                   "code = 1\nraise typer.Exit(code=2)\nn = 3\n")
    assert _exit_literals(bad, True) == [1, 2, 4, 5, 6]
    assert _exit_literals(bad, False) == [1, 2, 6]

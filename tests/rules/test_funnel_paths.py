"""One reporting path (issue 39, part C): every finding, of every family and from every caller,
reaches the report through :func:`zero.rules.funnel.funnel`: selection (per-file ignores
included), severity, one root cause, and the ``noqa`` / ``zero: ignore`` directives, decided once.

Each caller is asked the same questions: is a code the run ignores gone, does the run's severity
for a code replace the evidence's, does a per-file ignore of a prefix drop a code that was selected
by its full code (as ruff: whatever selected it), and does a directive written in the file hide
it. Inputs are written here (the machine fixtures are the project's own)."""

from __future__ import annotations

import ast
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT
from zero.catalog.registry import Registry
from zero.diagnostics import Severity
from zero.engine.convert import convert
from zero.engine.lint import (
    LintOptions,
    LintResult,
    layered_selection,
    lint_data,
    lint_file,
    lint_machine,
    lint_program,
    lint_update_in_machine,
)
from zero.machine.model import load_machine

SWE_CHECK = "P-AXIS-00705"  # kenngr.swe_check: -1, 0 or 1 (R005 for 5)
AXIS = b"kopf.achs_nr 1\nkenngr.swe_check 5%s\n"
PROGRAM = b"%%p\nN10 #MACHINE DATA [AX=X P-AXIS-00209=80000 WAIT]%s\nM30\n"

Lint = Callable[[Registry, LintOptions, bool], LintResult]  # registry, options, with a directive


def _list(reg: Registry, o: LintOptions, noqa: bool) -> LintResult:
    return lint_data(AXIS % (b"  ( noqa: R005 )" if noqa else b""), "achsmds1.lis", reg, o)


def _xml(reg: Registry, o: LintOptions, noqa: bool) -> LintResult:
    note = b"  <!-- noqa: R005 -->" if noqa else b""
    data = (b'<?xml version="1.0" encoding="utf-8"?>\n<AX_MDS>\n  <P-AXIS-00016 Value="1" />\n'
            b'  <%s Value="5" />%s\n</AX_MDS>\n' % (SWE_CHECK.encode(), note))
    return lint_data(data, "achsmds1.xml", reg, o)


def _yaml(reg: Registry, o: LintOptions, noqa: bool) -> LintResult:
    data = convert(AXIS % b"", "lis", "yaml", reg, "achsmds1.lis").output
    if noqa:
        data = data.replace(b"swe_check: 5", b"swe_check: 5  # ( noqa: R005 )")
    return lint_data(data, "achsmds1.yaml", reg, o)


def _program(reg: Registry, o: LintOptions, noqa: bool) -> LintResult:
    return lint_program(PROGRAM % (b" ( noqa: N001 )" if noqa else b""), reg, "p.nc", o)


def _unreadable(reg: Registry, o: LintOptions, noqa: bool) -> LintResult:
    return lint_file("/nonexistent/zero/achsmds1.lis", reg, o)


def _refused(reg: Registry, o: LintOptions, noqa: bool) -> LintResult:
    return lint_data(b"<?xml version='1.0'?>\n<AX_MDS><P-AXIS-00016 Value='1'>\n", "achsmds1.xml", reg, o)


CALLERS: list[tuple[str, Lint, str, bool]] = [  # name, lint, the code it finds, a directive can be written
    ("list", _list, "R005", True),
    ("xml", _xml, "R005", True),
    ("yaml", _yaml, "R005", True),
    ("program", _program, "N001", True),
    ("unreadable", _unreadable, "F001", False),
    ("refused", _refused, "S014", False),
]


def _codes(r: LintResult) -> list[str]:
    return [d.code for d in r.diagnostics]


@pytest.mark.parametrize(("name", "lint", "code", "noqa"), CALLERS, ids=[c[0] for c in CALLERS])
def test_every_caller_takes_the_one_funnel(registry: Registry, name: str, lint: Lint, code: str, noqa: bool) -> None:
    plain = lint(registry, LintOptions(), False)
    assert code in _codes(plain), plain.diagnostics
    assert code not in _codes(lint(registry, LintOptions(ignore=(code,)), False))
    info = LintOptions(severity={code: Severity.INFO})
    graded = [d for d in lint(registry, info, False).diagnostics if d.code == code]
    assert graded and all(d.severity is Severity.INFO for d in graded)
    # a per-file ignore of the prefix drops the code the run selected by its full code
    assert code in _codes(lint(registry, layered_selection([((code,), (), ())]), False))
    assert code not in _codes(lint(registry, layered_selection([((code,), (), ())], (code[0],)), False))
    if noqa:
        hidden = lint(registry, LintOptions(), True)
        assert code not in _codes(hidden) and "Z001" not in _codes(hidden), hidden.diagnostics
        assert code in _codes(lint(registry, LintOptions(ignore_noqa=True), True))


def _machine(tmp_path: Path, noqa: bool) -> Path:
    root = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine", root)
    if noqa:  # X001 on nullp.lis line 9 (G55 outside the soft limits): suppressed in that list
        nullp = root / "listen" / "nullp.lis"
        lines = nullp.read_text(encoding="latin-1").split("\n")
        lines[8] += "  ( noqa: X001 )"
        nullp.write_text("\n".join(lines), encoding="latin-1")
    return root / "listen" / "hochlauf.lis"


def _x001(registry: Registry, startup: Path, options: LintOptions) -> list[Severity]:
    m = load_machine(startup, registry)
    return [d.severity for r in lint_machine(m, registry, options) for d in r.diagnostics
            if d.code == "X001" and r.path.endswith("nullp.lis") and d.span.line == 9]


def test_machine_findings_take_the_funnel_of_the_list_they_land_in(tmp_path: Path, registry: Registry) -> None:
    startup = _machine(tmp_path, False)
    assert _x001(registry, startup, LintOptions()) == [Severity.WARNING]
    assert _x001(registry, startup, LintOptions(ignore=("X001",))) == []
    assert _x001(registry, startup, LintOptions(severity={"X001": Severity.ERROR})) == [Severity.ERROR]
    assert _x001(registry, startup, layered_selection([(("X001",), (), ())], ("X",))) == []
    assert _x001(registry, _machine(tmp_path / "q", True), LintOptions()) == []


def _update(tmp_path: Path, note: str) -> tuple[Path, Path]:
    root = tmp_path / "machine"
    shutil.copytree(FIXTURES / "twincat" / "machine", root)
    (root / "Update").mkdir()
    update = root / "Update" / "limit-Update.xml"
    update.write_text('<?xml version="1.0" encoding="utf-8"?>\n<AX_MDS>\n    <P-AXIS-00016 Value="1" />\n'
                      f'    <P-AXIS-00178 Value="-99000000" />{note}\n</AX_MDS>\n')
    return root / "startup" / "hochlauf.lis", update


def test_an_update_checked_in_its_machine_takes_its_own_suppressions(tmp_path: Path, registry: Registry) -> None:
    """The findings an update gets among the values of the list it changes (M001 here) were funnelled
    without the update's directives: a `noqa: M001` written in the update did not hide them, and the
    directive was reported as hiding nothing (Z001)."""
    startup, update = _update(tmp_path, "")
    m = load_machine(startup, registry)
    found = lint_update_in_machine(str(update), update.read_bytes(), m, registry, LintOptions())
    assert found is not None and _codes(found) == ["M001"]
    assert found.diagnostics[0].span.line == 4  # on the update's own line
    startup, update = _update(tmp_path / "q", "  <!-- noqa: M001 -->")
    m = load_machine(startup, registry)
    hidden = lint_update_in_machine(str(update), update.read_bytes(), m, registry, LintOptions())
    assert hidden is not None and _codes(hidden) == [], hidden.diagnostics
    shown = lint_update_in_machine(str(update), update.read_bytes(), m, registry, LintOptions(ignore_noqa=True))
    assert shown is not None and _codes(shown) == ["M001"]


def test_the_command_line_and_the_configuration_agree(tmp_path: Path) -> None:
    """`select = ["R005"]` with `"old/*.lis" = ["R"]` in per-file-ignores: nothing of R in old/, R005 in
    new/, whether a list is linted alone, in a folder or as part of its machine (a real process)."""
    (tmp_path / "zero.toml").write_text('select = ["R005", "X"]\n[per-file-ignores]\n"old/*.lis" = ["R"]\n')
    for folder in ("old", "new"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "achsmds1.lis").write_bytes(AXIS % b"")
    (tmp_path / "hochlauf.lis").write_text("konfiguration EIN_KANAL_KONFIGURIERUNG\nkanal_anzahl 1\nzahl_mds 2\n"
                                           "achs_mds[0] ./old/achsmds1.lis\nachs_mds[1] ./new/achsmds1.lis\nEnde\n")

    def run(*args: str) -> list[str]:
        p = subprocess.run([sys.executable, "-m", "zero", "lint", "--output-format", "concise", *args],
                           cwd=tmp_path, capture_output=True, text=True, timeout=120, check=False)
        assert "Traceback" not in p.stderr, p.stderr
        return [line.split(" ")[0:2] for line in p.stdout.splitlines() if " R" in line]

    assert run("old", "new") == [["new/achsmds1.lis:2:18:", "R005"]]
    assert run("--machine", "hochlauf.lis") == [["new/achsmds1.lis:2:18:", "R005"]]


def test_the_decision_lives_in_the_funnel_alone() -> None:
    """Only the funnel applies suppressions; no caller (engine, server, output, command line) selects
    findings by the run's selection itself (a check may skip work for unselected codes: ``Check.wanted``)."""
    src = ROOT / "src" / "zero"
    for path in src.rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        rel = path.relative_to(src).as_posix()
        if rel not in ("rules/funnel.py", "rules/suppress.py"):
            assert "apply_directives(" not in text, rel
        if rel.split("/")[0] not in ("engine", "server", "output", "cli"):
            continue  # a check may skip work for a code nobody selected (startup.py, registry.py)
        for node in ast.walk(ast.parse(text)):
            # `if d.code not in severities: continue`: a caller's own selection (the funnel's alone)
            if isinstance(node, ast.Compare) and any(isinstance(op, (ast.In, ast.NotIn)) for op in node.ops) \
                    and isinstance(node.left, ast.Attribute) and node.left.attr == "code":
                comparators = [ast.unparse(c) for c in node.comparators]
                assert not any("severities" in c or "selected" in c for c in comparators), (rel, node.lineno)


def test_the_language_server_takes_the_same_funnel(tmp_path: Path, registry: Registry) -> None:
    """The editor's findings are `zero lint`'s: the configuration's selection with its per-file ignore,
    its severity, and the list's own directives."""
    from zero.server.documents import Projects

    (tmp_path / "zero.toml").write_text('select = ["R005", "M"]\n[severity]\nR005 = "info"\n'
                                        '[per-file-ignores]\n"old/*.lis" = ["R"]\n')
    for folder in ("old", "new"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "achsmds1.lis").write_bytes(AXIS % b"")

    def found(folder: str, text: bytes) -> list[tuple[str, Severity]]:
        uri = (tmp_path / folder / "achsmds1.lis").as_uri()
        a = Projects(lambda _desc: registry).analyse(uri, 1, text.decode())
        assert a.result is not None
        return [(d.code, d.severity) for d in a.result.diagnostics]

    assert found("new", AXIS % b"") == [("R005", Severity.INFO)]
    assert found("old", AXIS % b"") == []
    assert found("new", AXIS % b"  ( noqa: R005 )") == []


def test_convert_checks_a_structured_form_with_its_configuration(tmp_path: Path) -> None:
    """`zero convert x.yaml --to lis` checked the list it makes with no configuration at all: it showed
    an R005 the file's configuration ignores (and `zero lint x.yaml` hides), and graded nothing as configured."""
    yaml = b"kopf:\n  achs_nr: 1\nkenngr:\n  swe_check: 5\n_zero:\n  zero: 1\n  kind: \"AXIS\"\n"
    (tmp_path / "achsmds1.yaml").write_bytes(yaml)

    def convert_shows(toml: str, out: str) -> str:
        (tmp_path / "zero.toml").write_text(toml)
        p = subprocess.run([sys.executable, "-m", "zero", "convert", "achsmds1.yaml", "--to", "lis", "-o", out],
                           cwd=tmp_path, capture_output=True, text=True, timeout=120, check=False)
        assert p.returncode == 0 and "Traceback" not in p.stderr, p.stderr
        return p.stdout + p.stderr

    assert "R005" in convert_shows("", "a.lis")
    assert "R005" not in convert_shows('ignore = ["R005"]\n', "b.lis")
    assert "R005" not in convert_shows('[per-file-ignores]\n"*.yaml" = ["R"]\n', "c.lis")
    assert "R005" not in convert_shows('[severity]\nR005 = "info"\n', "d.lis")  # convert shows warnings and errors

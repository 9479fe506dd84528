"""NC programs: #MACHINE DATA and G98/G99 against the machine (N rules)."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from conftest import FIXTURES, builtin_registry, golden
from zero.catalog.registry import Registry
from zero.cli.app import app
from zero.engine.lint import LintOptions, lint_program
from zero.machine.model import load_machine
from zero.nc.program import strip_comments

runner = CliRunner()
P = FIXTURES / "programs"
MACHINE = FIXTURES / "machine" / "listen" / "hochlauf.lis"
CLEAN_MACHINE = FIXTURES / "machine-clean" / "listen" / "hochlauf.lis"


def findings(path: Path, machine: Path | None) -> list[dict[str, object]]:
    registry = builtin_registry()
    m = load_machine(machine, registry) if machine else None
    result = lint_program(path.read_bytes(), registry, path.name, machine=m)
    return [{"line": d.span.line, "column": d.span.column, "code": d.code, "severity": d.severity.label}
            for d in result.diagnostics]


def test_bad_program_golden(request: pytest.FixtureRequest) -> None:
    actual = findings(P / "bad.nc", MACHINE)
    expected = golden(P / "bad.expected.json", actual, request.config.getoption("--update-golden"))
    assert actual == expected
    assert {f["code"] for f in actual} == {"N001", "N002", "N003", "N004"}


@pytest.mark.parametrize("machine", [None, MACHINE, CLEAN_MACHINE])
def test_good_program_has_no_fault_but_says_what_was_not_followed(machine: Path | None) -> None:
    # its cycle call is not followed (and without a machine no move is checked): one N010 info, never "clean"
    assert [(f["code"], f["severity"]) for f in findings(P / "good.nc", machine)] == [("N010", "info")]


def test_without_a_machine_only_syntax_and_order() -> None:
    assert {f["code"] for f in findings(P / "bad.nc", None)} == {"N001", "N002"}


def test_widening_is_fine_when_allowed() -> None:
    # the clean machine does not set range_check_prog_soft_limits: widening is allowed
    codes = [f["code"] for f in findings(P / "bad.nc", CLEAN_MACHINE)]
    assert "N003" not in codes and codes.count("N004") == 2


def test_comments_and_strings() -> None:
    assert strip_comments("N10 G98 X1 ( c G99 ) Y2 ; G99 X5") == "N10 G98 X1           Y2 "
    kept = 'N10 #MSG ["(not a comment) ; nor this"] '
    assert strip_comments(kept + "(but this") == kept + " " * len("(but this")


def test_cli_lints_programs_with_and_without_machine() -> None:
    r = runner.invoke(app, ["lint", str(P / "bad.nc"), "--output-format", "concise"])
    assert r.exit_code == 1 and "N001" in r.stdout and "N004" not in r.stdout
    r = runner.invoke(app, ["lint", "--machine", str(MACHINE), str(P / "bad.nc"), "--select", "N",
                            "--output-format", "concise"])
    assert r.exit_code == 1 and r.stdout.count("N004") == 2


def test_machine_data_axis_given_by_variable_or_expression_and_messages(registry: Registry) -> None:
    program = (b"N10 #MACHINE DATA [AXNR=V.P.NR P-AXIS-00209=80000]\n"
               b"N20 #MACHINE DATA [AXNR=[2+1] P-AXIS-00209=80000]\n"
               b"N30 #MACHINE DATA [AXNR=0 P-AXIS-00209=80000]\n"
               b"N40 #MACHINE DATA [AX=X P-AXIS-99999=1]\n")
    result = lint_program(program, registry, "p.nc")
    assert [(d.span.line, d.message) for d in result.diagnostics] == [
        (3, "#MACHINE DATA AXNR=0 is not a logical axis number (they start at 1); the controller does not "
            "check AXNR, so the block does not write the axis it is meant for"),
        (4, "#MACHINE DATA P-AXIS-99999 is not a parameter of the catalogue: the controller rejects the block"),
    ]


def test_suppressions_in_the_programs_own_comments(tmp_path: Path) -> None:
    """`( noqa: N003 )` and `; noqa` on a line, `( zero: ignore[N003] )` for the next line with
    code, `; zero: noqa: N003` for the program; unused ones are Z001, unreadable ones Z002 —
    as in a list, in the program's comment syntax."""
    body = ("N10 G99 X1600 ( noqa: N003 -- probing )\n"
            "N20 G98 X-1600 ; noqa\n"
            "( zero: ignore[N003] )\n"
            "( a comment line is skipped )\n"
            "N30 G99 X1700\n"
            "N40 G99 X1800 (noqa: R005)\n"
            "N50 G99 X1900 ( noqa R005 )\n"
            'N60 #MSG ["( noqa )"] G99 X2000\n')
    path = tmp_path / "p.nc"
    path.write_text(body)
    registry = builtin_registry()
    m = load_machine(MACHINE, registry)
    result = lint_program(path.read_bytes(), registry, path.name, LintOptions(extend_select=("Z",)), m)
    assert [(d.span.line, d.span.column, d.code) for d in result.diagnostics] == [
        (6, 9, "N003"), (6, 16, "Z001"),  # another code named: the finding stays, the directive is unused
        (7, 9, "N003"), (7, 17, "Z002"),  # `noqa R005` without the colon cannot be read
        (8, 27, "N003"),  # inside a string: no comment, no suppression
    ]
    path.write_text("; zero: noqa: N003\n" + body)
    result = lint_program(path.read_bytes(), registry, path.name, LintOptions(extend_select=("Z",)), m)
    assert [d.code for d in result.diagnostics if d.code == "N003"] == []

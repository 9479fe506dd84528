"""NC programs against the machine they run on (N005, N006), the language (N007-N009) and what
zero could not follow (N010): never "clean" for a program it did not evaluate."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from conftest import FIXTURES, builtin_registry
from zero.cli.app import app
from zero.diagnostics import Diagnostic
from zero.engine.lint import LintOptions, Totals, lint_program
from zero.machine.model import Machine, load_machine
from zero.nc.motion import AxisSetup, Setup, evaluate, follow
from zero.output.text import summary_line

runner = CliRunner()
P = FIXTURES / "programs"
MACHINE = P / "machine" / "listen" / "hochlauf.lis"


@pytest.fixture(scope="module")
def machine() -> Machine:
    return load_machine(MACHINE, builtin_registry())


def lint(path: Path, machine: Machine | None, select: tuple[str, ...] = ("N",)) -> list[Diagnostic]:
    return lint_program(path.read_bytes(), builtin_registry(), str(path), LintOptions(select=select),
                        machine).diagnostics


def codes(found: list[Diagnostic]) -> list[tuple[int, str]]:
    return [(d.span.line, d.code) for d in found]


def test_moves_inside_the_limits_give_no_finding(machine: Machine) -> None:
    """Every kind of move zero follows (G0-G3 with I/J/K and R, G91, G17/G18, G70, P-parameters,
    V.L variables, G54, G55 with a masked axis, G159=10, G53 without g53_verfuegbar, G98/G99 that
    narrow), each inside the limits: not a single finding, and every move was evaluated."""
    assert lint(P / "moves_inside.nc", machine) == []
    setup_lines = (P / "moves_inside.nc").read_text().splitlines()
    from zero.nc.program import read_program
    from zero.rules.base import ProgramContext
    from zero.rules.program import analysis  # the same analysis the checks use

    ctx = ProgramContext(read_program((P / "moves_inside.nc").read_bytes(), "m.nc", builtin_registry()),
                         builtin_registry(), machine, {}, str(P / "moves_inside.nc"))
    found, _ = analysis(ctx)
    assert found.moves == found.evaluated == 14 and found.skipped == {} and len(setup_lines) > 20


def test_each_kind_of_move_beyond_a_limit(machine: Machine) -> None:
    found = lint(P / "crossing.nc", machine)
    assert codes(found) == [
        (4, "N005"),  # G1 X510 in G54: 610 on the axis
        (6, "N005"),  # the arc passes X 550
        (10, "N005"),  # G91: the third relative step
        (11, "N005"),  # G70: 20 inch
        (14, "N005"),  # XP7
        (15, "N005"),  # G55
        (16, "N005"),  # G159=10
        (17, "N005"),  # G53 applies no offset
        (18, "N005"),  # Y: ERROR_LR
        (19, "N006"),  # Z: swe_check 0 (A400 on line 20: a modulo axis turns without end)
        (21, "N006"),  # B: swe_behaviour WARNING
        (23, "N006"),  # X[POS_LIMIT OFF]
        (26, "N005"),  # beyond the limit the program narrowed with G99
    ]
    by_line = {d.span.line: d for d in found}
    first = by_line[4]
    assert first.message == (
        "X goes to 510.000 mm in G54, 610.000 mm on the axis (offset 100.000 mm: G54 np_grp[1].achse[0].versch, "
        "nullp.lis:5), beyond the positive soft limit 600.000 mm (kenngr.swe_pos, achse_x.lis:6): the controller "
        "does not execute the block and aborts the program (P-ERR-120002 or P-ERR-120003)")
    assert first.kernel_error == "P-ERR-120002 or P-ERR-120003" and first.param_id == "P-AXIS-00178"
    assert (first.span.column, first.span.end_column) == (8, 12)  # the axis word X510
    assert first.related and first.related[0].span.line == 6 and str(first.related[0].path).endswith("achse_x.lis")
    assert by_line[6].message.startswith("the arc passes X 550.000 mm in G54, 650.000 mm on the axis")
    assert "G53 applies no offset (g53_verfuegbar 0)" in by_line[17].message
    assert "G159=10 np_grp[10].achse[0].versch, nullp.lis:11" in by_line[16].message
    assert "ERROR_LR" in by_line[18].message and "stops the axis" in by_line[18].message
    assert by_line[18].kernel_error is None
    assert "unchecked: `swe_check 0`" in by_line[19].message and by_line[19].severity.label == "warning"
    assert 20 not in by_line
    assert "only warns" in by_line[21].message
    assert "X[POS_LIMIT OFF] at line 22" in by_line[23].message
    assert "(programmed with G99 at line 25)" in by_line[26].message


def test_what_zero_cannot_follow_is_counted_and_said(machine: Machine) -> None:
    found = lint(P / "unsupported.nc", machine)
    assert codes(found) == [(7, "N010"), (25, "N009"), (27, "N005")]
    info = found[0]
    assert info.severity.label == "info"
    for said in ("6 of 13 moves not evaluated", "computed position (line 7 first)", "#TRAFO ON active from line 8",
                 "#CS ON active from line 11", "after L CYCLE SysDrill.ecy at line 14",
                 "inside the $WHILE loop from line 17", "after the jump target N200 at line 24",
                 "2 subprogram calls not followed into (L CYCLE SysDrill.ecy at line 14 first"):
        assert said in info.message, said
    # the called global subprogram is followed from its caller's state: its move is found at the call
    assert found[2].message.startswith("in L part.nc line 3: X goes to 550.000 mm in G54, 650.000 mm on the axis")


def test_the_language_words_structures_and_calls() -> None:
    found = lint(P / "language.nc", None)
    assert codes(found) == [(3, "N010"), (4, "N007"), (5, "N007"), (6, "N007"), (8, "N008"), (9, "N007"),
                            (10, "N008"), (11, "N009")]
    assert "1 subprogram call not followed into (LL NOWHERE at line 11 first" in found[0].message
    text = [d.message for d in found[1:]]
    assert text[0].startswith("`test` is no word of the ISG NC language")
    assert text[1].startswith("`$IFF` is no control keyword")
    assert text[2].startswith("`#FOO` is no #-command")
    assert text[3] == "$IF is not closed by $ENDIF at the end of the program"
    assert text[4].startswith("`....` is no word")
    assert text[5] == "$ENDWHILE without an open $WHILE"
    assert text[6] == "LL NOWHERE: no local subprogram `%L NOWHERE` in this file"
    assert all(d.severity.label != "error" for d in found)


def test_without_a_machine_no_move_is_called_checked() -> None:
    found = lint(P / "moves_inside.nc", None)
    assert codes(found) == [(5, "N010")]
    assert found[0].message.startswith("14 moves not checked against soft limits: no machine to check them against")


def test_constructs_of_the_language_are_read_without_a_finding() -> None:
    """What the vendor's own programs use (its VS Code extension's tests): %L parts, #VAR blocks,
    #COMMENT blocks, skipped blocks, labels and jumps, $SWITCH, multi-line cycle calls whose `]` is
    on a line of its own, address words without blanks, variables in axis words, spindle names."""
    found = lint(P / "constructs.nc", None)
    assert [d.code for d in found] == ["N010"]


def test_summary_never_counts_an_unevaluated_program_as_clean(machine: Machine, tmp_path: Path) -> None:
    totals = Totals()
    for name in ("moves_inside.nc", "unsupported.nc", "language.nc"):
        path = P / name
        totals.add(lint_program(path.read_bytes(), builtin_registry(), str(path), None, machine))
    assert totals.clean == 1 and totals.by_code["N010"] == 2
    assert summary_line(totals).startswith("3 files checked (1 clean, 2 not fully evaluated):")


def test_cli_with_machine_and_from_the_configuration(tmp_path: Path) -> None:
    r = runner.invoke(app, ["lint", "--machine", str(MACHINE), str(P / "crossing.nc"), "--select", "N",
                            "--output-format", "concise"])
    assert r.exit_code == 1 and r.stdout.count("N005") == 10 and r.stdout.count("N006") == 3
    root = tmp_path / "m"
    shutil.copytree(P / "machine", root / "machine")
    shutil.copy(P / "crossing.nc", root / "crossing.nc")
    (root / "zero.toml").write_text('[machine]\nstartup = "machine/listen/hochlauf.lis"\n')
    r = runner.invoke(app, ["lint", str(root / "crossing.nc"), "--select", "N", "--output-format", "concise"])
    assert r.exit_code == 1 and r.stdout.count("N005") == 10, r.stdout


def test_subprograms_in_the_machines_program_path(machine: Machine, tmp_path: Path) -> None:
    """`pfad[].prg[]` of the start-up list is searched too, names without case."""
    root = tmp_path / "m"
    shutil.copytree(P / "machine", root / "machine")
    (root / "machine" / "nc" / "library").mkdir(parents=True)
    (root / "machine" / "nc" / "library" / "Part.NC").write_text("%part\nN10 G90 X590\nM17\n")
    program = root / "main.nc"
    program.write_text("%main\nN10 G90 G54 X0\nN20 L part.nc\nN30 L gone.nc\nM30\n")
    m = load_machine(root / "machine" / "listen" / "hochlauf.lis", builtin_registry())
    found = lint(program, m)
    assert codes(found) == [(3, "N005"), (4, "N010"), (4, "N009")]
    assert found[0].message.startswith("in L part.nc line 2: X goes to 590.000 mm in G54, 690.000 mm")


@pytest.mark.parametrize(("text", "value"), [
    ("1 + 2 * 3", 7.0), ("[1 + 2] * 3", 9.0), ("-P1", -4.0), ("P1 / 2 - V.L.A", 1.0), ("SIN[90]", 1.0),
    ("2 ** 3", 8.0), ("SQRT[16] + ABS[-1]", 5.0), ("V.P.UNKNOWN", None), ("1 / 0", None), ("P1 > 2", None),
    ("V.L.ARR[1]", None), ("", None), ("[1 + 2", None),
])
def test_expressions(text: str, value: float | None) -> None:
    result = evaluate(text, {"P1": 4.0, "V.L.A": 1.0})
    assert (result is None and value is None) or (result is not None and value is not None
                                                   and math.isclose(result, value))


def test_follower_alone_branches_loops_and_arcs() -> None:
    setup = Setup([AxisSetup("X", -10, 10), AxisSetup("Y", -10, 10), AxisSetup("Z", -10, 10)])
    lines = ["G90 X0 Y0", "$IF V.L.A == 1", "X5", "$ELSE", "X6", "$ENDIF", "G91 X1",
             "G90 G2 X0 Y0 I5 J0",  # X's start is not known (after the $IF): no arc to compute
             "G3 X0 Y0 R-3"]  # a radius with the end on the start: no circle zero can compute
    found = follow(lines, setup)
    # after $IF/$ELSE, X is 5 or 6: the relative move is not evaluated
    assert found.skipped["after the $IF from line 2 (the path depends on data)"] == [1, 7]
    assert found.crossings == []
    assert found.skipped["arc whose extent zero cannot compute"] == [2, 8]
    found = follow(["G90 X0 Y0", "G2 X0 Y0 I5.5 J0"], setup)  # the full circle reaches X 11
    assert [(c.line, c.arc, c.machine) for c in found.crossings] == [(2, True, 11.0)]


NC_ALPHABET = "GXYZABIJKRNLPVF0123456789.-+=[]()$#%;:/\\\"@ \tÜß…\n" + "IFELSEENDWHILECYCLETRAFOONOFF"


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.text(alphabet=NC_ALPHABET, max_size=200))
def test_any_text_is_read_without_an_exception(text: str) -> None:
    """Hostile or broken programs: a finding at most, never a traceback (a letter outside A-Z
    once stopped the reader)."""
    setup = Setup([AxisSetup("X", -10, 10), AxisSetup("Y", -10, 10), AxisSetup("Z", -10, 10)],
                  {1: (1.0, 2.0, 3.0)}, 1)
    lines = text.split("\n")
    for s in (setup, None):
        found = follow(lines, s)
        assert found.evaluated <= found.moves


def test_the_editor_shows_the_findings_live(tmp_path: Path) -> None:
    """The language server lints a program as `zero lint` does, against the machine of its
    configuration, on the unsaved text: a move beyond the limit appears and goes as it is typed."""
    from zero.server.documents import Projects

    root = tmp_path / "m"
    shutil.copytree(P / "machine", root / "machine")
    (root / "zero.toml").write_text('[machine]\nstartup = "machine/listen/hochlauf.lis"\n')
    path = root / "part.nc"
    path.write_text("%part\nN10 G90 G54 X0\n")
    projects = Projects(lambda desc: builtin_registry())
    uri = path.resolve().as_uri()
    a = projects.analyse(uri, 1, "%part\nN10 G90 G54 X0\nN20 G1 X510\n")
    assert [(d.span.line, d.code) for d in a.diagnostics] == [(3, "N005")]
    assert "610.000 mm on the axis" in a.diagnostics[0].message
    a = projects.analyse(uri, 2, "%part\nN10 G90 G54 X0\nN20 G1 X490\n")
    assert a.diagnostics == []


def test_the_report_draws_a_programs_travel_in_the_axis_pictures(tmp_path: Path) -> None:
    """`zero report --program`: the lowest and highest position the program reaches on each axis,
    marked where it passes a soft limit."""
    pytest.importorskip("jinja2")
    out = tmp_path / "m.html"
    r = runner.invoke(app, ["report", "--machine", str(MACHINE), "--program", str(P / "crossing.nc"),
                            "--program", str(P / "moves_inside.nc"), "-o", str(out)])
    assert r.exit_code == 0, r.stdout
    page = out.read_text()
    assert page.count('class="travel beyond"') >= 2  # X and Y of crossing.nc
    assert 'data-program="crossing.nc" data-low="100" data-high="650"' in page  # X: G54 X0 .. the arc
    assert 'class="travel" x=' in page and 'data-program="moves_inside.nc"' in page

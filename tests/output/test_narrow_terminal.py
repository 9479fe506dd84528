"""`zero diff` and `zero limits` on a terminal of 60, 80 or 120 columns: no line wider than the
terminal, no value broken (issue 27: "(absent" / ")" in a diff cell, "PCS " / "-1000.0000 .. 1500.0000"
in the limits). A table where it fits at its natural width, else a record per row folded between
its values."""

from __future__ import annotations

import re

import pytest
from rich.cells import cell_len

from conftest import FIXTURES, zero_cli
from zero.output.tables import fold

ANSI = re.compile(r"\x1b\[[0-9;]*m")
COLUMNS = [60, 80, 120]

DIFFS = [
    ("diff/base.lis", "diff/changed.lis"),
    ("diff/values/axis-old.lis", "diff/values/axis-new.lis"),
    ("diff/values/chan-old.lis", "diff/values/chan-new.lis"),
    ("diff/values/comp-old.lis", "diff/values/comp-new.lis"),
]
MACHINES = ["machine-clean/listen/hochlauf.lis", "machine/listen/hochlauf.lis"]


def terminal(columns: int, *args: str) -> list[str]:
    """The lines `zero` prints on a terminal of ``columns`` (colours forced, then stripped)."""
    run = zero_cli(*args, env={"COLUMNS": str(columns), "FORCE_COLOR": "1", "NO_COLOR": ""})
    assert run.code in (0, 1), run.stderr
    return ANSI.sub("", run.stdout).split("\n")


def plain(*args: str) -> list[str]:
    """What `zero` prints into a pipe: every value on its row, in aligned text."""
    run = zero_cli(*args, env={"NO_COLOR": "1"})
    return run.stdout.split("\n")


def contains_run(stream: list[str], tokens: list[str]) -> bool:
    """Do ``tokens`` stand in ``stream`` one after the other?"""
    n = len(tokens)
    return any(stream[i: i + n] == tokens for i in range(len(stream) - n + 1))


def check(lines: list[str], rows: list[list[str]], columns: int, in_order: bool = True) -> None:
    """No line wider than the terminal; each token of each row whole (a record's commas aside), and
    ``in_order``, the row's tokens one after the other."""
    wide = [line for line in lines if cell_len(line) > columns]
    assert not wide, (columns, wide)
    assert "…" not in "\n".join(lines)
    tokens = [t.rstrip(",") for line in lines for t in line.split()]
    for row in rows:
        missing = [t for t in row if t not in tokens]
        assert not missing, (columns, row, missing)  # "(absent" is no "(absent)"
        assert not in_order or contains_run(tokens, row), (columns, row)


@pytest.mark.slow
@pytest.mark.parametrize("columns", COLUMNS)
@pytest.mark.parametrize(("old", "new"), DIFFS, ids=[d[1].rsplit("/", 1)[-1] for d in DIFFS])
def test_diff_fits_the_terminal_and_never_breaks_a_value(columns: int, old: str, new: str) -> None:
    args = ("diff", str(FIXTURES / old), str(FIXTURES / new))
    rows = [line.split() for line in plain(*args) if line.startswith("  ") and line.split()[0] in "~+-=#"]
    assert rows
    lines = terminal(columns, *args)
    check(lines, rows, columns)
    if columns == 80 and new == "diff/changed.lis":  # the cells of issue 27, each whole on one line
        text = "\n".join(lines)
        assert re.search(r"(?m)^.*400000 → \(absent\).*$", text)
        assert re.search(r"(?m)^.*\(absent\) → 12500.*$", text)


@pytest.mark.slow
@pytest.mark.parametrize("columns", COLUMNS)
@pytest.mark.parametrize("machine", MACHINES, ids=[m.split("/")[0] for m in MACHINES])
def test_limits_fit_the_terminal_and_never_break_a_range(columns: int, machine: str) -> None:
    args = ("limits", "--machine", str(FIXTURES / machine))
    out = plain(*args)
    rows = [line.split() for line in out[1:] if re.match(r"\d+\s+G\d+", line)]
    assert rows
    lines = terminal(columns, *args)
    if any("ACS min" in line for line in lines):  # the table: each row as the plain text has it
        check(lines, rows, columns)
    else:  # records: "ACS min .. max", "PCS min .. max" each whole on one line
        check(lines, [row[5:10] for row in rows], columns, in_order=False)  # ch, offset, axis (2), unit, the numbers
        for row in rows:
            acs, pcs = f"ACS {row[5]} .. {row[6]}", f"PCS {row[8]} .. {row[9]}"
            assert any(acs in line for line in lines) and any(pcs in line for line in lines), row
    if columns >= 80 and machine.startswith("machine-clean"):
        assert any("ACS min" in line for line in lines)  # 79 columns: a table at 80


def test_fold_moves_phrases_whole_and_never_splits_a_word() -> None:
    assert fold(["ACS -1000.0000 .. 1500.0000,", "offset 0.0000,", "PCS -1000.0000 .. 1500.0000"], 40,
                sep=" ") == ["ACS -1000.0000 .. 1500.0000,", "    offset 0.0000,", "    PCS -1000.0000 .. 1500.0000"]
    assert fold(["(absent) → 12500", "+1.2500 mm or °"], 21, "    ", "      ") == [
        "    (absent) → 12500", "      +1.2500 mm or °"]
    # a phrase longer than the line breaks between its words; a word longer than it stands alone, whole
    assert fold(["a " + "x" * 30 + " b"], 10) == ["a", "    " + "x" * 30, "    b"]
    assert all(cell_len(line) <= 12 for line in fold(["one two three four five six"], 12))

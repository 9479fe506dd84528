"""The kernel numbers the X rules carry and the start-up error table agree (issue 39: a rule's error
number). A machine rule's number is written in its text and its findings (``rules/machine.py``); the
table (``catalog/data/startup_errors.toml``) documents the same error with its source and names the
rule that checks it. Until both come from one place, this test keeps them in step."""

from __future__ import annotations

import re

from zero.catalog.data.startup_errors import ERRORS
from zero.rules import RULES

NUMBER = re.compile(r"P-ERR-(\d+)")
RULE = re.compile(r"(?<!as )\bX\d{3}\b")  # "checked by X026 ..., as X025": X026 only


def _carried() -> dict[str, set[int]]:
    """X rule → the kernel numbers its summary and explanation name."""
    out: dict[str, set[int]] = {}
    for code, rule in RULES.items():
        if code.startswith("X"):
            found = {int(n) for n in NUMBER.findall(rule.summary + rule.explanation)}
            if found:
                out[code] = found
    return out


def _named_by_table() -> dict[int, set[str]]:
    """Kernel number → the X rules its row's note names as checking (or naming) it."""
    return {int(row["number"]): set(RULE.findall(str(row.get("note", "")))) for row in ERRORS
            if RULE.search(str(row.get("note", "")))}


def test_every_number_an_x_rule_carries_is_a_row_that_names_the_rule() -> None:
    table = _named_by_table()
    documented = {int(row["number"]) for row in ERRORS}
    missing = {(code, n) for code, numbers in _carried().items() for n in numbers
               if n not in documented or code not in table.get(n, set())}
    assert missing == set()


def test_every_row_an_x_rule_checks_is_carried_by_that_rule() -> None:
    carried = _carried()
    unpaired = {(n, code) for n, codes in _named_by_table().items() for code in codes
                if code in RULES and n not in carried.get(code, set())}
    assert unpaired == set()


def test_the_pairing_is_seen() -> None:
    """The test reads what it should: X013 carries 70183 (plane compensation) and X004 110064."""
    carried = _carried()
    assert 70183 in carried["X013"] and 110064 in carried["X004"]
    assert "X013" in _named_by_table()[70183]

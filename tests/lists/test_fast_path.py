"""The tokenizer's fast path reads keys and comments as the careful scanner does (issue 40's speed work)."""

from __future__ import annotations

import random

import pytest

from zero.lists import model
from zero.lists.model import HUGE_INDEX, parse_key, scanned_key
from zero.lists.tokenizer import _fast_entry_re, tokenize_text

KEYS = ["wz[17].laenge", "kenngr.swe_neg", "np_grp[0].achse[2].versch", "a[1][2].b[3]", "x.y[4].z",
        "wz[0]", "tool[3].kinematic.param[12]", "unknown_key_5.member[7]",
        "kenngr.achse[2].x[3]", "ab_c", f"wz[{'9' * 25}].x", "q[007].r"]


@pytest.mark.parametrize("text", KEYS)
def test_scanned_key_is_parse_key(text: str) -> None:
    model._keys.clear()
    m = _fast_entry_re().match(f"{text} 1")
    assert m is not None and m.group(1) == text
    got = scanned_key(*m.group(1, 2, 3, 4))
    model._keys.clear()
    assert got == parse_key(text)


def test_a_huge_first_index_is_clamped() -> None:
    model._keys.clear()
    key = scanned_key(f"wz[{'9' * 25}].x", "wz", "9" * 25, ".x")
    assert key.indices == (HUGE_INDEX,) and key.pattern == "wz[].x"


def test_fast_path_equals_careful_scanner_on_random_lines() -> None:
    rnd = random.Random(40)
    parts = ["wz[3].laenge", "a.b[2]", "k", " ", "\t", "1", "0x1F", "-2.5", "P-AXIS-00001", "( P-AXIS-00007 : x",
             "# note P-TOOL-00002", "(", "word", "/* c */", "Ende", "a|b", '"q s"', "[", "]", "."]
    lines = [" ".join(rnd.choice(parts) for _ in range(rnd.randint(1, 5))) for _ in range(3000)]
    text = "\n".join(lines) + "\n"
    fast, careful = tokenize_text(text), tokenize_text(text, use_fast=False)
    assert repr(fast.items) == repr(careful.items)
    assert fast.problems == careful.problems

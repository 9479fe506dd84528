"""R003 and R007 by their fast paths find what the per-entry look-ups found (issue 40's speed work)."""

from __future__ import annotations

import random

from zero.catalog.registry import load_registry
from zero.diagnostics import Severity
from zero.lists.model import parse_key
from zero.lists.tokenizer import tokenize_text
from zero.rules.lists import check_document
from zero.rules.registry import _bounds, bounds_of

REGISTRY = load_registry()


def _r007_lines(text: str) -> list[tuple[int, int]]:
    doc = tokenize_text(text)
    found = check_document(doc, REGISTRY, "TOOL", {"R007": Severity.WARNING})[1]
    return sorted((d.span.line, int(d.message.split("line ")[1].split(" ")[0])) for d in found if d.code == "R007")


def test_keys_of_one_element_written_differently_are_duplicates() -> None:
    text = "wz[1].laenge 1\nwz[01].laenge 2\nwz[0].laenge 3\nwz[00].laenge 4\n" \
           f"wz[{'9' * 20}].laenge 5\nwz[{'8' * 21}].laenge 6\nwz[10].laenge 7\nwz[100].laenge 8\n"
    assert _r007_lines(text) == [(2, 1), (4, 3), (6, 5)]


def test_duplicates_match_the_element_rule_on_random_keys() -> None:
    rnd = random.Random(40)
    keys = [f"wz[{rnd.choice(['0', '00', '1', '01', '001', '10', '010', '9' * 19, '7' * 25])}].{m}"
            for _ in range(400) for m in [rnd.choice(["laenge", "radius", "x[1]", "x[01]"])]]
    text = "".join(f"{k} {i}\n" for i, k in enumerate(keys))
    last: dict[tuple[str, tuple[int, ...]], int] = {}
    want = []
    for line, k in enumerate(keys, 1):
        parsed = parse_key(k)
        assert parsed is not None
        slot = (parsed.pattern, parsed.indices)
        if slot in last:
            want.append((line, last[slot]))
        last[slot] = line
    assert _r007_lines(text) == sorted(want)


def test_bounds_say_what_index_outside_says() -> None:
    rnd = random.Random(3)
    specs = [s for s in REGISTRY.specs.values() if s.dims][:300]
    for spec in specs:
        bounds = _bounds(spec)
        assert bounds_of(spec) == bounds
        for _ in range(20):
            idx = tuple(rnd.choice([0, 1, 2, 5, 10, 50, 99, 1000, 10**18]) for _ in spec.dims)
            inside = all(first <= i < end for (first, end), i in zip(bounds, idx, strict=False))
            assert inside == (spec.index_outside(idx) is None), (spec.id, idx)

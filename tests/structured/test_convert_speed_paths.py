"""The converters' caches give what the uncached code gave (issue 40's speed work)."""

from __future__ import annotations

import random

from zero.structured import tree as T
from zero.structured.tree import Leaf, Tree
from zero.structured.yaml import write_yaml


def _split_whole(key: str) -> tuple[str, ...] | None:
    """split_key as it was: the whole key split at once."""
    if T._PLAIN_KEY_RE.fullmatch(key):
        return tuple(filter(None, T._SPLIT_RE.split(key)))
    out: list[str] = []
    for part in key.split("."):
        m = T._FRAGMENT_RE.fullmatch(part)
        if m is None:
            return None
        out.append(m.group(1))
        if m.group(2):
            out.extend(m.group(2)[1:-1].split("]["))
    return tuple(out)


def test_split_key_by_its_cached_tail_is_the_whole_split() -> None:
    rnd = random.Random(40)
    atoms = ["wz", "a", "_b", "1x", "[3]", "[07]", "[]", ".", "..", "x9", "[", "]", "é", "[2][4]", ".c", ""]
    for _ in range(50_000):
        key = "".join(rnd.choice(atoms) for _ in range(rnd.randint(1, 7)))
        assert T.split_key(key) == _split_whole(key), key


def test_equal_values_of_other_types_are_written_each_as_itself() -> None:
    leaves = [Leaf("a", ("a",), 1, [], None), Leaf("b", ("b",), 1.0, [], None), Leaf("c", ("c",), "1", [], None),
              Leaf("d", ("d",), 1, [], "x"), Leaf("e", ("e",), 1, [], None)]
    text = write_yaml(Tree(leaves, {"zero": 1}, [], "-", []))
    assert text.splitlines()[:5] == ["a: 1", "b: 1.0", 'c: "1"', "d: 1  # x", "e: 1"]

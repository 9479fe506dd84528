"""Did-you-mean without difflib (zero.nearest): the same answers as difflib.get_close_matches, word for word and
in the same order, and the registry's proposals for a mistyped key the same as before."""

from __future__ import annotations

import difflib

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from zero.catalog.registry import KeyIndex, load_registry
from zero.lists.model import Comment
from zero.lists.tokenizer import tokenize
from zero.nearest import close_matches

# few letters, so that words share runs and the cut-offs are met and missed alike
_WORD = st.text(alphabet="ab._[]xé", max_size=14)


@settings(max_examples=1500, deadline=None)
@given(word=_WORD, candidates=st.lists(_WORD, max_size=12), n=st.integers(1, 4),
       cutoff=st.sampled_from([0.0, 0.3, 0.5, 0.6, 0.75, 0.9, 1.0]))
@example(word="", candidates=["", "a"], n=2, cutoff=0.6)
@example(word="abab", candidates=["baba", "abba", "abab", "abab"], n=3, cutoff=0.5)
@example(word="kenngr.swe_poss", candidates=["kenngr.swe_pos", "kenngr.swe_neg", "kenngr.swe_pos"], n=1, cutoff=0.75)
def test_close_matches_answers_as_difflib(word: str, candidates: list[str], n: int, cutoff: float) -> None:
    assert close_matches(word, candidates, n, cutoff) == difflib.get_close_matches(word, candidates, n, cutoff)


@settings(max_examples=60, deadline=None)
@given(word=st.text(alphabet="ab.", min_size=200, max_size=260), candidates=st.lists(
    st.text(alphabet="ab.", min_size=180, max_size=260), max_size=5))
def test_a_long_word_is_difflibs_own_answer(word: str, candidates: list[str]) -> None:
    """From 200 characters difflib leaves out characters it finds too common (autojunk): it answers itself."""
    assert close_matches(word, candidates, 2, 0.5) == difflib.get_close_matches(word, candidates, 2, 0.5)


@pytest.mark.parametrize(("n", "cutoff"), [(0, 0.6), (1, -0.1), (1, 1.5)])
def test_arguments_difflib_refuses_are_refused(n: int, cutoff: float) -> None:
    with pytest.raises(ValueError):
        difflib.get_close_matches("a", ["a"], n, cutoff)
    with pytest.raises(ValueError):
        close_matches("a", ["a"], n, cutoff)


def _proposal_before(registry: object, pattern: str, kind: str) -> list[str]:
    """The registry's did-you-mean as it was: difflib over every (kind, key) of the index in its order,
    then a missing or extra member level, the shortest first in that order."""
    pool = [k for (kd, k) in registry._by_key if kd == kind]  # type: ignore[attr-defined]
    out = difflib.get_close_matches(pattern, pool, n=1, cutoff=0.75)
    if not out:
        last = pattern.rsplit(".", 1)[-1]
        first = pattern.split(".", 1)[0]
        out = sorted((k for k in pool if k.rsplit(".", 1)[-1] == last and k.split(".", 1)[0] == first), key=len)[:1]
    return out


def _typos(key: str) -> list[str]:
    """A letter left out, doubled and swapped with the next; a member level dropped and one added."""
    middle = len(key) // 2
    out = [key[:middle] + key[middle + 1:], key[:middle] + key[middle] + key[middle:],
           key[:middle] + key[middle + 1:middle + 2] + key[middle] + key[middle + 2:]]
    parts = key.split(".")
    if len(parts) > 2:
        out.append(".".join(parts[:1] + parts[2:]))
    if len(parts) > 1:
        out.append(".".join([parts[0], "extra", *parts[1:]]))
    return out


@pytest.mark.parametrize("kind", ["AXIS", "CHAN", "TOOL", "ZERO", "HWCF", "MANU", "EXTV", "COMP", "RTCF"])
def test_the_registry_proposes_what_it_proposed(kind: str) -> None:
    """Every kind's proposals for typos of a spread of its keys: the kind's own keys in the table's order
    answer as every kind's keys in the IDs' order did (and no other kind's table is read to answer)."""
    registry = load_registry(None)
    assert isinstance(registry._by_key, KeyIndex)
    keys = list(registry._by_key.keys_of_kind(kind))
    assert keys, kind
    checked = 0
    for key in keys[:: max(1, len(keys) // 40)]:
        for typo in _typos(key):
            if registry.by_pattern(typo, kind) is None:
                assert registry.suggest(typo, kind) == _proposal_before(registry, typo, kind), typo
                checked += 1
    assert checked >= 10


@settings(max_examples=300, deadline=None)
@given(lines=st.lists(st.sampled_from([
    "kenngr.swe_pos 5000000", "# CNC kernel V3.01.3074", "; a note", "", "   ", "Ende", "kopf.achs_nr 1",
    "wz[1].laenge 10", "'quoted' value", "kenngr.bez \"a b\"", "( a comment", "#", "x",
]), max_size=60), n=st.integers(0, 45))
def test_the_comments_of_a_lists_head_are_those_of_its_first_items(lines: list[str], n: int) -> None:
    """``comments_in_head`` (the header's kernel release, read without building every entry) answers as the
    first ``n`` items do, before and after the items are built."""
    doc = tokenize("\n".join(lines).encode(), "l.lis")
    got = doc.comments_in_head(n)
    assert got == [i for i in doc.items[:n] if type(i) is Comment]
    assert doc.comments_in_head(n) == got

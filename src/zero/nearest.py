"""Did-you-mean: the candidates a word is likely a typo of, as :func:`difflib.get_close_matches` finds them.

``difflib`` imports ``re`` and compiles a pattern at its import, some 17 M instructions: a lint of an axis
list with one mistyped key took 172 M instead of 128 M, and a commit hook is where typos are met. This
module measures the same similarity without either: the ratio ``2·M / T`` of Ratcliff and Obershelp, where
``M`` counts the characters of the matching blocks (the longest common run, then the same on each side of
it) and ``T`` both lengths. It answers what difflib answers, word for word and in the same order (a
property test holds it to difflib); a word of 200 characters or more, where difflib leaves out characters
it finds too common, is handed to difflib itself.
"""

from __future__ import annotations

from collections.abc import Iterable

# difflib's autojunk starts at a second sequence of this length: from here on, difflib answers
_AUTOJUNK = 200


def close_matches(word: str, candidates: Iterable[str], n: int = 3, cutoff: float = 0.6) -> list[str]:
    """At most ``n`` of ``candidates`` whose similarity to ``word`` is at least ``cutoff``, the most
    similar first (ties: the greater candidate first), as ``difflib.get_close_matches(word, candidates,
    n, cutoff)`` answers."""
    if not n > 0:
        raise ValueError(f"n must be > 0: {n!r}")
    if not 0.0 <= cutoff <= 1.0:
        raise ValueError(f"cutoff must be in [0.0, 1.0]: {cutoff!r}")
    if len(word) >= _AUTOJUNK:
        import difflib  # start-up: only for a word difflib would treat with its autojunk

        return difflib.get_close_matches(word, list(candidates), n=n, cutoff=cutoff)
    where: dict[str, list[int]] = {}  # each character of the word: its positions, in order
    for j, ch in enumerate(word):
        where.setdefault(ch, []).append(j)
    counts = [(ch, len(at)) for ch, at in where.items()]
    others = dict.fromkeys(map(ord, where))  # str.translate drops the word's characters, leaves the others
    lw = len(word)
    found: list[tuple[float, str]] = []
    for cand in candidates:
        total = len(cand) + lw
        # the upper bounds difflib tries first, cheapest first: the lengths, then the characters in common
        # (each character as often as the fewer of the two have it: counted in C, one call per character),
        # and between the two one call in C, the candidate's characters the word has at all
        if total and 2.0 * min(len(cand), lw) / total < cutoff:
            continue
        if total and 2.0 * min(len(cand) - len(cand.translate(others)), lw) / total < cutoff:
            continue
        common = 0
        for ch, most in counts:
            has = cand.count(ch)
            common += has if has < most else most
        if (2.0 * common / total if total else 1.0) < cutoff:
            continue
        score = 2.0 * matched(cand, word, where) / total if total else 1.0
        if score >= cutoff:
            found.append((score, cand))
    found.sort(reverse=True)
    return [cand for _, cand in found[:n]]


def matched(a: str, b: str, where: dict[str, list[int]]) -> int:
    """How many characters of ``a`` and ``b`` the matching blocks cover (``where``: each character of
    ``b`` and its positions): the longest common run of the two (the earliest in ``a``, then in ``b``),
    then the same in the parts before and after it, and so on."""
    total = 0
    spans = [(0, len(a), 0, len(b))]
    while spans:
        alo, ahi, blo, bhi = spans.pop()
        besti, bestj, best = alo, blo, 0
        ending: dict[int, int] = {}  # j -> length of the common run ending at a[i-1] and b[j]
        for i in range(alo, ahi):
            now: dict[int, int] = {}
            for j in where.get(a[i], ()):
                if j < blo:
                    continue
                if j >= bhi:
                    break
                k = now[j] = ending.get(j - 1, 0) + 1
                if k > best:
                    besti, bestj, best = i - k + 1, j - k + 1, k
            ending = now
        if best:
            total += best
            if alo < besti and blo < bestj:
                spans.append((alo, besti, blo, bestj))
            if besti + best < ahi and bestj + best < bhi:
                spans.append((besti + best, ahi, bestj + best, bhi))
    return total

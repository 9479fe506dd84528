"""zero's own gitignore-style matcher: the patterns of a configuration (``include``, ``exclude``,
``per-file-ignores``, ``kind``, ``encoding``) with the meaning pathspec's ``GitIgnoreSpec`` gives them,
without importing pathspec (which imports typing, dataclasses and inspect: 119 M instructions, more
than half of one list's lint).

Each pattern is translated to the very regular expression pathspec 1.x makes of it
(``GitIgnoreSpecPattern.pattern_to_regex``), searched as pathspec searches it, and the answers are
combined as its simple back end does (the last pattern that matches a file itself wins; else the last
that matches a folder above it); ``tests/engine/test_globs.py`` holds the answers to pathspec's.

What this module does not translate with certainty falls back to pathspec for the whole spec
(imported there), so behaviour never changes:

- a bracket expression other than a plain class (``[abc]``, ``[a-z0-9]``, ``[!x]``, ``[^x]`` of
  letters, digits, ``-``, ``_`` and ``.``, ranges ascending): pathspec hands the class to ``re`` as
  written (``[]a]``, ``[[:alpha:]]``, ``[\\]]``, ``[a--]`` or ``[z-a]`` have meanings, warnings or
  errors of ``re``'s), and an unclosed ``[`` makes it drop the pattern;
- a pattern pathspec rejects (a trailing ``\\`` escaping nothing, ``!`` or ``!/`` alone): it raises
  its own error, whose message the configuration's error repeats;
"""

from __future__ import annotations

import os
import re

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing
if TYPE_CHECKING:
    from pathspec import GitIgnoreSpec

_DIR_MARK = "ps_d"  # the group pathspec names the `/` after a folder a pattern matched
_DIR_MARK_CG = f"(?P<{_DIR_MARK}>/)"
_DIR_MARK_OPT = f"(?:{_DIR_MARK_CG}|$)"
# the separators pathspec's normalize_file turns into `/` (none on POSIX, `\` on Windows)
_SEPARATORS = tuple(s for s in (os.sep, os.altsep) if s and s != "/")
# a bracket expression translated with certainty: `[`, an optional `!` or `^`, plain members, `]`
_PLAIN_CLASS = re.compile(r"\[([!^]?)([A-Za-z0-9_.-]+)\]")


def _class(members: str) -> bool:
    """Plain members whose ranges ``re`` reads as the glob means them (``a-z``, ``0-9``, ``-`` at an end)."""
    i = 0
    while i < len(members):
        if i + 2 < len(members) and members[i + 1] == "-":
            if members[i] > members[i + 2] or members[i + 2] == "-" or members[i] == "-":
                return False
            i += 3
        else:
            if members[i] == "-" and 0 < i < len(members) - 1:  # a `-` between ranges: `a-c-e`
                return False
            i += 1
    return True


def _segment(pattern: str) -> str | None:
    """One path segment's glob as pathspec's ``_translate_segment_glob`` writes it (``None``: unsure)."""
    out = []
    i, end = 0, len(pattern)
    while i < end:
        char = pattern[i]
        i += 1
        if char == "\\":
            if i == end:
                return None  # pathspec: "Escape character found with no next character to escape"
            out.append(re.escape(pattern[i]))
            i += 1
        elif char == "*":
            out.append("[^/]*")
        elif char == "?":
            out.append("[^/]")
        elif char == "[":
            m = _PLAIN_CLASS.match(pattern, i - 1)
            if m is None or not _class(m.group(2)):
                return None
            out.append("[" + ("^" if m.group(1) else "") + m.group(2) + "]")
            i = m.end()
        else:
            out.append(re.escape(char))
    return "".join(out)


def translate(pattern: str) -> tuple[str | None, bool | None] | None:
    """The regular expression of one pattern and whether it includes (``True``), excludes (``!``,
    ``False``) or does nothing (``None``: blank, a comment, ``/``); ``None`` where this module does not
    answer with certainty. pathspec's ``GitIgnoreSpecPattern.pattern_to_regex``, step by step."""
    text = pattern if pattern.endswith("\\ ") else pattern.rstrip()
    if not text or text.startswith("#") or text == "/":
        return None, None
    include = not text.startswith("!")
    if not include:
        text = text[1:]
    segs = text.split("/")
    is_dir = not segs[-1]
    if not segs[0]:  # `/x`: anchored at the root
        del segs[0]
    elif (len(segs) == 1 or (len(segs) == 2 and not segs[1])) and segs[0] != "**":  # `x`, `x/`: at any depth
        segs.insert(0, "**")
    if not segs:
        return None  # pathspec: "Pattern normalized to nothing"
    if not segs[-1]:  # `x/`: what is below it
        segs[-1] = "**"
    for i in range(len(segs) - 1, 0, -1):  # `**/**` is `**`
        if segs[i - 1] == "**" and segs[i] == "**":
            del segs[i]
    if segs == ["**"]:
        return (_DIR_MARK_CG if is_dir else "."), include
    if segs == ["**", "*"]:
        return ".", include
    if segs == ["**", "*", "**"]:
        return (_DIR_MARK_CG if is_dir else "/"), include
    out = []
    need_slash = False
    last = len(segs) - 1
    for i, seg in enumerate(segs):
        if seg == "**":
            if i == 0:
                out.append("^(?:.+/)?")
            elif i < last:
                out.append("(?:/.+)?")
                need_slash = True
            else:
                out.append(_DIR_MARK_CG if is_dir else "/")
        else:
            if i == 0:
                out.append("^")
            if need_slash:
                out.append("/")
            glob = "[^/]+" if seg == "*" else _segment(seg)
            if glob is None:
                return None
            out.append(glob)
            if i == last:
                out.append(_DIR_MARK_OPT)
            need_slash = True
    return "".join(out), include


class GlobSpec:
    """Patterns with gitignore's meaning, as ``pathspec.GitIgnoreSpec.from_lines(lines)``: its
    :meth:`match_file` answers as that spec's, with pathspec itself behind it only for the patterns
    this module leaves to it (see the module's docstring)."""

    __slots__ = ("_fallback", "_patterns")

    def __init__(self, lines: list[str] | tuple[str, ...]) -> None:
        self._fallback: GitIgnoreSpec | None = None
        # each regular expression is compiled at its first search (re's cache keeps it)
        translated = [translate(line) for line in lines]
        if None in translated:
            import pathspec  # start-up: only for a pattern zero's matcher leaves to pathspec (see above)

            self._fallback = pathspec.GitIgnoreSpec.from_lines(lines)  # its errors are the configuration's
        # the patterns that do something, last first (pathspec's simple back end checks them so)
        self._patterns = [(t[0], t[1]) for t in reversed(translated)
                          if t is not None and t[0] is not None and t[1] is not None]

    @property
    def fallback(self) -> bool:
        """Does pathspec answer for these patterns?"""
        return self._fallback is not None

    def match_file(self, file: str) -> bool:
        """Is ``file`` (a path relative to the patterns' folder, ``/``-separated) matched: the last
        pattern that matches it itself decides, else the last that matches a folder above it."""
        if self._fallback is not None:
            return self._fallback.match_file(file)
        for sep in _SEPARATORS:  # pathspec's normalize_file
            file = file.replace(sep, "/")
        if file.startswith("/"):
            file = file[1:]
        elif file.startswith("./"):
            file = file[2:]
        answer: bool | None = None
        for regex, include in self._patterns:
            m = re.search(regex, file)
            if m is None:
                continue
            if not m.groupdict().get(_DIR_MARK):  # the file itself: the last such pattern wins
                return include
            if answer is None:  # a folder above it: the last such pattern, unless a file match
                answer = include
        return bool(answer)

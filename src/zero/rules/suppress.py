"""Z rules: suppressions written in the list's own comment syntax.

* same line: a trailing comment holding ``noqa`` (all codes) or ``noqa: R005, M003``,
  in any comment style (``# noqa: R005``, ``( noqa: R005 )``, ``/* noqa */``);
* next entry: a full-line comment ``# zero: ignore[R005]`` (or ``ignore[R005,M003]``);
* whole file: a full-line comment ``# zero: noqa`` or ``# zero: noqa: R005``.

In an NC program the same directives are written in its comments, ``( noqa: N003 )`` or
``; noqa`` on the line, ``( zero: ignore[N003] )`` before the next line with code, and
``; zero: noqa: N003`` for the program (:func:`parse_comment_directives`).

A reason may follow after `` -- ``. Codes may be prefixes (``R``, ``M00``). A
directive that suppresses nothing is reported (Z001), a directive zero cannot read
is reported (Z002): none is ever silently ignored. The funnel (:mod:`zero.rules.funnel`)
applies them to the findings of the other rules, so these rules have no check of their own.
"""

from __future__ import annotations

from collections.abc import Iterable

from zero.diagnostics import Diagnostic, Severity, Span
from zero.lists.model import Comment, Document, Entry
from zero.patterns import IGNORECASE, compiled
from zero.records import Record, field
from zero.rules.base import Context, Family, W

FAMILY: Family[Context] = Family("Z", "suppressions", "suppression")

UNUSED_SUPPRESSION = FAMILY.rule(
    "Z001", "unused-suppression", W, "A suppression that suppresses nothing",
    """
What it checks: every `noqa`, `zero: ignore[...]` and `zero: noqa` directive hides at least
one finding of each code it names.

Why it matters on the machine: a stale suppression hides the next real fault on that line
(a later value out of range, a key renamed) without anyone deciding so.

Example: `np_grp[1].achse[0].versch 5  # noqa: R005` when the value is in range
Fix: remove the directive, or narrow it to the codes that still apply.
""")
MALFORMED_SUPPRESSION = FAMILY.rule(
    "Z002", "malformed-suppression", W, "A suppression directive zero cannot read",
    """
What it checks: the form of suppression directives: `noqa`, `noqa: CODE[, CODE]`,
`# zero: ignore[CODE, ...]`, `# zero: noqa[: CODE, ...]`, each code a zero rule code or
prefix, an optional reason after ` -- `.

Why it matters on the machine: a misspelt directive suppresses nothing, so the finding it
was meant to hide keeps failing the commit, or worse, someone believes a fault was reviewed.

Example: `# zero: ignore R005` (brackets missing), `# noqa: R5O5`
Fix: write the directive as shown above (`zero rule Z002`).
""")

# The patterns of the directives, compiled at their first use (re keeps them): a list without
# `noqa` or `zero:` in its comments compiles none (they were a tenth of a one-list lint's imports).
_NOQA = r"(?<![A-Za-z0-9_])noqa(?![A-Za-z0-9_])(?P<rest>[^)]*)"  # re.IGNORECASE
_ZERO = r"^\s*#\s*zero\s*:\s*(?P<body>.*?)\s*$"  # re.IGNORECASE
_CODE = r"[A-Z][0-9]{0,3}"


class Directive(Record, eq=False):
    line: int  # where it is written
    start: int  # 0-based columns of the directive text
    end: int
    codes: tuple[str, ...] | None  # None: every code
    scope: str  # "line", "next", "file"
    target: int | None = None  # the line a "line"/"next" directive covers
    used: set[str] = field(default_factory=set)

    def covers(self, code: str) -> str | None:
        """The code or prefix of this directive that matches ``code``."""
        if self.codes is None:
            return "*"
        return next((c for c in self.codes if code.startswith(c)), None)


def _codes(text: str, known: set[str]) -> tuple[tuple[str, ...] | None, str | None]:
    """Parse ``CODE, CODE`` (reason after `` -- `` dropped); return codes or an error."""
    text = text.split("--", 1)[0].strip().rstrip("*/").strip()
    if not text:
        return None, None
    parts = [p.strip() for p in compiled(r"[,\s]+").split(text) if p.strip()]
    for p in parts:
        if not compiled(_CODE).fullmatch(p) or not any(k.startswith(p) for k in known):
            return None, f"`{p}` is not a zero rule code or prefix"
    return tuple(parts), None


Bad = tuple[int, int, int, str]  # a malformed directive: line, start, end, reason
_IGNORE = r"ignore\s*\[(?P<codes>[^\]]*)\]\s*(?:--.*)?"  # re.IGNORECASE
_FILE_NOQA = r"noqa\s*(?::(?P<codes>.*))?"  # re.IGNORECASE


def _zero_directive(body: str, line: int, start: int, end: int, bad_end: int,
                    known: set[str]) -> Directive | Bad:
    """The text after ``zero:``: ``ignore[CODE, ...]`` (the next entry; its target is the caller's
    to set) or ``noqa[: CODE, ...]`` (the whole file)."""
    im = compiled(_IGNORE, IGNORECASE).fullmatch(body)
    if im:
        codes, err = _codes(im.group("codes"), known)
        if err or codes is None:
            return (line, start, bad_end, err or "`ignore[...]` names no code")
        return Directive(line, start, end, codes, "next")
    nm = compiled(_FILE_NOQA, IGNORECASE).fullmatch(body)
    if nm:
        codes, err = _codes(nm.group("codes") or "", known)
        if err:
            return (line, start, bad_end, err)
        return Directive(line, start, end, codes, "file")
    return (line, start, bad_end, "expected `zero: ignore[CODE, ...]` or `zero: noqa[: CODE, ...]`")


def _noqa_directive(rest: str, line: int, start: int, end: int, known: set[str]) -> Directive | Bad:
    """A ``noqa`` on its line; ``rest`` is what follows the word."""
    rest = rest.strip()
    codes: tuple[str, ...] | None = None
    if rest.startswith(":"):
        codes, err = _codes(rest[1:], known)
        if err or codes is None:
            return (line, start, end, err or "`noqa:` names no code")
    elif rest and not rest.startswith(("--", "*/")):
        return (line, start, end, "expected `noqa` or `noqa: CODE, ...`")
    return Directive(line, start, end, codes, "line", line)


def parse_directives(doc: Document, known: set[str]) -> tuple[list[Directive], list[Bad]]:
    """Directives of a document, and malformed ones as (line, start, end, reason).

    Read from the full-line comments and the comments after a value that hold ``noqa`` (looked for
    once per distinct comment of :attr:`Document.columns`): no entry object is built but for those."""
    found: list[tuple[int, Directive | Bad]] = []  # (line, what it holds): one per line at most
    cols = doc.columns
    others = doc.other_items()
    entry_lines: list[int] | None = None  # the lines of every entry (after `Ende` too), for `ignore[...]`
    for item in others:
        # the item holds its line's text; `zero` in it (no other character folds to those letters) before the pattern
        if type(item) is not Comment or "zero" not in item.text.lower() or \
                compiled(_ZERO, IGNORECASE).match(item.text) is None:
            continue
        text = doc.line_text(item.line)
        m = compiled(_ZERO, IGNORECASE).match(text)
        if m is None:
            continue
        got = _zero_directive(m.group("body"), item.line, m.start("body"), len(text.rstrip()), len(text), known)
        if isinstance(got, Directive) and got.scope == "next":
            from bisect import bisect_right  # start-up: only for a list with `zero: ignore[...]`

            if entry_lines is None:
                entry_lines = [*cols.line, *(i.line for i in others if type(i) is Entry)]
            at = bisect_right(entry_lines, item.line)
            got.target = entry_lines[at] if at < len(entry_lines) else None
        found.append((item.line, got))
    # one look over all distinct comments first (lower() maps each character on its own, but for a final
    # sigma: a join holds `noqa` where a comment does)
    noqa = {cid for cid, c in enumerate(cols.comments) if "noqa" in c.lower()} \
        if "noqa" in "\n".join(cols.comments).lower() else set()
    entries = [doc.entry_at(row) for row, cid in enumerate(cols.comment) if cid in noqa] if noqa else []
    entries += [i for i in others if type(i) is Entry and i.comment is not None and "noqa" in i.comment.lower()]
    for entry in entries:
        assert entry.comment is not None
        m = compiled(_NOQA, IGNORECASE).search(entry.comment)
        if m is None:
            continue
        found.append((entry.line, _noqa_directive(m.group("rest"), entry.line, entry.comment_start + m.start(),
                                                  entry.comment_start + m.end(), known)))
    found.sort(key=_first)
    out = [got for _, got in found if isinstance(got, Directive)]
    bad = [got for _, got in found if not isinstance(got, Directive)]
    return out, bad


def _first(pair: tuple[int, Directive | Bad]) -> int:
    return pair[0]


def parse_comment_directives(comments: Iterable[tuple[int, int, str]], code_lines: Iterable[int],
                             known: set[str]) -> tuple[list[Directive], list[Bad]]:
    """Directives in comments given as (line, 0-based column, text with its delimiters) — an NC
    program's ``( … )`` and ``; …`` — and malformed ones. ``zero: ignore[...]`` covers the next of
    ``code_lines`` (lines with more than comments), ``zero: noqa`` the file, ``noqa`` its line."""
    out: list[Directive] = []
    bad: list[Bad] = []
    code = sorted(set(code_lines))
    for line, column, text in comments:
        if "noqa" not in text.lower() and "zero" not in text.lower():
            continue
        body_at = column + 1
        body = text[1:].rstrip(")") if text.startswith("(") else text[1:]
        m = compiled(r"\s*zero\s*:\s*(?P<body>.*?)\s*$", IGNORECASE).match(body)
        if m is not None:
            end = body_at + len(body.rstrip())
            got = _zero_directive(m.group("body"), line, body_at + m.start("body"), end, end, known)
            if isinstance(got, Directive) and got.scope == "next":
                got.target = next((n for n in code if n > line), None)
        else:
            nq = compiled(_NOQA, IGNORECASE).search(body)
            if nq is None:
                continue
            got = _noqa_directive(nq.group("rest"), line, body_at + nq.start(), body_at + nq.end(), known)
        if isinstance(got, Directive):
            out.append(got)
        else:
            bad.append(got)
    return out, bad


def apply_directives(path: str, directives: list[Directive], bad: list[Bad],
                     found: list[Diagnostic], severities: dict[str, Severity]) -> list[Diagnostic]:
    """Drop the findings the directives suppress; Z001 for an unused one, Z002 for a malformed one."""
    if not directives and not bad:
        return found
    by_line: dict[int, list[Directive]] = {}
    whole = [d for d in directives if d.scope == "file"]
    for d in directives:
        if d.target is not None:
            by_line.setdefault(d.target, []).append(d)
    kept: list[Diagnostic] = []
    for diag in found:
        hit = False
        for d in [*by_line.get(diag.span.line, ()), *whole]:
            c = d.covers(diag.code)
            if c is not None:
                d.used.add(c)
                hit = True
        if not hit:
            kept.append(diag)
    if "Z001" in severities:
        for d in directives:
            named = ("*",) if d.codes is None else d.codes
            unused = [c for c in named if c not in d.used
                      and (c == "*" or any(k.startswith(c) for k in severities))]
            if not unused:
                continue
            what = "finding" if unused == ["*"] else ", ".join(unused) + " finding"
            where = {"line": "on this line", "next": f"on line {d.target}" if d.target else
                     "(no entry follows)", "file": "in this file"}[d.scope]
            kept.append(Diagnostic("Z001", severities["Z001"],
                                   f"the suppression hides nothing: no {what} {where}",
                                   Span.on_line(d.line, d.start, d.end), path,
                                   hint="remove it, or name only the codes that still apply"))
    if "Z002" in severities:
        for line, start, end, reason in bad:
            kept.append(Diagnostic("Z002", severities["Z002"],
                                   f"malformed suppression: {reason}; it suppresses nothing",
                                   Span.on_line(line, start, end), path))
    kept.sort(key=Diagnostic.sort_key)
    return kept

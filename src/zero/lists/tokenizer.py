"""Read a list file exactly: bytes in, a :class:`~zero.lists.model.Document` out.

The scanner is hand-written and works one line at a time:

1. Decode the bytes (:mod:`zero.lists.encoding`; as the configuration declares them, else as
   detected), remembering the encoding.
2. Split on ``\\n`` only; a ``\\r`` before it is the CRLF ending of that line.
3. Classify each line: blank, full-line comment, ``Ende``, entry, or invalid.

It never raises on any input: every fault becomes a :class:`~zero.lists.model.Problem`
with its location, which :mod:`zero.rules.syntax` turns into a finding.
"""

from __future__ import annotations

from collections.abc import Iterable, MutableSequence, Sequence
from functools import cache
from itertools import compress, islice, repeat
from operator import and_, attrgetter, itemgetter, length_hint, methodcaller

from zero.lists.encoding import declarable, decode
from zero.lists.model import (
    _CACHE_LIMIT,
    Blank,
    Columns,
    ColumnTables,
    Comment,
    CommentStyle,
    Document,
    End,
    Entry,
    Invalid,
    Item,
    Key,
    Problem,
    ValueKind,
    _patterns,
    _singles,
    is_key,
    parse_key,
    row_readers,
    scanned_key,
    shape_parts,
)
from zero.patterns import DOTALL, compiled

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    import re
    from typing import Any

END_KEYWORD = "Ende"
# A file where more than this share of the characters are control characters or stray bytes
# (and at least this many) is not text: one "binary" problem instead of one per character.
BINARY_SHARE = 0.05
BINARY_MIN_CONTROLS = 8
_WS = " \t"
_PLAIN_COMMENT = ("# ", "#\t")
# What a key starts with (parse_key): after a `#`, anything else is no commented-out entry.
_KEY_START = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_")

# The patterns are compiled when first used (start-up: a lint of a short list with nothing unusual in it
# compiles the few its lines need, a third of what this module cost to import).
@cache
def _annotation_re() -> re.Pattern[str]:
    return compiled(r"\(\s*(P-[A-Z]{4}-[0-9]{5})")


@cache
def _key_continuation_re() -> re.Pattern[str]:
    """A token that continues a key after whitespace: `.member`, `[n]` or a lone `]`."""
    return compiled(r"(?:\.[A-Za-z_][A-Za-z0-9_]*(?:\[[0-9]*\]?)*|\[[0-9]*\]?)(?:\.[A-Za-z0-9_]+(?:\[[0-9]+\])*)*|\]")


_MAX_KEY_JOINS = 8


@cache
def _fast_entry_re() -> re.Pattern[str]:
    """The common line, matched in one go: `KEY VALUE [COMMENT]` where nothing needs the careful scanner (no
    quotes, flags, key continuations or `Ende`; a value may start with a `.` that no name follows,
    `./listen/x.lis`, `.5`: that is no key continuation `.name`). Whatever this does not match goes to
    scan_line, which gives the same result for what it does match. Groups: 1 the key, as 2 its names up to
    the first index, 3 that index (if any) and 4 the rest (what model.scanned_key reads); 5 the value; 6 the
    comment."""
    return compiled(
        r"[ \t]*(([A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z0-9_]+)*)(?:\[([0-9]+)\])?"
        r"((?:\[[0-9]+\])*(?:\.[A-Za-z0-9_]+(?:\[[0-9]+\])*)*))"
        r"[ \t]+((?!\.[A-Za-z_])[^\s\"|\[\]][^\s|]*)(?:[ \t]+([^\s|].*)|[ \t]*)\Z",
        DOTALL)


@cache
def _kind_re() -> re.Pattern[str]:
    """The lexical kinds of a value that are a number or a reference, by the name of the group that matches: what
    :func:`value_kind` tells without it (the tests hold the two alike)."""
    return compiled(
        r"(?P<int>[+-]?[0-9]+)|(?P<hex>[+-]?0[xX][0-9A-Fa-f]+)|(?P<ref>P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)?)"
        r"|(?P<real>[+-]?(?:[0-9]+\.[0-9]*|\.[0-9]+|[0-9]+(?=[eE]))(?:[eE][+-]?[0-9]+)?)")


@cache
def _leading_note_re() -> re.Pattern[str]:
    """The note of each comment (after a line feed) that starts `( P-AXIS-00016`: where _annotation_re() finds it
    first, 2 characters into the comment."""
    return compiled(r"\n\( (P-[A-Z]{4}-[0-9]{5})")


_KIND_OF = {"int": ValueKind.INT, "hex": ValueKind.HEX, "ref": ValueKind.REF, "real": ValueKind.REAL}
_HEX_DIGITS = "0123456789ABCDEFabcdef"


def _digits(text: str) -> bool:
    """``[0-9]+``."""
    return text.isdigit() and text.isascii()


def value_kind(value: str) -> ValueKind:
    """The lexical kind of an unquoted value that holds no `|`: what ``_kind_re().fullmatch`` tells (an int, a
    hex number, a reference or a real), else a word; without compiling that pattern (start-up: it cost more
    than a list's values take to tell)."""
    if value[:2] == "P-":  # P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)?
        letters = value[2:6]
        if (len(value) >= 12 and value[6] == "-" and letters.isascii() and letters.isalpha() and letters.isupper()
                and _digits(value[7:12]) and (len(value) == 12 or (value[12] == "." and _digits(value[13:])))):
            return ValueKind.REF
        return ValueKind.WORD
    unsigned = value[1:] if value[:1] in ("+", "-") else value
    if _digits(unsigned):
        return ValueKind.INT
    if unsigned[:2] in ("0x", "0X"):
        digits = unsigned[2:]
        return ValueKind.HEX if digits and not digits.strip(_HEX_DIGITS) else ValueKind.WORD
    # (?:[0-9]+\.[0-9]*|\.[0-9]+|[0-9]+(?=[eE]))(?:[eE][+-]?[0-9]+)?
    mantissa, e, exponent = unsigned.replace("E", "e").partition("e")
    if e:
        exponent = exponent[1:] if exponent[:1] in ("+", "-") else exponent
        if not _digits(exponent):
            return ValueKind.WORD
        if _digits(mantissa):
            return ValueKind.REAL
    whole, point, fraction = mantissa.partition(".")
    if point and (whole or fraction) and (not whole or _digits(whole)) and (not fraction or _digits(fraction)):
        return ValueKind.REAL
    return ValueKind.WORD


def annotation_at(comment: str) -> int:
    """Where the ID of the annotation a comment holds starts (``_annotation_re().search(comment).start(1)``:
    `( P-TOOL-00005 …`), -1 where it holds none; without compiling that pattern."""
    at = comment.find("(")
    while at >= 0:
        start = at + 1
        rest = comment[start:]
        start += len(rest) - len(rest.lstrip())  # \s*
        pid = comment[start:start + 12]
        letters = pid[2:6]
        if (len(pid) == 12 and pid[:2] == "P-" and pid[6] == "-" and letters.isascii() and letters.isalpha()
                and letters.isupper() and _digits(pid[7:])):
            return start
        at = comment.find("(", at + 1)
    return -1
_STYLE_OF = {"#": CommentStyle.HASH, "(": CommentStyle.PAREN}


@cache
def _control_re() -> re.Pattern[str]:
    """Control characters other than tab; \r only counts when it is not a CRLF ending."""
    return compiled(r"[\x00-\x08\x0b-\x1f\x7f-\x9f\udc80-\udcff]")


@cache
def _c1_re() -> re.Pattern[str]:
    """The C1 controls: what a byte above 0x7F becomes when a list written in another code page (CP850's 0x81
    `ü`) is read as Latin-1. In a comment the controller never reads it."""
    return compiled(r"[\x80-\x9f]")


_MARKED_COMMENTS = (CommentStyle.HASH, CommentStyle.PAREN, CommentStyle.BLOCK)
# The ASCII control characters but \r, as byte values (what bytes.find takes) and as characters: each searched for
# on its own.
_CONTROL_BYTES = (*range(0x09), 0x0B, 0x0C, *range(0x0E, 0x20), 0x7F)
_CONTROL_CHARS = tuple(map(chr, _CONTROL_BYTES))
# Every ASCII byte (and Latin-1 byte) _control_re does not match: deleting them leaves the control characters.
_NOT_CONTROL = b"\t\n" + bytes(range(0x20, 0x7F))
_NOT_CONTROL_LATIN1 = _NOT_CONTROL + bytes(range(0xA0, 0x100))


def classify_value(value: str) -> ValueKind:
    """The lexical kind of an unquoted value."""
    kind = value_kind(value)  # an int, hex, reference or real never holds a `|`
    return ValueKind.FLAGS if kind is ValueKind.WORD and "|" in value else kind


def comment_style(comment: str) -> CommentStyle:
    if comment.startswith("#"):
        return CommentStyle.HASH
    if comment.startswith("("):
        return CommentStyle.PAREN
    if comment.startswith("/*"):
        return CommentStyle.BLOCK
    return CommentStyle.TEXT


def _skip_ws(s: str, i: int, n: int) -> int:
    return n - len(s[i:n].lstrip(_WS)) if i < n else i


def _skip_token(s: str, i: int, n: int) -> int:
    while i < n and s[i] not in _WS:
        i += 1
    return i


def scan_entry(s: str, start: int, line: int, problems: list[Problem] | None) -> Item:
    """Scan ``KEY VALUE [COMMENT]`` starting at ``start`` of line text ``s``."""
    n = len(s)
    key_end = _skip_token(s, start, n)
    key_text = s[start:key_end]
    # Whitespace inside a key (`np_grp[0].achse[1]. inaktiv`): join the pieces so
    # the entry keeps its meaning, and report the gap.
    gaps: list[tuple[int, int]] = []
    while len(gaps) < _MAX_KEY_JOINS:
        nxt = _skip_ws(s, key_end, n)
        if nxt >= n or nxt == key_end:
            break
        nxt_end = _skip_token(s, nxt, n)
        token = s[nxt:nxt_end]
        if key_text[-1] in ".[" or _key_continuation_re().fullmatch(token):
            gaps.append((key_end, nxt))
            key_text += token
            key_end = nxt_end
        else:
            break
    key = parse_key(key_text)
    if key is None:
        if problems is not None:
            problems.append(Problem("malformed-line", line, start, key_end, key_text))
        return Invalid(line, s)
    if gaps and problems is not None:
        problems.append(Problem("key-whitespace", line, gaps[0][0], gaps[-1][1], key_text))

    if key_text == END_KEYWORD and not gaps:
        return End(line, start)

    vs = _skip_ws(s, key_end, n)
    if vs >= n:
        if problems is not None:
            problems.append(Problem("missing-value", line, start, key_end, key_text))
        return Entry(line, s[start:key_end], key_text, key, start, key_end, "", None, vs, vs)

    if s[vs] == '"':
        close = s.find('"', vs + 1)
        if close < 0:
            if problems is not None:
                problems.append(Problem("unterminated-quote", line, vs, n, key_text))
            return Entry(
                line, s[start:key_end], key_text, key, start, key_end,
                s[vs:n], ValueKind.QUOTED, vs, n,
            )
        ve = close + 1
        kind = ValueKind.QUOTED
    else:
        ve = _skip_token(s, vs, n)
        # Flag combinations continue across spaces: `REPORT | REPORT_EXTENDED |PRINT`.
        while True:
            nxt = _skip_ws(s, ve, n)
            if nxt >= n:
                break
            if s[ve - 1] == "|" or s[nxt] == "|":
                ve = _skip_token(s, nxt, n)
            else:
                break
        kind = classify_value(s[vs:ve])

    entry = Entry(
        line, s[start:key_end], key_text, key, start, key_end, s[vs:ve], kind, vs, ve
    )
    cs = _skip_ws(s, ve, n)
    if cs < n:
        comment = s[cs:]
        entry.comment = comment
        entry.comment_start = cs
        entry.comment_style = comment_style(comment)
        at = annotation_at(comment) if "P-" in comment else -1
        if at >= 0:
            entry.annotation = comment[at:at + 12]
            entry.annotation_start = cs + at
    return entry


def scan_line(s: str, line: int, problems: list[Problem]) -> Item:
    """Classify one line (without its line ending)."""
    n = len(s)
    i = _skip_ws(s, 0, n)
    if i >= n or not s.strip():
        return Blank(line)
    if s[i] == "#":
        if i + 1 >= n or s[i + 1] in _WS:
            return Comment(line, s)
        if s[i + 1] not in _KEY_START:  # `#****`: no key after the `#` (what scan_entry would find, at once)
            problems.append(Problem("hash-no-space", line, i, i + 1, ""))
            return Comment(line, s, None)
        m = _fast_entry_re().match(s, i + 1)  # `#key value`: the common commented-out entry, matched in one go
        if m is not None and m.group(1) != END_KEYWORD:
            inner: Item = _fast_entry(m, line, m.group(5), _value_kind(m.group(5)), None)
        else:
            inner = scan_entry(s, i + 1, line, None)
        commented = inner if type(inner) is Entry and inner.value else None
        problems.append(
            Problem("hash-no-space", line, i, i + 1, "entry" if commented is not None else "")
        )
        return Comment(line, s, commented)
    return scan_entry(s, i, line, problems)


def _comment_starts(items: list[Item], end_line: int | None) -> list[int]:
    """Per line, the column where the part the controller does not read begins (its length when
    it reads all of it): a full-line comment, a `#`, `(` or `/*` comment after a value, the rest of
    the `Ende` line and every line after it. Plain words after a value are not counted: after a
    string value the controller may read them (S006)."""
    out = []
    for item in items:
        if isinstance(item, Comment) or (end_line is not None and item.line > end_line):
            out.append(0)
        elif isinstance(item, Entry) and item.comment_style in _MARKED_COMMENTS:
            out.append(item.comment_start)
        elif isinstance(item, End):
            out.append(item.start + len(END_KEYWORD))
        else:
            out.append(-1)
    return out


def _c1_in_comments(lines: list[str], items: list[Item], end_line: int | None) -> int:
    """How many C1 controls the comments hold (counted, never one problem each: a binary file)."""
    starts = _comment_starts(items, end_line)
    return sum(len(_c1_re().findall(s, starts[n])) for n, s in enumerate(lines)
               if n < len(starts) and starts[n] >= 0 and not s.isascii())


def _controls(lines: list[str], items: list[Item], end_line: int | None, declared: str | None) -> list[Problem]:
    """The control characters and stray bytes of each line, but no C1 control in a comment."""
    starts: list[int] | None = None
    problems = []
    for number, s in enumerate(lines, 1):
        for m in _control_re().finditer(s):
            ch = m.group()
            code = ord(ch)
            if code == 0:
                problems.append(Problem("nul-byte", number, m.start(), m.end()))
            elif 0xDC80 <= code <= 0xDCFF:
                byte = f"0x{code - 0xDC00:02X}"
                problems.append(Problem("undecodable", number, m.start(), m.end(),
                                        byte if declared is None else f"{byte} {declared}"))
            else:
                if 0x80 <= code <= 0x9F:
                    if starts is None:
                        starts = _comment_starts(items, end_line)
                    at = starts[number - 1] if number <= len(starts) else -1
                    if 0 <= at <= m.start():
                        continue  # a byte of another code page in a comment: not read by the controller
                problems.append(
                    Problem("control-char", number, m.start(), m.end(), f"U+{code:04X}")
                )
    return problems


def _control_count(text: str) -> int:
    """How many characters of the text ``_control_re()`` matches (each CRLF's \\r among them)."""
    if text.isascii():
        return _ascii_controls(text)
    if len(text) <= _CHUNK:  # a small list with letters of a code page: in C as bytes, when Latin-1 holds it
        try:
            return len(text.encode("latin-1").translate(None, _NOT_CONTROL_LATIN1))
        except UnicodeEncodeError:
            pass
    return len(_control_re().findall(text))


def _ascii_controls(text: str | bytes) -> int:
    """:func:`_control_count` of an ASCII text, or of its bytes. A list mostly has none but the \\r of its CRLF
    endings: a search for each of the others (memchr: a few instructions per 32 characters) in each part of the
    text tells, for a tenth of the instructions of deleting every other character, which counts them (in C, ten
    times faster than the regex; in parts: no copy of the text)."""
    if isinstance(text, bytes):
        find = text.find
        if not any(find(c, at, at + _CHUNK) >= 0 for at in range(0, len(text), _CHUNK) for c in _CONTROL_BYTES):
            return text.count(b"\r") if b"\r" in text else 0  # a search for one (memchr) before a count
        return sum(len(text[at:at + _CHUNK].translate(None, _NOT_CONTROL)) for at in range(0, len(text), _CHUNK))
    search = text.find
    if not any(search(c, at, at + _CHUNK) >= 0 for at in range(0, len(text), _CHUNK) for c in _CONTROL_CHARS):
        return text.count("\r") if "\r" in text else 0
    return sum(len(text[at:at + _CHUNK].encode("ascii").translate(None, _NOT_CONTROL))
               for at in range(0, len(text), _CHUNK))


def split_lines(text: str) -> tuple[list[str], list[str]]:
    """The lines of a text without their endings, and each line's ending (``"\\n"``, ``"\\r\\n"``, or
    ``""`` for a last line without one); a text ending in a line break has no empty last line."""
    raw_lines = text.split("\n")
    endings = ["\n"] * (len(raw_lines) - 1) + [""]
    if raw_lines and raw_lines[-1] == "":
        raw_lines.pop()
        endings.pop()
    if "\r" not in text:
        return raw_lines, endings
    lines: list[str] = []
    for idx, s in enumerate(raw_lines):
        if s.endswith("\r") and endings[idx] == "\n":
            lines.append(s[:-1])
            endings[idx] = "\r\n"
        else:
            lines.append(s)
    return lines, endings


# The common entry line over the whole text (a pattern's source), one match per line (the lines
# _fast_entry_re() would match, or fewer): the key as 1 its names up to the first index, 2 that index (no
# leading zero) and 3 the rest from the index's `]` on (loose here: checked once per distinct key shape);
# 4 the value; 5 the comment; else 6 the line. Written for the regex engine's cheapest steps: every
# repeat possessive (none ever gives back what it took: what follows it cannot start with it), so no
# step of a line is kept to return to; the optional index an alternative with an empty one, not a
# repeat; a run of whitespace as its first character, then the spaces (compared one by one, not looked
# up in a set), then the rest. No whitespace group asks for at least one before a comment: a value ends
# at whitespace or `|` only, where no comment starts.
_ROW = (r"(?:[ \t]*+([A-Za-z_][A-Za-z0-9_.]*+)(?:\[(0|[1-9][0-9]{0,17}+)(\][A-Za-z0-9_.\[\]]*+)|)"
    r"[ \t] *+[ \t]*+((?!\.[A-Za-z_])[^\s\"|\[\]][^\s|]*+) *+[ \t]*+(?:([^\s|][^\r\n]*+)|)(?:\r?+(?=\n)|\Z)"
    r"|([^\n]*+))\n?+")
# _ROW with the whitespace before the key, between key and value and before the comment as groups 1, 5
# and 7 (names 2, first index 3, rest 4, value 6, comment 8, the line 9): where each part of a row starts,
# kept as widths so that an entry is built from the columns without its line matched again.
_ROW_AT = (r"(?:([ \t]*+)([A-Za-z_][A-Za-z0-9_.]*+)(?:\[(0|[1-9][0-9]{0,17}+)(\][A-Za-z0-9_.\[\]]*+)|)"
    r"([ \t] *+[ \t]*+)((?!\.[A-Za-z_])[^\s\"|\[\]][^\s|]*+)( *+[ \t]*+)(?:([^\s|][^\r\n]*+)|)(?:\r?+(?=\n)|\Z)"
    r"|([^\n]*+))\n?+")
# The groups of each pattern (what Pattern.split gives per line, and the text between two lines).
_ROW_GROUPS = 6
_ROW_AT_GROUPS = 9
# The patterns a text is read with, by (bytes, a CR in the text, widths): each compiled when first needed.
_ROW_PATTERNS: dict[tuple[bool, bool, bool], re.Pattern[Any]] = {}


def _row_pattern(binary: bool, crlf: bool, widths: bool) -> re.Pattern[Any]:
    """_ROW (_ROW_AT: ``widths``) for a text, or for the bytes of an ASCII text (``binary``): the same lines
    and groups. Without a carriage return in the text (not ``crlf``) the comment runs to the line's end: in C,
    a scan for the line feed, a quarter fewer instructions over a big list than a test of each character
    against a set. In a bytes pattern the whitespace class does not match the separators 0x1C-0x1F, which that
    of a str pattern does: spelt out."""
    got = _ROW_PATTERNS.get((binary, crlf, widths))
    if got is None:
        source = row_source(binary, crlf, widths)
        got = _ROW_PATTERNS[binary, crlf, widths] = compiled(source)  # pattern computed: row_source
    return got


def row_source(binary: bool, crlf: bool, widths: bool) -> str | bytes:
    """The source of :func:`_row_pattern`'s pattern."""
    source = _ROW_AT if widths else _ROW
    if not crlf:  # after a comment, the line's end: no test of it
        source = source.replace(r"(?:([^\s|][^\r\n]*+)|)(?:\r?+(?=\n)|\Z)", r"(?:([^\s|][^\n]*+)|(?=\n|\Z))")
    return source.replace(r"\s", r" \t\n\r\f\v\x1c-\x1f").encode("ascii") if binary else source


_CHUNK = 1 << 18  # characters of text read per pattern call: bounded memory for the match tuples
_BYTES_FROM = 1 << 18  # an ASCII list of more bytes is read as the bytes, never decoded as a whole
_PACK_FROM = 1024  # values an array is extended with at once, from which they are packed first
# The lines the columns do not take that are read the careful way at once, without the pattern of the common
# entry line (which reads what it matches alike): a list with a few (quoted values, flags) never compiles it.
_CAREFUL_FIRST = 32


def _fast_entry(m: re.Match[str], number: int, value: str, kind: ValueKind | None,
                notes: dict[str, tuple[str, CommentStyle, str | None, int]] | None) -> Entry:
    """The entry of a line ``_fast_entry_re()`` matched (its key is no ``Ende``)."""
    key_text, name, first, tail, comment = m.group(1, 2, 3, 4, 6)
    ks, ke = m.span(1)
    vs, ve = m.span(5)
    key = scanned_key(key_text, name, first, tail)
    if comment is None:
        return Entry(number, key_text, key_text, key, ks, ke, value, kind, vs, ve)
    known = notes.get(comment) if notes is not None else None
    if known is None:
        at = annotation_at(comment) if "P-" in comment else -1
        known = (comment, _STYLE_OF.get(comment[0]) or comment_style(comment), comment[at:at + 12] if at >= 0 else None,
                 at)
        if notes is not None and len(notes) < 4096:
            notes[comment] = known
    comment, style, note, at = known
    cs = m.start(6)
    return Entry(number, key_text, key_text, key, ks, ke, value, kind, vs, ve, comment, cs, style, note,
                 cs + at if at >= 0 else -1)


# What each distinct key shape, value and comment is, kept across the documents of a run (a fleet's lists
# repeat each other's keys, values and comments).
_TABLE_LIMIT = 65_536
_kinds: dict[str, ValueKind] = {}
_comment_table: dict[str, tuple[CommentStyle, str | None, int]] = {}


def _value_kind(value: str) -> ValueKind:
    got = _kinds.get(value)
    if got is None:
        got = value_kind(value)
        if len(_kinds) < _TABLE_LIMIT and len(value) < 256:
            _kinds[value] = got
    return got


def _value_kinds(values: list[str]) -> list[ValueKind]:
    """:func:`_value_kind` of each of ``values``, in one call (a big list holds thousands of distinct values)."""
    got: list[Any] = list(map(_kinds.get, values))
    if not any(got):
        # None seen before (a run's first list): an unsigned int (most values) and a name told in C, a step over
        # all values at a time (value_kind costs ~3,000 instructions an int, ~9,000 a name). A name (an
        # identifier: no sign, digit, dot or `-` in front, no `.` or `-` in it) is a word to value_kind.
        ints = map(and_, map(str.isdigit, values), map(str.isascii, values))  # [0-9]+
        got = [ValueKind.INT if i else ValueKind.WORD if w else value_kind(v)
               for i, w, v in zip(ints, map(str.isidentifier, values), values, strict=True)]
        if len(_kinds) < _TABLE_LIMIT:
            _kinds.update(zip(values, got, strict=True) if max(map(len, values), default=0) < 256
                          else ((v, k) for v, k in zip(values, got, strict=True) if len(v) < 256))
    elif not all(got):
        room = len(_kinds) < _TABLE_LIMIT
        for at, value in enumerate(values):
            if got[at] is None:
                kind = got[at] = value_kind(value)
                if room and len(value) < 256:
                    _kinds[value] = kind
    return got


def _comment_parts(comment: str) -> tuple[CommentStyle, str | None, int]:
    """A comment's style, the annotation it holds (`( P-TOOL-00005 …`) and where in it."""
    got = _comment_table.get(comment)
    if got is None:
        # annotation_at, its usual case inline (`( P-AXIS-00178 …` at the start): a call per comment costs as much
        at = -1
        if "P-" in comment:
            pid = comment[2:14]
            if comment[:2] == "( " and pid[:2] == "P-" and pid[6:7] == "-" and comment[2:3] != " ":
                letters = pid[2:6]
                at = 2 if (len(pid) == 12 and letters.isascii() and letters.isalpha() and letters.isupper()
                           and _digits(pid[7:])) else annotation_at(comment)
            else:
                at = annotation_at(comment)
        got = (_STYLE_OF.get(comment[0]) or comment_style(comment), comment[at:at + 12] if at >= 0 else None, at)
        if len(_comment_table) < _TABLE_LIMIT and len(comment) < 512:
            _comment_table[comment] = got
    return got


def _comments_parts(comments: list[str]) -> tuple[list[CommentStyle], list[str | None], list[int]]:
    """:func:`_comment_parts` of each of ``comments`` (distinct), as three lists: styles, notes, their columns.
    Comments the run has not seen (a first list's: all) in C, a step over all of them at a time: the annotation
    pattern searched in each, the style by its first character (one at a time a comment cost ~11,000
    instructions, most of them its ten slices: a 230-comment list's read 2 M instructions more)."""
    known = list(map(_comment_table.get, comments))
    if known.count(None) < len(known):  # some seen before (another list of a fleet): one at a time
        parts = [got or _comment_parts(c) for got, c in zip(known, comments, strict=True)]
        return [p[0] for p in parts], [p[1] for p in parts], [p[2] for p in parts]
    notes: list[str | None]
    if comments and comments[0][:4] == "( P-":
        # Each `( P-AXIS-00016 : …` (the usual list)? Then the style of each is PAREN, its note at 2, and the notes
        # are one pattern's finds over the comments joined (they hold no line feed): a search and two look-ups
        # per comment cost ~6,000 instructions, 1.4 M of reading a 330-line list.
        joined = "\n" + "\n".join(comments)
        if joined.count("\n( P-") == len(comments):
            found_notes: list[Any] = _leading_note_re().findall(joined)
            if len(found_notes) == len(comments):  # one at the start of each, in order
                styles: list[Any] = [CommentStyle.PAREN] * len(comments)
                notes, note_at = found_notes, [2] * len(comments)
                _remember_comments(comments, styles, notes, note_at)
                return styles, notes, note_at
    found: list[Any] = list(map(_annotation_re().search, comments))
    if not all(found):  # (a match is true; `None in found` compares each with None: ~300 instructions)
        notes = [m[1] if m is not None else None for m in found]
        note_at = [m.start(1) if m is not None else -1 for m in found]
    else:  # each holds one (`( P-AXIS-00016 : …`): the usual list
        notes = list(map(itemgetter(1), found))
        note_at = list(map(methodcaller("start", 1), found))
    styles = list(map(_STYLE_OF.get, map(itemgetter(0), comments)))
    if not all(styles):  # neither `#` nor `(`
        styles = [style or comment_style(c) for style, c in zip(styles, comments, strict=True)]
    _remember_comments(comments, styles, notes, note_at)
    return styles, notes, note_at


def _remember_comments(comments: list[str], styles: list[CommentStyle], notes: list[str | None],
                       note_at: list[int]) -> None:
    """Keep what :func:`_comments_parts` told of each of ``comments`` for the run's next lists."""
    if len(_comment_table) < _TABLE_LIMIT:
        said = zip(comments, zip(styles, notes, note_at, strict=True), strict=True)
        if max(map(len, comments), default=0) < 512:
            _comment_table.update(said)
        else:
            _comment_table.update((c, p) for c, p in said if len(c) < 512)


def _read_row(doc: Document, row: int) -> Entry:
    """The entry of a row the tokenizer read into columns only: from the columns' widths where it kept
    them, else its line read again, as it was."""
    if doc.columns.widths is not None:
        return _build(doc, (row,))[row]
    return _read(doc, (row,), [doc.line_text(doc.columns.line[row])], True)[row]


def _read_rows(doc: Document) -> None:
    """Every row's entry (those not built yet), as :func:`_read_row` builds one, in one pass."""
    if doc.columns.widths is not None:
        _build(doc, range(len(doc.columns)))
    else:
        _read(doc, range(len(doc.columns)), doc.lines, False)


def _build(doc: Document, rows: Sequence[int]) -> dict[int, Entry]:
    """Build the entries of ``rows`` into ``doc.columns.objects`` from the columns alone: the key from its
    shape and first index, the positions from the widths the tokenizer kept (no line read again)."""
    cols = doc.columns
    objects = cols.objects
    assert cols.widths is not None
    lead, key_gap, comment_gap = cols.widths
    line, shape, first, value, comment = cols.line, cols.shape, cols.first, cols.value, cols.comment
    shapes, patterns, values, kinds = cols.shapes, cols.patterns, cols.values, cols.kinds
    comments, styles, notes, note_at = cols.comments, cols.styles, cols.notes, cols.note_at
    for row in rows:
        if row in objects:
            continue
        sh = shapes[shape[row]]
        index = first[row]
        if index < 0:
            key_text = sh.head + sh.tail
            indices = sh.indices
        else:
            key_text = f"{sh.head}[{index}]{sh.tail}"
            if sh.indices:
                indices = (index, *sh.indices)
            else:  # the keys of one element (a tool's 38) share their tuple
                indices = _singles.get(index) or _singles.setdefault(index, (index,))
        ks = lead[row]
        ke = ks + len(key_text)
        vs = ke + key_gap[row]
        at = value[row]
        text = values[at]
        ve = vs + len(text)
        cid = comment[row]
        key = Key(key_text, patterns[sh.pattern], indices)
        if cid < 0:
            objects[row] = Entry(line[row], key_text, key_text, key, ks, ke, text, kinds[at], vs, ve)
            continue
        cs = ve + comment_gap[row]
        at_note = note_at[cid]
        objects[row] = Entry(line[row], key_text, key_text, key, ks, ke, text, kinds[at], vs, ve,
                             comments[cid], cs, styles[cid], notes[cid], cs + at_note if at_note >= 0 else -1)
    return objects


def _read(doc: Document, rows: Sequence[int], lines: list[str], one: bool) -> dict[int, Entry]:
    """Build the entries of ``rows`` (from ``lines``: the document's, or ``one`` row's line) into
    ``doc.columns.objects``: positions from the line (matched again by a row pattern: a row's line has no CR, so
    each variant reads it alike; one compiled already), the rest from the columns."""
    cols = doc.columns
    objects = cols.objects
    match = (_ROW_PATTERNS.get((False, False, False)) or _ROW_PATTERNS.get((False, True, False))
             or _row_pattern(False, False, False)).match
    line, shape, first, value, comment = cols.line, cols.shape, cols.first, cols.value, cols.comment
    shapes, patterns, values, kinds = cols.shapes, cols.patterns, cols.values, cols.kinds
    comments, styles, notes, note_at = cols.comments, cols.styles, cols.notes, cols.note_at
    for row in rows:
        if row in objects:
            continue
        number = line[row]
        text = lines[0 if one else number - 1]
        m = match(text)
        assert m is not None and m.start(1) >= 0, (doc.path, number)
        ks = m.start(1)
        ke = m.end(3) if m.start(3) >= 0 else m.end(1)  # the key: its names, then its first index and the rest
        vs, ve = m.span(4)
        sh = shapes[shape[row]]
        index = first[row]
        if index < 0:
            indices = sh.indices
        elif sh.indices:
            indices = (index, *sh.indices)
        else:  # the keys of one element (a tool's 38) share their tuple
            indices = _singles.get(index) or _singles.setdefault(index, (index,))
        key_text = text[ks:ke]
        key = Key(key_text, patterns[sh.pattern], indices)
        at = value[row]
        cid = comment[row]
        if cid < 0:
            objects[row] = Entry(number, key_text, key_text, key, ks, ke, values[at], kinds[at], vs, ve)
            continue
        cs = m.start(5)
        at_note = note_at[cid]
        objects[row] = Entry(number, key_text, key_text, key, ks, ke, values[at], kinds[at], vs, ve,
                             comments[cid], cs, styles[cid], notes[cid], cs + at_note if at_note >= 0 else -1)
    return objects


row_readers.extend((_read_row, _read_rows))


# A key shape as the row pattern splits it (names, `]` and the rest) -> what Columns.add_shape takes,
# None: not a key the columns take; kept across the documents of a run.
_ShapeInfo = tuple[str, bool, str, str, tuple[int, ...]]
_shape_info: dict[tuple[str, str | None], _ShapeInfo | None] = {}
_UNKNOWN: Any = object()  # a key _shape_info does not hold (it holds None for what is no key)


def _shape_of(key: tuple[str, str | None]) -> _ShapeInfo | None:
    """What the row pattern's names (``[A-Za-z_][A-Za-z0-9_.]*``) and rest of a key (``]`` and what follows the
    first index, or ``None`` or ``""``: no index) stand for, if they are a key: names `a.b`, then `[n]`s and
    `.name[n]`s."""
    name, tail = key
    info: _ShapeInfo | None = None
    if (is_key(f"{name}[0{tail}") if tail
            else ".." not in name and name[-1] != "." and name != END_KEYWORD):
        rest = tail[1:] if tail else ""
        info = (name, bool(tail), rest, *shape_parts(name, bool(tail), rest))
    if len(_shape_info) < _TABLE_LIMIT:
        _shape_info[key] = info
    return info


def _shapes_of(keys: list[tuple[str, str | None]]) -> list[_ShapeInfo | None]:
    """:func:`_shape_of` of each of ``keys`` (distinct), in one loop. What the row pattern matched needs few
    checks to be a key: no empty name, and a rest (after the first index) of `.name`s; only a rest with more
    indices is read by is_key and shape_parts, and the pattern of the others is their names and rest as they are
    (each key through _shape_of, is_key and shape_parts cost ~16,000 instructions: 3 M of a 330-line list's read,
    where nearly every key is a shape of its own). (Not a step over all keys at a time in C, as for comments: a
    map calling operator's functions costs as much as the few opcodes it stands for.)"""
    if len(_patterns) + len(keys) >= _CACHE_LIMIT:  # the patterns interned no more: one at a time, as ever
        return [_shape_of(key) for key in keys]
    out: list[_ShapeInfo | None] = []
    append = out.append
    intern = _patterns.setdefault  # a pattern interned (as shape_parts interns it)
    for key in keys:
        name, tail = key
        if not tail:  # no index: the names are the key, and its pattern (the names never start with a dot)
            append(None if ".." in name or name[-1] == "." or name == END_KEYWORD
                   else (name, False, "", intern(name, name), ()))
            continue
        rest = tail[1:]
        if "[" in rest or "]" in rest:  # more indices after the first (or a stray bracket)
            append(_shape_of(key))
        elif ".." in name or name[-1] == "." or (rest and (rest[0] != "." or ".." in rest or rest[-1] == ".")):
            append(None)
        else:  # `.name`s
            pattern = name + "[]" + rest
            append((name, True, rest, intern(pattern, pattern), ()))
    if len(_shape_info) + len(keys) <= _TABLE_LIMIT:
        _shape_info.update(zip(keys, out, strict=True))
    return out


# The tables of the small lists read in this run, by the distinct key shapes, values and comments they
# hold (in order): a fleet's lists of one kind repeat each other's, so another one copies the tables.
_SMALL_LIST = 8192  # lines
_SMALL_TABLES = 256
_small_tables: dict[tuple[tuple[tuple[str, str], ...], tuple[str, ...], tuple[str, ...]],
                    tuple[ColumnTables, dict[tuple[str, str], int], dict[str, int], dict[str, int], list[int]]] = {}


_pattern_of = attrgetter("pattern")  # of a Shape
_NEW = -2  # the id of a shape or comment a reader has just seen for the first time


def _extend(column: MutableSequence[int], count: int, values: Iterable[int]) -> None:
    """``column.extend(values)``, ``count`` of them: many are packed in C first (an array's extend parses each
    int as the argument of a call: a seventh of the instructions of reading a big list). Not the rows of a short
    list: importing struct (a library loaded) costs more than its extends; nor a list column (a small list's)."""
    if count < _PACK_FROM or type(column) is list:
        column.extend(values)
        return
    from array import array  # start-up: loaded with a big list's columns already
    from struct import pack  # start-up: only for a big part of a list

    assert isinstance(column, array)
    column.frombytes(pack(f"{count}{column.typecode}", *values))


class _Reader:
    """The state of reading a text into columns; lines the columns do not take are read as before."""

    def __init__(self, text: str | bytes, widths: bool) -> None:
        # an ASCII text's bytes are read as they are: the texts a part's pattern gives are bytes (keys of the
        # dictionaries below), each distinct one decoded once
        self.binary = isinstance(text, bytes)
        self.text: Any = text
        # A small list (one part, fewer than _SMALL_LIST line feeds) keeps its rows in lists (see Columns). One part
        # may have more: read() tells from the lines its pattern splits, and makes them arrays before the first row
        # (counting the line feeds first cost 5 instructions a character, a fiftieth of reading a 330-line list).
        small = isinstance(text, str) and len(text) <= _CHUNK
        self.cols = Columns(small)
        if widths:
            if small:
                self.cols.widths = ([], [], [])
            else:
                from array import array  # start-up: a big list's columns only

                self.cols.widths = (array("i"), array("i"), array("i"))
        self.slow: list[Item] = []
        self.problems: list[Problem] = []
        self.end_line: int | None = None
        self.after_end_reported = False
        self.careful = 0  # lines read by _line
        # (names, `]` and the rest of the key after the first index) -> shape id, -1: not read into columns; a
        # part a line does not have is None (no key: no row)
        self.shapes: dict[tuple[Any, Any], int] = {(None, None): -1}
        self.firsts: dict[Any, int] = {None: -1}
        self.values: dict[Any, int] = {None: -1}
        self.comments: dict[Any, int] = {None: -1}
        self.shape_pattern: list[int] = []

    def _arrays(self) -> None:
        """The per-row columns (and widths) as arrays, as Columns makes a big list's (before any row)."""
        from array import array  # start-up: a big list's columns only

        cols = self.cols
        cols.line, cols.shape, cols.first = array("i"), array("i"), array("q")
        cols.pattern, cols.value, cols.comment = array("i"), array("i"), array("i")
        if cols.widths is not None:
            cols.widths = (array("i"), array("i"), array("i"))

    def part(self, pos: int, end: int) -> str:
        """The text of a part, as a str."""
        got = self.text[pos:end]
        return got.decode("ascii") if self.binary else got  # type: ignore[no-any-return]

    def read(self) -> None:
        text = self.text
        n = len(text)
        pos = 0
        number = 1
        cols = self.cols
        shapes, firsts, values, comments = self.shapes, self.firsts, self.values, self.comments
        add_shapes, add_comments, add_values = cols.add_shapes, cols.add_comments, cols.add_values
        info_of = _shape_info.get
        shape_pattern = self.shape_pattern
        binary = self.binary
        nl: Any = b"\n" if binary else "\n"
        row_re = _row_pattern(binary, (b"\r" if binary else "\r") in text, cols.widths is not None)
        widths = cols.widths
        step = (_ROW_GROUPS if widths is None else _ROW_AT_GROUPS) + 1
        while pos < n:
            end = text.find(nl, pos + _CHUNK)
            end = n if end < 0 else end + 1
            # One list of every line's groups (then the text between two lines: none), no tuple per line; a
            # group a line does not have is None. The last match is the empty one where the part ends.
            got = row_re.split(text if pos == 0 and end == n else text[pos:end])
            del got[-step:]
            if widths is None:
                names, first_texts, tails, value_texts, comment_texts, wholes = (
                    got[1::step], got[2::step], got[3::step], got[4::step], got[5::step], got[6::step])
                leads = key_gaps = comment_gaps = []
            else:
                (leads, names, first_texts, tails, key_gaps, value_texts, comment_gaps, comment_texts, wholes) = (
                    got[1::step], got[2::step], got[3::step], got[4::step], got[5::step], got[6::step],
                    got[7::step], got[8::step], got[9::step])
            del got
            # Shapes and comments, which a big list repeats: each line's id in one look-up, a text not seen yet added
            # as _NEW (so the last keys of the dictionary are the new ones, in order), its lines' ids read again once
            # it has one (mostly none). Values and first indices, of which most parts have new ones: the distinct
            # ones first. (names, tail) pairs made by zip as they are read, never a list of them (zip reuses its
            # tuple).
            first_part = pos == 0  # every shape and comment new but "none" (its lines' ids read once they have them)
            if first_part:
                seen_shapes: dict[Any, None] = dict.fromkeys(zip(names, tails, strict=True))
                seen_shapes.pop((None, None), None)
                new_shapes = list(seen_shapes)
                seen_comments: dict[Any, None] = dict.fromkeys(comment_texts)
                seen_comments.pop(None, None)
                new_comments = list(seen_comments)
                del seen_shapes, seen_comments
            else:
                had_shapes, had_comments = len(shapes), len(comments)
                sids = list(map(shapes.setdefault, zip(names, tails, strict=True), repeat(_NEW)))
                cids = list(map(comments.setdefault, comment_texts, repeat(_NEW)))
                new_shapes = list(islice(shapes, had_shapes, None)) if len(shapes) > had_shapes else []
                new_comments = list(islice(comments, had_comments, None)) if len(comments) > had_comments else []
            new_values = [v for v in dict.fromkeys(value_texts) if v not in values]
            known = None
            count = len(names)
            if type(cols.line) is list and count - (not text.endswith(nl)) >= _SMALL_LIST:  # (a text's lines: its
                self._arrays()  # line feeds and, without one at its end, the last)
                widths = cols.widths
            small = not binary and pos == 0 and end == n and count <= _SMALL_LIST
            if small:  # a small list: like one read before?
                signature = (tuple(new_shapes), tuple(new_values), tuple(new_comments))
                known = _small_tables.get(signature)
                if known is not None:
                    tables, shape_map, value_map, comment_map, pattern_of = known
                    cols.load_tables(tables)
                    shapes, values, comments = dict(shape_map), dict(value_map), dict(comment_map)
                    self.shapes, self.values, self.comments = shapes, values, comments
                    shape_pattern.extend(pattern_of)
            if known is None:
                if new_shapes:
                    named = ([(a.decode("ascii"), b.decode("ascii") if b is not None else None) for a, b in new_shapes]
                             if binary else new_shapes)
                    infos = list(map(info_of, named, repeat(_UNKNOWN)))
                    if infos.count(_UNKNOWN) == len(infos):  # none seen before (the run's first list)
                        infos = _shapes_of(named)
                    elif _UNKNOWN in infos:
                        fresh = iter(_shapes_of([k for k, i in zip(named, infos, strict=True) if i is _UNKNOWN]))
                        infos = [next(fresh) if i is _UNKNOWN else i for i in infos]
                    shapes.update(zip(new_shapes, add_shapes(infos), strict=True))
                    if len(shape_pattern) < len(cols.shapes):
                        shape_pattern.extend(map(_pattern_of, cols.shapes[len(shape_pattern):]))
                if new_values:
                    said = [v.decode("ascii") for v in new_values] if binary else new_values
                    values.update(zip(new_values, add_values(said, _value_kinds(said)), strict=True))
                if new_comments:
                    said = [c.decode("ascii") for c in new_comments] if binary else new_comments
                    comments.update(zip(new_comments, add_comments(said, *_comments_parts(said)), strict=True))
                if small and len(_small_tables) < _SMALL_TABLES:
                    # not copied: a small list is one part, whose reader changes them no more
                    _small_tables[signature] = (cols.tables(), shapes, values, comments, shape_pattern)
            for f in dict.fromkeys(first_texts):
                if f not in firsts:
                    firsts[f] = int(f)
            if new_shapes or known is not None or first_part:
                sids = list(map(shapes.__getitem__, zip(names, tails, strict=True)))
            if new_comments or known is not None or first_part:
                cids = list(map(comments.__getitem__, comment_texts))
            if self.end_line is None and -1 not in sids:  # every line an entry of the columns
                _extend(cols.line, count, range(number, number + count))
                _extend(cols.shape, count, sids)
                _extend(cols.pattern, count, map(shape_pattern.__getitem__, sids))
                _extend(cols.first, count, map(firsts.__getitem__, first_texts))
                _extend(cols.value, count, map(values.__getitem__, value_texts))
                _extend(cols.comment, count, cids)
                if widths is not None:
                    _extend(widths[0], count, map(len, leads))
                    _extend(widths[1], count, map(len, key_gaps))
                    _extend(widths[2], count, map(len, comment_gaps))
            else:
                self._mixed(names, wholes, sids, number, text, pos, end, first_texts, value_texts, comment_texts,
                            (leads, key_gaps, comment_gaps))
            number += count
            pos = end
        self.line_count = number - 1

    def _mixed(self, names: list[Any], wholes: list[Any], sids: list[int], number: int, text: Any,
               pos: int, end: int, first_texts: list[Any], value_texts: list[Any],
               comment_texts: list[Any], gaps: tuple[list[Any], ...]) -> None:
        """A part where some lines are no row of the columns: plain comments and blank lines become their
        items here; the rows between the other lines go into the columns in bulk, those lines to _line.
        ``names``, ``wholes``: each line's key names (None: no row) and the line as a whole; ``gaps``: the
        whitespace before each key, value and comment (when the columns keep widths)."""
        first_row = len(self.cols.line)
        self._mixed_lines(names, wholes, sids, number, text, pos, end, first_texts, value_texts, comment_texts)
        widths = self.cols.widths
        if widths is not None:  # of the rows this part added, in bulk (a row read the careful way: never read)
            at = [n - number for n in self.cols.line[first_row:]]
            for width, gap in zip(widths, gaps, strict=True):
                _extend(width, len(at), map(length_hint, map(gap.__getitem__, at)))  # None (no such row): 0

    def _mixed_lines(self, names: list[Any], wholes: list[Any], sids: list[int], number: int,
                     text: Any, pos: int, end: int, first_texts: list[Any], value_texts: list[Any],
                     comment_texts: list[Any]) -> None:
        slow = self.slow
        last = len(names) - 1
        ends_nl = text.endswith(b"\n" if self.binary else "\n", pos, end)
        lines: list[str] | None = None
        if self.end_line is not None:  # after `Ende`: every line the careful way
            self._lines(self.part(pos, end).split("\n"), 0, last, ends_nl, number)
            return
        # The lines that are no row (their shape id -1, the only one below 0 read() leaves), each found by a
        # search in C, and the mask of the rows (a list comprehension over every line cost five times as much)
        mask = [True] * len(sids)
        others = []
        at = -1
        for _ in range(sids.count(-1)):
            at = sids.index(-1, at + 1)
            others.append(at)
            mask[at] = False
        start = 0
        for i in others:
            if not names[i]:  # the line as a whole
                s = wholes[i].decode("ascii") if self.binary else wholes[i]
                if s[-1:] == "\r" and (i < last or ends_nl):
                    s = s[:-1]
                # A plain comment or a blank line never matches _fast_entry_re() (a key starts with a letter or `_`).
                if s[:2] in _PLAIN_COMMENT or s == "#":
                    slow.append(Comment(number + i, s))
                    continue
                if not s.strip():
                    slow.append(Blank(number + i))
                    continue
            else:
                if lines is None:
                    lines = self.part(pos, end).split("\n")
                s = lines[i]
                if s[-1:] == "\r" and (i < last or ends_nl):
                    s = s[:-1]
            self._take(start, i, mask, sids, number, first_texts, value_texts, comment_texts)
            start = i + 1
            self._line(s, number + i)
            if self.end_line is not None:  # the rest of the part after `Ende`
                if lines is not None:
                    self._lines(lines, i + 1, last, ends_nl, number)
                else:  # its lines split off from the end (where `Ende` mostly is), not every line of the part
                    rest = self.part(pos, end).rsplit("\n", last - i + ends_nl)
                    self._lines(rest, 1, last - i, ends_nl, number + i)
                return
        self._take(start, last + 1, mask, sids, number, first_texts, value_texts, comment_texts)

    def _lines(self, lines: list[str], start: int, last: int, ends_nl: bool, number: int) -> None:
        """Lines ``start`` to ``last`` of a part (``lines``: its text split), each to _line."""
        for i in range(start, last + 1):
            s = lines[i]
            if s[-1:] == "\r" and (i < last or ends_nl):
                s = s[:-1]
            self._line(s, number + i)

    def _take(self, start: int, stop: int, mask: list[bool], sids: list[int], number: int,
              first_texts: list[Any], value_texts: list[Any], comment_texts: list[Any]) -> None:
        """The rows of the columns among a part's lines ``start`` to ``stop`` (exclusive), in bulk."""
        if start >= stop:
            return
        cols = self.cols
        if stop - start == 1:
            if mask[start]:
                sid = sids[start]
                cols.line.append(number + start)
                cols.shape.append(sid)
                cols.pattern.append(self.shape_pattern[sid])
                cols.first.append(self.firsts[first_texts[start]])
                cols.value.append(self.values[value_texts[start]])
                cols.comment.append(self.comments[comment_texts[start]])
            return
        keep = mask[start:stop]
        taken = list(compress(sids[start:stop], keep))
        count = len(taken)
        _extend(cols.line, count, compress(range(number + start, number + stop), keep))
        _extend(cols.shape, count, taken)
        _extend(cols.pattern, count, map(self.shape_pattern.__getitem__, taken))
        _extend(cols.first, count, map(self.firsts.__getitem__, compress(first_texts[start:stop], keep)))
        _extend(cols.value, count, map(self.values.__getitem__, compress(value_texts[start:stop], keep)))
        _extend(cols.comment, count, map(self.comments.__getitem__, compress(comment_texts[start:stop], keep)))

    def _line(self, s: str, number: int) -> None:
        """A line the columns do not take, read as the tokenizer always did."""
        # A plain comment or a blank line never matches _fast_entry_re() (its key starts with a letter or `_`).
        if s[:2] in _PLAIN_COMMENT or s == "#":
            self.slow.append(Comment(number, s))
            return
        if not s.strip():
            self.slow.append(Blank(number))
            return
        self.careful += 1
        m = _fast_entry_re().match(s) if self.end_line is None and self.careful > _CAREFUL_FIRST else None
        item: Item
        if m is not None and m.group(1) != END_KEYWORD:
            value = m.group(5)
            item = _fast_entry(m, number, value, _value_kind(value), None)
            self.cols.add_entry(item)
            self.slow.append(item)
            return
        item = scan_line(s, number, self.problems)
        if self.end_line is not None:
            if type(item) is Entry:
                item.after_end = True
            if type(item) in (Entry, Invalid, End) and not self.after_end_reported:
                self.after_end_reported = True
                self.problems.append(Problem("after-end", number, 0, len(s), str(self.end_line)))
        elif type(item) is End:
            self.end_line = number
        elif type(item) is Entry:
            self.cols.add_entry(item)
        self.slow.append(item)


def tokenize_text(text: str, path: str = "-", encoding: str = "utf-8", bom: bool = False,
                  use_fast: bool = True, declared: bool = False, objects: bool = False,
                  widths: bool = False) -> Document:
    """Tokenize already decoded text; ``declared``: the configuration named its encoding.

    The common entry lines go into the document's columns (one pattern over the whole text, no object
    per line); the other lines are read one at a time. ``use_fast=False``: every line the careful way,
    as objects (what the columns must agree with). ``objects``: the caller reads every item (a diff, a
    conversion): they are built as the lines are read, which costs less than columns built out afterwards.
    ``widths``: the columns keep where each row's key, value and comment start, so that its entry is built
    without its line matched again: for a caller that reads every entry (building them costs about half,
    reading a seventh more; a lint builds the entries of its findings only)."""
    if objects or not use_fast or "\x00" in text:  # a NUL ends a line where it stands: read line by line
        return _tokenize_items(text, path, encoding, bom, use_fast, declared)
    return _columnar(text, path, encoding, bom, declared, widths)


def _columnar(text: str | bytes, path: str, encoding: str, bom: bool, declared: bool, widths: bool) -> Document:
    """:func:`tokenize_text` into columns, of a text or of the bytes of an ASCII text without a NUL."""
    reader = _Reader(text, widths)
    reader.read()
    doc = Document.columnar(path, encoding, text, reader.line_count, reader.cols, reader.slow, reader.problems,
                            bom, reader.end_line)
    _text_problems(doc, text, reader.problems, encoding if declared else None)
    return doc


def _text_problems(doc: Document, text: str | bytes, problems: list[Problem], declared: str | None) -> None:
    """The problems of the text as a whole: control characters (or a binary file) and mixed line endings."""
    end_line = doc.end_line
    if isinstance(text, bytes):  # an ASCII text: no C1 control
        crlf = text.count(b"\r\n") if b"\r" in text else 0
        controls = _ascii_controls(text) - crlf
        lf = text.count(b"\n") if crlf else 0
    else:
        crlf = text.count("\r\n") if "\r" in text else 0
        # the \r of each CRLF ending is no control character of a line
        controls = _control_count(text) - crlf
        lf = text.count("\n") if crlf else 0
    if (controls >= BINARY_MIN_CONTROLS and controls > len(text) * BINARY_SHARE and isinstance(text, str)
            and _c1_re().search(text)):
        # C1 controls in comments are letters of another code page, not signs of a binary file
        controls -= _c1_in_comments(doc.lines, doc.items, end_line)
    if controls:
        if controls >= BINARY_MIN_CONTROLS and controls > len(text) * BINARY_SHARE:
            problems.append(Problem("binary", 1, 0, len(doc.line_text(1)), str(controls)))
        else:
            problems.extend(_controls(doc.lines, doc.items, end_line, declared))
    if crlf and lf > crlf:
        endings = doc.endings
        if "\r\n" in endings and "\n" in endings:
            first = endings.index("\n" if endings[0] == "\r\n" else "\r\n")
            width = len(doc.line_text(first + 1))
            problems.append(Problem("mixed-endings", first + 1, width, width))
    problems.sort(key=lambda p: (p.line, p.start))


def _tokenize_items(text: str, path: str = "-", encoding: str = "utf-8", bom: bool = False,
                  use_fast: bool = True, declared: bool = False) -> Document:
    """Tokenize already decoded text into objects, line by line (``tokenize_text`` without columns)."""
    lines, endings = split_lines(text)

    problems: list[Problem] = []
    items: list[Item] = []
    end_line: int | None = None
    after_end_reported = False
    fast = _fast_entry_re().match if use_fast else None
    # Values repeat ("0", "1"), and comments too (`( P-TOOL-00005 : …`): each is classified once and
    # kept once, whatever the number of entries that share it. A big list repeats a few dozen
    # comments: one string each instead of 114,000 (17 MB of a 14 MB tool list).
    values: dict[str, tuple[str, ValueKind]] = {}
    notes: dict[str, tuple[str, CommentStyle, str | None, int]] = {}
    append = items.append
    has_nul = "\x00" in text  # one scan of the text, not one per line
    for number, s in enumerate(lines, 1):
        if has_nul and "\x00" in s:  # the controller reads a line as a C string: it ends at the NUL
            s = s[: s.index("\x00")]
            m = None
        else:
            m = fast(s) if fast is not None else None
        if m is not None and end_line is None:
            key_text, name, first, tail, value, comment = m.group(1, 2, 3, 4, 5, 6)
            if key_text != END_KEYWORD:
                seen = values.get(value)
                if seen is not None:
                    value, kind = seen
                else:
                    kind = value_kind(value)
                    if len(values) < 4096:
                        values[value] = (value, kind)
                ks, ke = m.span(1)
                vs, ve = m.span(5)
                key = scanned_key(key_text, name, first, tail)
                if comment is None:
                    append(Entry(number, key_text, key_text, key, ks, ke, value, kind, vs, ve))
                    continue
                known = notes.get(comment)
                if known is None:
                    at = annotation_at(comment) if "P-" in comment else -1
                    known = (comment, _STYLE_OF.get(comment[0]) or comment_style(comment),
                             comment[at:at + 12] if at >= 0 else None, at)
                    if len(notes) < 4096:
                        notes[comment] = known
                comment, style, note, at = known
                cs = m.start(6)
                append(Entry(number, key_text, key_text, key, ks, ke, value, kind, vs, ve,
                             comment, cs, style, note, cs + at if at >= 0 else -1))
                continue
        if fast is not None:  # the common comment and blank lines, as scan_line reads them
            if s[:2] in _PLAIN_COMMENT or s == "#":
                append(Comment(number, s))
                continue
            if not s.strip():
                append(Blank(number))
                continue
        item = scan_line(s, number, problems)
        if end_line is not None:
            if type(item) is Entry:
                item.after_end = True
            if type(item) in (Entry, Invalid, End) and not after_end_reported:
                after_end_reported = True
                problems.append(Problem("after-end", number, 0, len(s), str(end_line)))
        elif type(item) is End:
            end_line = number
        append(item)

    # the \r of each CRLF ending is no control character of a line
    controls = _control_count(text) - (endings.count("\r\n") if "\r" in text else 0)
    if controls >= BINARY_MIN_CONTROLS and controls > len(text) * BINARY_SHARE and _c1_re().search(text):
        # C1 controls in comments are letters of another code page, not signs of a binary file
        controls -= _c1_in_comments(lines, items, end_line)
    if controls:
        if controls >= BINARY_MIN_CONTROLS and controls > len(text) * BINARY_SHARE:
            problems.append(Problem("binary", 1, 0, len(lines[0]) if lines else 0, str(controls)))
        else:
            problems.extend(_controls(lines, items, end_line, encoding if declared else None))
    if "\r\n" in endings and "\n" in endings:
        first = endings.index("\n" if endings[0] == "\r\n" else "\r\n")
        problems.append(Problem("mixed-endings", first + 1, len(lines[first]), len(lines[first])))
    problems.sort(key=lambda p: (p.line, p.start))
    return Document(path, encoding, lines, endings, items, problems, bom, end_line)


def read_as_bytes(data: bytes) -> bool:
    """Does :func:`tokenize` read these bytes as they are (a big list of ASCII bytes: the document
    holds them), rather than decode them into a text first?"""
    return len(data) > _BYTES_FROM and data.isascii() and b"\x00" not in data


def tokenize(data: bytes, path: str = "-", encoding: str | None = None, objects: bool = False,
             widths: bool = False) -> Document:
    """Tokenize the bytes of a list file. Never raises (but for an ``encoding`` that
    :func:`~zero.lists.encoding.declarable` refuses: :class:`ValueError`).

    ``encoding``: the codec the configuration declares for the file, which wins over detection;
    ``objects``, ``widths``: as :func:`tokenize_text`'s. A big list of ASCII bytes is read as the bytes (the
    same characters in any code page a list may declare): never decoded as a whole, the document holds them."""
    if not objects and read_as_bytes(data):
        return _columnar(data, path, declarable(encoding) if encoding is not None else "utf-8", False,
                         encoding is not None, widths)
    text, codec, bom = decode(data, encoding)
    return tokenize_text(text, path, codec, bom, declared=encoding is not None, objects=objects, widths=widths)

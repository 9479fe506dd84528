"""The parsed form of a list file: keys, entries, comments and the document.

Everything here is plain data produced by :mod:`zero.lists.tokenizer`. Column offsets
stored on items are 0-based character offsets into the decoded line; spans for
findings are made from them with :meth:`zero.diagnostics.Span.on_line`.
"""

from __future__ import annotations

import enum
import re

from zero.forms import XML_ROOTS, root_of
from zero.records import field, record

# An index with more digits than this is not converted to an int: it is clamped
# to HUGE_INDEX, which lies beyond every array size, and reported as such.
MAX_INDEX_DIGITS = 18
HUGE_INDEX = 10**MAX_INDEX_DIGITS

_KEY_RE = re.compile(r"[A-Za-z0-9_]+(?:\[[0-9]+\])*(?:\.[A-Za-z0-9_]+(?:\[[0-9]+\])*)*")
_INDEX_RE = re.compile(r"\[([0-9]+)\]")


class ValueKind(enum.Enum):
    """What a value looks like, before the registry says what it should be."""

    INT = "int"  # -12, +7, 0
    HEX = "hex"  # 0x400001
    REAL = "real"  # 1.5, 1e-6
    REF = "ref"  # P-AXIS-00212.0: the value of another parameter
    FLAGS = "flags"  # PLC_INFO | MOS
    WORD = "word"  # ABSOLUT, X_Achse, ./listen/achsmds1.lis, 20804,20805
    QUOTED = "quoted"  # "text with ( # spaces"


class CommentStyle(enum.Enum):
    HASH = "#"
    PAREN = "("
    BLOCK = "/*"
    TEXT = "text"  # plain words after a value


@record(unsafe_hash=True)
class Key:
    """A parameter key such as ``np_grp[5].achse[2].versch``.

    ``pattern`` has the indices removed (``np_grp[].achse[].versch``), which is
    how the registry spells keys; ``indices`` holds them in order. Treat it as immutable
    (not frozen only because a frozen record costs three times as much to build, and a
    big list builds one per entry).
    """

    text: str
    pattern: str
    indices: tuple[int, ...]

    @property
    def members(self) -> list[str]:
        return self.pattern.replace("[]", "").split(".")


_CACHE_LIMIT = 200_000
# A key split after its first index: ``wz[17]`` + ``.kinematic.param[3]``. Both halves repeat
# across a list (a few thousand heads, a few dozen tails), so each is parsed once.
_part_cache: dict[str, tuple[str, tuple[int, ...]]] = {}
_patterns: dict[str, str] = {}
# Whole keys: the lists of a fleet, and the two sides of a diff, repeat each other's keys. A key is
# never changed after parsing, so entries share it.
_KEY_CACHE_LIMIT = 65_536
_keys: dict[str, Key] = {}


def _part(text: str) -> tuple[str, tuple[int, ...]]:
    got = _part_cache.get(text)
    if got is None:
        digits = _INDEX_RE.findall(text)
        got = (_INDEX_RE.sub("[]", text) if digits else text,
               tuple(int(d) if len(d) <= MAX_INDEX_DIGITS else HUGE_INDEX for d in digits))
        if len(_part_cache) < _CACHE_LIMIT and len(text) < 512:
            _part_cache[text] = got
    return got


def parse_key(text: str, trusted: bool = False) -> Key | None:
    """Parse a key; ``None`` when it is not of the form ``name[n].name...``.

    ``trusted``: the caller has matched the key form already (the tokenizer's fast path).
    Patterns are interned: a million keys share a handful of pattern strings.
    """
    got = _keys.get(text)
    if got is not None:
        return got
    if not trusted and not _KEY_RE.fullmatch(text):
        return None
    cut = text.find("]") + 1
    if not cut:
        return Key(text, text, ())
    head, head_indices = _part(text[:cut])
    tail, tail_indices = _part(text[cut:])
    pattern = head + tail
    pattern = _patterns.get(pattern) or (
        _patterns.setdefault(pattern, pattern) if len(_patterns) < _CACHE_LIMIT else pattern)
    key = Key(text, pattern, head_indices + tail_indices)
    if len(_keys) < _KEY_CACHE_LIMIT:
        _keys[text] = key
    return key


_shapes: dict[tuple[str, str], tuple[str, tuple[int, ...]]] = {}
_singles: dict[int, tuple[int]] = {}


def scanned_key(text: str, name: str, first: str | None, tail: str) -> Key:
    """The key the tokenizer's fast path matched as ``name[first]tail`` (``name`` the names up to the
    first index, ``first`` ``None``: no index): what ``parse_key(text, True)`` gives, from one look-up per
    distinct shape (``wz[].laenge``, ``kenngr.achse[].x``) instead of a parse of each key."""
    if first is None:  # no index at all: parse_key's own look-up
        return parse_key(text, True)  # type: ignore[return-value]  # trusted: never None
    got = _keys.get(text)
    if got is not None:
        return got
    shape = _shapes.get((name, tail))
    if shape is None:
        tail_pattern, tail_indices = _part(tail)
        pattern = name + "[]" + tail_pattern
        pattern = _patterns.get(pattern) or (
            _patterns.setdefault(pattern, pattern) if len(_patterns) < _CACHE_LIMIT else pattern)
        shape = (pattern, tail_indices)
        if len(_shapes) < _CACHE_LIMIT and len(tail) < 512:
            _shapes[(name, tail)] = shape
    index = int(first) if len(first) <= MAX_INDEX_DIGITS else HUGE_INDEX
    if shape[1]:
        indices: tuple[int, ...] = (index, *shape[1])
    else:  # one index: the keys of one element (a tool's 38) share its tuple, as parse_key's heads do
        indices = _singles.get(index) or (_singles.setdefault(index, (index,)) if len(_singles) < _CACHE_LIMIT
                                          else (index,))
    key = Key(text, shape[0], indices)
    if len(_keys) < _KEY_CACHE_LIMIT:
        _keys[text] = key
    return key


def format_key(pattern: str, indices: tuple[int, ...] | list[int]) -> str:
    """Fill the ``[]`` slots of a pattern with indices: the inverse of ``parse_key``."""
    parts = pattern.split("[]")
    out = [parts[0]]
    for i, rest in enumerate(parts[1:]):
        out.append(f"[{indices[i]}]" if i < len(indices) else "[]")
        out.append(rest)
    return "".join(out)


@record(eq=False)
class Entry:
    """``KEY VALUE [COMMENT]`` on one line.

    Offsets are 0-based into ``Document.lines[line - 1]``. ``key_text`` is the
    key as the engineer meant it (whitespace inside removed); ``key_raw`` is the
    text as written, which differs when the key had whitespace inside.
    """

    line: int
    key_raw: str
    key_text: str
    key: Key | None
    key_start: int
    key_end: int
    value: str
    value_kind: ValueKind | None
    value_start: int
    value_end: int
    comment: str | None = None
    comment_start: int = -1
    comment_style: CommentStyle | None = None
    annotation: str | None = None
    annotation_start: int = -1
    after_end: bool = False


@record(eq=False)
class Comment:
    """A full-line comment. ``commented_out`` holds a ``#key value`` entry."""

    line: int
    text: str
    commented_out: Entry | None = None


@record(eq=False)
class Blank:
    line: int


@record(eq=False)
class End:
    """The ``Ende`` line: the controller stops reading here."""

    line: int
    start: int


@record(eq=False)
class Invalid:
    """A line that is no entry, comment or blank line."""

    line: int
    text: str


Item = Entry | Comment | Blank | End | Invalid


@record(frozen=True)
class Problem:
    """A fault the tokenizer saw, named by ``kind``; :mod:`zero.rules` gives it a code."""

    kind: str
    line: int
    start: int
    end: int
    detail: str = ""


@record(eq=False)
class Origin:
    """Where the lines of a list came from, when the file the user has open is not the list text
    itself: an XML list (one list line for one XML line) or a list inside a TwinCAT export.

    ``shift`` maps a list line to ``(file line, column shift, entry)``; ``entry`` is ``None`` for a
    line copied with a shift (a comment line holding an XML line, a line of an embedded list) and
    for a parameter element ``(value start in the list line, value start and end in the file line,
    1-based column of the element's `<`, length of its name)``.
    """

    form: str  # "xml", "twincat"
    source: list[str]  # the file's lines, as shown in a report
    shift: dict[int, tuple[int, int, tuple[int, int, int, int, int] | None]]
    final_newline: bool = True
    kind: str | None = None  # the list kind the form says (an XML list's root, a TwinCAT element)
    update: bool = False  # an update or revert file: a partial list applied to a running controller
    default_list: bool = False  # a default list by its root element (`<Default_AX_MDS>`)

    def locate(self, line: int, column: int, end: bool = False) -> tuple[int, int]:
        """A 1-based (line, column) of the list text as (line, column) in the file."""
        got = self.shift.get(line)
        if got is None:  # the `Ende` line an XML list gets: its last line
            last = max(len(self.source), 1)
            return last, max(len(self.source[-1]) if self.source else 0, 0) + 1
        target, shift, entry = got
        if entry is None:
            return target, max(column + shift, 1)
        lis_value, vstart, vend, tag_col, name_len = entry
        if column - 1 >= lis_value:
            return target, vstart + 1 + min(column - 1 - lis_value, vend - vstart)
        return target, tag_col + 1 + (name_len if end else 0)


@record(eq=False)
class Document:
    """A whole list file as read: its lines, items, encoding and line endings."""

    path: str
    encoding: str
    lines: list[str]
    endings: list[str]
    items: list[Item]
    problems: list[Problem] = field(default_factory=list)
    bom: bool = False
    end_line: int | None = None
    origin: Origin | None = None  # where the lines came from, when not from a list file

    @property
    def entries(self) -> list[Entry]:
        """The entries the controller reads (before ``Ende``)."""
        return [i for i in self.items if type(i) is Entry and not i.after_end]

    @property
    def newline(self) -> str:
        """The dominant line ending ("\\n" when the file has none)."""
        crlf = sum(1 for e in self.endings if e == "\r\n")
        lf = sum(1 for e in self.endings if e == "\n")
        return "\r\n" if crlf > lf else "\n"

    def line_text(self, line: int) -> str:
        if 1 <= line <= len(self.lines):
            return self.lines[line - 1]
        return ""

    def holds_xml_lines(self) -> bool:
        """Was this list text written from an XML list (do its first comment lines hold the XML lines,
        `# <?xml …`, `# <AX_MDS>`)? It is then written back as that XML, and its root says its kind."""
        for item in self.items:
            if type(item) is Blank:
                continue
            line = self.lines[item.line - 1]
            text = line.lstrip("# \ufeff")
            return type(item) is Comment and line.startswith("# ") and text.startswith("<") and (
                text[1:2] in ("?", "!") or text[1:2].isalpha())
        return False

    def declared_kind(self) -> str | None:
        """The list kind the file itself declares: an XML list's root element (read from XML, or kept
        as the comment lines of its list text, YAML, TOML or JSON form), else ``None`` (detected from
        the keys: an axis list and an axis compensation list share `kopf.achs_nr`)."""
        if self.origin is not None and self.origin.kind is not None:
            return self.origin.kind
        if not self.holds_xml_lines():
            return None
        held: list[str] = []  # the XML its leading comment lines hold: its root is the first element
        for seen, item in enumerate(i for i in self.items if type(i) is not Blank):  # outside XML comments
            if type(item) is not Comment or seen > 64:  # (`<AX_MDS>` inside `<!-- … -->` is none)
                break
            line = self.lines[item.line - 1]
            held.append(line[2:] if line.startswith("# ") else line[1:])
        root = root_of("\n".join(held).encode("utf-8", "surrogateescape"))
        return XML_ROOTS.get(root) if root is not None else None

    def file_line(self, line: int) -> int:
        """A line of this list as the line of the file that holds it (an XML list, a TwinCAT export)."""
        return self.origin.locate(line, 1)[0] if self.origin is not None else line

    def has_line(self, line: int) -> bool:
        return 1 <= line <= len(self.lines)


@record(eq=False)
class Excerpt(Document):
    """A document reduced to the lines its findings show: what a report of many files keeps of
    each, so that memory grows with the findings, not with the files' lines."""

    shown: dict[int, str] = field(default_factory=dict)

    def line_text(self, line: int) -> str:
        return self.shown.get(line, "")

    def has_line(self, line: int) -> bool:
        return line in self.shown

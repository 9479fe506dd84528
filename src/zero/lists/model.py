"""The parsed form of a list file: keys, entries, comments and the document.

Everything here is plain data produced by :mod:`zero.lists.tokenizer`. Column offsets
stored on items are 0-based character offsets into the decoded line; spans for
findings are made from them with :meth:`zero.diagnostics.Span.on_line`.
"""

from __future__ import annotations

from collections.abc import Iterator, MutableSequence, Sequence
from functools import cache
from itertools import accumulate, count, islice, pairwise, repeat

from zero.forms import XML_ROOTS, root_of
from zero.patterns import compiled
from zero.records import Field, Record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    import re
    from typing import Any, ClassVar

# An index with more digits than this is not converted to an int: it is clamped
# to HUGE_INDEX, which lies beyond every array size, and reported as such.
MAX_INDEX_DIGITS = 18
HUGE_INDEX = 10**MAX_INDEX_DIGITS


@cache
def key_form() -> re.Pattern[str]:
    """The form of a key, ``name[n].name...`` (compiled when first used, as every pattern of the lists)."""
    return compiled(r"[A-Za-z0-9_]+(?:\[[0-9]+\])*(?:\.[A-Za-z0-9_]+(?:\[[0-9]+\])*)*")


_WORD_CHARS = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_"


def is_key(text: str) -> bool:
    """``key_form().fullmatch(text)``, without the pattern (start-up: compiling it cost more than a list's keys
    take to check): names of ``[A-Za-z0-9_]`` joined by dots, each followed by any ``[digits]``."""
    for segment in text.split("."):
        cut = segment.find("[")
        head = segment if cut < 0 else segment[:cut]
        if not head or head.strip(_WORD_CHARS):
            return False
        if cut >= 0:
            rest = segment[cut:]
            if rest[-1] != "]":
                return False
            for digits in rest[1:-1].split("]["):
                if not digits or not digits.isascii() or not digits.isdigit():
                    return False
    return True


def _indices(text: str) -> list[tuple[int, int]]:
    """Where ``\\[([0-9]+)\\]`` matches in ``text`` (as ``re.finditer`` finds them, left to right, none
    overlapping): the span of each one's digits."""
    out = []
    at = text.find("[")
    while at >= 0:
        close = text.find("]", at + 1)
        if close < 0:
            break
        digits = text[at + 1:close]
        if digits and digits.isascii() and digits.isdigit():
            out.append((at + 1, close))
            at = text.find("[", close + 1)
        else:
            at = text.find("[", at + 1)
    return out


class Member:
    """A member of one of the two enumerations below, as :class:`enum.Enum` gives one: ``name``, ``value``,
    its ``repr`` and ``str``; compared by identity, hashed by it (in C), pickled and copied as itself (by name).
    Without enum's class machinery: creating the two classes was a fiftieth of a list's lint, and every
    hash of a member (each dictionary or set it keys) a call of Python."""

    __slots__ = ("name", "value")

    def __init__(self, name: str, value: str) -> None:
        self.name = name
        self.value = value

    def __repr__(self) -> str:
        return f"<{type(self).__name__}.{self.name}: {self.value!r}>"

    def __str__(self) -> str:
        return f"{type(self).__name__}.{self.name}"

    def __reduce__(self) -> str:
        return f"{type(self).__qualname__}.{self.name}"  # pickle and copy: the member itself, looked up by name

    def __setattr__(self, name: str, value: object) -> None:
        if hasattr(self, "value"):  # set once, in __init__
            raise AttributeError(f"cannot change {self!r}")
        object.__setattr__(self, name, value)


class ValueKind(Member):
    """What a value looks like, before the registry says what it should be."""

    __slots__ = ()
    INT: ClassVar[ValueKind]  # -12, +7, 0
    HEX: ClassVar[ValueKind]  # 0x400001
    REAL: ClassVar[ValueKind]  # 1.5, 1e-6
    REF: ClassVar[ValueKind]  # P-AXIS-00212.0: the value of another parameter
    FLAGS: ClassVar[ValueKind]  # PLC_INFO | MOS
    WORD: ClassVar[ValueKind]  # ABSOLUT, X_Achse, ./listen/achsmds1.lis, 20804,20805
    QUOTED: ClassVar[ValueKind]  # "text with ( # spaces"


ValueKind.INT = ValueKind("INT", "int")
ValueKind.HEX = ValueKind("HEX", "hex")
ValueKind.REAL = ValueKind("REAL", "real")
ValueKind.REF = ValueKind("REF", "ref")
ValueKind.FLAGS = ValueKind("FLAGS", "flags")
ValueKind.WORD = ValueKind("WORD", "word")
ValueKind.QUOTED = ValueKind("QUOTED", "quoted")


class CommentStyle(Member):
    __slots__ = ()
    HASH: ClassVar[CommentStyle]
    PAREN: ClassVar[CommentStyle]
    BLOCK: ClassVar[CommentStyle]
    TEXT: ClassVar[CommentStyle]  # plain words after a value


CommentStyle.HASH = CommentStyle("HASH", "#")
CommentStyle.PAREN = CommentStyle("PAREN", "(")
CommentStyle.BLOCK = CommentStyle("BLOCK", "/*")
CommentStyle.TEXT = CommentStyle("TEXT", "text")


class Key(Record, unsafe_hash=True):
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
    if "[" not in text:  # no index (`kenngr.swe_pos`, `.laenge`): most keys of most lists
        return text, ()
    got = _part_cache.get(text)
    if got is None:
        spans = _indices(text)
        if spans:
            parts = [text[:spans[0][0]]]
            parts.extend(text[end:start] for (_, end), (start, _) in pairwise(spans))  # "][", "].x["
            parts.append(text[spans[-1][1]:])
            digits = [text[start:end] for start, end in spans]
            pattern = "".join(parts)
        else:
            digits, pattern = [], text
        got = (pattern, tuple(int(d) if len(d) <= MAX_INDEX_DIGITS else HUGE_INDEX for d in digits))
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
    if not trusted and not is_key(text):
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
# (head, indexed, tail) -> (pattern, the tail's indices): Columns.shape_id's parse, shared by documents
_shape_parts: dict[tuple[str, bool, str], tuple[str, tuple[int, ...]]] = {}
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


class Entry(Record, eq=False):
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


class Comment(Record, eq=False):
    """A full-line comment. ``commented_out`` holds a ``#key value`` entry."""

    line: int
    text: str
    commented_out: Entry | None = None


class Blank(Record, eq=False):
    line: int


class End(Record, eq=False):
    """The ``Ende`` line: the controller stops reading here."""

    line: int
    start: int


class Invalid(Record, eq=False):
    """A line that is no entry, comment or blank line."""

    line: int
    text: str


Item = Entry | Comment | Blank | End | Invalid


def _F(name: str) -> Field:
    f = Field()
    f.name = name
    return f


class Problem(Record, frozen=True):
    """A fault the tokenizer saw, named by ``kind``; :mod:`zero.rules` gives it a code."""

    kind: str
    line: int
    start: int
    end: int
    detail: str = ""


class Origin(Record, eq=False):
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


def shape_parts(head: str, indexed: bool, tail: str) -> tuple[str, tuple[int, ...]]:
    """The pattern (interned) and the tail's indices of the shape ``head[first]tail`` (see
    :meth:`Columns.shape_id`), kept across documents."""
    key = (head, indexed, tail)
    parts = _shape_parts.get(key)
    if parts is None:
        tail_pattern, tail_indices = _part(tail)
        if indexed:
            pattern = head + "[]" + tail_pattern
        else:  # no index after the head: the whole key (`kenngr.swe_pos`, `wz[01].x` with its zero)
            pattern, tail_indices = _part(head + tail)
        pattern = _patterns.get(pattern) or (
            _patterns.setdefault(pattern, pattern) if len(_patterns) < _CACHE_LIMIT else pattern)
        parts = (pattern, tail_indices)
        if len(_shape_parts) < _CACHE_LIMIT and len(head) + len(tail) < 512:
            _shape_parts[key] = parts
    return parts


# What Columns.tables gives: its tables and their indexes as they are (not copied), and how many items each held.
ColumnTables = tuple[tuple[list["Shape"], list[str], dict[tuple[str, bool, str], int], dict[str, int], list[str],
                           list[ValueKind | None], dict[str, int], list[str], list[CommentStyle], list[str | None],
                           list[int], dict[str, int]], tuple[int, ...]]


def _head(table: Any, size: int) -> Any:
    """A copy of the first ``size`` items of a list or dictionary that has only grown at its end since it held
    ``size``."""
    if len(table) == size:
        return table.copy()
    return table[:size] if type(table) is list else dict(islice(table.items(), size))


class Columns:
    """The entries the controller reads (before ``Ende``), one row each, in line order: what
    :attr:`Document.entries` holds, as arrays and tables of distinct values instead of one object per
    entry (issue 40). A rule that looks at every entry loops over the arrays (or over a table: one
    check per distinct pattern, value or comment) and builds an :class:`Entry` with
    :meth:`Document.entry_at` only for the rows it reports.

    Per row (``len(columns)`` rows): ``line`` (1-based), ``shape`` (into ``shapes``: the key without its
    first index), ``first`` (the key's first index, ``-1`` when its shape has none), ``pattern`` (into
    ``patterns``: the key as the registry spells it, ``wz[].laenge``), ``value`` (into ``values``,
    ``kinds``), ``comment`` (into ``comments``, ``styles``, ``notes``, ``note_at``; ``-1``: none).
    A key is ``shape.head + f"[{first}]" + shape.tail`` (``head + tail`` without a first index);
    its indices ``(first, *shape.indices)`` (``shape.indices``). A snapshot: built once, not updated
    when entries are changed afterwards. Each per-row column is an array, or a list for a small list: read
    them as sequences of ints.
    """

    __slots__ = ("_comment_ids", "_pattern_ids", "_shape_ids", "_value_ids", "comment", "comments", "first",
                 "kinds", "line", "note_at", "notes", "objects", "pattern", "patterns", "shape", "shapes", "styles",
                 "value", "values", "widths")

    def __init__(self, small: bool = False) -> None:
        # ``small``: the per-row columns are lists, not arrays (a short list's: an array's extend parses each int
        # as the argument of a call, ~600 instructions, a list's takes it as it is; a 300-line list's read 1.0 M
        # instructions fewer). A big list's are arrays: 4 or 8 bytes a row, not a pointer and an int object.
        # (The array module is a shared library: loading it is a third of a millisecond a small list never pays.)
        if small:
            self.line: MutableSequence[int] = []
            self.shape: MutableSequence[int] = []
            self.first: MutableSequence[int] = []
            self.pattern: MutableSequence[int] = []
            self.value: MutableSequence[int] = []
            self.comment: MutableSequence[int] = []
        else:
            from array import array  # start-up: a big list's columns only

            self.line, self.shape, self.first = array("i"), array("i"), array("q")
            self.pattern, self.value, self.comment = array("i"), array("i"), array("i")
        self.shapes: list[Shape] = []
        self.patterns: list[str] = []
        self.values: list[str] = []
        self.kinds: list[ValueKind | None] = []
        self.comments: list[str] = []
        self.styles: list[CommentStyle] = []
        self.notes: list[str | None] = []  # the annotation (`( P-TOOL-00005 …`) a comment holds
        self.note_at: list[int] = []  # its column in the comment (-1: none)
        # rows whose Entry exists (scanned the careful way, or built on demand): row -> Entry
        self.objects: dict[int, Entry] = {}
        # Per row, when the tokenizer kept them: the widths of the whitespace before the key (its start), between
        # key and value and between value and comment, from which an entry's positions follow (0 for a row whose
        # object exists). None: an entry is built by reading its line again.
        self.widths: tuple[MutableSequence[int], MutableSequence[int], MutableSequence[int]] | None = None
        self._shape_ids: dict[tuple[str, bool, str], int] = {}
        self._pattern_ids: dict[str, int] = {}
        self._value_ids: dict[str, int] = {}
        self._comment_ids: dict[str, int] = {}

    def __len__(self) -> int:
        return len(self.line)

    def __repr__(self) -> str:
        return f"Columns({len(self)} rows, {len(self.shapes)} shapes, {len(self.values)} values)"

    # --- reading a row
    def key_text(self, row: int) -> str:
        shape = self.shapes[self.shape[row]]
        first = self.first[row]
        return shape.head + shape.tail if first < 0 else f"{shape.head}[{first}]{shape.tail}"

    def indices(self, row: int) -> tuple[int, ...]:
        shape = self.shapes[self.shape[row]]
        first = self.first[row]
        return shape.indices if first < 0 else (first, *shape.indices)

    def key(self, row: int) -> Key:
        return Key(self.key_text(row), self.patterns[self.pattern[row]], self.indices(row))

    def value_text(self, row: int) -> str:
        return self.values[self.value[row]]

    def value_kind(self, row: int) -> ValueKind | None:
        return self.kinds[self.value[row]]

    def comment_text(self, row: int) -> str | None:
        at = self.comment[row]
        return self.comments[at] if at >= 0 else None

    def rows_of_pattern(self) -> dict[int, list[int]]:
        """Pattern id -> its rows, in order (one pass)."""
        out: dict[int, list[int]] = {}
        for row, pid in enumerate(self.pattern):
            got = out.get(pid)
            if got is None:
                out[pid] = [row]
            else:
                got.append(row)
        return out

    # --- building
    def shape_id(self, head: str, indexed: bool, tail: str) -> int:
        """The id of the shape ``head[first]tail`` (``head + tail``: ``indexed`` False), added when new.
        ``head`` and ``tail`` must be a key's parts as :func:`parse_key` accepts it."""
        got = self._shape_ids.get((head, indexed, tail))
        if got is not None:
            return got
        return self.add_shape(head, indexed, tail, *shape_parts(head, indexed, tail))

    def add_shape(self, head: str, indexed: bool, tail: str, pattern: str, tail_indices: tuple[int, ...]) -> int:
        """:meth:`shape_id` with the shape's :func:`shape_parts` known (a reader keeps them across documents)."""
        key = (head, indexed, tail)
        got = self._shape_ids.get(key)
        if got is not None:
            return got
        pid = self._pattern_ids.get(pattern)
        if pid is None:
            pid = self._pattern_ids[pattern] = len(self.patterns)
            self.patterns.append(pattern)
        got = self._shape_ids[key] = len(self.shapes)
        self.shapes.append(Shape(head, tail, pid, tail_indices, indexed))
        return got

    def add_shapes(self, infos: list[tuple[str, bool, str, str, tuple[int, ...]] | None]) -> list[int]:
        """:meth:`add_shape` of each ``(head, indexed, tail, pattern, tail_indices)`` (distinct) in one call;
        ``None``: -1."""
        shape_ids, pattern_ids, patterns, shapes = self._shape_ids, self._pattern_ids, self.patterns, self.shapes
        if infos and all(infos):  # (not `None not in`: each info compared with None, ~500 instructions)
            # Each a key: in C, a step over all of them at a time (one at a time ~5,000 instructions a shape)
            heads, indexed, tails, pattern_texts, tail_indices = zip(*infos, strict=True)
            keys = list(zip(heads, indexed, tails, strict=True))
            # none added before (by add_entry): all new, in order (an empty dictionary asked first: isdisjoint
            # hashes each key)
            if not shape_ids or shape_ids.keys().isdisjoint(keys):
                new = list(dict.fromkeys(pattern_texts))
                if pattern_ids and not pattern_ids.keys().isdisjoint(new):
                    new = [p for p in new if p not in pattern_ids]
                pattern_ids.update(zip(new, count(len(patterns)), strict=False))  # (count: endless)
                patterns.extend(new)
                start = len(shapes)
                shapes.extend(_made_shapes(heads, tails, list(map(pattern_ids.__getitem__, pattern_texts)),
                                           tail_indices, indexed))
                shape_ids.update(zip(keys, count(start), strict=False))
                return list(range(start, len(shapes)))
        out: list[int] = []
        for info in infos:
            if info is None:
                out.append(-1)
                continue
            head, indexed, tail, pattern, tail_indices = info
            key = (head, indexed, tail)
            got = shape_ids.get(key)
            if got is None:
                pid = pattern_ids.get(pattern)
                if pid is None:
                    pid = pattern_ids[pattern] = len(patterns)
                    patterns.append(pattern)
                got = shape_ids[key] = len(shapes)
                shapes.append(Shape(head, tail, pid, tail_indices, indexed))
            out.append(got)
        return out

    def value_id(self, value: str, kind: ValueKind | None) -> int:
        got = self._value_ids.get(value)
        if got is not None and self.kinds[got] is kind:
            return got
        at = len(self.values)
        if got is None:
            self._value_ids[value] = at
        self.values.append(value)
        self.kinds.append(kind)
        return at

    def add_values(self, values: list[str], kinds: list[ValueKind]) -> list[int]:
        """:meth:`value_id` of each of ``values`` (distinct) with its kind, in bulk."""
        ids = self._value_ids
        if ids and not ids.keys().isdisjoint(values):
            return [self.value_id(v, k) for v, k in zip(values, kinds, strict=True)]
        start = len(self.values)
        stop = start + len(values)
        self.values.extend(values)
        self.kinds.extend(kinds)
        ids.update(zip(values, range(start, stop), strict=True))
        return list(range(start, stop))

    def comment_id(self, comment: str | None, style: CommentStyle | None = None, note: str | None = None,
                   note_at: int = -1) -> int:
        if comment is None:
            return -1
        got = self._comment_ids.get(comment)
        if got is not None:
            return got
        got = self._comment_ids[comment] = len(self.comments)
        self.comments.append(comment)
        self.styles.append(style if style is not None else CommentStyle.TEXT)
        self.notes.append(note)
        self.note_at.append(note_at)
        return got

    def add_comments(self, comments: list[str], styles: list[CommentStyle], notes: list[str | None],
                     note_at: list[int]) -> list[int]:
        """:meth:`comment_id` of each of ``comments`` (distinct) with its style, note and note's column, in bulk."""
        ids = self._comment_ids
        if ids and not ids.keys().isdisjoint(comments):
            return [self.comment_id(*p) for p in zip(comments, styles, notes, note_at, strict=True)]
        start = len(self.comments)
        stop = start + len(comments)
        self.comments.extend(comments)
        self.styles.extend(styles)
        self.notes.extend(notes)
        self.note_at.extend(note_at)
        ids.update(zip(comments, range(start, stop), strict=True))
        return list(range(start, stop))

    def tables(self) -> ColumnTables:
        """The tables (shapes, patterns, values, comments) and their indexes as they are now, for
        :meth:`load_tables`: not copied (a reader keeps those of each small list, mostly never loaded: copying
        them was a fortieth of reading a 330-line list). Each only grows at its end (nothing changes or removes an
        item), so their first items, as many as each holds now, stay what they are now. The :class:`Shape`
        objects are shared: nothing changes a shape once made."""
        held = (self.shapes, self.patterns, self._shape_ids, self._pattern_ids, self.values, self.kinds,
                self._value_ids, self.comments, self.styles, self.notes, self.note_at, self._comment_ids)
        each: tuple[Any, ...] = held
        return held, tuple(map(len, each))

    def load_tables(self, tables: ColumnTables) -> None:
        """Take a copy of :meth:`tables` of other columns (a reader's, for a list like one read before): of each
        table, the items it held then."""
        held, sizes = tables
        (self.shapes, self.patterns, self._shape_ids, self._pattern_ids, self.values, self.kinds, self._value_ids,
         self.comments, self.styles, self.notes, self.note_at, self._comment_ids) = map(_head, held, sizes)

    def add_entry(self, entry: Entry) -> int:
        """Append an entry built as an object (the careful scanner's, or a document's items): its row."""
        row = len(self.line)
        text = entry.key_text
        cut = text.find("[")
        close = text.find("]", cut) if cut >= 0 else -1
        digits = text[cut + 1:close] if close > cut >= 0 else ""
        if (entry.key is not None and digits.isdigit() and digits.isascii() and len(digits) <= MAX_INDEX_DIGITS
                and (digits == "0" or digits[0] != "0")):
            shape = self.shape_id(text[:cut], True, text[close + 1:])
            first = int(digits)
        else:
            shape = self.shape_id(text, False, "") if entry.key is not None else self._keyless(text)
            first = -1
        self.line.append(entry.line)
        self.shape.append(shape)
        self.first.append(first)
        self.pattern.append(self.shapes[shape].pattern)
        self.value.append(self.value_id(entry.value, entry.value_kind))
        note_at = entry.annotation_start - entry.comment_start if entry.annotation_start >= 0 else -1
        self.comment.append(self.comment_id(entry.comment, entry.comment_style, entry.annotation, note_at))
        self.objects[row] = entry
        return row

    def _keyless(self, text: str) -> int:
        got = self._shape_ids.get((text, False, "\x00"))
        if got is None:  # a pattern of its own: no key pattern shares it
            pid = len(self.patterns)
            self.patterns.append(text)
            got = self._shape_ids[(text, False, "\x00")] = len(self.shapes)
            self.shapes.append(Shape(text, "", pid, (), False))
        return got

    @classmethod
    def of_entries(cls, entries: list[Entry]) -> Columns:
        cols = cls()
        for e in entries:
            cols.add_entry(e)
        return cols


class Shape(Record, eq=False):
    """A key without its first index: ``head`` (``wz``, ``kenngr.swe_pos``), then the index, then
    ``tail`` (``.kinematic.param[3]``); ``indices`` are the tail's (all of the key's when not
    ``indexed``), ``pattern`` an id into :attr:`Columns.patterns`."""

    head: str
    tail: str
    pattern: int
    indices: tuple[int, ...]
    indexed: bool


def _made_shapes(heads: Sequence[str], tails: Sequence[str], patterns: Sequence[int],
                 indices: Sequence[tuple[int, ...]], indexed: Sequence[bool]) -> list[Shape]:
    """``list(map(Shape, heads, tails, patterns, indices, indexed))`` without the record's ``__init__`` called for
    each: the objects made in C, then their fields set as the targets of one loop (what that ``__init__`` does; a
    third fewer instructions: a call of a record's ``__init__`` from C costs more than its five stores)."""
    made = list(map(object.__new__, repeat(Shape, len(heads))))
    _each: Shape
    for _each, _each.head, _each.tail, _each.pattern, _each.indices, _each.indexed in zip(
            made, heads, tails, patterns, indices, indexed, strict=True):
        pass  # (the targets did it all)
    return made


# What builds the entry of a row the tokenizer read into columns only, and every row's (zero.lists.tokenizer
# sets them: it reads the line again).
row_readers: list[Any] = []


_DOC_FIELDS = ("path", "encoding", "lines", "endings", "items", "problems", "bom", "end_line", "origin")


class Document:
    """A whole list file as read: its lines, items, encoding and line endings.

    Read by the tokenizer, a document holds the decoded text and :class:`Columns` of its entries; its
    ``lines``, ``endings``, ``items`` and ``entries`` are built on first use (then kept: the same objects
    each time, and :meth:`entry_at` gives the object ``items`` holds). Built from lists (the other
    forms, tests), ``columns`` are built from ``entries`` on first use.
    """

    __slots__ = ("_columns", "_endings", "_items", "_lines", "_slow", "_starts", "_text", "bom", "encoding",
                 "end_line", "line_count", "origin", "path", "problems")
    __record_fields__ = tuple(_F(n) for n in _DOC_FIELDS)  # records.replace() and fields() read documents

    def __init__(self, path: str, encoding: str, lines: list[str] | None, endings: list[str] | None,
                 items: list[Item] | None, problems: list[Problem] | None = None, bom: bool = False,
                 end_line: int | None = None, origin: Origin | None = None) -> None:
        self.path = path
        self.encoding = encoding
        self._lines = lines
        self._endings = endings
        self._items = items
        self.problems = problems if problems is not None else []
        self.bom = bom
        self.end_line = end_line
        self.origin = origin
        # the text the tokenizer read: a str, or the file's own bytes when they are ASCII (a big list: never
        # decoded as a whole; a line is decoded when asked for)
        self._text: str | bytes | None = None
        self._columns: Columns | None = None
        self._slow: list[Item] = []
        self._starts: MutableSequence[int] | None = None
        self.line_count = len(lines) if lines is not None else 0

    @classmethod
    def columnar(cls, path: str, encoding: str, text: str | bytes, line_count: int, columns: Columns,
                 slow: list[Item], problems: list[Problem], bom: bool, end_line: int | None) -> Document:
        """A document the tokenizer read: ``slow`` are the items of the lines it did not read into
        columns (comments, blank lines, entries read the careful way, which ``columns`` holds too),
        in line order; ``text`` the decoded text, or the bytes of an ASCII text (the same characters)."""
        doc = cls(path, encoding, None, None, None, problems, bom, end_line)
        doc._text = text
        doc._columns = columns
        doc._slow = slow
        doc.line_count = line_count
        return doc

    def __repr__(self) -> str:
        return f"{type(self).__name__}(path={self.path!r}, encoding={self.encoding!r}, lines={self.line_count})"

    # --- the lazy parts
    @property
    def text(self) -> str | None:
        """The decoded text the tokenizer read (``None`` for a document built from lines). Of a document
        that holds the bytes of an ASCII text, a new copy each time: ask for :attr:`text_size` or
        :meth:`line_text` where they do."""
        text = self._text
        return text.decode("ascii") if isinstance(text, bytes) else text

    @property
    def text_size(self) -> int:
        """The characters of :attr:`text` (0 for a document built from lines), without a copy."""
        return len(self._text) if self._text is not None else 0

    def moved(self, path: str) -> Document:
        """This document under another path, sharing everything else as it is (the text, the columns with their
        tables and entry objects, the other items, problems, and lines, endings and items when built): nothing
        copied, nothing read again."""
        doc = object.__new__(type(self))
        for cls in type(self).__mro__:
            for name in getattr(cls, "__slots__", ()):
                setattr(doc, name, getattr(self, name))
        doc.path = path
        return doc

    @property
    def lines(self) -> list[str]:
        if self._lines is None:
            self._lines = _split_lines(self.text or "")
        return self._lines

    @lines.setter
    def lines(self, value: list[str]) -> None:
        self._lines = value
        self.line_count = len(value)
        self._starts = None

    @property
    def endings(self) -> list[str]:
        if self._endings is None:
            text = self._text or ""
            if isinstance(text, bytes):  # the last character, or the whole text when it has a \r
                text = text.decode("ascii") if b"\r" in text else text[-1:].decode("ascii")
            n = self.line_count
            if "\r" not in text:
                self._endings = ["\n"] * n
                if n and not text.endswith("\n"):
                    self._endings[-1] = ""
            else:
                self._endings = [("\r\n" if s.endswith("\r") else "\n") for s in text.split("\n")[:n]]
                if n and not text.endswith("\n"):
                    self._endings[-1] = ""
        return self._endings

    @endings.setter
    def endings(self, value: list[str]) -> None:
        self._endings = value

    @property
    def items(self) -> list[Item]:
        if self._items is None:
            self._items = list(self._stream(True))
        return self._items

    @items.setter
    def items(self, value: list[Item]) -> None:
        self._items = value
        self._columns = None  # built again from these items when asked for

    @property
    def columns(self) -> Columns:
        """The entries as columns (built from ``entries`` for a document the tokenizer did not read)."""
        if self._columns is None:
            self._columns = Columns.of_entries(self.entries)
        return self._columns

    def entry_at(self, row: int) -> Entry:
        """The entry of a row of :attr:`columns`: the same object each time, and the one ``items`` holds."""
        cols = self.columns
        objects = cols.objects
        got = objects.get(row)
        if got is None:
            if len(objects) >= 32 and 4 * len(objects) >= len(cols):  # asked for most rows: all in one pass
                return self._all_rows()[row]
            got = objects[row] = row_readers[0](self, row)
        return got

    def _all_rows(self) -> dict[int, Entry]:
        """Every row's entry, built in one pass (what forcing ``items`` or ``entries`` does)."""
        cols = self.columns
        if len(cols.objects) < len(cols):
            row_readers[1](self)
        return cols.objects

    def item_at(self, line: int) -> Item | None:
        """The item of ``line`` (1-based), without building the others."""
        if self._items is not None or self._columns is None or self._text is None:
            items = self.items
            return items[line - 1] if 1 <= line <= len(items) and items[line - 1].line == line else next(
                (i for i in items if i.line == line), None)
        from bisect import bisect_left  # start-up: only for a finding on a commented-out entry

        slow = self._slow
        at = bisect_left(slow, line, key=_line_of)
        if at < len(slow) and slow[at].line == line:
            return slow[at]
        rows = self._columns.line
        row = bisect_left(rows, line)
        return self.entry_at(row) if row < len(rows) and rows[row] == line else None

    def other_items(self) -> list[Item]:
        """The items that are no row of :attr:`columns` (full-line comments, blank lines, ``Ende``,
        invalid lines, entries after ``Ende``), in line order, without building the rows' entries."""
        if self._items is not None or self._text is None:
            return [i for i in self.items if type(i) is not Entry or i.after_end]
        return [i for i in self._slow if type(i) is not Entry or i.after_end]

    def comments_in_head(self, n: int) -> list[Comment]:
        """The full-line comments among the first ``n`` items (those of ``items[:n]``), without building an
        entry (a list's header comments: reading them built every entry of the list)."""
        if self._items is not None or self._columns is None or self._text is None:
            return [i for i in self.items[:n] if type(i) is Comment]
        others = self.other_items()[:n]
        # the line of the n-th item: the first n of each kind's lines hold the first n of both
        lines = sorted({*self._columns.line[:n], *(o.line for o in others)})[:n]
        last = lines[-1] if lines else 0
        return [c for c in others if type(c) is Comment and c.line <= last]

    def _stream(self, build: bool = False) -> Iterator[Item]:
        """The items in line order, each built when reached (``build``: all at once, first)."""
        if self._items is not None:
            yield from self._items
            return
        cols = self._columns
        slow = self._slow
        if cols is None:
            yield from slow
            return
        at = 0
        count = len(slow)
        objects = self._all_rows() if build else cols.objects
        for row, line in enumerate(cols.line):
            while at < count and slow[at].line < line:
                yield slow[at]
                at += 1
            if at < count and slow[at].line == line:  # an entry read the careful way
                yield slow[at]
                at += 1
            else:
                yield objects.get(row) or self.entry_at(row)
        yield from slow[at:]

    @property
    def entries(self) -> list[Entry]:
        """The entries the controller reads (before ``Ende``)."""
        if self._items is None and self._columns is not None:
            objects = self._all_rows()
            return list(map(objects.__getitem__, range(len(self._columns))))
        return [i for i in self.items if type(i) is Entry and not i.after_end]

    @property
    def newline(self) -> str:
        """The dominant line ending ("\\n" when the file has none)."""
        text = self._text
        if self._endings is None and text is not None:
            if isinstance(text, bytes):
                crlf = text.count(b"\r\n")
                lf = text.count(b"\n") - crlf
            else:
                crlf = text.count("\r\n")
                lf = text.count("\n") - crlf
        else:
            crlf = sum(1 for e in self.endings if e == "\r\n")
            lf = sum(1 for e in self.endings if e == "\n")
        return "\r\n" if crlf > lf else "\n"

    def line_text(self, line: int) -> str:
        if not 1 <= line <= self.line_count:
            return ""
        if self._lines is not None or self._text is None:
            return self.lines[line - 1]
        text = self._text
        if isinstance(text, bytes):
            return self._byte_line(text, line)
        if self._starts is None:
            if line <= 64:  # a line near the top (the kind an XML list's comments declare): no index of all
                at = 0
                for _ in range(line - 1):
                    at = text.find("\n", at) + 1
                end = text.find("\n", at)
                got = text[at:] if end < 0 else text[at:end]
                return got[:-1] if end >= 0 and got.endswith("\r") else got
            self._starts = _line_starts(text)
        got = text[self._starts[line - 1]:self._starts[line] - 1]
        return got[:-1] if got.endswith("\r") and self._starts[line] <= len(text) else got

    def _byte_line(self, data: bytes, line: int) -> str:
        """:meth:`line_text` of a document holding the bytes of an ASCII text."""
        if self._starts is None:
            if line <= 64:
                at = 0
                for _ in range(line - 1):
                    at = data.find(b"\n", at) + 1
                end = data.find(b"\n", at)
                got = data[at:] if end < 0 else data[at:end]
                return (got[:-1] if end >= 0 and got.endswith(b"\r") else got).decode("ascii")
            self._starts = _line_starts(data)
        got = data[self._starts[line - 1]:self._starts[line] - 1]
        return (got[:-1] if got.endswith(b"\r") and self._starts[line] <= len(data) else got).decode("ascii")

    def holds_xml_lines(self) -> bool:
        """Was this list text written from an XML list (do its first comment lines hold the XML lines,
        `# <?xml …`, `# <AX_MDS>`)? It is then written back as that XML, and its root says its kind."""
        for item in self._stream():
            if type(item) is Blank:
                continue
            line = self.line_text(item.line)
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
        for seen, item in enumerate(i for i in self._stream() if type(i) is not Blank):  # outside XML comments
            if type(item) is not Comment or seen > 64:  # (`<AX_MDS>` inside `<!-- … -->` is none)
                break
            line = self.line_text(item.line)
            held.append(line[2:] if line.startswith("# ") else line[1:])
        root = root_of("\n".join(held).encode("utf-8", "surrogateescape"))
        return XML_ROOTS.get(root) if root is not None else None

    def file_line(self, line: int) -> int:
        """A line of this list as the line of the file that holds it (an XML list, a TwinCAT export)."""
        return self.origin.locate(line, 1)[0] if self.origin is not None else line

    def has_line(self, line: int) -> bool:
        return 1 <= line <= self.line_count


_STARTS_STEP = 1 << 20  # characters split at a time for the index of line starts


def _line_starts(text: str | bytes) -> MutableSequence[int]:
    """Where each line of a text starts (then one past the end, as ``text.split("\\n")`` counts them), split
    a part at a time: a big list's lines are never all objects at once (a 60 MB list: 75 MB for a moment), and
    kept in an array (a small list's in a list: no shared library loaded for it)."""
    nl: Any = b"\n" if isinstance(text, bytes) else "\n"
    starts: MutableSequence[int] = [0]
    if len(text) > _STARTS_STEP:
        from array import array  # start-up: a big list's only

        starts = array("q", starts)
    pos = 0
    while True:
        end = text.find(nl, pos + _STARTS_STEP)
        part = text[pos:] if end < 0 else text[pos:end]  # a part's last line ends at the \n after it
        ends = accumulate(map((1).__add__, map(len, part.split(nl))), initial=starts[-1])
        next(ends)  # the initial value: the part's start, there already
        starts.extend(ends)
        if end < 0:
            return starts
        pos = end + 1


def _line_of(item: Item) -> int:
    return item.line


def _split_lines(text: str) -> list[str]:
    """The lines of a text without their endings (as :func:`zero.lists.tokenizer.split_lines`)."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
        if "\r" in text:
            return [s[:-1] if s.endswith("\r") else s for s in lines]
        return lines
    if "\r" in text:
        return [s[:-1] if s.endswith("\r") else s for s in lines[:-1]] + lines[-1:]
    return lines


class Excerpt(Document):
    """A document reduced to the lines its findings show: what a report of many files keeps of
    each, so that memory grows with the findings, not with the files' lines."""

    __slots__ = ("shown",)
    __record_fields__ = tuple(_F(n) for n in (*_DOC_FIELDS, "shown"))

    def __init__(self, path: str, encoding: str, lines: list[str] | None, endings: list[str] | None,
                 items: list[Item] | None, problems: list[Problem] | None = None, bom: bool = False,
                 end_line: int | None = None, origin: Origin | None = None,
                 shown: dict[int, str] | None = None) -> None:
        super().__init__(path, encoding, lines, endings, items, problems, bom, end_line, origin)
        self.shown = shown if shown is not None else {}

    def line_text(self, line: int) -> str:
        return self.shown.get(line, "")

    def has_line(self, line: int) -> bool:
        return line in self.shown

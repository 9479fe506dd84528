"""XML read safely, with the exact place of every tag, attribute value and CDATA section.

Two passes over one file. The hardened parser (:mod:`defusedxml`, over the standard library's
expat) decides whether the file is XML zero will read at all: well-formed, no DTD, no entity
declarations, no external references — so a billion-laughs file or an external entity that
names ``/etc/passwd`` is refused before anything is expanded or opened. It also gives each
attribute's value as XML means it (entities and character references decoded, whitespace
normalised). The second pass is a scanner over the decoded text that only this module trusts,
because the first pass has proved the text well-formed: it finds where each start tag, its
``Value`` attribute and each CDATA section sit, to the character, so that findings point at the
file the user has open and a rewrite changes only the bytes it means to.

Every refusal is a :class:`~zero.errors.ZeroError` with line and column; nothing else escapes.
"""

from __future__ import annotations

import bisect
import itertools
import re
import xml.sax
from xml.sax.handler import ContentHandler
from xml.sax.xmlreader import AttributesImpl, Locator

import defusedxml
import defusedxml.expatreader

from zero.errors import ZeroError
from zero.lists.encoding import BOM, declarable
from zero.records import Record, field

_DECL_RE = re.compile(rb"""<\?xml[^>]*?encoding\s*=\s*["']([A-Za-z0-9._-]+)["']""")
_TOKEN_RE = re.compile(
    r"<!--.*?-->"  # a comment
    r"|<!\[CDATA\[(?P<cdata>.*?)\]\]>"  # a CDATA section
    r"|<\?.*?\?>"  # the declaration, a processing instruction
    r"|<(?P<close>/)?(?P<name>[^\s/>!?]+)(?P<attrs>(?:\s+[^\s=/>]+\s*=\s*(?:\"[^\"]*\"|'[^']*'))*)\s*(?P<empty>/)?>",
    re.S)
_BREAK_RE = re.compile(rb"\r\n?|\n")  # a line break as expat counts lines
_ATTR_RE = re.compile(r"""([^\s=/>]+)\s*=\s*(?:"([^"]*)"|'([^']*)')""")


class Tag(Record, eq=False):
    """A start tag (or empty-element tag) as written: where it is and what XML says it holds."""

    name: str
    attrs: dict[str, str]  # decoded, as XML means them
    start: int  # offset of `<` in the decoded text
    end: int  # offset after `>`
    depth: int  # 0 for the root element
    empty: bool  # `<name ... />`
    raw: dict[str, tuple[int, int]] = field(default_factory=dict)  # attribute → span of its value as written


class Cdata(Record, eq=False):
    """A CDATA section: its content's span in the decoded text, and the element that holds it."""

    parent: str
    start: int
    end: int


class Scan(Record, eq=False):
    """An XML file as zero reads it."""

    text: str  # decoded, without the byte order mark
    encoding: str  # the Python codec that writes ``text`` back byte for byte
    bom: bool
    root: str
    tags: list[Tag]
    cdata: list[Cdata]
    line_starts: list[int]

    def position(self, offset: int) -> tuple[int, int]:
        """1-based line and column of a character offset."""
        return _position(self.line_starts, offset)


def _position(line_starts: list[int], offset: int) -> tuple[int, int]:
    line = bisect.bisect_right(line_starts, offset)
    return line, offset - line_starts[line - 1] + 1


class _Collect(ContentHandler):
    def __init__(self) -> None:
        super().__init__()
        self.elements: list[tuple[str, dict[str, str]]] = []
        self.locator: Locator | None = None

    def setDocumentLocator(self, locator: Locator) -> None:
        self.locator = locator

    def startElement(self, name: str, attrs: AttributesImpl) -> None:
        self.elements.append((name, dict(attrs.items())))


def encoding_of(data: bytes) -> tuple[str, bool]:
    """The codec the declaration (or the byte order mark) names; UTF-8 when none does."""
    if data.startswith(BOM):
        return "utf-8", True
    m = _DECL_RE.match(data.lstrip()[:200]) if data.lstrip().startswith(b"<?xml") else None
    if m is None:
        return "utf-8", False
    name = m.group(1).decode("ascii")
    try:  # a code page zero writes back byte for byte (as a list's declared encoding)
        return declarable(name), False
    except ValueError as exc:
        raise ZeroError(f"the XML declaration names the encoding `{name}`: {exc}", "", 1, 1) from None


def _line_starts(text: str) -> list[int]:
    starts = [0]
    find = text.find
    at = find("\n")
    while at >= 0:
        starts.append(at + 1)
        at = find("\n", at + 1)
    return starts


def scan(data: bytes, path: str = "-") -> Scan:
    """Read XML bytes safely; :class:`ZeroError` (located) for anything zero will not read."""
    handler = _Collect()
    _parse(data, path, handler)
    try:
        encoding, bom = encoding_of(data)
    except ZeroError as exc:
        raise ZeroError(exc.message, path, exc.line, exc.column) from None
    body = data[3:] if bom else data
    text = body.decode(encoding, "surrogateescape")
    starts = _line_starts(text)
    tags: list[Tag] = []
    cdata: list[Cdata] = []
    stack: list[str] = []
    for m in _TOKEN_RE.finditer(text):
        name = m.group("name")
        if m.group("cdata") is not None:
            cdata.append(Cdata(stack[-1] if stack else "", m.start("cdata"), m.end("cdata")))
            continue
        if name is None:
            continue
        if m.group("close"):
            if stack:
                stack.pop()
            continue
        raw: dict[str, tuple[int, int]] = {}
        base = m.start("attrs")
        for a in _ATTR_RE.finditer(m.group("attrs") or ""):
            group = 2 if a.group(2) is not None else 3
            raw[a.group(1)] = (base + a.start(group), base + a.end(group))
        index = len(tags)
        if index >= len(handler.elements) or handler.elements[index][0] != name:
            line, col = _position(starts, m.start())
            raise ZeroError(f"zero cannot follow the tag `<{name}>` here", path, line, col)
        empty = m.group("empty") is not None
        tags.append(Tag(name, handler.elements[index][1], m.start(), m.end(), len(stack), empty, raw))
        if not empty:
            stack.append(name)
    root = tags[0].name if tags else ""
    return Scan(text, encoding, bom, root, tags, cdata, starts)


def _relocate(data: bytes, line: int | None, column: int | None) -> tuple[int | None, int | None]:
    """Expat's line and column (a line ends at CR LF, CR or LF) as zero's (a line ends at LF): the
    same place in a file with lone CRs, which is one line for zero (S014 never past the last line)."""
    if line is None or column is None or line < 2 or b"\r" not in data:
        return line, column
    found = next(itertools.islice(_BREAK_RE.finditer(data), line - 2, None), None)
    if found is None:
        return line, column
    at = found.end()
    if data[at - 1:at] == b"\n":  # the same line for both
        return data.count(b"\n", 0, at) + 1, column
    start = data.rfind(b"\n", 0, at) + 1
    return data.count(b"\n", 0, at) + 1, len(data[start:at].decode("utf-8", "replace").lstrip("\ufeff")) + column


class _Lean(defusedxml.expatreader.DefusedExpatParser):
    """The hardened parser without content handlers: expat checks a whole file (a TwinCAT project of
    tens of MB) at its own speed, while the guards against DTDs, entities and external references stay."""

    def reset(self) -> None:
        super().reset()
        for name in ("StartElementHandler", "EndElementHandler", "CharacterDataHandler",
                     "ProcessingInstructionHandler", "CommentHandler"):
            setattr(self._parser, name, None)  # type: ignore[attr-defined]


def check(data: bytes, path: str = "-") -> None:
    """Is ``data`` XML zero reads (well-formed, no DTD, entities or external references)? Nothing is
    collected (:mod:`zero.markup.tsproj` locates what it needs); :class:`ZeroError` (located) if not."""
    _parse(data, path, _Collect(), lean=True)


def _parse(data: bytes, path: str, handler: _Collect, lean: bool = False) -> None:
    kind = _Lean if lean else defusedxml.expatreader.DefusedExpatParser
    parser = kind(forbid_dtd=True, forbid_entities=True, forbid_external=True)
    parser.setContentHandler(handler)
    parser.setFeature(xml.sax.handler.feature_external_ges, False)
    parser.setFeature(xml.sax.handler.feature_external_pes, False)

    def where() -> tuple[int | None, int | None]:
        loc = handler.locator
        if loc is None:
            return None, None
        return _relocate(data, loc.getLineNumber(), (loc.getColumnNumber() or 0) + 1)

    def first(marker: bytes) -> tuple[int | None, int | None]:
        """Where ``marker`` first occurs (the declaration the hardened parser refused)."""
        at = data.find(marker)
        if at < 0:
            return where()
        start = data.rfind(b"\n", 0, at) + 1
        return data.count(b"\n", 0, at) + 1, len(data[start:at].decode("utf-8", "replace").lstrip("\ufeff")) + 1

    try:
        parser.feed(data)
        parser.close()
    except defusedxml.DTDForbidden:
        line, col = first(b"<!DOCTYPE")
        raise ZeroError("the file declares a document type (DTD); zero does not read XML with a DTD "
                        "(a parameter list has none, and a DTD can expand or fetch text)", path, line, col) from None
    except defusedxml.EntitiesForbidden as exc:
        line, col = first(b"<!ENTITY")
        raise ZeroError(f"the file declares the entity `{exc.name}`; zero does not expand entities "
                        "(a parameter list has none, and entities can expand without bound)", path, line, col) from None
    except defusedxml.ExternalReferenceForbidden:
        line, col = where()
        raise ZeroError("the file refers to an external resource; zero never opens one", path, line, col) from None
    except xml.sax.SAXParseException as exc:
        message = str(exc.getMessage())
        opened, closed = data.rfind(b"<![CDATA["), data.rfind(b"]]>")
        if opened > closed and "unclosed" in message:  # the file ends inside a CDATA section: where it opens
            start = data.rfind(b"\n", 0, opened) + 1
            raise ZeroError("not well-formed XML: a CDATA section is never closed (`]]>` is missing)", path,
                            data.count(b"\n", 0, opened) + 1,
                            len(data[start:opened].decode("utf-8", "replace").lstrip("\ufeff")) + 1) from None
        line, col = _relocate(data, exc.getLineNumber(), (exc.getColumnNumber() or 0) + 1)
        raise ZeroError(f"not well-formed XML: {message}", path, line, col) from None
    except (ValueError, LookupError, UnicodeError) as exc:  # an encoding expat cannot read
        raise ZeroError(f"not readable as XML: {exc}", path, 1, 1) from None

"""Positions between zero and an editor, and the text an editor holds as the bytes zero lints.

zero counts 1-based lines and code points; the client counts 0-based lines in UTF-16 code
units (or UTF-8/UTF-32, as negotiated). :class:`Text` converts both ways. ``file:`` URIs and
paths are converted by :func:`path_of` and :func:`uri_of`.
"""

from __future__ import annotations

import os
import re
from pathlib import Path
from urllib.parse import unquote, urlparse
from urllib.request import url2pathname

from zero.diagnostics import Span
from zero.errors import ZeroError
from zero.files import read_file
from zero.lists.encoding import decode


def path_of(uri: str) -> Path | None:
    """The file a ``file:`` URI names; ``None`` for any other scheme (``untitled:``), and for a URI no
    file system can name (a NUL byte in it: the document is then checked as an untitled one)."""
    parsed = urlparse(uri)
    if parsed.scheme != "file":
        return None
    local = url2pathname(unquote(parsed.path))
    if "\x00" in local or "\x00" in parsed.netloc:
        return None
    if parsed.netloc and parsed.netloc != "localhost":
        local = f"//{parsed.netloc}{local}"
    return Path(local)


def uri_of(path: Path) -> str:
    return Path(os.path.abspath(path)).as_uri()


def _units(text: str, encoding: str) -> int:
    if text.isascii():
        return len(text)
    if encoding == "utf-8":
        return len(text.encode("utf-8", "surrogatepass"))
    if encoding == "utf-32":
        return len(text)
    return len(text) + sum(1 for ch in text if ord(ch) > 0xFFFF)


class Text:
    """A document's text as zero splits it into lines, and positions in the client's units."""

    def __init__(self, text: str, encoding: str = "utf-16") -> None:
        self.source = text
        self.encoding = encoding
        self.lines = [line[:-1] if line.endswith("\r") else line for line in text.split("\n")]
        self.bom = text.startswith("\ufeff")  # zero reads past a BOM: line 1 starts one later

    def line(self, index: int) -> str:
        """The text of 0-based line ``index`` ("" beyond the end)."""
        return self.lines[index] if 0 <= index < len(self.lines) else ""

    def character(self, line: int, column: int) -> int:
        """Client units of 0-based code-point ``column`` on 0-based ``line`` (clamped to the line)."""
        text = self.line(line)
        if line == 0 and self.bom:
            column += 1
        return _units(text[: max(0, min(column, len(text)))], self.encoding)

    def column(self, line: int, character: int) -> int:
        """The 0-based code-point column of a client position (as zero counts it)."""
        text = self.line(line)
        if text.isascii() and not (line == 0 and self.bom):
            return min(character, len(text))
        units = 0
        col = 0
        for ch in text:
            if units >= character:
                break
            units += _units(ch, self.encoding)
            col += 1
        if line == 0 and self.bom:
            col = max(0, col - 1)
        return col

    def position(self, line: int, column: int) -> tuple[int, int]:
        """A zero position (1-based line and column) as a client (line, character)."""
        line = max(1, min(line, len(self.lines)))
        return line - 1, self.character(line - 1, column - 1)

    def span(self, span: Span) -> tuple[tuple[int, int], tuple[int, int]]:
        start = self.position(span.line, span.column)
        end = self.position(span.end_line, span.end_column)
        return start, max(start, end)

    def end(self) -> tuple[int, int]:
        """The position after the last character."""
        last = len(self.lines) - 1
        return last, _units(self.lines[last], self.encoding)


_NOT_A_BYTE = re.compile(r"[\ud800-\udc7f\udd00-\udfff]")


_XML_ENCODING = re.compile(r"""<\?xml[^>]*?encoding\s*=\s*["']([A-Za-z0-9._-]+)["']""")


def encode_text(text: str, encoding: str | None = None) -> bytes:
    """The editor's text as the bytes zero lints: UTF-8 (or the code page the configuration declares
    for the file, or an XML text's declaration names, where the text fits it), with the bytes the
    client could not decode (``\udc80``–``\udcff``, as zero and the server's input keep them) as they
    were, so that zero reports them (S007) where they are; any other lone surrogate becomes `?`."""
    if encoding is None and text.lstrip("\ufeff").startswith("<?xml"):  # XML says its own encoding
        m = _XML_ENCODING.match(text.lstrip("\ufeff"))
        encoding = m.group(1) if m is not None else None
    if encoding is not None:
        try:
            return text.encode(encoding)
        except (UnicodeEncodeError, LookupError):
            pass
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError:
        return _NOT_A_BYTE.sub("?", text).encode("utf-8", "surrogateescape")


def source_bytes(path: Path | None, text: str, encoding: str | None = None) -> tuple[bytes, bool]:
    """The bytes to lint and whether they are the file's own: the file when the editor's text
    is the file as zero decodes it (so its encoding and endings count as on the command line),
    else the editor's text. ``encoding``: the code page the configuration declares for the file
    (a CP850 list the editor shows right is read, and its unsaved text written, in CP850)."""
    disk = None
    if path is not None:
        try:
            size = os.stat(path).st_size
            disk = read_file(path) if size <= 4 * len(text) + 8 else None  # far larger: not this text
        except (OSError, ZeroError):
            disk = None
        if disk is not None and decode(disk, encoding)[0] == text:
            return disk, True
    data = encode_text(text, encoding)
    return data, data == disk

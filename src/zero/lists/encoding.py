"""The encodings a list may have: read as found, written back byte for byte.

A list is UTF-8 (with or without BOM), else Windows-1252, else Latin-1. Bytes that
are not valid in the file's encoding are kept as lone surrogates
(``surrogateescape``), so decoding and encoding again gives the same bytes.
"""

from __future__ import annotations

from zero.lists.model import Document

BOM = b"\xef\xbb\xbf"


def decode(data: bytes) -> tuple[str, str, bool]:
    """Decode list bytes; return ``(text, encoding, bom)``.

    ``encoding`` is the Python codec that writes the text back byte for byte
    (with ``errors="surrogateescape"`` for ``utf-8`` files that hold stray bytes).
    """
    if data.startswith(BOM):
        return data[3:].decode("utf-8", "surrogateescape"), "utf-8", True
    try:
        return data.decode("utf-8"), "utf-8", False
    except UnicodeDecodeError:
        pass
    text = data.decode("utf-8", "surrogateescape")
    if len(text) < len(data):
        # Real UTF-8 sequences next to stray bytes: a file of mixed encodings. (ASCII and each stray
        # byte give one character per byte; only a real sequence of 2 to 4 bytes gives one for more.)
        return text, "utf-8", False
    try:
        return data.decode("cp1252"), "cp1252", False
    except UnicodeDecodeError:
        return data.decode("latin-1"), "latin-1", False


def document_bytes(doc: Document, lines: list[str] | None = None) -> bytes:
    """A document's text back to bytes: its encoding, BOM and per-line endings."""
    lines = doc.lines if lines is None else lines
    text = "".join(line + end for line, end in zip(lines, doc.endings, strict=True))
    data = text.encode(doc.encoding, "surrogateescape")
    return (BOM + data) if doc.bom else data

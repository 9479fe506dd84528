"""The encodings a list may have: read as found (or as declared), written back byte for byte.

A list is UTF-8 (with or without BOM), else Windows-1252, else Latin-1. Bytes that
are not valid in the file's encoding are kept as lone surrogates
(``surrogateescape``), so decoding and encoding again gives the same bytes.

A configuration may declare a list's code page (``encoding`` in ``[tool.zero]``, e.g.
``cp850`` for lists written on DOS tools); the declared codec then decodes the file
instead of the detection. :func:`declarable` says which codecs may be declared: UTF-8,
and single-byte codecs that read ASCII as ASCII (one byte, one character, each way).
"""

from __future__ import annotations

import codecs
import functools

from zero.errors import ZeroError
from zero.lists.model import Document

BOM = b"\xef\xbb\xbf"
# How zero names the codecs it also detects (``codecs.lookup`` says ``iso8859-1``).
_OWN_NAMES = {"iso8859-1": "latin-1", "utf-8-sig": "utf-8"}
# Bytes whose meaning a codec could make depend on its neighbours (UTF-7's `+…-`, the `\u` of the
# escape codecs, an ISO-2022 escape): decoded together they must give what they give one by one.
_PROBE = bytes(range(256)) + b"\\u00e4\\U000000e4+AOQ-~{~}\x1b$B\x1b(B"


@functools.lru_cache(maxsize=64)
def declarable(name: str) -> str:
    """The codec a configuration may declare for a list, by the name zero records (``cp850``,
    ``utf-8``, ``latin-1``); :class:`ValueError` saying why for any other name."""
    try:
        info = codecs.lookup(name)
    except (LookupError, TypeError, ValueError):
        raise ValueError(f"{name!r} is not a codec Python knows (e.g. \"cp850\", \"cp1252\", \"utf-8\")") from None
    canonical = _OWN_NAMES.get(info.name, info.name)
    if canonical == "utf-8":
        return canonical
    refusal = (f"{name!r} cannot hold a parameter list: zero reads UTF-8 or a single-byte code page that "
               "reads ASCII as ASCII (cp850, cp437, cp1252, latin-1, ...), not UTF-16/32 or other multi-byte "
               "or escape codecs")
    if not getattr(info, "_is_text_encoding", True):
        raise ValueError(refusal)
    try:
        for b in range(256):
            one = bytes([b])
            ch = info.decode(one, "surrogateescape")[0]
            if len(ch) != 1 or (b < 0x80 and ch != chr(b)) or info.encode(ch, "surrogateescape")[0] != one:
                raise ValueError(refusal)
        whole = info.decode(_PROBE, "surrogateescape")[0]
        if whole != "".join(info.decode(bytes([b]), "surrogateescape")[0] for b in _PROBE):
            raise ValueError(refusal)
    except (UnicodeError, LookupError, TypeError):
        raise ValueError(refusal) from None
    return canonical


def decode(data: bytes, declared: str | None = None) -> tuple[str, str, bool]:
    """Decode list bytes; return ``(text, encoding, bom)``.

    ``encoding`` is the Python codec that writes the text back byte for byte
    (with ``errors="surrogateescape"`` for files that hold stray bytes). ``declared``
    (a name :func:`declarable` accepts) decodes the file instead of the detection; a byte
    it does not define is kept as a stray byte.
    """
    if declared is not None:
        codec = declarable(declared)
        if codec == "utf-8" and data.startswith(BOM):
            return data[3:].decode("utf-8", "surrogateescape"), codec, True
        return data.decode(codec, "surrogateescape"), codec, False
    if data.startswith(BOM):
        return data[3:].decode("utf-8", "surrogateescape"), "utf-8", True
    try:
        return data.decode("utf-8"), "utf-8", False
    except UnicodeDecodeError as exc:
        valid = exc.start  # the bytes before the first stray byte are UTF-8
    # Real UTF-8 sequences next to stray bytes: a file of mixed encodings. (ASCII and each stray byte give one
    # character per byte; only a real sequence of 2 to 4 bytes gives one for more.) The valid bytes hold one
    # unless they are ASCII; the rest is decoded on its own (a sequence never spans the first stray byte): a
    # list that is no UTF-8 is decoded from there only, and searched for C1 bytes from there only (a 40 kB list
    # with a `µ` 30 kB in: 0.3 M instructions fewer).
    if not data[:valid].isascii() or len(data[valid:].decode("utf-8", "surrogateescape")) < len(data) - valid:
        return data.decode("utf-8", "surrogateescape"), "utf-8", False
    if _no_c1(data, valid):  # where CP1252 is Latin-1: the built-in codec decodes it (no codec module imported)
        return data.decode("latin-1"), "cp1252", False
    try:
        return data.decode("cp1252"), "cp1252", False
    except UnicodeDecodeError:
        return data.decode("latin-1"), "latin-1", False


_C1_BYTES = range(0x80, 0xA0)  # where CP1252 differs from Latin-1 (bytes.find takes a byte's value)
_PART = 1 << 18


def _no_c1(data: bytes, start: int = 0) -> bool:
    """Does ``data`` lack every byte from 0x80 to 0x9F (from ``start`` on)? A search for each (memchr) in each
    part of the data."""
    find = data.find
    return not any(find(c, at, at + _PART) >= 0 for at in range(start, len(data), _PART) for c in _C1_BYTES)


def encode_text(text: str, encoding: str, bom: bool = False, path: str = "-") -> bytes:
    """List text (written from YAML, TOML or JSON, or formatted) as the bytes of a list in
    ``encoding``; :class:`ZeroError` for a codec zero does not write or a character it lacks."""
    try:
        codec = declarable(encoding)
    except ValueError as exc:
        raise ZeroError(f"encoding {encoding!r} is not one zero writes: {exc}", path) from None
    try:
        data = text.encode(codec)
    except UnicodeEncodeError as exc:
        line = text.count("\n", 0, exc.start) + 1
        raise ZeroError(f"character {text[exc.start]!r} cannot be written in {codec}", path, line) from None
    return (BOM + data) if bom else data


def document_bytes(doc: Document, lines: list[str] | None = None) -> bytes:
    """A document's text back to bytes: its encoding, BOM and per-line endings."""
    lines = doc.lines if lines is None else lines
    text = "".join(line + end for line, end in zip(lines, doc.endings, strict=True))
    data = text.encode(doc.encoding, "surrogateescape")
    return (BOM + data) if doc.bom else data


def foreign_control(doc: Document) -> tuple[int, int, str] | None:
    """The first C1 control (U+0080 to U+009F) of a list read in a single-byte code page, as
    ``(line, 0-based column, byte)``: what a byte of another code page (CP850's 0x81 `ü`) becomes
    when the list is read as Latin-1. ``None`` for a list without one, or read as UTF-8."""
    if doc.encoding == "utf-8":
        return None
    for number, line in enumerate(doc.lines, 1):
        if line.isascii():
            continue
        for column, ch in enumerate(line):
            if "\x80" <= ch <= "\x9f":
                return number, column, ch.encode(doc.encoding, "surrogateescape").hex().upper()
    return None

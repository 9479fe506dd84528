"""The XML forms of a list: the kernel's XML lists and update files, and TwinCAT's exports.

``safe`` reads XML with a hardened parser and the exact place of every tag; ``lists`` turns an
XML list into the list text every rule reads (and back); ``documents`` reads an XML file as the
document model, finds the lists a TwinCAT export holds in its CDATA sections (and splices them
back), and places findings in the XML file. :func:`read_document` here is the one reader of a list
file's bytes, whatever the form.
"""

from __future__ import annotations

from zero.forms import is_xml
from zero.lists.model import Document
from zero.lists.tokenizer import tokenize

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from zero.catalog.registry import Registry


def read_document(data: bytes, path: str, registry: Registry, encoding: str | None = None,
                  objects: bool = False) -> Document:
    """A list file's bytes as the document model, whatever its form: an ASCII list tokenized as it is
    (in ``encoding``, the code page declared for it), XML read by :mod:`zero.markup.documents` — which,
    with the hardened parser, loads only when the bytes are XML (an ASCII list's start-up pays nothing).
    ``objects``: the caller reads every item (see :func:`~zero.lists.tokenizer.tokenize_text`)."""
    if not is_xml(data):
        return tokenize(data, path, encoding, objects)
    from zero.markup.documents import read_xml  # start-up: only for XML

    return read_xml(data, path, registry)


__all__ = ["read_document"]

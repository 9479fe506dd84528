"""``zero format``: a list in canonical layout, meaning kept.

Values aligned in one column, comments in another, no trailing whitespace; keys,
values, comments and their order stay, and so do the encoding and line endings (a list in a
code page the configuration declares, e.g. CP850, stays in it byte for byte).
"""

from __future__ import annotations

from zero.catalog.registry import Registry
from zero.errors import ZeroError
from zero.forms import PROJECT_ROOTS, TWINCAT_ROOT, XML_ROOTS, is_xml
from zero.lists.encoding import encode_text, foreign_control
from zero.lists.model import Document
from zero.lists.tokenizer import tokenize
from zero.structured.tree import DEFAULT_VALUE_COLUMN, from_document, to_list_text

COMMENT_OFFSET = 15  # comments start this many columns after the value column


def undeclared_code_page(doc: Document, why: str) -> None:
    """:class:`ZeroError` for a list that holds a C1 control (a byte of another code page read as
    Latin-1), saying ``why`` it cannot go on and that declaring the code page reads it right."""
    found = foreign_control(doc)
    if found is None:
        return
    line, column, byte = found
    code = ord(doc.lines[line - 1][column])
    raise ZeroError(f"byte 0x{byte} reads as control character U+{code:04X} in {doc.encoding}: {why}; a list "
                    "written in another code page (CP850: 0x81 is `ü`) is read right when the configuration "
                    'declares it, e.g. encoding = {"old/**/*.lis" = "cp850"}', doc.path, line, column + 1)


def format_bytes(data: bytes, path: str, registry: Registry, value_column: int | None = None,
                 encoding: str | None = None) -> bytes:
    """The list in canonical layout: values aligned in one column (the vendor's column 55, or
    after the longest key), comments 15 columns after it (one space after a longer value), no
    trailing whitespace; order, values, comments, encoding and line endings kept. Earlier lines
    of a key set twice stay as written. :class:`~zero.errors.ZeroError` for lines it cannot
    read (the registry only tells which values are numbers). ``encoding``: the code page the
    configuration declares for the list (``None``: detected). An XML list keeps its layout (the
    vendor's XML is its own canonical form: nothing changes); the lists of a TwinCAT export are
    formatted inside their CDATA sections, every byte outside them kept."""
    if is_xml(data):
        return _format_xml(data, path, registry, value_column)
    doc = tokenize(data, path, encoding)
    undeclared_code_page(doc, "zero format cannot lay out a line that holds it")
    tree = from_document(doc, registry)
    meta = tree.meta
    # A key written with whitespace inside means something else to the controller (S004):
    # format keeps such a line as it is; `zero lint --fix` joins the key.
    layout = meta.pop("layout", {})
    kept = {k: t for k, t in layout.items() if any(c in t.partition("{v}")[0].strip() for c in " \t")}
    if kept:
        meta["layout"] = kept
    for key in ("before", "tail"):
        meta.pop(key, None)
    if isinstance(meta.get("end"), str) and meta["end"]:
        meta["end"] = meta["end"].strip()
    if isinstance(meta.get("after_end"), list):
        meta["after_end"] = [x.rstrip() for x in meta["after_end"]]
    widest = max((len(leaf.key) for leaf in tree.leaves), default=0)
    column = value_column if value_column is not None else DEFAULT_VALUE_COLUMN
    if widest >= column:
        column = widest + 1
    meta["value_column"] = column
    if any(leaf.after is not None for leaf in tree.leaves):
        meta["comment_column"] = column + COMMENT_OFFSET  # the vendor's 55 / 70
    else:
        meta.pop("comment_column", None)
    text = to_list_text(tree).text
    return encode_text(text, doc.encoding, doc.bom, path)


def _format_xml(data: bytes, path: str, registry: Registry, value_column: int | None) -> bytes:
    from zero.markup.documents import embedded_documents, list_text, splice  # start-up: only for XML
    from zero.markup.safe import scan  # start-up: as above

    sc = scan(data, path)
    if sc.root != TWINCAT_ROOT and sc.root not in PROJECT_ROOTS:  # not an export or a project
        if sc.root not in XML_ROOTS:
            raise ZeroError(f"the root element `<{sc.root}>` is not that of a parameter list", path, 1, 1)
        return data
    _, lists = embedded_documents(data, path, sc)
    texts = [(item, format_bytes(list_text(item), path, registry, value_column, item.doc.encoding)
              .decode(item.doc.encoding, "surrogateescape")) for item in lists]
    return splice(sc, path, texts)

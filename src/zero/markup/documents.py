"""Any file that holds a list, read as the one document model every rule and command uses.

:func:`read_document` is the one reader of a list file's bytes: an ASCII list is tokenized as it
is; an XML list (recognised by its content, never by its name) is read as the list text of
:mod:`zero.markup.lists` with an :class:`~zero.lists.model.Origin` that maps each line back;
a TwinCAT export holds several lists (:func:`embedded_documents`). :func:`relocate` moves a
finding on such a document, and its fix, to the file the user has open.
"""

from __future__ import annotations

import re

from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic, Edit, Fix, Related, Span
from zero.errors import ZeroError
from zero.forms import (
    EMBEDDED,
    TWINCAT,
    TWINCAT_ROOT,
    XML_LIST,
    XML_ROOTS,
    is_update,
    is_xml,
    root_of,
    split_part,
    xml_form,
)
from zero.lists.model import Document, Origin
from zero.lists.tokenizer import tokenize, tokenize_text
from zero.markup.lists import escape, to_list
from zero.markup.safe import BOM, Scan, scan

__all__ = ["EMBEDDED", "TWINCAT", "TWINCAT_ROOT", "XML_LIST", "Embedded", "embedded_documents", "is_update", "is_xml",
           "put_back", "read_document", "relocate", "root_of", "shown_document", "xml_document", "xml_form"]
from zero.records import record, replace

_LINE_RE = re.compile(r"\bline (\d+)\b")


def xml_document(data: bytes, path: str, registry: Registry, parsed: Scan | None = None) -> Document:
    """An XML list as the document model: its list text, with the way back to the XML lines."""
    sc = parsed if parsed is not None else scan(data, path)
    if sc.root not in XML_ROOTS:
        raise ZeroError(f"the root element `<{sc.root}>` is not {_roots_said()}", path, 1, 1)
    text, origin, kind = to_list(data, registry, path, sc)
    origin.kind = kind
    origin.update = is_update(path)
    origin.default_list = sc.root.startswith("Default_")
    doc = tokenize_text(text, path, sc.encoding, sc.bom)
    doc.origin = origin
    return doc


def _roots_said() -> str:
    return "the root of a parameter list in XML (" + ", ".join(f"`<{r}>`" for r in XML_ROOTS) + ")"


def read_document(data: bytes, path: str, registry: Registry, encoding: str | None = None) -> Document:
    """A list file's bytes as the document model, whatever its form; :class:`ZeroError` (located)
    for XML zero will not read, and for a TwinCAT export (it holds several lists: see
    :func:`embedded_documents`). ``encoding``: the code page declared for an ASCII list."""
    if not is_xml(data):
        return tokenize(data, path, encoding)
    file, element = split_part(path)
    if xml_form(data) == TWINCAT:  # `export.xml#NullpD`, or the one list an export holds
        _, lists = embedded_documents(data, file)
        hits = [x for x in lists if element is None or x.element == element]
        if len(hits) != 1:
            held = ", ".join(x.element for x in lists) or "none"
            raise ZeroError(f"a TwinCAT export holding {held}: name the list meant (`--item`, or "
                            "`export.xml#Element` for a machine)", file, 1, 1)
        return hits[0].doc
    return xml_document(data, path, registry)


@record(eq=False)
class Embedded:
    """A list inside a TwinCAT export: the element that holds it and its document."""

    element: str
    kind: str
    doc: Document
    start: int  # offset of the CDATA content in the decoded file text
    end: int


def embedded_documents(data: bytes, path: str, parsed: Scan | None = None) -> tuple[Scan, list[Embedded]]:
    """The lists a TwinCAT export holds in CDATA, each with its place in the file."""
    sc = parsed if parsed is not None else scan(data, path)
    source = sc.text.split("\n")
    shown = [s[:-1] if s.endswith("\r") else s for s in source]
    out: list[Embedded] = []
    for section in sc.cdata:
        kind = EMBEDDED.get(section.parent)
        if kind is None:
            continue
        text = sc.text[section.start:section.end]
        doc = tokenize_text(text, path, sc.encoding, False)
        line, col = sc.position(section.start)
        doc.origin = Origin(TWINCAT, shown, {n: (line + n - 1, col - 1 if n == 1 else 0, None)
                                             for n in range(1, len(doc.lines) + 2)}, kind=kind)
        out.append(Embedded(section.parent, kind, doc, section.start, section.end))
    return sc, out


def _span(origin: Origin, span: Span) -> Span:
    line, col = origin.locate(span.line, span.column)
    end_line, end_col = origin.locate(span.end_line, span.end_column, end=True)
    if (end_line, end_col) < (line, col):
        end_line, end_col = line, col
    return Span(line, col, end_line, end_col)


def _edit(origin: Origin, edit: Edit) -> Edit | None:
    """An edit of the list text as an edit of the file; ``None`` where the file cannot take it (an
    XML list takes only edits inside a value)."""
    span = edit.span
    if origin.form == TWINCAT:
        return Edit(_span(origin, span), edit.replacement)
    got = origin.shift.get(span.line)
    if got is None or got[2] is None or span.end_line != span.line or span.column - 1 < got[2][0]:
        return None
    return Edit(_span(origin, span), escape(edit.replacement))


def relocate(d: Diagnostic, origin: Origin) -> Diagnostic:
    """A finding on a document read from another form, placed in the file the user has open."""
    message = d.message
    if origin.form == TWINCAT:
        message = _LINE_RE.sub(lambda m: f"line {origin.locate(int(m.group(1)), 1)[0]}", message)
    fix = d.fix
    if fix is not None:
        edits = [_edit(origin, e) for e in fix.edits]
        fix = Fix(fix.title, tuple(e for e in edits if e is not None), fix.safe) if all(edits) else None
    related = tuple(Related(_span(origin, r.span), r.message, r.path) if r.path is None else r for r in d.related)
    return replace(d, span=_span(origin, d.span), message=message, fix=fix, related=related)


def shown_document(path: str, origin: Origin, encoding: str = "utf-8") -> Document:
    """The file as a report shows it (its own lines, for the excerpts under each finding)."""
    return Document(path, encoding, list(origin.source), ["\n"] * len(origin.source), [])


def put_back(data: bytes, path: str, element: str, text: str) -> bytes:
    """A TwinCAT export with the list of ``element`` replaced by ``text``: every byte outside that
    CDATA section kept. Refused (located) when the export holds no such list, or several, or when
    the text cannot stand in CDATA (it holds ``]]>``)."""
    sc, lists = embedded_documents(data, path)
    hits = [item for item in lists if item.element == element]
    if len(hits) != 1:
        held = ", ".join(sorted({item.element for item in lists})) or "none"
        raise ZeroError(f"the export holds {len(hits)} `<{element}>` lists (it holds: {held}); "
                        "zero puts a list back into exactly one", path)
    if "]]>" in text:
        raise ZeroError("the list holds `]]>`, which cannot stand inside a CDATA section", path)
    hit = hits[0]
    new = sc.text[:hit.start] + text + sc.text[hit.end:]
    return (BOM if sc.bom else b"") + new.encode(sc.encoding, "surrogateescape")


def list_text(item: Embedded) -> bytes:
    """The bytes of an embedded list as a list file holds them."""
    doc = item.doc
    return "".join(a + b for a, b in zip(doc.lines, doc.endings, strict=True)).encode(doc.encoding, "surrogateescape")

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
    PROJECT_ROOTS,
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
from zero.lists.encoding import BOM
from zero.lists.model import Document, Origin
from zero.lists.tokenizer import tokenize_text
from zero.markup.lists import escape, to_list
from zero.markup.safe import Scan, scan
from zero.records import Record, field, replace

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


def read_xml(data: bytes, path: str, registry: Registry) -> Document:
    """XML bytes as the document model (see :func:`zero.markup.read_document`): an XML list, or one list
    of a TwinCAT export (`export.xml#NullpD`, or the one it holds) or of a TwinCAT project
    (`X.tsproj#Kanal_1/SdaMds`; the project's start-up list where none is named); :class:`ZeroError`
    (located) for XML zero will not read."""
    file, element = split_part(path)
    if xml_form(data) == TWINCAT:
        lists = embedded_documents(data, file)[1]
        if element is None and root_of(data) in PROJECT_ROOTS:
            starts = [x for x in lists if x.kind == "STUP" and x.name.lower() == "startup"]
            if len(starts) == 1 and len(lists) > 1:  # a project read as one list: its start-up list
                return starts[0].doc
        return pick(lists, element, file).doc
    return xml_document(data, path, registry)


class Embedded(Record, eq=False):
    """A list inside a TwinCAT export: the element that holds it and its document."""

    element: str  # an export's element (`NullpD`); a project's block address (`Kanal_1/SdaMds`)
    kind: str | None
    doc: Document
    start: int  # offset of the CDATA content in the decoded file text
    end: int
    offset: int | None = None  # a project's block: its `Offset` (what `tc_virtual_N\` names)
    item: str = ""  # a project's block: the TwinCAT tree item it belongs to
    name: str = ""  # a project's block: the `Name` of its `<Data>` element
    properties: dict[str, str] = field(default_factory=dict)  # its item's DriveType, Spindle, FeedAxis


def embedded_documents(data: bytes, path: str, parsed: Scan | None = None) -> tuple[Scan, list[Embedded]]:
    """The lists a TwinCAT export holds in CDATA, each with its place in the file; for a TwinCAT
    project or independent project file (:mod:`zero.markup.tsproj`), the lists of its ``<Data>`` blocks."""
    if (parsed is not None and parsed.root in PROJECT_ROOTS) or (parsed is None and root_of(data) in PROJECT_ROOTS):
        return project_documents(data, path)
    sc = parsed if parsed is not None else scan(data, path)
    shown = _shown_lines(sc.text)
    axis_group = any(t.name == AXIS_GROUP for t in sc.tags)
    said = _said(sc)
    out: list[Embedded] = []
    for section in sc.cdata:
        kind = EMBEDDED.get(section.parent)
        default = False
        if kind is None and section.parent == "Default" and axis_group:  # the default axis list
            kind, default = "AXIS", True
        if kind is None:
            continue
        doc = _placed(sc, shown, section.start, section.end, path, kind)
        if doc.origin is not None:
            doc.origin.default_list = default
        out.append(Embedded(section.parent, kind, doc, section.start, section.end, item=said.get("ItemName", ""),
                            properties={k: v for k, v in said.items() if k in ITEM_PROPERTIES}))
    return sc, out


def _said(sc: Scan) -> dict[str, str]:
    """What an export says of its item: its ``<ItemName>`` and the :data:`ITEM_PROPERTIES` of
    ``<IsgAxisDef>`` (``<DriveType>``, ``<Spindle>``, ``<FeedAxis>``), each the first one written."""
    out: dict[str, str] = {}
    for t in sc.tags:
        if (t.name == "ItemName" or t.name in ITEM_PROPERTIES) and not t.empty and t.name not in out:
            close = sc.text.find("<", t.end)
            if close >= 0 and sc.text.startswith(f"</{t.name}", close):
                out[t.name] = sc.text[t.end:close].strip()
    return out


AXIS_GROUP = "IsgAxisGroupDef"  # a TwinCAT export of the axis group: `<Default>` holds the default axis list
ITEM_PROPERTIES = ("DriveType", "Spindle", "FeedAxis")  # what an `<IsgAxisDef>` says beside its list (as tsproj)


def _shown_lines(text: str) -> list[str]:
    return [s[:-1] if s.endswith("\r") else s for s in text.split("\n")]


def _placed(sc: Scan, shown: list[str], start: int, end: int, path: str, kind: str | None) -> Document:
    doc = tokenize_text(sc.text[start:end], path, sc.encoding, False)
    line, col = sc.position(start)
    doc.origin = Origin(TWINCAT, shown, {n: (line + n - 1, col - 1 if n == 1 else 0, None)
                                         for n in range(1, len(doc.lines) + 2)}, kind=kind)
    return doc


def project_documents(data: bytes, path: str) -> tuple[Scan, list[Embedded]]:
    """The lists of a TwinCAT project's ``<Data>`` blocks, each placed in the project file."""
    from zero.markup.tsproj import read_project  # start-up: only for a TwinCAT project

    project = read_project(data, path)
    sc = project.scan
    shown: list[str] = []
    out: list[Embedded] = []
    for b in project.blocks:
        if not shown:
            shown = _shown_lines(sc.text)
        doc = _placed(sc, shown, b.start, b.end, path, b.kind)
        out.append(Embedded(b.address, b.kind, doc, b.start, b.end, b.offset, b.item, b.name, dict(b.properties)))
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


def _matches(x: Embedded, wanted: str) -> list[bool]:
    """How ``wanted`` may name a list, most exact first: its element or address, `tc_virtual_N` (its
    Offset), its `<Data>` name, its tree item."""
    w = wanted.lower().rstrip("\\/")
    virtual = w[len("tc_virtual_"):] if w.startswith("tc_virtual_") else None
    return [x.element.lower() == w,
            x.offset is not None and virtual is not None and virtual.isdigit() and int(virtual) == x.offset,
            bool(x.name) and x.name.lower() == w,
            bool(x.item) and x.item.lower() == w]


def pick(lists: list[Embedded], element: str | None, path: str) -> Embedded:
    """The one list of an export that ``element`` names (any case; the only one where ``None``), or a
    located :class:`ZeroError` saying which lists the export holds. In a project a list is named by its
    address (`Kanal_1/SdaMds`), by `tc_virtual_N` (its Offset), or by its `<Data>` name or tree item
    where only one list has it."""
    what = "project" if any(x.name for x in lists) else "export"
    hits = lists if element is None else []
    if element is not None:
        for level in range(4):
            hits = [x for x in lists if _matches(x, element)[level]]
            if hits:
                break
    if len(hits) != 1:
        held = ", ".join(x.element for x in lists) or "none"
        if element is None:
            if not lists:
                raise ZeroError(f"the {what} holds no list zero knows", path, 1, 1)
            raise ZeroError(f"the {what} holds the lists {held}: name one as `{path}#{lists[0].element}` (zero "
                            "convert also takes --item ELEMENT, and --out-dir for every one)", path, 1, 1)
        if not hits:
            raise ZeroError(f"the {what} holds no list `{element}` (it holds: {held})", path, 1, 1)
        raise ZeroError(f"the {what} holds {len(hits)} lists named `{element}` (it holds: {held}): zero takes "
                        "exactly one", path, 1, 1)
    return hits[0]


def splice(sc: Scan, path: str, texts: list[tuple[Embedded, str]]) -> bytes:
    """An export with the CDATA content of each list replaced by its text, every other byte kept (one
    scan, replaced by offsets from the end, so two lists of one element name are two lists).
    Refused (located) where a text cannot stand in CDATA (it holds ``]]>``)."""
    out = sc.text
    for item, text in sorted(texts, key=lambda pair: -pair[0].start):
        if "]]>" in text:
            raise ZeroError("the list holds `]]>`, which cannot stand inside a CDATA section", path,
                            *sc.position(item.start))
        out = out[:item.start] + text + out[item.end:]
    return (BOM if sc.bom else b"") + out.encode(sc.encoding, "surrogateescape")


def doc_text(doc: Document) -> str:
    """A document's text as it was read (its lines and endings)."""
    return "".join(a + b for a, b in zip(doc.lines, doc.endings, strict=True))


def list_text(item: Embedded) -> bytes:
    """The bytes of an embedded list as a list file holds them."""
    return doc_text(item.doc).encode(item.doc.encoding, "surrogateescape")


__all__ = ["AXIS_GROUP", "EMBEDDED", "PROJECT_ROOTS", "TWINCAT", "TWINCAT_ROOT", "XML_LIST", "Embedded", "doc_text",
           "embedded_documents", "is_update", "is_xml", "pick", "project_documents", "read_xml", "relocate", "root_of",
           "shown_document", "splice", "xml_document", "xml_form"]

"""TwinCAT projects (``*.tsproj``) and their independent project files (``*.xti``): the lists they hold.

A TwinCAT 3 CNC project keeps the whole machine inside the project file: the start-up list is
the CDATA of ``<Data Name="Startup">``, and every list it names is the CDATA of a
``<Data Name="…" Offset="N">`` element under the channel's or an axis's item, named from the
start-up list as ``tc_virtual_N\\file.lis``. TwinCAT may save an item (an axis, the CNC task, a
channel) as an *independent project file* (``.xti``, below the project's ``_Config`` folder): the
project file then keeps an element with a ``File`` attribute in its place, and the ``.xti`` file
(root ``<TcSmItem>``) holds the item's content, its ``<Data>`` blocks too.

Projects are large (mostly PLC and I/O configuration), so a project is read in two passes that
never build a tree: the hardened parser (:func:`zero.markup.safe.check`) proves the file
well-formed and free of DTDs, entities and external references, at expat's speed; then one
regular expression finds the ``<Data>`` blocks, the ``File`` references, comments and CDATA
sections, and only the stretch that holds the blocks is tokenized to name the TwinCAT tree item
each block belongs to (the text of its nearest ancestor's ``<Name>``). Every other byte is
passed over.

Each block becomes a :class:`Block` with an address a user can read in the TwinCAT tree:
``Kanal_1/SdaMds`` (item name, ``/``, the ``Data`` element's ``Name``), and with its list kind
(the start-up list's reference to its Offset says it; else a known element name).
"""

from __future__ import annotations

import bisect
import re
from xml.sax.saxutils import unescape

from zero.errors import ZeroError
from zero.forms import EMBEDDED, is_independent_file
from zero.lists.encoding import BOM
from zero.markup.safe import Scan, _line_starts, check, encoding_of
from zero.records import Record, field

STARTUP = "Startup"
VIRTUAL_RE = re.compile(r"^\s*\"?tc_virtual_([0-9]+)(?![0-9A-Za-z_])", re.I)  # `tc_virtual_3\achsmds1.lis`
# The start-up keys that name a list, and the kind of list each names (as zero.machine.model.REFERENCES).
REFERENCE_KINDS: dict[str, str] = {
    "default_sda_mds": "CHAN", "sda_mds": "CHAN", "werkz_data": "TOOL", "nullp_data": "ZERO", "pzv_data": "CLMP",
    "ve_var": "EXTV", "hand_mds": "MANU", "rtconf_lis": "RTCF", "hw_configuration_list": "HWCF",
    "default_achs_mds": "AXIS", "achs_mds": "AXIS", "achs_kw": "COMP",
}
_KEY_RE = re.compile(r"^\s*([A-Za-z_]+)(?:\[([0-9]+)\])?\s+(\S.*?)\s*$")
_FIND = re.compile(
    r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>"
    r"|<(?P<name>Data|[^\s/>!?]+(?=\s[^<>]*?\bFile\s*=))"
    r"(?P<attrs>(?:\s+[^\s=/>]+\s*=\s*(?:\"[^\"]*\"|'[^']*'))*)\s*(?P<empty>/)?>", re.S)
_TOKEN = re.compile(
    r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>"
    r"|<(?P<close>/)?(?P<name>[^\s/>!?]+)(?P<attrs>(?:\s+[^\s=/>]+\s*=\s*(?:\"[^\"]*\"|'[^']*'))*)\s*(?P<empty>/)?>",
    re.S)
_ATTR = re.compile(r"""([^\s=/>]+)\s*=\s*(?:"([^"]*)"|'([^']*)')""")
_CDATA_AFTER = re.compile(r"\s*<!\[CDATA\[(.*?)\]\]>", re.S)  # the list: the CDATA section the element opens with
WINDOW = 1 << 20  # how far before the first block (and after the last) its tree item is looked at (characters)
# What a CNC axis item says of itself beside its list (as the Automation Interface's `<IsgAxisDef>` writes it).
ITEM_PROPERTIES = ("DriveType", "Spindle", "FeedAxis")
_ENTITIES = {"&quot;": '"', "&apos;": "'"}
_CHAR_REF = re.compile(r"&#(x[0-9A-Fa-f]+|[0-9]+);")


class Block(Record, eq=False):
    """A ``<Data>`` element of a project holding a list in CDATA."""

    name: str  # the element's Name attribute
    offset: int | None  # its Offset attribute (None: it has none, or not a number)
    offset_text: str | None  # the Offset attribute as written
    item: str  # the TwinCAT tree item holding it ("" where zero cannot tell)
    tag: int  # offset of `<Data` in the decoded text
    start: int  # the CDATA content
    end: int
    address: str = ""  # how the block is named: `Kanal_1/SdaMds`
    kind: str | None = None
    properties: dict[str, str] = field(default_factory=dict)  # its item's DriveType, Spindle, FeedAxis


class ProjectFile(Record, eq=False):
    """What zero reads of a project file: its text (a :class:`Scan` without tags) and its blocks."""

    scan: Scan
    blocks: list[Block]
    files: list[tuple[int, str]] = field(default_factory=list)  # (offset of the tag, its `File` attribute)

    @property
    def startup(self) -> Block | None:
        found = [b for b in self.blocks if b.name.lower() == STARTUP.lower()]
        return found[0] if len(found) == 1 else None


def _attrs(text: str) -> dict[str, str]:
    return {m.group(1): _text(m.group(2) if m.group(2) is not None else m.group(3)) for m in _ATTR.finditer(text)}


def _text(raw: str) -> str:
    """An attribute value or element text as XML means it (the five entities and character references)."""
    out = unescape(raw, _ENTITIES)
    return _CHAR_REF.sub(lambda m: chr(int(m.group(1)[1:], 16) if m.group(1)[0] == "x" else int(m.group(1))), out)


def _safe_start(text: str, spans: list[tuple[int, int]], at: int) -> int:
    """The first tag start at or after ``at`` that is not inside a comment, CDATA section or processing
    instruction (``spans``): in well-formed XML every other `<` opens a tag."""
    while True:
        at = text.find("<", at)
        if at < 0:
            return len(text)
        i = bisect.bisect_right(spans, (at, len(text) + 1)) - 1
        if i >= 0 and spans[i][0] <= at < spans[i][1]:
            at = spans[i][1]
            continue
        return at


def _items(text: str, spans: list[tuple[int, int]], blocks: list[Block]) -> None:
    """Each block's tree item: the ``<Name>`` (child element, else ``Name`` attribute) of its nearest
    ancestor that has one, and that item's :data:`ITEM_PROPERTIES`, from a forward pass over the
    stretch that holds the blocks (and up to :data:`WINDOW` past the last, for what follows a block)."""
    if not blocks:
        return
    at = _safe_start(text, spans, max(0, blocks[0].tag - WINDOW))
    stop = blocks[-1].tag
    wanted = {b.tag: b for b in blocks}
    stack: list[_Entry] = []
    owners: list[tuple[Block, _Entry | None]] = []
    open_owners = 0
    for m in _TOKEN.finditer(text, at):
        if m.start() > stop and (open_owners <= 0 or m.start() > stop + WINDOW):
            break
        name = m.group("name")
        if name is None:
            continue
        if m.group("close"):
            if stack:
                gone = stack.pop()
                open_owners -= gone.owning
            continue
        block = wanted.get(m.start())
        if block is not None:
            owner = next((entry for entry in reversed(stack) if entry.item), None)
            block.item = owner.item if owner is not None else ""
            owners.append((block, owner))
            if owner is not None and not owner.owning:
                owner.owning, open_owners = 1, open_owners + 1
        if m.group("empty"):
            continue
        if stack and (name == "Name" or name in ITEM_PROPERTIES):
            close = text.find("<", m.end())
            if close >= 0 and text.startswith(f"</{name}", close):
                value = _text(text[m.end():close]).strip()
                if name == "Name":
                    stack[-1].item = value or stack[-1].item
                elif stack[-1].item or len(stack) < 2:
                    stack[-1].properties.setdefault(name, value)
                else:  # `<IsgAxisDef><DriveType>`: a property of the item one level up
                    stack[-2].properties.setdefault(name, value)
        named = _attrs(m.group("attrs") or "").get("Name") if name != "Data" else None
        stack.append(_Entry(name, named or ""))
    for block, owner in owners:
        if owner is not None:
            block.properties = dict(owner.properties)


class _Entry(Record, eq=False):
    """An element open in the pass of :func:`_items`."""

    name: str
    item: str  # the item name its `<Name>` child (or `Name` attribute) gives
    properties: dict[str, str] = field(default_factory=dict)
    owning: int = 0  # 1 while it is the item of a block


def _references(text: str) -> dict[int, list[tuple[str, int | None]]]:
    """The start-up list's `tc_virtual_N\\` references: Offset → [(key, index)]."""
    out: dict[int, list[tuple[str, int | None]]] = {}
    for line in text.splitlines():
        m = _KEY_RE.match(line)
        if m is None or m.group(1).lower() not in REFERENCE_KINDS:
            continue
        v = VIRTUAL_RE.match(m.group(3))
        if v is not None:
            out.setdefault(int(v.group(1)), []).append((m.group(1).lower(), int(m.group(2)) if m.group(2) else None))
    return out


def _kinds(blocks: list[Block], text: str) -> None:
    starts = [b for b in blocks if b.name.lower() == STARTUP.lower()]
    refs: dict[int, list[tuple[str, int | None]]] = {}
    for b in starts:
        b.kind = "STUP"
        for k, v in _references(text[b.start:b.end]).items():
            refs.setdefault(k, []).extend(v)
    named = {k.lower(): v for k, v in EMBEDDED.items()}
    for b in blocks:
        if b.kind is not None:
            continue
        by_ref = {REFERENCE_KINDS[key] for key, _ in refs.get(b.offset, [])} if b.offset is not None else set()
        b.kind = next(iter(by_ref)) if len(by_ref) == 1 else named.get(b.name.lower())


def _addresses(blocks: list[Block]) -> None:
    for b in blocks:
        b.address = f"{b.item}/{b.name}" if b.item else b.name
    seen: dict[str, int] = {}
    for b in blocks:
        seen[b.address.lower()] = seen.get(b.address.lower(), 0) + 1
    for b in blocks:
        if seen[b.address.lower()] > 1 and b.offset_text is not None:
            b.address = f"{b.address}@{b.offset_text}"


def _decode(data: bytes, path: str) -> tuple[str, str, bool]:
    try:
        encoding, bom = encoding_of(data)
    except ZeroError as exc:
        raise ZeroError(exc.message, path, exc.line, exc.column) from None
    body = data[len(BOM):] if bom else data
    return body.decode(encoding, "surrogateescape"), encoding, bom


# The last projects read (a machine reads many lists of one project; a project of 50 MB holds about
# 200 MB here, so only two are kept).
CACHED = 2
_CACHE: dict[tuple[str, int, int], tuple[bytes, ProjectFile]] = {}


def read_project(data: bytes, path: str = "-", root: str = "") -> ProjectFile:
    """A project file's blocks (each file read once per content: a machine reads many lists of one
    project). :class:`ZeroError` (located) for XML zero will not read."""
    key = (path, len(data), hash(data))
    got = _CACHE.get(key)
    if got is not None and (got[0] is data or got[0] == data):
        return got[1]
    check(data, path)
    text, encoding, bom = _decode(data, path)
    spans: list[tuple[int, int]] = []
    blocks: list[Block] = []
    files: list[tuple[int, str]] = []
    for m in _FIND.finditer(text):
        name = m.group("name")
        if name is None:
            spans.append((m.start(), m.end()))
            continue
        attrs = _attrs(m.group("attrs") or "")
        if name != "Data":
            if is_independent_file(attrs.get("File", "")):
                files.append((m.start(), attrs["File"]))
            continue
        if m.group("empty") or "Name" not in attrs:
            continue
        body = _CDATA_AFTER.match(text, m.end())
        if body is None:
            continue  # no list in CDATA: a <Data> of another kind (an I/O init command's bytes, ...)
        label = attrs["Name"]
        raw = attrs.get("Offset")
        if label.lower() != STARTUP.lower() and raw is None and label.lower() not in {k.lower() for k in EMBEDDED}:
            continue  # neither the start-up list, nor a list the start-up list can name, nor a known list
        number = _number(raw)
        blocks.append(Block(label, number, raw, "", m.start(), body.start(1), body.end(1)))
    _items(text, spans, blocks)
    _kinds(blocks, text)
    _addresses(blocks)
    scan = Scan(text, encoding, bom, root or _root(text, spans), [], [], _line_starts(text))
    out = ProjectFile(scan, blocks, files)
    if len(_CACHE) >= CACHED:
        _CACHE.pop(next(iter(_CACHE)))
    _CACHE[key] = (data, out)
    return out


def _number(raw: str | None) -> int | None:
    """An Offset as written: decimal, or hexadecimal as TwinCAT writes some numbers (``#x0C``)."""
    text = (raw or "").strip()
    if text.isdigit():
        return int(text)
    if text.lower().startswith("#x") and text[2:] and all(c in "0123456789abcdefABCDEF" for c in text[2:]):
        return int(text[2:], 16)
    return None


def _root(text: str, spans: list[tuple[int, int]]) -> str:
    m = _TOKEN.match(text, _safe_start(text, spans, 0))
    return m.group("name") or "" if m else ""


__all__ = ["REFERENCE_KINDS", "STARTUP", "VIRTUAL_RE", "Block", "ProjectFile", "read_project"]

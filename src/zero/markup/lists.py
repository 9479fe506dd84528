"""The kernel's XML lists as the list text every rule reads, and back.

An XML list names each parameter by its ID, with the array indices appended with dots, and
holds the value in the ``Value`` attribute: ``<P-ZERO-00003.1.0 Value="0" />`` is the entry
``np_grp[1].achse[0].versch 0``. Everything else in the file (the declaration, the grouping
elements, the XML comments) carries no data.

:func:`to_list` writes an XML list as list text, **one line for one line**: a line with one
parameter element becomes the entry; every other line becomes a comment line holding the XML
line as it is (``# <Head>``, ``# <!-- Logical axis number - 'achs_nr' -->``), and ``Ende`` is
added at the end. A parameter line written the way the vendor writes them (the element alone
on its line, ``<ID Value="…" />``, indented like the line before it, or one step deeper after
an opening tag) needs nothing more; any other is followed by a ``( xml:`` comment with the line
as written, the value replaced by ``{}``. So :func:`to_xml` gives the XML file back byte for
byte from that list text (and from its YAML, TOML or JSON form, which carry the same lines),
and every finding on the list text has an exact place in the XML file (:class:`Origin`).

:func:`to_xml` of a list that never was XML writes a new XML list: the root element of the
list kind, the version header, each comment line as an XML comment, each entry as its element
with its ``( …`` annotation or end-of-line comment as an XML comment behind it (which
:func:`to_list` turns back into the same comment). A key the catalogue has no ID for cannot be
an XML element: the conversion refuses it, located.
"""

from __future__ import annotations

import re
from collections import Counter

from zero.catalog.registry import KINDS, Registry
from zero.errors import ZeroError
from zero.forms import XML_ROOTS
from zero.lists.encoding import BOM
from zero.lists.model import MAX_INDEX_DIGITS, Blank, Comment, Document, End, Entry, Origin, Problem, parse_key
from zero.lists.tokenizer import scan_line, split_lines
from zero.markup.safe import Scan, Tag, scan

ROOT_OF_KIND = {kind: root for root, kind in XML_ROOTS.items() if not root.startswith("Default_")}
ID_RE = re.compile(r"P-([A-Z]{4})-[0-9]{5}")
_ELEMENT_RE = re.compile(r"(P-[A-Z]{4}-[0-9]{5})((?:\.[0-9]+)*)")
_PLAIN_RE = re.compile(r'(?P<indent>[ \t]*)<(?P<name>P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)*) Value="(?P<value>[^"&<]*)" />'
                       r'(?:  <!-- (?P<note>.*?) -->)?')
_OPEN_RE = re.compile(r"[ \t]*<[^/!?][^>]*(?<!/)>[ \t]*")
_KEPT_RE = re.compile(r"(?P<indent>[ \t]*)<!-- zero-entry: (?P<line>.*?) -->")
KEPT = "<!-- zero-entry: {} -->"  # an entry whose key has no ID, kept in the XML as a comment
TEMPLATE = "( xml: "  # `(` opens a comment after every value, a string too (S006)
SLOT = "{}"
VALUE_COLUMN = 54
EXPECTED_ROOT = "the root element of a parameter list in XML"


def kind_of_root(root: str) -> str | None:
    return XML_ROOTS.get(root)


def _indent(line: str) -> str:
    return line[: len(line) - len(line.lstrip(" \t"))]


def _unit(skeleton: list[str | None]) -> str:
    """The indentation step of a file, from its skeleton lines alone (so both directions agree)."""
    steps: Counter[str] = Counter()
    previous: str | None = None
    for line in skeleton:
        if line is None or not line.strip():
            previous = None if line is None else previous
            continue
        if previous is not None and _OPEN_RE.fullmatch(previous):
            a, b = _indent(previous), _indent(line)
            if b.startswith(a) and len(b) > len(a):
                steps[b[len(a):]] += 1
        previous = line
    return steps.most_common(1)[0][0] if steps else "  "


def _expected(previous: str | None, unit: str) -> str:
    if previous is None:
        return unit
    return _indent(previous) + unit if _OPEN_RE.fullmatch(previous) else _indent(previous)


def escape(value: str) -> str:
    return value.replace("&", "&amp;").replace("<", "&lt;").replace('"', "&quot;")


def _entry_line(key: str, value: str, note: str | None = None) -> str:
    s = key + " " * max(VALUE_COLUMN - len(key), 1) + value
    return s + "  " + note if note is not None else s


def _carries(line: str, key: str, value: str, note: str | None) -> bool:
    """Does the list line read back as exactly this key, value and comment?"""
    problems: list[Problem] = []
    item = scan_line(line, 1, problems)
    if not isinstance(item, Entry) or problems:
        return False
    return item.key_text == key and item.value == value and item.comment == note


def _is_kept(line: str) -> bool:
    m = _KEPT_RE.fullmatch(line) if "zero-entry" in line else None
    return m is not None and _kept_entry(m.group("line"))


def _kept_entry(text: str) -> bool:
    """Is the text of a ``zero-entry`` comment an entry (whose key has no ID) as a list writes it?"""
    problems: list[Problem] = []
    item = scan_line(text, 1, problems)
    return isinstance(item, Entry) and not problems and "--" not in text


def key_of(tag_name: str, registry: Registry, kind: str | None = None) -> tuple[str | None, str]:
    """``P-ZERO-00003.1.0`` → (``np_grp[1].achse[0].versch``, ""), or (None, why not); an element of
    another list kind than ``kind`` (the root's) makes no entry."""
    m = _ELEMENT_RE.fullmatch(tag_name)
    if m is None:
        return None, "not a parameter ID"
    spec = registry.get(m.group(1))
    if spec is None or not spec.key:
        return None, f"{m.group(1)} is not a parameter the catalogue ({registry.source}) knows"
    if kind is not None and spec.kind != kind:
        return None, f"{spec.id} belongs to another list kind"
    digits = m.group(2).split(".")[1:]
    longest = max(digits, key=len, default="")
    if len(longest) > MAX_INDEX_DIGITS:  # never converted: 4,400 digits are beyond Python's int limit
        return None, f"{spec.id} has an index of {len(longest)} digits, beyond every array"
    indices = [int(x) for x in digits]
    parts = spec.key.split("[]")
    if len(parts) - 1 != len(indices):
        return None, (f"{spec.id} (`{spec.key}`) takes {len(parts) - 1} indices, the element gives "
                      f"{len(indices)}")
    out = [parts[0]]
    for idx, rest in zip(indices, parts[1:], strict=True):
        out.append(f"[{idx}]{rest}")
    return "".join(out), ""


def id_of(key: str, registry: Registry, kind: str | None) -> str | None:
    """``np_grp[1].achse[0].versch`` → ``P-ZERO-00003.1.0``; ``None`` when the catalogue has no ID."""
    parsed = parse_key(key)
    if parsed is None:
        return None
    spec = registry.by_pattern(parsed.pattern, kind)
    if spec is None:
        return None
    return spec.id + "".join(f".{i}" for i in parsed.indices)


# ----------------------------------------------------------------------------- XML → list


def to_list(data: bytes, registry: Registry, path: str = "-",
            parsed: Scan | None = None) -> tuple[str, Origin, str | None]:
    """An XML list as list text, with the map back to the XML file and the list kind of its root.
    A parameter element zero cannot make an entry of (an ID the catalogue does not know, indices
    that do not fit, an empty ``Value``, two elements on a line) stays a comment line, where the
    rules find it (S015, S016)."""
    sc = parsed if parsed is not None else scan(data, path)
    lines, endings = split_lines(sc.text)
    kind = kind_of_root(sc.root)
    by_line: dict[int, list[Tag]] = {}
    for tag in sc.tags:
        if tag.depth >= 1:
            by_line.setdefault(sc.position(tag.start)[0], []).append(tag)
    entries: dict[int, tuple[str, str, Tag]] = {}
    for number, tags in by_line.items():
        tag = tags[0]
        if (len(tags) > 1 or not ID_RE.match(tag.name) or not tag.empty or sc.position(tag.end)[0] != number
                or not tag.attrs.get("Value") or "Value" not in tag.raw):
            continue
        found, _ = key_of(tag.name, registry, kind)
        if found is not None:
            entries[number] = (found, tag.attrs["Value"], tag)
    skeleton: list[str | None] = [None if (i + 1) in entries or _is_kept(s) else s for i, s in enumerate(lines)]
    unit = _unit(skeleton)
    out: list[str] = []
    origin = Origin("xml", lines, {})
    previous: str | None = None
    for number, line in enumerate(lines, 1):
        got = entries.get(number)
        entry = None
        if got is not None:
            key, value, tag = got
            start, end = tag.raw["Value"]
            line_start = sc.line_starts[number - 1]
            vstart, vend = start - line_start, end - line_start
            m = _PLAIN_RE.fullmatch(line)
            note = m.group("note") if m is not None else None
            if note is not None and not note.startswith("("):
                m = None
            entry = _entry_line(key, value, note)
            if not (m is not None and m.group("value") == value and m.group("indent") == _expected(previous, unit)
                    and _carries(entry, key, value, note)):
                template = TEMPLATE + line[:vstart] + SLOT + line[vend:]
                entry = _entry_line(key, value, template)
                if SLOT in line[:vstart] + line[vend:] or not _carries(entry, key, value, template):
                    entry = None  # not carried: a comment line (S016 says so)
        kept = _KEPT_RE.fullmatch(line) if got is None and "zero-entry" in line else None
        if kept is not None and kept.group("indent") == _expected(previous, unit) and \
                _kept_entry(kept.group("line")):
            out.append(kept.group("line"))
            origin.shift[number] = (number, kept.start("line"), None)
        elif entry is None:
            out.append("# " + line if line.strip() else line)
            origin.shift[number] = (number, -2 if line.strip() else 0, None)
        else:
            out.append(entry)
            origin.shift[number] = (number, 0, (len(key) + max(VALUE_COLUMN - len(key), 1), vstart, vend,
                                                sc.position(tag.start)[1], len(tag.name)))
        if line.strip():
            previous = line
    if endings and endings[-1]:  # the text ended with a line break
        text = "".join(s + e for s, e in zip(out, endings, strict=True)) + "Ende" + endings[-1]
    else:
        newline = "\r\n" if "\r\n" in endings else "\n"
        text = "".join(s + e for s, e in zip(out[:-1], endings[:-1], strict=True)) + (out[-1] if out else "")
        text += newline + "Ende"
        origin.final_newline = False
    return text, origin, kind


# ----------------------------------------------------------------------------- list → XML


def to_xml(doc: Document, registry: Registry, kind: str | None) -> bytes:
    """The bytes of the XML list this list text stands for (see the module's description): the XML it
    was read from, in its own encoding and BOM, where its comment lines make that XML again; else a new
    XML list in UTF-8, as its declaration says. Raises a located :class:`ZeroError` for what an XML
    list cannot hold."""
    if doc.holds_xml_lines():
        rebuilt = (BOM if doc.bom else b"") + _rebuild(doc, registry, doc.declared_kind() or kind).encode(
            doc.encoding, "surrogateescape")
        try:
            scan(rebuilt, doc.path)
            return rebuilt
        except ZeroError:
            pass
    text = _write_new(doc, registry, kind)
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError as exc:
        raise ZeroError("a byte the list's encoding cannot read: an XML list cannot hold it; fix the line first "
                        "(`zero lint` shows it as S007)", doc.path, text.count("\n", 0, exc.start) + 1) from None


def _element(entry: Entry, doc: Document, registry: Registry, kind: str | None) -> str:
    pid = id_of(entry.key_text, registry, kind)
    if pid is None:
        raise ZeroError(f"`{entry.key_text}` has no parameter ID in the catalogue ({registry.source}); an XML list "
                        "names each parameter by its ID, so it cannot hold this entry — fix or remove it first",
                        doc.path, entry.line, entry.key_start + 1)
    return pid


def _rebuild(doc: Document, registry: Registry, kind: str | None) -> str:
    lines: list[str] = []
    skeleton: list[str | None] = []
    by_line = {item.line: item for item in doc.items}
    end_line = doc.end_line
    for number, text in enumerate(doc.lines, 1):
        if end_line is not None and number >= end_line:
            break
        item = by_line.get(number)
        skeleton.append(None if isinstance(item, Entry) or (text.startswith("# ") and _is_kept(text[2:])) else
                        (text[2:] if text.startswith("# ") else "" if not text.strip() else text))
    unit = _unit(skeleton)
    previous: str | None = None
    for number, text in enumerate(doc.lines, 1):
        if end_line is not None and number >= end_line:
            break
        item = by_line.get(number)
        if isinstance(item, Entry) and id_of(item.key_text, registry, kind) is None:
            line = _expected(previous, unit) + _kept(item, doc)
        elif isinstance(item, Entry):
            pid = _element(item, doc, registry, kind)
            value = escape(item.value)
            comment = item.comment
            if comment is not None and comment.startswith(TEMPLATE):
                template = comment[len(TEMPLATE):]
                m = re.search(r"<(P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)*)", template)
                if m is not None and m.group(1) != pid:
                    template = template[: m.start(1)] + pid + template[m.end(1):]
                line = template.replace(SLOT, value, 1)
            else:
                line = f'{_expected(previous, unit)}<{pid} Value="{value}" />'
                if comment is not None:
                    line += f"  <!-- {_comment_text(comment.rstrip())} -->"
        elif text.startswith("# "):
            line = text[2:]
        elif not text.strip():
            line = text
        else:  # a comment line written in the list form: an XML comment
            line = f"{_expected(previous, unit)}<!-- {_comment_text(text.lstrip('#').strip())} -->"
        lines.append(line)
        if line.strip():
            previous = line
    endings = list(doc.endings[: len(lines)])
    if end_line is not None and end_line - 1 < len(doc.endings) and doc.endings[end_line - 1] == "" and lines:
        endings[-1] = ""
    return "".join(s + e for s, e in zip(lines, endings, strict=True))


def _kept(entry: Entry, doc: Document) -> str:
    """An entry whose key has no ID as the XML comment that keeps it (the kernel reads neither: the
    ASCII list's reader does not take an unknown key over, the XML reader never sees a comment)."""
    text = doc.lines[entry.line - 1].strip()
    if not _kept_entry(text):
        raise ZeroError(f"`{entry.key_text}` has no parameter ID in the catalogue, and its line cannot be kept in an "
                        "XML comment (it holds `--`); fix or remove it first", doc.path, entry.line,
                        entry.key_start + 1)
    return KEPT.format(text)


def _comment_text(text: str) -> str:
    """Text an XML comment can hold: ``--`` may not occur in one."""
    while "--" in text:
        text = text.replace("--", "- -")
    return text[:-1] + "- " if text.endswith("-") else text


def _write_new(doc: Document, registry: Registry, kind: str | None) -> str:
    if kind is None:
        raise ZeroError("the list kind is not known, so the XML root element is not either; give `--kind`", doc.path)
    root = ROOT_OF_KIND.get(kind)
    if root is None:
        raise ZeroError(f"the kernel's XML lists have no root element for a {KINDS[kind][1]}", doc.path)
    nl = doc.newline
    out = ['<?xml version="1.0" encoding="utf-8"?>', f"<{root}>", '  <Version Label="1">',
           '    <Schema Version="1" />', "  </Version>"]
    for item in doc.items:
        if isinstance(item, End):
            break
        if isinstance(item, Entry):
            if item.after_end:
                continue
            if id_of(item.key_text, registry, kind) is None:
                out.append("  " + _kept(item, doc))
                continue
            line = f'  <{_element(item, doc, registry, kind)} Value="{escape(item.value)}" />'
            if item.comment is not None:
                line += f"  <!-- {_comment_text(item.comment.rstrip())} -->"
            out.append(line)
        elif isinstance(item, Comment):
            text = doc.lines[item.line - 1].lstrip()
            text = text[1:].strip() if text.startswith("#") else text.strip()
            out.append(f"  <!-- {_comment_text(text)} -->" if text else "")
        elif isinstance(item, Blank):
            out.append("")
    out.append(f"</{root}>")
    return nl.join(out) + nl

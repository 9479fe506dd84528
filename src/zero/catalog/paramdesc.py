"""Read the vendor's machine-readable parameter description (``CncParaDesc.xml``).

Produces plain rows (dicts) of facts: ID, list kind, key pattern, type,
default, range, array sizes, symbols, units, restart flag. The committed
registry table (``data/table.py``) is generated from these rows by
``tools/gen_registry.py``; ``zero --param-desc PATH`` builds the same rows from
a user's own file at run time, and then also carries the vendor's English
descriptions (``with_text=True``), which are never committed to this project.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

from defusedxml import DefusedXmlException
from defusedxml.ElementTree import fromstring as defused_fromstring

from zero.catalog.ranges import parse_range
from zero.errors import ZeroError
from zero.files import read_file

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

_NS = "{https://www.isg-stuttgart.de/kernel/CncParaDesc}"


def _text(el: ET.Element | None, lang: str = "en") -> str | None:
    if el is None:
        return None
    texts = el.findall(f"{_NS}Text")
    for t in texts:
        if t.get("Language") == lang and t.text:
            return t.text.strip()
    return texts[0].text.strip() if texts and texts[0].text else None


_ENUM_LINE = re.compile(r"(0x[0-9A-Fa-f]+|[+-]?[0-9]+)\s*[:=]\s*(.*)")
_NO_ENUM_TYPES = ("BOOLEAN", "STRING")  # BOOLEAN is checked as 0/1; a STRING lists no numbers


def enumeration(text: str, typ: str, name: str = "") -> tuple[list[int], list[str], bool] | None:
    """Allowed values stated in prose, one per line (``1 : <meaning>``):
    ``(values, labels, flags)``, or ``None`` when the text is not such a list. Conservative:
    every other line must be an introduction ending in ``:`` (``0, 1, 2 where:``), or the
    text is not read as an enumeration. ``flags``: single bits of a mask, any combination allowed."""
    if typ in _NO_ENUM_TYPES:
        return None
    lines = [line.replace("\xa0", " ").strip() for line in re.split(r"\r?\n", text) if line.strip()]
    values: list[int] = []
    labels: list[str] = []
    for line in lines:
        m = _ENUM_LINE.fullmatch(line)
        if m is None:
            if not line.endswith(":"):
                return None
            continue
        values.append(int(m.group(1), 0))
        labels.append(m.group(2).strip())
    if len(values) < 2 or len(set(values)) != len(values):
        return None
    bits = all(v > 0 and v & (v - 1) == 0 for v in values)
    flags = bits and ("bit" in text.lower() or "mask" in name.lower())
    return values, labels, flags


_BIT_CODED = re.compile(r"bit[- ]?coded|bitkodiert|bitcodiert", re.I)


def _all_text(p: ET.Element, tag: str) -> str:
    """Every language's text of a child element (to find a fact in it; the text is not kept)."""
    el = p.find(f"{_NS}{tag}")
    return "".join(el.itertext()) if el is not None else ""


def _find(p: ET.Element, tag: str) -> str | None:
    v = p.findtext(f"{_NS}{tag}")
    return v.strip() if v is not None else None


def description_root(path: str | Path) -> ET.Element:
    """The root element of a parameter description, read safely: a regular file only (a FIFO or
    device is refused), no DTD, entities or external references; :class:`~zero.errors.ZeroError`
    when it cannot be read or is no ``CncParaDesc`` file."""
    try:
        root = defused_fromstring(read_file(path), forbid_dtd=True)
    except ZeroError as exc:
        raise ZeroError(f"cannot read parameter description {path}: {exc.message}") from None
    except ET.ParseError as exc:
        raise ZeroError(f"cannot read parameter description {path}: {exc}") from None
    except DefusedXmlException as exc:
        raise ZeroError(f"cannot read parameter description {path}: it declares a DTD, entities or external "
                        f"references, which a parameter description has none of ({type(exc).__name__})") from None
    if root.tag != f"{_NS}Parameters":
        raise ZeroError(f"not a CncParaDesc file (root element {root.tag!r})", str(path))
    return root


def read_param_desc(path: str | Path, *, with_text: bool = False) -> list[dict[str, Any]]:
    """Parse the XML into registry rows; :class:`~zero.errors.ZeroError` on bad input."""
    root = description_root(path)

    units: dict[str, str] = {}
    for u in root.findall(f"{_NS}Unit"):
        uid = _find(u, "Id")
        ascii_text = None
        for t in u.findall(f"{_NS}TextASCII"):
            if t.get("Language") == "en":
                ascii_text = t.text
        if uid:
            units[uid] = (ascii_text or uid).strip()

    rows: list[dict[str, Any]] = []
    for p in root.findall(f"{_NS}Parameter"):
        pid = _find(p, "Id")
        if not pid or not pid.startswith("P-") or len(pid) != 12:
            continue
        typ = _find(p, "Type") or "STRING"
        range_text = _text(p.find(f"{_NS}Range"))
        parsed = parse_range(range_text, pid) if range_text else None
        dims = [int(a.text or 0) for a in p.findall(f"{_NS}MaxNumber/{_NS}ArrayIndex")]
        symbols = []
        for s in p.findall(f"{_NS}SymbolValues/{_NS}SymbolValue"):
            name = _find(s, "Name")
            value = _find(s, "Value")
            if name:
                symbols.append([name, int(value) if value not in (None, "") else None])
        max_len = _find(p, "MaxStringLength")
        row: dict[str, Any] = {
            "id": pid,
            "kind": pid[2:6],
            "key": _find(p, "Name") or None,
            "type": typ,
            "default": _find(p, "DefaultValue"),
            "range": range_text if parsed is not None else None,
            "dims": dims,
            "symbols": symbols,
            "units": [units.get(u.text or "", u.text or "") for u in p.findall(f"{_NS}Units/{_NS}Unit")],
            "quantity": _find(p, "Quantity"),
            "max_len": int(max_len) if max_len else None,
            "restart": _find(p, "ChangeRequiresRestart") == "true",
            # its symbols are bits that combine: the catalogue gives a bit field width, or its
            # description calls the value bit-coded (a fact read from it; no text is kept)
            "bits": _find(p, "Bitfield") is not None or bool(_BIT_CODED.search(_all_text(p, "LongDescription"))),
            "source": "CncParaDesc.xml",
        }
        enum = enumeration(range_text, typ, row["key"] or "") if parsed is None and range_text else None
        if enum is not None:
            row["enum"] = enum[0]
            row["enum_flags"] = enum[2]
        if with_text:
            row["vendor_text"] = _text(p.find(f"{_NS}ShortDescription"))
            row["vendor_long"] = _text(p.find(f"{_NS}LongDescription"))
            if parsed is None and range_text:
                row["range_note"] = range_text
            if enum is not None:
                row["enum_labels"] = enum[1]
        elif parsed is None and range_text:
            row["range_prose"] = True
        rows.append(row)
    if not rows:
        raise ZeroError("no parameters found", str(path))
    return rows

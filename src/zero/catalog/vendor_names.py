"""The names a user's own ``CncParaDesc.xml`` gives its parameters in one language (their short
descriptions), read when asked and never kept: the documentation site's build reads the German ones from
the file ``ZERO_PARAM_DESC`` names and shows them as search terms on the parameters' pages. The
vendor's texts are never committed to this project (``read_param_desc`` reads the same file the same
way for ``--param-desc``)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from defusedxml import DefusedXmlException
from defusedxml.ElementTree import fromstring as defused_fromstring

from zero.errors import ZeroError
from zero.files import read_file

_NS = "{https://www.isg-stuttgart.de/kernel/CncParaDesc}"


def short_names(path: str | Path, language: str = "de") -> dict[str, str]:
    """Parameter ID → its short description in ``language`` (``de``: ``Positiver Softwareendschalter``
    for P-AXIS-00178), for every parameter the file names in that language;
    :class:`~zero.errors.ZeroError` when the file cannot be read or is no parameter description."""
    try:  # a regular file only; no DTD, entities or external references
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
    out: dict[str, str] = {}
    for p in root.findall(f"{_NS}Parameter"):
        pid = (p.findtext(f"{_NS}Id") or "").strip()
        for t in p.findall(f"{_NS}ShortDescription/{_NS}Text"):
            text = " ".join((t.text or "").split())
            if pid.startswith("P-") and t.get("Language") == language and text:
                out[pid] = text
                break
    return out

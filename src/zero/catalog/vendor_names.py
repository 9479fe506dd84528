"""The names a user's own ``CncParaDesc.xml`` gives its parameters in one language (their short
descriptions), read when asked and never kept: the documentation site's build reads the German ones from
the file ``ZERO_PARAM_DESC`` names and shows them as search terms on the parameters' pages. The
vendor's texts are never committed to this project (``read_param_desc`` reads the same file the same
way for ``--param-desc``)."""

from __future__ import annotations

from pathlib import Path

from zero.catalog.paramdesc import _NS, description_root


def short_names(path: str | Path, language: str = "de") -> dict[str, str]:
    """Parameter ID → its short description in ``language`` (``de``: ``Positiver Softwareendschalter``
    for P-AXIS-00178), for every parameter the file names in that language;
    :class:`~zero.errors.ZeroError` when the file cannot be read or is no parameter description."""
    root = description_root(path)
    out: dict[str, str] = {}
    for p in root.findall(f"{_NS}Parameter"):
        pid = (p.findtext(f"{_NS}Id") or "").strip()
        for t in p.findall(f"{_NS}ShortDescription/{_NS}Text"):
            text = " ".join((t.text or "").split())
            if pid.startswith("P-") and t.get("Language") == language and text:
                out[pid] = text
                break
    return out

"""What the emitters share: the findings of results in order, indented JSON byte for byte, paths
relative to the repository, fingerprints that survive moved lines, and where the rules' pages are."""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator

from zero.diagnostics import Diagnostic
from zero.engine.results import LintResult

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any


def each(results: Iterable[LintResult]) -> Iterator[Diagnostic]:
    """The findings of results read once, in order (they may be made as they are read)."""
    for r in results:
        yield from r.diagnostics


# the C function json.dumps writes a string with (ensure_ascii), taken from json's own C module: the json package
# imports its decoder, and the decoder re (a JSON report's lint imported re for it alone)
try:
    from _json import encode_basestring_ascii as _c_escape
except ImportError:  # a Python without it: json's own (its pure-Python escaper, the same text)
    from json.encoder import encode_basestring_ascii as _c_escape
ESCAPE = _c_escape
_ESCAPE = ESCAPE
_PADS = ["\n" + "  " * n for n in range(33)]


def _float(value: float) -> str:
    """A float as :func:`json.dumps` writes it (``NaN`` and ``Infinity`` as Python's encoder does)."""
    if value != value:
        return "NaN"
    if value in (float("inf"), float("-inf")):
        return "Infinity" if value > 0 else "-Infinity"
    return float.__repr__(value)


def _scalar(value: Any) -> str | None:
    """A scalar as :func:`json.dumps` writes it; ``None`` for a container (or what json refuses)."""
    if isinstance(value, str):
        return _ESCAPE(value)
    if value is None:
        return "null"
    if value is True:
        return "true"
    if value is False:
        return "false"
    if isinstance(value, int):
        return int.__repr__(value)
    if isinstance(value, float):
        return _float(value)
    return None


def _key(key: Any) -> str:
    if isinstance(key, str):
        return _ESCAPE(key)
    import json  # start-up: only for a key that is no string

    return _ESCAPE(json.dumps(key))


def indented_json(value: Any, level: int = 0) -> str:
    """``json.dumps(value, indent=2)``, byte for byte, at nesting ``level``. The standard library
    writes indented JSON through nested closures that call each other (the C encoder only without
    ``indent``): every call leaves a reference cycle that only the cycle collector frees, and the
    report of a fleet made one per finding. Here the strings go through the C function json uses,
    and a container's scalars are written in its own loop (a fleet's report: 1,140 findings,
    42,000 values, in 20 ms rather than 110 ms)."""
    out: list[str] = []
    _write(value, level, out)
    return "".join(out)


def _write(value: Any, level: int, out: list[str]) -> None:
    kind = type(value)
    if kind is str:
        out.append(_ESCAPE(value))
        return
    if kind is dict or (kind is not list and kind is not tuple and isinstance(value, dict)):
        if not value:
            out.append("{}")
            return
        pad = _PADS[level + 1] if level < 32 else "\n" + "  " * (level + 1)
        first = True
        for k, v in value.items():
            out.append(("{" if first else ",") + pad + (_ESCAPE(k) if type(k) is str else _key(k)) + ": ")
            first = False
            t = type(v)
            if t is str:
                out.append(_ESCAPE(v))
            elif v is None:
                out.append("null")
            elif t is int:
                out.append(int.__repr__(v))
            else:
                _write(v, level + 1, out)
        out.append((_PADS[level] if level < 33 else "\n" + "  " * level) + "}")
        return
    if kind is list or kind is tuple or isinstance(value, (list, tuple)):
        if not value:
            out.append("[]")
            return
        pad = _PADS[level + 1] if level < 32 else "\n" + "  " * (level + 1)
        first = True
        for v in value:
            out.append("[" + pad if first else "," + pad)
            first = False
            _write(v, level + 1, out)
        out.append((_PADS[level] if level < 33 else "\n" + "  " * level) + "]")
        return
    text = _scalar(value)
    if text is None:
        import json  # start-up: only for a value that is no scalar, list or mapping

        text = json.dumps(value)
    out.append(text)


def repo_path(path: str, root: str | None = None) -> str:
    """``path`` relative to ``root`` (by default the working directory, the repository's root in
    CI), with ``/`` between its parts, as GitLab and GitHub expect; as given where it lies outside
    (or is ``-``)."""
    if path == "-":
        return path
    try:
        rel = os.path.relpath(os.path.abspath(path), os.path.abspath(root) if root else None)
    except ValueError:  # another drive (Windows)
        return path
    if rel == os.pardir or rel.startswith(os.pardir + os.sep):
        return path
    return rel.replace(os.sep, "/")


def _subject(d: Diagnostic, r: LintResult) -> str:
    """What a finding is about, without its line: the key as written on its line, indices and
    all (``np_grp[2].achse[0].versch``), or the line's first word."""
    text = r.document.line_text(d.span.line)
    return text.split(None, 1)[0] if text.strip() else ""


def fingerprints(r: LintResult, root: str | None = None) -> list[str]:
    """A fingerprint per finding of ``r``, in order, that stays the same when lines move or other
    findings come and go: made of the repository-relative path, the code, the key as written
    (with its indices: every index of a parameter shares its ID) and which occurrence of that
    triple it is (a key written twice), never of the line number."""
    from hashlib import sha256  # start-up: 14 ms, only for the formats that fingerprint (GitLab, SARIF)

    seen: dict[tuple[str, str, str], int] = {}
    out = []
    for d in r.diagnostics:
        ident = (repo_path(d.path, root), d.code, _subject(d, r))
        seen[ident] = seen.get(ident, 0) + 1
        text = "\0".join((*ident, str(seen[ident])))
        out.append(sha256(text.encode("utf-8", "surrogateescape")).hexdigest())
    return out

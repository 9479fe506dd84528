"""What the emitters share: the findings of results in order, indented JSON byte for byte, paths
relative to the repository, fingerprints that survive moved lines, and where the rules' pages are."""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Iterable, Iterator
from typing import Any

from zero.diagnostics import Diagnostic
from zero.engine.lint import LintResult


def each(results: Iterable[LintResult]) -> Iterator[Diagnostic]:
    """The findings of results read once, in order (they may be made as they are read)."""
    for r in results:
        yield from r.diagnostics


def indented_json(value: Any, level: int = 0) -> str:
    """``json.dumps(value, indent=2)``, byte for byte, at nesting ``level``. The standard library
    writes indented JSON through nested closures that call each other: every call leaves a
    reference cycle that only the cycle collector frees, and the report of a fleet made one per
    finding. Scalars still go through :func:`json.dumps`."""
    pad = "\n" + "  " * (level + 1)
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = (f"{json.dumps(k if isinstance(k, str) else json.dumps(k))}: {indented_json(v, level + 1)}"
                 for k, v in value.items())
        return "{" + pad + ("," + pad).join(items) + "\n" + "  " * level + "}"
    if isinstance(value, (list, tuple)):
        if not value:
            return "[]"
        return "[" + pad + ("," + pad).join(indented_json(v, level + 1) for v in value) + "\n" + "  " * level + "]"
    return json.dumps(value)


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
    seen: dict[tuple[str, str, str], int] = {}
    out = []
    for d in r.diagnostics:
        ident = (repo_path(d.path, root), d.code, _subject(d, r))
        seen[ident] = seen.get(ident, 0) + 1
        text = "\0".join((*ident, str(seen[ident])))
        out.append(hashlib.sha256(text.encode("utf-8", "surrogateescape")).hexdigest())
    return out

"""``--output-format grouped``: each file's name, its findings indented below it."""

from __future__ import annotations

from collections.abc import Iterable

from zero.engine.results import LintResult
from zero.output.text import printable

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def render_grouped(results: Iterable[LintResult], stream: TextIO) -> None:
    """ruff's ``grouped`` format: each file's name, then its findings indented below it
    (``  line:col CODE message``, the positions aligned), a blank line between files."""
    for r in results:
        if not r.diagnostics:
            continue
        stream.write(f"{printable(r.path, escape=True)}:\n")
        where = [f"{d.span.line}:{d.span.column}" for d in r.diagnostics]
        width = max(len(w) for w in where)
        for d, w in zip(r.diagnostics, where, strict=True):
            stream.write(f"  {w:<{width}} {d.code} {d.severity.label} {printable(d.message, escape=True)}\n")
        stream.write("\n")

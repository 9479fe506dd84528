"""``--output-format concise``: one line per finding."""

from __future__ import annotations

from collections.abc import Iterable

from zero.engine.results import LintResult
from zero.output.formats.common import each
from zero.output.text import printable

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def render_concise(results: Iterable[LintResult], stream: TextIO) -> None:
    """One line per finding: ``path:line:col: CODE severity message``. A control character or an
    undecodable byte in the path or the message is written as its escape (``\\n``, ``\\r``,
    ``\\xff``): one finding stays one line, and the name can still be told."""
    for d in each(results):
        stream.write(f"{printable(d.path, escape=True)}:{d.span.line}:{d.span.column}: {d.code} "
                     f"{d.severity.label} {printable(d.message, escape=True)}\n")

"""``--output-format pylint``: the lines pylint's parseable output has."""

from __future__ import annotations

from collections.abc import Iterable

from zero.engine.results import LintResult
from zero.output.formats.common import each
from zero.output.text import printable

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def render_pylint(results: Iterable[LintResult], stream: TextIO) -> None:
    """The pylint (flake8 ``pylint`` formatter) lines ruff's ``pylint`` format writes:
    ``path:line: [CODE] message``, read by tools made for pylint's parseable output."""
    for d in each(results):
        stream.write(f"{printable(d.path, escape=True)}:{d.span.line}: [{d.code}] "
                     f"{printable(d.message, escape=True)}\n")

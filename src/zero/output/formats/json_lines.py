"""``--output-format json-lines``: each finding's JSON object on a line of its own."""

from __future__ import annotations

import json
from collections.abc import Iterable

from zero.engine.results import LintResult
from zero.output.formats.common import each

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def render_json_lines(results: Iterable[LintResult], stream: TextIO) -> None:
    """JSON Lines (``json-lines``, as ruff's): each finding's JSON object of ``--output-format json``
    on a line of its own."""
    for d in each(results):
        stream.write(json.dumps(d.to_json(), ensure_ascii=False) + "\n")

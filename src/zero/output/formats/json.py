"""``--output-format json``: zero's stable contract, one object per finding."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TextIO

from zero.engine.lint import LintResult
from zero.output.formats.common import each, indented_json


def render_json(results: Iterable[LintResult], stream: TextIO) -> None:
    """The JSON contract of ``--output-format json``: one object per finding. Written object by
    object (the bytes ``json.dumps(all, indent=2)`` gives, without holding them all: JSON escapes
    every newline inside a string, so each object's lines can be indented on their own)."""
    opened = False
    try:
        for d in each(results):
            stream.write(",\n  " if opened else "[\n  ")
            stream.write(indented_json(d.to_json(), 1))
            opened = True
    finally:  # results made as they are read may stop with an error (exit 2): the JSON stays whole
        stream.write("\n]\n" if opened else "[]\n")

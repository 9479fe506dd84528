"""``--output-format json``: zero's stable contract, one object per finding."""

from __future__ import annotations

from collections.abc import Iterable

from zero.diagnostics import Diagnostic
from zero.engine.results import LintResult
from zero.output.formats.common import ESCAPE, each, indented_json

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def render_json(results: Iterable[LintResult], stream: TextIO) -> None:
    """The JSON contract of ``--output-format json``: one object per finding. Written object by
    object (the bytes ``json.dumps(all, indent=2)`` gives, without holding them all: JSON escapes
    every newline inside a string, so each object's lines can be indented on their own)."""
    opened = False
    try:
        for d in each(results):
            stream.write(",\n  " if opened else "[\n  ")
            stream.write(_object(d))
            opened = True
    finally:  # results made as they are read may stop with an error (exit 2): the JSON stays whole
        stream.write("\n]\n" if opened else "[]\n")


# The first finding of each form (with a fix or without) is written both ways, :meth:`Diagnostic.to_json`
# through indented_json and the template below: where they differ (the contract gained a key), the
# template is never used again in the process. Held to json.dumps by tests/output/test_output_formats.py.
_checked: set[bool] = set()
_template_differs: list[bool] = []


def _object(d: Diagnostic) -> str:
    if _template_differs:
        return indented_json(d.to_json(), 1)
    text = _template(d)
    form = d.fix is None
    if form not in _checked:
        if text != indented_json(d.to_json(), 1):
            _template_differs.append(True)
            return indented_json(d.to_json(), 1)
        _checked.add(form)
    return text


# A message (a source, a fix's title) as JSON, by its text: a fleet's lists repeat each other's findings,
# and a long text costs some ten times as much to escape as to hash (a tenth of a fleet's report from the
# cache). Bounded.
_MESSAGES: dict[str, str] = {}


def _message(text: str) -> str:
    hit = _MESSAGES.get(text)
    if hit is None:
        if len(_MESSAGES) >= 16384:
            _MESSAGES.clear()
        hit = _MESSAGES[text] = ESCAPE(text)
    return hit


def _text(value: str | None) -> str:
    return "null" if value is None else ESCAPE(value)


def _template(d: Diagnostic) -> str:
    """A finding's object as :func:`indented_json` writes ``d.to_json()`` at level 1, without the dictionary."""
    s = d.span
    fix = d.fix
    if fix is None:
        fixed = "null"
    else:
        edits = ",\n        ".join(
            f'{{\n          "line": {e.span.line},\n          "column": {e.span.column},\n'
            f'          "end_line": {e.span.end_line},\n          "end_column": {e.span.end_column},\n'
            f'          "replacement": {ESCAPE(e.replacement)}\n        }}' for e in fix.edits)
        listed = "[\n        " + edits + "\n      ]" if edits else "[]"
        fixed = (f'{{\n      "title": {_message(fix.title)},\n      "safe": {"true" if fix.safe else "false"},\n'
                 f'      "edits": {listed}\n    }}')
    return (f'{{\n    "path": {_text(d.path)},\n    "line": {s.line},\n    "column": {s.column},\n'
            f'    "end_line": {s.end_line},\n    "end_column": {s.end_column},\n    "code": {ESCAPE(d.code)},\n'
            f'    "severity": {ESCAPE(d.severity.label)},\n    "message": {_message(d.message)},\n'
            f'    "param_id": {_text(d.param_id)},\n    "kernel_error": {_text(d.kernel_error)},\n'
            f'    "consequence": {_text(d.consequence)},\n'
            f'    "source": {"null" if d.source is None else _message(d.source)},\n'
            f'    "fix": {fixed}\n  }}')

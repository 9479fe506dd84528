"""The JSON report writes each finding from a template (zero.output.formats.json._template): the same
bytes as json.dumps of Diagnostic.to_json(), and where they would differ, the template is dropped."""

from __future__ import annotations

import io
import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import zero.output.formats.json as json_format
from zero.diagnostics import Diagnostic, Edit, Fix, Related, Severity, Span
from zero.engine.lint import LintResult
from zero.lists.model import Document
from zero.output.formats.common import indented_json

_TEXT = st.text(max_size=12)
_NONE_OR_TEXT = st.none() | _TEXT
_SPAN = st.builds(Span, st.integers(0, 10**6), st.integers(0, 999), st.integers(0, 10**6), st.integers(0, 999))
_FIX = st.none() | st.builds(Fix, _TEXT, st.lists(st.builds(Edit, _SPAN, _TEXT), max_size=3).map(tuple), st.booleans())
_DIAGNOSTIC = st.builds(Diagnostic, _TEXT, st.sampled_from(list(Severity)), _TEXT, _SPAN, _TEXT, _NONE_OR_TEXT, _FIX,
                        _NONE_OR_TEXT, st.just((Related(Span(1, 1, 1, 2), "x"),)), _NONE_OR_TEXT, _NONE_OR_TEXT,
                        _NONE_OR_TEXT)


@given(_DIAGNOSTIC)
@settings(max_examples=300)
def test_the_template_is_indented_json_of_to_json(d: Diagnostic) -> None:
    assert json_format._template(d) == indented_json(d.to_json(), 1)
    assert json.loads(json_format._template(d)) == d.to_json()


def test_a_template_that_differs_is_dropped(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(json_format, "_checked", set())
    monkeypatch.setattr(json_format, "_template_differs", [])
    monkeypatch.setattr(json_format, "_template", lambda d: "{}")
    found = [Diagnostic("R001", Severity.ERROR, "m", Span(1, 1, 1, 2), "a.lis"),
             Diagnostic("R002", Severity.WARNING, "n", Span(2, 1, 2, 2), "a.lis")]
    out = io.StringIO()
    json_format.render_json([LintResult("a.lis", Document("a.lis", "utf-8", [], [], []), "AXIS", found)], out)
    assert out.getvalue() == json.dumps([d.to_json() for d in found], indent=2) + "\n"
    assert json_format._template_differs

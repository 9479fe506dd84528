"""The text report stays readable on mass findings; JSON stays complete."""

from __future__ import annotations

import io

from conftest import lint_text
from zero.output.formats import render_json
from zero.output.text import MAX_SHOWN_PER_CODE, render_text


def test_mass_findings_are_counted_after_a_cap() -> None:
    text = "\n".join(f"np_grp[1].achse[0].vers{i} 5" for i in range(200)) + "\nEnde\n"
    result = lint_text(text, "mass.lis")
    assert len(result.diagnostics) == 200
    out = io.StringIO()
    render_text([result], out, color=False, summary=False)
    report = out.getvalue()
    assert report.count(": R001 ") == MAX_SHOWN_PER_CODE
    assert f"mass.lis: … and {200 - MAX_SHOWN_PER_CODE} more R001 findings in this file" in report
    complete = io.StringIO()
    render_json([result], complete)
    assert complete.getvalue().count('"code": "R001"') == 200

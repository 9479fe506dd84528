"""The text report stays readable on mass findings; JSON stays complete."""

from __future__ import annotations

import io

from hypothesis import given, settings
from hypothesis import strategies as st

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


def _printable_per_character(text: str, escape: bool) -> str:
    """printable() as it reads each character (what its shortcut for text with nothing to replace must equal)."""
    from zero.output.text import _escaped

    return "".join(ch if ch == "\t" or (" " <= ch < "\x7f") or (ord(ch) > 0x9F and not 0xD800 <= ord(ch) <= 0xDFFF)
                   else _escaped(ch) if escape else "\ufffd" for ch in text)


@settings(max_examples=400, deadline=None)
@given(st.text(), st.booleans())
def test_printable_shortcut_is_the_per_character_rule(text: str, escape: bool) -> None:
    from zero.output.text import printable

    assert printable(text, escape) == _printable_per_character(text, escape)


def test_printable_keeps_a_truncated_line_and_marks_controls() -> None:
    from zero.output.text import printable

    line = "kenngr.swe_pos 1 ( P-AXIS-00178 : Software limit switch …"
    assert printable(line) is line
    assert printable("a\x85b\udcffc\x7f") == "a\ufffdb\ufffdc\ufffd"
    assert printable("a\x85b", escape=True) == "a\\x85b"

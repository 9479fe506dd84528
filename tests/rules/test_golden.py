"""Golden fixtures from the manuals: complete findings, messages included."""

from __future__ import annotations

import pytest

from conftest import FIXTURES, builtin_registry, golden
from zero.engine.lint import lint_file
from zero.lists.model import CommentStyle, Entry
from zero.lists.tokenizer import tokenize


def _full(path: str) -> list[dict[str, object]]:
    result = lint_file(FIXTURES / "seed" / path, builtin_registry())
    out = []
    for d in result.diagnostics:
        j = d.to_json()
        j["path"] = path
        out.append(j)
    return out


def test_seed_zero_example(request: pytest.FixtureRequest) -> None:
    """ZERO manual §3: errors exactly at the two `achse[j]. inaktiv` lines: the plausibility check of a
    zero-offset list reports an incorrectly written parameter and the job is aborted (P-ERR-20407)."""
    actual = _full("nullp_3achsen.lis")
    expected = golden(FIXTURES / "seed" / "nullp_3achsen.expected.json", actual,
                      request.config.getoption("--update-golden"))
    assert actual == expected
    errors = [(d["line"], d["code"]) for d in actual if d["severity"] == "error"]
    assert errors == [(19, "S004"), (21, "S004")]
    assert all(d["kernel_error"] == "P-ERR-20407" and d["consequence"] == "aborted"
               for d in actual if d["code"] == "S004")
    # the rest is information about offsets the example masks on purpose
    assert {d["code"] for d in actual if d["severity"] == "info"} == {"M003"}


def test_seed_comment_example(request: pytest.FixtureRequest) -> None:
    """ZERO manual §1.4. The `*****` and `...` lines are the manual's own text as extracted
    (wrapped decoration and ellipsis), so the controller would reject them: S001."""
    actual = _full("kommentare.lis")
    expected = golden(FIXTURES / "seed" / "kommentare.expected.json", actual,
                      request.config.getoption("--update-golden"))
    assert actual == expected
    assert [d["line"] for d in actual if d["code"] == "S001"] == [2, 5, 13, 14]


def test_seed_comment_styles_are_read() -> None:
    doc = tokenize((FIXTURES / "seed" / "kommentare.lis").read_bytes())
    entries = [i for i in doc.items if isinstance(i, Entry)]
    styles = [(e.key_text, e.value, e.comment_style) for e in entries]
    assert styles == [
        ("dummy[1]", "1", CommentStyle.TEXT),
        ("dummy[2]", "1", CommentStyle.HASH),
        ("dummy[3]", "1", CommentStyle.PAREN),
        ("dummy[4]", "1", CommentStyle.BLOCK),
        ("beispiel[0].bezeichnung", "STRING_1", CommentStyle.PAREN),
        ("beispiel[1].bezeichnung", '"STRING_(2)"', CommentStyle.PAREN),
    ]

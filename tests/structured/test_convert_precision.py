"""Convert writes a list line only when the controller reads it as the YAML/TOML data says; the
user's visible order wins over the recorded one; a missing record says what it implies."""

from __future__ import annotations

import pytest

from zero.catalog.registry import Registry
from zero.engine.convert import convert
from zero.errors import ZeroError

OFFSET = "np_grp:\n  1:\n    achse:\n      0:\n        versch: {}\n"


@pytest.mark.parametrize(("value", "reason"), [
    ("true", "is a YAML boolean"),
    ("on", "is a YAML boolean"),
    ("1_000_000", "in a form the controller reads differently"),
    ("010", "in a form the controller reads differently"),
    ("1:30", "in a form the controller reads differently"),
    ("1e3", "is a floating-point number but P-ZERO-00003 is SGN32"),
    ("12.5", "is a floating-point number but P-ZERO-00003 is SGN32"),
    (".inf", "no list line holds"),
])
def test_a_value_the_list_would_read_differently_is_refused_where_it_stands(
        registry: Registry, value: str, reason: str) -> None:
    with pytest.raises(ZeroError, match=reason) as info:
        convert(OFFSET.format(value).encode(), "yaml", "lis", registry, "t.yaml", check=False)
    assert (info.value.line, info.value.column) == (5, 17)


@pytest.mark.parametrize("value", ["5", "-5", "0x1F", '"TRUE"', '"010"'])
def test_values_that_read_the_same_are_written(registry: Registry, value: str) -> None:
    out = convert(OFFSET.format(value).encode(), "yaml", "lis", registry, "t.yaml", check=False).output
    assert out.split(b"\n")[0].split()[-1] == value.strip('"').encode()


def test_the_users_visible_order_wins_over_the_recorded_one(registry: Registry) -> None:
    data = b"b.x 1\na.y 2\nb.z 3\nEnde\n"
    yaml = convert(data, "lis", "yaml", registry, "t.lis").output.decode()
    assert "order:" in yaml  # the list interleaves b and a: the record keeps its order
    assert convert(yaml.encode(), "yaml", "lis", registry, "t.yaml", check=False).output == data
    moved = yaml.replace('b:\n  x: 1\n  z: 3\na:\n  "y": 2\n', 'a:\n  "y": 2\nb:\n  x: 1\n  z: 3\n')
    assert moved != yaml
    out = convert(moved.encode(), "yaml", "lis", registry, "t.yaml", check=False).output
    assert out == b"a.y 2\nb.x 1\nb.z 3\nEnde\n"


def test_a_missing_record_says_what_is_written(registry: Registry) -> None:
    result = convert(OFFSET.format(5).encode(), "yaml", "lis", registry, "t.yaml", check=False)
    assert result.notes == ["no `_zero` record: the list is written in UTF-8 with LF line endings and the "
                            "canonical layout (convert the original list again to keep its encoding and layout)"]


@pytest.mark.parametrize(("text", "line", "column"), [
    ("np_grp:\n  # comment with \x01 control\n  1:\n    achse:\n      0:\n        versch: 5\n", 2, 18),
    ("a: 1\n# tail \x03 comment\n", 2, 8),
])
def test_a_character_yaml_refuses_is_located_even_in_a_comment(
        registry: Registry, text: str, line: int, column: int) -> None:
    with pytest.raises(ZeroError, match="is not allowed in YAML") as info:
        convert(text.encode(), "yaml", "lis", registry, "t.yaml")
    assert (info.value.line, info.value.column) == (line, column)
    assert "\n" not in str(info.value)

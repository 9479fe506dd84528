"""The fuzz targets, importable without atheris (tests replay crashes through them).

The first byte of an input picks the target; the rest is the data:
0 tokenizer + lint of list bytes, 1 list → YAML/TOML/JSON → list (must be the
identity), 2 YAML reader, 3 TOML reader, 4 JSON reader, 5 diff of two halves.
Only zero's own refusals (ConvertError) may escape; anything else is a crash.
"""

from __future__ import annotations

from zero.convert import convert, read_tree
from zero.diff import diff_sides, read_side
from zero.lint import lint_bytes
from zero.registry import default_registry
from zero.structured import ConvertError

default_registry()


def check_lint(data: bytes) -> None:
    result = lint_bytes(data, "f.lis")
    n = len(result.document.lines)
    for d in result.diagnostics:
        assert 1 <= d.span.line <= max(n, 1) + 1, d


def check_round_trip(data: bytes) -> None:
    for fmt in ("yaml", "toml", "json"):
        try:
            first = convert(data, "lis", fmt, "f.lis")
        except ConvertError:
            return
        back = convert(first.output, fmt, "lis", "f." + fmt, check=False).output
        if any("mixed line endings" in n for n in first.notes):  # said plainly: one style
            assert back.replace(b"\r\n", b"\n") == data.replace(b"\r\n", b"\n"), (fmt, data, back)
        else:
            assert back == data, (fmt, data, back)


def check_reader(fmt: str, data: bytes) -> None:
    try:
        read_tree(data, fmt, "f." + fmt)
        convert(data, fmt, "lis", "f." + fmt)
        for other in ("yaml", "toml", "json"):
            convert(data, fmt, other, "f." + fmt, check=False)
    except ConvertError:
        pass


def check_diff(data: bytes) -> None:
    half = len(data) // 2
    a, b = read_side(data[:half], "lis", "a"), read_side(data[half:], "lis", "b")
    diff_sides(a, b)
    diff_sides(b, a)


def one_input(raw: bytes) -> None:
    if not raw:
        return
    target, data = raw[0] % 6, raw[1:]
    if target == 0:
        check_lint(data)
    elif target == 1:
        check_round_trip(data)
    elif target in (2, 3, 4):
        check_reader(("yaml", "toml", "json")[target - 2], data)
    else:
        check_diff(data)

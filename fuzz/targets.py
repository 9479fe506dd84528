"""The fuzz targets, importable without atheris (tests replay crashes through them).

The first byte of an input picks the target; the rest is the data:
0 tokenizer + lint of list bytes, 1 list → YAML/TOML/JSON → list (must be the
identity), 2 YAML reader, 3 TOML reader, 4 JSON reader, 5 diff of two halves,
6 NC program against the fixture machine, 7 zero format (idempotent, meaning kept),
8 fixes (a fixed list has no fixable finding left, or the fix loop stopped).
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


_MACHINE = None


def check_program(data: bytes) -> None:
    global _MACHINE
    from pathlib import Path

    from zero.machine import load_machine
    from zero.program import lint_program

    if _MACHINE is None:
        _MACHINE = load_machine(Path(__file__).resolve().parent.parent / "fixtures" / "machine" / "listen"
                                / "hochlauf.lis")
    result = lint_program(data, "f.nc", machine=_MACHINE)
    for d in result.diagnostics:
        assert 1 <= d.span.line <= max(len(result.document.lines), 1), d


def check_format(data: bytes) -> None:
    from zero.diff import DiffOptions, diff_sides, read_side
    from zero.fix import format_bytes

    try:
        once = format_bytes(data, "f.lis")
    except ConvertError:
        return
    assert format_bytes(once, "f.lis") == once, (data, once)
    assert diff_sides(read_side(data, "lis", "a"), read_side(once, "lis", "b"),
                      DiffOptions(strict=True, comments=True)) == [], (data, once)


def check_fix(data: bytes) -> None:
    from zero.fix import fix_bytes

    fix_bytes(data, "f.lis", unsafe=True)


def one_input(raw: bytes) -> None:
    if not raw:
        return
    target, data = raw[0] % 9, raw[1:]
    if target == 0:
        check_lint(data)
    elif target == 1:
        check_round_trip(data)
    elif target in (2, 3, 4):
        check_reader(("yaml", "toml", "json")[target - 2], data)
    elif target == 5:
        check_diff(data)
    elif target == 6:
        check_program(data)
    elif target == 7:
        check_format(data)
    else:
        check_fix(data)

"""The fuzz targets, importable without atheris (tests replay crashes through them).

The first byte of an input picks the target; the rest is the data:
0 tokenizer + lint of list bytes, 1 list → YAML/TOML/JSON → list (must be the
identity), 2 YAML reader, 3 TOML reader, 4 JSON reader, 5 diff of two halves,
6 NC program against the fixture machine, 7 zero format (idempotent, meaning kept),
8 fixes (a fixed list has no fixable finding left, or the fix loop stopped).
Only zero's own refusals (ZeroError) may escape; anything else is a crash.
"""

from __future__ import annotations

from pathlib import Path

from zero.catalog.registry import load_registry
from zero.diff import DiffOptions, diff_sides, read_side
from zero.engine.convert import convert
from zero.engine.fixes import fix_bytes
from zero.engine.formatting import format_bytes
from zero.engine.lint import lint_bytes, lint_program
from zero.errors import ZeroError
from zero.machine.model import Machine, load_machine
from zero.structured.formats import read_tree

REGISTRY = load_registry()
MACHINE_STARTUP = Path(__file__).resolve().parent.parent / "fixtures" / "machine" / "listen" / "hochlauf.lis"


def check_lint(data: bytes) -> None:
    result = lint_bytes(data, REGISTRY, "f.lis")
    n = len(result.document.lines)
    for d in result.diagnostics:
        assert 1 <= d.span.line <= max(n, 1) + 1, d


def check_round_trip(data: bytes) -> None:
    for fmt in ("yaml", "toml", "json"):
        try:
            first = convert(data, "lis", fmt, REGISTRY, "f.lis")
        except ZeroError:
            return
        back = convert(first.output, fmt, "lis", REGISTRY, "f." + fmt, check=False).output
        if any("mixed line endings" in n for n in first.notes):  # said plainly: one style
            assert back.replace(b"\r\n", b"\n") == data.replace(b"\r\n", b"\n"), (fmt, data, back)
        else:
            assert back == data, (fmt, data, back)


def check_reader(fmt: str, data: bytes) -> None:
    try:
        read_tree(data, fmt, REGISTRY, "f." + fmt)
        convert(data, fmt, "lis", REGISTRY, "f." + fmt)
        for other in ("yaml", "toml", "json"):
            convert(data, fmt, other, REGISTRY, "f." + fmt, check=False)
    except ZeroError:
        pass


def check_diff(data: bytes) -> None:
    half = len(data) // 2
    try:
        a, b = read_side(data[:half], "lis", "a", REGISTRY), read_side(data[half:], "lis", "b", REGISTRY)
    except ZeroError:  # a binary half: refused plainly
        return
    diff_sides(a, b, REGISTRY)
    diff_sides(b, a, REGISTRY)


_machine: list[Machine] = []


def check_program(data: bytes) -> None:
    if not _machine:
        _machine.append(load_machine(MACHINE_STARTUP, REGISTRY))
    result = lint_program(data, REGISTRY, "f.nc", machine=_machine[0])
    for d in result.diagnostics:
        assert 1 <= d.span.line <= max(len(result.document.lines), 1), d


def check_format(data: bytes) -> None:
    try:
        once = format_bytes(data, "f.lis", REGISTRY)
    except ZeroError:
        return
    assert format_bytes(once, "f.lis", REGISTRY) == once, (data, once)
    try:
        before = read_side(data, "lis", "a", REGISTRY)
    except ZeroError:  # not text: format refused nothing, but there is nothing to compare
        return
    assert diff_sides(before, read_side(once, "lis", "b", REGISTRY), REGISTRY,
                      DiffOptions(strict=True, comments=True)) == [], (data, once)


def check_fix(data: bytes) -> None:
    fix_bytes(data, "f.lis", REGISTRY, unsafe=True)


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

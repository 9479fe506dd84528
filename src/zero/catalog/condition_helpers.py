"""What the conditions written at build time and the compiled closures share at run time (issue 40: start-up):
the language's names and facts (``DEFAULT_LIST``, ``unique:``, ``elsewhere:``, the drive types of
``supports()``), the operators, and the helpers the written functions call (the closures' bodies, see
:mod:`~zero.catalog.condition_source`). Kept apart from the parser (:mod:`~zero.catalog.conditions`), so that a
lint that reads the written functions imports no parser.
"""

from __future__ import annotations

from collections.abc import Callable

from zero.patterns import compiled

__all__ = ["DEFAULT_LIST", "DRIVE_TYPE", "ELSEWHERE", "HELPERS", "UNIQUE", "Compiled", "Lookup", "Number",
           "supported_drive_types"]

Number = int | float
# A parameter's value by (ID, element index or None for "the checked parameter's"); None: not known.
# A STRING parameter's value is its text.
Lookup = Callable[[str, int | None], Number | str | None]
_Value = Number | str | bool | None
Compiled = Callable[[Lookup], "_Value"]

DEFAULT_LIST = "DEFAULT_LIST"  # a fact of the list, not a parameter: read by the lookup like one
_NAME = r"[A-Za-z0-9_]+"  # what isname() accepts (compiled at its first use, through re's own cache)
UNIQUE = "unique:"  # the lookup's name of the fact unique(...) asks for
ELSEWHERE = "elsewhere:"  # and of elsewhere(...)
DRIVE_TYPE = "P-AXIS-00020"  # kenngr.antr_typ: what supports() reads


def _num(v: Number | bool) -> Number:
    return v if isinstance(v, float) else int(v)


def _drive_types() -> dict[str, frozenset[int]]:
    from zero.catalog.data.drive_types import DRIVE_TYPES  # start-up: read at the first supports()

    return {str(row["param"]): frozenset(int(str(t)) for t in row["types"]) for row in DRIVE_TYPES
            if "param" in row}  # a row for a subtree of keys (`antr.sercos.`) names no one parameter


_SUPPORTED: dict[str, frozenset[int]] = {}


def supported_drive_types(pid: str) -> frozenset[int] | None:
    """The drive types (P-AXIS-00020 values) the table lists for ``pid``; ``None``: no row."""
    if not _SUPPORTED:
        _SUPPORTED.update(_drive_types())
    return _SUPPORTED.get(pid)


_OPS: dict[str, Callable[[Number, Number], _Value]] = {
    "+": lambda a, b: a + b, "-": lambda a, b: a - b, "*": lambda a, b: a * b,
    "/": lambda a, b: None if b == 0 else a / b, "%": lambda a, b: None if b == 0 else a % b,
    "&": lambda a, b: int(a) & int(b),
    "<": lambda a, b: a < b, "<=": lambda a, b: a <= b, ">": lambda a, b: a > b, ">=": lambda a, b: a >= b,
    "==": lambda a, b: a == b, "!=": lambda a, b: a != b,
}


def _member(v: _Value, choices: tuple[Number | str, ...], negated: bool) -> _Value:
    if v is None:
        return None
    text = isinstance(v, str)
    for c in choices:  # any(): a loop, not a generator left unfinished
        if isinstance(c, str) == text and v == c:
            return not negated
    return negated


def _not(v: _Value) -> _Value:
    return None if v is None else (not v)


def _neg(v: _Value) -> _Value:
    return None if v is None or isinstance(v, str) else -v


def _abs(v: _Value) -> _Value:
    return None if v is None or isinstance(v, str) else abs(v)


def _len(v: _Value) -> _Value:
    return len(v) if isinstance(v, str) else None


def _isname(v: _Value) -> _Value:
    return compiled(_NAME).fullmatch(v) is not None if isinstance(v, str) and v else None


def _startswith(a: _Value, b: _Value) -> _Value:
    return a.startswith(b) if isinstance(a, str) and isinstance(b, str) else None


def _supports(pid: str, lookup: Lookup) -> _Value:
    types = supported_drive_types(pid)
    drive = lookup(DRIVE_TYPE, None)
    if types is None or drive is None or isinstance(drive, str):
        return None
    return int(drive) in types


def _fact(v: _Value) -> _Value:
    return None if v is None else bool(v)


def _both(a: _Value, b: _Value) -> _Value:  # `a` neither known nor false: `b` decides
    return None if a is None or b is None else bool(b)


def _binary(op: str, a: _Value, b: _Value) -> _Value:
    if a is None or b is None:
        return None
    if isinstance(a, str) or isinstance(b, str):  # text compares with text, for equality only
        return _OPS[op](a, b) if op in ("==", "!=") and isinstance(a, str) and isinstance(b, str) else None  # type: ignore[arg-type]
    try:  # _num of each, inline (a number's type tested first: most are int or float already)
        return _OPS[op](a if type(a) is float or type(a) is int else _num(a),
                        b if type(b) is float or type(b) is int else _num(b))
    except OverflowError:  # an integer beyond a float's range in arithmetic with a float: not known
        return None


HELPERS = ("_abs", "_binary", "_both", "_fact", "_isname", "_len", "_member", "_neg", "_not", "_startswith",
           "_supports")

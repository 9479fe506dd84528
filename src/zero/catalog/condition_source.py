"""Conditions as Python source, written at build time: what :func:`~zero.catalog.conditions.compile_condition`
builds at run time, read from bytecode instead (issue 40: start-up).

``tools/gen_conditions.py`` writes each K rule's condition with :func:`source` into
``data/startup_compiled.py``; :mod:`zero.rules.startup` takes a function from there where the row's
condition text is the one it was written from, and compiles the text otherwise. A function written here
gives what the compiled closure gives for every lookup (``tests/rules/test_condition_source.py``
compares them): ``None`` where a value it needs is not known, ``and``/``or`` deciding without the
unknown side where the known side decides. The helpers below are the closures' bodies.
"""

from __future__ import annotations

import re

from zero.catalog.conditions import (
    _NAME,
    _OPS,
    DRIVE_TYPE,
    ELSEWHERE,
    UNIQUE,
    Binary,
    Call,
    Lookup,
    Member,
    Num,
    Number,
    Ref,
    Str,
    Unary,
    _num,
    _Value,
    supported_drive_types,
)

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from zero.catalog.conditions import Node

__all__ = ["source"]


def _member(v: _Value, choices: tuple[Number | str, ...], negated: bool) -> _Value:
    if v is None:
        return None
    hit = any(v == c for c in choices if isinstance(v, str) == isinstance(c, str))
    return hit != negated


def _not(v: _Value) -> _Value:
    return None if v is None else (not v)


def _neg(v: _Value) -> _Value:
    return None if v is None or isinstance(v, str) else -v


def _abs(v: _Value) -> _Value:
    return None if v is None or isinstance(v, str) else abs(v)


def _len(v: _Value) -> _Value:
    return len(v) if isinstance(v, str) else None


def _isname(v: _Value) -> _Value:
    return re.fullmatch(_NAME, v) is not None if isinstance(v, str) and v else None


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
    try:
        return _OPS[op](_num(a), _num(b))
    except OverflowError:  # an integer beyond a float's range in arithmetic with a float: not known
        return None


HELPERS = ("_abs", "_binary", "_both", "_fact", "_isname", "_len", "_member", "_neg", "_not", "_startswith",
           "_supports")


class _Writer:
    def __init__(self) -> None:
        self.n = 0

    def fresh(self) -> str:
        self.n += 1
        return f"_v{self.n}"

    def expr(self, node: Node) -> str:
        if isinstance(node, Num | Str):
            return repr(node.value)
        if isinstance(node, Member):
            return f"_member({self.expr(node.arg)}, {node.choices!r}, {node.negated!r})"
        if isinstance(node, Ref):
            return f"lookup({node.pid!r}, {node.index!r})"
        if isinstance(node, Unary):
            return f"{'_not' if node.op == 'not' else '_neg'}({self.expr(node.arg)})"
        if isinstance(node, Call):
            if node.name == "supports":
                ref = node.args[0]
                assert isinstance(ref, Ref)
                return f"_supports({ref.pid!r}, lookup)"
            if node.name in ("unique", "elsewhere"):
                fact = UNIQUE if node.name == "unique" else ELSEWHERE
                key = fact + ",".join(a.pid for a in node.args if isinstance(a, Ref))
                return f"_fact(lookup({key!r}, None))"
            args = ", ".join(self.expr(a) for a in node.args)
            return f"_{node.name}({args})"
        assert isinstance(node, Binary)
        if node.op in ("and", "or"):
            # the left side first; the right one only where the left does not decide (as the closures)
            a = self.fresh()
            decided = f"not {a}" if node.op == "and" else a
            return (f"({node.op == 'or'!r} if ({a} := {self.expr(node.left)}) is not None and {decided} "
                    f"else _both({a}, {self.expr(node.right)}))")
        return f"_binary({node.op!r}, {self.expr(node.left)}, {self.expr(node.right)})"


def source(name: str, node: Node) -> str:
    """A ``def name(lookup)`` that evaluates ``node`` as its compiled closure does."""
    return f"def {name}(lookup):\n    return {_Writer().expr(node)}\n"

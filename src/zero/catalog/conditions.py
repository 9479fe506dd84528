"""Conditions between parameters, as the kernel's documentation states them: parsed once, evaluated
on a list's values.

The language is small and closed (no names but parameter IDs, no calls but ``abs``), so a table row
can never run code: numbers (``12``, ``0x40``, ``1.5``), parameter IDs (``P-AXIS-00219``; with an
element ``P-AXIS-00212.0``, without one the element of the parameter being checked), ``+ - * /``,
parentheses, comparisons ``< <= > >= == !=``, ``and``, ``or``, ``not``, ``abs(x)`` and ``&`` for bit
tests (``(P-AXIS-00015 & 0x40) != 0``), and one fact about the list itself: ``DEFAULT_LIST`` (1 in
a default list, the template the controller reads under the lists of its kind, else 0).
:func:`parse` raises :class:`ValueError` for anything else.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Union

Number = int | float
# A parameter's value by (ID, element index or None for "the checked parameter's"); None: not known.
Lookup = Callable[[str, int | None], Number | None]

DEFAULT_LIST = "DEFAULT_LIST"  # a fact of the list, not a parameter: read by the lookup like one
_TOKEN = re.compile(r"\s*(?:(P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)?|DEFAULT_LIST\b)|(0x[0-9A-Fa-f]+|[0-9]+(?:\.[0-9]+)?)"
                    r"|(<=|>=|==|!=|<|>|\+|-|\*|/|&|\(|\)|,)|(and|or|not|abs)\b)")

Node = Union["Num", "Ref", "Unary", "Binary", "Call"]


class Num:
    __slots__ = ("value",)

    def __init__(self, value: Number) -> None:
        self.value = value


class Ref:
    __slots__ = ("index", "pid")

    def __init__(self, pid: str, index: int | None) -> None:
        self.pid, self.index = pid, index


class Unary:
    __slots__ = ("arg", "op")

    def __init__(self, op: str, arg: Node) -> None:
        self.op, self.arg = op, arg


class Binary:
    __slots__ = ("left", "op", "right")

    def __init__(self, op: str, left: Node, right: Node) -> None:
        self.op, self.left, self.right = op, left, right


class Call:
    __slots__ = ("arg", "name")

    def __init__(self, name: str, arg: Node) -> None:
        self.name, self.arg = name, arg


def _tokens(text: str) -> list[str]:
    out: list[str] = []
    pos = 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            raise ValueError(f"cannot read the condition at {text[pos:pos + 12]!r}")
        out.append(m.group(m.lastindex or 0))
        pos = m.end()
    return out


class _Parser:
    def __init__(self, text: str) -> None:
        self.toks = _tokens(text)
        self.i = 0

    def peek(self) -> str | None:
        return self.toks[self.i] if self.i < len(self.toks) else None

    def take(self, want: str | None = None) -> str:
        tok = self.peek()
        if tok is None or (want is not None and tok != want):
            raise ValueError(f"expected {want or 'more'} in the condition, found {tok!r}")
        self.i += 1
        return tok

    def parse(self) -> Node:
        node = self.or_()
        if self.peek() is not None:
            raise ValueError(f"unexpected {self.peek()!r} in the condition")
        return node

    def or_(self) -> Node:
        node = self.and_()
        while self.peek() == "or":
            self.take()
            node = Binary("or", node, self.and_())
        return node

    def and_(self) -> Node:
        node = self.not_()
        while self.peek() == "and":
            self.take()
            node = Binary("and", node, self.not_())
        return node

    def not_(self) -> Node:
        if self.peek() == "not":
            self.take()
            return Unary("not", self.not_())
        return self.compare()

    def compare(self) -> Node:
        node = self.bits()
        while self.peek() in ("<", "<=", ">", ">=", "==", "!="):
            op = self.take()
            node = Binary(op, node, self.bits())
        return node

    def bits(self) -> Node:
        node = self.sum()
        while self.peek() == "&":
            self.take()
            node = Binary("&", node, self.sum())
        return node

    def sum(self) -> Node:
        node = self.product()
        while self.peek() in ("+", "-"):
            op = self.take()
            node = Binary(op, node, self.product())
        return node

    def product(self) -> Node:
        node = self.unary()
        while self.peek() in ("*", "/"):
            op = self.take()
            node = Binary(op, node, self.unary())
        return node

    def unary(self) -> Node:
        if self.peek() == "-":
            self.take()
            return Unary("-", self.unary())
        return self.atom()

    def atom(self) -> Node:
        tok = self.take()
        if tok == "(":
            node = self.or_()
            self.take(")")
            return node
        if tok == "abs":
            self.take("(")
            arg = self.or_()
            self.take(")")
            return Call("abs", arg)
        if tok == DEFAULT_LIST:
            return Ref(tok, None)
        if tok.startswith("P-"):
            pid, _, idx = tok.partition(".")
            return Ref(pid, int(idx) if idx else None)
        if tok.startswith("0x"):
            return Num(int(tok, 16))
        if tok[:1].isdigit():
            return Num(float(tok) if "." in tok else int(tok))
        raise ValueError(f"unexpected {tok!r} in the condition")


def parse(text: str) -> Node:
    """A condition as a tree; :class:`ValueError` for text outside the language."""
    return _Parser(text).parse()


def refs(node: Node) -> list[str]:
    """The parameter IDs a condition reads, in order of appearance (not ``DEFAULT_LIST``)."""
    return list(dict.fromkeys(pid for pid, _ in ref_elements(node)))


def ref_elements(node: Node) -> list[tuple[str, int | None]]:
    """Each parameter a condition reads with the element it names (``P-AXIS-00212.0``: 0; ``None``: the
    checked parameter's), in order of appearance, once each."""
    out: list[tuple[str, int | None]] = []
    stack = [node]
    while stack:
        n = stack.pop()
        if isinstance(n, Ref) and n.pid != DEFAULT_LIST:
            out.append((n.pid, n.index))
        elif isinstance(n, Unary | Call):
            stack.append(n.arg)
        elif isinstance(n, Binary):
            stack.extend((n.right, n.left))
    return list(dict.fromkeys(out))


_Value = Number | bool | None


def _num(v: Number | bool) -> Number:
    return v if isinstance(v, float) else int(v)


Compiled = Callable[[Lookup], "_Value"]
_OPS: dict[str, Callable[[Number, Number], _Value]] = {
    "+": lambda a, b: a + b, "-": lambda a, b: a - b, "*": lambda a, b: a * b,
    "/": lambda a, b: None if b == 0 else a / b, "&": lambda a, b: int(a) & int(b),
    "<": lambda a, b: a < b, "<=": lambda a, b: a <= b, ">": lambda a, b: a > b, ">=": lambda a, b: a >= b,
    "==": lambda a, b: a == b, "!=": lambda a, b: a != b,
}


def compile_condition(node: Node) -> Compiled:
    """A condition as a function of the lookup, built once (a fleet evaluates each condition once per
    list). ``None`` where a parameter it needs is not known: then nothing is said; ``and``/``or`` decide
    without the unknown side where the known side decides."""
    if isinstance(node, Num):
        value = node.value
        return lambda _lookup: value
    if isinstance(node, Ref):
        pid, index = node.pid, node.index
        return lambda lookup: lookup(pid, index)
    if isinstance(node, Unary):
        arg = compile_condition(node.arg)
        if node.op == "not":
            return lambda lookup: None if (v := arg(lookup)) is None else (not v)
        return lambda lookup: None if (v := arg(lookup)) is None else -v
    if isinstance(node, Call):
        arg = compile_condition(node.arg)
        return lambda lookup: None if (v := arg(lookup)) is None else abs(v)
    left, right = compile_condition(node.left), compile_condition(node.right)
    if node.op == "and":
        def both(lookup: Lookup) -> _Value:
            a = left(lookup)
            if a is not None and not a:
                return False
            b = right(lookup)
            return None if a is None or b is None else bool(b)
        return both
    if node.op == "or":
        def either(lookup: Lookup) -> _Value:
            a = left(lookup)
            if a is not None and a:
                return True
            b = right(lookup)
            return None if a is None or b is None else bool(b)
        return either
    op = _OPS[node.op]

    def binary(lookup: Lookup) -> _Value:
        a, b = left(lookup), right(lookup)
        return None if a is None or b is None else op(_num(a), _num(b))
    return binary

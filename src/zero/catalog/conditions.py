"""Conditions between parameters, as the kernel's documentation states them: parsed once, evaluated
on a list's values.

The language is small and closed (no names but parameter IDs, no calls but the few below), so a table
row can never run code: numbers (``12``, ``0x40``, ``1.5``, ``1e199``), parameter IDs (``P-AXIS-00219``; with an
element ``P-AXIS-00212.0``, without one the element of the parameter being checked), ``+ - * /``,
``%`` (the remainder: ``P-RTCF-00002 % P-RTCF-00003 == 0``, a whole multiple),
parentheses, comparisons ``< <= > >= == !=``, ``and``, ``or``, ``not``, ``abs(x)`` and ``&`` for bit
tests (``(P-AXIS-00015 & 0x40) != 0``), and one fact about the list itself: ``DEFAULT_LIST`` (1 in
a default list, the template the controller reads under the lists of its kind, else 0).

What the documentation says of text and of the drive type can be said too: string literals
(``"S"`` or ``'S'``), ``len(x)`` (a string's length), ``startswith(x, "S")``, ``isname(x)`` (a
non-empty text of the letters A-Z and a-z, the digits 0-9 and the underscore only), set membership
``x in ("X", "Y", 4)`` and ``x not in (...)``, ``unique(P-CHAN-00007)`` (a fact of the whole list,
answered by the lookup under the name ``unique:P-CHAN-00007``: 1 where the checked element's value
is no other element's value of the parameters named, 0 where it is one, unknown where it is not
set), ``elsewhere(P, Q)`` (answered as ``elsewhere:P,Q``: 1 where the checked element's value of
``P`` is the value of ``Q`` in another element of the same group, the last index differing: the
master of one coupling pair that is the slave of another), and ``supports(P-AXIS-00294)``: 1 where the axis's
drive type (P-AXIS-00020) is one the drive-type table (``data/drive_types.toml``, each row from the
parameter page's "Drive types" row) lists for that parameter, 0 where it is not, unknown where the
table has no row or the drive type is not known. A comparison of a string with a number is
unknown, never an error. :func:`parse` raises :class:`ValueError` for anything else.
"""

from __future__ import annotations

import re

from zero.catalog.condition_helpers import (
    _NAME,
    _OPS,
    DEFAULT_LIST,
    DRIVE_TYPE,
    ELSEWHERE,
    UNIQUE,
    Compiled,
    Lookup,
    Number,
    _num,
    _Value,
    supported_drive_types,
)

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
# compiled at the first condition parsed (through re's own cache): the K rules' and the prose ranges'
# are parsed at build time, so a lint seldom parses one (issue 40: start-up)
_TOKEN = (r"\s*(?:(P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)?|DEFAULT_LIST\b)"
          r"|(0x[0-9A-Fa-f]+|[0-9]+(?:\.[0-9]+)?(?:e[+-]?[0-9]+)?)"
          r"|(\"[^\"\\\n]*\"|'[^'\\\n]*')"
          r"|(<=|>=|==|!=|<|>|\+|-|\*|/|%|&|\(|\)|,)|(and|or|not|in|abs|len|startswith|isname|supports|unique|elsewhere)\b)")
# arguments of each function; 0: one or more IDs
_FUNCTIONS = {"abs": 1, "len": 1, "startswith": 2, "isname": 1, "supports": 1, "unique": 0, "elsewhere": 2}


class Num:
    __slots__ = ("value",)

    def __init__(self, value: Number) -> None:
        self.value = value


class Str:
    __slots__ = ("value",)

    def __init__(self, value: str) -> None:
        self.value = value


class Member:
    """``x in (a, b)``; ``negated``: ``x not in (a, b)``."""

    __slots__ = ("arg", "choices", "negated")

    def __init__(self, arg: Node, choices: tuple[Number | str, ...], negated: bool) -> None:
        self.arg, self.choices, self.negated = arg, choices, negated


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
    __slots__ = ("args", "name")

    def __init__(self, name: str, *args: Node) -> None:
        self.name, self.args = name, args

    @property
    def arg(self) -> Node:
        return self.args[0]


if TYPE_CHECKING:  # an expression's node (type checkers only)
    Node = Num | Str | Ref | Unary | Binary | Call | Member


def _tokens(text: str) -> list[str]:
    out: list[str] = []
    pos = 0
    text = text.rstrip()
    token = re.compile(_TOKEN)
    while pos < len(text):
        m = token.match(text, pos)
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
        while self.peek() in ("<", "<=", ">", ">=", "==", "!=", "in", "not"):
            if self.peek() in ("in", "not"):
                negated = self.take() == "not"
                if negated:
                    self.take("in")
                node = Member(node, self.choices(), negated)
                continue
            op = self.take()
            node = Binary(op, node, self.bits())
        return node

    def choices(self) -> tuple[Number | str, ...]:
        """``("X", "Y", 4)``: literals only."""
        self.take("(")
        out: list[Number | str] = []
        while True:
            lit = self.atom()
            if isinstance(lit, Unary) and lit.op == "-" and isinstance(lit.arg, Num):
                out.append(-lit.arg.value)
            elif isinstance(lit, Num | Str):
                out.append(lit.value)
            else:
                raise ValueError("a set holds literals only")
            sep = self.take()
            if sep == ")":
                return tuple(out)
            if sep != ",":
                raise ValueError(f"expected , or ) in a set, found {sep!r}")

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
        while self.peek() in ("*", "/", "%"):
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
        if tok == "-":
            return Unary("-", self.atom())
        if tok in _FUNCTIONS:
            self.take("(")
            args = [self.or_()]
            while self.peek() == ",":
                self.take()
                args.append(self.or_())
            self.take(")")
            if _FUNCTIONS[tok] and len(args) != _FUNCTIONS[tok]:
                raise ValueError(f"{tok}() takes {_FUNCTIONS[tok]} argument(s)")
            if tok in ("supports", "unique", "elsewhere") and not all(isinstance(a, Ref) and a.pid != DEFAULT_LIST
                                                         and a.index is None for a in args):
                raise ValueError(f"{tok}() takes parameter IDs")
            return Call(tok, *args)
        if tok[:1] in "\"'":
            return Str(tok[1:-1])
        if tok == DEFAULT_LIST:
            return Ref(tok, None)
        if tok.startswith("P-"):
            pid, _, idx = tok.partition(".")
            return Ref(pid, int(idx) if idx else None)
        if tok.startswith("0x"):
            return Num(int(tok, 16))
        if tok[:1].isdigit():
            return Num(float(tok) if "." in tok or "e" in tok else int(tok))
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
        elif isinstance(n, Call) and n.name == "supports":
            out.append((DRIVE_TYPE, None))  # the drive type is read; the parameter named is not
        elif isinstance(n, Call) and n.name in ("unique", "elsewhere"):
            out.extend((a.pid, None) for a in n.args if isinstance(a, Ref))
        elif isinstance(n, Call):
            stack.extend(reversed(n.args))
        elif isinstance(n, Unary | Member):
            stack.append(n.arg)
        elif isinstance(n, Binary):
            stack.extend((n.right, n.left))
    return list(dict.fromkeys(out))


def compile_condition(node: Node) -> Compiled:
    """A condition as a function of the lookup, built once (a fleet evaluates each condition once per
    list). ``None`` where a parameter it needs is not known: then nothing is said; ``and``/``or`` decide
    without the unknown side where the known side decides."""
    if isinstance(node, Num | Str):
        value = node.value
        return lambda _lookup: value
    if isinstance(node, Member):
        arg, choices, negated = compile_condition(node.arg), node.choices, node.negated

        def member(lookup: Lookup) -> _Value:
            v = arg(lookup)
            if v is None:
                return None
            hit = any(v == c for c in choices if isinstance(v, str) == isinstance(c, str))
            return hit != negated
        return member
    if isinstance(node, Ref):
        pid, index = node.pid, node.index
        return lambda lookup: lookup(pid, index)
    if isinstance(node, Unary):
        arg = compile_condition(node.arg)
        if node.op == "not":
            return lambda lookup: None if (v := arg(lookup)) is None else (not v)
        return lambda lookup: None if (v := arg(lookup)) is None or isinstance(v, str) else -v
    if isinstance(node, Call):
        return _compile_call(node)
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

    equality = node.op in ("==", "!=")

    def binary(lookup: Lookup) -> _Value:
        a, b = left(lookup), right(lookup)
        if a is None or b is None:
            return None
        if isinstance(a, str) or isinstance(b, str):  # text compares with text, for equality only
            return op(a, b) if equality and isinstance(a, str) and isinstance(b, str) else None  # type: ignore[arg-type]
        try:
            return op(_num(a), _num(b))
        except OverflowError:  # an integer beyond a float's range in arithmetic with a float: not known
            return None
    return binary


def _compile_call(node: Call) -> Compiled:
    if node.name == "supports":
        ref = node.args[0]
        assert isinstance(ref, Ref)
        pid = ref.pid

        def supports(lookup: Lookup) -> _Value:
            types = supported_drive_types(pid)
            drive = lookup(DRIVE_TYPE, None)
            if types is None or drive is None or isinstance(drive, str):
                return None
            return int(drive) in types
        return supports
    if node.name in ("unique", "elsewhere"):
        fact = UNIQUE if node.name == "unique" else ELSEWHERE
        key = fact + ",".join(a.pid for a in node.args if isinstance(a, Ref))
        return lambda lookup: None if (v := lookup(key, None)) is None else bool(v)
    args = [compile_condition(a) for a in node.args]
    if node.name == "abs":
        arg = args[0]
        return lambda lookup: None if (v := arg(lookup)) is None or isinstance(v, str) else abs(v)
    if node.name == "len":
        arg = args[0]
        return lambda lookup: len(v) if isinstance(v := arg(lookup), str) else None
    if node.name == "isname":
        arg = args[0]
        return lambda lookup: re.fullmatch(_NAME, v) is not None if isinstance(v := arg(lookup), str) and v else None
    text, prefix = args

    def startswith(lookup: Lookup) -> _Value:
        a, b = text(lookup), prefix(lookup)
        return a.startswith(b) if isinstance(a, str) and isinstance(b, str) else None
    return startswith


__all__ = ["DEFAULT_LIST", "DRIVE_TYPE", "ELSEWHERE", "UNIQUE", "Binary", "Call", "Compiled", "Lookup", "Member", "Num",
           "Number", "Ref", "Str", "Unary", "compile_condition", "parse", "ref_elements", "refs",
           "supported_drive_types"]

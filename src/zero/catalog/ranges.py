"""Formal value ranges of the parameter description, parsed once and evaluated.

The vendor writes ranges as text. Many are formal and can be checked::

    MIN(SGN32) < versch < MAX(SGN32)
    P-AXIS-00177 < swe_pos < MAX(SGN32)
    1 ≤ a_emergency ≤ 2*P-AXIS-00008
    0x00000001 - 0x10000000
    0 ... 96 (number of zero offset groups: 97, application-specific)
    0/1
    -1 … MAX(SGN16)
    MAX(UNS32) ≥ eigenfrequenz_n ≥ 1

The rest is prose, which :func:`parse_range` rejects (returns ``None``) so the
registry keeps it as text. References to other parameters (``P-AXIS-00008``)
are resolved at evaluation time through a callback, which the linter answers
from the other values of the same list (or the referenced parameter's default).
"""

from __future__ import annotations

from collections.abc import Callable

from zero.patterns import VERBOSE, compiled
from zero.records import Record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

TYPE_LIMITS: dict[str, tuple[float, float]] = {
    "BOOLEAN": (0, 1),
    "CHAR": (-128, 255),
    "SGN08": (-(2**7), 2**7 - 1),
    "UNS08": (0, 2**8 - 1),
    "SGN16": (-(2**15), 2**15 - 1),
    "UNS16": (0, 2**16 - 1),
    "SGN32": (-(2**31), 2**31 - 1),
    "UNS32": (0, 2**32 - 1),
    "SGN64": (-(2**63), 2**63 - 1),
    "UNS64": (0, 2**64 - 1),
    "ADDRESS": (0, 2**64 - 1),
    "REAL64": (-1.7976931348623157e308, 1.7976931348623157e308),
}

Number = int | float
# resolve(param_id, element_index_or_None) -> the value, or None when unknown
Resolver = Callable[[str, "int | None"], "Number | None"]


def format_number(n: Number | None) -> str:
    """A value as a message shows it: ``1400000`` for ``1400000.0``; ``not known`` for ``None``."""
    if n is None:
        return "not known"
    if isinstance(n, float) and n.is_integer() and abs(n) < 1e15:
        return str(int(n))
    return str(n)


class Num(Record, frozen=True):
    value: Number

    def eval(self, resolve: Resolver) -> Number | None:
        return self.value

    def __str__(self) -> str:
        return str(self.value)


class Limit(Record, frozen=True):
    """``MIN(TYPE)`` or ``MAX(TYPE)``."""

    which: str
    type: str

    def eval(self, resolve: Resolver) -> Number | None:
        lim = TYPE_LIMITS.get(self.type)
        if lim is None:
            return None
        return lim[0] if self.which == "MIN" else lim[1]

    def __str__(self) -> str:
        return f"{self.which}({self.type})"


class Ref(Record, frozen=True):
    """Another parameter's value: ``P-AXIS-00008`` or ``P-AXIS-00209.1``."""

    id: str
    index: int | None = None

    def eval(self, resolve: Resolver) -> Number | None:
        return resolve(self.id, self.index)

    def __str__(self) -> str:
        return self.id if self.index is None else f"{self.id}.{self.index}"


class BinOp(Record, frozen=True):
    op: str
    left: Expr
    right: Expr

    def eval(self, resolve: Resolver) -> Number | None:
        a = self.left.eval(resolve)
        b = self.right.eval(resolve)
        if a is None or b is None:
            return None
        try:
            if self.op == "*":
                return a * b
            if self.op == "+":
                return a + b
            return a - b
        except OverflowError:  # an integer beyond a float's range with a float (a 401-digit value): not known
            return None

    def __str__(self) -> str:
        return f"{self.left}{self.op}{self.right}"


class Neg(Record, frozen=True):
    operand: Expr

    def eval(self, resolve: Resolver) -> Number | None:
        v = self.operand.eval(resolve)
        return None if v is None else -v

    def __str__(self) -> str:
        return f"-{self.operand}"


Expr = Num | Limit | Ref | BinOp | Neg


class Bounds(Record, frozen=True):
    """Evaluated limits: ``None`` where a side is open or could not be resolved."""

    low: Number | None
    low_strict: bool
    high: Number | None
    high_strict: bool

    def contains(self, x: Number) -> bool:
        if self.low is not None and (x <= self.low if self.low_strict else x < self.low):
            return False
        return not (
            self.high is not None and (x >= self.high if self.high_strict else x > self.high)
        )


class Range(Record, frozen=True):
    """A parsed range: bounds, or an explicit set of allowed values."""

    low: Expr | None = None
    low_strict: bool = False
    high: Expr | None = None
    high_strict: bool = False
    allowed: tuple[Number, ...] | None = None

    @property
    def refs(self) -> list[Ref]:
        """The parameters the bounds refer to, left to right. Walked with a stack: a recursive
        inner function is a reference cycle, garbage only the cycle collector frees, and a
        fleet's lint asks this for every value whose range refers to another parameter."""
        out: list[Ref] = []
        stack: list[Expr | None] = [self.high, self.low]
        while stack:
            e = stack.pop()
            if isinstance(e, Ref):
                out.append(e)
            elif isinstance(e, BinOp):
                stack += (e.right, e.left)
            elif isinstance(e, Neg):
                stack.append(e.operand)
        return out

    def evaluate(self, resolve: Resolver) -> Bounds:
        low = self.low.eval(resolve) if self.low is not None else None
        high = self.high.eval(resolve) if self.high is not None else None
        return Bounds(low, self.low_strict, high, self.high_strict)

    def __str__(self) -> str:
        if self.allowed is not None:
            return ", ".join(str(a) for a in self.allowed)
        left = f"{self.low} {'<' if self.low_strict else '≤'} " if self.low is not None else ""
        right = f" {'<' if self.high_strict else '≤'} {self.high}" if self.high is not None else ""
        return f"{left}x{right}"


# Compiled at the first range parsed here (through re's own cache): the built-in ranges are parsed at
# build time (tools/gen_ranges.py), so a lint seldom parses one (issue 40: start-up).
_TOKEN_TEXT = r"""\s*(?:
      (?P<limit>(?:MIN|MAX)\s*\(\s*[A-Z0-9]+\s*\))
    | (?P<ref>P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)?)
    | (?P<num>0[xX][0-9A-Fa-f]+|[0-9]+(?:\.[0-9]+)?(?:[eE][+-]?[0-9]+)?)
    | (?P<ident>[A-Za-z_][A-Za-z0-9_.\[\]]*)
    | (?P<op><=|>=|≤|≥|<|>|…|\.\.\.|\*|\+|-|/|,)
    )"""
_CMP = {"<": ("<", True), "≤": ("<", False), "<=": ("<", False),
        ">": (">", True), "≥": (">", False), ">=": (">", False)}


def _tokenize(text: str) -> list[tuple[str, str]] | None:
    text = compiled(r"°|%").sub("", text).strip()
    token = compiled(_TOKEN_TEXT, VERBOSE)
    # A note in parentheses after the formal part: `0 ... 96 (number of groups: 97)`.
    cut = compiled(r"(?:MIN|MAX)\s*\(\s*[A-Z0-9]+\s*\)").sub(lambda m: "#" * len(m.group()), text)
    if "(" in cut:
        text = text[: cut.index("(")].rstrip()
    tokens: list[tuple[str, str]] = []
    pos = 0
    while pos < len(text):
        m = token.match(text, pos)
        if m is None or m.end() == pos:
            if text[pos:].strip() == "":
                break
            return None
        kind = m.lastgroup
        assert kind is not None
        tokens.append((kind, m.group(kind)))
        pos = m.end()
    return tokens


class _Parser:
    def __init__(self, tokens: list[tuple[str, str]], own_id: str) -> None:
        self.tokens = tokens
        self.pos = 0
        self.own_id = own_id

    def peek(self) -> tuple[str, str] | None:
        return self.tokens[self.pos] if self.pos < len(self.tokens) else None

    def take(self) -> tuple[str, str]:
        tok = self.tokens[self.pos]
        self.pos += 1
        return tok

    def expr(self) -> Expr | str | None:
        """Sum of products; returns ``"x"`` for the variable, ``None`` on error."""
        # Binary minus is not arithmetic here: `1 - 12` is a span, see parse_range.
        return self._chain(self.term, "+")

    def term(self) -> Expr | str | None:
        return self._chain(self.atom, "*")

    def _chain(self, operand: Callable[[], Expr | str | None], op: str) -> Expr | str | None:
        """``operand (op operand)*``, left-associative; the variable may not take part."""
        left = operand()
        while left is not None and self.peek() == ("op", op):
            self.take()
            right = operand()
            if right is None or isinstance(left, str) or isinstance(right, str):
                return None
            left = BinOp(op, left, right)
        return left

    def atom(self) -> Expr | str | None:
        t = self.peek()
        if t is None:
            return None
        kind, text = t
        if kind == "op" and text == "-":
            self.take()
            inner = self.atom()
            if inner is None or isinstance(inner, str):
                return None
            if isinstance(inner, Num):
                return Num(-inner.value)
            return Neg(inner)
        self.take()
        if kind == "num":
            if text.lower().startswith("0x"):
                return Num(int(text, 16))
            if "." in text or "e" in text.lower():
                value = float(text)
                return Num(int(value) if value.is_integer() else value)
            return Num(int(text))
        if kind == "limit":
            which = text[:3]
            typ = text[text.index("(") + 1 : text.index(")")].strip()
            return Limit(which, typ) if typ in TYPE_LIMITS else None
        if kind == "ref":
            if text == self.own_id:
                return "x"
            if "." in text:
                ident, idx = text.split(".")
                return Ref(ident, int(idx))
            return Ref(text)
        if kind == "ident":
            return "x"
        return None


def parse_range(text: str | None, own_id: str = "") -> Range | None:
    """Parse a formal range; ``None`` for prose or anything not understood."""
    if not text:
        return None
    tokens = _tokenize(text.replace("\r", " ").replace("\n", " "))
    if not tokens:
        return None
    ops = [t for t in tokens if t[0] == "op"]
    # An explicit set: `0/1`, `-1, 0, 1`.
    if any(t[1] in ("/", ",") for t in ops):
        values: list[Number] = []
        sign = 1
        for kind, tok in tokens:
            if kind == "op" and tok == "-":
                sign = -1
            elif kind == "num":
                values.append(sign * (int(tok, 16) if tok.lower().startswith("0x") else int(tok))
                              if "." not in tok else sign * float(tok))
                sign = 1
            elif not (kind == "op" and tok in ("/", ",")):
                return None
        return Range(allowed=tuple(values)) if len(values) >= 2 else None

    # The variable is the one identifier (or the parameter's own ID); a second,
    # different identifier (`swe_neg < pos_refpkt < swe_pos`) is prose to us.
    if len({t for k, t in tokens if k == "ident"}) > 1:
        return None
    p = _Parser(tokens, own_id)
    if tokens[0][0] == "op" and tokens[0][1] in _CMP:
        first: Expr | str | None = "x"  # `> 0`: the variable is implied
    else:
        first = p.expr()
    if first is None:
        return None
    terms: list[Expr | str] = [first]
    cmps: list[str] = []
    span_op = False
    while (t := p.peek()) is not None:
        if t[0] != "op":
            return None
        op = t[1]
        if op in _CMP:
            cmps.append(op)
        elif op in ("…", "...", "-") and not span_op and len(terms) == 1:
            span_op = True
            cmps.append("..")
        else:
            return None
        p.take()
        nxt = p.expr()
        if nxt is None:
            return None
        terms.append(nxt)

    if span_op:
        if len(terms) != 2 or any(isinstance(x, str) for x in terms):
            return None
        lo, hi = terms
        assert not isinstance(lo, str) and not isinstance(hi, str)
        return Range(low=lo, high=hi)
    if "x" not in terms:
        return None
    low: Expr | None = None
    high: Expr | None = None
    low_strict = high_strict = False
    for i, op in enumerate(cmps):
        a, b = terms[i], terms[i + 1]
        direction, strict = _CMP[op]
        if a == "x" and not isinstance(b, str):
            bound, upper = b, direction == "<"
        elif b == "x" and not isinstance(a, str):
            bound, upper = a, direction == ">"
        else:
            continue
        if upper:
            if high is not None:
                return None  # two upper bounds: a garbled range
            high, high_strict = bound, strict
        else:
            if low is not None:
                return None
            low, low_strict = bound, strict
    if low is None and high is None:
        return None
    return Range(low, low_strict, high, high_strict)


# A range as constants (``tools/gen_ranges.py`` writes the built-in catalogue's ranges parsed, so that
# they load from bytecode instead of being parsed at every run: issue 40). An expression is a number
# (Num), or a tuple: ("L", which, type) Limit, ("R", id, index) Ref, ("B", op, left, right) BinOp,
# ("N", operand) Neg; a range is (low, low_strict, high, high_strict, allowed), ``None`` for prose.
if TYPE_CHECKING:
    Encoded = Any


def encode_range(rng: Range | None) -> Encoded:
    """``rng`` as nested tuples of constants (``None`` stays ``None``)."""
    if rng is None:
        return None
    return (_encode(rng.low), rng.low_strict, _encode(rng.high), rng.high_strict, rng.allowed)


def _encode(e: Expr | None) -> Encoded:
    if e is None:
        return None
    if isinstance(e, Num):
        return e.value
    if isinstance(e, Limit):
        return ("L", e.which, e.type)
    if isinstance(e, Ref):
        return ("R", e.id, e.index)
    if isinstance(e, BinOp):
        return ("B", e.op, _encode(e.left), _encode(e.right))
    return ("N", _encode(e.operand))


def encoded_refers(data: Encoded) -> bool:
    """Whether the range :func:`encode_range` wrote refers to other parameters (``decode_range(data).refs`` is
    not empty), read from the constants without building the range."""
    if data is None:
        return False
    stack = [data[0], data[2]]
    while stack:
        e = stack.pop()
        if type(e) is tuple:
            tag = e[0]
            if tag == "R":
                return True
            if tag == "B":
                stack += (e[2], e[3])
            elif tag == "N":
                stack.append(e[1])
    return False


def decode_range(data: Encoded) -> Range | None:
    """The range :func:`encode_range` wrote (equal to what :func:`parse_range` gives for its text)."""
    if data is None:
        return None
    low, low_strict, high, high_strict, allowed = data
    return Range(_decode(low), low_strict, _decode(high), high_strict, allowed)


def _decode(data: Encoded) -> Expr | None:
    if data is None:
        return None
    if not isinstance(data, tuple):
        return Num(data)
    tag = data[0]
    if tag == "L":
        return Limit(data[1], data[2])
    if tag == "R":
        return Ref(data[1], data[2])
    if tag == "B":
        return BinOp(data[1], _decode(data[2]), _decode(data[3]))  # type: ignore[arg-type]
    return Neg(_decode(data[1]))  # type: ignore[arg-type]


def encoded_bounds(data: Encoded) -> tuple[Number | None, bool, Number | None, bool] | None:
    """What ``decode_range(data).evaluate(...)`` gives (low, low_strict, high, high_strict) for a range
    :func:`encode_range` wrote that refers to no other parameter, read from the constants without building
    the range or its bounds (a lint judges some two hundred values so, once per parameter: issue 40);
    ``None`` for a range that refers to one. Not for a set of values (``allowed``)."""
    low, high = data[0], data[2]
    if type(low) is tuple:  # not a number or None: an expression (most bounds are numbers, read as they are)
        low = _constant(low)
    if type(high) is tuple:
        high = _constant(high)
    if low is _REFERS or high is _REFERS:
        return None
    return low, data[1], high, data[3]


_REFERS: Any = object()  # what _constant gives for an expression that reads another parameter


def _constant(data: Encoded) -> Any:
    """What ``_decode(data).eval(...)`` gives for an expression without references (see the classes above),
    else ``_REFERS``."""
    if type(data) is not tuple:
        return data  # a number, or None (no bound)
    tag = data[0]
    if tag == "L":
        lim = TYPE_LIMITS.get(data[2])
        return None if lim is None else lim[0] if data[1] == "MIN" else lim[1]
    if tag == "R":
        return _REFERS
    if tag == "N":
        v = _constant(data[1])
        return v if v is None or v is _REFERS else -v
    a, b = _constant(data[2]), _constant(data[3])
    if a is _REFERS or b is _REFERS:
        return _REFERS
    if a is None or b is None:
        return None
    try:
        return a * b if data[1] == "*" else a + b if data[1] == "+" else a - b
    except OverflowError:  # as BinOp.eval
        return None

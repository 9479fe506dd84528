"""What every rule shares: its metadata, the lint context and value reading.

A :class:`Rule` is metadata (code, name, default severity, summary and an
explanation with fixed headings). Checks are generator functions over a
:class:`Context`; one check may report several related codes, and the engine
drops the findings of rules that are not selected.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field

from zero.diagnostics import Diagnostic, Fix, Severity, Span
from zero.model import Document, Entry, ValueKind
from zero.ranges import TYPE_LIMITS, Number
from zero.registry import INTEGER_TYPES, ParamSpec, Registry


@dataclass(frozen=True, slots=True)
class Rule:
    code: str
    name: str
    severity: Severity
    summary: str
    explanation: str

    def render(self) -> str:
        return (
            f"{self.code} ({self.name}) — default severity: {self.severity.label}\n\n"
            f"{self.summary}\n\n{self.explanation.strip()}\n"
        )


def rule(code: str, name: str, severity: Severity, summary: str, explanation: str) -> Rule:
    return Rule(code, name, severity, summary, explanation)


@dataclass(slots=True)
class Value:
    """An entry's value as the controller reads it for its parameter."""

    number: Number | None = None  # the numeric value, when there is one
    text: str | None = None  # the string value (quotes removed), for STRING
    ref: tuple[str, int | None] | None = None  # a parameter reference
    problem: str | None = None  # "type", "symbol", "bool", "length": why it is rejected
    detail: str = ""


@dataclass(slots=True)
class Resolved:
    """An entry bound to its parameter."""

    entry: Entry
    spec: ParamSpec
    value: Value
    via_alias: bool = False


@dataclass(slots=True)
class Context:
    """Everything a check may read. Built once per document by :mod:`zero.lint`."""

    doc: Document
    registry: Registry
    kind: str | None
    severities: dict[str, Severity]
    entries: list[Entry] = field(default_factory=list)
    resolved: list[Resolved] = field(default_factory=list)
    # param ID -> indices -> the entry that wins (the last one)
    by_id: dict[str, dict[tuple[int, ...], Resolved]] = field(default_factory=dict)

    def report(
        self,
        code: str,
        span: Span,
        message: str,
        *,
        param_id: str | None = None,
        fix: Fix | None = None,
        hint: str | None = None,
    ) -> Diagnostic:
        if len(message) > 300:
            message = _LONG_QUOTED.sub(_shorten, message)
        return Diagnostic(
            code,
            self.severities.get(code, Severity.ERROR),
            message,
            span,
            self.doc.path,
            param_id,
            fix,
            hint,
        )

    def value_of(self, param_id: str, indices: tuple[int, ...] = ()) -> Resolved | None:
        slot = self.by_id.get(param_id)
        if not slot:
            return None
        return slot.get(indices)

    def number_of(
        self, param_id: str, indices: tuple[int, ...] = (), _depth: int = 0
    ) -> Number | None:
        """The numeric value the controller will use: the list's, else the default."""
        spec = self.registry.get(param_id)
        if spec is None or _depth > 6:
            return None
        indices = indices[: len(spec.dims)] if spec.dims else ()
        if spec.dims and len(indices) < len(spec.dims):
            indices = indices + (0,) * (len(spec.dims) - len(indices))
        res = self.value_of(param_id, indices)
        if res is not None and res.value.problem is None:
            if res.value.number is not None:
                return res.value.number
            if res.value.ref is not None:
                rid, ridx = res.value.ref
                return self.number_of(rid, (ridx,) if ridx is not None else (), _depth + 1)
            return None
        return default_number(spec, self, _depth)


_LONG_QUOTED = re.compile(r"`([^`]{81,})`")


def _shorten(m: re.Match[str]) -> str:
    text = m.group(1)
    return f"`{text[:60]}…{text[-12:]}` ({len(text)} characters)"


Check = Callable[[Context], Iterator[Diagnostic]]


def parse_int(text: str) -> int | None:
    if text.isdigit() and text.isascii() and len(text) <= 40:
        return int(text)
    t = text.strip()
    sign = -1 if t.startswith("-") else 1
    body = t.lstrip("+-")
    try:
        if body.lower().startswith("0x"):
            return sign * int(body, 16)
        if len(body) > 40:
            return sign * 10**40  # beyond every type: reported as too large
        return sign * int(body)
    except ValueError:
        return None


def default_number(spec: ParamSpec, ctx: Context | None = None, depth: int = 0) -> Number | None:
    """The default as a number (symbols mapped; references followed when ``ctx``)."""
    d = (spec.default or "").strip()
    if not d:
        return None
    v = spec.symbol_value(d)
    if v is not None:
        return v
    if d in ("TRUE", "FALSE") and spec.type == "BOOLEAN":
        return 1 if d == "TRUE" else 0
    n = parse_int(d)
    if n is not None:
        return n
    if ctx is not None and d.startswith("P-") and len(d) >= 12:
        rid, _, ridx = d.partition(".")
        return ctx.number_of(rid, (int(ridx),) if ridx.isdigit() else (), depth + 1)
    try:
        return float(d)
    except ValueError:
        return None


def _symbol_number(spec: ParamSpec, word: str) -> tuple[bool, int | None]:
    """Is ``word`` an allowed symbol (or its number)? And its numeric value."""
    for name, val in spec.symbols:
        if name == word:
            return True, val
    n = parse_int(word)
    if n is not None and any(val == n for _, val in spec.symbols):
        return True, n
    return False, None


def read_value(spec: ParamSpec, entry: Entry) -> Value:
    """Interpret an entry's value for its parameter's type, symbols and length."""
    kind = entry.value_kind
    raw = entry.value
    t = spec.type
    if kind is ValueKind.REF:
        rid, _, ridx = raw.partition(".")
        return Value(ref=(rid, int(ridx) if ridx else None))

    if t == "STRING":
        if kind is ValueKind.QUOTED:
            text = raw[1:-1] if len(raw) >= 2 and raw.endswith('"') else raw[1:]
            text = text.rstrip(" ")
        else:
            text = raw
        if spec.symbols and kind is not ValueKind.QUOTED:
            parts = [p.strip() for p in text.split("|")] if kind is ValueKind.FLAGS else [text]
            number: int | None = 0
            for part in parts:
                ok, val = _symbol_number(spec, part)
                if not ok:
                    return Value(text=text, problem="symbol", detail=part)
                number = None if val is None or number is None else number | val
            return Value(number=number, text=text)
        if spec.max_len is not None and len(text) > spec.max_len:
            return Value(text=text, problem="length", detail=str(len(text)))
        return Value(text=text)

    if t in INTEGER_TYPES:
        if kind in (ValueKind.INT, ValueKind.HEX):
            n = parse_int(raw)
            assert n is not None
            lo, hi = TYPE_LIMITS.get(t, (None, None))
            if t == "BOOLEAN" and n not in (0, 1):
                return Value(number=n, problem="bool")
            if lo is not None and hi is not None and not lo <= n <= hi:
                return Value(number=n, problem="overflow")
            return Value(number=n)
        if kind in (ValueKind.WORD, ValueKind.FLAGS) and (spec.symbols or t == "BOOLEAN"):
            parts = [p.strip() for p in raw.split("|")] if kind is ValueKind.FLAGS else [raw]
            total: int | None = 0
            for part in parts:
                ok, val = _symbol_number(spec, part)
                if not ok and t == "BOOLEAN" and part in ("TRUE", "FALSE"):
                    ok, val = True, int(part == "TRUE")
                if not ok:
                    if t == "BOOLEAN":
                        return Value(problem="bool", detail=part)
                    return Value(problem="symbol", detail=part)
                total = None if val is None or total is None else total | val
            return Value(number=total)
        return Value(problem="type", detail="integer")

    if t == "REAL64":
        if kind in (ValueKind.INT, ValueKind.HEX):
            return Value(number=parse_int(raw))
        if kind is ValueKind.REAL:
            try:
                return Value(number=float(raw))
            except ValueError:
                return Value(problem="type", detail="number")
        if spec.symbols and kind is ValueKind.WORD:
            ok, val = _symbol_number(spec, raw)
            return Value(number=val) if ok else Value(problem="symbol", detail=raw)
        return Value(problem="type", detail="number")

    return Value(text=raw)  # STRUCT and anything undocumented: not checked

"""``zero schema``: a JSON Schema (draft 2020-12) of the structured form.

Generated from the registry: one property per key member, index levels as
``patternProperties`` whose pattern admits exactly the valid indices, and per
parameter its type, constant range, default, unit and ID. Editors (VS Code's
YAML extension, taplo, any JSON tool) validate while the engineer types.
"""

from __future__ import annotations

import math
import re
from typing import Any

from zero.catalog.ranges import TYPE_LIMITS, Range
from zero.catalog.registry import INTEGER_TYPES, KINDS, NO_DEFAULT, ParamSpec, Registry
from zero.catalog.values import default_number
from zero.structured.tree import META_KEY

SCHEMA_DIALECT = "https://json-schema.org/draft/2020-12/schema"

_INT_TEXT = r"[+-]?[0-9]+|[+-]?0[xX][0-9A-Fa-f]+"
_REAL_TEXT = r"[+-]?(?:[0-9]+\.[0-9]*|\.[0-9]+|[0-9]+)(?:[eE][+-]?[0-9]+)?"
_REF_TEXT = r"P-[A-Z]{4}-[0-9]{5}(?:\.[0-9]+)?"


def int_range_regex(lo: int, hi: int) -> str:
    """A regex (no anchors) matching the decimal numbers lo..hi without leading zeros."""
    if lo > hi:
        return "(?!)"
    parts: list[str] = []
    for digits in range(len(str(lo)), len(str(hi)) + 1):
        a = max(lo, 10 ** (digits - 1) if digits > 1 else 0)
        b = min(hi, 10**digits - 1)
        if a <= b:
            parts.extend(_same_length(str(a), str(b)))
    return "|".join(parts)


def _same_length(a: str, b: str) -> list[str]:
    """Patterns for a..b where both have the same number of digits."""
    if a == b:
        return [a]
    if len(a) == 1:
        return [f"[{a}-{b}]" if a != b else a]
    if a[0] == b[0]:
        return [a[0] + ("(?:" + "|".join(_same_length(a[1:], b[1:])) + ")")]
    out: list[str] = []
    rest = len(a) - 1
    if a[1:] != "0" * rest:
        out.append(a[0] + "(?:" + "|".join(_same_length(a[1:], "9" * rest)) + ")")
        lo_first = int(a[0]) + 1
    else:
        lo_first = int(a[0])
    if b[1:] != "9" * rest:
        hi_first = int(b[0]) - 1
        tail = b[0] + "(?:" + "|".join(_same_length("0" * rest, b[1:])) + ")"
    else:
        hi_first = int(b[0])
        tail = ""
    if lo_first <= hi_first:
        first = str(lo_first) if lo_first == hi_first else f"[{lo_first}-{hi_first}]"
        out.append(first + f"[0-9]{{{rest}}}")
    if tail:
        out.append(tail)
    return out


def _constant_bounds(rng: Range | None) -> tuple[float | None, bool, float | None, bool]:
    """Numeric bounds that need no other parameter; ``None`` where they do."""
    if rng is None:
        return None, False, None, False
    b = rng.evaluate(lambda *_: None)
    return b.low, b.low_strict, b.high, b.high_strict


# JSON tools read numbers into 64-bit machine types: taplo (serde_json) refuses a schema with an integer
# beyond u64/i64 or a float it rounds to infinity ("number out of range"), JavaScript (VS Code) reads
# every number as a double. So an integer is written as one only within i64; anything else as a double.
_I64_MIN, _I64_MAX = -(2**63), 2**63 - 1


def _num(x: float) -> int | float:
    """A number for the schema: an integer within i64 as an integer (``1``, not ``1.0``), any other
    number as a double in exponent form where large (REAL64's limit ``1.7976931348623157e+308``, not
    its 309 digits, which overflow taplo's reader)."""
    if isinstance(x, int):
        return x if _I64_MIN <= x <= _I64_MAX else float(x)
    if math.isfinite(x) and x.is_integer() and _I64_MIN <= x <= _I64_MAX:
        return int(x)
    return x


def _bound(x: float, upper: bool) -> int | float:
    """A minimum or maximum for the schema, never stricter than ``x``: :func:`_num`, and an integer
    beyond i64 (UNS64's and ADDRESS's maximum 2**64-1) as the nearest double on the far side. For
    UNS64 that is 2**64 (1.8446744073709552e+19): a validator of exact integers (Python's) then admits
    one value too many (2**64, which `zero lint` reports as R004), one of doubles (JavaScript) reads
    2**64-1 as 2**64 and still admits it; an exclusive 2**64 would be exact for the first and refuse
    the largest valid value for the second. TOML holds no integer beyond i64 anyway."""
    n = _num(x)
    if isinstance(n, float) and isinstance(x, int) and n != x:
        if upper and n < x:
            n = math.nextafter(n, math.inf)
        elif not upper and n > x:
            n = math.nextafter(n, -math.inf)
    return n


def leaf_schema(spec: ParamSpec, registry: Registry) -> dict[str, Any]:
    """The schema of one parameter value."""
    words = [s for s, _ in spec.symbols]
    unit = f" [{', '.join(spec.units)}]" if spec.units else ""
    desc = f"{spec.id} ({spec.type}){unit}"
    if spec.description:
        desc += f": {spec.description}"
    out: dict[str, Any] = {"description": desc}
    if spec.type == "STRING":
        s: dict[str, Any] = {"type": "string"}
        if spec.max_len:
            s["maxLength"] = spec.max_len
        out["anyOf"] = [s, {"type": "integer"}]
    elif spec.type in INTEGER_TYPES or spec.type.startswith("REAL"):
        real = spec.type.startswith("REAL")
        number: dict[str, Any] = {"type": "number" if real else "integer"}
        rng = registry.range_of(spec)
        if rng is not None and rng.allowed is not None:
            number["enum"] = [_num(a) for a in rng.allowed]
        lo, lo_x, hi, hi_x = _constant_bounds(rng)
        t_lo, t_hi = (None, None) if real else TYPE_LIMITS.get(spec.type, (None, None))
        if lo is None and t_lo is not None:
            lo, lo_x = t_lo, False
        if hi is None and t_hi is not None:
            hi, hi_x = t_hi, False
        if lo is not None:
            number["exclusiveMinimum" if lo_x else "minimum"] = _bound(lo, upper=False)
        if hi is not None:
            number["exclusiveMaximum" if hi_x else "maximum"] = _bound(hi, upper=True)
        dflt = default_number(spec)
        if dflt is not None and len(number) > 1:
            # The default itself is never faulty, even where a vendor range excludes it.
            number = {"anyOf": [number, {"const": _num(dflt)}]}
        alternatives = [_REAL_TEXT if real else _INT_TEXT, _REF_TEXT]
        if words:
            word = "|".join(re.escape(w) for w in words)
            alternatives.append(f"(?:{word})(?: *\\| *(?:{word}))*")
        out["anyOf"] = [number, {"type": "string", "pattern": "^(?:" + "|".join(alternatives) + ")$"}]
    else:
        out["type"] = ["string", "integer", "number"]
    if spec.default and spec.default.strip() not in NO_DEFAULT:
        d = spec.default.strip()
        if re.fullmatch(r"-?[0-9]+", d) and spec.type != "STRING":
            out["default"] = _num(int(d))
        else:
            out["default"] = d
    return out


def _index_pattern(dim: int, base: int) -> str:
    if dim <= 0:
        return "^(?:0|[1-9][0-9]*)$"
    return "^(?:" + int_range_regex(base, base + dim - 1) + ")$"


def _meta_schema() -> dict[str, Any]:
    return {
        "type": "object",
        "description": "zero's record of the list layout (encoding, columns, order, exact lines). "
                       "Keep it to get the original file back byte for byte.",
        "properties": {
            "zero": {"type": "integer", "const": 1},
            "kind": {"type": "string", "enum": sorted(KINDS)},
            "encoding": {"enum": ["utf-8", "cp1252", "latin-1"]},
            "bom": {"type": "boolean"},
            "newline": {"enum": ["\n", "\r\n"]},
            "final_newline": {"type": "boolean"},
            "value_column": {"type": "integer", "minimum": 0},
            "comment_column": {"type": "integer", "minimum": 0},
            "end": {"type": "string"},
        },
    }


def build_schema(registry: Registry, kind: str | None = None, strict: bool = True) -> dict[str, Any]:
    """The JSON Schema of the structured form of ``kind`` (all kinds when ``None``).

    With ``strict`` (the default) an unknown member is an error, as `zero lint`
    reports it (R001); aliases the registry knows are admitted.
    """
    root: dict[str, Any] = {"type": "object", "properties": {}}

    def child(node: dict[str, Any], name: str) -> dict[str, Any]:
        props = node.setdefault("properties", {})
        if name not in props:
            props[name] = {"type": "object"}
        sub: dict[str, Any] = props[name]
        return sub

    def index_child(node: dict[str, Any], dim: int, base: int) -> dict[str, Any]:
        pats = node.setdefault("patternProperties", {})
        pat = _index_pattern(dim, base)
        if pat not in pats:
            pats[pat] = {"type": "object"}
        sub: dict[str, Any] = pats[pat]
        return sub

    def place(pattern: str, spec: ParamSpec) -> None:
        node = root
        dims = list(spec.dims)
        members = pattern.split(".")
        for mi, member in enumerate(members):
            name, _, _rest = member.partition("[")
            slots = member.count("[]")
            last_member = mi == len(members) - 1
            if last_member and slots == 0:
                props = node.setdefault("properties", {})
                new = leaf_schema(spec, registry)
                old = props.get(name)
                if old is None or old.get("type") == "object":
                    props[name] = new
                elif old != new:
                    props[name] = {"anyOf": [old, new]} if "anyOf" not in old or "description" in old \
                        else {"anyOf": [*old["anyOf"], new]}
                return
            node = child(node, name)
            for s in range(slots):
                dim = dims.pop(0) if dims else 0
                base = spec.index_base if mi == 0 and s == 0 else 0
                if last_member and s == slots - 1:
                    pats = node.setdefault("patternProperties", {})
                    pats[_index_pattern(dim, base)] = leaf_schema(spec, registry)
                    return
                node = index_child(node, dim, base)

    specs = [s for s in registry.specs.values() if s.key and (kind is None or s.kind == kind)]
    for spec in sorted(specs, key=lambda s: s.id):
        assert spec.key is not None
        place(spec.key, spec)
    for (k, pattern), target in registry.aliases.items():
        if kind is None or k == kind:
            target_spec = registry.by_pattern(target, k)
            if target_spec is not None:
                place(pattern, target_spec)

    for (k, pattern), (source, _near) in registry.vendor_keys.items():
        if kind is None or k == kind:  # admitted, as zero lint reports them as information only
            prefix = pattern[: pattern.rfind("[]") + 2] if "[]" in pattern else None
            sibling = next((sp for sp in specs if prefix and sp.kind == k and sp.key
                            and sp.key.startswith(prefix)), None)  # its indices are the sibling's
            place(pattern, ParamSpec("(not in the catalogue)", k, pattern, "UNDOCUMENTED",
                                     dims=sibling.dims if sibling else (),
                                     index_base=sibling.index_base if sibling else 0,
                                     description=f"used by the vendor's own lists: {source}"))

    if strict:
        stack = [root]
        while stack:
            n = stack.pop()
            if n.get("type") == "object":
                n["additionalProperties"] = False
                stack.extend(n.get("properties", {}).values())
                stack.extend(n.get("patternProperties", {}).values())
    root["properties"][META_KEY] = _meta_schema()
    name = KINDS[kind][1] if kind else "ISG kernel CNC parameter list"
    return {
        "$schema": SCHEMA_DIALECT,
        "$id": f"urn:zero-lint:schema:{(KINDS[kind][0] if kind else 'all')}",  # a name, not an address to fetch
        "title": f"zero: structured {name}",
        "description": "Generated by `zero schema` from zero's parameter registry.",
        **root,
    }

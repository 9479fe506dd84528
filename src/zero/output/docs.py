"""What zero knows, as text: a rule's explanation, the list of rules, a parameter's facts."""

from __future__ import annotations

from zero.catalog.registry import KINDS, ParamSpec, Registry
from zero.rules import RULES


def rule_text(code: str) -> str:
    r = RULES[code]
    return r.render()


def rules_overview() -> str:
    lines = []
    for code, r in RULES.items():
        lines.append(f"{code}  {r.severity.label:<7}  {r.name:<30} {r.summary}")
    return "\n".join(lines) + "\n"


def param_text(spec: ParamSpec, registry: Registry) -> str:
    rng = registry.range_of(spec)
    if rng is not None:
        range_text = f"{spec.range_text}  (checked)"
    elif spec.enum:
        listed = spec.enum_listed()
        kind = "bits, any combination" if spec.enum_flags else "values"
        range_text = f"{listed}  ({kind} the catalogue lists in its text; checked)"
    elif spec.range_note:
        range_text = f"{spec.range_note}  (prose, not checked)"
    elif spec.type == "BOOLEAN":
        range_text = "0/1 (FALSE/TRUE)"
    else:
        range_text = "not stated formally (not checked)"
    dims = ""
    if spec.dims:
        names = spec.key.split("[]") if spec.key else []
        parts = []
        for i in range(len(spec.dims)):
            member = names[i].rsplit(".", 1)[-1] if i < len(names) else "?"
            parts.append(f"{member}[{spec.valid_indices(i)}]")
        dims = ", ".join(parts)
    rows = [
        ("ID", spec.id),
        ("key", spec.key or "(no list key documented)"),
        ("list", KINDS.get(spec.kind, (spec.kind, spec.kind))[1]),
        ("type", spec.type + (f", at most {spec.max_len} characters" if spec.max_len else "")),
        ("range", range_text),
        ("default", spec.default_display),
        ("unit", " or ".join(spec.units) if spec.units else "–"),
    ]
    if dims:
        rows.append(("indices", dims))
    if spec.symbols:
        rows.append(("symbols", ", ".join(n if v is None else f"{n}={v}" for n, v in spec.symbols)))
    if spec.restart:
        rows.append(("restart", "a change takes effect only after a restart"))
    rows.append(("meaning", spec.description or "(no description; load your CncParaDesc.xml with --param-desc)"))
    rows.append(("source", spec.source))
    width = max(len(k) for k, _ in rows)
    return "\n".join(f"{k:<{width}}  {v}" for k, v in rows) + "\n"

"""What zero says the controller does, and the document that says so (``data/evidence.toml``).

Every claim a rule makes about the controller — it ignores the entry, limits the value, sets it to
0, aborts the start-up, or nothing is documented — is a :class:`Claim`: a row of zero's evidence
table with its consequence, its severity, the words a finding ends with, the kernel's error number
where there is one, its source and the releases and list kinds it holds for. A finding's severity
follows its claim: an **error** only where the source documents that the controller rejects,
changes or ignores the value or stops; a **warning** where nothing is documented; **info** for what
the vendor itself writes or what does not apply.

The table is compiled to ``data/evidence_table.py`` by ``tools/gen_startup.py`` and read at the
first finding, once per process; a claim's rows become :class:`Claim` objects at its first use.
"""

from __future__ import annotations

from zero.diagnostics import Severity
from zero.records import Record

# consequences that a document must back for an error (and `unchecked`: zero could not read the file)
DOCUMENTED = frozenset({"ignored", "limited", "zeroed", "replaced", "corrected", "rejected", "aborted"})
# `reported`: a K rule whose row documents the kernel's error but not what it then does
CONSEQUENCES = DOCUMENTED | {"undocumented", "behaviour", "not-applicable", "vendor-writes", "unchecked", "reported"}


class Claim(Record, frozen=True):
    """One claim about the controller, as the evidence table states it."""

    name: str
    consequence: str
    severity: Severity
    says: str
    source: str
    releases: str = "all"
    kinds: tuple[str, ...] = ()
    kernel_error: str | None = None

    def holds_for(self, kind: str | None) -> bool:
        return not self.kinds or (kind is not None and kind in self.kinds)


_rows: dict[str, list[dict[str, object]]] | None = None  # claim name -> its rows, in order (read once)
_rules: dict[str, str] | None = None  # rule code -> the name of its claim
_built: dict[str, list[Claim]] = {}  # claim name -> its rows as claims (each name's at its first use)
_drives: list[tuple[str, tuple[int, ...], str]] | None = None


def _load() -> tuple[dict[str, list[dict[str, object]]], dict[str, str]]:
    """The table's rows by claim name, and the rules' claims (one pass over the rows, no claim built: a
    lint's findings ask for a few of them)."""
    global _rows, _rules
    if _rows is None or _rules is None:
        from zero.catalog.data.evidence_table import CLAIMS, RULES  # start-up: at the first finding

        rows: dict[str, list[dict[str, object]]] = {}
        for row in CLAIMS:
            rows.setdefault(str(row["name"]), []).append(row)
        _rows, _rules = rows, {str(k): str(v) for k, v in RULES.items()}
    return _rows, _rules


def _claims(name: str) -> list[Claim]:
    """The rows of claim ``name`` as claims (none: no such claim), built at its first use."""
    got = _built.get(name)
    if got is None:
        got = _built[name] = [
            Claim(str(row["name"]), str(row["consequence"]), Severity.parse(str(row["severity"])), str(row["says"]),
                  str(row["source"]), str(row.get("releases", "all")),
                  tuple(str(k) for k in row.get("kinds", ()) or ()),  # type: ignore[attr-defined]
                  str(row.get("kernel_error") or "") or None)
            for row in _load()[0].get(name, ())]
    return got


def claim(name: str, kind: str | None = None) -> Claim:
    """The claim ``name`` for a list of ``kind``: its first row that holds for the kind."""
    rows = _built.get(name) or _claims(name)
    if not rows:
        raise KeyError(f"no claim {name!r} in the evidence table")
    for c in rows:
        if c.holds_for(kind):
            return c
    return rows[-1]


def rule_claim(code: str, kind: str | None = None) -> Claim | None:
    """The claim a rule's finding carries where its check names none (``None``: the rule has none,
    as the K rules, whose claim is their own row of the start-up errors)."""
    name = _load()[1].get(code)
    return claim(name, kind) if name is not None else None


def drive_types(pattern: str) -> tuple[tuple[int, ...], str] | None:
    """The drive types (P-AXIS-00020) the documentation gives a parameter for, and the page, where it
    gives it for some only (a key pattern, or a subtree such as ``antr.sercos.``)."""
    global _drives
    if _drives is None:
        from zero.catalog.data.evidence_table import DRIVES  # start-up: at the first range finding

        _drives = [(str(r["key"]), tuple(int(t) for t in r["types"]), str(r["source"])) for r in DRIVES]
    for key, types, source in _drives:
        if pattern == key or (key.endswith(".") and pattern.startswith(key)):
            return types, source
    return None


def claims() -> list[Claim]:
    """Every row of the table."""
    return [c for name in _load()[0] for c in _claims(name)]


def rule_claims() -> dict[str, str]:
    """Rule code → the name of its claim."""
    return dict(_load()[1])


__all__ = ["CONSEQUENCES", "DOCUMENTED", "Claim", "claim", "claims", "drive_types", "rule_claim", "rule_claims"]

"""What zero says the controller does, and the document that says so (``data/evidence.toml``).

Every claim a rule makes about the controller — it ignores the entry, limits the value, sets it to
0, aborts the start-up, or nothing is documented — is a :class:`Claim`: a row of zero's evidence
table with its consequence, its severity, the words a finding ends with, the kernel's error number
where there is one, its source and the releases and list kinds it holds for. A finding's severity
follows its claim: an **error** only where the source documents that the controller rejects,
changes or ignores the value or stops; a **warning** where nothing is documented; **info** for what
the vendor itself writes or what does not apply.

The table is compiled to ``data/evidence_table.py`` by ``tools/gen_evidence.py`` (a row a line of text)
and read at the first finding, once per process; a claim's lines are found and become :class:`Claim`
objects at its first use, and a rule's claim is found at the first finding of the rule.
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


_table: tuple[str, str] | None = None  # the table's claims and rules, as written (read once)
_built: dict[str, list[Claim]] = {}  # claim name -> its rows as claims (each name's at its first use)
_chosen: dict[tuple[str, str | None], Claim] = {}  # (claim name, list kind) -> the claim (each pair's at its first use)
_named: dict[str, str | None] = {}  # rule code -> the name of its claim (each code's at its first use)
_drives: list[tuple[str, tuple[int, ...], str]] | None = None


def _load() -> tuple[str, str]:
    """The table's claims and its rules' claims, each a text of a row a line (``data/evidence_table.py``):
    a lint's findings ask for one or two claims, which are found in it, not the whole table built."""
    global _table
    if _table is None:
        from zero.catalog.data.evidence_table import CLAIMS, RULES  # start-up: at the first finding

        _table = CLAIMS, RULES
    return _table


def _claim(line: str) -> Claim:
    """A row of the table (its fields separated by tabs, as tools/gen_evidence.py writes them) as a claim."""
    name, consequence, severity, says, source, releases, kinds, kernel_error = line.split("\t")
    return Claim(name, consequence, Severity.parse(severity), says, source, releases,
                 tuple(kinds.split(",")) if kinds else (), kernel_error or None)


def _claims(name: str) -> list[Claim]:
    """The rows of claim ``name`` as claims (none: no such claim), built at its first use from its lines
    (a claim's rows are together, each line after a line break)."""
    got = _built.get(name)
    if got is None:
        text = _load()[0]
        head = f"\n{name}\t"
        got = []
        at = text.find(head)
        while at >= 0:
            end = text.index("\n", at + 1)
            got.append(_claim(text[at + 1:end]))
            at = end if text.startswith(head, end) else -1
        _built[name] = got
    return got


def claim(name: str, kind: str | None = None) -> Claim:
    """The claim ``name`` for a list of ``kind``: its first row that holds for the kind (chosen once per
    name and kind: a list of many findings asks for the same two or three claims for each)."""
    got = _chosen.get((name, kind))
    if got is None:
        rows = _built.get(name) or _claims(name)
        if not rows:
            raise KeyError(f"no claim {name!r} in the evidence table")
        got = next((c for c in rows if c.holds_for(kind)), rows[-1])
        _chosen[(name, kind)] = got
    return got


def _claim_name(code: str) -> str | None:
    """The name of rule ``code``'s claim (its line: the code, a tab, the name), found at its first finding."""
    text = _load()[1]
    at = text.find(f"\n{code}\t")
    name = None
    if at >= 0:
        at += len(code) + 2
        name = text[at:text.index("\n", at)]
    _named[code] = name
    return name


def rule_claim(code: str, kind: str | None = None) -> Claim | None:
    """The claim a rule's finding carries where its check names none (``None``: the rule has none,
    as the K rules, whose claim is their own row of the start-up errors)."""
    name = _named[code] if code in _named else _claim_name(code)
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
    names = dict.fromkeys(line.split("\t", 1)[0] for line in _load()[0].splitlines() if line)
    return [c for name in names for c in _claims(name)]


def rule_claims() -> dict[str, str]:
    """Rule code → the name of its claim."""
    return {code: name for code, name in (line.split("\t") for line in _load()[1].splitlines() if line)}


__all__ = ["CONSEQUENCES", "DOCUMENTED", "Claim", "claim", "claims", "drive_types", "rule_claim", "rule_claims"]

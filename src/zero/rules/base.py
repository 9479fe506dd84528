"""What every rule shares: its metadata, the one check interface, and the contexts.

A :class:`Rule` is a code with its name, default severity, summary and explanation
(fixed headings: what it checks, why it matters on the machine, example, fix). A
check is a generator over a context that reports one or more *declared* rules: the
rules of one root cause share a check, so that one fault gives one finding (an entry
whose value is not an integer is reported as R004 and never also as out of range).
Each family module declares its rules beside the check that reports them through a
:class:`Family`.

Every check has the same shape, ``check(context) -> Iterator[Diagnostic]``, and
every context reports through :meth:`Reporter.report`; what differs is what the
context holds: one list (:class:`Context`), a machine (:class:`MachineContext`) or
an NC program (:class:`ProgramContext`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence

from zero.catalog.evidence import Claim, rule_claim
from zero.catalog.evidence import claim as evidence_claim
from zero.catalog.registry import Registry
from zero.catalog.values import ListValues
from zero.diagnostics import Diagnostic, Fix, Related, Severity, Span
from zero.hints import Generic, TypeVar
from zero.patterns import compiled
from zero.records import Record, field, record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: a list's lint does not load the machine and program models
    from zero.machine.model import Machine
    from zero.nc.program import Program

if TYPE_CHECKING:
    import re
    from typing import Literal

    Scope = Literal["list", "machine", "program", "suppression", "file"]
E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO


# declared with the decorator: for type checkers a subclass of a Record is a record too, and the K family's
# rule (zero.rules.startup._KernelRule) is a plain subclass whose texts are properties read at their first use
@record(frozen=True)
class Rule:
    code: str
    name: str
    severity: Severity
    summary: str
    explanation: str
    scope: Scope = "list"
    opt_in: bool = False  # runs only when selected by its full code
    # the parameters its check reads, by ID (a key where the catalogue has no ID): the docs link them
    # both ways, and tests/docs fails on a rule that declares none or one the catalogue does not know
    reads: tuple[str, ...] = ()

    def render(self) -> str:
        return (
            f"{self.code} ({self.name}) — default severity: {self.severity.label}\n\n"
            f"{self.summary}\n\n{self.explanation.strip()}\n"
        )


_LONG_QUOTED = r"`([^`]{81,})`"  # compiled at the first long message (through re's cache)
_LONG_WORD = r"[^\s`]{81,}"


def _shorten(m: re.Match[str]) -> str:
    text = m.group(1)
    return f"`{text[:60]}…{text[-12:]}` ({len(text)} characters)"


def _shorten_word(m: re.Match[str]) -> str:
    text = m.group()
    return f"{text[:60]}…{text[-12:]} ({len(text)} characters)"


class Reporter:
    """Makes findings with the severity their evidence gives them (the run's severity for a code is
    the funnel's to apply: :mod:`zero.rules.funnel`)."""

    __slots__ = ()
    path: str

    def report(self, code: str, span: Span, message: str, *, param_id: str | None = None,
               fix: Fix | None = None, hint: str | None = None, path: str | None = None,
               related: tuple[Related, ...] = (), kernel_error: str | None = None,
               claim: str | Claim | None = None) -> Diagnostic:
        """A finding of ``code``. Its severity, consequence and source follow its claim (``claim``, else
        the rule's own claim in the evidence table: :mod:`zero.catalog.evidence`); the rule's declared
        severity is the most its findings can be. Whether it is reported, and with the severity the
        run gives its code (the user's word wins), is decided by the funnel alone."""
        if len(message) > 300:
            message = compiled(_LONG_WORD).sub(_shorten_word, compiled(_LONG_QUOTED).sub(_shorten, message))
        default = _defaults.get(code, Severity.ERROR)
        c = claim if isinstance(claim, Claim) else \
            evidence_claim(claim, self.list_kind) if claim is not None else rule_claim(code, self.list_kind)
        if c is None:
            return Diagnostic(code, default, message, span, self.path if path is None else path,
                              param_id, fix, hint, related, kernel_error)
        severity = min(c.severity, default)  # the evidence may lower the declared severity
        return Diagnostic(code, severity, message, span, self.path if path is None else path,
                          param_id, fix, hint, related, kernel_error or c.kernel_error, c.consequence, c.source)

    @property
    def list_kind(self) -> str | None:
        """The kind of the list a finding is about (``None``: a machine or a program)."""
        return None


_defaults: dict[str, Severity] = {}  # code → declared severity: set once, by the registry (zero.rules.families)


def declare(severities: dict[str, Severity]) -> None:
    """The declared severity of every rule, given by the one registry of families
    (:mod:`zero.rules.families`, imported with :mod:`zero.rules`, before any check runs)."""
    _defaults.clear()
    _defaults.update(severities)


def default_severity(code: str) -> Severity | None:
    """The severity a rule is declared with (the run's severity equal to it: the evidence decides)."""
    return _defaults.get(code)


def declared_codes() -> set[str]:
    """Every rule code the registry lists."""
    return set(_defaults)


class Context(ListValues, Reporter, Record):
    """One list as its checks see it: its values (:class:`ListValues`) and the selected codes."""

    severities: dict[str, Severity] = field(default_factory=dict)
    kernel: str | None = None  # the kernel release the machine runs, where the configuration says it
    default_list: bool = False  # a default list (the template read under the lists of its kind)
    # code -> the findings of this list counted so far, while run_checks runs the checks: a check may yield a
    # finding's code alone where MAX_PER_CODE + 1 of that code are counted already (it is counted, not shown)
    tally: dict[str, int] | None = None

    @property
    def path(self) -> str:  # type: ignore[override]
        return self.doc.path

    @property
    def list_kind(self) -> str | None:
        return self.kind


class MachineContext(Reporter, Record):
    """A machine: its lists and axes; findings carry the path of the list they are about."""

    machine: Machine
    registry: Registry
    severities: dict[str, Severity] = field(default_factory=dict)
    path: str = "-"


class ProgramContext(Reporter, Record):
    """An NC program, and the machine it runs on when one is known (N003/N004 need it)."""

    program: Program
    registry: Registry
    machine: Machine | None = None
    severities: dict[str, Severity] = field(default_factory=dict)
    path: str = "-"


C = TypeVar("C", Context, MachineContext, ProgramContext)
_Run = TypeVar("_Run", bound="Callable[..., Iterator[Diagnostic | str]]")  # a check function, as declared


class Check(Generic[C], Record, frozen=True):
    """A check and the rules it reports (the engine skips it when none of them is selected)."""

    codes: tuple[str, ...]
    run: Callable[[C], Iterator[Diagnostic | str]]  # a code alone: a finding past the cap (run_checks)

    def wanted(self, severities: dict[str, Severity]) -> bool:
        return not severities.keys().isdisjoint(self.codes)  # no generator left unfinished (GeneratorExit)


class Family(Generic[C]):
    """The rules of one family (one letter, one module) and the checks that report them."""

    def __init__(self, letter: str, title: str, scope: Scope) -> None:
        self.letter = letter
        self.title = title
        self.scope = scope
        self._rules: dict[str, Rule] = {}
        self._later: tuple[Callable[[], Iterable[Rule]], dict[str, Severity]] | None = None
        self.checks: list[Check[C]] = []

    @property
    def rules(self) -> dict[str, Rule]:
        """Code → rule, in the order declared (those declared later made here, at the first look)."""
        later = self._later
        if later is not None:
            self._later = None
            made = {self._add(r).code: r.severity for r in later[0]()}
            if made != later[1]:
                raise ValueError(f"the rules made for family {self.letter} are not the ones it declared")
        return self._rules

    def severities(self) -> dict[str, Severity]:
        """Code → declared severity of every rule (those declared later without making them: a list's lint
        reads no K, X or N rule object, only their codes and severities; issue 40, start-up)."""
        out = {code: r.severity for code, r in self._rules.items()}
        if self._later is not None:
            out.update(self._later[1])
        return out

    def declare_later(self, make: Callable[[], Iterable[Rule]], severities: dict[str, Severity]) -> None:
        """Rules made at the first look at :attr:`rules` by ``make``, whose codes and severities are
        ``severities`` (checked then)."""
        for code in severities:
            self._new(code)
        self._later = (make, severities)

    def _new(self, code: str) -> None:
        if not code.startswith(self.letter) or code in self._rules:
            raise ValueError(f"rule {code} does not belong to family {self.letter} or is declared twice")

    def _add(self, r: Rule) -> Rule:
        self._new(r.code)
        self._rules[r.code] = r
        return r

    def rule(self, code: str, name: str, severity: Severity, summary: str, explanation: str,
             opt_in: bool = False, reads: tuple[str, ...] = ()) -> Rule:
        """Declare a rule of this family (its code is never reused) and the parameters it reads."""
        return self._add(Rule(code, name, severity, summary, explanation, self.scope, opt_in, reads))

    def check(self, *rules: Rule | str) -> Callable[[_Run], _Run]:
        """Declare the function below as the check that reports ``rules`` (rules, or their codes)."""
        def register(run: _Run) -> _Run:
            self.checks.append(Check(tuple(r if isinstance(r, str) else r.code for r in rules), run))
            return run

        return register


MAX_PER_CODE = 10_000  # findings of one code in one file; the rest are counted in one more finding


def run_checks(checks: Sequence[Check[C]], context: C) -> list[Diagnostic]:
    """The findings of the checks that report any selected rule (``context.severities``: a pre-filter
    for speed; what is reported is the funnel's decision, :mod:`zero.rules.funnel`): at most
    ``MAX_PER_CODE`` of one code, and then one that counts the rest (a file of five million
    malformed lines held five million findings: 9 GB and minutes; one root cause, a bounded report).
    While they run, ``context.tally`` (a list's) holds the counts, and a check may yield a finding's code
    alone, unbuilt, where ``MAX_PER_CODE + 1`` of it are counted already: it is counted the same."""
    severities = context.severities
    out: list[Diagnostic] = []
    counts: dict[str, int] = {}
    more: dict[str, Diagnostic] = {}
    tallied = context if isinstance(context, Context) else None
    if tallied is not None:
        tallied.tally = counts  # a check that can tell a finding's code cheaply yields the code alone past the cap
    try:
        for check in checks:
            if not check.wanted(severities):
                continue
            for d in check.run(context):
                if isinstance(d, str):  # past the cap, counted only (a million made-up keys: no million findings)
                    counts[d] = counts.get(d, 0) + 1
                    continue
                n = counts.get(d.code, 0) + 1
                counts[d.code] = n
                if n <= MAX_PER_CODE:
                    out.append(d)
                elif n == MAX_PER_CODE + 1:
                    more[d.code] = d
    finally:
        if tallied is not None:
            tallied.tally = None  # a check called on its own afterwards yields findings only
    for code, first in more.items():
        rest = counts[code] - MAX_PER_CODE
        out.append(Diagnostic(code, first.severity, f"{rest} more {code} finding{'s' if rest != 1 else ''} in this "
                              f"file from here on (zero lists the first {MAX_PER_CODE} of each code): "
                              f"{first.message}", first.span, first.path, first.param_id))
    return out

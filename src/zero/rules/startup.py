"""K rules: the kernel's own start-up checks of a list, each with the number the kernel reports.

The controller checks its lists when it starts and reports what it finds as numbered errors (the
axis management's list-load errors: 110000–119999), then corrects the value in a documented way
— not always to the default. zero keeps one row per documented error a list can cause
(``catalog/data/startup_errors.toml``: number, list kind, the condition as the documentation
states it, the correction, the source page) and checks each one offline as a rule of its own:
K001 is P-ERR-…, and so on. A condition is evaluated on the list's values, a parameter the list
does not set taking its catalogue default; where the documentation does not say what the kernel
does, the message says so.
"""

from __future__ import annotations

import importlib
import itertools
import os
from collections.abc import Iterable, Iterator

from zero import patterns
from zero.catalog.condition_helpers import DEFAULT_LIST, ELSEWHERE, UNIQUE, supported_drive_types
from zero.catalog.data import startup_facts
from zero.catalog.ranges import format_number
from zero.catalog.registry import ParamSpec
from zero.catalog.values import Resolved, default_number, parse_int
from zero.diagnostics import Diagnostic, Severity, Span
from zero.lists.model import Entry, format_key
from zero.records import Record
from zero.rules.base import Context, E, Family, Rule, W

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

    from zero.catalog.condition_helpers import Compiled
    from zero.rules.base import Scope

FAMILY: Family[Context] = Family("K", "kernel start-up checks", "list")


class StartupError(Record, frozen=True):
    code: str
    number: int
    kind: str
    params: tuple[str, ...]
    condition_text: str
    when_text: str
    correction: str
    title: str
    source: str
    written: bool = False  # checked only where the list writes the reported parameter (absent is fine)
    reported: str = "at start-up"  # when the kernel reports it (the page's error type)

    @property
    def kernel_error(self) -> str:
        return f"P-ERR-{self.number}"


class _Compiled(Record, frozen=True):
    condition: Compiled
    when: Compiled | None
    read: tuple[str, ...]  # the parameters the condition reads
    shown: tuple[tuple[str, int | None], ...]  # each with the element it names, as a finding shows it


# A row's condition as the checks read it: (condition, guard or None, the parameters it reads, the elements it
# shows), a plain tuple (what :class:`_Compiled` holds): a list's lint reads some hundred rows, none of which needs
# a record, and a row's StartupError is made where its condition fails (issue 40, start-up: axis.lis's checks
# 21.7 → 20.1 M instructions).
Plan = tuple["Compiled", "Compiled | None", tuple[str, ...], tuple[tuple[str, "int | None"], ...]]

_compiled: dict[str, _Compiled] = {}
_plans: dict[str, Plan] = {}  # code -> its row's plan, once made
_written: dict[str, dict[str, tuple[Any, ...]]] = {}  # kind -> startup_compiled_<kind>.COMPILED, once read


def _written_of(kind: str) -> dict[str, tuple[Any, ...]]:
    """The K conditions of one list kind written at build time (``data/startup_compiled_axis.py``, ...),
    imported at the kind's first check (an axis list's lint reads no channel rule); empty for a kind
    that has none."""
    got = _written.get(kind)
    if got is None:
        try:  # start-up: written at build time, imported at the kind's first check
            got = importlib.import_module(f"zero.catalog.data.startup_compiled_{kind.lower()}").COMPILED \
                if kind.isascii() and kind.isalnum() else {}
        except ModuleNotFoundError:  # a kind without K rules written
            got = {}
        _written[kind] = got
    return got


def compiled(err: StartupError) -> _Compiled:
    """An error's condition compiled at its first check (not at start-up: a zero-offset list never
    needs the axis checks)."""
    hit = _compiled.get(err.code)
    if hit is None:
        hit = _compiled[err.code] = _Compiled(*_plan_of(err.code, err.kind, err.condition_text, err.when_text))
    return hit


def _plan_of(code: str, kind: str, condition: str, when: str, written: dict[str, tuple[Any, ...]] | None = None) \
        -> Plan:
    """The plan of the error declared with these facts (its :class:`StartupError` not needed): written at build
    time where the row's texts are the ones written (``written``: its kind's, where the caller has them), else
    compiled here."""
    hit = _plans.get(code)
    if hit is None:
        pre = (_written_of(kind) if written is None else written).get(code)
        if pre is not None and pre[0] == condition and pre[1] == when:  # else stale: compiled here
            hit = _plans[code] = pre[2:]
            return hit
        from zero.catalog.conditions import compile_condition, parse, ref_elements, refs  # start-up: a stale row only

        node = parse(condition)
        hit = _plans[code] = (compile_condition(node), compile_condition(parse(when)) if when else None,
                              tuple(refs(node)), tuple(ref_elements(node)))
    return hit


def _correction_said(correction: str) -> str:
    """The documented correction in words (``P-AXIS-00219 = P-AXIS-00268`` → "sets P-AXIS-00219 to the
    value of P-AXIS-00268")."""
    c = correction.strip()
    if not c:
        return "the documentation does not say what the kernel then uses"
    if c == "default":
        return "the kernel uses the parameter's default instead"
    if c == "abort":
        return "the kernel aborts the start-up"
    if c == "none":
        return "the kernel only warns: it changes no value"
    if not c.startswith("P-"):  # the documented reaction in words: "switches the I position controller off"
        return f"the kernel {c}"
    target, _, value = c.partition("=")
    value = value.strip()
    what = f"the value of {value}" if value.startswith("P-") else value
    return f"the kernel sets {target.strip()} to {what}"


# What a declaration reads of a row of startup_errors.toml, in StartupError's order, and its severity
# word: (code, number, list, params, condition, when, correction, title, source, written, reported, severity).
Facts = tuple[str, int, str, tuple[str, ...], str, str, str, str, str, bool, str, str]
# What is declared of it: (the severity's letter, name, summary, explanation, the parameters it reads).
Said = tuple[str, str, str, str, tuple[str, ...]]


def facts(row: dict[str, object]) -> Facts:
    """The facts of a row that its rule and its :class:`StartupError` are declared from."""
    params = row.get("params", ()) or ()
    return (str(row["code"]), int(str(row["number"])), str(row["list"]),
            tuple(str(p) for p in params) if isinstance(params, (list, tuple)) else (),
            str(row.get("condition", "")), str(row.get("when", "")), str(row.get("correction", "")),
            str(row["title"]), str(row["source"]), bool(row.get("written", False)),
            str(row.get("reported", "at start-up")), str(row.get("severity", "")))


def said(f: Facts) -> Said:
    """A row's rule as declared: a documented warning without a reaction, or a documented message whose
    reaction no page gives, is a warning; it reads the reported parameters and the condition's."""
    _, number, _, params, condition, when, correction, title, source, _, reported, _ = f
    letter = _letter(f)
    guard = f" (checked where {when} holds)" if when else ""
    said_when = "" if reported == "at start-up" else f" ({reported})"
    explanation = f"""
What it checks: {title}. When it takes over the list, the kernel checks that `{condition}` holds{guard}, and
reports error P-ERR-{number} when it does not{said_when}.

Why it matters on the machine: the message appears when the controller starts, and {_correction_said(correction)}.

Fix: change the values so that `{condition}` holds. Source: {source}
"""
    reads = tuple(dict.fromkeys([*params, *patterns.compiled(r"P-[A-Z]{4}-\d{5}").findall(f"{condition} {when}")]))
    return letter, f"kernel-{number}", f"P-ERR-{number}: {title}", explanation, reads


def _letter(f: Facts) -> str:
    """A row's severity letter: a documented warning without a reaction, or a documented message whose
    reaction no page gives, is a warning ("W"); else an error ("E")."""
    return "W" if f[6] == "none" or f[11] == "warning" else "E"


def _facts_declared() -> Iterable[Facts]:
    """Each row's facts, in order (the rows with a condition). Written at build time (tools/gen_startup_rules.py:
    data/startup_facts.py): taken as written while ``startup_errors.py`` has the size they were written from
    (the rows are then not imported at all), else read from the rows (slower, never wrong)."""
    try:
        size = os.stat(os.path.join(os.path.dirname(startup_facts.__file__), "startup_errors.py")).st_size
    except OSError:
        size = -1
    if size == startup_facts.ERRORS_SIZE:
        written: dict[str, Facts] = startup_facts.FACTS
        return written.values()
    from zero.catalog.data.startup_errors import ERRORS  # start-up: only where the module written from them is stale

    return [facts(row) for row in ERRORS if row.get("condition")]  # (a row without: documented, not evaluable)


def _said(f: Facts) -> Said:
    """What the rule of a row's facts declares (:func:`said`), as written at build time
    (data/startup_rules.py, imported where a rule's summary, explanation or what it reads is first read:
    a lint prints none of them) where the facts it was written from are these, else worded here."""
    from zero.catalog.data.startup_rules import DECLARED  # start-up: a rule's texts only where something reads them

    pre = DECLARED.get(f[0])
    return pre[1] if pre is not None and pre[0] == f else said(f)


def _declared() -> list[tuple[Facts, Said]]:
    """Each row's facts and what it declares, in order."""
    return [(f, _said(f)) for f in _facts_declared()]


_SLOTS = {name: Rule.__dict__[name] for name in ("summary", "explanation", "reads")}  # Rule's own fields
_set = object.__setattr__  # a frozen record's fields, as its own __init__ sets them
_ROWS: dict[str, Facts] = {}  # code -> its row's facts


class _KernelRule(Rule):
    """A K rule whose summary, explanation and the parameters it reads are its row's (:func:`_said`), read
    at their first use (declared unset): a list's lint reads none of them (issue 40, start-up)."""

    __slots__ = ()

    def __init__(self, code: str, name: str, severity: Severity, summary: str = "", explanation: str = "",
                 scope: Scope = "list", opt_in: bool = False, reads: tuple[str, ...] = ()) -> None:
        _set(self, "code", code)
        _set(self, "name", name)
        _set(self, "severity", severity)
        _set(self, "scope", scope)
        _set(self, "opt_in", opt_in)
        if summary or explanation:  # given (replace() gives every field): else read at their first use
            for field, value in (("summary", summary), ("explanation", explanation), ("reads", reads)):
                _SLOTS[field].__set__(self, value)

    def _field(self, name: str) -> Any:
        try:
            return _SLOTS[name].__get__(self, Rule)
        except AttributeError:  # not read yet
            pass
        _, _, summary, explanation, reads = _said(_ROWS[self.code])
        for field, value in (("summary", summary), ("explanation", explanation), ("reads", reads)):
            _SLOTS[field].__set__(self, value)
        return _SLOTS[name].__get__(self, Rule)

    @property
    def summary(self) -> str:
        return str(self._field("summary"))

    @summary.setter
    def summary(self, value: str) -> None:
        _SLOTS["summary"].__set__(self, value)

    @property
    def explanation(self) -> str:
        return str(self._field("explanation"))

    @explanation.setter
    def explanation(self, value: str) -> None:
        _SLOTS["explanation"].__set__(self, value)

    @property
    def reads(self) -> tuple[str, ...]:
        return tuple(self._field("reads"))

    @reads.setter
    def reads(self, value: tuple[str, ...]) -> None:
        _SLOTS["reads"].__set__(self, value)


def _declare() -> dict[str, list[Facts]]:
    """Each row's facts by list kind, in order, and its rule's code and severity: the rule itself is made at the
    first look at the family's rules (:func:`_rules`; its texts at their first use: :class:`_KernelRule`), and a
    row's :class:`StartupError` where a check needs it (:func:`_error`), not here (an axis list's lint checks
    some sixty of the 125: issue 40, start-up)."""
    out: dict[str, list[Facts]] = {"": []}  # (never empty once built)
    severities: dict[str, Severity] = {}
    for f in _facts_declared():
        code = f[0]
        if code in _ROWS:
            raise ValueError(f"rule {code} is declared twice")
        _ROWS[code] = f
        severities[code] = W if _letter(f) == "W" else E
        got = out.get(f[2])
        if got is None:
            out[f[2]] = [f]
        else:
            got.append(f)
    FAMILY.declare_later(_rules, severities)
    return out


def codes() -> frozenset[str]:
    """Every K code (without making the rules: :func:`_rules`)."""
    return frozenset(_ROWS)


def _rules() -> list[Rule]:
    """Each row's rule, in order: made at the first look at the family's rules (``zero rule``, the docs, SARIF's
    rule table), never by a list's lint, which reads only their codes and severities."""
    return [_KernelRule(code, f"kernel-{f[1]}", W if _letter(f) == "W" else E) for code, f in _ROWS.items()]


_BY_KIND: dict[str, list[Facts]] = _declare()  # list kind -> its rows' facts, in order
_ERRORS: dict[str, StartupError] = {}  # code -> its check, made once


def _error(f: Facts) -> StartupError:
    """The :class:`StartupError` of a row's facts (made once)."""
    err = _ERRORS.get(f[0])
    if err is None:
        err = _ERRORS[f[0]] = StartupError(*f[:11])
    return err


CHECKS: list[StartupError]  # every row's check, in order: made at its first use (__getattr__ below)


def __getattr__(name: str) -> list[StartupError]:
    """``CHECKS``: every row's :class:`StartupError`, in order (made at the first use: a list's lint
    makes only those of its kind that it checks)."""
    if name != "CHECKS":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    checks = [_error(f) for f in _ROWS.values()]
    globals()["CHECKS"] = checks
    return checks


@FAMILY.check(*_ROWS)
def check_startup(ctx: Context) -> Iterator[Diagnostic]:
    """The documented start-up checks of this list's kind, on its values (defaults where unset). One
    root cause, one finding: of the checks that fail on one line, the one that reports that line's
    own parameter (`getriebe[0].dynamik.vb_max 0`: 110079, not the checks that merely read it)."""
    by_line: dict[int, list[tuple[bool, Diagnostic]]] = {}
    by_id = ctx.by_id
    severities = ctx.severities
    rows = _BY_KIND.get(ctx.kind or "", ())
    written = _written_of(rows[0][2]) if rows else {}
    for f in rows:
        code = f[0]
        if code not in severities:
            continue  # not selected
        plan = _plans.get(code) or _plan_of(code, f[2], f[4], f[5], written)
        for p in plan[2]:
            if p in by_id:
                break
        else:
            continue  # the list sets nothing the condition reads
        for d, own in _check(ctx, f, plan):
            by_line.setdefault(d.span.line, []).append((own, d))
    for line in sorted(by_line):
        found = by_line[line]
        primary = [d for own, d in found if own] or [found[0][1]]
        yield primary[0]


def _facts(ctx: Context, pid: str) -> tuple[ParamSpec | None, bool, int]:
    """A parameter as the K checks read it: its spec, whether its value is text (:func:`_text`), and
    how many indices its elements have; found once per registry (a fleet's K checks read a few hundred
    parameters a hundred thousand times)."""
    memo: dict[str, tuple[ParamSpec | None, bool, int]] = ctx.registry.memo.setdefault("startup", {})
    got = memo.get(pid)
    if got is None:
        spec = ctx.registry.get(pid)
        got = memo[pid] = (spec, _text(spec), len(spec.dims) if spec is not None else 0)
    return got


def _elements(ctx: Context, params: tuple[str, ...], read: tuple[str, ...]) -> list[tuple[int, ...]]:
    """The elements to check: those the list sets of the reported parameter (``params[0]``; or of any parameter
    of the condition, ``read``), so that a condition on `getriebe[g]` is checked for each gear the list writes."""
    n = _facts(ctx, params[0])[2] if params else 0
    if not n:
        return [()]  # a single value (or no reported parameter): every element the list sets is element ()
    seen: dict[tuple[int, ...], None] = {}
    for pid in (*params, *read):
        for idx in ctx.ids_of(pid):
            seen[idx[:n] if n else ()] = None
    return list(seen) or [()]


def _check(ctx: Context, f: Facts, plan: Plan) -> Iterator[tuple[Diagnostic, bool]]:
    """Each failing element's finding, and whether it lies on the line of the parameter it reports (``f``: the
    row's facts, ``plan``: its compiled condition; its :class:`StartupError` made where the condition fails)."""
    condition, when, _, _ = plan
    for idx in _elements(ctx, f[3], plan[2]):
        def lookup(pid: str, index: int | None, idx: tuple[int, ...] = idx) -> float | int | str | None:
            if pid == DEFAULT_LIST:
                return int(ctx.default_list)
            if pid.startswith(UNIQUE):
                return _unique(ctx, pid[len(UNIQUE):].split(","), idx)
            if pid.startswith(ELSEWHERE):
                first, _, second = pid[len(ELSEWHERE):].partition(",")
                return _elsewhere(ctx, first, second, idx)
            return _value(ctx, pid, (index,) if index is not None else idx)

        if when is not None and when(lookup) is not True:
            continue
        if condition(lookup) is not False:
            continue  # holds, or a value it needs is not known: nothing to say
        err = _ERRORS.get(f[0]) or _error(f)
        c = compiled(err)
        if err.written:
            if _reported_entry(ctx, err, idx, own_only=True) is None:
                continue  # absent is fine: only a value the list writes is checked
        elif _fails_on_defaults(ctx, err, idx):
            continue  # the catalogue's own defaults fail it too: its 0 means "not used", or the row says too much
        hit = _reported_entry(ctx, err, idx)
        if hit is None:
            continue  # the list sets none of the values the condition reads: not this list's doing
        entry, pid_on_line = hit
        shared = err.condition_text.startswith(("unique(", "not elsewhere("))
        shown = c.shown[:1] if shared else c.shown  # the value another element shares
        values = ", ".join(f"{_named(ctx, pid, idx if index is None else (index,))} = "
                           f"{_shown(lookup(pid, index))}" for pid, index in shown)
        yield ctx.report(
            err.code, Span.on_line(entry.line, entry.value_start, entry.value_end),
            f"P-ERR-{err.number}: {err.title} ({values}): the controller reports {_kind(err)} {err.number} "
            f"{err.reported}, "
            f"and {_correction_said(err.correction)}", hint=f"the documented condition: {err.condition_text}"
            f"{_drive_types_said(err)}",
            param_id=err.params[0] if err.params else None, kernel_error=err.kernel_error), \
            bool(err.params) and pid_on_line == err.params[0]


def _unique(ctx: Context, pids: list[str], idx: tuple[int, ...]) -> int | None:
    """``unique(P, Q…)`` for element ``idx`` of ``P``: 1 where its value is the value of no other element
    of ``P`` set on an earlier line (the later of two is the one reported) and of no element of ``Q…``;
    0 where it is; unknown where this list does not set it, or sets it empty or 0 (not configured)."""
    first = pids[0]
    element = _element(ctx, first, idx)
    own = _own(ctx, first, idx)
    mine = _value(ctx, first, idx)
    if own is None or mine in (None, "", 0) or not _counted(ctx, first, element):
        return None
    for pid in pids:
        for other, res in ctx.ids_of(pid).items():
            if pid == first and (other == element or res.entry.line >= own.entry.line):
                continue
            if _counted(ctx, pid, other) and _value(ctx, pid, other) == mine:
                return 0
    return 1


def _elsewhere(ctx: Context, first: str, second: str, idx: tuple[int, ...]) -> int | None:
    """``elsewhere(P, Q)`` for element ``idx`` of ``P``: 1 where its value is ``Q``'s in another element
    of the same group (all indices but the last equal), or in any element where ``Q`` belongs to another
    structure than ``P``; for ``elsewhere(P, P)`` an earlier element of the group (the later of two is
    reported); 0 where it is not; unknown where this list does not set it, or sets it empty or 0."""
    element = _element(ctx, first, idx)
    mine = _value(ctx, first, idx)
    if _own(ctx, first, idx) is None or mine in (None, "", 0) or not _counted(ctx, first, element):
        return None
    apart = _structure(ctx, first) != _structure(ctx, second)  # var[i].type against struct[j].name: any j
    for other in ctx.ids_of(second):
        later = first != second or other < element  # elsewhere(P, P): an earlier element's, the later reported
        if (apart or (other != element and other[:-1] == element[:-1] and later)) and _counted(ctx, second, other) \
                and _value(ctx, second, other) == mine:
            return 1
    return 0


def _structure(ctx: Context, pid: str) -> str:
    """The structure a parameter is an element of (``var[]`` for ``var[].type``), "" where it is none."""
    spec = ctx.registry.get(pid)
    key = (spec.key if spec is not None else None) or ""
    return key[:key.rfind("[]") + 2] if "[]" in key else ""


def _counted(ctx: Context, pid: str, idx: tuple[int, ...]) -> bool:
    """Is element ``idx`` of ``pid`` within its count (`spindel[2]` with `spdl_anzahl 2` is not: the
    controller does not configure it)? True where no count is known."""
    spec = ctx.registry.get(pid)
    if spec is None:
        return True
    for count_pid, pos in ctx.registry.counted_by(spec):
        count = ctx.number_of(count_pid, idx[:pos] if pos else ())
        if count is not None and pos < len(idx) and idx[pos] >= count:
            return False
    return True


def _kind(err: StartupError) -> str:
    """"warning" for a documented warning without a reaction, else "error"."""
    return "warning" if err.correction == "none" else "error"


def _drive_types_said(err: StartupError) -> str:
    """For a condition on the drive type: which drive types (P-AXIS-00020) the parameter page lists."""
    said = []
    for pid in patterns.compiled(r"supports\((P-[A-Z]{4}-[0-9]{5})\)").findall(err.condition_text):
        types = supported_drive_types(pid)
        if types is not None:
            said.append(f"the {pid} page lists drive types (P-AXIS-00020) {', '.join(str(t) for t in sorted(types))}")
    return f"; {'; '.join(said)}" if said else ""


def _text(spec: ParamSpec | None) -> bool:
    """Is the value text (a STRING that is a name, or whose symbols have no numbers: `homing_type
    TORQ`), not a number or a symbol's number (`achs_typ ACHSTYP_ROTATOR` is 2)?"""
    # not all() over a generator: one it leaves unfinished is closed by raising GeneratorExit in it
    return spec is not None and spec.type == "STRING" and \
        [n for _, n in spec.symbols].count(None) == len(spec.symbols)


def _shown(value: float | int | str | None) -> str:
    """A value as a finding shows it: a number as the catalogue writes it, text quoted."""
    if isinstance(value, str):
        return f'"{value}"'
    return format_number(value)


def _element(ctx: Context, pid: str, idx: tuple[int, ...]) -> tuple[int, ...]:
    """The element of ``pid`` that element ``idx`` of the checked parameter pairs with."""
    n = _facts(ctx, pid)[2]
    return idx if len(idx) == n else idx[:n] if len(idx) > n else idx + (0,) * (n - len(idx))


def _own(ctx: Context, pid: str, idx: tuple[int, ...]) -> Resolved | None:
    """This list's entry of ``pid`` at that element (never a default list's)."""
    return ctx.by_id.get(pid, {}).get(_element(ctx, pid, idx))


def _value(ctx: Context, pid: str, idx: tuple[int, ...]) -> float | int | str | None:
    """The value as written, where the list writes a number (also one the catalogue's range refuses:
    the kernel's own check sees it), else the value the controller uses (the default where unset); a
    STRING parameter's text (the list's, else the default list's, else the catalogue default)."""
    _, text, n = _facts(ctx, pid)
    element = idx if len(idx) == n else idx[:n] if len(idx) > n else idx + (0,) * (n - len(idx))
    if text:
        return ctx.text_of(pid, element)
    res = ctx.by_id.get(pid, {}).get(element)  # this list's entry (_own)
    if res is not None:
        if res.value.number is not None:
            return res.value.number
        raw = parse_int(res.entry.value)
        if raw is not None:
            return raw
    return ctx.number_of(pid, idx)


def _named(ctx: Context, pid: str, idx: tuple[int, ...]) -> str:
    """``P-AXIS-00219`` as ``P-AXIS-00219 (`kenngr.vb_refmax`)``, with the element checked."""
    spec = ctx.registry.get(pid)
    if spec is None or not spec.key:
        return pid
    return f"{pid} (`{format_key(spec.key, _element(ctx, pid, idx))}`)"


def _fails_on_defaults(ctx: Context, err: StartupError, idx: tuple[int, ...]) -> bool:
    """Does the condition fail with nothing but the catalogue's defaults? Then the list is not what makes
    it fail: a default of 0 that means "not used" (an emergency deceleration of 0 takes the normal
    one), which the documented condition leaves unsaid."""

    def defaults(pid: str, index: int | None) -> float | int | str | None:
        if pid == DEFAULT_LIST:
            return int(ctx.default_list)
        spec = ctx.registry.get(pid)
        if spec is not None and _text(spec):
            return spec.default or ""
        return default_number(spec) if spec is not None else None

    c = compiled(err)
    if c.when is not None and c.when(defaults) is not True:
        return False
    return c.condition(defaults) is False


def _reported_entry(ctx: Context, err: StartupError, idx: tuple[int, ...],
                    own_only: bool = False) -> tuple[Entry, str] | None:
    """The line to report on, and its parameter: this list's entry of the reported parameter, else of
    another one the condition reads (never a default list's: its own findings are its own);
    ``own_only``: the reported parameter's entry or none."""
    read = compiled(err).read
    order = err.params[:1] if own_only else list(itertools.chain((p for p in err.params if p in read), read))
    for pid in order:
        res = _own(ctx, pid, idx)
        if res is not None:
            return res.entry, pid
    return None


__all__ = ["CHECKS", "FAMILY", "StartupError", "check_startup", "codes"]

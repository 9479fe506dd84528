"""``zero report``: one self-contained HTML page about a machine.

The page is in the order of work: a summary whose cards link to the sections; every finding of
``zero lint --machine``, errors first, a class of many findings of one code collapsed to its count;
against a golden machine or a git revision, the differences of ``zero diff --machine``; a fleet's
drift; the machine's structure (channels, their axes and spindles, which list sets what); a
picture of every axis's travel range (:mod:`zero.output.svg`), marked where its soft limits do not
stop it; and last, collapsible, the effective values with their origin, the value the controller
uses where a finding with documented evidence says it changes one (linked to the finding), the
default, and the value in engineering units (searchable, filterable by list, by origin and by
"differs from the default"). Printed, the page is the hand-over document: everything but the
values that equal their defaults (``values="all"``: the full table).

Everything on it comes from :func:`zero.engine.report.report_facts` (the machine, its lint results,
the machine compared against, the programs' travel, the fleet's drift): this module only lays them
out. The page is rendered with Jinja2 (the ``report`` extra), autoescaped; it loads
nothing (no script, font, style or image from anywhere): CSS and a small script are inline.
"""

from __future__ import annotations

import os
import re
import urllib.request
from collections.abc import Sequence
from datetime import UTC, datetime
from importlib import resources
from pathlib import Path
from typing import Any

from zero import __version__
from zero.catalog.ids import (
    AXIS_TYPE,
    COMP_LIST_AXIS,
    SPINDLE_AXIS,
    SWE_BEHAVIOUR,
    SWE_CHECK,
    SWE_NEG,
    SWE_POS,
    SWE_TOL,
    engineering_number,
    in_engineering,
    is_rotary,
)
from zero.catalog.ranges import format_number
from zero.catalog.registry import ParamSpec, Registry
from zero.diff import Change, default_effective
from zero.diff import effective as value_of
from zero.engine.report import ReportFacts
from zero.engine.results import LintResult
from zero.errors import ZeroError
from zero.forms import split_part
from zero.machine.effective import CATALOGUE, DEFAULT_LIST, LIST, Scope, effective, entries_of, scope_values
from zero.machine.limits import pcs_limits
from zero.machine.model import ListFile, Machine
from zero.output.formats import rule_docs_template
from zero.output.svg import REF_POINT, STYLE, AxisPicture, axis_pictures, axis_svg
from zero.records import Record, field
from zero.rules import RULES
from zero.rules.startup import CHECKS

ORIGINS = (LIST, DEFAULT_LIST, CATALOGUE)  # the layers a value comes from, named as zero show --machine does
VALUES = ("changed", "all")  # --values: the printed table holds the values that differ from their defaults, or all
SEVERITIES = ("error", "warning", "info")  # the order of work
NOISE = 5  # this many warnings (or infos) of one code are a class, collapsed to its count


class Link(Record):
    """A place in a file: the text shown (``path:line``) and a relative link to the file."""

    text: str
    href: str | None


class ValueRow(Record):
    scope: str
    key: str
    param_id: str | None
    value: str | None  # as written (or the catalogue's default where no list sets it)
    origin: str  # list, default list, catalogue default
    where: Link | None
    differs: bool  # from the catalogue default
    shown: str | None = None  # the value in engineering units (1,040 mm), where the catalogue gives a unit
    default: str | None = None  # the catalogue's default as written, and in engineering units
    default_shown: str | None = None
    used: str | None = None  # the value the controller uses where a finding with documented evidence changes it
    used_by: str | None = None  # the anchor of that finding
    findings: list[tuple[str, str, str]] = field(default_factory=list)  # anchor, code, severity on this line
    also: list[str] = field(default_factory=list)  # the other lists that take this same line of a default list
    repeated: bool = False  # a default list's line printed once, under the first list that takes it

    @property
    def anchor(self) -> str:
        return "value-" + "".join(c if c.isalnum() else "-" for c in f"{self.scope}-{self.key}")

    @property
    def printed(self) -> bool:
        """In the hand-over print with ``--values changed``: differs, is corrected or has a finding."""
        return not self.repeated and (self.differs or self.used is not None or bool(self.findings))


class AxisView(Record):
    picture: AxisPicture
    svg: str
    settings: list[tuple[str, str | None, str, Link | None]] = field(default_factory=list)  # key, value, origin, where
    monitor_where: Link | None = None  # the line that switches the monitoring off or to warnings


class FindingGroup(Record):
    """The findings of one code and severity: a class, collapsed to its count where it is noise."""

    code: str
    severity: str
    name: str
    summary: str
    results: list[dict[str, Any]] = field(default_factory=list)

    @property
    def noise(self) -> bool:
        return self.severity != "error" and len(self.results) >= NOISE

    @property
    def lists(self) -> list[str]:
        return list(dict.fromkeys(d["scope"] for d in self.results))


class Against(Record):
    """The machine compared against: what was given, the changes, and which axes' soft limits changed."""

    given: str
    label: str  # "start-up list golden/hochlauf.lis" or "git revision HEAD~1 (1a2b3c4)"
    changes: list[Change] = field(default_factory=list)
    deltas: list[str] = field(default_factory=list)  # each change's delta in engineering units ("" where none)


class MachineReport(Record):
    title: str
    startup: Link
    workdir: str
    generated: str
    named: list[dict[str, Any]]
    channels: list[dict[str, Any]]
    axis_lists: list[dict[str, Any]]
    axes: list[AxisView]
    scopes: list[str]
    values: list[ValueRow]
    findings: list[FindingGroup]
    rules: list[dict[str, str]]
    rule_url: str | None
    against: Against | None = None
    counts: dict[str, int] = field(default_factory=dict)
    fleet: dict[str, Any] | None = None  # `--fleet`: the JSON of `zero diff --fleet` with this machine golden
    values_printed: str = "changed"  # --values: changed (the values that differ from their defaults) or all

    def by_severity(self) -> list[tuple[str, list[FindingGroup]]]:
        """The finding classes in the order of work: errors, warnings, infos; noise last in each."""
        return [(s, sorted((g for g in self.findings if g.severity == s), key=lambda g: (g.noise, g.code)))
                for s in SEVERITIES if any(g.severity == s for g in self.findings)]

    @property
    def unmonitored(self) -> list[AxisView]:
        return [v for v in self.axes if v.picture.monitoring_said]


# ---------------------------------------------------------------------------- links


def link(path: str | Path | None, line: int | None, base: Path) -> Link | None:
    """``path:line`` with a link to the file relative to ``base`` (the report's folder)."""
    if path is None:
        return None
    file, _ = split_part(str(path))
    text = f"{path}:{line}" if line else str(path)
    try:
        rel = os.path.relpath(os.path.abspath(file), os.path.abspath(base))
    except ValueError:  # another drive
        return Link(text, None)
    return Link(text, urllib.request.pathname2url(rel))


# ---------------------------------------------------------------------------- the report


# ------------------------------------------------------------------------- engineering units
# (the catalogue's units as an engineer reads them: zero.catalog.ids, the one home of units)


def _engineering(spec: ParamSpec | None, value: tuple[str, Any] | None, rotary: bool | None) -> str | None:
    if spec is None or value is None or value[0] != "num" or not spec.units:
        return None
    return in_engineering(spec.units, value[1], rotary)


def delta_in_engineering(c: Change, rotary: bool | None) -> str:
    """A change's delta in engineering units: ``zero diff`` gives lengths in mm or degrees ("mm or °"
    where it does not know the axis) and other quantities in the catalogue's units ("um/s, mdeg/s")."""
    if c.delta is None or c.unit is None:
        return ""
    if c.unit in ("mm or °", "mm", "°"):
        unit = c.unit if c.unit != "mm or °" or rotary is None else ("°" if rotary else "mm")
        return f"{'+' if c.delta > 0 else ''}{engineering_number(c.delta)} {unit}"
    shown = in_engineering(c.unit.split(", "), c.delta, rotary)
    if shown is None:
        return f"{'+' if c.delta > 0 else ''}{engineering_number(c.delta)} {c.unit}"
    return ("+" if c.delta > 0 else "") + shown


_AXIS_INDEX = re.compile(r"\bachse\[(\d+)\]")
_TOOL_LENGTH = re.compile(r"\.(laenge|radius)$")  # wz[i].laenge, wz[i].radius: lengths, in mm


def _rotary_by_scope(machine: Machine) -> dict[str, bool | dict[int, bool]]:
    """For each list of the machine: whether its lengths are degrees (an axis list), or per channel
    axis ``j`` (a channel's zero-offset list: ``np_grp[i].achse[j]``); absent: not known."""
    axes = machine.axes()
    out: dict[str, bool | dict[int, bool]] = {}
    for name, lf in machine.scopes():
        if lf.values.kind == "AXIS":
            out[name] = is_rotary(lf.number(AXIS_TYPE))
    for i, lf in machine.compensation:  # a compensation list: the axis it names (kopf.achs_nr)
        nr = lf.number(COMP_LIST_AXIS)
        if nr is not None and int(nr) in axes:
            out[f"compensation {i} ({lf.key})"] = axes[int(nr)].rotary
    for ch in machine.channels:
        if ch.tools is not None:  # a tool's length and radius are lengths
            out[f"channel {ch.index} ({ch.tools.key})"] = {-1: False}
        per_axis = {ca.index: axes[ca.log_nr].rotary for ca in ch.axes if ca.log_nr in axes}
        for per_channel in (ch.zero, ch.lists):
            if per_channel is not None:
                out[f"channel {ch.index} ({per_channel.key})"] = per_axis
    return out


def _rotary(known: dict[str, bool | dict[int, bool]], scope: str, key: str) -> bool | None:
    hit = known.get(scope)
    if isinstance(hit, dict):
        if -1 in hit:
            return False if _TOOL_LENGTH.search(key) else None
        m = _AXIS_INDEX.search(key)
        return hit.get(int(m.group(1))) if m else None
    return hit


# ---------------------------------------------------------------------------- the values


def _file_key(path: str | Path | None) -> str:
    return os.path.abspath(split_part(str(path))[0]) if path is not None else ""


def _values(machine: Machine, base: Path, findings: Sequence[FindingGroup] = ()) -> list[ValueRow]:
    rows: list[ValueRow] = []
    rotary = _rotary_by_scope(machine)
    on_line: dict[tuple[str, int], list[dict[str, Any]]] = {}
    for g in findings:
        for d in g.results:
            on_line.setdefault((_file_key(d["path"]), d["line"]), []).append(d)
    for scope in effective(machine, with_defaults=True):
        entries = entries_of(scope.file.values)
        registry = scope.file.values.registry
        for v in scope.values:
            spec = registry.get(v.param_id) if v.param_id else None
            entry = entries.get(v.key)
            differs = False
            now = value_of(entry, spec) if entry is not None else default_effective(spec)
            dflt = default_effective(spec)
            if v.origin.source != CATALOGUE and entry is not None:
                differs = now != dflt
            ax = _rotary(rotary, scope.name, v.key)
            here = on_line.get((_file_key(v.origin.path), v.origin.line or 0), []) \
                if v.origin.source != CATALOGUE else []
            row = ValueRow(scope.name, v.key, v.param_id, v.value, v.origin.source,
                           link(v.origin.path, v.origin.line, base), differs, _engineering(spec, now, ax),
                           spec.default_display if spec is not None else None,
                           _engineering(spec, dflt, ax),
                           findings=[(d["anchor"], d["code"], d["severity"]) for d in here])
            for d in here:
                if d.get("param_id") == v.param_id or "value" not in d:
                    d["value"] = row.anchor  # the finding links its parameter's row (else the line's first)
                used = d.get("corrects", {}).get(v.param_id) if v.param_id else None
                if used == ZEROED:
                    used = "0 (an invalid number format is set to 0)"
                elif used == LIMITED:
                    used = _limited(spec, now, registry)
                if used is not None and row.used is None:
                    row.used, row.used_by = used, d["anchor"]
            rows.append(row)
    _resolve_references(rows)
    first: dict[tuple[str, str], ValueRow] = {}
    for row in rows:  # a default list's line that differs: printed once, not under every axis that takes it
        if row.origin == DEFAULT_LIST and row.where is not None and row.used is None and not row.findings:
            hit = first.setdefault((row.where.text, row.key), row)
            if hit is not row:
                hit.also.append(row.scope)
                row.repeated = True
    return rows


def _resolve_references(rows: list[ValueRow]) -> None:
    """A correction "to the value of P-AXIS-00268" as that value, where the same list holds it."""
    by_id = {(r.scope, r.param_id): r for r in rows if r.param_id}
    for r in rows:
        if r.used is not None and r.used.startswith("the value of "):
            other = by_id.get((r.scope, r.used.removeprefix("the value of ")))
            if other is not None and other.value is not None:
                r.used = f"{other.value} (the value of {other.key})"


_CORRECTIONS = {err.code: err.correction.strip() for err in CHECKS}


ZEROED, LIMITED = "@zeroed", "@limited"  # R004, R005 on an axis list: resolved with the row's value


def corrects(code: str, param_id: str | None, registry: Registry, kind: str | None = None) -> dict[str, str]:
    """What the documented correction of a finding sets: parameter → the value the controller then
    uses (the default, a number, or "the value of P-…"). A K rule's start-up error as its row of
    ``catalog/data/startup_errors.toml`` says; on an axis list, a value of an invalid number format
    (R004) is set to 0 and one outside its range (R005) limited to the permissible minimum or
    maximum (P-ERR-1001138, ``catalog/data/evidence.toml``). Empty where the documentation says
    nothing, the kernel aborts or only warns."""
    if kind == "AXIS" and param_id and code in ("R004", "R005"):
        return {param_id: ZEROED if code == "R004" else LIMITED}
    c = _CORRECTIONS.get(code, "")
    if c == "default" and param_id:
        spec = registry.get(param_id)
        return {param_id: f"{spec.default_display} (the default)"} if spec is not None else {}
    target, eq, value = c.partition("=")
    if not eq or not target.strip().startswith("P-"):
        return {}
    value = value.strip()
    return {target.strip(): f"the value of {value}" if value.startswith("P-") else value}


def _limited(spec: ParamSpec | None, now: tuple[str, Any] | None, registry: Registry) -> str | None:
    """The permissible minimum or maximum a value outside its range is limited to, where the range
    is plain numbers with inclusive bounds (else None: the page claims no value)."""
    rng = registry.range_of(spec) if spec is not None else None
    if rng is None or rng.refs or now is None or now[0] != "num":
        return None
    try:
        bounds = rng.evaluate(lambda *_: None)
    except (ArithmeticError, ValueError):  # a bound that cannot be evaluated: no claim
        return None
    if bounds.high is not None and now[1] > bounds.high and not bounds.high_strict:
        return f"{format_number(bounds.high)} (the permissible maximum)"
    if bounds.low is not None and now[1] < bounds.low and not bounds.low_strict:
        return f"{format_number(bounds.low)} (the permissible minimum)"
    return None


def _structure(machine: Machine, base: Path) -> tuple[list[dict[str, Any]], list[dict[str, Any]], list[dict[str, Any]]]:
    doc = machine.startup.values.doc
    items: dict[str, dict[str, str]] = {}
    if any(n.path is not None and "#" in str(n.path) for n in machine.named):
        from zero.machine.tsproj import twincat_items  # start-up: only for a machine read from TwinCAT

        items = twincat_items(machine)
    named = [{"key": n.key, "raw": n.raw, "status": n.status, "reason": n.reason,
              "where": link(machine.startup.path, doc.file_line(n.line), base),
              "file": link(n.path, None, base) if n.path is not None else None,
              "twincat": _twincat_label(items.get(n.key))} for n in machine.named]
    axes = machine.axes()
    channels = []
    for ch in machine.channels:
        lists = [(key, lf) for key, lf in (("sda_mds", ch.lists), ("nullp_data", ch.zero), ("werkz_data", ch.tools),
                                           *ch.others.items()) if lf is not None]
        rows = []
        for ca in ch.axes:
            ax = axes.get(ca.log_nr)
            kind = "—" if ax is None else ("spindle" if ax.list.number(AXIS_TYPE) == 4 else
                                           "rotary" if ax.rotary else "linear")
            rows.append({"index": ca.index, "name": ca.name, "log_nr": ca.log_nr, "kind": kind,
                         "set_at": link(ca.source, doc_line(ca.source, ca.entry.line if ca.entry else None, machine),
                                        base),
                         "axis_list": link(ax.list.path, None, base) if ax is not None else None})
        spindles = []
        if ch.lists is not None:
            for ix in sorted(ch.lists.values.ids_of(SPINDLE_AXIS)):
                nr = ch.lists.number(SPINDLE_AXIS, ix)
                if nr is None:
                    continue
                ax = axes.get(int(nr))
                spindles.append({"index": ix[0] if ix else 0, "log_nr": int(nr),
                                 "name": ch.lists.text("P-CHAN-00007", ix) or (ax.name if ax else ""),
                                 "axis_list": link(ax.list.path, None, base) if ax is not None else None})
        channels.append({"index": ch.index, "lists": [(key, link(lf.path, None, base)) for key, lf in lists],
                         "axes": rows, "spindles": spindles})
    axis_lists = []
    for nr, ax in sorted(axes.items()):
        axis_lists.append({"nr": nr, "name": ax.name, "unit": ax.unit, "file": link(ax.list.path, None, base),
                           "default": link(ax.list.values.base.doc.path, None, base)
                           if ax.list.values.base is not None else None})
    return named, channels, axis_lists


def _twincat_label(item: dict[str, str] | None) -> str:
    """What TwinCAT says of a list's item, as the structure table shows it: the item's name and, for
    an axis, ``DriveType``, ``Spindle`` and ``FeedAxis`` as written (shown, never compared with the
    lists: the vendor does not document how they relate to ``kenngr.antr_typ``)."""
    if not item:
        return ""
    props = [f"{k} {v}" for k, v in item.items() if k not in ("item", "element")]
    return " · ".join([item.get("item", ""), *props]).strip(" ·")


def doc_line(path: Path | None, line: int | None, machine: Machine) -> int | None:
    """The line in the file of an entry's line in its document (a list inside an export)."""
    if path is None or line is None:
        return line
    for lf in machine.lists:
        if str(lf.path) == str(path):
            return lf.values.doc.file_line(line)
    return line


def _axis_settings(lf: ListFile, base: Path) -> list[tuple[str, str | None, str, Link | None]]:
    scope: Scope = scope_values("", lf, keys=[SWE_NEG, SWE_POS, SWE_TOL, REF_POINT, SWE_CHECK, SWE_BEHAVIOUR])
    return [(v.key, v.value, v.origin.source, link(v.origin.path, v.origin.line, base)) for v in scope.values]


def _findings(machine: Machine, results: list[LintResult], base: Path, registry: Registry) -> list[FindingGroup]:
    """Every finding, by code (a class of one rule), each with its anchor, its list's name and, for a
    K rule with a documented correction, what the controller then uses."""
    scope_of = {str(lf.path): name for name, lf in machine.scopes()}
    for lf in machine.defaults.values():
        scope_of.setdefault(str(lf.path), f"default list ({lf.key})")
    kind_of = {str(lf.path): lf.values.kind for lf in [*machine.lists, *machine.defaults.values()]}
    groups: dict[tuple[str, str], FindingGroup] = {}
    n = 0
    for r in results:
        for d in r.diagnostics:
            n += 1
            rule = RULES.get(d.code)
            group = groups.get((d.code, d.severity.label))
            if group is None:
                group = groups[(d.code, d.severity.label)] = FindingGroup(
                    d.code, d.severity.label, rule.name if rule else "", rule.summary if rule else "")
            group.results.append({"anchor": f"finding-{n}", "code": d.code, "severity": d.severity.label,
                                  "line": d.span.line, "column": d.span.column, "message": d.message,
                                  "path": d.path, "scope": scope_of.get(r.path, r.path),
                                  "where": link(d.path, d.span.line, base), "hint": d.hint,
                                  "param_id": d.param_id, "kernel_error": d.kernel_error,
                                  "corrects": corrects(d.code, d.param_id, registry, kind_of.get(r.path))})
    return list(groups.values())


def check_values(values: str) -> None:
    """``--values``: one of :data:`VALUES` (said before anything is read)."""
    if values not in VALUES:
        raise ZeroError(f"--values {values}: one of {', '.join(VALUES)}")


def build_report(facts: ReportFacts, output: Path | None = None, values: str = "changed") -> MachineReport:
    """The page of what ``zero report`` found (:func:`zero.engine.report.report_facts`); links
    relative to the folder ``output`` is written to (the current folder for standard output).
    ``values``: "changed" (the printed page holds the values that differ from their defaults, are
    corrected or have a finding; the page opens with that filter) or "all". Nothing is read or
    checked here: the page only lays out the facts."""
    check_values(values)
    machine, registry, results = facts.machine, facts.registry, facts.results
    base = Path(os.path.abspath(output)).parent if output is not None else Path.cwd()
    compared: Against | None = None
    old: Machine | None = None
    if facts.against is not None:
        old = facts.against.machine
        compared = Against(facts.against.given, facts.against.label, facts.against.changes)
    views = []
    travels = facts.travels
    for pic in axis_pictures(machine, pcs_limits(machine), old):
        for name, channel, travel in travels:
            span = travel.get(pic.index) if pic.channel == channel and pic.index is not None else None
            if span is not None:
                pic.travel.append((name, span[0], span[1]))
        ax = machine.axes().get(pic.log_nr)
        settings = _axis_settings(ax.list, base) if ax is not None else []
        view = AxisView(pic, axis_svg(pic), settings)
        if pic.monitoring_said:
            key = pic.monitoring_why.partition(" = ")[0]
            view.monitor_where = next((where for k, _, _, where in settings if k == key), None)
            if view.monitor_where is None and pic.channel is not None:
                ch = next((c for c in machine.channels if c.index == pic.channel), None)
                if ch is not None and ch.lists is not None:
                    e = ch.lists.entry("P-CHAN-00147")
                    view.monitor_where = link(ch.lists.path, ch.lists.values.doc.file_line(e.line) if e else None, base)
        views.append(view)
    named, channels, axis_lists = _structure(machine, base)
    findings = _findings(machine, results, base, registry)
    codes = sorted({d["code"] for g in findings for d in g.results})
    template = rule_docs_template()
    rules = [{"code": c, "name": RULES[c].name, "severity": RULES[c].severity.label, "summary": RULES[c].summary,
              "explanation": RULES[c].explanation.strip(),
              "url": template.format(code=c) if template else ""} for c in codes if c in RULES]
    rows = _values(machine, base, findings)
    if compared is not None:
        known = _rotary_by_scope(machine)
        compared.deltas = [delta_in_engineering(c, _rotary(known, c.group.partition(": ")[0], c.key))
                           for c in compared.changes]
    shown = machine.startup.path
    counts = {"lists": len(machine.lists), "named": len(machine.named), "channels": len(machine.channels),
              "axes": len(machine.axes()), "findings": sum(len(g.results) for g in findings),
              "values": len(rows), "changes": len(compared.changes) if compared else 0,
              "differ": sum(1 for v in rows if v.differs), "printed": sum(1 for v in rows if v.printed),
              "corrected": sum(1 for v in rows if v.used is not None),
              "unmonitored": sum(1 for v in views if v.picture.monitoring_said),
              **{s: sum(1 for g in findings for d in g.results if d["severity"] == s)
                 for s in ("error", "warning", "info")}}
    drift = None
    if facts.drift is not None:
        from zero.output.fleet import fleet_json, short_names  # start-up: only a report with --fleet

        drift = fleet_json(facts.drift)
        names = short_names(drift["machines"])
        for p in drift["parameters"]:
            for v in p["values"]:
                v["shown"] = [names.get(m, m) for m in v["machines"]]
        counts["drifting"] = drift["summary"]["drifting"]
    return MachineReport(f"Machine {shown}", link(shown, None, base) or Link(str(shown), None), str(machine.workdir),
                         _generated(), named, channels, axis_lists,
                         views, [name for name, _ in machine.scopes()], rows, findings, rules, template,
                         compared, counts, drift, values)


def _generated() -> str:
    """When the report was made (``SOURCE_DATE_EPOCH`` where set: a reproducible page)."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    when = datetime.fromtimestamp(int(epoch), UTC) if epoch.isdigit() else datetime.now(UTC)
    return when.strftime("%Y-%m-%d %H:%M UTC")


def render_report(report: MachineReport) -> str:
    """The report as one HTML page (Jinja2, autoescaped); :class:`ZeroError` without Jinja2."""
    try:
        import jinja2  # start-up: Jinja2 (the report extra) only for a report
        from markupsafe import Markup  # start-up: Jinja2's own dependency, as above
    except ImportError:
        raise ZeroError("zero report needs Jinja2: pip install 'zero-lint[report]'") from None
    env = jinja2.Environment(autoescape=True, undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True)
    text = resources.files("zero.output").joinpath("templates/report.html.j2").read_text(encoding="utf-8")
    def ticks(text: str) -> Any:
        """A rule's text with its `code` spans as <code> (escaped first)."""
        parts = str(Markup.escape(text)).split("`")
        return Markup("".join(f"<code>{p}</code>" if i % 2 else p for i, p in enumerate(parts)))

    env.filters["ticks"] = ticks
    env.filters["number"] = lambda n: f"{n:,}"
    return env.from_string(text).render(r=report, version=__version__, origins=ORIGINS, svg=Markup, noise=NOISE,
                                        svg_style=Markup(STYLE))


__all__ = ["MachineReport", "build_report", "check_values", "render_report"]

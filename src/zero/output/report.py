"""``zero report``: one self-contained HTML page about a machine.

The page holds the machine's structure (channels, their axes and spindles, which list sets what),
a picture of every axis's travel range (:mod:`zero.output.svg`), the effective values with their
origin (searchable, filterable by list, by origin and by "differs from the default"), every
finding of ``zero lint --machine`` grouped by list with its rule's text, and, against a golden
machine or a git revision, the differences of ``zero diff --machine`` with the changed soft limits
drawn over the old ones.

Everything comes from the one resolver (:class:`zero.engine.project.Project`): the machine, its
lint results and the machine compared against (a revision's lists are read from git through the
resolver's reader). The page is rendered with Jinja2 (the ``report`` extra), autoescaped; it loads
nothing (no script, font, style or image from anywhere): CSS and a small script are inline.
"""

from __future__ import annotations

import os
import urllib.request
from collections.abc import Callable, Sequence
from datetime import UTC, datetime
from importlib import resources
from pathlib import Path
from typing import Any

from zero import __version__
from zero.catalog.ids import AXIS_TYPE, SPINDLE_AXIS, SWE_NEG, SWE_POS, SWE_TOL
from zero.catalog.registry import Registry
from zero.diff import Change, default_effective
from zero.diff import effective as value_of
from zero.engine.git import revision_reader
from zero.engine.lint import LintResult, lint_machine
from zero.engine.project import Project
from zero.engine.queries import machine_changes
from zero.errors import ZeroError
from zero.forms import split_part
from zero.machine.effective import CATALOGUE, DEFAULT_LIST, LIST, Scope, effective, entries_of, scope_values
from zero.machine.limits import pcs_limits
from zero.machine.model import ListFile, Machine
from zero.output.formats import rule_docs_template
from zero.output.svg import REF_POINT, STYLE, AxisPicture, axis_pictures, axis_svg
from zero.records import field, record
from zero.rules import RULES

Reader = Callable[[Path], bytes]
ORIGINS = (LIST, DEFAULT_LIST, CATALOGUE)  # the layers a value comes from, named as zero show --machine does


@record
class Link:
    """A place in a file: the text shown (``path:line``) and a relative link to the file."""

    text: str
    href: str | None


@record
class ValueRow:
    scope: str
    key: str
    param_id: str | None
    value: str | None
    origin: str  # list, default list, catalogue default
    where: Link | None
    differs: bool  # from the catalogue default


@record
class AxisView:
    picture: AxisPicture
    svg: str
    settings: list[tuple[str, str | None, str, Link | None]] = field(default_factory=list)  # key, value, origin, where


@record
class FindingGroup:
    scope: str
    path: str
    link: Link
    results: list[dict[str, Any]] = field(default_factory=list)


@record
class Against:
    """The machine compared against: what was given, the changes, and which axes' soft limits changed."""

    given: str
    label: str  # "start-up list golden/hochlauf.lis" or "git revision HEAD~1 (1a2b3c4)"
    changes: list[Change] = field(default_factory=list)


@record
class MachineReport:
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


# ------------------------------------------------------------------------- the machine compared


def git_reader(startup: Path, revision: str) -> tuple[str, Reader]:
    """A reader of the files of ``revision`` in the git work tree ``startup`` lies in, through the one
    module that runs git (:func:`zero.engine.git.revision_reader`: nothing the repository configures
    runs, nothing is fetched). The commit's short name, and the reader."""
    return revision_reader(startup, revision)


def machine_against(project: Project, against: str) -> tuple[Machine, str, Registry]:
    """The machine ``--against`` names: a start-up list (with its own configuration's list overrides),
    else the current machine's lists at a git revision (read through the resolver's reader)."""
    if os.path.isfile(split_part(against)[0]):
        golden = project.machine(Path(against), startup=against, required=True)
        assert golden is not None
        return golden, f"start-up list {against}", project.registry(Path(against))
    start = project.startup()
    if start is None:
        raise ZeroError("name the start-up list with --machine (or [tool.zero.machine] startup)")
    short, reader = git_reader(start, against)
    shown = project.machine_shown if project.machine_given is not None else start
    old = project.machine(startup=shown, reader=reader, reader_key=("git", short), required=True)
    assert old is not None
    return old, f"git revision {against} ({short})", project.registry(start)


# ---------------------------------------------------------------------------- the report


def _values(machine: Machine, base: Path) -> list[ValueRow]:
    rows: list[ValueRow] = []
    for scope in effective(machine, with_defaults=True):
        entries = entries_of(scope.file.values)
        registry = scope.file.values.registry
        for v in scope.values:
            spec = registry.get(v.param_id) if v.param_id else None
            entry = entries.get(v.key)
            differs = False
            if v.origin.source != CATALOGUE and entry is not None:
                differs = value_of(entry, spec) != default_effective(spec)
            rows.append(ValueRow(scope.name, v.key, v.param_id, v.value, v.origin.source,
                                 link(v.origin.path, v.origin.line, base), differs))
    return rows


def _structure(machine: Machine, base: Path) -> tuple[list[dict[str, Any]], list[dict[str, Any]], list[dict[str, Any]]]:
    doc = machine.startup.values.doc
    named = [{"key": n.key, "raw": n.raw, "status": n.status, "reason": n.reason,
              "where": link(machine.startup.path, doc.file_line(n.line), base),
              "file": link(n.path, None, base) if n.path is not None else None} for n in machine.named]
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


def doc_line(path: Path | None, line: int | None, machine: Machine) -> int | None:
    """The line in the file of an entry's line in its document (a list inside an export)."""
    if path is None or line is None:
        return line
    for lf in machine.lists:
        if str(lf.path) == str(path):
            return lf.values.doc.file_line(line)
    return line


def _axis_settings(lf: ListFile, base: Path) -> list[tuple[str, str | None, str, Link | None]]:
    scope: Scope = scope_values("", lf, keys=[SWE_NEG, SWE_POS, SWE_TOL, REF_POINT])
    return [(v.key, v.value, v.origin.source, link(v.origin.path, v.origin.line, base)) for v in scope.values]


def _findings(machine: Machine, results: list[LintResult], base: Path) -> list[FindingGroup]:
    scope_of = {str(lf.path): name for name, lf in machine.scopes()}
    for lf in machine.defaults.values():
        scope_of.setdefault(str(lf.path), f"default list ({lf.key})")
    groups = []
    for r in results:
        if not r.diagnostics:
            continue
        group = FindingGroup(scope_of.get(r.path, r.path), r.path, link(r.path, None, base) or Link(r.path, None))
        for d in r.diagnostics:
            group.results.append({"code": d.code, "severity": d.severity.label, "line": d.span.line,
                                  "column": d.span.column, "message": d.message, "path": d.path,
                                  "where": link(d.path, d.span.line, base), "hint": d.hint})
        groups.append(group)
    return groups


def build_report(project: Project, output: Path | None = None, against: str | None = None,
                 fleet: Sequence[str] = (), jobs: int | None = None) -> MachineReport:
    """Everything ``zero report`` shows about the machine of ``project`` (``--machine``, else the
    configuration's); links relative to the folder ``output`` is written to (the current folder
    for standard output). ``fleet``: machines (start-up lists or folders) whose drift from this
    machine, as ``zero diff --fleet`` reports it, is a section of the page."""
    machine = project.machine(required=True)
    assert machine is not None
    start = project.startup()
    assert start is not None
    base = Path(os.path.abspath(output)).parent if output is not None else Path.cwd()
    registry = project.registry(start)
    results = lint_machine(machine, registry, project.options)
    compared: Against | None = None
    old: Machine | None = None
    if against is not None:
        old, label, diff_registry = machine_against(project, against)
        compared = Against(against, label, machine_changes(old, machine, diff_registry))
    views = []
    for pic in axis_pictures(machine, pcs_limits(machine), old):
        ax = machine.axes().get(pic.log_nr)
        views.append(AxisView(pic, axis_svg(pic), _axis_settings(ax.list, base) if ax is not None else []))
    named, channels, axis_lists = _structure(machine, base)
    findings = _findings(machine, results, base)
    codes = sorted({d["code"] for g in findings for d in g.results})
    template = rule_docs_template()
    rules = [{"code": c, "name": RULES[c].name, "severity": RULES[c].severity.label, "summary": RULES[c].summary,
              "explanation": RULES[c].explanation.strip(),
              "url": template.format(code=c) if template else ""} for c in codes if c in RULES]
    values = _values(machine, base)
    shown = machine.startup.path
    counts = {"lists": len(machine.lists), "named": len(machine.named), "channels": len(machine.channels),
              "axes": len(machine.axes()), "findings": sum(len(g.results) for g in findings),
              "values": len(values), "changes": len(compared.changes) if compared else 0,
              **{s: sum(1 for g in findings for d in g.results if d["severity"] == s)
                 for s in ("error", "warning", "info")}}
    drift = None
    if fleet:
        from zero.engine.fleet import fleet_drift  # start-up: only a report with --fleet
        from zero.output.fleet import fleet_json, short_names  # start-up: as above

        drift = fleet_json(fleet_drift(start, list(fleet), project, jobs=jobs))
        names = short_names(drift["machines"])
        for p in drift["parameters"]:
            for v in p["values"]:
                v["shown"] = [names.get(m, m) for m in v["machines"]]
        counts["drifting"] = drift["summary"]["drifting"]
    return MachineReport(f"Machine {shown}", link(shown, None, base) or Link(str(shown), None), str(machine.workdir),
                         _generated(), named, channels, axis_lists,
                         views, [name for name, _ in machine.scopes()], values, findings, rules, template,
                         compared, counts, drift)


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
    return env.from_string(text).render(r=report, version=__version__, origins=ORIGINS, svg=Markup,
                                                    svg_style=Markup(STYLE))


__all__ = ["MachineReport", "build_report", "git_reader", "machine_against", "render_report"]

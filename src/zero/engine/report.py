"""``zero report``: everything the page shows about a machine, found by the engine.

The machine and its findings (as ``zero lint --machine`` finds them, with the configuration of
each list), the machine compared against (a golden start-up list, or this machine's lists at a
git revision read through the one module that runs git), where NC programs take each axis, and a
fleet's drift from this machine. :mod:`zero.output.report` only lays these out as a page.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from zero.catalog.registry import Registry
from zero.diff import Change
from zero.engine.git import revision_reader
from zero.engine.lint import LintResult, lint_machine
from zero.engine.project import Project
from zero.engine.queries import machine_changes, machine_of, program_travel_of
from zero.errors import ZeroError
from zero.forms import split_part
from zero.machine.model import Machine
from zero.records import Record, field

if TYPE_CHECKING:  # start-up: the fleet only for a report with --fleet
    from zero.engine.fleet import FleetDrift

Reader = Callable[[Path], bytes]
Travel = tuple[str, int, dict[int, tuple[float, float]]]  # program, line past a soft limit (-1: none), axis spans


class Compared(Record):
    """The machine ``--against`` names, and how this machine differs from it."""

    given: str
    label: str  # "start-up list golden/hochlauf.lis" or "git revision HEAD~1 (1a2b3c4)"
    machine: Machine
    changes: list[Change] = field(default_factory=list)


class ReportFacts(Record):
    """What ``zero report`` found: the page is laid out from it and from nothing else."""

    machine: Machine
    startup: Path  # absolute
    registry: Registry
    results: list[LintResult]
    against: Compared | None = None
    travels: list[Travel] = field(default_factory=list)
    drift: FleetDrift | None = None


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
        return golden, f"start-up list {against}", project.settings(Path(against)).registry
    start = project.startup()
    if start is None:
        raise ZeroError("name the start-up list with --machine (or [tool.zero.machine] startup)")
    short, reader = git_reader(start, against)
    old = project.machine(startup=project.shown(start), reader=reader, reader_key=("git", short), required=True)
    assert old is not None
    return old, f"git revision {against} ({short})", project.settings(start).registry


def report_facts(project: Project, against: str | None = None, fleet: Sequence[str] = (), jobs: int | None = None,
                 programs: Sequence[str] = ()) -> ReportFacts:
    """Everything ``zero report`` shows about the machine of ``project`` (``--machine``, else the
    configuration's): its findings with each list's own configuration (``--config``, per-file
    ignores, severities: as ``zero lint --machine``), the machine ``against`` names and the changes
    from it, the travel of each NC program of ``programs``, and the drift of ``fleet`` (start-up
    lists or folders of machines, as ``zero diff --fleet``) from this machine."""
    machine = machine_of(project)
    start = project.startup()
    assert start is not None
    registry = project.settings(start).registry
    facts = ReportFacts(machine, start, registry, lint_machine(machine, registry, project.options))
    if against is not None:
        old, label, diff_registry = machine_against(project, against)
        facts.against = Compared(against, label, old, machine_changes(old, machine, diff_registry))
    facts.travels = [program_travel_of(Path(p), machine, registry) for p in programs]
    if fleet:
        from zero.engine.fleet import fleet_drift  # start-up: only a report with --fleet

        facts.drift = fleet_drift(start, list(fleet), project, jobs=jobs)
    return facts


__all__ = ["Compared", "ReportFacts", "git_reader", "machine_against", "report_facts"]

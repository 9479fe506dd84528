"""The report of ``zero diff --fleet``: text, JSON and CSV.

**Text**: one block per differing parameter (its list, key and ID, "differs on K of N machines",
the golden value, then each value with its delta and the machines that have it), one block per
list missing (or extra) on some machines, one line per machine that could not be read, and a
summary line. Machines are shown by the part of their start-up list's path that tells them apart
(``m017`` for ``fleet/m017/listen/hochlauf.lis``; the header gives the whole pattern).

**JSON** (a stable shape; keys are only ever added)::

    {"golden": "gold/listen/hochlauf.lis",
     "machines": ["fleet/m000/listen/hochlauf.lis", ...],     # every machine compared, in order
     "summary": {"machines": 300,              # those read: the N of every "K of N"
                 "drifting": 2,                # machines that differ in a parameter or a list
                 "parameters": 1, "lists_missing": 0, "lists_extra": 0, "unreadable": 0},
     "parameters": [{"scope": "axis 1 (achs_mds[0])", "key": "kenngr.vb_max", "id": "P-AXIS-00212",
                     "group": "kenngr", "unit": "mm or °",
                     "golden": {"value": "500000", "note": null, "name": null},
                     "count": 2, "of": 300,
                     "values": [{"value": "600000", "note": null, "name": null, "delta": 10.0,
                                 "count": 1, "machines": ["fleet/m017/listen/hochlauf.lis"]}, ...]}],
     "lists": [{"scope": "axis 2 (achs_mds[1])", "status": "missing",
                "reason": "achs_mds[1] (./listen/achse_y.lis) does not exist",
                "count": 1, "machines": [...]}],
     "unreadable": [{"machine": "...", "error": "..."}]}

``value`` is the value as the list writes it, ``null`` where the list does not set it; ``note`` then
says what it is (``the default 1000``). ``name`` is the value's meaning where the catalogue names
it (``on``, ``SERCOS``, ``VEL | ACC``); ``delta`` the value minus the golden one for a quantity.

**CSV**: a header, then one row per parameter and machine that differs
(``list,key,id,golden,machine,value,delta,note``), then one row per list and machine (``key``
empty, ``note`` ``list missing: …``/``list extra: …``), then one row per machine that could not be
read (``note`` ``could not be read: …``). ``golden``/``value`` are empty where the list does not
set the parameter; ``note`` says what the value then is.
"""

from __future__ import annotations

import csv
import json
from collections.abc import Callable, Sequence
from pathlib import PurePath

from zero.engine.fleet import EXTRA, MISSING, FleetDrift, FleetValue, ParamDrift
from zero.errors import ZeroError

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # typing for type checkers only (start-up of zero diff --fleet)
    from typing import Any, TextIO

FLEET_FORMATS = ("text", "json", "csv")


def _plural(n: int, word: str, many: str | None = None) -> str:
    return f"{n} {word if n == 1 else many or word + 's'}"


def short_names(machines: Sequence[str]) -> dict[str, str]:
    """Each machine by the part of its path that tells it apart from the others (the folders and
    file name all of them share, before and after, left out); the whole path for one machine."""
    parts = [PurePath(m).parts for m in machines]
    if len(parts) < 2:
        return {m: m for m in machines}
    shortest = min(len(p) for p in parts)
    head = 0
    while head < shortest - 1 and len({p[head] for p in parts}) == 1:
        head += 1
    tail = 0
    while tail < shortest - head - 1 and len({p[-1 - tail] for p in parts}) == 1:
        tail += 1
    out = {m: str(PurePath(*p[head:len(p) - tail])) for m, p in zip(machines, parts, strict=True)}
    return out if len(set(out.values())) == len(out) else {m: m for m in machines}


def _pattern(machines: Sequence[str]) -> str | None:
    """The paths the short names stand in: ``fleet/*/listen/hochlauf.lis``."""
    parts = [PurePath(m).parts for m in machines]
    if len(parts) < 2:
        return None
    names = short_names(machines)
    first = machines[0]
    if names[first] == first:
        return None
    p, short = parts[0], PurePath(names[first]).parts
    head = next(i for i in range(len(p)) if p[i:i + len(short)] == short)
    return str(PurePath(*p[:head], "*", *p[head + len(short):]))


def _delta(d: float | int | None, unit: str | None) -> str:
    if d is None:
        return ""
    text = f"{d:+.4f}" if isinstance(d, float) or (unit or "").startswith(("mm", "°")) else f"{d:+d}"
    return f"{text} {unit}" if unit else text


def _shown(value: str | None, note: str, name: str | None) -> str:
    text = value if value is not None else f"not set ({note})" if note else "not set"
    return f"{text} ({name})" if name and name != value else text


def _machines(ms: Sequence[str], names: dict[str, str]) -> str:
    return f"{_plural(len(ms), 'machine')}: {', '.join(names[m] for m in ms)}"


def summary_line(drift: FleetDrift) -> str:
    n = drift.compared
    parts = [f"{_plural(len(drift.params), 'parameter')} "
             f"differ{'s' if len(drift.params) == 1 else ''} from the golden machine on "
             f"{len({m for p in drift.params for m in p.machines})} of {n} machines"]
    missing = [ld for ld in drift.lists if ld.status == MISSING]
    extra = [ld for ld in drift.lists if ld.status == EXTRA]
    if missing:
        parts.append(f"{_plural(len(missing), 'list')} missing on {len({m for x in missing for m in x.machines})}")
    if extra:
        parts.append(f"{_plural(len(extra), 'list')} only on {len({m for x in extra for m in x.machines})}")
    if drift.unreadable:
        parts.append(f"{_plural(len(drift.unreadable), 'machine')} could not be read")
    return "; ".join(parts) + f" ({_plural(len(drift.drifting), 'machine')} drift)"


def render_fleet_text(drift: FleetDrift, stream: TextIO) -> None:
    names = short_names(drift.machines)
    w = stream.write
    pattern = _pattern(drift.machines)
    w(f"golden machine: {drift.golden}; {_plural(len(drift.machines), 'machine')} compared"
      + (f" ({pattern})" if pattern else "") + "\n")
    for p in drift.params:
        w(f"\n{p.scope}: {p.key}" + (f" ({p.param_id})" if p.param_id else "")
          + f" differs on {p.count} of {drift.compared} machines\n")
        w(f"  golden {_shown(p.golden, p.golden_note, p.golden_name)}\n")
        rows = [(_shown(v.value, v.note, v.name), _delta(v.delta, p.unit), _machines(v.machines, names))
                for v in p.values]
        first = max(len(r[0]) for r in rows)
        second = max(len(r[1]) for r in rows)
        for value, delta, machines in rows:
            w(f"    {value:<{first}}  {delta:<{second}}  → {machines}\n" if second
              else f"    {value:<{first}}  → {machines}\n")
    for ld in drift.lists:
        where = "missing on" if ld.status == MISSING else "only on"
        w(f"\n{ld.scope}: list {where} {ld.count} of {drift.compared} machines: "
          f"{', '.join(names[m] for m in ld.machines)}\n  {ld.reason}\n")
    if drift.unreadable:
        w("\n")
    for u in drift.unreadable:
        w(f"{names[u.machine]}: could not be read: {u.error}\n")
    w("\n" + summary_line(drift) + "\n")


def _value_json(v: FleetValue) -> dict[str, Any]:
    return {"value": v.value, "note": v.note or None, "name": v.name, "delta": v.delta, "count": v.count,
            "machines": list(v.machines)}


def _param_json(p: ParamDrift, of: int) -> dict[str, Any]:
    return {"scope": p.scope, "key": p.key, "id": p.param_id, "group": p.group, "unit": p.unit,
            "golden": {"value": p.golden, "note": p.golden_note or None, "name": p.golden_name},
            "count": p.count, "of": of, "values": [_value_json(v) for v in p.values]}


def fleet_json(drift: FleetDrift) -> dict[str, Any]:
    """The JSON report (the shape in this module's documentation)."""
    return {
        "golden": drift.golden,
        "machines": list(drift.machines),
        "summary": {"machines": drift.compared, "drifting": len(drift.drifting), "parameters": len(drift.params),
                    "lists_missing": sum(1 for ld in drift.lists if ld.status == MISSING),
                    "lists_extra": sum(1 for ld in drift.lists if ld.status == EXTRA),
                    "unreadable": len(drift.unreadable)},
        "parameters": [_param_json(p, drift.compared) for p in drift.params],
        "lists": [{"scope": ld.scope, "status": ld.status, "reason": ld.reason, "count": ld.count,
                   "machines": list(ld.machines)} for ld in drift.lists],
        "unreadable": [{"machine": u.machine, "error": u.error} for u in drift.unreadable],
    }


def render_fleet_json(drift: FleetDrift, stream: TextIO) -> None:
    stream.write(json.dumps(fleet_json(drift), indent=2, ensure_ascii=False) + "\n")


CSV_COLUMNS = ("list", "key", "id", "golden", "machine", "value", "delta", "note")


def fleet_rows(drift: FleetDrift) -> list[tuple[str, ...]]:
    """The CSV rows (without the header): a parameter and a machine, a list and a machine, an unread machine."""
    rows: list[tuple[str, ...]] = []
    for p in drift.params:
        golden_note = f"not set on the golden machine: {p.golden_note}" if p.golden is None else ""
        for v in p.values:
            note = "; ".join(x for x in (golden_note, f"not set: {v.note}" if v.value is None else "") if x)
            delta = "" if v.delta is None else str(v.delta)
            rows.extend((p.scope, p.key, p.param_id or "", p.golden or "", m, v.value or "", delta, note)
                        for m in v.machines)
    for ld in drift.lists:
        rows.extend((ld.scope, "", "", "", m, "", "", f"list {ld.status}: {ld.reason}") for m in ld.machines)
    rows.extend(("", "", "", "", u.machine, "", "", f"could not be read: {u.error}") for u in drift.unreadable)
    return rows


def render_fleet_csv(drift: FleetDrift, stream: TextIO) -> None:
    writer = csv.writer(stream, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    writer.writerows(fleet_rows(drift))


RENDERERS: dict[str, Callable[[FleetDrift, TextIO], None]] = {
    "text": render_fleet_text, "json": render_fleet_json, "csv": render_fleet_csv}


def render_fleet(drift: FleetDrift, output_format: str, stream: TextIO) -> None:
    RENDERERS[output_format](drift, stream)


def check_fleet_format(output_format: str) -> None:
    """An output format of ``zero diff --fleet`` (said before anything is read)."""
    if output_format not in RENDERERS:
        raise ZeroError(f"unknown output format {output_format!r} for --fleet (use one of: {', '.join(RENDERERS)})")


__all__ = ["CSV_COLUMNS", "FLEET_FORMATS", "check_fleet_format", "fleet_json", "fleet_rows", "render_fleet",
           "render_fleet_csv", "render_fleet_json", "render_fleet_text", "short_names", "summary_line"]

"""Fleet drift (``zero diff --fleet``): a fleet of fixture machines, one value changed on two of them."""

from __future__ import annotations

import csv
import io
import json
import shutil
from pathlib import Path

import pytest

from conftest import FIXTURES
from zero.catalog.registry import Registry
from zero.cli.app import run_fleet_diff
from zero.cli.exits import fleet_exit
from zero.engine.fleet import (
    EXTRA,
    MISSING,
    FleetDrift,
    FleetRequest,
    fleet_drift,
    machine_startups,
    run_fleet,
)
from zero.engine.project import Project
from zero.engine.queries import run_diff
from zero.errors import ZeroError
from zero.output.fleet import (
    CSV_COLUMNS,
    fleet_json,
    render_fleet_csv,
    render_fleet_json,
    render_fleet_text,
    short_names,
)

N = 6


def build_fleet(tmp_path: Path, fixture: str, n: int = N) -> tuple[Path, Path, list[Path]]:
    """The golden machine and ``n`` copies of it in ``fleet/mNN``; (golden start-up, fleet folder, start-ups)."""
    golden = tmp_path / "golden"
    shutil.copytree(FIXTURES / fixture, golden)
    fleet = tmp_path / "fleet"
    for i in range(n):
        shutil.copytree(FIXTURES / fixture / "listen", fleet / f"m{i:02d}" / "listen")
    return golden / "listen" / "hochlauf.lis", fleet, [fleet / f"m{i:02d}" / "listen" / "hochlauf.lis"
                                                       for i in range(n)]


def set_value(path: Path, key: str, value: str) -> None:
    """Set ``key`` to ``value`` in a list (replaced where it is, else added before ``Ende``)."""
    lines = path.read_text(encoding="latin-1").splitlines()
    for i, line in enumerate(lines):
        if line.split()[:1] == [key]:
            lines[i] = f"{key:<54}{value}"
            break
    else:
        lines.insert(lines.index("Ende"), f"{key:<54}{value}")
    path.write_text("\n".join(lines) + "\n", encoding="latin-1")


def project(registry: Registry) -> Project:
    return Project(lambda _desc: registry, isolated=True)


def drift_of(registry: Registry, golden: Path, machines: list[Path] | list[str], jobs: int | None = 1) -> FleetDrift:
    return fleet_drift(golden, [str(m) for m in machines], project(registry), jobs=jobs)


def axis(startup: Path, name: str) -> Path:
    return startup.parent / name


# ----------------------------------------------------------------------------- drift


def test_one_value_changed_on_two_machines_is_exactly_what_is_reported(tmp_path: Path, registry: Registry) -> None:
    golden, fleet, ms = build_fleet(tmp_path, "machine-clean")
    for m in (ms[1], ms[4]):
        set_value(axis(m, "achse_x.lis"), "kenngr.swe_pos", "16000000")
    drift = drift_of(registry, golden, [fleet])
    assert drift.machines == [str(m) for m in ms]
    assert drift.compared == N
    assert [(p.scope, p.key, p.param_id) for p in drift.params] == [
        ("axis 1 (achs_mds[0])", "kenngr.swe_pos", "P-AXIS-00178")]
    p = drift.params[0]
    assert (p.golden, p.count, p.unit) == ("15000000", 2, "mm")
    assert [(v.value, v.delta, v.machines) for v in p.values] == [("16000000", 100.0, [str(ms[1]), str(ms[4])])]
    assert drift.lists == [] and drift.unreadable == []
    assert drift.drifting == [str(ms[1]), str(ms[4])]
    assert fleet_exit(drift) == 1
    out = io.StringIO()
    render_fleet_text(drift, out)
    text = out.getvalue()
    assert f"axis 1 (achs_mds[0]): kenngr.swe_pos (P-AXIS-00178) differs on 2 of {N} machines" in text
    assert "golden 15000000" in text
    assert "→ 2 machines: m01, m04" in text
    assert text.rstrip().endswith(f"1 parameter differs from the golden machine on 2 of {N} machines "
                                  "(2 machines drift)")


def test_an_identical_fleet_has_no_drift(tmp_path: Path, registry: Registry) -> None:
    golden, fleet, _ = build_fleet(tmp_path, "machine-clean", 3)
    drift = drift_of(registry, golden, [fleet])
    assert (drift.params, drift.lists, drift.unreadable, fleet_exit(drift)) == ([], [], [], 0)


def test_values_are_grouped_by_effective_value_most_machines_first(tmp_path: Path, registry: Registry) -> None:
    golden, _, ms = build_fleet(tmp_path, "machine-clean")
    set_value(axis(ms[0], "achse_x.lis"), "kenngr.swe_pos", "17000000")
    set_value(axis(ms[2], "achse_x.lis"), "kenngr.swe_pos", "16000000")
    set_value(axis(ms[3], "achse_x.lis"), "kenngr.swe_pos", "0xF42400")  # 16000000 written in hex: one value
    drift = drift_of(registry, golden, ms)
    [p] = drift.params
    assert [(v.value, v.machines) for v in p.values] == [("16000000", [str(ms[2]), str(ms[3])]),
                                                         ("17000000", [str(ms[0])])]
    assert p.count == 3


def test_a_parameter_set_only_on_machines_has_the_golden_default(tmp_path: Path, registry: Registry) -> None:
    golden, _, ms = build_fleet(tmp_path, "machine-clean", 3)
    set_value(axis(ms[1], "achse_x.lis"), "kenngr.swe_toleranz", "5000")
    [p] = drift_of(registry, golden, ms).params
    assert (p.key, p.golden, p.golden_note) == ("kenngr.swe_toleranz", None, "the default 1000")
    assert [(v.value, v.machines) for v in p.values] == [("5000", [str(ms[1])])]
    removed = tmp_path / "removed"
    shutil.copytree(ms[0].parent.parent, removed)
    x = removed / "listen" / "achse_x.lis"
    x.write_text("".join(line for line in x.read_text().splitlines(keepends=True) if "swe_pos" not in line))
    [p] = drift_of(registry, golden, [removed / "listen" / "hochlauf.lis"]).params
    assert (p.key, p.golden, p.values[0].value, p.values[0].note) == (
        "kenngr.swe_pos", "15000000", None, "the default 100000000")


def test_values_layered_from_a_default_list_count_as_effective_values(tmp_path: Path, registry: Registry) -> None:
    golden, fleet, ms = build_fleet(tmp_path, "machine-layered")
    for m in (ms[1], ms[3]):  # the default axis list: under axes X and Y (Y sets only its own swe_pos)
        set_value(axis(m, "achse_vorgabe.lis"), "kenngr.swe_neg", "-1500000")
    set_value(axis(ms[3], "achse_x.lis"), "kenngr.swe_neg", "-1000000")  # X keeps the golden value on m03
    set_value(axis(ms[5], "achse_x.lis"), "kenngr.swe_neg", "-1000000")  # the golden's effective value: no drift
    drift = drift_of(registry, golden, [fleet])
    assert [(p.scope, p.key, p.golden, [(v.value, v.machines) for v in p.values]) for p in drift.params] == [
        ("axis 1 (achs_mds[0])", "kenngr.swe_neg", "-1000000", [("-1500000", [str(ms[1])])]),
        ("axis 2 (achs_mds[1])", "kenngr.swe_neg", "-1000000", [("-1500000", [str(ms[1]), str(ms[3])])]),
    ]
    assert drift.lists == []  # the lists the golden machine misses too (hand_mds, SoE/achse_c.lis) are no drift


def test_a_missing_list_is_reported_once_not_as_every_parameter(tmp_path: Path, registry: Registry) -> None:
    golden, fleet, ms = build_fleet(tmp_path, "machine-clean")
    axis(ms[2], "achse_y.lis").unlink()
    set_value(axis(ms[4], "achse_x.lis"), "kenngr.swe_pos", "16000000")
    drift = drift_of(registry, golden, [fleet])
    assert [(p.scope, p.key, p.machines) for p in drift.params] == [
        ("axis 1 (achs_mds[0])", "kenngr.swe_pos", [str(ms[4])])]
    assert [(ld.scope, ld.status, ld.reason, ld.machines) for ld in drift.lists] == [
        ("axis 2 (achs_mds[1])", MISSING, "achs_mds[1] (./listen/achse_y.lis) does not exist", [str(ms[2])])]
    assert drift.drifting == [str(ms[2]), str(ms[4])]
    out = io.StringIO()
    render_fleet_text(drift, out)
    assert f"axis 2 (achs_mds[1]): list missing on 1 of {N} machines: m02" in out.getvalue()


def test_a_missing_default_list_is_one_finding_and_the_lists_over_it_still_compare(
        tmp_path: Path, registry: Registry) -> None:
    golden, _, ms = build_fleet(tmp_path, "machine-layered", 2)
    axis(ms[0], "achse_vorgabe.lis").unlink()
    set_value(axis(ms[0], "achse_y.lis"), "kenngr.swe_pos", "2500000")
    drift = drift_of(registry, golden, ms)
    assert [(ld.scope, ld.status, ld.machines) for ld in drift.lists] == [("default_achs_mds", MISSING, [str(ms[0])])]
    assert [(p.scope, p.key, p.machines) for p in drift.params] == [
        ("axis 2 (achs_mds[1])", "kenngr.swe_pos", [str(ms[0])])]


def test_a_list_only_a_machine_loads_is_extra(tmp_path: Path, registry: Registry) -> None:
    golden, _, ms = build_fleet(tmp_path, "machine-clean", 2)
    shutil.copyfile(axis(ms[1], "achse_x.lis"), axis(ms[1], "hand.lis"))
    (axis(ms[1], "hand.lis")).write_text("# manual mode\nmove_limit_warning 1\nEnde\n")
    set_value(ms[1], "hand_mds", "./listen/hand.lis")
    drift = drift_of(registry, golden, ms)
    assert [(ld.scope, ld.status, ld.machines) for ld in drift.lists] == [("hand_mds", EXTRA, [str(ms[1])])]
    assert [(p.scope, p.key) for p in drift.params] == [("start-up", "hand_mds")]


def test_an_axis_list_with_another_axis_number_is_paired_by_its_startup_key(
        tmp_path: Path, registry: Registry) -> None:
    golden, _, ms = build_fleet(tmp_path, "machine-clean", 2)
    set_value(axis(ms[0], "achse_y.lis"), "kopf.achs_nr", "7")
    drift = drift_of(registry, golden, ms)
    assert drift.lists == []
    assert [(p.scope, p.key, p.golden, p.values[0].value) for p in drift.params] == [
        ("axis 2 (achs_mds[1])", "kopf.achs_nr", "2", "7")]


def test_an_unreadable_machine_is_said_and_the_others_compared(tmp_path: Path, registry: Registry) -> None:
    golden, _, ms = build_fleet(tmp_path, "machine-clean", 2)
    bad = tmp_path / "bad" / "hochlauf.lis"
    bad.parent.mkdir()
    bad.write_text("# nothing\nEnde\n")
    set_value(axis(ms[1], "achse_x.lis"), "kenngr.swe_pos", "16000000")
    drift = drift_of(registry, golden, [ms[0], bad, ms[1]])
    assert [u.machine for u in drift.unreadable] == [str(bad)]
    assert "names no list of a machine" in drift.unreadable[0].error
    assert drift.compared == 2 and drift.params[0].machines == [str(ms[1])]
    assert fleet_exit(drift) == 2


def test_a_golden_machine_that_cannot_be_read_is_an_error(tmp_path: Path, registry: Registry) -> None:
    _, fleet, _ = build_fleet(tmp_path, "machine-clean", 1)
    with pytest.raises(ZeroError):
        drift_of(registry, tmp_path / "nothing.lis", [fleet])
    (tmp_path / "empty").mkdir()
    with pytest.raises(ZeroError, match="no start-up list"):
        drift_of(registry, fleet / "m00" / "listen" / "hochlauf.lis", [tmp_path / "empty"])


# ----------------------------------------------------------------------------- machines


def test_a_folder_holds_the_machines_below_it_one_start_up_list_each(tmp_path: Path) -> None:
    (tmp_path / "b" / "listen" / "SoE").mkdir(parents=True)
    (tmp_path / "b" / "listen" / "hochlauf.lis").write_text("")
    (tmp_path / "b" / "listen" / "SoE" / "hochlauf.lis").write_text("")  # a variant of b's: not a machine
    (tmp_path / "a").mkdir()
    (tmp_path / "a" / "Startup.xml").write_text("")
    (tmp_path / ".hidden").mkdir()
    (tmp_path / ".hidden" / "hochlauf.lis").write_text("")
    (tmp_path / "c" / "d").mkdir(parents=True)
    (tmp_path / "c" / "d" / "HOCHLAUF.LIS").write_text("")
    (tmp_path / "c" / "d" / "startup.xml").write_text("")  # hochlauf.lis first
    golden = tmp_path / "c" / "d" / "HOCHLAUF.LIS"
    assert machine_startups([tmp_path]) == [str(tmp_path / "a" / "Startup.xml"),
                                            str(tmp_path / "b" / "listen" / "hochlauf.lis"), str(golden)]
    # the golden machine is not compared with itself; a machine named twice is compared once
    named = str(tmp_path / "b" / "listen" / "hochlauf.lis")
    assert machine_startups([named, tmp_path], golden) == [named, str(tmp_path / "a" / "Startup.xml")]


def test_short_names_are_what_tells_machines_apart() -> None:
    assert short_names(["f/m1/listen/hochlauf.lis", "f/m2/listen/hochlauf.lis"]) == {
        "f/m1/listen/hochlauf.lis": "m1", "f/m2/listen/hochlauf.lis": "m2"}
    assert short_names(["x/hochlauf.lis"]) == {"x/hochlauf.lis": "x/hochlauf.lis"}


# ----------------------------------------------------------------------------- parallel, formats


def test_jobs_give_the_same_result_in_the_same_order(tmp_path: Path, registry: Registry,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("zero.engine.fleet.PARALLEL_MIN_MACHINES", 2)  # two processes for these 24
    golden, fleet, ms = build_fleet(tmp_path, "machine-clean", 24)
    for i in (3, 17, 20):
        set_value(axis(ms[i], "achse_x.lis"), "kenngr.swe_pos", str(16000000 + i % 2))
    axis(ms[9], "achse_c.lis").unlink()
    one = drift_of(registry, golden, [fleet], jobs=1)
    import zero.engine.fleet as fleet_module

    here: list[str] = []  # the machines compared in this process (a worker counts in its own copy)
    compare = fleet_module.compare_machine
    monkeypatch.setattr(fleet_module, "compare_machine", lambda g, s: here.append(s) or compare(g, s))
    two = drift_of(registry, golden, [fleet], jobs=2)
    assert here == []  # every machine compared by the workers
    assert fleet_json(one) == fleet_json(two)
    assert [v.machines for v in one.params[0].values] == [[str(ms[3]), str(ms[17])], [str(ms[20])]]
    assert one.lists[0].machines == [str(ms[9])]


def test_json_and_csv_parse_and_say_the_same(tmp_path: Path, registry: Registry) -> None:
    golden, fleet, ms = build_fleet(tmp_path, "machine-clean")
    for m in (ms[1], ms[4]):
        set_value(axis(m, "achse_x.lis"), "kenngr.swe_pos", "16000000")
    set_value(axis(ms[5], "achse_c.lis"), "kenngr.swe_toleranz", "5000")
    axis(ms[2], "achse_y.lis").unlink()
    drift = drift_of(registry, golden, [fleet])
    out = io.StringIO()
    render_fleet_json(drift, out)
    data = json.loads(out.getvalue())
    assert data["golden"] == str(golden) and data["machines"] == [str(m) for m in ms]
    assert data["summary"] == {"machines": N, "drifting": 4, "parameters": 2, "lists_missing": 1, "lists_extra": 0,
                               "unreadable": 0}
    first = data["parameters"][0]
    assert {k: first[k] for k in ("scope", "key", "id", "count", "of")} == {
        "scope": "axis 1 (achs_mds[0])", "key": "kenngr.swe_pos", "id": "P-AXIS-00178", "count": 2, "of": N}
    assert first["golden"] == {"value": "15000000", "note": None, "name": None}
    assert first["values"] == [{"value": "16000000", "note": None, "name": None, "delta": 100.0, "count": 2,
                                "machines": [str(ms[1]), str(ms[4])]}]
    out = io.StringIO()
    render_fleet_csv(drift, out)
    rows = list(csv.DictReader(io.StringIO(out.getvalue())))
    assert tuple(rows[0]) == CSV_COLUMNS
    from_json = [(p["scope"], p["key"], p["id"] or "", p["golden"]["value"] or "", m, v["value"] or "")
                 for p in data["parameters"] for v in p["values"] for m in v["machines"]]
    from_csv = [(r["list"], r["key"], r["id"], r["golden"], r["machine"], r["value"]) for r in rows if r["key"]]
    assert from_csv == from_json
    assert len(from_csv) == 3
    assert [(r["list"], r["machine"], r["note"]) for r in rows if not r["key"]] == [
        ("axis 2 (achs_mds[1])", str(ms[2]), "list missing: achs_mds[1] (./listen/achse_y.lis) does not exist")]
    swe_tol = next(r for r in rows if r["key"] == "kenngr.swe_toleranz")
    assert (swe_tol["golden"], swe_tol["value"], swe_tol["note"]) == (
        "", "5000", "not set on the golden machine: the default 1000")


def test_run_fleet_diff_writes_the_report_and_gives_the_exit_code(tmp_path: Path, registry: Registry) -> None:
    golden, fleet, ms = build_fleet(tmp_path, "machine-clean", 3)
    set_value(axis(ms[0], "achse_x.lis"), "kenngr.swe_pos", "16000000")
    out = io.StringIO()
    code = run_fleet_diff(FleetRequest(str(golden), [str(fleet)], jobs=1), lambda _d: registry, "json", out)
    assert code == 1 and json.loads(out.getvalue())["summary"]["drifting"] == 1
    with pytest.raises(ZeroError, match="unknown output format"):
        run_fleet_diff(FleetRequest(str(golden), [str(fleet)]), lambda _d: registry, "yaml", io.StringIO())
    with pytest.raises(ZeroError, match="give their start-up lists"):
        run_fleet(FleetRequest(str(golden), []), lambda _d: registry)


# ----------------------------------------------------------------------------- the same as zero diff --machine


@pytest.mark.parametrize("fixture", ["machine-clean", "machine-layered"])
def test_each_machine_drifts_as_zero_diff_machine_says(tmp_path: Path, registry: Registry, fixture: str) -> None:
    golden, fleet, ms = build_fleet(tmp_path, fixture, 3)
    m = ms[1]
    set_value(axis(m, "achse_x.lis"), "kenngr.swe_pos", "16000000")
    set_value(axis(m, "achse_x.lis"), "kenngr.swe_toleranz", "5000")  # added (the golden has the default)
    set_value(axis(m, "achse_y.lis"), "kenngr.achs_typ", "0x1")  # written differently, the same value: no drift
    set_value(axis(m, "kanal.lis"), "range_check_prog_soft_limits", "0" if fixture == "machine-layered" else "1")
    set_value(axis(m, "nullp.lis"), "np_grp[1].achse[0].versch", "123")
    if fixture == "machine-layered":
        set_value(axis(m, "achse_vorgabe.lis"), "kenngr.swe_neg", "-2000000")
        set_value(axis(m, "kanal_vorgabe.lis"), "gruppe[0].achse[1].bezeichnung", "Y2")
    drift = drift_of(registry, golden, [fleet])
    fleet_says = {(p.scope, p.key, p.golden, v.value) for p in drift.params for v in p.values if str(m) in v.machines}
    run = run_diff(str(golden), str(m), project(registry), lambda: b"", machine=True)
    diff_says = {(c.group.split(": ", 1)[0], c.key, c.old, c.new) for c in run.changes}
    assert fleet_says == diff_says
    assert len(fleet_says) >= 4
    assert {p.key for p in drift.params} == {k for _, k, _, _ in fleet_says}  # only machine m01 drifts

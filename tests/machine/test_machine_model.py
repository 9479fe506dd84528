"""The machine as the controller builds it: every list, counts, default lists underneath,
the working directory found once, and every effective value with its origin (golden)."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT, golden
from zero.catalog.registry import Registry
from zero.engine.lint import LintOptions, lint_machine
from zero.engine.project import Project
from zero.machine.effective import effective
from zero.machine.limits import pcs_limits
from zero.machine.model import REFERENCES, load_machine

LAYERED = FIXTURES / "machine-layered" / "listen" / "hochlauf.lis"
REL = os.path.relpath(LAYERED, ROOT)


def _zero(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "zero", *args], cwd=ROOT, capture_output=True, text=True,
                          check=False, timeout=60)


def test_the_working_directory_is_found_once_and_nothing_is_replaced(registry: Registry) -> None:
    m = load_machine(LAYERED, registry)
    assert m.workdir == FIXTURES / "machine-layered"
    status = {n.key: n.status for n in m.named}
    assert status == {"default_sda_mds": "loaded", "sda_mds[0]": "loaded", "nullp_data[0]": "loaded",
                      "hand_mds": "missing", "default_achs_mds": "loaded", "achs_mds[0]": "loaded",
                      "achs_mds[1]": "loaded", "achs_mds[2]": "missing", "achs_mds[3]": "beyond-count"}
    # listen/achse_c.lis exists next to the start-up list, but ./listen/SoE/achse_c.lis is named
    assert [lf.path.name for lf in m.axis_lists] == ["achse_x.lis", "achse_y.lis"]


def test_default_lists_lie_under_the_specific_lists(registry: Registry) -> None:
    m = load_machine(LAYERED, registry)
    axes = m.axes()
    assert (axes[1].swe_neg, axes[1].swe_pos) == (-1_000_000, 1_000_000)  # all from achse_vorgabe.lis
    assert (axes[2].swe_neg, axes[2].swe_pos) == (-1_000_000, 2_000_000)  # its own positive limit
    # the channel's axes come from the default channel list
    assert [(a.index, a.log_nr, a.name) for a in m.channels[0].axes] == [(0, 1, "X"), (1, 2, "Y")]
    g54_x = {(r.group, r.axis_name): r for r in pcs_limits(m)}[(1, "X")]
    assert (g54_x.acs_neg, g54_x.acs_pos, g54_x.pcs_neg) == (-1_000_000, 1_000_000, -6_000_000)


def test_layered_machine_findings_golden(registry: Registry, request: pytest.FixtureRequest) -> None:
    results = lint_machine(load_machine(LAYERED, registry), registry)
    lines = [f"{os.path.relpath(d.path, ROOT)}:{d.span.line}:{d.span.column}: {d.code} "
             + d.message.replace(f"{ROOT}{os.sep}", "") for r in results for d in r.diagnostics]
    expected = golden(FIXTURES / "machine-layered" / "expected.json", lines,
                      request.config.getoption("--update-golden"))
    assert lines == expected
    codes = {line.split(": ")[1].split()[0] for line in lines}
    assert {"X001", "X005", "X008"} <= codes
    linted = [os.path.basename(r.path) for r in results]
    assert sorted(linted) == sorted(set(linted))  # each list once
    assert "achse_vorgabe.lis" in linted and "kanal_vorgabe.lis" in linted


@pytest.mark.slow
def test_effective_values_with_their_origin_golden(request: pytest.FixtureRequest) -> None:
    update = request.config.getoption("--update-golden")
    text = _zero("show", "--machine", REL)
    assert text.returncode == 0, text.stderr
    assert text.stdout == golden_text(FIXTURES / "machine-layered" / "effective.txt", text.stdout, update)
    data = _zero("show", "--machine", REL, "--output-format", "json")
    assert json.loads(data.stdout) == golden(FIXTURES / "machine-layered" / "effective.json",
                                             json.loads(data.stdout), update)
    explained = _zero("explain", "kenngr.swe_neg", "--machine", REL)
    assert explained.returncode == 0, explained.stderr
    assert explained.stdout == golden_text(FIXTURES / "machine-layered" / "explain.txt", explained.stdout, update)


def golden_text(path: Path, actual: str, update: bool) -> str:
    if update:
        path.write_text(actual, encoding="utf-8")
    return path.read_text(encoding="utf-8")


def test_explain_names_every_layer(registry: Registry) -> None:
    m = load_machine(LAYERED, registry)
    scopes = {s.name: s for s in effective(m, ["kenngr.swe_pos"], explain=True)}
    x = scopes["axis 1 (achs_mds[0])"].values[0]
    assert (x.value, x.origin.source, x.origin.line) == ("1000000", "default list", 4)
    assert [o.source for _, o in x.layers] == ["not set", "default list", "catalogue default"]
    y = scopes["axis 2 (achs_mds[1])"].values[0]
    assert (y.value, y.origin.source, y.origin.line) == ("2000000", "list", 4)


def test_every_reference_is_a_start_up_parameter_of_the_catalogue(registry: Registry) -> None:
    for ref in REFERENCES:
        spec = registry.get(ref.param_id)
        assert spec is not None and spec.kind == "STUP" and spec.key == ref.key, ref


def test_corpus_machines_load_every_list_they_name(registry: Registry, corpus: Path) -> None:
    listen = corpus / "isg-sdk" / "listen"
    for startup in (listen / "hochlauf.lis", listen / "SoE" / "hochlauf.lis"):
        m = load_machine(startup, registry)
        assert m.workdir == corpus / "isg-sdk"
        assert {n.status for n in m.named} == {"loaded"}, [(n.key, n.status) for n in m.named]
        assert {n.key for n in m.named} >= {"default_sda_mds", "default_achs_mds", "hand_mds", "pzv_data[0]",
                                            "ve_var[0]", "rtconf_lis", "achs_kw[0]"}
        assert len(m.lists) == 15
        scopes = effective(m)
        assert len(scopes) == 13 and all(s.values for s in scopes)  # every list but the two default lists
        results = lint_machine(load_machine(startup, registry), registry)
        assert len(results) == 15


def test_configuration_overrides_a_reference_and_the_working_directory(tmp_path: Path, registry: Registry) -> None:
    import shutil

    from zero.engine.config import ConfigFinder

    machine = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine-layered", machine)
    (machine / "pyproject.toml").write_text(
        '[tool.zero.machine]\nstartup = "listen/hochlauf.lis"\n"achs_mds[2]" = "listen/achse_c.lis"\n'
        'working-directory = "."\n')
    cfg = ConfigFinder().for_path(machine / "listen" / "hochlauf.lis")
    assert cfg.machine_workdir == machine / "."
    m = load_machine(machine / "listen" / "hochlauf.lis", registry, None, cfg.machine_lists, cfg.machine_workdir)
    assert {n.key: n.status for n in m.named}["achs_mds[2]"] == "overridden"
    assert [lf.path.name for lf in m.axis_lists] == ["achse_x.lis", "achse_y.lis", "achse_c.lis"]
    bad = machine / "pyproject.toml"
    bad.write_text('[tool.zero.machine]\n"achs_kw_log_ax_nr[0]" = "x"\n')
    from zero.engine.config import parse_config
    from zero.errors import ZeroError

    with pytest.raises(ZeroError, match="names a list"):
        parse_config(bad)


def test_diff_of_two_machines_compares_effective_values(tmp_path: Path, registry: Registry) -> None:
    import shutil

    from zero.engine.queries import run_diff

    other = tmp_path / "other"
    shutil.copytree(FIXTURES / "machine-layered", other)
    default = other / "listen" / "achse_vorgabe.lis"
    default.write_text(default.read_text().replace("kenngr.swe_neg                                        -1000000",
                                                   "kenngr.swe_neg                                        -2000000"))
    run = run_diff(str(LAYERED), str(other / "listen" / "hochlauf.lis"), Project(lambda _d: registry), lambda: b"",
                   machine=True)
    changed = [(c.group, c.key, c.old, c.new, c.delta) for c in run.changes]
    # the axis lists are the same files: the change comes from the default list under both
    assert changed == [("axis 1 (achs_mds[0]): kenngr", "kenngr.swe_neg", "-1000000", "-2000000", -100.0),
                       ("axis 2 (achs_mds[1]): kenngr", "kenngr.swe_neg", "-1000000", "-2000000", -100.0)]
    same = run_diff(str(LAYERED), str(LAYERED), Project(lambda _d: registry), lambda: b"", machine=True)
    assert same.changes == []


def test_diff_of_two_lists_names_the_machines_default_list(tmp_path: Path, registry: Registry) -> None:
    import shutil

    from zero.engine.queries import run_diff

    machine = tmp_path / "m"
    shutil.copytree(FIXTURES / "machine-layered", machine)
    (machine / "pyproject.toml").write_text('[tool.zero.machine]\nstartup = "listen/hochlauf.lis"\n')
    old = machine / "listen" / "achse_y.lis"
    new = machine / "listen" / "achse_y_neu.lis"
    new.write_text(old.read_text().replace("kenngr.swe_pos                                        2000000\n", ""))
    run = run_diff(str(old), str(new), Project(lambda _d: registry), lambda: b"")
    [change] = run.changes
    assert (change.key, change.kind, change.delta) == ("kenngr.swe_pos", "removed", -100.0)
    assert change.note == "now the default list's 1000000 (achse_vorgabe.lis:4)"
    (machine / "pyproject.toml").unlink()
    [plain] = run_diff(str(old), str(new), Project(lambda _d: registry), lambda: b"").changes
    assert plain.note == "now the default 100000000" and plain.delta == 9800.0


def test_an_alias_counts_as_the_parameter_it_stands_for(registry: Registry, corpus: Path) -> None:
    m = load_machine(corpus / "isg-sdk" / "listen" / "hochlauf.lis", registry)
    scopes = effective(m, ["kenngr.homing.homing_type"], explain=True)
    value = scopes[0].values[0]
    assert (value.value, value.origin.source) == ("CNC_CONTROLLED", "list")  # written `kenngr.homing_type`
    assert [o.source for _, o in value.layers] == ["list", "default list", "catalogue default"]


def test_an_indexed_key_is_found_as_written(registry: Registry) -> None:
    """`np_grp[1].achse[0].versch` names that element; fnmatch alone read `[1]` as a character class
    and found nothing ("no list of the machine has or documents …")."""
    m = load_machine(LAYERED, registry)
    found = [(s.name, v.key, v.value) for s in effective(m, ["np_grp[1].achse[0].versch"]) for v in s.values]
    assert [(key, value) for _, key, value in found] == [("np_grp[1].achse[0].versch", "5000000")]
    globbed = {v.key for s in effective(m, ["np_grp*.versch"]) for v in s.values}  # a glob stays a glob
    assert {"np_grp[1].achse[0].versch", "np_grp[1].achse[1].versch"} <= globbed


def test_a_machine_finding_is_suppressed_in_the_list_it_concerns(registry: Registry, tmp_path: Path) -> None:
    """X findings land on a list's line; that list's `zero: noqa` covers them as it covers the
    list's own findings (and an unused one is still Z001)."""
    shutil.copytree(FIXTURES / "machine-layered", tmp_path / "m")
    startup = tmp_path / "m" / "listen" / "hochlauf.lis"
    zero_list = tmp_path / "m" / "listen" / "nullp.lis"

    def x001() -> list[int]:
        results = lint_machine(load_machine(startup, registry), registry, LintOptions(extend_select=("Z",)))
        found = [d for r in results for d in r.diagnostics if r.path == str(zero_list)]
        return [d.span.line for d in found if d.code in ("X001", "Z001")]

    assert x001() == [2]
    lines = zero_list.read_text().split("\n")
    lines[1] += "  ( noqa: X001 -- reviewed: the offset is meant"
    zero_list.write_text("\n".join(lines))
    assert x001() == []
    lines[1] = lines[1].replace("X001", "X002")
    zero_list.write_text("\n".join(lines))
    assert x001() == [2, 2]  # X001 again, and the suppression hides nothing


def test_an_offset_outside_its_soft_limits_points_at_the_entries_that_set_them(registry: Registry) -> None:
    """X001 on the zero-offset list names the soft limits it is measured against: here the default
    axis list's (the axis list sets none), as related locations."""
    results = lint_machine(load_machine(LAYERED, registry), registry)
    (x001,) = [d for r in results for d in r.diagnostics if d.code == "X001"]
    default = str(LAYERED.parent / "achse_vorgabe.lis")
    assert [(r.path, r.message.split()[0]) for r in x001.related] == [(default, "kenngr.swe_neg"),
                                                                     (default, "kenngr.swe_pos")]
    lines = (LAYERED.parent / "achse_vorgabe.lis").read_text().split("\n")
    assert all(lines[r.span.line - 1].startswith(r.message.split()[0]) for r in x001.related)

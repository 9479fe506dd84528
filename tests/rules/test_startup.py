"""K rules: the kernel's documented start-up errors, each with its number, source and fixtures."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from conftest import FIXTURES, ROOT
from zero.catalog.conditions import parse, refs
from zero.catalog.data.startup_errors import ERRORS
from zero.catalog.registry import Registry
from zero.diagnostics import Diagnostic
from zero.engine.lint import LintOptions, lint_file
from zero.rules import RULES
from zero.rules.startup import CHECKS

TOML = ROOT / "src" / "zero" / "catalog" / "data" / "startup_errors.toml"
ROWS = tomllib.loads(TOML.read_text(encoding="utf-8"))["error"]
CHECKED = [row for row in ROWS if row.get("condition")]


def test_the_compiled_table_is_the_toml() -> None:
    """tools/gen_startup.py was run after the last edit of the TOML."""
    assert ERRORS == ROWS


def test_every_row_is_sourced_and_well_formed(registry: Registry) -> None:
    codes = [row["code"] for row in ROWS]
    numbers = [row["number"] for row in ROWS]
    assert len(set(codes)) == len(codes) and len(set(numbers)) == len(numbers)
    for row in ROWS:
        assert row["source"].startswith(("https://", "CncParaDesc.xml (")), row
        assert row["title"] and row["list"] in {"AXIS", "CHAN", "ZERO", "TOOL", "COMP", "STUP", "CLMP", "EXTV",
                                                "MANU", "RTCF"}, row
        for text in (row.get("condition", ""), row.get("when", "")):
            if text:
                for pid in refs(parse(text)):
                    assert registry.get(pid) is not None, (row["number"], pid)
        if row.get("condition"):  # a documented row only may name parameters of another release
            for pid in row.get("params", []):
                assert registry.get(pid) is not None, (row["number"], pid)


def test_every_condition_is_a_rule_with_its_number() -> None:
    assert [c.code for c in CHECKS] == [row["code"] for row in CHECKED]
    for row in CHECKED:
        rule = RULES[row["code"]]
        assert rule.summary.startswith(f"P-ERR-{row['number']}: ") and row["source"] in rule.explanation


@pytest.mark.parametrize("row", CHECKED, ids=lambda r: f"{r['code']}-{r['number']}")
def test_failing_and_passing_fixture(row: dict[str, object], registry: Registry) -> None:
    folder = FIXTURES / "startup" / str(row["number"])
    options = LintOptions(select=("K",))
    # a default list is one by the machine that reads it, or by an XML list's root: those fixtures are XML
    suffix = ".xml" if (folder / "fail.xml").exists() else ".lis"
    failing = lint_file(folder / f"fail{suffix}", registry, options).diagnostics
    own = [d for d in failing if d.code == row["code"]]
    assert len(own) == 1, failing
    # another start-up check may fail too, never on the same line (one root cause, one finding): the
    # slow homing speed cannot exceed a limit without the fast one exceeding it as well (110422, 110421)
    assert all(d.span.line != own[0].span.line for d in failing if d is not own[0]), failing
    assert own[0].kernel_error == f"P-ERR-{row['number']}"
    assert f"P-ERR-{row['number']}" in own[0].message
    passing = lint_file(folder / f"pass{suffix}", registry, options).diagnostics
    assert [d.code for d in passing if d.code == row["code"]] == [], passing


def test_no_fixture_folder_without_its_row() -> None:
    folders = {int(p.name) for p in (FIXTURES / "startup").iterdir() if p.is_dir()}
    assert folders == {int(str(row["number"])) for row in CHECKED}


def test_the_kernel_number_reaches_json_and_sarif(tmp_path: Path) -> None:
    import json

    row = CHECKED[0]
    path = FIXTURES / "startup" / str(row["number"]) / "fail.lis"
    out = subprocess.run([sys.executable, "-m", "zero", "lint", "--isolated", "--select", "K", "--output-format",
                          "json", str(path)], capture_output=True, text=True, check=False)
    assert [d["kernel_error"] for d in json.loads(out.stdout)] == [f"P-ERR-{row['number']}"]
    out = subprocess.run([sys.executable, "-m", "zero", "lint", "--isolated", "--select", "K", "--output-format",
                          "sarif", str(path)], capture_output=True, text=True, check=False)
    [result] = json.loads(out.stdout)["runs"][0]["results"]
    assert result["properties"]["kernelError"] == f"P-ERR-{row['number']}"


def test_a_default_list_of_a_machine_is_checked_as_one(tmp_path: Path) -> None:
    """The sixth planted fault of issue 26: the machine's default axis list with `kopf.achs_nr` 3."""
    import shutil

    from conftest import zero_cli

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    (listen / "default_achse.lis").write_text("kopf.achs_nr 3\nkenngr.achs_typ 1\nEnde\n")
    startup = listen / "hochlauf.lis"
    startup.write_text(startup.read_text().replace("Ende", "default_achs_mds ./listen/default_achse.lis\nEnde", 1))
    run = zero_cli("lint", "--machine", str(startup), "--select", "K", "--output-format", "concise")
    assert [line.split(" ")[1] for line in run.stdout.splitlines()] == ["K056"], run.stdout
    assert "default_achse.lis:1:" in run.stdout and "P-ERR-110300" in run.stdout


def test_the_compiled_prose_ranges_are_the_toml() -> None:
    """tools/gen_startup.py compiles the prose ranges too."""
    from zero.catalog.data.prose_ranges import RANGES

    toml = ROOT / "src" / "zero" / "catalog" / "data" / "prose_ranges.toml"
    assert tomllib.loads(toml.read_text(encoding="utf-8"))["range"] == RANGES


def test_the_resolution_mix_in_a_default_list_is_reported_there_once(tmp_path: Path) -> None:
    """M009 (the fifth planted fault) in the machine's default axis list: one finding, on the
    default list's line, none repeated in the axis lists it lies under."""
    import shutil

    from conftest import zero_cli

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    (listen / "default_achse.lis").write_text(
        "kopf.achs_nr 0\ngetriebe[0].wegaufn 10\nantr.feed_const_num 100000\nEnde\n")
    startup = listen / "hochlauf.lis"
    startup.write_text(startup.read_text().replace("Ende", "default_achs_mds ./listen/default_achse.lis\nEnde", 1))
    run = zero_cli("lint", "--machine", str(startup), "--select", "M009", "--output-format", "concise")
    assert [line.split(" ")[0].rsplit("/", 1)[-1] for line in run.stdout.splitlines()] == [
        "default_achse.lis:3:21:"], run.stdout
    assert "`getriebe[0].wegaufn 10`" in run.stdout and "`antr.feed_const_num 100000`" in run.stdout


def test_two_axis_lists_with_one_logical_axis_number_carry_110064() -> None:
    """Issue 38: X004 (one `kopf.achs_nr` in two axis lists) is the kernel's P-ERR-110064, whose page
    says the second axis's data is not taken over; P-ERR-1001121 aborts the start-up."""
    import json

    from conftest import zero_cli

    startup = FIXTURES / "machine" / "listen" / "hochlauf.lis"
    run = zero_cli("lint", "--machine", str(startup), "--select", "X004", "--output-format", "json")
    found = [d for d in json.loads(run.stdout) if d["code"] == "X004" and d["param_id"] == "P-AXIS-00016"]
    assert found and all(d["kernel_error"] == "P-ERR-110064" for d in found), run.stdout
    assert all("does not take over this axis's data" in d["message"] and "1001121" in d["message"] for d in found)
    assert "262200203.html" in RULES["X004"].explanation and "269224331.html" in RULES["X004"].explanation


def test_a_pre_output_time_below_the_real_time_cycle_is_21203(tmp_path: Path) -> None:
    """Issue 38: a value from another list of the machine: the channel list's MET_SVS pre-output time
    (P-CHAN-00070) against the real-time configuration's cycle time (P-RTCF-00002), X015 with
    P-ERR-21203; none without a real-time configuration, none at or above the cycle time."""
    import json
    import shutil

    from conftest import zero_cli

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    (listen / "rtconf.lis").write_text("cycle_time 2000\nEnde\n")
    kanal = listen / "kanal.lis"
    kanal.write_text(kanal.read_text().replace(
        "Ende", "m_synch[97] 0x02000000\nm_pre_outp[97] 1000\nm_synch[98] MET_SVS\nm_pre_outp[98] 2000\nEnde", 1))
    startup = listen / "hochlauf.lis"

    def x015() -> list[dict[str, object]]:
        run = zero_cli("lint", "--machine", str(startup), "--select", "X015", "--output-format", "json")
        return [d for d in json.loads(run.stdout) if d["code"] == "X015"]

    assert x015() == []  # the start-up list names no real-time configuration: the cycle time is not known
    startup.write_text(startup.read_text().replace("Ende", "rtconf_lis ./listen/rtconf.lis\nEnde", 1))
    [found] = x015()
    assert found["kernel_error"] == "P-ERR-21203" and found["param_id"] == "P-CHAN-00070"
    assert "M97" in str(found["message"]) and "1000 µs" in str(found["message"]) and "2000 µs" in str(found["message"])
    assert str(found["path"]).endswith("kanal.lis")


def test_cross_list_kernel_checks_of_a_machine(tmp_path: Path) -> None:
    """Issue 38: values from two lists of a machine, each with its kernel number: a channel spindle
    whose axis list is no spindle (X016, P-ERR-110304), a gantry slave whose modulo limits differ
    from its master's (X017, P-ERR-70202) and whose master lacks the gantry master bit (X018,
    P-ERR-70124, a documented warning); the clean machine has none."""
    import json
    import shutil

    from conftest import zero_cli

    def found(startup: Path) -> list[tuple[str, str, str, str]]:
        run = zero_cli("lint", "--machine", str(startup), "--select", "X016,X017,X018", "--output-format", "json")
        return sorted((d["code"], Path(str(d["path"])).name, str(d["kernel_error"]), d["severity"])
                      for d in json.loads(run.stdout))

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    startup = listen / "hochlauf.lis"
    assert found(startup) == []
    kanal = listen / "kanal.lis"
    kanal.write_text(kanal.read_text().replace("Ende", "spdl_anzahl 1\nspindel[0].bezeichnung S1\n"
                                               "spindel[0].log_achs_nr 3\nEnde", 1))  # axis 3 is rotary (2)
    y = listen / "achse_y.lis"  # Y becomes X's gantry slave, X is no gantry master; X's modulo is the default
    y.write_text(y.read_text().replace("Ende", "kenngr.gantry_ax_nr 1\ngetriebe[0].moduloo 1000\nEnde", 1))
    assert found(startup) == [("X016", "kanal.lis", "P-ERR-110304", "error"),
                              ("X017", "achse_y.lis", "P-ERR-70202", "error"),
                              ("X018", "achse_y.lis", "P-ERR-70124", "warning")]
    x = listen / "achse_x.lis"  # X becomes a gantry master with Y's modulo limits, C a spindle
    x.write_text(x.read_text().replace("Ende", "kenngr.achs_mode 0x10001\ngetriebe[0].moduloo 1000\nEnde", 1))
    c = listen / "achse_c.lis"
    c.write_text(c.read_text().replace("kenngr.achs_typ                                       2", "kenngr.achs_typ 4"))
    assert found(startup) == []


def test_unique_reads_only_the_elements_the_count_configures(registry: Registry) -> None:
    """unique(): a spindle beyond `spdl_anzahl` is not configured, so its name is no duplicate
    (20419); within the count the later of two lines is the one reported."""
    from zero.engine.lint import lint_bytes

    def k002(text: str) -> list[int]:
        result = lint_bytes(text.encode(), registry, "sda_mds.lis", LintOptions(select=("K002",)))
        return [d.span.line for d in result.diagnostics]

    names = "spindel[0].bezeichnung S1\nspindel[1].bezeichnung S2\nspindel[2].bezeichnung S1\n"
    assert k002(f"spdl_anzahl 2\n{names}Ende\n") == []
    assert k002(f"spdl_anzahl 3\n{names}Ende\n") == [4]


def test_what_a_finding_says_follows_the_page(registry: Registry) -> None:
    """Issue 38: a documented warning without a reaction is a warning and says so (110658); an error
    reported other than at list transfer says when (70385, the position controller); a reaction the
    page gives in words is said in words (110574); a drive-type condition names the drive types the
    parameter's page lists (110614)."""
    options = LintOptions(select=("K",))

    def finding(number: int) -> Diagnostic:
        [d] = lint_file(FIXTURES / "startup" / str(number) / "fail.lis", registry, options).diagnostics
        return d

    warning = finding(110658)
    assert warning.severity.label == "warning" and "reports warning 110658 at start-up" in warning.message
    assert "changes no value" in warning.message
    swapped = finding(70385)
    assert "reports error 70385 when the position controller takes over the list" in swapped.message
    assert swapped.message.endswith("the kernel swaps P-AXIS-00408 and P-AXIS-00409")
    assert finding(110574).message.endswith("the kernel switches the I position controller off")
    drive = finding(110614)
    assert drive.hint is not None and "the P-AXIS-00539 page lists drive types (P-AXIS-00020) 2, 3" in drive.hint


def test_one_channel_id_on_two_channels_is_1001850(tmp_path: Path) -> None:
    """Issue 38: two channel lists writing one non-zero channel_id (P-CHAN-00400) are X019 with
    P-ERR-1001850, on the later channel's line; distinct IDs, or IDs left at 0, are not."""
    import json
    import shutil

    from conftest import zero_cli

    def found(startup: Path) -> list[tuple[str, str, int, str]]:
        run = zero_cli("lint", "--machine", str(startup), "--select", "X019", "--output-format", "json")
        return [(d["code"], Path(str(d["path"])).name, d["line"], str(d["kernel_error"]))
                for d in json.loads(run.stdout)]

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    startup = listen / "hochlauf.lis"
    startup.write_text(startup.read_text().replace("kanal_anzahl                                          1",
                                                   "kanal_anzahl 2").replace(
        "Ende", "sda_mds[1] ./listen/kanal2.lis\nEnde", 1))
    kanal = listen / "kanal.lis"
    text = kanal.read_text()
    (listen / "kanal2.lis").write_text(text)
    assert found(startup) == []  # both IDs at the default 0
    kanal.write_text(text.replace("Ende", "channel_id 7\nEnde", 1))
    (listen / "kanal2.lis").write_text(text.replace("Ende", "channel_id 8\nEnde", 1))
    assert found(startup) == []
    (listen / "kanal2.lis").write_text(text.replace("Ende", "channel_id 7\nEnde", 1))
    line = text.splitlines().index("Ende") + 1
    assert found(startup) == [("X019", "kanal2.lis", line, "P-ERR-1001850")]


def test_path_axes_against_their_axis_lists(tmp_path: Path) -> None:
    """Issue 38: a channel path axis whose axis list is a single axis (SAI) or a spindle is X020
    (P-ERR-21238, start-up aborted); with alias names active, a path axis named like its axis list's
    alias is X021 (P-ERR-22016); the clean machine has neither."""
    import json
    import shutil

    from conftest import zero_cli

    def found(startup: Path) -> list[tuple[str, str, str]]:
        run = zero_cli("lint", "--machine", str(startup), "--select", "X020,X021", "--output-format", "json")
        return sorted((d["code"], Path(str(d["path"])).name, str(d["kernel_error"])) for d in json.loads(run.stdout))

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    startup = listen / "hochlauf.lis"
    assert found(startup) == []
    kanal = listen / "kanal.lis"
    kanal.write_text(kanal.read_text().replace("Ende", "use_alias_name_in_ax_list 1\nEnde", 1))
    assert found(startup) == []  # the names X, Y, C are not the aliases X_Achse, ...
    y = listen / "achse_y.lis"
    y.write_text(y.read_text().replace("Ende", "kenngr.configure_sai TRUE\nEnde", 1))
    x = listen / "achse_x.lis"
    x.write_text(x.read_text().replace("X_Achse", "X"))
    assert found(startup) == [("X020", "kanal.lis", "P-ERR-21238"), ("X021", "kanal.lis", "P-ERR-22016")]
    c = listen / "achse_c.lis"
    c.write_text(c.read_text().replace("kenngr.achs_typ                                       2", "kenngr.achs_typ 4"))
    assert [f[0] for f in found(startup)] == ["X020", "X020", "X021"]


def test_a_gantry_slave_as_path_axis_is_21020(tmp_path: Path) -> None:
    """Issue 38: a channel path axis whose axis list names a gantry master (P-AXIS-00070) is X022
    (P-ERR-21020, the current job aborted); the clean machine has none."""
    import json
    import shutil

    from conftest import zero_cli

    def found(startup: Path) -> list[tuple[str, str, int]]:
        run = zero_cli("lint", "--machine", str(startup), "--select", "X022", "--output-format", "json")
        return [(d["code"], str(d["kernel_error"]), d["line"]) for d in json.loads(run.stdout)]

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    startup = listen / "hochlauf.lis"
    assert found(startup) == []
    y = listen / "achse_y.lis"  # Y becomes X's gantry slave but stays a path axis of the channel
    y.write_text(y.read_text().replace("Ende", "kenngr.gantry_ax_nr 1\nEnde", 1))
    line = (listen / "kanal.lis").read_text().splitlines().index(
        "gruppe[0].achse[1].log_achs_nr                        2") + 1
    assert found(startup) == [("X022", "P-ERR-21020", line)]


def test_plane_compensation_masters_against_the_axis_lists(tmp_path: Path) -> None:
    """Issue 38: an axis that switches plane compensation on (P-AXIS-00174) with a compensation list
    whose master axis is 0 or no axis of the machine is X023 (P-ERR-70182); a master axis that is not
    linear is X024 (P-ERR-70184); linear masters of the machine are neither, and the clean machine has none."""
    import json
    import shutil

    from conftest import zero_cli

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    startup = listen / "hochlauf.lis"

    def found() -> list[tuple[str, str, int, str]]:
        run = zero_cli("lint", "--machine", str(startup), "--select", "X023,X024,X013", "--output-format", "json")
        return sorted((d["code"], Path(str(d["path"])).name, d["line"], str(d["kernel_error"]))
                      for d in json.loads(run.stdout))

    assert found() == []
    y = listen / "achse_y.lis"
    y.write_text(y.read_text().replace("Ende", "lr_param.crosscomp2 1\nEnde", 1))
    startup.write_text(startup.read_text().replace(
        "Ende", "zahl_kw 1\nachs_kw[0] ./listen/kw_y.lis\nachs_kw_log_ax_nr[0] 2\nEnde", 1))
    table = "kw.crosscomp2.table[0][0].correction 5\n"
    kw = listen / "kw_y.lis"
    kw.write_text(f"kopf.achs_nr 2\nkw.crosscomp2.master1_ax_nr 1\nkw.crosscomp2.master2_ax_nr 3\n{table}Ende\n")
    assert found() == [("X024", "kw_y.lis", 3, "P-ERR-70184")]  # axis 3 (C) is rotary
    kw.write_text(f"kopf.achs_nr 2\nkw.crosscomp2.master1_ax_nr 9\n{table}Ende\n")
    assert found() == [("X023", "achse_y.lis", y.read_text().count("\n") - 1, "P-ERR-70182"),  # master 2 unset
                       ("X023", "kw_y.lis", 2, "P-ERR-70182")]  # no axis list has number 9
    kw.write_text(f"kopf.achs_nr 2\nkw.crosscomp2.master1_ax_nr 1\nkw.crosscomp2.master2_ax_nr 2\n{table}Ende\n")
    assert found() == []


def test_feedforward_delays_against_the_interpolator_cycle(tmp_path: Path) -> None:
    """Issue 38: a feedforward delay time (P-AXIS-00390, P-AXIS-00389) an axis list writes at or above
    the cycle of the real-time configuration's CNC_IPO thread is X025 (P-ERR-70348) or X026
    (P-ERR-70349); below it, or without a real-time configuration that names the thread, nothing."""
    import json
    import shutil

    from conftest import zero_cli

    shutil.copytree(FIXTURES / "machine-clean", tmp_path / "m")
    listen = tmp_path / "m" / "listen"
    startup = listen / "hochlauf.lis"

    def found() -> list[tuple[str, str, str, str]]:
        run = zero_cli("lint", "--machine", str(startup), "--select", "X025,X026", "--output-format", "json")
        return sorted((d["code"], Path(str(d["path"])).name, str(d["param_id"]), str(d["kernel_error"]))
                      for d in json.loads(run.stdout))

    x, y = listen / "achse_x.lis", listen / "achse_y.lis"
    x.write_text(x.read_text().replace("Ende", "vorsteuer.acceleration_delay_time 2000\n"
                                       "vorsteuer.velocity_delay_time 500\nEnde", 1))
    y.write_text(y.read_text().replace("Ende", "vorsteuer.velocity_delay_time 3000\nEnde", 1))
    assert found() == []  # no real-time configuration: the interpolator cycle is not known
    (listen / "rtconf.lis").write_text("cycle_time 1000\ntime_slice 1000\nthread[0].name CNC_DEC\n"
                                       "thread[0].cycle 8000\nthread[1].name CNC_IPO\nthread[1].cycle 2000\nEnde\n")
    startup.write_text(startup.read_text().replace("Ende", "rtconf_lis ./listen/rtconf.lis\nEnde", 1))
    assert found() == [("X025", "achse_x.lis", "P-AXIS-00390", "P-ERR-70348"),
                       ("X026", "achse_y.lis", "P-AXIS-00389", "P-ERR-70349")]
    (listen / "rtconf.lis").write_text("cycle_time 1000\nthread[0].name CNC_IPO\nthread[0].cycle 4000\nEnde\n")
    assert found() == []


def test_a_message_whose_reaction_no_page_gives_is_a_warning(registry: Registry) -> None:
    """Issue 38: 110591 (a negative velocity in the friction compensation table) is documented as an
    error message the kernel outputs when it takes over the list, but no page says what it then does:
    the row's `severity = "warning"` makes its rule a warning that says so; a row with a documented
    correction stays an error (110473)."""
    options = LintOptions(select=("K",))
    [friction] = lint_file(FIXTURES / "startup" / "110591" / "fail.lis", registry, options).diagnostics
    assert friction.severity.label == "warning" and RULES[friction.code].severity.label == "warning"
    assert "when it takes over the compensation value list" in friction.message
    assert friction.message.endswith("the documentation does not say what the kernel then uses")
    [jerk] = lint_file(FIXTURES / "startup" / "110473" / "fail.lis", registry, options).diagnostics
    assert jerk.severity.label == "error" and jerk.message.endswith("the kernel sets P-AXIS-00338 to 100")

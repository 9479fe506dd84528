"""zero diff: semantic comparison, units, grouping, defaults, formats, git textconv."""

from __future__ import annotations

import json
import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conftest import FIXTURES, ROOT, builtin_registry, golden
from zero.catalog.registry import Registry
from zero.cli.app import app
from zero.diff import DiffOptions, diff_defaults, diff_sides, read_side
from zero.engine.convert import convert

runner = CliRunner()
D = FIXTURES / "diff"


def side(path: Path, fmt: str = "lis"):  # type: ignore[no-untyped-def]
    return read_side(path.read_bytes(), fmt, str(path), builtin_registry())


def test_reordered_and_recommented_lists_do_not_differ(registry: Registry) -> None:
    changes = diff_sides(side(D / "base.lis"), side(D / "reordered.lis"), registry)
    assert changes == []
    result = runner.invoke(app, ["diff", str(D / "base.lis"), str(D / "reordered.lis")])
    assert result.exit_code == 0 and result.output == ""


def test_comments_count_when_asked(registry: Registry) -> None:
    changes = diff_sides(side(D / "base.lis"), side(D / "reordered.lis"), registry, DiffOptions(comments=True))
    assert {c.kind for c in changes} == {"comment"}
    assert "np_grp[1].achse[1].versch" in {c.key for c in changes}
    code = runner.invoke(app, ["diff", "--comments", str(D / "base.lis"), str(D / "reordered.lis")]).exit_code
    assert code == 1


def test_changed_offset_added_and_removed_groups_golden(registry: Registry, request: pytest.FixtureRequest) -> None:
    changes = diff_sides(side(D / "base.lis"), side(D / "changed.lis"), registry)
    actual = [c.to_json() for c in changes]
    expected = golden(D / "changed.expected.json", actual, request.config.getoption("--update-golden"))
    assert actual == expected
    first = changes[0]
    assert (first.key, first.param_id, first.old, first.new, first.delta, first.unit) == (
        "np_grp[1].achse[0].versch", "P-ZERO-00003", "100000", "110000", 1.0, "mm or °")
    assert [c.group for c in changes] == ["G54 (G159=1)", "G55 (G159=2)", "G55 (G159=2)",
                                          "G159=7", "G159=7", "G159=7"]


def test_text_output_golden(request: pytest.FixtureRequest) -> None:
    result = runner.invoke(app, ["diff", "fixtures/diff/base.lis", "fixtures/diff/changed.lis"],
                           env={"NO_COLOR": "1"})
    assert result.exit_code == 1
    path = D / "changed.expected.txt"
    if request.config.getoption("--update-golden"):
        path.write_text(result.output, encoding="utf-8")
    assert result.output == path.read_text(encoding="utf-8")
    assert "np_grp[1].achse[0].versch  P-ZERO-00003  100000 → 110000  +1.0000 mm or °" in result.output


def test_default_versus_absent_only_with_strict(registry: Registry) -> None:
    a, b = side(D / "base.lis"), side(D / "changed.lis")
    key = "np_grp[0].achse[2].inaktiv"
    assert key not in {c.key for c in diff_sides(a, b, registry)}
    strict = [c for c in diff_sides(a, b, registry, DiffOptions(strict=True)) if c.key == key]
    assert len(strict) == 1 and strict[0].kind == "same"


def test_defaults_shows_what_the_machine_changed(registry: Registry) -> None:
    changes = diff_defaults(side(D / "base.lis"), registry)
    keys = [c.key for c in changes]
    assert "np_grp[1].achse[0].versch" in keys
    assert "np_grp[0].achse[0].versch" not in keys  # 0 is the default
    assert "np_grp[1].achse[2].inaktiv" not in keys
    result = runner.invoke(app, ["diff", "--defaults", str(D / "base.lis"), "--output-format", "json"])
    assert result.exit_code == 1
    assert {c["key"] for c in json.loads(result.output)} == set(keys)


@pytest.mark.parametrize("fmt", ["yaml", "toml", "json"])
def test_list_and_its_structured_form_do_not_differ(registry: Registry, tmp_path: Path, fmt: str) -> None:
    data = (D / "base.lis").read_bytes()
    target = tmp_path / f"base.{fmt}"
    target.write_bytes(convert(data, "lis", fmt, registry, "base.lis").output)
    result = runner.invoke(app, ["diff", str(D / "base.lis"), str(target)])
    assert result.exit_code == 0, result.output
    assert diff_sides(side(D / "base.lis"), side(D / "hand.yaml", "yaml"), registry) == []


def test_axis_unit_from_the_axis_type(registry: Registry, corpus: Path) -> None:
    axis = (corpus / "isg-sdk" / "listen" / "achsmds1.lis").read_bytes()
    changed = axis.replace(b"kenngr.swe_pos                                        15000000",
                           b"kenngr.swe_pos                                        15010000")
    assert changed != axis
    changes = diff_sides(read_side(axis, "lis", "a.lis", registry), read_side(changed, "lis", "b.lis", registry),
                         registry)
    assert [(c.key, c.delta, c.unit) for c in changes] == [("kenngr.swe_pos", 1.0, "mm")]
    rotary = changed.replace(b"kenngr.achs_typ                                       1",
                             b"kenngr.achs_typ                                       2")
    c = [x for x in diff_sides(read_side(axis, "lis", "a.lis", registry), read_side(rotary, "lis", "b.lis", registry),
                               registry)
         if x.key == "kenngr.swe_pos"]
    assert c[0].unit == "°"


def test_errors_exit_2(tmp_path: Path) -> None:
    assert runner.invoke(app, ["diff", str(D / "base.lis"), str(tmp_path / "nope.lis")]).exit_code == 2
    bad = tmp_path / "bad.yaml"
    bad.write_text("a: &x 1\n")
    assert runner.invoke(app, ["diff", str(D / "base.lis"), str(bad)]).exit_code == 2
    assert runner.invoke(app, ["diff", str(D / "base.lis")]).exit_code == 2
    assert runner.invoke(app, ["diff", "--defaults", str(D / "base.lis"), str(D / "base.lis")]).exit_code == 2


def test_stdin_side() -> None:
    data = (D / "changed.lis").read_bytes()
    result = runner.invoke(app, ["diff", str(D / "base.lis"), "-"], input=data)
    assert result.exit_code == 1 and "110000" in result.output


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("git") is None, reason="git not installed")
def test_git_textconv_shows_the_semantic_view(tmp_path: Path) -> None:
    env = {**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@example.invalid",
           "GIT_COMMITTER_NAME": "t", "GIT_COMMITTER_EMAIL": "t@example.invalid",
           "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1", "NO_COLOR": "1"}

    def git(*args: str) -> str:
        return subprocess.run(["git", *args], cwd=tmp_path, env=env, check=True,
                              capture_output=True, text=True).stdout

    git("init", "-q")
    git("config", "diff.zero.textconv", f"{shlex.quote(sys.executable)} -m zero show")
    (tmp_path / ".gitattributes").write_text("*.lis diff=zero\n")
    target = tmp_path / "nullp.lis"
    target.write_bytes((D / "base.lis").read_bytes())
    git("add", ".")
    git("commit", "-q", "-m", "base")
    target.write_bytes((D / "changed.lis").read_bytes())
    git("commit", "-q", "-am", "re-clamped")
    out = git("diff", "HEAD~1", "HEAD")
    assert "-np_grp[1].achse[0].versch = 100000  (P-ZERO-00003, 10.0000 mm or °)" in out
    assert "+np_grp[1].achse[0].versch = 110000  (P-ZERO-00003, 11.0000 mm or °)" in out
    assert "+[G159=7]" in out
    assert "# G54: vice" not in out  # comments are not part of the view
    log = git("log", "-p", "-1")
    assert "+np_grp[7].achse[3].versch = 900000" in log


def test_two_full_zero_lists_one_change(registry: Registry) -> None:
    sys.path.insert(0, str(ROOT / "benchmarks"))
    from workloads import full_zero_list

    a = full_zero_list()
    b = a.replace(b"np_grp[50].achse[3].versch                            50003",
                  b"np_grp[50].achse[3].versch                            60003")
    assert a != b
    changes = diff_sides(read_side(a, "lis", "a.lis", registry), read_side(b, "lis", "b.lis", registry), registry)
    assert [(c.key, c.delta) for c in changes] == [("np_grp[50].achse[3].versch", 1.0)]


def test_enumerations_and_bit_masks_get_no_arithmetic(registry: Registry) -> None:
    a = read_side(b"kenngr.antr_typ 8\nkenngr.achs_mode 0x400001\nkenngr.swe_pos 100\n", "lis", "a.lis", registry,
                  "AXIS")
    b = read_side(b"kenngr.antr_typ 2\nkenngr.achs_mode 0x000001\nkenngr.swe_pos 200\n", "lis", "b.lis", registry,
                  "AXIS")
    by_key = {c.key: c for c in diff_sides(a, b, registry)}
    assert (by_key["kenngr.antr_typ"].delta, by_key["kenngr.antr_typ"].coding) == (None, "symbol")
    achs_mode = by_key["kenngr.achs_mode"]  # tests/test_diff_values.py: how each kind of value reads
    assert (achs_mode.delta, achs_mode.coding, achs_mode.bits) == (None, "bits", ((), ("bit 22 (0x400000)",)))
    assert by_key["kenngr.swe_pos"].delta == 0.01


def test_a_default_in_exponent_notation_is_shown_as_a_number(registry: Registry) -> None:
    spec = registry.get("P-AXIS-00067")
    assert spec is not None and spec.default == "3.000000e+001" and spec.default_display == "30"


@pytest.mark.parametrize("axis_type", ["2", "ACHSTYP_ROTATOR", "0x2", "4"])
def test_the_unit_of_a_rotary_axis_is_degrees_however_its_type_is_written(registry: Registry, axis_type: str) -> None:
    """One decision for rotary or linear (zero.catalog.ids.is_rotary): diff, hover, the rules and
    the machine model read `kenngr.achs_typ` alike, its symbols included."""
    old = read_side(f"kenngr.achs_typ {axis_type}\nkenngr.swe_pos 3600000\nEnde\n".encode(), "lis", "a.lis", registry)
    new = read_side(f"kenngr.achs_typ {axis_type}\nkenngr.swe_pos 1800000\nEnde\n".encode(), "lis", "b.lis", registry)
    [change] = diff_sides(old, new, registry)
    assert (change.unit, change.delta) == ("°", -180.0)
    translator = read_side(b"kenngr.achs_typ ACHSTYP_TRANSLATOR\nkenngr.swe_pos 1\nEnde\n", "lis", "a", registry)
    [linear] = diff_sides(translator, read_side(b"kenngr.achs_typ 1\nkenngr.swe_pos 2\nEnde\n", "lis", "b", registry),
                          registry)
    assert linear.unit == "mm"

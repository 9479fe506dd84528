"""What one list's lint leaves unloaded (issue 40, start-up): the configuration's declarations where no
configuration file applies, and the K table where no K finding is reported; each is loaded where it is needed."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import pytest

from conftest import FIXTURES, zero_modules


def _run(folder: Path) -> tuple[str, set[str], int]:
    env = {**os.environ, "ZERO_NO_CACHE": "1"}
    report, modules, table = zero_modules(
        "lint", "--exit-zero", "--output-format", "json", "lists", cwd=folder, env=env,
        probe='__import__("zero.rules.lists", fromlist=["kernel_rules"]).kernel_rules.cache_info().currsize')
    return report, modules, int(table)


def _settled(lst: Path, cache_dir: Path, cache: bool) -> dict[str, str]:
    """The environment of a run with the cache in ``cache_dir`` (or none), ``lst`` made long settled (the cache
    keeps the result of a file that is not still being written)."""
    old = 10**9 * 1_600_000_000
    os.utime(lst, ns=(old, old))
    env = {k: v for k, v in os.environ.items() if k != "ZERO_NO_CACHE"}
    env["ZERO_CACHE_DIR"] = str(cache_dir)
    if not cache:
        env["ZERO_NO_CACHE"] = "1"
    return env


@pytest.mark.parametrize("config", [None, 'ignore = ["R"]\n'])
def test_the_declarations_are_read_only_with_a_configuration(tmp_path: Path, config: str | None) -> None:
    lists = tmp_path / "lists"
    lists.mkdir()
    (lists / "achse.lis").write_text("kopf.achs_nr 1\nkenngr.swe_pos 5000000000\nEnde\n", encoding="utf-8")
    if config is not None:
        (tmp_path / "zero.toml").write_text(config, encoding="utf-8")
    report, loaded, _ = _run(tmp_path)
    assert ("zero.engine.config_file" in loaded) == (config is not None)
    assert ('"code": "R' in report) == (config is None)  # the configuration read is the one applied


@pytest.mark.parametrize("k_finding", [False, True])
def test_the_k_table_is_built_only_for_a_k_finding(tmp_path: Path, k_finding: bool) -> None:
    lists = tmp_path / "lists"
    lists.mkdir()
    # issue 26's planted start-up faults (K032, K075, K074), or a list with findings but none of them K
    planted = (FIXTURES / "kernel" / "planted_spindle.lis").read_bytes()
    (lists / "achse.lis").write_bytes(planted if k_finding else b"kopf.achs_nr 1\nkenngr.swe_pos 5000000000\nEnde\n")
    report, _, table = _run(tmp_path)
    assert '"code": "R' in report
    assert ('"code": "K074"' in report) == k_finding
    assert (table > 0) == k_finding


@pytest.mark.parametrize("cache", [False, True])
@pytest.mark.parametrize("command", ["lint", "diff --fleet"])
def test_a_lint_and_a_fleet_diff_import_no_typing(tmp_path: Path, command: str, cache: bool) -> None:
    """typing is a twentieth of a list's lint at start-up; annotations are strings that only type
    checkers read (zero.hints holds the few run-time names), so neither command, cold or from the cache,
    loads it. A module that imports typing at run time on these paths fails here."""
    for name in ("m001", "m002"):  # a fleet of two copies of the clean fixture machine
        shutil.copytree(FIXTURES / "machine-clean", tmp_path / "fleet" / name)
    startup = tmp_path / "fleet" / "m001" / "listen" / "hochlauf.lis"
    args = (["lint", "--exit-zero", "--output-format", "json", str(startup)] if command == "lint"
            else ["diff", "--fleet", str(startup), str(tmp_path / "fleet"), "--output-format", "json"])
    env = {k: v for k, v in os.environ.items() if k != "ZERO_NO_CACHE"}
    env["ZERO_CACHE_DIR"] = str(tmp_path / "cache")
    if not cache:
        env["ZERO_NO_CACHE"] = "1"
    for _ in range(2 if cache else 1):  # the second run answers from the cache
        report, modules, _ = zero_modules(*args, cwd=tmp_path, env=env)
    answer = json.loads(report)
    if command == "lint":
        assert isinstance(answer, list)
    else:  # the other machine compared with the golden one
        assert [Path(m).parts[-3] for m in answer["machines"]] == ["m002"]
    assert "zero.cli.run" in modules
    assert "typing" not in modules
    if command == "lint":  # the JSON report escapes with json's C function, without the json package (and re)
        assert not {"json", "re"} & modules


@pytest.mark.parametrize("config", [None, 'select = ["R"]\nignore = ["R009"]\n'])
@pytest.mark.parametrize("cache", [False, True])
@pytest.mark.parametrize("named", ["lists/achse.lis", "./lists/", "lists"])
def test_a_lint_imports_no_pathlib(tmp_path: Path, named: str, cache: bool, config: str | None) -> None:
    """pathlib, with the urllib.parse and ipaddress it imports, is 7% of one list's lint at start-up: the lint
    path names files by their text (zero.files.path_str prints them as a Path would), so neither a list nor a
    folder (walked, .gitignore asked), cold or from the cache, with a configuration file or without, loads
    it; the names printed are a Path's. (A configuration's pattern imports pathspec, which imports it.)"""
    lists = tmp_path / "lists"
    lists.mkdir()
    if config is not None:
        (tmp_path / "zero.toml").write_text(config, encoding="utf-8")
    (lists / "achse.lis").write_text("kopf.achs_nr 1\nkenngr.swe_pos 5000000000\nEnde\n", encoding="utf-8")
    env = _settled(lists / "achse.lis", tmp_path / "cache", cache)
    for _ in range(2 if cache else 1):  # the second run answers from the cache
        report, modules, _ = zero_modules("lint", "--exit-zero", "--output-format", "json", named, cwd=tmp_path,
                                          env=env)
    assert {d["path"] for d in json.loads(report)} == {os.path.join("lists", "achse.lis")}
    assert "zero.engine.discovery" in modules
    assert ("zero.engine.cache" in modules) == cache
    assert ("zero.engine.config_file" in modules) == (config is not None)
    assert not {"pathlib", "urllib.parse", "ipaddress"} & modules


@pytest.mark.parametrize("cache", [False, True])
def test_a_lint_imports_no_re_enum_or_extension_module(tmp_path: Path, cache: bool) -> None:
    """``re`` with ``enum`` (seven modules) was a third of the standard library a list's lint loaded, and ``math``,
    ``array`` and ``_bisect`` are extension modules (a shared library to load each): patterns come from the code
    written at build time (zero.patterns), Severity is no enum, no value needs math, a small list's columns are
    lists and the catalogue's indexes dictionaries. A list with findings of the common kinds, the text report,
    cold or answered from the cache (a cache written the first time: writing it may load more)."""
    lists = tmp_path / "lists"
    lists.mkdir()
    (lists / "achse.lis").write_text(
        "# axis\nkopf.achs_nr 1  ( P-AXIS-00016 : logical axis number\nkopf.log_achs_name X_Achse\n"
        "kenngr.swe_pos 5000000000  # zero: noqa: R003\nkenngr.swe_neg  -1.5e400 x\nkenngr.homing_type 1\nEnde\n",
        encoding="utf-8")
    env = _settled(lists / "achse.lis", tmp_path / "cache", cache)
    for _ in range(2 if cache else 1):  # the second run answers from the cache
        report, modules, _ = zero_modules("lint", "--exit-zero", "lists", cwd=tmp_path, env=env)
    assert "R00" in report and "checked" in report
    assert ("zero.engine.cache" in modules) == cache
    assert {"re", "enum", "math", "array", "_bisect"} & modules == set()


_UNMADE = ("(__import__('zero.rules.families', fromlist=['x']).__dict__.get('RULES') is None, "
           "[f.letter for f in __import__('zero.rules.families', fromlist=['x']).FAMILIES if f._later is not None])")


@pytest.mark.parametrize("k_finding", [False, True])
def test_a_lint_makes_no_k_x_or_n_rule(tmp_path: Path, k_finding: bool) -> None:
    """The registry's K, X and N rules (their names and texts) are made at the first look at them (``zero
    rule``, the docs, SARIF): a list's lint, K findings and all, reads only their codes and severities."""
    lists = tmp_path / "lists"
    lists.mkdir()
    planted = (FIXTURES / "kernel" / "planted_spindle.lis").read_bytes()
    (lists / "achse.lis").write_bytes(planted if k_finding else b"kopf.achs_nr 1\nkenngr.swe_pos 5000000000\nEnde\n")
    env = {**os.environ, "ZERO_NO_CACHE": "1"}
    report, _, unmade = zero_modules("lint", "--exit-zero", "--output-format", "json", "lists", cwd=tmp_path,
                                     env=env, probe=_UNMADE)
    assert ('"code": "K074"' in report) == k_finding
    assert '"severity": "error"' in report
    assert unmade == "(True, ['K', 'X', 'N'])"


@pytest.mark.parametrize("typo", ["kenngr.swe_poss 1", "foo_bar 1", "kenngr.homing_typ 1"])
def test_a_typo_loads_neither_difflib_nor_re_nor_another_kinds_table(tmp_path: Path, typo: str) -> None:
    """A mistyped key (a commit hook's commonest finding) took a lint of an axis list from 128 M to 172 M
    instructions: did-you-mean imported difflib, which imports and compiles with re, and scanned every kind's
    table for a list of a known kind; the header's kernel release was looked for by building every entry.
    The proposal is zero.nearest's, over the kind's own keys; the finding is the one it was."""
    lists = tmp_path / "lists"
    lists.mkdir()
    (lists / "achse.lis").write_text(f"# an axis\nkopf.achs_nr 1\n{typo}\nkenngr.swe_pos 5000000\nEnde\n",
                                     encoding="utf-8")
    env = {**os.environ, "ZERO_NO_CACHE": "1"}
    report, modules, _ = zero_modules("lint", "--exit-zero", "lists", cwd=tmp_path, env=env)  # text: json imports re
    assert "lists/achse.lis:3:1: R001 error unknown key" in report
    assert report.count(": R0") == 1
    assert ("did you mean `kenngr.swe_pos`?" in report) == typo.startswith("kenngr.swe_poss")
    assert "zero.nearest" in modules
    assert not {"difflib", "re"} & modules
    assert sorted(m for m in modules if m.startswith("zero.catalog.data.table_")) == ["zero.catalog.data.table_axis"]

"""Every schema `zero schema` writes loads in taplo (Even Better TOML) and in any JSON reader of
64-bit numbers: no integer beyond i64, no number a double cannot hold (issue 27: the REAL64 limit
was written as a 309-digit integer, and taplo failed "number out of range")."""

from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import jsonschema
import pytest

from conftest import builtin_registry
from zero.catalog.registry import KINDS
from zero.structured.schema import build_schema

ALL_KINDS: list[str | None] = [None, *sorted(KINDS)]
I64_MIN, I64_MAX = -(2**63), 2**63 - 1
NUMERIC = {"minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum", "const", "default", "enum",
           "maxLength", "minLength", "multipleOf"}


def numbers(node: Any, keyword: str = "") -> Iterator[tuple[str, Any]]:
    """(keyword, number) for every number in a schema (items of ``enum`` under ``enum``)."""
    stack = [(keyword, node)]
    while stack:
        key, n = stack.pop()
        if isinstance(n, dict):
            stack.extend(n.items())
        elif isinstance(n, list):
            stack.extend((key, x) for x in n)
        elif isinstance(n, (int, float)) and not isinstance(n, bool):
            yield key, n


@pytest.mark.parametrize("kind", ALL_KINDS, ids=lambda k: k or "all")
def test_every_number_fits_a_double_or_an_i64(kind: str | None) -> None:
    text = json.dumps(build_schema(builtin_registry(), kind))  # as `zero schema` writes it
    seen = 0

    def check_int(s: str) -> int:
        n = int(s)
        assert I64_MIN <= n <= I64_MAX, f"integer {s[:30]}… ({len(s)} digits) is beyond i64"
        return n

    def check_float(s: str) -> float:
        x = float(s)
        assert math.isfinite(x), s
        return x

    # read back with the checks a reader of 64-bit numbers makes (serde_json, taplo)
    schema = json.loads(text, parse_int=check_int, parse_float=check_float, parse_constant=pytest.fail)
    for keyword, _value in numbers(schema):
        seen += keyword in NUMERIC
    assert seen
    jsonschema.Draft202012Validator.check_schema(schema)


@pytest.mark.parametrize("kind", ["AXIS", "CHAN", "TOOL", "SECO", None], ids=lambda k: k or "all")
def test_real64_limits_are_doubles_in_exponent_form(kind: str | None) -> None:
    text = json.dumps(build_schema(builtin_registry(), kind))
    assert "1.7976931348623157e+308" in text
    assert "179769313486231570814527423731704356798070567525844996598917476803157" not in text


def test_uns64_maximum_admits_every_uns64_and_nothing_a_double_cannot_tell_apart() -> None:
    """UNS64's maximum 2**64-1 is beyond i64: written as the double 2**64, the nearest above, so no
    validator (exact integers or doubles) refuses a valid value; `zero lint` reports 2**64 (R004)."""
    schema = build_schema(builtin_registry(), "STUP")
    leaf = schema["properties"]["digital_driver_adr"]["anyOf"][0]
    bound = next(v for k, v in numbers(leaf) if k == "maximum")
    assert isinstance(bound, float) and bound == 2.0**64
    validator = jsonschema.Draft202012Validator(schema)
    assert list(validator.iter_errors({"digital_driver_adr": 2**64 - 1})) == []
    assert list(validator.iter_errors({"digital_driver_adr": -1}))


# ----------------------------------------------------------------------- taplo itself


def taplo_command() -> list[str] | None:
    """taplo as CI installs it (`npm install --global @taplo/cli`), a `taplo` binary on PATH, or
    the one ZERO_TAPLO names."""
    named = os.environ.get("ZERO_TAPLO")
    if named:
        return [named]
    found = shutil.which("taplo")
    if found:
        return [found]
    npx = shutil.which("npx")
    if npx:
        try:
            probe = subprocess.run([npx, "--no-install", "taplo", "--version"], capture_output=True,
                                   timeout=60, check=False)
        except (OSError, subprocess.TimeoutExpired):
            return None
        if probe.returncode == 0:
            return [npx, "--no-install", "taplo"]
    return None


TAPLO = taplo_command()
needs_taplo = pytest.mark.skipif(TAPLO is None, reason="taplo not installed (npm install --global @taplo/cli)")

# per kind: a table of the TOML form, a valid value, a value the schema refuses
SAMPLES: dict[str | None, tuple[str, str, str, str]] = {
    "ZERO": ("np_grp.1.achse.0", "versch", "1", '"abc"'),
    "AXIS": ("antr", "acc_reference_value", "2.5", "-5.0"),  # REAL64, 0 <= x < DBL_MAX
    "CHAN": ("", "lin_aufloes", "5000.0", "0.0"),  # REAL64, 0 < x < DBL_MAX
    "STUP": ("", "digital_driver_adr", "9223372036854775807", "-1"),  # UNS64
    None: ("antr", "acc_reference_value", "2.5", "-5.0"),
}


def name(kind: str | None) -> str:
    return (kind or "all").lower()


def toml_list(kind: str | None, table: str = "", key: str = "", value: str = "") -> str:
    head = f"[{table}]\n" if table else ""
    entry = f"{key} = {value}\n" if key else ""
    record = f'[_zero]\nzero = 1\nkind = "{kind}"\n' if kind else "[_zero]\nzero = 1\n"
    return f"{head}{entry}{record}"


@pytest.fixture(scope="module")
def taplo_run(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, str, int]:
    """One `taplo check` of a TOML list per kind (only the layout record), and of a valid and a wrong
    value per kind of SAMPLES, each file under its kind's schema by a `.taplo.toml` rule as the
    README sets it up (one run: taplo takes seconds to start)."""
    if TAPLO is None:
        pytest.skip("taplo not installed (npm install --global @taplo/cli)")
    root = tmp_path_factory.mktemp("taplo")
    rules = []
    files: list[str] = []

    def add(file: str, kind: str | None, text: str) -> None:
        (root / file).write_text(text, encoding="utf-8")
        rules.append(f'[[rule]]\ninclude = ["{file}"]\nschema = {{ path = "{name(kind)}.schema.json" }}\n')
        files.append(file)

    for kind in ALL_KINDS:
        (root / f"{name(kind)}.schema.json").write_text(json.dumps(build_schema(builtin_registry(), kind)),
                                                         encoding="utf-8")
        add(f"{name(kind)}-empty.toml", kind, toml_list(kind))
    for kind, (table, key, good, bad) in SAMPLES.items():
        add(f"{name(kind)}-good.toml", kind, toml_list(kind, table, key, good))
        add(f"{name(kind)}-bad.toml", kind, toml_list(kind, table, key, bad))
    (root / ".taplo.toml").write_text("\n".join(rules), encoding="utf-8")
    run = subprocess.run([*TAPLO, "check", "--config", str(root / ".taplo.toml"), *files],
                         capture_output=True, text=True, timeout=600, cwd=root, check=False)
    return root, run.stderr, run.returncode


@needs_taplo
@pytest.mark.slow
def test_taplo_loads_the_schema_of_every_kind(taplo_run: tuple[Path, str, int]) -> None:
    _, stderr, _ = taplo_run
    assert "out of range" not in stderr, stderr
    assert "failed to load schema" not in stderr, stderr
    assert "failed to fetch schema" not in stderr, stderr
    for kind in ALL_KINDS:
        assert f"{name(kind)}-empty.toml" not in stderr, stderr


@needs_taplo
@pytest.mark.slow
@pytest.mark.parametrize("kind", list(SAMPLES), ids=name)
def test_taplo_checks_a_toml_list_with_the_schema(kind: str | None, taplo_run: tuple[Path, str, int]) -> None:
    _, stderr, code = taplo_run
    assert code != 0  # the wrong values
    assert f"{name(kind)}-good.toml" not in stderr, stderr
    assert f"{name(kind)}-bad.toml:" in stderr, stderr  # a finding at a line of the file

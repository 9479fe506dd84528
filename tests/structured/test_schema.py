"""zero schema: a valid draft 2020-12 schema that agrees with zero lint."""

from __future__ import annotations

import json
import re
from pathlib import Path

import jsonschema
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import FIXTURES, builtin_registry
from zero.catalog.registry import Registry
from zero.engine.convert import convert
from zero.engine.lint import lint_bytes
from zero.rules.base import Context
from zero.rules.registry import not_configured
from zero.structured.schema import build_schema, int_range_regex

SEED = FIXTURES / "seed" / "nullp_3achsen.lis"


def validator(kind: str | None) -> jsonschema.Draft202012Validator:
    schema = build_schema(builtin_registry(), kind)
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def as_json(data: bytes, path: str) -> dict[str, object]:
    result: dict[str, object] = json.loads(convert(data, "lis", "json", builtin_registry(), path).output)
    return result


@pytest.mark.slow
def test_every_kind_gives_a_valid_schema() -> None:
    """Each schema passes the 2020-12 meta-schema (check_schema raises otherwise) and describes the
    list's top-level keys, closed to others."""
    for kind in [None, "ZERO", "AXIS", "CHAN", "TOOL", "STUP", "RTCF"]:
        schema = validator(kind).schema
        assert schema["type"] == "object" and schema["properties"] and "additionalProperties" in schema, kind


def test_seed_example_is_valid_and_wrong_values_fail() -> None:
    v = validator("ZERO")
    data = as_json(SEED.read_bytes(), str(SEED))
    assert list(v.iter_errors(data)) == []
    group = data["np_grp"]["1"]["achse"]["0"]  # type: ignore[index]
    for bad in ["abc", 2**31, 1.5, True]:
        group["versch"] = bad
        assert list(v.iter_errors(data)), bad
    group["versch"] = "0x10"
    assert list(v.iter_errors(data)) == []
    data["np_grp"]["97"] = {"achse": {"0": {"versch": 1}}}  # type: ignore[index]
    group["versch"] = 1
    errors = list(v.iter_errors(data))
    assert len(errors) == 1 and "97" in errors[0].message
    del data["np_grp"]["97"]  # type: ignore[attr-defined]
    data["np_grp"]["1"]["achse"]["0"]["versh"] = 1  # type: ignore[index]
    assert "versh" in next(v.iter_errors(data)).message


@pytest.mark.slow
def test_corpus_fails_the_schema_exactly_where_lint_finds_unknown_keys_or_ranges(registry: Registry,
                                                                                 corpus: Path) -> None:
    validators: dict[str | None, jsonschema.Draft202012Validator] = {}
    checked = 0
    for path in sorted((corpus / "isg-sdk" / "listen").rglob("*.lis")):
        raw = path.read_bytes()
        data = as_json(raw, str(path))
        kind = data["_zero"].get("kind")  # type: ignore[attr-defined]
        if kind not in validators:
            validators[kind] = validator(kind)
        schema_keys = set()
        for e in validators[kind].iter_errors(data):
            where = ".".join(str(p) for p in e.absolute_path)
            m = re.search(r"\('(\w+)' was unexpected\)", e.message)
            schema_keys.add(f"{where}.{m.group(1)}".lstrip(".") if m else where)
        result = lint_bytes(raw, registry, str(path))
        # An element beyond its count (`spindel[0]` with `spdl_anzahl 0`) is not checked by zero lint; a
        # schema cannot see the count, so it still refuses the value.
        ctx = Context.of(result.document, registry, result.kind)
        for res in ctx.resolved:
            if not_configured(ctx, res):
                schema_keys.discard(re.sub(r"\[(\d+)\]", r".\1", res.entry.key_text))
        lint_keys = set()
        for d in result.diagnostics:
            if d.code in ("R001", "R004", "R005"):
                line = result.document.lines[d.span.line - 1]
                key = line.split()[0]
                lint_keys.add(re.sub(r"\[(\d+)\]", r".\1", key))
        assert schema_keys == lint_keys, path
        checked += 1
    assert checked == 21


def test_index_patterns_are_exact(registry: Registry) -> None:
    schema = build_schema(registry, "ZERO")
    pattern = next(iter(schema["properties"]["np_grp"]["patternProperties"]))
    assert re.fullmatch(pattern, "96") and re.fullmatch(pattern, "0")
    assert not re.fullmatch(pattern, "97") and not re.fullmatch(pattern, "01")
    tool = build_schema(registry, "TOOL")
    wz = next(iter(tool["properties"]["wz"]["patternProperties"]))
    assert not re.fullmatch(wz, "0") and re.fullmatch(wz, "1")


@settings(max_examples=300, deadline=None)
@given(st.integers(0, 5000), st.integers(0, 5000))
def test_int_range_regex_matches_exactly_the_range(a: int, b: int) -> None:
    lo, hi = min(a, b), max(a, b)
    rx = re.compile(f"(?:{int_range_regex(lo, hi)})")
    for n in {0, lo - 1, lo, lo + 1, (lo + hi) // 2, hi - 1, hi, hi + 1, hi * 10, 10**len(str(hi))}:
        if n >= 0:
            assert bool(rx.fullmatch(str(n))) == (lo <= n <= hi), (lo, hi, n)
    assert not rx.fullmatch("0" + str(hi))


def test_schema_command_and_editor_settings(tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from zero.cli.app import app

    runner = CliRunner()
    out = runner.invoke(app, ["schema", "--kind", "zero"])
    assert out.exit_code == 0
    assert json.loads(out.output)["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    target = tmp_path / "zero.schema.json"
    assert runner.invoke(app, ["schema", "--kind", "zero", "-o", str(target)]).exit_code == 0
    assert runner.invoke(app, ["schema", "-o", str(target)]).exit_code == 2  # exists
    loose = json.loads(runner.invoke(app, ["schema", "--kind", "zero", "--allow-unknown"]).output)
    jsonschema.validate({"np_grp": {"1": {"achse": {"0": {"other": 1}}}}}, loose)
    assert runner.invoke(app, ["schema", "--kind", "nope"]).exit_code == 2


@pytest.mark.parametrize("kind", ["AXIS", "CHAN"])
def test_aliases_are_admitted(registry: Registry, kind: str) -> None:
    reg = registry
    aliases = [p for (k, p) in reg.aliases if k == kind]
    if not aliases:
        pytest.skip(f"no alias for {kind}")
    schema = build_schema(reg, kind)
    first = aliases[0].split(".")[0].split("[")[0]
    assert first in schema["properties"]


@pytest.mark.slow
def test_the_structured_form_of_every_corpus_xml_list_is_valid(corpus: Path) -> None:
    """The XML lines an XML list's structured form carries are comments: the schema of its kind takes
    it as it takes a list's (the vendor's templates, whose findings are of values, not of keys)."""
    validators: dict[str | None, jsonschema.Draft202012Validator] = {}
    for path in sorted((corpus / "isg-sdk" / "xml").rglob("*.xml")):
        data = json.loads(convert(path.read_bytes(), "xml", "json", builtin_registry(), str(path)).output)
        kind = data["_zero"].get("kind")
        if kind not in validators:
            validators[kind] = validator(kind)
        bad = [".".join(str(p) for p in e.absolute_path) for e in validators[kind].iter_errors(data)]
        assert all(not where.startswith("_zero") for where in bad), (path.name, bad)
        assert len(bad) <= 3, (path.name, bad)  # the values `zero lint` reports (R004/R005), never a key

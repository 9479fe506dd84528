"""Severity without enum (issue 40, start-up: importing enum was ~8 M instructions of a list's lint): an int
subclass that behaves, wherever zero and its users use it, as the ``enum.IntEnum`` it was. Each behaviour is
checked against a reference IntEnum of the same members, on Python 3.11's rules."""

from __future__ import annotations

import ast
import enum
import json
import operator
import pickle
import subprocess
import sys
from collections.abc import Callable
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import ROOT, assert_stays_itself
from zero.diagnostics import Diagnostic, Severity, Span
from zero.engine.cache import _canonical, fingerprint

Reference = enum.IntEnum("Severity", [("INFO", 1), ("WARNING", 2), ("ERROR", 3)])  # type: ignore[misc]
NAMES = ("INFO", "WARNING", "ERROR")
MEMBERS = [Severity.INFO, Severity.WARNING, Severity.ERROR]
PAIRS = [(Severity[n], Reference[n]) for n in NAMES]


def test_the_members_are_the_ints_1_2_3_with_their_names() -> None:
    assert [(s.name, s.value, s.label, int(s)) for s in MEMBERS] == [
        ("INFO", 1, "info", 1), ("WARNING", 2, "warning", 2), ("ERROR", 3, "error", 3)]
    for s in MEMBERS:
        assert isinstance(s, int) and type(s) is Severity
        assert type(s.value) is int and type(int(s)) is int
        assert s == s.value and hash(s) == hash(s.value)
    assert Severity.__module__ == "zero.diagnostics" and Severity.__qualname__ == "Severity"


@pytest.mark.parametrize(("ours", "reference"), PAIRS)
def test_repr_str_and_format_are_intenums(ours: Severity, reference: enum.IntEnum) -> None:
    assert repr(ours) == repr(reference) == f"<Severity.{ours.name}: {ours.value}>"
    assert str(ours) == str(reference) == str(ours.value)
    assert f"{ours}|{ours!s}|{ours!r}" == f"{reference}|{reference!s}|{reference!r}"
    template = "%s %d %r %i %x"  # the old style of formatting too
    assert template % ((ours,) * 5) == template % ((reference,) * 5)


FORMAT_SPECS = ["", "d", "n", "x", "X", "#x", "o", "b", "e", "f", ".2f", "%", "+", " ", "05", ">5", "<4", "^7",
                "*^9d", ",", "_", "=+6", "s", "c", "z"]


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(PAIRS), st.sampled_from(FORMAT_SPECS) | st.text(max_size=4))
def test_format_gives_what_intenum_gives(pair: tuple[Severity, enum.IntEnum], spec: str) -> None:
    ours, reference = pair

    def formatted(value: object) -> str:
        try:
            return format(value, spec)
        except (ValueError, TypeError) as exc:
            return f"{type(exc).__name__}: {exc}"

    assert formatted(ours) == formatted(reference)


@given(st.sampled_from(MEMBERS), st.sampled_from(MEMBERS) | st.integers(-5, 5) | st.floats(0, 4))
def test_compared_and_computed_as_ints(s: Severity, other: Severity | int | float) -> None:
    plain = other.value if isinstance(other, Severity) else other
    ops: list[Callable[[Any, Any], object]] = [operator.eq, operator.ne, operator.lt, operator.le, operator.gt,
                                               operator.ge, operator.add, operator.sub]
    for op in ops:
        assert op(s, other) == op(s.value, plain)
    assert (s > other) == (Reference(s.value) > other)


def test_max_sorting_and_dictionaries_work_as_with_ints() -> None:
    assert max(Severity) is Severity.ERROR and min(Severity) is Severity.INFO
    assert max([Severity.WARNING, Severity.INFO]) is Severity.WARNING
    assert sorted([Severity.ERROR, 1, Severity.WARNING]) == [1, 2, 3]
    by_member: dict[int, str] = {Severity.INFO: "i"}
    assert {1: "one", 3: "three"}[Severity.ERROR] == "three" and by_member[1] == "i"
    assert len({1, 2, 3, *Severity}) == 3


def test_json_writes_the_number() -> None:
    value = {"worst": Severity.ERROR, "all": list(Severity), Severity.WARNING: Severity.INFO}
    reference = {"worst": Reference.ERROR, "all": list(Reference), Reference.WARNING: Reference.INFO}
    assert json.dumps(value) == json.dumps(reference) == '{"worst": 3, "all": [1, 2, 3], "2": 1}'
    assert json.dumps(value, indent=1) == json.dumps(reference, indent=1)  # the encoder written in Python


def test_a_diagnostic_writes_the_label() -> None:
    d = Diagnostic("R001", Severity.WARNING, "m", Span(1, 1, 1, 2), "a.lis")
    assert d.to_json()["severity"] == "warning"
    assert d == Diagnostic("R001", Severity(2), "m", Span(1, 1, 1, 2), "a.lis")


def test_parse_takes_a_name_in_any_case() -> None:
    assert [Severity.parse(t) for t in ("error", " Warning\n", "INFO")] == [Severity.ERROR, Severity.WARNING,
                                                                          Severity.INFO]
    for bad in ("", "fatal", "3", "err"):
        with pytest.raises(ValueError, match=r"unknown severity .* \(use error, warning or info\)"):
            Severity.parse(bad)


def test_a_member_by_name() -> None:
    assert [Severity[n] for n in NAMES] == MEMBERS
    assert all(Severity[n] is getattr(Severity, n) for n in NAMES)
    for bad in ("error", "Error", "", "label", "parse", "__class__"):
        with pytest.raises(KeyError) as ours:
            Severity[bad]
        with pytest.raises(KeyError) as reference:
            Reference[bad]
        assert ours.value.args == reference.value.args == (bad,)


@pytest.mark.parametrize("value", [1, 2, 3, 3.0, True, *MEMBERS])
def test_a_member_by_value_is_the_member(value: int) -> None:
    assert Severity(value) is Severity[Reference(value).name]
    assert Severity(Severity(value)) is Severity(value)


@pytest.mark.parametrize("value", [0, 4, -1, 2.5, "3", "ERROR", None, [], b"\x03"])
def test_another_value_is_a_value_error_as_with_intenum(value: object) -> None:
    with pytest.raises(ValueError) as ours:
        Severity(value)  # type: ignore[arg-type]
    with pytest.raises(ValueError) as reference:
        Reference(value)  # type: ignore[arg-type]
    assert str(ours.value) == str(reference.value) == f"{value!r} is not a valid Severity"


def test_iteration_is_in_value_order() -> None:
    assert list(Severity) == [s for s in Severity] == MEMBERS
    assert [s.name for s in Severity] == [r.name for r in Reference]
    assert len(Severity) == 3 and list(reversed(Severity)) == MEMBERS[::-1]
    assert all(s in Severity for s in MEMBERS)
    with pytest.raises(TypeError):  # as Python 3.11's enum: only a member can be asked about
        3 in Severity  # noqa: B015


@pytest.mark.parametrize("member", MEMBERS)
def test_a_member_stays_itself_through_pickle_and_copy(member: Severity) -> None:
    assert_stays_itself(member)


def test_a_pickle_is_the_one_intenum_wrote() -> None:
    """Severity(3) by the class's qualified name, byte for byte as before: pickles written by either load."""
    written_by_intenum = {
        0: b"czero.diagnostics\nSeverity\np0\n(I3\ntp1\nRp2\n.",
        2: b"\x80\x02czero.diagnostics\nSeverity\nq\x00K\x03\x85q\x01Rq\x02.",
        4: b"\x80\x04\x95'\x00\x00\x00\x00\x00\x00\x00\x8c\x10zero.diagnostics\x94\x8c\x08Severity\x94\x93\x94K"
           b"\x03\x85\x94R\x94.",
    }
    for protocol, data in written_by_intenum.items():
        assert pickle.dumps(Severity.ERROR, protocol) == data
        assert pickle.loads(data) is Severity.ERROR


def test_a_member_cannot_be_changed() -> None:
    for name, value in (("name", "FATAL"), ("value", 4), ("label", "fatal"), ("other", 1)):
        with pytest.raises(AttributeError):
            setattr(Severity.ERROR, name, value)
    for name in ("name", "value", "label"):
        with pytest.raises(AttributeError):
            delattr(Severity.ERROR, name)
    with pytest.raises(AttributeError):
        Severity.ERROR = Severity.INFO
    with pytest.raises(AttributeError):
        del Severity.WARNING
    assert (Severity.ERROR.name, Severity.ERROR.value, Severity.ERROR.label) == ("ERROR", 3, "error")
    assert Severity.WARNING is Severity["WARNING"] and list(Severity) == MEMBERS


def test_the_fingerprint_of_a_severity_is_the_one_of_the_enum_member() -> None:
    """The cache's keys are those of zero with the IntEnum (a changed one would only invalidate caches)."""
    assert _canonical(Severity.ERROR) == ("Severity", "ERROR") == _canonical(Reference.ERROR)
    assert _canonical({"R001": Severity.INFO}) == ("dict", (("R001", ("Severity", "INFO")),))
    # written by zero with the IntEnum (commit 49f6491)
    assert fingerprint((Severity.ERROR, [Severity.INFO], {Severity.WARNING: Severity.ERROR})) == \
        "4dcb1ef8d37c6337cb2eda432ab2916a"


class _Colour(enum.Enum):
    RED = "r"


class _Level(enum.IntEnum):
    LOW = 1


def test_other_enumerations_are_fingerprinted_as_before() -> None:
    """Where enum is imported a value can be an enum member zero does not define: by class and name."""
    assert _canonical(_Colour.RED) == ("_Colour", "RED")
    assert _canonical(_Level.LOW) == ("_Level", "LOW")  # not as an int
    assert fingerprint(_Level.LOW) != fingerprint(1)


@pytest.mark.parametrize("module", ["diagnostics.py", "engine/cache.py"])
def test_neither_module_imports_enum(module: str) -> None:
    tree = ast.parse((ROOT / "src" / "zero" / module).read_text(encoding="utf-8"))
    imported = {alias.name for node in ast.walk(tree) if isinstance(node, ast.Import) for alias in node.names}
    imported |= {node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom) and node.module}
    assert "enum" not in imported


def test_importing_the_diagnostics_does_not_import_enum() -> None:
    probe = "import sys, zero.diagnostics; print(sorted(m for m in ('enum', 're', 'typing') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=False,
                         env={"PATH": "", "PYTHONPATH": str(ROOT / "src")})
    assert out.stdout.strip() == "[]", out.stdout + out.stderr

"""Values the catalogue lists in prose (``1 : <meaning>``) are checked like
formal ranges, over every such parameter of the catalogue, and cost the vendor's lists nothing."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import builtin_registry
from zero.catalog.paramdesc import enumeration
from zero.catalog.registry import Registry, load_registry
from zero.engine.lint import lint_bytes, lint_file
from zero.lists.model import format_key

ENUMS = sorted(pid for pid in builtin_registry().specs if builtin_registry().specs[pid].enum)


def _line(registry: Registry, pid: str, value: int) -> tuple[bytes, str]:
    spec = registry.get(pid)
    assert spec is not None and spec.key
    key = format_key(spec.key, [spec.index_base] * spec.key.count("[]"))
    return f"{key} {value}\n".encode(), spec.kind


def test_the_catalogue_has_enumerations() -> None:
    assert len(ENUMS) >= 40
    assert builtin_registry().get("P-AXIS-00020").enum == (1, 2, 3, 4, 5, 6, 7, 8, 16, 32)  # type: ignore[union-attr]


@pytest.mark.parametrize("pid", ENUMS)
def test_every_listed_value_passes_and_others_fail(pid: str, registry: Registry) -> None:
    spec = registry.get(pid)
    assert spec is not None
    for value in spec.enum:
        data, _kind = _line(registry, pid, value)
        assert [d.code for d in lint_bytes(data, registry, "t.lis").diagnostics
                if d.code == "R005"] == [], (pid, value)
    outside = max(spec.enum) * 2 + 1 if spec.enum_flags else max(spec.enum) + 1
    data, _kind = _line(registry, pid, outside)
    found = lint_bytes(data, registry, "t.lis").diagnostics
    codes = [d.code for d in found]
    if str(outside) != (spec.default or "").strip():
        # or the kernel's own start-up error for it, which then says it once (with its number)
        assert "R005" in codes or "R004" in codes or any(d.kernel_error and d.param_id == pid for d in found), \
            (pid, outside, codes)


def test_the_message_names_the_listed_values_and_their_meaning(tmp_path: Path, corpus: Path) -> None:
    own = load_registry(corpus / "isg-sdk" / "meta-data" / "CncParaDesc.xml")
    [finding] = lint_bytes(b"kenngr.antr_typ 9\n", own, "a.lis").diagnostics
    assert finding.code == "R005"
    spec = own.get("P-AXIS-00020")
    assert spec is not None and len(spec.enum_labels) == len(spec.enum)  # the labels come from the user's file
    assert (f"9 is not one of the values the catalogue lists for `kenngr.antr_typ` (1 {spec.enum_labels[0]}, "
            f"2 {spec.enum_labels[1]}") in finding.message
    # a listed value set, not a range: P-ERR-1001138 speaks of a minimum and maximum, so nothing is documented
    assert finding.message.endswith("the documentation lists the allowed values but does not say what the "
                                    "controller does with another one")
    assert finding.severity.label == "warning" and finding.consequence == "undocumented"
    assert "replaces it with the default" not in finding.message


def test_a_default_is_never_predicted(registry: Registry) -> None:
    """No message says the controller puts the default in (issue 36: nothing documents it); a SERCOS-only
    parameter of an axis of another drive type (the catalogue's default 4, simulation) is not used."""
    [finding] = lint_bytes(b"antr.sercos.ident[0].type 3\n", registry, "a.lis").diagnostics
    assert "default 0" not in finding.message and finding.severity.label == "info"
    assert finding.message.endswith("this axis has drive type 4 (the catalogue's default, P-AXIS-00020): the kernel "
                                    "does not use the value")
    [sercos] = lint_bytes(b"kenngr.antr_typ 2\nantr.sercos.ident[0].type 3\n", registry, "a.lis").diagnostics
    assert sercos.severity.label == "warning" and sercos.consequence == "undocumented"


@pytest.mark.parametrize(("text", "expected"), [
    ("0: off\r\n1: on\r\n2: both", ([0, 1, 2], ["off", "on", "both"], False)),
    ("0, 1, 2 where:\n0: a\n1 : b\n2\xa0: c", ([0, 1, 2], ["a", "b", "c"], False)),
    ("0x0040: Status bit 1\n0x0080: Status bit 2", ([64, 128], ["Status bit 1", "Status bit 2"], True)),
    ("1*: with an asterisk\n2*: not read\n3: three", None),  # a form we do not read: not an enumeration
    ("0: a\nsome explanation\n1: b", None),
    ("0: only one", None),
])
def test_enumeration_parser_is_conservative(text: str, expected: object) -> None:
    assert enumeration(text, "UNS16") == expected


def test_no_corpus_list_gains_a_finding_from_enumerations(registry: Registry, corpus: Path) -> None:
    for path in sorted((corpus / "isg-sdk" / "listen").rglob("*.lis")):
        for d in lint_file(path, registry).diagnostics:
            assert "the catalogue lists" not in d.message, (path, d)

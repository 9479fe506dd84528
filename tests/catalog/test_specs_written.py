"""The built-in catalogue's parameters as the registry makes them, written at build time (tools/gen_specs.py,
issue 40: start-up): each written spec is the one its table row and the seed overlay make, and a module
written from another table, overlay or ParamSpec is never read."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest

from zero.catalog import registry as registry_module
from zero.catalog.data import table
from zero.catalog.registry import ParamSpec, SpecTable, load_registry, spec_fields

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(autouse=True)
def _fresh_modules(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each test reads the written modules afresh (the registry keeps them per kind)."""
    monkeypatch.setattr(registry_module, "_SPEC_TABLES", {})


def _overlay_index() -> dict[str, int]:
    return registry_module._overlay().get("index_base", {})  # type: ignore[no-any-return]


def _specs() -> SpecTable:
    specs = load_registry().specs
    assert isinstance(specs, SpecTable)
    return specs


def test_every_kind_of_the_table_has_its_module_in_the_order_of_its_ids() -> None:
    for kind, size in table.SIZES.items():
        written = importlib.import_module(f"zero.catalog.data.specs_{kind.lower()}")
        assert len(written.SPECS) == size == len(registry_module._kind_table(kind).IDS)
        assert (spec_fields(), _overlay_index()) == (written.FIELDS, written.INDEX_BASE)
        assert written.TABLE == registry_module._kind_table(kind).DIGEST


def test_each_written_spec_is_the_one_its_row_and_the_overlay_make() -> None:
    specs = _specs()
    seen = 0
    for kind in table.SIZES:
        for pid in registry_module._kind_table(kind).IDS:
            written = registry_module._written_spec(pid, specs._seeds or {}, specs._index_base)
            assert written is not None, pid
            made = specs.build(pid)
            assert ParamSpec(*written) == made and repr(ParamSpec(*written)) == repr(made), pid
            assert specs[pid] == made
            seen += 1
    assert seen == sum(table.SIZES.values()) > 1700


def test_an_id_the_table_does_not_have_has_no_written_spec() -> None:
    specs = _specs()
    assert registry_module._written_spec(17, {}, {}) is None  # type: ignore[arg-type]
    assert registry_module._written_spec("P-AXIS-99999", specs._seeds or {}, specs._index_base) is None
    assert registry_module._written_spec("P-NONE-00001", specs._seeds or {}, specs._index_base) is None
    assert "P-AXIS-99999" not in specs and specs.get("P-AXIS-99999") is None


@pytest.mark.parametrize("stale", ["TABLE", "FIELDS", "INDEX_BASE"])
def test_a_module_written_from_something_else_is_never_read(monkeypatch: pytest.MonkeyPatch, stale: str) -> None:
    """Another table module, another ParamSpec or other index bases: the specs are made of the rows (slower,
    never wrong)."""
    written = importlib.import_module("zero.catalog.data.specs_axis")
    other = {"TABLE": "0" * 32, "FIELDS": (*spec_fields(), "new"), "INDEX_BASE": {"AXIS:x": 1}}[stale]
    monkeypatch.setattr(written, stale, other)
    specs = _specs()
    pid = registry_module._kind_table("AXIS").IDS[0]
    assert registry_module._written_spec(pid, specs._seeds or {}, specs._index_base) is None
    assert specs[pid] == specs.build(pid)


def test_a_spec_written_with_other_facts_of_the_overlay_is_never_read() -> None:
    """The overlay changed since the module was written (a parameter's facts, or a parameter it did not name):
    that parameter is made of its row and the overlay as they are."""
    specs = _specs()
    seeds = dict(specs._seeds or {})
    seeded = next(pid for pid in seeds if pid.startswith("P-AXIS"))
    plain = next(pid for pid in registry_module._kind_table("AXIS").IDS if pid not in seeds)
    assert registry_module._written_spec(seeded, seeds, specs._index_base) is not None
    changed = {**seeds, seeded: {**seeds[seeded], "default": "12345"}, plain: {"default": "7"}}
    assert registry_module._written_spec(seeded, changed, specs._index_base) is None
    assert registry_module._written_spec(plain, changed, specs._index_base) is None


def test_a_missing_module_makes_the_specs_of_the_rows(monkeypatch: pytest.MonkeyPatch) -> None:
    real = importlib.import_module

    def without_specs(name: str, package: str | None = None) -> object:
        if name.startswith("zero.catalog.data.specs_"):
            raise ModuleNotFoundError(name)
        return real(name, package)

    monkeypatch.setattr(registry_module.importlib, "import_module", without_specs)
    specs = _specs()
    pid = registry_module._kind_table("CHAN").IDS[3]
    assert registry_module._written_spec(pid, specs._seeds or {}, specs._index_base) is None
    assert specs[pid] == specs.build(pid)


def test_a_users_catalogue_never_reads_the_written_specs() -> None:
    """Rows of a user's CncParaDesc.xml (dictionaries): no overlay of the built-in table is handed on."""
    row = {"id": "P-AXIS-00016", "kind": "AXIS", "key": "kopf.achs_nr", "type": "UNS16", "default": "99"}
    built = registry_module.build_registry([row], "user.xml")
    assert isinstance(built.specs, SpecTable) and built.specs._seeds is None
    assert built.specs["P-AXIS-00016"].default == "99"

"""The counts table built per kind is the one built by comparing every pair of keys (issue 40: start-up)."""

from __future__ import annotations

import re

from zero.catalog.registry import SpecTable, _counts, _letters_in_order, load_registry

_COUNT_RE = re.compile(r"(?:^|\.)([a-z]+)_anzahl$")  # a count's key, as a pattern: the reference


def test_counts_per_kind_are_the_counts_of_every_pair() -> None:
    registry = load_registry()
    specs = registry.specs
    triples = list(specs.keys_by_kind()) if isinstance(specs, SpecTable) else \
        [(s.id, s.kind, s.key) for s in specs.values() if s.key]
    want: dict[str, tuple[tuple[str, int], ...]] = {"": ()}
    for count_id, count_kind, count_key in triples:
        m = _COUNT_RE.search(count_key)
        if m is None or not specs[count_id].type.startswith("UNS"):
            continue
        stem, parent = m.group(1), count_key[: m.start(1)]
        for pid, kind, key in triples:
            if kind != count_kind or not key.startswith(parent):
                continue
            first = key[len(parent):].split(".")[0]
            if first.endswith("[]") and first[:-2] != stem and first[0] == stem[0] and \
                    _letters_in_order(stem, first[:-2]):
                want[pid] = (*want.get(pid, ()), (count_id, parent.count("[]")))
    got = _counts(registry)
    assert got == want and len(got) > 10


def test_a_spec_table_gets_as_a_mapping_gets() -> None:
    specs = load_registry().specs
    assert isinstance(specs, SpecTable)
    some = next(iter(specs))
    assert specs.get(some) is specs[some] and specs.get(some) is specs.get(some)
    assert specs.get("P-NONE-00000") is None and specs.get("P-NONE-00000", 5) == 5


def test_counted_by_answers_each_parameter_as_the_whole_table_does() -> None:
    table = _counts(load_registry())
    registry = load_registry()  # a fresh one: counted_by builds its own counts, one parameter at a time
    asked = 0
    for pid in registry.specs:
        spec = registry.specs[pid]
        if spec.dims:
            asked += 1
            assert registry.counted_by(spec) == table.get(pid, ()), pid
    assert asked > 100 and sum(1 for v in table.values() if v) > 10

"""A diff's element keys, bound once per (kind, pattern), are the keys bound per entry (issue 40)."""

from __future__ import annotations

from zero.catalog.registry import load_registry
from zero.catalog.values import bind, canonical_key
from zero.lists.model import Entry, format_key
from zero.lists.tokenizer import tokenize_text

TEXT = ("kenngr.homing_type 1\nkenngr.homing.homing_type 2\nwz[01].laenge 3\nwz[1].laenge 4\n"
        "unknown_key[02].x 5\nkenngr.swe_pos 6\nantr_simu.totzeit 7\n")


def _uncached(registry: object, kind: str | None, entry: Entry) -> str:
    key = entry.key
    if key is None:
        return entry.key_text
    hit = bind(registry, key.pattern, kind)  # type: ignore[arg-type]
    pattern = hit[0].key if hit is not None and hit[0].key else key.pattern
    return format_key(pattern, key.indices)


def test_canonical_keys_per_kind_are_the_keys_bound_per_entry() -> None:
    registry = load_registry()
    entries = tokenize_text(TEXT).entries
    for kind in ("AXIS", "TOOL", None, "AXIS"):  # each kind its own binding, asked twice
        got = [canonical_key(registry, kind, e) for e in entries]
        assert got == [_uncached(registry, kind, e) for e in entries], kind
    assert canonical_key(registry, "AXIS", entries[0]) == "kenngr.homing.homing_type"
    assert canonical_key(registry, "TOOL", entries[2]) == "wz[1].laenge"


def test_bindings_kept_across_lists_bind_as_each_list_alone() -> None:
    from zero.catalog.values import ListValues

    shared = load_registry()
    for text in (TEXT, "kenngr.homing_type 3\nkenngr.swe_neg -5\n", TEXT):
        doc = tokenize_text(text)
        for kind in ("AXIS", "TOOL"):
            got = ListValues.of(doc, shared, kind)
            alone = ListValues.of(doc, load_registry(), kind)  # a registry of its own: nothing kept
            assert [(r.entry.line, r.spec.id, r.via_alias) for r in got.resolved] == \
                [(r.entry.line, r.spec.id, r.via_alias) for r in alone.resolved]

"""A list's entries by documented key, read from its rows (issue 40): the key each row sets (an alias
as the key it stands for, `[01]` as `[1]`) worked out once per key shape, the value texts at hand,
an :class:`~zero.lists.model.Entry` built only where one is asked for. The machine model layers them
(:mod:`zero.machine.effective`), ``zero diff`` compares them (:mod:`zero.diff`)."""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping

from zero.catalog.registry import Registry
from zero.catalog.values import ListValues
from zero.lists.model import Columns, Document, Entry, format_key

_LEADING_ZERO = r"\[0[0-9]"  # `[01]`: a leading zero (canonical_key's test), compiled at its first use


class Rows(Mapping[str, Entry]):
    """Documented key → the entry the controller uses, read from the rows of a list's columns (issue 40):
    each key's value text at hand (``texts``, in the order the keys are first set), the :class:`Entry`
    built only when one is asked for (a difference shown, a page's value). ``layers``: (document, key →
    its row), the default list's first; a key's entry is the last layer's that sets it."""

    __slots__ = ("layers", "texts")

    def __init__(self, texts: dict[str, str], layers: tuple[tuple[Document, dict[str, int]], ...]) -> None:
        self.texts = texts
        self.layers = layers

    def __getitem__(self, key: str) -> Entry:
        for doc, rows in reversed(self.layers):
            row = rows.get(key)
            if row is not None:
                return doc.entry_at(row)
        raise KeyError(key)

    def get(self, key: str, default: Entry | None = None) -> Entry | None:  # type: ignore[override]
        if key not in self.texts:
            return default
        return self[key]

    def __contains__(self, key: object) -> bool:
        return key in self.texts

    def __iter__(self) -> Iterator[str]:
        return iter(self.texts)

    def __len__(self) -> int:
        return len(self.texts)

    def __repr__(self) -> str:
        return f"Rows({len(self.texts)} keys, {len(self.layers)} layers)"

    def over(self, base: Rows) -> Rows:
        """These entries over ``base`` (the list's over its default list's): this one's win."""
        return Rows({**base.texts, **self.texts}, base.layers + self.layers)


def row_keys(values: ListValues) -> list[str]:
    """The documented key of each row of a list (:func:`canonical_key` of its entry, without building
    it): an alias as the key it stands for, `[01]` as `[1]`; worked out once per key shape."""
    cols = values.doc.columns
    bound = values.bound
    # per shape: the key of each of its rows (no first index), or (before, after) the first index
    # (written as documented), or (documented pattern, the indices after the first) to fill
    forms: list[str | tuple[str, str] | tuple[str, tuple[int, ...], None]] = []
    for shape, (pattern, indices, indexed) in zip(cols.shapes, values.shape_keys, strict=True):
        text = shape.head + shape.tail
        if not pattern:  # a key zero cannot read: as written
            forms.append(text)
            continue
        hit = bound.get(pattern)
        canon = hit[0].key if hit is not None and hit[0].key else pattern
        plain = canon == pattern and ("[0" not in text or re.search(_LEADING_ZERO, text) is None)
        if not indexed:
            forms.append(text if plain else format_key(canon, indices))
        elif plain:
            forms.append((shape.head + "[", "]" + shape.tail))
        else:
            forms.append((canon, indices, None))
    out: list[str] = []
    append = out.append
    for form, first in zip(map(forms.__getitem__, cols.shape), cols.first, strict=True):
        if type(form) is str:
            append(form)
        elif len(form) == 2:
            append(f"{form[0]}{first}{form[1]}")
        else:
            append(format_key(form[0], (first, *form[1])))
    return out


# The keys of the rows of the last few columns read, per kind and registry: the lists a run shares by
# content (zero.machine.model.SHARED: a fleet's copies) share their columns, and so these. The dicts
# are never changed once made (Rows.over makes new ones).
_KEYED_MAX = 64
_KEYED_ROWS = 16_384
_keyed: dict[tuple[int, str | None, int], tuple[Columns, Registry, dict[str, str], dict[str, int]]] = {}


def own_entries(values: ListValues) -> Rows:
    """The entries of a list itself by documented key (the later one wins, as on the controller), read
    from its rows: no entry is built until one is asked for."""
    cols = values.doc.columns
    slot = (id(cols), values.kind, id(values.registry))
    hit = _keyed.get(slot)
    if hit is not None and hit[0] is cols and hit[1] is values.registry:
        return Rows(hit[2], ((values.doc, hit[3]),))
    keys = row_keys(values)
    texts = dict(zip(keys, map(cols.values.__getitem__, cols.value), strict=True))
    rows = dict(zip(keys, range(len(keys)), strict=True))
    if len(keys) <= _KEYED_ROWS:  # a big list (a tool list read by diff) is not kept
        if len(_keyed) >= _KEYED_MAX:
            del _keyed[next(iter(_keyed))]
        _keyed[slot] = (cols, values.registry, texts, rows)
    return Rows(texts, ((values.doc, rows),))


__all__ = ["Rows", "own_entries", "row_keys"]

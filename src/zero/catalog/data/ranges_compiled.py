"""The formal ranges of the built-in catalogue (table.py and seeds.py), parsed, written by
tools/gen_ranges.py: each kind's in a module of its own (``ranges_compiled_axis.py``: RANGES, ID -> (range
text, the range encoded by zero.catalog.ranges.encode_range)), imported at the first range of that kind;
here the kinds that have one, and RANGES of every kind (built on first use, for tools and tests).

Generated: do not edit."""

# ruff: noqa
from __future__ import annotations

import importlib

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

KINDS: tuple[str, ...] = ('AXIS', 'CHAN', 'CLMP', 'COMP', 'EXTV', 'MANU', 'RTCF', 'SECO', 'STUP', 'TOOL', 'VOLC', 'ZERO')
_RANGES: dict[str, tuple[str, Any]] = {}


def __getattr__(name: str) -> dict[str, tuple[str, Any]]:
    if name != "RANGES":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    if not _RANGES:
        for kind in KINDS:
            _RANGES.update(importlib.import_module(f"{__name__}_{kind.lower()}").RANGES)
    return _RANGES

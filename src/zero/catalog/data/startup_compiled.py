"""The K rules' conditions of startup_errors.toml as Python, written by tools/gen_conditions.py: each list
kind's in a module of its own (``startup_compiled_axis.py``: COMPILED, code -> (condition, guard, the
condition's function, the guard's or None, the parameters it reads, the elements it shows)), imported at
the first check of that kind; here the kinds, and COMPILED of every kind (built on first use, for tools
and tests).

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
import importlib

KINDS = ('AXIS', 'CHAN', 'COMP', 'EXTV', 'RTCF', 'ZERO')
_COMPILED = {}


def __getattr__(name):
    if name != "COMPILED":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    if not _COMPILED:
        for kind in KINDS:
            _COMPILED.update(importlib.import_module(f"{__name__}_{kind.lower()}").COMPILED)
    return _COMPILED

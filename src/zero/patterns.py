"""Regular expressions without importing :mod:`re` where the code it compiles them to was written at build time.

``re`` and the ``enum`` it needs were the largest part of what a list's lint imported from the standard library
(seven modules: a third of a short lint's start-up, issue 40). Every pattern zero compiles goes through
:func:`compiled`: the code the engine runs is read from ``pattern_codes.py`` (written by
``tools/gen_pattern_codes.py`` from the literal patterns in zero's source and the tokenizer's row patterns, with
the Python and engine that compiled them) and handed to the engine (``_sre``, which is built into Python) as
``re.compile`` would hand it: the result is a ``re.Pattern`` equal to ``re.compile(source, flags)``. A pattern not
written there, another Python or another engine compiles with ``re`` (slower to start, never different).

The flags are ``re``'s values, under the same names.
"""

from __future__ import annotations

import marshal
import sys

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from re import Pattern
    from typing import Any, AnyStr

IGNORECASE = 2  # re.IGNORECASE (re.I)
MULTILINE = 8  # re.MULTILINE
DOTALL = 16  # re.DOTALL
VERBOSE = 64  # re.VERBOSE
ASCII = 256  # re.ASCII

_COMPILED: dict[tuple[Any, int], Any] = {}  # (source, flags) -> its pattern, compiled once
_written: dict[tuple[Any, int], tuple[int, bytes, int, dict[str, int], tuple[str | None, ...]]] | None = None


def compiled(source: AnyStr, flags: int = 0) -> Pattern[AnyStr]:
    """``re.compile(source, flags)``, from the code written at build time where there is one (see the module)."""
    hit: Pattern[AnyStr] | None = _COMPILED.get((source, flags))
    if hit is None:
        hit = _COMPILED[source, flags] = _from_written(source, flags) or _compile(source, flags)
    return hit


def written(source: str | bytes, flags: int = 0) -> bool:
    """Whether :func:`compiled` takes ``source`` from the code written at build time (for this Python and engine)."""
    return (source, flags) in _codes()


def _compile(source: AnyStr, flags: int) -> Pattern[AnyStr]:
    import re  # start-up: only a pattern whose code was not written at build time

    return re.compile(source, flags)


def _from_written(source: AnyStr, flags: int) -> Pattern[AnyStr] | None:
    got = _codes().get((source, flags))
    if got is None:
        return None
    import _sre  # type: ignore[import-not-found]  # start-up: built into CPython (what re.compile hands code to)

    all_flags, code, groups, groupindex, indexgroup = got
    return _sre.compile(source, all_flags, list(marshal.loads(code)), groups, dict(groupindex), indexgroup)  # type: ignore[no-any-return]


def _codes() -> dict[tuple[Any, int], tuple[int, bytes, int, dict[str, int], tuple[str | None, ...]]]:
    """The written codes, where they were written by this Python and engine; else none."""
    global _written
    if _written is None:
        _written = {}
        if sys.implementation.name == "cpython":  # (another Python's engine is its own)
            import _sre  # start-up: with the first pattern compiled (built into CPython)

            from zero import pattern_codes  # start-up: read with the first pattern compiled

            if (*sys.version_info[:2], _sre.MAGIC, _sre.CODESIZE) == pattern_codes.BUILT:
                _written = pattern_codes.CODES
    return _written


__all__ = ["ASCII", "DOTALL", "IGNORECASE", "MULTILINE", "VERBOSE", "compiled", "written"]

"""Exit codes, in one place, and the guard every command runs under.

0: nothing to report (warnings allowed, unless ``--strict``); 1: findings, differences,
violations, changes a ``--diff`` shows, or inputs that could not be converted or formatted;
2: a usage or input problem, or a file that could not be read (one line on stderr, or an
F001 finding; never a traceback); 130: interrupted; 141: the reader of standard output
went away (``zero lint … | head``).
"""

from __future__ import annotations

import gc
import os
import sys
from collections.abc import Callable

from zero.cli import GC_THRESHOLDS
from zero.diagnostics import Severity
from zero.engine.results import Totals
from zero.errors import ZeroError

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: the fleet only for zero diff --fleet
    from zero.engine.fleet import FleetDrift

OK, FINDINGS, USAGE, INTERRUPTED, BROKEN_PIPE = 0, 1, 2, 130, 141


def fail(message: str) -> int:
    """Say what is wrong in one line on stderr; the usage exit code."""
    sys.stderr.write(f"zero: {message}\n")
    return USAGE


def lint_exit(totals: Totals, strict: bool, exit_zero: bool) -> int:
    """1 when a finding is an error (a warning too with ``strict``), unless ``exit_zero``."""
    if exit_zero:
        return OK
    worst = totals.worst
    threshold = Severity.WARNING if strict else Severity.ERROR
    return FINDINGS if worst is not None and worst >= threshold else OK


def found(anything: bool) -> int:
    """1 when there is something to report (differences, violations, failed inputs)."""
    return FINDINGS if anything else OK


def fleet_exit(drift: FleetDrift) -> int:
    """``zero diff --fleet``: 2 when a machine could not be read, else 1 when anything drifts, else 0
    (like ``zero diff``)."""
    return USAGE if drift.unreadable else FINDINGS if drift.differs else OK


def of_system_exit(code: object) -> int:
    """The exit code of ``SystemExit(code)``, as Python gives it: a number as it is, ``None`` 0, anything
    else (a message) 1."""
    if isinstance(code, int):
        return code
    return OK if code is None else FINDINGS


def _quiet_stdout() -> None:
    os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


def guard(command: Callable[[], int]) -> int:
    """Run a command; turn what escapes it into its exit code and one line on stderr (with the cycle
    collector's thresholds of :data:`zero.cli.GC_THRESHOLDS`)."""
    gc.set_threshold(*GC_THRESHOLDS)
    try:
        code = command()
    except ZeroError as exc:
        code = fail(str(exc))
    except KeyboardInterrupt:
        sys.stderr.write("zero: interrupted\n")
        return INTERRUPTED
    except BrokenPipeError:
        _quiet_stdout()
        return BROKEN_PIPE
    except Exception as exc:  # a bug in zero: one line, unless debugging
        if os.environ.get("ZERO_DEBUG"):
            raise
        code = fail(f"internal error: {type(exc).__name__}: {exc} (set ZERO_DEBUG=1 for the traceback)")
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        _quiet_stdout()
        return BROKEN_PIPE
    return code

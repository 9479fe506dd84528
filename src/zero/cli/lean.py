"""The ``zero`` console script: a lean path for ``zero lint``, typer for the rest.

A pre-commit hook starts ``zero lint`` on every commit, so that path (and ``zero diff --fleet``) imports neither
typer (with pydantic) nor rich: its options are parsed from the one option table
(:mod:`zero.cli.options`), and anything that parser does not accept exactly
(``--help`` included) goes to the typer command line, which gives the same result
plus help and error messages.
"""

from __future__ import annotations

import contextlib
import gc
import os
import sys

from zero import BUNDLES_ASKED, preload
from zero.cli import GC_THRESHOLDS

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import NoReturn


def main() -> None:
    gc.set_threshold(*GC_THRESHOLDS)  # before zero is imported (its tables and rules: some twenty passes)
    args = sys.argv[1:]
    if args[:1] == ["lint"]:
        preload("lint")  # its modules at once, where their bundle is current (zero.bundles)
    from zero.cli.exits import guard, of_system_exit  # start-up: imported with the collector's thresholds set
    from zero.cli.options import parse_fleet_args, parse_lint_args  # start-up: as above

    if args[:1] == ["lint"]:
        parsed = parse_lint_args(args[1:])
        if parsed is not None:
            from zero.cli.run import lint  # start-up: the engine only once the arguments are known

            parsed["param_desc"] = parsed.get("param_desc") or os.environ.get("ZERO_PARAM_DESC") or None
            end(guard(lambda: lint(**parsed)))  # type: ignore[arg-type]
    if args[:1] == ["diff"] and "--fleet" in args:
        fleet = parse_fleet_args(args[1:])
        if fleet is not None:
            from zero.cli.run import fleet_diff  # start-up: the engine only once the arguments are known

            fleet["param_desc"] = fleet["param_desc"] or os.environ.get("ZERO_PARAM_DESC") or None
            end(guard(lambda: fleet_diff(**fleet)))  # type: ignore[arg-type]
    from zero.cli.app import main as typer_main  # start-up: typer only off the lean path

    try:
        typer_main()
    except SystemExit as stop:
        if isinstance(stop.code, str):  # what Python does with SystemExit("message")
            sys.stderr.write(stop.code + "\n")
        end(of_system_exit(stop.code))


def end(code: int) -> NoReturn:
    """End the process once the command is done, without tearing the interpreter down.

    Freeing every object one by one (modules, the registry, the compiled patterns, the entries
    of the lists read) is a tenth of a pre-commit run, and nothing zero does waits for it: files
    are written, closed and renamed before a command returns, worker pools are joined, and no
    ``atexit`` work is registered. The standard streams are flushed here.
    """
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):  # a closed pipe or stream: nothing more to say
            stream.flush()
    if not all(BUNDLES_ASKED.values()):  # once the output is out: as Python writes cached bytecode
        from zero.bundles import write_missing  # start-up: only when a bundle is missing or stale

        # as Python's cached bytecode: a bundle not written never changes the command's outcome (the tests
        # write and read them: tests/test_fast_imports.py)
        with contextlib.suppress(Exception):
            write_missing()
    os._exit(code)

"""The command bodies that both command lines share (no typer, no rich at import).

:func:`lint` is ``zero lint`` from parsed options to an exit code: it asks the engine
(:func:`zero.engine.commands.run_lint`), renders with :mod:`zero.output`, and takes
its exit code from :mod:`zero.cli.exits`. :data:`REGISTRIES` loads each parameter
description once per process and hands the registry down.
"""

from __future__ import annotations

import io
import sys
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TextIO

from zero.catalog.registry import Registry, load_registry
from zero.cli import exits
from zero.engine.commands import Echo, LintRequest, run_lint
from zero.engine.lint import LintResult, Totals, tallied
from zero.errors import ZeroError
from zero.files import max_file_bytes, read_stream, write_report
from zero.output import OUTPUT_FORMATS, STREAMED_FORMATS
from zero.output.text import ProgressBar, render_text, statistics


class RegistryCache:
    """Parameter description path (``None``: built-in) → its registry, loaded once."""

    def __init__(self) -> None:
        self._loaded: dict[Path | None, Registry] = {}

    def __call__(self, desc: Path | None) -> Registry:
        registry = self._loaded.get(desc)
        if registry is None:
            registry = self._loaded[desc] = load_registry(desc)
        return registry


REGISTRIES = RegistryCache()


def _write_out(text: str) -> None:
    sys.stdout.write(text)


def _write_err(text: str) -> None:
    sys.stderr.write(text)


def _write_bytes(data: bytes) -> None:
    sys.stdout.buffer.write(data)
    sys.stdout.buffer.flush()


def echo() -> Echo:
    """A command's streamed text to this process's standard output and error."""
    return Echo(out=_write_out, err=_write_err, out_bytes=_write_bytes)


def read_stdin() -> bytes:
    """Standard input, refused beyond the size limit."""
    return read_stream(sys.stdin.buffer)




def render_lint(results: Iterable[LintResult], output_format: str, stream: TextIO, totals: Totals,
                color: bool | None = None) -> None:
    """The findings in one of the output formats, each result counted into ``totals``; the text
    summary goes to stderr."""
    if output_format == "text":
        render_text(results, stream, color=color, summary_stream=sys.stderr, totals=totals)
        return
    from zero.output.formats import RENDERERS, STREAMED  # start-up: only for machine-readable reports

    counted = tallied(results, totals)
    if output_format in STREAMED:
        STREAMED[output_format](counted, stream)
    else:
        RENDERERS[output_format](list(counted), stream)


def lint(paths: Sequence[str | Path] = (), output_format: str = "text", output_file: str | Path | None = None,
         show_statistics: bool = False, exit_zero: bool = False, config: str | Path | None = None,
         isolated: bool = False, strict: bool = False, select: Sequence[str] = (), ignore: Sequence[str] = (),
         extend_select: Sequence[str] = (),
         kind: str | None = None, jobs: int | None = None, fix: bool = False, show_diff: bool = False,
         unsafe_fixes: bool = False, stdin_filename: str | None = None, machine: str | Path | None = None,
         add_noqa: bool = False,
         param_desc: str | Path | None = None) -> int:
    """``zero lint``: report what the controller will do with the files; the exit code."""
    if add_noqa and (fix or show_diff):
        raise ZeroError("--add-noqa writes the suppressions into the files: it does not go with --fix or --diff")
    max_file_bytes()  # a bad ZERO_MAX_FILE_SIZE is one usage error, not one finding per file
    if output_format not in OUTPUT_FORMATS:
        raise ZeroError(f"unknown output format {output_format!r} (use one of: {', '.join(OUTPUT_FORMATS)})")
    if not paths and stdin_filename is None and machine is None:
        raise ZeroError("give list files or directories (or - with --stdin-filename)")
    request = LintRequest([str(p) for p in paths], tuple(select), tuple(ignore), kind, param_desc, jobs,
                          config, isolated, fix, show_diff, unsafe_fixes, stdin_filename, machine,
                          tuple(extend_select), add_noqa,
                          stream=output_file is None and output_format in STREAMED_FORMATS)
    bar = ProgressBar()
    try:
        run = run_lint(request, REGISTRIES, echo(), read_stdin, bar.start)
    finally:
        bar.finish()
    if not run.report:
        return exits.OK
    totals = Totals()
    if output_file is not None:
        results = list(run.results)
        buffer = io.StringIO()
        render_lint(results, output_format, buffer, totals, color=False)
        inputs = tuple(Path(r.path) for r in results if r.path != "-")
        write_report(Path(output_file), buffer.getvalue().encode("utf-8", "surrogateescape"), inputs)
    else:
        render_lint(run.results, output_format, sys.stderr if run.findings_to_stderr else sys.stdout, totals)
    if show_statistics:
        sys.stderr.write(statistics(totals))
    if totals.unreadable:
        return exits.USAGE  # a file could not be read: something went wrong, whatever else
    if show_diff:
        if run.changed and not exit_zero:
            sys.stderr.write(f"zero: fixes would change {run.changed} file{'s' if run.changed != 1 else ''}\n")
        return exits.OK if exit_zero else exits.found(bool(run.changed))
    return exits.lint_exit(totals, strict, exit_zero)

"""The command bodies that both command lines share (no typer, no rich at import).

:func:`lint` is ``zero lint`` from parsed options to an exit code: it asks the engine
(:func:`zero.engine.commands.run_lint`), renders with :mod:`zero.output`, and takes
its exit code from :mod:`zero.cli.exits`. :data:`REGISTRIES` loads each parameter
description once per process and hands the registry down.
"""

from __future__ import annotations

import io
import sys
from collections.abc import Iterable, Iterator, Sequence
from pathlib import Path
from typing import TextIO

from zero.catalog.registry import KINDS, Registry, kind_from_name, load_registry
from zero.cli import exits
from zero.cli.options import close_matches
from zero.diagnostics import Severity
from zero.engine.commands import Echo, LintRequest, run_lint
from zero.engine.lint import LintResult, Totals, tallied
from zero.errors import ZeroError
from zero.files import max_file_bytes, read_stream, write_report
from zero.output import OUTPUT_FORMATS, STREAMED_FORMATS
from zero.output.text import ProgressBar, printable, render_text, statistics


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


def _discard(text: str) -> None:
    """Where ``--quiet`` and ``--silent`` send what they leave out."""


def kind_names() -> dict[str, str]:
    """Every list kind by its name, with what it is (for messages and shell completion)."""
    return {name: what for name, what in KINDS.values()}


def check_kind(kind: str | None) -> str | None:
    """``--kind`` as given, refused with the nearest kind when it names none.

    (The engine's ``parse_kind`` refuses it too, without a suggestion: this belongs there.)"""
    if kind is None or kind_from_name(kind) is not None:
        return kind
    names = kind_names()
    near = close_matches(kind.strip().lower(), names)
    hint = f"; did you mean {near[0]}?" if near else ""
    raise ZeroError(f"unknown list kind {kind!r}{hint} (use one of: {', '.join(names)})")


def rule_completions(incomplete: str) -> list[tuple[str, str]]:
    """Rule codes and their prefixes (``R``, ``R0``) that complete ``incomplete``, with their titles.

    After a comma (``--select R001,S``) the last code is completed, the ones before kept."""
    from zero.rules import RULES  # start-up: only for shell completion

    head, comma, tail = incomplete.rpartition(",")
    tail = tail.strip().upper()
    candidates: dict[str, str] = {}
    for code in sorted(RULES):
        letters = code.rstrip("0123456789")
        candidates.setdefault(letters, f"every {letters} rule")
    candidates.update((code, RULES[code].summary or RULES[code].name) for code in sorted(RULES))
    return [(head + comma + code, what) for code, what in candidates.items() if code.startswith(tail)]


def kind_completions(incomplete: str) -> list[tuple[str, str]]:
    """The list kinds whose name starts with ``incomplete``, with what each is."""
    return [(name, what) for name, what in kind_names().items() if name.startswith(incomplete.strip().lower())]


def check_paths(paths: Sequence[str | Path]) -> None:
    """Refuse what cannot be done with the paths: standard input is read once and goes alone."""
    dashes = sum(str(p) == "-" for p in paths)
    if dashes > 1:
        raise ZeroError("- (standard input) is given more than once: standard input can be read only once")
    if dashes and len(paths) > 1:
        raise ZeroError("- (standard input) goes alone: lint standard input or files, not both in one run")


def files_to_check(paths: Sequence[str | Path], config: str | Path | Sequence[str] | None, isolated: bool,
                   param_desc: str | Path | None) -> list[str]:
    """``--show-files``: the files ``zero lint`` would check, without checking them."""
    from zero.engine.commands import lint_files  # start-up: only for --show-files
    from zero.engine.project import Project  # start-up: only for --show-files

    if [str(p) for p in paths] in ([], ["-"]):
        return ["-"]
    project = Project(REGISTRIES, config=config, isolated=isolated, param_desc=param_desc)
    return [str(f) for f in lint_files([Path(p) for p in paths], project)]


def _noted(results: Iterable[LintResult], err: TextIO) -> Iterator[LintResult]:
    """The results, each skipped file's note said on ``err`` as it passes (``zero: package.json: …``)."""
    for r in results:
        if r.note:
            err.write(f"zero: {printable(r.path, escape=True)}: {r.note}\n")
        yield r


def render_lint(results: Iterable[LintResult], output_format: str, stream: TextIO, totals: Totals,
                color: bool | None = None, summary_stream: TextIO | None = None,
                fail_on: Severity = Severity.ERROR) -> None:
    """The findings in one of the output formats, each result counted into ``totals``; the text
    summary goes to ``summary_stream`` (stderr by default); ``fail_on``: the severity from which a
    finding fails the run (a JUnit failure)."""
    if output_format == "text":
        render_text(results, stream, color=color, summary_stream=summary_stream or sys.stderr, totals=totals)
        return
    from zero.output.formats import RENDERERS, STREAMED  # start-up: only for machine-readable reports

    counted = tallied(results, totals)
    if output_format in STREAMED:
        STREAMED[output_format](counted, stream)
    else:
        if output_format == "junit":
            from zero.output.formats import render_junit  # start-up: as above

            render_junit(list(counted), stream, fail_on=fail_on)
        else:
            RENDERERS[output_format](list(counted), stream)


def lint(paths: Sequence[str | Path] = (), output_format: str = "text", output_file: str | Path | None = None,
         show_statistics: bool = False, exit_zero: bool = False,
         config: str | Path | Sequence[str] | None = None,
         isolated: bool = False, strict: bool = False, select: Sequence[str] = (), ignore: Sequence[str] = (),
         extend_select: Sequence[str] = (),
         kind: str | None = None, jobs: int | None = None, fix: bool = False, show_diff: bool = False,
         unsafe_fixes: bool = False, stdin_filename: str | None = None, machine: str | Path | None = None,
         add_noqa: bool = False, exit_non_zero_on_fix: bool = False, quiet: bool = False, silent: bool = False,
         show_files: bool = False, param_desc: str | Path | None = None) -> int:
    """``zero lint``: report what the controller will do with the files; the exit code.

    ``quiet``: the findings only (no summary line, progress bar or notes); ``silent``: not even
    those (the exit code tells; a report file is still written)."""
    if add_noqa and (fix or show_diff):
        raise ZeroError("--add-noqa writes the suppressions into the files: it does not go with --fix or --diff")
    max_file_bytes()  # a bad ZERO_MAX_FILE_SIZE is one usage error, not one finding per file
    if output_format not in OUTPUT_FORMATS:
        raise ZeroError(f"unknown output format {output_format!r} (use one of: {', '.join(OUTPUT_FORMATS)})")
    check_paths(paths)
    check_kind(kind)
    if show_files:
        if machine is not None:
            raise ZeroError("--show-files lists the files named or found in directories: not with --machine")
        listed = files_to_check(paths, config, isolated, param_desc)
        sys.stdout.write("".join(f"{f}\n" for f in listed))
        return exits.OK
    if not paths and stdin_filename is None and machine is None:
        raise ZeroError("give list files or directories (or - with --stdin-filename)")
    quiet = quiet or silent
    request = LintRequest([str(p) for p in paths], tuple(select), tuple(ignore), kind, param_desc, jobs,
                          config, isolated, fix, show_diff, unsafe_fixes, stdin_filename, machine,
                          tuple(extend_select), add_noqa,
                          stream=output_file is None and output_format in STREAMED_FORMATS)
    streams = echo()
    if quiet:
        streams = Echo(out=streams.out, err=_discard, out_bytes=streams.out_bytes)
    bar = ProgressBar()
    try:
        run = run_lint(request, REGISTRIES, streams, read_stdin, None if quiet else bar.start)
    finally:
        bar.finish()
    if not run.report:
        return exits.OK
    totals = Totals()
    summary = io.StringIO() if quiet else sys.stderr
    fail_on = Severity.WARNING if strict else Severity.ERROR
    shown = run.results if quiet else _noted(run.results, sys.stderr)
    if output_file is not None:
        results = list(shown)
        buffer = io.StringIO()
        render_lint(results, output_format, buffer, totals, color=False, summary_stream=summary, fail_on=fail_on)
        inputs = tuple(Path(r.path) for r in results if r.path != "-")
        write_report(Path(output_file), buffer.getvalue().encode("utf-8", "surrogateescape"), inputs)
    else:
        report = io.StringIO() if silent else sys.stderr if run.findings_to_stderr else sys.stdout
        render_lint(shown, output_format, report, totals, color=None if not silent else False,
                    summary_stream=summary, fail_on=fail_on)
    if show_statistics and not silent:
        sys.stderr.write(statistics(totals))
    if totals.unreadable:
        return exits.USAGE  # a file could not be read: something went wrong, whatever else
    if show_diff:
        if run.changed and not exit_zero and not quiet:
            sys.stderr.write(f"zero: fixes would change {run.changed} file{'s' if run.changed != 1 else ''}\n")
        return exits.OK if exit_zero else exits.found(bool(run.changed))
    if fix and exit_non_zero_on_fix and run.changed and not exit_zero:
        return exits.FINDINGS  # as ruff: a fixed file fails the run, whatever remains
    return exits.lint_exit(totals, strict, exit_zero)

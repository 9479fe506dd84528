"""The command bodies that both command lines share (no typer, no rich at import).

:func:`lint` is ``zero lint`` from parsed options to an exit code: it asks the engine
(:func:`zero.engine.commands.run_lint`), renders with :mod:`zero.output`, and takes
its exit code from :mod:`zero.cli.exits`. :data:`REGISTRIES` loads each parameter
description once per process and hands the registry down.
"""

from __future__ import annotations

import io
import os
import sys
from collections.abc import Callable, Iterable, Iterator, Sequence

from zero.cli import exits
from zero.diagnostics import Severity
from zero.engine.commands import Echo, LintRequest, parse_kind, run_lint
from zero.engine.results import LintResult, Totals, tallied
from zero.errors import ZeroError
from zero.files import max_file_bytes, path_str, read_stream, walk, write_report
from zero.output.formats import FORMATS, OUTPUT_FORMATS, STREAMED_FORMATS, emitter
from zero.output.text import ProgressBar, printable, render_text, statistics, statistics_json

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: the fleet only for zero diff --fleet
    from pathlib import Path  # (and pathlib only where a command needs it: zero lint names files by their text)
    from typing import TextIO

    from zero.catalog.registry import Registry
    from zero.engine.fleet import FleetRequest
    from zero.engine.project import Registries


def run_fleet_diff(request: FleetRequest, registries: Registries, output_format: str, stream: TextIO) -> int:
    """``zero diff --fleet``: the engine compares (:func:`zero.engine.fleet.run_fleet`), the output
    layer writes the report in ``output_format`` to ``stream``; the exit code (:func:`exits.fleet_exit`)."""
    from zero.engine.fleet import run_fleet  # start-up: only with --fleet
    from zero.output.fleet import check_fleet_format, render_fleet  # start-up: as above

    check_fleet_format(output_format)
    drift = run_fleet(request, registries)
    render_fleet(drift, output_format, stream)
    return exits.fleet_exit(drift)


def fleet_diff(golden: str, machines: Sequence[str], output_format: str = "text", jobs: int | None = None,
               no_cache: bool = False, config: Sequence[str] = (), isolated: bool = False,
               param_desc: str | None = None) -> int:
    """``zero diff --fleet GOLDEN MACHINE...`` as the lean path parses it (:func:`zero.cli.options.parse_fleet_args`):
    the report on standard output, and its exit code."""
    from pathlib import Path  # start-up: only with --fleet (whose modules import it)

    from zero.engine.fleet import FleetRequest  # start-up: only with --fleet

    desc = Path(param_desc) if param_desc else None  # as typer gives it
    request = FleetRequest(golden, list(machines), jobs=jobs, param_desc=desc, config=tuple(config), isolated=isolated,
                           cache=not no_cache)
    return run_fleet_diff(request, REGISTRIES, output_format, sys.stdout)


class RegistryCache:
    """Parameter description path (``None``: built-in) → its registry, loaded once (a path is known by
    its text as a ``Path`` prints it: ``./desc.xml`` and ``desc.xml`` share one)."""

    def __init__(self) -> None:
        self._loaded: dict[str | None, Registry] = {}

    def __call__(self, desc: str | os.PathLike[str] | None) -> Registry:
        key = path_str(desc) if desc is not None else None
        registry = self._loaded.get(key)
        if registry is None:
            from zero.catalog.registry import load_registry  # start-up: a cached run loads no catalogue

            registry = self._loaded[key] = load_registry(key)
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
    from zero.catalog.registry import KINDS  # start-up: only for messages and shell completion

    return {name: what for name, what in KINDS.values()}


def check_kind(kind: str | None) -> str | None:
    """``--kind`` as given, refused (by the engine's ``parse_kind``) with the nearest kind when it names none."""
    parse_kind(kind)
    return kind


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
                   param_desc: str | Path | None, force_exclude: bool = True) -> list[str]:
    """``--show-files``: the files ``zero lint`` would check, without checking them."""
    from zero.engine.commands import lint_files  # start-up: only for --show-files
    from zero.engine.project import common_of, open_project  # start-up: only for --show-files

    if [str(p) for p in paths] in ([], ["-"]):
        return ["-"]
    project = open_project(REGISTRIES, common_of(config, isolated, param_desc))
    return lint_files(paths, project, force_exclude)


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
    chosen = FORMATS[output_format]
    if chosen.module is None:  # the report for people (`full`: ruff's name for it with the source lines)
        render_text(results, stream, color=color, summary_stream=summary_stream or sys.stderr, totals=totals)
        return
    emit = emitter(output_format)  # its module only: the others are never imported
    counted = tallied(results, totals)
    if chosen.streamed:
        emit(counted, stream)
    elif chosen.fail_on:
        emit(list(counted), stream, fail_on=fail_on)
    else:
        emit(list(counted), stream)


def command_line_config(exclude: Sequence[str], extend_exclude: Sequence[str], respect_gitignore: bool | None,
                        kernel: str | None) -> list[str]:
    """``--exclude``, ``--extend-exclude``, ``--[no-]respect-gitignore`` and ``--kernel`` as the
    ``KEY = VALUE`` overrides of ``--config`` (patterns repeatable or comma-separated, as ruff's)."""
    out: list[str] = []
    if not (exclude or extend_exclude or respect_gitignore is not None or kernel is not None):
        return out
    import json  # start-up: only when one of these options is given

    def patterns(values: Sequence[str]) -> list[str]:
        return [p.strip() for v in values for p in v.split(",") if p.strip()]

    if exclude:
        out.append(f"exclude = {json.dumps(patterns(exclude))}")
    if extend_exclude:
        out.append(f"extend-exclude = {json.dumps(patterns(extend_exclude))}")
    if respect_gitignore is not None:
        out.append(f"respect-gitignore = {'true' if respect_gitignore else 'false'}")
    if kernel is not None:
        out.append(f"kernel = {json.dumps(kernel)}")
    return out


def statistics_report(totals: Totals, output_format: str) -> str:
    """``--statistics``: the count per code, most frequent first; a JSON array with a JSON format."""
    if FORMATS[output_format].json_statistics:
        return statistics_json(totals)
    return statistics(totals)


def fixes_report(fixed: Sequence[tuple[str, dict[str, int]]], applied: bool,
                 results: Sequence[LintResult] | None = None) -> str:
    """``--show-fixes``: per file, the fixes applied by code (with ``--fix``), or the findings that
    have a fix (without it); one line when there is none."""
    from zero.rules import RULES  # start-up: only for --show-fixes

    if applied:
        rows = [(path, counts) for path, counts in fixed if counts]
        head = "Fixed {n} finding{s}:"
    else:
        rows = []
        for r in results or ():
            counts: dict[str, int] = {}
            for d in r.diagnostics:
                if d.fix is not None:
                    counts[d.code] = counts.get(d.code, 0) + 1
            if counts:
                rows.append((r.path, counts))
        head = "{n} finding{s} can be fixed (--fix applies the safe ones):"
    n = sum(sum(c.values()) for _, c in rows)
    if not n:
        return "No fixes applied.\n" if applied else "No finding has a fix.\n"
    out = [head.format(n=n, s="" if n == 1 else "s")]
    for path, counts in rows:
        out.append(f"- {printable(path, escape=True)}:")
        out += [f"    {k} × {code} ({RULES[code].name if code in RULES else code})"
                for code, k in sorted(counts.items())]
    return "\n".join(out) + "\n"


WATCH_INTERVAL = 0.5  # seconds between two looks at the files (--watch)


def _snapshot(paths: Sequence[str | Path]) -> dict[str, tuple[int, int]]:
    """Every file below ``paths`` (hidden folders left out) with its modification time and size."""
    out: dict[str, tuple[int, int]] = {}

    def look(name: str) -> None:
        try:
            st = os.stat(name)
        except OSError:
            return
        out[name] = (st.st_mtime_ns, st.st_size)

    for p in paths:
        if os.path.isdir(p):
            for root, dirs, files in walk(p):
                dirs[:] = [d for d in dirs if not d.startswith(".")]
                for f in files:
                    look(os.path.join(root, f))
        else:
            look(str(p))
    return out


def watch_loop(run_once: Callable[[], int], paths: Sequence[str | Path], interval: float = WATCH_INTERVAL) -> int:
    """``--watch``: run the lint, then again whenever a file below ``paths`` is added, removed or
    changed (its modification time or size, polled every ``interval`` seconds: pure Python, on
    every system), until interrupted (exit 130)."""
    import time  # start-up: only for --watch

    if not paths or any(str(p) == "-" for p in paths):
        raise ZeroError("--watch needs files or directories to watch (not standard input)")
    while True:
        before = _snapshot(paths)
        code = exits.guard(run_once)
        if code == exits.INTERRUPTED:
            return code
        sys.stderr.write(f"zero: watching {len(before)} file{'s' if len(before) != 1 else ''} for changes "
                         "(Ctrl-C ends)\n")
        sys.stderr.flush()
        sys.stdout.flush()
        try:
            while _snapshot(paths) == before:
                time.sleep(interval)
        except KeyboardInterrupt:
            return exits.INTERRUPTED
        sys.stderr.write("zero: a file changed: linting again\n")


def lint(paths: Sequence[str | Path] = (), output_format: str = "text", output_file: str | Path | None = None,
         show_statistics: bool = False, exit_zero: bool = False,
         config: str | Path | Sequence[str] | None = None,
         isolated: bool = False, strict: bool = False, select: Sequence[str] = (), ignore: Sequence[str] = (),
         extend_select: Sequence[str] = (),
         kind: str | None = None, jobs: int | None = None, fix: bool = False, show_diff: bool = False,
         unsafe_fixes: bool = False, stdin_filename: str | None = None, machine: str | Path | None = None,
         add_noqa: bool = False, exit_non_zero_on_fix: bool = False, quiet: bool = False, silent: bool = False,
         show_files: bool = False, param_desc: str | Path | None = None,
         exclude: Sequence[str] = (), extend_exclude: Sequence[str] = (), respect_gitignore: bool | None = None,
         force_exclude: bool | None = None, kernel: str | None = None, fix_only: bool = False,
         show_fixes: bool = False, watch: bool = False, ignore_noqa: bool = False, no_cache: bool = False) -> int:
    """``zero lint``: report what the controller will do with the files; the exit code.

    ``quiet``: the findings only (no summary line, progress bar or notes); ``silent``: not even
    those (the exit code tells; a report file is still written). ``exclude``, ``extend_exclude``,
    ``respect_gitignore`` and ``kernel`` are the configuration's keys of those names, laid over it
    as ``--config KEY=VALUE`` is; ``fix_only``: ``fix`` without a report (as ruff's ``--fix-only``);
    ``show_statistics``: the counts per code instead of the findings; ``watch``: lint again on
    every change below ``paths`` (:func:`watch_loop`); ``no_cache``: neither read nor write the
    cache of results (:mod:`zero.engine.cache`; ``ZERO_NO_CACHE=1`` does the same)."""
    if watch:
        again = {k: v for k, v in locals().items() if k != "watch"}
        return watch_loop(lambda: lint(**again), paths)
    config = [*([config] if isinstance(config, (str, os.PathLike)) else (config or ())),
              *command_line_config(exclude, extend_exclude, respect_gitignore, kernel)]
    fix = fix or fix_only
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
        listed = files_to_check(paths, config, isolated, param_desc, force_exclude is not False)
        sys.stdout.write("".join(f"{f}\n" for f in listed))
        return exits.OK
    if not paths and stdin_filename is None and machine is None:
        raise ZeroError("give list files or directories (or - with --stdin-filename)")
    quiet = quiet or silent
    request = LintRequest([path_str(p) for p in paths], tuple(select), tuple(ignore), kind, param_desc, jobs,
                          config, isolated, fix, show_diff, unsafe_fixes, stdin_filename, machine,
                          tuple(extend_select), add_noqa, force_exclude is not False, ignore_noqa,
                          stream=output_file is None and output_format in STREAMED_FORMATS and not show_fixes,
                          cache=not no_cache)
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
    if fix_only or show_statistics:  # the counts alone, or nothing: the findings are counted, not shown
        counted = list(tallied(shown, totals))
        if show_statistics and output_file is not None:  # the counts are the report
            inputs = tuple(r.path for r in counted if r.path != "-")
            write_report(output_file, statistics_report(totals, output_format).encode("utf-8"), inputs)
        elif show_statistics and not silent:
            sys.stdout.write(statistics_report(totals, output_format))
        if show_fixes and not silent:
            sys.stderr.write(fixes_report(run.fixed, fix))
        if totals.unreadable:
            return exits.USAGE
        if fix_only:
            return exits.FINDINGS if exit_non_zero_on_fix and run.changed and not exit_zero else exits.OK
        return exits.lint_exit(totals, strict, exit_zero)
    if output_file is not None:
        results = list(shown)
        buffer = io.StringIO()
        render_lint(results, output_format, buffer, totals, color=False, summary_stream=summary, fail_on=fail_on)
        inputs = tuple(r.path for r in results if r.path != "-")
        write_report(output_file, buffer.getvalue().encode("utf-8", "surrogateescape"), inputs)
    else:
        report = io.StringIO() if silent else sys.stderr if run.findings_to_stderr else sys.stdout
        render_lint(shown, output_format, report, totals, color=None if not silent else False,
                    summary_stream=summary, fail_on=fail_on)
    if show_fixes and not silent:
        sys.stderr.write(fixes_report(run.fixed, fix, run.results if isinstance(run.results, list) else None))
    if totals.unreadable:
        return exits.USAGE  # a file could not be read: something went wrong, whatever else
    if show_diff:
        if run.changed and not exit_zero and not quiet:
            sys.stderr.write(f"zero: fixes would change {run.changed} file{'s' if run.changed != 1 else ''}\n")
        return exits.OK if exit_zero else exits.found(bool(run.changed))
    if fix and exit_non_zero_on_fix and run.changed and not exit_zero:
        return exits.FINDINGS  # as ruff: a fixed file fails the run, whatever remains
    return exits.lint_exit(totals, strict, exit_zero)

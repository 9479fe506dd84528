"""Command bodies shared by the typer CLI and the lean entry point.

``run_lint`` is what ``zero lint`` does, from parsed options to an exit code.
:mod:`zero.entry` calls it directly for the hot pre-commit path (no typer
import); :mod:`zero.cli` calls it from the typer command.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path

from zero.lint import LintOptions, ZeroError, collect_files, lint_many

OUTPUT_FORMATS = ("text", "concise", "json", "github", "gitlab", "junit", "sarif")


class UsageError(Exception):
    """Bad options: one line on stderr, exit 2."""


def parse_codes(values: Sequence[str] | None) -> tuple[str, ...]:
    from zero.rules import RULES

    out = tuple(c.strip().upper() for v in values or () for c in v.split(",") if c.strip())
    for c in out:
        if not any(code.startswith(c) for code in RULES):
            raise UsageError(f"{c!r} matches no rule code (see `zero rule --all`)")
    return out


def parse_kind(kind: str | None) -> str | None:
    from zero.registry import KINDS, kind_from_name

    if kind is None:
        return None
    forced = kind_from_name(kind)
    if forced is None:
        names = ", ".join(v[0] for v in KINDS.values())
        raise UsageError(f"unknown list kind {kind!r} (use one of: {names})")
    return forced


def run_lint(paths: Sequence[str | Path], output_format: str = "text", strict: bool = False,
             select: Sequence[str] | None = None, ignore: Sequence[str] | None = None,
             kind: str | None = None, param_desc: str | Path | None = None,
             jobs: int | None = None, output_file: str | Path | None = None,
             show_statistics: bool = False, exit_zero: bool = False) -> int:
    """Lint files, print the report, return the exit code (0, 1; 2 is raised as UsageError).

    Findings go to standard output (or ``output_file``); the summary line and the
    statistics go to standard error, so standard output stays parseable.
    """
    from zero.diagnostics import Severity
    from zero.registry import load_registry

    if output_format not in OUTPUT_FORMATS:
        raise UsageError(f"unknown output format {output_format!r} (use one of: "
                         f"{', '.join(OUTPUT_FORMATS)})")
    options = LintOptions(select=parse_codes(select), ignore=parse_codes(ignore), kind=parse_kind(kind))
    try:
        registry = load_registry(param_desc)
    except Exception as exc:
        from zero.paramdesc import ParamDescError

        if isinstance(exc, ParamDescError):
            raise UsageError(str(exc)) from None
        raise
    try:
        files = collect_files(paths)
        if not files:
            raise ZeroError("no list files found (looked for *.lis and *.lst)")
        results = lint_many(files, registry, options, jobs)
    except ZeroError as exc:
        raise UsageError(str(exc)) from None

    import io

    from zero import report

    out = io.StringIO() if output_file is not None else sys.stdout
    if output_format == "json":
        report.render_json(results, out)
    elif output_format == "text":
        report.render_text(results, out, color=False if output_file is not None else None,
                           summary_stream=sys.stderr)
    else:
        report.RENDERERS[output_format](results, out)
    if output_file is not None:
        from zero.convert import write_atomic

        assert isinstance(out, io.StringIO)
        try:
            write_atomic(Path(output_file), out.getvalue().encode("utf-8", "surrogateescape"),
                         force=True)
        except ZeroError as exc:
            raise UsageError(str(exc)) from None
    if show_statistics:
        sys.stderr.write(report.statistics(results))
    if exit_zero:
        return 0
    worst = max((r.worst for r in results if r.worst is not None), default=None)
    threshold = Severity.WARNING if strict else Severity.ERROR
    return 1 if worst is not None and worst >= threshold else 0


def fail(message: str) -> int:
    sys.stderr.write(f"zero: {message}\n")
    return 2

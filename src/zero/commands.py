"""Command bodies shared by the typer CLI and the lean entry point.

``run_lint`` is what ``zero lint`` does, from parsed options to an exit code.
:mod:`zero.entry` calls it directly for the hot pre-commit path (no typer
import); :mod:`zero.cli` calls it from the typer command.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from zero.lint import LintOptions, LintResult, ZeroError, collect_files, lint_many

if TYPE_CHECKING:
    from zero.config import Config
    from zero.registry import Registry

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
             show_statistics: bool = False, exit_zero: bool = False,
             config: str | Path | None = None, isolated: bool = False) -> int:
    """Lint files, print the report, return the exit code (0, 1; 2 is raised as UsageError).

    Findings go to standard output (or ``output_file``); the summary line and the
    statistics go to standard error, so standard output stays parseable.
    """
    from zero.diagnostics import Severity

    if output_format not in OUTPUT_FORMATS:
        raise UsageError(f"unknown output format {output_format!r} (use one of: "
                         f"{', '.join(OUTPUT_FORMATS)})")
    from zero.config import ConfigFinder

    cli = LintOptions(select=parse_codes(select), ignore=parse_codes(ignore), kind=parse_kind(kind))
    try:
        finder = ConfigFinder(Path(config) if config else None, isolated)
        named = [Path(p) for p in paths]
        files = collect_files(named, include=lambda f: finder.for_path(f).included(f),
                              exclude=lambda f: finder.for_path(f).excluded(f))
        if not files and any(p.is_dir() for p in named):
            raise ZeroError("no list files found (looked for *.lis and *.lst)")
        groups: dict[Path | None, list[Path]] = {}
        for f in files:  # files sharing a parameter description share a registry
            groups.setdefault(param_desc_of(finder.for_path(f), param_desc), []).append(f)
        by_file: dict[Path, LintResult] = {}
        for desc, members in groups.items():
            registry = _registry(desc)
            for f, r in zip(members, lint_many(members, registry,
                                               lambda f: finder.for_path(f).options_for(f, cli), jobs),
                            strict=True):
                by_file[f] = r
        results = [by_file[f] for f in files]
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


def param_desc_of(config: Config, given: str | Path | None) -> Path | None:
    """The command line's --param-desc, else the configuration's."""
    if given:
        return Path(given)
    return config.param_desc


_registries: dict[Path | None, Registry] = {}


def _registry(desc: Path | None) -> Registry:
    from zero.registry import load_registry

    if desc not in _registries:
        try:
            _registries[desc] = load_registry(desc)
        except Exception as exc:
            from zero.paramdesc import ParamDescError

            if isinstance(exc, ParamDescError):
                raise UsageError(str(exc)) from None
            raise
    return _registries[desc]


def fail(message: str) -> int:
    sys.stderr.write(f"zero: {message}\n")
    return 2

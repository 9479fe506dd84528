"""Command bodies shared by the typer CLI and the lean entry point.

``run_lint`` is what ``zero lint`` does, from parsed options to an exit code.
:mod:`zero.entry` calls it directly for the hot pre-commit path (no typer
import); :mod:`zero.cli` calls it from the typer command.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from zero.lint import LintOptions, LintResult, ZeroError, collect_files, lint_many, read_file

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
             config: str | Path | None = None, isolated: bool = False,
             fix: bool = False, show_diff: bool = False, unsafe_fixes: bool = False,
             stdin_filename: str | None = None, machine: str | Path | None = None) -> int:
    """Lint files, print the report, return the exit code (0, 1; 2 is raised as UsageError).

    Findings go to standard output (or ``output_file``); the summary line and the
    statistics go to standard error, so standard output stays parseable.
    """

    if output_format not in OUTPUT_FORMATS:
        raise UsageError(f"unknown output format {output_format!r} (use one of: "
                         f"{', '.join(OUTPUT_FORMATS)})")
    from zero.config import ConfigFinder

    cli = LintOptions(select=parse_codes(select), ignore=parse_codes(ignore), kind=parse_kind(kind))
    if machine is not None:
        from zero.config import ConfigFinder
        from zero.lint import PROGRAM_SUFFIXES, lint_file
        from zero.machine import lint_machine
        from zero.program import lint_program

        registry = _registry(Path(param_desc) if param_desc else None)
        try:
            overrides = ConfigFinder(Path(config) if config else None, isolated).for_path(Path(machine)).machine_lists
            the_machine, results = lint_machine(Path(machine), registry, cli, overrides)
            for f in collect_files([Path(p) for p in paths]):  # programs and lists named as well
                if f.suffix.lower() in PROGRAM_SUFFIXES:
                    results.append(lint_program(read_file(f), str(f), registry, cli, the_machine))
                else:
                    results.append(lint_file(f, registry, cli))
        except ZeroError as exc:
            raise UsageError(str(exc)) from None
        return _report(results, output_format, output_file, show_statistics, exit_zero, strict)
    if list(paths) in ([], ["-"]) and (stdin_filename or list(paths) == ["-"]):
        return _lint_stdin(stdin_filename or "-", cli, output_format, strict, param_desc, config, isolated,
                           fix or show_diff, unsafe_fixes, exit_zero)
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
        progress = _progress_bar(len(files))
        done = 0
        for desc, members in groups.items():
            registry = _registry(desc)

            def step(n: int, _total: int, base: int = done) -> None:
                if progress is not None:
                    progress(base + n, len(files))

            for f, r in zip(members, lint_many(members, registry,
                                               lambda f: finder.for_path(f).options_for(f, cli), jobs,
                                               step if progress is not None else None),
                            strict=True):
                by_file[f] = r
            done += len(members)
        if progress is not None:
            sys.stderr.write("\r\033[K")
        results = [by_file[f] for f in files]
        results = [_with_machine(f, r, finder.for_path(f), cli, param_desc) for f, r in zip(files, results,
                                                                                         strict=True)]
        if fix or show_diff:
            results = [_fix_one(f, r, finder.for_path(f).options_for(f, cli),
                                _registry(param_desc_of(finder.for_path(f), param_desc)),
                                fix, unsafe_fixes) for f, r in zip(files, results, strict=True)]
    except ZeroError as exc:
        raise UsageError(str(exc)) from None

    return _report(results, output_format, output_file, show_statistics, exit_zero, strict)


def _report(results: list[LintResult], output_format: str, output_file: str | Path | None,
            show_statistics: bool, exit_zero: bool, strict: bool) -> int:
    """Render the results, write them where asked, and give the exit code."""
    import io

    from zero import report
    from zero.diagnostics import Severity

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


_machines: dict[Path, object] = {}


def _with_machine(path: Path, result: LintResult, cfg: Config, cli: LintOptions,
                  param_desc: str | Path | None) -> LintResult:
    """An NC program in a project whose configuration names the machine: lint it against it."""
    from zero.lint import PROGRAM_SUFFIXES

    if cfg.machine is None or path.suffix.lower() not in PROGRAM_SUFFIXES:
        return result
    from zero.machine import Machine, load_machine
    from zero.program import lint_program

    registry = _registry(param_desc_of(cfg, param_desc))
    m = _machines.get(cfg.machine)
    if m is None:
        m = _machines[cfg.machine] = load_machine(cfg.machine, registry, cli, cfg.machine_lists)
    assert isinstance(m, Machine)
    return lint_program(read_file(path), str(path), registry, cfg.options_for(path, cli), m)


def _lint_stdin(name: str, cli: LintOptions, output_format: str, strict: bool,
                param_desc: str | Path | None, config: str | Path | None, isolated: bool,
                fix: bool, unsafe: bool, exit_zero: bool) -> int:
    """Lint standard input as the file ``name`` (its configuration applies). With a fix
    option the fixed list goes to standard output and the findings to standard error."""
    from zero import report
    from zero.config import ConfigFinder
    from zero.diagnostics import Severity
    from zero.lint import lint_bytes

    data = sys.stdin.buffer.read()
    try:
        cfg = ConfigFinder(Path(config) if config else None, isolated).for_path(Path(name))
        if name != "-" and cfg.excluded(Path(name)):
            if fix:
                sys.stdout.buffer.write(data)
            return 0
        options = cfg.options_for(Path(name), cli)
        registry = _registry(param_desc_of(cfg, param_desc))
    except ZeroError as exc:
        raise UsageError(str(exc)) from None
    if fix:
        from zero.fix import fix_bytes

        fixed = fix_bytes(data, name, registry, options, unsafe)
        sys.stdout.buffer.write(fixed.fixed)
        result = fixed.result
        stream = sys.stderr
    else:
        result = lint_bytes(data, name, registry, options)
        stream = sys.stdout
    if output_format == "json":
        report.render_json([result], stream)
    elif output_format == "text":
        report.render_text([result], stream, summary_stream=sys.stderr)
    else:
        report.RENDERERS[output_format]([result], stream)
    if exit_zero or result.worst is None:
        return 0
    return 1 if result.worst >= (Severity.WARNING if strict else Severity.ERROR) else 0


PROGRESS_MIN_FILES = 200


def _progress_bar(total: int) -> Callable[[int, int], None] | None:
    """A one-line progress bar on stderr, only on a terminal and only for long runs."""
    if total < PROGRESS_MIN_FILES or not sys.stderr.isatty():
        return None

    def show(done: int, total: int) -> None:
        width = 30
        filled = width * done // max(total, 1)
        sys.stderr.write(f"\r\033[Kzero: [{'#' * filled}{'.' * (width - filled)}] {done}/{total} files")
        sys.stderr.flush()

    return show


def _fix_one(path: Path, result: LintResult, options: LintOptions, registry: Registry, write: bool,
             unsafe: bool) -> LintResult:
    """Fix one list file: write it (``write``) or print the unified diff; return what is left."""
    from zero.convert import write_atomic
    from zero.fix import fix_bytes, unified_diff
    from zero.lint import STRUCTURED_SUFFIXES, read_file

    if path.suffix.lower() in STRUCTURED_SUFFIXES:
        return result  # findings in YAML/TOML/JSON carry no list edits
    data = read_file(path)
    fixed = fix_bytes(data, str(path), registry, options, unsafe)
    if fixed.fixed == data:
        return result
    if write:
        write_atomic(path, fixed.fixed, force=True)
        sys.stderr.write(f"zero: {path}: {fixed.applied} fix{'es' if fixed.applied != 1 else ''} applied\n")
        return fixed.result
    sys.stdout.write(unified_diff(str(path), data, fixed.fixed, fixed.result.document.encoding))
    return result


def run_format(paths: Sequence[str | Path], check: bool = False, show_diff: bool = False,
               config: str | Path | None = None, isolated: bool = False) -> int:
    """``zero format``: rewrite files in canonical layout; with ``check``/``show_diff`` only report.

    Returns 1 when a file is (or, with --check, would be) changed or cannot be formatted.
    """
    from zero.config import ConfigFinder
    from zero.convert import ConvertError, write_atomic
    from zero.fix import format_bytes, unified_diff
    from zero.lint import read_file
    from zero.tokenizer import decode

    try:
        finder = ConfigFinder(Path(config) if config else None, isolated)
        files = collect_files([Path(p) for p in paths], include=lambda f: finder.for_path(f).included(f),
                              exclude=lambda f: finder.for_path(f).excluded(f))
        changed = failed = 0
        for f in files:
            data = read_file(f)
            try:
                new = format_bytes(data, str(f))
            except ConvertError as exc:
                sys.stderr.write(f"zero: {exc} (not formatted)\n")
                failed += 1
                continue
            if new == data:
                continue
            changed += 1
            if show_diff:
                sys.stdout.write(unified_diff(str(f), data, new, decode(data)[1]))
            elif check:
                sys.stdout.write(f"would reformat {f}\n")
            else:
                write_atomic(f, new, force=True)
    except ZeroError as exc:
        raise UsageError(str(exc)) from None
    verb = "would be reformatted" if (check or show_diff) else "reformatted"
    sys.stderr.write(f"{changed} file{'s' if changed != 1 else ''} {verb}, "
                     f"{len(files) - changed - failed} unchanged"
                     + (f", {failed} not formatted" if failed else "") + "\n")
    return 1 if failed or (changed and (check or show_diff)) else 0


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

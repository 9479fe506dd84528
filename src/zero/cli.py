"""The ``zero`` command line: a thin typer layer over :mod:`zero.lint` and friends.

Exit codes: 0 no error (warnings allowed), 1 an error (with ``--strict`` also a
warning), 2 a usage or I/O problem (one line on stderr, never a traceback).
"""

from __future__ import annotations

import os
import sys
from enum import StrEnum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from zero import __version__

if TYPE_CHECKING:
    from zero.diff import Side
    from zero.registry import Registry

app = typer.Typer(
    name="zero",
    help="Lint, diff and convert ISG kernel CNC parameter lists.",
    add_completion=True,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
)


class OutputFormat(StrEnum):
    text = "text"
    json = "json"


class LintFormat(StrEnum):
    text = "text"
    concise = "concise"
    json = "json"
    github = "github"
    gitlab = "gitlab"
    junit = "junit"
    sarif = "sarif"


class _State:
    param_desc: Path | None = None


state = _State()


def _fail(message: str) -> typer.Exit:
    sys.stderr.write(f"zero: {message}\n")
    return typer.Exit(code=2)


def _registry() -> Registry:
    from zero.paramdesc import ParamDescError
    from zero.registry import load_registry

    try:
        return load_registry(state.param_desc)
    except ParamDescError as exc:
        raise _fail(str(exc)) from None


def _version(value: bool) -> None:
    if value:
        typer.echo(f"zero {__version__}")
        raise typer.Exit()


@app.callback()
def main_callback(
    version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True,
                                          help="Show the version and exit.")] = False,
    param_desc: Annotated[Path | None, typer.Option(
        "--param-desc", help="Use this CncParaDesc.xml instead of the built-in table.",
        envvar="ZERO_PARAM_DESC")] = None,
) -> None:
    """zero: lint ISG kernel CNC parameter lists before the machine boots."""
    state.param_desc = param_desc


@app.command()
def lint(
    paths: Annotated[list[Path] | None, typer.Argument(
        help="List files or directories (*.lis, *.lst); - reads standard input.")] = None,
    output_format: Annotated[LintFormat, typer.Option(
        "--output-format", help="text (for people), concise (one line each), json (a stable "
        "contract), github, gitlab, junit or sarif.")] = LintFormat.text,
    output_file: Annotated[Path | None, typer.Option(
        "--output-file", "-o", help="Write the report to this file (atomically) instead of stdout.")] = None,
    statistics: Annotated[bool, typer.Option(
        "--statistics", help="Print the number of findings per code to stderr.")] = False,
    exit_zero: Annotated[bool, typer.Option(
        "--exit-zero", help="Exit 0 even when there are findings (usage errors still exit 2).")] = False,
    config: Annotated[Path | None, typer.Option(
        "--config", help="Use this configuration file for every file (zero.toml or pyproject.toml).")] = None,
    isolated: Annotated[bool, typer.Option(
        "--isolated", help="Ignore all configuration files.")] = False,
    strict: Annotated[bool, typer.Option(help="Exit 1 on warnings too.")] = False,
    select: Annotated[list[str] | None, typer.Option(
        help="Only these codes or prefixes (repeatable, or comma-separated).")] = None,
    ignore: Annotated[list[str] | None, typer.Option(
        help="Skip these codes or prefixes (repeatable, or comma-separated).")] = None,
    kind: Annotated[str | None, typer.Option(
        help="List kind instead of detecting it: zero, axis, channel, tool, startup, ...")] = None,
    jobs: Annotated[int | None, typer.Option(
        "--jobs", "-j", help="Processes for many files [default: all cores; 1 = no parallelism].")] = None,
    fix: Annotated[bool, typer.Option("--fix", help="Apply safe fixes to the files.")] = False,
    show_diff: Annotated[bool, typer.Option(
        "--diff", help="Show the fixes as a unified diff; write nothing.")] = False,
    unsafe_fixes: Annotated[bool, typer.Option(
        "--unsafe-fixes", help="Also apply fixes that change what the controller reads.")] = False,
    stdin_filename: Annotated[str | None, typer.Option(
        "--stdin-filename", help="Lint standard input as this file (for editors).")] = None,
    machine: Annotated[Path | None, typer.Option(
        "--machine", help="Lint every list a start-up list (hochlauf.lis) names, plus the checks "
        "across them (X rules).")] = None,
) -> None:
    """Check list files and report what the controller will do with them."""
    from zero.commands import UsageError, run_lint

    try:
        if not paths and stdin_filename is None and machine is None:
            raise UsageError("give list files or directories (or - with --stdin-filename)")
        code = run_lint([str(p) for p in paths or []], output_format.value, strict, select, ignore, kind,
                        state.param_desc, jobs, output_file, statistics, exit_zero, config, isolated,
                        fix, show_diff, unsafe_fixes, stdin_filename, machine)
    except UsageError as exc:
        raise _fail(str(exc)) from None
    if code:
        raise typer.Exit(code=code)


class Format(StrEnum):
    lis = "lis"
    yaml = "yaml"
    toml = "toml"
    json = "json"


def _kind_option(kind: str | None) -> str | None:
    from zero.commands import UsageError, parse_kind

    try:
        return parse_kind(kind)
    except UsageError as exc:
        raise _fail(str(exc)) from None


@app.command()
def convert(
    inputs: Annotated[list[str], typer.Argument(
        help="Files to convert (list, YAML, TOML or JSON); - reads standard input.")],
    to: Annotated[Format | None, typer.Option(
        "--to", help="Output format [default: from -o's suffix; yaml for a list, lis otherwise].")] = None,
    from_: Annotated[Format | None, typer.Option(
        "--from", help="Input format [default: from the suffix; lis for standard input].")] = None,
    output: Annotated[str | None, typer.Option(
        "-o", "--output", help="Output file; - or nothing writes to standard output.")] = None,
    out_dir: Annotated[Path | None, typer.Option(
        "--out-dir", help="Write one file per input here (name.yaml, name.lis, ...).")] = None,
    force: Annotated[bool, typer.Option(help="Replace existing output files.")] = False,
    kind: Annotated[str | None, typer.Option(help="List kind instead of detecting it.")] = None,
    check: Annotated[bool, typer.Option(
        help="Lint the list a YAML/TOML/JSON input makes and report the findings.")] = True,
    strict: Annotated[bool, typer.Option(
        help="Refuse (exit 1, nothing written) when that lint finds an error.")] = False,
) -> None:
    """Convert lists to YAML/TOML/JSON and back, keeping values, order, comments and layout."""
    from zero.convert import (
        ConvertError,
        output_path,
        source_format,
        target_format,
        write_atomic,
    )
    from zero.convert import (
        convert as run_convert,
    )
    from zero.diagnostics import Severity
    from zero.lint import ZeroError, read_file
    from zero.report import render_text

    forced = _kind_option(kind)
    if len(inputs) > 1 and out_dir is None:
        raise _fail("several inputs need --out-dir (one output file per input)")
    if output is not None and out_dir is not None:
        raise _fail("give either -o/--output or --out-dir, not both")
    if inputs.count("-") > 1 or ("-" in inputs and out_dir is not None):
        raise _fail("standard input (-) converts alone, to -o or standard output")

    jobs = []
    failed = False
    try:
        for name in inputs:
            src_fmt = (from_.value if from_ else "lis") if name == "-" else \
                source_format(from_.value if from_ else None, name)
            dst_fmt = target_format(to.value if to else None, output, src_fmt)
            data = sys.stdin.buffer.read() if name == "-" else read_file(name)
            try:
                result = run_convert(data, src_fmt, dst_fmt, name, forced, check)
            except ConvertError as exc:
                sys.stderr.write(f"zero: {exc}\n")
                failed = True
                continue
            for note in result.notes:
                sys.stderr.write(f"zero: note: {name}: {note}\n")
            shown = [d for d in result.lint.diagnostics if d.severity >= Severity.WARNING] \
                if result.lint is not None else []
            if result.lint is not None and shown:
                from zero.lint import LintResult

                render_text([LintResult(result.lint.path, result.lint.document, result.lint.kind, shown)],
                            sys.stderr, summary=False)
                if strict and result.lint.worst is not None and result.lint.worst >= Severity.ERROR:
                    sys.stderr.write(f"zero: {name}: not converted (--strict): the list has errors\n")
                    failed = True
                    continue
            jobs.append((name, dst_fmt, result.output))
        if failed:
            raise typer.Exit(code=1)
        sources = tuple(Path(n) for n in inputs if n != "-")
        if out_dir is not None:
            targets = [output_path(Path(n), f, out_dir) for n, f, _ in jobs]
            if len(set(targets)) != len(targets):
                raise ZeroError("two inputs would write the same output name; convert them separately")
            out_dir.mkdir(parents=True, exist_ok=True)
            for target, (_, _, data) in zip(targets, jobs, strict=True):
                write_atomic(target, data, force, sources)
        elif output is not None and output != "-":
            write_atomic(Path(output), jobs[0][2], force, sources)
        else:
            sys.stdout.buffer.write(jobs[0][2])
            sys.stdout.buffer.flush()
    except ZeroError as exc:
        raise _fail(str(exc)) from None


def _read_side(name: str, fmt: Format | None, kind: str | None, registry: Registry) -> Side:
    from zero.convert import ConvertError, source_format
    from zero.diff import read_side
    from zero.lint import ZeroError, read_file

    try:
        src = (fmt.value if fmt else "lis") if name == "-" else source_format(fmt.value if fmt else None, name)
        data = sys.stdin.buffer.read() if name == "-" else read_file(name)
        return read_side(data, src, name, registry, kind)
    except (ZeroError, ConvertError) as exc:
        raise _fail(str(exc)) from None


@app.command()
def diff(
    a: Annotated[str, typer.Argument(help="Old side: list, YAML, TOML or JSON (- for stdin).")],
    b: Annotated[str | None, typer.Argument(help="New side (omit with --defaults).")] = None,
    defaults: Annotated[bool, typer.Option(
        "--defaults", help="Compare A with the registry defaults: what this machine changed.")] = False,
    strict: Annotated[bool, typer.Option(
        help="Also show default-vs-absent and values written differently but equal.")] = False,
    comments: Annotated[bool, typer.Option(help="Comment changes count too.")] = False,
    output_format: Annotated[OutputFormat, typer.Option(
        "--output-format", help="text (a table) or json (one object per change).")] = OutputFormat.text,
    from_: Annotated[Format | None, typer.Option("--from", help="Format of both inputs.")] = None,
    kind: Annotated[str | None, typer.Option(help="List kind instead of detecting it.")] = None,
) -> None:
    """Compare two lists by parameter: added, removed, changed, with mm/° deltas.

    Exit 0 when equal, 1 when different, 2 on error (like diff).
    """
    import json

    from zero.diff import DiffOptions, diff_defaults, diff_sides
    from zero.report import render_diff

    forced = _kind_option(kind)
    registry = _registry()
    options = DiffOptions(strict=strict, comments=comments)
    if defaults:
        if b is not None:
            raise _fail("--defaults compares one file with the registry; give one file")
        side = _read_side(a, from_, forced, registry)
        changes = diff_defaults(side, options, registry)
        header = f"{a}: {len(changes)} parameters differ from the registry defaults"
    else:
        if b is None:
            raise _fail("give two files to compare (or one with --defaults)")
        if a == "-" and b == "-":
            raise _fail("only one side can be standard input")
        side_a = _read_side(a, from_, forced, registry)
        side_b = _read_side(b, from_, forced or side_a.kind, registry)
        changes = diff_sides(side_a, side_b, options, registry)
        header = f"--- {a}\n+++ {b}"
    if output_format is OutputFormat.json:
        sys.stdout.write(json.dumps([c.to_json() for c in changes], indent=2, ensure_ascii=False) + "\n")
    elif changes:
        render_diff(changes, header)
    counted = [c for c in changes if c.kind != "same"]
    if counted:
        raise typer.Exit(code=1)


@app.command()
def show(
    path: Annotated[str, typer.Argument(help="A list, YAML, TOML or JSON file (- for stdin).")],
    from_: Annotated[Format | None, typer.Option("--from", help="Input format.")] = None,
    kind: Annotated[str | None, typer.Option(help="List kind instead of detecting it.")] = None,
) -> None:
    """Print a list as the controller reads it: one parameter per line, grouped (for git textconv)."""
    from zero.diff import show_lines

    registry = _registry()
    side = _read_side(path, from_, _kind_option(kind), registry)
    sys.stdout.write("\n".join(show_lines(side, registry)) + "\n")


@app.command()
def schema(
    kind: Annotated[str | None, typer.Option(
        help="Only this list kind (zero, axis, channel, ...); all kinds when omitted.")] = None,
    output: Annotated[str | None, typer.Option("-o", "--output", help="Write to this file.")] = None,
    force: Annotated[bool, typer.Option(help="Replace an existing output file.")] = False,
    allow_unknown: Annotated[bool, typer.Option(
        help="Admit keys the registry does not know (by default they fail, like R001).")] = False,
) -> None:
    """Print a JSON Schema of the structured (YAML/TOML/JSON) form for editors."""
    import json

    from zero.convert import write_atomic
    from zero.lint import ZeroError
    from zero.schema import build_schema

    text = json.dumps(build_schema(_registry(), _kind_option(kind), strict=not allow_unknown),
                      indent=2, ensure_ascii=False) + "\n"
    if output is None or output == "-":
        sys.stdout.write(text)
        return
    try:
        write_atomic(Path(output), text.encode("utf-8"), force)
    except ZeroError as exc:
        raise _fail(str(exc)) from None


@app.command()
def limits(
    machine: Annotated[Path | None, typer.Option(
        "--machine", help="The start-up list (hochlauf.lis) [default: [tool.zero.machine] startup].")] = None,
    output_format: Annotated[OutputFormat, typer.Option(
        "--output-format", help="text (a table) or json.")] = OutputFormat.text,
    all_groups: Annotated[bool, typer.Option(
        "--all-groups", help="All 97 groups, not only G53..G59 and the ones the list sets.")] = False,
    profile: Annotated[str | None, typer.Option(
        help="Also apply a rule set: ip247 (Siemens S5: offsets and limits within ±99.999999 m).")] = None,
) -> None:
    """Soft limits in the programming coordinate system, per work offset (G53..G59, G159=n) and axis."""
    import json

    from zero.config import ConfigFinder
    from zero.lint import ZeroError
    from zero.machine import ip247, load_machine, pcs_limits
    from zero.report import render_limits

    if profile not in (None, "ip247"):
        raise _fail(f"unknown profile {profile!r} (known: ip247)")
    try:
        cfg = ConfigFinder().for_path(machine if machine is not None else Path.cwd())
        startup = machine or cfg.machine
        if startup is None:
            raise ZeroError("name the start-up list with --machine (or [tool.zero.machine] startup)")
        m = load_machine(startup, _registry(), None, cfg.machine_lists)
    except ZeroError as exc:
        raise _fail(str(exc)) from None
    rows = pcs_limits(m, all_groups)
    violations = ip247(m) if profile == "ip247" else []
    if output_format is OutputFormat.json:
        data: dict[str, object] = {"limits": [r.to_json() for r in rows]}
        if profile:
            data["violations"] = [{"what": v.what, "value": v.value, "where": v.where} for v in violations]
        sys.stdout.write(json.dumps(data, indent=2, ensure_ascii=False) + "\n")
    else:
        render_limits(rows, violations)
    if violations:
        raise typer.Exit(code=1)


@app.command("format")
def format_cmd(
    paths: Annotated[list[Path], typer.Argument(help="List files or directories.")],
    check: Annotated[bool, typer.Option("--check", help="Only say which files would change (exit 1).")] = False,
    diff: Annotated[bool, typer.Option("--diff", help="Show the changes as a unified diff; write nothing.")] = False,
    config: Annotated[Path | None, typer.Option("--config", help="Use this configuration file.")] = None,
    isolated: Annotated[bool, typer.Option("--isolated", help="Ignore configuration files.")] = False,
) -> None:
    """Rewrite lists in canonical layout (aligned values and comments); keys, values, comments
    and their order stay."""
    from zero.commands import UsageError, run_format

    try:
        code = run_format(paths, check, diff, config, isolated)
    except UsageError as exc:
        raise _fail(str(exc)) from None
    if code:
        raise typer.Exit(code=code)


@app.command("config")
def config_cmd(
    path: Annotated[Path, typer.Argument(help="A list file or directory whose configuration to show.")] = Path("."),
    show: Annotated[bool, typer.Option("--show", help="Print the effective configuration.")] = True,
    config: Annotated[Path | None, typer.Option("--config", help="Use this configuration file.")] = None,
    isolated: Annotated[bool, typer.Option("--isolated", help="Ignore configuration files.")] = False,
) -> None:
    """Show the configuration that applies to PATH ([tool.zero], zero.toml, .zero.toml)."""
    from zero.config import ConfigFinder
    from zero.lint import ZeroError

    try:
        cfg = ConfigFinder(config, isolated).for_path(path)
    except ZeroError as exc:
        raise _fail(str(exc)) from None
    if show:
        typer.echo(cfg.show(), nl=False)


@app.command("rule")
def rule_cmd(
    code: Annotated[str | None, typer.Argument(help="A rule code such as S004.")] = None,
    all_: Annotated[bool, typer.Option("--all", help="Explain every rule.")] = False,
) -> None:
    """Explain a rule: what it checks, why it matters on the machine, and the fix."""
    from zero.report import rule_text, rules_overview
    from zero.rules import RULES

    if all_:
        typer.echo("\n".join(rule_text(c) for c in RULES))
        return
    if code is None:
        typer.echo(rules_overview(), nl=False)
        return
    if code.upper() not in RULES:
        raise _fail(f"unknown rule {code!r} (see `zero rule` for the list)")
    typer.echo(rule_text(code.upper()), nl=False)


@app.command()
def param(
    name: Annotated[str, typer.Argument(help="A parameter ID (P-AXIS-00178) or key (kenngr.swe_pos).")],
    kind: Annotated[str | None, typer.Option(help="List kind, where a key exists in several.")] = None,
) -> None:
    """Show what zero knows about a parameter: type, range, default, unit, meaning."""
    from zero.model import parse_key
    from zero.registry import kind_from_name
    from zero.report import param_text

    registry = _registry()
    spec = registry.get(name.strip().upper()) if name.upper().startswith("P-") else None
    indices: tuple[int, ...] = ()
    if spec is None:
        key = parse_key(name.strip())
        if key is not None:
            forced = kind_from_name(kind) if kind else None
            spec = registry.by_pattern(key.pattern, forced) or registry.alias(key.pattern, forced)
            indices = key.indices
    if spec is None:
        near = registry.suggest(name.strip(), None)
        hint = f" (did you mean {near[0]}?)" if near else ""
        raise _fail(f"unknown parameter {name!r}{hint}")
    text = param_text(spec, registry)
    if indices:
        text = f"{'element':<7}  {name.strip()}\n" + text
    typer.echo(text, nl=False)


def main() -> None:
    """Console-script entry point: typer, with a last guard against tracebacks."""
    try:
        app()
    except SystemExit:
        raise
    except KeyboardInterrupt:
        sys.stderr.write("zero: interrupted\n")
        raise SystemExit(130) from None
    except BrokenPipeError:  # the reader went away (`zero ... | head`): stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        raise SystemExit(141) from None
    except Exception as exc:  # a bug in zero: one line, unless debugging
        if os.environ.get("ZERO_DEBUG"):
            raise
        sys.stderr.write(f"zero: internal error: {type(exc).__name__}: {exc} "
                         "(set ZERO_DEBUG=1 for the traceback)\n")
        raise SystemExit(2) from None

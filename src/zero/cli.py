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
    from zero.registry import Registry

app = typer.Typer(
    name="zero",
    help="Lint, diff and convert ISG kernel CNC parameter lists.",
    add_completion=False,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
)


class OutputFormat(StrEnum):
    text = "text"
    json = "json"


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
    paths: Annotated[list[Path], typer.Argument(help="List files or directories (*.lis, *.lst).")],
    output_format: Annotated[OutputFormat, typer.Option(
        "--output-format", help="text (for people) or json (a stable contract).")] = OutputFormat.text,
    strict: Annotated[bool, typer.Option(help="Exit 1 on warnings too.")] = False,
    select: Annotated[list[str] | None, typer.Option(
        help="Only these codes or prefixes (repeatable, or comma-separated).")] = None,
    ignore: Annotated[list[str] | None, typer.Option(
        help="Skip these codes or prefixes (repeatable, or comma-separated).")] = None,
    kind: Annotated[str | None, typer.Option(
        help="List kind instead of detecting it: zero, axis, channel, tool, startup, ...")] = None,
) -> None:
    """Check list files and report what the controller will do with them."""
    from zero.diagnostics import Severity
    from zero.lint import LintOptions, ZeroError, collect_files, lint_file
    from zero.registry import KINDS, kind_from_name
    from zero.report import render_json, render_text
    from zero.rules import RULES

    forced = None
    if kind is not None:
        forced = kind_from_name(kind)
        if forced is None:
            names = ", ".join(v[0] for v in KINDS.values())
            raise _fail(f"unknown list kind {kind!r} (use one of: {names})")

    def codes(values: list[str] | None) -> tuple[str, ...]:
        out = tuple(c.strip().upper() for v in values or () for c in v.split(",") if c.strip())
        for c in out:
            if not any(code.startswith(c) for code in RULES):
                raise _fail(f"{c!r} matches no rule code (see `zero rule --all`)")
        return out

    options = LintOptions(select=codes(select), ignore=codes(ignore), kind=forced)
    registry = _registry()
    try:
        files = collect_files(paths)
        if not files:
            raise ZeroError("no list files found (looked for *.lis and *.lst)")
        results = [lint_file(f, registry, options) for f in files]
    except ZeroError as exc:
        raise _fail(str(exc)) from None

    if output_format is OutputFormat.json:
        render_json(results)
    else:
        render_text(results)
    worst = max((r.worst for r in results if r.worst is not None), default=None)
    threshold = Severity.WARNING if strict else Severity.ERROR
    if worst is not None and worst >= threshold:
        raise typer.Exit(code=1)


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
    except Exception as exc:  # a bug in zero: one line, unless debugging
        if os.environ.get("ZERO_DEBUG"):
            raise
        sys.stderr.write(f"zero: internal error: {type(exc).__name__}: {exc} "
                         "(set ZERO_DEBUG=1 for the traceback)\n")
        raise SystemExit(2) from None

"""The typer command line: one function per command, each a few lines over the engine.

Exit codes come from :mod:`zero.cli.exits`; every command body runs under its guard,
so a :class:`~zero.errors.ZeroError` is one line on stderr and exit 2, never a traceback.
``zero lint``'s parameters are generated from the option table in :mod:`zero.cli.options`.
"""

from __future__ import annotations

import gc
import inspect
import sys
import typing
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
import typer.core

from zero import __version__
from zero.catalog.registry import KINDS, ParamSpec, Registry
from zero.cli import PYTHON_GC_THRESHOLDS, exits
from zero.cli.help import ZeroCommand, ZeroGroup
from zero.cli.options import COMMON_OPTIONS, LINT_OPTIONS, PATHS_HELP, Option, PathOption, close_matches
from zero.cli.run import (
    REGISTRIES,
    check_kind,
    echo,
    kind_completions,
    read_stdin,
    render_lint,
    rule_completions,
    run_fleet_diff,
)
from zero.cli.run import lint as run_lint_command
from zero.diff import SAME, DiffOptions, show_lines
from zero.engine.commands import parse_kind
from zero.engine.config_file import config_schema_text
from zero.engine.convert import check_convert_options, convert_inputs, write_into, write_outputs
from zero.engine.project import Common, Project, open_project
from zero.engine.queries import find_param, load_side, machine_of, run_diff, run_effective, run_limits
from zero.errors import ZeroError
from zero.files import write_report
from zero.output.docs import param_text, rule_text, rules_overview
from zero.output.queries import diff_json, effective_json, limits_json, schema_json
from zero.output.tables import render_diff, render_effective, render_limits
from zero.output.text import render_text
from zero.rules import RULES
from zero.structured.schema import build_schema

if TYPE_CHECKING:  # start-up: the fleet only with --fleet
    pass

# ---------------------------------------------------------------- values, completion
# Values are checked here, not by typer: typer 0.29 checks them with pydantic and says
# "Value error, 'xml' is not one of …" or "Input should be greater than or equal to 0".


def _bad(ctx: Any, param: Any, message: str) -> Exception:
    """A bad value, said plainly: which option (or environment variable) gave it, and why."""
    hint = "'" + "' / '".join(param.opts) + "'"
    source = ctx.get_parameter_source(param.name) if hasattr(ctx, "get_parameter_source") else None
    envvar = getattr(param, "envvar", None)
    if envvar and getattr(source, "name", "") == "ENVIRONMENT":
        hint = f"{hint} (from the environment variable {envvar})"
    return typer.BadParameter(message, param_hint=hint)


def choice(values: Sequence[str]) -> dict[str, Any]:
    """``typer.Option`` arguments for a value that must be one of ``values``: checked with a plain
    message, and completed in the shell."""

    def check(ctx, param, value):  # type: ignore[no-untyped-def]  # typer passes them by position
        if value is None or value in values:
            return value
        near = close_matches(value, values)
        hint = f" (did you mean {near[0]}?)" if near else ""
        raise _bad(ctx, param, f"{value!r} is not one of {', '.join(values)}{hint}")

    def complete(incomplete: str) -> list[str]:
        return [v for v in values if v.startswith(incomplete)]

    return {"callback": check, "autocompletion": complete}


def count(minimum: int = 0) -> dict[str, Any]:
    """``typer.Option`` arguments for a whole number at least ``minimum``, checked with a plain message."""

    def check(ctx, param, value):  # type: ignore[no-untyped-def]  # typer passes them by position
        if value is None or isinstance(value, int):
            return value
        text = value.strip()
        body = text[1:] if text[:1] in "+-" else text
        if not body.isdigit() or int(text) < minimum:
            raise _bad(ctx, param, f"{value!r} is not a whole number of at least {minimum}")
        return int(text)

    return {"callback": check}


def complete_kind(incomplete: str) -> list[tuple[str, str]]:
    """Shell completion of ``--kind``: the list kinds."""
    return kind_completions(incomplete)


def complete_codes(incomplete: str) -> list[tuple[str, str]]:
    """Shell completion of ``--select``, ``--ignore``, ``--extend-select`` and ``zero rule``: codes and prefixes."""
    return rule_completions(incomplete)


KIND_OPTION: dict[str, Any] = {"autocompletion": complete_kind, "metavar": "KIND"}

app = typer.Typer(
    name="zero",
    help="Lint, diff and convert ISG kernel CNC parameter lists.",
    cls=ZeroGroup,
    add_completion=True,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,  # no rich panels (the help is zero's own; errors plain)
)

REPORTS = ("text", "json")  # the output formats of diff, show and explain
LIMITS_FORMATS = (*REPORTS, "svg")  # zero limits also draws
FORMATS = ("lis", "yaml", "toml", "json", "xml")  # the formats of convert's --to and --from


class _State:
    param_desc: Path | None = None


def _param_desc_given(value: Path | None) -> Path | None:
    """``--param-desc`` after the command: the same as before it."""
    if value is not None:
        state.param_desc = value
    return value


ParamDesc = Annotated[Path | None, typer.Option(
    "--param-desc", help="Use this CncParaDesc.xml instead of the built-in table.", metavar="FILE",
    callback=_param_desc_given, expose_value=True)]


state = _State()


def _project(common: Common | None = None, machine: Path | None = None) -> Project:
    """The resolver of this run (one per command): the settings of each file, from the common options."""
    return open_project(REGISTRIES, common or Common(param_desc=state.param_desc), machine=machine)


def _file(name: str | Path | None) -> Path | None:
    """A file named on the command line as the resolver is asked about it (``-``: none)."""
    return Path(name) if name is not None and str(name) != "-" else None


def _registry(path: str | Path | None = None) -> Registry:
    """The catalogue of the current directory (``zero schema``, ``zero param``: no list is read)."""
    return _project().settings(_file(path)).registry


def _run(command: Callable[[], int]) -> None:
    """Run a command body under the guard; exit with its code when it is not 0."""
    code = exits.guard(command)
    if code:
        raise typer.Exit(code=code)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"zero {__version__}")
        raise typer.Exit()


@app.callback()
def main_callback(
    version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True,
                                          help="Show the version and exit.")] = False,
    param_desc: Annotated[Path | None, typer.Option(
        "--param-desc", help="Use this CncParaDesc.xml instead of the built-in table.", metavar="FILE",
        envvar="ZERO_PARAM_DESC")] = None,
) -> None:
    """zero: lint ISG kernel CNC parameter lists before the machine boots."""
    state.param_desc = param_desc


# ------------------------------------------------------------------------------ lint


_CODE_OPTIONS = ("select", "extend_select", "ignore")


def _typer_parameter(option: Option) -> inspect.Parameter:
    """One ``zero lint`` option from the table as a typer parameter (values checked by zero, not typer)."""
    names = [f"{option.flags[0]}/{option.negative}"] if option.negative else list(option.flags)
    extra: dict[str, Any] = {}
    annotation: Any
    if option.kind == "flag":
        annotation = bool
    elif option.kind == "multi":
        annotation = list[str] | None
    elif option.choices:
        annotation = str
        extra.update(choice(option.choices))
    elif option.type is int:
        annotation = str | None  # read by count(): a plain message for a bad number
        extra.update(count(option.minimum or 0))
    else:
        annotation = (Path if option.type is PathOption else option.type) | None
    if option.dest in _CODE_OPTIONS:
        extra["autocompletion"] = complete_codes
    elif option.dest == "kind":
        extra["autocompletion"] = complete_kind
    if option.metavar:
        extra["metavar"] = option.metavar
    if option.envvar:
        extra["envvar"] = option.envvar
    marker = typer.Option(*names, help=option.help, **extra)
    return inspect.Parameter(option.dest, inspect.Parameter.KEYWORD_ONLY,
                             annotation=Annotated[annotation, marker], default=option.default)


def _lint(**params: Any) -> None:
    """Check list files and report what the controller will do with them."""
    params["paths"] = params.get("paths") or []
    params["select"] = params.get("select") or []
    params["ignore"] = params.get("ignore") or []
    params["extend_select"] = params.get("extend_select") or []
    params["param_desc"] = params.get("param_desc") or state.param_desc
    _run(lambda: run_lint_command(**params))


_paths = inspect.Parameter("paths", inspect.Parameter.POSITIONAL_OR_KEYWORD, default=None,
                           annotation=Annotated[list[Path] | None, typer.Argument(help=PATHS_HELP, metavar="PATH")])
_lint.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
    [_paths, *(_typer_parameter(o) for o in LINT_OPTIONS)])
_lint.__annotations__ = {p.name: p.annotation for p in _lint.__signature__.parameters.values()}  # type: ignore[attr-defined]
app.command("lint", cls=ZeroCommand)(_lint)


_COMMON = tuple(o.dest for o in COMMON_OPTIONS)


def common_options(command: Callable[..., None]) -> Callable[..., None]:
    """A command that reads lists takes the common options (``--config``, ``--isolated``,
    ``--param-desc``, ``--kernel``) from the one table (:data:`zero.cli.options.COMMON_OPTIONS`,
    as ``zero lint`` does) and receives them as one :class:`~zero.engine.project.Common`
    (its keyword ``common``)."""
    hints = typing.get_type_hints(command, include_extras=True)  # the annotations are strings (postponed)
    own = [p.replace(annotation=hints[p.name]) for p in inspect.signature(command).parameters.values()
           if p.name != "common"]

    def wrapper(**params: Any) -> None:
        given = {name: params.pop(name) for name in _COMMON}
        common = Common(tuple(given["config"] or ()), bool(given["isolated"]),
                        given["param_desc"] or state.param_desc, given["kernel"])
        command(**params, common=common)

    wrapper.__name__ = command.__name__
    wrapper.__doc__ = command.__doc__
    wrapper.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
        [*own, *(_typer_parameter(o) for o in COMMON_OPTIONS)])
    wrapper.__annotations__ = {p.name: p.annotation for p in wrapper.__signature__.parameters.values()}  # type: ignore[attr-defined]
    return wrapper


# --------------------------------------------------------------------------- convert


@app.command(cls=ZeroCommand)
@common_options
def convert(
    inputs: Annotated[list[str], typer.Argument(
        help="Files to convert (list, YAML, TOML or JSON); - reads standard input.", metavar="FILE")],
    to: Annotated[str | None, typer.Option(
        "--to", help="Output format [default: from -o's suffix; yaml for a list, lis otherwise].",
        metavar="FORMAT", **choice(FORMATS))] = None,
    from_: Annotated[str | None, typer.Option(
        "--from", help="Input format [default: from the suffix; lis for standard input].", metavar="FORMAT",
        **choice(FORMATS))] = None,
    output: Annotated[str | None, typer.Option(
        "-o", "--output", help="Output file; - or nothing writes to standard output.", metavar="FILE")] = None,
    out_dir: Annotated[Path | None, typer.Option(
        "--out-dir", help="Write one file per input here (name.yaml, name.lis, ...).", metavar="DIR")] = None,
    force: Annotated[bool, typer.Option(help="Replace existing output files.")] = False,
    kind: Annotated[str | None, typer.Option(help="List kind instead of detecting it.", **KIND_OPTION)] = None,
    check: Annotated[bool, typer.Option(
        help="Lint the list a YAML/TOML/JSON input makes and report the findings.")] = True,
    strict: Annotated[bool, typer.Option(
        help="Refuse (exit 1, nothing written) when that lint finds an error.")] = False,
    item: Annotated[str | None, typer.Option(
        "--item", help="The list of a TwinCAT export to convert (AchsMds, SdaMds, NullpD, WerkzD, PzvD, VeD, "
        "Startup); with --out-dir and without --item, every list it holds.", metavar="ELEMENT")] = None,
    into: Annotated[Path | None, typer.Option(
        "--into", help="Put the list back into this TwinCAT export (its --item element's CDATA; every other "
        "byte kept).", metavar="EXPORT")] = None,
    *, common: Common,
) -> None:
    """Convert lists to XML/YAML/TOML/JSON and back, keeping values, order, comments and layout."""

    def body() -> int:
        forced = parse_kind(check_kind(kind))
        project = _project(common)

        def catalogue(name: str) -> Registry:
            return project.settings(_file(name)).registry

        if into is not None:
            if len(inputs) != 1 or output is not None or out_dir is not None or to is not None:
                raise ZeroError("--into puts one list into an export: give one input and no -o/--out-dir/--to")
            write_into(inputs[0], into, item, catalogue, read_stdin, src=from_, kind=forced, project=project)
            return exits.OK
        check_convert_options(inputs, output, out_dir)
        items = convert_inputs(inputs, catalogue, read_stdin, src=from_,
                               to=to, output=output, kind=forced, check=check,
                               strict=strict, element=item, every_list=out_dir is not None, project=project)
        for done in items:
            if done.error is not None and done.findings is None:
                sys.stderr.write(f"zero: {done.error}\n")
                continue
            for note in done.notes:
                sys.stderr.write(f"zero: note: {done.name}: {note}\n")
            if done.findings is not None:
                render_text([done.findings], sys.stderr, summary=False)
            if done.error is not None:
                sys.stderr.write(f"zero: {done.error}\n")
        if any(done.failed for done in items):
            return exits.FINDINGS
        data = write_outputs(items, output, out_dir, force)
        if data is not None:
            echo().out_bytes(data)
        return exits.OK

    _run(body)


# ------------------------------------------------------------------------ diff, show


@app.command(cls=ZeroCommand)
@common_options
def diff(
    a: Annotated[str, typer.Argument(help="Old side: list, YAML, TOML or JSON (- for stdin).", metavar="A")],
    b: Annotated[list[str] | None, typer.Argument(
        help="New side (omit with --defaults); with --fleet: machines (start-up lists or folders of machines).",
        metavar="B")] = None,
    defaults: Annotated[bool, typer.Option(
        "--defaults", help="Compare A with the registry defaults: what this machine changed.")] = False,
    strict: Annotated[bool, typer.Option(
        help="Also show default-vs-absent and values written differently but equal.")] = False,
    comments: Annotated[bool, typer.Option(help="Comment changes count too.")] = False,
    output_format: Annotated[str, typer.Option(
        "--output-format", help="text (a table), json (one object per change), or csv (with --fleet).",
        metavar="FORMAT", **choice((*REPORTS, "csv")))] = "text",
    from_: Annotated[str | None, typer.Option("--from", help="Format of both inputs.", metavar="FORMAT",
                                              **choice(FORMATS))] = None,
    kind: Annotated[str | None, typer.Option(help="List kind instead of detecting it.", **KIND_OPTION)] = None,
    machine: Annotated[bool, typer.Option(
        "--machine", help="A and B are start-up lists: compare the machines' effective values list by list.")] = False,
    revert: Annotated[str | None, typer.Option(
        "--revert", help="With A a list and B its update file: apply B, then this revert file, and show what "
        "is not put back (nothing: exit 0).", metavar="REVERT")] = None,
    fleet: Annotated[str | None, typer.Option(
        "--fleet", help="Compare every machine given (A, B...: start-up lists, or folders holding one machine per "
        "subfolder) with this golden machine: which parameters differ, on which machines, with which values.",
        metavar="GOLDEN")] = None,
    jobs: Annotated[int | None, typer.Option(
        "--jobs", "-j", help="With --fleet: compare in this many processes [default: all cores].", metavar="N")] = None,
    no_cache: Annotated[bool, typer.Option(
        "--no-cache", help="With --fleet: compare every machine again; neither read nor write the cache "
        "(.zero_cache; also ZERO_NO_CACHE=1).")] = False,
    *, common: Common,
) -> None:
    """Compare two lists by parameter: added, removed, changed, with mm/° deltas.

    B may be an update file: the diff then shows what applying it to A changes.
    Exit 0 when equal, 1 when different, 2 on error (like diff).
    """

    def body() -> int:
        if fleet is not None:
            other = [name for name, given in (("--defaults", defaults), ("--machine", machine), ("--strict", strict),
                                              ("--comments", comments), ("--revert", revert is not None),
                                              ("--from", from_ is not None), ("--kind", kind is not None)) if given]
            return _fleet_diff(fleet, [a, *(b or [])], output_format, jobs, other, common, cache=not no_cache)
        if output_format == "csv":
            raise ZeroError("--output-format csv is the report of --fleet")
        if b is not None and len(b) > 1:
            raise ZeroError(f"give two files to compare, not {1 + len(b)} (many machines: --fleet GOLDEN MACHINE...)")
        forced = parse_kind(check_kind(kind))
        run = run_diff(a, b[0] if b else None, _project(common), read_stdin, defaults=defaults,
                       options=DiffOptions(strict=strict, comments=comments),
                       fmt=from_, kind=forced, machine=machine, revert=revert)
        if output_format == "json":
            sys.stdout.write(diff_json(run.changes))
        elif run.changes:
            render_diff(run.changes, run.header)
        return exits.found(any(c.kind != SAME for c in run.changes))

    _run(body)


def _fleet_diff(golden: str, machines: list[str], output_format: str, jobs: int | None, other: list[str],
                common: Common, cache: bool = True) -> int:
    """``zero diff --fleet GOLDEN MACHINE...``: the report on standard output, and its exit code."""
    if other:
        raise ZeroError(f"--fleet compares machines' effective values: {', '.join(other)} does not apply to it")
    from zero.engine.fleet import FleetRequest  # start-up: only with --fleet

    return run_fleet_diff(FleetRequest(golden, machines, jobs=jobs, param_desc=common.param_desc, config=common.configs,
                                       isolated=common.isolated, cache=cache), REGISTRIES, output_format, sys.stdout)


@app.command(cls=ZeroCommand)
@common_options
def show(
    args: Annotated[list[str] | None, typer.Argument(
        help="A list, YAML, TOML or JSON file (- for stdin); with --machine: keys, IDs or patterns.",
        metavar="FILE|KEY")] = None,
    machine: Annotated[Path | None, typer.Option(
        "--machine", help="Show the effective values of every list this start-up list loads, with origins.",
        metavar="STARTUP")] = None,
    effective_: Annotated[bool, typer.Option(
        "--effective", help="With --machine: also the catalogue defaults of what no list sets.")] = False,
    textconv: Annotated[bool, typer.Option(
        "--textconv", help="With --machine: name files relative to the start-up list's folder (for a git "
        "textconv, whose copy lies in a new temporary folder each time).")] = False,
    output_format: Annotated[str, typer.Option(
        "--output-format", help="text or json (with --machine).", metavar="FORMAT", **choice(REPORTS))] = "text",
    from_: Annotated[str | None, typer.Option("--from", help="Input format.", metavar="FORMAT",
                                              **choice(FORMATS))] = None,
    kind: Annotated[str | None, typer.Option(help="List kind instead of detecting it.", **KIND_OPTION)] = None,
    *, common: Common,
) -> None:
    """Print a list as the controller reads it: one parameter per line, grouped (for git textconv);
    with --machine, every list of a machine with each value's origin."""

    def body() -> int:
        if machine is not None:
            return _effective(_project(common, machine), args or [], effective_, False, output_format, textconv)
        if not args or len(args) != 1:
            raise ZeroError("give one file to show (or --machine STARTUP [KEY...])")
        project = _project(common)
        registry = project.settings(_file(args[0])).registry
        side = load_side(args[0], from_, parse_kind(check_kind(kind)), registry, read_stdin, project)
        sys.stdout.write("\n".join(show_lines(side, registry)) + "\n")
        return exits.OK

    _run(body)


def _effective(project: Project, keys: list[str], with_defaults: bool, explain: bool,
               output_format: str, textconv: bool = False) -> int:
    run = run_effective(project, keys, with_defaults, explain)
    if output_format == "json":
        sys.stdout.write(effective_json(run))
    else:
        render_effective(run.summary, run.scopes, explain=explain, textconv=textconv)
    return exits.OK


@app.command(cls=ZeroCommand)
@common_options
def explain(
    keys: Annotated[list[str], typer.Argument(
        help="Keys, IDs or patterns (kenngr.swe_pos, P-AXIS-00178, 'kenngr.*').", metavar="KEY")],
    machine: Annotated[Path | None, typer.Option(
        "--machine", help="The start-up list [default: [tool.zero.machine] startup].",
        metavar="STARTUP")] = None,
    output_format: Annotated[str, typer.Option("--output-format", help="text or json.",
        metavar="FORMAT", **choice(REPORTS))] = "text",
    *, common: Common,
) -> None:
    """Where the value of a parameter comes from on a machine: the list, the default list under it,
    or the catalogue, for every list of the machine that has it."""
    _run(lambda: _effective(_project(common, machine), keys, False, True, output_format))


# ---------------------------------------------------------------------------- schema


@app.command(cls=ZeroCommand)
def schema(
    kind: Annotated[str | None, typer.Option(
        help="Only this list kind (zero, axis, channel, ...); all kinds when omitted.", **KIND_OPTION)] = None,
    output: Annotated[str | None, typer.Option("-o", "--output", help="Write to this file.", metavar="FILE")] = None,
    force: Annotated[bool, typer.Option(help="Replace an existing output file.")] = False,
    allow_unknown: Annotated[bool, typer.Option(
        help="Admit keys the registry does not know (by default they fail, like R001).")] = False,
    param_desc: ParamDesc = None,
) -> None:
    """Print a JSON Schema of the structured (YAML/TOML/JSON) form for editors."""

    def body() -> int:
        text = schema_json(build_schema(_registry(), parse_kind(check_kind(kind)), strict=not allow_unknown))
        if output is None or output == "-":
            sys.stdout.write(text)
        else:
            write_report(Path(output), text.encode("utf-8"), force=force)
        return exits.OK

    _run(body)


# ---------------------------------------------------------------------------- limits


@app.command(cls=ZeroCommand)
@common_options
def limits(
    machine: Annotated[Path | None, typer.Option(
        "--machine", help="The start-up list (hochlauf.lis) [default: [tool.zero.machine] startup].",
        metavar="STARTUP")] = None,
    output_format: Annotated[str, typer.Option(
        "--output-format", help="text (a table), json, or svg (a picture of every axis).", metavar="FORMAT",
        **choice(LIMITS_FORMATS))] = "text",
    all_groups: Annotated[bool, typer.Option(
        "--all-groups", help="All 97 groups, not only G53..G59 and the ones the list sets.")] = False,
    profile: Annotated[str | None, typer.Option(
        help="Also apply a rule set: ip247 (Siemens S5: offsets and limits within ±99.999999 m).",
        metavar="PROFILE")] = None,
    *, common: Common,
) -> None:
    """Soft limits in the programming coordinate system, per work offset (G53..G59, G159=n) and axis."""

    def body() -> int:
        project = _project(common, machine)
        run = run_limits(project, all_groups, profile)
        if output_format == "svg":
            from zero.output.svg import limits_svg  # start-up: only for a picture

            sys.stdout.write(limits_svg(machine_of(project), run.rows))
        elif output_format == "json":
            sys.stdout.write(limits_json(run, profile))
        else:
            render_limits(run.rows, run.violations)
        return exits.found(bool(run.violations))

    _run(body)


# ---------------------------------------------------------------------------- report


@app.command(cls=ZeroCommand)
@common_options
def report(
    machine: Annotated[Path | None, typer.Option(
        "--machine", help="The start-up list (hochlauf.lis) [default: [tool.zero.machine] startup].",
        metavar="STARTUP")] = None,
    output: Annotated[str | None, typer.Option(
        "-o", "--output", help="The HTML file to write; - or nothing writes to standard output.",
        metavar="FILE")] = None,
    against: Annotated[str | None, typer.Option(
        "--against", help="Also show the differences from this machine: a golden start-up list, or a git "
        "revision (HEAD~1) of this machine's lists.", metavar="GOLDEN")] = None,
    fleet: Annotated[list[str] | None, typer.Option(
        "--fleet", help="Also show the fleet's drift from this machine (repeatable): start-up lists of other "
        "machines, or folders of machines, as zero diff --fleet.", metavar="MACHINE")] = None,
    jobs: Annotated[int | None, typer.Option(
        "--jobs", "-j", help="With --fleet: compare in this many processes [default: all cores].", metavar="N")] = None,
    values: Annotated[str, typer.Option(
        "--values", help="The value table printed (and shown first): changed (the values that differ from their "
        "defaults, are changed by the controller or have a finding) or all.", metavar="all|changed")] = "changed",
    program: Annotated[list[str] | None, typer.Option(
        "--program", help="Also draw where this NC program takes each axis (repeatable).", metavar="PROG")] = None,
    force: Annotated[bool, typer.Option(help="Replace an existing output file.")] = False,
    *, common: Common,
) -> None:
    """Write one self-contained HTML page about a machine: its channels and axes, a picture of each
    axis's travel range with the work offsets, the effective values with their origin, every finding,
    the differences from a golden machine or a git revision, and a fleet's drift from it. Needs the
    report extra (Jinja2)."""

    def body() -> int:
        from zero.engine.report import report_facts  # start-up: only for a report
        from zero.output.report import build_report, check_values, render_report  # start-up: Jinja2 as above

        target = Path(output) if output not in (None, "-") else None
        check_values(values)
        facts = report_facts(_project(common, machine), against, fleet or (), jobs, program or ())
        page = render_report(build_report(facts, target, values))
        if target is None:
            sys.stdout.write(page)
        else:
            write_report(target, page.encode("utf-8"), force=force)
        return exits.OK

    _run(body)


# ---------------------------------------------------------------------------- format


@app.command("format", cls=ZeroCommand)
@common_options
def format_cmd(
    paths: Annotated[list[Path], typer.Argument(help="List files or directories; - formats standard input.",
        metavar="PATH")],
    check: Annotated[bool, typer.Option("--check", help="Only say which files would change (exit 1).")] = False,
    diff: Annotated[bool, typer.Option("--diff", help="Show the changes as a unified diff; write nothing.")] = False,
    stdin_filename: Annotated[str | None, typer.Option(
        "--stdin-filename", help="Format standard input as this file (its configuration applies).",
        metavar="NAME")] = None,
    *, common: Common,
) -> None:
    """Rewrite lists in canonical layout (aligned values and comments); keys, values, comments
    and their order stay."""

    def body() -> int:
        from zero.engine.formatting import run_format  # start-up: the catalogue and tokenizer only to format

        run = run_format(paths, REGISTRIES, echo(), check, diff, common.configs, common.isolated, common.param_desc,
                         read_stdin, stdin_filename)
        if [str(p) for p in paths] == ["-"]:
            return exits.found(bool(run.failed or (run.changed and (check or diff))))
        verb = "would be reformatted" if (check or diff) else "reformatted"
        skipped = run.failed + run.unreadable
        sys.stderr.write(f"{run.changed} file{'s' if run.changed != 1 else ''} {verb}, "
                         f"{run.files - run.changed - skipped} unchanged"
                         + (f", {skipped} not formatted" if skipped else "") + "\n")
        if run.unreadable:
            return exits.USAGE  # a file could not be read, as zero lint says it
        return exits.found(bool(run.failed or (run.changed and (check or diff))))

    _run(body)


# ---------------------------------------------------------------------------- server


@app.command("server", cls=ZeroCommand)
def server_cmd(
    stdio: Annotated[bool, typer.Option(
        "--stdio", help="Talk over standard input and output: the default and only transport (accepted for "
        "editors that pass it).", show_default=False)] = False,
    param_desc: ParamDesc = None,
) -> None:
    """Run the language server (LSP) for editors: findings as you type, hover, completion, fixes,
    formatting, outline (see the README's Editors section)."""

    def body() -> int:
        from zero.server.lsp import serve  # start-up: pygls only for the server

        gc.set_threshold(*PYTHON_GC_THRESHOLDS)  # a long run: cycles must be collected (see zero.cli)
        serve(REGISTRIES, state.param_desc)
        return exits.OK

    _run(body)


# ------------------------------------------------------------------ config, rule, param


@app.command("config", cls=ZeroCommand)
@common_options
def config_cmd(
    path: Annotated[Path, typer.Argument(help="A list file or directory whose configuration to show.",
        metavar="PATH")] = Path("."),
    show: Annotated[bool, typer.Option("--show", help="Print the effective configuration.")] = True,
    schema: Annotated[bool, typer.Option("--schema", help="Print the JSON Schema of zero.toml and [tool.zero] "
                                         "(zero.schema.json, for taplo and editors) instead.")] = False,
    *, common: Common,
) -> None:
    """Show the configuration that applies to PATH ([tool.zero], zero.toml, .zero.toml)."""

    def body() -> int:
        if schema:
            sys.stdout.write(config_schema_text())
            return exits.OK
        cfg = _project(common).config(path, directory=path.is_dir())
        if show:
            sys.stdout.write(cfg.show())
        return exits.OK

    _run(body)


@app.command("rule", cls=ZeroCommand)
def rule_cmd(
    code: Annotated[str | None, typer.Argument(help="A rule code such as S004.", metavar="CODE",
                                               autocompletion=complete_codes)] = None,
    all_: Annotated[bool, typer.Option("--all", help="Explain every rule.")] = False,
) -> None:
    """Explain a rule: what it checks, why it matters on the machine, and the fix."""

    def body() -> int:
        if all_:
            registry = _registry()  # a K rule's consequence and every rule's parameters name keys
            sys.stdout.write("\n".join(rule_text(c, registry) for c in RULES) + "\n")
        elif code is None:
            sys.stdout.write(rules_overview())
        elif code.upper() not in RULES:
            raise ZeroError(f"unknown rule {code!r} (see `zero rule` for the list)")
        else:
            sys.stdout.write(rule_text(code.upper(), _registry()))
        return exits.OK

    _run(body)


@app.command(cls=ZeroCommand)
def param(
    name: Annotated[str, typer.Argument(help="A parameter ID (P-AXIS-00178), key (kenngr.swe_pos) or a word to search.",
                                        metavar="NAME")],
    kind: Annotated[str | None, typer.Option(help="List kind, where a key exists in several.", **KIND_OPTION)] = None,
    param_desc: ParamDesc = None,
) -> None:
    """Show what zero knows about a parameter: type, range, default, unit, meaning."""

    def body() -> int:
        registry = _registry()
        found = find_param(registry, name, parse_kind(check_kind(kind)))
        if found.spec is None:
            sys.stdout.write(f"{len(found.matches)} parameters match {name.strip()!r}"
                             f"{' (the first 20)' if len(found.matches) == 20 else ''}; `zero param ID` shows one:\n")
            for match in found.matches:
                sys.stdout.write(f"  {match.id}  {match.key or '(no key)'}  ({KINDS[match.kind][1]})\n")
            return exits.OK
        if found.searched:
            sys.stdout.write(f"(the one parameter matching {name.strip()!r})\n")
        text = param_text(found.spec, registry)
        if found.indices:
            text = f"{'element':<7}  {name.strip()}{_outside(found.spec, found.indices)}\n" + text
        sys.stdout.write(text)
        return exits.OK

    _run(body)


def _outside(spec: ParamSpec, indices: tuple[int, ...]) -> str:
    """A note when an index lies outside its array (what R003 reports in a list)."""
    outside = spec.index_outside(indices)
    if outside is None:
        return ""
    pos, idx = outside
    return f"  (index {idx} is outside {spec.valid_indices(pos)}: no such element, R003)"


def main() -> None:
    """Console-script entry point for everything but the lean ``zero lint``."""
    code = exits.guard(lambda: _standalone(app))
    raise SystemExit(code)


# click's own error class (typer 0.29 carries its own copy of click, older typers use click's)
_CLICK_ERROR: type[Exception] = next(c for c in typer.BadParameter.__mro__ if c.__name__ == "ClickException")


def usage_error_line(exc: Exception) -> str:
    """A usage error in one line: the command, what is wrong, and where the help is
    (click prints four: Usage, Try, a blank line, Error)."""
    ctx = getattr(exc, "ctx", None)
    path = getattr(ctx, "command_path", None) or "zero"
    message = " ".join(str(exc.format_message()).split()).rstrip(".")  # type: ignore[attr-defined]
    return f"{path}: {message}; see '{path} --help'"


def _standalone(application: typer.Typer) -> int:
    try:
        code = application(prog_name="zero", standalone_mode=False)
    except SystemExit as exc:
        return exits.of_system_exit(exc.code)
    except typer.Abort:  # click's form of an interrupt
        raise KeyboardInterrupt from None
    except _CLICK_ERROR as exc:
        if type(exc).__name__ == "NoArgsIsHelpError":  # `zero` alone: the help, as click shows it
            exc.show()  # type: ignore[attr-defined]
        else:
            sys.stderr.write(usage_error_line(exc) + "\n")
        return int(getattr(exc, "exit_code", exits.USAGE))
    return code if isinstance(code, int) else exits.OK


__all__ = ["app", "main", "render_lint"]

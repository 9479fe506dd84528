"""The options of ``zero lint``, defined once.

Both command lines are built from :data:`LINT_OPTIONS`: the typer command
(:mod:`zero.cli.app`, its parameters generated from this table) and the lean parser of
the pre-commit path (:func:`parse_lint_args`, which imports neither typer nor rich). A
test holds the two to the same options and the same parsed values; anything the lean
parser does not accept exactly (``--help``, a bad value, ``-j4``) goes to typer, which
gives the same result or the error message.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from zero.output import OUTPUT_FORMATS
from zero.records import record


@record(frozen=True)
class Option:
    dest: str  # the keyword of zero.cli.run.lint
    flags: tuple[str, ...]  # long name first
    help: str
    kind: Literal["flag", "value", "multi"] = "value"
    type: type = str  # str, int or Path
    choices: tuple[str, ...] = ()
    minimum: int | None = None
    negative: str | None = None  # the flag that sets a "flag" option back to False
    default: object = None
    metavar: str | None = None  # the value's placeholder in --help

    @property
    def names(self) -> tuple[str, ...]:
        return (*self.flags, self.negative) if self.negative else self.flags


PATHS_HELP = "List files or directories (*.lis, *.lst); - reads standard input."

LINT_OPTIONS: tuple[Option, ...] = (
    Option("output_format", ("--output-format",),
           "text (for people), concise (one line each), json (a stable contract), github, gitlab, junit "
           "or sarif.", choices=OUTPUT_FORMATS, default="text", metavar="FORMAT"),
    Option("output_file", ("--output-file", "-o"),
           "Write the report to this file (atomically) instead of stdout.", type=Path, metavar="FILE"),
    Option("show_statistics", ("--statistics",), "Print the number of findings per code to stderr.", "flag",
           default=False),
    Option("exit_zero", ("--exit-zero",), "Exit 0 even when there are findings (usage errors still exit 2).",
           "flag", default=False),
    Option("config", ("--config",),
           "Use this configuration file for every file (zero.toml or pyproject.toml).", type=Path, metavar="FILE"),
    Option("isolated", ("--isolated",), "Ignore all configuration files.", "flag", default=False),
    Option("strict", ("--strict",), "Exit 1 on warnings too.", "flag", negative="--no-strict", default=False),
    Option("select", ("--select",), "Only these codes or prefixes (repeatable, or comma-separated).", "multi",
        metavar="CODES"),
    Option("extend_select", ("--extend-select",),
           "Add these codes or prefixes to the selection (opt-in rules by their full code).", "multi", metavar="CODES"),
    Option("ignore", ("--ignore",), "Skip these codes or prefixes (repeatable, or comma-separated).", "multi",
        metavar="CODES"),
    Option("kind", ("--kind",), "List kind instead of detecting it: zero, axis, channel, tool, startup, ...",
        metavar="KIND"),
    Option("jobs", ("--jobs", "-j"),
           "Processes for many files (default: all cores; 0 = all cores, 1 = no parallelism).", type=int,
           minimum=0, metavar="N"),
    Option("fix", ("--fix",), "Apply safe fixes to the files.", "flag", default=False),
    Option("show_diff", ("--diff",), "Show the fixes as a unified diff; write nothing.", "flag", default=False),
    Option("add_noqa", ("--add-noqa",),
           "Record today's findings: add a `noqa` with their codes to each entry line (a baseline).",
           "flag", default=False),
    Option("unsafe_fixes", ("--unsafe-fixes",), "Also apply fixes that change what the controller reads.",
           "flag", default=False),
    Option("stdin_filename", ("--stdin-filename",), "Lint standard input as this file (for editors).", metavar="NAME"),
    Option("param_desc", ("--param-desc",), "Use this CncParaDesc.xml instead of the built-in table.",
           type=Path, metavar="FILE"),
    Option("machine", ("--machine",),
           "Lint every list a start-up list (hochlauf.lis) names, plus the checks across them (X rules).",
           type=Path, metavar="STARTUP"),
)


def _value(option: Option, text: str) -> object | None:
    """The option's value from its text; ``None`` when typer must judge it."""
    if option.choices and text not in option.choices:
        return None
    if option.type is int:
        body = text[1:] if text[:1] == "-" else text
        if not body.isdigit():
            return None
        number = int(text)
        return None if option.minimum is not None and number < option.minimum else number
    return Path(text) if option.type is Path else text


def parse_lint_args(args: list[str]) -> dict[str, object] | None:
    """``zero lint`` arguments as keyword arguments; ``None`` when typer must decide."""
    by_name = {name: o for o in LINT_OPTIONS for name in o.names}
    out: dict[str, object] = {o.dest: [] if o.kind == "multi" else o.default for o in LINT_OPTIONS}
    paths: list[Path] = []
    i = 0
    only_paths = False
    while i < len(args):
        a = args[i]
        i += 1
        if only_paths or not a.startswith("-") or a == "-":
            paths.append(Path(a))
            continue
        if a == "--":
            only_paths = True
            continue
        # `--name=value`; a short option takes its value as the next argument (click reads
        # `-o=x` as the value `=x`: such forms go to typer).
        name, eq, text = a.partition("=") if a.startswith("--") else (a, "", "")
        option = by_name.get(name)
        if option is None:
            return None
        if option.kind == "flag":
            if eq:
                return None
            out[option.dest] = name != option.negative
            continue
        if not eq:
            if i >= len(args):
                return None
            text = args[i]
            i += 1
        value = _value(option, text)
        if value is None:
            return None
        if option.kind == "multi":
            multi = out[option.dest]
            assert isinstance(multi, list)
            multi.append(value)
        else:
            out[option.dest] = value
    if not paths and out["stdin_filename"] is None and out["machine"] is None:
        return None
    out["paths"] = paths
    return out

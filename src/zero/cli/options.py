"""The options of ``zero lint``, defined once.

Both command lines are built from :data:`LINT_OPTIONS`: the typer command
(:mod:`zero.cli.app`, its parameters generated from this table) and the lean parser of
the pre-commit path (:func:`parse_lint_args`, which imports neither typer nor rich). A
test holds the two to the same options and the same parsed values; anything the lean
parser does not accept exactly (``--help``, a bad value, ``-j4``) goes to typer, which
gives the same result or the error message.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping

from zero.files import path_str
from zero.forms import LIST_SUFFIXES, PROGRAM_SUFFIXES, XML_SUFFIX
from zero.output.formats import OUTPUT_FORMATS
from zero.output.formats import help_text as format_help
from zero.records import Record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Literal


class PathOption:
    """The ``type`` of an option whose value names a file: a ``str`` to the lean parser, as a ``Path``
    prints it (:func:`zero.files.path_str`: pathlib with urllib.parse and ipaddress is 7% of a lint's
    start-up), a ``pathlib.Path`` to typer (:mod:`zero.cli.app`, which completes file names for it)."""


class Option(Record, frozen=True):
    dest: str  # the keyword of zero.cli.run.lint
    flags: tuple[str, ...]  # long name first
    help: str
    kind: Literal["flag", "value", "multi"] = "value"
    type: type = str  # str, int or PathOption
    choices: tuple[str, ...] = ()
    minimum: int | None = None
    negative: str | None = None  # the flag that sets a "flag" option back to False
    default: object = None
    metavar: str | None = None  # the value's placeholder in --help
    envvar: str | None = None  # the environment variable that gives the value when the option is not given

    @property
    def names(self) -> tuple[str, ...]:
        return (*self.flags, self.negative) if self.negative else self.flags


# How close a typo must be to be suggested: `--jbos` → `--jobs` (0.83), `axsi` → `axis` (0.75),
# but not `--bogus` → `--jobs` (0.62) nor `respect-gitignore` → `per-file-ignores` (0.61).
SUGGEST_CUTOFF = 0.7

PATHS_HELP = (f"Files or directories: lists ({', '.join('*' + s for s in LIST_SUFFIXES)}), the kernel's XML lists "
              f"and TwinCAT exports (*{XML_SUFFIX}), YAML/TOML/JSON forms named on the command line, NC programs "
              f"({', '.join('*' + s for s in PROGRAM_SUFFIXES)}); - reads standard input.")

# The options of every command that reads lists (lint, format, show, explain, diff, limits, convert,
# report, config): which configuration applies, which catalogue, which kernel release. Declared here
# once; `zero lint` takes them from LINT_OPTIONS, the other commands from COMMON_OPTIONS, and the
# engine receives them as one zero.engine.project.Common.
CONFIG = Option("config", ("--config",),
                "A configuration file for every file (zero.toml or pyproject.toml), or KEY = VALUE over the "
                "configuration that applies, as in ruff (repeatable).", "multi", metavar="FILE|KEY=VALUE")
ISOLATED = Option("isolated", ("--isolated",), "Ignore all configuration files.", "flag", default=False)
KERNEL = Option("kernel", ("--kernel", "--target-version"),
                "The kernel release the machines run (as `kernel` in the configuration), e.g. V3.1.3079.",
                metavar="RELEASE")
PARAM_DESC = Option("param_desc", ("--param-desc",), "Use this CncParaDesc.xml instead of the built-in table.",
                    type=PathOption, metavar="FILE")
COMMON_OPTIONS: tuple[Option, ...] = (CONFIG, ISOLATED, PARAM_DESC, KERNEL)

LINT_OPTIONS: tuple[Option, ...] = (
    Option("output_format", ("--output-format",), format_help(), choices=OUTPUT_FORMATS, default="text",
           metavar="FORMAT", envvar="ZERO_OUTPUT_FORMAT"),
    Option("output_file", ("--output-file", "-o"),
           "Write the report to this file (atomically) instead of stdout.", type=PathOption, metavar="FILE"),
    Option("show_statistics", ("--statistics",),
           "Print the number of findings per code instead of the findings (as ruff).", "flag", default=False),
    Option("exit_zero", ("--exit-zero",), "Exit 0 even when there are findings (usage errors still exit 2).",
           "flag", default=False),
    Option("exit_non_zero_on_fix", ("--exit-non-zero-on-fix",),
           "With --fix: exit 1 when a file was fixed, even if no finding remains.", "flag", default=False),
    Option("quiet", ("--quiet", "-q"), "Print the findings only: no summary line, no progress, no notes.",
           "flag", default=False),
    Option("silent", ("--silent", "-s"), "Print nothing but errors; the exit code still tells.", "flag",
           default=False),
    Option("watch", ("--watch", "-w"), "Lint again whenever a file below PATH changes, until interrupted.", "flag",
           default=False),
    Option("show_files", ("--show-files",), "List the files that would be checked, and exit.", "flag",
           default=False),
    CONFIG,
    ISOLATED,
    Option("strict", ("--strict",), "Exit 1 on warnings too.", "flag", negative="--no-strict", default=False),
    Option("select", ("--select",), "Only these codes or prefixes (repeatable, or comma-separated).", "multi",
           metavar="CODES"),
    Option("extend_select", ("--extend-select",),
           "Add these codes or prefixes to the selection (opt-in rules by their full code).", "multi", metavar="CODES"),
    Option("ignore", ("--ignore",), "Skip these codes or prefixes (repeatable, or comma-separated).", "multi",
           metavar="CODES"),
    Option("exclude", ("--exclude",),
           "Skip files and directories matching these patterns, in place of the configuration's `exclude` "
           "(repeatable, or comma-separated).", "multi", metavar="PATTERNS"),
    Option("extend_exclude", ("--extend-exclude",),
           "Skip these patterns as well as those the configuration excludes.", "multi", metavar="PATTERNS"),
    Option("respect_gitignore", ("--respect-gitignore",),
           "Skip what .gitignore ignores when walking a directory (default: the configuration's "
           "respect-gitignore, which is true).", "flag", negative="--no-respect-gitignore"),
    Option("force_exclude", ("--force-exclude",),
           "Exclude files named on the command line too, as a pre-commit hook needs (the default); "
           "--no-force-exclude checks every named file.", "flag", negative="--no-force-exclude"),
    KERNEL,
    Option("kind", ("--kind",), "List kind instead of detecting it: zero, axis, channel, tool, startup, ...",
           metavar="KIND"),
    Option("jobs", ("--jobs", "-j"),
           "Processes for many files (default: all cores; 0 = all cores, 1 = no parallelism).", type=int,
           minimum=0, metavar="N"),
    Option("fix", ("--fix",), "Apply safe fixes to the files.", "flag", default=False),
    Option("fix_only", ("--fix-only",), "Apply safe fixes and report no finding (implies --fix).", "flag",
           default=False),
    Option("show_fixes", ("--show-fixes",),
           "After the findings, list the fixes: applied (with --fix) or available, per file.", "flag", default=False),
    Option("show_diff", ("--diff",), "Show the fixes as a unified diff; write nothing.", "flag", default=False),
    Option("add_noqa", ("--add-noqa",),
           "Record today's findings: add a `noqa` with their codes to each entry line (a baseline).",
           "flag", default=False),
    Option("ignore_noqa", ("--ignore-noqa",), "Report the findings `noqa` and the other suppressions hide.",
           "flag", default=False),
    Option("no_cache", ("--no-cache",),
           "Lint every file again: neither read nor write the cache (.zero_cache; also ZERO_NO_CACHE=1).",
           "flag", default=False),
    Option("unsafe_fixes", ("--unsafe-fixes",), "Also apply fixes that change what the controller reads.",
           "flag", default=False),
    Option("stdin_filename", ("--stdin-filename",), "Lint standard input as this file (for editors).", metavar="NAME"),
    PARAM_DESC,
    Option("machine", ("--machine",),
           "Lint every list a start-up list (hochlauf.lis) names, plus the checks across them (X rules).",
           type=PathOption, metavar="STARTUP"),
)


def close_matches(word: str, candidates: Iterable[str], cutoff: float = SUGGEST_CUTOFF) -> list[str]:
    """The candidates ``word`` is likely a typo of, nearest first (did-you-mean).

    difflib's default cutoff (0.6) suggests ``--jobs`` for ``--bogus`` and ``per-file-ignores``
    for ``respect-gitignore``: only close ones are offered."""
    from zero.nearest import close_matches as nearest  # start-up: only for a word that is not known

    return nearest(word, candidates, n=3, cutoff=cutoff)


def did_you_mean(word: str, candidates: Iterable[str]) -> str:
    """`` (did you mean `x`?)`` for a likely typo; empty when nothing is close."""
    near = close_matches(word, candidates)
    return f" (did you mean {near[0]}?)" if near else ""


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
    return path_str(text) if option.type is PathOption else text


FLEET_FORMATS = ("text", "json", "csv")


def parse_fleet_args(args: list[str]) -> dict[str, object] | None:
    """``zero diff --fleet GOLDEN MACHINE...`` arguments (after ``diff``) as keyword arguments of
    :func:`zero.cli.run.fleet_diff`; ``None`` when typer must decide (any other option or form, ``--help``
    included: typer gives the same result, or its message). Read: ``--fleet GOLDEN``, ``--output-format
    text|json|csv``, ``-j``/``--jobs N``, ``--no-cache``, ``--config X`` (repeatable), ``--isolated``,
    ``--param-desc P``, and the machines."""
    out: dict[str, object] = {"golden": None, "machines": [], "output_format": "text", "jobs": None,
                              "no_cache": False, "config": [], "isolated": False, "param_desc": None}
    machines: list[str] = []
    config: list[str] = []
    i = 0
    while i < len(args):
        a = args[i]
        i += 1
        if not a.startswith("-"):
            machines.append(a)
        elif a in ("--no-cache", "--isolated"):
            out[a[2:].replace("-", "_")] = True
        elif a in ("--fleet", "--output-format", "-j", "--jobs", "--config", "--param-desc"):
            if i >= len(args) or args[i].startswith("-") or not args[i]:
                return None
            value = args[i]
            i += 1
            if a == "--fleet":
                if out["golden"] is not None:
                    return None
                out["golden"] = value
            elif a == "--output-format":
                if value not in FLEET_FORMATS:
                    return None
                out["output_format"] = value
            elif a in ("-j", "--jobs"):
                if not value.isascii() or not value.isdigit():
                    return None
                out["jobs"] = int(value)
            elif a == "--config":
                config.append(value)
            else:
                out["param_desc"] = value
        else:
            return None
    if out["golden"] is None or not machines:
        return None
    out["machines"], out["config"] = machines, config
    return out


def parse_lint_args(args: list[str], environ: Mapping[str, str] | None = None) -> dict[str, object] | None:
    """``zero lint`` arguments as keyword arguments; ``None`` when typer must decide.

    An option not given takes its value from its environment variable (``environ``, by default
    ``os.environ``), as typer does."""
    by_name = {name: o for o in LINT_OPTIONS for name in o.names}
    out: dict[str, object] = {o.dest: [] if o.kind == "multi" else o.default for o in LINT_OPTIONS}
    paths: list[str] = []
    given: set[str] = set()
    i = 0
    only_paths = False
    while i < len(args):
        a = args[i]
        i += 1
        if only_paths or not a.startswith("-") or a == "-":
            paths.append(path_str(a))  # as typer's Path prints it (./a.lis: a.lis)
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
        given.add(option.dest)
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
    if environ is None:
        environ = os.environ
    for option in LINT_OPTIONS:
        variable = environ.get(option.envvar) if option.envvar else None
        if variable and option.dest not in given:  # an empty variable is not set (as in click)
            value = _value(option, variable)
            if value is None:
                return None
            out[option.dest] = value
    if not paths and out["stdin_filename"] is None and out["machine"] is None and not out["show_files"]:
        return None
    out["paths"] = paths
    return out

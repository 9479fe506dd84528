"""The help of every command in zero's words: usage line, description, arguments, options,
commands, and the suggestion for a mistyped option.

The help and the usage line are written here from the parameters (their names, metavar, help,
default, environment variable), not by typer: what typer/click print differs between their
versions (typer 0.29 shows Python types: ``PATH... <list[Path]>``, ``{FILE...}...``). Kept apart
from :mod:`zero.cli.app`, whose commands only say which parameters they take.
"""

from __future__ import annotations

import inspect
import shutil
import textwrap
from collections.abc import Sequence
from enum import Enum
from typing import Any

import typer
import typer.core

from zero.cli.options import close_matches

HELP_WIDTH = 80  # help lines never exceed this, whatever the terminal
_COLUMN = 30  # the widest option column before its text goes to the next line


def help_width() -> int:
    """The width of the help: the terminal's (COLUMNS), at most :data:`HELP_WIDTH`."""
    return max(min(shutil.get_terminal_size((HELP_WIDTH, 24)).columns, HELP_WIDTH), 40)


def _wrap(text: str, width: int, indent: str, first: str | None = None) -> list[str]:
    """Paragraphs (blank-line separated) rewrapped to ``width``; words never broken."""
    out: list[str] = []
    for n, paragraph in enumerate(p for p in inspect.cleandoc(text).split("\n\n") if p.strip()):
        if n:
            out.append("")
        out.extend(textwrap.wrap(" ".join(paragraph.split()), width, initial_indent=first if first and not n
                                 else indent, subsequent_indent=indent, break_long_words=False,
                                 break_on_hyphens=False))
    return out


def _is_argument(param: Any) -> bool:
    return getattr(param, "param_type_name", "") == "argument"


def _placeholder(param: Any) -> str:
    """An argument's or option value's placeholder: its metavar, or its name in capitals."""
    name = getattr(param, "metavar", None) or (param.name or "").upper()
    return str(name)


def _usage_piece(param: Any) -> str:
    name = _placeholder(param)
    many = getattr(param, "nargs", 1) != 1
    piece = name if param.required else f"[{name}]"
    return f"{piece}..." if many else piece


def usage_line(command: Any, ctx: Any) -> str:
    """``Usage: zero lint [OPTIONS] [PATH]...``: arguments by their placeholders."""
    pieces = ["[OPTIONS]"] + [_usage_piece(p) for p in command.params if _is_argument(p) and not p.hidden]
    if isinstance(command, typer.core.TyperGroup):
        pieces.append("COMMAND [ARGS]...")
    lines = textwrap.wrap(" ".join(pieces), help_width(), initial_indent=f"Usage: {ctx.command_path} ",
                          subsequent_indent=" " * 8, break_long_words=False, break_on_hyphens=False)
    return "\n".join(lines)


def _shown(value: Any) -> str:
    if isinstance(value, Enum):
        value = value.value
    if isinstance(value, (list, tuple)):
        return ", ".join(_shown(v) for v in value)
    return str(value)


def _extras(param: Any) -> list[str]:
    """``default: …``, ``env var: …``, ``required``: what the help adds in brackets."""
    extras: list[str] = []
    show_default = getattr(param, "show_default", None)
    default = param.default
    if isinstance(show_default, str):
        extras.append(f"default: {show_default}")
    elif show_default is not False and not callable(default):
        if getattr(param, "is_flag", False):
            if param.secondary_opts:  # --strict / --no-strict: which one holds
                name = param.opts[0] if default else param.secondary_opts[0]
                extras.append(f"default: {name.lstrip('-')}")
        elif default not in (None, [], (), "") and not param.required:
            extras.append(f"default: {_shown(default)}")
    envvar = getattr(param, "envvar", None)
    if envvar and getattr(param, "show_envvar", True):
        extras.append(f"env var: {envvar if isinstance(envvar, str) else ', '.join(envvar)}")
    if param.required and _is_argument(param):
        extras.append("required")
    return extras


def _record(param: Any) -> tuple[str, str]:
    """One line of the Arguments or Options section: the names, and the help text."""
    if _is_argument(param):
        names = _placeholder(param)
    else:
        opts = sorted(param.opts, key=lambda o: len(o) - len(o.lstrip("-")))  # -o before --output
        names = ", ".join(opts)
        if param.secondary_opts:
            names += " / " + ", ".join(param.secondary_opts)
        if not getattr(param, "is_flag", False) and not getattr(param, "count", False):
            names += f" {_placeholder(param)}"
    text = getattr(param, "help", None) or ""
    extras = _extras(param)
    if extras:
        text = f"{text}  [{'; '.join(extras)}]" if text else f"[{'; '.join(extras)}]"
    return names, text


def _section(title: str, rows: Sequence[tuple[str, str]], width: int) -> list[str]:
    """A titled definition list: names in the first column, the text wrapped beside them."""
    if not rows:
        return []
    column = min(max(len(name) for name, _ in rows), _COLUMN)
    out = ["", f"{title}:"]
    for name, text in rows:
        indent = " " * (2 + column + 2)
        first = f"  {name:<{column}}  "
        if len(name) > column:
            out.append(f"  {name}")
            first = indent
        out.extend(_wrap(text, width, indent, first) if text.strip() else [first.rstrip()])
    return out


def _short_help(command: Any, limit: int) -> str:
    """The first sentence of a command's help, cut at a word to fit ``limit``."""
    text = " ".join((getattr(command, "short_help", None) or command.help or "").split("\n\n")[0].split())
    sentence, dot, _ = text.partition(". ")
    text = sentence + "." if dot else text
    if len(text) <= limit:
        return text
    return text[:limit - 3].rsplit(" ", 1)[0].rstrip(",;:") + "..."


def help_text(command: Any, ctx: Any) -> str:
    """A command's whole --help: usage, description, arguments, options, commands."""
    width = help_width()
    lines = [usage_line(command, ctx)]
    if command.help:
        lines += ["", *_wrap(command.help, width, "  ")]
    visible = [p for p in command.get_params(ctx) if not getattr(p, "hidden", False)]
    lines += _section("Arguments", [_record(p) for p in visible if _is_argument(p)], width)
    lines += _section("Options", [_record(p) for p in visible if not _is_argument(p)], width)
    if isinstance(command, typer.core.TyperGroup):
        commands = {n: command.get_command(ctx, n) for n in command.list_commands(ctx)}
        shown = {n: c for n, c in commands.items() if c is not None and not c.hidden}
        if shown:
            column = max(len(n) for n in shown)
            lines += _section("Commands", [(n, _short_help(c, width - column - 6)) for n, c in shown.items()], width)
    return "\n".join(lines)  # echoed with its newline


def _suggest_option(command: Any, ctx: Any, exc: Exception) -> None:
    """A mistyped option: suggest only a close one (click's cutoff offers ``--jobs`` for ``--bogus``)."""
    name = getattr(exc, "option_name", None)
    if not isinstance(name, str) or not hasattr(exc, "possibilities"):
        return
    known = [o for p in command.get_params(ctx) if not _is_argument(p) for o in (*p.opts, *p.secondary_opts)]
    near = close_matches(name, known)
    exc.possibilities = None  # the message says it, in zero's words
    exc.message = f"No such option: {name}" + (f" (did you mean {near[0]}?)" if near else "")  # type: ignore[attr-defined]


class _ZeroHelp:
    """Help, usage line and option suggestions in zero's own words (for a command or the group)."""

    def get_help(self, ctx: Any) -> str:
        return help_text(self, ctx)

    def get_usage(self, ctx: Any) -> str:
        return usage_line(self, ctx)

    def format_help(self, ctx: Any, formatter: Any) -> None:
        formatter.write(help_text(self, ctx))

    def parse_args(self, ctx: Any, args: list[str]) -> list[str]:
        try:
            return super().parse_args(ctx, args)  # type: ignore[misc,no-any-return]
        except Exception as exc:
            _suggest_option(self, ctx, exc)
            raise


class ZeroCommand(_ZeroHelp, typer.core.TyperCommand):
    """A typer command whose help, usage line and option suggestions are zero's own."""


class ZeroGroup(_ZeroHelp, typer.core.TyperGroup):
    """The ``zero`` group, with the help of :class:`ZeroCommand`."""


__all__ = ["HELP_WIDTH", "ZeroCommand", "ZeroGroup", "help_text", "help_width", "usage_line"]

"""The documentation site's generated pages, written at build time by mkdocs-gen-files.

One page per command (its help, from the typer app, as ``zero CMD --help`` prints it, with the
hand-written text of ``docs/commands-text/CMD.md`` where there is one), one per rule and one per
parameter of the catalogue (from :mod:`zero.output.docs`), the indexes, and each section's
``SUMMARY.md`` for mkdocs-literate-nav. Nothing on these pages is typed twice: a rule or a parameter
that is added gets its page at the next build, and ``tests/docs`` fails when one has none.

Run by ``mkdocs build`` (the ``gen-files`` plugin in ``mkdocs.yml``); ``tests/docs`` imports it
and calls :func:`pages` to see which pages it makes without building the site.

``ZERO_PARAM_DESC``, where set, names the user's own ``CncParaDesc.xml``: its German parameter names
go onto the parameters' pages as search terms (read at build time, never written into the project).
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from functools import partial
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
COMMAND_TEXTS = DOCS / "commands-text"  # the hand-written part of a command's page, by command


@contextmanager
def _columns(width: int) -> Iterator[None]:
    """The help rendered at ``width`` columns whatever the terminal (it follows COLUMNS)."""
    old = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = str(width)
    try:
        yield
    finally:
        if old is None:
            del os.environ["COLUMNS"]
        else:
            os.environ["COLUMNS"] = old


@functools.cache
def _commands() -> tuple[Any, Any, dict[str, Any]]:
    """The ``zero`` group, its context, and its visible commands by name, in the help's order.

    Contexts are made by the commands' own ``context_class``: typer 0.29 carries its own copy of
    click and no longer installs click, so this module never imports it."""
    import typer.main

    from zero.cli.app import app

    group = typer.main.get_command(app)
    ctx = group.context_class(group, info_name="zero")
    shown = {}
    for name in group.list_commands(ctx):  # type: ignore[attr-defined]
        command = group.get_command(ctx, name)  # type: ignore[attr-defined]
        if command is not None and not command.hidden:
            shown[name] = command
    return group, ctx, shown


def _help() -> Any:
    """The module that renders a command's help: ``zero.cli.help`` (``zero.cli.app`` before it moved)."""
    try:
        from zero.cli import help as module
    except ImportError:
        from zero.cli import app as module
    return module


def _help_page(name: str) -> str:
    """A command's page: what it does, its usage, arguments and options, and ``--help`` as printed."""
    from zero.output.docs import md_code, md_text

    h = _help()
    _record, _short_help, help_text, usage_line = h._record, h._short_help, h.help_text, h.usage_line

    _, root_ctx, commands = _commands()
    command = commands[name]
    ctx = command.context_class(command, info_name=name, parent=root_ctx)
    with _columns(80):
        text = help_text(command, ctx)
        usage = usage_line(command, ctx)
    paragraphs = [" ".join(p.split()) for p in (command.help or "").split("\n\n") if p.strip()]
    out = [f"# zero {name}", "", md_text(_short_help(command, 10_000)), ""]
    out += [md_text(p) + "\n" for p in paragraphs[1:]] if len(paragraphs) > 1 else []
    hand = COMMAND_TEXTS / f"{name}.md"
    if hand.is_file():
        out += [hand.read_text(encoding="utf-8").strip(), ""]
    out += ["## Usage", "", "```text", usage, "```", ""]
    params = [p for p in command.get_params(ctx) if not getattr(p, "hidden", False)]
    for title, arguments in (("Arguments", True), ("Options", False)):
        rows = [_record(p) for p in params if (getattr(p, "param_type_name", "") == "argument") == arguments]
        if rows:
            out += [f"## {title}", "", f"| {title[:-1]} | Meaning |", "| --- | --- |"]
            out += [f"| {md_code(names)} | {md_text(help_) or '–'} |" for names, help_ in rows]
            out.append("")
    out += [f"## `zero {name} --help`", "", "```text", text, "```", ""]
    return "\n".join(out)


def _commands_index() -> str:
    from zero.output.docs import md_text

    _short_help, help_text = _help()._short_help, _help().help_text

    group, ctx, commands = _commands()
    with _columns(80):
        text = help_text(group, ctx)
    out = ["# Commands", "", md_text(group.help or ""), "", "| Command | What it does |", "| --- | --- |"]
    out += [f"| [zero {n}]({n}.md) | {md_text(_short_help(c, 10_000))} |" for n, c in commands.items()]
    out += ["", "## `zero --help`", "", "```text", text, "```", ""]
    return "\n".join(out)


def _commands_summary() -> str:
    _, _, commands = _commands()
    return "\n".join(["* [All commands](index.md)", *(f"* [zero {n}]({n}.md)" for n in commands)]) + "\n"


def _params_summary(registry: Any) -> str:
    from zero.catalog.registry import KINDS

    kinds = sorted({s.kind for s in registry.specs.values()},
                   key=lambda k: (list(KINDS).index(k) if k in KINDS else len(KINDS), k))
    lines = ["* [All parameters](index.md)"]
    names = {k: KINDS.get(k, (k, k))[1] for k in kinds}
    lines += [f"* [{names[k][:1].upper()}{names[k][1:]}]({k}.md)" for k in kinds]
    return "\n".join(lines) + "\n"


def pages() -> dict[str, Callable[[], str]]:
    """Every generated page by its path under ``docs/``, each made when it is called."""
    from zero.catalog.registry import load_registry
    from zero.output import docs
    from zero.rules import RULES

    registry = load_registry()
    desc = os.environ.get("ZERO_PARAM_DESC")  # the user's CncParaDesc.xml: its German names as search terms
    german = docs.german_names(desc) if desc else {}
    english = docs.english_names(desc) if desc else {}  # the meaning of those zero describes nowhere
    out: dict[str, Callable[[], str]] = {
        "commands/index.md": _commands_index,
        "commands/SUMMARY.md": _commands_summary,
        "rules/index.md": docs.rules_index_page,
        "parameters/index.md": partial(docs.params_index_page, registry, desc),
        "parameters/SUMMARY.md": partial(_params_summary, registry),
    }
    for name in _commands()[2]:
        out[f"commands/{name}.md"] = partial(_help_page, name)
    for code in RULES:
        out[docs.rule_page_path(code)] = partial(docs.rule_page, code, ROOT, registry)
    for kind in sorted({s.kind for s in registry.specs.values()}):
        out[docs.kind_page_path(kind)] = partial(docs.kind_page, kind, registry)
    checks: dict[str, Any] = {}

    def param(pid: str) -> str:
        if not checks:
            checks.update(docs.param_checks(registry))
        return docs.param_page(registry.specs[pid], registry, checks[pid], german.get(pid), english.get(pid))

    for pid in registry.specs:
        out[docs.param_page_path(pid)] = partial(param, pid)
    return out


def main() -> None:
    import mkdocs_gen_files

    for path, make in pages().items():
        with mkdocs_gen_files.open(path, "w") as f:
            f.write(make())


if __name__ in ("__main__", "<run_path>"):  # mkdocs-gen-files runs it with runpy.run_path
    main()

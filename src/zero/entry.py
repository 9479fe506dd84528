"""The ``zero`` console script: a lean path for ``zero lint``, typer for the rest.

A pre-commit hook starts ``zero lint`` on every commit, so that path imports
neither typer (with pydantic) nor rich: its options are parsed here, and any
argument this parser does not know (``--help`` included) goes to the full typer
CLI, which gives the same result plus help and error messages.
"""

from __future__ import annotations

import os
import sys

_VALUE_OPTIONS = {"--output-format": "output_format", "--select": "select", "--ignore": "ignore",
                  "--kind": "kind", "--jobs": "jobs", "-j": "jobs", "--output-file": "output_file",
                  "-o": "output_file", "--config": "config",
                  "--stdin-filename": "stdin_filename", "--machine": "machine"}
_FLAGS = {"--strict": ("strict", True), "--no-strict": ("strict", False),
          "--statistics": ("show_statistics", True), "--exit-zero": ("exit_zero", True),
          "--isolated": ("isolated", True), "--fix": ("fix", True), "--diff": ("show_diff", True),
          "--unsafe-fixes": ("unsafe_fixes", True)}


def parse_lint_args(args: list[str]) -> dict[str, object] | None:
    """Options of ``zero lint`` as keyword arguments; ``None`` when typer must decide."""
    out: dict[str, object] = {"paths": [], "select": [], "ignore": []}
    i = 0
    only_paths = False
    while i < len(args):
        a = args[i]
        i += 1
        if only_paths or not a.startswith("-") or a == "-":
            out["paths"].append(a)  # type: ignore[attr-defined]
            continue
        if a == "--":
            only_paths = True
            continue
        if a in _FLAGS:
            name, flag = _FLAGS[a]
            out[name] = flag
            continue
        name, eq, value = a.partition("=")
        field = _VALUE_OPTIONS.get(name)
        if field is None:
            return None
        if not eq:
            if i >= len(args):
                return None
            value = args[i]
            i += 1
        if field in ("select", "ignore"):
            out[field].append(value)  # type: ignore[attr-defined]
        elif field == "jobs":
            if not value.isdigit():
                return None
            out[field] = int(value)
        else:
            out[field] = value
    if not out["paths"] and "stdin_filename" not in out and "machine" not in out:
        return None
    return out


def main() -> None:
    args = sys.argv[1:]
    if args[:1] == ["lint"]:
        parsed = parse_lint_args(args[1:])
        if parsed is not None:
            from zero.commands import UsageError, fail, run_lint

            try:
                code = run_lint(param_desc=os.environ.get("ZERO_PARAM_DESC") or None,
                                **parsed)  # type: ignore[arg-type]
            except UsageError as exc:
                code = fail(str(exc))
            except KeyboardInterrupt:
                sys.stderr.write("zero: interrupted\n")
                code = 130
            except BrokenPipeError:  # the reader went away (`zero lint ... | head`): stop quietly
                os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
                raise SystemExit(141) from None
            except Exception as exc:  # a bug in zero: one line, unless debugging
                if os.environ.get("ZERO_DEBUG"):
                    raise
                code = fail(f"internal error: {type(exc).__name__}: {exc} "
                            "(set ZERO_DEBUG=1 for the traceback)")
            try:
                sys.stdout.flush()
            except BrokenPipeError:
                os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
                code = 141
            raise SystemExit(code)
    from zero.cli import main as typer_main

    typer_main()

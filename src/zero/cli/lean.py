"""The ``zero`` console script: a lean path for ``zero lint``, typer for the rest.

A pre-commit hook starts ``zero lint`` on every commit, so that path imports neither
typer (with pydantic) nor rich: its options are parsed from the one option table
(:mod:`zero.cli.options`), and anything that parser does not accept exactly
(``--help`` included) goes to the typer command line, which gives the same result
plus help and error messages.
"""

from __future__ import annotations

import os
import sys

from zero.cli.exits import guard
from zero.cli.options import parse_lint_args


def main() -> None:
    args = sys.argv[1:]
    if args[:1] == ["lint"]:
        parsed = parse_lint_args(args[1:])
        if parsed is not None:
            from zero.cli.run import lint  # start-up: the engine only once the arguments are known

            parsed["param_desc"] = parsed.get("param_desc") or os.environ.get("ZERO_PARAM_DESC") or None
            raise SystemExit(guard(lambda: lint(**parsed)))  # type: ignore[arg-type]
    from zero.cli.app import main as typer_main  # start-up: typer only off the lean path

    typer_main()

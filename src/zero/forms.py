"""What a file is, by its name: a parameter list, an NC program, or a list's structured form.

The one place that knows the suffixes. ``zero lint`` picks the reader by it, a directory
walk picks up lists and programs by it (the default ``include``), ``zero convert`` takes the
format from it, the language server decides how to analyse a document by it, and a report
written with ``-o`` never replaces a file of these kinds.
"""

from __future__ import annotations

import os

LIST, PROGRAM, STRUCTURED = "list", "program", "structured"
LIST_SUFFIXES = (".lis", ".lst")
PROGRAM_SUFFIXES = (".nc", ".mpf", ".spf")  # NC programs (zero.nc)
STRUCTURED_SUFFIXES = {".yaml": "yaml", ".yml": "yaml", ".toml": "toml", ".json": "json"}
DEFAULT_INCLUDE = tuple(f"*{s}" for s in (*LIST_SUFFIXES, *PROGRAM_SUFFIXES))  # what a directory walk picks up
CONFIG_NAMES = ("zero.toml", ".zero.toml", "pyproject.toml")  # nearest wins; in this order within a folder
# A report (`zero lint -o FILE`) never replaces one of these: lists, programs, list forms, configuration.
NOT_A_REPORT = (*LIST_SUFFIXES, *PROGRAM_SUFFIXES, *(s for s in STRUCTURED_SUFFIXES if s != ".json"))  # JSON: reports
EXTENSION = {"lis": ".lis", "yaml": ".yaml", "toml": ".toml", "json": ".json"}


def _suffix(name: str | os.PathLike[str]) -> str:
    return os.path.splitext(os.fspath(name))[1].lower()


def form_of(name: str | os.PathLike[str]) -> str:
    """A list, an NC program or a structured form; a list unless the suffix says otherwise."""
    suffix = _suffix(name)
    if suffix in PROGRAM_SUFFIXES:
        return PROGRAM
    if suffix in STRUCTURED_SUFFIXES:
        return STRUCTURED
    return LIST


def is_list(name: str | os.PathLike[str]) -> bool:
    """A parameter list by its name (not an NC program, not a YAML/TOML/JSON form)."""
    return form_of(name) == LIST


def is_program(name: str | os.PathLike[str]) -> bool:
    return _suffix(name) in PROGRAM_SUFFIXES


def format_of(name: str | os.PathLike[str]) -> str | None:
    """The format a file name implies for `zero convert` (``None`` when the suffix says nothing)."""
    suffix = _suffix(name)
    return "lis" if suffix in LIST_SUFFIXES else STRUCTURED_SUFFIXES.get(suffix)

"""Finding the files to lint: names given on the command line, and list files below
named directories, without what ``.gitignore`` ignores.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable

from zero.errors import ZeroError
from zero.files import check_regular, path_str, read_file, walk
from zero.forms import PROJECT_SUFFIXES, WALKED_SUFFIXES, XML_SUFFIX, is_project, is_xml_name, xml_form

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TypeAlias

    FileName: TypeAlias = str | os.PathLike[str]


def git_visible(directory: FileName, note: Callable[[str], None] | None = None) -> set[str] | None:
    """Files below ``directory`` that git does not ignore, as paths relative to it
    (``os.sep``-separated); ``None`` outside a git work tree, without git, or where git gives no
    answer (:func:`zero.engine.git.visible_files`: then ``note`` is told why, in one line: the walk
    goes on without the ignore rules, and says so)."""
    from zero.engine.git import visible_files  # start-up: only where a directory is walked

    seen = visible_files(directory)
    if seen.files is None and seen.reason:
        (note or _stderr)(f"zero: {directory}: .gitignore not applied: {seen.reason}\n")
    return seen.files


def _stderr(text: str) -> None:
    sys.stderr.write(text)


_WALKED = WALKED_SUFFIXES


# The suffixes of the files whose content says whether they hold lists (an XML file, a TwinCAT project).
_READ_FOR_LISTS = (XML_SUFFIX, *PROJECT_SUFFIXES)


def holds_lists(path: FileName) -> bool:
    """Does a walked file hold parameter lists? Always, but for XML, which is a list only by its
    content: a kernel XML list or a TwinCAT export (every other XML file of a project is skipped in
    silence). An XML file that cannot be read is kept, so that the lint reports it."""
    text = os.fspath(path)
    if "#" not in text and not text.lower().endswith(_READ_FOR_LISTS):
        return True  # neither an XML file nor a TwinCAT project by its name (most files of a walk): at once
    if is_project(os.path.basename(path)):  # a TwinCAT project: one that holds a `<Data>` block
        try:
            check_regular(path)
            return b"<Data " in read_file(path)
        except (OSError, ZeroError):
            return True
    if not is_xml_name(path):
        return True
    try:
        check_regular(path)
        with open(path, "rb") as f:
            head = f.read(65536)
    except (OSError, ZeroError):
        return True
    return xml_form(head) is not None


GITIGNORE, EXCLUDE = ".gitignore", "exclude"  # what a walk skips a file for (the keys of `skipped`)


def skipped_note(skipped: dict[str, int]) -> str:
    """What a walk left out and how to include it: ``; 3 files skipped by .gitignore
    (--no-respect-gitignore includes them)``; empty when nothing was."""
    how = {GITIGNORE: "--no-respect-gitignore or respect-gitignore = false includes them",
           EXCLUDE: "exclude/extend-exclude in the configuration decides; --no-force-exclude checks files named"}
    parts = [f"{n} file{'s' if n != 1 else ''} skipped by {why} ({how[why]})" for why, n in skipped.items() if n]
    return "; " + "; ".join(parts) if parts else ""


def joined(folder: str, name: str) -> str:
    """``str(Path(folder) / name)`` for a folder as :func:`zero.files.path_str` gives it and a name of
    a directory listing (no ``/``, never ``.``): how a walk names what it finds."""
    return name if folder == "." else folder + name if folder.endswith(os.sep) else folder + os.sep + name


def collect_files(paths: Iterable[FileName], include: Callable[[str], bool] | None = None,
                  exclude: Callable[[str], bool] | None = None,
                  respect_gitignore: bool | Callable[[str], bool] = True,
                  note: Callable[[str], None] | None = None, force_exclude: bool = True,
                  skipped: dict[str, int] | None = None) -> list[str]:
    """Files named explicitly, plus list files below named directories (sorted), each named as a
    ``Path`` prints it (:func:`zero.files.path_str`: ``./a.lis`` is ``a.lis``).

    ``include`` decides which files a directory walk picks up (default: lists ``*.lis``,
    ``*.lst``, NC programs ``*.nc``, ``*.mpf``, ``*.spf`` and ``*.xml`` that hold lists, by their
    content: :func:`holds_lists`); ``exclude`` drops files and
    directories, named ones included. A
    directory walk skips what ``.gitignore`` ignores when the directory is in a git
    work tree and ``respect_gitignore`` (a flag, or the directory's configuration's
    ``respect-gitignore``) says so (named files are always linted). ``force_exclude`` false: a file
    named is linted whatever ``exclude`` says (as ruff without ``--force-exclude``). ``skipped``, where
    given, counts the files a walk would have picked up but ``.gitignore`` or ``exclude`` left out
    (:data:`GITIGNORE`, :data:`EXCLUDE`), for a message that says why nothing was found.
    """
    tally = skipped if skipped is not None else {}
    out: list[str] = []
    for raw in paths:
        p = path_str(raw)
        if os.path.isdir(p):
            respect = respect_gitignore(p) if callable(respect_gitignore) else respect_gitignore
            visible = git_visible(p, note) if respect else None
            found: list[str] = []
            for root, dirs, files in walk(p):
                folder = path_str(root)
                kept_dirs = [d for d in dirs if not d.startswith(".")]
                dirs[:] = sorted(d for d in kept_dirs if not (exclude and exclude(joined(folder, d))))
                if skipped is not None:
                    for d in set(kept_dirs) - set(dirs):  # an excluded folder: what it holds counts as skipped
                        tally[EXCLUDE] = tally.get(EXCLUDE, 0) + _walkable(joined(folder, d), include)
                rel_root = os.path.relpath(root, p)
                for f in files:
                    path = joined(folder, f)
                    wanted = include(path) if include else f.lower().endswith(_WALKED)
                    if visible is not None and os.path.normpath(os.path.join(rel_root, f)) not in visible:
                        if wanted:
                            tally[GITIGNORE] = tally.get(GITIGNORE, 0) + 1
                        continue
                    if wanted and exclude and exclude(path):
                        tally[EXCLUDE] = tally.get(EXCLUDE, 0) + 1
                    elif wanted and holds_lists(path):
                        found.append(path)
            out.extend(sorted(found))
        elif os.path.lexists(p):
            if not (force_exclude and exclude and exclude(p)):
                check_regular(p)  # a FIFO, device, dangling link or loop named here: refused at once
                out.append(p)
        else:
            raise ZeroError("no such file or directory", str(raw))
    return out


def _walkable(directory: str, include: Callable[[str], bool] | None) -> int:
    """How many files below ``directory`` a walk would pick up by their names (for the count of
    what ``exclude`` skipped; hidden folders are never walked)."""
    n = 0
    for root, dirs, files in walk(directory):
        dirs[:] = [d for d in dirs if not d.startswith(".")]
        folder = path_str(root)
        n += sum(1 for f in files if (include(joined(folder, f)) if include else f.lower().endswith(_WALKED)))
    return n

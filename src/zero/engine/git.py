"""The one module that runs git (``tests/test_architecture.py`` allows no other), for every question
zero asks it (which files a walk skips, a revision's lists), with one set of protections: a
repository zero is given must never make it run a program or reach a network.

Every call (:func:`run`) is

* **without transport**: ``protocol.allow=never`` (git refuses every transport, so a partial clone's
  missing object is never fetched lazily from its promisor remote), ``GIT_NO_LAZY_FETCH=1`` (git 2.44
  and later), ``core.sshCommand``, ``core.gitProxy``, ``GIT_SSH*``, the askpass programs and the
  credential helpers neutralised;
* **without a program of the repository's**: no hooks, no fsmonitor, no untracked cache, no pager,
  no external diff; only plumbing that applies no filter and no text conversion (``ls-files``,
  ``rev-parse``, ``ls-tree``, ``cat-file blob``);
* **in a cleared environment**: every ``GIT_*`` variable of the caller removed (the folder asked
  about decides, not the shell's ``GIT_DIR``), no terminal prompt, no optional locks, standard input
  closed, English messages;
* **bounded**: a time limit (:data:`TIMEOUT`); past it the question has no answer, and zero says so.

A blob the repository does not hold (a partial clone) is a :class:`~zero.errors.ZeroError` that
says so: zero fetches nothing and stops.
"""

from __future__ import annotations

import os
import stat
from collections.abc import Callable, Iterator

from zero.errors import ZeroError
from zero.files import describe, path_str, walk
from zero.forms import split_part
from zero.records import Record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: subprocess only when git is asked (and pathlib never: folders are strings)
    import subprocess
    from pathlib import Path
    from typing import TypeAlias

    FileName: TypeAlias = str | os.PathLike[str]  # a file as the engine names it (a Path from the library)

TIMEOUT = 30.0  # seconds for one git call
# Every setting through which a repository's configuration (or the user's) could make git start a
# program or open a connection, overridden on the command line (which wins over every file).
SAFE_CONFIG: tuple[str, ...] = (
    "protocol.allow=never",
    "core.sshCommand=false",
    "core.gitProxy=",
    "core.askPass=",
    "credential.helper=",
    "core.fsmonitor=false",
    "core.untrackedCache=false",
    f"core.hooksPath={os.devnull}",
    "core.pager=cat",
    "diff.external=",
    "core.alternateRefsCommand=",
    "gc.auto=0",
    "maintenance.auto=false",
    "fetch.recurseSubmodules=false",
    "submodule.recurse=false",
)
# What git is started with: the caller's environment without any GIT_* variable, without the
# programs ssh and git ask for passwords with, and with these set.
SAFE_ENV: dict[str, str] = {
    "GIT_NO_LAZY_FETCH": "1",
    "GIT_TERMINAL_PROMPT": "0",
    "GIT_OPTIONAL_LOCKS": "0",
    "GIT_PROTOCOL_FROM_USER": "0",
    "GIT_NO_REPLACE_OBJECTS": "1",
    "GIT_CONFIG_PARAMETERS": "",
    "GIT_LITERAL_PATHSPECS": "1",
    "LC_ALL": "C",
    "LANGUAGE": "C",
}
_DROPPED = ("SSH_ASKPASS", "SSH_ASKPASS_REQUIRE", "DISPLAY")


def environment() -> dict[str, str]:
    """The environment every git call gets (:data:`SAFE_ENV` over the caller's, cleared of ``GIT_*``)."""
    env = {k: v for k, v in os.environ.items() if not k.upper().startswith("GIT_") and k not in _DROPPED}
    env.update(SAFE_ENV)
    return env


def command(*args: str) -> list[str]:
    """The command line of one git call: git, every protection of :data:`SAFE_CONFIG`, ``args``."""
    out = ["git", "--no-pager", "--no-replace-objects"]
    for setting in SAFE_CONFIG:
        out += ["-c", setting]
    return [*out, *args]


def available() -> bool:
    import shutil  # start-up: only when git is asked

    return shutil.which("git") is not None


def run(folder: FileName, *args: str, timeout: float = TIMEOUT) -> subprocess.CompletedProcess[bytes]:
    """Run git in ``folder`` with every protection; :class:`OSError` or ``subprocess.SubprocessError``
    (a time-out) when it cannot be run or answer in time."""
    import subprocess  # start-up: only when git is asked

    return subprocess.run(command(*args), cwd=folder, capture_output=True, check=False, timeout=timeout,
                          stdin=subprocess.DEVNULL, env=environment())


# ---------------------------------------------------------------------------- ignore rules


class Visible(Record):
    """What git says a walk of a folder sees: the files it does not ignore (relative paths,
    ``os.sep``-separated), or ``None`` with the reason (``""``: not a git work tree, or no git)."""

    files: set[str] | None
    reason: str = ""


def _ignore_sources(directory: str, top: str, git_dir: str, excludes: str) -> Iterator[str]:
    """Every file git reads ignore rules from for a walk of ``directory`` (absolute): ``.gitignore`` in
    it and below it and in each folder from the work tree's top down to it, ``info/exclude`` and the
    configured (or default) ``core.excludesFile`` (each named as a ``Path`` prints it)."""
    yield path_str(os.path.join(git_dir, "info", "exclude"))
    if excludes:
        yield path_str(os.path.expanduser(excludes))
    else:
        xdg = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"), ".config")
        yield path_str(os.path.join(xdg, "git", "ignore"))
    here = path_str(os.path.abspath(directory))
    top = os.path.normcase(path_str(top))  # as Paths compare (without regard to case on Windows)
    d = here
    while True:
        if d != here:
            yield os.path.join(d, ".gitignore")
        parent = os.path.dirname(d)
        if os.path.normcase(d) == top or parent == d:
            break
        d = parent
    for root, dirs, files in walk(directory):
        dirs[:] = [d for d in dirs if d != ".git"]
        if ".gitignore" in files:
            yield os.path.join(path_str(root), ".gitignore")


def _not_readable(path: str) -> str | None:
    """Why git would hang on, or cannot read, an ignore file (``None``: a regular file, or none)."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    if stat.S_ISREG(st.st_mode) or stat.S_ISDIR(st.st_mode):
        return None
    return f"{path} is {describe(st.st_mode)}, which git would wait on"


def may_be_in_repository(folder: FileName) -> bool:
    """Could git find a repository for ``folder`` (absolute)? Not where neither it nor a folder above
    it holds a ``.git`` (a work tree's, or a file naming one) or is itself a repository's folder (a
    ``HEAD`` in it: a bare repository, which git also finds): git looks nowhere else, since every
    ``GIT_*`` variable is cleared (:func:`environment`)."""
    d = path_str(folder)
    while True:
        if os.path.lexists(os.path.join(d, ".git")) or os.path.lexists(os.path.join(d, "HEAD")):
            return True
        parent = os.path.dirname(d)
        if parent == d:
            return False
        d = parent


def visible_files(directory: FileName) -> Visible:
    """The files below ``directory`` that git does not ignore (``ls-files --cached --others
    --exclude-standard``). No answer, with the reason, where an ignore file is no regular file (a FIFO
    would stall git), where git refuses the repository (owned by another user: git's
    ``safe.directory``), fails or takes too long; no answer and no reason outside a work tree."""
    folder = path_str(os.path.abspath(directory))
    if not may_be_in_repository(folder):
        return Visible(None)  # what git would say, without starting it (15 ms)
    import subprocess  # start-up: only when git is asked

    if not available():
        return Visible(None)
    try:
        where = run(folder, "rev-parse", "--show-toplevel", "--absolute-git-dir")
        if where.returncode != 0:
            said = where.stderr.decode("utf-8", "replace")
            if "dubious ownership" in said or "safe.directory" in said:
                return Visible(None, "git refuses this repository: it belongs to another user (git's "
                                     "safe.directory)")
            return Visible(None)  # not a git work tree
        lines = where.stdout.decode("utf-8", "surrogateescape").splitlines()
        if len(lines) < 2:
            return Visible(None)
        top, git_dir = lines[0], lines[1]
        excludes = run(folder, "config", "--get", "core.excludesFile")
        for source in _ignore_sources(folder, top, git_dir, excludes.stdout.decode("utf-8", "replace").strip()):
            why = _not_readable(source)
            if why is not None:
                return Visible(None, why)
        proc = run(folder, "ls-files", "-z", "--cached", "--others", "--exclude-standard", "--", ".")
    except subprocess.TimeoutExpired:
        return Visible(None, f"git did not answer within {TIMEOUT:g} s")
    except (OSError, subprocess.SubprocessError) as exc:
        return Visible(None, f"git cannot be run ({exc})")
    if proc.returncode != 0:
        first = proc.stderr.decode("utf-8", "replace").strip().splitlines()
        return Visible(None, f"git ls-files failed: {first[0] if first else proc.returncode}")
    return Visible({os.path.normpath(os.fsdecode(name)) for name in proc.stdout.split(b"\0") if name})


# ---------------------------------------------------------------------------- revisions

Reader = Callable[["Path"], bytes]  # (a string: pathlib is imported where a machine is read)


def revision_reader(startup: FileName, revision: str, label: str = "--against") -> tuple[str, Reader]:
    """A reader of the files of ``revision`` in the git work tree ``startup`` lies in: each file's
    bytes as that commit has them (``cat-file blob``: no filter, no text conversion). The commit's
    short name, and the reader. A file the revision does not have is "no such file"; a blob the
    repository does not hold (a partial clone) stops zero with a message: nothing is fetched."""
    import subprocess  # start-up: only when git is asked

    if revision.startswith("-") or not revision.strip():
        raise ZeroError(f"{label} {revision!r}: not a start-up list, nor a git revision")
    folder = os.path.dirname(path_str(os.path.abspath(split_part(startup)[0])))

    def git(*args: str) -> subprocess.CompletedProcess[bytes]:
        try:
            return run(folder, *args)
        except subprocess.TimeoutExpired:
            raise ZeroError(f"{label} {revision}: git did not answer within {TIMEOUT:g} s") from None
        except (OSError, subprocess.SubprocessError) as exc:
            raise ZeroError(f"{label} {revision}: git cannot be run ({exc})") from None

    top = git("rev-parse", "--show-toplevel")
    commit = git("rev-parse", "--verify", "--quiet", "--end-of-options", f"{revision}^{{commit}}")
    if top.returncode or commit.returncode:
        said = (top.stderr + commit.stderr).decode("utf-8", "replace")
        if "dubious ownership" in said or "safe.directory" in said:
            raise ZeroError(f"{label} {revision}: git refuses this repository: it belongs to another user "
                            "(git's safe.directory)")
        raise ZeroError(f"{label} {revision}: no such file, and not a revision of a git repository here")
    root = os.path.realpath(top.stdout.decode("utf-8", "surrogateescape").strip())
    sha = commit.stdout.decode().strip()

    def read(path: Path) -> bytes:
        file = split_part(path)[0]
        rel = os.path.relpath(os.path.realpath(file), root)
        if rel == os.pardir or rel.startswith(os.pardir + os.sep) or os.path.isabs(rel):
            raise ZeroError("no such file", str(path))  # outside the repository: not in the revision
        name = rel.replace(os.sep, "/")
        listed = git("ls-tree", "-z", "--full-tree", sha, "--", name)
        if listed.returncode:
            raise ZeroError(f"{label} {revision}: the repository does not hold the tree of {sha[:12]} "
                            "(a partial clone?); zero fetches nothing: fetch it with git and try again", str(path))
        entry = listed.stdout.split(b"\0")[0]
        meta, _, _ = entry.partition(b"\t")
        parts = meta.split()
        if len(parts) != 3 or parts[1] != b"blob":
            raise ZeroError("no such file", str(path))  # not in the revision (or a folder, a submodule)
        blob = parts[2].decode()
        data = git("cat-file", "blob", blob)
        if data.returncode:
            raise ZeroError(f"{label} {revision}: the repository does not hold this file's content at {sha[:12]} "
                            f"(blob {blob[:12]}: a partial clone?); zero fetches nothing: fetch it with git and "
                            "try again", str(path))
        return data.stdout

    return sha[:12], read


__all__ = ["SAFE_CONFIG", "SAFE_ENV", "TIMEOUT", "Visible", "available", "command", "environment",
           "may_be_in_repository", "revision_reader", "run", "visible_files"]

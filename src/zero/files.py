"""Reading and writing files: the one module through which zero touches the disk.

Every layer that reads (the commands, and the machine model, which follows the lists a
start-up list names) and every command that writes goes through these functions, so the
rules below hold for all of them:

Reading (:func:`read_file`, :func:`read_stream`)
  Only regular files and standard input are read. A FIFO, device, socket or directory is
  refused at once with a one-line reason (opening never blocks); so are inputs larger
  than :func:`max_file_bytes` (256 MiB, or ``$ZERO_MAX_FILE_SIZE``), dangling links and
  link loops.

Writing (:func:`write_atomic`)
  The new content is complete and on disk (temporary file in the target's directory,
  fsync) before it replaces anything. A symbolic link is written through to its target
  and stays a link; mode, owner and group are kept; a file with several hard links, or
  whose owner a rename could not keep, is rewritten in place after the new content is
  safe, so every name and the owner stay: the complete new content is first kept beside it
  as a journal (``.NAME.zero-PID-….journal``), and a write that is stopped half way (SIGKILL,
  a full disk, a power cut) is completed from it by the next zero that reads or writes the
  file, so the file is never left neither old nor new. Anything that is not a regular file is never
  replaced (``/dev/null`` and a terminal are written to, as meant); a file the user may
  not write is refused even where a rename would be allowed; without ``force`` an
  existing file is never replaced, atomically (a hard link claims the name), so two
  writers racing for one new name cannot both succeed. Temporary files are removed on
  errors, Ctrl-C and SIGTERM, and carry the writer's process ID, so one left by a killed
  process is removed by the next write to the same target.
"""

from __future__ import annotations

import contextlib
import errno
import io
import os
import stat
import sys
import time
from collections.abc import Callable, Iterator

from zero.errors import ZeroError
from zero.forms import CONFIG_NAMES, NOT_A_REPORT, split_part, xml_form
from zero.patterns import compiled

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from pathlib import Path  # start-up: pathlib (and urllib.parse, ipaddress) only where a file is written
    from typing import Any, BinaryIO

MAX_FILE_BYTES = 256 * 1024 * 1024
# What no parameter list (nor its YAML/TOML/JSON form) comes near: the largest zero is measured on,
# a tool list of 30,000 tools, has 1,140,000 lines of at most 200 characters (the vendor's own
# lists have a few thousand). Past these a file is refused before it is parsed, which bounds the
# memory one input can take (each line and each byte of a line costs objects).
MAX_LINES = 4_000_000
MAX_LINE_BYTES = 1024 * 1024
_UNITS = {"": 1, "B": 1, "K": 1024, "KB": 1000, "KIB": 1024, "M": 1024**2, "MB": 1000**2, "MIB": 1024**2,
          "G": 1024**3, "GB": 1000**3, "GIB": 1024**3}
_SIZE = r"\s*([0-9]+)\s*([A-Za-z]*)\s*"  # compiled at its first use (ZERO_MAX_FILE_SIZE set)
_O_BINARY = getattr(os, "O_BINARY", 0)
_STALE_SECONDS = 24 * 3600  # where process IDs cannot be checked (Windows)


def path_str(path: str | os.PathLike[str]) -> str:
    """``str(Path(path))`` without importing pathlib (with urllib.parse and ipaddress, 7% of a
    lint's start-up): the text of a path as a ``Path`` gives it, which is how zero names a file:
    ``./a.lis`` → ``a.lis``, ``a//b/`` → ``a/b``, ``a/./b`` → ``a/b``, ``''`` → ``.``; ``..`` is
    kept (``os.path.normpath`` would take it away with the folder before it), and so is a leading
    ``//`` (POSIX lets a system give it a meaning of its own; three or more are one). Windows
    paths have rules of their own (drives, shares, both separators): pathlib's there."""
    text = os.fspath(path)
    if os.sep != "/" or os.altsep is not None:  # pragma: no cover - Windows: its paths' own rules
        from pathlib import Path  # start-up: only on Windows

        return str(Path(text))
    if not text:
        return "."
    root = ""
    if text[0] == "/":
        rest = text.lstrip("/")
        root = "//" if len(text) - len(rest) == 2 else "/"
        text = rest
    if "//" not in text and "." not in text and not text.endswith("/"):
        return root + text or "."  # nothing to drop (the common name of a folder)
    return root + "/".join(part for part in text.split("/") if part and part != ".") or "."


def parse_size(text: str) -> int:
    """``"256MiB"``, ``"64M"``, ``"1000000"`` → bytes; :class:`ZeroError` for anything else."""
    m = compiled(_SIZE).fullmatch(text)
    unit = m.group(2).upper() if m else ""
    if m is None or unit not in _UNITS or int(m.group(1)) <= 0:
        raise ZeroError(f"{text!r} is not a size (e.g. 256MiB, 64M, 1000000)", "ZERO_MAX_FILE_SIZE")
    return int(m.group(1)) * _UNITS[unit]


_OFF = ("", "0", "false", "no", "off")


def switched_on(variable: str) -> bool:
    """Is the environment variable ``variable`` set to anything but ``0``, ``false``, ``no``, ``off`` or
    nothing (``ZERO_NO_CACHE=1``)?"""
    return os.environ.get(variable, "").strip().lower() not in _OFF


def content_digest(data: bytes) -> bytes:
    """The 16-byte BLAKE2b of ``data``: what the cache and a run's twins know a content by. From
    ``_blake2``, hashlib's own module without OpenSSL (importing hashlib costs 14 ms of start-up)."""
    global _blake2b
    if _blake2b is None:
        try:
            from _blake2 import blake2b  # start-up: at the first content hashed
        except ImportError:  # pragma: no cover - an interpreter without the module
            from hashlib import blake2b  # start-up: as above
        _blake2b = blake2b
    return _blake2b(data, digest_size=16).digest()


_blake2b: Callable[..., Any] | None = None


def max_file_bytes() -> int:
    """The largest input zero reads: 256 MiB unless ``$ZERO_MAX_FILE_SIZE`` says otherwise."""
    text = os.environ.get("ZERO_MAX_FILE_SIZE")
    return parse_size(text) if text else MAX_FILE_BYTES


def _mib(n: int) -> str:
    return f"{n // (1024 * 1024)} MiB" if n >= 1024 * 1024 and n % (1024 * 1024) == 0 else f"{n} bytes"


def describe(mode: int) -> str:
    """What a file is, in words, from its ``st_mode``."""
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISCHR(mode):
        return "a character device"
    if stat.S_ISBLK(mode):
        return "a block device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def _open_error(exc: OSError, path: str | os.PathLike[str]) -> ZeroError:
    where = str(path)
    if isinstance(exc, FileNotFoundError):
        if os.path.islink(path):
            return ZeroError("dangling symbolic link: its target does not exist", where)
        return ZeroError("no such file", where)
    if isinstance(exc, IsADirectoryError):
        return ZeroError("is a directory", where)
    if isinstance(exc, PermissionError):
        return ZeroError("permission denied", where)
    if exc.errno == errno.ELOOP:
        return ZeroError("symbolic link loop (too many levels of symbolic links)", where)
    return ZeroError(str(exc.strerror or exc), where)


def walk(top: str | os.PathLike[str]) -> Iterator[tuple[str, list[str], list[str]]]:
    """``os.walk(top)``: each folder below ``top`` (itself first) with the names of its folders and its other
    entries, top-down, depth first, links to folders listed but not entered, a folder that cannot be read
    skipped, and the folders a caller takes out of the list it was given not entered. A loop, not os.walk's
    recursion (Python 3.11's): a tree nested deeper than the interpreter's recursion limit is walked like any
    other instead of ending the run with a RecursionError."""
    pending: list[str] = [os.fspath(top)]
    while pending:
        root = pending.pop()
        dirs: list[str] = []
        files: list[str] = []
        folders: dict[str, bool] = {}  # a folder's name -> is it a link (as the listing says: no lstat each)
        try:
            with os.scandir(root) as entries:
                for entry in entries:
                    try:
                        is_dir = entry.is_dir()
                    except OSError:
                        is_dir = False
                    if is_dir:
                        dirs.append(entry.name)
                        folders[entry.name] = entry.is_symlink()
                    else:
                        files.append(entry.name)
        except OSError:
            continue
        yield root, dirs, files
        for name in reversed(dirs):  # the first one walked next, whole, as os.walk does
            below = os.path.join(root, name)
            link = folders.get(name)
            if not (os.path.islink(below) if link is None else link):  # (a name the caller added: asked)
                pending.append(below)


def check_regular(path: str | os.PathLike[str]) -> None:
    """Raise the reason :func:`read_file` would give if ``path`` is no readable regular file,
    without reading it (for paths named on the command line, checked before any work)."""
    try:
        st = os.stat(path)
    except OSError as exc:
        raise _open_error(exc, path) from None
    if not stat.S_ISREG(st.st_mode):
        raise ZeroError(f"is {describe(st.st_mode)}, not a regular file; zero reads regular files "
                        "and standard input (-)", str(path))


def read_file(path: str | os.PathLike[str], limit: int | None = None) -> bytes:
    """The bytes of a regular file; :class:`ZeroError` with a one-line reason otherwise."""
    limit = max_file_bytes() if limit is None else limit
    where = str(path)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) | _O_BINARY
    try:
        fd = os.open(path, flags)  # non-blocking: opening a FIFO never waits for a writer
    except OSError as exc:
        raise _open_error(exc, path) from None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise ZeroError(f"is {describe(st.st_mode)}, not a regular file; zero reads regular files "
                            "and standard input (-)", where)
        if st.st_size > limit:
            raise ZeroError(f"file is {st.st_size} bytes, larger than the {_mib(limit)} zero reads "
                            "(ZERO_MAX_FILE_SIZE raises the limit)", where)
        # an in-place rewrite stopped half way is completed (never through a link to another's file)
        if (st.st_nlink > 1 or _foreign(st)) and not (_foreign(st) and through_link(path)) \
                and recover_journals(path):
            return read_file(path, limit)
        data = _read_at_most(fd, st.st_size, limit)
        if data is None:  # the file grew while it was read: never more than the limit is held
            raise ZeroError(f"file is larger than the {_mib(limit)} zero reads (it grew while it was read)", where)
        check_shape(data, where)
        return data
    except OSError as exc:
        raise ZeroError(str(exc.strerror or exc), where) from None
    finally:
        os.close(fd)


def read_as_is(st: os.stat_result, limit: int | None = None) -> bool:
    """Would :func:`read_file` read a file of this ``os.stat`` and give its bytes as they are: a
    regular file within the size limit, of one link and of the user zero runs as (no journal of an
    interrupted rewrite to complete)? A cache that knows the file by its stat may then skip reading it."""
    return (stat.S_ISREG(st.st_mode) and st.st_size <= (max_file_bytes() if limit is None else limit)
            and st.st_nlink == 1 and not _foreign(st))


def _read_at_most(fd: int, size: int, limit: int) -> bytes | None:
    """The file's bytes, read in one allocation of its size where it does not grow; ``None`` as soon
    as more than ``limit`` bytes come (the memory held never exceeds the limit plus one chunk)."""
    f = io.FileIO(fd, closefd=False)
    # one read of the size fstat gave, one byte more to see growth (a file that says it has no size,
    # as /proc and some FUSE files do, is read on by chunks)
    data = f.read(size + 1) or b""
    if len(data) <= size:
        return data
    chunks = [data]
    total = len(data)
    while True:
        if total > limit:
            return None
        chunk = f.read(min(1 << 20, limit + 1 - total))
        if not chunk:
            return b"".join(chunks)
        chunks.append(chunk)
        total += len(chunk)


def read_stream(stream: BinaryIO, name: str = "-", limit: int | None = None) -> bytes:
    """All of a stream (standard input), refused beyond the size limit instead of filling memory."""
    limit = max_file_bytes() if limit is None else limit
    data = stream.read(limit + 1)
    if len(data) > limit:
        raise ZeroError(f"standard input is larger than the {_mib(limit)} zero reads "
                        "(ZERO_MAX_FILE_SIZE raises the limit)", name)
    check_shape(data, name)
    return data


def check_shape(data: bytes, where: str) -> None:
    """Refuse an input with more than ``MAX_LINES`` lines or a line longer than ``MAX_LINE_BYTES``
    (both found at the speed of a byte search: no line is split off for it)."""
    lines = data.count(b"\n")
    if lines > MAX_LINES:
        raise ZeroError(f"{lines} lines, more than the {MAX_LINES} any parameter list has", where)
    if len(data) > MAX_LINE_BYTES:
        pos = 0
        while len(data) - pos > MAX_LINE_BYTES:  # the last line break within each window of the limit
            cut = data.rfind(b"\n", pos, pos + MAX_LINE_BYTES + 1)
            if cut < 0:
                line = data.count(b"\n", 0, pos) + 1
                raise ZeroError(f"line {line} is longer than the {_mib(MAX_LINE_BYTES)} a line of any parameter "
                                "list has", where)
            pos = cut + 1


def resolve(path: str | os.PathLike[str]) -> str:
    """The one resolution of a path zero reads: the file it names, every symbolic link followed
    (of the file and of each folder on the way), ``..`` taken after the links as the operating
    system does, and a list element's suffix (``export.xml#AchsMds``) taken off first, so that the
    file the suffix sits on is resolved too."""
    return os.path.realpath(split_part(path)[0])


def within(path: str | os.PathLike[str], root: str | os.PathLike[str]) -> bool:
    """Is ``path`` (:func:`resolve`d: links followed, in every form, ``#Element`` suffix included)
    ``root`` or below it? The one containment test: a start-up list or a configuration cannot make
    zero read, and print, any other file (``/proc/self/environ``, ``../../etc/passwd``, a link in the
    machine's folder to a file elsewhere)."""
    real, top = resolve(path), os.path.realpath(root)
    return real == top or real.startswith(top.rstrip(os.sep) + os.sep)


def nearest_holding(folder: str | os.PathLike[str], names: tuple[str, ...]) -> Path | None:
    """The nearest of ``folder`` (made absolute) and its ancestors that holds one of ``names``
    (``.git``, a configuration file); ``None`` where none does."""
    from pathlib import Path  # start-up: only for a machine or a configuration file's folders

    base = Path(os.path.abspath(folder))
    for d in (base, *base.parents):
        if any(os.path.lexists(d / name) for name in names):
            return d
    return None


# --------------------------------------------------------------------------- writing


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True  # it exists, but is not ours
    return True


def temp_name(target: str | os.PathLike[str]) -> str:
    """The temporary file a write to ``target`` uses: hidden, beside it, with this process's ID."""
    folder, name = os.path.split(os.fspath(target))
    return os.path.join(folder, f".{name}.zero-{os.getpid()}-{os.urandom(4).hex()}.tmp")


def _leftover_pid(name: str, prefix: str, end: str) -> int | None:
    """The process ID in a file name ``{prefix}{pid}-{hex}{end}`` (``[0-9]+-[0-9a-f]+`` between the two), else None."""
    if not (name.startswith(prefix) and name.endswith(end)) or len(name) < len(prefix) + len(end):
        return None
    pid, dash, tag = name[len(prefix):len(name) - len(end)].partition("-")
    if not (dash and pid.isascii() and pid.isdigit() and tag and not tag.strip("0123456789abcdef")):
        return None
    return int(pid)


def _stale(target: Path, suffix: str) -> list[Path]:
    """Files a killed zero left beside ``target`` (``.tmp``: incomplete, ``.journal``: complete)."""
    out: list[Path] = []
    try:
        names = os.listdir(target.parent if str(target.parent) else ".")
    except OSError:
        return out
    prefix, end = f".{target.name}.zero-", f".{suffix}"
    for name in sorted(names):
        pid = _leftover_pid(name, prefix, end)
        if pid is None or pid == os.getpid():
            continue
        path = target.parent / name
        stale = False
        if os.name == "posix":
            stale = not _pid_alive(pid)
        else:  # no safe way to ask whether a process lives: only old leftovers go
            with contextlib.suppress(OSError):
                stale = time.time() - path.stat().st_mtime > _STALE_SECONDS
        if stale:
            out.append(path)
    return out


def remove_stale_temps(target: Path) -> list[Path]:
    """Remove temporary files a killed zero left for ``target`` (never complete: a write renames
    its temporary file to a journal once it holds everything); return what was removed."""
    removed: list[Path] = []
    for path in _stale(target, "tmp"):
        with contextlib.suppress(OSError):
            path.unlink()
            removed.append(path)
    return removed


_JOURNAL_MAGIC = b"ZERO-JOURNAL 1\n"
_warned: set[str] = set()


def _euid() -> int | None:
    return os.geteuid() if hasattr(os, "geteuid") else None


def through_link(path: str | os.PathLike[str]) -> bool:
    """Is ``path`` reached through a symbolic link (of the file itself or of a folder on the way)?"""
    return os.path.realpath(path) != os.path.normpath(os.path.abspath(path))


def _foreign(st: os.stat_result) -> bool:
    """A file of another owner than the user zero runs as."""
    euid = _euid()
    return euid is not None and st.st_uid != euid


def _journal_bytes(target_st: os.stat_result, name: str, old: bytes, new: bytes) -> bytes:
    """A journal: what zero writes before an in-place rewrite, proving for which file (device, inode,
    owner, name) and which old content (size, SHA-256) the new content (size, SHA-256) is meant; the
    header carries its own checksum. It holds the old content too, so that a copy stopped half way is
    recognised byte for byte (old and new, a prefix of the new over the old, nothing else)."""
    import hashlib  # start-up: only an in-place rewrite needs it
    import json  # start-up: as above

    head = {"dev": target_st.st_dev, "ino": target_st.st_ino, "uid": target_st.st_uid, "name": name,
            "old": [len(old), hashlib.sha256(old).hexdigest()], "new": [len(new), hashlib.sha256(new).hexdigest()]}
    text = json.dumps(head, sort_keys=True)
    line = json.dumps({**head, "sum": hashlib.sha256(text.encode()).hexdigest()}, sort_keys=True).encode()
    return _JOURNAL_MAGIC + line + b"\n" + old + new


def _parse_journal(data: bytes, target: Path, st: os.stat_result) -> tuple[bytes, bytes]:
    """The old and new content of a journal proven to be zero's own for ``target`` as it is (``st``);
    :class:`ValueError` saying why it is not."""
    import hashlib  # start-up: only a journal needs it
    import json  # start-up: as above

    if not data.startswith(_JOURNAL_MAGIC):
        raise ValueError("not a journal zero wrote")
    end = data.find(b"\n", len(_JOURNAL_MAGIC))
    try:
        head = json.loads(data[len(_JOURNAL_MAGIC):end]) if end > 0 else None
    except ValueError:
        head = None
    if not isinstance(head, dict) or not isinstance(head.get("sum"), str):
        raise ValueError("its header does not read")
    claimed = head.pop("sum")
    if hashlib.sha256(json.dumps(head, sort_keys=True).encode()).hexdigest() != claimed:
        raise ValueError("its header's checksum does not match")
    if (head.get("dev"), head.get("ino"), head.get("uid"), head.get("name")) != (
            st.st_dev, st.st_ino, st.st_uid, target.name):
        raise ValueError("it was written for another file (device, inode, owner or name differ)")
    body = data[end + 1:]
    (old_size, old_sum), (new_size, new_sum) = head["old"], head["new"]
    old, new = body[:old_size], body[old_size:]
    if len(old) != old_size or len(new) != new_size or hashlib.sha256(old).hexdigest() != old_sum \
            or hashlib.sha256(new).hexdigest() != new_sum:
        raise ValueError("its content does not match its checksums")
    return old, new


def _stopped_copy(current: bytes, old: bytes, new: bytes) -> bool:
    """Is ``current`` what an in-place copy of ``new`` over ``old`` leaves when stopped at any point:
    the old content (with the blocks claimed for a longer new one: NUL bytes after it), a prefix of
    the new content over that, or the new content before the file is cut to its length?"""
    base = old + b"\0" * max(0, len(new) - len(old))
    if len(current) not in (len(old), len(base)):
        return False
    k = 0
    step = 1 << 16
    limit = min(len(current), len(new))
    while k < limit and current[k:k + step] == new[k:k + step]:
        k = min(k + step, limit)
    while k < limit and current[k] == new[k]:
        k += 1
    return current[k:] == base[k:len(current)]


def _note(key: str, text: str) -> None:
    if key not in _warned:
        _warned.add(key)
        sys.stderr.write(text)


def recover_journals(target: str | os.PathLike[str]) -> bool:
    """Complete an in-place rewrite that a killed zero left half done, from its journal, beside the
    file itself (links followed). A journal is applied only when it is proven zero's own for this
    very file and its content: a regular file of zero's user (or root, or the file's owner) with one
    link, its header's checksum right, written for this device, inode, owner and name, and the file
    as the copy leaves it (old, new, or a prefix of the new over the old). A journal proven zero's
    but stale (the file was changed since) is removed unapplied; anything else is left alone, said
    once. ``True`` when something was recovered."""
    from pathlib import Path  # start-up: only for a file of several links or another owner

    real = Path(os.path.realpath(target))
    recovered = False
    for journal in _stale(real, "journal"):
        try:
            jst = os.lstat(journal)
            st = os.stat(real)
        except OSError:
            continue
        why = ""
        if not stat.S_ISREG(jst.st_mode) or jst.st_nlink != 1:
            why = "not a regular file with one name"
        elif jst.st_uid not in {_euid(), 0, st.st_uid} and _euid() is not None:
            why = f"it belongs to another user (uid {jst.st_uid})"
        elif not stat.S_ISREG(st.st_mode):
            why = "the file is not a regular file"
        elif jst.st_size > 2 * max_file_bytes() + 4096:
            why = "it is larger than any journal zero writes"
        try:
            old, new = _parse_journal(_read_plain(journal), real, st) if not why else (b"", b"")
            current = _read_plain(real) if not why else b""
        except ValueError as exc:
            why = str(exc)
        except OSError as exc:
            why = f"it cannot be read: {exc.strerror or exc}"
        if why:
            _note(str(journal), f"zero: {real}: {journal.name} not applied: {why}; it is left as it is\n")
            continue
        if current == new:
            with contextlib.suppress(OSError):
                os.unlink(journal)
            continue
        if not _stopped_copy(current, old, new):
            with contextlib.suppress(OSError):
                os.unlink(journal)
            _note(str(journal), f"zero: {real}: {journal.name} not applied: the file was changed after that "
                                "rewrite was stopped; the journal is removed\n")
            continue
        try:
            with _signals_held():
                _rewrite_in_place(real, new, (st.st_dev, st.st_ino))
                os.unlink(journal)
            recovered = True
        except OSError as exc:
            raise ZeroError(f"a rewrite stopped half way and cannot be completed from {journal.name}: "
                            f"{exc.strerror or exc}", str(target)) from None
    if recovered:
        _fsync_directory(real.parent)
        sys.stderr.write(f"zero: {target}: an earlier rewrite was stopped half way; completed from its journal\n")
    return recovered


def _read_plain(path: Path) -> bytes:
    """A regular file's bytes, without following a final link and without blocking."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOFOLLOW", 0) | _O_BINARY)
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise OSError(errno.EINVAL, "not a regular file")
        data = _read_at_most(fd, st.st_size, 2 * max_file_bytes() + 4096)
        if data is None:
            raise OSError(errno.EFBIG, "it grew while it was read")
        return data
    finally:
        os.close(fd)


@contextlib.contextmanager
def _signals_unwind(done: list[bool]) -> Iterator[None]:
    """While writing, turn SIGTERM and SIGHUP into SystemExit (Ctrl-C already raises), so that
    the temporary file is removed on the way out; what is said depends on ``done[0]`` (the file was
    replaced: a signal held during an in-place copy arrives after it)."""
    import signal  # start-up: only a write needs them (with threading, 1.8 ms of every lint)
    import threading  # start-up: as above

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def unwind(signum: int, _frame: object) -> None:
        what = "the file was written completely" if done[0] else "nothing was replaced"
        sys.stderr.write(f"zero: stopped by signal {signum}; {what}\n")
        raise SystemExit(128 + signum)

    names = [s for s in ("SIGTERM", "SIGHUP") if hasattr(signal, s)]
    old = {name: signal.signal(getattr(signal, name), unwind) for name in names}
    try:
        yield
    finally:
        for name, handler in old.items():
            signal.signal(getattr(signal, name), handler)


def _fsync_directory(directory: str | os.PathLike[str]) -> None:
    if os.name != "posix":
        return
    with contextlib.suppress(OSError):
        fd = os.open(directory, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        n = os.write(fd, view)
        view = view[n:]


def _write_to_stream(path: Path, data: bytes) -> bool:
    """Write to ``/dev/null`` or a terminal the way the user meant; ``False`` for anything else."""
    flags = os.O_WRONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) | _O_BINARY
    try:
        fd = os.open(path, flags)
    except OSError:
        return False
    try:
        st = os.fstat(fd)
        null = os.stat(os.devnull)
        if not stat.S_ISCHR(st.st_mode) or not (
                os.isatty(fd) or (st.st_dev, st.st_ino) == (null.st_dev, null.st_ino)):
            return False
        _write_all(fd, data)
        return True
    finally:
        os.close(fd)


def _claim_blocks(target: Path, size: int) -> None:
    """Claim the disk blocks a longer content needs before the first byte of the file is changed, so
    that a full disk fails with the file as it was (:class:`OSError`); a file system that cannot
    claim them ahead is written as it comes."""
    fd = os.open(target, os.O_WRONLY | getattr(os, "O_NOFOLLOW", 0) | _O_BINARY)
    try:
        old = os.fstat(fd).st_size
        if size > old and hasattr(os, "posix_fallocate"):
            try:
                os.posix_fallocate(fd, old, size - old)
            except OSError as exc:
                with contextlib.suppress(OSError):
                    os.ftruncate(fd, old)  # nothing of the old content was changed
                if exc.errno not in (errno.EINVAL, errno.EOPNOTSUPP, errno.ENOTSUP):
                    raise
    finally:
        os.close(fd)


def _rewrite_in_place(target: Path, data: bytes, inode: tuple[int, int] | None = None) -> None:
    """Overwrite the file itself (same inode: every hard link and the owner stay); its blocks are
    claimed already (:func:`_claim_blocks`). Never through a link; ``inode`` (device, inode): only
    that file."""
    fd = os.open(target, os.O_WRONLY | getattr(os, "O_NOFOLLOW", 0) | _O_BINARY)
    try:
        st = os.fstat(fd)
        if inode is not None and (st.st_dev, st.st_ino) != inode:
            raise OSError(errno.ESTALE, "the file was replaced meanwhile")
        _write_all(fd, data)
        os.ftruncate(fd, len(data))
        os.fsync(fd)
    finally:
        os.close(fd)


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """Ctrl-C, SIGTERM and SIGHUP wait until the block is done (an in-place copy is never left half
    done by them; SIGKILL and power cuts are what the journal is for)."""
    import signal  # start-up: only a write needs it

    names = [s for s in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, s)]
    held = {getattr(signal, s) for s in names}
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, held)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def write_atomic(path: str | os.PathLike[str], data: bytes, force: bool = False,
                 inputs: tuple[str | os.PathLike[str], ...] = ()) -> None:
    """Write ``data`` to ``path`` all at once or not at all (see the module's rules).

    Never over an input file; never over an existing file unless ``force``.
    """
    from pathlib import Path  # start-up: only a command that writes a file

    given = Path(path)
    where = str(given)
    target = given
    if given.is_symlink():
        target = Path(os.path.realpath(given))
        if not target.exists() and not target.is_symlink():
            try:
                os.stat(given)
            except OSError as exc:
                raise _open_error(exc, given) from None
    for src in inputs:
        with contextlib.suppress(OSError):
            if os.path.samefile(target, src):
                raise ZeroError("is an input file; zero never writes over its input", where)
    try:
        st: os.stat_result | None = os.stat(target)
    except FileNotFoundError:
        st = None
    except OSError as exc:
        raise _open_error(exc, given) from None
    if st is not None:
        if stat.S_ISDIR(st.st_mode):
            raise ZeroError("is a directory", where)
        if not stat.S_ISREG(st.st_mode):
            if _write_to_stream(target, data):
                return
            raise ZeroError(f"is {describe(st.st_mode)}, not a regular file: not replaced", where)
        if not force:
            raise ZeroError("already exists (use --force to replace it)", where)
        if _foreign(st) and through_link(given):
            raise ZeroError(f"is reached through a symbolic link and belongs to another user (uid {st.st_uid}); "
                            "zero never writes through a link to another user's file: not replaced", where)
        if not os.access(target, os.W_OK):
            raise ZeroError("not writable (permission denied): not replaced", where)
    directory = target.parent if str(target.parent) else Path(".")
    remove_stale_temps(target)
    recover_journals(target)
    tmp = temp_name(target)
    done = [False]
    try:
        with _signals_unwind(done):  # from before the temporary file exists: a signal never leaves it
            with _signals_held():
                try:
                    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _O_BINARY, 0o600)
                except OSError as exc:
                    raise ZeroError(f"cannot write here: {exc.strerror or exc}", where) from None
            in_place = False
            try:
                in_place = st is not None and _keeps_owner_in_place(tmp, st)
                # in place: the temporary file becomes the journal, complete before its name says so
                _write_all(fd, _journal_for(target, data) if in_place else data)
                os.fsync(fd)
            finally:
                os.close(fd)
            if st is None:
                _create(tmp, target, force, where)
                done[0] = True
            elif in_place:
                _rewrite_journaled(tmp, target, data, done)
            else:
                with _signals_held():
                    os.replace(tmp, target)
                    done[0] = True
            _fsync_directory(directory)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise ZeroError(f"not written: {exc.strerror or exc}", where) from None
        raise


# compiled at its first use (re keeps it): a file whose name does not say what it holds
_LIST_LINE = rb"[A-Za-z_][A-Za-z0-9_]*(?:\[[0-9]+\])*(?:\.[A-Za-z0-9_]+(?:\[[0-9]+\])*)*[ \t]+[^ \t\r\n]"


_COMMENT_STARTS = (b"#", b"(", b"/*", b";")


def _looks_like_a_list(path: Path) -> bool:
    """Does a file read like a parameter list, or a list's JSON form? A list: an entry `key value`
    (or `Ende`) among its first 20 lines that are not comments, however long a comment header comes
    first (a 9 KB header hid the entries from a sniff of 8 KB), or nothing but comments; an XML list
    or TwinCAT export. A JSON form: a JSON object that is neither a SARIF report (``runs``) nor a
    JSON Schema (``zero schema``). A report never reads so: its lines start with a path and a colon,
    `::`, `[`, `{` or `<`."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | _O_BINARY)
    except OSError:
        return False
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            return False
        f = io.FileIO(fd, closefd=False)
        head = f.read(65536) or b""
        if xml_form(head):  # a kernel XML list or a TwinCAT export
            return True
        if head.lstrip(b"\xef\xbb\xbf \t\r\n").startswith(b"<"):  # other markup: an HTML, SVG or JUnit report
            return False
        if head.lstrip().startswith(b"{"):
            return _json_form(head + (f.read(max_file_bytes()) or b""))
        seen = 0
        rest = b""
        chunk = head
        total = len(head)
        while chunk or rest:
            lines = (rest + chunk).split(b"\n")
            rest = lines.pop() if chunk else b""
            for line in lines:
                text = line.strip()
                if not text or text.startswith(_COMMENT_STARTS):
                    continue
                if compiled(_LIST_LINE).match(text) or text == b"Ende":
                    return True
                seen += 1
                if seen >= 20:
                    return False
            if not chunk or total > max_file_bytes():
                break
            chunk = f.read(1 << 20) or b""
            total += len(chunk)
        return seen == 0  # nothing but comments (and blank lines): a list's header, never a report
    except OSError:
        return False
    finally:
        os.close(fd)


def _json_form(data: bytes) -> bool:
    import json  # start-up: only a report over a JSON file needs it

    try:
        tree = json.loads(data)
    except (ValueError, RecursionError):
        return False
    if not isinstance(tree, dict):
        return False
    schema = tree.get("$schema")
    sarif = "runs" in tree and "version" in tree
    json_schema = isinstance(schema, str) and "json-schema.org" in schema and "_zero" not in tree
    return not (sarif or json_schema)


def write_disposable(path: str | os.PathLike[str], data: bytes) -> None:
    """Write a file of zero's own that can always be made again (a cache entry): complete in a
    temporary file beside it (this process's ID in its name), then renamed over ``path`` in one
    step, so a reader sees the old file or the new one, never half of one; of two writers racing
    for one name the last rename wins, each complete. No fsync (a power cut may leave a torn
    entry, which its reader finds out by its checksum and treats as missing); never through a
    symbolic link; :class:`OSError` when it cannot be written (the caller goes on without it)."""
    tmp = temp_name(path)
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _O_BINARY | getattr(os, "O_NOFOLLOW", 0), 0o644)
    try:
        try:
            _write_all(fd, data)
        finally:
            os.close(fd)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def write_report(path: str | os.PathLike[str], data: bytes, inputs: tuple[str | os.PathLike[str], ...] = (),
                 force: bool = True) -> None:
    """Write a report (``lint -o``, ``report -o``, ``schema -o``): over a previous report (only with
    ``force`` where the command asks for it), never over a list, a program, a structured form, a
    configuration file, an input, a file with another hard link, or a file whose content reads like
    a list or a list's JSON form, whatever the name, and whether named directly or through a link.
    The one decision of what a report may replace."""
    from pathlib import Path  # start-up: only a command that writes a report

    given = Path(path)
    real = Path(os.path.realpath(given))
    where = str(given)
    for name in {given, real}:
        if name.suffix.lower() in NOT_A_REPORT or name.name in CONFIG_NAMES:
            what = "a configuration file" if name.name in CONFIG_NAMES else "a list, NC program or list form"
            link = f" (it links to {real})" if name is real and real != given.absolute() else ""
            raise ZeroError(f"is {what}{link}, not a report: not replaced", where)
    try:
        st = os.stat(given)
    except OSError:
        st = None
    if st is not None and stat.S_ISREG(st.st_mode):
        if not force:
            raise ZeroError("already exists (use --force to replace it)", where)
        if st.st_nlink > 1:
            raise ZeroError(f"has {st.st_nlink} hard links: replacing it would change another file, not only a "
                            "report; not replaced", where)
        if st.st_size and _looks_like_a_list(given):
            raise ZeroError("reads like a parameter list (or a list's form), not a report: not replaced (give the "
                            "report a new name, or remove the file first)", where)
    write_atomic(given, data, force=True, inputs=inputs)


def _create(tmp: str, target: Path, force: bool, where: str) -> None:
    """A new file: the default mode; claimed atomically unless ``force``."""
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)
    if force:
        os.replace(tmp, target)
        return
    try:
        os.link(tmp, target)  # fails if the name exists, however close the race
    except FileExistsError:
        raise ZeroError("already exists (use --force to replace it)", where) from None
    except OSError as exc:
        if exc.errno not in (errno.EPERM, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EXDEV, errno.EMLINK,
                             errno.ENOSYS, errno.EACCES):
            raise
        os.replace(tmp, _exclusive(target, where, tmp))  # a file system without hard links
        return
    os.unlink(tmp)


def _exclusive(target: Path, where: str, tmp: str) -> Path:
    """Claim ``target`` with O_EXCL where hard links are not available; return it for the rename."""
    try:
        os.close(os.open(target, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _O_BINARY, 0o600))
    except FileExistsError:
        raise ZeroError("already exists (use --force to replace it)", where) from None
    return target


def _keeps_owner_in_place(tmp: str, st: os.stat_result) -> bool:
    """Give the (still empty) temporary file the mode, owner and group of the existing file; ``True``
    where the file must be rewritten in place instead: it has several hard links, or a rename would
    change its owner (the owner could not be given)."""
    os.chmod(tmp, stat.S_IMODE(st.st_mode))
    if st.st_nlink > 1:
        return True
    if hasattr(os, "chown"):
        mine = os.stat(tmp)
        if (mine.st_uid, mine.st_gid) != (st.st_uid, st.st_gid):
            try:
                os.chown(tmp, st.st_uid, st.st_gid)
            except OSError:
                return True
    return False


def _journal_for(target: Path, data: bytes) -> bytes:
    """The journal of an in-place rewrite of ``target`` with ``data`` (:func:`_journal_bytes`)."""
    fd = os.open(target, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | _O_BINARY)
    try:
        now = os.fstat(fd)
        old = _read_at_most(fd, now.st_size, max_file_bytes())
    finally:
        os.close(fd)
    if old is None:
        raise ZeroError("not written: the file grew while it was rewritten; the file is unchanged", str(target))
    return _journal_bytes(now, target.name, old, data)


def _rewrite_journaled(tmp: str, target: Path, data: bytes, done: list[bool]) -> None:
    """Rewrite the file itself (every hard link and the owner stay): first a journal, complete and on
    disk, proving for which file and which old content the new content is meant; then, with Ctrl-C,
    SIGTERM and SIGHUP held, the disk blocks a longer content needs are claimed (a full disk: the
    file is as it was, the journal removed), the copy is made, and the journal removed. SIGKILL or a
    power cut at any point leaves the old file, the new one, or a prefix of the new over the old with
    the journal beside it: the next zero proves the journal and completes the copy."""
    journal = tmp[: -len(".tmp")] + ".journal"
    with _signals_held():
        os.replace(tmp, journal)
        _fsync_directory(os.path.dirname(tmp) or ".")
        try:  # a full disk fails here, with the file as it was and nothing left to complete later
            _claim_blocks(target, len(data))
        except OSError as exc:
            with contextlib.suppress(OSError):
                os.unlink(journal)
            raise ZeroError(f"not written: {exc.strerror or exc}; the file is unchanged", str(target)) from None
        try:
            _rewrite_in_place(target, data)
        except OSError as exc:
            raise ZeroError(f"not written completely: {exc.strerror or exc}; the next zero that reads or "
                            f"writes it completes it from {os.path.basename(journal)}", str(target)) from None
        os.unlink(journal)
        done[0] = True

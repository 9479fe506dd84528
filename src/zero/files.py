"""Reading and writing files: the one module through which zero touches the disk.

:func:`read_file` reads a whole file with a size cap and a one-line reason when it
cannot; :func:`write_atomic` writes all at once or not at all (temporary file in the
target directory, fsync, rename). Every layer that reads lists (the machine model
follows the lists a start-up list names) and every command that writes uses these
two functions, so a safety rule for files is made in one place.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

from zero.errors import ZeroError

MAX_FILE_BYTES = 256 * 1024 * 1024


def read_file(path: str | Path) -> bytes:
    """Read a file; :class:`ZeroError` with a one-line reason on failure."""
    p = Path(path)
    where = str(path)
    try:
        size = p.stat().st_size
        if size > MAX_FILE_BYTES:
            raise ZeroError(f"file is {size} bytes, larger than the "
                            f"{MAX_FILE_BYTES // (1024 * 1024)} MiB zero reads", where)
        return p.read_bytes()
    except FileNotFoundError:
        raise ZeroError("no such file", where) from None
    except IsADirectoryError:
        raise ZeroError("is a directory", where) from None
    except PermissionError:
        raise ZeroError("permission denied", where) from None
    except OSError as exc:
        raise ZeroError(str(exc.strerror or exc), where) from None


def write_atomic(path: Path, data: bytes, force: bool = False,
                 inputs: tuple[Path, ...] = ()) -> None:
    """Write ``data`` to ``path`` all at once or not at all.

    Never over an input file, never over an existing file unless ``force``.
    The bytes go to a temporary file in the same directory, are flushed to
    disk, and replace the target by one rename; on any failure the temporary
    file is removed and the target is untouched.
    """
    target = Path(path)
    where = str(target)
    for src in inputs:
        try:
            if target.exists() and os.path.samefile(target, src):
                raise ZeroError("is an input file; zero never writes over its input", where)
        except FileNotFoundError:
            continue
    if target.exists() and not force:
        raise ZeroError("already exists (use --force to replace it)", where)
    if target.is_dir():
        raise ZeroError("is a directory", where)
    directory = target.parent if str(target.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=directory)
    except OSError as exc:
        raise ZeroError(f"cannot write here: {exc.strerror or exc}", where) from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        if target.exists():
            with contextlib.suppress(OSError):
                os.chmod(tmp, target.stat().st_mode & 0o7777)
        else:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, target)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise ZeroError(f"not written: {exc.strerror or exc}", where) from None
        raise

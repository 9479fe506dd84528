"""Bundles: the code of every module a command loads, in one file beside zero's cached bytecode (start-up).

A lint loads some sixty of zero's modules. Each one imported on its own is a search, a read of its cached
bytecode, a check of it, a module and spec made step by step by Python's import machinery, and its code
read out of its bytes; the names and constants the modules share (``self``, ``__init__``, each record's
field names) are read again in each. A bundle is those modules' code in one file, read at once and run
in the order a lint imports them (:func:`zero.preload`): some 10 M of the 140 M instructions of a lint of
an axis list.

A bundle is written the way Python writes cached bytecode: by the first run that finds none (or a stale
one), from the cached bytecode Python checked or wrote for it, into the package's own ``__pycache__``
folder, and never where Python would not write cached bytecode (``-B``, ``PYTHONDONTWRITEBYTECODE``, a
folder it cannot write to, no ``__pycache__`` folder). It holds the path, modification time (to the
nanosecond) and size of every source it was made of, and is used only while each is the same: an edited,
replaced or moved module, or another version of zero, makes the next run import as Python does and write
the bundle again. ``python -m zero.bundles`` writes them all at once (as ``compileall`` does cached
bytecode); the benchmarks do so.

Which modules a command's bundle holds is :mod:`zero.bundled_modules` (written by
``tools/gen_bundled_modules.py`` from real runs: the modules every lint of a list loads, whatever its kind).
"""

from __future__ import annotations

import marshal
import os
import sys
from importlib import import_module
from importlib.util import MAGIC_NUMBER
from types import CodeType

import zero
from zero.bundled_modules import COMMANDS
from zero.files import write_disposable


def write(command: str) -> bool:
    """Write ``command``'s bundle (see the module); ``False`` where it is not written: zero's finder is not
    in use (another Python, ``-O``, a ``pycache_prefix``), Python writes no cached bytecode, the folder is
    missing or not writable, or a module's cached bytecode is not current (Python could not write it)."""
    path = zero.bundle_path(command)
    if path is None or sys.dont_write_bytecode or not os.access(os.path.dirname(path), os.W_OK):
        return False
    root = zero.__path__[0]
    sources: list[tuple[str, int, int]] = []
    items: list[tuple[str, bool, str, CodeType]] = []
    try:
        for name in COMMANDS[command]:
            module = sys.modules.get(name) or import_module(name)
            source = module.__file__
            cached = module.__cached__
            if not source or not cached or not source.startswith(root + os.sep):
                return False
            found = zero.current_bytecode(source, cached)
            if found is None:
                return False
            st, data = found
            code = marshal.loads(memoryview(data)[16:])
            rel = source[len(root) + 1:]
            sources.append((rel, st.st_mtime_ns, st.st_size))
            items.append((name, hasattr(module, "__path__"), rel, code))
        listed = os.path.join(root, "bundled_modules.py")  # another list of modules: another bundle
        st = os.stat(listed)
        sources.append((listed[len(root) + 1:], st.st_mtime_ns, st.st_size))
        header = marshal.dumps((zero.BUNDLE_FORMAT, MAGIC_NUMBER, root, tuple(sources)))
        write_disposable(path, len(header).to_bytes(4, "little") + header + marshal.dumps(tuple(items)))
    except (OSError, ValueError, EOFError):  # a file gone or not writable meanwhile: the next run tries again
        return False
    return True


def write_missing() -> None:
    """Write each bundle this process asked for and did not find current (at the end of a command)."""
    for command, used in zero.BUNDLES_ASKED.items():
        if not used and command in COMMANDS:
            write(command)


def main() -> None:
    """``python -m zero.bundles``: write every bundle; where one is not written, say so (exit status 1)."""
    failed = [command for command in COMMANDS if not write(command)]
    if failed:
        raise SystemExit(f"zero: not written (see zero.bundles for where a bundle is written): "
                         f"the bundle of {', '.join(failed)}")


if __name__ == "__main__":
    main()

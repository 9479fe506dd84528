"""zero: lint, diff and convert the ASCII parameter lists of the ISG kernel CNC controller.

Importing zero also puts one finder in front of ``sys.meta_path`` for zero's own modules (start-up):
a lint loads some sixty of them, and Python's path finder spends about a third of a millisecond on
each (the folder's ``stat``, each suffix tried, the spec built from the file location, the cached
bytecode read and checked in several steps). The finder reads the module's cached bytecode and checks
it exactly as Python's own loader does (the magic number, a timestamp-based file, the source's
modification time and size), then hands Python a spec with a standard ``SourceFileLoader`` (so
``__file__``, ``__cached__``, ``__path__``, ``get_source`` and reloading are what they always were).
Anything else (no cached file, a stale or hash-based one, another Python, ``-O``, a
``pycache_prefix``, a name that is not a module here) it leaves to Python's finders, which compile and
write the cache as always.
"""

from __future__ import annotations

import sys

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing
if TYPE_CHECKING:
    from types import CodeType

__version__ = "0.1.0"

# The subpackages (folders with an __init__.py); any other zero.X.Y is a module file.
# tests/test_fast_imports.py keeps this equal to the folders.
PACKAGES = frozenset({"catalog", "catalog.data", "cli", "engine", "lists", "machine", "markup", "nc", "output",
                      "output.formats", "rules", "server", "structured"})


def _install() -> None:
    if (sys.implementation.name != "cpython" or sys.implementation.cache_tag is None or sys.flags.optimize
            or sys.pycache_prefix is not None or not __file__ or not __path__):
        return
    for finder in sys.meta_path:
        if getattr(finder, "__module__", None) == __name__:  # zero imported again (importlib.reload): replaced
            sys.meta_path.remove(finder)
            break
    try:
        import _frozen_importlib_external as external  # start-up: CPython's path machinery, loaded at start
        from _frozen_importlib import ModuleSpec  # start-up: as above
        from _imp import _fix_co_filename  # type: ignore[attr-defined]  # start-up: built in
    except ImportError:  # pragma: no cover - CPython always has them
        return
    from marshal import loads  # start-up: built in
    from os import sep, stat  # start-up: loaded at start

    root = __path__[0]
    tag = f".{sys.implementation.cache_tag}.pyc"
    header = external.MAGIC_NUMBER + b"\0\0\0\0"  # the magic number, and flags 0: checked by timestamp

    class Loader(external.SourceFileLoader):
        """Python's own loader, given the bytecode the finder read and checked (used once)."""

        data: bytes | None = None

        def get_code(self, fullname: str) -> CodeType | None:
            data = self.data
            if data is None or fullname != self.name:
                return super().get_code(fullname)
            self.data = None
            code: CodeType = loads(memoryview(data)[16:])
            _fix_co_filename(code, self.path)  # as Python's loader: the module's file, should it have moved
            return code

    class Finder:
        """``zero.X`` from its cached bytecode, when that is current; ``None`` (Python's finders) otherwise."""

        @staticmethod
        def find_spec(name: str, path: object = None, target: object = None) -> ModuleSpec | None:
            if not name.startswith("zero."):
                return None
            dotted = name[5:]
            package = dotted in PACKAGES
            if package:
                folder, leaf = f"{root}{sep}{dotted.replace('.', sep)}", "__init__"
            else:
                folder, _, leaf = f"{root}{sep}{dotted.replace('.', sep)}".rpartition(sep)
            if path is not None and (folder.rpartition(sep)[0] if package else folder) not in path:  # type: ignore[operator]
                return None  # the parent's search path moved elsewhere: Python's finders look there
            source = f"{folder}{sep}{leaf}.py"
            cached = f"{folder}{sep}__pycache__{sep}{leaf}{tag}"
            try:
                st = stat(source)
                with open(cached, "rb", buffering=0) as f:  # unbuffered: one read of the whole file
                    data = f.readall()
            except (OSError, ValueError):
                return None
            if (data[:8] != header or len(data) < 16
                    or int.from_bytes(data[8:12], "little") != int(st.st_mtime) & 0xFFFFFFFF
                    or int.from_bytes(data[12:16], "little") != st.st_size & 0xFFFFFFFF):
                return None
            loader = Loader(name, source)
            loader.data = data
            spec = ModuleSpec(name, loader, origin=source, is_package=package)
            spec.cached = cached
            spec.has_location = True
            if package:
                spec.submodule_search_locations = [folder]
            return spec

    sys.meta_path.insert(0, Finder)


_install()

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

A command's modules can also come all at once from a bundle (:func:`preload`): the code of every module a
lint loads, written by :mod:`zero.bundles` beside the cached bytecode and used only while each of their
sources is the file it was written from.
"""

from __future__ import annotations

import marshal
import os
import sys

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing
if TYPE_CHECKING:
    from mmap import mmap
    from os import stat_result
    from types import CodeType, ModuleType
    from typing import Any, BinaryIO

__version__ = "0.1.0"

# The subpackages (folders with an __init__.py); any other zero.X.Y is a module file.
# tests/test_fast_imports.py keeps this equal to the folders.
PACKAGES = frozenset({"catalog", "catalog.data", "cli", "engine", "lists", "machine", "markup", "nc", "output",
                      "output.formats", "rules", "server", "structured"})


# What the finder was installed with (None: not installed, and no bundle is read or written): the package's
# folder, the cached bytecode's suffix, its header (magic number, flags 0), the loader and spec classes.
_FOUND: tuple[str, str, bytes, type, type] | None = None


class _Module(type(sys)):  # type: ignore[misc]
    """The class of zero's modules that do not answer missing names themselves (no module ``__getattr__``):
    a module whose missing attribute is looked for without an error made and thrown away. CPython 3.11
    looks a module's ``__path__`` up at every ``from module import name`` (is it a package?) and, for a
    plain module, formats "module ... has no attribute" first: some 3,500 instructions each, 400 of them in
    a lint. Python allows a module's class to be a subclass of its own (the language reference:
    "customizing module attribute access"); this one takes ``object``'s attribute look-up, which CPython
    asks without an error where the attribute may be missing. A missing attribute still raises
    ``AttributeError`` ("'module' object has no attribute ...")."""

    __slots__ = ()
    __getattribute__ = object.__getattribute__


_Module.__name__ = _Module.__qualname__ = "module"  # the name its errors give


def _plain(module: ModuleType) -> None:
    """``module`` of class :class:`_Module`, unless it answers missing names itself (PEP 562)."""
    if "__getattr__" not in module.__dict__:
        module.__class__ = _Module


BUNDLE_FORMAT = 1  # the layout of a bundle (see preload): another one is not read
# The bundles this process asked for, and whether each was used (zero.bundles writes the others at the end).
BUNDLES_ASKED: dict[str, bool] = {}


def current_bytecode(source: str, cached: str) -> tuple[stat_result, bytes] | None:
    """The source's ``stat`` and the cached bytecode of it, when that is current exactly as Python's loader
    checks it (the magic number, a timestamp-based file, the source's modification time and size); ``None``
    otherwise (no such file, a stale or hash-based one, another Python, zero's finder not installed)."""
    if _FOUND is None:
        return None
    try:
        st = os.stat(source)
        with open(cached, "rb", buffering=0) as f:  # unbuffered: one read of the whole file
            data = f.readall()
    except (OSError, ValueError):
        return None
    if (data[:8] != _FOUND[2] or len(data) < 16
            or int.from_bytes(data[8:12], "little") != int(st.st_mtime) & 0xFFFFFFFF
            or int.from_bytes(data[12:16], "little") != st.st_size & 0xFFFFFFFF):
        return None
    return st, data


def bundle_path(command: str) -> str | None:
    """The file of ``command``'s bundle (beside zero's cached bytecode, named for this Python as a cached
    module is); ``None`` where zero's finder is not installed (another Python, ``-O``, a ``pycache_prefix``)."""
    if _FOUND is None:
        return None
    return f"{_FOUND[0]}{os.sep}__pycache__{os.sep}bundle-{command}{_FOUND[1][:-4]}.bin"


def preload(command: str) -> bool:
    """Run the modules of ``command``'s bundle, each as Python's import would (in ``sys.modules``, on its
    package, with its spec, loader, file and cached file), in the order a run of the command imported them;
    ``False`` where there is no bundle to use (none written, or one source differs in time or size from the
    one it was written from: a stale bundle is never used, and Python's import loads every module).

    A bundle is one file: the length of its header, the header (:data:`BUNDLE_FORMAT`, Python's magic
    number, the package's folder, and each source's path below it, modification time in nanoseconds and
    size) and the modules (name, whether a package, source path, code), both in ``marshal``'s format:
    reading it is one mapping and two ``loads``, where importing the modules one by one is a search, a
    read and a check each, and the names and constants they share are read once.
    """
    path = bundle_path(command)
    if path is None or command in BUNDLES_ASKED:
        return False
    BUNDLES_ASKED[command] = False
    root = _FOUND[0]  # type: ignore[index]
    try:
        with open(path, "rb", buffering=0) as f:
            data = _mapped(f)
    except OSError:  # none
        return False
    try:
        with memoryview(data) as view:
            size = int.from_bytes(view[:4], "little")
            form, magic, where, sources = marshal.loads(view[4:4 + size])
            if form != BUNDLE_FORMAT or magic != _FOUND[2][:4] or where != root:  # type: ignore[index]
                return False
            for rel, mtime, length in sources:
                st = os.stat(f"{root}{os.sep}{rel}")
                if st.st_mtime_ns != mtime or st.st_size != length:
                    return False
            items = marshal.loads(view[4 + size:])
            code = type(_run.__code__)
            if not all(len(item) == 4 and type(item[3]) is code for item in items):
                return False  # marshal's, but not modules
    except (OSError, EOFError, ValueError, TypeError):  # not a bundle: as none
        return False
    finally:
        if not isinstance(data, bytes):
            data.close()
    _run(items, root)
    BUNDLES_ASKED[command] = True
    return True


def _mapped(f: BinaryIO) -> bytes | mmap:
    """The bytes of the open file ``f``, mapped where the system can: a read copies them into memory the
    process has not touched yet, which the system hands over a page at a time (some 3 µs each on a virtual
    machine, 255 for a lint's bundles), where a mapping takes them from its file cache many pages at a
    time; read where ``mmap`` cannot map it (an empty file, another system)."""
    try:
        import mmap  # start-up: only where a bundle is read (an extension module, cheaper than the pages it saves)

        return mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_READ)
    except (ImportError, OSError, ValueError):
        return f.read()


def _run(items: tuple[tuple[str, bool, str, CodeType], ...], root: str) -> None:
    """Run each module of ``items`` not loaded yet, in their order (see :func:`preload`)."""
    sep = os.sep
    modules = sys.modules
    _, tag, _, loader_class, spec_class = _FOUND  # type: ignore[misc]
    known = {item[0]: item for item in items}
    waiting: dict[str, ModuleType] = {}  # made here, their body not run yet

    def made(name: str) -> ModuleType:
        """The module ``name`` of the bundle before its body runs, as Python's import makes it."""
        _, package, rel, _ = known[name]
        parent = name.rpartition(".")[0]
        if parent not in modules:  # a package whose body imports this module runs after it, as in a run
            if parent in known:
                made(parent)
            else:
                __import__(parent)  # a package the bundle does not hold: Python imports it
        source = f"{root}{sep}{rel}"
        folder, _, leaf = source.rpartition(sep)
        cached = f"{folder}{sep}__pycache__{sep}{leaf[:-3]}{tag}"
        loader = loader_class(name, source)
        spec = spec_class(name, loader, origin=source, is_package=package)
        spec.cached = cached
        spec.has_location = True
        module = type(sys)(name)
        module.__loader__ = loader
        module.__package__ = name if package else parent
        module.__spec__ = spec
        if package:
            spec.submodule_search_locations = module.__path__ = [folder]
        module.__file__ = source
        module.__cached__ = cached  # type: ignore[attr-defined]
        modules[name] = waiting[name] = module
        return module

    name = ""
    try:
        for name, _, _, code in items:
            module = waiting.pop(name, None)
            if module is None:
                if name in modules:
                    continue  # imported already
                parent = name.rpartition(".")[0]
                if parent not in modules and parent not in known:
                    __import__(parent)  # a package the bundle does not hold: Python imports it
                    if name in modules:
                        continue
                module = made(name)
                waiting.pop(name)
            spec: Any = module.__spec__
            spec._initializing = True  # as Python's import: while its body runs, and ...
            try:
                exec(code, module.__dict__)
            finally:
                spec._initializing = False  # ... after (each import of it looks: it fails slowly where unset)
            _plain(module)
            parent, _, leaf = name.rpartition(".")
            setattr(modules[parent], leaf, module)
    except BaseException:
        for gone in (name, *waiting):  # as Python's import: a module whose body did not finish is not kept
            modules.pop(gone, None)
        raise


def _install() -> None:
    global _FOUND
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
    loads = marshal.loads
    sep = os.sep
    root = __path__[0]
    tag = f".{sys.implementation.cache_tag}.pyc"

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

        def exec_module(self, module: ModuleType) -> None:
            super().exec_module(module)
            _plain(module)

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
            found = current_bytecode(source, cached)
            if found is None:
                return None
            loader = Loader(name, source)
            loader.data = found[1]
            spec = ModuleSpec(name, loader, origin=source, is_package=package)
            spec.cached = cached
            spec.has_location = True
            if package:
                spec.submodule_search_locations = [folder]
            return spec

    _FOUND = (root, tag, external.MAGIC_NUMBER + b"\0\0\0\0", Loader, ModuleSpec)
    sys.meta_path.insert(0, Finder)


_install()
_plain(sys.modules[__name__])

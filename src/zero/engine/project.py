"""The resolver: which configuration, catalogue and machine apply to a file.

Every command and the language server ask one :class:`Project` (one per run, or per
workspace in the server, built by :func:`open_project` and nowhere else) for the finished
:class:`Settings` of a path (:meth:`Project.settings`), as ruff's ``Resolver::resolve(path)``
gives one ``Settings`` per file with the command line laid over it once. A command reads
what applies to a file from that one object, and no other module answers these questions:

* **configuration**: the ``zero.toml`` / ``.zero.toml`` / ``pyproject.toml`` ``[tool.zero]``
  nearest the file (``--config`` for every file, ``--isolated`` none), found from the
  directory that holds the file, cached by that directory; :meth:`Project.options` lays the
  command line over it (per-file ignores included) — the options the funnel applies, and
  the code page the configuration declares for the list (:meth:`Project.encoding`), which
  every reader of the list decodes it with (the machine's too);
* **catalogue**: ``--param-desc`` (or ``ZERO_PARAM_DESC``), else the configuration's
  ``param-desc``, else the built-in table; one registry per description, loaded once;
* **machine**: the start-up list ``--machine`` names, else the configuration's
  ``[tool.zero.machine] startup``, with the list overrides and working directory of the
  configuration that applies to *the start-up list*, read with the file's catalogue; one
  machine per start-up list (by its absolute path), list overrides, working directory and
  registry, read again only when a file it was read from changes.

In the spirit of ruff's settings resolver and flake8's style guide manager: resolved once,
cached by identity (absolute paths and the registry object, never a string two different
things could share), and the only place that reads a configuration file or loads a machine.

Paths in messages: a machine's files are named relative to the current directory when they lie
below it, else absolutely (as ruff names them), whether the start-up list came from ``--machine``
or from ``[tool.zero.machine]`` (:func:`shown_path`; the language server names them absolutely).
"""

from __future__ import annotations

import os
from collections import OrderedDict
from collections.abc import Callable, Hashable, Sequence

from zero.engine.config import Config, ConfigFinder, is_inline
from zero.engine.results import LintOptions
from zero.errors import ZeroError
from zero.files import path_str, read_file, resolve
from zero.records import Record, field

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: `zero lint` of lists loads no machine model (nor pathlib: its files are strings)
    from pathlib import Path
    from typing import TypeAlias

    from zero.catalog.registry import Registry
    from zero.lists.model import Document
    from zero.machine.model import Machine

    FileName: TypeAlias = str | os.PathLike[str]  # a file as the engine names it (a Path from the library)
    Reader: TypeAlias = Callable[[Path], bytes]
    Layout: TypeAlias = tuple[dict[str, Path], Path | None, tuple[tuple[str, Path], ...]]  # overrides, workdir, roots

# (strings: the catalogue is imported where it is loaded, pathlib where a machine is)
Registries = Callable[["str | os.PathLike[str] | None"], "Registry"]
Signature = tuple[tuple[str, int, int, str | None], ...]  # path, mtime, size, declared codec


def absolute(path: FileName) -> Path:
    """``path`` made absolute against the current directory, links and ``..`` kept as written."""
    from pathlib import Path  # start-up: only for a machine

    return Path(os.path.abspath(path))


def shown_path(path: FileName, base: FileName | None) -> Path:
    """How messages name a file: relative to ``base`` (the current directory of the run) when it lies
    below it, else absolute (ruff's ``relativize_path``); ``base`` ``None``: always absolute (the
    language server, whose current directory is nobody's)."""
    from pathlib import Path  # start-up: only for a machine

    full = absolute(path)
    if base is not None:
        try:
            rel = full.relative_to(base)
        except ValueError:
            return full
        return rel if rel.parts else Path(".")
    return full


class Common(Record, frozen=True):
    """The options of every command that reads lists (declared once in :mod:`zero.cli.options`):
    ``--config`` (a file, or ``KEY = VALUE`` over the configuration that applies), ``--isolated``,
    ``--param-desc`` and the kernel release (``--kernel``, laid over as ``kernel = …``)."""

    config: tuple[str, ...] = ()
    isolated: bool = False
    param_desc: str | Path | None = None  # a str as a Path prints it (zero.files.path_str) where common_of made it
    kernel: str | None = None

    @property
    def configs(self) -> tuple[str, ...]:
        """``--config`` with the kernel release as one more ``KEY = VALUE`` over it."""
        if self.kernel is None:
            return self.config
        escaped = self.kernel.replace("\\", "\\\\").replace('"', '\\"')
        return (*self.config, f'kernel = "{escaped}"')


def common_of(config: FileName | Sequence[str] | None, isolated: bool = False,
              param_desc: FileName | None = None, kernel: str | None = None) -> Common:
    """The common options as a library function is given them (``config``: one file, or files and
    ``KEY = VALUE`` overrides)."""
    given = [config] if isinstance(config, (str, os.PathLike)) else list(config or ())
    return Common(tuple(str(c) for c in given), isolated, path_str(param_desc) if param_desc else None, kernel)


class Settings(Record, frozen=True, eq=False):
    """Everything that applies to one file, resolved once: its configuration, the lint options with
    the command line laid over them (per-file ignores, severities, kind, code page, kernel release),
    the catalogue it is read against, and (lazily) the machine it belongs to. Every command and the
    language server read a file's answers from here, never from the configuration or the loaders."""

    path: FileName | None  # the file (None: standard input without a name, or the current directory's)
    config: Config
    options: LintOptions
    param_desc: str | Path | None  # the parameter description of the catalogue (None: the built-in table)
    project: Project = field(repr=False)

    @property
    def root(self) -> Path:
        """The folder relative paths of the configuration are relative to."""
        return self.config.root

    @property
    def encoding(self) -> str | None:
        """The code page the configuration declares for the list (None: detected from the bytes)."""
        return self.options.encoding

    @property
    def release(self) -> str | None:
        """The kernel release the machines run (``kernel``, ``--kernel``); None: not said."""
        return self.options.kernel

    @property
    def kind(self) -> str | None:
        """The list kind the command line or the configuration forces (None: detected)."""
        return self.options.kind

    @property
    def registry(self) -> Registry:
        """The catalogue (loaded once per description, :class:`ZeroError` when it cannot be read)."""
        return self.project.registries(self.param_desc)

    @property
    def startup(self) -> Path | None:
        """The start-up list of the machine the file belongs to (absolute), if one is named."""
        return self.project.startup(self.path)

    def machine(self, *, required: bool = False, reader: Reader | None = None,
                reader_key: Hashable = None) -> Machine | None:
        """The machine the file belongs to, read once per run (:meth:`Project.machine`)."""
        return self.project.machine(self.path, required=required, reader=reader, reader_key=reader_key)


def _signature(machine: Machine, encoding: Callable[[FileName], str | None]) -> Signature:
    """What a machine was read from: every named file's size and modification time, and the code
    page the configuration declares for it."""
    paths = [machine.startup.path, *(n.path for n in machine.named if n.path is not None)]
    out = []
    for p in paths:
        try:
            st = os.stat(resolve(p))  # `export.xml#AchsMds`: the export's own size and time
            out.append((str(p), st.st_mtime_ns, st.st_size, encoding(p)))
        except OSError:
            out.append((str(p), -1, -1, encoding(p)))
    return tuple(out)


class Project:
    """The answers of one run (or one editor workspace) to "what applies to this file"."""

    def __init__(self, registries: Registries, *, config: FileName | Sequence[str] | None = None,
                 isolated: bool = False, param_desc: FileName | None = None, cli: LintOptions | None = None,
                 machine: FileName | None = None, shown_from: FileName | None = None) -> None:
        self.registries = registries
        self.shown_from = shown_from  # messages name a machine's files relative to it (None: absolutely)
        given = [config] if isinstance(config, (str, os.PathLike)) else list(config or ())
        files = [path_str(c) for c in given if not is_inline(str(c))]
        if len(files) > 1:
            raise ZeroError(f"--config names {len(files)} files; one file, and any number of KEY=VALUE")
        self.finder = ConfigFinder(files[0] if files else None, isolated,
                                   tuple(str(c) for c in given if is_inline(str(c))))
        self.param_desc_given = path_str(param_desc) if param_desc else None
        self.cli = cli or LintOptions()
        self.machine_given = absolute(machine) if machine is not None else None
        self.machine_shown = shown_path(machine, shown_from) if machine is not None else None
        self._settings: dict[FileName | None, Settings] = {}
        self._machines: dict[Hashable, tuple[Signature, Machine]] = {}
        self._shaped: OrderedDict[Hashable, Machine] = OrderedDict()  # read with an editor's unsaved text

    def shown(self, path: FileName) -> Path:
        """How messages of this run name a file (:func:`shown_path`)."""
        return shown_path(path, self.shown_from)

    # ----------------------------------------------------------------- settings

    def settings(self, path: FileName | None) -> Settings:
        """The finished settings of one file: its configuration with the command line laid over it
        once (cached by the path; :meth:`forget` drops them)."""
        hit = self._settings.get(path)
        if hit is None:
            cfg = self.config(path)
            options = cfg.options_for(path if path is not None else "-", self.cli)
            hit = self._settings[path] = Settings(path, cfg, options, self.param_desc_given or cfg.param_desc, self)
        return hit

    # ----------------------------------------------------------------- configuration

    def config(self, path: FileName | None, directory: bool = False) -> Config:
        """The configuration of a file (or of a directory, ``directory=True``: ``zero config DIR``);
        the current directory's for ``None`` (standard input without a name, ``zero limits``)."""
        if path is None:
            return self.finder.for_path(os.getcwd(), directory=True)
        return self.finder.for_path(path, directory)

    def options(self, path: FileName | None) -> LintOptions:
        """The options of one file: the command line over its configuration (:meth:`settings`)."""
        return self.settings(path).options

    def encoding(self, path: FileName | None) -> str | None:
        """The codec the configuration declares for a list (``[tool.zero] encoding``), else ``None``:
        detected from the bytes. Standard input without a name has none."""
        return self.config(path).encoding_for(path) if path is not None else None  # asked per file of a machine

    def excluded(self, path: FileName) -> bool:
        """Excluded by the configuration of the directory that holds it (a file or a directory)."""
        return self.config(path).excluded(path)

    def included(self, path: FileName) -> bool:
        return self.config(path).included(path)

    def respects_gitignore(self, directory: FileName) -> bool:
        """Does a walk of ``directory`` skip what git ignores (``respect-gitignore``, default true)?"""
        return self.config(directory, directory=True).respect_gitignore

    # ----------------------------------------------------------------- catalogue

    def param_desc(self, path: FileName | None) -> FileName | None:
        """The parameter description of a file: the command line's, else its configuration's."""
        return self.settings(path).param_desc

    def registry(self, path: FileName | None) -> Registry:
        """The catalogue a file is checked against (:class:`ZeroError` when a description cannot be read)."""
        return self.settings(path).registry

    # ----------------------------------------------------------------- machine

    def startup(self, path: FileName | None = None) -> Path | None:
        """The start-up list of the machine a file belongs to (absolute): ``--machine``, else the
        configuration's ``[tool.zero.machine] startup``."""
        if self.machine_given is not None:
            return self.machine_given
        named = self.config(path).machine
        return absolute(named) if named is not None else None

    def machine(self, path: FileName | None = None, *, required: bool = False, startup: FileName | None = None,
                reader: Reader | None = None, reader_key: Hashable = None) -> Machine | None:
        """The machine ``path`` belongs to (or the one of ``startup``), as the controller builds it.

        ``required``: a command about a machine: no start-up list, or one that yields no machine
        (names no list, or is another kind of list), is a :class:`ZeroError`. ``reader`` gives a
        list's bytes where they are not the saved file's (an editor's unsaved text), ``reader_key``
        says what it gives (the machines read with it are kept apart)."""
        if startup is not None:
            start: Path | None = absolute(startup)
            shown: Path | None = shown_path(startup, self.shown_from)
        else:
            start = self.startup(path)
            named = self.config(path).machine
            shown = self.machine_shown if self.machine_given is not None else \
                shown_path(named, self.shown_from) if named is not None else None
        if start is None or shown is None:
            if required:
                raise ZeroError("name the start-up list with --machine (or [tool.zero.machine] startup)")
            return None
        registry = self.registry(path if path is not None else start)
        layout = self._layout(start)
        overrides, workdir, roots = layout
        key = (start, tuple(sorted(overrides.items())), workdir, roots, id(registry), self.cli.kind)
        if reader is not None:
            machine = self._read_with(key, reader_key, shown, registry, layout, reader)
        else:
            hit = self._machines.get(key)
            if hit is not None and hit[0] == _signature(hit[1], self.encoding):
                machine = hit[1]
            else:
                machine = self._load(shown, registry, layout, read_file)
                self._machines[key] = (_signature(machine, self.encoding), machine)
        return require_startup(machine, registry) if required else machine  # asked each time, cached or not

    def _read_with(self, key: Hashable, reader_key: Hashable, shown: Path, registry: Registry,
                   layout: Layout, reader: Reader) -> Machine:
        full = (key, reader_key)
        hit = self._shaped.get(full)
        if hit is None:
            hit = self._shaped[full] = self._load(shown, registry, layout, reader)
            while len(self._shaped) > 4:
                self._shaped.popitem(last=False)
        return hit

    def _load(self, startup: Path, registry: Registry, layout: Layout, reader: Reader) -> Machine:
        from zero.machine.model import load_machine, machine_ceiling  # start-up: only with a machine

        return load_machine(startup, registry, self.cli.kind, layout[0], layout[1], reader, machine_ceiling(startup),
                            layout[2], self.encoding)

    def references(self, startup: Path, doc: Document) -> dict[str, Path]:
        """The lists a start-up list names (key as written → the path the controller opens), resolved
        as its machine is (list overrides and working directory of its configuration); nothing is
        read. A reference zero would not read (outside the working directory, empty) has none."""
        from zero.machine.model import machine_ceiling, named_lists  # start-up: only for a start-up list

        overrides, workdir, roots = self._layout(startup)
        _, named = named_lists(startup, doc, overrides, workdir, machine_ceiling(startup), roots)
        return {n.key: n.path for n in named if n.path is not None and n.status != "not-checked"}

    def _layout(self, startup: Path) -> Layout:
        """The list overrides, working directory and folder mapping (``roots``) of ``[tool.zero.machine]``
        that apply to a start-up list: those of the configuration that applies to it, where that
        configuration names this start-up list or none (overrides written for another machine's
        start-up list never apply; its folder mapping does: it describes the controller)."""
        cfg = self.config(startup)
        if cfg.machine is not None and os.path.realpath(cfg.machine) != os.path.realpath(startup):
            return {}, None, cfg.machine_roots
        return cfg.machine_lists, cfg.machine_workdir, cfg.machine_roots

    def forget(self) -> None:
        """Configuration files changed (or may have): find and read them again."""
        self.finder = ConfigFinder(self.finder.explicit.path if self.finder.explicit else None, self.finder.isolated,
                                   self.finder.overrides)
        self._settings.clear()


def require_startup(machine: Machine, registry: Registry) -> Machine:
    """A machine question needs a start-up list that names lists: anything else is said plainly."""
    doc = machine.startup.values.doc
    kind = registry.kind_of(doc)
    if not machine.named:
        if kind not in (None, "STUP"):
            from zero.catalog.registry import KINDS  # start-up: only for this message

            raise ZeroError(f"not a start-up list: it reads as a {KINDS[kind][1]} and names no other list; "
                            "give the start-up list (hochlauf.lis)", doc.path)
        raise ZeroError("names no list of a machine (no `achs_mds[i]`, `sda_mds[c]`, ...): not a start-up "
                        "list, or an empty one; give the start-up list (hochlauf.lis)", doc.path)
    return machine


def open_project(registries: Registries, common: Common | None = None, *, cli: LintOptions | None = None,
                 machine: FileName | None = None, shown_from: FileName | bool | None = True) -> Project:
    """The resolver of one run (ruff's ``resolve``: isolated defaults, one ``--config``, or the
    configuration found per file): the one place a :class:`Project` is made. ``shown_from``: the
    folder messages name a machine's files relative to (``True``: the current directory; ``None``:
    absolutely, as the language server does)."""
    common = common or Common()
    base = os.path.abspath(os.curdir) if shown_from is True else shown_from or None
    return Project(registries, config=common.configs, isolated=common.isolated, param_desc=common.param_desc,
                   cli=cli, machine=machine, shown_from=base)


__all__ = ["Common", "Project", "Registries", "Settings", "absolute", "common_of", "open_project", "require_startup",
           "shown_path"]


def _no_catalogue(_desc: FileName | None) -> Registry:
    raise ZeroError("no catalogue is resolved here")  # pragma: no cover - only configurations are asked


def configurations_only(common: Common | None = None) -> Project:
    """A project asked only for configurations (a list's declared code page): it loads no catalogue."""
    return open_project(_no_catalogue, common)

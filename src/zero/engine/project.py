"""The resolver: which configuration, catalogue and machine apply to a file.

Every command and the language server ask one :class:`Project` (one per run, or per
workspace in the server) three questions about a path, and no other module answers them:

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
"""

from __future__ import annotations

import os
from collections import OrderedDict
from collections.abc import Callable, Hashable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from zero.catalog.registry import KINDS, Registry
from zero.engine.config import Config, ConfigFinder, is_inline
from zero.engine.lint import LintOptions
from zero.errors import ZeroError
from zero.files import read_file, resolve

if TYPE_CHECKING:  # start-up: `zero lint` of lists loads no machine model
    from zero.lists.model import Document
    from zero.machine.model import Machine

Registries = Callable[[Path | None], Registry]
Reader = Callable[[Path], bytes]
Signature = tuple[tuple[str, int, int, str | None], ...]  # path, mtime, size, declared codec
Layout = tuple[dict[str, Path], Path | None, tuple[tuple[str, Path], ...]]  # overrides, working directory, roots


def absolute(path: str | Path) -> Path:
    """``path`` made absolute against the current directory, links and ``..`` kept as written."""
    return Path(os.path.abspath(path))


def _signature(machine: Machine, encoding: Callable[[Path], str | None]) -> Signature:
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

    def __init__(self, registries: Registries, *, config: str | Path | Sequence[str] | None = None,
                 isolated: bool = False, param_desc: str | Path | None = None, cli: LintOptions | None = None,
                 machine: str | Path | None = None) -> None:
        self.registries = registries
        given = [config] if isinstance(config, (str, Path)) else list(config or ())
        files = [Path(c) for c in given if not is_inline(str(c))]
        if len(files) > 1:
            raise ZeroError(f"--config names {len(files)} files; one file, and any number of KEY=VALUE")
        self.finder = ConfigFinder(files[0] if files else None, isolated,
                                   tuple(str(c) for c in given if is_inline(str(c))))
        self.param_desc_given = Path(param_desc) if param_desc else None
        self.cli = cli or LintOptions()
        self.machine_given = absolute(machine) if machine is not None else None
        self.machine_shown = Path(machine) if machine is not None else None
        self._machines: dict[Hashable, tuple[Signature, Machine]] = {}
        self._shaped: OrderedDict[Hashable, Machine] = OrderedDict()  # read with an editor's unsaved text

    # ----------------------------------------------------------------- configuration

    def config(self, path: Path | None, directory: bool = False) -> Config:
        """The configuration of a file (or of a directory, ``directory=True``: ``zero config DIR``);
        the current directory's for ``None`` (standard input without a name, ``zero limits``)."""
        if path is None:
            return self.finder.for_path(Path.cwd(), directory=True)
        return self.finder.for_path(path, directory)

    def options(self, path: Path | None) -> LintOptions:
        """The options of one file: the command line over its configuration."""
        return self.config(path).options_for(path if path is not None else Path("-"), self.cli)

    def encoding(self, path: Path | None) -> str | None:
        """The codec the configuration declares for a list (``[tool.zero] encoding``), else ``None``:
        detected from the bytes. Standard input without a name has none."""
        return self.config(path).encoding_for(path) if path is not None else None

    def excluded(self, path: Path) -> bool:
        """Excluded by the configuration of the directory that holds it (a file or a directory)."""
        return self.config(path).excluded(path)

    def included(self, path: Path) -> bool:
        return self.config(path).included(path)

    def respects_gitignore(self, directory: Path) -> bool:
        """Does a walk of ``directory`` skip what git ignores (``respect-gitignore``, default true)?"""
        return self.config(directory, directory=True).respect_gitignore

    # ----------------------------------------------------------------- catalogue

    def param_desc(self, path: Path | None) -> Path | None:
        """The parameter description of a file: the command line's, else its configuration's."""
        return self.param_desc_given or self.config(path).param_desc

    def registry(self, path: Path | None) -> Registry:
        """The catalogue a file is checked against (:class:`ZeroError` when a description cannot be read)."""
        return self.registries(self.param_desc(path))

    # ----------------------------------------------------------------- machine

    def startup(self, path: Path | None = None) -> Path | None:
        """The start-up list of the machine a file belongs to (absolute): ``--machine``, else the
        configuration's ``[tool.zero.machine] startup``."""
        if self.machine_given is not None:
            return self.machine_given
        named = self.config(path).machine
        return absolute(named) if named is not None else None

    def machine(self, path: Path | None = None, *, required: bool = False, startup: str | Path | None = None,
                reader: Reader | None = None, reader_key: Hashable = None) -> Machine | None:
        """The machine ``path`` belongs to (or the one of ``startup``), as the controller builds it.

        ``required``: a command about a machine: no start-up list, or one that yields no machine
        (names no list, or is another kind of list), is a :class:`ZeroError`. ``reader`` gives a
        list's bytes where they are not the saved file's (an editor's unsaved text), ``reader_key``
        says what it gives (the machines read with it are kept apart)."""
        if startup is not None:
            start: Path | None = absolute(startup)
            shown: Path | None = Path(startup)
        else:
            start = self.startup(path)
            shown = self.machine_shown if self.machine_given is not None else self.config(path).machine
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
        self.finder = ConfigFinder(self.finder.explicit.path if self.finder.explicit else None, self.finder.isolated)


def require_startup(machine: Machine, registry: Registry) -> Machine:
    """A machine question needs a start-up list that names lists: anything else is said plainly."""
    doc = machine.startup.values.doc
    kind = doc.declared_kind() or registry.detect_kind((e.key.pattern for e in doc.entries if e.key), doc.path)
    if not machine.named:
        if kind not in (None, "STUP"):
            raise ZeroError(f"not a start-up list: it reads as a {KINDS[kind][1]} and names no other list; "
                            "give the start-up list (hochlauf.lis)", doc.path)
        raise ZeroError("names no list of a machine (no `achs_mds[i]`, `sda_mds[c]`, ...): not a start-up "
                        "list, or an empty one; give the start-up list (hochlauf.lis)", doc.path)
    return machine


__all__ = ["Project", "Registries", "absolute", "require_startup"]


def _no_catalogue(_desc: Path | None) -> Registry:
    raise ZeroError("no catalogue is resolved here")  # pragma: no cover - only configurations are asked


def configurations_only() -> Project:
    """A project asked only for configurations (a list's declared code page): it loads no catalogue."""
    return Project(_no_catalogue)

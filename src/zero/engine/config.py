"""Project configuration: ``[tool.zero]`` in ``pyproject.toml``, or ``zero.toml`` / ``.zero.toml``.

The file closest to a linted file wins (no merging), found by walking up from the
file's directory; ``--config PATH`` names one for every file and ``--isolated``
ignores them all. Globs are relative to the configuration file's directory
(``**/`` for any depth). Unknown keys and bad values are errors naming the file,
line and key.

Every option is declared once, in :data:`zero.engine.config_file.OPTIONS` (key, type, default,
description, example, section, how it is read and checked, how ``zero config --show`` prints it):
that module is imported only where a configuration file is read (its names are also
answered here, as before), so a lint where none is found does not load the declarations.
"""

from __future__ import annotations

import contextlib
import functools
import os
import stat
from collections.abc import Callable, Iterator

from zero.diagnostics import Severity
from zero.engine.results import LintOptions
from zero.engine.selection import layered_selection
from zero.errors import ZeroError
from zero.files import path_str, read_file
from zero.forms import CONFIG_NAMES, DEFAULT_INCLUDE
from zero.patterns import compiled
from zero.records import Record, field, replace

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from pathlib import Path  # start-up: pathlib only where a configuration names a file (param-desc, machine)
    from typing import Any, TypeAlias

    FileName: TypeAlias = str | os.PathLike[str]  # a file as the engine names it (a Path from the library)


MAX_CONFIG_BYTES = 1 << 20  # a configuration larger than 1 MiB is no configuration
MAX_EXTEND_DEPTH = 8  # `extend` chains longer than this are a loop or a mistake


def _resolved(file: FileName) -> Path:
    """The absolute path of a file under its own name: its directory resolved, the name kept (a
    link named `m.lis` is matched as `m.lis`, whatever it points to)."""
    from pathlib import Path  # start-up: only on Windows (Config.relative)

    path = Path(file)
    return path.parent.resolve() / path.name


# While a command runs (:func:`one_resolution`): a folder as named → the folder resolved, so that
# the files of one folder resolve it once (a fleet of 630 lists: 1,350 `realpath` calls, 30% of a
# run answered from the cache). Only for the span of a command: a link may change between two
# requests of the language server.
_RESOLVED: list[dict[str, str]] = []


@contextlib.contextmanager
def one_resolution() -> Iterator[None]:
    """Within the block, each folder is resolved once (the first answer is kept till it ends)."""
    _RESOLVED.append(_RESOLVED[-1] if _RESOLVED else {})
    try:
        yield
    finally:
        _RESOLVED.pop()


_CWD = "\0cwd"  # the current directory's key in the memo (no folder's name holds a NUL)


def _cwd() -> str:
    """``os.getcwd()``, asked once within :func:`one_resolution` (whose folders as named assume it stays)."""
    if not _RESOLVED:
        return os.getcwd()
    memo = _RESOLVED[-1]
    hit = memo.get(_CWD)
    if hit is None:
        hit = memo[_CWD] = os.getcwd()
    return hit


def _resolved_folder(folder: FileName) -> str:
    """``str(Path(folder).resolve())`` (``os.path.realpath``: absolute, links followed, normalised as a
    ``Path`` prints it), once per folder within :func:`one_resolution`."""
    name = os.fspath(folder)
    if not _RESOLVED:
        return os.path.realpath(name)
    memo = _RESOLVED[-1]
    hit = memo.get(name)
    if hit is None:
        hit = memo[name] = _resolved_below(name, memo)
    return hit


def _resolved_below(name: str, memo: dict[str, str]) -> str:
    """``os.path.realpath(name)``, from its parent folder's (resolved once in ``memo``) and one ``lstat`` of its
    last part where that is a plain name (no ``.``, ``..`` or doubled separator) and no link: what realpath gives
    then, without an ``lstat`` of every part above it (a fleet's 900 folders: 6,000 of them). Anything else, a
    name that does not exist included, is realpath's own answer. POSIX names only. A loop, not a recursion: a
    folder two thousand levels deep is a name like any other."""
    below: list[tuple[str, str]] = []  # (a folder on the way to name, its last part), from name up
    prefix = name
    while True:
        cut = prefix.rfind("/")
        last, head = prefix[cut + 1:], prefix[:cut]
        if cut <= 0 or os.altsep is not None or last in ("", ".", "..") or head.endswith("/"):
            resolved = memo[prefix] = os.path.realpath(prefix)
            break
        below.append((prefix, last))
        hit = memo.get(head)
        if hit is not None:
            resolved = hit
            break
        prefix = head
    for prefix, last in reversed(below):  # down again, each from its parent's answer
        here = resolved + last if resolved.endswith("/") else resolved + "/" + last
        try:
            plain = not stat.S_ISLNK(os.lstat(here).st_mode)
        except OSError:
            plain = False
        resolved = memo[prefix] = here if plain else os.path.realpath(prefix)
    return resolved


@functools.lru_cache(maxsize=64)
def _suffixes(globs: tuple[str, ...]) -> tuple[str, ...] | None:
    """The suffixes of patterns that are all ``*.suffix`` (the default ``include``), else ``None``:
    such a pattern matches a path one of whose parts ends with the suffix (gitignore's meaning,
    checked against pathspec), without importing pathspec (24 ms)."""
    out = []
    for g in globs:
        tail = g[1:]
        if not g.startswith("*.") or not tail or any(c in tail for c in "*?[]\\!/# \t\r\n\f\v"):
            return None
        out.append(tail)
    return tuple(out)


# (configuration, command line, per-file ignores, kind, code page) → the options they make
_OPTIONS: dict[tuple[object, ...], tuple[Config, LintOptions, LintOptions]] = {}


class Config(Record):
    path: str | None = None  # the file it came from, as a Path prints it (zero.files.path_str); None: defaults
    select: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    per_file_ignores: tuple[tuple[str, tuple[str, ...]], ...] = ()
    severity: dict[str, Severity] = field(default_factory=dict)
    kind: tuple[tuple[str, str], ...] = ()
    encoding: tuple[tuple[str, str], ...] = ()  # glob → the codec of the lists it matches (first match)
    include: tuple[str, ...] = DEFAULT_INCLUDE
    exclude: tuple[str, ...] = ()
    param_desc: Path | None = None
    kernel: str | None = None  # the kernel release the machines run (`V3.1.3074`), when not the catalogue's
    machine: Path | None = None  # the start-up list of the machine ([tool.zero.machine] startup)
    machine_lists: dict[str, Path] = field(default_factory=dict)  # start-up key → path override
    machine_workdir: Path | None = None  # the controller's working directory, where it cannot be found
    # a folder of the controller (`C:/TwinCAT/3.1/Components/Mc/CNC`) → where it lies in the project
    machine_roots: tuple[tuple[str, Path], ...] = ()
    extend_exclude: tuple[str, ...] = ()
    extend_per_file_ignores: tuple[tuple[str, tuple[str, ...]], ...] = ()
    respect_gitignore: bool = True
    # `extend = "../zero.toml"`: the configuration this one inherits (its patterns stay relative to
    # its own folder), and the keys this file sets itself (they replace the inherited ones)
    parent: Config | None = None
    given: frozenset[str] = frozenset()

    @property
    def root(self) -> Path:
        from pathlib import Path  # start-up: not on the lint path (its files ask relative())

        return Path(self.path).parent if self.path is not None else Path.cwd()

    def relative(self, file: FileName) -> str | None:
        if os.sep != "/" or os.altsep is not None:  # pragma: no cover - Windows: its paths' own rules
            try:
                return _resolved(file).relative_to(self.root.resolve()).as_posix()
            except ValueError:
                return None
        text = os.fspath(file)
        cut = text.rfind("/") + 1
        head, name = text[:cut], text[cut:]  # os.path.split's, its head's trailing separators still on
        own = os.fspath(self.path) if self.path is not None else None
        memo = _RESOLVED[-1] if _RESOLVED else {}
        key = f"\0rel\0{own}\0{head}"  # the files of a folder: its place below the configuration's, once
        rel = memo.get(key)
        if rel is None:
            parent = head.rstrip("/") or head  # file.parent as os.path.split gives it ("/" stays "/")
            folder = _resolved_folder(parent or ".")
            root = _resolved_folder((os.path.dirname(own) or ".") if own is not None else _cwd())
            head = root if root.endswith("/") else root + "/"
            rel = memo[key] = "" if folder == root else folder[len(head):] if folder.startswith(head) else "\0"
        if not rel:
            return name if name else "."
        if rel == "\0":  # outside it
            return None
        return rel + "/" + name if name else rel

    def _matches(self, globs: tuple[str, ...], file: FileName) -> bool:
        """gitignore's meaning: a pattern with a `/` is anchored at the configuration's
        directory, one without matches a name at any depth; `dir/` matches what is below it."""
        if not globs:
            return False
        rel = self.relative(file)
        name = rel if rel is not None else os.path.basename(os.fspath(file))
        suffixes = _suffixes(globs)
        if suffixes is not None and "\n" not in name and not name.startswith("/"):
            # the last part first: it ends with a suffix exactly when the name does (no suffix holds a `/`)
            return name.endswith(suffixes) or ("/" in name and any(
                part.endswith(suffixes) for part in name.split("/")[:-1]))
        from zero.engine.config_file import patterns  # start-up: only for patterns other than `*.suffix`

        return patterns(globs).match_file(name)

    def _own(self, key: str) -> bool:
        """Does this file decide ``key`` (set here, or nothing inherited)?"""
        return key in self.given or self.parent is None

    def excluded(self, file: FileName) -> bool:
        """``exclude`` (this file's, else the inherited one's), or any ``extend-exclude`` of the chain."""
        return self._excluded(file) or self._extend_excluded(file)

    def _excluded(self, file: FileName) -> bool:
        if not self._own("exclude") and self.parent is not None:
            return self.parent._excluded(file)
        return bool(self.exclude) and self._matches(self.exclude, file)

    def _extend_excluded(self, file: FileName) -> bool:
        return (bool(self.extend_exclude) and self._matches(self.extend_exclude, file)) or (
            self.parent is not None and self.parent._extend_excluded(file))

    def included(self, file: FileName) -> bool:
        if not self._own("include") and self.parent is not None:
            return self.parent.included(file)
        return self._matches(self.include, file)

    def encoding_for(self, file: FileName) -> str | None:
        """The codec the configuration declares for a list (the first pattern that matches), else
        ``None``: the list's encoding is detected."""
        if not self._own("encoding") and self.parent is not None:
            return self.parent.encoding_for(file)
        return next((codec for glob, codec in self.encoding if self._matches((glob,), file)), None)

    def kind_for(self, file: FileName) -> str | None:
        if not self._own("kind") and self.parent is not None:
            return self.parent.kind_for(file)
        return next((k for glob, k in self.kind if self._matches((glob,), file)), None)

    def ignored_for(self, file: FileName) -> tuple[str, ...]:
        """The codes the per-file ignores drop for one file (``per-file-ignores``, this file's or the
        inherited one's, and every ``extend-per-file-ignores`` of the chain)."""
        return (*self._ignored(file), *self._extended_ignores(file))

    def _ignored(self, file: FileName) -> list[str]:
        if not self._own("per-file-ignores") and self.parent is not None:
            return self.parent._ignored(file)
        return [c for glob, codes in self.per_file_ignores if self._matches((glob,), file) for c in codes]

    def _extended_ignores(self, file: FileName) -> list[str]:
        out = [c for glob, codes in self.extend_per_file_ignores if self._matches((glob,), file) for c in codes]
        return out + (self.parent._extended_ignores(file) if self.parent is not None else [])

    @property
    def layers(self) -> tuple[tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]], ...]:
        """The rule selection of the chain, the inherited configuration's first (see
        :func:`zero.engine.lint.layered_selection`)."""
        below = self.parent.layers if self.parent is not None else ()
        return (*below, (self.select, self.extend_select, self.ignore))

    def _no_file_patterns(self) -> bool:
        """Neither this configuration nor one it extends has a per-file ignore, kind or encoding pattern:
        the per-file answers are then none (``ignored_for`` empty, ``kind_for`` and ``encoding_for``
        ``None``) for every file."""
        cfg: Config | None = self
        while cfg is not None:
            if cfg.per_file_ignores or cfg.extend_per_file_ignores or cfg.kind or cfg.encoding:
                return False
            cfg = cfg.parent
        return True

    def options_for(self, file: FileName, cli: LintOptions) -> LintOptions:
        """The lint options for one file: the command line as the last layer over this configuration
        (and the one it extends), as ruff resolves them; the file's per-file ignores drop what they
        match whatever selected it."""
        if self._no_file_patterns():  # the common case: nothing below depends on the file's name
            ignored: tuple[str, ...] = ()
            kind, encoding = cli.kind or None, cli.encoding or None
        else:
            ignored = self.ignored_for(file)
            kind = cli.kind or self.kind_for(file)
            encoding = cli.encoding or self.encoding_for(file)
        # the files of a folder (of a project, without per-file patterns) share one object, made once:
        # what a file's options depend on beyond this configuration and the command line is in the key
        memo = (id(self), id(cli), ignored, kind, encoding)
        hit = _OPTIONS.get(memo)
        if hit is not None and hit[0] is self and hit[1] is cli:
            return hit[2]
        chosen = layered_selection((*self.layers, (cli.select, cli.extend_select, cli.ignore)), ignored)
        severity = {**self.parent.severity, **self.severity} if self.parent is not None else self.severity
        options = LintOptions(select=chosen.select, ignore=chosen.ignore, kind=kind,
                              severity={**severity, **cli.severity}, encoding=encoding,
                              kernel=cli.kernel or self.kernel, ignore_noqa=cli.ignore_noqa)
        if len(_OPTIONS) > 4096:
            _OPTIONS.clear()
        _OPTIONS[memo] = (self, cli, options)  # both kept with it: their identities are no other's
        return options

    def show(self) -> str:
        """The effective configuration as TOML (``zero config --show``), each option as it declares."""
        from zero.engine.config_file import OPTIONS  # start-up: only for `zero config --show`

        table = "[tool.zero]" if self.path is None or os.path.basename(self.path) == "pyproject.toml" else None
        prefix = "tool.zero." if table else ""
        source = f"# from {self.path}" if self.path else "# no configuration file: defaults"
        if self.parent is not None and self.parent.path is not None:
            source += f" over {self.parent.path} (the settings it does not set are that file's)"
        lines = [source, *([table] if table else [])]
        for option in OPTIONS:  # the keys first, then the tables: TOML's order
            if option.show is not None and not option.table:
                lines += option.show(self, prefix)
        for option in OPTIONS:
            if option.show is not None and option.table:
                lines += option.show(self, prefix)
        return "\n".join(lines) + "\n"


_TOML_AT = r"\s*\(at line (\d+), column (\d+)\)\s*$"  # compiled at its first use: a file tomllib refuses
# guard_toml refuses a key of more than MAX_NESTING (zero.structured.common: 64) dotted parts, which
# holds at least that many dots: a text of fewer is not asked (zero.structured.toml, json and the tree
# model stay unloaded: 23 M instructions of a lint with a configuration file)
_GUARDED_DOTS = 64


def parse_config(file: FileName, text: str | None = None, _chain: tuple[str, ...] = (),
                 over: Config | None = None) -> Config | None:
    """Read one configuration file; ``None`` for a pyproject.toml without ``[tool.zero]``. With
    ``extend = "other.toml"`` the other file is read first and this one is laid over it; ``over``
    lays ``text`` over a configuration already read (``--config KEY=VALUE``)."""
    import tomllib  # start-up: only when a configuration file exists

    path = path_str(file)
    if text is None:
        try:
            # a regular file only (a FIFO or device is refused), and no larger than a configuration is
            text = read_file(path, limit=MAX_CONFIG_BYTES).decode("utf-8")
        except ZeroError as exc:
            raise ZeroError(f"cannot read the configuration: {exc.message}", str(path)) from None
        except UnicodeDecodeError:
            raise ZeroError("the configuration is not UTF-8", str(path)) from None
    if text.count(".") >= _GUARDED_DOTS:
        from zero.structured.toml import guard_toml  # start-up: only for a text that could hold such a key

        guard_toml(text, str(path))
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        at = compiled(_TOML_AT).search(str(exc))  # tomllib says where only in its message
        if at is None:
            raise ZeroError(f"not valid TOML: {exc}", str(path)) from None
        raise ZeroError(f"not valid TOML: {str(exc)[:at.start()].rstrip()}", str(path),
                        int(at.group(1)), int(at.group(2))) from None
    except RecursionError:  # brackets nested without end
        raise ZeroError("not valid TOML: nested too deeply", str(path)) from None
    except ValueError:  # an integer beyond Python's conversion limit (TOMLDecodeError is one too: above)
        raise ZeroError("not valid TOML: a number too long to read", str(path)) from None
    from zero.engine.config_file import BY_KEY, _Reading  # start-up: only when a configuration file is read

    table: tuple[str, ...] = ()
    tool = data.get("tool", {})
    if os.path.basename(path) == "pyproject.toml":
        if not isinstance(tool, dict) or "zero" not in tool:
            return None
        data = tool["zero"]
        table = ("tool", "zero")
    elif set(data) == {"tool"} and isinstance(tool, dict) and set(tool) == {"zero"}:
        data = tool["zero"]  # a zero.toml written like pyproject.toml: the same settings
        table = ("tool", "zero")
    if not isinstance(data, dict):
        raise ZeroError("[tool.zero] must be a table", str(path))

    cfg = Config(path=path, given=frozenset(data))
    reading = _Reading(cfg, path, text, table)
    if over is not None:
        cfg = reading.cfg = _layered(over, over.path, cfg.given)
    elif "extend" in data:
        cfg = reading.cfg = _extended(cfg, data["extend"], path, _chain, reading.fail)
    for key, value in data.items():
        option = BY_KEY.get(key)
        if option is None:
            import difflib  # start-up: only for a configuration error

            near = difflib.get_close_matches(key.replace("_", "-"), BY_KEY, n=1, cutoff=0.7)  # as the CLI
            hint = f" (did you mean `{near[0]}`?)" if near else ""
            raise reading.fail(key, f"unknown key{hint}; known: {', '.join(BY_KEY)}")
        option.read(reading, value)
    return cfg


def _extended(cfg: Config, value: Any, path: str, chain: tuple[str, ...],
              fail: Callable[..., ZeroError]) -> Config:
    """``extend = "../zero.toml"``: the inherited configuration under ``cfg`` (its settings where this
    file sets none; its rule selection a layer below this file's), as ruff's ``extend``."""
    if not isinstance(value, str) or not value:
        raise fail("extend", "expected the path of another configuration file (zero.toml or pyproject.toml)")
    target = path_str(os.path.expanduser(os.path.expandvars(value)))
    target = target if os.path.isabs(target) else path_str(os.path.join(os.path.dirname(path), target))
    here = os.path.abspath(path)
    if os.path.abspath(target) in (*chain, here) or len(chain) >= MAX_EXTEND_DEPTH:
        raise fail("extend", f"{value!r} extends in a circle (or more than {MAX_EXTEND_DEPTH} deep)")
    try:
        parent = parse_config(target, None, (*chain, here))
    except ZeroError as exc:
        raise fail("extend", f"{value!r}: {exc}") from None
    if parent is None:
        raise fail("extend", f"{value!r} has no [tool.zero] table")
    return _layered(parent, path, cfg.given)


def _layered(parent: Config, path: str | None, given: frozenset[str]) -> Config:
    """A configuration over ``parent``: its settings until the keys in ``given`` replace them, its
    rule selection and its extending keys (``extend-*``) a layer of their own."""
    return replace(parent, path=path, given=given, parent=parent, select=(), extend_select=(), ignore=(),
                   severity={}, extend_exclude=(), extend_per_file_ignores=())


def inline_config(text: str, over: Config) -> Config:
    """``--config 'select = ["R005"]'`` (as ruff's): one ``KEY = VALUE`` of the configuration, in
    TOML, laid over the configuration that applies (it takes precedence over every file); patterns
    and paths relative to the current directory where nothing else applies."""
    if text.split("=", 1)[0].strip().strip("\"'") in ("extend", "tool.zero.extend"):
        raise ZeroError(f"--config {text!r}: `extend` names a file; use --config FILE")
    cfg = parse_config("--config", text, over=over)
    assert cfg is not None  # only a pyproject.toml may hold no [tool.zero]
    return cfg


def is_inline(value: str) -> bool:
    """Is a ``--config`` value one ``KEY = VALUE`` rather than a file (as ruff tells them)?"""
    return "=" in value and not os.path.lexists(value)


class ConfigFinder:
    """Finds (and caches) the configuration that applies to each file."""

    def __init__(self, explicit: FileName | None = None, isolated: bool = False,
                 overrides: tuple[str, ...] = ()) -> None:
        self.isolated = isolated
        self.overrides = overrides  # `--config KEY=VALUE`, in order: over whatever configuration applies
        self._overlaid: dict[int, tuple[Config, Config]] = {}
        self.explicit: Config | None = None
        if explicit is not None and not isolated:
            cfg = parse_config(explicit)
            if cfg is None:
                raise ZeroError("has no [tool.zero] table", str(explicit))
            self.explicit = cfg
        self._by_dir: dict[str, Config] = {}  # a folder resolved → the configuration that applies in it
        self._by_name: dict[str, Config] = {}  # the absolute directory → its configuration
        self._by_path: dict[tuple[object, ...], Config] = {}  # a path's text (and the directory if relative)
        # a file's folder as its name writes it (the text to its last separator) and the current directory → the
        # configuration: a file's is its folder's, and a walk names the files of a folder alike
        self._by_folder: dict[tuple[str, str], Config] = {}
        self._default = Config()
        if overrides:
            self._overlay(self._default)  # a bad override is an error before any file is read

    def _overlay(self, cfg: Config) -> Config:
        """``cfg`` with the command line's ``--config KEY=VALUE`` over it (each a layer of its own)."""
        if not self.overrides:
            return cfg
        hit = self._overlaid.get(id(cfg))
        if hit is None:
            out = cfg
            for text in self.overrides:
                out = inline_config(text, out)
            hit = self._overlaid[id(cfg)] = (cfg, out)  # the original kept: its id stays unique
        return hit[1]

    def for_path(self, path: FileName, directory: bool | None = None) -> Config:
        """The configuration of a file (found from its directory up) or of a directory (found from
        the directory itself up). ``directory`` says which ``path`` is; ``None`` asks the file system.
        Cached by the absolute directory the search starts from (links not resolved, which costs
        nothing per file): a file and a folder share an entry only when they mean one directory."""
        if self.isolated:
            return self._overlay(self._default)
        if self.explicit is not None:
            return self._overlay(self.explicit)
        name = os.fspath(path)  # a Path's text is made once; hashing the text is cheaper than the Path
        if directory is None:
            directory = os.path.isdir(name)
        if not directory and os.altsep is None:
            # os.path.dirname of a name depends only on its text to the last separator: a folder's files share
            # one look-up, without dirname and abspath per file (a third of collecting a fleet's 6,300 files)
            slot = (name[:name.rfind(os.sep) + 1], _cwd())
            hit = self._by_folder.get(slot)
            if hit is None:
                if len(self._by_folder) > 65536:
                    self._by_folder.clear()
                hit = self._by_folder[slot] = self._for_path(name, False)
            return hit
        return self._for_path(name, directory)

    def _for_path(self, name: str, directory: bool) -> Config:
        """:meth:`for_path` of a path's text, told whether it is a directory."""
        given = (name, directory) if os.path.isabs(name) else (name, directory, _cwd())
        hit = self._by_path.get(given)  # the files of a run are asked about several times each
        if hit is not None:
            return hit
        key = os.path.abspath(name if directory else os.path.dirname(name) or ".")
        hit = self._by_name.get(key)
        if hit is None:
            start = _resolved_folder(name if directory else os.path.dirname(name) or ".")
            hit = self._by_name[key] = self._overlay(self._lookup(start))
        if len(self._by_path) > 65536:
            self._by_path.clear()
        self._by_path[given] = hit
        return hit

    def _lookup(self, start: str) -> Config:
        """The configuration nearest ``start`` (a folder resolved: absolute, normalised), from it up."""
        walked: list[str] = []
        d: str | None = start
        found = self._default
        while d is not None:
            hit = self._by_dir.get(d)
            if hit is not None:
                found = hit
                break
            walked.append(d)
            cfg = next((c for c in (parse_config(os.path.join(d, n)) for n in CONFIG_NAMES
                                    if os.path.lexists(os.path.join(d, n))) if c is not None), None)
            if cfg is not None:
                found = cfg
                break
            parent = os.path.dirname(d)
            d = parent if parent != d else None
        for w in walked:
            self._by_dir[w] = found
        return found

"""Project configuration: ``[tool.zero]`` in ``pyproject.toml``, or ``zero.toml`` / ``.zero.toml``.

The file closest to a linted file wins (no merging), found by walking up from the
file's directory; ``--config PATH`` names one for every file and ``--isolated``
ignores them all. Globs are relative to the configuration file's directory
(``**/`` for any depth). Unknown keys and bad values are errors naming the file,
line and key.

Every option is declared once, in :data:`OPTIONS` (key, type, default, description, example,
section, how it is read and checked, how ``zero config --show`` prints it); the parser, ``--show``,
the reference of docs/configuration.md and ``zero.schema.json`` are made from it
(``tools/gen_config.py`` writes the last two, ``tests/test_declarations.py`` holds them to it).
"""

from __future__ import annotations

import contextlib
import functools
import os
import re
from collections.abc import Callable, Iterator
from pathlib import Path

from zero.diagnostics import Severity
from zero.engine.results import LintOptions
from zero.engine.selection import known_code, layered_selection, rule_table
from zero.errors import ZeroError
from zero.files import nearest_holding, read_file, within
from zero.forms import CONFIG_NAMES, DEFAULT_INCLUDE, controller_absolute
from zero.lists.model import parse_key
from zero.records import field, record, replace

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

    from pathspec import GitIgnoreSpec

MAX_PATTERN_WILDCARDS = 3  # `*` runs in one segment of a glob pattern, and `**` segments
MAX_PATTERN_LENGTH = 512
MAX_CONFIG_BYTES = 1 << 20  # a configuration larger than 1 MiB is no configuration
MAX_EXTEND_DEPTH = 8  # `extend` chains longer than this are a loop or a mistake


@functools.lru_cache(maxsize=512)
def patterns(globs: tuple[str, ...]) -> GitIgnoreSpec:
    """Patterns with gitignore's meaning (``old/``, ``/old/**``, ``**/nullp*.lis``, ``[n]*``),
    relative to the configuration's directory (a leading ``./`` is allowed); :class:`ZeroError`
    for a pattern that cannot be read."""
    lines = []
    for g in globs:
        text = g[2:] if g.startswith("./") else g
        if text.count("[") > text.count("]"):
            raise ZeroError(f"pattern {g!r}: `[` is not closed")
        segments = text.split("/")
        stars = max((len(re.findall(r"\*+", s)) for s in segments if s != "**"), default=0)
        deep = sum(1 for s in segments if s == "**")
        if len(text) > MAX_PATTERN_LENGTH or stars > MAX_PATTERN_WILDCARDS or deep > MAX_PATTERN_WILDCARDS:
            # pathspec matches with a backtracking regular expression: the time a name takes grows as
            # its length to the power of the wildcards in one segment (100: 12 s per file, 8: 20 s on
            # a 60-character name); 3 keep the worst name of 255 characters below 30 ms
            raise ZeroError(f"pattern {g[:40]!r}{'…' if len(g) > 40 else ''}: too complex (at most "
                            f"{MAX_PATTERN_WILDCARDS} `*` in one path segment, {MAX_PATTERN_WILDCARDS} `**` "
                            f"and {MAX_PATTERN_LENGTH} characters)")
        lines.append(text)
    import pathspec  # start-up: only where a pattern is matched (not for files named with the defaults)

    try:
        return pathspec.GitIgnoreSpec.from_lines(lines)
    except (ValueError, TypeError) as exc:
        raise ZeroError(f"a pattern cannot be read: {exc}") from None


def _is_reference(key: str) -> bool:
    """A start-up key that names a list (``achs_mds[0]``, ``hand_mds``)."""
    from zero.machine.model import BY_KEY  # start-up: only a configuration that names lists

    parsed = parse_key(key)
    ref = BY_KEY.get(parsed.pattern) if parsed is not None else None
    return ref is not None and len(parsed.indices) == ref.key.count("[]")  # type: ignore[union-attr]


def project_root(folder: Path) -> Path:
    """The project a configuration belongs to: the git work tree that holds its folder, else the folder."""
    return nearest_holding(folder, (".git",)) or Path(os.path.abspath(folder))


def _resolved(file: Path) -> Path:
    """The absolute path of a file under its own name: its directory resolved, the name kept (a
    link named `m.lis` is matched as `m.lis`, whatever it points to)."""
    return file.parent.resolve() / file.name


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


def _resolved_folder(folder: str | Path) -> str:
    """``str(Path(folder).resolve())``, once per folder within :func:`one_resolution`."""
    name = os.fspath(folder)
    if not _RESOLVED:
        return str(Path(name).resolve())
    memo = _RESOLVED[-1]
    hit = memo.get(name)
    if hit is None:
        hit = memo[name] = str(Path(name).resolve())
    return hit


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


@record
class Config:
    path: Path | None = None  # the file it came from; None: defaults
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
        return self.path.parent if self.path is not None else Path.cwd()

    def relative(self, file: Path) -> str | None:
        if os.sep != "/" or os.altsep is not None:  # pragma: no cover - Windows: its paths' own rules
            try:
                return _resolved(file).relative_to(self.root.resolve()).as_posix()
            except ValueError:
                return None
        parent, name = os.path.split(os.fspath(file))  # a Path's text: file.parent and file.name
        own = os.fspath(self.path) if self.path is not None else None
        memo = _RESOLVED[-1] if _RESOLVED else {}
        key = f"\0rel\0{own}\0{parent}"  # the files of a folder: its place below the configuration's, once
        rel = memo.get(key)
        if rel is None:
            folder = _resolved_folder(parent or ".")
            root = _resolved_folder((os.path.dirname(own) or ".") if own is not None else _cwd())
            head = root if root.endswith("/") else root + "/"
            rel = memo[key] = "" if folder == root else folder[len(head):] if folder.startswith(head) else "\0"
        if not rel:
            return name if name else "."
        if rel == "\0":  # outside it
            return None
        return rel + "/" + name if name else rel

    def _matches(self, globs: tuple[str, ...], file: Path) -> bool:
        """gitignore's meaning: a pattern with a `/` is anchored at the configuration's
        directory, one without matches a name at any depth; `dir/` matches what is below it."""
        if not globs:
            return False
        rel = self.relative(file)
        name = rel if rel is not None else file.name
        suffixes = _suffixes(globs)
        if suffixes is not None and "\n" not in name and not name.startswith("/"):
            return any(part.endswith(suffixes) for part in name.split("/"))
        return patterns(globs).match_file(name)

    def _own(self, key: str) -> bool:
        """Does this file decide ``key`` (set here, or nothing inherited)?"""
        return key in self.given or self.parent is None

    def excluded(self, file: Path) -> bool:
        """``exclude`` (this file's, else the inherited one's), or any ``extend-exclude`` of the chain."""
        return self._excluded(file) or self._extend_excluded(file)

    def _excluded(self, file: Path) -> bool:
        if not self._own("exclude") and self.parent is not None:
            return self.parent._excluded(file)
        return bool(self.exclude) and self._matches(self.exclude, file)

    def _extend_excluded(self, file: Path) -> bool:
        return (bool(self.extend_exclude) and self._matches(self.extend_exclude, file)) or (
            self.parent is not None and self.parent._extend_excluded(file))

    def included(self, file: Path) -> bool:
        if not self._own("include") and self.parent is not None:
            return self.parent.included(file)
        return self._matches(self.include, file)

    def encoding_for(self, file: Path) -> str | None:
        """The codec the configuration declares for a list (the first pattern that matches), else
        ``None``: the list's encoding is detected."""
        if not self._own("encoding") and self.parent is not None:
            return self.parent.encoding_for(file)
        return next((codec for glob, codec in self.encoding if self._matches((glob,), file)), None)

    def kind_for(self, file: Path) -> str | None:
        if not self._own("kind") and self.parent is not None:
            return self.parent.kind_for(file)
        return next((k for glob, k in self.kind if self._matches((glob,), file)), None)

    def ignored_for(self, file: Path) -> tuple[str, ...]:
        """The codes the per-file ignores drop for one file (``per-file-ignores``, this file's or the
        inherited one's, and every ``extend-per-file-ignores`` of the chain)."""
        return (*self._ignored(file), *self._extended_ignores(file))

    def _ignored(self, file: Path) -> list[str]:
        if not self._own("per-file-ignores") and self.parent is not None:
            return self.parent._ignored(file)
        return [c for glob, codes in self.per_file_ignores if self._matches((glob,), file) for c in codes]

    def _extended_ignores(self, file: Path) -> list[str]:
        out = [c for glob, codes in self.extend_per_file_ignores if self._matches((glob,), file) for c in codes]
        return out + (self.parent._extended_ignores(file) if self.parent is not None else [])

    @property
    def layers(self) -> tuple[tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]], ...]:
        """The rule selection of the chain, the inherited configuration's first (see
        :func:`zero.engine.lint.layered_selection`)."""
        below = self.parent.layers if self.parent is not None else ()
        return (*below, (self.select, self.extend_select, self.ignore))

    def options_for(self, file: Path, cli: LintOptions) -> LintOptions:
        """The lint options for one file: the command line as the last layer over this configuration
        (and the one it extends), as ruff resolves them; the file's per-file ignores drop what they
        match whatever selected it."""
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
        table = "[tool.zero]" if self.path is None or self.path.name == "pyproject.toml" else None
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


def _roots(value: Any, path: Path, root: Path,
           fail: Callable[[str | None, str, tuple[str, ...]], ZeroError]) -> tuple[tuple[str, Path], ...]:
    """``roots = {"C:/TwinCAT/3.1/Components/Mc/CNC" = "."}``: an absolute folder of the controller
    and the folder of the project that holds what lies below it (inside the project)."""
    if not isinstance(value, dict) or not all(isinstance(k, str) and k and isinstance(v, str) and v
                                              for k, v in value.items()):
        raise fail("roots", 'expected a table of "controller folder" = "project folder"', ("machine",))
    out = []
    for k, v in value.items():
        if not controller_absolute(k.rstrip("/\\") + "/"):
            raise fail("roots", f"{k!r} is no absolute path of the controller (`C:/…`, `/…` or `CncKernelRootDir/…`)",
                       ("machine",))
        if not within(path.parent / v, root):
            raise fail("roots", f"{v!r} lies outside the project {root}", ("machine",))
        out.append((k, path.parent / v))
    return tuple(out)


# ------------------------------------------------------------------------------------------------
# The options, each declared once: its key, type, default, description, example, section, how it is
# read (validation) and how `zero config --show` prints it. The parser, `zero config --show`, the
# reference section of docs/configuration.md and zero.schema.json (the JSON Schema of zero.toml and
# [tool.zero]) are all made from OPTIONS; tests/test_declarations.py holds the page and the schema to it.


@record(frozen=True)
class ConfigOption:
    """One key of the configuration (as ruff's ``#[option(default, value_type, example)]``)."""

    key: str
    section: str  # where the reference lists it: "rules", "files", "machine" or "general"
    type: str  # the value in words (the reference's "Type")
    default: Any  # the default as JSON (None: none; the reference says `default_text`)
    description: str  # what it does: one paragraph of Markdown
    example: str  # TOML, the lines below the option's table header ([tool.zero] or [tool.zero.KEY])
    schema: dict[str, Any]  # the JSON Schema of the value (description, default and example are added)
    read: Callable[[_Reading, Any], None]  # validate the value and set it on the configuration
    show: Callable[[Config, str], list[str]] | None = None  # the lines of `zero config --show` (prefix given)
    table: bool = False  # written as a table of its own: [tool.zero.KEY]
    default_text: str = ""  # the default in words, where the value alone does not say it


class _Reading:
    """One configuration file being read: the configuration it fills, and its located errors."""

    __slots__ = ("cfg", "path", "table", "text")

    def __init__(self, cfg: Config, path: Path, text: str, table: tuple[str, ...]) -> None:
        self.cfg, self.path, self.text, self.table = cfg, path, text, table

    def fail(self, key: str | None, message: str, sub: tuple[str, ...] = ()) -> ZeroError:
        """An error naming the file, the line of ``key`` and the key in full (``tool.zero.kind.*.lis``)."""
        line = _line_of(self.text or "", (*self.table, *sub), key)
        name = ".".join((*self.table, *sub, key) if key else (*self.table, *sub)) or "(top level)"
        return ZeroError(f"{name}: {message}", str(self.path), line)

    def codes(self, key: str, value: Any, sub: tuple[str, ...] = ()) -> tuple[str, ...]:
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise self.fail(key, "expected a list of rule codes, e.g. [\"R005\", \"M\"]", sub)
        out = tuple(v.strip().upper() for v in value)
        for c in out:
            if not known_code(c):
                raise self.fail(key, f"{c!r} matches no rule code (see `zero rule`)", sub)
        return out

    def globs(self, key: str, value: Any, sub: tuple[str, ...] = ()) -> tuple[str, ...]:
        if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
            raise self.fail(key, "expected a list of glob patterns, e.g. [\"old/**\"]", sub)
        try:
            patterns(tuple(value))
        except ZeroError as exc:
            raise self.fail(key, exc.message, sub) from None
        return tuple(value)

    def table_of(self, key: str, value: Any, expected: str) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(key, f"expected a table of {expected}")
        return value

    def code_table(self, key: str, value: Any) -> tuple[tuple[str, tuple[str, ...]], ...]:
        """``"glob" = ["CODE", ...]``: every pattern readable, every code matching a rule."""
        table = self.table_of(key, value, "glob = [codes]")
        for g in table:
            self.globs(g, [g], (key,))
        return tuple((g, self.codes(g, v, (key,))) for g, v in table.items())


def _toml_list(xs: tuple[str, ...]) -> str:
    return "[" + ", ".join(f'"{x}"' for x in xs) + "]"


def _shown_list(name: str, attr: str) -> Callable[[Config, str], list[str]]:
    return lambda c, _prefix: [f"{name} = {_toml_list(getattr(c, attr))}"]


def _read_extend(r: _Reading, value: Any) -> None:
    """Read before every other key (by :func:`parse_config`): nothing to do in order."""


def _read_select(r: _Reading, value: Any) -> None:
    r.cfg.select = r.codes("select", value)


def _read_extend_select(r: _Reading, value: Any) -> None:
    r.cfg.extend_select = r.codes("extend-select", value)


def _read_ignore(r: _Reading, value: Any) -> None:
    r.cfg.ignore = (*r.codes("ignore", value), *r.cfg.ignore)


def _read_extend_ignore(r: _Reading, value: Any) -> None:  # ruff's older spelling: added to this file's `ignore`
    r.cfg.ignore = (*r.cfg.ignore, *r.codes("extend-ignore", value))


def _read_include(r: _Reading, value: Any) -> None:
    r.cfg.include = r.globs("include", value)


def _read_exclude(r: _Reading, value: Any) -> None:
    r.cfg.exclude = r.globs("exclude", value)


def _read_extend_exclude(r: _Reading, value: Any) -> None:
    r.cfg.extend_exclude = r.globs("extend-exclude", value)


def _read_respect_gitignore(r: _Reading, value: Any) -> None:
    if not isinstance(value, bool):
        raise r.fail("respect-gitignore", "expected true or false")
    r.cfg.respect_gitignore = value


def _read_param_desc(r: _Reading, value: Any) -> None:
    if not isinstance(value, str) or not value:
        raise r.fail("param-desc", "expected the path of a CncParaDesc.xml")
    r.cfg.param_desc = r.path.parent / value


def _read_kernel(r: _Reading, value: Any) -> None:
    from zero.catalog.releases import parse_release  # start-up: only when a release is set

    if not isinstance(value, str):
        raise r.fail("kernel", 'expected the kernel release the machines run, e.g. "V3.1.3074"')
    try:
        parse_release(value)
    except ZeroError as exc:
        raise r.fail("kernel", exc.message) from None
    r.cfg.kernel = value


def _read_machine(r: _Reading, value: Any) -> None:
    if not isinstance(value, dict):
        raise r.fail("machine", "expected a table: startup = \"listen/hochlauf.lis\" and list overrides")
    path, cfg = r.path, r.cfg
    root = project_root(path.parent)
    for mk, mv in value.items():
        if mk == "roots":
            cfg.machine_roots = _roots(mv, path, root, r.fail)
            continue
        if not isinstance(mv, str) or not mv:
            raise r.fail(mk, "expected a path", ("machine",))
        if not within(path.parent / mv, root):
            raise r.fail(mk, f"{mv!r} lies outside the project {root}: a configuration names only the "
                         "project's own files (give a path inside it, or --machine on the command line)",
                         ("machine",))
        if mk == "startup":
            cfg.machine = path.parent / mv
        elif mk == "working-directory":
            cfg.machine_workdir = path.parent / mv
        elif _is_reference(mk):
            cfg.machine_lists[mk] = path.parent / mv
        else:
            raise r.fail(mk, "expected `startup`, `working-directory`, `roots` or a key of the start-up list "
                         "that names a list, such as `achs_mds[0]` or `hand_mds`", ("machine",))


def _read_per_file_ignores(r: _Reading, value: Any) -> None:
    r.cfg.per_file_ignores = r.code_table("per-file-ignores", value)


def _read_extend_per_file_ignores(r: _Reading, value: Any) -> None:
    r.cfg.extend_per_file_ignores = r.code_table("extend-per-file-ignores", value)


def _read_severity(r: _Reading, value: Any) -> None:
    table = r.table_of("severity", value, "CODE = \"error\" | \"warning\" | \"info\"")
    given: dict[str, Severity] = {}
    for code, sev in table.items():
        prefix = code.strip().upper()
        if not any(c.startswith(prefix) for c in rule_table()):
            raise r.fail(code, f"{code!r} matches no rule code (see `zero rule`)", ("severity",))
        try:
            given[prefix] = Severity.parse(sev if isinstance(sev, str) else "")
        except ValueError:
            raise r.fail(code, f"{sev!r} is not a severity (error, warning or info)", ("severity",)) from None
    for c in rule_table():  # a prefix sets every code it matches; the longest prefix wins
        best = max((p for p in given if c.startswith(p)), key=len, default=None)
        if best is not None:
            r.cfg.severity[c] = given[best]


def _read_kind(r: _Reading, value: Any) -> None:
    pairs = []
    for glob, name in r.table_of("kind", value, "glob = kind").items():
        r.globs(glob, [glob], ("kind",))
        from zero.catalog.registry import kind_from_name  # start-up: only a configuration that names kinds

        k = kind_from_name(name) if isinstance(name, str) else None
        if k is None:
            raise r.fail(glob, f"{name!r} is not a list kind (zero, axis, channel, ...)", ("kind",))
        pairs.append((glob, k))
    r.cfg.kind = tuple(pairs)


def _read_encoding(r: _Reading, value: Any) -> None:
    from zero.lists.encoding import declarable  # start-up: only a configuration that names a codec

    declared = []
    for glob, name in r.table_of("encoding", value, 'glob = codec, e.g. {"old/**/*.lis" = "cp850"}').items():
        r.globs(glob, [glob], ("encoding",))
        try:
            codec = declarable(name) if isinstance(name, str) else None
        except ValueError as exc:
            raise r.fail(glob, str(exc), ("encoding",)) from None
        if codec is None:
            raise r.fail(glob, f"{name!r} is not the name of a codec (e.g. \"cp850\")", ("encoding",))
        declared.append((glob, codec))
    r.cfg.encoding = tuple(declared)


def _show_machine(c: Config, prefix: str) -> list[str]:
    if not (c.machine or c.machine_lists or c.machine_workdir or c.machine_roots):
        return []
    lines = [f"[{prefix}machine]"]
    if c.machine:
        lines.append(f'startup = "{c.machine}"')
    if c.machine_workdir:
        lines.append(f'working-directory = "{c.machine_workdir}"')
    if c.machine_roots:
        lines.append("roots = { " + ", ".join(f'"{k}" = "{v}"' for k, v in c.machine_roots) + " }")
    return lines + [f'"{k}" = "{v}"' for k, v in c.machine_lists.items()]


def _show_code_table(name: str, attr: str, always: bool) -> Callable[[Config, str], list[str]]:
    def show(c: Config, prefix: str) -> list[str]:
        pairs = getattr(c, attr)
        if not pairs and not always:
            return []
        return [f"[{prefix}{name}]", *(f'"{g}" = {_toml_list(codes)}' for g, codes in pairs)]
    return show


def _show_severity(c: Config, prefix: str) -> list[str]:
    return [f"[{prefix}severity]", *(f'{code} = "{s.label}"' for code, s in sorted(c.severity.items()))]


def _show_kind(c: Config, prefix: str) -> list[str]:
    return [f"[{prefix}kind]", *(f'"{g}" = "{k}"' for g, k in c.kind)]


def _show_encoding(c: Config, prefix: str) -> list[str]:
    return [f"[{prefix}encoding]", *(f'"{g}" = "{codec}"' for g, codec in c.encoding)] if c.encoding else []


_CODE = {"type": "string", "pattern": r"^\s*([A-Za-z]+[0-9]*)\s*$"}  # a code or prefix; `ALL`: every rule
_CODES = {"type": "array", "items": _CODE}
_GLOBS = {"type": "array", "items": {"type": "string", "minLength": 1}}
_CODE_TABLE = {"type": "object", "additionalProperties": _CODES}
_PATH = {"type": "string", "minLength": 1}
# `zero` or `ZERO`: the catalogue's kinds, filled in by config_schema() (a run imports the catalogue only to lint)
_KIND_NAMES: list[str] = []

OPTIONS: tuple[ConfigOption, ...] = (
    ConfigOption(
        "extend", "general", "path of a configuration file", None,
        "Another configuration file (zero.toml or pyproject.toml) this one inherits: its settings apply "
        "where this file sets none, its patterns stay relative to its own folder, and its rule selection "
        "is the layer below this file's (as ruff's `extend`).",
        'extend = "../zero.toml"', _PATH, _read_extend, default_text="none"),
    ConfigOption(
        "select", "rules", "list of rule codes or prefixes", [],
        "The rules to run, by code or prefix (`R005`, `R`, `ALL`). A layer with `select` starts anew; the "
        "command line's `--select` is the last layer.",
        'select = ["S", "R", "M"]', _CODES, _read_select, _shown_list("select", "select"),
        default_text="every rule but the opt-in ones"),
    ConfigOption(
        "extend-select", "rules", "list of rule codes or prefixes", [],
        "Codes or prefixes added to the selection; an opt-in rule (S012) only by its full code.",
        'extend-select = ["Z", "S012"]', _CODES, _read_extend_select, _shown_list("extend-select", "extend_select")),
    ConfigOption(
        "ignore", "rules", "list of rule codes or prefixes", [],
        "Codes or prefixes removed from the selection; at equal length `ignore` wins over a selection.",
        'ignore = ["M003"]', _CODES, _read_ignore, _shown_list("ignore", "ignore")),
    ConfigOption(
        "extend-ignore", "rules", "list of rule codes or prefixes", [],
        "ruff's older spelling of `ignore`: added to this file's `ignore`.",
        'extend-ignore = ["R007"]', _CODES, _read_extend_ignore),
    ConfigOption(
        "include", "files", "list of patterns", list(DEFAULT_INCLUDE),
        "What a directory walk picks up (XML files only where they hold lists). Patterns mean what "
        "they mean in a `.gitignore`, relative to the configuration's folder.",
        'include = ["*.lis", "*.lst", "*.nc", "*.xml"]', _GLOBS, _read_include, _shown_list("include", "include")),
    ConfigOption(
        "exclude", "files", "list of patterns", [],
        "Files never linted, even when named on the command line (as pre-commit names them; "
        "`--no-force-exclude` lints a named file anyway).",
        'exclude = ["old/**"]', _GLOBS, _read_exclude, _shown_list("exclude", "exclude")),
    ConfigOption(
        "extend-exclude", "files", "list of patterns", [],
        "Patterns added to `exclude` (also to an inherited one).",
        'extend-exclude = ["tmp/"]', _GLOBS, _read_extend_exclude, _shown_list("extend-exclude", "extend_exclude")),
    ConfigOption(
        "respect-gitignore", "files", "boolean", True,
        "A directory walk skips what `.gitignore` ignores; `false` walks into it.",
        "respect-gitignore = true", {"type": "boolean"}, _read_respect_gitignore,
        lambda c, _p: [f"respect-gitignore = {'true' if c.respect_gitignore else 'false'}"]),
    ConfigOption(
        "param-desc", "machine", "path of a CncParaDesc.xml", None,
        "The catalogue to check against (the vendor's CncParaDesc.xml), relative to the configuration's "
        "folder; `--param-desc` and `ZERO_PARAM_DESC` win over it.",
        'param-desc = "vendor/CncParaDesc.xml"', _PATH, _read_param_desc,
        lambda c, _p: [f'param-desc = "{c.param_desc}"'] if c.param_desc else [],
        default_text="the built-in catalogue"),
    ConfigOption(
        "kernel", "machine", "kernel release", None,
        "The kernel release the machines run, where older than the catalogue's (V4.13), as ruff's "
        "`target-version`: a key this catalogue lacks is then R013 instead of R001.",
        'kernel = "V3.1.3074"', {"type": "string", "minLength": 1}, _read_kernel,
        lambda c, _p: [f'kernel = "{c.kernel}"'] if c.kernel else [], default_text="the catalogue's"),
    ConfigOption(
        "machine", "machine", "table", None,
        "The machine NC programs and `zero limits` refer to: `startup` (the start-up list), "
        "`working-directory` (where the controller resolves `./listen/…`), `roots` (a folder of the "
        "controller → the project's folder that holds it) and a start-up key that names a list "
        "(`\"achs_mds[0]\"`) to replace that list. Every path lies inside the project.",
        'startup = "listen/hochlauf.lis"\n"achs_mds[0]" = "listen/achse_x_neu.lis"\nworking-directory = "."\n'
        'roots = { "C:/TwinCAT/3.1/Components/Mc/CNC" = "." }',
        {"type": "object", "properties": {"startup": _PATH, "working-directory": _PATH,
                                          "roots": {"type": "object", "additionalProperties": _PATH}},
         "additionalProperties": _PATH},
        _read_machine, _show_machine, table=True, default_text="none"),
    ConfigOption(
        "per-file-ignores", "rules", "table of pattern → codes", {},
        "Codes dropped for the files a pattern matches, whatever selected them.",
        '"machines/**/nullp*.lis" = ["M003"]', _CODE_TABLE, _read_per_file_ignores,
        _show_code_table("per-file-ignores", "per_file_ignores", always=True), table=True),
    ConfigOption(
        "extend-per-file-ignores", "rules", "table of pattern → codes", {},
        "Per-file ignores added to `per-file-ignores` (also to an inherited one).",
        '"machines/old/**" = ["R"]', _CODE_TABLE, _read_extend_per_file_ignores,
        _show_code_table("extend-per-file-ignores", "extend_per_file_ignores", always=False), table=True),
    ConfigOption(
        "severity", "rules", "table of code → severity", {},
        "A rule's severity in this project (`error`, `warning` or `info`), by code or prefix (the longest "
        "wins); by default each finding's evidence decides (see evidence.md).",
        'R007 = "error"', {"type": "object", "additionalProperties": {"enum": ["error", "warning", "info"]}},
        _read_severity, _show_severity, table=True),
    ConfigOption(
        "kind", "files", "table of pattern → list kind", {},
        "The list kind by pattern instead of detecting it (the first pattern that matches).",
        '"**/nullp*.lis" = "zero"', {"type": "object", "additionalProperties": {"enum": _KIND_NAMES}},
        _read_kind, _show_kind, table=True),
    ConfigOption(
        "encoding", "files", "table of pattern → codec", {},
        "A list's code page by pattern instead of detecting it (the first pattern that matches): UTF-8 or "
        "a single-byte code page that reads ASCII as ASCII (cp850, cp437, cp1252, latin-1, iso8859-15 …).",
        '"machines/old/**/*.lis" = "cp850"', {"type": "object", "additionalProperties": {"type": "string",
                                                                                       "minLength": 1}},
        _read_encoding, _show_encoding, table=True),
)
BY_KEY: dict[str, ConfigOption] = {o.key: o for o in OPTIONS}
SECTIONS = {"rules": "Which rules run", "files": "Which files, and how they are read",
            "machine": "The catalogue and the machine", "general": "Inheriting another file"}


def config_schema() -> dict[str, Any]:
    """The JSON Schema of ``zero.toml`` and of ``[tool.zero]`` (``zero.schema.json``), from :data:`OPTIONS`."""
    if not _KIND_NAMES:
        from zero.catalog.registry import KINDS  # start-up: only for the schema

        _KIND_NAMES.extend([*(name for name, _ in KINDS.values()), *KINDS])
    import tomllib  # start-up: only for the schema

    props = {}
    for o in OPTIONS:
        example = tomllib.loads(o.example if not o.table else f"[{o.key}]\n{o.example}")[o.key]
        prop = {"description": o.description, **o.schema, "examples": [example]}
        if o.default is not None:
            prop["default"] = o.default
        props[o.key] = prop
    settings = {"type": "object", "properties": props, "additionalProperties": False}
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "zero configuration (zero.toml, .zero.toml, [tool.zero] in pyproject.toml)",
        "$defs": {"zero": settings},
        "anyOf": [{"$ref": "#/$defs/zero"},
                  {"type": "object", "required": ["tool"], "additionalProperties": False,
                   "properties": {"tool": {"type": "object", "required": ["zero"], "additionalProperties": False,
                                           "properties": {"zero": {"$ref": "#/$defs/zero"}}}}}],
    }


def config_schema_text() -> str:
    """:func:`config_schema` as ``zero.schema.json`` holds it (``zero config --schema`` prints it)."""
    import json  # start-up: only for the schema

    return json.dumps(config_schema(), indent=2, ensure_ascii=False) + "\n"


def _default_text(o: ConfigOption) -> str:
    if o.default_text:
        return o.default_text
    if o.default == {} or o.default == []:
        return "none"
    return "`" + (_toml_list(tuple(o.default)) if isinstance(o.default, list) else
                  str(o.default).lower() if isinstance(o.default, bool) else str(o.default)) + "`"


def options_example() -> str:
    """Every option's example in one ``[tool.zero]`` (the keys first, then the tables)."""
    lines = ["[tool.zero]", *(o.example for o in OPTIONS if not o.table and o.key != "extend")]
    for o in (o for o in OPTIONS if o.table):
        lines += ["", f"[tool.zero.{o.key}]", o.example]
    return "\n".join(lines)


# The module's documentation ends with every option's example, made from OPTIONS as the docs page's is.
__doc__ = f"{__doc__}\n```toml\n{options_example()}\n```\n"


def options_reference() -> str:
    """The reference section of docs/configuration.md: every option at once, then each by section."""
    out = ["```toml", options_example(), "```", ""]
    for section, title in SECTIONS.items():
        out += [f"### {title}", ""]
        for o in (o for o in OPTIONS if o.section == section):
            header = f"[tool.zero.{o.key}]" if o.table else "[tool.zero]"
            out += [f"#### `{o.key}`", "", o.description, "",
                    f"Type: {o.type}. Default: {_default_text(o)}.", "",
                    "```toml", header, o.example, "```", ""]
    return "\n".join(out)


def _line_of(text: str, table: tuple[str, ...], key: str | None) -> int | None:
    """Best effort: the line of ``key`` in ``table`` (or of the table header)."""
    from zero.structured.toml import scan_toml  # start-up: only for a configuration error

    found, _ = scan_toml(text)
    if key is not None:
        hit = found.get((*table, key))
        if hit is not None:
            return hit.line
    header = re.compile(r"^\s*\[\s*" + r"\s*\.\s*".join(re.escape(t) for t in table) + r"\s*\]")
    for n, line in enumerate(text.splitlines(), 1):
        if header.match(line):
            return n
    return None


_TOML_AT = r"\s*\(at line (\d+), column (\d+)\)\s*$"  # compiled at its first use: a file tomllib refuses


def parse_config(path: Path, text: str | None = None, _chain: tuple[Path, ...] = (),
                 over: Config | None = None) -> Config | None:
    """Read one configuration file; ``None`` for a pyproject.toml without ``[tool.zero]``. With
    ``extend = "other.toml"`` the other file is read first and this one is laid over it; ``over``
    lays ``text`` over a configuration already read (``--config KEY=VALUE``)."""
    import tomllib  # start-up: only when a configuration file exists

    if text is None:
        try:
            # a regular file only (a FIFO or device is refused), and no larger than a configuration is
            text = read_file(path, limit=MAX_CONFIG_BYTES).decode("utf-8")
        except ZeroError as exc:
            raise ZeroError(f"cannot read the configuration: {exc.message}", str(path)) from None
        except UnicodeDecodeError:
            raise ZeroError("the configuration is not UTF-8", str(path)) from None
    from zero.structured.toml import guard_toml  # start-up: only when a configuration file exists

    guard_toml(text, str(path))
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        at = re.search(_TOML_AT, str(exc))  # tomllib says where only in its message
        if at is None:
            raise ZeroError(f"not valid TOML: {exc}", str(path)) from None
        raise ZeroError(f"not valid TOML: {str(exc)[:at.start()].rstrip()}", str(path),
                        int(at.group(1)), int(at.group(2))) from None
    except RecursionError:  # brackets nested without end
        raise ZeroError("not valid TOML: nested too deeply", str(path)) from None
    except ValueError:  # an integer beyond Python's conversion limit (TOMLDecodeError is one too: above)
        raise ZeroError("not valid TOML: a number too long to read", str(path)) from None
    table: tuple[str, ...] = ()
    tool = data.get("tool", {})
    if path.name == "pyproject.toml":
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


def _extended(cfg: Config, value: Any, path: Path, chain: tuple[Path, ...],
              fail: Callable[..., ZeroError]) -> Config:
    """``extend = "../zero.toml"``: the inherited configuration under ``cfg`` (its settings where this
    file sets none; its rule selection a layer below this file's), as ruff's ``extend``."""
    if not isinstance(value, str) or not value:
        raise fail("extend", "expected the path of another configuration file (zero.toml or pyproject.toml)")
    target = Path(os.path.expanduser(os.path.expandvars(value)))
    target = target if target.is_absolute() else path.parent / target
    here = Path(os.path.abspath(path))
    if Path(os.path.abspath(target)) in (*chain, here) or len(chain) >= MAX_EXTEND_DEPTH:
        raise fail("extend", f"{value!r} extends in a circle (or more than {MAX_EXTEND_DEPTH} deep)")
    try:
        parent = parse_config(target, None, (*chain, here))
    except ZeroError as exc:
        raise fail("extend", f"{value!r}: {exc}") from None
    if parent is None:
        raise fail("extend", f"{value!r} has no [tool.zero] table")
    return _layered(parent, path, cfg.given)


def _layered(parent: Config, path: Path | None, given: frozenset[str]) -> Config:
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
    cfg = parse_config(Path("--config"), text, over=over)
    assert cfg is not None  # only a pyproject.toml may hold no [tool.zero]
    return cfg


def is_inline(value: str) -> bool:
    """Is a ``--config`` value one ``KEY = VALUE`` rather than a file (as ruff tells them)?"""
    return "=" in value and not os.path.lexists(value)


class ConfigFinder:
    """Finds (and caches) the configuration that applies to each file."""

    def __init__(self, explicit: Path | None = None, isolated: bool = False, overrides: tuple[str, ...] = ()) -> None:
        self.isolated = isolated
        self.overrides = overrides  # `--config KEY=VALUE`, in order: over whatever configuration applies
        self._overlaid: dict[int, tuple[Config, Config]] = {}
        self.explicit: Config | None = None
        if explicit is not None and not isolated:
            cfg = parse_config(explicit)
            if cfg is None:
                raise ZeroError("has no [tool.zero] table", str(explicit))
            self.explicit = cfg
        self._by_dir: dict[Path, Config] = {}
        self._by_name: dict[str, Config] = {}  # the absolute directory → its configuration
        self._by_path: dict[tuple[object, ...], Config] = {}  # a path's text (and the directory if relative)
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

    def for_path(self, path: Path, directory: bool | None = None) -> Config:
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
            directory = path.is_dir()
        given = (name, directory) if os.path.isabs(name) else (name, directory, _cwd())
        hit = self._by_path.get(given)  # the files of a run are asked about several times each
        if hit is not None:
            return hit
        key = os.path.abspath(name if directory else os.path.dirname(name) or ".")
        hit = self._by_name.get(key)
        if hit is None:
            start = Path(_resolved_folder(path if directory else path.parent))
            hit = self._by_name[key] = self._overlay(self._lookup(start))
        if len(self._by_path) > 65536:
            self._by_path.clear()
        self._by_path[given] = hit
        return hit

    def _lookup(self, start: Path) -> Config:
        walked: list[Path] = []
        d: Path | None = start
        found = self._default
        while d is not None:
            hit = self._by_dir.get(d)
            if hit is not None:
                found = hit
                break
            walked.append(d)
            cfg = next((c for c in (parse_config(d / n) for n in CONFIG_NAMES if os.path.lexists(d / n))
                        if c is not None), None)
            if cfg is not None:
                found = cfg
                break
            d = d.parent if d.parent != d else None
        for w in walked:
            self._by_dir[w] = found
        return found

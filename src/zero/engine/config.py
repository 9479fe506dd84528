"""Project configuration: ``[tool.zero]`` in ``pyproject.toml``, or ``zero.toml`` / ``.zero.toml``.

The file closest to a linted file wins (no merging), found by walking up from the
file's directory; ``--config PATH`` names one for every file and ``--isolated``
ignores them all. Globs are relative to the configuration file's directory
(``**/`` for any depth). Unknown keys and bad values are errors naming the file,
line and key.

```toml
[tool.zero]
select = ["S", "R", "M"]          # codes or prefixes; default: all
extend-select = ["Z"]
ignore = ["M003"]
exclude = ["old/**"]              # never linted, even when named on the command line
include = ["*.lis", "*.lst", "*.nc", "*.xml"]  # what a directory walk picks up (XML: lists only)
param-desc = "vendor/CncParaDesc.xml"

[tool.zero.per-file-ignores]
"machines/**/nullp*.lis" = ["M003"]

[tool.zero.severity]              # override a rule's default severity
R007 = "error"

[tool.zero.kind]                  # list kind by glob instead of detection
"**/nullp*.lis" = "zero"

[tool.zero.encoding]              # a list's code page by glob instead of detection (first match)
"machines/old/**/*.lis" = "cp850" # lists written on DOS tools; any single-byte codec or utf-8

[tool.zero.machine]               # the machine NC programs and `zero limits` refer to
startup = "listen/hochlauf.lis"
"achs_mds[0]" = "listen/achse_x_neu.lis"   # override a list the start-up list names
working-directory = "."                    # where the controller resolves ./listen/...
roots = { "C:/TwinCAT/3.1/Components/Mc/CNC" = "." }  # a controller folder → a project folder
```
"""

from __future__ import annotations

import functools
import os
import re
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from zero.catalog.registry import kind_from_name
from zero.diagnostics import Severity
from zero.engine.lint import LintOptions, layered_selection
from zero.errors import ZeroError
from zero.files import nearest_holding, read_file, within
from zero.forms import CONFIG_NAMES, DEFAULT_INCLUDE, controller_absolute
from zero.lists.encoding import declarable
from zero.lists.model import parse_key
from zero.records import field, record, replace
from zero.rules import RULES

if TYPE_CHECKING:
    from pathspec import GitIgnoreSpec

MAX_PATTERN_WILDCARDS = 3  # `*` runs in one segment of a glob pattern, and `**` segments
MAX_PATTERN_LENGTH = 512
MAX_CONFIG_BYTES = 1 << 20  # a configuration larger than 1 MiB is no configuration
_KEYS = ("extend", "select", "extend-select", "ignore", "extend-ignore", "per-file-ignores",
         "extend-per-file-ignores", "severity", "kind", "include", "exclude", "extend-exclude", "respect-gitignore",
         "param-desc", "machine", "encoding", "kernel")
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
        try:
            return _resolved(file).relative_to(self.root.resolve()).as_posix()
        except ValueError:
            return None

    def _matches(self, globs: tuple[str, ...], file: Path) -> bool:
        """gitignore's meaning: a pattern with a `/` is anchored at the configuration's
        directory, one without matches a name at any depth; `dir/` matches what is below it."""
        if not globs:
            return False
        rel = self.relative(file)
        return patterns(globs).match_file(rel if rel is not None else file.name)

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
        chosen = layered_selection((*self.layers, (cli.select, cli.extend_select, cli.ignore)), self.ignored_for(file))
        severity = {**self.parent.severity, **self.severity} if self.parent is not None else self.severity
        return LintOptions(select=chosen.select, ignore=chosen.ignore, kind=cli.kind or self.kind_for(file),
                           severity={**severity, **cli.severity},
                           encoding=cli.encoding or self.encoding_for(file),
                           kernel=cli.kernel or self.kernel, ignore_noqa=cli.ignore_noqa)

    def show(self) -> str:
        """The effective configuration as TOML (``zero config --show``)."""
        def arr(xs: tuple[str, ...]) -> str:
            return "[" + ", ".join(f'"{x}"' for x in xs) + "]"

        table = "[tool.zero]" if self.path is None or self.path.name == "pyproject.toml" else None
        prefix = "tool.zero." if table else ""
        source = f"# from {self.path}" if self.path else "# no configuration file: defaults"
        if self.parent is not None and self.parent.path is not None:
            source += f" over {self.parent.path} (the settings it does not set are that file's)"
        lines = [source, *([table] if table else []), f"select = {arr(self.select)}",
                 f"extend-select = {arr(self.extend_select)}",
                 f"ignore = {arr(self.ignore)}", f"include = {arr(self.include)}",
                 f"exclude = {arr(self.exclude)}", f"extend-exclude = {arr(self.extend_exclude)}",
                 f"respect-gitignore = {'true' if self.respect_gitignore else 'false'}"]
        if self.param_desc:
            lines.append(f'param-desc = "{self.param_desc}"')
        if self.kernel:
            lines.append(f'kernel = "{self.kernel}"')
        if self.machine or self.machine_lists or self.machine_workdir or self.machine_roots:
            lines.append(f"[{prefix}machine]")
            if self.machine:
                lines.append(f'startup = "{self.machine}"')
            if self.machine_workdir:
                lines.append(f'working-directory = "{self.machine_workdir}"')
            if self.machine_roots:
                lines.append("roots = { " + ", ".join(f'"{k}" = "{v}"' for k, v in self.machine_roots) + " }")
            lines += [f'"{k}" = "{v}"' for k, v in self.machine_lists.items()]
        lines.append(f"[{prefix}per-file-ignores]")
        lines += [f'"{g}" = {arr(c)}' for g, c in self.per_file_ignores]
        lines.append(f"[{prefix}severity]")
        lines += [f'{c} = "{s.label}"' for c, s in sorted(self.severity.items())]
        lines.append(f"[{prefix}kind]")
        lines += [f'"{g}" = "{k}"' for g, k in self.kind]
        if self.encoding:
            lines.append(f"[{prefix}encoding]")
            lines += [f'"{g}" = "{c}"' for g, c in self.encoding]
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


_TOML_AT = re.compile(r"\s*\(at line (\d+), column (\d+)\)\s*$")


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
        at = _TOML_AT.search(str(exc))  # tomllib says where only in its message
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

    def fail(key: str | None, message: str, sub: tuple[str, ...] = ()) -> ZeroError:
        line = _line_of(text or "", (*table, *sub), key)
        name = ".".join((*table, *sub, key) if key else (*table, *sub)) or "(top level)"
        return ZeroError(f"{name}: {message}", str(path), line)

    def codes(key: str, value: Any, sub: tuple[str, ...] = ()) -> tuple[str, ...]:
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise fail(key, "expected a list of rule codes, e.g. [\"R005\", \"M\"]", sub)
        out = tuple(v.strip().upper() for v in value)
        for c in out:
            if c != "ALL" and not any(code.startswith(c) for code in RULES):
                raise fail(key, f"{c!r} matches no rule code (see `zero rule`)", sub)
        return out

    def globs(key: str, value: Any, sub: tuple[str, ...] = ()) -> tuple[str, ...]:
        if not isinstance(value, list) or not all(isinstance(v, str) and v for v in value):
            raise fail(key, "expected a list of glob patterns, e.g. [\"old/**\"]", sub)
        try:
            patterns(tuple(value))
        except ZeroError as exc:
            raise fail(key, exc.message, sub) from None
        return tuple(value)

    cfg = Config(path=path, given=frozenset(data))
    if over is not None:
        cfg = _layered(over, over.path, cfg.given)
    elif "extend" in data:
        cfg = _extended(cfg, data["extend"], path, _chain, fail)
    for key, value in data.items():
        if key not in _KEYS:
            import difflib  # start-up: only for a configuration error

            near = difflib.get_close_matches(key.replace("_", "-"), _KEYS, n=1, cutoff=0.7)  # as the CLI
            hint = f" (did you mean `{near[0]}`?)" if near else ""
            raise fail(key, f"unknown key{hint}; known: {', '.join(_KEYS)}")
        if key == "extend":
            continue  # read first, above
        if key == "select":
            cfg.select = codes(key, value)
        elif key == "extend-ignore":  # ruff's older spelling: added to this file's `ignore`
            cfg.ignore = (*cfg.ignore, *codes(key, value))
        elif key == "extend-exclude":
            cfg.extend_exclude = globs(key, value)
        elif key == "respect-gitignore":
            if not isinstance(value, bool):
                raise fail(key, "expected true or false")
            cfg.respect_gitignore = value
        elif key == "extend-per-file-ignores":
            if not isinstance(value, dict):
                raise fail(key, "expected a table of glob = [codes]")
            for g in value:
                globs(g, [g], ("extend-per-file-ignores",))
            cfg.extend_per_file_ignores = tuple((g, codes(g, v, ("extend-per-file-ignores",)))
                                                for g, v in value.items())
        elif key == "extend-select":
            cfg.extend_select = codes(key, value)
        elif key == "ignore":
            cfg.ignore = (*codes(key, value), *cfg.ignore)
        elif key == "include":
            cfg.include = globs(key, value)
        elif key == "exclude":
            cfg.exclude = globs(key, value)
        elif key == "kernel":
            from zero.catalog.releases import parse_release  # start-up: only when a release is set

            if not isinstance(value, str):
                raise fail(key, 'expected the kernel release the machines run, e.g. "V3.1.3074"')
            try:
                parse_release(value)
            except ZeroError as exc:
                raise fail(key, exc.message) from None
            cfg.kernel = value
        elif key == "param-desc":
            if not isinstance(value, str) or not value:
                raise fail(key, "expected the path of a CncParaDesc.xml")
            cfg.param_desc = (path.parent / value)
        elif key == "machine":
            if not isinstance(value, dict):
                raise fail(key, "expected a table: startup = \"listen/hochlauf.lis\" and list overrides")
            root = project_root(path.parent)
            for mk, mv in value.items():
                if mk == "roots":
                    cfg.machine_roots = _roots(mv, path, root, fail)
                    continue
                if not isinstance(mv, str) or not mv:
                    raise fail(mk, "expected a path", ("machine",))
                if not within(path.parent / mv, root):
                    raise fail(mk, f"{mv!r} lies outside the project {root}: a configuration names only the "
                               "project's own files (give a path inside it, or --machine on the command line)",
                               ("machine",))
                if mk == "startup":
                    cfg.machine = path.parent / mv
                elif mk == "working-directory":
                    cfg.machine_workdir = path.parent / mv
                elif _is_reference(mk):
                    cfg.machine_lists[mk] = path.parent / mv
                else:
                    raise fail(mk, "expected `startup`, `working-directory`, `roots` or a key of the start-up list "
                               "that names a list, such as `achs_mds[0]` or `hand_mds`", ("machine",))
        elif key == "per-file-ignores":
            if not isinstance(value, dict):
                raise fail(key, "expected a table of glob = [codes]")
            for g in value:
                globs(g, [g], ("per-file-ignores",))
            cfg.per_file_ignores = tuple((g, codes(g, v, ("per-file-ignores",))) for g, v in value.items())
        elif key == "severity":
            if not isinstance(value, dict):
                raise fail(key, "expected a table of CODE = \"error\" | \"warning\" | \"info\"")
            given: dict[str, Severity] = {}
            for code, sev in value.items():
                prefix = code.strip().upper()
                if not any(c.startswith(prefix) for c in RULES):
                    raise fail(code, f"{code!r} matches no rule code (see `zero rule`)", ("severity",))
                try:
                    given[prefix] = Severity.parse(sev if isinstance(sev, str) else "")
                except ValueError:
                    raise fail(code, f"{sev!r} is not a severity (error, warning or info)",
                               ("severity",)) from None
            for c in RULES:  # a prefix sets every code it matches; the longest prefix wins
                best = max((p for p in given if c.startswith(p)), key=len, default=None)
                if best is not None:
                    cfg.severity[c] = given[best]
        elif key == "kind":
            if not isinstance(value, dict):
                raise fail(key, "expected a table of glob = kind")
            pairs = []
            for glob, name in value.items():
                globs(glob, [glob], ("kind",))
                k = kind_from_name(name) if isinstance(name, str) else None
                if k is None:
                    raise fail(glob, f"{name!r} is not a list kind (zero, axis, channel, ...)", ("kind",))
                pairs.append((glob, k))
            cfg.kind = tuple(pairs)
        elif key == "encoding":
            if not isinstance(value, dict):
                raise fail(key, 'expected a table of glob = codec, e.g. {"old/**/*.lis" = "cp850"}')
            declared = []
            for glob, name in value.items():
                globs(glob, [glob], ("encoding",))
                try:
                    codec = declarable(name) if isinstance(name, str) else None
                except ValueError as exc:
                    raise fail(glob, str(exc), ("encoding",)) from None
                if codec is None:
                    raise fail(glob, f"{name!r} is not the name of a codec (e.g. \"cp850\")", ("encoding",))
                declared.append((glob, codec))
            cfg.encoding = tuple(declared)
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
        if directory is None:
            directory = path.is_dir()
        key = os.path.abspath(str(path) if directory else os.path.dirname(str(path)) or ".")
        hit = self._by_name.get(key)
        if hit is None:
            start = path.resolve() if directory else _resolved(path).parent
            hit = self._by_name[key] = self._overlay(self._lookup(start))
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

"""The options of the configuration, each declared once, and how a configuration file's values are read.

Every option is declared once, in :data:`OPTIONS` (key, type, default, description, example,
section, how it is read and checked, how ``zero config --show`` prints it); the parser
(:func:`zero.engine.config.parse_config`), ``--show``, the reference of docs/configuration.md and
``zero.schema.json`` are made from it (``tools/gen_config.py`` writes the last two,
``tests/test_declarations.py`` holds them to it). Kept apart from :mod:`zero.engine.config`, which
finds the configuration that applies: a lint where no configuration file is found imports none of this.
"""

from __future__ import annotations

import functools
import os
import re
from collections.abc import Callable

from zero.diagnostics import Severity
from zero.engine.globs import GlobSpec
from zero.engine.selection import known_code, rule_table
from zero.errors import ZeroError
from zero.files import nearest_holding, within
from zero.forms import DEFAULT_INCLUDE, controller_absolute
from zero.lists.model import parse_key
from zero.records import Record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # (pathlib only for the keys that name files: param-desc, [tool.zero.machine])
    from pathlib import Path
    from typing import Any

    # The configuration being read (zero.engine.config's Config) is `Any` here: that module imports
    # this one where a file is read, and the layers allow no circle, not even through annotations.
    Config = Any

MAX_PATTERN_WILDCARDS = 3  # `*` runs in one segment of a glob pattern, and `**` segments
MAX_PATTERN_LENGTH = 512


@functools.lru_cache(maxsize=512)
def patterns(globs: tuple[str, ...]) -> GlobSpec:
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
            # a pattern is matched with a backtracking regular expression (zero.engine.globs', pathspec's):
            # the time a name takes grows as its length to the power of the wildcards in one segment (100:
            # 12 s per file, 8: 20 s on a 60-character name); 3 keep the worst name of 255 characters below 30 ms
            raise ZeroError(f"pattern {g[:40]!r}{'…' if len(g) > 40 else ''}: too complex (at most "
                            f"{MAX_PATTERN_WILDCARDS} `*` in one path segment, {MAX_PATTERN_WILDCARDS} `**` "
                            f"and {MAX_PATTERN_LENGTH} characters)")
        lines.append(text)
    try:  # GitIgnoreSpec's answers without importing pathspec (but for what zero.engine.globs leaves to it)
        return GlobSpec(lines)
    except (ValueError, TypeError) as exc:
        raise ZeroError(f"a pattern cannot be read: {exc}") from None


def project_root(folder: Path) -> Path:
    """The project a configuration belongs to: the git work tree that holds its folder, else the folder."""
    from pathlib import Path  # start-up: only a configuration that names a machine

    return nearest_holding(folder, (".git",)) or Path(os.path.abspath(folder))


def _is_reference(key: str) -> bool:
    """A start-up key that names a list (``achs_mds[0]``, ``hand_mds``)."""
    from zero.machine.model import BY_KEY  # start-up: only a configuration that names lists

    parsed = parse_key(key)
    ref = BY_KEY.get(parsed.pattern) if parsed is not None else None
    return ref is not None and len(parsed.indices) == ref.key.count("[]")  # type: ignore[union-attr]


def _roots(value: Any, folder: Path, root: Path,
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
        if not within(folder / v, root):
            raise fail("roots", f"{v!r} lies outside the project {root}", ("machine",))
        out.append((k, folder / v))
    return tuple(out)


# ------------------------------------------------------------------------------------------------
# The options, each declared once: its key, type, default, description, example, section, how it is
# read (validation) and how `zero config --show` prints it. The parser, `zero config --show`, the
# reference section of docs/configuration.md and zero.schema.json (the JSON Schema of zero.toml and
# [tool.zero]) are all made from OPTIONS; tests/test_declarations.py holds the page and the schema to it.


class ConfigOption(Record, frozen=True):
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

    def __init__(self, cfg: Config, path: str, text: str, table: tuple[str, ...]) -> None:
        self.cfg, self.path, self.text, self.table = cfg, path, text, table

    @property
    def folder(self) -> Path:
        """The folder of the file, which the paths it names are relative to."""
        from pathlib import Path  # start-up: only a configuration that names a file (param-desc, machine)

        return Path(self.path).parent

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
    r.cfg.param_desc = r.folder / value


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
    folder, cfg = r.folder, r.cfg
    root = project_root(folder)
    for mk, mv in value.items():
        if mk == "roots":
            cfg.machine_roots = _roots(mv, folder, root, r.fail)
            continue
        if not isinstance(mv, str) or not mv:
            raise r.fail(mk, "expected a path", ("machine",))
        if not within(folder / mv, root):
            raise r.fail(mk, f"{mv!r} lies outside the project {root}: a configuration names only the "
                         "project's own files (give a path inside it, or --machine on the command line)",
                         ("machine",))
        if mk == "startup":
            cfg.machine = folder / mv
        elif mk == "working-directory":
            cfg.machine_workdir = folder / mv
        elif _is_reference(mk):
            cfg.machine_lists[mk] = folder / mv
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

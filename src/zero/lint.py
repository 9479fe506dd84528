"""Run the rules over a document: select, stamp severity, sort.

Everything the ``zero lint`` command does is callable from here.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from zero.diagnostics import Diagnostic, Severity
from zero.model import Document
from zero.registry import Registry, default_registry
from zero.rules import CHECKS, RULES, suppress
from zero.rules.base import Context, Resolved, read_value
from zero.tokenizer import tokenize

LIST_SUFFIXES = (".lis", ".lst")
_KNOWN = set(RULES)
PROGRAM_SUFFIXES = (".nc", ".mpf", ".spf")  # NC programs (zero.program)
STRUCTURED_SUFFIXES = {".yaml": "yaml", ".yml": "yaml", ".toml": "toml", ".json": "json"}
MAX_FILE_BYTES = 256 * 1024 * 1024


class ZeroError(Exception):
    """A usage or I/O problem: reported in one line, exit code 2."""


@dataclass(slots=True)
class LintOptions:
    select: tuple[str, ...] = ()  # code prefixes; empty = all
    ignore: tuple[str, ...] = ()
    kind: str | None = None  # force the list kind
    severity: dict[str, Severity] = field(default_factory=dict)  # per-code overrides


@dataclass(slots=True)
class LintResult:
    path: str
    document: Document
    kind: str | None
    diagnostics: list[Diagnostic] = field(default_factory=list)

    @property
    def worst(self) -> Severity | None:
        return max((d.severity for d in self.diagnostics), default=None)


_selected: dict[tuple[object, ...], dict[str, Severity]] = {}


def selected_rules(options: LintOptions) -> dict[str, Severity]:
    """Code → severity of every rule the options enable (longest prefix wins); memoised."""
    key = (options.select, options.ignore, tuple(sorted(options.severity.items())))
    hit = _selected.get(key)
    if hit is None:
        hit = _selected[key] = _selected_rules(options)
    return hit


def _selected_rules(options: LintOptions) -> dict[str, Severity]:
    out: dict[str, Severity] = {}
    for code, r in RULES.items():
        sel = max((len(p) for p in options.select if code.startswith(p)), default=-1)
        ign = max((len(p) for p in options.ignore if code.startswith(p)), default=-1)
        if options.select and sel < 0:
            continue
        if ign > sel:
            continue
        out[code] = options.severity.get(code, r.severity)
    return out


def build_context(doc: Document, registry: Registry, kind: str | None,
                  severities: dict[str, Severity]) -> Context:
    entries = doc.entries
    if kind is None:
        kind = registry.detect_kind((e.key.pattern for e in entries if e.key), doc.path)
    ctx = Context(doc, registry, kind, severities, entries)
    for e in entries:
        if e.key is None:
            continue
        via_alias = False
        spec = registry.by_pattern(e.key.pattern, kind)
        if spec is None:
            spec = registry.alias(e.key.pattern, kind)
            via_alias = spec is not None
        if spec is None or e.value_kind is None:
            continue
        res = Resolved(e, spec, read_value(spec, e), via_alias)
        ctx.resolved.append(res)
        ctx.by_id.setdefault(spec.id, {})[e.key.indices] = res
    return ctx


def lint_document(doc: Document, registry: Registry | None = None,
                  options: LintOptions | None = None) -> LintResult:
    registry = registry or default_registry()
    options = options or LintOptions()
    severities = selected_rules(options)
    ctx = build_context(doc, registry, options.kind, severities)
    found = [d for check in CHECKS for d in check(ctx) if d.code in severities]
    found.sort(key=Diagnostic.sort_key)
    found = suppress.apply(doc, found, severities, _KNOWN)
    return LintResult(doc.path, doc, ctx.kind, found)


def lint_bytes(data: bytes, path: str = "-", registry: Registry | None = None,
               options: LintOptions | None = None) -> LintResult:
    return lint_document(tokenize(data, path), registry, options)


def read_file(path: str | Path) -> bytes:
    """Read a list file; :class:`ZeroError` with a one-line reason on failure."""
    p = Path(path)
    try:
        size = p.stat().st_size
        if size > MAX_FILE_BYTES:
            raise ZeroError(f"{path}: file is {size} bytes, larger than the "
                            f"{MAX_FILE_BYTES // (1024 * 1024)} MiB zero reads")
        return p.read_bytes()
    except FileNotFoundError:
        raise ZeroError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise ZeroError(f"{path}: is a directory") from None
    except PermissionError:
        raise ZeroError(f"{path}: permission denied") from None
    except OSError as exc:
        raise ZeroError(f"{path}: {exc.strerror or exc}") from None


def lint_file(path: str | Path, registry: Registry | None = None,
              options: LintOptions | None = None) -> LintResult:
    """Lint a list file; a YAML/TOML/JSON file is linted as the list it converts to."""
    suffix = Path(path).suffix.lower()
    if suffix in PROGRAM_SUFFIXES:
        from zero.program import lint_program

        return lint_program(read_file(path), str(path), registry, options)
    fmt = STRUCTURED_SUFFIXES.get(suffix)
    if fmt is None:
        return lint_bytes(read_file(path), str(path), registry, options)
    from zero.convert import ConvertError, lint_tree, read_tree

    data = read_file(path)
    try:
        tree = read_tree(data, fmt, str(path))
    except ConvertError as exc:
        raise ZeroError(str(exc)) from None
    source = data.decode("utf-8", "replace").lstrip("\ufeff")
    return lint_tree(tree, options, source if fmt in ("yaml", "toml") else None, registry)


def git_visible(directory: Path) -> set[str] | None:
    """Files below ``directory`` that git does not ignore, as paths relative to it
    (``os.sep``-separated); ``None`` outside a git work tree or without git."""
    import shutil
    import subprocess

    if shutil.which("git") is None:
        return None
    try:
        proc = subprocess.run(["git", "-C", str(directory), "ls-files", "-z", "--cached", "--others",
                               "--exclude-standard", "."], capture_output=True, timeout=60, check=False)
    except (OSError, subprocess.SubprocessError):
        return None
    if proc.returncode != 0:
        return None
    return {os.path.normpath(os.fsdecode(name)) for name in proc.stdout.split(b"\0") if name}


def collect_files(paths: Iterable[str | Path], include: Callable[[Path], bool] | None = None,
                  exclude: Callable[[Path], bool] | None = None,
                  respect_gitignore: bool = True) -> list[Path]:
    """Files named explicitly, plus list files below named directories (sorted).

    ``include`` decides which files a directory walk picks up (default: ``*.lis``,
    ``*.lst``); ``exclude`` drops files and directories, named ones included. A
    directory walk skips what ``.gitignore`` ignores when the directory is in a git
    work tree (named files are always linted).
    """
    out: list[Path] = []
    for raw in paths:
        p = Path(raw)
        if p.is_dir():
            visible = git_visible(p) if respect_gitignore else None
            found: list[Path] = []
            for root, dirs, files in os.walk(p):
                dirs[:] = sorted(d for d in dirs if not d.startswith(".")
                                 and not (exclude and exclude(Path(root) / d)))
                rel_root = os.path.relpath(root, p)
                for f in files:
                    if visible is not None and os.path.normpath(os.path.join(rel_root, f)) not in visible:
                        continue
                    path = Path(root) / f
                    if (include(path) if include else f.lower().endswith(LIST_SUFFIXES)) and \
                            not (exclude and exclude(path)):
                        found.append(path)
            out.extend(sorted(found, key=str))
        elif p.exists():
            if not (exclude and exclude(p)):
                out.append(p)
        else:
            raise ZeroError(f"{raw}: no such file or directory")
    return out


def lint_paths(paths: Iterable[str | Path], registry: Registry | None = None,
               options: LintOptions | None = None) -> Iterator[LintResult]:
    registry = registry or default_registry()
    for p in collect_files(paths):
        yield lint_file(p, registry, options)


# Below this many files a second process costs more than it saves.
PARALLEL_MIN_FILES = 64
OptionsFor = Callable[[Path], LintOptions]
_worker_state: tuple[Registry, OptionsFor] | None = None


def _slim(result: LintResult) -> LintResult:
    """A result without the parsed items, keeping only the lines findings show (cheap to pickle)."""
    doc = result.document
    wanted = {d.span.line for d in result.diagnostics}
    lines = [t if n in wanted else "" for n, t in enumerate(doc.lines, 1)]
    slim = Document(doc.path, doc.encoding, lines, [], [], [], doc.bom, doc.end_line)
    return LintResult(result.path, slim, result.kind, result.diagnostics)


def _lint_in_worker(path: Path) -> LintResult | ZeroError:
    assert _worker_state is not None
    registry, options_for = _worker_state
    try:
        return _slim(lint_file(path, registry, options_for(path)))
    except ZeroError as exc:
        return exc


def lint_many(files: list[Path], registry: Registry | None = None,
              options: LintOptions | OptionsFor | None = None, jobs: int | None = None,
              progress: Callable[[int, int], None] | None = None) -> list[LintResult]:
    """Lint files, in parallel across ``jobs`` processes (default: all cores) when there are
    many; results come back in the order of ``files`` whatever the number of processes.
    ``options`` may be a function giving each file its own options (configuration)."""
    global _worker_state
    registry = registry or default_registry()
    fixed = options or LintOptions()
    options_for: OptionsFor = fixed if callable(fixed) else (lambda _p: fixed)
    cores = os.cpu_count() or 1
    jobs = cores if jobs is None or jobs <= 0 else jobs
    jobs = min(jobs, cores * 4, max(1, len(files) // 16))
    if jobs <= 1 or len(files) < PARALLEL_MIN_FILES:
        serial = []
        for n, f in enumerate(files, 1):
            serial.append(lint_file(f, registry, options_for(f)))
            if progress is not None and (n % 50 == 0 or n == len(files)):
                progress(n, len(files))
        return serial
    import multiprocessing as mp

    try:
        ctx = mp.get_context("fork")
    except ValueError:  # pragma: no cover - platforms without fork lint in one process
        return [lint_file(f, registry, options_for(f)) for f in files]
    _worker_state = (registry, options_for)
    try:
        with ctx.Pool(jobs) as pool:
            out = []
            for n, r in enumerate(pool.imap(_lint_in_worker, files,
                                            chunksize=max(1, min(64, len(files) // (jobs * 8)))), 1):
                out.append(r)
                if progress is not None and (n % 50 == 0 or n == len(files)):
                    progress(n, len(files))
    finally:
        _worker_state = None
    for r in out:
        if isinstance(r, ZeroError):
            raise r
    return out  # type: ignore[return-value]

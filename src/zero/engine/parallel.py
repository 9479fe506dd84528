"""Linting many files: in parallel across processes (fork) when there are many,
results in the order of the files whatever the number of processes.

Files of one run with the same bytes, the same options and the same kind by name are linted once
(:class:`SameFiles`): a fleet's machines share most of their lists byte for byte, and the findings
of such a file differ from its twin's only in the path they name.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Sequence

from zero.catalog.registry import Registry
from zero.engine.lint import LintOptions, LintResult, lint_data, lint_file
from zero.errors import ZeroError
from zero.files import content_digest, max_file_bytes, read_file
from zero.forms import is_program, is_xml, kind_hint, structured_format
from zero.lists.model import Excerpt
from zero.records import replace

# Below this many files a second process costs more than it saves.
PARALLEL_MIN_FILES = 64
# A file larger than this is linted on its own (its bytes let go once decoded: lint_file), never
# shared: a big list is seldom another's twin, and its lint is the run's cost anyway.
SHARED_MAX_BYTES = 1 << 20
# How many distinct files' results a run keeps to share (a window, oldest out first): a fleet's
# machines follow each other, each with its twenty or so lists.
SHARED_KEPT = 512
TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TypeAlias

    FileName: TypeAlias = str | os.PathLike[str]  # a file as the engine names it (a Path from the library)
    OptionsFor: TypeAlias = Callable[[FileName], LintOptions]
_worker_state: tuple[Registry, OptionsFor] | None = None


def _slim(result: LintResult) -> LintResult:
    """A result without the parsed items, keeping only the lines findings show (cheap to pickle)."""
    doc = result.document
    if type(doc) is Excerpt:
        return result
    shown = {n: doc.line_text(n) for d in result.diagnostics for n in (d.span.line, d.span.end_line)
             if doc.has_line(n)}  # the end's too: a report (rdjson) counts its column in the line's bytes
    slim = Excerpt(doc.path, doc.encoding, [], [], [], [], doc.bom, doc.end_line, shown=shown)
    return LintResult(result.path, slim, result.kind, result.diagnostics, result.note)


def _shareable(result: LintResult) -> bool:
    """Does nothing in the result name its file but its path fields (so that moving it to a twin
    is changing those)?"""
    path = result.path
    return all(d.path == path and path not in d.message and (d.hint is None or path not in d.hint)
               and all(r.path is None for r in d.related) for d in result.diagnostics) \
        and (result.note is None or path not in result.note)


def _moved(result: LintResult, path: str) -> LintResult:
    """``result`` (slim, :func:`_shareable`) as the result of its twin at ``path``."""
    doc = result.document
    assert isinstance(doc, Excerpt)
    shown = Excerpt(path, doc.encoding, [], [], [], [], doc.bom, doc.end_line, shown=doc.shown)
    return LintResult(path, shown, result.kind, [replace(d, path=path) for d in result.diagnostics], result.note)


class SameFiles:
    """The results of a run's list files by what decides them: the hash of the bytes, the options
    object (the configuration, command line and per-file ignores of the file), the registry, and the
    kind the file's name suggests (:func:`zero.forms.kind_hint`, which breaks a tie in detection).
    NC programs, YAML/TOML/JSON and XML files are linted each on its own."""

    def __init__(self) -> None:
        self._kept: dict[tuple[bytes, str | None, int, int], tuple[LintOptions, Registry, LintResult]] = {}
        self.shared = 0  # files whose result was a twin's

    @staticmethod
    def key(path: FileName, options: LintOptions, registry: Registry) -> tuple[tuple[bytes, str | None, int, int],
                                                                            bytes] | None:
        """The key of a list file and its bytes; ``None``: linted on its own (not a plain list, too big,
        or unreadable: :func:`lint_file` says why)."""
        name = str(path)
        if is_program(name) or structured_format(name) is not None:
            return None
        try:
            data = read_file(path, min(SHARED_MAX_BYTES, max_file_bytes()))
        except ZeroError:  # too big to share (or to read at all), or unreadable
            return None
        if is_xml(data):
            return None
        return (content_digest(data), kind_hint(name), id(options), id(registry)), data

    def twin(self, key: tuple[bytes, str | None, int, int], path: FileName, options: LintOptions,
             registry: Registry) -> LintResult | None:
        """The result of a file linted earlier in the run with ``key``, moved to ``path``."""
        hit = self._kept.get(key)
        if hit is None or hit[0] is not options or hit[1] is not registry:
            return None
        self.shared += 1
        return _moved(hit[2], str(path))

    def keep(self, key: tuple[bytes, str | None, int, int], options: LintOptions, registry: Registry,
             result: LintResult) -> LintResult:
        """Keep a file's (slim) result for its twins; the slim result."""
        slim = _slim(result)
        if _shareable(slim):
            if len(self._kept) >= SHARED_KEPT:
                del self._kept[next(iter(self._kept))]
            self._kept[key] = (options, registry, slim)
        return slim

    def lint(self, path: FileName, registry: Registry, options: LintOptions) -> LintResult:
        """A file's result (slim): its twin's, or linted now."""
        found = self.key(path, options, registry)
        if found is None:
            return _slim(lint_file(path, registry, options))
        key, data = found
        twin = self.twin(key, path, options, registry)
        if twin is not None:
            return twin
        return self.keep(key, options, registry, lint_data(data, str(path), registry, options))


def _lint_keyed(path: FileName, registry: Registry, options: LintOptions) -> tuple[bytes | None, LintResult]:
    """A file's (slim) result, and the hash of the bytes it was made from (``None``: not a file
    :class:`SameFiles` shares)."""
    found = SameFiles.key(path, options, registry)
    if found is None:
        return None, _slim(lint_file(path, registry, options))
    key, data = found
    return key[0], _slim(lint_data(data, str(path), registry, options))


def _lint_in_worker(path: FileName) -> tuple[bytes | None, LintResult] | ZeroError:
    assert _worker_state is not None
    registry, options_for = _worker_state
    try:
        return _lint_keyed(path, registry, options_for(path))
    except ZeroError as exc:  # a file that cannot be converted stops the run, as in one process
        return exc


def lint_many(files: Sequence[FileName], registry: Registry,
              options: LintOptions | OptionsFor | None = None, jobs: int | None = None,
              progress: Callable[[int, int], None] | None = None) -> list[LintResult]:
    """Lint files, in parallel across ``jobs`` processes (default: all cores) when there are
    many; results come back in the order of ``files`` whatever the number of processes.
    ``options`` may be a function giving each file its own options (configuration)."""
    return list(iter_lint_many(files, registry, options, jobs, progress))


def iter_lint_many(files: Sequence[FileName], registry: Registry,
                   options: LintOptions | OptionsFor | None = None, jobs: int | None = None,
                   progress: Callable[[int, int], None] | None = None) -> Iterator[LintResult]:
    """:func:`lint_many` as a stream: each result as soon as it and those before it are done,
    so that a report can be written while the files are linted and need not keep them. Of files
    with the same bytes and options (:class:`SameFiles`), the first is linted and the others share
    its findings."""
    fixed = options or LintOptions()
    options_for: OptionsFor = fixed if callable(fixed) else (lambda _p: fixed)
    if len(files) == 1:  # the whole result (its document too: a fix, --show-files, the server)
        yield lint_file(files[0], registry, options_for(files[0]))
        if progress is not None:
            progress(1, 1)
        return
    cores = os.cpu_count() or 1
    jobs = cores if jobs is None or jobs <= 0 else jobs
    same = SameFiles()
    if jobs <= 1 or len(files) < PARALLEL_MIN_FILES:  # one process: each file read once, in order
        for n, f in enumerate(files, 1):
            yield same.lint(f, registry, options_for(f))
            if progress is not None and (n % 50 == 0 or n == len(files)):
                progress(n, len(files))
        return
    # many files: the twins are told apart first (their bytes hashed, then let go), and only the
    # first of each is linted, across processes where those are still many
    plan: list[tuple[FileName, LintOptions, tuple[bytes, str | None, int, int] | None, bool]] = []
    seen: set[tuple[bytes, str | None, int, int]] = set()
    for f in files:
        opts = options_for(f)
        found = same.key(f, opts, registry)
        key = found[0] if found is not None else None
        plan.append((f, opts, key, key is None or key not in seen))
        if key is not None:
            seen.add(key)
    todo = [f for f, _, _, first in plan if first]
    made = _made(todo, registry, options_for, min(jobs, cores * 4, max(1, len(todo) // 16)))
    for n, (f, opts, key, first) in enumerate(plan, 1):
        if first:
            digest, result = next(made)
            if key is not None and digest == key[0]:  # not changed since it was hashed: its twins share it
                result = same.keep(key, opts, registry, result)
        else:
            assert key is not None
            twin = same.twin(key, f, opts, registry)
            result = twin if twin is not None else _slim(lint_file(f, registry, opts))
        yield result
        if progress is not None and (n % 50 == 0 or n == len(files)):
            progress(n, len(files))


def _made(files: Sequence[FileName], registry: Registry, options_for: OptionsFor,
          jobs: int) -> Iterator[tuple[bytes | None, LintResult]]:
    """:func:`_lint_keyed` of ``files``, in their order: in ``jobs`` processes when there are many."""
    global _worker_state
    if jobs <= 1 or len(files) < PARALLEL_MIN_FILES:
        for f in files:
            yield _lint_keyed(f, registry, options_for(f))
        return
    import multiprocessing as mp  # start-up: only when many files are linted

    try:
        ctx = mp.get_context("fork")
    except ValueError:  # pragma: no cover - platforms without fork lint in one process
        yield from (_lint_keyed(f, registry, options_for(f)) for f in files)
        return
    _worker_state = (registry, options_for)
    try:
        with ctx.Pool(jobs) as pool:
            for r in pool.imap(_lint_in_worker, files, chunksize=max(1, min(64, len(files) // (jobs * 8)))):
                if isinstance(r, ZeroError):
                    raise r
                yield r
    finally:
        _worker_state = None

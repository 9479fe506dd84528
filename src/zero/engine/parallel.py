"""Linting many files: in parallel across processes (fork) when there are many,
results in the order of the files whatever the number of processes.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from pathlib import Path

from zero.catalog.registry import Registry
from zero.engine.lint import LintOptions, LintResult, lint_file
from zero.errors import ZeroError
from zero.lists.model import Excerpt

# Below this many files a second process costs more than it saves.
PARALLEL_MIN_FILES = 64
OptionsFor = Callable[[Path], LintOptions]
_worker_state: tuple[Registry, OptionsFor] | None = None


def _slim(result: LintResult) -> LintResult:
    """A result without the parsed items, keeping only the lines findings show (cheap to pickle)."""
    doc = result.document
    shown = {n: doc.line_text(n) for d in result.diagnostics for n in (d.span.line, d.span.end_line)
             if doc.has_line(n)}  # the end's too: a report (rdjson) counts its column in the line's bytes
    slim = Excerpt(doc.path, doc.encoding, [], [], [], [], doc.bom, doc.end_line, shown=shown)
    return LintResult(result.path, slim, result.kind, result.diagnostics, result.note)


def _lint_in_worker(path: Path) -> LintResult | ZeroError:
    assert _worker_state is not None
    registry, options_for = _worker_state
    try:
        return _slim(lint_file(path, registry, options_for(path)))
    except ZeroError as exc:  # a file that cannot be converted stops the run, as in one process
        return exc


def lint_many(files: list[Path], registry: Registry,
              options: LintOptions | OptionsFor | None = None, jobs: int | None = None,
              progress: Callable[[int, int], None] | None = None) -> list[LintResult]:
    """Lint files, in parallel across ``jobs`` processes (default: all cores) when there are
    many; results come back in the order of ``files`` whatever the number of processes.
    ``options`` may be a function giving each file its own options (configuration)."""
    return list(iter_lint_many(files, registry, options, jobs, progress))


def iter_lint_many(files: list[Path], registry: Registry,
                   options: LintOptions | OptionsFor | None = None, jobs: int | None = None,
                   progress: Callable[[int, int], None] | None = None) -> Iterator[LintResult]:
    """:func:`lint_many` as a stream: each result as soon as it and those before it are done,
    so that a report can be written while the files are linted and need not keep them."""
    global _worker_state
    fixed = options or LintOptions()
    options_for: OptionsFor = fixed if callable(fixed) else (lambda _p: fixed)
    cores = os.cpu_count() or 1
    jobs = cores if jobs is None or jobs <= 0 else jobs
    jobs = min(jobs, cores * 4, max(1, len(files) // 16))
    if jobs <= 1 or len(files) < PARALLEL_MIN_FILES:
        keep = (lambda r: r) if len(files) == 1 else _slim  # many files: memory does not grow with them
        for n, f in enumerate(files, 1):
            yield keep(lint_file(f, registry, options_for(f)))
            if progress is not None and (n % 50 == 0 or n == len(files)):
                progress(n, len(files))
        return
    import multiprocessing as mp  # start-up: only when many files are linted

    try:
        ctx = mp.get_context("fork")
    except ValueError:  # pragma: no cover - platforms without fork lint in one process
        yield from (lint_file(f, registry, options_for(f)) for f in files)
        return
    _worker_state = (registry, options_for)
    try:
        with ctx.Pool(jobs) as pool:
            for n, r in enumerate(pool.imap(_lint_in_worker, files,
                                            chunksize=max(1, min(64, len(files) // (jobs * 8)))), 1):
                if isinstance(r, ZeroError):
                    raise r
                yield r
                if progress is not None and (n % 50 == 0 or n == len(files)):
                    progress(n, len(files))
    finally:
        _worker_state = None

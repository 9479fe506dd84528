"""The commands as library functions: everything a command does except printing.

Each function takes what the user asked for and returns what the command found; the
command line renders it (:mod:`zero.output`) and turns it into an exit code
(:mod:`zero.cli.exits`). Registries are passed in through ``registries`` (parameter
description path → registry), which the caller keeps; text a command streams while it
works (a patch, "3 fixes applied") goes through an :class:`Echo`.
"""

from __future__ import annotations

import os
from collections import Counter
from collections.abc import Callable, Iterable, Sequence

from zero import preload
from zero.diagnostics import Diagnostic, Severity
from zero.engine.config import one_resolution
from zero.engine.discovery import collect_files, skipped_note
from zero.engine.project import Project, Registries, common_of, open_project
from zero.engine.results import LintOptions, LintResult, is_unreadable
from zero.engine.selection import known_code, rule_table
from zero.errors import ZeroError
from zero.files import path_str, read_file, switched_on, write_atomic
from zero.forms import PROJECT_ROOTS, TWINCAT_ROOT, is_list, is_program, is_update, is_xml, walked_names
from zero.records import Record, field, replace

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TypeAlias

    from zero.catalog.registry import Registry

    FileName: TypeAlias = str | os.PathLike[str]  # a file as the engine names it (a Path from the library)

Progress = Callable[[int, int], None]


class Echo(Record):
    """Where a command's streamed text goes (standard output and error on the command line)."""

    out: Callable[[str], None]
    err: Callable[[str], None]
    out_bytes: Callable[[bytes], None]


def parse_codes(values: Sequence[str] | None) -> tuple[str, ...]:
    """Rule codes or prefixes, repeatable or comma-separated; each must match a rule."""
    out = tuple(c.strip().upper() for v in values or () for c in v.split(",") if c.strip())
    for c in out:
        if not known_code(c):  # ALL: every rule, as in ruff
            raise ZeroError(f"{c!r} matches no rule code (see `zero rule --all`)")
    return out


def parse_kind(kind: str | None) -> str | None:
    """A list kind by name or letters (``zero``, ``ZERO``); ``None`` detects it."""
    if kind is None:
        return None
    from zero.catalog.registry import KINDS, kind_from_name  # start-up: the catalogue only for --kind

    forced = kind_from_name(kind)
    if forced is None:
        import difflib  # start-up: only for a kind that is not known

        names = [name for name, _ in KINDS.values()]
        near = difflib.get_close_matches(kind.strip().lower(), names, n=1, cutoff=0.7)  # as the command line
        hint = f"; did you mean {near[0]}?" if near else ""
        raise ZeroError(f"unknown list kind {kind!r}{hint} (use one of: {', '.join(names)})")
    return forced


# ------------------------------------------------------------------------------ lint


class LintRequest(Record):
    """What ``zero lint`` was asked to do (option names as on the command line)."""

    paths: Sequence[str] = ()
    select: Sequence[str] = ()
    ignore: Sequence[str] = ()
    kind: str | None = None
    param_desc: FileName | None = None
    jobs: int | None = None
    config: FileName | Sequence[str] | None = None
    isolated: bool = False
    fix: bool = False
    show_diff: bool = False
    unsafe_fixes: bool = False
    stdin_filename: str | None = None
    machine: FileName | None = None
    extend_select: Sequence[str] = ()
    add_noqa: bool = False
    force_exclude: bool = True  # `exclude` drops files named on the command line too (--no-force-exclude: not)
    ignore_noqa: bool = False  # report what suppression directives hide (--ignore-noqa)
    # The results may come as a stream, each made as it is read: for a report written as it goes,
    # which then keeps no result (used only where the order and the results are the same).
    stream: bool = False
    cache: bool = False  # keep results between runs (zero.engine.cache; the command line's default, --no-cache)

    @property
    def reads_stdin(self) -> bool:
        paths = list(self.paths)
        return paths in ([], ["-"]) and (self.stdin_filename is not None or paths == ["-"])


class LintRun(Record):
    # A list, or with ``LintRequest.stream`` an iterator to read once (count with ``Totals``)
    results: Iterable[LintResult] = field(default_factory=list)
    report: bool = True  # False: nothing to report (standard input excluded by the configuration)
    findings_to_stderr: bool = False  # standard output holds the fixed list or the patch
    changed: int = 0  # files a fix changes (or, with --diff, would change)
    fixed: list[tuple[str, dict[str, int]]] = field(default_factory=list)  # per file written: fixes by code


def lint_files(named: Sequence[FileName], project: Project, force_exclude: bool = True,
               skipped: dict[str, int] | None = None) -> list[str]:
    """The files ``zero lint`` checks (``--show-files`` lists them): those named, and the list files
    below the directories, as each file's or directory's configuration includes and excludes them
    (a file named is excluded too unless ``force_exclude`` is false); ``skipped`` counts what a
    directory walk left out, by what (:func:`zero.engine.discovery.collect_files`)."""
    return collect_files(named, include=project.included, exclude=project.excluded,
                         respect_gitignore=project.respects_gitignore, force_exclude=force_exclude, skipped=skipped)


def run_lint(request: LintRequest, registries: Registries, echo: Echo,
             read_stdin: Callable[[], bytes], progress: Callable[[int], Progress | None] | None = None) -> LintRun:
    """``zero lint``: lint files, a machine or standard input; apply or show fixes."""
    with one_resolution():  # the files of a folder resolve it once (which patterns match them, settings)
        return _run_lint(request, registries, echo, read_stdin, progress)


def _run_lint(request: LintRequest, registries: Registries, echo: Echo,
              read_stdin: Callable[[], bytes], progress: Callable[[int], Progress | None] | None) -> LintRun:
    cli = LintOptions(select=parse_codes(request.select), ignore=parse_codes(request.ignore),
                      kind=parse_kind(request.kind), extend_select=parse_codes(request.extend_select),
                      ignore_noqa=request.ignore_noqa)
    project = open_project(registries, common_of(request.config, request.isolated, request.param_desc), cli=cli,
                           machine=request.machine)
    if request.machine is not None:
        return LintRun(_lint_machine(request, project))
    if request.reads_stdin:
        return _lint_stdin(request, project, echo, read_stdin())
    named = [path_str(p) for p in request.paths]  # files named as a Path prints them (./a.lis: a.lis)
    files = lint_files(named, project, request.force_exclude)
    if not files and any(os.path.isdir(p) for p in named):
        skipped: dict[str, int] = {}  # counted only here: walking an excluded folder costs a run nothing else
        lint_files(named, project, request.force_exclude, skipped)
        raise ZeroError(f"no list files or NC programs found (looked for {walked_names()}, XML files only where "
                        "they hold lists)" + skipped_note(skipped))
    cache = None  # results kept between runs (zero.engine.cache); never for a run that writes or shows fixes
    if request.cache and not (request.fix or request.show_diff or request.add_noqa or switched_on("ZERO_NO_CACHE")):
        from zero.engine.cache import open_lint_cache  # start-up: only when the cache is on

        cache = open_lint_cache(project)
    kept = cache.lookup(files) if cache is not None else {}
    todo = [f for f in files if f not in kept] if kept else files
    if todo:
        preload("check")  # what checking a list needs, at once, where its bundle is current (zero.bundles)
    groups: dict[FileName | None, list[str]] = {}
    for f in todo:  # files sharing a parameter description share a registry
        groups.setdefault(project.settings(f).param_desc, []).append(f)
    bar = progress(len(files)) if progress is not None else None

    across: dict[int, dict[str, list[Diagnostic]]] = {}  # the X findings of each machine, found once

    def finish(f: str, r: LintResult) -> LintResult:
        r = _with_machine(f, r, project, found=across)
        if cache is not None:
            cache.store(f, r)
        return r

    if (request.stream and bar is None and len(groups) <= 1
            and not (request.fix or request.show_diff or request.add_noqa)):
        desc = next(iter(groups), None)  # one group: its files are all the files to lint, in their order
        if todo:
            from zero.engine.parallel import iter_lint_many  # start-up: not for a cached run
        stream = iter_lint_many(todo, registries(desc), project.options, request.jobs) if todo else iter(())
        made = (finish(f, r) for f, r in zip(todo, stream, strict=True))
        if cache is None:
            return LintRun(made)
        return LintRun(cache.finishing(cache.merged(files, kept, made) if kept else made))
    by_file: dict[str, LintResult] = {}
    done = 0
    for desc, members in groups.items():
        from zero.engine.parallel import lint_many  # start-up: not for a cached run

        def step(n: int, total: int, base: int = done) -> None:
            if bar is not None:
                bar(base + n, len(files))

        for f, r in zip(members, lint_many(members, registries(desc), project.options, request.jobs,
                                           step if bar is not None else None), strict=True):
            by_file[f] = r
        done += len(members)
    results = [kept[f] if f in kept else finish(f, by_file[f]) for f in files]
    if cache is not None:
        cache.finish()
    run = LintRun(results, findings_to_stderr=request.show_diff)
    if request.add_noqa:
        run.results = [_add_noqa(f, r, project.settings(f).options, project.settings(f).registry, echo, run)
                       for f, r in zip(files, results, strict=True)]
        return run
    if request.fix or request.show_diff:
        run.results = [_fix_one(f, r, project.settings(f).options, project.settings(f).registry, request, echo, run)
                       for f, r in zip(files, results, strict=True)]
    return run


def _lint_machine(request: LintRequest, project: Project) -> list[LintResult]:
    """``--machine``: every list of the machine and the X rules, each list with its own configuration
    (selection, per-file ignores), plus the files named, checked against the machine."""
    from zero.engine.lint import (  # start-up: not for a cached run
        lint_file,
        lint_machine,
        lint_program,
        lint_update_in_machine,
        unreadable,
    )

    machine = project.machine(required=True)
    assert machine is not None and project.machine_given is not None
    results = lint_machine(machine, project.settings(project.machine_given).registry, project.options)
    for f in collect_files(request.paths, exclude=project.excluded,
                             respect_gitignore=project.respects_gitignore):
        settings = project.settings(f)
        if is_program(f):
            try:
                data = read_file(f)
            except ZeroError as exc:
                results.append(unreadable(str(f), exc, settings.options))
                continue
            results.append(lint_program(data, settings.registry, str(f), settings.options, machine))
            continue
        result = lint_file(f, settings.registry, settings.options)
        if not is_unreadable(result) and is_update(str(f)):  # an update: checked against the machine too
            in_machine = lint_update_in_machine(str(f), read_file(f), machine, settings.registry, settings.options)
            result = in_machine if in_machine is not None else result
        results.append(result)
    return results


def _with_machine(path: str, result: LintResult, project: Project, data: bytes | None = None,
                  found: dict[int, dict[str, list[Diagnostic]]] | None = None) -> LintResult:
    """A file of a project whose configuration names its machine, checked against it: an NC program
    (N003/N004), and a list the machine reads as ``zero lint --machine`` checks it (its kind, the X
    findings on it). ``found`` keeps each machine's X findings for the run."""
    if is_unreadable(result):
        return result
    program = is_program(path)
    if not program and (not is_list(path) or data is not None or project.startup(path) is None):
        return result  # standard input: not the file the machine reads
    try:
        machine = project.machine(path)
    except ZeroError:
        if program:
            raise  # the program's checks need it: said, as for a program named with --machine
        return result  # a list is checked as without a machine; `zero lint --machine` says why
    if machine is None:
        return result
    from zero.engine.lint import lint_in_machine, lint_program, machine_findings  # start-up: not for a cached run

    settings = project.settings(path)
    registry, options = settings.registry, settings.options
    if program:
        source = read_file(path) if data is None else data
        return lint_program(source, registry, str(path), options, machine)
    if found is None:
        found = {}
    across = found.get(id(machine))
    if across is None:
        across = found[id(machine)] = machine_findings(machine, registry, _every_code())
    linted = lint_in_machine(str(path), machine, registry, options, across=across)
    return linted if linted is not None else result


def _every_code() -> dict[str, Severity]:
    return {code: severity for code, (severity, _) in rule_table().items()}


def _lint_stdin(request: LintRequest, project: Project, echo: Echo, data: bytes) -> LintRun:
    """Standard input as the file ``--stdin-filename`` names: read as that file would be (a list,
    an NC program, YAML/TOML/JSON), its configuration applied. With ``--fix`` the fixed text goes
    to standard output, with ``--diff`` the patch; the findings then go to standard error."""
    from zero.engine.lint import lint_data  # start-up: not for a cached run

    name = request.stdin_filename or "-"
    passthrough = request.fix and not request.show_diff
    if name != "-" and project.excluded(path_str(name)):
        if passthrough:
            echo.out_bytes(data)
        return LintRun(report=False)
    settings = project.settings(path_str(name))
    options, registry = settings.options, settings.registry
    if (request.fix or request.show_diff) and is_list(name):
        from zero.engine.fixes import fix_bytes, unified_diff  # start-up: only with --fix/--diff

        fixed = fix_bytes(data, name, registry, options, request.unsafe_fixes)
        if request.show_diff:
            patch = unified_diff(name, data, fixed.fixed)
            echo.out_bytes(patch)
            return LintRun([lint_data(data, name, registry, options)], findings_to_stderr=True,
                           changed=int(bool(patch)))
        echo.out_bytes(fixed.fixed)
        return LintRun([fixed.result], findings_to_stderr=True, changed=int(fixed.fixed != data))
    result = lint_data(data, name, registry, options)
    result = _with_machine(path_str(name), result, project, data)
    if passthrough:
        echo.out_bytes(data)  # nothing to fix in an NC program or a structured file
    return LintRun([result], findings_to_stderr=request.fix or request.show_diff)


def _fix_one(path: str, result: LintResult, options: LintOptions, registry: Registry, request: LintRequest,
             echo: Echo, run: LintRun) -> LintResult:
    """Fix one list file: write it (``--fix``) or only show the patch (``--diff``, which never
    writes); return the findings that are left (with ``--diff``, the findings as they are)."""
    if not is_list(str(path)) or is_unreadable(result):
        return result  # findings in YAML/TOML/JSON and NC programs carry no list edits
    from zero.engine.fixes import fix_bytes, unified_diff  # start-up: only with --fix/--diff

    data = read_file(path)
    fixed = fix_bytes(data, str(path), registry, options, request.unsafe_fixes)
    if fixed.fixed == data:
        return result
    run.changed += 1
    if request.show_diff:
        echo.out_bytes(unified_diff(str(path), data, fixed.fixed))
        return result
    write_atomic(path, fixed.fixed, force=True)
    left = Counter(d.code for d in fixed.result.diagnostics)
    run.fixed.append((str(path), dict(Counter(d.code for d in result.diagnostics) - left)))
    echo.err(f"zero: {path}: {fixed.applied} fix{'es' if fixed.applied != 1 else ''} applied\n")
    return fixed.result


def _add_noqa(path: str, result: LintResult, options: LintOptions, registry: Registry, echo: Echo,
              run: LintRun) -> LintResult:
    """Record a list's findings as ``noqa`` directives; return what is still reported."""
    if not is_list(str(path)) or is_unreadable(result) or not result.diagnostics:
        return result
    from zero.engine.baseline import add_noqa  # start-up: only with --add-noqa
    from zero.engine.lint import lint_bytes  # start-up: as above

    data = read_file(path)
    if is_xml(data):
        return _add_noqa_xml(path, data, result, options, registry, echo, run)
    baseline = add_noqa(lint_bytes(data, registry, str(path), options))
    if baseline.added:
        write_atomic(path, baseline.data, force=True)
        run.changed += 1
        echo.err(f"zero: {path}: {baseline.added} noqa directive{'s' if baseline.added != 1 else ''} added\n")
    if baseline.unplaced:
        echo.err(f"zero: {path}: {baseline.unplaced} finding{'s' if baseline.unplaced != 1 else ''} on lines "
                 "without an entry cannot be recorded on their line\n")
    return lint_bytes(baseline.data, registry, str(path), options)


def _add_noqa_xml(path: str, data: bytes, result: LintResult, options: LintOptions, registry: Registry,
                  echo: Echo, run: LintRun) -> LintResult:
    """``--add-noqa`` on XML: the lists of a TwinCAT export get their directives inside their CDATA
    sections (every other byte kept); an XML list has no list comments to hold them and is left as it is."""
    from zero.engine.baseline import add_noqa  # start-up: only with --add-noqa
    from zero.engine.lint import lint_data, lint_document  # start-up: as above
    from zero.markup.documents import embedded_documents, splice  # start-up: only for XML
    from zero.markup.safe import scan  # start-up: as above

    try:
        sc = scan(data, str(path))
    except ZeroError:
        return result
    if sc.root != TWINCAT_ROOT and sc.root not in PROJECT_ROOTS:  # not an export or a project
        echo.err(f"zero: {path}: --add-noqa writes list comments, which an XML list has no place for: not changed "
                 "(per-file-ignores in the configuration suppress its findings)\n")
        return result
    texts, added = [], 0
    for item in embedded_documents(data, str(path), sc)[1]:
        baseline = add_noqa(lint_document(replace(item.doc, origin=None), registry, options))  # its own lines
        if baseline.added:
            added += baseline.added
            texts.append((item, baseline.data.decode(item.doc.encoding, "surrogateescape")))
    new = splice(sc, str(path), texts) if texts else data
    if added:
        write_atomic(path, new, force=True)
        run.changed += 1
        echo.err(f"zero: {path}: {added} noqa directive{'s' if added != 1 else ''} added\n")
    return lint_data(new, str(path), registry, options)


__all__ = ["Echo", "LintRequest", "LintRun", "Registries", "parse_codes", "parse_kind", "run_lint"]

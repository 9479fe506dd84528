"""The cache of ``zero lint`` and ``zero diff --fleet``: results kept between runs, as ruff's.

**What it keeps.** Per file linted, the findings (codes, spans, messages, fixes, related places,
consequences, sources), the lines they show, the list kind and the note; per machine of a fleet,
what it differs in from the golden machine. They are kept in the cache folder (see
:func:`cache_folder`: ``.zero_cache/`` in the folder of the configuration that applies to the
current directory, else the current directory; ``$ZERO_CACHE_DIR``), which holds a ``.gitignore``
of its own (``*``) and a ``CACHEDIR.TAG``, one file per entry.

**When it is trusted.** An entry's name is a hash of everything that decides the result, so that
a change to any of them is a miss, never a stale hit:

* zero itself (:func:`generation`): its version, the Python that runs it, and in a development
  install the size and modification time of every file of zero's own source (an edited rule never
  gets a result of the rule before);
* the file: its path as given and a hash of its content (read through :func:`zero.files.read_file`,
  so a file that cannot be read now is read again, and reported, never answered from the cache);
* the options the resolver gives the file (:meth:`zero.engine.project.Project.options`: selection,
  severities, per-file ignores, kind, code page, kernel release, ``--ignore-noqa``; every field of
  the record, fingerprinted whatever fields it gains: :func:`fingerprint`);
* the catalogue (:func:`catalogue_id`): the built-in table (part of zero), or the parameter
  description's path and a hash of its content;
* for a list of a machine (the X findings on it, its kind as the start-up list reads it) and for
  a fleet's machine: the machine's configuration (start-up list, list overrides, working directory,
  folder mapping, forced kind, the current directory) in the name, and in the entry the machine's
  files (:func:`machine_deps`): every list it read or looked for (size, modification time and a
  hash of the content, checked again by content where the time is too recent to tell, as git
  does with its index), the folders that hold them (a list added or removed), and every place the
  working directory and the project's ceiling are looked for.

**What it never keeps.** Standard input, a file that could not be read or that zero refused
(F001, S014/S017 "not checked"), NC programs (they read the subprograms of their folder), a
machine that could not be read, and anything of a run with ``--fix``, ``--diff`` or ``--add-noqa``.

**Safe.** Entries are written through :func:`zero.files.write_disposable` (a temporary file, then
renamed), so concurrent runs each see whole entries; each entry carries a checksum, and an entry
that is torn, garbage or of another format is a miss. The folder is bounded (:data:`MAX_ENTRIES`,
:data:`MAX_BYTES`): past either, the oldest entries go (:meth:`Store.prune`; looked at by the first
entry a run writes, at most every :data:`PRUNE_EVERY` seconds, and every quarter of the bound a
run writes), and at most :data:`GENERATIONS` versions of zero keep entries. ``--no-cache`` and
``ZERO_NO_CACHE=1`` switch it off; a folder that cannot be written is the same as none.

The format is :mod:`marshal` of plain tuples (measured against :mod:`json`: loading is about
3× faster, writing 2×, see docs/performance.md); only this module reads it.
"""

from __future__ import annotations

import contextlib
import marshal
import os
import sys
import time
from collections.abc import Callable, Iterable, Iterator, Sequence

from zero import __version__
from zero.diagnostics import Diagnostic, Edit, Fix, Related, Severity, Span
from zero.engine.results import LintOptions, LintResult
from zero.errors import ZeroError
from zero.files import content_digest, max_file_bytes, read_as_is, read_file, switched_on, write_disposable
from zero.forms import CONFIG_NAMES, controller_absolute, is_list, is_program, split_part
from zero.lists.model import Document, Excerpt
from zero.records import fields

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: a plain lint loads no machine model (nor pathlib: files are named by their text)
    from typing import Any, TypeAlias

    from zero.engine.project import Project
    from zero.machine.model import Machine

    FileName: TypeAlias = str | os.PathLike[str]  # a file as the engine names it (a Path from the library)

FOLDER = ".zero_cache"
FORMAT = 2  # of an entry; a new one makes every entry of the old one a miss
MAX_ENTRIES = 50_000  # past this many entries, the oldest go (to three quarters of it)
MAX_BYTES = 512 * 1024 * 1024  # the same for their size
PRUNE_EVERY = 600  # seconds between two looks at the folder's size by runs that keep few entries
GENERATIONS = 4  # versions of zero whose entries are kept side by side
RACY_NS = 3_000_000_000  # a file modified this close to when it was checked is checked by its content
INDEX_RACY_NS = RACY_NS  # the same for a file's record in a run's index (by its modification or change time)
_MAGIC = b"ZEROCACHE\n"
_DIGEST = 16  # the bytes of files.content_digest
_TAG = (b"Signature: 8a477f597d28d172789f06886806bc55\n"
        b"# This file is a cache directory tag created by zero.\n"
        b"# For information about cache directory tags see https://bford.info/cachedir/\n")
_IGNORE = b"# Automatically created by zero.\n*\n"

# The fields a stored finding has: a record that gains one is not cached until this module keeps it.
_DIAGNOSTIC_FIELDS = ("code", "severity", "message", "span", "path", "param_id", "fix", "hint", "related",
                      "kernel_error", "consequence", "source")
_RESULT_FIELDS = ("path", "document", "kind", "diagnostics", "note")


def disabled() -> bool:
    """``ZERO_NO_CACHE`` set to anything but ``0``, ``false``, ``no``, ``off`` or nothing."""
    return switched_on("ZERO_NO_CACHE")


def digest(data: bytes) -> bytes:
    return content_digest(data)


# ----------------------------------------------------------------------------- keys


def _source_files(folder: str, out: list[tuple[str, int, int]]) -> None:
    with os.scandir(folder) as it:
        for e in it:
            if e.is_dir(follow_symlinks=False):
                if e.name != "__pycache__":
                    _source_files(e.path, out)
            elif not e.name.endswith((".pyc", ".pyo")):
                st = e.stat()
                out.append((e.path, st.st_size, st.st_mtime_ns))


_generation: list[str] = []


def generation() -> str:
    """What zero itself contributes to every key: its version, the cache's format, the Python that
    runs it, and (in a development install, where the source can be edited) every file of zero's
    source by size and modification time. Found once per process."""
    if _generation:
        return _generation[0]
    package = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parts: list[object] = [FORMAT, __version__, sys.implementation.cache_tag, sys.version, package]
    parts_of_package = package.replace(os.altsep, os.sep).split(os.sep) if os.altsep else package.split(os.sep)
    if not any(p in ("site-packages", "dist-packages") for p in parts_of_package):
        files: list[tuple[str, int, int]] = []
        with contextlib.suppress(OSError):
            _source_files(package, files)
        parts.append(tuple(sorted(files)))
    _generation.append(digest(repr(parts).encode("utf-8", "surrogateescape")).hex())
    return _generation[0]


_tuples: dict[int, tuple[object, object]] = {}


def _canonical(value: object) -> object:
    """``value`` as nested tuples of plain values whose ``repr`` is the same in every run."""
    kind = type(value)
    if kind is str or kind is int or value is None or kind is bytes:
        return value
    if kind is tuple:
        seen = _tuples.get(id(value))  # a selection the files of a run share: looked at once
        if seen is not None and seen[0] is value:
            return seen[1]
        items: tuple[object, ...] = value  # type: ignore[assignment]
        out = items if all(type(v) is str for v in items) else tuple(_canonical(v) for v in items)
        if len(_tuples) > 4096:
            _tuples.clear()
        _tuples[id(value)] = (value, out)  # the tuple kept with it: its identity is no other's
        return out
    if kind is list:
        return _canonical(tuple(value))  # type: ignore[arg-type]
    if kind is bool or kind is float:  # tagged: 1, 1.0 and True are equal keys of a dict
        return (kind.__name__, repr(value))
    if isinstance(value, dict):
        return ("dict", tuple(sorted(((_canonical(k), _canonical(v)) for k, v in value.items()), key=repr)))
    if getattr(kind, "__record_fields__", None) is not None:
        return (kind.__qualname__, tuple((f.name, _canonical(getattr(value, f.name))) for f in fields(value)))
    if isinstance(value, Severity):  # as the enum member it was: its class and name
        return (kind.__name__, value.name)
    enum = sys.modules.get("enum")  # start-up: a value is an enum only where enum was imported
    if enum is not None and isinstance(value, enum.Enum):
        return (kind.__name__, value.name)
    if isinstance(value, os.PathLike):
        return ("path", os.fspath(value))
    if isinstance(value, (set, frozenset)):
        return ("set", tuple(sorted((_canonical(v) for v in value), key=repr)))
    if isinstance(value, (tuple, list)):  # a subclass (a NamedTuple, ...): its items, tagged with its class
        return (kind.__qualname__, tuple(_canonical(v) for v in value))
    if isinstance(value, (str, int, float)):  # a subclass: its plain value, tagged with its class
        return (kind.__qualname__, repr(value))
    raise TypeError(f"cannot fingerprint {kind.__name__}")


def fingerprint(value: object) -> str:
    """A deterministic fingerprint of a settings object (a record such as ``LintOptions``, with every
    field it has, nested records, tuples, dictionaries, enumerations, paths): equal settings give
    equal fingerprints in every run. :class:`TypeError` for a value it cannot fingerprint."""
    canonical = _canonical(value)
    hit = _fingerprints.get(canonical)  # the files of a run share a few settings: each hashed once
    if hit is None:
        if len(_fingerprints) > 4096:
            _fingerprints.clear()
        hit = _fingerprints[canonical] = digest(repr(canonical).encode("utf-8", "surrogateescape")).hex()
    return hit


_fingerprints: dict[object, str] = {}


def catalogue_id(param_desc: FileName | None) -> tuple[str, ...]:
    """The identity of a catalogue: the built-in table (part of zero, so in :func:`generation`),
    or a parameter description by its absolute path and the hash of its content."""
    if param_desc is None:
        return ("built-in",)
    data = read_file(param_desc)
    return ("description", os.path.abspath(param_desc), digest(data).hex())


def cache_folder(project: Project) -> str:
    """``$ZERO_CACHE_DIR``, else ``.zero_cache`` in the folder of the configuration that applies to the
    current directory (the project's root, as ruff's ``.ruff_cache``), else in the current directory
    (absolute)."""
    given = os.environ.get("ZERO_CACHE_DIR", "").strip()
    if given:
        return os.path.abspath(given)
    own = project.config(None).path  # Config.root without pathlib
    return os.path.join(os.path.abspath(os.path.dirname(own) if own is not None else os.curdir), FOLDER)


# ----------------------------------------------------------------------------- the folder


class Store:
    """The cache folder: entries by name, each a checksummed :mod:`marshal` payload."""

    def __init__(self, folder: FileName) -> None:
        self.folder = os.fspath(folder)
        self.entries = os.path.join(self.folder, generation()[:20])
        self.ready: bool | None = None  # None: not yet made; False: cannot be written
        self.written = 0

    def path(self, key: str) -> str:
        return os.path.join(self.entries, key)

    def get(self, key: str) -> Any:
        """The value stored under ``key``; ``None`` when there is none, or it is torn or garbage."""
        try:
            with open(os.path.join(self.entries, key), "rb") as f:
                data = f.read()
        except OSError:
            return None
        head = len(_MAGIC) + _DIGEST
        if len(data) < head or not data.startswith(_MAGIC) or digest(data[head:]) != data[len(_MAGIC):head]:
            return None
        try:
            return marshal.loads(data[head:])
        except (EOFError, ValueError, TypeError):  # pragma: no cover - the checksum matched
            return None

    def put(self, key: str, value: Any) -> bool:
        """Store ``value`` (plain values only) under ``key``; ``False`` when it cannot be."""
        if not self._ready():
            return False
        try:
            payload = marshal.dumps(value, 4)
        except ValueError:  # a value marshal does not keep: not cached
            return False
        if self.written % max(1, MAX_ENTRIES // 4) == 0 and (self.written or self._due()):
            self.prune()
        try:
            write_disposable(os.path.join(self.entries, key), _MAGIC + digest(payload) + payload)
        except OSError:
            return False
        self.written += 1
        return True

    def _ready(self) -> bool:
        if self.ready is None:
            try:
                if not os.path.isdir(self.entries):  # a new zero (or an edited one): the oldest others' go
                    os.makedirs(self.entries, exist_ok=True)
                    self._drop_generations()
                for name, text in ((".gitignore", _IGNORE), ("CACHEDIR.TAG", _TAG)):
                    if not os.path.lexists(os.path.join(self.folder, name)):
                        write_disposable(os.path.join(self.folder, name), text)
                self.ready = os.access(self.entries, os.W_OK)
            except OSError:
                self.ready = False
        return self.ready

    def _due(self) -> bool:
        """Is the folder's size to be checked (at most every :data:`PRUNE_EVERY` seconds, so that a run
        that keeps one entry does not list them all)? Marks it checked."""
        marker = os.path.join(self.folder, ".pruned")
        try:
            if time.time() - os.stat(marker).st_mtime < PRUNE_EVERY:
                return False
        except OSError:
            pass
        with contextlib.suppress(OSError):
            write_disposable(marker, b"")
        return True

    def _drop_generations(self) -> None:
        """Keep the entries of at most :data:`GENERATIONS` versions of zero (the newest, by when their
        folder last changed): a development install makes one whenever its source is edited."""
        import shutil  # start-up: only when a new version of zero writes its first entry

        with contextlib.suppress(OSError):
            others = sorted((e.stat(follow_symlinks=False).st_mtime_ns, e.path) for e in os.scandir(self.folder)
                            if e.is_dir(follow_symlinks=False) and e.path != self.entries)
            for _, path in others[:max(0, len(others) - (GENERATIONS - 1))]:
                shutil.rmtree(path, ignore_errors=True)

    def prune(self) -> int:
        """Keep the folder within :data:`MAX_ENTRIES` and :data:`MAX_BYTES`: past either, remove the
        oldest entries (by when they were written, of every generation of zero) down to three quarters
        of the bound, and temporary files an hour old. Returns how many files went."""
        found: list[tuple[int, int, str]] = []
        old = time.time_ns() - 3600 * 10**9
        removed = 0
        try:
            generations = [e.path for e in os.scandir(self.folder) if e.is_dir(follow_symlinks=False)]
        except OSError:
            return 0
        for g in generations:
            with contextlib.suppress(OSError), os.scandir(g) as it:
                for e in it:
                    with contextlib.suppress(OSError):
                        st = e.stat(follow_symlinks=False)
                        if e.name.endswith(".tmp"):
                            if st.st_mtime_ns < old:
                                os.unlink(e.path)
                                removed += 1
                            continue
                        found.append((st.st_mtime_ns, st.st_size, e.path))
        total = sum(size for _, size, _ in found)
        if len(found) <= MAX_ENTRIES and total <= MAX_BYTES:
            return removed
        found.sort()
        count, keep_count, keep_bytes = len(found), MAX_ENTRIES * 3 // 4, MAX_BYTES * 3 // 4
        for _, size, path in found:
            if count <= keep_count and total <= keep_bytes:
                break
            with contextlib.suppress(OSError):
                os.unlink(path)
                removed += 1
            count, total = count - 1, total - size
        for g in generations:
            if g != self.entries:
                with contextlib.suppress(OSError):
                    os.rmdir(g)  # an older zero's folder, once empty
        return removed


def open_store(project: Project) -> Store | None:
    """The cache of a run, or ``None`` where ``ZERO_NO_CACHE`` switches it off."""
    if disabled():
        return None
    return Store(cache_folder(project))


# ----------------------------------------------------------------------------- dependencies

# What a machine read or looked for: ("f", path, size, mtime, code page) for a file (size -1:
# absent), ("d", path, mtime) for a folder, ("e", path, exists) for a place looked at.
Dep = tuple["Any", ...]  # (a string: typing is not imported at run time)


class Checker:
    """Checks stored dependencies against the file system, each path once per run."""

    def __init__(self, encoding: Callable[[str], str | None]) -> None:
        self.encoding = encoding
        self._stat: dict[str, os.stat_result | None] = {}
        self._codecs: dict[str, str | None] = {}

    def stat(self, path: str) -> os.stat_result | None:
        if path not in self._stat:
            try:
                self._stat[path] = os.stat(path)
            except (OSError, ValueError):
                self._stat[path] = None
        return self._stat[path]

    def _codec(self, path: str) -> str | None:
        codec = self._codecs[path] = self.encoding(path)
        return codec

    def holds(self, deps: Iterable[Dep]) -> bool:
        """Is every dependency as it was?"""
        for dep in deps:
            tag, path = dep[0], dep[1]
            st = self.stat(path)
            if tag == "e":
                if (st is not None) != dep[2]:
                    return False
            elif tag == "f":
                if (st is None and dep[2] != -1) or (st is not None and (st.st_size != dep[2]
                                                                         or st.st_mtime_ns != dep[3])):
                    return False
                if (self._codecs[path] if path in self._codecs else self._codec(path)) != dep[4]:
                    return False
            elif tag != "d" or st is None or st.st_mtime_ns != dep[2]:
                return False
        return True


def settled(deps: Iterable[Dep], started: int) -> bool:
    """Were all the files and folders last changed well before ``started`` (when the run began)?
    Only then is what was read from them surely what their size and time now describe: a file
    changed while the run read it, or in the same tick of a coarse clock, is left to the next run."""
    return all(dep[0] == "e" or dep[3 if dep[0] == "f" else 2] < started - RACY_NS for dep in deps)


def machine_deps(machine: Machine, encoding: Callable[[str], str | None]) -> tuple[Dep, ...]:
    """What a machine depends on: every list it read or looked for (the start-up list, each list it
    names, found or not; for a start-up list that is no list file, every file of its folder), the
    folders that hold them (a file added or removed), the places its working directory is looked
    for (the start-up list's folder and the ancestors above it, each joined with each path the
    start-up list names) and the places the project's ceiling is looked for (``.git`` and the
    configuration files in every folder above it)."""
    from zero.machine.model import MAX_ANCESTORS  # start-up: only with a machine

    startup = split_part(machine.startup.path)[0]
    files = [startup, *(split_part(n.path)[0] for n in machine.named if n.path is not None)]
    if not is_list(startup):  # an export or a project: the other files of its folder may hold its lists
        with contextlib.suppress(OSError):
            folder = os.path.dirname(os.path.abspath(startup))
            files += sorted(e.path for e in os.scandir(folder) if e.is_file())
    out: list[Dep] = []
    folders: dict[str, None] = {}
    for f in dict.fromkeys(os.path.abspath(p) for p in files):
        folders[os.path.dirname(f)] = None
        try:
            st = os.stat(f)
            out.append(("f", f, st.st_size, st.st_mtime_ns, encoding(f)))
        except OSError:
            out.append(("f", f, -1, -1, encoding(f)))
    for d in folders:
        try:
            out.append(("d", d, os.stat(d).st_mtime_ns))
        except OSError:
            out.append(("e", d, False))
    raws = [r for r in (n.raw.strip().strip('"').replace("\\", "/") for n in machine.named)
            if r and not controller_absolute(r)]
    above = [os.path.dirname(os.path.abspath(startup))]  # the start-up list's folder and every one above it
    while os.path.dirname(above[-1]) != above[-1]:
        above.append(os.path.dirname(above[-1]))
    for n, d in enumerate(above):
        if n <= MAX_ANCESTORS + 1:
            out.extend(("e", os.path.join(d, r), os.path.exists(os.path.join(d, r))) for r in raws)
        out.extend(("e", os.path.join(d, m), os.path.exists(os.path.join(d, m))) for m in (".git", *CONFIG_NAMES))
    return tuple(out)


# ----------------------------------------------------------------------------- lint results


def _span(s: Span) -> tuple[int, int, int, int]:
    return (s.line, s.column, s.end_line, s.end_column)


def _fix(f: Fix | None) -> tuple[Any, ...] | None:
    if f is None:
        return None
    return (f.title, f.safe, tuple((*_span(e.span), e.replacement) for e in f.edits))


def _shared(value: Any, shared: dict[Any, Any] | None) -> Any:
    """The object equal to ``value`` in ``shared`` (the parts packed before), else ``value`` (kept there)."""
    if shared is None:
        return value
    try:
        hit = shared.get(value)
        if hit is None:
            hit = shared[value] = value
    except TypeError:  # pragma: no cover - what pack_result makes is hashable
        return value
    return hit


_OWN = 0  # a packed finding's (or related place's) file where it is the result's (a file is a str or None)


def pack_result(r: LintResult, shared: dict[Any, Any] | None = None) -> tuple[Any, ...]:
    """A lint result as plain tuples: the findings with everything they say, and of the document
    only the lines they show (as many-file runs keep them). A finding's file is :data:`_OWN` where
    it is the result's, so that lists of equal content pack equal findings; with ``shared`` (a run's:
    what it packed before), equal findings and shown lines are one object, which :mod:`marshal` writes
    once in a run's index and refers to after that (a fleet's lists repeat each other's findings: the
    index of 300 machines' 6,300 lists, 21 contents, half the size and a quarter of the time to load)."""
    doc = r.document
    own = r.path
    lines: dict[int, str] = {}
    diagnostics = []
    for d in r.diagnostics:
        for n in (d.span.line, d.span.end_line):
            if n not in lines and doc.has_line(n):
                lines[n] = doc.line_text(n)
        diagnostics.append((d.code, int(d.severity), d.message, _span(d.span), _OWN if d.path == own else d.path,
                            d.param_id, _fix(d.fix), d.hint,
                            tuple((_span(x.span), x.message, _OWN if x.path == own else x.path) for x in d.related),
                            d.kernel_error, d.consequence, d.source))
    shown = (doc.path, doc.encoding, doc.bom, doc.end_line, _shared(tuple(sorted(lines.items())), shared))
    return (r.path, r.kind, r.note, shown, _shared(tuple(diagnostics), shared))


_SEVERITIES = {int(s): s for s in Severity}  # a stored severity → its member (a look-up, not an enum call)


def unpack_result(packed: tuple[Any, ...], made: dict[int, tuple[object, Any]] | None = None) -> LintResult:
    """:func:`pack_result` undone. ``made``: the findings unpacked before, by the identity of their
    packed tuple (kept with it), as their fields with the span and fix made, whatever their file: the results
    of a run's index share them (:func:`pack_result`)."""
    path, kind, note, (doc_path, encoding, bom, end_line, lines), found = packed
    doc: Document = Excerpt(doc_path, encoding, [], [], [], [], bom, end_line, shown=dict(lines))
    hit = made.get(id(found)) if made is not None else None
    if hit is not None and hit[0] is found:
        parts = hit[1]
    else:
        severities = _SEVERITIES
        parts = [(code, severities.get(severity) or Severity(severity), message, Span(*span), where, param_id,
                  None if fix is None else Fix(fix[0], tuple(Edit(Span(*e[:4]), e[4]) for e in fix[2]), fix[1]),
                  hint, related, kernel_error, consequence, source)
                 for (code, severity, message, span, where, param_id, fix, hint, related, kernel_error, consequence,
                      source) in found]
        if made is not None:
            made[id(found)] = (found, parts)
    diagnostics = [
        Diagnostic(code, severity, message, span, path if where is _OWN else where, param_id, fix, hint,
                   tuple([Related(Span(*s), m, path if p is _OWN else p) for s, m, p in related]) if related else (),
                   kernel_error, consequence, source)
        for (code, severity, message, span, where, param_id, fix, hint, related, kernel_error, consequence,
             source) in parts]
    return LintResult(path, doc, kind, diagnostics, note)


def _records_known() -> bool:
    """Do the result and finding records have exactly the fields this module keeps?"""
    return (tuple(f.name for f in fields(Diagnostic)) == _DIAGNOSTIC_FIELDS
            and tuple(f.name for f in fields(LintResult)) == _RESULT_FIELDS)


def refused_or_unreadable(r: LintResult) -> bool:
    """A result about a file zero could not read or would not read (never kept)."""
    return any(d.code == "F001" or (d.code in ("S014", "S017") and d.message.endswith("not checked"))
               for d in r.diagnostics)


def _stat(st: os.stat_result) -> tuple[int, int, int, int]:
    """What a file's ``os.stat`` says of its content, as git's index keeps it: size, modification and
    change times, inode (a rename over it, a ``touch -d`` back in time, a ``chmod``: each differs)."""
    return (st.st_size, st.st_mtime_ns, st.st_ctime_ns, st.st_ino)


class LintCache:
    """``zero lint``'s results by file, for one run: :meth:`lookup` before linting, :meth:`store` after,
    :meth:`finish` (or :meth:`finishing`) once every result is made.

    Besides an entry per file, a run keeps an index of its files (one entry named by the list of
    files and the current directory): per file its stat (:func:`_stat`), the hash of its content,
    its entry's name, its result and what of its settings the name holds (:meth:`_part`). The same run
    again reads that one entry, not the files: a file whose stat is the one recorded has the content
    whose hash was recorded (recorded only for a file last changed :data:`RACY_NS` before the run that
    read it, as git's index does), and its result is used only where today's settings give the
    recorded part (and so the recorded name). Any other file is read, hashed and looked up as without
    the index."""

    def __init__(self, store: Store, project: Project) -> None:
        self.disk = store
        self.project = project
        self.checker = Checker(project.encoding)
        self.started = time.time_ns()  # before anything is read
        self.cwd = os.getcwd()
        # file → (entry name, its machine's name, its stat before it was read, the hash of its content, _part)
        self._keys: dict[FileName, tuple[str, str | None, tuple[int, int, int, int], str,
                                         tuple[str, tuple[str, ...], str | None]]] = {}
        self._catalogues: dict[FileName | None, tuple[str, ...]] = {}
        self._fingerprints: dict[int, tuple[object, str]] = {}
        self._holds: dict[str, bool] = {}  # a machine's name → do its files hold
        self._deps: dict[str, tuple[Dep, ...] | None] = {}  # a machine's name → its files (None: not settled)
        self._index_key: str | None = None  # the name of this run's index (None: none kept)
        self._index: dict[str, tuple[Any, ...]] = {}  # as read: file → (*stat, content hash, entry name, value, _part)
        self._indexed: dict[str, tuple[Any, ...]] = {}  # as it is to be written
        self._shared: dict[Any, Any] = {}  # the parts of the results this run packed, each once (pack_result)
        self._index_same = True  # is what is to be written what was read?
        self.hits = 0
        self.on = _records_known()

    def _options(self, path: FileName, options: LintOptions | None = None) -> str:
        """The fingerprint of a file's options (``options``: as its settings give them), found once per
        options object (the files of a folder share one; the object is kept with it, so its identity is
        not another's)."""
        if options is None:
            options = self.project.options(path)
        hit = self._fingerprints.get(id(options))
        if hit is None or hit[0] is not options:
            hit = self._fingerprints[id(options)] = (options, fingerprint(options))
        return hit[1]

    def _catalogue(self, desc: FileName | None) -> tuple[str, ...]:
        hit = self._catalogues.get(desc)
        if hit is None:
            hit = self._catalogues[desc] = catalogue_id(desc)
        return hit

    def _machine_part(self, path: FileName) -> tuple[object, ...] | None:
        """What of a machine decides a list's findings (its files are checked from the entry)."""
        startup = self.project.startup(path)
        if startup is None:
            return None
        cfg = self.project.config(startup)
        own = self.project.config(path)
        return (str(startup), str(self.project.machine_shown or own.machine), self.cwd, self.project.cli.kind,
                _canonical(cfg.machine), _canonical(cfg.machine_lists), _canonical(cfg.machine_workdir),
                _canonical(cfg.machine_roots))

    def key(self, path: FileName, data: bytes | str) -> tuple[str, str | None]:
        """The entry name of a file as read now (``data``: its bytes, or the hex hash of them), and
        that of its machine (``None``: it has none). :class:`TypeError` where the options cannot be
        fingerprinted, :class:`ZeroError` where the catalogue cannot be read."""
        part = self._part(path)
        return self._name(path, data if isinstance(data, str) else digest(data).hex(), part), part[2]

    def _part(self, path: FileName) -> tuple[str, tuple[str, ...], str | None]:
        """What of a file's settings its entry's name holds besides the file's name and content: the
        fingerprints of its options, its catalogue and its machine (``None``: it has none)."""
        settings = self.project.settings(path)  # one look-up for the options, the catalogue and the machine
        # no machine where neither --machine nor the configuration names a start-up list (Project.startup)
        named = self.project.machine_given is not None or settings.config.machine is not None
        machine = self._machine_part(path) if named and is_list(path) else None
        return (self._options(path, settings.options), self._catalogue(settings.param_desc),
                None if machine is None else fingerprint(machine))

    @staticmethod
    def _name(path: FileName, content: str, part: tuple[str, tuple[str, ...], str | None]) -> str:
        """The entry name of a file by its name, the hash of its content and :meth:`_part`."""
        parts = (generation(), "lint", str(path), content, *part)
        # plain strings (and a tuple of them, and None) are their own canonical form: the name is
        # fingerprint(parts), without walking them (`test_the_entry_name_is_the_fingerprint_of_its_parts`)
        return digest(repr(parts).encode("utf-8", "surrogateescape")).hex()

    def _open_index(self, files: Sequence[FileName]) -> None:
        self._index_key = "run-" + fingerprint((generation(), "index", self.cwd, tuple(str(f) for f in files)))
        value = self.disk.get(self._index_key)
        if type(value) is dict:
            self._index = value
        self._index_same = type(value) is dict

    def _known(self, name: str, st: os.stat_result, now: tuple[int, int, int, int], limit: int
               ) -> tuple[Any, ...] | None:
        """The file's record in the index, where its stat (``now``: :func:`_stat` of ``st``) is the one recorded."""
        rec = self._index.get(name)
        if type(rec) is not tuple or len(rec) != 8 or rec[:4] != now or not read_as_is(st, limit):
            return None
        return rec

    def lookup(self, files: Iterable[FileName]) -> dict[FileName, LintResult]:
        """The files whose results are kept and still hold, with them."""
        out: dict[FileName, LintResult] = {}
        if not self.on:
            return out
        files = list(files)
        self._open_index(files)
        limit = max_file_bytes()
        made: dict[int, tuple[object, Any]] = {}
        for f in files:
            if is_program(f):
                continue
            name = str(f)
            try:
                st = os.stat(f)
                now = _stat(st)
                rec = self._known(name, st, now, limit)
                content = rec[4] if rec is not None else digest(read_file(f)).hex()
                part = self._part(f)
            except (OSError, ZeroError, TypeError):
                continue
            # a file the index holds with the content and settings of now has the entry name it recorded (the
            # name is made of them and the file's name): not made again (a hash per file, a sixth of a run
            # that the cache answers)
            kept = rec if rec is not None and rec[7] == part else None
            if kept is not None:
                key, value = kept[5], kept[6]
            else:
                key = self._name(f, content, part)
                value = rec[6] if rec is not None and rec[5] == key else self.disk.get(key)
            machine = part[2]
            self._keys[f] = (key, machine, now, content, part)
            if value is None:
                continue
            try:
                packed, deps = value
                if machine is not None:
                    holds = self._holds.get(machine)
                    if holds is None:
                        holds = self._holds[machine] = self.checker.holds(deps)
                    if not holds:
                        continue
                out[f] = unpack_result(packed, made)
            except (TypeError, ValueError, KeyError, IndexError):
                continue
            self._note(name, kept or (*now, content, key, value, part), rec)
        self.hits = len(out)
        return out

    def _note(self, name: str, record: tuple[Any, ...], before: tuple[Any, ...] | None) -> None:
        """Keep a file's record for the index; not for a file changed too recently to tell by its stat:
        by its modification time or its change time (which no one sets back: a file rewritten and
        given its old modification time within a tick of the clock has its change time of now)."""
        if max(record[1], record[2]) >= self.started - INDEX_RACY_NS:
            self._index_same = False
            return
        self._indexed[name] = record
        if before is None or before[5] != record[5] or before[6] is not record[6]:
            self._index_same = False

    def store(self, path: FileName, result: LintResult) -> None:
        """Keep a file's result (the one reported: its machine's findings included), unless it is one
        never kept, or the file (or a list of its machine) changed while the run read it or too
        recently to tell; a failure to keep it is silent (the next run lints the file again)."""
        known = self._keys.get(path)
        if known is None or not self.on or refused_or_unreadable(result):
            self._index_same = False
            return
        key, machine_key, before, content, part = known
        try:
            st = os.stat(path)
        except OSError:
            return
        if _stat(st) != before or st.st_mtime_ns >= self.started - RACY_NS:
            self._index_same = False
            return
        deps: tuple[Dep, ...] | None = ()
        if machine_key is not None:
            deps = self._machine_deps(path, machine_key)
            if deps is None:
                self._index_same = False
                return
        with contextlib.suppress(ValueError, TypeError):
            value = (pack_result(result, self._shared), deps)
            if self.disk.put(key, value):
                self._note(str(path), (*before, content, key, value, part), None)
                return
        self._index_same = False

    def finish(self) -> None:
        """Write this run's index, where it is not the one read (every result made and kept)."""
        if self._index_key is not None and self._indexed and not (self._index_same
                                                                  and len(self._indexed) == len(self._index)):
            self.disk.put(self._index_key, self._indexed)
        self._index_key = None

    def finishing(self, results: Iterator[LintResult]) -> Iterator[LintResult]:
        """``results`` as they come, then :meth:`finish` (not when they stop half way)."""
        yield from results
        self.finish()

    def _machine_deps(self, path: FileName, machine_key: str) -> tuple[Dep, ...] | None:
        if machine_key not in self._deps:
            try:
                machine = self.project.machine(path)
            except ZeroError:
                machine = None
            deps = machine_deps(machine, self.project.encoding) if machine is not None else None
            self._deps[machine_key] = deps if deps is not None and settled(deps, self.started) else None
        return self._deps[machine_key]

    def merged(self, files: Sequence[FileName], hits: dict[FileName, LintResult],
               made: Iterator[LintResult]) -> Iterator[LintResult]:
        """The results in the order of ``files``: kept ones from ``hits``, the others from ``made``
        (made in the order of the files not in ``hits``)."""
        for f in files:
            hit = hits.get(f)
            yield hit if hit is not None else next(made)


def open_lint_cache(project: Project) -> LintCache | None:
    """The lint cache of a run (``None``: switched off by ``ZERO_NO_CACHE``)."""
    store = open_store(project)
    return LintCache(store, project) if store is not None else None


# ----------------------------------------------------------------------------- fleets


class FleetCache:
    """``zero diff --fleet``'s comparisons by machine, for one run: the golden machine's order and
    files, and each machine's differences from it, valid while neither machine's files changed."""

    def __init__(self, store: Store, project: Project, golden: str, options: object) -> None:
        self.disk = store
        self.project = project
        self.checker = Checker(project.encoding)
        self.started = time.time_ns()  # before anything is read
        self.cwd = os.getcwd()
        start = os.path.abspath(golden)
        self.common = (generation(), self.cwd, catalogue_id(project.param_desc(start)), fingerprint(options),
                       project.cli.kind)
        self.golden_key = fingerprint(("golden", str(start), golden, self._layout(start), *self.common))
        self.golden_id: str | None = None  # the fingerprint of the golden machine's files, once known

    def _layout(self, startup: FileName) -> object:
        cfg = self.project.config(startup)
        return _canonical((cfg.machine, cfg.machine_lists, cfg.machine_workdir, cfg.machine_roots))

    def deps(self, machine: Machine) -> tuple[Dep, ...] | None:
        """A machine's files as they are kept, ``None`` where one changed too recently to tell."""
        deps = machine_deps(machine, self.project.encoding)
        return deps if settled(deps, self.started) else None

    def golden_order(self) -> tuple[list[str], list[str]] | None:
        """The golden machine's scope names and default lists' keys, if its files are as they were."""
        value = self.disk.get(self.golden_key)
        try:
            deps, scopes, defaults = value
            if not self.checker.holds(deps):
                return None
            self.golden_id = fingerprint(deps)
            return list(scopes), list(defaults)
        except (TypeError, ValueError):
            return None

    def put_golden(self, deps: tuple[Dep, ...] | None, scopes: list[str], defaults: list[str]) -> None:
        """Keep the golden machine (``deps`` ``None``: not settled, so neither it nor any comparison)."""
        self.golden_id = fingerprint(deps) if deps is not None else None
        if deps is not None:
            self.disk.put(self.golden_key, (deps, tuple(scopes), tuple(defaults)))

    def _key(self, startup: str) -> str:
        start = os.path.abspath(startup)
        return fingerprint(("machine", self.golden_id, str(start), startup, self._layout(start), *self.common))

    def machine(self, startup: str) -> Any:
        """A machine's stored comparison (as :meth:`put_machine` got it), if its files are as they were."""
        if self.golden_id is None:
            return None
        value = self.disk.get(self._key(startup))
        try:
            packed, deps = value
            return packed if self.checker.holds(deps) else None
        except (TypeError, ValueError):
            return None

    def put_machine(self, startup: str, packed: object, deps: tuple[Dep, ...] | None) -> None:
        if self.golden_id is not None and deps is not None:
            self.disk.put(self._key(startup), (packed, deps))


def open_fleet_cache(project: Project, golden: str, options: object) -> FleetCache | None:
    store = open_store(project)
    if store is None:
        return None
    try:
        return FleetCache(store, project, golden, options)
    except (ZeroError, TypeError):  # a description that cannot be read is said where it is loaded
        return None


__all__ = ["FOLDER", "MAX_BYTES", "MAX_ENTRIES", "Checker", "FleetCache", "LintCache", "Store", "cache_folder",
           "catalogue_id", "disabled", "fingerprint", "generation", "machine_deps", "open_fleet_cache",
           "open_lint_cache", "open_store", "pack_result", "unpack_result"]

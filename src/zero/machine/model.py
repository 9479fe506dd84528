"""A machine as the controller builds it at start-up, with the origin of every value.

The start-up list (``hochlauf.lis``) names every other list of the machine
(:data:`REFERENCES`: the keys the catalogue documents for it). The controller reads
them from its working directory, honours the counts (``zahl_mds`` axis lists,
``zahl_kw`` compensation lists, ``kanal_anzahl`` channels: lists beyond a count are not
read), and applies a default list (``default_achs_mds``, ``default_sda_mds``) under the
specific lists of its kind, so that a parameter a specific list does not set takes the
default list's value, and only then the catalogue default. :func:`load_machine` builds
that picture; every machine question (the X rules, ``zero limits``, the NC program
checks, ``zero show --machine``) is answered from it.

The working directory is found once: the start-up list's directory or the nearest of
its ancestors in which the most named lists exist (the vendor's start-up lists name
``./listen/…`` from inside ``listen/``). A list is looked for there only; a list that is
not there is missing, never replaced by a same-named file elsewhere.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from pathlib import Path

from zero.catalog.ids import (
    AXIS_LISTS,
    AXIS_NAME,
    AXIS_NR,
    AXIS_TYPE,
    CH_COUNT,
    CH_LOG_NR,
    CH_NAME,
    CHANNELS,
    COMP_LISTS,
    SWE_NEG,
    SWE_POS,
    Number,
    is_rotary,
)
from zero.catalog.registry import Registry
from zero.catalog.values import ListValues
from zero.errors import ZeroError
from zero.files import content_digest, nearest_holding, read_file, within
from zero.forms import (
    CONFIG_NAMES,
    KERNEL_ROOT,
    TWINCAT,
    XML_SUFFIX,
    controller_absolute,
    is_project,
    is_xml,
    kernel_rooted,
    split_part,
    xml_form,
)
from zero.lists.model import Document, Entry, Invalid
from zero.markup import read_document
from zero.records import Record, field, replace

# Soft limits the controller uses when no list sets them (±10 m, the catalogue default).
DEFAULT_SOFT_LIMIT = 100_000_000
MAX_ANCESTORS = 4  # how far above the start-up list the working directory is looked for
LIST_FOLDER = "listen"  # the vendor's folder of lists, which its start-up lists name as ./listen/…
# The entries of a machine's lists, each list counted as often as the start-up list names it (the
# rules, tables and pages work per reference). A real machine holds tens of thousands (64 axes of
# about 1,500); 64 references to one list of a million lines needed 7 GB.
MAX_MACHINE_ENTRIES = 500_000


class Reference(Record, frozen=True):
    """A start-up key that names a list, as the catalogue documents it."""

    key: str  # pattern: "achs_mds[]", "hand_mds"
    param_id: str
    kind: str  # the kind of list it names
    default: bool = False  # a default list, applied under the specific lists of its kind
    count: str | None = None  # the start-up parameter that limits how many are read
    missing: str = ("the catalogue does not document what the controller does without it")


ABORTS = "the catalogue says start-up is aborted when a named list cannot be opened"
# In the controller's order: default lists before the lists they underlie.
REFERENCES: tuple[Reference, ...] = (
    Reference("default_sda_mds", "P-STUP-00034", "CHAN", default=True),
    Reference("sda_mds[]", "P-STUP-00009", "CHAN", count=CHANNELS),
    Reference("werkz_data[]", "P-STUP-00010", "TOOL", count=CHANNELS),
    Reference("nullp_data[]", "P-STUP-00011", "ZERO", count=CHANNELS),
    Reference("pzv_data[]", "P-STUP-00012", "CLMP", count=CHANNELS),
    Reference("ve_var[]", "P-STUP-00146", "EXTV", count=CHANNELS),
    Reference("hand_mds", "P-STUP-00013", "MANU"),
    Reference("rtconf_lis", "P-STUP-00135", "RTCF"),
    Reference("hw_configuration_list", "P-STUP-00136", "HWCF"),
    Reference("default_achs_mds", "P-STUP-00035", "AXIS", default=True),
    Reference("achs_mds[]", "P-STUP-00015", "AXIS", count=AXIS_LISTS, missing=ABORTS),
    Reference("achs_kw[]", "P-STUP-00017", "COMP", count=COMP_LISTS, missing=ABORTS),
)
BY_KEY = {r.key: r for r in REFERENCES}
COUNT_KEYS = {CHANNELS: "kanal_anzahl", AXIS_LISTS: "zahl_mds", COMP_LISTS: "zahl_kw"}


class ListFile(Record):
    """One list of the machine with the values the controller takes from it (the default
    list's under this list's, where there is one)."""

    key: str  # the start-up entry that names it: achs_mds[0]
    path: Path
    values: ListValues
    line: int  # where the start-up list names it

    def number(self, pid: str, indices: tuple[int, ...] = ()) -> Number | None:
        return self.values.number_of(pid, indices)

    def text(self, pid: str, indices: tuple[int, ...] = ()) -> str | None:
        return self.values.text_of(pid, indices)

    def entry(self, pid: str, indices: tuple[int, ...] = ()) -> Entry | None:
        """The entry of *this* list that sets the parameter (not the default list's)."""
        layer = self.values.layer_of(pid, indices)
        return layer.entry_of(pid, indices) if layer is self.values else None


class Named(Record):
    """A list reference of the start-up list and what became of it."""

    key: str  # as written: achs_mds[4]
    reference: Reference
    index: int | None
    raw: str  # the path as written
    line: int
    path: Path | None = None  # where it was looked for
    status: str = "loaded"  # loaded, missing, unreadable, beyond-count, overridden
    reason: str = ""


class Axis(Record):
    nr: int  # logical axis number (kopf.achs_nr)
    name: str
    rotary: bool
    swe_neg: Number
    swe_pos: Number
    list: ListFile

    @property
    def unit(self) -> str:
        return "°" if self.rotary else "mm"  # the unit of its lengths, as is_rotary decided


class ChannelAxis(Record):
    index: int  # j in np_grp[i].achse[j]
    log_nr: int
    name: str
    entry: Entry | None  # the entry that sets log_achs_nr
    source: Path | None = None  # the list that entry is in (the channel list or its default list)


class Channel(Record):
    index: int
    lists: ListFile | None  # the channel list
    zero: ListFile | None  # the zero-offset list
    axes: list[ChannelAxis] = field(default_factory=list)
    tools: ListFile | None = None  # the tool list (werkz_data[c])
    others: dict[str, ListFile] = field(default_factory=dict)  # pzv_data, ve_var by key pattern


class Missing(Record):
    key: str
    raw: str  # the path as written
    line: int
    reason: str = "does not exist"
    consequence: str = ""


class Machine(Record):
    startup: ListFile
    workdir: Path = Path(".")
    named: list[Named] = field(default_factory=list)
    axis_lists: list[ListFile] = field(default_factory=list)
    channels: list[Channel] = field(default_factory=list)
    defaults: dict[str, ListFile] = field(default_factory=dict)  # list kind → its default list
    singles: dict[str, ListFile] = field(default_factory=dict)  # hand_mds, rtconf_lis, ...
    compensation: list[tuple[int, ListFile]] = field(default_factory=list)  # (index i, achs_kw[i])

    @property
    def unchecked(self) -> list[Named]:
        """The references zero did not follow: absolute paths and paths outside the machine's folder."""
        return [n for n in self.named if n.status == "not-checked"]

    def complete_axes(self) -> bool:
        """Were all the axis lists the start-up list names (within `zahl_mds`) followed and read? When
        one was not (not followed, missing, unreadable), its axis number is not known, so no "axis
        without a list" can be claimed: the missing list is the one root cause (X005/X012)."""
        return not any(n.reference.key == "achs_mds[]" for n in self.unchecked) and not any(
            n.reference.key == "achs_mds[]" and n.status in ("missing", "unreadable") for n in self.named)

    @property
    def missing(self) -> list[Missing]:
        return [Missing(n.key, n.raw, n.line, n.reason, n.reference.missing) for n in self.named
                if n.status in ("missing", "unreadable")]

    @property
    def lists(self) -> list[ListFile]:
        """Every list the machine loads, each once (the start-up list first)."""
        out: dict[Path, ListFile] = {self.startup.path: self.startup}
        for lf in (*self.defaults.values(), *self.axis_lists, *self.singles.values(),
                   *(lf for _, lf in self.compensation)):
            out.setdefault(lf.path, lf)
        for ch in self.channels:
            for per_channel in (ch.lists, ch.zero, ch.tools, *ch.others.values()):
                if per_channel is not None:
                    out.setdefault(per_channel.path, per_channel)
        return list(out.values())

    def axes(self) -> dict[int, Axis]:
        """Logical axis number → axis (the first list wins when two claim one number)."""
        out: dict[int, Axis] = {}
        for lf in self.axis_lists:
            ax = axis_of(lf)
            if ax is not None and ax.nr not in out:
                out[ax.nr] = ax
        return out

    def scopes(self) -> list[tuple[str, ListFile]]:
        """Every list with a name for what it configures: ``axis 1 (achs_mds[0])``, ..."""
        out = [("start-up", self.startup)]
        for lf in self.axis_lists:
            nr = lf.number(AXIS_NR)
            out.append((f"axis {int(nr) if nr is not None else '?'} ({lf.key})", lf))
        for ch in self.channels:
            for per_channel in (ch.lists, ch.zero, ch.tools, *ch.others.values()):
                if per_channel is not None:
                    out.append((f"channel {ch.index} ({per_channel.key})", per_channel))
        out.extend((lf.key, lf) for lf in self.singles.values())
        out.extend((f"compensation {i} ({lf.key})", lf) for i, lf in self.compensation)
        return out


def axis_of(lf: ListFile) -> Axis | None:
    nr = lf.number(AXIS_NR)
    if nr is None:
        return None
    kind = lf.number(AXIS_TYPE)
    neg, pos = lf.number(SWE_NEG), lf.number(SWE_POS)
    return Axis(int(nr), lf.text(AXIS_NAME) or f"axis {nr}", is_rotary(kind),
                neg if neg is not None else -DEFAULT_SOFT_LIMIT, pos if pos is not None else DEFAULT_SOFT_LIMIT, lf)


def _clean(raw: str) -> str:
    """A reference's path as written, quotes removed, ``\\`` read as the separator it is on a
    Windows controller (TwinCAT writes ``.\\sda_mds1.lis`` and ``..\\prg``)."""
    return raw.strip().strip('"').replace("\\", "/")


def machine_ceiling(startup: Path) -> Path | None:
    """The highest folder a machine's lists may lie in: the nearest folder, from the start-up list's
    own up, that is a project (holds a zero configuration or ``pyproject.toml``) or a git work tree
    (holds ``.git``); ``None`` where there is none (the search then stops below the file system's root)."""
    return nearest_holding(Path(os.path.abspath(startup)).parent, (".git", *CONFIG_NAMES))


def _candidates(base: Path, ceiling: Path | None) -> list[Path]:
    """The start-up list's folder and the ancestors the vendor's layout needs (at most
    MAX_ANCESTORS), never above the ceiling, never the file system's root."""
    out: list[Path] = []
    for d in (base, *base.parents):
        if len(out) > MAX_ANCESTORS or d.parent == d:  # `/` (or a drive's root) is never a machine's folder
            break
        out.append(d)
        if ceiling is not None and d == ceiling:
            break
    return out or [base]


def working_directory(startup: Path, raws: list[str], ceiling: Path | None = None, *,
                      realpath: Callable[[str], str] = os.path.realpath) -> Path:
    """The controller's working directory: the start-up list's directory or the nearest
    ancestor in which the most of ``raws`` exist (the directory itself when none does), never
    above ``ceiling`` (:func:`machine_ceiling`) and never the file system's root.

    The ancestors are those of the start-up list's absolute path, however it was typed
    (``hochlauf.lis`` from inside ``listen/`` has the same ancestors as ``listen/hochlauf.lis``);
    the answer is said the way the start-up list was given: relative to the current directory
    when it was given relative and the answer lies below the current directory, else absolute.

    Without a ceiling (no project marker above), an ancestor counts only the references that lead
    back down the start-up list's way (:func:`layout_bound`; the vendor's layout: ``./listen/…`` named
    from inside ``listen/`` or ``listen/SoE/``): a file beside an ancestor (``../.bashrc`` as
    ``./.bashrc``) never makes it the working directory. ``realpath``: ``os.path.realpath``, or a
    machine's reading's (:class:`_Realpaths`)."""
    absolute = Path(os.path.abspath(startup))
    base = absolute.parent
    candidates = _candidates(base, ceiling)
    # each reference as a path joins it (`./listen//x.lis` as `listen/x.lis`), joined to each folder as text
    relative = [str(Path(c)) for c in map(_clean, raws) if c and not controller_absolute(c)]
    best, hits = base, 0
    for d in candidates:
        folder = os.fspath(d)
        found = [f for f in (os.path.join(folder, r) for r in relative) if os.path.isfile(f)]
        if len(found) <= hits:
            continue  # cannot count more than the best so far
        if ceiling is None:
            inside = _inside(layout_bound(d, base), realpath)
            n = sum(1 for f in found if inside(f))
        else:
            n = len(found)
        if n > hits:
            best, hits = d, n
    return shown(best, relative_to_cwd=not startup.is_absolute())


def _inside(root: Path, realpath: Callable[[str], str] = os.path.realpath) -> Callable[[str | Path], bool]:
    """:func:`zero.files.within` of many paths in one ``root`` (the root resolved once; each path as
    :func:`zero.files.resolve` resolves it, by ``realpath``)."""
    top = realpath(os.fspath(root))
    below = top.rstrip(os.sep) + os.sep

    def test(path: str | Path) -> bool:
        real = realpath(split_part(path)[0])
        return real == top or real.startswith(below)

    return test


class _Realpaths:
    """``os.path.realpath`` of the paths one reading of a machine asks about, each asked once: a list's
    path is tested by the working directory's search, by the containment test and by its reading.

    A path's folder is resolved once for all the lists in it: ``realpath`` of ``folder/name`` is the
    folder's real path joined with ``name`` unless ``name`` is a link (one ``lstat``), which is what
    ``realpath`` itself does after resolving the folder, component by component, with an ``lstat``
    each (seven a list in a fleet, before). A link, ``.``, ``..`` or a trailing separator is left to
    ``realpath`` whole."""

    def __init__(self) -> None:
        self.seen: dict[str, str] = {}

    def __call__(self, path: str) -> str:
        got = self.seen.get(path)
        if got is None:
            head, tail = os.path.split(path)
            if head and head != path and tail not in ("", ".", "..") and not os.path.islink(
                    joined := os.path.join(self(head), tail)):
                got = joined
            else:
                got = os.path.realpath(path)
            self.seen[path] = got
        return got


def layout_bound(workdir: Path, folder: Path) -> Path:
    """Without a project marker, the highest folder a machine's lists may lie in: the start-up list's
    ``folder`` itself, or, where the start-up list lies in the vendor's list folder ``listen/`` (or
    below it) and the working directory holds that folder, ``listen/`` (``./listen/default_sda.lis``
    and ``./listen/SoE/achsmds1.lis`` named from ``listen/SoE/hochlauf.lis``); never a file beside the
    working directory or in another of its folders."""
    work, here = Path(os.path.abspath(workdir)), Path(os.path.abspath(folder))
    try:
        rest = here.relative_to(work).parts
    except ValueError:
        return here
    return work / rest[0] if rest and rest[0].lower() == LIST_FOLDER else here


def shown(path: Path, relative_to_cwd: bool) -> Path:
    """``path`` (absolute) as zero names it: relative to the current directory where asked for and
    it lies below it (``.`` for the directory itself), else absolute."""
    if relative_to_cwd:
        rel = os.path.relpath(path)
        if rel != ".." and not rel.startswith(".." + os.sep):
            return Path(rel)
    return path


Encodings = Callable[[Path], str | None]  # a list → the codec its configuration declares (None: detected)


def _detected(_path: Path) -> str | None:
    return None


# A run's lists by content (issue 40): the machines of a fleet are mostly copies of each other
# (the vendor's lists, a few values changed), so a list whose bytes, declared codec, kind and
# registry equal those of one read before in the process takes that one's reading and binding: its
# own document (the same rows and entries under its own path), no tokenizing, no binding again.
# Plain lists only (not XML, not a list inside a TwinCAT export); bounded in count and size.
SHARED_LISTS = 64  # distinct contents kept
SHARED_MAX_CHARS = 1 << 20  # a longer list is read on its own (a tool list of 100,000 entries)
SHARED_TOTAL_CHARS = 1 << 23  # the text all of them hold together (8 M characters)
ContentKey = tuple[bytes, str | None, str, int]  # the bytes' hash, the declared codec, the kind, the registry


class _Shared:
    """The lists read in this process by content: the first reading and binding of each (oldest out first)."""

    def __init__(self) -> None:
        self.kept: dict[ContentKey, tuple[Registry, ListValues]] = {}
        self.chars = 0

    @staticmethod
    def key(data: bytes, codec: str | None, kind: str, registry: Registry) -> ContentKey:
        return content_digest(data), codec, kind, id(registry)

    def twin(self, key: ContentKey, registry: Registry) -> ListValues | None:
        hit = self.kept.get(key)
        return hit[1] if hit is not None and hit[0] is registry else None

    def keep(self, key: ContentKey, registry: Registry, values: ListValues) -> None:
        size = values.doc.text_size  # 0: no text of its own (a document built from lines)
        if not 0 < size <= SHARED_MAX_CHARS or values.doc.origin is not None or key in self.kept:
            return
        while self.kept and (len(self.kept) >= SHARED_LISTS or self.chars + size > SHARED_TOTAL_CHARS):
            self.chars -= self.kept.pop(next(iter(self.kept)))[1].doc.text_size
        self.kept[key] = (registry, values)
        self.chars += size

    def clear(self) -> None:
        self.kept.clear()
        self.chars = 0


SHARED = _Shared()


def _read(key: str, path: Path, line: int, registry: Registry, kind: str,
          base: ListValues | None = None, reader: Callable[[Path], bytes] = read_file,
          docs: dict[str, Document] | None = None, encoding: Encodings = _detected,
          built: dict[tuple[str, str, str, int], ListValues] | None = None,
          realpath: Callable[[str], str] = os.path.realpath) -> ListFile:
    """One list of the machine; ``docs`` keeps each file read once (a start-up list may name one
    file many times: each reference costs its binding, never another read). ``encoding`` gives
    the codec the configuration declares for a list (``None``: detected). A list with the bytes of
    one read before (:data:`SHARED`) takes its reading and binding, under its own path."""
    real = realpath(os.fspath(path))
    doc = docs.get(real) if docs is not None else None
    file, part = split_part(path)  # `channel_1.xml#NullpD`: a list inside a TwinCAT export
    twin: ListValues | None = None
    shared: ContentKey | None = None
    if doc is None:
        data = reader(Path(file))
        codec = encoding(path)
        if part is None and not is_xml(data):
            shared = SHARED.key(data, codec, kind, registry)
            twin = SHARED.twin(shared, registry)
        doc = twin.doc.moved(str(path)) if twin is not None else read_document(data, str(path), registry, codec)
        if docs is not None:
            docs.setdefault(real, doc)
    elif doc.path != str(path) and part is None:
        doc = replace(doc, path=str(path))
        if docs is not None:
            docs.setdefault(real, doc)
    # ``built`` keeps each file's values once per kind and default list: 64 references to one list
    # share them (built per reference, they took 0.7 s and a copy of every entry each).
    cache_key = (real, str(doc.path), kind, id(base))
    values = built.get(cache_key) if built is not None else None
    if values is None:
        if twin is not None:  # the twin's binding (and what it found since), over this machine's default list
            values = replace(twin, doc=doc, base=base)
        else:
            values = ListValues.of(doc, registry, kind)
            values.base = base
            if shared is not None:
                SHARED.keep(shared, registry, values)
        if built is not None:
            built[cache_key] = values
    return ListFile(key, path, values, line)


def _not_a_list(values: ListValues) -> str | None:
    """Why a file named as a list is no parameter list at all (``None`` when it is one): text whose
    lines are entries of no parameter the catalogue knows, or not entries at all (``/etc/passwd``).
    An empty list, or one of comments, is a list."""
    doc = values.doc
    if any(p.kind == "binary" for p in doc.problems):
        return "is not a text file, not a parameter list: not read"
    if values.resolved:
        return None
    registry = values.registry
    if any(e.key is not None and (registry.by_pattern(e.key.pattern, None) or registry.alias(e.key.pattern, None))
           for e in doc.entries):
        return None  # a list of another kind than its key says: a list all the same
    content = sum(1 for item in doc.items if isinstance(item, (Entry, Invalid)))
    if not content:
        return None
    return (f"is not a parameter list (none of its {content} lines sets a parameter the catalogue knows): "
            "not read, and none of its lines is shown")


def _count(startup: ListValues, pid: str) -> int:
    n = startup.number_of(pid)
    return int(n) if n is not None else 0


Roots = tuple[tuple[str, Path], ...]  # a folder of the controller → where it lies here


def _mapped(text: str, roots: Roots) -> Path | None:
    """An absolute path of the controller below one of ``roots`` (the longest that fits; letters'
    case and separators do not matter, as on Windows), as the file here; ``None`` otherwise."""
    norm = text.replace("\\", "/").rstrip("/").lower()
    best: tuple[int, Path] | None = None
    for prefix, folder in roots:
        p = prefix.replace("\\", "/").rstrip("/").lower()
        if (norm == p or norm.startswith(p + "/")) and (best is None or len(p) > best[0]):
            best = (len(p), folder)
    if best is None:
        return None
    rest = text.replace("\\", "/")[best[0]:].lstrip("/")
    return best[1] / rest if rest else best[1]


def named_lists(startup_path: Path, doc: Document, overrides: dict[str, Path] | None = None,
                workdir: Path | None = None, ceiling: Path | None = None,
                roots: Roots = (), *, realpath: Callable[[str], str] = os.path.realpath) -> tuple[Path, list[Named]]:
    """The working directory and every list reference of a start-up list, each with the path the
    controller opens (``path``; status ``overridden`` where ``[tool.zero.machine]`` names it,
    ``missing`` for an empty one, ``not-checked`` for an absolute path or one outside the
    machine's folder: zero never reads a file a start-up list points it to outside the machine).
    Only paths: nothing is read. :func:`load_machine` reads them; the editor links them."""
    named: list[Named] = []
    for e in doc.entries:
        if e.key is None:
            continue
        ref = BY_KEY.get(e.key.pattern)
        if ref is None or len(e.key.indices) != ref.key.count("[]"):
            continue
        named.append(Named(e.key_text, ref, e.key.indices[0] if e.key.indices else None, e.value, e.line))
    root = workdir if workdir is not None else working_directory(startup_path, [n.raw for n in named], ceiling,
                                                                 realpath=realpath)
    # A relative path may climb out of the working directory (TwinCAT's `..\listen\nullp_d1.lis`), never
    # out of the project (its git work tree or configuration folder), nor, without one, the start-up list's
    # folder (the vendor's `./listen/…` named from inside `listen/` stays in it).
    inside = ceiling is not None and within(root, ceiling)
    folder = Path(os.path.abspath(split_part(startup_path)[0])).parent
    bound, what = (ceiling, "project") if inside and ceiling is not None else (
        (root, "machine's folder") if workdir is not None else (layout_bound(root, folder), "machine's folder"))
    inside_bound = _inside(bound, realpath)
    for n in named:
        override = (overrides or {}).get(n.key)
        text = _clean(n.raw)
        if override is not None:
            n.path, n.status = override, "overridden"
        elif not text:
            n.status, n.reason = "missing", "is empty"
        elif controller_absolute(text) and (mapped := _mapped(text, roots)) is not None:
            n.path = mapped  # `[tool.zero.machine] roots` says where that folder of the controller lies
            if not any(within(mapped, folder) for _, folder in roots):
                n.status, n.reason = "not-checked", "climbs out of the folder `roots` maps it to"
                n.path = None
        elif controller_absolute(text):
            where = (f"lies below the kernel's root folder `{KERNEL_ROOT}`" if kernel_rooted(text)
                     else "is an absolute path on the controller")
            n.status, n.reason = "not-checked", f"{where} (`[tool.zero.machine] roots` can map its folder)"
        else:
            n.path = Path(os.path.normpath(root / text))  # `startup/../listen/x.lis` shown as `listen/x.lis`
            if not inside_bound(n.path):
                n.status, n.reason = "not-checked", f"lies outside the {what} {bound}"
                n.path = None
    return root, named


# The start-up references a TwinCAT export of a channel or an axis answers, by the element holding the list.
_EXPORTED = {"sda_mds[]": "SdaMds", "nullp_data[]": "NullpD", "werkz_data[]": "WerkzD", "pzv_data[]": "PzvD",
             "ve_var[]": "VeD", "achs_mds[]": "AchsMds"}
_CHANNEL_NO = re.compile(r"<ChannelNo>\s*([0-9]+)\s*</ChannelNo>")


def _from_exports(startup: Path, named: list[Named], reader: Callable[[Path], bytes],
                  bound: Path | None = None) -> None:
    """A machine whose start-up list is a TwinCAT CNC task's export: the lists it names by files
    TwinCAT writes when it activates the configuration (`.\\sda_mds1.lis`) are taken from the
    exports of the channels and axes in the same folder, where no such file lies there: channel
    `c`'s lists from the export of channel `c + 1` (its `<ChannelNo>`, else the exports in name
    order), the axis lists from the axis exports in the order of their logical axis numbers (the
    set of axes is what the X rules need: TwinCAT does not say which file each axis list becomes)."""
    from zero.markup.documents import embedded_documents  # start-up: only for a TwinCAT machine

    channels: list[tuple[int, Path, set[str]]] = []
    axes: list[tuple[int, Path]] = []
    for f in sorted(startup.parent.glob(f"*{XML_SUFFIX}")):
        if f == startup or not within(f, bound if bound is not None else startup.parent):
            continue  # a link to an export elsewhere is never read
        try:
            data = reader(f)
            if xml_form(data) != TWINCAT:
                continue
            sc, lists = embedded_documents(data, str(f))
        except ZeroError:
            continue
        held = {x.element for x in lists}
        if "AchsMds" in held:
            doc = next(x.doc for x in lists if x.element == "AchsMds")
            nr = next((e.value for e in doc.entries if e.key_text == "kopf.achs_nr"), "")
            axes.append((int(nr) if nr.isdigit() else 10**6 + len(axes), f))
        elif held & {"SdaMds", "NullpD", "WerkzD", "PzvD", "VeD"}:
            m = _CHANNEL_NO.search(sc.text)
            channels.append((int(m.group(1)) if m else 10**6 + len(channels), f, held))
    channels.sort()
    axes.sort()
    by_number = {number: (f, held) for number, f, held in channels}
    for n in named:
        element = _EXPORTED.get(n.reference.key)
        if element is None or n.index is None or (n.path is not None and os.path.exists(n.path)):
            continue
        hit: Path | None = None
        if element == "AchsMds":
            hit = axes[n.index][1] if n.index < len(axes) else None
        else:
            f_held = by_number.get(n.index + 1) or (channels[n.index][1:] if n.index < len(channels) else None)
            hit = f_held[0] if f_held is not None and element in f_held[1] else None
        if hit is not None:
            n.path, n.status, n.reason = Path(f"{hit}#{element}"), "loaded", f"from the TwinCAT export {hit.name}"


def load_machine(startup_path: Path, registry: Registry, forced_kind: str | None = None,
                 overrides: dict[str, Path] | None = None, workdir: Path | None = None,
                 reader: Callable[[Path], bytes] = read_file, ceiling: Path | None = None,
                 roots: Roots = (), encoding: Encodings = _detected) -> Machine:
    """Read a start-up list and every list it names, as the controller would.

    ``overrides`` (start-up key → path, from ``[tool.zero.machine]``) replace what the
    start-up list names; ``workdir`` fixes the working directory. Each list is read as the
    kind its key says (``achs_mds`` an axis list, ...), or as ``forced_kind``. ``reader`` gives
    a list's bytes (an editor passes its unsaved text; :class:`ZeroError` when it cannot);
    ``encoding`` the codec the configuration declares for a list (``None``: detected).
    """
    realpath = _Realpaths()
    startup = _read("start-up list", startup_path, 0, registry, forced_kind or "STUP", None, reader,
                    encoding=encoding, realpath=realpath)
    root, named = named_lists(startup_path, startup.values.doc, overrides, workdir, ceiling, roots, realpath=realpath)
    origin = startup.values.doc.origin
    if is_project(startup_path):  # a TwinCAT project: `tc_virtual_N\` names its own Offset blocks
        from zero.machine.tsproj import resolve_virtual  # start-up: only for a TwinCAT project

        resolve_virtual(Path(split_part(startup_path)[0]), named, reader)
    elif origin is not None and origin.form == TWINCAT:  # the CNC task's export: the lists of its folder's exports
        _from_exports(Path(split_part(startup_path)[0]), named, reader,
                      ceiling if ceiling is not None and within(startup_path, ceiling) else None)
    machine = Machine(startup, root, named)
    counts = {pid: _count(startup.values, pid) for pid in COUNT_KEYS}
    sizes = {ref.param_id: spec.dims[0] for ref in REFERENCES
             if (spec := registry.get(ref.param_id)) is not None and spec.dims}  # achs_mds[0..63], ...
    docs: dict[str, Document] = {}
    built: dict[tuple[str, str, str, int], ListValues] = {}
    loaded: dict[str, ListFile] = {}
    entries = len(startup.values.doc.columns)  # of every list as often as it is named: the work to come

    def load(n: Named, base: ListValues | None = None) -> ListFile | None:
        if n.index is not None and n.index >= sizes.get(n.reference.param_id, n.index + 1):
            n.status, n.reason = "out-of-range", "has an index outside its array (R003): not taken over"
            return None
        if n.reference.count is not None and n.index is not None and n.index >= counts[n.reference.count]:
            n.status = "beyond-count"
            return None
        if n.path is None or n.status == "not-checked":
            return None  # empty, absolute or outside the machine's folder: said by named_lists
        try:
            lf = _read(n.key, n.path, n.line, registry, forced_kind or n.reference.kind, base, reader, docs,
                       encoding, built, realpath)
        except ZeroError as exc:
            n.status = "missing" if exc.message == "no such file" else "unreadable"
            n.reason = "does not exist" if n.status == "missing" else f"cannot be read: {exc.message}"
            return None
        foreign = _not_a_list(lf.values)
        if foreign is not None:  # never a line of it in a finding: it is not a list of this machine
            n.status, n.reason = "unreadable", foreign
            return None
        nonlocal entries
        entries += len(lf.values.doc.columns)  # its entries (before `Ende`), none built
        if entries > MAX_MACHINE_ENTRIES:  # refused before any rule, table or page is built from them
            raise ZeroError(f"`{n.key}` brings the machine's lists to more than {MAX_MACHINE_ENTRIES:,} entries "
                            f"(each list counted as often as the start-up list names it): zero does not "
                            f"check a machine this large", str(startup_path), n.line, 1)
        loaded[n.key] = lf
        return lf

    for n in named:  # default lists first: the specific lists are read over them
        if n.reference.default:
            lf = load(n)
            if lf is not None:
                machine.defaults[n.reference.kind] = lf
    per_channel: dict[int, dict[str, ListFile]] = {}
    for n in sorted(named, key=lambda n: (n.reference.key, n.index or 0)):
        ref = n.reference
        if ref.default:
            continue
        under = machine.defaults.get(ref.kind)
        lf = load(n, under.values if under is not None else None)
        if lf is None:
            continue
        if ref.key == "achs_mds[]":
            machine.axis_lists.append(lf)
        elif ref.key == "achs_kw[]":
            machine.compensation.append((n.index or 0, lf))
        elif ref.key.endswith("[]"):
            per_channel.setdefault(n.index or 0, {})[ref.key] = lf
        else:
            machine.singles[ref.key] = lf
    for c in sorted(per_channel):
        lists = per_channel[c]
        ch = Channel(c, lists.get("sda_mds[]"), lists.get("nullp_data[]"), tools=lists.get("werkz_data[]"),
                     others={k: v for k, v in lists.items()
                             if k not in ("sda_mds[]", "nullp_data[]", "werkz_data[]")})
        if ch.lists is not None:
            _channel_axes(ch, ch.lists)
        machine.channels.append(ch)
    return machine


def _channel_axes(ch: Channel, lists: ListFile) -> None:
    count = lists.number(CH_COUNT, (0,))
    present = {ix[1] for ix in lists.values.ids_of(CH_LOG_NR) if len(ix) == 2 and ix[0] == 0}
    n = max(int(count or 0), max(present, default=-1) + 1)
    for j in range(min(n, 32)):
        nr = lists.number(CH_LOG_NR, (0, j))
        if nr is None:
            continue
        name = lists.text(CH_NAME, (0, j)) or f"axis {j}"
        layer = lists.values.layer_of(CH_LOG_NR, (0, j))
        entry = layer.entry_of(CH_LOG_NR, (0, j)) if layer is not None else None
        ch.axes.append(ChannelAxis(j, int(nr), name, entry, Path(layer.doc.path) if layer is not None else None))

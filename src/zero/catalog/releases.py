"""Key renames and removals between kernel releases, each row with its source.

zero's catalogue is one kernel release (:data:`CATALOGUE_RELEASE`, the SDK's CncParaDesc.xml).
Lists written for other releases use keys it spells differently or does not have. This module
answers, from ``data/releases.toml``, what zero *knows* about such a key:

- :func:`renamed`: the key is an older spelling of a key the catalogue has (``antr_simu.totzeit``
  is ``antr.simu.totzeit``, P-AXIS-00194);
- :func:`removed`: the key is absent from the catalogue, and a source shows it in a list of an
  older release (which says nothing about what that release's kernel did with it);
- :func:`parse_release`: ``"V3.01.3074"``, ``"V3.1.3074"``, ``"4.13"`` as comparable tuples.

Nothing here guesses. Every row of the table is backed by a source (a list line's own
``( P-AXIS-nnnnn`` annotation, a vendor page, a file of the vendor's corpus) and records it; a key
that merely looks like a known one is not a rename. The one rule beyond single rows, a prefix
(``antr_simu.`` → ``antr.simu.``), is itself a row with a source, and maps a key only to a key the
catalogue in use really has.

The table is compiled from ``data/releases.toml`` to ``data/releases_table.py`` (checked on the way) and
built at the first question, once per process: nothing of it runs at start-up.
"""

from __future__ import annotations

from collections.abc import Callable

from zero.errors import ZeroError
from zero.lists.model import format_key
from zero.patterns import compiled
from zero.records import Record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from pathlib import Path
    from typing import Any, TypeVar

    from zero.catalog.registry import Registry

    _Row = TypeVar("_Row")

# The kernel release of the catalogue zero ships: CncParaDesc.xml of the ISG CNC Kernel SDK
# V1.5.0.0, kernel V4.13.0.0 (the corpus README; data/table.py's GENERATED_FROM).
CATALOGUE_RELEASE: tuple[int, ...] = (4, 13)

VENDOR_SOURCE = "isg-sdk "  # a row's source that names a file of the vendor's SDK (lists, XML templates)
UNKNOWN_RELEASE = "unknown"  # a row whose source does not say which release wrote the spelling
DATA: Path  # data/releases.toml (a pathlib.Path made at the first use: below)

_RELEASE_RE = compiled(r"[Vv]?\s*(\d+(?:\.\d+)*)")


def parse_release(text: str) -> tuple[int, ...]:
    """A kernel release as a comparable tuple: ``"V3.01.3074"`` and ``"V3.1.3074"`` → ``(3, 1, 3074)``,
    ``"4.13"`` and ``"V4.13.0.0"`` → ``(4, 13)``.

    Leading zeros of a part do not count (``01`` is ``1``: the kernel's own spellings differ
    there), nor do trailing zero parts (``4.13.0.0`` is ``4.13``), so equal releases compare
    equal however they are written. :class:`~zero.errors.ZeroError` for text that is no release.
    """
    m = _RELEASE_RE.fullmatch(text.strip())
    if m is None:
        raise ZeroError(f"not a kernel release: {text!r} (expected e.g. V3.1.3074 or 4.13)")
    parts = [int(p) for p in m.group(1).split(".")]
    while len(parts) > 1 and parts[-1] == 0:
        parts.pop()
    return tuple(parts)


def format_release(release: tuple[int, ...]) -> str:
    """``(3, 1, 3074)`` → ``"V3.1.3074"``; a bare major gets its minor: ``(4,)`` → ``"V4.0"``."""
    parts = list(release) + [0] * (2 - len(release))
    return "V" + ".".join(str(p) for p in parts)


def _release_tuple(release: str) -> tuple[int, ...] | None:
    """A row's release as a comparable tuple; ``None`` where its source does not say."""
    return None if release == UNKNOWN_RELEASE else parse_release(release)


class Rename(Record, frozen=True):
    """``old`` is an older spelling of today's ``new`` (``id``), as ``source`` shows.

    ``release`` is the kernel release of the list the source shows ``old`` in (``"unknown"``
    where it does not say): where the spelling was seen, not where it began or ended.
    """

    old: str
    kind: str
    new: str
    id: str
    release: str
    source: str
    see: tuple[str, ...] = ()
    release_tuple = property(lambda self: _release_tuple(self.release), doc="The release, comparable.")

    def new_key(self, indices: tuple[int, ...] | list[int] = ()) -> str:
        """Today's key with a list line's indices filled in (``lr_hw[1]...``)."""
        return format_key(self.new, indices)

    @property
    def vendor(self) -> bool:
        """The row's source is the vendor's own SDK lists or templates (``isg-sdk …``): the vendor writes
        the spelling, evidence that the kernel of that release accepts it (R013 at info)."""
        return self.source.startswith(VENDOR_SOURCE)


class Removal(Record, frozen=True):
    """``old`` is absent from the catalogue; ``source`` shows it in a list of ``release``.

    What zero knows is exactly that: not whether that release's kernel read the key, nor what
    it meant, nor whether another key took its place.
    """

    old: str
    kind: str
    release: str
    source: str
    see: tuple[str, ...] = ()
    release_tuple = property(lambda self: _release_tuple(self.release), doc="The release, comparable.")


class Prefix(Record, frozen=True):
    """A subtree written ``old…`` in older lists and ``new…`` today (``antr_simu.`` → ``antr.simu.``)."""

    old: str
    kind: str
    new: str
    release: str
    source: str
    see: tuple[str, ...] = ()


class ReleaseTable(Record, frozen=True):
    """The rows of ``data/releases.toml``, in file order."""

    renames: tuple[Rename, ...]
    removals: tuple[Removal, ...]
    prefixes: tuple[Prefix, ...]


_table: ReleaseTable | None = None
_renames: dict[tuple[str, str], Rename] = {}
_removals: dict[tuple[str, str], Removal] = {}


def table() -> ReleaseTable:
    """The table, built at the first call from its compiled form (``data/releases_table.py``, written
    from the TOML by ``tools/gen_startup.py``: no TOML parser for a list's first unknown key) and kept
    for the process."""
    global _table
    if _table is None:
        from zero.catalog.data.releases_table import PREFIXES, REMOVALS, RENAMES  # start-up: first unknown key

        _table = ReleaseTable(renames=_rows(Rename, RENAMES), removals=_rows(Removal, REMOVALS),
                              prefixes=_rows(Prefix, PREFIXES))
        _renames.update(((r.kind, r.old), r) for r in _table.renames)
        _removals.update(((r.kind, r.old), r) for r in _table.removals)
    return _table


def _rows(cls: Callable[..., _Row], data: list[dict[str, Any]]) -> tuple[_Row, ...]:
    return tuple(cls(**{**r, "see": tuple(r["see"])}) for r in data)  # compiled through JSON: lists


def read_table(path: Path) -> ReleaseTable:
    """Read and check a table file (:class:`~zero.errors.ZeroError` where a row lacks a field or says
    nothing of its source: a row without one is a guess). ``tools/gen_startup.py`` compiles it with this."""
    import tomllib  # start-up: the table is read only when a key is not in the catalogue

    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise ZeroError(f"cannot read the release table: {exc}", str(path)) from exc

    def rows(section: str, required: tuple[str, ...], allowed: tuple[str, ...]) -> list[dict[str, Any]]:
        out = []
        for n, row in enumerate(data.get(section, []), 1):
            missing = [f for f in required if not isinstance(row.get(f), str) or not row[f].strip()]
            unknown = sorted(set(row) - set(allowed))
            see = row.get("see", [])
            if not isinstance(see, list) or not all(isinstance(u, str) for u in see):
                unknown.append("see (not a list of texts)")
            if missing or unknown:
                what = f"lacks {', '.join(missing)}" if missing else f"has wrong fields {', '.join(unknown)}"
                raise ZeroError(f"[[{section}]] row {n} {what}", str(path))
            if row["release"] != UNKNOWN_RELEASE:
                parse_release(row["release"])
            out.append({**row, "see": tuple(see)})
        return out

    base = ("old", "kind", "release", "source")
    renames = (*base, "new", "id")
    prefixes = (*base, "new")
    return ReleaseTable(
        renames=tuple(Rename(**r) for r in rows("rename", renames, (*renames, "see"))),
        removals=tuple(Removal(**r) for r in rows("removal", base, (*base, "see"))),
        prefixes=tuple(Prefix(**r) for r in rows("prefix", prefixes, (*prefixes, "see"))),
    )


def renamed(pattern: str, kind: str | None, registry: Registry | None = None) -> Rename | None:
    """The rename row for an older key pattern (``antr_simu.totzeit``) in a list kind, or ``None``.

    A row of the table answers first. Otherwise a prefix row answers, but only with a
    ``registry`` whose catalogue has the key the prefix leads to in that kind: the ID is then
    that catalogue's, the source the prefix row's. Without a registry only single rows answer.
    With one, a row also answers only where that catalogue has the row's new key under the
    row's ID (another release's catalogue may not): zero never proposes a key it cannot check.
    ``kind`` ``None`` (undetected) matches rows of any kind.
    """
    t = table()
    if kind is not None:
        exact = _renames.get((kind, pattern))
        rows = [exact] if exact is not None else []
    else:
        rows = [r for r in t.renames if r.old == pattern]
    for row in rows:
        if registry is None:
            return row
        spec = registry.by_pattern(row.new, row.kind)
        if spec is not None and spec.id == row.id:
            return row
    if registry is None:
        return None
    for p in t.prefixes:
        if (kind is None or p.kind == kind) and pattern.startswith(p.old) and len(pattern) > len(p.old):
            new = p.new + pattern[len(p.old):]
            spec = registry.by_pattern(new, p.kind)
            if spec is not None:
                return Rename(pattern, p.kind, new, spec.id, p.release, p.source, p.see)
    return None


def removed(pattern: str, kind: str | None) -> Removal | None:
    """The removal row for a key pattern (``lr_hw[].cntr_adr``) in a list kind, or ``None``
    (``kind`` ``None`` matches rows of any kind)."""
    t = table()
    if kind is not None:
        return _removals.get((kind, pattern))
    return next((r for r in t.removals if r.old == pattern), None)


def __getattr__(name: str) -> Path:
    """``DATA``, made where it is read (start-up: a lint that names a release imports no pathlib)."""
    if name != "DATA":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from pathlib import Path  # start-up: see above

    return Path(__file__).parent / "data" / "releases.toml"

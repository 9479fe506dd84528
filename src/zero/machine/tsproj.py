"""A TwinCAT project as a machine: the start-up list's ``tc_virtual_N\\`` references resolved to the
``<Data … Offset="N">`` blocks of the project (:mod:`zero.markup.tsproj`), never to a path on disk.

The blocks are looked for in the project file and in the independent project files (``.xti``) it
names with ``File="…"`` (and they in turn name), each found by its name below the project's
``_Config`` folder (where TwinCAT saves them; a name found twice there is not guessed between) or
beside the file that names it, never outside the project's folder.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Protocol

from zero.errors import ZeroError
from zero.files import read_file, walk, within
from zero.forms import split_part
from zero.markup.documents import embedded_documents, pick
from zero.markup.tsproj import VIRTUAL_RE, Block, read_project
from zero.records import Record


class Named(Protocol):
    """A start-up reference as :class:`zero.machine.model.Named` has it (the model imports this module)."""

    key: str
    raw: str
    path: Path | None
    status: str
    reason: str


class Machine(Protocol):
    @property
    def named(self) -> Sequence[Named]: ...

CONFIG_FOLDER = "_Config"
MAX_FILES = 2000  # independent project files followed at most (a project has one per item)
MAX_WALK = 50_000  # entries of `_Config` looked at at most


class Found(Record, eq=False):
    """A block of the project and the file that holds it."""

    path: Path
    block: Block
    line: int


def _walk(folder: Path) -> dict[str, list[Path]]:
    """Every file below ``folder`` by its name in lower case (at most MAX_WALK entries looked at)."""
    out: dict[str, list[Path]] = {}
    seen = 0
    for here, dirs, files in walk(folder):
        dirs.sort()
        for name in sorted(files):
            out.setdefault(name.lower(), []).append(Path(here) / name)
        seen += len(files) + len(dirs)
        if seen > MAX_WALK:
            break
    return out


def project_blocks(project: Path, reader: Callable[[Path], bytes]) -> tuple[list[Found], list[str]]:
    """Every block of a project (the project file first, then its independent project files in the
    order they are named) and what could not be followed, said in words."""
    top = project.parent
    index: dict[str, list[Path]] | None = None
    found: list[Found] = []
    problems: list[str] = []
    queue: list[Path] = [project]
    done: set[str] = set()
    while queue and len(done) < MAX_FILES:
        path = queue.pop(0)
        real = os.path.realpath(path)
        if real in done:
            continue
        done.add(real)
        try:
            pf = read_project(reader(path), str(path))
        except ZeroError as exc:
            problems.append(f"{path}: {exc.message}")
            continue
        found.extend(Found(path, b, pf.scan.position(b.tag)[0]) for b in pf.blocks)
        for _, name in pf.files:
            if index is None:
                index = _walk(top / CONFIG_FOLDER) if (top / CONFIG_FOLDER).is_dir() else {}
            base = os.path.basename(name.replace("\\", "/"))
            hits = [h for h in index.get(base.lower(), []) if within(h, top)]
            beside = path.parent / base
            if not hits and beside.is_file() and within(beside, top):
                hits = [beside]
            if len(hits) == 1:
                queue.append(hits[0])
            elif not hits:
                problems.append(f"{path}: the independent project file `{name}` is not below {top / CONFIG_FOLDER}")
            else:
                problems.append(f"{path}: the independent project file `{name}` lies {len(hits)} times below "
                                f"{top / CONFIG_FOLDER}; zero does not guess which one TwinCAT reads")
    return found, problems


def resolve_virtual(project: Path, named: Sequence[Named], reader: Callable[[Path], bytes]) -> list[str]:
    """Point every ``tc_virtual_N\\`` reference of the start-up list at the block with Offset N (as
    ``file#address``); one that no block or more than one block answers is not read, and says why."""
    blocks, problems = project_blocks(project, reader)
    by_offset: dict[int, list[Found]] = {}
    for f in blocks:
        if f.block.offset is not None:
            by_offset.setdefault(f.block.offset, []).append(f)
    for n in named:
        m = VIRTUAL_RE.match(n.raw)
        if m is None:
            continue
        offset = int(m.group(1))
        hits = by_offset.get(offset, [])
        if len(hits) == 1:
            hit = hits[0]
            n.path, n.status, n.reason = Path(f"{hit.path}#{hit.block.address}"), "loaded", ""
        elif not hits:
            n.path, n.status = None, "missing"
            n.reason = (f"no `<Data>` block of the project answers: none has Offset {offset} (`tc_virtual_N\\` names "
                        "the block with Offset N, never a folder on disk)")
            if problems:
                n.reason += "; not followed: " + "; ".join(problems)
        else:
            where = ", ".join(f"{h.path.name}:{h.line} ({h.block.address})" for h in hits)
            n.path, n.status = None, "unreadable"
            n.reason = (f"{len(hits)} blocks of the project answer, each with Offset {offset} ({where}): which one "
                        f"TwinCAT writes for tc_virtual_{offset} is not documented, so zero reads none")
    return problems


def twincat_items(machine: Machine, reader: Callable[[Path], bytes] | None = None) -> dict[str, dict[str, str]]:
    """What TwinCAT says of the item each list of the machine comes from, by the start-up key that
    names the list: the item's name in the TwinCAT tree and, for an axis, its ``DriveType``,
    ``Spindle`` and ``FeedAxis`` as the project or export writes them (``achs_mds[1]`` →
    ``{"item": "Y_Achse", "element": "Y_Achse/AchsMds", "DriveType": "4", ...}``). Lists read from
    plain files have none. Shown beside the lists, never compared with them: the vendor's
    documentation does not say how these values relate to ``kenngr.antr_typ`` or ``kenngr.achs_typ``."""
    read = reader or read_file
    out: dict[str, dict[str, str]] = {}
    for n in machine.named:
        if n.path is None or n.status not in ("loaded", "overridden"):
            continue
        file, element = split_part(n.path)
        if element is None:
            continue
        try:
            hit = pick(embedded_documents(read(Path(file)), file)[1], element, file)
        except (ZeroError, OSError):
            continue
        out[n.key] = {"item": hit.item, "element": hit.element, **hit.properties}
    return out


__all__ = ["CONFIG_FOLDER", "Found", "project_blocks", "resolve_virtual", "twincat_items"]

"""What every generator in ``tools/`` shares: its command line (``--check``) and how it writes.

A generator works out each file's text (``None``: a file that must not exist, such as the module of a
kind that has no rows any more) and hands them to :func:`update`: it writes them, or with ``--check``
writes nothing and names each stale file (exit 1), so that a stale generated file can be found by a
script (CI, a hook) without changing the tree.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CHECK = "--check"


def checking(argv: list[str] | None = None, usage: str = "") -> bool:
    """Whether the command line (``sys.argv[1:]`` by default) asks for ``--check``; any other argument
    ends the run with the usage (exit 2)."""
    args = sys.argv[1:] if argv is None else argv
    if args in ([], [CHECK]):
        return bool(args)
    print(f"usage: {usage or 'python ' + _shown(Path(sys.argv[0]))} [{CHECK}]\n"
          f"  {CHECK}: exit 1 if a generated file is stale, write nothing", file=sys.stderr)
    raise SystemExit(2)


def _shown(path: Path) -> str:
    """``path`` relative to the repository where it lies in it."""
    try:
        return path.resolve().relative_to(ROOT).as_posix()
    except ValueError:
        return str(path)


def in_folder(folder: Path, pattern: str, texts: Mapping[str, str]) -> dict[Path, str | None]:
    """``texts`` by file name as files of ``folder``, and ``None`` for each other file there that ``pattern``
    matches (the module of a kind that has nothing to write any more: removed)."""
    files: dict[Path, str | None] = {path: None for path in sorted(folder.glob(pattern))}
    files.update((folder / name, text) for name, text in texts.items())
    return files


def stale(files: Mapping[Path, str | None]) -> list[Path]:
    """The files whose bytes are not the text given (``None``: the file exists)."""
    out = []
    for path, text in files.items():
        have = path.read_bytes() if path.is_file() else None
        if have != (text.encode("utf-8") if text is not None else None):
            out.append(path)
    return out


def update(tool: str, files: Mapping[Path, str | None], check: bool) -> list[Path]:
    """Write ``files`` (remove those given ``None``), saying each; with ``check``, write nothing and
    return the stale ones, each said with how to renew it (``tool``: the generator's file name)."""
    if check:
        found = stale(files)
        for path in found:
            why = "is stale" if files[path] is not None else "is no longer generated"
            print(f"{_shown(path)} {why}: run python tools/{tool}")
        return found
    for path, text in files.items():
        if text is None:
            if path.exists():
                path.unlink()
                print(f"removed {path}")
        else:
            path.write_text(text, encoding="utf-8")
            print(f"wrote {path}")
    return []


def done(tool: str, found: list[Path], check: bool) -> None:
    """End a generator's run: exit 1 where ``--check`` found a stale file, else say that all is current."""
    if found:
        raise SystemExit(1)
    if check:
        print(f"tools/{tool}: every file is current")


def run(tool: str, files: Callable[[], Mapping[Path, str | None]], argv: list[str] | None = None) -> None:
    """A generator run from the command line: its arguments read (:func:`checking`), then the texts
    ``files()`` gives written or checked (:func:`update`, :func:`done`)."""
    check = checking(argv, f"python tools/{tool}")
    done(tool, update(tool, files(), check), check)

"""``zero convert``: lists ↔ YAML / TOML / JSON, and writing files safely.

Everything the command does is callable here: :func:`read_tree` (any format →
:class:`~zero.structured.Tree`), :func:`write_tree` (tree → bytes),
:func:`convert` (both, with the findings ``zero lint`` gives on the result) and
:func:`write_atomic` (temporary file in the target directory, fsync, rename).
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from zero.formats import EXTENSION, READERS, WRITERS, format_of
from zero.lint import LintOptions, LintResult, ZeroError, lint_document
from zero.registry import Registry
from zero.structured import ConvertError, Tree, encode_list, from_document, to_list_text
from zero.tokenizer import tokenize

__all__ = [
    "Conversion",
    "ConvertError",
    "convert",
    "decode_structured",
    "output_path",
    "read_tree",
    "write_atomic",
    "write_tree",
]


def decode_structured(data: bytes, path: str) -> str:
    """YAML/TOML/JSON are UTF-8 (a BOM is allowed); anything else is refused with its offset."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        col = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
        raise ConvertError(f"not UTF-8 (byte 0x{data[exc.start]:02X}); YAML, TOML and JSON files "
                           "are read as UTF-8", path, line, col) from None


def read_tree(data: bytes, fmt: str, path: str = "-", kind: str | None = None) -> Tree:
    """Read list, YAML, TOML or JSON bytes as a tree."""
    if fmt == "lis":
        return from_document(tokenize(data, path), kind)
    if fmt not in READERS:
        raise ConvertError(f"unknown input format {fmt!r} (use one of: lis, yaml, toml, json)", path)
    tree = READERS[fmt](decode_structured(data, path), path)
    if kind and "kind" not in tree.meta:
        tree.meta["kind"] = kind
    return tree


def write_tree(tree: Tree, fmt: str) -> bytes:
    """A tree as list, YAML, TOML or JSON bytes."""
    if fmt == "lis":
        return encode_list(tree, to_list_text(tree).text)
    if fmt not in WRITERS:
        raise ConvertError(f"unknown output format {fmt!r} (use one of: lis, yaml, toml, json)")
    return WRITERS[fmt](tree).encode("utf-8")


@dataclass(slots=True)
class Conversion:
    output: bytes
    tree: Tree
    notes: list[str] = field(default_factory=list)
    lint: LintResult | None = None  # findings on the list a structured input makes


def lint_tree(tree: Tree, options: LintOptions | None = None, source: str | None = None,
              registry: Registry | None = None) -> LintResult:
    """Lint the list a tree makes; findings point at the structured file where known."""
    from dataclasses import replace

    from zero.diagnostics import Span
    from zero.model import Document
    from zero.structured import structured_path

    written = to_list_text(tree)
    data = encode_list(tree, written.text)
    doc = tokenize(data, tree.path)
    opts = options or LintOptions()
    kind = tree.meta.get("kind") if isinstance(tree.meta.get("kind"), str) else None
    if opts.kind is None and kind:
        from zero.registry import kind_from_name

        opts = LintOptions(opts.select, opts.ignore, kind_from_name(kind))
    result = lint_document(doc, registry, opts)
    lines = source.split("\n") if source is not None else []
    shown = Document(tree.path, "utf-8", [x.rstrip("\r") for x in lines], [], [])
    import re

    def relocate(m: re.Match[str]) -> str:
        other = written.lines_of.get(int(m.group(1)))
        if other is None:
            return m.group(0)
        at = f"line {other.line}" if other.line else "the entry"
        return f"{at} (`{structured_path(other.path)}`)"

    out = []
    for d in result.diagnostics:
        leaf = written.lines_of.get(d.span.line)
        if leaf is None:
            span = Span(1, 1, 1, 1)
            message = f"(list line {d.span.line}) {d.message}"
        else:
            line = leaf.line or 1
            col = leaf.column or 1
            span = Span(line, col, line, col + len(str(leaf.value)))
            message = f"{structured_path(leaf.path)}: " + re.sub(r"\bline (\d+)", relocate, d.message)
        out.append(replace(d, span=span, message=message, fix=None))
    out.sort(key=lambda d: d.sort_key())
    return LintResult(tree.path, shown, result.kind, out)


def convert(data: bytes, src: str, dst: str, path: str = "-", kind: str | None = None,
            check: bool = True) -> Conversion:
    """Convert bytes from one format to another.

    A structured input becomes a list only after every entry line has been
    verified to read back as written; ``check`` also lints that list.
    """
    tree = read_tree(data, src, path, kind)
    output = write_tree(tree, dst)
    result = None
    if check and src != "lis" and dst == "lis":
        source = data.decode("utf-8", "replace").lstrip("\ufeff")
        result = lint_tree(tree, None, source if src in ("yaml", "toml") else None)
    return Conversion(output, tree, list(tree.notes), result)


def output_path(src: Path, fmt: str, out_dir: Path) -> Path:
    return out_dir / (src.stem + EXTENSION[fmt])


def target_format(to: str | None, output: str | None, src_fmt: str) -> str:
    """``--to``, else the output's suffix, else the other side of the conversion."""
    if to:
        return to
    if output and output != "-":
        fmt = format_of(output)
        if fmt:
            return fmt
    return "yaml" if src_fmt == "lis" else "lis"


def source_format(given: str | None, path: str) -> str:
    if given:
        return given
    fmt = format_of(path)
    if fmt is None:
        raise ZeroError(f"{path}: cannot tell the format from the name; give --from "
                        "(lis, yaml, toml or json)")
    return fmt


def write_atomic(path: Path, data: bytes, force: bool = False,
                 inputs: tuple[Path, ...] = ()) -> None:
    """Write ``data`` to ``path`` all at once or not at all.

    Never over an input file, never over an existing file unless ``force``.
    The bytes go to a temporary file in the same directory, are flushed to
    disk, and replace the target by one rename; on any failure the temporary
    file is removed and the target is untouched.
    """
    target = Path(path)
    for src in inputs:
        try:
            if target.exists() and os.path.samefile(target, src):
                raise ZeroError(f"{target}: is an input file; zero never writes over its input")
        except FileNotFoundError:
            continue
    if target.exists() and not force:
        raise ZeroError(f"{target}: already exists (use --force to replace it)")
    if target.is_dir():
        raise ZeroError(f"{target}: is a directory")
    directory = target.parent if str(target.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=directory)
    except OSError as exc:
        raise ZeroError(f"{target}: cannot write here: {exc.strerror or exc}") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        if target.exists():
            with contextlib.suppress(OSError):
                os.chmod(tmp, target.stat().st_mode & 0o7777)
        else:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, target)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise ZeroError(f"{target}: not written: {exc.strerror or exc}") from None
        raise

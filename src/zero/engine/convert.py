"""``zero convert``: lists ↔ YAML / TOML / JSON, as library functions.

:func:`convert` converts bytes (and lints the list a structured input makes);
:func:`convert_inputs` is the whole command without its printing: each input read,
converted and checked, one :class:`ConvertItem` per input; :func:`write_outputs`
writes the results (atomically, never over an input) once every input converted.

A list is read in the code page its configuration declares (``[tool.zero] encoding``), which
the ``_zero`` record of the structured form keeps, so that converting back writes the
original bytes.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from zero.catalog.registry import Registry
from zero.diagnostics import Severity
from zero.engine.formatting import undeclared_code_page
from zero.engine.lint import LintResult, lint_tree
from zero.engine.project import Project
from zero.errors import ZeroError
from zero.files import read_file, write_atomic
from zero.forms import EXTENSION, format_of
from zero.lists.encoding import encode_text
from zero.lists.tokenizer import tokenize
from zero.records import field, record, replace
from zero.structured.formats import read_tree, write_tree
from zero.structured.tree import Tree, from_document, to_list_text

# The encodings `zero.structured.tree.encode_list` writes: a list in a code page the configuration
# declared (cp850) is written here instead, until it writes those too.
_TREE_WRITES = ("utf-8", "cp1252", "latin-1")


@record
class Conversion:
    output: bytes
    tree: Tree
    notes: list[str] = field(default_factory=list)
    lint: LintResult | None = None  # findings on the list a structured input makes


def convert(data: bytes, src: str, dst: str, registry: Registry, path: str = "-", kind: str | None = None,
            check: bool = True, encoding: str | None = None) -> Conversion:
    """Convert bytes from one format to another.

    A structured input becomes a list only after every entry line has been
    verified to read back as written; ``check`` also lints that list. ``encoding``: the code
    page the configuration declares for a list input (``None``: detected).
    """
    if src == "lis":
        doc = tokenize(data, path, encoding)
        undeclared_code_page(doc, "YAML, TOML and JSON text cannot carry it")
        tree = from_document(doc, registry, kind)
    else:
        tree = read_tree(data, src, registry, path, kind)
    output = write_tree(tree, dst) if dst != "lis" else list_bytes(tree)
    result = None
    if check and src != "lis" and dst == "lis":
        source = data.decode("utf-8", "replace").lstrip("\ufeff")
        # The findings are the same in any encoding: lint_tree encodes the list only to read it back.
        readable = tree if tree.meta.get("encoding", "utf-8") in _TREE_WRITES else \
            replace(tree, meta={**tree.meta, "encoding": "utf-8"})
        result = lint_tree(readable, registry, None, source if src in ("yaml", "toml") else None)
    return Conversion(output, tree, list(tree.notes), result)


def list_bytes(tree: Tree) -> bytes:
    """A tree as the bytes of a list, in the encoding its ``_zero`` record names (a declared code
    page such as cp850 too)."""
    encoding = tree.meta.get("encoding", "utf-8")
    if encoding in _TREE_WRITES or not isinstance(encoding, str):
        return write_tree(tree, "lis")
    return encode_text(to_list_text(tree).text, encoding, tree.meta.get("bom") is True, tree.path)


def _no_catalogue(_desc: Path | None) -> Registry:
    raise ZeroError("no catalogue is resolved here")  # pragma: no cover - never asked


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
    """``--from``, else the format the name implies (standard input is a list)."""
    if given:
        return given
    if path == "-":
        return "lis"
    fmt = format_of(path)
    if fmt is None:
        raise ZeroError("cannot tell the format from the name; give --from (lis, yaml, toml or json)", path)
    return fmt


@record
class ConvertItem:
    """One input of ``zero convert``: its output, or why there is none."""

    name: str
    fmt: str  # the output format
    output: bytes | None = None
    notes: list[str] = field(default_factory=list)
    findings: LintResult | None = None  # warnings and errors of the list a structured input makes
    error: str | None = None  # not converted: why

    @property
    def failed(self) -> bool:
        return self.output is None


def check_convert_options(inputs: Sequence[str], output: str | None, out_dir: Path | None) -> None:
    """The combinations of inputs and outputs ``zero convert`` accepts."""
    if len(inputs) > 1 and out_dir is None:
        raise ZeroError("several inputs need --out-dir (one output file per input)")
    if output is not None and out_dir is not None:
        raise ZeroError("give either -o/--output or --out-dir, not both")
    if list(inputs).count("-") > 1 or ("-" in inputs and out_dir is not None):
        raise ZeroError("standard input (-) converts alone, to -o or standard output")


def convert_inputs(inputs: Sequence[str], registry: Registry | Callable[[str], Registry],
                   read_stdin: Callable[[], bytes], *,
                   src: str | None = None, to: str | None = None, output: str | None = None,
                   kind: str | None = None, check: bool = True, strict: bool = False,
                   project: Project | None = None) -> list[ConvertItem]:
    """Read, convert and check every input; nothing is written. A file that cannot be read
    raises :class:`ZeroError`; an input that cannot be converted is an item with ``error``.
    ``registry`` may give each input its own catalogue (its configuration's ``param-desc``);
    ``project`` says the code page each list input's configuration declares (by default the
    configuration found from the input's folder)."""
    if project is None:  # only its configurations are asked: the catalogue comes from `registry`
        project = Project(_no_catalogue)
    items = []
    for name in inputs:
        catalogue = registry(name) if callable(registry) else registry
        src_fmt = source_format(src, name)
        item = ConvertItem(name, target_format(to, output, src_fmt))
        data = read_stdin() if name == "-" else read_file(name)
        try:
            encoding = project.encoding(Path(name)) if name != "-" else None
            result = convert(data, src_fmt, item.fmt, catalogue, name, kind, check, encoding)
        except ZeroError as exc:
            item.error = str(exc)
            items.append(item)
            continue
        item.notes = result.notes
        if result.lint is not None:
            shown = [d for d in result.lint.diagnostics if d.severity >= Severity.WARNING]
            if shown:
                item.findings = LintResult(result.lint.path, result.lint.document, result.lint.kind, shown)
            if strict and result.lint.worst is not None and result.lint.worst >= Severity.ERROR:
                item.error = f"{name}: not converted (--strict): the list has errors"
                items.append(item)
                continue
        item.output = result.output
        items.append(item)
    return items


def write_outputs(items: Sequence[ConvertItem], output: str | None, out_dir: Path | None,
                  force: bool) -> bytes | None:
    """Write converted items to ``out_dir`` or ``output``; the bytes for standard output otherwise."""
    sources = tuple(Path(i.name) for i in items if i.name != "-")
    done = [(i, i.output) for i in items if i.output is not None]
    if out_dir is not None:
        targets = [output_path(Path(i.name), i.fmt, out_dir) for i, _ in done]
        if len(set(targets)) != len(targets):
            raise ZeroError("two inputs would write the same output name; convert them separately")
        out_dir.mkdir(parents=True, exist_ok=True)
        for target, (_, data) in zip(targets, done, strict=True):
            write_atomic(target, data, force, sources)
        return None
    if output is not None and output != "-":
        write_atomic(Path(output), done[0][1], force, sources)
        return None
    return done[0][1]

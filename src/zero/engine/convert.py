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

import os
from collections.abc import Callable, Sequence
from pathlib import Path

from zero.catalog.registry import Registry, kind_from_name
from zero.diagnostics import Severity
from zero.engine.formatting import undeclared_code_page
from zero.engine.lint import LintOptions, LintResult, lint_tree
from zero.engine.project import Project, configurations_only
from zero.errors import ZeroError
from zero.files import read_file, write_atomic
from zero.forms import CONFIG_NAMES, EXTENSION, TWINCAT, format_of, split_part, xml_form
from zero.lists.encoding import document_bytes
from zero.lists.tokenizer import tokenize
from zero.records import Record, field
from zero.structured.formats import read_tree, write_tree
from zero.structured.tree import Tree, from_document


class Conversion(Record):
    output: bytes
    tree: Tree
    notes: list[str] = field(default_factory=list)
    lint: LintResult | None = None  # findings on the list a structured input makes


def xml_source(data: bytes, path: str, registry: Registry, item: str | None = None) -> tuple[bytes, str, str | None]:
    """An XML input as the bytes of the list it is (the XML lines kept as comments: see
    :mod:`zero.markup.lists`), its codec and its list kind; a TwinCAT export as the list of its
    element ``item`` (the one list it holds when ``item`` is not given)."""
    from zero.markup.documents import embedded_documents, list_text, pick, xml_document  # start-up: only for XML
    from zero.markup.safe import scan  # start-up: as above

    file, part = split_part(path)
    if xml_form(data) == TWINCAT:  # a TwinCAT export or project: the list `item` (or `FILE#ITEM`) names
        hit = pick(embedded_documents(data, file)[1], item or part, file)
        return list_text(hit), hit.doc.encoding, hit.kind
    sc = scan(data, path)
    if item is not None:
        raise ZeroError("--item names a list inside a TwinCAT export; this is an XML list", path)
    doc = xml_document(data, path, registry, sc)
    return document_bytes(doc), doc.encoding, doc.origin.kind if doc.origin is not None else None


def xml_bytes(tree: Tree, registry: Registry, path: str) -> bytes:
    """A tree as the kernel's XML list (byte for byte the XML it was read from, where it was one)."""
    from zero.markup.lists import to_xml  # start-up: only for XML

    encoding = tree.meta.get("encoding")
    doc = tokenize(list_bytes(tree), path, encoding if isinstance(encoding, str) else None)
    kind = tree.meta.get("kind") if isinstance(tree.meta.get("kind"), str) else None
    return to_xml(doc, registry, kind_from_name(kind) if kind else None)


def convert(data: bytes, src: str, dst: str, registry: Registry, path: str = "-", kind: str | None = None,
            check: bool = True, encoding: str | None = None, item: str | None = None,
            options: LintOptions | None = None) -> Conversion:
    """Convert bytes from one format to another (``options``: the file's, for the check's findings).

    A structured input becomes a list only after every entry line has been
    verified to read back as written; ``check`` also lints that list. ``encoding``: the code
    page the configuration declares for a list input (``None``: detected). An XML input is read as
    the list it is (``item``: which list of a TwinCAT export); ``xml`` writes the kernel's XML list.
    """
    if src == "xml":
        data, encoding, own = xml_source(data, path, registry, item)
        kind, src = kind or own, "lis"
    if src == "lis":
        doc = tokenize(data, path, encoding, objects=True)  # every item is read
        undeclared_code_page(doc, "YAML, TOML and JSON text cannot carry it")
        tree = from_document(doc, registry, kind)
        del doc  # the tokens are not needed to write: a big list's peak is 25 MiB lower without them
    else:
        tree = read_tree(data, src, registry, path, kind)
    if dst == "xml":
        output = xml_bytes(tree, registry, path)
    else:
        output = write_tree(tree, dst) if dst != "lis" else list_bytes(tree)
    result = None
    if check and src != "lis" and dst in ("lis", "xml"):
        source = data.decode("utf-8", "replace").lstrip("\ufeff")
        result = lint_tree(tree, registry, options, source if src in ("yaml", "toml") else None)
    return Conversion(output, tree, list(tree.notes), result)


def list_bytes(tree: Tree) -> bytes:
    """A tree as the bytes of a list, in the encoding its ``_zero`` record names (a declared code
    page such as cp850 too)."""
    return write_tree(tree, "lis")



def output_path(src: Path, fmt: str, out_dir: Path, element: str | None = None) -> Path:
    """``name.yaml`` in ``out_dir``; ``name.Element.lis`` for the list ``element`` of a TwinCAT export
    (``Maschine.Kanal_1.SdaMds.lis`` for a project's ``Kanal_1/SdaMds``)."""
    part = element.replace("/", ".").replace("\\", ".") if element else None
    return out_dir / (src.stem + (f".{part}" if part else "") + EXTENSION[fmt])


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
    fmt = format_of(split_part(path)[0])  # `X.tsproj#Kanal_1/SdaMds`: a list inside a TwinCAT project
    if fmt is None:
        raise ZeroError("cannot tell the format from the name; give --from (lis, xml, yaml, toml or json)", path)
    return fmt


class ConvertItem(Record):
    """One input of ``zero convert``: its output, or why there is none."""

    name: str
    fmt: str  # the output format
    output: bytes | None = None
    notes: list[str] = field(default_factory=list)
    findings: LintResult | None = None  # warnings and errors of the list a structured input makes
    error: str | None = None  # not converted: why
    element: str | None = None  # the list of a TwinCAT export this is (its output: name.Element.fmt)

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
                   project: Project | None = None, element: str | None = None,
                   every_list: bool = False) -> list[ConvertItem]:
    """Read, convert and check every input; nothing is written. A file that cannot be read
    raises :class:`ZeroError`; an input that cannot be converted is an item with ``error``.
    ``registry`` may give each input its own catalogue (its configuration's ``param-desc``);
    ``project`` says the code page each list input's configuration declares (by default the
    configuration found from the input's folder)."""
    if project is None:  # only its configurations are asked: the catalogue comes from `registry`
        project = configurations_only()
    items = []
    for name in inputs:
        catalogue = registry(name) if callable(registry) else registry
        src_fmt = source_format(src, name)
        item = ConvertItem(name, target_format(to, output, src_fmt))
        data = read_stdin() if name == "-" else read_file(name)
        if src_fmt == "xml" and element is None and every_list:
            embedded = _elements(data, name)
            if len(embedded) > 1:  # a TwinCAT export: every list it holds, one output each
                for part in embedded:
                    items.extend(convert_inputs([name], catalogue, read_stdin, src=src, to=to, output=output,
                                                kind=kind, check=check, strict=strict, project=project,
                                                element=part))
                continue
        item.element = element
        try:
            encoding = project.settings(Path(name)).encoding if name != "-" else None
            result = convert(data, src_fmt, item.fmt, catalogue, name, kind, check, encoding, element,
                             project.settings(Path(name)).options if name != "-" else None)  # its selection
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


def write_into(name: str, export: Path, element: str | None, registry: Registry | Callable[[str], Registry],
               read_stdin: Callable[[], bytes], *, src: str | None = None, kind: str | None = None,
               project: Project | None = None) -> bytes:
    """``zero convert LIST --into EXPORT [--item ELEMENT]``: the list (in any form) put back into the
    CDATA section of ``element`` in a TwinCAT export, written atomically; every other byte of the
    export kept. The element may be left out when the export holds one list. Returns the new bytes."""
    from zero.markup.documents import doc_text, embedded_documents, pick, splice  # start-up: only for XML
    from zero.markup.safe import scan  # start-up: as above

    catalogue = registry(name) if callable(registry) else registry
    data = read_stdin() if name == "-" else read_file(name)
    src_fmt = source_format(src, name)
    if src_fmt != "lis":
        data = convert(data, src_fmt, "lis", catalogue, name, kind, False).output
    declared = (project or configurations_only()).settings(Path(name)).encoding if name != "-" else None
    text = doc_text(tokenize(data, name, declared))  # the list's own code page, read as text
    file, part = split_part(export)  # `--into X.tsproj#Y_Achse/AchsMds`: the list named with the file
    if part is not None and not export.exists():
        export, element = Path(file), element or part
    target = read_file(export)
    sc, lists = embedded_documents(target, str(export))
    new = splice(sc, str(export), [(pick(lists, element, str(export)), text)])
    try:
        new.decode(sc.encoding)
        scan(new, str(export))  # the export as it will be: still XML (a character its codec lacks is not)
    except (UnicodeDecodeError, ZeroError) as exc:
        raise ZeroError(f"the list cannot be put into the export: {exc}", str(export)) from None
    write_atomic(export, new, force=True, inputs=(Path(name),) if name != "-" else ())
    return new


def _elements(data: bytes, name: str) -> list[str]:
    """The elements holding lists in a TwinCAT export (none for an XML list or unreadable XML)."""
    from zero.markup.documents import embedded_documents  # start-up: only for XML

    try:
        return [x.element for x in embedded_documents(data, name)[1]]
    except ZeroError:
        return []


def _not_a_configuration(target: Path) -> Path:
    """A converted list is written anywhere but over a configuration file (``pyproject.toml``,
    ``zero.toml``), by its name or through a link."""
    for name in (target.name, os.path.basename(os.path.realpath(target))):
        if name in CONFIG_NAMES:
            raise ZeroError("is a configuration file, not a list: not replaced", str(target))
    return target


def write_outputs(items: Sequence[ConvertItem], output: str | None, out_dir: Path | None,
                  force: bool) -> bytes | None:
    """Write converted items to ``out_dir`` or ``output``; the bytes for standard output otherwise."""
    sources = tuple(Path(i.name) for i in items if i.name != "-")
    done = [(i, i.output) for i in items if i.output is not None]
    if out_dir is not None:
        targets = [output_path(Path(i.name), i.fmt, out_dir, i.element) for i, _ in done]
        if len(set(targets)) != len(targets):
            raise ZeroError("two inputs would write the same output name; convert them separately")
        out_dir.mkdir(parents=True, exist_ok=True)
        for target, (_, data) in zip(targets, done, strict=True):
            write_atomic(_not_a_configuration(target), data, force, sources)
        return None
    if output is not None and output != "-":
        write_atomic(_not_a_configuration(Path(output)), done[0][1], force, sources)
        return None
    return done[0][1]

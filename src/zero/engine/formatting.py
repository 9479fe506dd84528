"""``zero format``: a list in canonical layout, meaning kept.

Values aligned in one column, comments in another, no trailing whitespace; keys,
values, comments and their order stay, and so do the encoding and line endings (a list in a
code page the configuration declares, e.g. CP850, stays in it byte for byte).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from zero.catalog.registry import Registry
from zero.engine.commands import Echo
from zero.engine.discovery import collect_files
from zero.engine.project import Project, Registries, common_of, open_project
from zero.errors import ZeroError
from zero.files import read_file, write_atomic
from zero.forms import PROJECT_ROOTS, TWINCAT_ROOT, XML_ROOTS, is_list, is_xml
from zero.lists.encoding import encode_text, foreign_control
from zero.lists.model import Document
from zero.lists.tokenizer import tokenize
from zero.records import Record
from zero.structured.tree import DEFAULT_VALUE_COLUMN, from_document, to_list_text

COMMENT_OFFSET = 15  # comments start this many columns after the value column


def undeclared_code_page(doc: Document, why: str) -> None:
    """:class:`ZeroError` for a list that holds a C1 control (a byte of another code page read as
    Latin-1), saying ``why`` it cannot go on and that declaring the code page reads it right."""
    found = foreign_control(doc)
    if found is None:
        return
    line, column, byte = found
    code = ord(doc.lines[line - 1][column])
    raise ZeroError(f"byte 0x{byte} reads as control character U+{code:04X} in {doc.encoding}: {why}; a list "
                    "written in another code page (CP850: 0x81 is `ü`) is read right when the configuration "
                    'declares it, e.g. encoding = {"old/**/*.lis" = "cp850"}', doc.path, line, column + 1)


def format_bytes(data: bytes, path: str, registry: Registry, value_column: int | None = None,
                 encoding: str | None = None) -> bytes:
    """The list in canonical layout: values aligned in one column (the vendor's column 55, or
    after the longest key), comments 15 columns after it (one space after a longer value), no
    trailing whitespace; order, values, comments, encoding and line endings kept. Earlier lines
    of a key set twice stay as written. :class:`~zero.errors.ZeroError` for lines it cannot
    read (the registry only tells which values are numbers). ``encoding``: the code page the
    configuration declares for the list (``None``: detected). An XML list keeps its layout (the
    vendor's XML is its own canonical form: nothing changes); the lists of a TwinCAT export are
    formatted inside their CDATA sections, every byte outside them kept."""
    if is_xml(data):
        return _format_xml(data, path, registry, value_column)
    doc = tokenize(data, path, encoding)
    undeclared_code_page(doc, "zero format cannot lay out a line that holds it")
    tree = from_document(doc, registry)
    meta = tree.meta
    # A key written with whitespace inside means something else to the controller (S004):
    # format keeps such a line as it is; `zero lint --fix` joins the key.
    layout = meta.pop("layout", {})
    kept = {k: t for k, t in layout.items() if any(c in t.partition("{v}")[0].strip() for c in " \t")}
    if kept:
        meta["layout"] = kept
    for key in ("before", "tail"):
        meta.pop(key, None)
    if isinstance(meta.get("end"), str) and meta["end"]:
        meta["end"] = meta["end"].strip()
    if isinstance(meta.get("after_end"), list):
        meta["after_end"] = [x.rstrip() for x in meta["after_end"]]
    widest = max((len(leaf.key) for leaf in tree.leaves), default=0)
    column = value_column if value_column is not None else DEFAULT_VALUE_COLUMN
    if widest >= column:
        column = widest + 1
    meta["value_column"] = column
    if any(leaf.after is not None for leaf in tree.leaves):
        meta["comment_column"] = column + COMMENT_OFFSET  # the vendor's 55 / 70
    else:
        meta.pop("comment_column", None)
    text = to_list_text(tree).text
    return encode_text(text, doc.encoding, doc.bom, path)


def _format_xml(data: bytes, path: str, registry: Registry, value_column: int | None) -> bytes:
    from zero.markup.documents import embedded_documents, list_text, splice  # start-up: only for XML
    from zero.markup.safe import scan  # start-up: as above

    sc = scan(data, path)
    if sc.root != TWINCAT_ROOT and sc.root not in PROJECT_ROOTS:  # not an export or a project
        if sc.root not in XML_ROOTS:
            raise ZeroError(f"the root element `<{sc.root}>` is not that of a parameter list", path, 1, 1)
        return data
    _, lists = embedded_documents(data, path, sc)
    texts = [(item, format_bytes(list_text(item), path, registry, value_column, item.doc.encoding)
              .decode(item.doc.encoding, "surrogateescape")) for item in lists]
    return splice(sc, path, texts)


# ------------------------------------------------------------------ zero format (the command)


class FormatRun(Record):
    """What ``zero format`` did: files looked at, changed, that could not be formatted or read."""

    files: int = 0
    changed: int = 0
    failed: int = 0
    unreadable: int = 0


def run_format(paths: Sequence[str | Path], registries: Registries, echo: Echo, check: bool = False,
               show_diff: bool = False, config: str | Path | Sequence[str] | None = None, isolated: bool = False,
               param_desc: str | Path | None = None, read_stdin: Callable[[], bytes] | None = None,
               stdin_filename: str | None = None) -> FormatRun:
    """``zero format``: rewrite files in canonical layout; with ``check``/``show_diff`` only
    report (never write). ``-`` formats standard input to standard output."""
    from zero.engine.fixes import unified_diff  # start-up: `zero lint` does not format

    project = open_project(registries, common_of(config, isolated, param_desc))
    if [str(p) for p in paths] == ["-"]:
        if read_stdin is None:
            raise ZeroError("standard input is not available here")
        return _format_stdin(read_stdin(), stdin_filename or "-", project, echo, check, show_diff)
    files = collect_files([Path(p) for p in paths], include=project.included, exclude=project.excluded,
                          respect_gitignore=project.respects_gitignore)
    lists = [f for f in files if is_list(str(f))]  # NC programs and structured forms are not reformatted
    run = FormatRun(len(lists))
    for f in lists:
        try:
            data = read_file(f)
        except ZeroError as exc:  # one file that cannot be read: said, and the others go on
            echo.err(f"zero: {exc} (not formatted)\n")
            run.unreadable += 1
            continue
        settings = project.settings(f)
        new = _formatted(data, str(f), settings.registry, echo, run, settings.encoding)
        if new is None or new == data:
            continue
        run.changed += 1
        if show_diff:
            echo.out_bytes(unified_diff(str(f), data, new))
        elif check:
            echo.out(f"would reformat {f}\n")
        else:
            write_atomic(f, new, force=True)
    return run


def _formatted(data: bytes, name: str, registry: Registry, echo: Echo, run: FormatRun,
               encoding: str | None = None) -> bytes | None:
    try:
        return format_bytes(data, name, registry, encoding=encoding)
    except ZeroError as exc:
        echo.err(f"zero: {exc} (not formatted)\n")
        run.failed += 1
        return None


def _format_stdin(data: bytes, name: str, project: Project, echo: Echo, check: bool, show_diff: bool) -> FormatRun:
    from zero.engine.fixes import unified_diff  # start-up: `zero lint` does not format

    run = FormatRun(1)
    if not is_list(name):  # an NC program or a structured form passes through unchanged
        if not (check or show_diff):
            echo.out_bytes(data)
        return run
    new = None if name != "-" and project.excluded(Path(name)) else \
        _formatted(data, name, project.settings(Path(name)).registry, echo, run,
                   project.settings(Path(name)).encoding if name != "-" else None)
    if new is not None and new != data:
        run.changed = 1
    if show_diff:
        echo.out_bytes(unified_diff(name, data, new) if new is not None else b"")
    elif check:
        if run.changed:
            echo.out(f"would reformat {name}\n")
    else:
        echo.out_bytes(new if new is not None else data)
    return run

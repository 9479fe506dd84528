"""The documents an editor has open, each analysed as ``zero lint`` analyses the file.

The protocol layer hands in a document's URI, version and text; :meth:`Projects.analyse`
returns an :class:`Analysis`: the findings of the engine with the configuration of the
file's project applied (``[tool.zero]``, ``per-file-ignores``, ``exclude``, ``param-desc``,
noqa), and, where the project names its machine (``[tool.zero.machine]``), the X findings
of the machine's lists and the N findings of NC programs against it. The text the editor
holds is linted, not the file: where it equals the file as zero decodes it, the file's own
bytes are linted (its encoding, BOM and line endings, exactly as on the command line).

Positions between zero and the client are :mod:`zero.server.positions`; what the client may
set is :mod:`zero.server.settings`.
"""

from __future__ import annotations

import os
import re
from collections import OrderedDict
from collections.abc import Mapping
from pathlib import Path

from zero.catalog.registry import Registry
from zero.catalog.values import ListValues
from zero.diagnostics import Diagnostic, Severity
from zero.engine.config import Config
from zero.engine.lint import (
    LintOptions,
    LintResult,
    lint_data,
    lint_in_machine,
    lint_program,
)
from zero.engine.project import Common, Registries, open_project
from zero.engine.project import Settings as FileSettings
from zero.errors import ZeroError
from zero.files import check_shape, max_file_bytes, read_file
from zero.forms import LIST, PROGRAM, STRUCTURED, TWINCAT, form_of, is_xml, xml_form
from zero.lists.model import Document
from zero.lists.tokenizer import tokenize
from zero.machine.model import ListFile, Machine
from zero.markup import read_document
from zero.markup.documents import embedded_documents
from zero.records import Record, field, replace
from zero.server.positions import Text, path_of, source_bytes
from zero.server.settings import Settings

# A YAML/TOML/JSON file is a list's structured form when it carries zero's record.
# Leading `[ \t]`, not `\s`: `\s*` at every line start ran over every blank line after it (quadratic in
# them); a record after blank lines is found at its own line's start all the same.
_ZERO_RECORD = re.compile(r'^(?:_zero\s*+:|\[\s*+_zero\s*+\]|[ \t]*+"_zero"\s*+:)', re.MULTILINE)


class Note(Record):
    """Something to show that is no rule's finding: a configuration that cannot be read, a
    structured form that is not a list, a machine that cannot be built."""

    message: str
    line: int = 1
    column: int = 1
    severity: Severity = Severity.ERROR
    elsewhere: tuple[Path, int, int] | None = None  # the place in another file it is about (1-based)


class Place(Record, eq=False):
    """A position of the file the editor has open in the list text it holds: the list (the list a list
    file or an XML list is, or one list of a TwinCAT export) and the 0-based line and column there."""

    values: ListValues
    line: int
    column: int
    shift: int = 0  # the file's column of the list's column 0 on this line (not on an XML parameter element)
    element: bool = False  # on a parameter element of an XML list (its name is the key, its Value the value)


def file_position(doc: Document, line: int, column: int, end: bool = False) -> tuple[int, int]:
    """A 0-based line and column of a list's text as the 0-based line and column in the file it was
    read from (the same where the list is the file; ``end``: the column is the end of a span)."""
    if doc.origin is None:
        return line, column
    target, col = doc.origin.locate(line + 1, column + 1, end)
    return target - 1, col - 1


def _place(exc: ZeroError) -> tuple[Path, int, int] | None:
    """Where in its file an error is (the configuration's TOML errors carry their line and column)."""
    if not exc.path:
        return None
    return Path(exc.path), exc.line or 1, exc.column or 1


class Analysis(Record, eq=False):
    uri: str
    version: int | None
    path: Path | None  # the file on disk, for file: URIs
    name: str  # what zero calls it in its findings
    form: str  # list, program, structured
    text: Text
    data: bytes
    saved: bool  # the editor's text is the file as saved
    registry: Registry
    config: Config
    options: LintOptions
    result: LintResult | None = None  # None: not linted (excluded, not a list's form, config error)
    notes: list[Note] = field(default_factory=list)
    machine: Machine | None = None
    references: dict[str, Path] = field(default_factory=dict)  # a start-up list: key → the list it opens
    cache: dict[str, object] = field(default_factory=dict)  # answers that depend on the text only
    _values: ListValues | None = None
    _lists: list[tuple[str, ListValues]] | None = None
    _rows: dict[int, list[tuple[ListValues, int]]] | None = None  # 1-based file line → (list, its line)

    @property
    def markup(self) -> str | None:
        """``"xml"`` for an XML list, ``"twincat"`` for a TwinCAT export, else ``None`` (lists only)."""
        return xml_form(self.data) if self.form == LIST else None

    @property
    def diagnostics(self) -> list[Diagnostic]:
        return self.result.diagnostics if self.result is not None else []

    def values(self) -> ListValues | None:
        """The list's entries bound to their parameters (lists only), built on first use."""
        if self._values is None and self.form == LIST:
            if is_xml(self.data):  # the list an XML list is (a report shows the XML lines instead)
                if xml_form(self.data) == TWINCAT:
                    return None  # several lists: :meth:`lists`
                try:
                    doc = read_document(self.data, self.name, self.registry)
                except ZeroError:
                    return None
            else:
                doc = self.result.document if self.result is not None else tokenize(self.data, self.name)
            kind = self.result.kind if self.result is not None else self.options.kind
            self._values = ListValues.of(doc, self.registry, kind)
        return self._values

    def document(self) -> Document | None:
        """The list text the document is (an XML list's with its way back to the XML lines); ``None``
        for a TwinCAT export (it holds several) and XML zero cannot read."""
        if self.markup is None and self.result is not None:
            return self.result.document
        values = self.values()
        return values.doc if values is not None else None

    def lists(self) -> list[tuple[str, ListValues]]:
        """Every list the document holds, with the element that holds it in a TwinCAT export ("" for
        the list a list file or an XML list is)."""
        if self._lists is None:
            self._lists = []
            if self.markup == TWINCAT:
                try:
                    _, items = embedded_documents(self.data, self.name)
                except ZeroError:
                    items = []
                self._lists = [(item.element, ListValues.of(item.doc, self.registry, item.kind)) for item in items]
            elif (values := self.values()) is not None:
                self._lists = [("", values)]
        return self._lists

    def place(self, line: int, column: int) -> Place | None:
        """The list text at the 0-based ``line`` and code-point ``column`` of the document: the same
        place in a list file; in an XML list the same line, a column on a parameter element mapped to
        its key (the element's name and what comes before its value) or its value; in a TwinCAT export
        the line of the list whose CDATA holds the position (``None`` outside every list)."""
        lists = self.lists()
        if len(lists) == 1 and lists[0][1].doc.origin is None:
            return Place(lists[0][1], line, column)
        if self._rows is None:
            self._rows = {}
            for _, values in lists:
                origin = values.doc.origin
                for n, (target, _, _) in (origin.shift.items() if origin is not None else ()):
                    self._rows.setdefault(target, []).append((values, n))
        for values, n in self._rows.get(line + 1, []):
            assert values.doc.origin is not None
            _, shift, entry = values.doc.origin.shift[n]
            if entry is not None:
                lis_value, vstart, vend, _, _ = entry
                col = 0 if column < vstart else (lis_value + column - vstart if column <= vend else
                                                 lis_value + vend - vstart + 1)
                return Place(values, n - 1, col, element=True)
            col = column - shift
            if 0 <= col <= len(values.doc.line_text(n)):
                return Place(values, n - 1, col, shift)
        return None

    def machine_list(self) -> ListFile | None:
        """This document as one of the lists of the machine (with the default list under it)."""
        if self.machine is None or self.path is None:
            return None
        me = os.path.realpath(self.path)
        return next((lf for lf in self.machine.lists if os.path.realpath(lf.path) == me), None)


def _structural(machine: Machine) -> set[str]:
    """The lists whose content decides the machine's shape (which lists, which channel axes,
    which values lie under others): only their saved content is used."""
    out = {os.path.realpath(machine.startup.path)}
    out.update(os.path.realpath(lf.path) for lf in machine.defaults.values())
    out.update(os.path.realpath(ch.lists.path) for ch in machine.channels if ch.lists is not None)
    return out


def _swap(machine: Machine, new: dict[int, ListFile]) -> Machine:
    """The machine with some of its lists replaced (by ``id`` of the list they replace)."""
    if not new:
        return machine

    def s(lf: ListFile) -> ListFile:
        return new.get(id(lf), lf)

    def o(lf: ListFile | None) -> ListFile | None:
        return s(lf) if lf is not None else None

    channels = [replace(ch, lists=o(ch.lists), zero=o(ch.zero), tools=o(ch.tools),
                        others={k: s(v) for k, v in ch.others.items()}) for ch in machine.channels]
    return replace(machine, startup=s(machine.startup), axis_lists=[s(lf) for lf in machine.axis_lists],
                   channels=channels, defaults={k: s(v) for k, v in machine.defaults.items()},
                   singles={k: s(v) for k, v in machine.singles.items()},
                   compensation=[(i, s(lf)) for i, lf in machine.compensation])


class Projects:
    """The configuration, registry and machine of each document's project, read once and read
    again when the files change (:meth:`forget`)."""

    def __init__(self, registries: Registries, param_desc: Path | None = None,
                 settings: Settings | None = None) -> None:
        self.registries = registries
        self.settings = settings or Settings()
        # the resolver `zero lint` uses; files named absolutely (the server's current directory is nobody's)
        self.project = open_project(registries, Common(param_desc=param_desc), shown_from=None)
        self._values: OrderedDict[tuple[str, int, str], ListValues] = OrderedDict()

    def forget(self) -> None:
        """Configuration files changed (or may have): find and read them again."""
        self.project.forget()

    def config(self, path: Path | None) -> Config:
        """The configuration that applies to ``path`` (:class:`ZeroError` when it cannot be read)."""
        return self.project.settings(path).config if path is not None else Config()

    def file_settings(self, path: Path) -> FileSettings:
        """Everything that applies to ``path``, as ``zero lint`` resolves it (:class:`ZeroError` when
        its configuration or parameter description cannot be read)."""
        return self.project.settings(path)

    def machine(self, path: Path | None) -> Machine | None:
        """The machine the file's configuration names, as saved (:class:`ZeroError` when it cannot be read)."""
        if path is None or not self.settings.machine:
            return None
        return self.project.machine(path)

    def analyse(self, uri: str, version: int | None, text: str, encoding: str = "utf-16",
                buffers: Mapping[str, str] | None = None) -> Analysis:
        """Lint one document as ``zero lint`` lints the file; ``buffers`` (real path → text) are the
        other open documents, whose text counts for the machine's X findings."""
        path = path_of(uri)
        name = str(path) if path is not None else uri
        notes: list[Note] = []
        settings: FileSettings | None = None
        try:
            settings = self.file_settings(path) if path is not None else None
        except ZeroError as exc:
            notes.append(Note(f"the configuration cannot be read, nothing is checked: {exc}", elsewhere=_place(exc)))
        config = settings.config if settings is not None else Config()
        try:
            # an untitled document, or a configuration that cannot be read: no param-desc of its own
            registry = settings.registry if settings is not None else self.registries(self.project.param_desc_given)
        except ZeroError as exc:
            registry = self.registries(None)
            notes.append(Note(f"the parameter description cannot be read, nothing is checked: {exc}"))
        options = settings.options if settings is not None and not notes else \
            config.options_for(Path(name), LintOptions())
        data, saved = source_bytes(path, text, options.encoding)
        a = Analysis(uri, version, path, name, form_of(name), Text(text, encoding), data, saved, registry, config,
                     options, notes=notes)
        if notes or (path is not None and config.excluded(path)):
            return a  # as `zero lint`: a broken configuration checks nothing; an excluded file is not linted
        if len(data) > max_file_bytes():
            a.notes.append(Note(f"larger than the size limit ({max_file_bytes()} bytes, ZERO_MAX_FILE_SIZE): "
                                "not checked", severity=Severity.WARNING))
            return a
        try:
            check_shape(data, name)
        except ZeroError as exc:
            a.notes.append(Note(f"{exc.message}: not checked", severity=Severity.WARNING))
            return a
        if a.form == STRUCTURED and not self._is_list_form(text, config, path):
            return a
        if a.form == PROGRAM:
            a.machine = self._try_machine(a, buffers or {})
        try:
            if a.form == PROGRAM:
                a.result = lint_program(data, registry, name, options, a.machine)
            else:
                a.result = lint_data(data, name, registry, options)
        except ZeroError as exc:  # a YAML/TOML/JSON form that does not make a list
            a.notes.append(Note(exc.message, exc.line or 1, exc.column or 1))
            return a
        if a.form == LIST and path is not None:
            if a.markup is None and a.result.kind == "STUP":
                a.references = self.project.references(path, a.result.document)
            elif a.markup is not None:  # a start-up list in XML, or the `<Startup>` list of a TwinCAT export
                for _, values in a.lists():
                    if values.kind == "STUP":
                        a.references.update(self.project.references(path, values.doc))
        if a.form == LIST:
            a.machine = self._try_machine(a, buffers or {})
            doc = a.document()
            if a.machine is not None and a.path is not None and doc is not None:
                # as `zero lint` and `zero lint --machine` lint it (an XML list: its list text, placed in the XML)
                linted = lint_in_machine(name, a.machine, registry, options, doc)
                a.result = linted if linted is not None else a.result
        return a

    def _try_machine(self, a: Analysis, buffers: Mapping[str, str]) -> Machine | None:
        """The machine, or None with a note where it cannot be read (said on NC programs, as `zero lint`
        says it, and on the start-up list; the project's other lists are checked as without one)."""
        try:
            return self._machine_for(a, buffers)
        except ZeroError as exc:
            startup = self.project.startup(a.path) if a.path is not None else None
            if a.form == PROGRAM or (startup is not None and a.path is not None
                                     and os.path.realpath(startup) == os.path.realpath(a.path)):
                a.notes.append(Note(f"the machine of [tool.zero.machine] cannot be read: {exc}",
                                    severity=Severity.WARNING))
            return None

    def _is_list_form(self, text: str, config: Config, path: Path | None) -> bool:
        if self.settings.structured == "all" or _ZERO_RECORD.search(text):
            return True
        return path is not None and config.path is not None and config.included(path)

    def _list_values(self, lf: ListFile, text: str) -> ListValues:
        """An open document's text as the values of one of the machine's lists (cached)."""
        key = (str(lf.path), id(lf.values.registry), text)
        hit = self._values.get(key)
        if hit is None:
            data, _ = source_bytes(lf.path, text, self.project.settings(lf.path).encoding)
            hit = ListValues.of(read_document(data, str(lf.path), lf.values.registry), lf.values.registry,
                                lf.values.kind)
            self._values[key] = hit
            while len(self._values) > 8:
                self._values.popitem(last=False)
        return hit

    def _machine_for(self, a: Analysis, buffers: Mapping[str, str]) -> Machine | None:
        """The machine with the open documents' text in place of their saved lists: read again with
        it where a list that shapes the machine (start-up, channel, default lists) is changed."""
        machine = self.machine(a.path)
        if machine is None:
            return None
        me = os.path.realpath(a.path) if a.path is not None else None
        structural = _structural(machine)
        texts = {real: buffers[real] for real in structural if real in buffers}
        if me in structural and a.path is not None:
            texts[me] = a.text.source
        texts = {real: t for real, t in texts.items()  # the changed ones
                 if not source_bytes(Path(real), t, self.project.settings(Path(real)).encoding)[1]}
        if texts:
            try:
                def reader(path: Path) -> bytes:
                    text = texts.get(os.path.realpath(path))
                    return read_file(path) if text is None else \
                        source_bytes(path, text, self.project.settings(path).encoding)[0]

                shaped = self.project.machine(a.path, reader=reader, reader_key=tuple(sorted(texts.items())))
            except ZeroError as exc:
                a.notes.append(Note(f"the machine cannot be read with the unsaved lists: {exc}",
                                    severity=Severity.WARNING))
                return None
            assert shaped is not None  # the project names its machine: it was read above
            machine = shaped
            structural = _structural(machine)
        if a.form == LIST and me not in {os.path.realpath(lf.path) for lf in machine.lists}:
            return None  # a list of the project the machine does not read
        new: dict[int, ListFile] = {}
        for lf in machine.lists:
            real = os.path.realpath(lf.path)
            if real in structural:
                continue
            if real == me and a.result is not None:  # this document: as its lint has read it
                own = a.values()
                doc = a.document()
                if doc is None:
                    continue  # XML it cannot read: the list as saved
                values = own if own is not None and own.kind == lf.values.kind else \
                    ListValues.of(doc, a.registry, lf.values.kind)
            elif real in buffers:
                values = self._list_values(lf, buffers[real])
            else:
                continue
            new[id(lf)] = replace(lf, values=replace(values, base=lf.values.base))
        return _swap(machine, new)

"""Lint orchestration: which rules run, over what, with which registry.

Everything ``zero lint`` does to one input is callable here: a list (bytes or a
document), a YAML/TOML/JSON file (linted as the list it converts to, findings located
in the structured file), an NC program (with the machine it runs on, when known), and a
whole machine (every list its start-up list names, plus the X rules across them).
:func:`lint_file` picks the right one by the file's suffix. The registry is always
passed in.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence

from zero.catalog.registry import Registry, kind_from_name
from zero.diagnostics import Diagnostic, Severity, Span
from zero.engine.results import LintOptions, LintResult, Totals, is_unreadable, tallied
from zero.engine.selection import ALL, Layer, layered_selection, selected_rules
from zero.engine.selection import _selected_rules as _selected_rules  # the reference tests/engine/ hold to
from zero.errors import ZeroError
from zero.files import read_file
from zero.forms import is_program, is_update, is_xml, structured_format
from zero.lists.encoding import decode
from zero.lists.model import Document
from zero.lists.tokenizer import read_as_bytes, tokenize, tokenize_text
from zero.patterns import compiled
from zero.records import replace
from zero.rules import (
    MACHINE_CHECKS,
    PROGRAM_CHECKS,
    MachineContext,
    ProgramContext,
    check_document,
    run_checks,
)
from zero.rules.base import declared_codes, default_severity
from zero.rules.funnel import funnel
from zero.rules.suppress import parse_comment_directives

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:  # start-up: linting a list loads neither the machine model nor the structured forms
    import re
    from pathlib import Path  # (nor pathlib: the lint path names files by their text)

    from zero.catalog.values import ListValues
    from zero.machine.model import ListFile, Machine
    from zero.structured.common import Found
    from zero.structured.tree import Tree


def lint_document(doc: Document, registry: Registry, options: LintOptions | None = None,
                  extra: Sequence[Diagnostic] = (), default_list: bool = False,
                  base: ListValues | None = None) -> LintResult:
    """One list's findings; ``extra`` are findings about it from its machine (suppressible in it);
    ``default_list``: its machine reads it as a default list; ``base``: the default list its machine
    reads under it (every rule then judges the machine's layered values)."""
    options = options or LintOptions()
    kind = options.kind or (doc.origin.kind if doc.origin is not None else None)
    ctx, found = check_document(doc, registry, kind, selected_rules(options), extra, options.kernel, default_list,
                                base, noqa=not options.ignore_noqa)
    if doc.origin is not None:  # read from XML: the findings where the user has the file open
        from zero.markup.documents import relocate, shown_document  # start-up: only for XML

        placed = sorted((relocate(d, doc.origin) for d in found), key=lambda d: d.sort_key())
        return LintResult(doc.path, shown_document(doc.path, doc.origin, doc.encoding), ctx.kind, placed)
    return LintResult(doc.path, doc, ctx.kind, found)


def lint_bytes(data: bytes, registry: Registry, path: str = "-",
               options: LintOptions | None = None) -> LintResult:
    return lint_document(tokenize(data, path, options.encoding if options else None), registry, options)


def lint_tree(tree: Tree, registry: Registry, options: LintOptions | None = None,
              source: str | None = None, json_source: bool = False) -> LintResult:
    """Lint the list a tree makes; findings point at the structured file where known (in JSON,
    which its reader does not locate, found in ``source`` when there are findings)."""
    from zero.structured.tree import (  # start-up: not for lists
        encode_list,
        source_span,
        structured_path,
        to_list_text,
    )

    written = to_list_text(tree)
    data = encode_list(tree, written.text)
    doc = tokenize(data, tree.path)
    opts = options or LintOptions()
    kind = tree.meta.get("kind") if isinstance(tree.meta.get("kind"), str) else None
    if opts.kind is None and kind:
        opts = replace(opts, kind=kind_from_name(kind))
    result = lint_document(doc, registry, opts)
    lines = source.split("\n") if source is not None else []
    shown = Document(tree.path, "utf-8", [x.rstrip("\r") for x in lines], [], [])

    def relocate(m: re.Match[str]) -> str:
        other = written.lines_of.get(int(m.group(1)))
        if other is None:
            return m.group(0)
        at = f"line {other.line}" if other.line else "the entry"
        return f"{at} (`{structured_path(other.path)}`)"

    positions: dict[tuple[str, ...], Found] | None = None
    out = []
    for d in result.diagnostics:
        leaf = written.lines_of.get(d.span.line)
        if leaf is not None and leaf.line is None and json_source and source is not None:
            if positions is None:
                from zero.structured.json import scan_json  # start-up: only a JSON file with findings

                positions = scan_json(source)
            at = positions.get(leaf.path)
            if at is not None:
                leaf = replace(leaf, line=at.line, column=at.column, key_at=at.key_at)
        if leaf is None:
            span = Span(1, 1, 1, 1)
            message = f"(list line {d.span.line}) {d.message}"
        else:
            span = source_span(leaf, doc, d.span)  # a key rule's finding on the key, any other on the value
            message = f"{structured_path(leaf.path)}: " + compiled(r"\bline (\d+)").sub(relocate, d.message)
        out.append(replace(d, span=span, message=message, fix=None, related=()))
    out.sort(key=lambda d: d.sort_key())
    return LintResult(tree.path, shown, result.kind, out)


_P_ID = r"P-[A-Z]{4}-[0-9]{5}"  # compiled at its first use (re keeps it): YAML/TOML/JSON forms only


def list_form(tree: Tree, registry: Registry) -> bool:
    """Is a YAML/TOML/JSON document a list form: zero's ``_zero`` table, or top-level keys most of
    which are parameter IDs or the first name of a parameter key (``kopf``, ``np_grp``)? Decided
    on the tree read with every guard (never by parsing the file again)."""
    if tree.meta:
        return True
    top = {leaf.path[0] for leaf in tree.leaves if leaf.path}
    if not top:
        return True  # an empty form: an empty list
    heads: dict[str, bool] = registry.memo.setdefault("key-heads", {})
    if not heads:
        heads.update((compiled(r"[.\[]").split(s.key, maxsplit=1)[0], True) for s in registry.specs.values() if s.key)
    ours = sum(1 for k in top if k in heads or compiled(_P_ID).fullmatch(k) is not None)
    return ours > 0 and 2 * ours >= len(top)  # most of them: `a`, `tool`, `path` are parameters' too


def lint_structured(data: bytes, fmt: str, registry: Registry, path: str = "-",
                    options: LintOptions | None = None) -> LintResult:
    """Lint YAML/TOML/JSON bytes as the list they convert to. What does not read as a list form
    (invalid, hostile, keys that are no keys) is one S017 finding where the reader stopped; a
    document that reads but is no list form (see :func:`list_form`) is skipped with a note."""
    from zero.structured.formats import read_tree  # start-up: not for lists

    try:
        tree = read_tree(data, fmt, registry, path)
    except ZeroError as exc:
        return refused(path, data, exc, options, "S017")
    if not list_form(tree, registry):
        return LintResult(path, _shown(path, data), None, [],
                          note=f"not a {fmt.upper()} list form (its top-level keys are not parameters', no `_zero` "
                               "table): skipped")
    source = data.decode("utf-8", "replace").lstrip("\ufeff")
    return lint_tree(tree, registry, options, source, fmt == "json")


def lint_program(data: bytes, registry: Registry, path: str = "-", options: LintOptions | None = None,
                 machine: Machine | None = None) -> LintResult:
    """Findings N001–N004 for one NC program (N003/N004 need the machine)."""
    from zero.nc.program import comment_spans, read_program, strip_comments  # start-up: not for lists

    program = read_program(data, path, registry)
    severities = selected_rules(options or LintOptions())
    ctx = ProgramContext(program, registry, machine, severities, path)
    found = run_checks(PROGRAM_CHECKS, ctx)
    lines = program.doc.lines  # suppressions in the program's own comments: `( noqa: N003 )`, `; noqa`
    comments = [(n, col, text) for n, line in enumerate(lines, 1) if "(" in line or ";" in line
                 for col, text in comment_spans(line)]
    directives = None
    if comments and not (options and options.ignore_noqa):
        code = [n for n, line in enumerate(lines, 1) if strip_comments(line).strip()]
        directives = parse_comment_directives(comments, code, declared_codes())
    return LintResult(path, program.doc, "PROGRAM", funnel(path, found, severities, directives))


def lint_data(data: bytes, path: str, registry: Registry, options: LintOptions | None = None) -> LintResult:
    """Lint bytes as the file ``path`` names: an NC program, YAML/TOML/JSON, else a list (an XML list
    or a TwinCAT export when the content is XML)."""
    if is_program(path):
        return lint_program(data, registry, path, options)
    fmt = structured_format(path)
    if fmt is not None:
        return lint_structured(data, fmt, registry, path, options)
    if is_xml(data):
        return lint_xml(data, path, registry, options)
    return lint_bytes(data, registry, path, options)


def lint_xml(data: bytes, path: str, registry: Registry, options: LintOptions | None = None) -> LintResult:
    """An XML list, or every list a TwinCAT export holds, with findings placed in the XML file. XML
    zero will not read (not well-formed, a DTD, entities) is one located S014 finding."""
    from zero.markup.documents import (  # start-up: only for XML
        TWINCAT,
        embedded_documents,
        shown_document,
        xml_document,
        xml_form,
    )
    from zero.markup.safe import scan  # start-up: only for XML

    opts = options or LintOptions()
    try:
        if xml_form(data) == TWINCAT:  # a TwinCAT export or project: every list it holds
            sc, items = embedded_documents(data, path)
            docs = [item.doc for item in items]
        else:
            sc = scan(data, path)
            docs = [xml_document(data, path, registry, sc)]
    except ZeroError as exc:
        return refused(path, data, exc, opts)
    if not docs:  # never "checked (clean)": nothing in it was checked
        return LintResult(path, _shown(path, data), None, [],
                          note=f"a TwinCAT {'export' if sc.root == 'TreeItem' else 'file'} `<{sc.root}>` that holds no "
                               "parameter list zero knows: skipped")
    results = [lint_document(doc, registry, opts) for doc in docs]  # each placed in the XML file by its origin
    found = sorted((d for r in results for d in r.diagnostics), key=lambda d: d.sort_key())
    shown = shown_document(path, docs[0].origin, sc.encoding) if docs and docs[0].origin else _shown(path, data)
    return LintResult(path, shown, results[0].kind if len(results) == 1 else None, found)


def _shown(path: str, data: bytes) -> Document:
    lines = data.decode("utf-8", "replace").lstrip("\ufeff").split("\n")
    return Document(path, "utf-8", [x.rstrip("\r") for x in lines], ["\n"] * len(lines), [])


def refused(path: str, data: bytes, error: ZeroError, options: LintOptions | None = None,
            code: str = "S014") -> LintResult:
    """The result for a file zero will not read (XML: S014; a YAML/TOML/JSON form: S017): one
    finding where the reader stopped, nothing checked."""
    line, col = error.line or 1, error.column or 1
    finding = Diagnostic(code, default_severity(code) or Severity.ERROR, f"{error.message}: not checked",
                         Span(line, col, line, col + 1), path)
    found = funnel(path, [finding], selected_rules(options or LintOptions()))
    return LintResult(path, _shown(path, data), None, found)


def unreadable(path: str, error: ZeroError, options: LintOptions | None = None) -> LintResult:
    """The result for a file that could not be read: one F001 finding (through the funnel, so
    ``--ignore F001`` leaves the file out in silence), nothing checked."""
    message = f"{error.message}: not checked"
    finding = Diagnostic("F001", default_severity("F001") or Severity.ERROR, message, Span(1, 1, 1, 1), path)
    found = funnel(path, [finding], selected_rules(options or LintOptions()))
    return LintResult(path, Document(path, "utf-8", [], [], []), None, found)


def lint_file(path: str | os.PathLike[str], registry: Registry, options: LintOptions | None = None) -> LintResult:
    """Lint a file by its suffix; a file that cannot be read is one F001 finding."""
    try:
        data = read_file(path)
    except ZeroError as exc:
        return unreadable(str(path), exc, options)
    name = str(path)
    if is_program(name) or structured_format(name) is not None or is_xml(data):
        return lint_data(data, name, registry, options)
    # a list file (lint_bytes), held once: a big ASCII list as its bytes (the document keeps them), any
    # other as its text (the bytes let go once decoded)
    declared = options.encoding if options else None
    if read_as_bytes(data):
        return lint_document(tokenize(data, name, declared), registry, options)
    text, codec, bom = decode(data, declared)
    del data
    return lint_document(tokenize_text(text, name, codec, bom, declared=declared is not None), registry, options)


def lint_update_in_machine(path: str, data: bytes, machine: Machine, registry: Registry,
                           options: LintOptions | None = None) -> LintResult | None:
    """An update or revert file checked against the machine it is applied to (``zero lint --machine
    STARTUP UPDATE``): its own findings, U003 when its axis number names no axis of the machine, and
    the findings its values get among the other values of the list it changes (the list with the
    update applied, each finding on the update's line). ``None`` when ``path`` is no update file."""
    from zero.markup.documents import xml_document  # start-up: only for XML

    if not is_update(path) or not is_xml(data):
        return None
    opts = options or LintOptions()
    try:
        doc = xml_document(data, path, registry)
    except ZeroError:
        return None
    assert doc.origin is not None
    result = lint_document(doc, registry, opts)
    kind = result.kind
    severities = selected_rules(opts)
    target, extra = _update_target(doc, kind, machine, severities)
    if target is not None:
        extra.extend(_in_context(doc, target, registry, kind, severities))
    if not extra:
        return result
    # through the update's own funnel (its selection, severities and suppressions), as its own findings
    return lint_document(doc, registry, replace(opts, kind=kind) if kind else opts, extra)


def _update_target(doc: Document, kind: str | None, machine: Machine,
                   severities: dict[str, Severity]) -> tuple[ListFile | None, list[Diagnostic]]:
    """The list of the machine an update changes, or why there is none (U003)."""
    from zero.catalog.evidence import claim  # start-up: only with a machine
    from zero.machine.model import axis_of  # start-up: as above

    if kind == "AXIS":
        entry = next((e for e in doc.entries if e.key_text == "kopf.achs_nr"), None)
        if entry is None or not entry.value.lstrip("-").isdigit():
            return None, []  # U002 says so
        nr = int(entry.value)
        for lf in machine.axis_lists:
            ax = axis_of(lf)
            if ax is not None and ax.nr == nr:
                return lf, []
        if "U003" not in severities or not machine.complete_axes():
            return None, []
        known = ", ".join(str(n) for n in sorted(machine.axes())) or "none"
        c = claim("update-axis-unknown")  # what the kernel does, and the page (zero.catalog.evidence)
        return None, [Diagnostic("U003", severities["U003"],
                                 f"this update is for logical axis {nr}, which no axis list of the machine has "
                                 f"(its axes: {known}): {c.says}",
                                 Span.on_line(entry.line, entry.value_start, entry.value_end), doc.path,
                                 "P-AXIS-00016", kernel_error=c.kernel_error, consequence=c.consequence,
                                 source=c.source)]
    if len(machine.channels) != 1:  # which channel a channel-wide update is for: not said
        return None, []
    channel = machine.channels[0]
    by_kind = {"CHAN": channel.lists, "ZERO": channel.zero, "TOOL": channel.tools}
    return by_kind.get(kind or ""), []


def _in_context(doc: Document, target: ListFile, registry: Registry, kind: str | None,
                severities: dict[str, Severity]) -> list[Diagnostic]:
    """The findings an update's entries get in the list they change and not alone, on their lines."""
    from zero.catalog.values import canonical_key  # start-up: only with a machine
    from zero.lists.tokenizer import tokenize_text  # start-up: as above

    base = target.values.doc
    end = base.end_line - 1 if base.end_line is not None else len(base.lines)
    changed = {canonical_key(registry, kind, e) for e in doc.entries}
    lines = list(base.lines[:end])
    for e in base.entries:  # the values the update replaces: blank lines, so every line keeps its number
        if e.line <= end and canonical_key(registry, kind, e) in changed:
            lines[e.line - 1] = ""
    where: dict[int, int] = {}
    for e in doc.entries:
        lines.append(doc.lines[e.line - 1])
        where[len(lines)] = e.line
    merged = tokenize_text("\n".join([*lines, "Ende"]) + "\n", doc.path)
    # the update's directives are applied once, by its own funnel (lint_update_in_machine), not here
    alone = {(d.code, d.span.line) for d in check_document(doc, registry, kind, severities, noqa=False)[1]}
    out = []
    for d in check_document(merged, registry, kind, severities, noqa=False)[1]:
        line = where.get(d.span.line)
        if line is None or (d.code, line) in alone:
            continue
        message = compiled(r"\bline (\d+)\b").sub(lambda m: (f"line {where[int(m.group(1))]}"
                                                              if int(m.group(1)) in where
                                                              else f"{target.path}:{m.group(1)}"), d.message)
        span = Span(line, d.span.column, line, d.span.end_column)
        out.append(replace(d, span=span, message=f"with the update applied to {target.path}: {message}",
                           fix=None, related=()))
    return out


def machine_findings(machine: Machine, registry: Registry, wanted: dict[str, Severity]) -> dict[str, list[Diagnostic]]:
    """The X findings of a machine for the codes in ``wanted``, by the real path of the list they
    concern (each still to pass the funnel of that list)."""
    across: dict[str, list[Diagnostic]] = {}
    for d in run_checks(MACHINE_CHECKS, MachineContext(machine, registry, wanted)):
        across.setdefault(os.path.realpath(d.path), []).append(d)
    return across


def lint_machine(machine: Machine, registry: Registry,
                 options: LintOptions | Callable[[Path], LintOptions] | None = None) -> list[LintResult]:
    """Every list of a machine (loaded by :mod:`zero.engine.project`) with its own findings, plus the
    X findings on the list they concern (the start-up list, a channel list, a zero-offset list or an
    axis list). ``options`` may give each list its own options (its configuration): the X checks run
    for every code any list selects, and each finding then passes the funnel of the list it lands in."""
    fixed = options or LintOptions()
    options_for: Callable[[Path], LintOptions] = fixed if callable(fixed) else (lambda _p: fixed)
    per_list = [(lf, options_for(lf.path)) for lf in machine.lists]
    wanted: dict[str, Severity] = {}
    for _, opts in per_list:
        wanted.update(selected_rules(opts))
    across = machine_findings(machine, registry, wanted)
    results: dict[str, LintResult] = {}
    for lf, opts in per_list:
        if str(lf.path) not in results:
            results[str(lf.path)] = _in_machine(lf, lf.values.doc, registry, opts,
                                                across.get(os.path.realpath(lf.path), []), machine)
    return list(results.values())


def _in_machine(lf: ListFile, doc: Document, registry: Registry, options: LintOptions,
                found: list[Diagnostic], machine: Machine | None = None) -> LintResult:
    kind = lf.values.kind
    extra = [d if d.path == doc.path else replace(d, path=doc.path) for d in found]
    default = machine is not None and any(d is lf for d in machine.defaults.values())
    return lint_document(doc, registry, replace(options, kind=kind) if kind else options, extra, default,
                         None if default else lf.values.base)


def lint_in_machine(path: str, machine: Machine, registry: Registry, options: LintOptions,
                    doc: Document | None = None,
                    across: dict[str, list[Diagnostic]] | None = None) -> LintResult | None:
    """A list of the machine linted as ``zero lint --machine`` lints it: as the kind the start-up list
    reads it as, with the X findings that concern it (``across``: the machine's, when already
    found); ``None`` when the machine does not read this file. ``doc`` is the list as read here (an
    editor's unsaved text); by default the file as the machine read it, under the name ``path``."""
    me = os.path.realpath(path)
    lf = next((lf for lf in machine.lists if os.path.realpath(lf.path) == me), None)
    if lf is None:
        return None
    if doc is None:
        doc = lf.values.doc if lf.values.doc.path == path else replace(lf.values.doc, path=path)
    if across is None:
        across = machine_findings(machine, registry, selected_rules(options))
    return _in_machine(lf, doc, registry, options, across.get(me, []), machine)


__all__ = [
    "ALL",
    "Layer",
    "LintOptions",
    "LintResult",
    "Totals",
    "ZeroError",
    "is_unreadable",
    "layered_selection",
    "lint_bytes",
    "lint_data",
    "lint_document",
    "lint_file",
    "lint_in_machine",
    "lint_machine",
    "lint_program",
    "lint_structured",
    "lint_tree",
    "lint_update_in_machine",
    "lint_xml",
    "machine_findings",
    "refused",
    "selected_rules",
    "tallied",
    "unreadable",
]

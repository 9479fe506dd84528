"""Code actions and formatting: zero's own fixes, ``noqa`` directives and ``zero format`` as
text edits.

Every fix a finding carries is offered as a quick fix, labelled when it is unsafe (it
changes what the controller reads; ``zero lint --unsafe-fixes``); every finding of a list
can be suppressed on its line in the list's own comment syntax, written as ``zero lint
--add-noqa`` writes it (:func:`zero.engine.baseline.add_noqa`), and in the trailing comment
of a YAML/TOML line. ``source.fixAll.zero`` applies the safe fixes as ``zero lint --fix``
does, ``source.zero.fixAllUnsafe`` the unsafe ones too; formatting is ``zero format``.

Commands (``workspace/executeCommand``): ``zero.fixAll`` (arguments: the document's URI) makes
the edit of ``zero lint --fix``, which the server asks the client to apply
(``workspace/applyEdit``); ``zero.showEffectiveValue`` (arguments: the URI and a position
``{line, character}``) says where the value of the parameter there comes from on the machine,
as ``zero explain KEY`` says it (:func:`zero.machine.effective.scope_values`).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

from lsprotocol import types
from pygls.exceptions import JsonRpcInvalidParams

from zero.diagnostics import Diagnostic
from zero.engine.baseline import NOT_RECORDED, add_noqa
from zero.engine.fixes import fix_bytes
from zero.engine.formatting import format_bytes
from zero.engine.lint import LintResult
from zero.forms import COMMENTED_FORMS, LIST, PROGRAM, STRUCTURED, structured_format
from zero.lists.encoding import BOM, decode
from zero.server.documents import Analysis
from zero.server.findings import RuleDocs, span_range, to_lsp
from zero.server.hover import machine_lines, target_at
from zero.server.positions import Text

FIX_ALL = "source.fixAll.zero"
FIX_ALL_UNSAFE = "source.zero.fixAllUnsafe"  # not below source.fixAll: never applied on save unasked
KINDS = [types.CodeActionKind.QuickFix, FIX_ALL, FIX_ALL_UNSAFE]
_LINES = re.compile(r"[^\n]*\n|[^\n]+\Z")


def _split(text: str) -> list[str]:
    """Lines with their endings, split where zero and the client split them (after each LF)."""
    return _LINES.findall(text)


def _line_start(text: Text, old_lines: list[str], i: int) -> types.Position:
    """Where line ``i`` of the document starts (its end, for the line after the last)."""
    if i < len(old_lines):
        return types.Position(i, 0)
    if not old_lines or old_lines[-1].endswith("\n"):
        return types.Position(len(old_lines), 0)
    last = len(old_lines) - 1
    return types.Position(last, text.character(last, len(old_lines[-1])))


def line_edits(text: Text, new: str) -> list[types.TextEdit]:
    """The edits that turn the document into ``new``: one per run of changed lines (line by line
    where the number of lines stays, as ``zero format`` keeps it; else a diff of the lines between
    the common start and end: difflib over a whole long list that repeats itself took half a minute)."""
    old_lines, new_lines = _split(text.source), _split(new)

    def start_of(i: int) -> types.Position:
        return _line_start(text, old_lines, i)

    head = 0
    while head < min(len(old_lines), len(new_lines)) and old_lines[head] == new_lines[head]:
        head += 1
    tail = 0
    while tail < min(len(old_lines), len(new_lines)) - head and old_lines[-1 - tail] == new_lines[-1 - tail]:
        tail += 1
    if len(old_lines) == len(new_lines):
        opcodes = []
        i = head
        while i < len(old_lines) - tail:
            if old_lines[i] == new_lines[i]:
                i += 1
                continue
            j = i
            while j < len(old_lines) - tail and old_lines[j] != new_lines[j]:
                j += 1
            opcodes.append((i, j, i, j))
            i = j
    else:
        import difflib  # start-up: only when lines come or go

        matcher = difflib.SequenceMatcher(None, old_lines[head:len(old_lines) - tail],
                                          new_lines[head:len(new_lines) - tail], autojunk=False)
        opcodes = [(head + i1, head + i2, head + j1, head + j2)
                   for tag, i1, i2, j1, j2 in matcher.get_opcodes() if tag != "equal"]
    return [types.TextEdit(types.Range(start_of(i1), start_of(i2)), "".join(new_lines[j1:j2]))
            for i1, i2, j1, j2 in opcodes]


def _decoded(data: bytes, encoding: str | None) -> str:
    """Bytes zero wrote back in the document's own encoding, as text (a BOM dropped, as the editor does)."""
    if encoding is None:
        return decode(data)[0]
    return (data[3:] if data.startswith(BOM) else data).decode(encoding, "surrogateescape")


def _formatted(a: Analysis) -> str | None:
    """``zero format`` of the document as text, or None where nothing changes (:class:`~zero.errors.
    ZeroError` for a line it cannot read); NC programs and structured forms are not reformatted."""
    if a.form != LIST:
        return None
    new = format_bytes(a.data, a.name, a.registry, encoding=a.options.encoding)
    if new == a.data:
        return None
    return _decoded(new, a.result.document.encoding if a.result is not None else None)


def formatting(a: Analysis) -> list[types.TextEdit]:
    """``zero format`` of the document as edits."""
    decoded = _formatted(a)
    return [] if decoded is None else line_edits(a.text, decoded)


def range_formatting(a: Analysis, rng: types.Range) -> list[types.TextEdit]:
    """``zero format`` of the lines a range touches: the list is laid out as a whole (its value and
    comment columns are the list's), and only the changes on those lines are given."""
    decoded = _formatted(a)
    if decoded is None:
        return []
    first = rng.start.line
    last = rng.end.line - 1 if rng.end.character == 0 and rng.end.line > first else rng.end.line
    old_lines, new_lines = _split(a.text.source), _split(decoded)
    if len(old_lines) != len(new_lines):  # zero format keeps the lines; should it not: the runs in range
        return [e for e in line_edits(a.text, decoded) if e.range.start.line <= last and e.range.end.line >= first]
    return [types.TextEdit(types.Range(_line_start(a.text, old_lines, i), _line_start(a.text, old_lines, i + 1)),
                           new_lines[i])
            for i in range(max(first, 0), min(last + 1, len(old_lines))) if old_lines[i] != new_lines[i]]


def _fix_edits(a: Analysis, d: Diagnostic) -> list[types.TextEdit]:
    assert d.fix is not None
    return [types.TextEdit(span_range(a.text, e.span), e.replacement) for e in d.fix.edits]


def _noqa_edit(a: Analysis, d: Diagnostic) -> types.TextEdit | None:
    """The edit that suppresses ``d`` on its line, or None where zero cannot suppress it there."""
    if d.code in NOT_RECORDED or d.code[0] == "F" or a.result is None or (d.code[0] == "X" and a.form != LIST):
        return None
    line = d.span.line
    if a.form == LIST:
        doc = a.result.document
        baseline = add_noqa(LintResult(a.name, doc, a.result.kind, [d]), reason="reviewed")
        if not baseline.added:
            return None
        new_lines = [x[:-1] if x.endswith("\r") else x for x in _decoded(baseline.data, doc.encoding).split("\n")]
        old, new = doc.line_text(line), new_lines[line - 1] if line <= len(new_lines) else ""
    elif a.form == STRUCTURED and structured_format(a.name) in COMMENTED_FORMS:
        old = a.text.line(line - 1)
        if "#" in old or d.message.startswith("(list line") or not old.strip():
            return None  # a trailing comment there already, or no line of its own
        new = f"{old.rstrip()}  # ( noqa: {d.code} -- reviewed )"
    elif a.form == PROGRAM and d.code[0] == "N":
        old = a.text.line(line - 1)
        if "noqa" in old.lower() or not old.strip():
            return None  # a suppression there already (it would hide this finding or be Z001)
        # a `( … )` comment: read as a comment also after a `;`, where everything is comment
        new = f"{old.rstrip()} ( noqa: {d.code} -- reviewed )"
    else:
        return None
    keep = 0
    while keep < min(len(old), len(new)) and old[keep] == new[keep]:
        keep += 1
    index = line - 1
    rng = types.Range(types.Position(index, a.text.character(index, keep)),
                      types.Position(index, a.text.character(index, len(old))))
    return types.TextEdit(rng, new[keep:])


def _wanted(kind: str, only: Sequence[str] | None) -> bool:
    return not only or any(kind == o or kind.startswith(o + ".") for o in only)


def fix_all_edits(a: Analysis, unsafe: bool) -> list[types.TextEdit]:
    """The edits of ``zero lint --fix`` (``unsafe``: ``--unsafe-fixes`` too) to the document."""
    fixed = fix_bytes(a.data, a.name, a.registry, a.options, unsafe)
    if fixed.fixed == a.data:
        return []
    return line_edits(a.text, _decoded(fixed.fixed, a.result.document.encoding if a.result else None))


def code_actions(a: Analysis, rng: types.Range, only: Sequence[str] | None, docs: RuleDocs,
                 lazy: bool = False) -> list[types.CodeAction]:
    """The fixes and suppressions of the findings on the lines of ``rng``, and the whole-file fixes
    (``lazy``: those without their edit, which :func:`resolve` adds when the user picks one)."""
    out: list[types.CodeAction] = []
    first, last = rng.start.line, max(rng.start.line, rng.end.line)
    here = [d for d in a.diagnostics if d.span.line - 1 <= last and d.span.end_line - 1 >= first]
    for d in here:
        diag = to_lsp(a, d, docs)
        if d.fix is not None and d.fix.edits and _wanted(types.CodeActionKind.QuickFix, only):
            title = f"{d.fix.title} ({d.code})" if d.fix.safe else \
                f"{d.fix.title} ({d.code}, unsafe: changes what the controller reads)"
            out.append(types.CodeAction(title, kind=types.CodeActionKind.QuickFix, diagnostics=[diag],
                                        is_preferred=d.fix.safe or None,
                                        edit=types.WorkspaceEdit(changes={a.uri: _fix_edits(a, d)})))
        noqa = _noqa_edit(a, d) if _wanted(types.CodeActionKind.QuickFix, only) else None
        if noqa is not None:
            out.append(types.CodeAction(f"Suppress {d.code} on this line (noqa)", kind=types.CodeActionKind.QuickFix,
                                        diagnostics=[diag], edit=types.WorkspaceEdit(changes={a.uri: [noqa]})))
    if a.form == LIST and a.result is not None:
        fixes = [d.fix for d in a.diagnostics if d.fix is not None and d.fix.edits]
        for kind, unsafe, title in ((FIX_ALL, False, "Apply zero's safe fixes (zero lint --fix)"),
                                    (FIX_ALL_UNSAFE, True, "Apply all of zero's fixes, unsafe ones too "
                                                           "(zero lint --fix --unsafe-fixes)")):
            if not _wanted(kind, only) or not any(f.safe or unsafe for f in fixes):
                continue
            if unsafe and all(f.safe for f in fixes):
                continue  # the same as the safe fixes
            if lazy:
                out.append(types.CodeAction(title, kind=kind, data={"uri": a.uri, "unsafe": unsafe}))
                continue
            edits = fix_all_edits(a, unsafe)
            if edits:
                out.append(types.CodeAction(title, kind=kind, edit=types.WorkspaceEdit(changes={a.uri: edits})))
    return out


def resolve(a: Analysis, action: types.CodeAction) -> types.CodeAction:
    """A whole-file fix with its edit (for the current text of the document)."""
    data = action.data if isinstance(action.data, dict) else {}
    if action.edit is None and a.form == LIST and a.result is not None:
        action.edit = types.WorkspaceEdit(changes={a.uri: fix_all_edits(a, bool(data.get("unsafe")))})
    return action


# ------------------------------------------------------------------ commands


FIX_ALL_COMMAND = "zero.fixAll"
SHOW_EFFECTIVE_VALUE = "zero.showEffectiveValue"
COMMANDS = [FIX_ALL_COMMAND, SHOW_EFFECTIVE_VALUE]


def uri_argument(command: str, args: tuple[Any, ...], count: int) -> str:
    if len(args) != count or not isinstance(args[0], str):
        wanted = "[uri]" if count == 1 else "[uri, {line, character}]"
        raise JsonRpcInvalidParams(f"{command} takes the arguments {wanted}, not {list(args)!r}"[:300])
    return args[0]


def position_argument(command: str, value: Any) -> tuple[int, int]:
    if isinstance(value, dict) and isinstance(value.get("line"), int) and isinstance(value.get("character"), int) \
            and value["line"] >= 0 and value["character"] >= 0:
        return value["line"], value["character"]
    raise JsonRpcInvalidParams(f"{command}: the position is not {{line, character}}: {value!r}"[:300])


def fix_all_edit(a: Analysis) -> types.WorkspaceEdit | None:
    """The edit ``zero lint --fix`` makes to the document (``None``: nothing to fix)."""
    if a.form != LIST or a.result is None:
        return None
    edits = fix_all_edits(a, unsafe=False)
    return types.WorkspaceEdit(changes={a.uri: edits}) if edits else None


def effective_value(a: Analysis, line: int, character: int) -> dict[str, Any]:
    """Where the value of the parameter at the position comes from: ``key``, ``message`` (the text
    shown), ``lines`` (each layer, as ``zero explain`` lists them); ``key`` None where there is no
    parameter."""
    if line >= len(a.text.lines):
        return {"key": None, "message": "zero: no parameter here", "lines": []}
    t = target_at(a, line, a.text.column(line, character))
    if t is None:
        return {"key": None, "message": "zero: no parameter here", "lines": []}
    key = t.key or t.spec.key or t.spec.id
    lines = machine_lines(a, t)
    if lines:
        message = f"{key} ({t.spec.id}): " + "; ".join(x.removeprefix("- ") for x in lines)
    elif a.machine_list() is None:
        written = f" = `{t.entry.value}` in this list" if t.entry is not None else ""
        message = f"{key} ({t.spec.id}){written}: this file is not a list of a machine ([tool.zero.machine])"
    else:
        message = f"{key} ({t.spec.id}): not set on the machine"
    return {"key": key, "id": t.spec.id, "message": message, "lines": lines}

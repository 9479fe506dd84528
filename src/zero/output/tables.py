"""Tables: the changes of ``zero diff`` and the soft limits of ``zero limits``, as a rich
table on a terminal and as aligned plain text otherwise.
"""

from __future__ import annotations

import io
import os
import sys
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, TextIO

from zero.catalog.ids import fixed, g_code
from zero.diff import ADDED, CHANGED, COMMENT, REMOVED, SAME, Change
from zero.machine.effective import Scope
from zero.machine.limits import Ip247Violation, LimitRow
from zero.output.text import use_color

if TYPE_CHECKING:
    from rich.console import Console
    from rich.table import Table


def format_delta(c: Change) -> str:
    if c.delta is None:
        return ""
    if isinstance(c.delta, float) or (c.unit or "").startswith(("mm", "°")):
        text = f"{c.delta:+.4f}"
    else:
        text = f"{c.delta:+d}" if isinstance(c.delta, int) else f"{c.delta:+g}"
    return f"{text} {c.unit}" if c.unit else text


def format_change(c: Change) -> str:
    """What changed, in the column of the delta: a quantity's delta, a mask's bits (``+JERK -ACC``),
    a symbol or a BOOLEAN by name (``SERCOS → CANOPEN``, ``off → on``); empty where the values
    column already says it all."""
    if c.coding is None:
        return format_delta(c)
    if c.bits is not None:
        return " ".join([*(f"+{b}" for b in c.bits[0]), *(f"-{b}" for b in c.bits[1])])
    if c.old_name is None and c.new_name is None:
        return ""
    text = f"{c.old_name or c.old or '(absent)'} → {c.new_name or c.new or '(absent)'}"
    return "" if text == _values(c) else text


def _values(c: Change) -> str:
    return f"{'(absent)' if c.old is None else c.old} → {'(absent)' if c.new is None else c.new}"


_MARK = {ADDED: "+", REMOVED: "-", CHANGED: "~", SAME: "=", COMMENT: "#"}


def rows(changes: Iterable[Change]) -> list[tuple[str, list[tuple[str, ...]]]]:
    """Changes as (group, rows of cells) for the text and table renderers: mark, key, ID, old → new,
    what changed, notes (in parentheses: the note, `restart` where the catalogue says a change
    takes effect only at a restart)."""
    out: list[tuple[str, list[tuple[str, ...]]]] = []
    for c in changes:
        if not out or out[-1][0] != c.group:
            out.append((c.group, []))
        out[-1][1].append((_MARK[c.kind], c.key, c.param_id or "", _values(c), format_change(c),
                           "  ".join(_notes(c))))
    return out


def _notes(c: Change) -> list[str]:
    return [f"({n})" for n in (c.note, "restart" if c.restart else "") if n]


def fold(phrases: Sequence[str], width: int, first: str = "", indent: str = "    ", sep: str = "  ") -> list[str]:
    """Phrases on lines of at most ``width`` columns, joined by ``sep``; the first line starts with
    ``first``, the others with ``indent``. A phrase moves whole to the next line; only one longer than
    a line breaks, between its words. Nothing breaks inside a word (a value, an ID, a key): a word
    longer than a line stands whole on a line of its own, the one case a line is wider than ``width``."""
    from rich.cells import cell_len  # start-up: rich only on a terminal

    lines: list[str] = []
    line = ""  # the line being filled, with its indent; "" before its first phrase

    def lead() -> str:
        return indent if lines else first

    for phrase in (p for p in phrases if p):
        if line and cell_len(line + sep + phrase) <= width:
            line += sep + phrase
            continue
        if line:
            lines.append(line)
        line = lead() + phrase
        if cell_len(line) <= width or " " not in phrase:
            continue
        line = ""
        for word in phrase.split(" "):  # a phrase longer than a line: between its words
            if line and cell_len(line + " " + word) <= width:
                line += " " + word
                continue
            if line:
                lines.append(line)
            line = lead() + word
    if line:
        lines.append(line)
    return lines


def render_plain(changes: list[Change], header: str) -> str:
    lines = [header]
    for group, cells in rows(changes):
        lines.append(f"\n{group}")
        widths = [max(len(r[i]) for r in cells) for i in range(5)]
        for r in cells:
            text = "  ".join(r[i].rjust(widths[i]) if i == 4 else r[i].ljust(widths[i])
                             for i in range(5)).rstrip()
            lines.append(f"  {text}" + (f"  {r[5]}" if r[5] else ""))
    return "\n".join(lines) + "\n"


def summary(changes: list[Change]) -> str:
    n = {k: sum(1 for c in changes if c.kind == k) for k in _MARK}
    parts = [f"{n[CHANGED]} changed", f"{n[ADDED]} added", f"{n[REMOVED]} removed"]
    if n[COMMENT]:
        parts.append(f"{n[COMMENT]} comments changed")
    if n[SAME]:
        parts.append(f"{n[SAME]} same effective value")
    return ", ".join(parts)


def render_diff(changes: Sequence[Change], header: str, stream: TextIO | None = None,
                color: bool | None = None) -> None:
    """The changes of ``zero diff``: a rich table on a terminal, aligned text otherwise."""
    stream = stream or sys.stdout
    if not (use_color(stream) if color is None else color):
        stream.write(render_plain(list(changes), header))
        stream.write(summary(list(changes)) + "\n")
        return
    from rich.cells import cell_len  # start-up: rich only on a terminal
    from rich.console import Console  # start-up: as above
    from rich.table import Table  # start-up: as above

    console = Console(file=stream, force_terminal=True, highlight=False, emoji=False, markup=False)
    console.print(header, style="bold")
    styles = {"+": "green", "-": "red", "~": "yellow", "=": "dim", "#": "cyan"}
    tables = []
    grouped = rows(changes)
    names = ("", "key", "ID", "old → new", "change", "")
    widths = [max((cell_len(r[i]) for _, cells in grouped for r in cells), default=0) for i in range(len(names))]
    for group, cells in grouped:
        table = Table(title=group, title_justify="left", title_style="bold", box=None, pad_edge=False)
        for name, width in zip(names, widths, strict=True):  # the columns of every group aligned
            # nothing is cut or folded: where the tables are too wide, the changes are records
            table.add_column(name, no_wrap=True, min_width=max(width, cell_len(name)))
        for r in cells:
            table.add_row(*r, style=styles.get(r[0], ""))
        tables.append(table)
    if all(_fits(console, t) for t in tables):
        for table in tables:
            console.print(table)
    else:  # too narrow for the tables: a record per change, its values never split (see fold)
        shown: str | None = None
        for c in changes:
            if c.group != shown:
                shown = c.group
                console.print(c.group, style="bold")
            style = styles.get(_MARK[c.kind], "")
            for line in fold([f"{_MARK[c.kind]} {c.key}", c.param_id or ""], console.width):
                console.print(line, style=style, soft_wrap=True)
            for line in fold([_values(c), format_change(c), *_notes(c)], console.width, "    ", "      "):
                console.print(line, soft_wrap=True)
    console.print(summary(list(changes)), style="bold")


def _fits(console: Console, table: Table) -> bool:
    """Does the table fit the terminal at its natural width (no cell cut or wrapped)?"""
    from rich.measure import Measurement  # start-up: rich only on a terminal

    natural = Measurement.get(console, console.options.update_width(1 << 16), table).maximum  # unclamped
    return natural <= console.width


def _ip247_line(v: Ip247Violation) -> str:
    return f"IP247: {v.what} {fixed(v.value, 'mm')} outside ±99999.999 mm ({v.where})"


_NUMBERS = {4, 5, 6, 7, 8}  # the columns of render_limits that hold numbers


def render_limits(rows: Sequence[LimitRow], violations: Sequence[Ip247Violation] = (),
                  stream: TextIO | None = None, color: bool | None = None) -> None:
    """``zero limits``: a rich table on a terminal, aligned text otherwise."""
    stream = stream or sys.stdout
    head = ("ch", "offset", "axis", "unit", "ACS min", "ACS max", "offset", "PCS min", "PCS max", "")
    cells = [(str(r.channel), g_code(r.group), f"{r.axis_index} {r.axis_name}", r.unit,
              *(fixed(v) for v in (r.acs_neg, r.acs_pos, r.offset, r.pcs_neg, r.pcs_pos)),
              r.note) for r in rows]
    if use_color(stream) if color is None else color:
        from rich.box import SIMPLE_HEAD  # start-up: as above
        from rich.console import Console  # start-up: rich only on a terminal
        from rich.table import Table  # start-up: as above

        title = "soft limits in the programming coordinate system"
        table = Table(title=title, title_justify="left", box=SIMPLE_HEAD, pad_edge=False,
                      collapse_padding=True, show_edge=False)
        shown = len(head) if any(c[-1] for c in cells) else len(head) - 1  # the notes, where there are any
        for i, name in enumerate(head[:shown]):  # nothing is cut or folded: too wide, and it is records
            table.add_column(name, justify="right" if i in _NUMBERS else "left", no_wrap=True)
        for c in cells:
            table.add_row(*c[:shown])
        console = Console(file=stream, force_terminal=True, highlight=False, emoji=False, markup=False)
        if _fits(console, table):
            console.print(table)
        else:  # too narrow for the table: a record per row, folded between its parts (see fold)
            console.print(title, style="bold")
            for c in cells:
                parts = [f"ch {c[0]} {c[1]} axis {c[2]} ({c[3]}):", f"ACS {c[4]} .. {c[5]},",
                         f"offset {c[6]},", f"PCS {c[7]} .. {c[8]}", f"({c[9]})" if c[9] else ""]
                for line in fold(parts, console.width, sep=" "):
                    console.print(line, soft_wrap=True)
        for v in violations:
            console.print(_ip247_line(v), style="bold red")
        return
    widths = [max(len(head[i]), *(len(c[i]) for c in cells)) if cells else len(head[i]) for i in range(10)]
    right = {4, 5, 6, 7, 8}
    for c in [head, *cells]:
        stream.write("  ".join(c[i].rjust(widths[i]) if i in right else c[i].ljust(widths[i])
                               for i in range(10)).rstrip() + "\n")
    for v in violations:
        stream.write(_ip247_line(v) + "\n")


def _below(path: str, folder: str) -> str:
    """``path`` relative to ``folder`` (``.`` for the folder itself)."""
    return os.path.relpath(path, folder) if os.path.isabs(path) and os.path.isabs(folder) else path


def render_effective(summary: dict[str, object], scopes: Sequence[Scope], stream: TextIO | None = None,
                     explain: bool = False, textconv: bool = False) -> None:
    """Effective values, one line per parameter with its origin (``git config --show-origin``).
    ``textconv``: every file named relative to the start-up list's folder, as a git textconv needs
    (git hands it a copy in a temporary folder whose name changes on every call)."""
    stream = stream or sys.stdout
    if textconv:
        buffer = io.StringIO()
        render_effective(summary, scopes, buffer, explain)
        folder = os.path.dirname(str(summary["startup"]))
        text = buffer.getvalue().replace(f"working directory {summary['working_directory']},",
                                         f"working directory {_below(str(summary['working_directory']), folder)},")
        stream.write(text.replace(folder.rstrip("/\\") + os.sep, ""))
        return
    named = summary["lists"]
    assert isinstance(named, list)
    read = sum(1 for n in named if n["status"] in ("loaded", "overridden"))
    stream.write(f"# machine {summary['startup']}: working directory {summary['working_directory']}, "
                 f"{read} of {len(named)} named lists read\n")
    for n in named:
        if n["status"] not in ("loaded", "overridden"):
            stream.write(f"#   {n['key']} {n['path']}: {n['status']}{': ' + n['reason'] if n['reason'] else ''}\n")
    items = summary.get("twincat")
    for key, item in (items.items() if isinstance(items, dict) else ()):  # what TwinCAT says of each list's item
        said = ", ".join(f"{k} {v}" for k, v in item.items() if k not in ("item", "element"))
        stream.write(f"#   {key}: TwinCAT item {item.get('item') or '?'} ({item.get('element')})"
                     f"{': ' + said if said else ''}\n")
    for scope in scopes:
        under = f" over {scope.default_list}" if scope.default_list else ""
        stream.write(f"\n[{scope.name}: {scope.file.path}{under}]\n")
        width = max((len(v.key) + len(v.value or "") for v in scope.values), default=0) + 3
        for v in scope.values:
            head = f"{v.key} = {v.value if v.value is not None else '(none)'}"
            stream.write(f"{head.ljust(width)}  {v.param_id or '-':<12}  {v.origin}\n")
            if explain:
                for value, origin in v.layers:
                    shown = value if value is not None else "(not set)"
                    where = f"{origin.path or ''}{':' + str(origin.line) if origin.line else ''}"
                    stream.write(f"    {origin.source:<18} {shown:<20} {where}".rstrip() + "\n")

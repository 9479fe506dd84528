"""NC programs (``*.nc``): ``#MACHINE DATA`` and programmed soft limits (G98/G99).

zero reads a program line by line and looks only at what it checks; everything else
(cycles, ``$IF``, ``#MSG``, variables) is read past. Comments ``( … )`` (closed or
not) and ``; …`` are skipped, strings in double quotes are kept whole.

* ``#MACHINE DATA [SYN] [AX=<name> | AXNR=<n>  <P-AXIS-id>[.<idx>]=<value> | AXPARAM="<key> <value>" [WAIT]]``
  is read with its form faults, the keyword IDs it accepts, and the key and value of
  AXPARAM;
* ``G98``/``G99`` with axis words set the negative/positive soft limits, absolute under
  G90, relative to P-AXIS-00177/00178 under G91.

:func:`read_program` gives these constructs in order; the N rules
(:mod:`zero.rules.program`) say what the controller does with them.
"""

from __future__ import annotations

import re

from zero.catalog.registry import Registry
from zero.lists.encoding import decode
from zero.lists.model import Document
from zero.records import Record, field

_MACHINE_DATA_RE = re.compile(r"#\s*MACHINE\s+DATA\b", re.IGNORECASE)
_WORD_RE = re.compile(r"(?<![A-Za-z_#$.])([A-Z])\s*(=?)\s*([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))", re.IGNORECASE)
_G9X = re.compile(r"(?<![A-Za-z_#$.])G\s*0*9[0189](?![0-9.])", re.IGNORECASE)
_G_RE = re.compile(r"(?<![A-Za-z_#$.])G\s*0*([0-9]+)(?![0-9.])", re.IGNORECASE)
_ITEM_RE = re.compile(
    r'(?<!\s)\s*+(?:(?P<ax>AX)\s*+=\s*+(?P<axname>[A-Za-z_][A-Za-z0-9_]*)'
    r'|(?P<axnr>AXNR)\s*+=\s*+(?P<axnrv>\[[^\]]*\]|[^\s\]]+)'
    r'|(?P<pid>P-AXIS-[0-9]{5})(?:\.(?P<pidx>[0-9]+))?\s*+=\s*+(?P<pval>[^\s\]]+)'
    r'|(?P<axparam>AXPARAM)\s*+=?+\s*+"(?P<axparamv>[^"]*)"'
    r'|(?P<axparamvar>AXPARAM)\s*+=?+\s*+(?P<axparamvarv>V\.[A-Za-z0-9_.\[\]]+)'
    r'|(?P<wait>WAIT)\b'
    r'|(?P<other>\S+))', re.IGNORECASE)


def _blank_strings(line: str) -> str:
    """The line with the contents of double-quoted strings blanked (columns kept)."""
    return re.sub(r'"[^"]*"?', lambda m: '"' + " " * (len(m.group()) - 1), line)


def comment_spans(line: str) -> list[tuple[int, str]]:
    """The comments of a program line as (0-based column, text with its delimiters): ``( … )``
    (nested parentheses inside), and ``; …`` to the end; what is in double quotes is no comment."""
    out: list[tuple[int, str]] = []
    depth = 0
    start = 0
    in_str = False
    for i, ch in enumerate(line):
        if in_str:
            in_str = ch != '"'
        elif depth:
            depth += (ch == "(") - (ch == ")")
            if not depth:
                out.append((start, line[start:i + 1]))
        elif ch == '"':
            in_str = True
        elif ch == "(":
            depth, start = 1, i
        elif ch == ";":
            out.append((i, line[i:]))
            return out
    if depth:  # not closed: to the end of the line
        out.append((start, line[start:]))
    return out


def strip_comments(line: str) -> str:
    """The line with ``( … )`` and ``; …`` comments blanked (columns kept), strings kept."""
    if "(" not in line and ";" not in line:
        return line
    for start, text in reversed(comment_spans(line)):
        line = line[:start] if text.startswith(";") else line[:start] + " " * len(text) + line[start + len(text):]
    return line


def _closing(text: str, start: int) -> int:
    """The ``]`` that closes the ``[`` at ``start`` (brackets of expressions nest); -1 if none."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == "[":
            depth += 1
        elif text[i] == "]":
            depth -= 1
            if depth == 0:
                return i
    return -1


class MachineData(Record):
    line: int
    start: int
    end: int
    syn: bool
    axis: str | None = None
    axnr: str | None = None
    writes: list[tuple[str, str, int, int]] = field(default_factory=list)  # (what, value, start, end)
    wait: bool = False
    problems: list[tuple[str, int, int]] = field(default_factory=list)  # (message, start, end)
    axparams: list[tuple[str, int, int]] = field(default_factory=list)  # literal AXPARAM texts to check


def parse_machine_data(text: str, line: int, start: int, registry: Registry) -> MachineData:
    """One ``#MACHINE DATA`` command from column ``start`` of the comment-free line."""
    m = _MACHINE_DATA_RE.match(text, start)
    assert m is not None
    md = MachineData(line, start, len(text.rstrip()), False)
    rest_at = m.end()
    rest = text[rest_at:]
    head = re.match(r"\s*(SYN\b)?\s*", rest, re.IGNORECASE)
    assert head is not None
    md.syn = head.group(1) is not None
    pos = rest_at + head.end()
    if pos >= len(text) or text[pos] != "[":
        md.problems.append(("expected `[` with the axis and the parameter (`#MACHINE DATA [AX=X P-AXIS-00209=80000]`)",
                            pos, len(text.rstrip())))
        return md
    masked = _blank_strings(text)
    close = _closing(masked, pos)
    if close < 0:
        md.problems.append(("the `[` is not closed", pos, len(text.rstrip())))
        close = len(text)
    keywords = registry.machine_data_ids()
    body_at = pos + 1
    for im in _ITEM_RE.finditer(text[body_at:close]):
        a, b = body_at + im.start(im.lastgroup or 0), body_at + im.end()
        if im.group("ax"):
            md.axis = im.group("axname")
        elif im.group("axnr"):
            md.axnr = im.group("axnrv")
            computed = md.axnr.startswith("[") or md.axnr.upper().startswith("V.")  # known at run time only
            if not computed and not (md.axnr.isdigit() and int(md.axnr) > 0):
                md.problems.append((f"AXNR={md.axnr} is not a logical axis number (they start at 1); the "
                                    "controller does not check AXNR, so the block does not write the axis "
                                    "it is meant for", a, b))
        elif im.group("pid"):
            pid = im.group("pid").upper()
            md.writes.append((pid + (f".{im.group('pidx')}" if im.group("pidx") else ""), im.group("pval"), a, b))
            if pid not in keywords:
                spec = registry.get(pid)
                if spec is None:
                    md.problems.append((f"{pid} is not a parameter of the catalogue", a, b))
                else:
                    what = f"{pid} ({spec.key})" if spec.key else pid
                    md.problems.append((f"{what} is not one of the parameters #MACHINE DATA accepts by ID; "
                                        "write it with AXPARAM=\"<key> <value>\"", a, b))
        elif im.group("axparam"):
            md.writes.append(("AXPARAM", im.group("axparamv"), a, b))
            md.axparams.append((im.group("axparamv"), a, b))
        elif im.group("axparamvar"):  # a string variable: its content is known only at run time
            md.writes.append(("AXPARAM", im.group("axparamvarv"), a, b))
        elif im.group("wait"):
            md.wait = True
        else:
            md.problems.append((f"`{im.group('other')}` is not part of #MACHINE DATA "
                                "(AX=, AXNR=, P-AXIS-…=, AXPARAM=\"…\", WAIT)", a, b))
    if md.axis is None and md.axnr is None:
        md.problems.append(("names no axis: give AX=<name> or AXNR=<logical axis number>", pos, close))
    if md.axis is not None and md.axnr is not None:
        md.problems.append(("gives both AX= and AXNR=: name the axis once", pos, close))
    if not md.writes:
        md.problems.append(("writes no parameter (P-AXIS-…=<value> or AXPARAM=\"<key> <value>\")", pos, close))
    if md.wait and not md.syn:
        md.problems.append(("WAIT is only allowed with SYN (`#MACHINE DATA SYN [… WAIT]`)", pos, close))
    return md


class SoftLimit(Record):
    line: int
    start: int
    end: int
    positive: bool  # G99
    relative: bool  # G91
    axis: str
    value: float  # programmed, in mm / degrees


class Program(Record):
    """An NC program as zero reads it: its lines (for reports) and the constructs it checks."""

    doc: Document
    machine_data: list[MachineData]
    limits: list[SoftLimit]

    @property
    def path(self) -> str:
        return self.doc.path


def read_program(data: bytes, path: str, registry: Registry) -> Program:
    """The checked constructs of a program, in order."""
    text, encoding, bom = decode(data)
    lines = [x[:-1] if x.endswith("\r") else x for x in text.split("\n")]
    if lines and lines[-1] == "":
        lines.pop()
    doc = Document(path, encoding, lines, ["\n"] * len(lines), [], [], bom)  # lines for reports
    machine_data: list[MachineData] = []
    limits: list[SoftLimit] = []
    relative = False
    for number, raw in enumerate(doc.lines, 1):
        s = strip_comments(raw)
        s_blank = _blank_strings(s) if '"' in s else s
        md = _MACHINE_DATA_RE.search(s_blank) if "#" in s_blank else None
        if md:
            machine_data.append(parse_machine_data(s, number, md.start(), registry))
            continue
        s = s_blank
        if "9" not in s or not _G9X.search(s):  # no G90, G91, G98 or G99 (of any spelling) on the line
            continue
        gs = [int(g.group(1)) for g in _G_RE.finditer(s)]
        if 91 in gs:
            relative = True
        elif 90 in gs:
            relative = False
        if 98 in gs or 99 in gs:
            positive = 99 in gs
            for w in _WORD_RE.finditer(s):
                letter = w.group(1).upper()
                if letter in ("G", "N", "F", "S", "T", "M", "D", "H"):
                    continue
                try:
                    value = float(w.group(3))
                except ValueError:
                    continue
                limits.append(SoftLimit(number, w.start(), w.end(), positive, relative, letter, value))
    return Program(doc, machine_data, limits)

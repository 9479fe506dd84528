"""NC programs (``*.nc``): ``#MACHINE DATA`` and programmed soft limits (G98/G99).

zero reads a program line by line and looks only at what it checks; everything else
(cycles, ``$IF``, ``#MSG``, variables) is read past. Comments ``( … )`` (closed or
not) and ``; …`` are skipped, strings in double quotes are kept whole.

* ``#MACHINE DATA [SYN] [AX=<name> | AXNR=<n>  <P-AXIS-id>[.<idx>]=<value> | AXPARAM="<key> <value>" [WAIT]]``
  is checked for its form, the keyword IDs it accepts, and the key and value of AXPARAM
  against the registry (N001); one after G98/G99 in the same program is reported (N002),
  since writing machine data reloads the axis list and discards programmed soft limits.
* ``G98``/``G99`` with axis words set the negative/positive soft limits, absolute under
  G90, relative to P-AXIS-00177/00178 under G91. With a machine (``--machine``), zero
  reports what the controller would: P-ERR-21648/21650 (N003, beyond the configured
  limit while ``range_check_prog_soft_limits`` is 1) and P-ERR-21649/21878 (N004, the
  negative limit not below the positive one).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from zero.diagnostics import Diagnostic, Severity, Span
from zero.lint import LintOptions, LintResult, selected_rules
from zero.model import Document
from zero.registry import LENGTH_UNIT, Registry, default_registry
from zero.tokenizer import decode

if TYPE_CHECKING:
    from zero.machine import Axis, Machine

MM = LENGTH_UNIT  # program millimetres (or degrees) in list units
SWE_NEG, SWE_POS = "P-AXIS-00177", "P-AXIS-00178"
RANGE_CHECK = "P-CHAN-00498"

_MACHINE_DATA_RE = re.compile(r"#\s*MACHINE\s+DATA\b", re.IGNORECASE)
_WORD_RE = re.compile(r"(?<![A-Za-z_#$.])([A-Z])\s*(=?)\s*([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))", re.IGNORECASE)
_G_RE = re.compile(r"(?<![A-Za-z_#$.])G\s*0*([0-9]+)(?![0-9.])", re.IGNORECASE)
_ITEM_RE = re.compile(
    r'\s*(?:(?P<ax>AX)\s*=\s*(?P<axname>[A-Za-z_][A-Za-z0-9_]*)'
    r'|(?P<axnr>AXNR)\s*=\s*(?P<axnrv>[^\s\]]+)'
    r'|(?P<pid>P-AXIS-[0-9]{5})(?:\.(?P<pidx>[0-9]+))?\s*=\s*(?P<pval>[^\s\]]+)'
    r'|(?P<axparam>AXPARAM)\s*=?\s*"(?P<axparamv>[^"]*)"'
    r'|(?P<axparamvar>AXPARAM)\s*=?\s*(?P<axparamvarv>V\.[A-Za-z0-9_.\[\]]+)'
    r'|(?P<wait>WAIT)\b'
    r'|(?P<other>\S+))', re.IGNORECASE)


def _blank_strings(line: str) -> str:
    """The line with the contents of double-quoted strings blanked (columns kept)."""
    return re.sub(r'"[^"]*"?', lambda m: '"' + " " * (len(m.group()) - 1), line)


def strip_comments(line: str) -> str:
    """The line with ``( … )`` and ``; …`` comments blanked (columns kept), strings kept."""
    out = []
    depth = 0
    in_str = False
    for ch in line:
        if in_str:
            out.append(ch)
            in_str = ch != '"'
            continue
        if depth:
            depth += ch == "("
            depth -= ch == ")"
            out.append(" ")
            continue
        if ch == '"':
            in_str = True
            out.append(ch)
        elif ch == "(":
            depth = 1
            out.append(" ")
        elif ch == ";":
            break
        else:
            out.append(ch)
    return "".join(out)


@dataclass(slots=True)
class MachineData:
    line: int
    start: int
    end: int
    syn: bool
    axis: str | None = None
    axnr: str | None = None
    writes: list[tuple[str, str, int, int]] = field(default_factory=list)  # (what, value, start, end)
    wait: bool = False
    problems: list[tuple[str, int, int]] = field(default_factory=list)  # (message, start, end)


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
    close = masked.find("]", pos)
    if close < 0:
        md.problems.append(("the `[` is not closed", pos, len(text.rstrip())))
        close = len(text)
    keywords = {s.id for s in registry.specs.values() if s.source.startswith("#MACHINE DATA")}
    body_at = pos + 1
    for im in _ITEM_RE.finditer(text[body_at:close]):
        a, b = body_at + im.start(im.lastgroup or 0), body_at + im.end()
        if im.group("ax"):
            md.axis = im.group("axname")
        elif im.group("axnr"):
            md.axnr = im.group("axnrv")
            if not (md.axnr.isdigit() and int(md.axnr) > 0):
                md.problems.append((f"AXNR={md.axnr}: the logical axis number is a positive integer "
                                    "(the controller does not check it: a wrong one writes to another axis)", a, b))
        elif im.group("pid"):
            pid = im.group("pid").upper()
            md.writes.append((pid + (f".{im.group('pidx')}" if im.group("pidx") else ""), im.group("pval"), a, b))
            if pid not in keywords:
                spec = registry.get(pid)
                what = f"{pid} ({spec.key})" if spec and spec.key else pid
                md.problems.append((f"{what} is not one of the parameters #MACHINE DATA accepts by ID; "
                                    "write it with AXPARAM=\"<key> <value>\"", a, b))
        elif im.group("axparam"):
            md.writes.append(("AXPARAM", im.group("axparamv"), a, b))
            md.problems.extend((msg, a, b) for msg in _check_axparam(im.group("axparamv"), registry))
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


def _check_axparam(text: str, registry: Registry) -> list[str]:
    """AXPARAM's ``"<key> <value>"``: the key known in the axis list, the value valid for it."""
    from zero.lint import lint_bytes

    parts = text.split(None, 1)
    if len(parts) != 2:
        return [f"AXPARAM=\"{text}\" needs a key and a value (\"kenngr.swe_pos 15000000\")"]
    result = lint_bytes(f"{parts[0]} {parts[1]}\n".encode("utf-8", "surrogateescape"), "axparam.lis",
                        registry, LintOptions(select=("R", "S"), ignore=("R007", "R008"), kind="AXIS"))
    return [f"AXPARAM: {d.message}" for d in result.diagnostics if d.severity >= Severity.WARNING]


@dataclass(slots=True)
class SoftLimit:
    line: int
    start: int
    end: int
    positive: bool  # G99
    relative: bool  # G91
    axis: str
    value: float  # programmed, in mm / degrees


def read_program(data: bytes, path: str, registry: Registry) -> tuple[Document, list[MachineData], list[SoftLimit]]:
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
        md = _MACHINE_DATA_RE.search(_blank_strings(s))
        if md:
            machine_data.append(parse_machine_data(s, number, md.start(), registry))
            continue
        s = _blank_strings(s)
        if not s.strip():
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
    return doc, machine_data, limits


def lint_program(data: bytes, path: str, registry: Registry | None = None,
                 options: LintOptions | None = None, machine: Machine | None = None) -> LintResult:
    """Findings N001–N004 for one program (N003/N004 need the machine)."""
    from zero.rules.program import RULES

    registry = registry or default_registry()
    severities = selected_rules(options or LintOptions())
    doc, machine_data, limits = read_program(data, path, registry)
    out: list[Diagnostic] = []

    def report(code: str, line: int, start: int, end: int, message: str, pid: str | None = None) -> None:
        if code in severities:
            out.append(Diagnostic(code, severities.get(code, RULES[code].severity), message,
                                  Span.on_line(line, start, max(end, start + 1)), path, pid))

    for md in machine_data:
        for message, a, b in md.problems:
            tail = "" if message.startswith("AXPARAM:") else ": the controller rejects the block"
            report("N001", md.line, a, b, f"#MACHINE DATA {message}{tail}")
    first_limit = limits[0] if limits else None
    if first_limit is not None:
        for md in machine_data:
            if md.line > first_limit.line:
                report("N002", md.line, md.start, md.end,
                       f"#MACHINE DATA after G98/G99 (line {first_limit.line}): writing machine data reloads "
                       "the whole axis list and silently discards the programmed soft limits")
                break
    if machine is not None:
        out.extend(_check_limits(limits, machine, path, report))
    out.sort(key=Diagnostic.sort_key)
    return LintResult(path, doc, "PROGRAM", out)


def _check_limits(limits: list[SoftLimit], machine: Machine, path: str, report: object) -> list[Diagnostic]:
    """G98/G99 against the configured soft limits of each named axis."""
    assert callable(report)
    by_name: dict[str, Axis] = {}
    axes = machine.axes()
    limited = False
    for ch in machine.channels:
        if ch.lists is not None:
            limited = limited or bool(ch.lists.number(RANGE_CHECK))
        for ca in ch.axes:
            ax = axes.get(ca.log_nr)
            if ax is not None:
                by_name.setdefault(ca.name.upper(), ax)
    for lim in limits:
        ax = by_name.get(lim.axis)
        if ax is None:
            continue
        base = ax.swe_pos if lim.positive else ax.swe_neg
        new = (base + lim.value * MM) if lim.relative else lim.value * MM
        u = ax.unit
        shown = f"{new / MM:.4f} {u}"
        if lim.positive and new <= ax.swe_neg:
            report("N004", lim.line, lim.start, lim.end,
                   f"P-ERR-21878: G99 sets the positive soft limit of {lim.axis} to {shown}, not above the "
                   f"configured negative one ({ax.swe_neg / MM:.4f} {u}): not taken over, the controller "
                   "resets", SWE_POS)
        elif lim.positive and limited and new > ax.swe_pos:
            report("N003", lim.line, lim.start, lim.end,
                   f"P-ERR-21650: G99 widens the positive soft limit of {lim.axis} to {shown} beyond the "
                   f"configured {ax.swe_pos / MM:.4f} {u} while range_check_prog_soft_limits is 1: "
                   "not taken over", SWE_POS)
        elif not lim.positive and new >= ax.swe_pos:
            report("N004", lim.line, lim.start, lim.end,
                   f"P-ERR-21649: G98 sets the negative soft limit of {lim.axis} to {shown}, not below the "
                   f"configured positive one ({ax.swe_pos / MM:.4f} {u}): not taken over, the controller "
                   "resets", SWE_NEG)
        elif not lim.positive and limited and new < ax.swe_neg:
            report("N003", lim.line, lim.start, lim.end,
                   f"P-ERR-21648: G98 widens the negative soft limit of {lim.axis} to {shown} beyond the "
                   f"configured {ax.swe_neg / MM:.4f} {u} while range_check_prog_soft_limits is 1: "
                   "not taken over", SWE_NEG)
    return []

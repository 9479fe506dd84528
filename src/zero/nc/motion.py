"""Following an NC program's positions, and reading its words (the N005–N010 checks).

One pass over the program's lines, block by block, gives an :class:`Analysis`:

* the **language**: words the ISG NC language does not have, unknown ``$`` keywords and
  ``#`` commands (:mod:`zero.nc.language`), unbalanced control structures
  (``$IF``/``$ENDIF``, ``$WHILE``/``$ENDWHILE``, ``$FOR``, ``$SWITCH``, ``$DO``, ``$REPEAT``),
  and the subprogram calls (``L name``, ``LL name``, ``L CYCLE [NAME=…]``);
* the **moves**, followed against a :class:`Setup` (the channel's axes, their soft limits
  and the work offsets): ``G90``/``G91``, ``G0``–``G3`` end points and the extent of arcs
  (``I``/``J``/``K`` or ``R``, in the plane ``G17``/``G18``/``G19``), ``G70``/``G71``,
  the work offsets ``G53``–``G59`` and ``G159=n``, ``G98``/``G99`` and ``POS_LIMIT``, and
  P-parameters and ``V.`` variables assigned literal values (or expressions of them). A
  target whose machine position (programmed position plus the active offset) lies beyond a
  soft limit is a :class:`Crossing`.

What zero cannot follow is counted, never guessed: computed positions, transformations and
coordinate systems (``#TRAFO``, ``#CS``, ``#ACS``, ``#RTCP``, …), moves after a subprogram call
or a jump target until the program sets ``G90``/``G91`` and the work offset again, relative
moves from an unknown position, ``G92`` presets, diameter programming, G codes zero does not
know, local subprograms (their start state is the caller's), and, inside loops, whatever
the loop changes. :attr:`Analysis.skipped` says why, with the first line of each reason.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence

from zero.catalog.ids import LENGTH_UNIT
from zero.forms import PROGRAM_SUFFIX
from zero.nc import language as lang
from zero.nc.program import strip_comments
from zero.records import Record, field

INCH = 25.4
MAX_DEPTH = 8  # subprogram calls followed into each other
FOLLOW_BUDGET = 200_000  # lines of subprograms followed per program (at least four times its own)


class AxisSetup(Record):
    """One axis of the channel as the program names it, its soft limits in mm or degrees."""

    name: str  # upper case, as the channel list names it
    neg: float
    pos: float
    rotary: bool = False


class Setup(Record):
    """What the program runs on: the channel's axes (in channel order), the offset each work
    offset group applies to each of them, and the state at program start (P-CHAN-00063)."""

    axes: list[AxisSetup]
    offsets: dict[int, tuple[float, ...]] = field(default_factory=dict)  # group → per axis, mm/°
    default_group: int = 0
    absolute: bool = True  # G90 (the manual's initial state)
    plane: int = 17
    inch: bool = False
    centre_absolute: bool = False  # G161 (else G162, relative centre)
    diameter: bool = False  # G51
    range_check: bool = False  # P-CHAN-00498: G98/G99 only narrow the limits

    def offset(self, group: int, axis: int) -> float:
        row = self.offsets.get(group)
        return row[axis] if row is not None and axis < len(row) else 0.0


class Crossing(Record):
    """A target (or the extreme of an arc) beyond a soft limit."""

    line: int
    start: int
    end: int
    axis: int  # index into Setup.axes
    programmed: float  # programming coordinate system
    machine: float  # axis coordinate system: programmed + offset
    limit: float
    positive: bool
    group: int
    offset: float
    limit_from: str = ""  # "" the configured limit; else "G99 at line 7", "POS_LIMIT at line 9"
    unmonitored: str = ""  # why the program switched monitoring off ("POS_LIMIT OFF at line 9")
    arc: bool = False
    via: str = ""  # in a called subprogram: "in `L sub.nc` line 12"


class Word(Record):
    line: int
    start: int
    end: int
    text: str
    kind: str  # "word", "$", "#"


class Call(Record):
    line: int
    start: int
    end: int
    name: str
    local: bool  # LL
    cycle: bool  # L CYCLE [NAME=…]


class Analysis(Record):
    moves: int = 0
    evaluated: int = 0
    skipped: dict[str, list[int]] = field(default_factory=dict)  # reason → [count, first line]
    crossings: list[Crossing] = field(default_factory=list)
    unknown: list[Word] = field(default_factory=list)
    structure: list[tuple[int, int, int, str]] = field(default_factory=list)  # line, start, end, message
    calls: list[Call] = field(default_factory=list)
    travel: dict[int, list[float]] = field(default_factory=dict)  # axis → [min, max] machine position
    machine: bool = False  # followed against a machine
    locals: set[str] = field(default_factory=set)  # names of the local subprograms (%L), upper case
    unfollowed: list[tuple[str, int]] = field(default_factory=list)  # G codes zero does not follow, line
    not_followed: list[Call] = field(default_factory=list)  # calls zero could not follow into
    followed: list[Call] = field(default_factory=list)  # calls followed into their subprogram

    @property
    def not_evaluated(self) -> int:
        return self.moves - self.evaluated

    def skip(self, reason: str, line: int) -> None:
        slot = self.skipped.get(reason)
        if slot is None:
            self.skipped[reason] = [1, line]
        else:
            slot[0] += 1


# ----------------------------------------------------------------------------- expressions

_EXPR_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:E[-+]?\d+)?|\.\d+)|(P\d+)|(V\.[A-Z_]+\.[A-Z0-9_.]*)|([A-Z_][A-Z0-9_]*)"
                         r"|(\*\*|==|!=|<=|>=|[-+*/\[\],<>]))")
_FUNCS: dict[str, Callable[[float], float]] = {
    "ABS": abs, "SQRT": math.sqrt, "SQR": lambda x: x * x, "INT": lambda x: float(int(x)),
    "ROUND": lambda x: float(round(x)), "FLOOR": lambda x: float(math.floor(x)), "CEIL": lambda x: float(math.ceil(x)),
    "SIN": lambda x: math.sin(math.radians(x)), "COS": lambda x: math.cos(math.radians(x)),
    "TAN": lambda x: math.tan(math.radians(x)), "EXP": math.exp, "LN": math.log,
}


def evaluate(text: str, variables: dict[str, float]) -> float | None:
    """The value of an ISG expression of numbers, known P-parameters and ``V.`` variables,
    ``+ - * / **``, ``[ ]`` and a few functions (angles in degrees); None when any part of it
    is not known to zero (a variable of the controller, an indexed one, a comparison)."""
    tokens: list[tuple[int, str]] = []
    pos, n = 0, len(text)
    while pos < n:
        m = _EXPR_TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            if text[pos:].strip() == "":
                break
            return None
        kind = m.lastindex or 0
        tokens.append((kind, m.group(kind)))
        pos = m.end()
        if pos < n and kind == 3 and text[pos] == "[":  # an indexed variable: not followed
            return None
    if not tokens:
        return None
    at = 0

    def peek() -> str | None:
        return tokens[at][1] if at < len(tokens) else None

    def take() -> tuple[int, str]:
        nonlocal at
        if at >= len(tokens):
            raise ValueError(text)
        at += 1
        return tokens[at - 1]

    def primary() -> float:
        kind, tok = take()
        if kind == 1:
            return float(tok)
        if kind in (2, 3):
            if tok in variables:
                return variables[tok]
            raise ValueError(text)
        if tok == "-":
            return -primary()
        if tok == "+":
            return primary()
        if tok == "[":
            v = additive()
            if take()[1] != "]":
                raise ValueError(text)
            return v
        if kind == 4:
            if tok == "PI":
                return math.pi
            fn = _FUNCS.get(tok)
            if fn is None or take()[1] != "[":
                raise ValueError(text)
            v = additive()
            if take()[1] != "]":
                raise ValueError(text)
            try:
                return fn(v)
            except (ValueError, OverflowError) as exc:
                raise ValueError(tok) from exc
        raise ValueError(text)

    def power() -> float:
        v = primary()
        if peek() == "**":
            take()
            try:
                return float(v ** power())
            except (OverflowError, ZeroDivisionError, TypeError) as exc:
                raise ValueError(text) from exc
        return v

    def term() -> float:
        v = power()
        while peek() in ("*", "/"):
            op = take()[1]
            w = power()
            if op == "*":
                v *= w
            elif w == 0:
                raise ValueError(text)
            else:
                v /= w
        return v

    def additive() -> float:
        v = term()
        while peek() in ("+", "-"):
            op = take()[1]
            w = term()
            v = v + w if op == "+" else v - w
        return v

    try:
        value = additive()
    except ValueError:
        return None
    if at != len(tokens) or not math.isfinite(value):
        return None
    return value


# ----------------------------------------------------------------------------- blocks

_IDENT = re.compile(r"[A-Z_][A-Z0-9_]*")
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)")
_VALUE_START = re.compile(r"\s*+=?\s*+(?:[-+]?(?:\d|\.\d)|[-+]?P\d|[-+]?V\.|[-+]?\[)")
_VAR = re.compile(r"V\.[A-Z_]+\.[A-Z0-9_.]*(?:\[[^\]]*\])*(?:\.[A-Z0-9_]+)*")
_PRIMARY = re.compile(r"[-+]?(?:\d+\.?\d*(?!\.)|\.\d+|P\d+|V\.[A-Z_]+\.[A-Z0-9_.]*(?:\[[^\]]*\])*)")
_ASSIGN = re.compile(r"\s*=(?!=)")
# a block of address letters and plain numbers only, and its words (the fast path of CAM programs)
_SIMPLE = re.compile(r"\s*+(?:N\d++(?=[\sA-Z]|$))?(?:\s*+[A-Z]\s*+[-+]?+(?:\d++(?:\.\d*+)?+|\.\d++))++\s*+$")
_SIMPLE_WORD = re.compile(r"([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")
_CENTRE = frozenset("IJKR")
# a run of name characters followed by `=` (never `==`), found once per run: a search for the
# variable itself restarted inside a long run of `V.` (quadratic)
_ASSIGNED_RUN = re.compile(r"(?<![A-Z0-9_.])([A-Z0-9_.]++)\s*+=(?!=)")
_CHAIN_START = re.compile(r"V\.[A-Z_]++\.")  # a V.-variable: whatever follows in the run is its name
_P_TAIL = re.compile(r"P\d++$")
_G_DIMS = re.compile(r"\bG0*(?:90|91)\b")
_G_OFFSET = re.compile(r"\bG0*(?:5[3-9]|159)\b")
_CALL_WORD = re.compile(r"\bLL?\s|\bG0*92\b")
_DOLLAR = re.compile(r"\$([A-Z]+)")
_MOTION = frozenset({0, 1, 2, 3})
_NO_MACHINE = "no machine to check them against (zero lint --machine STARTUP, or `machine` in the configuration)"
_NOT_PLAIN = frozenset("IJKR") | frozenset(lang.DEFAULT_AXES)  # centre words, axes the channel may not have
_NAMED = re.compile(r"[A-Z]{1,4}\d*")
_SKIP_MARK = re.compile(r"/\d*")
_BLOCK_NUMBER = re.compile(r"N(\d+)(:?)")
_AT_PARAM = re.compile(r"@P\d+")
_PARAM = re.compile(r"P\d+")
_CYCLE = re.compile(r"\s*(CYCLE|SEQUENCE)\s*\[")
_CALL_NAME = re.compile(r"\s*\"?([^\s\"()\[\];]+)\"?")
_COMMENT_BLOCK = re.compile(r"#COMMENT\s*(BEGIN|END)")
_VAR_BLOCK = re.compile(r"\s*(?:N\d+\s+)?#VAR\b")
_DECLARATION = re.compile(r"\s*(?:N\d+\s+)?(V\.(?:P|L|S|CYC)\.[A-Z0-9_]+)\s*(?::\s*[A-Z0-9_\[\]]+\s*)?(=\s*(.*))?$")
_HEADER = re.compile(r"\s*%\s*(L\s+)?(\S*)")
_LOCAL_CALL = re.compile(r"\bLL\s+(?!CYCLE\b)\"?([^\s\"()\[\];]+)")
_GOTO = re.compile(r"\$GOTO\s*+(?:N(\d++)|\[([^\]$]*+)\])")  # a label holds no `$`: each `$GOTO[` scans to the next
_AXPARAM_SWE = re.compile(r"\s*KENNGR\.SWE_(NEG|POS)\s+([-+]?\d+)\s*$")


def _reached(travel: dict[int, list[float]], i: int, machine: float, limits: tuple[float, float]) -> bool:
    """Widen axis ``i``'s travel to take in ``machine``; ``True`` where that position lies beyond
    the soft limits ``(negative, positive)`` by more than rounding."""
    span = travel.get(i)
    if span is None:
        travel[i] = [machine, machine]
    elif machine < span[0]:
        span[0] = machine
    elif machine > span[1]:
        span[1] = machine
    neg, posl = limits
    if machine > posl or machine < neg:
        tol = 1e-9 * max(1.0, abs(machine))
        return machine > posl + tol or machine < neg - tol
    return False


def assigned(up: str) -> list[str]:
    """The P-parameters and V.-variables a block assigns (``P1 = 5``, ``V.L.X=P1``), each once per
    run of name characters before its `=`, in time linear in the block."""
    out = []
    for m in _ASSIGNED_RUN.finditer(up):
        run = m.group(1)
        starts = [x.start() for x in (_CHAIN_START.search(run), _P_TAIL.search(run)) if x is not None]
        if starts:  # the earliest variable that reaches the `=`
            out.append(run[min(starts):])
    return out


def _closing(text: str, start: int) -> int:
    depth = 0
    for i in range(start, len(text)):
        c = text[i]
        if c == "[":
            depth += 1
        elif c == "]":
            depth -= 1
            if depth == 0:
                return i
    return -1


class _Tok(Record):
    """One word of a block: ``kind`` is axis, addr, call, assign, dollar, hash, label, posl."""

    kind: str
    name: str
    line: int
    start: int
    end: int
    value: float | None = None
    text: str = ""  # the value as written


class _State:
    __slots__ = (
        "absolute",
        "centre_abs",
        "diameter",
        "g92",
        "g92_from",
        "group",
        "inch",
        "limit_from",
        "limits",
        "motion",
        "plane",
        "pos",
        "pos_why",
        "unmonitored",
        "variables",
        "why",
    )

    def __init__(self, setup: Setup, n: int) -> None:
        self.pos: list[float | None] = [None] * n
        self.pos_why: list[str] = ["relative move from an unknown start position"] * n
        self.absolute: bool | None = setup.absolute
        self.group: int | None = setup.default_group
        self.why = ""  # why absolute/group are unknown
        self.inch = setup.inch
        self.plane = setup.plane
        self.centre_abs = setup.centre_absolute
        self.diameter = setup.diameter
        self.g92: list[float] = [0.0] * n
        self.g92_from: list[str] = [""] * n
        self.limits: list[tuple[float, float]] = [(a.neg, a.pos) for a in setup.axes]
        self.limit_from: list[tuple[str, str]] = [("", "")] * n
        self.unmonitored: list[str] = [""] * n
        self.variables: dict[str, float] = {}
        self.motion = 1  # G01 unless the program says (the moves are checked the same)

    def copy(self) -> _State:
        new = _State.__new__(_State)
        new.pos, new.pos_why = self.pos.copy(), self.pos_why.copy()
        new.absolute, new.group, new.why = self.absolute, self.group, self.why
        new.inch, new.plane, new.centre_abs, new.diameter = self.inch, self.plane, self.centre_abs, self.diameter
        new.g92, new.g92_from = self.g92.copy(), self.g92_from.copy()
        new.limits, new.limit_from = self.limits.copy(), self.limit_from.copy()
        new.unmonitored = self.unmonitored.copy()
        new.variables, new.motion = self.variables.copy(), self.motion
        return new

    def join(self, others: Sequence[_State], why: str) -> None:
        """This state where control flow from ``others`` meets: what differs is unknown."""
        for o in others:
            for i, p in enumerate(o.pos):
                if p != self.pos[i]:
                    self.pos[i] = None
                    self.pos_why[i] = why
            if o.absolute != self.absolute:
                self.absolute = None
                self.why = why
            if o.group != self.group:
                self.group = None
                self.why = why
            for k in list(self.variables):
                if o.variables.get(k) != self.variables[k]:
                    del self.variables[k]
            for i in range(len(self.g92)):
                if o.g92[i] != self.g92[i]:
                    self.g92[i] = math.nan
                    self.g92_from[i] = why
            if o.limits != self.limits or o.unmonitored != self.unmonitored:
                self.limits = [(min(a[0], b[0]), max(a[1], b[1])) for a, b in zip(self.limits, o.limits, strict=True)]

    def forget(self, why: str, local_only: bool = False) -> None:
        """After a call or at a jump target: positions, dimensions and offset unknown."""
        self.pos = [None] * len(self.pos)
        self.pos_why = [why] * len(self.pos)
        self.absolute = None
        self.group = None
        self.why = why
        self.variables = {k: v for k, v in self.variables.items() if k.startswith("V.L.")} if local_only else {}


class _Facts:
    __slots__ = ("axes", "dims", "offset", "variables")

    def __init__(self) -> None:
        self.variables: set[str] = set()
        self.axes: set[int] = set()
        self.dims = False
        self.offset = False


class _Frame:
    __slots__ = ("branches", "end", "entry", "has_default", "key", "line", "start", "started")

    def __init__(self, key: str, line: int, start: int, end: int, entry: _State | None) -> None:
        self.key = key
        self.line = line
        self.start = start
        self.end = end
        self.entry = entry
        self.branches: list[_State] = []
        self.has_default = False
        self.started = True


class Follower:
    """Reads a program's blocks in order (one instance per program)."""

    def __init__(self, lines: Sequence[str], setup: Setup | None,
                 machine_data: dict[int, list[tuple[str, str]]] | None = None,
                 resolve: Callable[[str], Sequence[str] | None] | None = None, depth: int = 0,
                 state: _State | None = None) -> None:
        self.lines = lines
        self.resolve = resolve
        self.depth = depth
        self.inherit = state is not None  # a subprogram: it starts where its caller is
        self.budget = [max(FOLLOW_BUDGET, 4 * len(lines))]  # lines the calls of one program may follow, shared
        self.setup = setup
        self.machine_data = machine_data or {}  # line → [(AX name, AXPARAM text)]
        axes = setup.axes if setup is not None else [AxisSetup(a, -math.inf, math.inf) for a in lang.DEFAULT_AXES]
        self.axes = axes
        self.names = {a.name.upper(): i for i, a in enumerate(axes)}
        self.multi = sorted((n for n in self.names if len(n) > 1), key=len, reverse=True)
        self.result = Analysis(machine=setup is not None)
        self.state = state if state is not None else _State(setup or Setup(axes), len(axes))
        self.sections: dict[str, tuple[int, int]] = {}  # local subprogram → its lines (0-based, end excluded)
        self.called_locals: set[str] = set()
        self.loop_facts: dict[int, _Facts] = {}  # a loop's line → what its body changes
        self.stack: list[_Frame] = []
        self.targets: set[str] = set()  # $GOTO targets: "N20", "[LABEL]"
        self.section = ""  # "" main, else the local subprogram's name
        self._open = False
        self._transform: tuple[str, int] | None = None
        self.unfollowed = self.result.unfollowed

    # ------------------------------------------------------------------ driver

    def _index(self) -> None:
        """Jump targets, local subprograms and which of them the file calls."""
        opened: tuple[str, int] | None = None
        for index, text in enumerate(self.lines):
            if "$GOTO" in text or "$goto" in text.lower():
                for m in _GOTO.finditer(text.upper()):
                    self.targets.add(f"N{int(m.group(1))}" if m.group(1) else f"[{m.group(2).strip()}]")
            if "%" in text:
                hm = _HEADER.match(text.upper())
                if hm is not None and not text.lstrip().startswith(";"):
                    if opened is not None:
                        self.sections[opened[0]] = (opened[1], index)
                    opened = (hm.group(2), index + 1) if hm.group(1) else None
            if "LL" in text.upper():
                self.called_locals.update(x.upper() for x in _LOCAL_CALL.findall(text.upper()))
        if opened is not None:
            self.sections[opened[0]] = (opened[1], len(self.lines))
        self._loops()

    def _loops(self) -> None:
        """What each loop's body changes (its variables, the axes it moves, whether it sets
        G90/G91 or the offset), gathered in one pass: a body's facts go to the innermost open
        structure and, when it closes, to the one around it (nested or unclosed loops stay linear)."""
        stack: list[tuple[int, str, _Facts]] = []
        names = self.names
        for number, text in enumerate(self.lines, 1):
            if "$" not in text and not stack:
                continue
            up = text.upper() if text.isascii() else _upper(text)
            if "(" in up or ";" in up:
                up = strip_comments(up)
            if stack:
                facts = stack[-1][2]
                if "=" in up:
                    facts.variables.update(assigned(up))
                if "G" in up:
                    if _G_DIMS.search(up):
                        facts.dims = True
                    if _G_OFFSET.search(up):
                        facts.offset = True
                if "#" in up or _CALL_WORD.search(up):
                    facts.dims = facts.offset = True
                for name, i in names.items():
                    if name in up and re.search(rf"(?<![A-Z0-9_.]){re.escape(name)}\s*+=?+\s*+[-+.\d\[PV]", up):
                        facts.axes.add(i)
            if "$" not in up:
                continue
            for kw in _DOLLAR.findall(up):
                if kw in lang.OPENERS and not (kw == "IF" and "$GOTO" in up):
                    facts = _Facts()
                    if kw == "FOR":  # the loop variable changes per iteration
                        facts.variables.update(assigned(up))
                    stack.append((number, kw, facts))
                elif kw in lang.CLOSERS and stack:
                    self._close_loop(stack)
        while stack:
            self._close_loop(stack)

    def _close_loop(self, stack: list[tuple[int, str, _Facts]]) -> None:
        line, kw, facts = stack.pop()
        if kw in lang.LOOPS:
            self.loop_facts[line] = facts
        if stack:
            outer = stack[-1][2]
            outer.variables |= facts.variables
            outer.axes |= facts.axes
            outer.dims = outer.dims or facts.dims
            outer.offset = outer.offset or facts.offset

    def run(self, start: int = 0, end: int | None = None) -> Analysis:
        lines = self.lines
        if not self.sections and not self.targets:
            self._index()
        in_comment = 0
        in_var = False
        pending: list[tuple[int, str]] = []
        fast = not self.multi  # axis names of one letter: a word is a letter and its number
        for number in range(start + 1, (len(lines) if end is None else end) + 1):
            raw = lines[number - 1]
            up = raw.upper() if raw.isascii() else _upper(raw)
            if "(" in up or ";" in up or '"' in up:
                up = strip_comments(up)
            if "#COMMENT" in up:
                cm = _COMMENT_BLOCK.search(up)
                if cm is not None:
                    in_comment = in_comment + 1 if cm.group(1) == "BEGIN" else max(in_comment - 1, 0)
                    continue
            if in_comment:
                continue
            if self._open:  # a cycle's arguments in brackets go on to the closing `]`
                if "]" in up:
                    self._open = False
                continue
            if in_var:
                if "#ENDVAR" in up:
                    in_var = False
                else:
                    self._declaration(up)
                continue
            stripped = up.rstrip()
            if not stripped:
                continue
            if fast and not pending and _SIMPLE.match(stripped):
                self._fast(number, stripped)
                continue
            if stripped.endswith("\\"):
                pending.append((number, stripped[:-1]))
                continue
            if pending:
                pending.append((number, stripped))
                parts, pending = pending, []
            else:
                parts = [(number, stripped)]
            if "#VAR" in parts[0][1] and _VAR_BLOCK.match(parts[0][1]):
                if "#ENDVAR" not in parts[0][1]:
                    in_var = True
                continue
            self._block(parts)
        if pending:
            self._block(pending)
        if self.depth == 0 or end is None:
            self._close_all(len(lines) + 1, "at the end of the program")
        else:
            self.stack.clear()
        return self.result

    def _close_all(self, line: int, where: str) -> None:
        for frame in reversed(self.stack):
            self.result.structure.append((frame.line, frame.start, frame.end,
                                          f"${frame.key} is not closed by ${lang.OPENERS[frame.key]} {where}"))
        self.stack.clear()

    def _declaration(self, up: str) -> None:
        m = _DECLARATION.match(up)
        if m is None:
            return
        if m.group(2):
            value = evaluate(m.group(3), self.state.variables)
            if value is not None:
                self.state.variables[m.group(1)] = value
                return
        self.state.variables.pop(m.group(1), None)

    # ------------------------------------------------------------------ one block

    def _block(self, parts: list[tuple[int, str]]) -> None:
        toks: list[_Tok] = []
        first_line = parts[0][0]
        for index, (number, text) in enumerate(parts):
            if not self._lex(number, text, toks, index == 0):
                if self._open and any("]" in rest for _, rest in parts[index + 1:]):
                    self._open = False
                break
        if toks:
            self._execute(toks, first_line)

    def _unknown(self, line: int, start: int, end: int, text: str, kind: str = "word") -> None:
        self.result.unknown.append(Word(line, start, end, text, kind))

    def _lex(self, line: int, text: str, toks: list[_Tok], first: bool) -> bool:
        """The words of one physical line into ``toks``; False when the rest of the block is no
        words (a $ or # command with its arguments)."""
        n = len(text)
        i = 0
        at_start = first
        while i < n:
            c = text[i]
            if c in " \t":
                i += 1
                continue
            if at_start:
                if c == "%" and not toks:
                    m = _HEADER.match(text, i)
                    assert m is not None
                    self._header(line, bool(m.group(1)), m.group(2))
                    return False
                if c == "/":
                    m = _SKIP_MARK.match(text, i)
                    assert m is not None
                    i = m.end()
                    continue
                if c == ":":
                    i += 1
                    continue
                if c == "N":
                    m = _BLOCK_NUMBER.match(text, i)
                    if m is not None and (m.end() >= n or not text[m.end()].isalnum() or m.group(2)):
                        self._label(f"N{int(m.group(1))}", line)
                        i = m.end()
                        continue
                if c == "[":
                    close = text.find("]", i)
                    if close > 0 and not _ASSIGN.match(text, close + 1):
                        self._label(f"[{text[i + 1:close].strip()}]", line)
                        i = close + 1
                        if text.startswith(":", i):  # [NAME]: as the extension's grammar writes a label too
                            i += 1
                        at_start = False
                        continue
            at_start = False
            if c == "$":
                m = _IDENT.match(text, i + 1)
                word = m.group() if m else ""
                end = m.end() if m else i + 1
                if word not in lang.DOLLAR_KEYWORDS:
                    self._unknown(line, i, end, text[i:end], "$")
                else:
                    toks.append(_Tok("dollar", word, line, i, end, text=text[end:]))
                return False
            if c == "#":
                m = _IDENT.match(text, i + 1)
                word = m.group() if m else ""
                end = m.end() if m else i + 1
                if word not in lang.HASH_COMMANDS and not word.startswith(lang.HASH_PREFIXES):
                    self._unknown(line, i, end, text[i:end], "#")
                else:
                    toks.append(_Tok("hash", word, line, i, end, text=text[end:]))
                return False
            if c == '"':
                close = text.find('"', i + 1)
                i = n if close < 0 else close + 1
                continue
            if c == "V" and text.startswith("V.", i):
                m = _VAR.match(text, i)
                if m is not None:
                    a = _ASSIGN.match(text, m.end())
                    if a is not None:
                        toks.append(_Tok("assign", m.group(), line, i, m.end(), text=text[a.end():]))
                        return False
                    i = m.end()  # a variable alone (its value shown) or an argument: no word to check
                    continue
            if c == "@":
                m = _AT_PARAM.match(text, i)
                if m is not None:
                    i = self._value_end(text, m.end())
                    continue
            if c == "P":
                m = _PARAM.match(text, i)
                if m is not None:
                    a = _ASSIGN.match(text, m.end())
                    if a is not None:
                        toks.append(_Tok("assign", m.group(), line, i, m.end(), text=text[a.end():]))
                        return False
            if "A" <= c <= "Z" or c == "_":
                m = _IDENT.match(text, i)
                assert m is not None
                ident = m.group()
                if ident in ("L", "LL") and (m.end() >= n or text[m.end()] in " \t"):
                    i = self._call(line, ident == "LL", text, m.end(), toks)
                    if self._open:
                        return False  # the cycle's arguments go on over the next lines
                    continue
                name = self._address(ident, text, i)
                if name is None:
                    self._unknown(line, i, m.end(), text[i:m.end()])
                    i = m.end()
                    continue
                j = i + len(name)
                vstart = _skip_eq(text, j)
                if text.startswith("[", vstart) or text.startswith("-[", vstart):
                    close = _closing(text, vstart)
                    end = n if close < 0 else close + 1
                    inner = text[vstart + (2 if text[vstart] == "-" else 1):end - 1]
                    if name in self.names and re.match(r"\s*POS_LIMIT\b", inner):
                        toks.append(_Tok("posl", name, line, i, end, text=inner))
                        i = end
                        continue
                    value = evaluate(text[vstart:end], self.state.variables)
                    kind = "axis" if name in self.names else "addr"
                    toks.append(_Tok(kind, name, line, i, end, value, text[vstart:end]))
                    i = end
                    continue
                end = self._value_end(text, vstart)
                raw = text[vstart:end]
                value = _number(raw)
                if value is None:
                    value = evaluate(raw, self.state.variables)
                kind = "axis" if name in self.names else "addr"
                toks.append(_Tok(kind, name, line, i, end, value, raw))
                i = end
                continue
            # anything else: a word the language does not have (up to the next blank)
            j = i
            while j < n and text[j] not in " \t":
                j += 1
            self._unknown(line, i, j, text[i:j])
            i = j
        return True

    def _address(self, ident: str, text: str, at: int) -> str | None:
        """The address (an axis name or a letter) the word at ``at`` starts with, when a value follows."""
        named = ident in self.names or (_ASSIGN.match(text, at + len(ident)) and _NAMED.fullmatch(ident))
        if named and _VALUE_START.match(text, at + len(ident)):
            return ident  # an axis or spindle named with digits, written NAME=value (S1=1000, A1 = 0)
        for name in self.multi:
            if ident.startswith(name) and _VALUE_START.match(text, at + len(name)):
                return name
        if ident[0] in lang.ADDRESS_LETTERS and _VALUE_START.match(text, at + 1):
            return ident[0]
        return None

    @staticmethod
    def _value_end(text: str, at: int) -> int:
        """The end of an address value: a primary, then (op primary)* with no blank between."""
        at = _skip_eq(text, at)
        m = _PRIMARY.match(text, at)
        if m is None:
            return at
        end = m.end()
        while end < len(text) and text[end] in "+-*/":
            nxt = _PRIMARY.match(text, end + 1)
            if nxt is None:
                if text.startswith("[", end + 1):
                    close = _closing(text, end + 1)
                    end = len(text) if close < 0 else close + 1
                    continue
                break
            end = nxt.end()
        return end

    def _call(self, line: int, local: bool, text: str, at: int, toks: list[_Tok]) -> int:
        m = _CYCLE.match(text, at)
        if m is not None:
            close = _closing(text, m.end() - 1)
            end = len(text) if close < 0 else close + 1
            self._open = close < 0
            body = text[m.end():end - 1]
            nm = re.search(r"NAME\s*=\s*\"?([^\s\"\]]+)", body)
            name = nm.group(1) if nm else ""
            start = m.end() + nm.start(1) if nm else at
            toks.append(_Tok("call", name, line, start, start + len(name), text="cycle" + ("L" if local else "")))
            return end
        m = _CALL_NAME.match(text, at)
        if m is None:
            self._unknown(line, at - (2 if local else 1), at, "LL" if local else "L")
            return at
        name = m.group(1)
        toks.append(_Tok("call", name, line, m.start(1), m.end(1), text="L" if local else ""))
        return m.end()

    def _header(self, line: int, local: bool, name: str) -> None:
        if self.inherit and not local:
            self.inherit = False  # the subprogram's own name: it goes on from its caller's state
            return
        if self.stack:
            self._close_all(line, f"before the program part at line {line}")
        self.section = name if local else ""
        if local:
            self.result.locals.add(name.upper())
        setup = self.setup or Setup(self.axes)
        self.state = _State(setup, len(self.axes))
        if local:
            self.state.forget(f"local subprogram %L {name} (its start depends on the caller)")

    def _label(self, label: str, line: int) -> None:
        if label in self.targets:
            self.state.forget(f"after the jump target {label} at line {line}")

    # ------------------------------------------------------------------ semantics

    def _execute(self, toks: list[_Tok], line: int) -> None:
        codes: set[int] = set()
        group_code: int | None = None
        axes: list[_Tok] = []
        centre: dict[str, _Tok] = {}
        other: list[_Tok] = []
        for t in toks:
            if t.kind == "axis":
                axes.append(t)
            elif t.kind != "addr":
                other.append(t)
            elif t.name == "G":
                if t.value is not None and t.value == int(t.value):
                    codes.add(int(t.value))
                else:
                    self.unfollowed.append(("a computed G code", t.line))
            elif t.name == "G159":
                codes.add(159)
                group_code = int(t.value) if t.value is not None and t.value == int(t.value) else None
            elif t.name in ("I", "J", "K", "R"):
                centre[t.name] = t
            elif t.name in lang.DEFAULT_AXES or (len(t.name) > 1 and not t.name.startswith("S")):
                axes.append(t)  # an axis this channel does not have (S1=…: a spindle)
        self._apply(line, codes, group_code, axes, centre, other)

    def _fast(self, line: int, text: str) -> None:
        """A block of address letters with plain numbers only (most of a CAM program): the words
        straight from one regular expression, then what every block does. The spans of its words
        are found when a finding needs them."""
        words = _SIMPLE_WORD.findall(text)
        st = self.state
        if self.setup is None and not self.targets:  # nothing to check them against: count the moves
            if any(letter in self.names for letter, _ in words) and not any(
                    letter == "G" and float(raw) in lang.G_NOT_TARGETS for letter, raw in words):
                self.result.moves += 1
                self.result.skip(_NO_MACHINE, line)
            return
        if self._plain(st):  # the common case, inline: linear moves in a known state
            codes = 0
            targets: list[tuple[int, str, float]] = []
            names = self.names
            other = False
            for letter, raw in words:
                if letter == "G":
                    codes += 1
                    g = float(raw)
                    if g not in (0.0, 1.0):
                        other = True
                        break
                elif letter in names:
                    targets.append((names[letter], raw, float(raw)))
                elif letter in _NOT_PLAIN:
                    other = True
                    break
            if not other and (codes or st.motion < 2):
                if codes:
                    st.motion = int(float(next(raw for letter, raw in words if letter == "G")))
                if targets:
                    self._plain_move(line, targets)
                return
        codes_set: set[int] = set()
        axes: list[_Tok] = []
        centre: dict[str, _Tok] = {}
        names = self.names
        for letter, raw in words:
            if letter == "N":
                if self.targets and f"N{int(float(raw))}" in self.targets:
                    self._label(f"N{int(float(raw))}", line)
                continue
            value = float(raw)
            if letter == "G":
                if value == int(value):
                    codes_set.add(int(value))
                else:
                    self.unfollowed.append(("a computed G code", line))
            elif letter in names:
                axes.append(_Tok("axis", letter, line, -1, -1, value, raw))
            elif letter in _CENTRE:
                centre[letter] = _Tok("addr", letter, line, -1, -1, value, raw)
            elif letter in lang.DEFAULT_AXES:
                axes.append(_Tok("addr", letter, line, -1, -1, value, raw))
        self._apply(line, codes_set, None, axes, centre, ())

    def _plain(self, st: _State) -> bool:
        """Whether a block of linear moves needs nothing but adding offsets and comparing."""
        return (self.setup is not None and self._transform is None and st.absolute is not None
                and st.group is not None and not st.inch and not st.diameter and not self.targets
                and not (self.section and self.depth == 0) and not any(st.g92))

    def _plain_move(self, line: int, targets: list[tuple[int, str, float]]) -> None:
        st = self.state
        res = self.result
        res.moves += 1
        pos = st.pos
        assert self.setup is not None and st.group is not None
        row = self.setup.offsets.get(st.group)
        limits = st.limits
        travel = res.travel
        absolute = st.absolute
        for i, raw, value in targets:
            if not absolute:
                base = pos[i]
                if base is None:
                    res.skip(st.pos_why[i], line)
                    for j, _, _ in targets:  # the block's other targets still move
                        if j != i and pos[j] is not None:
                            pos[j] = None
                            st.pos_why[j] = st.pos_why[i]
                    return
                value += base
            pos[i] = value
            machine = value + (row[i] if row is not None and i < len(row) else 0.0)
            if _reached(travel, i, machine, limits[i]):
                self._crossing(i, value, machine, _Tok("axis", self.axes[i].name, line, -1, -1, value, raw), False)
        res.evaluated += 1

    def _apply(self, line: int, codes: set[int], group_code: int | None, axes: list[_Tok],
               centre: dict[str, _Tok], other: Sequence[_Tok]) -> None:
        st = self.state
        if not other and codes <= _MOTION:  # the common block: a motion code at most
            if codes:
                st.motion = min(codes)
            if axes:
                self._move(axes, centre, line, ())
            return
        unknown_g = sorted(codes - lang.G_FOLLOWED - lang.G_NOT_TARGETS - lang.G_STATE)
        for g in unknown_g:
            self.unfollowed.append((f"G{g}", line))
        if 90 in codes:
            st.absolute = True
        elif 91 in codes:
            st.absolute = False
        if 70 in codes:
            st.inch = True
        elif 71 in codes:
            st.inch = False
        for p in (17, 18, 19):
            if p in codes:
                st.plane = p
        if 161 in codes:
            st.centre_abs = True
        elif 162 in codes:
            st.centre_abs = False
        if 51 in codes:
            st.diameter = True
        elif 52 in codes:
            st.diameter = False
        if codes & {21, 22, 23}:
            self._transform = (f"mirroring G{min(codes & {21, 22, 23})}", line)
        elif 20 in codes and self._transform is not None and self._transform[0].startswith("mirroring"):
            self._transform = None
        for g in (53, 54, 55, 56, 57, 58, 59):
            if g in codes:
                st.group = g - 53
        if 159 in codes:
            st.group = group_code
            if group_code is None:
                st.why = f"a computed work offset G159= at line {line}"
        for g in (0, 1, 2, 3):
            if g in codes:
                st.motion = g
        for t in other:
            if t.kind == "dollar":
                self._control(t)
            elif t.kind == "hash":
                self._hash(t)
            elif t.kind == "assign":
                value = evaluate(t.text, st.variables)
                if value is None:
                    st.variables.pop(t.name, None)
                else:
                    st.variables[t.name] = value
            elif t.kind == "posl":
                self._pos_limit(t)
        if 98 in codes or 99 in codes:
            self._programmed_limits(axes, positive=99 in codes)
            axes = []
        if 92 in codes:
            for t in axes:
                i = self.names.get(t.name)
                if i is None:
                    continue
                if t.value is None or st.absolute is None:
                    st.g92[i] = math.nan
                else:
                    st.g92[i] = t.value if st.absolute else st.g92[i] + t.value
                st.g92_from[i] = f"G92 coordinate preset at line {t.line}"
            axes = []
        if 74 in codes:
            for t in axes:
                i = self.names.get(t.name)
                if i is not None:
                    st.pos[i] = None
                    st.pos_why[i] = f"after homing (G74) at line {t.line}"
            axes = []
        if 4 in codes:
            axes = []
        if axes:
            self._move(axes, centre, line, unknown_g)
        for t in other:
            if t.kind == "call":
                self._called(t)

    def _move(self, axes: list[_Tok], centre: dict[str, _Tok], line: int, unknown_g: Sequence[int]) -> None:
        """One block with axis words: its targets (and an arc's extent) against the limits."""
        st = self.state
        res = self.result
        if self.section and self.depth == 0 and self.section.upper() in self.called_locals:
            return  # followed where it is called
        res.moves += 1
        block = ""  # why no target of the block can be checked
        if self.setup is None:
            block = _NO_MACHINE
        elif self._transform is not None:
            name, at = self._transform
            block = f"{'' if name.startswith('mirroring') else '#'}{name} active from line {at}"
        elif unknown_g:
            block = f"G{unknown_g[0]} (zero does not follow it)"
        elif st.absolute is None or st.group is None:
            block = st.why or "dimensions or work offset not known"
        reason = ""  # why some targets cannot be checked
        arc = st.motion == 2 or st.motion == 3
        start = list(st.pos) if arc else None
        pos = st.pos
        names = self.names
        checks: list[tuple[int, float, _Tok]] = []
        for t in axes:
            i = names.get(t.name)
            if i is None:
                reason = reason or f"{t.name} is no axis of the channel"
                continue
            value = t.value
            if value is None:
                reason = reason or "computed position"
                pos[i] = None
                st.pos_why[i] = f"computed position at line {t.line}"
                continue
            if st.diameter and i == 0:
                reason = reason or "diameter programming (G51)"
                pos[i] = None
                st.pos_why[i] = f"diameter programming at line {t.line}"
                continue
            absolute = st.absolute
            if absolute is None:
                pos[i] = None
                st.pos_why[i] = st.why
                continue
            if st.inch and not self.axes[i].rotary:
                value *= INCH
            if absolute:
                target = value
            else:
                base = pos[i]
                if base is None:
                    reason = reason or st.pos_why[i]
                    continue
                target = base + value
            pos[i] = target
            if st.g92[i] != 0:
                reason = reason or st.g92_from[i]
                continue
            checks.append((i, target, t))
        targets = len(checks)
        if arc and not block and not reason:
            assert start is not None
            pts = self._arc(start, centre, axes)
            if pts is None:
                reason = "arc whose extent zero cannot compute"
            else:
                checks.extend(pts)
        if not block:
            group = st.group
            assert self.setup is not None and group is not None
            row = self.setup.offsets.get(group)
            limits = st.limits
            travel = res.travel
            for k, (i, target, t) in enumerate(checks):
                machine = target + (row[i] if row is not None and i < len(row) else 0.0)
                if _reached(travel, i, machine, limits[i]):
                    self._crossing(i, target, machine, t, arc=k >= targets)
        why = block or reason
        if why:
            res.skip(why, line)
        else:
            res.evaluated += 1

    def _crossing(self, i: int, target: float, machine: float, t: _Tok, arc: bool) -> None:
        st = self.state
        assert self.setup is not None and st.group is not None
        neg, pos = st.limits[i]
        positive = machine > pos
        if t.start < 0:
            self._locate(t)
        self.result.crossings.append(Crossing(
            t.line, t.start, t.end, i, target, machine, pos if positive else neg, positive, st.group,
            self.setup.offset(st.group, i), st.limit_from[i][1 if positive else 0], st.unmonitored[i], arc))

    def _locate(self, t: _Tok) -> None:
        """The span of a word the fast path read without one: the first `<letter><number>` that matches."""
        text = self.lines[t.line - 1].upper()
        m = re.search(rf"(?<![A-Z0-9_.]){re.escape(t.name)}\s*{re.escape(t.text)}(?![0-9.])", text)
        if m is None:
            m = re.search(rf"{re.escape(t.name)}\s*{re.escape(t.text)}", text)
        t.start, t.end = (m.start(), m.end()) if m is not None else (0, max(len(text.rstrip()), 1))

    def _arc(self, start: list[float | None], centre: dict[str, _Tok],
             axes: list[_Tok]) -> list[tuple[int, float, _Tok]] | None:
        """The extreme points of the arc in the plane's two axes that lie beyond its end points."""
        st = self.state
        plane = {17: (0, 1, "I", "J"), 18: (2, 0, "K", "I"), 19: (1, 2, "J", "K")}[st.plane]
        a, b, ca, cb = plane
        if max(a, b) >= len(self.axes):
            return None
        sa, sb = start[a], start[b]
        ea, eb = st.pos[a], st.pos[b]
        if sa is None or sb is None or ea is None or eb is None:
            return None
        tok = next((t for t in axes if self.names.get(t.name) in (a, b)), axes[0])
        cw = st.motion == 2
        if "R" in centre:
            r = centre["R"].value
            if r is None or r == 0:
                return None
            dx, dy = ea - sa, eb - sb
            d = math.hypot(dx, dy)
            if d == 0 or d > 2 * abs(r) + 1e-9:
                return None
            h = math.sqrt(max(r * r - d * d / 4, 0.0))
            sign = 1.0 if (cw == (r > 0)) else -1.0
            mx, my = (sa + ea) / 2, (sb + eb) / 2
            px, py = dy / d, -dx / d
            ma, mb = mx + sign * h * px, my + sign * h * py
        else:
            ia, ib = centre.get(ca), centre.get(cb)
            if (ia is not None and ia.value is None) or (ib is not None and ib.value is None):
                return None
            va = ia.value if ia is not None and ia.value is not None else 0.0
            vb = ib.value if ib is not None and ib.value is not None else 0.0
            scale = INCH if st.inch else 1.0
            ma = va * scale if st.centre_abs else sa + va * scale
            mb = vb * scale if st.centre_abs else sb + vb * scale
        radius = math.hypot(sa - ma, sb - mb)
        if radius == 0:
            return None
        a0 = math.atan2(sb - mb, sa - ma)
        a1 = math.atan2(eb - mb, ea - ma)
        sweep = (a0 - a1) % (2 * math.pi) if cw else (a1 - a0) % (2 * math.pi)
        if sweep < 1e-12:
            sweep = 2 * math.pi  # end = start: a full circle
        out: list[tuple[int, float, _Tok]] = []
        for k, (axis, value) in enumerate(((a, ma + radius), (b, mb + radius), (a, ma - radius), (b, mb - radius))):
            angle = k * math.pi / 2
            delta = (a0 - angle) % (2 * math.pi) if cw else (angle - a0) % (2 * math.pi)
            if 0 < delta < sweep:
                out.append((axis, value, tok))
        return out

    def _programmed_limits(self, axes: list[_Tok], positive: bool) -> None:
        st = self.state
        for t in axes:
            i = self.names.get(t.name)
            if i is None or self.setup is None:
                continue
            ax = self.axes[i]
            if t.value is None or st.absolute is None:
                continue
            base = ax.pos if positive else ax.neg
            new = t.value if st.absolute else base + t.value
            neg, pos = st.limits[i]
            if positive:
                if new <= ax.neg or (self.setup.range_check and new > ax.pos):
                    continue  # not taken over (N003/N004)
                st.limits[i] = (neg, new)
            else:
                if new >= ax.pos or (self.setup.range_check and new < ax.neg):
                    continue
                st.limits[i] = (new, pos)
            src = f"G{99 if positive else 98} at line {t.line}"
            old = st.limit_from[i]
            st.limit_from[i] = (old[0], src) if positive else (src, old[1])

    def _pos_limit(self, t: _Tok) -> None:
        st = self.state
        i = self.names.get(t.name)
        if i is None:
            return
        ax = self.axes[i]
        inner = t.text
        src = f"POS_LIMIT at line {t.line}"
        if re.search(r"\bOFF\b", inner):
            st.unmonitored[i] = f"{t.name}[POS_LIMIT OFF] at line {t.line}"
            return
        if re.search(r"\bDEFAULT\b", inner):
            st.limits[i] = (ax.neg, ax.pos)
            st.limit_from[i] = ("", "")
            st.unmonitored[i] = ""
            return
        st.unmonitored[i] = ""
        neg, pos = st.limits[i]
        frm = list(st.limit_from[i])
        for key, value in re.findall(r"\b(MIN|MAX)\s*=\s*([^\s\]]+)", inner):
            v = evaluate(value, st.variables)
            if v is None:
                neg, pos = -math.inf, math.inf  # computed limits: nothing beyond them is known
                frm = [src, src]
                continue
            if key == "MIN":
                neg, frm[0] = v, src
            else:
                pos, frm[1] = v, src
        st.limits[i] = (neg, pos)
        st.limit_from[i] = (frm[0], frm[1])

    def _hash(self, t: _Tok) -> None:
        word, rest = t.name, t.text.strip()
        if word in lang.TRANSFORMS:
            off = rest.startswith("OFF")
            if off:
                self._transform = None
            elif word in ("CS", "ACS") and not rest.startswith(("ON", "DEF ACT", "SELECT")):
                return  # #CS DEF / ADD / DEL only define a coordinate system
            elif word == "TRAFO" and not rest.startswith("ON") and rest:
                return
            else:
                self._transform = (f"{word} {rest.split()[0]}" if rest.split() else word, t.line)
            return
        if word == "MCS":
            if rest.startswith("ON"):
                self._transform = ("MCS ON", t.line)
            elif rest.startswith("OFF"):
                self._transform = None
            return
        if word == "MACHINE":  # #MACHINE DATA reloads the axis list: programmed limits are gone
            st = self.state
            for i, ax in enumerate(self.axes):
                st.limits[i] = (ax.neg, ax.pos)
                st.limit_from[i] = ("", "")
            for name, text in self.machine_data.get(t.line, []):
                j = self.names.get(name.upper())
                m = _AXPARAM_SWE.match(text.upper())
                if j is None or m is None:
                    continue
                i = j
                v = int(m.group(2)) / LENGTH_UNIT
                neg, pos = st.limits[i]
                st.limits[i] = (v, pos) if m.group(1) == "NEG" else (neg, v)
                src = f"#MACHINE DATA at line {t.line}"
                frm = st.limit_from[i]
                st.limit_from[i] = (src, frm[1]) if m.group(1) == "NEG" else (frm[0], src)

    def _called(self, t: _Tok) -> None:
        name = self.lines[t.line - 1][t.start:t.end] if t.end > t.start else ""
        local, cycle = t.text.endswith("L"), t.text.startswith("cycle")
        call = Call(t.line, t.start, t.end, name, local, cycle)
        self.result.calls.append(call)
        shown = f"{'LL' if local else 'L'} {'CYCLE ' if cycle else ''}{name}".rstrip()
        if self.depth == 0 and self.section and self.section.upper() in self.called_locals:
            return  # this part is followed where it is called
        if not cycle and name and self.depth < MAX_DEPTH and self._follow(call, shown):
            return
        self.result.not_followed.append(call)
        self.state.forget(f"after {shown} at line {t.line}")

    def _follow(self, call: Call, shown: str) -> bool:
        """Follow a called subprogram from the caller's state; its findings land on the call."""
        if call.local:
            span = self.sections.get(call.name.upper())
            if span is None:
                return False
            sub = Follower(self.lines, self.setup, self.machine_data, self.resolve, self.depth + 1, self.state.copy())
            sub.sections, sub.targets, sub.called_locals = self.sections, self.targets, self.called_locals
            sub.loop_facts = self.loop_facts
            sub.section = call.name
            start, end = span
        else:
            lines = self.resolve(call.name) if self.resolve is not None else None
            if lines is None:
                return False
            sub = Follower(lines, self.setup, None, self.resolve, self.depth + 1, self.state.copy())
            start, end = 0, len(lines)
        cost = max(end - start, 50)  # a call costs its lines, and at least what reading a block costs fifty times
        if self.budget[0] < cost:
            return False  # the program's calls have followed enough lines: the rest are counted
        self.budget[0] -= cost
        sub.budget = self.budget
        sub._transform = self._transform
        found = sub.run(start, end)
        res = self.result
        res.moves += found.moves
        res.evaluated += found.evaluated
        where = f"in {shown}"
        for reason, (count, _) in found.skipped.items():
            key = reason if reason.startswith("in L") else f"{where}: {reason}"
            res.skip(key, call.line)
            res.skipped[key][0] += count - 1
        for c in found.crossings:
            via = f"{where} line {c.line}" + (f", {c.via}" if c.via else "")
            res.crossings.append(Crossing(call.line, call.start, call.end, c.axis, c.programmed, c.machine, c.limit,
                                          c.positive, c.group, c.offset, c.limit_from, c.unmonitored, c.arc, via))
        for i, (low, high) in found.travel.items():
            travel = res.travel.setdefault(i, [low, high])
            travel[0], travel[1] = min(travel[0], low), max(travel[1], high)
        res.unfollowed.extend((f"{what} {where}", call.line) for what, _ in found.unfollowed)
        res.not_followed.extend(Call(call.line, call.start, call.end, c.name, c.local, c.cycle)
                                for c in found.not_followed)
        res.followed.append(call)
        self.state = sub.state
        self._transform = sub._transform
        return True

    # ------------------------------------------------------------------ control structures

    def _control(self, t: _Tok) -> None:
        key = t.name
        st = self.state
        if key == "GOTO":
            return
        if key == "IF" and "$GOTO" in t.text:
            return  # $IF <condition> $GOTO <target>: one block, no $ENDIF
        if key in ("BREAK", "CONTINUE"):
            return
        if key in lang.OPENERS:
            frame = _Frame(key, t.line, t.start, t.end, st.copy())
            frame.started = key != "SWITCH"
            self.stack.append(frame)
            if key in lang.LOOPS:
                self._enter_loop(frame)
                frame.entry = self.state.copy()
            return
        if key in lang.BRANCHES:
            opener = lang.BRANCHES[key]
            if not self.stack or self.stack[-1].key != opener:
                self.result.structure.append((t.line, t.start, t.end,
                                              f"${key} without an open ${opener}"))
                return
            frame = self.stack[-1]
            if not frame.started:  # the first $CASE: nothing before it in the $SWITCH runs
                frame.started = True
                if frame.entry is not None:
                    self.state = frame.entry.copy()
                return
            frame.branches.append(st.copy())
            if key in ("ELSE", "DEFAULT"):
                frame.has_default = True
            assert frame.entry is not None
            self.state = frame.entry.copy()
            return
        if key in lang.CLOSERS:
            opener = lang.CLOSERS[key]
            if not self.stack or self.stack[-1].key != opener:
                self.result.structure.append((t.line, t.start, t.end, f"${key} without an open ${opener}"))
                return
            frame = self.stack.pop()
            assert frame.entry is not None
            why = f"after the ${opener} from line {frame.line} (the path depends on data)"
            ends = [*frame.branches, st]
            if not frame.has_default:
                ends.append(frame.entry)
            joined = ends[0].copy()
            joined.join(ends[1:], why)
            self.state = joined
            return

    def _enter_loop(self, frame: _Frame) -> None:
        """At a loop's head, what the loop body changes is unknown (it differs per iteration):
        the variables it assigns, the positions of the axes it moves, its dimensions and offset."""
        st = self.state
        why = f"inside the ${frame.key} loop from line {frame.line}"
        facts = self.loop_facts.get(frame.line)
        if facts is None:  # not indexed (cannot happen for a file's own loops): nothing is known
            st.forget(why)
            return
        for name in facts.variables:
            st.variables.pop(name, None)
        for i in facts.axes:
            st.pos[i] = None
            st.pos_why[i] = why
        if facts.dims:
            st.absolute = None
            st.why = why
        if facts.offset:
            st.group = None
            st.why = why


def _upper(text: str) -> str:
    """Upper case with the columns kept (``ß`` stays one character)."""
    return "".join(c if len(u := c.upper()) != 1 else u for c in text)


def _skip_eq(text: str, at: int) -> int:
    n = len(text)
    while at < n and text[at] in " \t":
        at += 1
    if at < n and text[at] == "=" and not text.startswith("==", at):
        at += 1
        while at < n and text[at] in " \t":
            at += 1
    return at


def _number(raw: str) -> float | None:
    m = _NUMBER.fullmatch(raw)
    return float(raw) if m is not None else None


def find_subprogram(name: str, dirs: Sequence[str]) -> str | None:
    """The file ``name`` (or ``name.nc``) in one of ``dirs``, names compared without case as the
    controller's file system does; an absolute name is looked up as it is. None: not found."""
    import os  # start-up: only programs with calls

    name = name.strip('"').replace("\\", "/")
    candidates = (name, name + PROGRAM_SUFFIX) if "." not in os.path.basename(name) else (name,)
    for folder in dirs:
        for cand in candidates:
            path = cand if os.path.isabs(cand) else os.path.join(folder, cand)
            if os.path.isfile(path):
                return path
            parent, base = os.path.split(path)
            try:
                for entry in os.listdir(parent or "."):
                    if entry.lower() == base.lower() and os.path.isfile(os.path.join(parent, entry)):
                        return os.path.join(parent, entry)
            except OSError:
                continue
    return None


def follow(lines: Sequence[str], setup: Setup | None,
           machine_data: dict[int, list[tuple[str, str]]] | None = None,
           resolve: Callable[[str], Sequence[str] | None] | None = None) -> Analysis:
    """Read the program's lines: its words, structures, calls, and (against ``setup``) its moves;
    ``resolve`` gives the lines of a called global subprogram (None: not found)."""
    return Follower(lines, setup, machine_data, resolve).run()


__all__ = ["Analysis", "AxisSetup", "Call", "Crossing", "Follower", "Setup", "Word", "evaluate", "find_subprogram",
           "follow"]

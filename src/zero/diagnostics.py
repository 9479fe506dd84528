"""Findings: severity, location, message and an optional fix.

This module imports nothing else from zero, so every other module can use it.
Lines and columns are 1-based; ``end_column`` is exclusive (one past the last
character), so a span of width zero marks a position between two characters.
"""

from __future__ import annotations

from zero.records import Record, field

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from collections.abc import Iterator
    from typing import ClassVar


class _SeverityType(type):
    """The class of :class:`Severity`, for what enum's class gives: ``Severity[name]`` (:class:`KeyError`
    otherwise), iteration in value order, ``len``, ``member in Severity`` and members that cannot be
    reassigned."""

    def __getitem__(cls, name: str) -> Severity:
        return _BY_NAME[name]

    def __iter__(cls) -> Iterator[Severity]:
        return iter(_MEMBERS)

    def __reversed__(cls) -> Iterator[Severity]:
        return reversed(_MEMBERS)

    def __len__(cls) -> int:
        return len(_MEMBERS)

    def __contains__(cls, member: object) -> bool:
        if isinstance(member, Severity):
            return True
        # as enum on Python 3.11: only a member can be asked about
        raise TypeError(f"unsupported operand type(s) for 'in': {type(member).__qualname__!r} and 'EnumType'")

    def __setattr__(cls, name: str, value: object) -> None:
        if name in _BY_NAME:
            raise AttributeError(f"cannot reassign member {name!r}")
        super().__setattr__(name, value)

    def __delattr__(cls, name: str) -> None:
        if name in _BY_NAME:
            raise AttributeError(f"cannot delete member {name!r}")
        super().__delattr__(name)


class Severity(int, metaclass=_SeverityType):
    """How bad a finding is. Ordered so that ``max()`` gives the worst.

    An :class:`int` (1, 2, 3: compared, hashed and written to JSON as one) that behaves as the member of
    an ``enum.IntEnum`` it was: ``name``, ``value``, its ``repr`` (``<Severity.ERROR: 3>``), ``str`` and
    ``format`` (the number), ``Severity[name]``, ``Severity(value)``, iteration in value order, pickled and
    copied as itself, immutable. Without enum: importing it was a twentieth of a list's lint (issue 40,
    start-up)."""

    INFO: ClassVar[Severity]
    WARNING: ClassVar[Severity]
    ERROR: ClassVar[Severity]
    if TYPE_CHECKING:  # read-only, as enum's (each member holds them in its own dictionary, set once)
        @property
        def name(self) -> str: ...

        @property
        def value(self) -> int: ...

        @property
        def label(self) -> str: ...  # the name in lower case: a report writes one per finding

    def __new__(cls, value: int) -> Severity:
        """The member of value ``value`` (a member gives itself); :class:`ValueError` for another value."""
        try:
            return _BY_VALUE[value]
        except (KeyError, TypeError):  # TypeError: an unhashable value
            raise ValueError(f"{value!r} is not a valid {cls.__qualname__}") from None

    @classmethod
    def parse(cls, text: str) -> Severity:
        member = _BY_NAME.get(text.strip().upper())
        if member is None:
            raise ValueError(f"unknown severity {text!r} (use error, warning or info)")
        return member

    def __repr__(self) -> str:
        return f"<{type(self).__name__}.{self.name}: {int.__repr__(self)}>"

    __str__ = int.__repr__  # as IntEnum's: the number, also for format() and f-strings
    __format__ = int.__format__

    def __reduce_ex__(self, protocol: object) -> tuple[type[Severity], tuple[int]]:
        return type(self), (self.value,)  # as enum's: Severity(3) when unpickled, the member itself

    def __copy__(self) -> Severity:
        return self

    def __deepcopy__(self, memo: object) -> Severity:
        return self

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"cannot change {self!r}")

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"cannot change {self!r}")


def _member(name: str, value: int) -> Severity:
    member = int.__new__(Severity, value)
    vars(member).update(name=name, value=value, label=name.lower())
    type.__setattr__(Severity, name, member)
    return member


_MEMBERS = (_member("INFO", 1), _member("WARNING", 2), _member("ERROR", 3))  # in value order
_BY_NAME = {m.name: m for m in _MEMBERS}
_BY_VALUE: dict[object, Severity] = {m.value: m for m in _MEMBERS}


class Span(Record, frozen=True):
    """A region of a file: 1-based line and column, end column exclusive."""

    line: int
    column: int
    end_line: int
    end_column: int

    @classmethod
    def on_line(cls, line: int, start: int, end: int) -> Span:
        """A span on one line from 0-based character offsets ``start``..``end``."""
        return cls(line, start + 1, line, max(end, start) + 1)


class Edit(Record, frozen=True):
    """Replace the text of ``span`` with ``replacement``."""

    span: Span
    replacement: str


class Fix(Record, frozen=True):
    """A change that resolves a finding. ``safe`` fixes keep what the controller reads."""

    title: str
    edits: tuple[Edit, ...] = ()
    safe: bool = True

    def to_json(self) -> dict[str, object]:
        return {
            "title": self.title,
            "safe": self.safe,
            "edits": [
                {
                    "line": e.span.line,
                    "column": e.span.column,
                    "end_line": e.span.end_line,
                    "end_column": e.span.end_column,
                    "replacement": e.replacement,
                }
                for e in self.edits
            ],
        }


class Related(Record, frozen=True):
    """Another place a finding is about, e.g. the earlier entry a duplicate overwrites; ``path``
    ``None`` is the finding's own file."""

    span: Span
    message: str
    path: str | None = None


class Diagnostic(Record, frozen=True):
    """One finding. ``hint`` is a one-line suggestion shown under the source line."""

    code: str
    severity: Severity
    message: str
    span: Span
    path: str = "-"
    param_id: str | None = None
    fix: Fix | None = None
    hint: str | None = field(default=None, compare=False)
    related: tuple[Related, ...] = field(default=(), compare=False)
    kernel_error: str | None = None  # the number the kernel reports for it at start-up: P-ERR-110421
    # what the controller does (zero.catalog.evidence: ignored, limited, zeroed, undocumented, ...) and
    # the document that says so (a page's address, or why there is none)
    consequence: str | None = field(default=None, compare=False)
    source: str | None = field(default=None, compare=False)

    def sort_key(self) -> tuple[str, int, int, str]:
        return (self.path, self.span.line, self.span.column, self.code)

    def to_json(self) -> dict[str, object]:
        """The JSON contract of ``--output-format json``: exactly these keys."""
        return {
            "path": self.path,
            "line": self.span.line,
            "column": self.span.column,
            "end_line": self.span.end_line,
            "end_column": self.span.end_column,
            "code": self.code,
            "severity": self.severity.label,
            "message": self.message,
            "param_id": self.param_id,
            "kernel_error": self.kernel_error,
            "consequence": self.consequence,
            "source": self.source,
            "fix": self.fix.to_json() if self.fix is not None else None,
        }

"""What a lint gives, without what makes it: the options of one file's lint, its result, and the
totals a report counts as the results pass.

Kept apart from :mod:`zero.engine.lint` (which imports the rules, the tokenizer and the catalogue)
so that a run whose every result comes from the cache (:mod:`zero.engine.cache`), the command line
and the output formats load none of those. :mod:`zero.engine.lint` exports the same names.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from zero.diagnostics import Diagnostic, Severity
from zero.records import Record, field

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from zero.lists.model import Document


class LintOptions(Record):
    select: tuple[str, ...] = ()  # code prefixes; empty = all
    ignore: tuple[str, ...] = ()
    kind: str | None = None  # force the list kind
    severity: dict[str, Severity] = field(default_factory=dict)  # per-code overrides
    extend_select: tuple[str, ...] = ()  # codes or prefixes added to the selection
    encoding: str | None = None  # the codec the configuration declares for the list; None: detected
    kernel: str | None = None  # the kernel release the machine runs (`kernel` in [tool.zero]); None: not said
    ignore_noqa: bool = False  # report what `noqa` and the other suppression directives hide (--ignore-noqa)


class LintResult(Record):
    path: str
    document: Document
    kind: str | None
    diagnostics: list[Diagnostic] = field(default_factory=list)
    note: str | None = None  # why the file was skipped, unchecked (not a list form): said, not a finding

    @property
    def worst(self) -> Severity | None:
        return max((d.severity for d in self.diagnostics), default=None)


UNREADABLE = "F001"  # the code of a file zero could not read


def is_unreadable(result: LintResult) -> bool:
    return any(d.code == UNREADABLE for d in result.diagnostics)


class Totals(Record):
    """What a report says at its end (the summary line, ``--statistics``, the exit code), counted
    as the results pass: a report of many files need not keep them to say it."""

    files: int = 0
    clean: int = 0
    unreadable: int = 0
    by_severity: dict[Severity, int] = field(default_factory=dict)
    by_code: dict[str, int] = field(default_factory=dict)
    worst: Severity | None = None

    def add(self, result: LintResult) -> None:
        if result.note is not None and not result.diagnostics:  # skipped: neither checked nor clean
            return
        self.files += 1
        if not result.diagnostics:
            self.clean += 1
            return
        by_severity, by_code = self.by_severity, self.by_code
        unreadable = False
        for d in result.diagnostics:
            severity, code = d.severity, d.code
            by_severity[severity] = by_severity.get(severity, 0) + 1
            by_code[code] = by_code.get(code, 0) + 1
            if code == UNREADABLE:  # is_unreadable, in the same pass
                unreadable = True
        self.worst = max(by_severity)  # the worst of every finding counted so far
        if unreadable:
            self.unreadable += 1


def tallied(results: Iterable[LintResult], totals: Totals) -> Iterator[LintResult]:
    """``results``, each added to ``totals`` as it passes."""
    for r in results:
        totals.add(r)
        yield r


__all__ = ["LintOptions", "LintResult", "Totals", "is_unreadable", "tallied"]

"""``--output-format github``: GitHub Actions workflow commands (annotations)."""

from __future__ import annotations

from collections.abc import Iterable

from zero.diagnostics import Severity
from zero.engine.results import LintResult
from zero.output.formats.common import each, repo_path

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def _gh_escape(text: str, prop: bool = False) -> str:
    text = text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")
    return text.replace(":", "%3A").replace(",", "%2C") if prop else text


def render_github(results: Iterable[LintResult], stream: TextIO) -> None:
    """GitHub Actions workflow commands: an annotation per finding."""
    level = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}
    for d in each(results):
        props = (f"file={_gh_escape(repo_path(d.path), True)},line={d.span.line},col={d.span.column},"
                 f"endLine={d.span.end_line},endColumn={d.span.end_column},"
                 f"title={_gh_escape(f'zero {d.code}', True)}")
        stream.write(f"::{level[d.severity]} {props}::{_gh_escape(f'{d.code} {d.message}')}\n")

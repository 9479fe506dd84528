"""``--output-format azure``: Azure Pipelines logging commands."""

from __future__ import annotations

from collections.abc import Iterable

from zero.diagnostics import Severity
from zero.engine.results import LintResult
from zero.output.formats.common import each, repo_path

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def _azure_data(text: str) -> str:
    """A logging command's message: the agent reads ``%AZP25`` as ``%``, ``%0D``/``%0A`` as line ends."""
    return text.replace("%", "%AZP25").replace("\r", "%0D").replace("\n", "%0A")


def _azure_property(text: str) -> str:
    """A logging command's property value: as its message, and ``;`` and ``]`` end a property."""
    return _azure_data(text).replace(";", "%3B").replace("]", "%5D")


def render_azure(results: Iterable[LintResult], stream: TextIO) -> None:
    """Azure Pipelines logging commands: ``##vso[task.logissue type=error;sourcepath=…;linenumber=…;
    columnnumber=…;code=…;]message``, one per finding (an information finding is a warning: the
    command knows only errors and warnings)."""
    for d in each(results):
        kind = "error" if d.severity == Severity.ERROR else "warning"
        props = (f"type={kind};sourcepath={_azure_property(repo_path(d.path))};linenumber={d.span.line};"
                 f"columnnumber={d.span.column};code={_azure_property(d.code)};")
        stream.write(f"##vso[task.logissue {props}]{_azure_data(f'{d.code} {d.message}')}\n")

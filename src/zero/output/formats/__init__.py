"""The report formats of ``zero lint``, each declared once: its name, the module that writes it, what
it is, and how it is written. One module per format (``json.py``, ``sarif.py``, ``junit.py`` …, as
ruff's ``message/`` holds one emitter per format); what they share is in ``common.py``.

The command line's choices (``--output-format``), its help, the lint page of the docs (made from
the help) and the report path (``zero.cli.run.render_lint``) all read :data:`FORMATS`. This module
imports no emitter: ``zero lint`` with the text report loads none of them, and an emitter is
imported by its name only when it is asked for (:func:`emitter`).
"""

from __future__ import annotations

import os
from collections.abc import Callable

from zero.records import Record

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import Any

# Where a rule's text is on the web, ``{code}`` replaced by its code: each SARIF rule's
# ``helpUri``. zero has no public home yet, so there is none by default (SARIF makes it
# optional; the rule's text is in the log itself, ``help``); whoever publishes the rule texts
# sets it here, or passes ``rule_docs`` to :func:`render_sarif`.
RULE_DOCS_URL: str | None = None


DOCS_URL_VARIABLE = "ZERO_DOCS_URL"  # the documentation site's address (`https://…`): rule pages below it


def rule_docs_template() -> str | None:
    """Where each rule's page is (``{code}`` for its code): :data:`RULE_DOCS_URL` where set, else
    below the documentation site ``$ZERO_DOCS_URL`` names (``<site>/rules/R006/``, the page the
    site's generator writes); ``None`` where zero knows no address (the rule's text then travels
    in the report itself)."""
    if RULE_DOCS_URL:
        return RULE_DOCS_URL
    site = os.environ.get(DOCS_URL_VARIABLE, "").strip()
    return f"{site.rstrip('/')}/rules/{{code}}/" if site.startswith(("https://", "http://")) else None


# The tool's home page (SARIF ``informationUri``); none by default, for the same reason: the
# documentation site's address ($ZERO_DOCS_URL) where it is set.
PROJECT_URL: str | None = None


def information_uri() -> str | None:
    """SARIF ``tool.driver.informationUri``: :data:`PROJECT_URL`, else the documentation site."""
    if PROJECT_URL:
        return PROJECT_URL
    site = os.environ.get(DOCS_URL_VARIABLE, "").strip()
    return site.rstrip("/") + "/" if site.startswith(("https://", "http://")) else None


class Format(Record, frozen=True):
    name: str  # as --output-format takes it
    module: str | None  # the module of zero.output.formats that writes it (None: zero.output.text, the report)
    function: str  # its emitter there: function(results, stream)
    note: str  # what it is, in the help's few words ("" for a name that says it)
    streamed: bool = True  # written finding by finding as the results come (else it needs them all)
    fail_on: bool = False  # the emitter takes the severity from which a finding fails the run (JUnit)
    json_statistics: bool = False  # --statistics in this format is a JSON array (else the text table)
    aliases: tuple[str, ...] = ()  # other names --output-format takes for it


_DECLARED = (
    Format("text", None, "render_text", "for people, with the source lines", aliases=("full",)),  # full: ruff's
    Format("concise", "concise", "render_concise", "one line each"),
    Format("grouped", "grouped", "render_grouped", "by file"),
    Format("json", "json", "render_json", "a stable contract", json_statistics=True),
    Format("json-lines", "json_lines", "render_json_lines", "", json_statistics=True),
    Format("github", "github", "render_github", ""),
    Format("gitlab", "gitlab", "render_gitlab", "", streamed=False),
    Format("azure", "azure", "render_azure", ""),
    Format("junit", "junit", "render_junit", "", streamed=False, fail_on=True),
    Format("sarif", "sarif", "render_sarif", "", streamed=False),
    Format("rdjson", "rdjson", "render_rdjson", "reviewdog", streamed=False),
    Format("pylint", "pylint", "render_pylint", ""),
)
FORMATS: dict[str, Format] = {name: f for f in _DECLARED for name in (f.name, *f.aliases)}
OUTPUT_FORMATS = tuple(FORMATS)
STREAMED_FORMATS = tuple(name for name, f in FORMATS.items() if f.streamed)
FOR_PEOPLE = tuple(name for name, f in FORMATS.items() if f.module is None)  # the text report


def help_text() -> str:
    """``--output-format``'s help: every format, with its note."""
    names = [" or ".join((f.name, *f.aliases)) + (f" ({f.note})" if f.note else "") for f in _DECLARED]
    return ", ".join(names[:-1]) + " or " + names[-1] + "."


def emitter(name: str) -> Callable[..., None]:
    """The function that writes format ``name`` (a machine-readable one), its module imported now."""
    import importlib  # start-up: an emitter is imported by its name, only when it is asked for

    f = FORMATS[name]
    if f.module is None:
        raise KeyError(f"{name} is the text report (zero.output.text.render_text)")
    function: Callable[..., None] = getattr(importlib.import_module(f"{__name__}.{f.module}"), f.function)
    return function


_MODULES = ("common", *(f.module for f in _DECLARED if f.module is not None))


def __getattr__(name: str) -> Any:
    """``RENDERERS`` and ``STREAMED`` (name → emitter), and every name of the format modules
    (``render_sarif``, ``rule_docs_template`` …) from here too, each module imported when asked."""
    import importlib  # start-up: as in emitter()

    if name in ("RENDERERS", "STREAMED"):
        return {n: emitter(n) for n, f in FORMATS.items()
                if f.module is not None and (f.streamed or name == "RENDERERS")}
    for module in _MODULES:
        found = getattr(importlib.import_module(f"{__name__}.{module}"), name, _MISSING)
        if found is not _MISSING:
            return found
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


_MISSING = object()

"""The machine-readable answers of ``zero diff``, ``zero show --machine``, ``zero explain``,
``zero limits`` and ``zero schema``: JSON, each built here from what the engine found
(:mod:`zero.engine.queries`), never in the command line. The tables for people are
:mod:`zero.output.tables`.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from zero.diff import Change

if TYPE_CHECKING:
    from zero.engine.queries import EffectiveRun, LimitsRun


def json_text(data: object) -> str:
    """JSON as zero writes it: indented, UTF-8 characters as they are, one newline at the end."""
    return json.dumps(data, indent=2, ensure_ascii=False) + "\n"


def diff_json(changes: Sequence[Change]) -> str:
    """``zero diff --output-format json``: one object per change."""
    return json_text([c.to_json() for c in changes])


def effective_json(run: EffectiveRun) -> str:
    """``zero show --machine`` / ``zero explain --output-format json``: the machine and every scope."""
    return json_text(run.to_json())


def limits_json(run: LimitsRun, profile: str | None = None) -> str:
    """``zero limits --output-format json``: the rows, and with a profile its violations."""
    data: dict[str, object] = {"limits": [r.to_json() for r in run.rows]}
    if profile:
        data["violations"] = [{"what": v.what, "value": v.value, "where": v.where} for v in run.violations]
    return json_text(data)


def schema_json(schema: Mapping[str, object]) -> str:
    """``zero schema``: the JSON Schema of the structured form."""
    return json_text(schema)


__all__ = ["diff_json", "effective_json", "json_text", "limits_json", "schema_json"]

"""JSON-like data as the text of a Python module: zero reads its built-in tables by ``import``, so
that they load from the compiled bytecode (3 ms) instead of being parsed at every start-up
(JSON: 9 ms with the ``json`` import)."""

from __future__ import annotations

import json
from typing import Any

# The annotations of a written module, for type checkers only: importing typing at run time costs a
# lint's start-up more than the table itself (zero.hints).
TYPING_FOR_CHECKERS = ("from __future__ import annotations", "",
                       "TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (zero.hints)",
                       "if TYPE_CHECKING:", "    from typing import Any")


def module_text(doc: str, constants: dict[str, Any], rows_name: str | None = None) -> str:
    """``constants`` as module-level names, in order; ``rows_name`` (a list) one item per line.
    The values go through JSON first, so the module holds exactly what a JSON file held."""
    out = [f'"""{doc}\n\nGenerated: do not edit."""', "", *TYPING_FOR_CHECKERS, ""]
    for name, value in constants.items():
        value = json.loads(json.dumps(value, ensure_ascii=False))
        if name == rows_name:
            out.append(f"{name}: list[dict[str, Any]] = [")
            out.extend(f"    {row!r}," for row in value)
            out.append("]")
        else:
            kind = "dict[str, Any]" if isinstance(value, dict) else \
                "list[dict[str, Any]]" if isinstance(value, list) else type(value).__name__
            out.append(f"{name}: {kind} = {value!r}")
    return "\n".join(out) + "\n"

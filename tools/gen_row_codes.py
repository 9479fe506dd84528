#!/usr/bin/env python3
"""Write the code ``re`` compiles the tokenizer's row patterns to (``zero.lists.tokenizer.row_source``, each
variant) to ``src/zero/lists/row_codes.py``, with the Python and regular expression engine it was compiled by:
a lint reads its first list without parsing and compiling the pattern (issue 40: start-up). Another Python or
engine, or a pattern changed since, compiles the pattern at run time (slower, never wrong); a test fails while
the module is stale.

Usage: python tools/gen_row_codes.py
"""

from __future__ import annotations

import itertools
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "src"))

TARGET = Path(__file__).resolve().parent.parent / "src" / "zero" / "lists" / "row_codes.py"


def render() -> str:
    """The module's text, from the patterns as they are now and this Python's engine."""
    import _sre  # type: ignore[import-not-found]
    from re import _compiler, _parser  # type: ignore[attr-defined]

    from zero.lists.tokenizer import row_source

    lines = []
    for binary, crlf, widths in itertools.product((False, True), repeat=3):
        source = row_source(binary, crlf, widths)
        parsed = _parser.parse(source, 0)
        assert not parsed.state.groupdict  # no named group: the written patterns take an empty groupindex
        code = _compiler._code(parsed, 0)
        numbers = tuple(int(c) for c in code)  # plain ints (the engine's opcodes are named ints)
        lines.append(f"    {source!r}: ({parsed.state.flags}, {numbers!r}, {parsed.state.groups - 1}, "
                     f"{(None,) * parsed.state.groups!r}),")
    built = (*sys.version_info[:2], _sre.MAGIC, _sre.CODESIZE)
    return ('"""The code the regular expression engine compiles the tokenizer\'s row patterns to, by source: (flags,\n'
            "code, groups, index -> group name), written by tools/gen_row_codes.py with the Python (major, minor)\n"
            "and engine (MAGIC, CODESIZE) of BUILT, and read only by that one.\n\n"
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n"
            "from __future__ import annotations\n\n"
            "TYPE_CHECKING = False\n"
            "if TYPE_CHECKING:\n"
            "    from typing import Any\n\n"
            f"BUILT: tuple[int, ...] = {built!r}\n"
            "CODES: dict[Any, tuple[int, tuple[int, ...], int, tuple[None, ...]]] = {\n" + "\n".join(lines) + "\n}\n")


def main() -> None:
    TARGET.write_text(render(), encoding="utf-8")
    print(f"wrote {TARGET}")


if __name__ == "__main__":
    main()

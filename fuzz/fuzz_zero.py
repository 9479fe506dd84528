#!/usr/bin/env python3
"""Coverage-guided fuzzing of zero with atheris (``pip install -e '.[fuzz]'``).

    python fuzz/fuzz_zero.py -runs=1000000 -max_len=4096 -artifact_prefix=fuzz/crashes/ CORPUS_DIR fuzz/seeds

Targets are in ``fuzz/targets.py``. A crash is written to ``fuzz/crashes/``; copy it to
``fixtures/fuzz/NAME.bin`` with the fix, and ``tests/test_fuzz_regressions.py`` replays it.
"""

from __future__ import annotations

import sys

import atheris

with atheris.instrument_imports():
    from targets import one_input


def main() -> None:
    atheris.Setup(sys.argv, one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main()

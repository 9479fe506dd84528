"""The command line: thin, over library functions.

``options`` (the one option table of ``zero lint``), ``lean`` (the console script and its
lean ``zero lint`` path), ``app`` (the typer command line, ``lint`` generated from the
table), ``run`` (command bodies both share), ``exits`` (exit codes and the crash guard).
"""

import gc

# A command builds one object per entry and frees little before it ends: the cycle collector's
# default (a pass every 700 allocations, whole-heap passes as the heap grows) costs a third of
# the time of a big lint and finds nothing, since zero's data holds no reference cycles. The
# console script sets them before it imports zero (its tables and rules ran some twenty passes
# over the growing heap: a tenth of a pre-commit run's imports), every command under its guard.
GC_THRESHOLDS = (100_000, 50, 1000)
# Python's own, read before the console script sets the above: the language server runs for hours, and
# its protocol library and asyncio make reference cycles that only the default passes collect.
PYTHON_GC_THRESHOLDS = gc.get_threshold()

"""The command line: thin, over library functions.

``options`` (the one option table of ``zero lint``), ``lean`` (the console script and its
lean ``zero lint`` path), ``app`` (the typer command line, ``lint`` generated from the
table), ``run`` (command bodies both share), ``exits`` (exit codes and the crash guard).
"""

"""The engine: lint orchestration and everything around it.

``lint`` (what runs over a list, a structured file, a program, a machine), ``parallel``
(many files across processes), ``discovery`` (which files), ``config`` (``[tool.zero]``),
``fixes`` and ``formatting`` (rewriting lists), ``convert`` (the convert command),
``commands`` (lint and format) and ``queries`` (diff, show, limits, explain): every command as
a library function, printing left to the caller.
"""

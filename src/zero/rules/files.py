"""F rules: files zero was asked to check but could not read.

A file in a walked directory (or named on the command line) that cannot be read is one
finding for that file; the other files are still checked and reported, and ``zero lint``
exits 2 so that a CI job notices. The engine reports it; there is no check.
"""

from __future__ import annotations

from zero.rules.base import Context, E, Family

FAMILY: Family[Context] = Family("F", "files", "file")

UNREADABLE_FILE = FAMILY.rule(
    "F001", "unreadable-file", E, "A file zero cannot read",
    """
What it checks: every file zero is to check can be read: it exists, is a regular file (not a
FIFO, device, socket or directory), is readable, is no larger than the size limit (256 MiB, or
`ZERO_MAX_FILE_SIZE`), and is no dangling symbolic link or link loop.

Why it matters on the machine: a list that zero cannot read is a list nobody checked; the
controller may still read it at start-up. zero reports the file, checks all the others, and
exits 2 so that a CI job does not pass silently.

Example: `listen/achsmds2.lis -> ../old/achsmds2.lis` with the target deleted.
Fix: repair or remove the file, or exclude it (`exclude` in `[tool.zero]`).
""")

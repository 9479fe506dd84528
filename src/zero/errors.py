"""The one error type of zero: a message with the place it is about.

Every layer raises :class:`ZeroError` for input it cannot use (a file that cannot be
read, a YAML document that cannot be converted, a bad option or configuration value).
Like tomli's ``TOMLDecodeError`` it carries its location; ``str()`` gives the one line
the user sees (``path:line:column: message``). The command line turns it into exit
code 2 in one place (:mod:`zero.cli.exits`); commands that go on with their other
inputs (``convert``, ``format``) count it as a failed input instead.

This module imports nothing, so every module can raise it.
"""

from __future__ import annotations


class ZeroError(Exception):
    """Input or usage zero cannot work with: one located line for the user."""

    def __init__(self, message: str, path: str = "", line: int | None = None,
                 column: int | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.path = path
        self.line = line
        self.column = column

    def __str__(self) -> str:
        where = self.path
        if self.line is not None:
            where += f":{self.line}"
            if self.column is not None:
                where += f":{self.column}"
        return f"{where}: {self.message}" if where else self.message

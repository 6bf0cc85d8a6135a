"""The two error classes of :mod:`analysis.safe_io`, and what they share."""

from __future__ import annotations

import os

__all__ = ["InputError", "OutputError", "PathLike", "cannot_write"]

PathLike = str | os.PathLike[str]


def _one_line(text: str) -> str:
    return text.replace("\r\n", " ").replace("\n", " ").replace("\r", " ")


class OutputError(ValueError):
    """An output that cannot or must not be written; the message is one line naming the path.

    Attributes
    ----------
    path : str or None
        The output concerned (as the caller gave it).
    """

    def __init__(self, message: str, path: PathLike | None = None) -> None:
        super().__init__(_one_line(message))
        self.path = None if path is None else os.fspath(path)


class InputError(ValueError):
    """An input file that cannot be read or breaks the table rules; one line naming the place.

    Attributes
    ----------
    path : str
        The input file.
    line : int or None
        Physical line number (1-based; blank lines and quoted newlines counted), if known.
    column : str or None
        Column name, if the error is about one cell or one header name.
    """

    def __init__(
        self, message: str, path: PathLike, line: int | None = None, column: str | None = None
    ) -> None:
        where = os.fspath(path)
        if line is not None:
            where += f" line {line}"
        if column is not None:
            where += f" column {column}"
        super().__init__(_one_line(f"{where}: {message}"))
        self.path = os.fspath(path)
        self.line = line
        self.column = column


def cannot_write(path: PathLike, exc: OSError) -> OutputError:
    """``cannot write <path>: <strerror>`` for an OSError of a write."""
    reason = exc.strerror or str(exc) or type(exc).__name__
    return OutputError(f"cannot write {os.fspath(path)}: {reason}", path)

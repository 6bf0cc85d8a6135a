"""Safe file input and output for every layer: nothing lost, nothing half-written, nothing
read that should not be (the floor below the kinematics: every module may use it).

Outputs
-------
:func:`atomic_writer` (and :func:`write_text_atomic`) writes to a temporary file in the output's
own directory, flushes and fsyncs it, gives it the permissions the old file had (or the umask
default for a new file) and renames it over the output with :func:`os.replace`. A reader, or a
crash, sees the old file or the new one, never a prefix of the new one. On any error the
temporary file is removed and the old file is untouched. :func:`write_many_atomic` does the same
for several files that belong together (see there for what POSIX allows it to guarantee).
:func:`check_paths`, called before anything is written, refuses an output that is an input
(symlinks resolved, hard links detected), two outputs that are one file, an output that is a
directory and an output whose directory is missing.

An :class:`OSError` from writing (disk full, ``EFBIG`` over ``RLIMIT_FSIZE``, no permission,
read-only file system) becomes a one-line :class:`OutputError` ``"cannot write X: <strerror>"``.

Inputs
------
:func:`read_table` and its streaming form :func:`iter_table_chunks` read a CSV file strictly with
the :mod:`csv` module: a duplicate header name, a row with more or fewer fields than the header,
an empty or non-numeric or non-finite cell in a numeric column, an unknown column (unless
allowed) and malformed quoting are :class:`InputError` naming the file, the physical line (blank
lines and newlines inside quoted fields counted) and the column.

Both error classes derive from :class:`ValueError`, which ``analysis.app.cli.main`` already turns
into exit status 2 and a one-line message.

:func:`read_bytes` and :func:`read_text` read a whole input (a description, a table, a
program) only if it is a regular file, and at most a size limit, enforced while reading.

The package: ``_write`` (outputs), ``_paths`` (the path checks of both), ``_read`` (CSV
inputs), ``_bounded`` (whole files, bounded), ``_errors`` (both error classes).
"""

from __future__ import annotations

from analysis.safe_io._bounded import read_bytes, read_text
from analysis.safe_io._errors import InputError, OutputError
from analysis.safe_io._paths import check_paths
from analysis.safe_io._read import Records, iter_record_chunks, iter_table_chunks, read_table
from analysis.safe_io._write import (
    atomic_writer,
    output_stream,
    sweep_stale,
    write_many_atomic,
    write_text_atomic,
)

__all__ = [
    "InputError",
    "OutputError",
    "Records",
    "atomic_writer",
    "check_paths",
    "iter_record_chunks",
    "iter_table_chunks",
    "output_stream",
    "read_bytes",
    "read_table",
    "read_text",
    "sweep_stale",
    "write_many_atomic",
    "write_text_atomic",
]

"""Bounded reads of :mod:`analysis.safe_io`: a whole input file (a description, a table,
``--params``, a program) read only if it is a regular file, and at most a size limit, the
limit enforced while reading (a file that grows, a /proc file that reports size 0 and a
device never take more memory than the limit).

The file is opened without blocking (``O_NONBLOCK``: opening a FIFO for reading would wait
for a writer) and without following a final symbolic link into a device by accident: the
opened descriptor itself is examined (:func:`os.fstat`), so a path swapped between a check
and the open cannot slip a FIFO or a device in. Errors are :class:`InputError` (one line,
naming the file and the rule); nothing of a refused file's contents is quoted.
"""

from __future__ import annotations

import os
import stat

from analysis.safe_io._errors import InputError, PathLike

__all__ = ["read_bytes", "read_text"]

_KINDS = ((stat.S_ISDIR, "a directory"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
          (stat.S_ISSOCK, "a socket"))  # fmt: skip


def read_bytes(path: PathLike, limit: int, what: str = "file") -> bytes:
    """The bytes of the regular file ``path``, at most ``limit`` of them.

    Raises
    ------
    InputError
        ``path`` does not exist or cannot be opened (the reason, not its contents), is not a
        regular file (a directory, a device, a FIFO, a socket: named), or holds more than
        ``limit`` bytes (``what`` says what the file is for the message: "arm description").
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        raise InputError(f"cannot read the {what}: {exc.strerror or exc}", path) from None
    try:
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):
            kind = next((w for test, w in _KINDS if test(mode)), "not a regular file")
            raise InputError(f"the {what} is {kind}; only a regular file is read", path)
        chunks, size = [], 0
        while True:
            try:
                chunk = os.read(fd, min(1 << 20, limit + 1 - size))
            except OSError as exc:
                raise InputError(f"cannot read the {what}: {exc.strerror or exc}",
                                 path) from None  # fmt: skip
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
            if size > limit:
                raise InputError(
                    f"the {what} is larger than {limit:,} bytes, the most read from one", path
                )
        return b"".join(chunks)
    finally:
        os.close(fd)


def read_text(path: PathLike, limit: int, what: str = "file", encoding: str = "utf-8") -> str:
    """:func:`read_bytes` decoded (``encoding``; a byte that does not decode is an
    :class:`InputError` naming its offset, never the text around it). A UTF-8 byte-order
    mark is dropped."""
    data = read_bytes(path, limit, what)
    try:
        text = data.decode(encoding)
    except UnicodeDecodeError as exc:
        raise InputError(
            f"the {what} is not {encoding} text (byte {exc.start} does not decode)", path
        ) from None
    return text[1:] if text.startswith("\ufeff") else text

"""Safe file input and output for the command line: nothing lost, nothing half-written.

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
"""

from __future__ import annotations

import codecs
import contextlib
import csv
import errno
import math
import os
import secrets
import shutil
import stat
import tempfile
from collections.abc import Iterable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import IO, Any

import numpy as np
import numpy.typing as npt

__all__ = [
    "InputError",
    "OutputError",
    "atomic_writer",
    "check_paths",
    "iter_table_chunks",
    "read_table",
    "write_many_atomic",
    "write_text_atomic",
]

PathLike = str | os.PathLike[str]

# errno values a write to an already open file can fail with; an OSError with one of these
# raised inside an atomic_writer block is reported as "cannot write <output>".
_WRITE_ERRNOS = frozenset(
    code
    for code in (errno.ENOSPC, errno.EFBIG, errno.EIO, getattr(errno, "EDQUOT", None))
    if code is not None
)
_SHOW = 40  # characters of a cell value quoted in a message


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


# --------------------------------------------------------------------------------------------
# outputs
# --------------------------------------------------------------------------------------------


def _cannot_write(path: PathLike, exc: OSError) -> OutputError:
    reason = exc.strerror or str(exc) or type(exc).__name__
    return OutputError(f"cannot write {os.fspath(path)}: {reason}", path)


def _umask() -> int:
    """The process umask, read without changing it where Linux allows."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    mask = os.umask(0o022)  # elsewhere: set and restore (not thread-safe, but brief)
    os.umask(mask)
    return mask


def _target(path: PathLike, make_parents: bool) -> Path:
    """Where ``path`` really is (a symlink is written through), after the output checks."""
    given = Path(path)
    target = Path(os.path.realpath(given)) if given.is_symlink() else given
    if target.is_dir():
        raise OutputError(f"cannot write {os.fspath(path)}: it is a directory", path)
    parent = target.parent
    if not parent.is_dir():
        if parent.exists():
            raise OutputError(f"cannot write {os.fspath(path)}: {parent} is not a directory", path)
        if not make_parents:
            raise OutputError(
                f"cannot write {os.fspath(path)}: directory {parent} does not exist", path
            )
        try:
            parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise _cannot_write(path, exc) from exc
    return target


def _mode_for(target: Path) -> int:
    """Permission bits for the replacement: the old file's, or the umask default."""
    try:
        return stat.S_IMODE(os.stat(target).st_mode)
    except FileNotFoundError:
        return 0o666 & ~_umask()


def _mkstemp(target: Path, path: PathLike) -> tuple[int, Path]:
    try:
        fd, tmp = tempfile.mkstemp(
            prefix=f".{target.name[:100]}.", suffix=".tmp", dir=target.parent
        )
    except OSError as exc:
        raise _cannot_write(path, exc) from exc
    return fd, Path(tmp)


def _unlink(path: Path | None) -> None:
    if path is not None:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(path)


def _fsync_path(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _fsync_dir(directory: Path) -> None:
    """Make a rename in ``directory`` durable; file systems that cannot are tolerated."""
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


@contextlib.contextmanager
def _staged(
    path: PathLike,
    target: Path,
    mode: str,
    encoding: str | None,
    newline: str | None,
) -> Iterator[tuple[IO[Any], list[Path]]]:
    """Open a temporary file beside ``target``; on a clean exit it is complete and fsynced.

    Yields the open file and a one-element list holding the temporary path (for the caller to
    rename). The temporary file is removed if the block or the finishing steps fail.
    """
    if mode not in ("w", "wt", "wb"):
        raise ValueError(f"mode must be 'w', 'wt' or 'wb', not {mode!r}")
    fd, tmp = _mkstemp(target, path)
    done = False
    try:
        try:
            if "b" in mode:
                fh: IO[Any] = os.fdopen(fd, "wb")
            else:
                fh = os.fdopen(fd, "w", encoding=encoding or "utf-8", newline=newline)
        except BaseException:
            os.close(fd)
            raise
        try:
            try:
                yield fh, [tmp]
            except OSError as exc:
                if exc.errno in _WRITE_ERRNOS and exc.filename is None:
                    raise _cannot_write(path, exc) from exc
                raise
            try:
                if fh.closed:  # the block closed it (some writers do): fsync by name
                    _fsync_path(tmp)
                else:
                    fh.flush()
                    os.fsync(fh.fileno())
                    fh.close()
                os.chmod(tmp, _mode_for(target))
            except OSError as exc:
                raise _cannot_write(path, exc) from exc
            done = True
        finally:
            if not fh.closed:
                with contextlib.suppress(OSError):  # buffered data cannot be written either
                    fh.close()
    finally:
        if not done:
            _unlink(tmp)


@contextlib.contextmanager
def atomic_writer(
    path: PathLike,
    mode: str = "w",
    *,
    encoding: str | None = "utf-8",
    newline: str | None = None,
    make_parents: bool = False,
) -> Iterator[IO[Any]]:
    """Write ``path`` all at once: the old content stays until the new one is complete.

    Parameters
    ----------
    path : str or os.PathLike
        The output file. A symlink is written through (its target is replaced).
    mode : {"w", "wt", "wb"}
        Text or binary.
    encoding : str, optional
        Text encoding (ignored for ``"wb"``), UTF-8 by default.
    newline : str, optional
        As for :func:`open`; pass ``""`` when handing the file to :func:`csv.writer`.
    make_parents : bool, default False
        Create a missing parent directory instead of raising :class:`OutputError`.

    Yields
    ------
    file object
        A temporary file in the output's directory. When the block exits normally it is
        flushed, fsynced, given the old file's permission bits (the umask default for a new
        file) and renamed over ``path`` (:func:`os.replace`); the directory is then fsynced.

    Raises
    ------
    OutputError
        ``path`` is a directory, its directory is missing, or writing fails with an
        :class:`OSError` (``"cannot write X: <strerror>"``). Inside the block, an
        :class:`OSError` that a write to an open file raises (``ENOSPC``, ``EFBIG``,
        ``EDQUOT``, ``EIO``, without a file name) is converted too; any other exception from
        the block propagates unchanged.

    Notes
    -----
    On any exception the temporary file is removed and ``path`` is left exactly as it was.
    The file's owner and group are not carried over (the new file is the writer's), and if
    ``path`` has other hard links they keep the old content.

    Examples
    --------
    >>> with atomic_writer("build/out.csv", newline="", make_parents=True) as fh:  # doctest: +SKIP
    ...     csv.writer(fh).writerows(rows)
    """
    if mode not in ("w", "wt", "wb"):
        raise ValueError(f"mode must be 'w', 'wt' or 'wb', not {mode!r}")
    target = _target(path, make_parents)
    with _staged(path, target, mode, encoding, newline) as (fh, tmp):
        yield fh
    replaced = False
    try:
        os.replace(tmp[0], target)
        replaced = True
    except OSError as exc:
        raise _cannot_write(path, exc) from exc
    finally:
        if not replaced:
            _unlink(tmp[0])
    _fsync_dir(target.parent)


def write_text_atomic(
    path: PathLike,
    text: str,
    *,
    encoding: str = "utf-8",
    newline: str | None = None,
    make_parents: bool = False,
) -> None:
    """Replace ``path`` with ``text`` atomically (see :func:`atomic_writer`).

    Parameters
    ----------
    path : str or os.PathLike
        The output file.
    text : str
        The complete new content.
    encoding : str, default "utf-8"
        Text encoding.
    newline : str, optional
        As for :func:`open`.
    make_parents : bool, default False
        Create a missing parent directory.

    Raises
    ------
    OutputError
        As :func:`atomic_writer`.
    """
    with atomic_writer(
        path, "w", encoding=encoding, newline=newline, make_parents=make_parents
    ) as fh:
        fh.write(text)


def _backup(target: Path) -> Path | None:
    """A hard link (or, where links are impossible, a copy) of ``target``; None if absent."""
    if not target.exists():
        return None
    while True:
        backup = target.with_name(f".{target.name[:100]}.{secrets.token_hex(4)}.bak")
        try:
            os.link(target, backup)
        except FileExistsError:
            continue
        except OSError as exc:
            if exc.errno not in (errno.EPERM, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EXDEV):
                raise
            shutil.copy2(target, backup)
        return backup


def write_many_atomic(
    files: Mapping[PathLike, str | bytes],
    *,
    encoding: str = "utf-8",
    newline: str | None = None,
    make_parents: bool = False,
) -> None:
    """Write several files that belong together: all of them, or (on an error) none.

    Parameters
    ----------
    files : mapping of path to str or bytes
        Each output and its complete new content (bytes are written as they are).
    encoding : str, default "utf-8"
        Encoding of the ``str`` contents.
    newline : str, optional
        As for :func:`open`, for the ``str`` contents.
    make_parents : bool, default False
        Create missing parent directories.

    Raises
    ------
    OutputError
        Two outputs are the same file, an output is a directory or its directory is missing
        (all checked before anything is written), or writing fails.

    Notes
    -----
    What is guaranteed, and what POSIX does not allow:

    1. Every new content is first written to a temporary file beside its output and fsynced.
       Any failure in this phase (disk full, file size limit, permission) removes the
       temporary files and leaves every output untouched.
    2. Each existing output is then hard-linked to a backup beside it (copied where the file
       system has no hard links), and the temporary files are renamed over the outputs one by
       one. A rename rarely fails; if one does (the directory became read-only, an output was
       replaced by a directory, a directory could not grow) the outputs already renamed are
       restored from their backups (or removed if they did not exist) and
       :class:`OutputError` is raised. If even a restore fails the error says so and names the
       backup that still holds the old content.

    So when this function returns, all files are new; when it raises, all files are old. There
    is no atomic rename of several files in POSIX, though: a reader looking during phase 2 can
    see some files new and others old, and a crash (power loss, SIGKILL) in phase 2 can leave
    that mix on disk, with the hidden ``.<name>.*.tmp`` / ``.<name>.*.bak`` files beside the
    outputs showing what happened.
    """
    paths = list(files)
    check_paths(outputs=paths, make_parents=make_parents)
    targets = [_target(path, make_parents) for path in paths]
    staged: list[tuple[PathLike, Path, Path]] = []
    backups: list[Path | None] = []
    try:
        for path, target in zip(paths, targets, strict=True):
            content = files[path]
            mode = "wb" if isinstance(content, bytes) else "w"
            with _staged(path, target, mode, encoding, newline) as (fh, tmp):
                fh.write(content)
            staged.append((path, target, tmp[0]))
        for path, target, _ in staged:
            try:
                backups.append(_backup(target))
            except OSError as exc:
                raise _cannot_write(path, exc) from exc
        for i, (path, target, tmp) in enumerate(staged):
            try:
                os.replace(tmp, target)
            except OSError as exc:
                error = _cannot_write(path, exc)
                failed = _rollback(staged[:i], backups[:i])
                if failed:
                    kept = set(failed.values())
                    backups = [None if b in kept else b for b in backups]  # keep those on disk
                    detail = "; ".join(
                        f"{t} (old content kept in {b})" if b else f"{t} (new; was absent)"
                        for t, b in failed.items()
                    )
                    raise OutputError(
                        f"{error}; {i} of {len(staged)} outputs were already replaced and "
                        f"could not all be restored: {detail}",
                        path,
                    ) from exc
                raise error from exc
        for directory in {target.parent for target in targets}:
            _fsync_dir(directory)
    finally:
        for _, _, tmp in staged:
            _unlink(tmp)
        for backup in backups:
            _unlink(backup)


def _rollback(
    done: Sequence[tuple[PathLike, Path, Path]], backups: Sequence[Path | None]
) -> dict[Path, Path | None]:
    """Put back the outputs already replaced; returns {target: backup} for those that failed."""
    failed: dict[Path, Path | None] = {}
    for (_, target, _), backup in zip(done, backups, strict=True):
        try:
            if backup is None:
                _unlink(target)
            else:
                os.replace(backup, target)
        except OSError:
            failed[target] = backup
    return failed


def _same_file(a: str, b: str) -> str | None:
    """How ``a`` and ``b`` are the same file ("" if literally, else a reason), or None."""
    if os.path.realpath(a) == os.path.realpath(b):
        return "" if os.path.abspath(a) == os.path.abspath(b) else " (through a symlink)"
    try:
        if os.path.samefile(a, b):
            return " (hard link)"
    except OSError:  # one of them does not exist (or cannot be examined)
        pass
    return None


def check_paths(
    inputs: Iterable[PathLike] = (),
    outputs: Iterable[PathLike] = (),
    *,
    make_parents: bool = False,
) -> None:
    """Refuse an output set that would destroy an input or collide with itself.

    Parameters
    ----------
    inputs : iterable of path
        Files the command reads.
    outputs : iterable of path
        Files the command writes.
    make_parents : bool, default False
        Accept an output whose parent directory is missing (it will be created).

    Raises
    ------
    OutputError
        The first of: an output is a directory; an output's parent directory is missing (or
        not a directory); an output is the same file as an input; two outputs are the same
        file. "Same file" resolves symlinks and, where both exist, compares device and inode
        (:func:`os.path.samefile`), so hard links count.
    """
    ins = [os.fspath(p) for p in inputs]
    outs = [os.fspath(p) for p in outputs]
    for out in outs:
        if os.path.isdir(out):
            raise OutputError(f"output {out} is a directory; give a file name", out)
        parent = os.path.dirname(os.path.realpath(out))
        if not os.path.isdir(parent) and not (make_parents and not os.path.exists(parent)):
            what = "is not a directory" if os.path.exists(parent) else "does not exist"
            raise OutputError(f"output {out}: directory {parent} {what}", out)
    for out in outs:
        for inp in ins:
            how = _same_file(out, inp)
            if how is not None:
                raise OutputError(
                    f"output {out} is the same file as input {inp}{how}; writing it would "
                    "destroy the input, choose another output",
                    out,
                )
    for i, first in enumerate(outs):
        for second in outs[i + 1 :]:
            how = _same_file(first, second)
            if how is not None:
                raise OutputError(
                    f"outputs {first} and {second} are the same file{how}; "
                    "give each output its own file",
                    second,
                )


# --------------------------------------------------------------------------------------------
# inputs
# --------------------------------------------------------------------------------------------


def _show(value: str) -> str:
    return repr(value if len(value) <= _SHOW else value[:_SHOW] + "...")


def _open_text(path: PathLike, encoding: str) -> IO[str]:
    """Open for csv: lines end only at \\n (a \\r\\n ending stays), a UTF-8 BOM is dropped."""
    if codecs.lookup(encoding).name == "utf-8":
        encoding = "utf-8-sig"
    try:
        return open(path, encoding=encoding, newline="\n")
    except OSError as exc:
        raise InputError(f"cannot read: {exc.strerror or exc}", path) from exc


def _decode_error(path: PathLike, encoding: str, exc: UnicodeDecodeError) -> InputError:
    """The decoding error with its line: the text layer decodes in blocks, so find the line.

    No line break byte occurs inside a multibyte character of an ASCII-compatible encoding,
    so decoding line by line fails on the same bytes as decoding the whole file.
    """
    with open(path, "rb") as fh:
        for number, raw in enumerate(fh, start=1):
            try:
                raw.decode(encoding)
            except UnicodeDecodeError as line_exc:
                bad = raw[line_exc.start : line_exc.start + 4]
                return InputError(
                    f"not valid {encoding} text (byte(s) {bad!r} at byte {line_exc.start + 1} "
                    "of the line)",
                    path,
                    number,
                )
    return InputError(f"not valid {encoding} text ({exc.reason})", path)


def _first_line(row: list[str], last_line: int) -> int:
    """Physical line a record starts on, from the line it ends on and its embedded newlines."""
    return last_line - sum(field.count("\n") for field in row)


class _Table:
    """Header checks and record reading shared by :func:`read_table` and the chunk iterator."""

    def __init__(
        self,
        path: PathLike,
        required: Sequence[str],
        optional: Sequence[str],
        numeric: Sequence[str],
        allow_extra: bool,
        encoding: str,
        delimiter: str,
    ) -> None:
        for group, names in (("required", required), ("optional", optional)):
            if isinstance(names, str) or len(set(names)) != len(names):
                raise ValueError(f"{group} must be a sequence of distinct column names")
        self.path = path
        self.required = tuple(required)
        self.optional = tuple(optional)
        self.numeric = frozenset(numeric)
        self.allow_extra = allow_extra
        self.encoding = encoding
        self.delimiter = delimiter
        if "\n".encode(codecs.lookup(encoding).name) != b"\n":
            raise ValueError(f"encoding {encoding!r} is not ASCII-compatible; re-encode as UTF-8")
        both = set(self.required) & set(self.optional)
        if both:
            raise ValueError(f"column(s) {', '.join(sorted(both))} both required and optional")
        stray = self.numeric - set(self.required) - set(self.optional)
        if stray:
            raise ValueError(
                f"numeric column(s) {', '.join(sorted(stray))} are neither required nor optional"
            )

    def _expected(self) -> str:
        names = [*self.required, *(f"{n} (optional)" for n in self.optional)]
        return ", ".join(names) if names else "(none)"

    def open(self) -> None:
        """Read and check the header; sets ``names``, ``keep``, ``header_line``."""
        self.file = _open_text(self.path, self.encoding)
        self.reader = csv.reader(self.file, delimiter=self.delimiter, strict=True)
        header = None
        try:
            while header is None:
                previous = self.reader.line_num
                try:
                    row = next(self.reader)
                except StopIteration:
                    raise InputError(
                        f"no header line; expected the columns {self._expected()}", self.path
                    ) from None
                except csv.Error as exc:
                    raise InputError(
                        f"malformed CSV header ({exc})", self.path, previous + 1
                    ) from None
                except UnicodeDecodeError as exc:
                    raise _decode_error(self.path, self.encoding, exc) from None
                if row:
                    header = row
                    self.header_line = previous + 1
                    self.last_line = self.reader.line_num
            self._check_header(header)
        except BaseException:
            self.file.close()
            raise

    def _check_header(self, header: list[str]) -> None:
        names = [name.strip() for name in header]
        where = {}
        for index, name in enumerate(names, start=1):
            if not name:
                raise InputError(
                    f"header field {index} is empty; every column needs a name",
                    self.path,
                    self.header_line,
                )
            if name in where:
                raise InputError(
                    f"column {name!r} appears twice in the header (fields {where[name]} and "
                    f"{index}); rename or remove one",
                    self.path,
                    self.header_line,
                    name,
                )
            where[name] = index
        missing = [n for n in self.required if n not in where]
        if missing:
            raise InputError(
                f"missing required column(s) {', '.join(missing)} (the header has: "
                f"{', '.join(names)})",
                self.path,
                self.header_line,
            )
        known = set(self.required) | set(self.optional)
        unknown = [n for n in names if n not in known]
        if unknown and not self.allow_extra:
            raise InputError(
                f"unknown column(s) {', '.join(unknown)}; expected {self._expected()}",
                self.path,
                self.header_line,
            )
        self.width = len(names)
        self.keep = list(enumerate(names))
        self.names = names

    def chunks(self, chunk_rows: int | None) -> Iterator[tuple[int, dict[str, np.ndarray]]]:
        """Yield (first line, columns) for every ``chunk_rows`` records (all if None)."""
        with self.file:
            yield from self._chunks(chunk_rows)

    def _chunks(self, chunk_rows: int | None) -> Iterator[tuple[int, dict[str, np.ndarray]]]:
        # Cells go straight into per-column lists: keeping the csv row lists alive instead
        # makes the cyclic garbage collector rescan them and halves the throughput.
        reader, width = self.reader, self.width
        columns: list[list[str]] = [[] for _ in range(width)]
        ends: list[int] = []  # physical line each record ends on
        try:
            for row in reader:
                if len(row) != width:
                    if not row:  # blank line
                        self.last_line = reader.line_num
                        continue
                    self._field_count_error(row, reader.line_num)
                for column, cell in zip(columns, row):  # noqa: B905 - lengths checked above
                    column.append(cell)
                ends.append(reader.line_num)
                if len(ends) == chunk_rows:
                    self.last_line = ends[-1]
                    yield self._chunk(columns, ends)
                    columns, ends = [[] for _ in range(width)], []
        except csv.Error as exc:
            start = max(self.last_line, ends[-1] if ends else 0) + 1
            if "unexpected end of data" in str(exc):
                message = f"quoted field not closed before the end of the file ({exc})"
            else:
                message = f"malformed CSV ({exc})"
            raise InputError(message, self.path, start) from None
        except UnicodeDecodeError as exc:
            raise _decode_error(self.path, self.encoding, exc) from None
        if ends:
            yield self._chunk(columns, ends)

    def _field_count_error(self, row: list[str], last: int) -> None:
        first = _first_line(row, last)
        span = f" (the record spans lines {first}-{last})" if last > first else ""
        raise InputError(
            f"{len(row)} field(s) where the header (line {self.header_line}) has "
            f"{self.width} ({', '.join(self.names)}){span}",
            self.path,
            first,
        )

    def _chunk(
        self, columns: list[list[str]], ends: list[int]
    ) -> tuple[int, dict[str, np.ndarray]]:
        out: dict[str, np.ndarray] = {}
        for index, name in self.keep:
            if name in self.numeric:
                out[name] = self._numbers(columns, index, ends, name)
            else:
                out[name] = np.array(columns[index], dtype=str)
        return _first_line([c[0] for c in columns], ends[0]), out

    def empty(self) -> dict[str, np.ndarray]:
        return {
            name: np.empty(0, dtype=np.float64 if name in self.numeric else str)
            for _, name in self.keep
        }

    def _numbers(
        self, columns: list[list[str]], index: int, ends: list[int], name: str
    ) -> np.ndarray:
        cells = columns[index]
        try:
            values = np.fromiter(map(float, cells), dtype=np.float64, count=len(cells))
            good = "_" not in "".join(cells) and bool(np.isfinite(values).all())
        except ValueError:
            good = False
        if good:
            return values
        for i, cell in enumerate(cells):
            problem = _number_problem(cell)
            if problem:
                line = _first_line([c[i] for c in columns], ends[i])
                raise InputError(problem, self.path, line, name)
        raise AssertionError("unreachable: a bad cell was detected but not found")


def _number_problem(cell: str) -> str | None:
    """Why ``cell`` is not a finite number, or None if it is one."""
    text = cell.strip()
    if not text:
        return "empty cell; a number is required"
    try:
        if "_" in text:
            raise ValueError
        value = float(text)
    except ValueError:
        return f"{_show(cell)} is not a number"
    if not math.isfinite(value):
        return f"{_show(cell)} is not a finite number"
    return None


def iter_table_chunks(
    path: PathLike,
    required: Sequence[str] = (),
    optional: Sequence[str] = (),
    numeric: Sequence[str] = (),
    *,
    allow_extra: bool = False,
    chunk_rows: int = 100_000,
    encoding: str = "utf-8",
    delimiter: str = ",",
) -> Iterator[tuple[int, dict[str, np.ndarray]]]:
    """Stream a CSV table in chunks of at most ``chunk_rows`` records, checked as it goes.

    Memory is bounded by one chunk whatever the file size, so a batch job over 10^7 rows can
    solve and write chunk by chunk. The rules are those of :func:`read_table`; an error in a
    later chunk is raised when that chunk is reached (earlier chunks have been yielded).

    Parameters
    ----------
    path : str or os.PathLike
        The CSV file (lines ending in ``\\n`` or ``\\r\\n``; a UTF-8 byte-order mark is
        accepted).
    required, optional, numeric, allow_extra, encoding, delimiter
        As for :func:`read_table`.
    chunk_rows : int, default 100_000
        Records per chunk (the last chunk may be shorter). A file without records yields
        nothing.

    Yields
    ------
    first_line : int
        Physical line number of the chunk's first record.
    columns : dict of str to numpy.ndarray
        One array per column in header order: float64 for numeric columns, str otherwise.

    Raises
    ------
    InputError
        As :func:`read_table` (raised on iteration).
    ValueError
        Bad arguments (raised at the call, before the file is opened).
    """
    if isinstance(chunk_rows, bool) or not isinstance(chunk_rows, int) or chunk_rows < 1:
        raise ValueError(f"chunk_rows must be a positive integer, not {chunk_rows!r}")
    table = _Table(path, required, optional, numeric, allow_extra, encoding, delimiter)

    def generate() -> Iterator[tuple[int, dict[str, np.ndarray]]]:
        table.open()
        yield from table.chunks(chunk_rows)

    return generate()


def read_table(
    path: PathLike,
    required: Sequence[str] = (),
    optional: Sequence[str] = (),
    numeric: Sequence[str] = (),
    *,
    allow_extra: bool = False,
    encoding: str = "utf-8",
    delimiter: str = ",",
) -> dict[str, npt.NDArray[Any]]:
    """Read a whole CSV table strictly.

    Parameters
    ----------
    path : str or os.PathLike
        The CSV file (lines ending in ``\\n`` or ``\\r\\n``; a UTF-8 byte-order mark is
        accepted).
    required : sequence of str
        Columns that must be in the header.
    optional : sequence of str
        Columns that may be in the header.
    numeric : sequence of str
        Required or optional columns whose every cell must be a finite number (surrounding
        spaces allowed; empty cells, ``nan``, ``inf`` and ``1_000`` are not).
    allow_extra : bool, default False
        Accept (and return, as text) header columns that are neither required nor optional.
    encoding : str, default "utf-8"
        An ASCII-compatible encoding.
    delimiter : str, default ","
        Field separator.

    Returns
    -------
    dict of str to numpy.ndarray
        One array per column present, in header order: float64 for numeric columns, str
        otherwise. An optional column missing from the header is absent from the dict.

    Raises
    ------
    InputError
        The file cannot be opened or decoded; it has no header; a header name is empty or
        repeated; a required column is missing; an unknown column is present (without
        ``allow_extra``); a record has more or fewer fields than the header; quoting is
        malformed; a numeric cell is empty, not a number or not finite. The message names the
        file, the physical line (blank lines and newlines inside quoted fields counted) and,
        for a cell or a header name, the column. Blank lines (also a trailing one) are skipped.
    ValueError
        ``required``/``optional``/``numeric`` contradict each other.
    """
    table = _Table(path, required, optional, numeric, allow_extra, encoding, delimiter)
    table.open()
    parts = [columns for _, columns in table.chunks(None)]  # one chunk at most
    return parts[0] if parts else table.empty()

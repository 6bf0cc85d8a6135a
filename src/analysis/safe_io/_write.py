"""Outputs of :mod:`analysis.safe_io`: atomic replacement of one file or several."""

from __future__ import annotations

import contextlib
import errno
import os
import re
import secrets
import shutil
import stat
import sys
import tempfile
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import IO, Any

from analysis.safe_io._errors import OutputError, PathLike, cannot_write
from analysis.safe_io._paths import check_paths, remove_dirs, target_of

__all__ = [
    "atomic_writer",
    "check_paths",
    "output_stream",
    "sweep_stale",
    "write_many_atomic",
    "write_text_atomic",
]

# errno values a write to an already open file can fail with; an OSError with one of these
# raised inside an atomic_writer block is reported as "cannot write <output>".
_WRITE_ERRNOS = frozenset(
    code
    for code in (errno.ENOSPC, errno.EFBIG, errno.EIO, getattr(errno, "EDQUOT", None))
    if code is not None
)


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


def _mode_for(target: Path) -> int:
    """Permission bits for the replacement: the old file's, or the umask default."""
    try:
        return stat.S_IMODE(os.stat(target).st_mode)
    except FileNotFoundError:
        return 0o666 & ~_umask()


def _tmp_prefix(target: Path) -> str:
    return f".{target.name[:100]}."


def _mkstemp(target: Path, path: PathLike) -> tuple[int, Path]:
    """A temporary file beside ``target``, named ``.<name>.<pid>.<random>.tmp``: the writer's
    process id lets a later run tell a file whose writer was killed (:func:`sweep_stale`)."""
    sweep_stale(target)
    try:
        fd, tmp = tempfile.mkstemp(
            prefix=f"{_tmp_prefix(target)}{os.getpid()}.", suffix=".tmp", dir=target.parent
        )
    except OSError as exc:
        raise cannot_write(path, exc) from exc
    return fd, Path(tmp)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # EPERM: it exists, another user's
        return True
    return True


def sweep_stale(target: PathLike) -> list[Path]:
    """Remove the temporary files that writers of ``target`` left when they were killed
    (SIGKILL, power loss: no handler ran): ``.<name>.<pid>.*.tmp`` beside it whose process
    ``pid`` no longer exists. Files of a running writer are kept. Returns those removed.

    A killed writer's file can outlive it only until the next write of the same output;
    SIGTERM, SIGHUP and SIGINT remove it at once (:mod:`analysis.app.cli` turns them into
    exceptions, and :func:`atomic_writer` removes its file on any exception)."""
    target = Path(target)
    pattern = re.compile(re.escape(_tmp_prefix(target)) + r"(\d+)\.[^./]+\.tmp")
    removed = []
    try:
        names = os.listdir(target.parent)
    except OSError:
        return removed
    for name in names:
        match = pattern.fullmatch(name)
        if match and int(match.group(1)) != os.getpid() and not _alive(int(match.group(1))):
            stale = target.parent / name
            with contextlib.suppress(OSError):
                stale.unlink()
                removed.append(stale)
    return removed


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
                    raise cannot_write(path, exc) from exc
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
                raise cannot_write(path, exc) from exc
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
        Create a missing parent directory instead of raising :class:`OutputError` (removed
        again if the write fails).

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
    created: list[Path] = []
    target = target_of(path, make_parents, created)
    replaced = False
    try:
        with _staged(path, target, mode, encoding, newline) as (fh, tmp):
            yield fh
        try:
            os.replace(tmp[0], target)
            replaced = True
        except OSError as exc:
            raise cannot_write(path, exc) from exc
        finally:
            if not replaced:
                _unlink(tmp[0])
    finally:
        if not replaced:
            remove_dirs(created)  # no directory left behind by a failed write
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
    created: list[Path] = []
    targets = []
    try:
        targets = [target_of(path, make_parents, created) for path in paths]
    except BaseException:
        remove_dirs(created)
        raise
    staged: list[tuple[PathLike, Path, Path]] = []
    backups: list[Path | None] = []
    done = False
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
                raise cannot_write(path, exc) from exc
        for i, (path, target, tmp) in enumerate(staged):
            try:
                os.replace(tmp, target)
            except OSError as exc:
                error = cannot_write(path, exc)
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
        done = True
    finally:
        for _, _, tmp in staged:
            _unlink(tmp)
        for backup in backups:
            _unlink(backup)
        if not done:
            remove_dirs(created)


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


@contextlib.contextmanager
def output_stream(
    path: PathLike,
    *,
    encoding: str = "utf-8",
    newline: str | None = None,
    make_parents: bool = False,
) -> Iterator[IO[Any]]:
    """Write ``path`` with :func:`atomic_writer`, or standard output for ``"-"`` (written as
    it goes; not closed).

    Raises :class:`OutputError` as :func:`atomic_writer` does; for ``"-"`` nothing is
    checked."""
    if os.fspath(path) == "-":
        yield sys.stdout
        sys.stdout.flush()
        return
    with atomic_writer(
        path, "w", encoding=encoding, newline=newline, make_parents=make_parents
    ) as fh:
        yield fh

"""Path checks of :mod:`analysis.safe_io`, shared by its outputs and inputs: what a path is
(a regular file, a device, a FIFO, a socket), whether two paths are one file, which
directories a write may create."""

from __future__ import annotations

import contextlib
import os
import stat
from collections.abc import Iterable, Sequence
from pathlib import Path

from analysis.safe_io._errors import OutputError, PathLike, cannot_write

__all__ = ["check_paths", "not_regular", "remove_dirs", "same_file", "target_of"]

_KINDS = (
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISFIFO, "a FIFO (named pipe)"),
    (stat.S_ISSOCK, "a socket"),
)


def not_regular(path: PathLike) -> str | None:
    """What ``path`` is if it exists and is neither a regular file nor a directory (symlinks
    followed: /dev/stdout is a pipe or a terminal), else None."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return None
    for test, what in _KINDS:
        if test(mode):
            return what
    return None


def _refuse_special(path: PathLike) -> None:
    what = not_regular(path)
    if what:
        raise OutputError(
            f"output {os.fspath(path)} is {what}, not a regular file: it would be replaced by "
            "one; write to '-' (standard output) and redirect instead",
            path,
        )


def _make_parents(parent: Path, path: PathLike) -> list[Path]:
    """Create ``parent`` and its missing ancestors; return those created, outermost first."""
    missing = []
    d = parent
    while not d.exists():
        missing.append(d)
        if d.parent == d:
            break
        d = d.parent
    created = []
    try:
        for d in reversed(missing):
            d.mkdir()
            created.append(d)
    except OSError as exc:
        remove_dirs(created)
        raise cannot_write(path, exc) from exc
    return created


def remove_dirs(created: Sequence[Path]) -> None:
    """Remove directories this process created, innermost first, if they are empty."""
    for d in reversed(created):
        with contextlib.suppress(OSError):
            d.rmdir()


def target_of(path: PathLike, make_parents: bool, created: list[Path] | None = None) -> Path:
    """Where ``path`` really is (a symlink is written through), after the output checks.

    Missing parent directories are created with ``make_parents`` (and appended to
    ``created``, so that a failure can remove them again)."""
    given = Path(path)
    target = Path(os.path.realpath(given)) if given.is_symlink() else given
    if target.is_dir():
        raise OutputError(f"cannot write {os.fspath(path)}: it is a directory", path)
    _refuse_special(target)
    parent = target.parent
    if not parent.is_dir():
        if parent.exists():
            raise OutputError(f"cannot write {os.fspath(path)}: {parent} is not a directory", path)
        if not make_parents:
            raise OutputError(
                f"cannot write {os.fspath(path)}: directory {parent} does not exist", path
            )
        made = _make_parents(parent, path)
        if created is not None:
            created.extend(made)
    return target


def same_file(a: str, b: str) -> str | None:
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

    ``"-"`` (standard input or output) is never checked.

    Raises
    ------
    OutputError
        The first of: an output is a directory; an output exists and is not a regular file
        (a device, a FIFO, a socket: replacing it with a file would destroy it, and /dev/null
        with it); an output's parent directory is missing (or
        not a directory); an output is the same file as an input; two outputs are the same
        file. "Same file" resolves symlinks and, where both exist, compares device and inode
        (:func:`os.path.samefile`), so hard links count.
    """
    ins = [os.fspath(p) for p in inputs if os.fspath(p) != "-"]
    outs = [os.fspath(p) for p in outputs if os.fspath(p) != "-"]
    for out in outs:
        if os.path.isdir(out):
            raise OutputError(f"output {out} is a directory; give a file name", out)
        _refuse_special(out)
        parent = os.path.dirname(os.path.realpath(out))
        if not os.path.isdir(parent) and not (make_parents and not os.path.exists(parent)):
            what = "is not a directory" if os.path.exists(parent) else "does not exist"
            raise OutputError(f"output {out}: directory {parent} {what}", out)
    for out in outs:
        for inp in ins:
            how = same_file(out, inp)
            if how is not None:
                raise OutputError(
                    f"output {out} is the same file as input {inp}{how}; writing it would "
                    "destroy the input, choose another output",
                    out,
                )
    for i, first in enumerate(outs):
        for second in outs[i + 1 :]:
            how = same_file(first, second)
            if how is not None:
                raise OutputError(
                    f"outputs {first} and {second} are the same file{how}; "
                    "give each output its own file",
                    second,
                )



"""A number of an arm description read from a table of the paper kept verbatim as CSV
(``L1 = { table = "table3.csv", match = { link = "waist" }, column = "d_mm" }``).

Only what the description may read is read (issue 27 item 3): a table is named by a plain
file name (no folder, no ``..``), looked for next to the description, then in ``data/``; the
file found (symbolic links resolved) must lie in that folder, be a regular file and hold at
most :data:`MAX_TABLE_BYTES` (:func:`analysis.safe_io.read_text`: no FIFO, device or endless
stream is opened for reading); nothing of its contents is quoted in an error but the names of
its columns. A caller (the API, ``--params``) may replace a table by a path of its own
choosing (``tables``): that path is the caller's decision and is read with the same bounds.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

from analysis import validate
from analysis.kinematics.schema import DescriptionError
from analysis.paths import data_dir
from analysis.safe_io import InputError, read_text

__all__ = ["MAX_TABLE_BYTES", "TABLE_NAME", "table_path", "table_value"]

MAX_TABLE_BYTES = 1 << 20
"""Largest table read [bytes] (1 MiB: a paper's table is a few kilobytes)."""
TABLE_NAME = "a plain file name ending in .csv (letters, digits, '.', '-', '_'; no folder)"
_TABLE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.-]*\.csv")


def table_path(name: object, desc_path: Path, file: str, key: str) -> Path:
    """The table ``name`` a description at ``desc_path`` may read: next to it, else in
    ``data/`` (DescriptionError naming the rule broken)."""
    if not isinstance(name, str) or not _TABLE_NAME.fullmatch(name) or ".." in name:
        raise DescriptionError(file, key, f"table {name!r} is not {TABLE_NAME}")
    for folder in (desc_path.resolve().parent, data_dir().resolve()):
        path = folder / name
        if path.exists() or path.is_symlink():
            real = path.resolve()
            if not real.is_relative_to(folder):
                raise DescriptionError(
                    file, key, f"table {name} resolves (through a symbolic link) outside "
                    f"{folder}: a description reads tables of its own folder or data/ only"
                )  # fmt: skip
            return real
    raise DescriptionError(file, key, f"table {name} is neither next to the description nor "
                           "in data/")  # fmt: skip


def table_value(spec: dict, path: Path, file: str, key: str) -> float:
    """The number in column ``spec["column"]`` of the one row of CSV ``path`` whose columns
    equal ``spec["match"]`` (parsed by :func:`analysis.validate.parse_real`)."""
    try:
        text = read_text(path, MAX_TABLE_BYTES, "table")
    except InputError as exc:  # the reason (a FIFO, a device, too large), not the contents
        rule = str(exc).split(": ", 1)[-1]
        raise DescriptionError(file, key, f"table {path.name}: {rule}") from None
    col, match = spec.get("column"), spec.get("match", {})
    plain = isinstance(match, dict) and all(
        isinstance(v, (str, int, float)) and not isinstance(v, bool) for v in match.values()
    )
    if not plain:
        raise DescriptionError(file, f"{key} match", "must be a table of column = value")
    if not isinstance(col, str):
        raise DescriptionError(file, f"{key} column", f"{col!r} must name a column (text)")
    try:
        reader = csv.reader(text.splitlines(), strict=True)
        header = next(reader, [])
        rows = [(reader.line_num, r) for r in reader if r]
    except csv.Error as exc:
        raise DescriptionError(file, key, f"table {path.name} is not valid CSV ({exc})") from None
    if len(set(header)) != len(header):
        raise DescriptionError(file, key, f"table {path.name} repeats a column name")
    for name in [*match, col]:
        if name not in header:
            shown = ", ".join(h for h in header if re.fullmatch(r"[\w.-]{1,40}", h))
            raise DescriptionError(file, key, f"table {path.name} has no column {name!r} "
                                   f"(its columns: {shown or len(header)})")  # fmt: skip
    hits = []
    for line, r in rows:
        if len(r) != len(header):
            raise DescriptionError(file, key, f"table {path.name} line {line} has {len(r)} "
                                   f"fields, its header {len(header)}")  # fmt: skip
        cells = dict(zip(header, r, strict=True))
        if all(cells[k] == str(v) for k, v in match.items()):
            hits.append((line, cells))
    if len(hits) != 1:
        raise DescriptionError(file, key, f"{len(hits)} rows of table {path.name} match "
                               f"{match} (one must)")  # fmt: skip
    line, cells = hits[0]
    problem = validate.number_problem(cells[col])
    if problem:
        raise DescriptionError(file, key, f"table {path.name} line {line} column {col}: "
                               "not a number by the rules of analysis.validate")  # fmt: skip
    return float(cells[col])


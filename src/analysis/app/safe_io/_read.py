"""Inputs of :mod:`analysis.app.safe_io`: strict CSV tables, whole or in chunks."""

from __future__ import annotations

import codecs
import csv
import math
from collections.abc import Iterator, Sequence
from typing import IO, Any

import numpy as np
import numpy.typing as npt

from analysis.app.safe_io._errors import InputError, PathLike

__all__ = ["iter_table_chunks", "read_table"]

_SHOW = 40  # characters of a cell value quoted in a message


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

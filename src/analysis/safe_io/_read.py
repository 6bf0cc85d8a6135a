"""Inputs of :mod:`analysis.safe_io`: strict CSV tables, whole or in chunks."""

from __future__ import annotations

import codecs
import csv
import io
import itertools
import os
import re
import stat
import sys
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import IO, Any

import numpy as np
import numpy.typing as npt

from analysis.safe_io._errors import InputError, PathLike
from analysis.validate import number_problem

__all__ = ["DELIMITERS", "Records", "iter_record_chunks", "iter_table_chunks", "read_table"]

DELIMITERS = (",", ";", "\t", "|")
"""Field separators a header is sniffed for (``delimiter=None``), in order of preference."""
CHUNK_BYTES = 32 << 20
"""A chunk ends before its cells take more than about this much memory (32 MB as Python
strings: text length plus about 56 bytes per cell), whatever ``chunk_rows`` says: a file
of 10,000-character cells or of 200,000 columns streams in chunks of a few rows."""
_CELL_OVERHEAD = 56  # bytes of a short str object and its list slot
_PLAIN = re.compile(r"[0-9eE.+\- \t]*")  # the characters of a plain number (fast path)

_SHOW = 40  # characters of a cell value quoted in a message
MAX_LINE_CHARS = 1 << 24
"""Longest physical line read [characters] (16,777,216: 200,000 columns of 80 characters):
a line is read at most this far, so a file of one endless line (``/dev/zero`` behind a FIFO,
a generated file without a newline) is refused there, not after it filled the memory."""


def _show(value: str) -> str:
    return repr(value if len(value) <= _SHOW else value[:_SHOW] + "...")


def _open_text(path: PathLike, encoding: str) -> IO[str]:
    """Open for csv: lines end only at \\n (a \\r\\n ending stays), a UTF-8 BOM is dropped.

    A directory, a device or a socket is refused (a FIFO and standard input are streams the
    reader takes, line by line, each line bounded: :class:`_Lines`); the path is opened
    without blocking first, so that the descriptor itself is examined."""
    if codecs.lookup(encoding).name == "utf-8":
        encoding = "utf-8-sig"
    if str(path) == "-":  # standard input
        return io.TextIOWrapper(sys.stdin.buffer, encoding=encoding, newline="\n")
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        raise InputError(f"cannot read: {exc.strerror or exc}", path) from exc
    mode = os.fstat(fd).st_mode
    if not (stat.S_ISREG(mode) or stat.S_ISFIFO(mode)):
        os.close(fd)
        kind = "a directory" if stat.S_ISDIR(mode) else "a device or a socket"
        raise InputError(f"is {kind}, not a file of rows", path)
    os.set_blocking(fd, True)
    return open(fd, encoding=encoding, newline="\n", closefd=True)


class _Lines:
    """The lines of a text file, each read at most :data:`MAX_LINE_CHARS` far (InputError
    naming the line beyond that); iterates like the file itself."""

    def __init__(self, fh: IO[str], path: PathLike) -> None:
        self.fh, self.path, self.n = fh, path, 0

    def __iter__(self) -> Iterator[str]:
        return self

    def __next__(self) -> str:
        line = self.fh.readline(MAX_LINE_CHARS + 1)
        if not line:
            raise StopIteration
        self.n += 1
        if len(line) > MAX_LINE_CHARS:
            raise InputError(
                f"is longer than {MAX_LINE_CHARS:,} characters (the longest line read)",
                self.path,
                self.n,
            )
        return line


def _decode_error(path: PathLike, encoding: str, exc: UnicodeDecodeError) -> InputError:
    """The decoding error with its line: the text layer decodes in blocks, so find the line.

    No line break byte occurs inside a multibyte character of an ASCII-compatible encoding,
    so decoding line by line fails on the same bytes as decoding the whole file.
    """
    if str(path) == "-" or not os.path.isfile(path):  # a stream cannot be read again
        return InputError(f"not valid {encoding} text ({exc.reason})", path)
    with open(path, "rb") as fh:
        for number, raw in enumerate(iter(lambda: fh.readline(4 * MAX_LINE_CHARS), b""), 1):
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
        delimiter: str | None,
        bad_numbers: str = "raise",
        aliases: Mapping[str, Sequence[str]] | None = None,
    ) -> None:
        self.aliases = {k: tuple(v) for k, v in (aliases or {}).items()}
        if bad_numbers not in ("raise", "mark"):
            raise ValueError(f"bad_numbers must be 'raise' or 'mark', not {bad_numbers!r}")
        self.bad_numbers = bad_numbers
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
        header = None
        try:
            peeked: list[str] = []  # the lines up to the first non-blank one, for the sniff
            lines = _Lines(self.file, self.path)
            try:
                for line in lines:
                    peeked.append(line)
                    if line.strip():
                        break
            except UnicodeDecodeError as exc:
                raise _decode_error(self.path, self.encoding, exc) from None
            self.first_text = peeked[-1] if peeked else ""
            if self.delimiter is None:
                self.delimiter = _sniff(self.first_text, self.required, self.aliases)
            self.reader = csv.reader(
                itertools.chain(peeked, lines), delimiter=self.delimiter, strict=True
            )
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

    def _or_alias(self, name: str) -> str:
        return name + "".join(f" (or {a})" for a in self.aliases.get(name, ()))

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
        written, self.written = list(names), {}  # .written: column -> alias, as written
        for canon, others in self.aliases.items():  # x -> x_mm where x_mm is not there
            given = [a for a in others if a in where]
            if canon not in where and len(given) == 1:
                where[canon] = where.pop(given[0])
                names[where[canon] - 1] = canon
                self.written[canon] = given[0]
        missing = [n for n in self.required if n not in where]
        if missing:
            raise InputError(
                f"missing required column(s) {', '.join(map(self._or_alias, missing))} "
                f"(the header has: "
                f"{', '.join(written)}){_delimiter_hint(self.first_text, self.delimiter)}",
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
        self.header = header  # as written (names unstripped)

    def chunks(self, chunk_rows: int | None) -> Iterator[tuple[int, dict[str, np.ndarray]]]:
        """Yield (first line, columns) for every ``chunk_rows`` records (all if None)."""
        with self.file:
            yield from self._chunks(chunk_rows)

    def _chunks(self, chunk_rows: int | None) -> Iterator[tuple[int, dict[str, np.ndarray]]]:
        for columns, ends in self._raw_chunks(chunk_rows, None):
            yield self._chunk(columns, ends)

    def _raw_chunks(
        self, chunk_rows: int | None, chunk_bytes: int | None
    ) -> Iterator[tuple[list[list[str]], list[int]]]:
        """(columns of raw cells, the line each record ends on) per chunk of at most
        ``chunk_rows`` records and about ``chunk_bytes`` of cells."""
        # Cells go straight into per-column lists: keeping the csv row lists alive instead
        # makes the cyclic garbage collector rescan them and halves the throughput.
        reader, width = self.reader, self.width
        columns: list[list[str]] = [[] for _ in range(width)]
        ends: list[int] = []  # physical line each record ends on
        row_cost = _CELL_OVERHEAD * width
        size = 0
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
                if chunk_bytes is not None:
                    size += row_cost + sum(map(len, row))
                if len(ends) == chunk_rows or (chunk_bytes is not None and size >= chunk_bytes):
                    self.last_line = ends[-1]
                    yield columns, ends
                    columns, ends, size = [[] for _ in range(width)], [], 0
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
            yield columns, ends

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
        self,
        columns: list[list[str]],
        index: int,
        ends: list[int],
        name: str,
        problems: list[str | None] | None = None,
    ) -> np.ndarray:
        """The numeric column ``index``; a bad cell raises, or (``problems`` given) becomes
        NaN with its reason in ``problems`` (the first per record)."""
        cells = columns[index]
        try:
            values = np.fromiter(map(float, cells), dtype=np.float64, count=len(cells))
            # float() also takes 1_000, non-ASCII digits, nan and inf: the rule is
            # analysis.validate's, which the plain characters and finiteness ensure
            good = bool(_PLAIN.fullmatch("".join(cells))) and bool(np.isfinite(values).all())
        except ValueError:
            good = False
            values = np.empty(len(cells))
        if good:
            return values
        shown = self.written.get(name, name)  # the column as the header wrote it
        for i, cell in enumerate(cells):
            problem = _number_problem(cell)
            if problem is None:
                values[i] = float(cell)
                continue
            line = _first_line([c[i] for c in columns], ends[i])
            if problems is None:
                raise InputError(problem, self.path, line, shown)
            values[i] = np.nan
            if problems[i] is None:
                problems[i] = str(InputError(problem, self.path, line, shown))
        return values

    def records(self, chunk_rows: int | None, chunk_bytes: int | None) -> Iterator[Records]:
        """The chunks as :class:`Records` (raw text of every cell, numbers parsed)."""
        with self.file:
            for columns, ends in self._raw_chunks(chunk_rows, chunk_bytes):
                n = len(ends)
                problems: list[str | None] | None = (
                    [None] * n if self.bad_numbers == "mark" else None
                )
                numbers = {
                    name: self._numbers(columns, index, ends, name, problems)
                    for index, name in self.keep
                    if name in self.numeric
                }
                yield Records(ends, columns, numbers, problems or [None] * n, self.written)


@dataclass
class Records:
    """One chunk of :func:`iter_record_chunks`.

    Attributes
    ----------
    lines : list of int
        The physical line each record ends on (where it starts, unless a quoted cell holds
        a line break).
    cells : list of list of str
        Per column, in header order, every cell's text exactly as read (after CSV unquoting).
    numbers : dict of str to ndarray
        The numeric columns parsed (float64; NaN where a cell is bad and ``bad_numbers`` is
        "mark").
    problems : list of str or None
        Per record: None, or the one-line reason (file, line, column) of its first bad
        numeric cell.
    written : dict of str to str
        A column read under an alias -> its name as the header wrote it (``x_mm`` -> ``x``).
    """

    lines: list[int]
    cells: list[list[str]]
    numbers: dict[str, np.ndarray]
    problems: list[str | None]
    written: dict[str, str] = field(default_factory=dict)


def _number_problem(cell: str) -> str | None:
    """Why ``cell`` is not a finite number (:func:`analysis.validate.number_problem`), or
    None if it is one."""
    if not cell.strip():
        return "empty cell; a number is required"
    return number_problem(cell)


def _split(line: str, delimiter: str) -> list[str]:
    return [name.strip().strip('"').strip() for name in line.rstrip("\r\n").split(delimiter)]


def _sniff(line: str, required: Sequence[str], aliases: Mapping[str, Sequence[str]]) -> str:
    """The delimiter of a header line: the first of :data:`DELIMITERS` under which it has
    every required column or one of its ``aliases`` (else the one that splits it into the
    most fields, else ",")."""
    for d in DELIMITERS:
        names = _split(line, d)
        if required and all(r in names or set(aliases.get(r, ())) & set(names) for r in required):
            return d
    if not required:
        counts = {d: line.count(d) for d in DELIMITERS}
        best = max(counts, key=lambda d: counts[d])
        if counts[best]:
            return best
    return ","


def _delimiter_hint(line: str, used: str | None) -> str:
    """A second sentence when the header looks separated by another delimiter than ``used``."""
    name = {"\t": "tab", ",": "','", ";": "';'", "|": "'|'"}
    others = [d for d in DELIMITERS if d != used and line.count(d) > line.count(used or ",")]
    if not others:
        return ""
    d = max(others, key=line.count)
    flag = "\\t" if d == "\t" else d
    return (
        f"; the header looks {name[d]}-separated, not {name.get(used or ',', repr(used))}: "
        f"give --delimiter '{flag}'"
    )


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


def iter_record_chunks(
    path: PathLike,
    required: Sequence[str] = (),
    optional: Sequence[str] = (),
    numeric: Sequence[str] = (),
    *,
    allow_extra: bool = False,
    chunk_rows: int = 100_000,
    chunk_bytes: int = CHUNK_BYTES,
    encoding: str = "utf-8",
    delimiter: str | None = None,
    bad_numbers: str = "raise",
    aliases: Mapping[str, Sequence[str]] | None = None,
) -> tuple[list[str], Iterator[Records]]:
    """Stream a CSV table as :class:`Records`: every cell's text as given (for an output
    that echoes its input byte for byte) and the numeric columns parsed.

    Memory is bounded by the chunk, in rows (``chunk_rows``) and in bytes (``chunk_bytes``,
    estimated as Python strings): text cells stay Python strings, never fixed-width arrays.
    ``path`` may be ``"-"`` (standard input). ``delimiter=None`` sniffs it from the header
    (:data:`DELIMITERS`: the first under which every required column is there). With
    ``bad_numbers="mark"`` a bad numeric cell (not a number by
    :func:`analysis.validate.parse_real`'s rules) does not raise: its record carries the
    reason in ``problems`` and NaN in ``numbers``. Structural errors (header, field counts,
    quoting, encoding) raise :class:`InputError` as :func:`read_table` does.

    ``aliases`` {column: other names}: a header without ``column`` but with exactly one of
    its other names (``x`` for ``x_mm``) reads that one as ``column`` (named as written).

    Returns ``(header, chunks)``: the header's names as written, and the iterator.
    """
    if isinstance(chunk_rows, bool) or not isinstance(chunk_rows, int) or chunk_rows < 1:
        raise ValueError(f"chunk_rows must be a positive integer, not {chunk_rows!r}")
    table = _Table(
        path, required, optional, numeric, allow_extra, encoding, delimiter, bad_numbers, aliases
    )
    table.open()
    return list(table.header), table.records(chunk_rows, chunk_bytes)


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

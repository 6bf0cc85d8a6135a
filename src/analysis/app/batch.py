"""Batch inverse kinematics from CSV to CSV, streamed in chunks with bounded memory.

``ik --input IN.csv --output OUT.csv``: the input (columns :func:`input_columns`: x_mm,
y_mm, z_mm; for a pose also its angles in degrees; any other columns too) is read strictly
(:func:`analysis.safe_io.iter_record_chunks`: a missing, duplicate or ragged column is an
error naming its true line), solved chunk by chunk, and written to a temporary file that
replaces the output only when everything succeeded (:func:`~analysis.safe_io.
atomic_writer`; ``-`` writes standard output as it goes); the output may not be the input,
nor a device or a FIFO. Memory is bounded by one chunk whatever the file size and the cell
widths: at most ``chunk_rows`` records and about 32 MB of cell text
(:data:`analysis.safe_io._read.CHUNK_BYTES`), read, solved and written before the next.

Nothing of the input is lost: every input column is echoed byte for byte (the cell text as
read, never re-formatted: ``100.12345678901234`` stays that), under its own name; a name that
clashes with an output column (or with a name given to another clash) gets the prefix
``input_`` and, if that is taken too, a number: ``status`` -> ``input_status``,
``input_status`` -> ``input_status_2``, never one column for two.

Output: the input columns, then ``branch, reachable``, the joint values (``Arm.joint_labels``:
``theta1_deg .. thetan_deg``; a prismatic joint's in mm), ``c1 .. cn`` (the pulses: none for
an arm whose description gives no drive), ``status, reason``, one row per target and branch,
targets in input order. ``reachable`` is true where the row has a
solution; ``status`` says why not, branch by branch (ok, out-of-reach, inside-reach, base-axis,
joint-limits, degenerate, orientation, invalid: :attr:`IKSolutions.branch_status`, so a GR-1
back branch whose wrist is out of reach says out-of-reach, not joint-limits). Unsolved rows
leave angles and pulses empty, never "nan".
Angles are written in full (the shortest text that reads back as the same float). A row whose
numbers are bad (not a number by :mod:`analysis.validate`'s rules, or outside its range) is not
solved: its status is ``invalid`` and ``reason`` names the line, the column, the value and the
limit; the batch goes on (``strict=True``: it stops at the first, and the output is not
written).
"""

from __future__ import annotations

import csv
from collections import Counter
from collections.abc import Callable
from pathlib import Path

import numpy as np

from analysis import validate
from analysis.app.explain import batch_reasons
from analysis.kinematics.arm import Arm
from analysis.kinematics.status import STATUS_TEXT, Status
from analysis.safe_io import InputError, check_paths, iter_record_chunks, output_stream

__all__ = [
    "INPUT_COLUMNS",
    "WRITE_ROWS",
    "input_columns",
    "output_columns",
    "output_header",
    "solve_csv",
]

INPUT_COLUMNS = ("x_mm", "y_mm", "z_mm")
"""The columns of a point target (every arm's first three inputs, px, py, pz)."""
WRITE_ROWS = 25_000
"""Targets solved and formatted at a time (bounds the memory of the text being written)."""


def input_columns(arm: Arm) -> tuple[str, ...]:
    """The input CSV's columns for ``arm``: ``x_mm, y_mm, z_mm``, then any angle of a pose in
    degrees, as on the command line (the GR-1: ``alpha_deg, beta_deg, gamma_deg``, RPY).

    >>> from analysis.kinematics.arm import load_arm
    >>> input_columns(load_arm("gr1"))
    ('x_mm', 'y_mm', 'z_mm', 'alpha_deg', 'beta_deg', 'gamma_deg')
    """
    point = dict(zip(("px", "py", "pz"), INPUT_COLUMNS, strict=True))
    return tuple(
        point.get(name) or f"{name}_{unit}"
        for name, unit in zip(arm.inputs, arm.user_units, strict=True)
    )


def input_aliases(columns: tuple[str, ...]) -> dict[str, tuple[str, ...]]:
    """Other names a header may give the input ``columns``: the name without its unit
    (``x`` for ``x_mm``, ``alpha`` for ``alpha_deg``), read as that column where the header
    has it and not the full name.

    >>> input_aliases(("x_mm", "y_mm", "z_mm"))
    {'x_mm': ('x',), 'y_mm': ('y',), 'z_mm': ('z',)}
    """
    return {c: (c.rsplit("_", 1)[0],) for c in columns if "_" in c}


def output_columns(arm: Arm) -> list[str]:
    """The columns ``solve_csv`` appends to the input's (pulses ``c1 .. cn`` only for an arm
    with a drive)."""
    n = arm.n_joints
    return [
        "branch",
        "reachable",
        *arm.joint_labels,
        *(f"c{j + 1}" for j in range(n) if arm.has_drive),  # no drive given: no pulses
        "status",
        "reason",
    ]


def output_header(header: list[str], outputs: list[str]) -> list[str]:
    """The output's header: the input names as written, those that clash renamed.

    A clash is a name (stripped) equal to an output column or to a name already given;
    it becomes ``input_<name>``, then ``input_<name>_2``, ``_3``, ... until free.

    >>> output_header(["x_mm", "status", "input_status"], ["branch", "status"])
    ['x_mm', 'input_status_2', 'input_status', 'branch', 'status']
    """
    names = [h.strip() for h in header]
    taken = set(outputs)
    out = []
    for raw, name in zip(header, names, strict=True):
        if name in taken:
            new, k = f"input_{name}", 2
            while new in taken or new in names:
                new, k = f"input_{name}_{k}", k + 1
            name = raw = new
        taken.add(name)
        out.append(raw)  # as written
    return [*out, *outputs]


def _range_problems(
    arm: Arm, values: np.ndarray, columns: tuple[str, ...], lines: list[int], path
) -> list[str | None]:
    """Per row: why its numbers are outside :mod:`analysis.validate`'s ranges, or None.
    Coordinates (mm) within +-MAX_COORD_MM; angles in degrees have no range (they are
    reduced exactly)."""
    mm = np.array([u == "mm" for u in arm.user_units])
    bad = ~(np.abs(values[:, mm]) <= validate.MAX_COORD_MM) & ~np.isnan(values[:, mm])
    out: list[str | None] = [None] * len(values)
    if not bad.any():
        return out
    mm_cols = [c for c, m in zip(columns, mm, strict=True) if m]
    for i in np.flatnonzero(bad.any(axis=1)):
        j = int(np.flatnonzero(bad[i])[0])
        message = (
            f"{mm_cols[j]} = {values[i, mm][j]:g} mm is beyond +-{validate.MAX_COORD_MM:.4g} mm, "
            "the largest coordinate the code supports (a PLC REAL)"
        )
        out[i] = str(InputError(message, path, lines[i], mm_cols[j]))
    return out


def _fmt_angles(deg: np.ndarray, ok: np.ndarray) -> list[str]:
    """Each angle as the shortest text that reads back as the same float; "" where not ok."""
    text = [repr(v) for v in (deg + 0.0).tolist()]  # + 0.0: no "-0.0"
    return [t if good else "" for t, good in zip(text, ok.tolist(), strict=True)]


def solve_csv(
    arm: Arm,
    input_path: Path | str,
    output_path: Path | str,
    *,
    branch: str | None = None,
    tol: float = 1e-6,
    theta1_on_axis: float | None = None,
    chunk_rows: int = 100_000,
    params: Path | None = None,
    strict: bool = False,
    delimiter: str | None = None,
    make_dirs: bool = False,
    progress: Callable[[int], None] | None = None,
) -> dict:
    """Solve every target of ``input_path`` into ``output_path``; return a summary.

    ``input_path`` and ``output_path`` may be ``"-"`` (standard input, output).
    ``delimiter=None`` sniffs the input's delimiter from its header. ``make_dirs`` creates a
    missing output directory (removed again if the batch fails). ``progress`` is called with
    the number of targets done after each part.

    Raises ``InputError`` (bad CSV, naming line and column; with ``strict``, also the first
    bad number), ``OutputError`` (cannot write, or the output is an input, a device or a
    FIFO) or ``ValueError`` (bad options); the output is then untouched.
    """
    if (
        isinstance(chunk_rows, bool)
        or not isinstance(chunk_rows, int)
        or not (1 <= chunk_rows <= 10_000_000)
    ):
        raise ValueError(f"--chunk-rows {chunk_rows!r} must be a whole number in 1 .. 10,000,000")
    tol = validate.tolerance_mm(tol, "--tol")
    check_paths(inputs=[*arm.input_files, *(p for p in (input_path, params) if p)],
                outputs=[output_path], make_parents=make_dirs)  # fmt: skip
    names = arm.branch_names(branch or arm.branches[0])
    columns = input_columns(arm)
    header, chunks = iter_record_chunks(
        input_path,
        required=columns,
        numeric=columns,
        allow_extra=True,
        chunk_rows=chunk_rows,
        delimiter=delimiter,
        bad_numbers="raise" if strict else "mark",
        aliases=input_aliases(columns),
    )
    status_text = np.array([STATUS_TEXT[Status(s)] for s in range(len(Status))], dtype=object)
    counts: Counter = Counter()
    total = solved = 0
    with output_stream(output_path, newline="", make_parents=make_dirs) as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(output_header(header, output_columns(arm)))
        for rec in chunks:
            values = np.stack([rec.numbers[c] for c in columns], axis=-1)
            problems = _problems(arm, rec, values, columns, input_path)
            if strict and any(problems):
                raise ValueError(next(p for p in problems if p))
            for s in range(0, len(values), WRITE_ROWS):
                e = min(s + WRITE_ROWS, len(values))
                reason = problems[s:e]
                theta, ok, status, row_status, outside = _solve_part(
                    arm, values[s:e], reason, names, tol, theta1_on_axis
                )
                counts.update(status_text[status].tolist())
                total += e - s
                solved += int(ok.any(axis=-1).sum())
                cells = [col[s:e] for col in rec.cells]
                row_text = status_text[row_status.reshape(-1)].tolist()
                said = batch_reasons(
                    row_text, np.repeat(outside, len(names)), list(names) * (e - s)
                )
                writer.writerows(_rows(arm, cells, names, theta, ok, row_text, reason, said))
                if progress is not None:
                    progress(total)
    return {
        "input": str(input_path),
        "output": str(output_path),
        "arm": arm.name,
        "branches": list(names),
        "targets": total,
        "solved": solved,
        "status": {k: counts.get(k, 0) for k in STATUS_TEXT.values() if counts.get(k, 0)},
        "pulses": arm.has_drive,  # False: no drive given, no c1..cn columns written
    }


def _problems(arm: Arm, rec, values: np.ndarray, columns, path) -> list[str | None]:
    """Per record of a chunk: why it is not solved (a bad number as read, or a coordinate
    out of range), or None."""
    shown = tuple(rec.written.get(c, c) for c in columns)  # as the header wrote them
    ranges = _range_problems(arm, values, shown, rec.lines, path)
    return [a or b for a, b in zip(rec.problems, ranges, strict=True)]


def _solve_part(arm: Arm, values: np.ndarray, reason, names, tol, theta1_on_axis):
    """Solve the valid rows of one part (``reason`` None): joint values ``(k, nb, nj)``
    (NaN where not solved), ``ok`` ``(k, nb)``, each target's status and each branch's own
    (``Status.INVALID`` for a row not solved), and each target's distance outside the reach
    [mm]."""
    k, nb, nj = len(values), len(names), arm.n_joints
    valid = np.array([r is None for r in reason])
    theta = np.full((k, nb, nj), np.nan)
    ok = np.zeros((k, nb), dtype=bool)
    status = np.full(k, int(Status.INVALID), dtype=np.int64)
    row_status = np.full((k, nb), int(Status.INVALID), dtype=np.int64)
    outside = np.zeros(k)
    if valid.any():
        sol = arm.solve(
            arm.from_user(values[valid]),
            names,
            tol=tol,
            theta1_on_axis=theta1_on_axis,
        )
        theta[valid], ok[valid] = sol.theta, sol.ok
        status[valid] = sol.status
        row_status[valid] = sol.branch_status  # each branch's own reason
        outside[valid] = sol.outside_mm
    return theta, ok, status, row_status, outside


def _rows(arm: Arm, cells, names, theta, ok, row_text, reason, said):
    """The output rows of one part, one per target and branch: the input cells as read,
    branch, reachable, the joint values (deg | mm), the pulses, status and reason (a bad
    number's, else ``said``: why the row is not ok)."""
    k, nb, nj = theta.shape
    flat_ok = ok.reshape(-1)
    out: list[list[str]] = []
    for part in cells:
        out.append(part if nb == 1 else [v for v in part for _ in range(nb)])
    out.append(list(names) * k)
    out.append(["true" if v else "false" for v in flat_ok.tolist()])
    flat = theta.reshape(k * nb, nj)
    user = arm.joints_to_user(np.where(flat_ok[:, None], flat, 0.0))  # deg | mm
    for j in range(nj):
        out.append(_fmt_angles(user[:, j], flat_ok))
    pulses = np.zeros((k * nb, nj), dtype=np.int64)
    if flat_ok.any() and arm.has_drive:
        pulses[flat_ok] = arm.pulses(flat[flat_ok])
    for j in range(nj if arm.has_drive else 0):
        given = zip(pulses[:, j].tolist(), flat_ok.tolist(), strict=True)
        out.append([str(c) if good else "" for c, good in given])
    out.append(row_text)
    out.append([r or said[i * nb + j] for i, r in enumerate(reason) for j in range(nb)])
    return zip(*out, strict=True)

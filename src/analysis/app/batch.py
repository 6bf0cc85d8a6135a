"""Batch inverse kinematics from CSV to CSV, streamed in chunks with constant memory.

``ik --input IN.csv --output OUT.csv``: the input (columns :func:`input_columns`: x_mm,
y_mm, z_mm; for a pose also its angles in degrees) is read strictly
(:func:`analysis.app.safe_io.iter_table_chunks`: a missing, duplicate or ragged column is an
error naming its true line), solved chunk by chunk, and written to a temporary file that
replaces the output only when everything succeeded (:func:`~analysis.app.safe_io.
atomic_writer`); the output may not be the input. Memory does not grow with the file:
a chunk of targets is read, solved and written before the next is read.

Output: every input column (renamed ``input_<name>`` where it clashes with an output
column), then ``branch, reachable``, the joint values (``Arm.joint_labels``: ``theta1_deg ..
thetan_deg``; a prismatic joint's in mm), ``c1 .. cn, status``, one row per
target and branch, targets in input order. ``reachable`` is true where the row has a
solution; ``status`` says why not (ok, out-of-reach, inside-reach, base-axis, joint-limits,
degenerate). Unsolved rows leave angles and pulses empty, never "nan".
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np

from analysis.app.safe_io import atomic_writer, check_paths, iter_table_chunks
from analysis.kinematics.arm import Arm
from analysis.kinematics.status import STATUS_TEXT, Status

__all__ = ["INPUT_COLUMNS", "WRITE_ROWS", "input_columns", "output_columns", "solve_csv"]

INPUT_COLUMNS = ("x_mm", "y_mm", "z_mm")
"""The columns of a point target (every arm's first three inputs, px, py, pz)."""
WRITE_ROWS = 25_000
"""Targets formatted at a time (bounds the memory of the text being written)."""


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


def output_columns(arm: Arm) -> list[str]:
    """The columns ``solve_csv`` appends to the input's."""
    n = arm.n_joints
    return [
        "branch",
        "reachable",
        *arm.joint_labels,
        *(f"c{j + 1}" for j in range(n)),
        "status",
    ]


def _frame(arm, names, cols, header, sol):
    """One chunk's output rows as a DataFrame (pandas formats the CSV text)."""
    import pandas as pd

    n, nb = sol.ok.shape
    nj = arm.n_joints
    out_cols = output_columns(arm)
    data = {}
    for k in header:
        v = cols[k]
        name = f"input_{k}" if k in out_cols else k
        data[name] = np.repeat(v, nb)
    ok = sol.ok.reshape(n * nb)
    theta = sol.theta.reshape(n * nb, nj)
    pulses = np.zeros((n * nb, nj), dtype=np.int64)
    if ok.any():
        pulses[ok] = arm.pulses(theta[ok])
    deg = arm.joints_to_user(np.where(ok[:, None], theta, 0.0))  # degrees | mm
    status = np.repeat(sol.status, nb).astype(np.int64)
    status = np.where((status == Status.OK) & ~ok, int(Status.JOINT_LIMITS), status)
    data["branch"] = np.tile(np.array(names, dtype=object), n)
    data["reachable"] = np.where(ok, "true", "false")
    for j, label in enumerate(arm.joint_labels):
        data[label] = pd.arrays.FloatingArray(deg[:, j], ~ok)
    for j in range(nj):
        data[f"c{j + 1}"] = pd.arrays.IntegerArray(pulses[:, j], ~ok)
    text = np.array([STATUS_TEXT[Status(s)] for s in range(len(Status))], dtype=object)
    data["status"] = text[status]
    return pd.DataFrame(data), Counter(text[sol.status.astype(np.int64)].tolist())


def solve_csv(
    arm: Arm,
    input_path: Path,
    output_path: Path,
    *,
    branch: str | None = None,
    tol: float = 1e-6,
    theta1_on_axis: float | None = None,
    chunk_rows: int = 100_000,
    params: Path | None = None,
) -> dict:
    """Solve every target of ``input_path`` into ``output_path``; return a summary.

    Raises ``InputError`` (bad CSV, naming line and column), ``OutputError`` (cannot write,
    or the output is an input) or ``ValueError`` (bad options); the output is then untouched.
    """
    if not 1 <= chunk_rows <= 10_000_000:
        raise ValueError(f"--chunk-rows {chunk_rows} must be in 1 .. 10,000,000")
    check_paths(inputs=[p for p in (input_path, params) if p], outputs=[output_path],
                make_parents=True)  # fmt: skip
    names = arm.branch_names(branch or arm.branches[0])
    columns = input_columns(arm)
    counts: Counter = Counter()
    total = solved = 0
    with atomic_writer(output_path, newline="", make_parents=True) as fh:
        first = True
        for _, cols in iter_table_chunks(
            input_path,
            required=columns,
            numeric=columns,
            allow_extra=True,
            chunk_rows=chunk_rows,
        ):
            header = list(cols)
            p_all = arm.from_user(np.stack([cols[c] for c in columns], axis=-1))
            for s in range(0, len(p_all), WRITE_ROWS):
                part = {k: v[s : s + WRITE_ROWS] for k, v in cols.items()}
                p = p_all[s : s + WRITE_ROWS]
                sol = arm.solve(p, names, tol=tol, theta1_on_axis=theta1_on_axis)
                df, c = _frame(arm, names, part, header, sol)
                df.to_csv(fh, header=first, index=False, float_format="%.10g")
                first = False
                counts.update(c)
                total += len(p)
                solved += int(sol.ok.any(axis=-1).sum())
        if first:  # no data rows: the header alone
            import pandas as pd

            pd.DataFrame(columns=[*columns, *output_columns(arm)]).to_csv(fh, index=False)
    return {
        "input": str(input_path),
        "output": str(output_path),
        "arm": arm.name,
        "branches": list(names),
        "targets": total,
        "solved": solved,
        "status": {k: counts.get(k, 0) for k in STATUS_TEXT.values() if counts.get(k, 0)},
    }

"""A machine run played in the 3D view (issue 31 item 3): the trace that ``python -m analysis
stl-run PROGRAM --dialect st --scenario S.csv --trace T.csv`` writes (issue 29 item 3, a
contract: one row per cycle, ``t_s``, ``q1 .. qN`` in joint units, deg or mm, ``v1 .. vN`` per
second, then every output of the program by name, a BOOL as TRUE/FALSE, then
``plc_q1 .. plc_qN``, what the PLC reads of each axis, into ``pos``) read strictly
(:func:`read_trace`) and drawn with a time slider, the outputs at each frame under the title
(:func:`machine_run_figure`, :func:`analysis.app.arm3d.trajectory_figure`: the arm, its joint
axes and its tool frame from the arm's forward kinematics at the trace's joint values).

A trace is input from others (a file a user hands over): it is read only if it is a regular
file of at most :data:`MAX_TRACE_BYTES`, with at most :data:`MAX_TRACE_ROWS` rows (the longest
run ``stl-run`` writes, :data:`analysis.plc.machine.offline.MAX_CYCLES`, and its header), by
the project's strict CSV reader (:func:`analysis.safe_io.read_table`: field counts, quoting,
numbers, each error naming the file, line and column); here the joint columns must be the
arm's (``q1 .. qN`` and ``v1 .. vN``, N its joints), times must increase, joint values must be
within what the kinematics accepts (:data:`analysis.kinematics.arm.MAX_JOINT_DEG`,
``MAX_JOINT_MM``), and each output column is all TRUE/FALSE or all numbers. Every refusal is
one line (a :class:`ValueError`) naming the row, the column and the limit.
"""

from __future__ import annotations

import math
import re
import stat
from pathlib import Path

import numpy as np

from analysis import validate
from analysis.kinematics.solution import MAX_JOINT_DEG, MAX_JOINT_MM
from analysis.kinematics.status import STATUS_TEXT
from analysis.plc.machine.checks import PLC_COLUMN, Trace
from analysis.plc.machine.offline import MAX_CYCLES
from analysis.plc.machine.spec import MACHINE_STATUS
from analysis.safe_io import InputError, read_table

__all__ = ["MAX_TRACE_BYTES", "MAX_TRACE_ROWS", "SHOWN", "machine_run_figure", "read_trace"]

MAX_TRACE_ROWS = MAX_CYCLES + 1
"""The most rows read: the longest run ``stl-run`` writes (cycles 0 .. MAX_CYCLES)."""
MAX_TRACE_BYTES = 256 << 20
"""The largest trace file read [bytes] (a run of MAX_TRACE_ROWS cycles of a six-axis arm
with its outputs is about 200 MB)."""
SHOWN = ("Status", "Busy", "Done", "Homed", "Error", "Gripper")
"""The outputs shown under the title at each frame, in this order, where the trace has them
(the machine program's outputs, :data:`analysis.plc.machine.spec.MACHINE_OUTPUTS`, but
GripperClosed, the gripper's state after its dwell: with it the line overran a 560 px view)."""
_WORDS = {"TRUE": True, "FALSE": False}


def _status_word(code: float) -> str:
    """The word of a status code: the IK block's (0-7) or the machine's own (100-104)."""
    if not float(code).is_integer():
        return ""
    k = int(code)
    if k in MACHINE_STATUS:
        return MACHINE_STATUS[k][0]
    return next((w for s, w in STATUS_TEXT.items() if int(s) == k), "")


def _joint_columns(head: list[str], n: int, where: str) -> None:
    """The header's joint columns are ``t_s, q1..qN, v1..vN`` for the arm's N joints."""
    qs = [h for h in head if re.fullmatch(r"q[0-9]+", h)]
    vs = [h for h in head if re.fullmatch(r"v[0-9]+", h)]
    want = ["t_s", *(f"q{j}" for j in range(1, n + 1)), *(f"v{j}" for j in range(1, n + 1))]
    if len(qs) != n or len(vs) != n:
        raise ValueError(
            f"{where}: {len(qs)} joint position columns ({', '.join(qs) or 'none'}); the arm "
            f"has {n} joints (expected q1..q{n} and v1..v{n})"
        )
    if head[: len(want)] != want:
        raise ValueError(f"{where}: the header starts {','.join(head[: len(want)])}; "
                         f"expected {','.join(want)} (stl-run --trace)")  # fmt: skip


def _output(name: str, cells, where: str) -> np.ndarray:
    """An output column: all TRUE/FALSE (bool) or all numbers (float; nan and inf as a REAL
    output writes them)."""
    words = np.char.upper(np.char.strip(np.asarray(cells, dtype=str)))
    is_word = np.isin(words, list(_WORDS))
    if is_word.all():
        return words == "TRUE"
    out = np.empty(len(cells))
    for k, (c, w) in enumerate(zip(cells, is_word, strict=True)):
        text = c.strip()
        if w:
            raise ValueError(f"{where}: row {k + 1}, column {name}: {text!r} in a column "
                             "of numbers (a BOOL column is all TRUE/FALSE)")  # fmt: skip
        if text.lower().lstrip("+-") in ("nan", "inf", "infinity"):
            out[k] = float(text)
            continue
        problem = validate.number_problem(text)
        if problem:
            raise ValueError(f"{where}: row {k + 1}, column {name}: {problem}")
        out[k] = float(text)
    return out


def read_trace(path, arm) -> Trace:
    """The trace at ``path`` (``stl-run --trace``) for ``arm``, checked (module docstring):
    a :class:`~analysis.plc.machine.checks.Trace` with ``t`` [s], ``q`` (rows, N) [deg | mm],
    ``v`` (rows, N) [per s] and ``outputs`` {name: bool or float array}.

    Raises ValueError (one line: the file, row or line, column and limit) for anything else:
    a file that is not a regular file or is larger than :data:`MAX_TRACE_BYTES`, more than
    :data:`MAX_TRACE_ROWS` rows or fewer than 2, joint columns that are not the arm's, a
    time that does not increase, a joint value beyond the kinematics' range, a cell that is
    not a number (or TRUE/FALSE in an output column).
    """
    path = Path(path)
    where = f"trace {path}"
    try:
        st = path.stat()
    except OSError as exc:
        raise InputError(f"cannot read the trace: {exc.strerror}", path) from None
    if not stat.S_ISREG(st.st_mode):
        raise InputError("the trace is not a regular file", path)
    if st.st_size > MAX_TRACE_BYTES:
        raise InputError(f"the trace has {st.st_size} bytes: at most {MAX_TRACE_BYTES}", path)
    n = arm.n_joints
    joints = ["t_s", *(f"q{j}" for j in range(1, n + 1)), *(f"v{j}" for j in range(1, n + 1))]
    plc = [PLC_COLUMN.format(j) for j in range(1, n + 1)]  # what the PLC reads (stl-run)
    # one read: the arm's columns as numbers where the header has them, the rest as text
    cols = read_table(path, optional=joints + plc, numeric=joints + plc, allow_extra=True)
    head = list(cols)
    _joint_columns(head, n, where)
    plc = plc if all(h in head for h in plc) else []
    rows = len(cols["t_s"])
    if not 2 <= rows <= MAX_TRACE_ROWS:
        raise ValueError(f"{where}: {rows} rows; a run to play has 2 .. {MAX_TRACE_ROWS}")
    t = cols["t_s"]
    back = np.flatnonzero(np.diff(t) <= 0)
    if len(back):
        k = int(back[0]) + 1
        raise ValueError(f"{where}: row {k + 1}, column t_s: {t[k]:g} s does not come after "
                         f"{t[k - 1]:g} s (times must increase)")  # fmt: skip
    q = np.stack([cols[f"q{j}"] for j in range(1, n + 1)], axis=1)
    v = np.stack([cols[f"v{j}"] for j in range(1, n + 1)], axis=1)
    units = arm.joint_user_units
    bound = np.array([MAX_JOINT_MM if u == "mm" else MAX_JOINT_DEG for u in units])
    bad = np.argwhere(np.abs(q) > bound)
    if len(bad):
        k, j = (int(i) for i in bad[0])
        raise ValueError(f"{where}: row {k + 1}, column q{j + 1}: {q[k, j]:g} {units[j]} is "
                         f"beyond +-{bound[j]:g} {units[j]}")  # fmt: skip
    outputs = {h: _output(h, cols[h], where) for h in head[len(joints) :] if h not in plc}
    pos = np.stack([cols[h] for h in plc], axis=1) if plc else None
    return Trace(t, q, v, outputs, pos)


def _fmt(name: str, value) -> str:
    if isinstance(value, (bool, np.bool_)):
        return f"{name} {'TRUE' if value else 'FALSE'}"
    v = float(value)
    if name == "Status" and math.isfinite(v):
        word = _status_word(v)
        return f"Status {v:g}" + (f" ({word})" if word else "")
    return f"{name} {v:g}"


def machine_run_figure(arm, trace: Trace, *, title: str = "", frames: int = 61, box=None):
    """The machine run ``trace`` (:func:`read_trace`, or
    :meth:`~analysis.plc.machine.checks.Trace.from_run`) of ``arm`` played with a time
    slider (:func:`analysis.app.arm3d.trajectory_figure`: the arm, its joint axes and tool
    frame at ``frames`` times spread over the run, the tool's path), and under the title at
    each frame the time and the outputs of :data:`SHOWN` the trace has (Status with its word:
    the IK block's or the machine's, :data:`analysis.plc.machine.spec.MACHINE_STATUS`)."""
    from analysis.app.arm3d import trajectory_figure

    q = np.asarray(trace.q, dtype=float)
    if q.ndim != 2 or q.shape[1] != arm.n_joints:
        raise ValueError(f"the trace has {q.shape[-1]} joints; arm {arm.name} has "
                         f"{arm.n_joints}")  # fmt: skip
    names = [n for n in SHOWN if n in trace.outputs]
    cols = [np.asarray(trace.outputs[n]) for n in names]
    notes = [
        " · ".join([f"t = {t:.2f} s", *(_fmt(n, c[k]) for n, c in zip(names, cols, strict=True))])
        for k, t in enumerate(trace.t)
    ]
    return trajectory_figure(
        arm, trace.t, arm.joints_from_user(q), title=title, frames=frames, notes=notes, box=box
    )

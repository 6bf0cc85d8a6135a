"""What a generated PLC program computes, as one function: recorded it is the program,
evaluated in float32 it predicts the PLC.

:func:`program_body` is the whole program for one branch: the arm's closed form, its
refusals (in priority order), the joint limits and the pulse conversion (eqs. 20-22).
:func:`analysis.plc.ir.build_program` records it and lowers the recording to PLC
instructions; :func:`predict` evaluates it with
:class:`~analysis.plc.approx.PlcFloat32Ops` (every REAL operation rounded to float32, the
dialect's ATAN2/ACOS and ROUND/RND), which reproduces what awlsim executes bit for bit
(``tests/plc/test_plc_awlsim.py``), or with the ideal float32 namespace
(:class:`~analysis.kinematics.ops.Float32Ops`: correctly rounded trigonometry) to separate
what REAL arithmetic costs from what the approximations cost.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from analysis.kinematics.arms import closed_form
from analysis.kinematics.ops import Ops
from analysis.kinematics.pulses import pulse_count, pulse_value
from analysis.kinematics.status import Status
from analysis.plc.approx import PlcFloat32Ops

__all__ = ["PLC_TOL_MM", "Prediction", "predict", "program_body"]

PLC_TOL_MM = 1e-6
"""The reach and base-axis tolerance compiled into the programs: the Python default
(:data:`analysis.kinematics.arm.DEFAULT_TOL_MM`)."""


def program_body(m: Ops, params, p, branch: str, *, tol=PLC_TOL_MM, theta1_on_axis=None):
    """The generated program, in namespace ``m``.

    Returns a dict: ``c`` (pulse counts per joint, in ``m``), ``theta`` (the branch's
    angles), ``refusals`` [(Status, condition), ...] in the order the program tests them
    (the closed form's, then its ``branch_refusals`` for this branch, then the joint
    limits).
    """
    cf = closed_form(params.description.closed_form)
    if branch not in cf.BRANCHES:
        raise ValueError(f"unknown branch {branch!r}; expected one of {', '.join(cf.BRANCHES)}")
    opts = {} if theta1_on_axis is None else {"theta1_on_axis": float(theta1_on_axis)}
    sol = cf.ik(m, p, dict(params), tol=tol, **opts)
    q = sol["branches"][branch]
    refusals = list(sol["refusals"]) + list(sol.get("branch_refusals", {}).get(branch, ()))
    limited = [(qj, j) for qj, j in zip(q, params.description.joints, strict=True)]
    limited = [(qj, j) for qj, j in limited if not j.unlimited]
    if limited:
        m.section("joint limits")
        for qj, j in limited:
            refusals.append((Status.JOINT_LIMITS, m.or_(m.lt(qj, j.lower), m.gt(qj, j.upper))))
    ppr = params.pulses_per_rev
    m.section(f"pulses c = ROUND(theta_deg / 360 * {ppr[0]:g}) (eqs. 20-22); reach flag on")
    c = [pulse_count(m, qj, n) for qj, n in zip(q, ppr, strict=True)]
    count = [pulse_value(m, qj, n) for qj, n in zip(q, ppr, strict=True)]  # recorded: shared
    return {"c": c, "count": count, "theta": q, "refusals": refusals}


class Prediction(NamedTuple):
    """A program's outputs predicted for N targets (the PLC's: c unchanged if refused).

    pulses : int64 (N, n) (0 where refused); status : int64 (N,); reachable : bool (N,);
    theta : float32 (N, n) (the REAL joint angles before the pulse conversion);
    counts : float32 (N, n) (the REAL values the program hands to ROUND/RND).
    """

    pulses: npt.NDArray[np.int64]
    status: npt.NDArray[np.int64]
    reachable: npt.NDArray[np.bool_]
    theta: npt.NDArray[np.float32]
    counts: npt.NDArray[np.float32]


def predict(
    params,
    targets: npt.ArrayLike,
    branch: str | None = None,
    *,
    ops: Ops | None = None,
    theta1_on_axis: float | None = None,
) -> Prediction:
    """Evaluate :func:`program_body` for targets (N, k) in single precision.

    ``ops`` defaults to the S7-200 program (``PlcFloat32Ops("s7-200")``); pass
    ``PlcFloat32Ops("s7-300")`` for the S7-300 program with native trigonometry, or
    ``Float32Ops()`` for ideal REAL arithmetic. Targets are rounded to float32 first,
    as writing them into REAL double words does.
    """
    cf = closed_form(params.description.closed_form)
    branch = branch or cf.BRANCHES[0]
    m = ops if ops is not None else PlcFloat32Ops("s7-200")
    t = np.asarray(targets, dtype=np.float32).reshape(-1, len(cf.INPUTS))
    finite = np.isfinite(t).all(axis=1)
    t = np.where(finite[:, None], t, np.float32(0.0))
    with np.errstate(all="ignore"):
        r = program_body(
            m, params, tuple(t[:, k] for k in range(t.shape[1])), branch,
            theta1_on_axis=theta1_on_axis,
        )  # fmt: skip
    status = np.zeros(len(t), dtype=np.int64)
    for code, cond in reversed(r["refusals"]):
        status = np.where(np.broadcast_to(cond, status.shape), int(code), status)
    status = np.where(finite, status, int(Status.INVALID))
    ok = status == 0
    c = np.stack([np.broadcast_to(cj, status.shape) for cj in r["c"]], axis=-1)
    theta = np.stack([np.broadcast_to(q, status.shape) for q in r["theta"]], axis=-1)
    counts = np.stack([np.broadcast_to(v, status.shape) for v in r["count"]], axis=-1)
    pulses = np.where(ok[:, None], c, 0).astype(np.int64)
    return Prediction(pulses, status, ok, theta.astype(np.float32), counts.astype(np.float32))

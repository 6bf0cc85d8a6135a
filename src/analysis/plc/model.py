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

from analysis.kinematics.ops import Ops, numpy_ops
from analysis.kinematics.pulses import pulse_count, pulse_value
from analysis.kinematics.solution import DEFAULT_TOL_MM, refusal_options, status_of
from analysis.kinematics.status import Status
from analysis.plc.approx import PlcFloat32Ops

__all__ = ["PLC_MARGIN_MM", "PLC_MARGIN_RAD", "Prediction", "predict", "program_body"]

PLC_MARGIN_MM = 1e-3
"""The band [mm] the programs refuse inside every reach shell and around every singular set
(the base axis, a wrist on the shoulder). REAL arithmetic puts a distance of ~500 mm within
~1e-4 mm (float32 steps there are 3e-5 mm), so with this band the PLC never accepts a target
that Python (float64, tolerance :data:`analysis.kinematics.solution.DEFAULT_TOL_MM`) refuses,
and it refuses nothing more than 1e-3 mm (plus that error) away from a boundary."""

PLC_MARGIN_RAD = 2e-5
"""The band [rad] the programs take off an arm's angular tolerance (the GR-1's orientation,
whose test value float32 gets within ~1e-7). Joint limits get no band: a pose on a stop is
legitimate (the palletizer's eq. 7 pose has theta3 on its 90 deg stop); there the PLC
decides with its float32 angle, within rounding of the exact one
(:func:`analysis.plc.verify.compare` explains each such case)."""


def program_body(m: Ops, arm, p, branch: str, *, theta1_on_axis=None):
    """The generated program of ``arm`` (:class:`analysis.kinematics.arm.Arm`), in namespace
    ``m``: its closed form solved with the
    refusal band (:data:`PLC_MARGIN_MM`, :data:`PLC_MARGIN_RAD`;
    :func:`~analysis.kinematics.solution.refusal_options`), as
    ``Arm.solve(..., margin_mm=PLC_MARGIN_MM, margin_rad=PLC_MARGIN_RAD)`` does in float64.

    Returns a dict: ``c`` (pulse counts per joint, in ``m``), ``theta`` (the branch's
    angles), ``refusals`` [(Status, condition), ...] in the order the program tests them
    (the closed form's, then its ``branch_refusals`` for this branch, then the joint
    limits).
    """
    cf, params = arm.closed_form, arm.params
    if branch not in arm.branches:
        raise ValueError(f"unknown branch {branch!r}; expected one of {', '.join(arm.branches)}")
    opts = refusal_options(DEFAULT_TOL_MM, PLC_MARGIN_MM, PLC_MARGIN_RAD)
    if theta1_on_axis is not None:
        opts["theta1_on_axis"] = float(theta1_on_axis)
    sol = cf.solve(m, p, dict(params), **opts)
    q = sol.branches[branch]
    refusals = [*sol.refusals, *sol.branch_refusals[branch]]
    joints = arm.description.joints
    bounds = [None if j.unlimited else (j.lower, j.upper) for j in joints]
    limited = [(qj, lim) for qj, lim in zip(q, bounds, strict=True) if lim is not None]
    if limited:
        m.section("joint limits")
        for qj, (lo, hi) in limited:
            refusals.append((Status.JOINT_LIMITS, m.or_(m.lt(qj, lo), m.gt(qj, hi))))
    ppr = params.pulses_per_rev
    lead = [j.lead_mm for j in joints]
    m.section(f"pulses c = ROUND(theta_deg / 360 * {ppr[0]:g}) (eqs. 20-22); reach flag on")
    c = [pulse_count(m, qj, n, s) for qj, n, s in zip(q, ppr, lead, strict=True)]
    count = [pulse_value(m, qj, n, s) for qj, n, s in zip(q, ppr, lead, strict=True)]  # shared
    return {"c": c, "count": count, "theta": q, "refusals": refusals}


class Prediction(NamedTuple):
    """A program's outputs predicted for N targets (the PLC's: c unchanged if refused).

    pulses : int64 (N, n) (0 where refused); status : int64 (N,); reachable : bool (N,);
    theta : float32 (N, n) (the REAL joint angles before the pulse conversion);
    counts : float32 (N, n) (the REAL values the program hands to ROUND/RND);
    computed : int64 (N, n) (the rounded counts, also where the program refuses: what the
    arithmetic gives, meaningful wherever the closed form has a solution).
    """

    pulses: npt.NDArray[np.int64]
    status: npt.NDArray[np.int64]
    reachable: npt.NDArray[np.bool_]
    theta: npt.NDArray[np.float32]
    counts: npt.NDArray[np.float32]
    computed: npt.NDArray[np.int64]


def predict(
    arm,
    targets: npt.ArrayLike,
    branch: str | None = None,
    *,
    ops: Ops | None = None,
    theta1_on_axis: float | None = None,
) -> Prediction:
    """Evaluate :func:`program_body` of ``arm`` for targets (N, k) in single precision.

    ``ops`` defaults to the S7-200 program (``PlcFloat32Ops("s7-200")``); pass
    ``PlcFloat32Ops("s7-300")`` for the S7-300 program with native trigonometry, or
    ``Float32Ops()`` for ideal REAL arithmetic. Targets are rounded to float32 first,
    as writing them into REAL double words does.
    """
    branch = branch or arm.branches[0]
    m = ops if ops is not None else PlcFloat32Ops("s7-200")
    t = np.asarray(targets, dtype=np.float32).reshape(-1, len(arm.inputs))
    finite = np.isfinite(t).all(axis=1)
    t = np.where(finite[:, None], t, np.float32(0.0))
    with np.errstate(all="ignore"):
        r = program_body(
            m, arm, tuple(t[:, k] for k in range(t.shape[1])), branch,
            theta1_on_axis=theta1_on_axis,
        )  # fmt: skip
    status = np.broadcast_to(status_of(numpy_ops, r["refusals"]), len(t)).astype(np.int64)
    status = np.where(finite, status, int(Status.INVALID))
    ok = status == 0
    c = np.stack([np.broadcast_to(cj, status.shape) for cj in r["c"]], axis=-1)
    theta = np.stack([np.broadcast_to(q, status.shape) for q in r["theta"]], axis=-1)
    counts = np.stack([np.broadcast_to(v, status.shape) for v in r["count"]], axis=-1)
    # a refused target's count may be any REAL (a huge one on a joint beyond its limit):
    # only the DINT range is a count
    computed = np.where(np.isfinite(c) & (np.abs(c) < 2.0**31), c, 0).astype(np.int64)
    pulses = np.where(ok[:, None], computed, 0)
    return Prediction(
        pulses, status, ok, theta.astype(np.float32), counts.astype(np.float32), computed
    )

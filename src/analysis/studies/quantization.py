"""What whole stepper pulses (eqs. 20-22) and PLC REAL arithmetic cost at the gripper.

The paper turns each exact joint angle into ``c = round(theta_deg / 360 * 4000)`` pulses
(eqs. 20-22; 4000 pulses/rev = 0.09 deg per pulse, Table 3 and section 3) and claims
"high navigation accuracy ... 0.09 deg per joint" (conclusion 4). Here that is turned
into millimetres at the gripper:

- :func:`quantization_error`: exact IK -> whole pulses -> commanded angles -> FK ->
  distance to the target (the end-point error of rounding), vectorized over (..., 3);
- :func:`worst_case_box`: the largest end-point error when every joint is off by up to
  half a pulse, exactly (over the 8 sign corners of the box) and to first order
  (``sum_j |J[:, j]| h_j``), plus :func:`box_grid_max` to check that the corners hold
  the maximum;
- :func:`joint_shares`, :func:`stats_by_ppr`, :func:`stats_by_length_scale`: where the
  error comes from and how it scales;
- :func:`pulses_float32`: the PLC program's pipeline (:func:`analysis.plc.model.
  program_body`) in IEEE single precision, the S7-200's REAL, to count targets whose pulse
  count changes.

The rounding pipeline is :func:`rounding_body`, one function for numpy
(:func:`quantization_error`) and the compiled kernel (:func:`quantization_map`).

Angles in radians, lengths in mm, pulses as int64.
"""

from __future__ import annotations

import itertools
import math
from functools import cache
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from analysis.kinematics.arm import DEFAULT_TOL_MM, Arm, as_points, check_tol, solve_body
from analysis.kinematics.description import MAX_PULSES_PER_REV
from analysis.kinematics.dh import chain_frames
from analysis.kinematics.ops import Float32Ops, NumpyOps
from analysis.kinematics.pulses import Rounding, pulse_angle, pulse_count

__all__ = [
    "ErrorStats",
    "QuantizationResult",
    "WorstCase",
    "box_grid_max",
    "error_stats",
    "half_step_rad",
    "joint_shares",
    "pulses_float32",
    "quantization_error",
    "quantization_map",
    "stats_by_length_scale",
    "stats_by_ppr",
    "worst_case_box",
]


def _ppr(arm: Arm, pulses_per_rev) -> npt.NDArray[np.float64]:
    """Pulses per revolution per joint (default: the arm's), validated as whole numbers."""
    n = arm.n_joints
    value = arm.params.pulses_per_rev if pulses_per_rev is None else pulses_per_rev
    ppr = np.broadcast_to(np.asarray(value, dtype=float), (n,))
    if not all(v == int(v) and 1 <= v <= MAX_PULSES_PER_REV for v in ppr if np.isfinite(v)) or (
        not np.isfinite(ppr).all()
    ):
        raise ValueError(
            f"pulses_per_rev = {ppr.tolist()} must be {n} whole numbers in "
            f"1 .. {MAX_PULSES_PER_REV:,}"
        )
    return ppr.copy()


def half_step_rad(arm: Arm, pulses_per_rev: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
    """Half a pulse per joint [rad], shape (n,): pi / pulses_per_rev (4000 -> 0.045 deg)."""
    return np.pi / _ppr(arm, pulses_per_rev)


def rounding_body(m, arm: Arm, p, P, ppr, *, branch: str, tol):
    """One target's rounding pipeline, in namespace ``m`` (written once for numpy and the
    compiled kernel): exact IK on ``branch`` -> whole pulses (eqs. 20-22, ``m.round``) ->
    commanded angles -> FK (the chain) -> distance to the target [mm]."""
    r = solve_body(m, arm.closed_form, p, P, (branch,), tol=tol, limits=arm.limits)
    ok = r[f"ok:{branch}"]
    n = arm.n_joints
    q = [m.select(ok, r[f"q:{branch}:{j}"], 0.0) for j in range(n)]
    c = [pulse_count(m, q[j], ppr[j]) for j in range(n)]
    qc = [pulse_angle(m, c[j], ppr[j]) for j in range(n)]
    end = chain_frames(m, arm.description.dh_table(P), qc)[-1]
    d = [end[k] - p[k] for k in range(3)]
    err = m.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
    out = {"ok": ok, "err": m.select(ok, err, math.nan)}
    out.update({f"q{j}": q[j] for j in range(n)})
    out.update({f"c{j}": m.select(ok, c[j], 0.0) for j in range(n)})
    out.update({f"qc{j}": qc[j] for j in range(n)})
    return out


class QuantizationResult(NamedTuple):
    """Rounding of exact IK angles to whole pulses, per target (shapes (...,) or (..., n)).

    ``ok`` marks targets with a solution on the branch; elsewhere angles and error are
    NaN and pulses 0.
    """

    ok: npt.NDArray[np.bool_]
    q_exact: npt.NDArray[np.float64]
    pulses: npt.NDArray[np.int64]
    q_commanded: npt.NDArray[np.float64]
    error_mm: npt.NDArray[np.float64]


def quantization_error(
    arm: Arm,
    p: npt.ArrayLike,
    *,
    branch: str | None = None,
    pulses_per_rev: npt.ArrayLike | None = None,
    rounding: Rounding = "half-away",
    tol: float = DEFAULT_TOL_MM,
) -> QuantizationResult:
    """End-point error [mm] of rounding the exact IK angles to whole pulses (eqs. 20-22).

    Parameters
    ----------
    arm : Arm
    p : array_like, shape (..., 3)
        Targets [mm].
    branch : str
        IK branch (default the paper's, the arm's first).
    pulses_per_rev : array_like of n, optional
        Default ``arm.params.pulses_per_rev`` (Table 3: 4000).
    rounding : {"half-away", "half-even"}
        S7-200 ROUND or S7-300 RND.

    Examples
    --------
    Table 4 row 1, (100, 100, 600) mm: pulses (500, 113, -1724), 0.10 mm off target:

    >>> from analysis.kinematics.arm import paper_arm
    >>> r = quantization_error(paper_arm(), [100, 100, 600])
    >>> r.pulses.tolist(), round(float(r.error_mm), 2)
    ([500, 113, -1724], 0.1)
    """
    p = as_points(p)
    ppr = _ppr(arm, pulses_per_rev)
    branch = arm.branch_names(branch or arm.branches[0])[0]
    with np.errstate(invalid="ignore", divide="ignore"):
        r = rounding_body(
            NumpyOps(rounding), arm, tuple(p[..., k] for k in range(3)), arm.params, ppr,
            branch=branch, tol=check_tol(tol),
        )  # fmt: skip
    shape = p.shape[:-1]
    n = arm.n_joints

    def stack(key):
        return np.stack([np.broadcast_to(r[f"{key}{j}"], shape) for j in range(n)], axis=-1)

    ok = np.broadcast_to(r["ok"], shape).copy()
    q = np.where(ok[..., None], stack("q"), np.nan)
    qc = np.where(ok[..., None], stack("qc"), np.nan)
    err = np.broadcast_to(r["err"], shape).astype(float)
    return QuantizationResult(ok, q, stack("c").astype(np.int64), qc, err)


def quantization_map(
    arm: Arm,
    p: npt.ArrayLike,
    *,
    pulses_per_rev: npt.ArrayLike | None = None,
    tol: float = DEFAULT_TOL_MM,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.bool_]]:
    """Fast rounding error map on the paper's branch: ``(error_mm (...,), pulses (..., n),
    ok (...,))``.

    The numbers of :func:`quantization_error` (the same :func:`rounding_body`, S7-200
    ROUND), compiled into one pass per target (:mod:`analysis.kinematics.compiled`).
    """
    p = as_points(p)
    ppr = _ppr(arm, pulses_per_rev)
    tol = check_tol(tol)
    branch = arm.branches[0]
    n = arm.n_joints
    kern = _rounding_kernel(arm.name, arm.description, tuple(arm.params), branch)
    shape = p.shape[:-1]
    size = int(np.prod(shape, dtype=np.int64))
    ok = np.empty(size, dtype=bool)
    err = np.empty(size)
    pulses = np.empty((n, size), dtype=np.int64)
    kern.run(
        p.reshape(size, 3),
        [*arm.params.values(), *ppr, tol],
        [ok, err, *(pulses[j] for j in range(n))],
    )
    return err.reshape(shape), np.moveaxis(pulses, 0, -1).reshape(*shape, n), ok.reshape(shape)


@cache
def _rounding_kernel(name, description, params: tuple, branch: str):
    from analysis.kinematics import compiled
    from analysis.kinematics.arm import arm_of

    arm = arm_of(description)
    n = arm.n_joints
    cf = arm.closed_form

    def body(m, v):
        p = tuple(v[k] for k in cf.INPUTS)
        P = {k: v[k] for k in params}
        ppr = [v[f"ppr{j}"] for j in range(n)]
        return rounding_body(m, arm, p, P, ppr, branch=branch, tol=v["tol"])

    outputs = {"ok": "b1", "err": "f8", **{f"c{j}": "i8" for j in range(n)}}
    scalars = (*params, *(f"ppr{j}" for j in range(n)), "tol")
    return compiled.build(body, cf.INPUTS, scalars, outputs)


class ErrorStats(NamedTuple):
    """Summary of end-point errors [mm] over the targets that have a solution."""

    n: int
    max_mm: float
    mean_mm: float
    p99_mm: float
    rms_mm: float


def error_stats(error_mm: npt.ArrayLike, ok: npt.ArrayLike | None = None) -> ErrorStats:
    """max, mean, 99th percentile and RMS of errors [mm] where ``ok`` (default: finite)."""
    e = np.asarray(error_mm, dtype=float)
    m = np.isfinite(e) if ok is None else np.asarray(ok, dtype=bool)
    v = e[m]
    if v.size == 0:
        raise ValueError("no target with a solution: error statistics are undefined")
    if not np.isfinite(v).all():
        raise ValueError("errors marked ok contain NaN or inf")
    return ErrorStats(
        int(v.size),
        float(v.max()),
        float(v.mean()),
        float(np.percentile(v, 99)),
        float(np.sqrt((v * v).mean())),
    )


# --- worst case over the +-half-pulse box ----------------------------------------------
class WorstCase(NamedTuple):
    """Largest end-point error [mm] for joint errors |dq_j| <= h_j, per target (...,).

    exact_mm: max over the 8 sign corners of |fk(q + s h) - fk(q)| (the exact maximum
    over the box up to second-order terms; see :func:`box_grid_max`).
    linear_corner_mm: max over the corners of |J (s h)| (first order, attained).
    bound_mm: sum_j |J[:, j]| h_j (first-order triangle-inequality bound).
    """

    exact_mm: npt.NDArray[np.float64]
    linear_corner_mm: npt.NDArray[np.float64]
    bound_mm: npt.NDArray[np.float64]


def _corners(n: int) -> npt.NDArray[np.float64]:
    """The 2^n sign corners of an n-joint box, shape (2^n, n)."""
    return np.array(list(itertools.product((-1.0, 1.0), repeat=n)))


def worst_case_box(arm: Arm, q: npt.ArrayLike, half_step: npt.ArrayLike) -> WorstCase:
    """Worst end-point error when each joint is off by up to ``half_step`` [rad] (n,).

    For this arm |J[:, 1]| = r (distance from the base axis), |J[:, 2]| = D (distance
    from the shoulder) and |J[:, 3]| = L3, so the first-order bound is
    h (r + D + L3): at most 7.854e-4 rad * 1220 mm = 0.958 mm at full reach for
    4000 pulses/rev.

    Parameters
    ----------
    q : array_like, shape (..., 3)
        Joint angles [rad] (finite).
    half_step : array_like, shape (n,)
        Half a pulse per joint [rad], e.g. :func:`half_step_rad`.
    """
    q = np.asarray(q, dtype=float)
    if not np.isfinite(q).all():
        raise ValueError("joint angles contain NaN or inf; pass solved angles only")
    h = np.broadcast_to(np.asarray(half_step, dtype=float), (q.shape[-1],))
    p0 = arm.fk(q)
    J = arm.jacobian(q)
    exact = np.zeros(q.shape[:-1])
    lin = np.zeros(q.shape[:-1])
    for s in _corners(q.shape[-1]):  # loop over the corners, vectorized over targets
        d = s * h
        exact = np.maximum(exact, np.linalg.norm(arm.fk(q + d) - p0, axis=-1))
        lin = np.maximum(lin, np.linalg.norm(J @ d, axis=-1))
    bound = (np.linalg.norm(J, axis=-2) * h).sum(axis=-1)
    return WorstCase(exact, lin, bound)


def box_grid_max(
    arm: Arm, q: npt.ArrayLike, half_step: npt.ArrayLike, m: int = 5
) -> npt.NDArray[np.float64]:
    """max |fk(q + d) - fk(q)| over an m x m x m grid of the box |d_j| <= h_j (faces and
    interior included), per target (...,): the check that the corners hold the maximum."""
    if m < 2:
        raise ValueError(f"m = {m} grid points per joint must be at least 2")
    q = np.asarray(q, dtype=float)
    h = np.broadcast_to(np.asarray(half_step, dtype=float), (q.shape[-1],))
    p0 = arm.fk(q)
    best = np.zeros(q.shape[:-1])
    ticks = np.linspace(-1.0, 1.0, m)
    for s in itertools.product(ticks, repeat=q.shape[-1]):  # box points, vectorized over targets
        best = np.maximum(best, np.linalg.norm(arm.fk(q + np.asarray(s) * h) - p0, axis=-1))
    return best


# --- where the error comes from, how it scales ------------------------------------------
def joint_shares(
    arm: Arm, p: npt.ArrayLike, *, pulses_per_rev: npt.ArrayLike | None = None
) -> dict[str, npt.NDArray[np.float64]]:
    """Each joint's share of the rounding error over targets (..., 3).

    Returns ``{"alone_mean_mm": (n,), "alone_max_mm": (n,), "variance_share": (n,)}``:
    the mean and max end-point error when only joint j is rounded (the others exact), and
    the first-order share of the mean squared error, |J[:, j]|^2 / sum_k |J[:, k]|^2
    averaged over targets (rounding residuals are independent, zero-mean and uniform on
    [-h, h] with equal h, and J's first column is orthogonal to the other two).
    """
    p = as_points(p)
    ppr = _ppr(arm, pulses_per_rev)
    r = quantization_error(arm, p, pulses_per_rev=ppr)
    q = r.q_exact[r.ok]
    qc = r.q_commanded[r.ok]
    target = p[r.ok]
    mean, mx = np.zeros(arm.n_joints), np.zeros(arm.n_joints)
    for j in range(arm.n_joints):  # loop over joints
        qj = q.copy()
        qj[:, j] = qc[:, j]
        e = np.linalg.norm(arm.fk(qj) - target, axis=-1)
        mean[j], mx[j] = e.mean(), e.max()
    col2 = (arm.jacobian(q) ** 2).sum(axis=-2) * (np.pi / ppr) ** 2
    share = (col2 / col2.sum(axis=-1, keepdims=True)).mean(axis=0)
    return {"alone_mean_mm": mean, "alone_max_mm": mx, "variance_share": share}


def stats_by_ppr(arm: Arm, p: npt.ArrayLike, ppr_values) -> dict[int, ErrorStats]:
    """Error statistics over targets ``p`` for each pulses-per-rev value (same for all joints)."""
    out = {}
    for ppr in ppr_values:  # loop over settings
        r = quantization_error(arm, p, pulses_per_rev=(ppr, ppr, ppr))
        out[int(ppr)] = error_stats(r.error_mm, r.ok)
    return out


def stats_by_length_scale(
    arm: Arm, factors, n: int = 200_000, *, seed: int = 0
) -> dict[float, ErrorStats]:
    """Error statistics when L1, L2, L3 are all scaled by each factor, over ``n`` targets
    uniform in each scaled arm's reach shell (same seed, so the same relative targets)."""
    from analysis.studies.workspace import sample_shell

    out = {}
    P = arm.params
    for f in factors:  # loop over settings
        a = arm.with_(L1=P.L1 * f, L2=P.L2 * f, L3=P.L3 * f)
        r = quantization_error(a, sample_shell(a, n, np.random.default_rng(seed)))
        out[float(f)] = error_stats(r.error_mm, r.ok)
    return out


# --- PLC REAL arithmetic -------------------------------------------------------------------
def pulses_float32(
    arm: Arm, p: npt.ArrayLike, *, pulses_per_rev: npt.ArrayLike | None = None
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float32]]:
    """The paper's-branch pipeline of the PLC program in ideal IEEE single precision.

    :func:`analysis.plc.model.predict` with :class:`~analysis.kinematics.ops.Float32Ops`:
    every input, constant and intermediate a float32 (a PLC's REAL), correctly rounded
    trigonometry (the best a PLC's REAL routines could do; the generated S7-200
    subroutines are modelled by ``predict``'s default). The counts are what that arithmetic
    computes, also within the program's refusal band (1e-3 mm inside a reach shell, where the
    program itself would stop); only meaningful where the float64 solution exists.

    Returns
    -------
    pulses : ndarray of int64, shape (..., n)
    theta : ndarray of float32, shape (..., n)
        The float32 joint angles [rad].
    """
    from analysis.plc.model import predict

    p = as_points(p)
    if pulses_per_rev is not None:
        arm = arm.with_(pulses_per_rev=tuple(int(v) for v in _ppr(arm, pulses_per_rev)))
    r = predict(arm, p.reshape(-1, 3), ops=Float32Ops())
    shape = p.shape[:-1]
    return r.computed.reshape(*shape, -1), r.theta.reshape(*shape, -1)

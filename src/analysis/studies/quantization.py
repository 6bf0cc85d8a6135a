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
- :func:`pulses_float32`: the same pipeline in IEEE single precision, the S7-200's REAL
  (stl_reference: REAL = IEEE-754 single), to count targets whose pulse count changes.

Angles in radians, lengths in mm, pulses as int64.
"""

from __future__ import annotations

import itertools
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from analysis.kinematics.arm import DEFAULT_TOL_MM, Arm, as_points
from analysis.kinematics.pulses import Rounding, angles_to_pulses, pulses_to_angles

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
    ppr = np.broadcast_to(
        np.asarray(
            arm.params.pulses_per_rev if pulses_per_rev is None else pulses_per_rev, dtype=float
        ),
        (3,),
    )
    if not (np.isfinite(ppr).all() and (ppr > 0).all()):
        raise ValueError(f"pulses_per_rev = {ppr.tolist()} must be three positive numbers")
    return ppr.copy()


def half_step_rad(arm: Arm, pulses_per_rev: npt.ArrayLike | None = None) -> npt.NDArray[np.float64]:
    """Half a pulse per joint [rad], shape (3,): pi / pulses_per_rev (4000 -> 0.045 deg)."""
    return np.pi / _ppr(arm, pulses_per_rev)


class QuantizationResult(NamedTuple):
    """Rounding of exact IK angles to whole pulses, per target (shapes (...,) or (..., 3)).

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
    branch: str = "front-up",
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
        IK branch (default the paper's front-up).
    pulses_per_rev : array_like of 3, optional
        Default ``arm.params.pulses_per_rev`` (Table 3: 4000).
    rounding : {"half-away", "half-even"}
        S7-200 ROUND or S7-300 RND.

    Examples
    --------
    Table 4 row 1, (100, 100, 600) mm: pulses (500, 113, -1724), 0.10 mm off target:

    >>> r = quantization_error(paper_arm(), [100, 100, 600])
    >>> r.pulses.tolist(), round(float(r.error_mm), 2)
    ([500, 113, -1724], 0.1)
    """
    p = as_points(p)
    ppr = _ppr(arm, pulses_per_rev)
    sol = arm.solve(p, (branch,), tol=tol)
    ok = sol.ok[..., 0]
    q = sol.theta[..., 0, :]
    c = np.where(
        ok[..., None], angles_to_pulses(np.where(ok[..., None], q, 0.0), ppr, rounding=rounding), 0
    )
    qc = np.where(ok[..., None], pulses_to_angles(c, ppr), np.nan)
    err = np.linalg.norm(arm.fk(np.where(ok[..., None], qc, 0.0)) - p, axis=-1)
    return QuantizationResult(ok, q, c, qc, np.where(ok, err, np.nan))


def quantization_map(
    arm: Arm,
    p: npt.ArrayLike,
    *,
    pulses_per_rev: npt.ArrayLike | None = None,
    tol: float = DEFAULT_TOL_MM,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.bool_]]:
    """Fast front-up rounding error map: ``(error_mm (...,), pulses (..., 3), ok (...,))``.

    The same numbers as :func:`quantization_error` (front-up, S7-200 ROUND), computed in
    one compiled pass per target by :func:`analysis.kinematics.fastik.ik_front_up_pulses` (10^6
    targets in well under a second; tests/studies/test_quantization.py holds the two equal).
    """
    from analysis.kinematics.fastik import ik_front_up_pulses

    c, err, ok = ik_front_up_pulses(arm, p, _ppr(arm, pulses_per_rev), tol=tol)
    return err, c, ok


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


_CORNERS = np.array(list(itertools.product((-1.0, 1.0), repeat=3)))  # (8, 3)


def worst_case_box(arm: Arm, q: npt.ArrayLike, half_step: npt.ArrayLike) -> WorstCase:
    """Worst end-point error when each joint is off by up to ``half_step`` [rad] (3,).

    For this arm |J[:, 1]| = r (distance from the base axis), |J[:, 2]| = D (distance
    from the shoulder) and |J[:, 3]| = L3, so the first-order bound is
    h (r + D + L3): at most 7.854e-4 rad * 1220 mm = 0.958 mm at full reach for
    4000 pulses/rev.

    Parameters
    ----------
    q : array_like, shape (..., 3)
        Joint angles [rad] (finite).
    half_step : array_like, shape (3,)
        Half a pulse per joint [rad], e.g. :func:`half_step_rad`.
    """
    q = np.asarray(q, dtype=float)
    if not np.isfinite(q).all():
        raise ValueError("joint angles contain NaN or inf; pass solved angles only")
    h = np.broadcast_to(np.asarray(half_step, dtype=float), (3,))
    p0 = arm.fk(q)
    J = arm.jacobian(q)
    exact = np.zeros(q.shape[:-1])
    lin = np.zeros(q.shape[:-1])
    for s in _CORNERS:  # loop over the 8 corners, vectorized over targets
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
    h = np.broadcast_to(np.asarray(half_step, dtype=float), (3,))
    p0 = arm.fk(q)
    best = np.zeros(q.shape[:-1])
    ticks = np.linspace(-1.0, 1.0, m)
    for s in itertools.product(ticks, repeat=3):  # loop over box points, vectorized over targets
        best = np.maximum(best, np.linalg.norm(arm.fk(q + np.asarray(s) * h) - p0, axis=-1))
    return best


# --- where the error comes from, how it scales ------------------------------------------
def joint_shares(
    arm: Arm, p: npt.ArrayLike, *, pulses_per_rev: npt.ArrayLike | None = None
) -> dict[str, npt.NDArray[np.float64]]:
    """Each joint's share of the rounding error over targets (..., 3).

    Returns ``{"alone_mean_mm": (3,), "alone_max_mm": (3,), "variance_share": (3,)}``:
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
    mean, mx = np.zeros(3), np.zeros(3)
    for j in range(3):  # loop over joints
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
        a = Arm(P.with_(L1=P.L1 * f, L2=P.L2 * f, L3=P.L3 * f))
        r = quantization_error(a, sample_shell(a, n, np.random.default_rng(seed)))
        out[float(f)] = error_stats(r.error_mm, r.ok)
    return out


# --- PLC REAL arithmetic -------------------------------------------------------------------
def pulses_float32(
    arm: Arm, p: npt.ArrayLike, *, pulses_per_rev: npt.ArrayLike | None = None
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float32]]:
    """The front-up pipeline (corrected eqs. 6-22) in IEEE single precision, step by step.

    Every input, constant and intermediate is a float32 (the S7-200 REAL), in the order a
    PLC program computes them, following the paper's Figures 4-6 where they are sound::

        t1  = atan2(Py, Px)                      (eq. 6; Fig. 4 divides, then ARCTAN)
        r   = cos(t1) Px + sin(t1) Py            (eq. 7; Fig. 5 uses COS/SIN of t1)
        z   = Pz - L1                            (eq. 8)
        c3  = (r r + z z - L2 L2 - L3 L3) / (2 L2 L3), clipped to [-1, 1]   (eqs. 9-10)
        t3  = -acos(c3)
        k   = L2 cos t3 + L3,  s = L2 sin t3
        t23 = atan2(z k + r s, r k - z s);  t2 = t23 - t3 wrapped   (eqs. 18-19)
        c   = ROUND(t * (180/pi) / 360 * ppr)    (eqs. 20-22, half away from zero)

    numpy's float32 ``arctan2``/``arccos``/``cos``/``sin`` are correctly rounded-ish single
    precision library functions, i.e. the best a PLC's REAL subroutines could do; the
    S7-200 has no ARCTAN/ARCCOS instruction and a series subroutine is likely worse.

    Only meaningful where the float64 front-up solution exists; other targets still get
    numbers (no NaN: c3 is clipped), so mask them with ``arm.solve(...).ok``.

    Returns
    -------
    pulses : ndarray of int64, shape (..., 3)
    theta : ndarray of float32, shape (..., 3)
        The float32 joint angles [rad].
    """
    p = as_points(p)
    f = np.float32
    ppr = _ppr(arm, pulses_per_rev).astype(f)
    x, y, pz = (p[..., k].astype(f) for k in range(3))
    L1, L2, L3 = f(arm.params.L1), f(arm.params.L2), f(arm.params.L3)
    pi = f(np.pi)
    t1 = np.arctan2(y, x)
    r = np.cos(t1) * x + np.sin(t1) * y
    z = pz - L1
    c3 = (r * r + z * z - L2 * L2 - L3 * L3) / (f(2.0) * L2 * L3)
    c3 = np.clip(c3, f(-1.0), f(1.0))
    t3 = -np.arccos(c3)
    k = L2 * np.cos(t3) + L3
    s = L2 * np.sin(t3)
    t23 = np.arctan2(z * k + r * s, r * k - z * s)
    t2 = t23 - t3
    t2 = np.where(t2 > pi, t2 - f(2.0) * pi, np.where(t2 <= -pi, t2 + f(2.0) * pi, t2)).astype(f)
    theta = np.stack([t1, t2, t3], axis=-1).astype(f)
    deg = theta * f(180.0 / np.pi)
    exact = deg / f(360.0) * ppr
    assert exact.dtype == np.float32
    whole = np.trunc(
        exact
    )  # ROUND, half away from zero, as analysis.kinematics.pulses.round_half_away
    pulses = (whole + np.where(np.abs(exact - whole) >= f(0.5), np.sign(exact), f(0.0))).astype(
        np.int64
    )
    return pulses, theta

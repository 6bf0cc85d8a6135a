"""The paper's 3R waist/shoulder/elbow arm: FK, closed-form IK (all branches), Jacobian.

Geometry (Table 1 / Table 3, standard D-H): the waist turns about the vertical base axis;
the shoulder sits on that axis at height L1; the upper arm (L2) and forearm (L3) move in
the vertical arm plane at azimuth theta1. Angles in radians, lengths in mm.

Branches
--------
Four solutions exist for a reachable target off the base axis:

============  ====================================  =========================================
name          theta1                                elbow
============  ====================================  =========================================
front-up      atan2(Py, Px)  (the paper, eq. 6)     above the shoulder-wrist line: theta3 < 0
front-down    atan2(Py, Px)                         below: theta3 > 0
back-up       atan2(Py, Px) + pi (wrapped)          above: theta3 > 0
back-down     atan2(Py, Px) + pi (wrapped)          below: theta3 < 0
============  ====================================  =========================================

"front-up" is the paper's choice (eq. 6 and Table 4's negative elbow angles). In the back
branches the arm reaches over the base axis, so the elbow sign flips for the same
physical elbow-up posture.

Corrected closed form (see the errata register for what the paper printed)::

    theta1 = atan2(Py, Px)                                      (eq. 6, with atan2)
    r      = cos(theta1) Px + sin(theta1) Py   (= +rho front, -rho back)   (eq. 7)
    z      = Pz - L1                                                       (eq. 8)
    cos(theta3) = (r^2 + z^2 - L2^2 - L3^2) / (2 L2 L3)                    (eqs. 9-10)
    theta3 = -/+ acos(...)                       (eq. 10 gives only the + branch)
    theta23 = atan2(z (L2 cos theta3 + L3) + r L2 sin theta3,
                    r (L2 cos theta3 + L3) - z L2 sin theta3)          (eqs. 15-18, atan2)
    theta2 = theta23 - theta3                                              (eq. 19)
"""

from __future__ import annotations

import enum
from collections.abc import Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from analysis.kinematics.params import ArmParams, paper_params

__all__ = [
    "BRANCHES",
    "DEFAULT_TOL_MM",
    "Arm",
    "BaseAxisError",
    "IKSolutions",
    "Status",
    "UnreachableError",
    "as_points",
    "paper_arm",
]

BRANCHES: tuple[str, ...] = ("front-up", "front-down", "back-up", "back-down")
DEFAULT_TOL_MM = 1e-6
"""Default distance tolerance [mm]: targets this close outside the reach shell are put on
the shell (cos theta3 clipped to +-1), and targets this close to the base axis count as on
it. 1 nm is far below any mechanical meaning and far above float64 round-off at this
scale (|p| ~ 1e3 mm, eps * |p| ~ 2e-13 mm)."""

_BRANCH_SIGNS = {  # (sign of r = front/back, sign of theta3 relative to -r: up/down)
    "front-up": (1.0, 1.0),
    "front-down": (1.0, -1.0),
    "back-up": (-1.0, 1.0),
    "back-down": (-1.0, -1.0),
}


class Status(enum.IntEnum):
    """Why a target has (or has no) solution, per target in batch results."""

    OK = 0
    OUT_OF_REACH = 1  # farther than L2 + L3 from the shoulder
    INSIDE_REACH = 2  # nearer than |L2 - L3| to the shoulder
    BASE_AXIS = 3  # on the waist axis: theta1 undefined (reachable, but caller must choose)


class UnreachableError(ValueError):
    """The target lies outside the reachable shell; ``distance_mm`` says how far."""

    def __init__(self, message: str, target, distance_mm: float, limit_mm: float):
        super().__init__(message)
        self.target = tuple(float(v) for v in target)
        self.distance_mm = float(distance_mm)
        self.limit_mm = float(limit_mm)


class BaseAxisError(ValueError):
    """The target is on the base (waist) axis, where theta1 is undefined."""

    def __init__(self, message: str, target):
        super().__init__(message)
        self.target = tuple(float(v) for v in target)


class IKSolutions(NamedTuple):
    """Batch IK result for targets of shape (..., 3) and B branches.

    Attributes
    ----------
    theta : ndarray, shape (..., B, 3)
        Joint angles [rad], wrapped to (-pi, pi]. NaN exactly where ``ok`` is False.
    ok : ndarray of bool, shape (..., B)
        True where the branch has a solution.
    status : ndarray of int, shape (...,)
        :class:`Status` code per target.
    outside_mm : ndarray, shape (...,)
        Signed distance outside the reachable shell [mm]: > 0 unreachable (by that
        much), <= 0 reachable (its magnitude is the margin to the nearer boundary).
    branches : tuple of str
        Branch names along axis -2 of ``theta``.
    """

    theta: npt.NDArray[np.float64]
    ok: npt.NDArray[np.bool_]
    status: npt.NDArray[np.int8]
    outside_mm: npt.NDArray[np.float64]
    branches: tuple[str, ...]

    @property
    def reachable(self) -> npt.NDArray[np.bool_]:
        """Targets inside the reachable shell within the tolerance ``solve`` used (base-axis
        targets included): consistent with ``status`` and ``ok``. (``outside_mm <= 0``
        would call a target 5e-7 mm outside "unreachable" although it is solved.)"""
        return (self.status != Status.OUT_OF_REACH) & (self.status != Status.INSIDE_REACH)

    def branch(self, name: str) -> npt.NDArray[np.float64]:
        """Angles of one branch, shape (..., 3)."""
        return self.theta[..., self.branches.index(name), :]


def as_points(p: npt.ArrayLike, name: str = "target") -> npt.NDArray[np.float64]:
    """Validate and convert targets to a float array of shape (..., 3) [mm].

    Raises ``ValueError`` naming the offending value for text, wrong shapes, NaN or inf.
    """
    try:
        arr = np.asarray(p, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} {p!r} is not numeric: {exc}") from None
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(f"{name} has shape {arr.shape}; expected (..., 3) = (x, y, z) in mm")
    bad = ~np.isfinite(arr)
    if bad.any():
        idx = np.argwhere(bad)[0]
        where = "" if arr.ndim == 1 else f" at index {tuple(int(i) for i in idx[:-1])}"
        raise ValueError(
            f"{name}{where} has a non-finite coordinate: {arr[tuple(idx[:-1])].tolist()}"
        )
    return arr


def _wrap(angle: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Wrap to (-pi, pi]."""
    out = np.mod(angle + np.pi, 2.0 * np.pi) - np.pi
    return np.where(out == -np.pi, np.pi, out)


def _mm(distance: float) -> str:
    """3 decimals, or 3 significant digits below 1e-3 mm (never "0.000 mm beyond")."""
    return f"{distance:.3f}" if abs(distance) >= 1e-3 else f"{distance:.3g}"


def _fmt(p) -> str:
    return "(" + ", ".join(f"{v:g}" for v in np.asarray(p, dtype=float)) + ")"


@dataclass(frozen=True)
class Arm:
    """The paper's arm with parameters ``params`` (Table 3 by default: :func:`paper_arm`)."""

    params: ArmParams

    # --- geometry -------------------------------------------------------------------
    @property
    def shoulder(self) -> npt.NDArray[np.float64]:
        """Shoulder point (0, 0, L1) [mm], centre of the reachable shell."""
        return np.array([0.0, 0.0, self.params.L1])

    def fk(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Gripper point for joint angles: the P column of eq. 2, T3 = A1 A2 A3.

        Parameters
        ----------
        q : array_like, shape (..., 3)
            (theta1, theta2, theta3) [rad].

        Returns
        -------
        ndarray, shape (..., 3)
            (Px, Py, Pz) [mm].

        Examples
        --------
        Table 4 row 1, corrected angles (45, 10.21, -155.13) deg, lands on (100, 100, 600):

        >>> paper_arm().fk(np.radians([45.0, 10.2087, -155.1291])).round(2).tolist()
        [100.0, 100.0, 600.0]
        """
        q = np.asarray(q, dtype=float)
        if q.ndim == 0 or q.shape[-1] != 3:
            raise ValueError(f"joint array has shape {q.shape}; expected (..., 3)")
        L1, L2, L3 = self.params.L1, self.params.L2, self.params.L3
        t1, t2, t3 = q[..., 0], q[..., 1], q[..., 2]
        t23 = t2 + t3
        r = L2 * np.cos(t2) + L3 * np.cos(t23)
        return np.stack(
            [np.cos(t1) * r, np.sin(t1) * r, L1 + L2 * np.sin(t2) + L3 * np.sin(t23)], axis=-1
        )

    def elbow(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Elbow point (origin of frame 2) [mm], shape (..., 3)."""
        q = np.asarray(q, dtype=float)
        t1, t2 = q[..., 0], q[..., 1]
        r = self.params.L2 * np.cos(t2)
        return np.stack(
            [np.cos(t1) * r, np.sin(t1) * r, self.params.L1 + self.params.L2 * np.sin(t2)], axis=-1
        )

    def jacobian(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Positional Jacobian dP/dq [mm/rad], shape (..., 3, 3); column j is dP/dtheta_j.

        Derivative of eq. 2's P column. Singular on the base axis (r = 0) and with the
        elbow stretched or folded (sin theta3 = 0): det J = -L2 L3 sin(theta3) r
        with r = L2 cos(theta2) + L3 cos(theta2 + theta3) (checked in sympy by the tests).
        """
        q = np.asarray(q, dtype=float)
        L2, L3 = self.params.L2, self.params.L3
        t1, t2, t3 = q[..., 0], q[..., 1], q[..., 2]
        t23 = t2 + t3
        c1, s1 = np.cos(t1), np.sin(t1)
        r = L2 * np.cos(t2) + L3 * np.cos(t23)
        h = L2 * np.sin(t2) + L3 * np.sin(t23)
        zero = np.zeros_like(r)
        cols = [
            np.stack([-s1 * r, c1 * r, zero], axis=-1),
            np.stack([-c1 * h, -s1 * h, r], axis=-1),
            np.stack([-c1 * L3 * np.sin(t23), -s1 * L3 * np.sin(t23), L3 * np.cos(t23)], axis=-1),
        ]
        return np.stack(cols, axis=-1)

    # --- reach -----------------------------------------------------------------------
    def outside_distance(self, p: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Signed distance [mm] of targets outside the reachable shell (> 0: unreachable).

        The shell is centred on the shoulder (0, 0, L1), radii |L2 - L3| and L2 + L3.
        """
        p = as_points(p)
        D = np.linalg.norm(p - self.shoulder, axis=-1)
        return np.maximum(D - self.params.reach_outer, self.params.reach_inner - D)

    def is_reachable(self, p: npt.ArrayLike, tol: float = DEFAULT_TOL_MM) -> npt.NDArray[np.bool_]:
        """Mask of targets within ``tol`` mm of the reachable shell (..., )."""
        return self.outside_distance(p) <= tol

    # --- inverse kinematics ----------------------------------------------------------
    def solve(
        self,
        p: npt.ArrayLike,
        branches: str | Sequence[str] = BRANCHES,
        *,
        theta1_on_axis: npt.ArrayLike | None = None,
        tol: float = DEFAULT_TOL_MM,
    ) -> IKSolutions:
        """Batch closed-form IK (corrected eqs. 6-19); never raises for unreachable targets.

        Parameters
        ----------
        p : array_like, shape (..., 3)
            Targets [mm].
        branches : str or sequence of str
            Branch names (see module docstring) or ``"all"``.
        theta1_on_axis : array_like, optional
            Waist angle [rad] to use for targets on the base axis (broadcast against
            ``p[..., 0]``). Without it such targets get ``Status.BASE_AXIS`` and no solution.
        tol : float
            Distance tolerance [mm] for the reach shell and the base axis.

        Returns
        -------
        IKSolutions
        """
        names = _branch_names(branches)
        p = as_points(p)
        _check_options(theta1_on_axis, tol)
        L1, L2, L3 = self.params.L1, self.params.L2, self.params.L3
        x, y = p[..., 0], p[..., 1]
        z, rho, D, D2 = _distances(p, L1)
        on_axis = rho <= tol
        phi = np.arctan2(y, x)
        if theta1_on_axis is not None:
            phi = np.where(on_axis, np.asarray(theta1_on_axis, dtype=float), phi)
        outside = np.maximum(D - (L2 + L3), abs(L2 - L3) - D)
        status = np.full(p.shape[:-1], Status.OK, dtype=np.int8)
        status[on_axis & (theta1_on_axis is None)] = Status.BASE_AXIS
        status[D - (L2 + L3) > tol] = Status.OUT_OF_REACH
        status[abs(L2 - L3) - D > tol] = Status.INSIDE_REACH

        c3 = np.clip((D2 - L2 * L2 - L3 * L3) / (2.0 * L2 * L3), -1.0, 1.0)  # eqs. 9-10
        t3_mag = np.arccos(c3)
        rsign, usign = (np.array([_BRANCH_SIGNS[n][k] for n in names]) for k in (0, 1))
        # broadcast targets (..., 1) against branches (B,)
        r = rsign * rho[..., None]
        t1 = _wrap(phi[..., None] + np.where(rsign > 0, 0.0, np.pi))
        t3 = _wrap(-usign * rsign * t3_mag[..., None])  # folded elbow: -pi -> pi
        zb = z[..., None]
        k = L2 * np.cos(t3) + L3
        s = L2 * np.sin(t3)
        t23 = np.arctan2(zb * k + r * s, r * k - zb * s)  # eq. 18 with atan2
        t2 = _wrap(t23 - t3)  # eq. 19
        theta = np.stack(np.broadcast_arrays(t1, t2, t3), axis=-1)
        ok = np.broadcast_to((status == Status.OK)[..., None], theta.shape[:-1]).copy()
        theta[~ok] = np.nan
        return IKSolutions(theta, ok, status, outside, names)

    def ik(
        self,
        p: npt.ArrayLike,
        branch: str = "front-up",
        *,
        theta1_on_axis: float | None = None,
        tol: float = DEFAULT_TOL_MM,
    ) -> npt.NDArray[np.float64]:
        """Closed-form IK for one target and one branch; raises on bad targets.

        Parameters
        ----------
        p : array_like, shape (3,)
            Target (Px, Py, Pz) [mm].
        branch : str
            One of :data:`BRANCHES`; the default is the paper's front-up.
        theta1_on_axis : float, optional
            Waist angle [rad] to use if the target is on the base axis.

        Returns
        -------
        ndarray, shape (3,)
            (theta1, theta2, theta3) [rad].

        Raises
        ------
        UnreachableError
            The target is outside the reachable shell; the message says by how much.
        BaseAxisError
            The target is on the base axis and ``theta1_on_axis`` was not given.

        Examples
        --------
        Table 4 row 1 (100, 100, 600) mm -> (45.00, 10.21, -155.13) deg; the paper prints
        190.20 for theta2 (see the errata register):

        >>> np.degrees(paper_arm().ik([100, 100, 600])).round(2).tolist()
        [45.0, 10.21, -155.13]
        """
        if branch not in BRANCHES:
            raise ValueError(f"unknown branch {branch!r}; expected one of {', '.join(BRANCHES)}")
        return self.ik_all(p, theta1_on_axis=theta1_on_axis, tol=tol, branches=(branch,))[branch]

    def ik_all(
        self,
        p: npt.ArrayLike,
        *,
        theta1_on_axis: float | None = None,
        tol: float = DEFAULT_TOL_MM,
        branches: Sequence[str] = BRANCHES,
    ) -> dict[str, npt.NDArray[np.float64]]:
        """All IK solutions of one target, ``{branch: (theta1, theta2, theta3)}`` [rad].

        Raises like :meth:`ik`. On the base axis with ``theta1_on_axis`` given, the
        "back" branches use theta1_on_axis + pi.
        """
        p = as_points(p)
        if p.shape != (3,):
            raise ValueError(
                f"ik takes one target of shape (3,), got {p.shape}; use solve() for batches"
            )
        self.check_target(p, tol=tol, allow_axis=theta1_on_axis is not None)
        sol = self.solve(p, branches, theta1_on_axis=theta1_on_axis, tol=tol)
        return {name: sol.theta[i] for i, name in enumerate(sol.branches)}

    def check_target(
        self, p: npt.ArrayLike, *, tol: float = DEFAULT_TOL_MM, allow_axis: bool = False
    ) -> None:
        """Raise :class:`UnreachableError` or :class:`BaseAxisError` for one bad target."""
        p = as_points(p)
        _check_options(None, tol)
        P = self.params
        _, rho, D, _ = (float(v) for v in _distances(p, P.L1))  # exactly as solve() decides
        sh = _fmt(self.shoulder)
        if D - P.reach_outer > tol:
            raise UnreachableError(
                f"target {_fmt(p)} mm is {_mm(D - P.reach_outer)} mm beyond the reach of "
                f"{P.reach_outer:g} mm (L2 + L3) around the shoulder at {sh} mm "
                f"(it is {D:.3f} mm away)",
                p,
                D - P.reach_outer,
                P.reach_outer,
            )
        if P.reach_inner - D > tol:
            raise UnreachableError(
                f"target {_fmt(p)} mm is {_mm(P.reach_inner - D)} mm inside the inner reach "
                f"radius of {P.reach_inner:g} mm (|L2 - L3|) around the shoulder at {sh} mm "
                f"(it is {D:.3f} mm away)",
                p,
                P.reach_inner - D,
                P.reach_inner,
            )
        if rho <= tol and not allow_axis:
            raise BaseAxisError(
                f"target {_fmt(p)} mm lies on the base axis (distance {rho:.3g} mm <= tolerance "
                f"{tol:g} mm): theta1 is undefined there; choose it with theta1_on_axis "
                f"(CLI: --theta1-on-axis DEG)",
                p,
            )


def _distances(p: npt.NDArray[np.float64], L1: float):
    """``(z, rho, D, D^2)`` of targets relative to the shoulder: z = Pz - L1 (eq. 8),
    rho = |(Px, Py)|, D = |(rho, z)|.

    The squares are summed directly (no hypot) because eqs. 9-10 need D^2, not a rounded
    D squared again; :mod:`analysis.kinematics.fastik` repeats these operations bit for bit, and
    :meth:`Arm.check_target` uses them so that it and :meth:`Arm.solve` always agree.
    """
    x, y, z = p[..., 0], p[..., 1], p[..., 2] - L1
    rho2 = x * x + y * y
    D2 = rho2 + z * z
    return z, np.sqrt(rho2), np.sqrt(D2), D2


def _check_options(theta1_on_axis, tol) -> None:
    """Reject options that would otherwise turn into silent NaN or wrong statuses."""
    if not (
        isinstance(tol, (int, float, np.floating, np.integer)) and np.isfinite(tol) and tol >= 0
    ):
        raise ValueError(f"tol = {tol!r} mm: the tolerance must be a finite number >= 0 mm")
    if theta1_on_axis is not None:
        t = np.asarray(theta1_on_axis, dtype=float)
        if not np.isfinite(t).all():
            raise ValueError(f"theta1_on_axis = {theta1_on_axis!r} rad is not finite")


def _branch_names(branches: str | Sequence[str]) -> tuple[str, ...]:
    if isinstance(branches, str):
        branches = BRANCHES if branches == "all" else (branches,)
    names = tuple(branches)
    unknown = [b for b in names if b not in BRANCHES]
    if unknown or not names:
        raise ValueError(
            f"unknown branch {unknown or names!r}; expected 'all' or from {', '.join(BRANCHES)}"
        )
    return names


def paper_arm() -> Arm:
    """The arm of the paper, parameters from ``data/table3.csv``."""
    return Arm(paper_params())

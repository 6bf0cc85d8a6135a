"""The companion papers: a 4-axis palletizer (seed 001), screw theory (seed 002) and cubic
joint trajectories (seed 004), each tied back to the main paper's arm.

Seed 001 (Li & Hu 2021, palletizer, geometric IK)
    Modified D-H table ``data/palletizer_mdh.csv`` (eq. 8 and the five matrices before
    eq. 9; lengths illustrative, the paper gives none). The shoulder is at the base
    origin (L0 = 0), the L-shaped gripper reaches L3 forward and h down and stays
    parallel to the base (theta5 = 0). Corrected geometric IK, with ``rho = hypot(X0, Y0)``::

        gamma  = atan2(Y0, X0)                                (eqs. 1 and 6, corrected)
        L4     = hypot(rho - L3, Z0 + h)                      (eq. 2)
        alpha1 = acos((L1^2 + L4^2 - L2^2) / (2 L1 L4))       (eq. 3)
        alpha2 = atan2(Z0 + h, rho - L3)                      (eq. 3 printed arcsin)
        beta1  = acos((L1^2 + L2^2 - L4^2) / (2 L1 L2))       (eq. 3, "acos" lost in print)
        alpha  = alpha1 + alpha2 - pi/2,  beta = pi/2 - beta1 (eq. 4, sign of alpha fixed)
        theta  = alpha - beta                                 (eq. 5 printed -alpha + beta)
        theta1..4 = gamma, -pi/2 - alpha, pi/2 + beta, pi/2 - (theta2 + theta3)   (eq. 12)

    :func:`palletizer_ik_printed` evaluates the formulas as printed, for counterexamples.
Seed 002 (screw theory, product of exponentials)
    ``T(q) = exp([S1] q1) exp([S2] q2) exp([S3] q3) M`` with the screw axes of the main
    paper's arm (Table 3) read off its home configuration q = 0: :func:`screw_axes`.
Seed 004 (handling arm, section 5.4.1, eqs. 5.1-5.7)
    Cubic ``q(t) = a0 + a1 t + a2 t^2 + a3 t^3`` with q(0)=q0, q(T)=qf, zero end
    velocities: a0 = q0, a1 = 0, a2 = 3 (qf-q0)/T^2, a3 = -2 (qf-q0)/T^3. Defined in
    :mod:`analysis.studies.trajectories` (``cubic_coefficients``, ``cubic_trajectory``,
    ``peak_pulse_rates``, ``trajectory_pulses``), imported here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from analysis.kinematics.arm import as_points
from analysis.kinematics.dh import DHTable
from analysis.kinematics.params import ArmParams, data_dir, paper_params
from analysis.studies.trajectories import (
    cubic_coefficients,
    cubic_trajectory,
    peak_pulse_rates,
    trajectory_pulses,
)

__all__ = [
    "PRINTED_FORMULAS",
    "Palletizer",
    "cubic_coefficients",
    "cubic_trajectory",
    "exp_twist",
    "gamma_printed",
    "load_palletizer",
    "palletizer_ik_printed",
    "peak_pulse_rates",
    "poe_fk",
    "screw_axes",
    "trajectory_pulses",
]

_EXPECTED_ALPHA_DEG = (0.0, -90.0, 0.0, 0.0, 90.0)


# --------------------------------------------------------------------------- seed 001
@dataclass(frozen=True)
class Palletizer:
    """The seed-001 palletizer: modified D-H chain theta1..theta4 plus the fixed tool row.

    Lengths [mm] are read from the table: L1 = a_2, L2 = a_3, h = a_4 (tool row a),
    L3 = d_5 (tool row d); the shoulder height is d_1 (0 in the paper, L0 = 0).
    """

    table: DHTable

    def __post_init__(self) -> None:
        rows = self.table.rows
        if self.table.convention != "modified" or len(rows) != 5 or self.table.n_joints != 4:
            raise ValueError(
                f"palletizer table must be modified D-H with 4 revolute rows and 1 fixed tool "
                f"row; got {self.table.convention!r} with {len(rows)} rows"
            )
        alphas = tuple(round(math.degrees(r.alpha), 9) for r in rows)
        if alphas != _EXPECTED_ALPHA_DEG or rows[4].kind != "fixed":
            raise ValueError(f"palletizer twists {alphas} deg; expected {_EXPECTED_ALPHA_DEG}")
        for name, value in (("L1", self.L1), ("L2", self.L2), ("h", self.h), ("L3", self.L3)):
            if not value > 0:
                raise ValueError(f"palletizer {name} = {value} mm must be > 0")

    L1 = property(lambda self: self.table.rows[2].a)
    L2 = property(lambda self: self.table.rows[3].a)
    h = property(lambda self: self.table.rows[4].a)
    L3 = property(lambda self: self.table.rows[4].d)
    z0 = property(lambda self: self.table.rows[0].d)

    def fk(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Gripper tip (t14, t24, t34 of eqs. 10-11) [mm], (..., 3), for D-H q (..., 4) [rad]."""
        return self.table.fk(q)[..., :3, 3]

    def motor_angles(self, target: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Corrected geometric IK (eqs. 1-6): motor angles (gamma, alpha, beta, theta) [rad].

        Parameters
        ----------
        target : array_like, shape (..., 3)
            Grasp point G = (X0, Y0, Z0) [mm] in the base frame.

        Returns
        -------
        ndarray, shape (..., 4)
            Rotations from the initial pose (upper arm vertical, forearm horizontal), in
            eq. 12's sign convention. Elbow above the shoulder-wrist line (section 2).

        Raises
        ------
        ValueError
            If a target is on the base axis (gamma undefined) or L4 is outside
            [|L1 - L2|, L1 + L2].
        """
        p = as_points(target)
        rho = np.hypot(p[..., 0], p[..., 1])
        if np.any(rho == 0.0):
            raise ValueError("target on the base axis (X0 = Y0 = 0): gamma is undefined")
        w, zw = rho - self.L3, p[..., 2] + self.h - self.z0
        L4 = np.hypot(w, zw)
        lo, hi = abs(self.L1 - self.L2), self.L1 + self.L2
        if np.any(L4 == 0.0):
            raise ValueError("L4 = 0 mm: the wrist is on the shoulder, alpha is undefined")
        bad = (L4 > hi * (1 + 1e-12)) | (L4 < lo * (1 - 1e-12))
        if np.any(bad):
            k = np.argwhere(np.atleast_1d(bad))[0]
            value = float(np.atleast_1d(L4)[tuple(k)])
            raise ValueError(f"L4 = {value:.3f} mm is outside the reach [{lo:g}, {hi:g}] mm")
        L1, L2 = self.L1, self.L2
        alpha1 = np.arccos(np.clip((L1**2 + L4**2 - L2**2) / (2 * L1 * L4), -1, 1))
        alpha2 = np.arctan2(zw, w)
        beta1 = np.arccos(np.clip((L1**2 + L2**2 - L4**2) / (2 * L1 * L2), -1, 1))
        alpha = alpha1 + alpha2 - np.pi / 2
        beta = np.pi / 2 - beta1
        gamma = np.arctan2(p[..., 1], p[..., 0])
        return np.stack([gamma, alpha, beta, alpha - beta], axis=-1)

    def ik(self, target: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """D-H joint angles (theta1..theta4) [rad], (..., 4), for targets (..., 3) [mm].

        :meth:`motor_angles` converted with eq. 12, corrected to the keep-level form
        theta4 = pi/2 - (theta2 + theta3) = pi/2 + theta.
        """
        gamma, alpha, beta, theta = np.moveaxis(self.motor_angles(target), -1, 0)
        return np.stack([gamma, -np.pi / 2 - alpha, np.pi / 2 + beta, np.pi / 2 + theta], -1)


def load_palletizer(path: str | Path | None = None) -> Palletizer:
    """The palletizer of ``data/palletizer_mdh.csv`` (seed 001, illustrative lengths)."""
    path = Path(path) if path is not None else data_dir() / "palletizer_mdh.csv"
    return Palletizer(DHTable.from_csv(path, "modified"))


def gamma_printed(x0: npt.ArrayLike, y0: npt.ArrayLike, reading: str = "signed"):
    """Waist angle by eqs. 1 and 6 exactly as printed [rad].

    ``reading="signed"`` takes gamma' = arctan(Y0/X0); ``"abs"`` takes the acute angle
    arctan(|Y0/X0|). Eq. 6: gamma' if X0 > 0; pi - gamma' if X0 <= 0, Y0 > 0;
    -pi/2 + gamma' if X0 <= 0, Y0 < 0. Cases eq. 6 does not cover (X0 <= 0, Y0 = 0) and
    X0 = 0 (division by zero in eq. 1) raise ValueError.
    """
    x0, y0 = np.broadcast_arrays(np.asarray(x0, float), np.asarray(y0, float))
    if np.any(x0 == 0) or np.any((x0 < 0) & (y0 == 0)):
        raise ValueError("eqs. 1 and 6 are undefined for X0 = 0 or (X0 < 0, Y0 = 0)")
    if reading not in ("signed", "abs"):
        raise ValueError(f"unknown reading {reading!r}; expected 'signed' or 'abs'")
    g = np.arctan(y0 / x0) if reading == "signed" else np.arctan(np.abs(y0 / x0))
    return np.where(x0 > 0, g, np.where(y0 > 0, np.pi - g, -np.pi / 2 + g))


PRINTED_FORMULAS = ("gamma", "alpha2", "alpha", "theta4")


def palletizer_ik_printed(
    pal: Palletizer, target: npt.ArrayLike, printed=PRINTED_FORMULAS
) -> npt.NDArray[np.float64]:
    """D-H angles (..., 4) [rad] with the named formulas taken as printed (counterexamples).

    ``printed`` is a subset of :data:`PRINTED_FORMULAS`; the others use the corrected form:

    - "gamma": eqs. 1 and 6, :func:`gamma_printed` (signed) instead of atan2(Y0, X0);
    - "alpha2": eq. 3 arcsin((Z0 + h)/L4) instead of atan2(Z0 + h, rho - L3);
    - "alpha": eq. 4 pi/2 - alpha1 + alpha2 instead of alpha1 + alpha2 - pi/2;
    - "theta4": eq. 12 pi/2 - theta2 + theta3 instead of pi/2 - (theta2 + theta3).
    """
    unknown = set(printed) - set(PRINTED_FORMULAS)
    if unknown:
        raise ValueError(f"unknown formula(s) {sorted(unknown)}; expected {PRINTED_FORMULAS}")
    p = as_points(target)
    gamma, alpha, beta, _ = np.moveaxis(pal.motor_angles(p), -1, 0)
    if "gamma" in printed:
        gamma = gamma_printed(p[..., 0], p[..., 1])
    if {"alpha2", "alpha"} & set(printed):
        rho = np.hypot(p[..., 0], p[..., 1])
        zw = p[..., 2] + pal.h - pal.z0
        L4 = np.hypot(rho - pal.L3, zw)
        alpha1 = np.arccos((pal.L1**2 + L4**2 - pal.L2**2) / (2 * pal.L1 * L4))
        alpha2 = np.arcsin(zw / L4) if "alpha2" in printed else np.arctan2(zw, rho - pal.L3)
        alpha = np.pi / 2 - alpha1 + alpha2 if "alpha" in printed else alpha1 + alpha2 - np.pi / 2
    t2, t3 = -np.pi / 2 - alpha, np.pi / 2 + beta
    t4 = np.pi / 2 - t2 + t3 if "theta4" in printed else np.pi / 2 - (t2 + t3)
    return np.stack([gamma, t2, t3, t4], axis=-1)


# --------------------------------------------------------------------------- seed 002
def screw_axes(params: ArmParams | None = None) -> tuple[npt.NDArray, npt.NDArray]:
    """Space-frame screw axes and home pose of the main paper's arm (Table 3), seed 002.

    At q = 0 the arm is stretched along +x at height L1: the waist axis is +z through
    the origin, shoulder and elbow axes are -y (z1 = Rx(90 deg) z) through (0, 0, L1)
    and (L2, 0, L1). A revolute screw is S = (omega, -omega x q) (seed 002 eq. 7).

    Returns
    -------
    S : ndarray, shape (3, 6)
        Rows (omega, v) [-, mm].
    M : ndarray, shape (4, 4)
        Home tool pose: position (L2 + L3, 0, L1) [mm], rotation Rx(90 deg).
    """
    p = params if params is not None else paper_params()
    omega = np.array([[0.0, 0, 1], [0, -1, 0], [0, -1, 0]])
    points = np.array([[0.0, 0, 0], [0, 0, p.L1], [p.L2, 0, p.L1]])
    S = np.concatenate([omega, -np.cross(omega, points)], axis=1) + 0.0  # no -0.0
    M = np.eye(4)
    M[:3, :3] = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
    M[:3, 3] = [p.L2 + p.L3, 0.0, p.L1]
    return S, M


def exp_twist(S: npt.ArrayLike, theta: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Matrix exponential exp([S] theta) of a unit revolute screw (seed 002 eqs. 3-5).

    Parameters
    ----------
    S : array_like, shape (6,)
        (omega, v) with |omega| = 1.
    theta : array_like, shape (...)
        Joint angles [rad].

    Returns
    -------
    ndarray, shape (..., 4, 4)
        Rodrigues rotation and translation (I theta + (1-c)[w] + (theta-s)[w]^2) v.
    """
    S = np.asarray(S, dtype=float)
    if S.shape != (6,) or not math.isclose(np.linalg.norm(S[:3]), 1.0, rel_tol=1e-9):
        raise ValueError(f"screw {S.tolist()} must be 6 numbers with a unit omega")
    th = np.asarray(theta, dtype=float)[..., None, None]
    w, v = S[:3], S[3:]
    W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    s, c = np.sin(th), np.cos(th)
    R = np.eye(3) + s * W + (1 - c) * (W @ W)
    G = np.eye(3) * th + (1 - c) * W + (th - s) * (W @ W)
    T = np.zeros((*th.shape[:-2], 4, 4))
    T[..., :3, :3] = R
    T[..., :3, 3] = G @ v
    T[..., 3, 3] = 1.0
    return T


def poe_fk(q: npt.ArrayLike, params: ArmParams | None = None) -> npt.NDArray[np.float64]:
    """Product-of-exponentials FK of the main arm, (..., 4, 4), for q (..., 3) [rad].

    T(q) = exp([S1] q1) exp([S2] q2) exp([S3] q3) M (seed 002 eq. 9), with
    :func:`screw_axes`. Equals the D-H chain of Table 3 (paper eq. 2).
    """
    q = np.asarray(q, dtype=float)
    if q.ndim == 0 or q.shape[-1] != 3:
        raise ValueError(f"joint array has shape {q.shape}; expected (..., 3)")
    S, M = screw_axes(params)
    T = exp_twist(S[0], q[..., 0])
    for i in (1, 2):  # loop over joints, not points
        T = T @ exp_twist(S[i], q[..., i])
    return T @ M


# --------------------------------------------------------------------------- seed 004
# The cubic of seed 004 (and the pulse helpers built on it) lives in
# analysis.studies.trajectories, with the quintic and trapezoidal profiles; the names are
# re-exported here for the seed 000 companion notebook (08).

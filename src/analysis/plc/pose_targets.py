"""Test poses for PLC programs of an arm whose inputs are a pose (the GR-1: position and RPY
angles), labelled by kind, in the table format of :func:`analysis.plc.verify.compare`.

The point sweep of :func:`analysis.plc.verify.sweep_targets` is the paper's 3R arm's; a pose
needs its orientation too, and the interesting boundaries are different: the orientation
tolerance, each branch's own wrist reach, the base axis with a feasible orientation. Every
pose here is built from joint angles through the D-H chain (:mod:`analysis.kinematics.rpy`
for the angles), so its expected answer is known, or is drawn at random in a box.

Kinds: ``table5-3`` (the thesis's two poses: refused for their orientation; and their
nearest reachable poses), ``config`` (forward kinematics of configurations within the
joint limits), ``pose`` (uniform in a box around the reach, orientations uniform: mostly
refused), ``outer-1mm`` (the front wrist 1e-3 .. 1 mm inside or outside a2 + a3),
``orient-tol`` (reachable poses tipped out of the arm plane by 0.5 or 2 times the
tolerance), ``axis`` (the tool 0 .. 1 mm from the base axis, orientation feasible),
``half-pulse`` (one joint of a front-up configuration within 1e-3 pulse of k + 1/2), ``bad``
(NaN/inf in a position or an angle), ``huge`` (finite, squares overflow a REAL).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import Arm
from analysis.kinematics.rpy import pose_from_transform, rpy_from_matrix

__all__ = ["pose_sweep_targets"]


def _limits(arm: Arm) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    lo = np.array([lim[0] if lim else -np.pi for lim in arm.limits])
    hi = np.array([lim[1] if lim else np.pi for lim in arm.limits])
    return lo, hi


def _pose(arm: Arm, q) -> npt.NDArray[np.float64]:
    return pose_from_transform(arm.table.fk(q))


def _front_up(arm: Arm, q) -> npt.NDArray[np.bool_]:
    """Configurations that are the front-up solution of their own pose: the tool's radial
    coordinate along x1 is positive (theta1 = atan2(py, px)) and theta3 < 0."""
    P = arm.params
    r = (
        P.a2 * np.cos(q[:, 1])
        + P.a3 * np.cos(q[:, 1] + q[:, 2])
        + P.a4 * np.cos(q[:, 1] + q[:, 2] + q[:, 3])
    )
    return (r > 1.0) & (q[:, 2] < -1e-3)


def _tip(arm: Arm, q, angle: float) -> npt.NDArray[np.float64]:
    """Poses of ``q`` turned by ``angle`` [rad] about a x z1: the approach vector leaves the
    arm plane by exactly ``angle``."""
    T = arm.table.fk(q)
    R = T[:, :3, :3]
    z1 = np.stack([np.sin(q[:, 0]), -np.cos(q[:, 0]), np.zeros(len(q))], axis=-1)
    axis = np.cross(R[:, :, 2], z1)
    axis /= np.linalg.norm(axis, axis=-1, keepdims=True)
    K = np.zeros((len(q), 3, 3))
    K[:, 0, 1], K[:, 0, 2], K[:, 1, 2] = -axis[:, 2], axis[:, 1], -axis[:, 0]
    K -= np.swapaxes(K, 1, 2)
    turn = np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K
    return np.concatenate([T[:, :3, 3], rpy_from_matrix(turn @ R)], axis=-1)


def pose_sweep_targets(
    arm: Arm,
    *,
    n_config: int = 400,
    n_pose: int = 200,
    n_half: int = 150,
    seed: int = 20070602,
    orientation_tol: float | None = None,
) -> pd.DataFrame:
    """Seeded test poses (N, 6) across the reachable set and its boundaries, by kind.

    Parameters
    ----------
    arm : Arm
        An arm with inputs (px, py, pz, alpha, beta, gamma) and parameters a2, a3, a4, d1
        (the GR-1).
    orientation_tol : float, optional
        The closed form's orientation tolerance [rad] (default: its ORIENTATION_TOL_RAD).

    Returns
    -------
    DataFrame
        Columns ``kind`` and the arm's inputs.
    """
    if tuple(arm.inputs) != ("px", "py", "pz", "alpha", "beta", "gamma"):
        raise ValueError(f"arm {arm.name} takes {arm.inputs}, not a pose with RPY angles")
    from analysis.studies.gr1 import project_orientation, thesis_poses

    tol = arm.closed_form.ORIENTATION_TOL_RAD if orientation_tol is None else orientation_tol
    rng = np.random.default_rng(seed)
    P = arm.params
    lo, hi = _limits(arm)
    parts = []
    thesis = thesis_poses()
    parts.append(("table5-3", np.concatenate([thesis, project_orientation(arm, thesis)[0]])))
    parts.append(("config", _pose(arm, rng.uniform(lo, hi, (n_config, 5)))))
    R = arm.geometry["reach_tool"]
    box = np.c_[
        rng.uniform(-1.1 * R, 1.1 * R, (n_pose, 3)), rng.uniform(-np.pi, np.pi, (n_pose, 3))
    ]
    parts.append(("pose", box))
    # the front wrist at a2 + a3 +- 1e-3 .. 1 mm: wrist from (theta1, elevation), hand
    # direction theta234 with its cosine > 0 so the tool point stays in front
    n = 120
    t1 = rng.uniform(-np.pi, np.pi, n)
    elev = rng.uniform(-1.2, 1.2, n)
    t234 = rng.uniform(-1.2, 1.2, n)
    t5 = rng.uniform(-np.pi, np.pi, n)
    dist = P.a2 + P.a3 + rng.choice([-1.0, 1.0], n) * 10.0 ** rng.uniform(-3, 0, n)
    r = dist * np.cos(elev) + P.a4 * np.cos(t234)
    z = dist * np.sin(elev) + P.a4 * np.sin(t234) + P.d1
    # a configuration with that theta1, theta234, theta5 gives the orientation: the arm
    # stretched along the wrist direction, hand at theta234
    q = np.stack([t1, elev, np.zeros(n), t234 - elev, t5], axis=-1)
    rot = _pose(arm, q)[:, 3:]
    parts.append(("outer-1mm", np.c_[r * np.cos(t1), r * np.sin(t1), z, rot]))
    q = rng.uniform(lo, hi, (60, 5))
    parts.append(("orient-tol", np.concatenate([_tip(arm, q[:30], 0.5 * tol),
                                                _tip(arm, q[30:], 2.0 * tol)])))  # fmt: skip
    # the tool on the base axis (hand upright, a2 c2 + a3 c23 = 0), then moved off it by
    # rho in [0, 1] mm along x1: the orientation stays in the arm plane
    n = 100
    t2 = rng.uniform(0.3, 1.4, n)
    t3 = np.pi - 2 * t2
    t1, t5 = rng.uniform(-np.pi, np.pi, n), rng.uniform(-np.pi, np.pi, n)
    q = np.stack([t1, t2, t3, np.pi / 2 - t2 - t3, t5], axis=-1)  # theta234 = 90 deg
    pose = _pose(arm, q)
    rho = np.concatenate([[0.0] * 5, 10.0 ** rng.uniform(-3, 0, n - 5)])
    pose[:, 0] = rho * np.cos(q[:, 0])
    pose[:, 1] = rho * np.sin(q[:, 0])
    parts.append(("axis", pose))
    # half pulses: one joint (cycling 1..5) at (k + 1/2 + delta) pulses, front-up configs
    q = rng.uniform(lo, hi, (20 * n_half, 5))
    q = q[_front_up(arm, q)][:n_half]
    ppr = np.asarray(P.pulses_per_rev, dtype=float)
    j = np.arange(len(q)) % 5
    c = q[np.arange(len(q)), j] / (2 * np.pi) * ppr[j]
    delta = rng.choice([-1.0, 1.0], len(q)) * 10.0 ** rng.uniform(-7, -3, len(q))
    q[np.arange(len(q)), j] = (np.floor(c) + 0.5 + delta) * 2 * np.pi / ppr[j]
    parts.append(("half-pulse", _pose(arm, q)))
    nan, inf = np.nan, np.inf
    bad = np.full((6, 6), 100.0)
    bad[:, 3:] = 0.0
    bad[np.arange(6), np.arange(6)] = [nan, inf, -inf, nan, inf, -inf]
    parts.append(("bad", bad))
    huge = [[1e20, -1e20, 100.0, 0, 0, 0], [3e38, 0, 0, 0, 0, 0], [-1e30, 1e30, -1e30, 0, 0, 0],
            [200.0, 100.0, 50.0, 1e30, 0.0, 0.0]]  # fmt: skip
    parts.append(("huge", np.array(huge, dtype=float)))
    cols = list(arm.inputs)
    rows = [pd.DataFrame(p, columns=cols).assign(kind=k) for k, p in parts]
    df = pd.concat(rows, ignore_index=True)
    return df[["kind", *cols]]

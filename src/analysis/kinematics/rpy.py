"""RPY angles (the GR-1 thesis, seed 004, eqs. 3.14-3.18): orientation <-> rotation matrix.

The thesis defines the orientation of the hand by three rotations about the *fixed*
reference axes, x first (section 3.3, eq. 3.14)::

    RPY(alpha, beta, gamma) = Rot(z, alpha) Rot(y, beta) Rot(x, gamma)

with ``alpha`` about z (roll in the thesis's words), ``beta`` about y (pitch), ``gamma``
about x (yaw); the Greek letters are lost in the extraction, the names are the VB6
listing's (``α0, β0, γ0``: Text4-6). Multiplied out (eq. 3.15) the columns are the
normal, sliding and approach vectors ``n, o, a`` of eq. 3.16::

    n = (ca cb,  sa cb,  -sb)
    o = (ca sb sg - sa cg,  sa sb sg + ca cg,  cb sg)
    a = (ca sb cg + sa sg,  sa sb cg - ca sg,  cb cg)

The inverse (eq. 3.18, corrected: the print has ``atan2(o_x, n_x)`` and ``atan2(a_y, a_z)``
for the second and third angle) with the thesis's choice -90 deg <= beta <= 90 deg::

    beta  = atan2(-n_z, sqrt(n_x^2 + n_y^2))
    alpha = atan2(n_y, n_x)
    gamma = atan2(o_z, a_z)

:func:`rpy_columns` is written once against a math namespace (:mod:`analysis.kinematics.ops`)
so that the GR-1's closed form (:mod:`analysis.kinematics.arms.gr1`) and its compiled and
PLC backends use the same formula; the numpy functions below are for tests, tables and
figures. Angles in radians; arrays broadcast over leading axes.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from analysis.kinematics.ops import numpy_ops

__all__ = [
    "GIMBAL_LOCK_COS",
    "matrix_from_rpy",
    "pose_from_transform",
    "rotation_angle",
    "rpy_columns",
    "rpy_from_matrix",
    "transform_from_pose",
]


def rpy_columns(m, alpha, beta, gamma):
    """Columns ``(n, o, a)`` of RPY(alpha, beta, gamma) (eq. 3.15), each a 3-tuple of ``m``
    values; angles [rad]."""
    ca, sa = m.cos(alpha), m.sin(alpha)
    cb, sb = m.cos(beta), m.sin(beta)
    cg, sg = m.cos(gamma), m.sin(gamma)
    sbsg, sbcg = sb * sg, sb * cg
    n = (ca * cb, sa * cb, -sb)
    o = (ca * sbsg - sa * cg, sa * sbsg + ca * cg, cb * sg)
    a = (ca * sbcg + sa * sg, sa * sbcg - ca * sg, cb * cg)
    return n, o, a


def matrix_from_rpy(rpy: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Rotation matrices (..., 3, 3) for RPY angles (..., 3) = (alpha, beta, gamma) [rad].

    Examples
    --------
    Table 5-3's start orientation (32, 45, 60) deg; its approach vector:

    >>> matrix_from_rpy(np.radians([32.0, 45.0, 60.0]))[:, 2].round(4).tolist()
    [0.7588, -0.5471, 0.3536]
    """
    rpy = np.asarray(rpy, dtype=float)
    if rpy.ndim == 0 or rpy.shape[-1] != 3:
        raise ValueError(f"RPY angles have shape {rpy.shape}; expected (..., 3)")
    cols = rpy_columns(numpy_ops, rpy[..., 0], rpy[..., 1], rpy[..., 2])
    return np.stack([np.stack(c, axis=-1) for c in cols], axis=-1)


GIMBAL_LOCK_COS = 1e-10
"""Below this cos(beta) = |(n_x, n_y)|, alpha and gamma are not separately defined (beta =
+-90 deg: only gamma -+ alpha is); :func:`rpy_from_matrix` then takes alpha = 0."""


def rpy_from_matrix(R: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """RPY angles (..., 3) [rad] of rotation matrices (..., 3, 3): eq. 3.18 corrected,
    beta in [-90, 90] deg (eq. 3.17's root taken positive).

    At beta = +-90 deg (gimbal lock: n_x = n_y = 0, where eq. 3.18's atan2 of two zeros
    leaves alpha and gamma to round-off) alpha = 0 and gamma carries the rotation:
    o = (sin(gamma - alpha), cos(gamma - alpha), 0) at +90 deg and
    (-sin(gamma + alpha), cos(gamma + alpha), 0) at -90 deg, so that
    ``matrix_from_rpy(rpy_from_matrix(R)) == R`` everywhere.

    >>> R = matrix_from_rpy(np.radians([-60.0, 90.0, -64.0]))
    >>> np.degrees(rpy_from_matrix(R)).round(6).tolist()
    [0.0, 90.0, -4.0]
    """
    R = np.asarray(R, dtype=float)
    if R.ndim < 2 or R.shape[-2:] != (3, 3):
        raise ValueError(f"rotation matrices have shape {R.shape}; expected (..., 3, 3)")
    cb = np.hypot(R[..., 0, 0], R[..., 1, 0])
    beta = np.arctan2(-R[..., 2, 0], cb)
    lock = cb < GIMBAL_LOCK_COS
    alpha = np.where(lock, 0.0, np.arctan2(R[..., 1, 0], R[..., 0, 0]))
    sign = np.where(R[..., 2, 0] < 0, 1.0, -1.0)  # n_z = -sin(beta)
    locked = np.arctan2(sign * R[..., 0, 1], R[..., 1, 1])
    gamma = np.where(lock, locked, np.arctan2(R[..., 2, 1], R[..., 2, 2]))
    return np.stack([alpha, beta, gamma], axis=-1)


def pose_from_transform(T: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Pose (..., 6) = (px, py, pz [mm], alpha, beta, gamma [rad]) of transforms (..., 4, 4)."""
    T = np.asarray(T, dtype=float)
    if T.ndim < 2 or T.shape[-2:] != (4, 4):
        raise ValueError(f"transforms have shape {T.shape}; expected (..., 4, 4)")
    return np.concatenate([T[..., :3, 3], rpy_from_matrix(T[..., :3, :3])], axis=-1)


def transform_from_pose(pose: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Transforms (..., 4, 4) of poses (..., 6) = (px, py, pz [mm], alpha, beta, gamma [rad])."""
    pose = np.asarray(pose, dtype=float)
    if pose.ndim == 0 or pose.shape[-1] != 6:
        raise ValueError(f"poses have shape {pose.shape}; expected (..., 6)")
    T = np.zeros((*pose.shape[:-1], 4, 4))
    T[..., :3, :3] = matrix_from_rpy(pose[..., 3:])
    T[..., :3, 3] = pose[..., :3]
    T[..., 3, 3] = 1.0
    return T


def rotation_angle(R1: npt.ArrayLike, R2: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Angle [rad] of the rotation between R1 and R2 (..., 3, 3): ``|log(R1^T R2)|``.

    From the skew part and the trace together (``atan2(|w|, (tr - 1) / 2)``), accurate
    near 0 and near pi, where ``acos`` of the trace alone loses half the digits.
    """
    R1, R2 = np.asarray(R1, dtype=float), np.asarray(R2, dtype=float)
    D = np.swapaxes(R1, -1, -2) @ R2
    w = np.stack(
        [D[..., 2, 1] - D[..., 1, 2], D[..., 0, 2] - D[..., 2, 0], D[..., 1, 0] - D[..., 0, 1]],
        axis=-1,
    )
    tr = D[..., 0, 0] + D[..., 1, 1] + D[..., 2, 2]
    return np.arctan2(0.5 * np.linalg.norm(w, axis=-1), 0.5 * (tr - 1.0))

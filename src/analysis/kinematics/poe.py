"""Product-of-exponentials (POE) kinematics: screw axes, exp6, space-frame FK and Jacobian.

The screw-theory route to forward kinematics used by the picker paper (seed 002,
``analysis.papers.picker``: sections 1.1-1.2, its eqs. 3-9 as the text describes them;
the bodies are lost in the extraction). It is the textbook formula of Murray, Li & Sastry
and of Lynch & Park, written once and evaluated two ways.

Conventions
-----------
A screw axis is a 6-vector ``S = (omega, v)`` in the space (base) frame at the home
configuration q = 0 (angular part first, as the picker paper's eqs. 7-8):

* revolute joint: ``omega`` a unit vector along the axis, ``v = -omega x q`` with ``q`` any
  point on the axis [mm] (seed 002 eq. 7); the joint variable is an angle [rad];
* prismatic joint: ``omega = 0``, ``v`` a unit vector along the motion (seed 002 eq. 8);
  the joint variable is a displacement [mm].

The matrix exponential of ``[S] theta`` (Rodrigues, seed 002 eqs. 3-5)::

    R = I + sin(theta) [w] + (1 - cos(theta)) [w]^2
    p = (I theta + (1 - cos(theta)) [w] + (theta - sin(theta)) [w]^2) v

holds for both kinds: with ``w = 0`` it reduces to ``R = I, p = v theta``. One function body
(:func:`exp6_entries`) holds it and is called with NumPy (arrays, any leading shape) or
with SymPy (symbols), so the numeric and symbolic paths cannot drift apart (the same design
as :mod:`analysis.kinematics.dh`).

Forward kinematics in the space frame (seed 002 eq. 9)::

    T(q) = exp([S1] q1) exp([S2] q2) ... exp([Sn] qn) M

and the space Jacobian ``J_s = [S1, Ad_{T1} S2, ..., Ad_{T1...T(n-1)} Sn]`` (6 x n, rows
``(omega, v)``). Lengths are millimetres, angles radians.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt
import sympy as sp

from analysis.kinematics.dh import DHTable

__all__ = [
    "UNIT_TOL",
    "adjoint",
    "axis_point",
    "check_home",
    "check_screws",
    "exp6",
    "exp6_sym",
    "fk",
    "fk_sym",
    "joint_kinds",
    "point_jacobian",
    "prismatic_screw",
    "revolute_screw",
    "screws_from_dh",
    "space_jacobian",
]

UNIT_TOL = 1e-9
"""Allowed deviation of |omega| (revolute) or |v| (prismatic) from 1, and of the pitch
omega . v / max(1, |v|) from 0. Screw axes built from exact directions or from float64
transforms are unit to ~1e-15; a hand-typed non-unit axis is off by far more."""


# --------------------------------------------------------------------------- the formula
def exp6_entries(w, v, th, sin, cos) -> list[list]:
    """The top 3x4 block of ``exp([S] th)`` for ``S = (w, v)``; the last row is [0 0 0 1].

    ``w``, ``v``: three components each (NumPy arrays broadcastable against ``th``, or SymPy
    expressions); ``sin``/``cos``: the namespace's functions. Valid for |w| = 1 (revolute)
    and w = 0 (prismatic), with no branch between the two.
    """
    s, c = sin(th), cos(th)
    k = 1 - c  # (1 - cos theta)
    m = th - s  # (theta - sin theta)
    ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2]
    W = ((0 * w[0], -w[2], w[1]), (w[2], 0 * w[0], -w[0]), (-w[1], w[0], 0 * w[0]))
    W2 = [[w[i] * w[j] - (ww if i == j else 0) for j in range(3)] for i in range(3)]
    R = [[(1 if i == j else 0) + s * W[i][j] + k * W2[i][j] for j in range(3)] for i in range(3)]
    G = [[(th if i == j else 0) + k * W[i][j] + m * W2[i][j] for j in range(3)] for i in range(3)]
    p = [G[i][0] * v[0] + G[i][1] * v[1] + G[i][2] * v[2] for i in range(3)]
    return [[R[i][0], R[i][1], R[i][2], p[i]] for i in range(3)]


# --------------------------------------------------------------------------- screw axes
def revolute_screw(omega: npt.ArrayLike, point: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Screw axis ``(omega, -omega x q)`` of a revolute joint (seed 002 eq. 7).

    Parameters
    ----------
    omega : array_like, shape (3,)
        Axis direction; normalised here (it must not be zero).
    point : array_like, shape (3,)
        Any point q on the axis [mm].

    Returns
    -------
    ndarray, shape (6,)
        ``(omega, v)`` with |omega| = 1, v [mm].
    """
    w = np.asarray(omega, dtype=float)
    q = np.asarray(point, dtype=float)
    if w.shape != (3,) or q.shape != (3,) or not (np.isfinite(w).all() and np.isfinite(q).all()):
        raise ValueError(f"revolute screw needs finite omega (3,) and point (3,); got {w}, {q}")
    n = float(np.linalg.norm(w))
    if n < UNIT_TOL:
        raise ValueError(f"revolute screw: omega = {w.tolist()} is zero; it has no direction")
    w = w / n
    return np.concatenate([w, -np.cross(w, q)]) + 0.0  # + 0.0: no -0.0 in printed tables


def prismatic_screw(direction: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Screw axis ``(0, v)`` of a prismatic joint (seed 002 eq. 8); ``v`` normalised.

    Returns
    -------
    ndarray, shape (6,)
    """
    v = np.asarray(direction, dtype=float)
    if v.shape != (3,) or not np.isfinite(v).all():
        raise ValueError(f"prismatic screw needs a finite direction (3,); got {v}")
    n = float(np.linalg.norm(v))
    if n < UNIT_TOL:
        raise ValueError(f"prismatic screw: direction {v.tolist()} is zero")
    return np.concatenate([np.zeros(3), v / n]) + 0.0


def check_screws(screws: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Validate screw axes; return them as a float array of shape (n, 6).

    Each row must be a revolute axis (|omega| = 1, pitch omega . v = 0) or a prismatic
    one (omega = 0, |v| = 1), within :data:`UNIT_TOL`.

    Raises
    ------
    ValueError
        Naming the first offending screw (0-based index), the value found and the limit.
    """
    S = np.asarray(screws, dtype=float)
    if S.ndim == 1:
        S = S[None, :]
    if S.ndim != 2 or S.shape[1] != 6 or S.shape[0] == 0:
        raise ValueError(f"screw axes have shape {np.shape(screws)}; expected (n, 6) or (6,)")
    for i, row in enumerate(S):
        if not np.isfinite(row).all():
            raise ValueError(f"screw {i} = {row.tolist()} contains NaN or inf")
        nw, nv = float(np.linalg.norm(row[:3])), float(np.linalg.norm(row[3:]))
        if nw > UNIT_TOL:  # revolute
            if abs(nw - 1.0) > UNIT_TOL:
                raise ValueError(
                    f"screw {i} = {row.tolist()}: |omega| = {nw:.12g}; a revolute screw needs "
                    f"|omega| = 1 (within {UNIT_TOL:g})"
                )
            pitch = float(row[:3] @ row[3:]) / max(1.0, nv)
            if abs(pitch) > UNIT_TOL:
                raise ValueError(
                    f"screw {i} = {row.tolist()}: pitch omega.v/max(1,|v|) = {pitch:.3g}; "
                    f"only revolute (pitch 0, within {UNIT_TOL:g}) or prismatic screws are "
                    "supported"
                )
        elif abs(nv - 1.0) > UNIT_TOL:
            raise ValueError(
                f"screw {i} = {row.tolist()}: omega = 0 and |v| = {nv:.12g}; a prismatic screw "
                f"needs |v| = 1 (within {UNIT_TOL:g})"
            )
    return S


def joint_kinds(screws: npt.ArrayLike) -> tuple[str, ...]:
    """``"revolute"`` or ``"prismatic"`` for each (validated) screw axis."""
    S = check_screws(screws)
    return tuple("revolute" if np.linalg.norm(r[:3]) > 0.5 else "prismatic" for r in S)


def axis_point(screw: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The point of a revolute axis closest to the origin, ``omega x v`` [mm], shape (3,).

    For a prismatic screw (no axis position) it returns the origin.
    """
    S = check_screws(screw)[0]
    return np.cross(S[:3], S[3:]) + 0.0


def check_home(M: npt.ArrayLike, name: str = "M") -> npt.NDArray[np.float64]:
    """Validate a homogeneous transform (4, 4): rotation orthonormal with det +1 within
    1e-9, bottom row [0 0 0 1]. Returns it as a float array."""
    M = np.asarray(M, dtype=float)
    if M.shape != (4, 4) or not np.isfinite(M).all():
        raise ValueError(f"{name} must be a finite (4, 4) transform; got shape {M.shape}")
    R = M[:3, :3]
    err = float(np.abs(R.T @ R - np.eye(3)).max())
    if err > 1e-9 or np.linalg.det(R) < 0 or not np.array_equal(M[3], [0.0, 0.0, 0.0, 1.0]):
        raise ValueError(
            f"{name} is not a rigid transform: |R^T R - I| = {err:.3g} (limit 1e-9), "
            f"det R = {np.linalg.det(R):.6g}, bottom row {M[3].tolist()}"
        )
    return M


def _joints(q: npt.ArrayLike, n: int) -> npt.NDArray[np.float64]:
    q = np.asarray(q, dtype=float)
    if q.ndim == 0 or q.shape[-1] != n:
        raise ValueError(f"joint array has shape {q.shape}; expected (..., {n})")
    if not np.isfinite(q).all():
        raise ValueError("joint array contains NaN or inf")
    return q


# --------------------------------------------------------------------------- numeric path
def exp6(screws: npt.ArrayLike, theta: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Matrix exponentials ``exp([S_i] theta_i)`` (seed 002 eqs. 3-5), vectorised.

    Parameters
    ----------
    screws : array_like, shape (6,) or (n, 6)
        Validated screw axes (:func:`check_screws`).
    theta : array_like, shape (...) for one screw, (..., n) for n screws
        Joint values [rad] (revolute) or [mm] (prismatic).

    Returns
    -------
    ndarray, shape (..., 4, 4) for one screw, (..., n, 4, 4) for n screws
    """
    single = np.ndim(screws) == 1
    S = check_screws(screws)
    th = np.asarray(theta, dtype=float)
    if single:
        th = th[..., None]
    elif th.ndim == 0 or th.shape[-1] != S.shape[0]:
        raise ValueError(f"joint array has shape {th.shape}; expected (..., {S.shape[0]})")
    rows = exp6_entries(S[:, :3].T, S[:, 3:].T, th, np.sin, np.cos)
    out = np.zeros((*th.shape, 4, 4))
    for i, row in enumerate(rows):
        for j, value in enumerate(row):
            out[..., i, j] = value
    out[..., 3, 3] = 1.0
    return out[..., 0, :, :] if single else out


def fk(screws: npt.ArrayLike, M: npt.ArrayLike, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Space-frame POE forward kinematics ``exp([S1]q1) ... exp([Sn]qn) M`` (seed 002 eq. 9).

    Parameters
    ----------
    screws : array_like, shape (n, 6)
        Screw axes at the home configuration, space frame.
    M : array_like, shape (4, 4)
        Home pose of the tool frame (g_st(0) of the picker paper).
    q : array_like, shape (..., n)
        Joint values [rad | mm].

    Returns
    -------
    ndarray, shape (..., 4, 4)
        Tool pose in the base frame [mm].
    """
    S = check_screws(screws)
    M = check_home(M)
    q = _joints(q, S.shape[0])
    E = exp6(S, q)
    T = E[..., 0, :, :]
    for i in range(1, S.shape[0]):  # loop over joints, never over points
        T = T @ E[..., i, :, :]
    return T @ M


def adjoint(T: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Adjoint representation ``[[R, 0], [[p] R, R]]`` of transforms (..., 4, 4) -> (..., 6, 6),
    acting on twists ordered (omega, v)."""
    T = np.asarray(T, dtype=float)
    R, p = T[..., :3, :3], T[..., :3, 3]
    P = np.zeros((*p.shape[:-1], 3, 3))
    P[..., 0, 1], P[..., 0, 2] = -p[..., 2], p[..., 1]
    P[..., 1, 0], P[..., 1, 2] = p[..., 2], -p[..., 0]
    P[..., 2, 0], P[..., 2, 1] = -p[..., 1], p[..., 0]
    out = np.zeros((*T.shape[:-2], 6, 6))
    out[..., :3, :3] = R
    out[..., 3:, 3:] = R
    out[..., 3:, :3] = P @ R
    return out


def space_jacobian(screws: npt.ArrayLike, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Space Jacobian ``J_s(q)`` (Murray-Li-Sastry / Lynch-Park), shape (..., 6, n).

    Column i is the i-th screw axis carried to the current configuration,
    ``Ad_{exp([S1]q1)...exp([S(i-1)]q(i-1))} S_i``; rows (omega [rad/unit], v [mm/unit]).
    The spatial twist of the tool is ``J_s(q) qdot``.
    """
    S = check_screws(screws)
    q = _joints(q, S.shape[0])
    E = exp6(S, q)
    J = np.zeros((*q.shape[:-1], 6, S.shape[0]))
    J[..., :, 0] = S[0]
    T = E[..., 0, :, :]
    for i in range(1, S.shape[0]):
        J[..., :, i] = np.einsum("...ij,j->...i", adjoint(T), S[i])
        T = T @ E[..., i, :, :]
    return J


def point_jacobian(
    screws: npt.ArrayLike, M: npt.ArrayLike, q: npt.ArrayLike
) -> npt.NDArray[np.float64]:
    """Linear-velocity Jacobian of the tool origin [mm/rad | mm/mm], shape (..., 3, n).

    From the space Jacobian: ``pdot = v_s + omega_s x p = (J_v - [p] J_omega) qdot`` with
    ``p`` the tool origin of :func:`fk`.
    """
    J = space_jacobian(screws, q)
    p = fk(screws, M, q)[..., :3, 3]
    return J[..., 3:, :] - np.cross(p[..., :, None], J[..., :3, :], axis=-2)


# --------------------------------------------------------------------------- symbolic path
def exp6_sym(screw: Sequence, theta) -> sp.Matrix:
    """Symbolic ``exp([S] theta)`` (4x4 SymPy matrix) from the same formula as :func:`exp6`.

    ``screw`` holds six SymPy-compatible entries (numbers or symbols); numeric screws are
    validated by :func:`check_screws` first. Exact entries (0, 1, ``sp.Rational``) give
    exact results.
    """
    entries = [sp.sympify(e) for e in screw]
    if len(entries) != 6:
        raise ValueError(f"screw has {len(entries)} entries; expected 6")
    if all(e.is_number for e in entries):
        check_screws([float(e) for e in entries])
    rows = exp6_entries(entries[:3], entries[3:], sp.sympify(theta), sp.sin, sp.cos)
    return sp.Matrix([*[[sp.expand(e) for e in r] for r in rows], [0, 0, 0, 1]])


def fk_sym(screws: Sequence[Sequence], M, q: Sequence | None = None) -> sp.Matrix:
    """Symbolic POE forward kinematics; ``q`` defaults to symbols ``q1..qn`` (real)."""
    screws = [list(s) for s in screws]
    if q is None:
        q = sp.symbols(f"q1:{len(screws) + 1}", real=True)
    q = list(q)
    if len(q) != len(screws):
        raise ValueError(f"{len(q)} joint symbols for {len(screws)} screws")
    T = sp.eye(4)
    for s, qi in zip(screws, q, strict=True):
        T = T * exp6_sym(s, qi)
    return T * sp.Matrix(M)


# --------------------------------------------------------------------------- from a D-H table
def screws_from_dh(table: DHTable) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Screw axes and home pose of a D-H chain, read off its frames at q = 0.

    Standard D-H (``A_i = Rz(theta_i) Tz Tx Rx``): joint i turns about (a prismatic one
    slides along) z of frame i-1 through its origin. Modified D-H (``A_i = Rx Tx
    Rz(theta_i) Tz``): z of frame i. Only the home configuration uses the D-H
    transforms, so :func:`fk` with these screws and :meth:`DHTable.fk` are two
    independent routes to the pose at any other q.

    Returns
    -------
    S : ndarray, shape (n_joints, 6)
        Revolute and prismatic screw axes (omega, v) [-, mm].
    M : ndarray, shape (4, 4)
        ``table.fk(0)``: the base-to-last-frame transform at q = 0 (tool rows included).

    Entries below 1e-12 in magnitude (cos 90 deg = 6e-17 and its products) are set to 0.
    """
    A = table.transforms(np.zeros(table.n_joints))
    T = np.eye(4)
    screws = []
    for row, Ai in zip(table.rows, A, strict=True):
        if table.convention == "standard":
            frame, T = T, T @ Ai
        else:
            T = T @ Ai
            frame = T
        if row.kind == "revolute":
            screws.append(revolute_screw(frame[:3, 2], frame[:3, 3]))
        elif row.kind == "prismatic":
            screws.append(prismatic_screw(frame[:3, 2]))
    if not screws:
        raise ValueError(f"D-H table {table.name!r} has no joint row")
    S = np.array(screws)
    S[np.abs(S) < 1e-12] = 0.0  # cos(90 deg) = 6e-17 etc.: round-off, not geometry
    return S + 0.0, T

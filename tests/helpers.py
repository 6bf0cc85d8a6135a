"""Domain assertions and independent reference formulas shared by the kinematics tests.

Failures print both arrays and the worst offender, so a red test says where and by how
much, not only that something differs.

The elementary transforms below (``rot_x``, ``rot_z``, ``trans``) are written out here on
purpose, independently of :mod:`analysis.kinematics.dh`: the D-H tests compose them as
``Rz Tz Tx Rx`` (standard) and ``Rx Tx Rz Tz`` (modified) and hold the library's single
formula against that product.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

TWO_PI = 2.0 * np.pi


def _report(name: str, actual, desired, excess, what: str) -> str:
    """Failure text: the worst offender (by ``excess`` over the bound) and both arrays."""
    actual, desired, excess = np.asarray(actual), np.asarray(desired), np.asarray(excess)
    worst = np.unravel_index(int(np.nanargmax(excess)), excess.shape) if excess.ndim else ()
    with np.printoptions(precision=12, threshold=60, edgeitems=3):
        return (
            f"{name}: {what}; worst at index {tuple(int(i) for i in worst)}:\n"
            f"  actual  = {actual[worst]}\n  desired = {desired[worst]}\n"
            f"all actual:\n{actual}\nall desired:\n{desired}"
        )


def assert_points_close(actual, desired, atol: float, name: str = "points") -> None:
    """Euclidean distance between points (..., 3) [mm] below ``atol`` [mm] everywhere.

    NaN anywhere fails (a silent NaN is a bug here).
    """
    actual, desired = np.broadcast_arrays(np.asarray(actual, float), np.asarray(desired, float))
    assert actual.shape[-1] == 3, f"{name}: expected (..., 3) points, got {actual.shape}"
    assert np.isfinite(actual).all(), f"{name}: actual contains NaN/inf\n{actual}"
    err = np.linalg.norm(actual - desired, axis=-1)
    if not (err <= atol).all():
        raise AssertionError(
            _report(
                name, actual, desired, err, f"max distance {err.max():.3e} mm > atol {atol:g} mm"
            )
        )


def assert_allclose(actual, desired, atol: float, name: str = "values", rtol: float = 0.0) -> None:
    """Elementwise ``|actual - desired| <= atol + rtol |desired|``, NaN fails, both printed."""
    actual, desired = np.broadcast_arrays(np.asarray(actual, float), np.asarray(desired, float))
    assert np.isfinite(actual).all(), f"{name}: actual contains NaN/inf\n{actual}"
    err = np.abs(actual - desired)
    bound = atol + rtol * np.abs(desired)
    if not (err <= bound).all():
        what = (
            f"max |difference| {np.max(err):.3e} exceeds atol {atol:g} + rtol {rtol:g} * |desired|"
        )
        raise AssertionError(_report(name, actual, desired, err - bound, what))


def angle_diff(a, b):
    """Signed difference a - b wrapped to [-pi, pi) [rad]."""
    return np.mod(np.asarray(a, float) - np.asarray(b, float) + np.pi, TWO_PI) - np.pi


def assert_angles_close(actual, desired, atol: float, name: str = "angles") -> None:
    """Angles [rad] equal modulo 2*pi within ``atol`` [rad] (so -pi and pi agree)."""
    actual, desired = np.broadcast_arrays(np.asarray(actual, float), np.asarray(desired, float))
    assert np.isfinite(actual).all(), f"{name}: actual contains NaN/inf\n{actual}"
    err = np.abs(angle_diff(actual, desired))
    if not (err <= atol).all():
        what = f"max angle difference {err.max():.3e} rad > atol {atol:g} rad (mod 2 pi)"
        raise AssertionError(_report(name, actual, desired, err, what))


def assert_transform_close(
    actual, desired, atol_rot: float, atol_mm: float, name: str = "transform"
) -> None:
    """Homogeneous transforms (..., 4, 4): rotation block within ``atol_rot``, translation
    within ``atol_mm`` [mm], bottom row exactly [0, 0, 0, 1]."""
    actual, desired = np.broadcast_arrays(np.asarray(actual, float), np.asarray(desired, float))
    assert actual.shape[-2:] == (4, 4), f"{name}: expected (..., 4, 4), got {actual.shape}"
    bottom = actual[..., 3, :]
    assert (bottom == np.array([0.0, 0.0, 0.0, 1.0])).all(), (
        f"{name}: bottom row is not [0 0 0 1]\n{bottom}"
    )
    assert_allclose(actual[..., :3, :3], desired[..., :3, :3], atol_rot, f"{name} rotation")
    assert_points_close(actual[..., :3, 3], desired[..., :3, 3], atol_mm, f"{name} translation")


def contains_angles(candidates, q, atol: float) -> np.ndarray:
    """Mask (...,): does some row of ``candidates`` (..., B, n) equal ``q`` (..., n) modulo
    2*pi within ``atol`` [rad] in every joint?"""
    err = np.abs(angle_diff(candidates, np.asarray(q)[..., None, :])).max(axis=-1)
    return (err <= atol).any(axis=-1)


# --- independent elementary transforms (numeric, vectorized; and sympy) -------------------


def rot_x(angle):
    a = np.asarray(angle, float)
    c, s = np.cos(a), np.sin(a)
    out = np.zeros((*a.shape, 4, 4))
    out[..., 0, 0] = 1.0
    out[..., 1, 1], out[..., 1, 2] = c, -s
    out[..., 2, 1], out[..., 2, 2] = s, c
    out[..., 3, 3] = 1.0
    return out


def rot_z(angle):
    a = np.asarray(angle, float)
    c, s = np.cos(a), np.sin(a)
    out = np.zeros((*a.shape, 4, 4))
    out[..., 0, 0], out[..., 0, 1] = c, -s
    out[..., 1, 0], out[..., 1, 1] = s, c
    out[..., 2, 2] = 1.0
    out[..., 3, 3] = 1.0
    return out


def trans(x=0.0, y=0.0, z=0.0):
    x, y, z = np.broadcast_arrays(*(np.asarray(v, float) for v in (x, y, z)))
    out = np.broadcast_to(np.eye(4), (*x.shape, 4, 4)).copy()
    out[..., 0, 3], out[..., 1, 3], out[..., 2, 3] = x, y, z
    return out


def reference_link(theta, d, a, alpha, convention):
    """D-H link transform as a product of elementary motions (the textbook definition)."""
    if convention == "standard":  # Rz(theta) Tz(d) Tx(a) Rx(alpha)
        return rot_z(theta) @ trans(z=d) @ trans(x=a) @ rot_x(alpha)
    if convention == "modified":  # Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)
        return rot_x(alpha) @ trans(x=a) @ rot_z(theta) @ trans(z=d)
    raise ValueError(convention)


def sym_rot_x(a):
    return sp.Matrix(
        [[1, 0, 0, 0], [0, sp.cos(a), -sp.sin(a), 0], [0, sp.sin(a), sp.cos(a), 0], [0, 0, 0, 1]]
    )


def sym_rot_z(a):
    return sp.Matrix(
        [[sp.cos(a), -sp.sin(a), 0, 0], [sp.sin(a), sp.cos(a), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    )


def sym_trans(x=0, y=0, z=0):
    return sp.Matrix([[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]])


def sym_reference_link(theta, d, a, alpha, convention):
    if convention == "standard":
        return sym_rot_z(theta) * sym_trans(z=d) * sym_trans(x=a) * sym_rot_x(alpha)
    return sym_rot_x(alpha) * sym_trans(x=a) * sym_rot_z(theta) * sym_trans(z=d)


def assert_sym_equal(actual: sp.Matrix, desired: sp.Matrix, name: str = "matrix") -> None:
    """Exact symbolic equality, entry by entry (``simplify(a - b) == 0``); lists the
    entries that differ."""
    assert actual.shape == desired.shape, f"{name}: shape {actual.shape} != {desired.shape}"
    bad = [
        (i, j, actual[i, j], desired[i, j])
        for i in range(actual.rows)
        for j in range(actual.cols)
        if sp.simplify(actual[i, j] - desired[i, j]) != 0
    ]
    assert not bad, f"{name}: entries differ (row, col, actual, desired):\n" + "\n".join(
        map(str, bad)
    )


def seed_file(name: str):
    """A seed paper's text extraction, which lives outside the repository: in
    ``$ANALYSIS_SEEDS`` or ``../shared/seeds`` beside the checkout (tests skip without it)."""
    import os
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    return Path(os.environ.get("ANALYSIS_SEEDS", root.parent / "shared" / "seeds")) / name

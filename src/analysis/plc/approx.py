"""Inverse trigonometry for the S7-200, which has no ATAN/ASIN/ACOS instruction.

The S7-200 instruction set has SQRT, SIN, COS, TAN, LN, EXP and the four REAL operations
(System Manual p.157) but no inverse trigonometric function; the paper's Figures 4-6 call
``ARCTAN`` and ``ARCCOS`` subroutines it never lists. We generate them from instructions the
CPU has, by argument reduction plus a polynomial:

``atan2(y, x)`` (used for theta1, eq. 6, and theta2+theta3, eq. 18)
    1. ``a = |y|, b = |x|``; if both are 0 the result is 0 (the numpy/C convention);
    2. ``t = min(a, b) / max(a, b)`` in [0, 1];
    3. if ``t > tan(pi/12)``: ``t' = (sqrt(3) t - 1) / (t + sqrt(3))`` and offset pi/6
       (the tangent subtraction formula; |t'| <= tan(pi/12) = 0.2679);
    4. ``atan(t') = t' (c0 + c1 u + c2 u^2 + c3 u^3 + c4 u^4)``, ``u = t'^2`` (odd degree 9,
       least-squares on Chebyshev nodes of [0, tan(pi/12)^2]);
    5. undo the reductions: ``pi/2 - .`` if ``a > b``, ``pi - .`` if ``x < 0``, ``-.`` if
       ``y < 0``.
``acos(c)`` (eq. 10)
    ``atan2(sqrt((1 - c)(1 + c)), c)``: (1 - c) is exact in float32 for c in [0.5, 1]
    (Sterbenz), so the result keeps full relative precision near the reach boundary.

:func:`atan2_f32` and :func:`acos_f32` evaluate exactly this sequence with numpy float32
(each operation rounded to float32, as a REAL accumulator/V-memory store is), so the
approximation error can be measured densely in Python; the awlsim runs then confirm that
the generated STL computes the same thing.

Measured (:func:`measure_errors`, float32, 4000 pulses/rev): ATAN2 worst error 2.9e-7 rad
= 1.7e-5 deg = 1.9e-4 pulse over 4,000,002 directions; ACOS 3.1e-7 rad = 1.8e-5 deg =
2.0e-4 pulse over 2,000,007 arguments: a few float32 ulps of pi, about 2,500 times below
half a pulse (0.045 deg).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache

import numpy as np
import numpy.typing as npt

__all__ = [
    "ATAN_DEGREE",
    "ApproxError",
    "acos_f32",
    "atan2_f32",
    "atan_coefficients",
    "measure_errors",
]

ATAN_DEGREE = 9
"""Odd polynomial degree of the reduced arctangent (5 coefficients)."""

TAN_PI_12 = 2.0 - math.sqrt(3.0)  # tan(15 deg), the reduction threshold
SQRT3 = math.sqrt(3.0)


@cache
def atan_coefficients(degree: int = ATAN_DEGREE) -> tuple[float, ...]:
    """Coefficients c_k of ``atan(t) ~ t * sum_k c_k t^(2k)`` on |t| <= tan(pi/12).

    Least squares of the relative error on 512 Chebyshev nodes (deterministic), each
    coefficient then rounded to float32 because that is what a REAL constant in the PLC
    program holds.

    Returns
    -------
    tuple of float
        ``(degree + 1) // 2`` coefficients, c0 first (c0 ~ 1, c1 ~ -1/3, ...).
    """
    if degree < 1 or degree % 2 == 0:
        raise ValueError(f"degree = {degree} must be a positive odd integer")
    n = (degree + 1) // 2
    k = np.arange(512)
    t = TAN_PI_12 * 0.5 * (1.0 + np.cos(np.pi * (k + 0.5) / k.size))
    u = t * t
    A = np.stack([u**j for j in range(n)], axis=-1)
    target = np.arctan(t) / t
    coef, *_ = np.linalg.lstsq(A, target, rcond=None)
    return tuple(float(np.float32(c)) for c in coef)


def _f(x) -> npt.NDArray[np.float32]:
    return np.asarray(x, dtype=np.float32)


def atan2_f32(
    y: npt.ArrayLike, x: npt.ArrayLike, degree: int = ATAN_DEGREE
) -> npt.NDArray[np.float32]:
    """The generated ATAN2 subroutine, evaluated step by step in float32.

    Parameters
    ----------
    y, x : array_like (broadcast), REAL
        Finite arguments (the PLC program never calls it with NaN or inf).

    Returns
    -------
    ndarray of float32
        Angle [rad] in [-pi, pi]; 0 for y = x = 0.
    """
    f32 = np.float32
    y, x = np.broadcast_arrays(_f(y), _f(x))
    a, b = np.abs(y), np.abs(x)
    swap = a > b
    num = np.where(swap, b, a)
    den = np.where(swap, a, b)
    zero = den == 0
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(zero, f32(0), num / np.where(zero, f32(1), den)).astype(f32)
    red = t > f32(TAN_PI_12)
    with np.errstate(divide="ignore", invalid="ignore"):
        t_red = ((t * f32(SQRT3) - f32(1)) / (t + f32(SQRT3))).astype(f32)
    tr = np.where(red, t_red, t)
    u = (tr * tr).astype(f32)
    coef = atan_coefficients(degree)
    p = f32(coef[-1]) * np.ones_like(u)
    for c in coef[-2::-1]:  # Horner, one float32 rounding per operation
        p = (p * u).astype(f32)
        p = (p + f32(c)).astype(f32)
    r = (p * tr).astype(f32)
    r = np.where(red, (r + f32(math.pi / 6)).astype(f32), r)
    r = np.where(swap, (f32(math.pi / 2) - r).astype(f32), r)
    r = np.where(x < 0, (f32(math.pi) - r).astype(f32), r)
    r = np.where(y < 0, -r, r)
    return np.where(zero, f32(0), r).astype(f32)


def acos_f32(c: npt.ArrayLike, degree: int = ATAN_DEGREE) -> npt.NDArray[np.float32]:
    """The generated ACOS subroutine in float32: ``atan2(sqrt((1 - c)(1 + c)), c)``.

    Parameters
    ----------
    c : array_like, REAL in [-1, 1]
        The caller (the IK program) clips cos(theta3) to [-1, 1] before the call.

    Returns
    -------
    ndarray of float32
        Angle [rad] in [0, pi].
    """
    f32 = np.float32
    c = _f(c)
    if (np.abs(c) > 1).any():
        raise ValueError(f"acos argument outside [-1, 1]: max |c| = {float(np.abs(c).max())}")
    s = np.sqrt(((f32(1) - c) * (f32(1) + c)).astype(f32)).astype(f32)
    return atan2_f32(s, c, degree)


@dataclass(frozen=True)
class ApproxError:
    """Worst-case error of one generated function over a dense sweep (float32 evaluation)."""

    name: str
    samples: int
    max_rad: float
    argmax: float
    pulses_per_rev: float

    @property
    def max_deg(self) -> float:
        return math.degrees(self.max_rad)

    @property
    def max_pulses(self) -> float:
        """Worst error expressed in stepper pulses (eqs. 20-22)."""
        return self.max_deg / 360.0 * self.pulses_per_rev


def measure_errors(
    pulses_per_rev: float = 4000, n: int = 2_000_001, degree: int = ATAN_DEGREE
) -> dict[str, ApproxError]:
    """Dense sweeps of the float32 ATAN2 and ACOS against float64 numpy.

    ``atan2`` is swept over the full circle of directions (angle grid of ``n`` points,
    unit radius and radius 500 mm, the scale of the arm), ``acos`` over ``n`` points of
    [-1, 1] plus the float32 neighbours of -1, 0 and 1. The reference is
    ``np.arctan2``/``np.arccos`` of the *same float32 inputs*, so the numbers are the
    error of the routine, not of the argument rounding.

    Returns
    -------
    dict
        ``{"atan2": ApproxError, "acos": ApproxError}``.
    """
    ang = np.linspace(-np.pi, np.pi, n)
    out = {}
    worst = (0.0, 0.0)
    for radius in (1.0, 500.0):
        y = np.float32(radius * np.sin(ang))
        x = np.float32(radius * np.cos(ang))
        err = np.abs(
            atan2_f32(y, x, degree).astype(float) - np.arctan2(y.astype(float), x.astype(float))
        )
        # the two results of +-pi are the same angle
        err = np.minimum(err, np.abs(err - 2 * np.pi))
        i = int(np.argmax(err))
        if err[i] > worst[0]:
            worst = (float(err[i]), float(ang[i]))
    out["atan2"] = ApproxError("atan2", 2 * n, worst[0], worst[1], float(pulses_per_rev))
    c = np.linspace(-1.0, 1.0, n).astype(np.float32)
    edges = np.concatenate(
        [
            np.nextafter(np.float32(v), np.float32(d), dtype=np.float32)[None]
            for v in (-1.0, 0.0, 1.0)
            for d in (-2.0, 2.0)
        ]
    )
    c = np.clip(np.concatenate([c, edges]), -1, 1).astype(np.float32)
    err = np.abs(acos_f32(c, degree).astype(float) - np.arccos(c.astype(float)))
    i = int(np.argmax(err))
    out["acos"] = ApproxError("acos", c.size, float(err[i]), float(c[i]), float(pulses_per_rev))
    return out

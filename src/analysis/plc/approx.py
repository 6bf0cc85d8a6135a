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

:func:`atan2_poly` is that algorithm, written once against a math namespace: recorded, it
becomes the subroutine (:mod:`analysis.plc.ir`); run with :class:`PlcFloat32Ops` (every
operation rounded to float32, as a REAL accumulator/V-memory store is) it is the exact
model of the subroutine, so the approximation error is measured densely in Python and the
awlsim runs confirm that the generated STL computes the same thing.

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

from analysis.kinematics.ops import Float32Ops

__all__ = [
    "ATAN_DEGREE",
    "ApproxError",
    "PlcFloat32Ops",
    "acos_f32",
    "atan2_f32",
    "atan2_from_atan",
    "atan2_poly",
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


def atan2_poly(m, y, x, degree: int = ATAN_DEGREE):
    """ATAN2(y, x) [rad] in [-pi, pi] from ``+ - * /`` and compares only: the algorithm of
    the generated S7-200 subroutine (steps 1-5 of the module docstring), written once.

    Run with :class:`PlcFloat32Ops` it is the exact float32 model of the subroutine; recorded
    with :class:`~analysis.kinematics.trace.TraceOps` it *is* the subroutine
    (:func:`analysis.plc.ir.atan2_subroutine`). Both reductions are computed and chosen
    with selects (a PLC executes a few more instructions; no value is ever NaN or inf:
    the divisors are >= 1 or the max(|x|, |y|) > 0).
    """
    a = m.let("A", m.abs(y))
    b = m.let("B", m.abs(x))
    swap = m.gt(a, b)
    num = m.select(swap, b, a)
    den = m.select(swap, a, b)
    zero = m.eq(den, 0.0)
    t = m.let("T", num / m.select(zero, 1.0, den))
    red = m.gt(t, TAN_PI_12)
    t = m.let("T", m.select(red, (t * SQRT3 - 1.0) / (t + SQRT3), t))
    u = m.let("U", t * t)
    coef = atan_coefficients(degree)
    p = coef[-1] * u + coef[-2]
    for c in coef[-3::-1]:  # Horner in u = t^2
        p = p * u + c
    r = p * t
    r = m.select(red, r + math.pi / 6, r)
    r = m.select(swap, math.pi / 2 - r, r)
    r = m.select(m.lt(x, 0.0), math.pi - r, r)
    r = m.select(m.lt(y, 0.0), -r, r)
    return m.select(zero, 0.0, r)


def atan2_from_atan(m, y, x, *, names: bool = False):
    """ATAN2(y, x) [rad] from the S7-300's ATAN instruction and quadrant selects.

    ``atan(y / x)``, plus pi (y >= 0) or minus pi (y < 0) for x < 0; +-pi/2 or 0 on x = 0.
    The generated S7-300 program computes exactly this (:mod:`analysis.plc.ir`). ``names``:
    the intermediates named (``m.let``) for a program a person reads.
    """

    def let(name, value):
        return m.let(name, value) if names else value

    xz = m.eq(x, 0.0)
    divisor = let("divisor", m.select(xz, 1.0, x))
    r = let("principal", m.atan(y / divisor))
    r = let("quadrant", m.select(m.lt(x, 0.0), m.select(m.lt(y, 0.0), r - math.pi, r + math.pi),
                                 r))  # fmt: skip
    on_axis = let("on_axis", m.select(m.gt(y, 0.0), math.pi / 2,
                                      m.select(m.lt(y, 0.0), -math.pi / 2, 0.0)))  # fmt: skip
    return m.select(xz, on_axis, r)


class PlcFloat32Ops(Float32Ops):
    """The REAL arithmetic of a generated program, instruction for instruction.

    ``dialect`` names a printer of :data:`analysis.plc.dialects.DIALECTS`, whose
    ``rounding`` is the tie rule: ``"s7-200"``, ROUND halves away from zero; ``"s7-300"``,
    RND halves to even; ``"st"``/``"scl"``/``"plcopen-xml"`` (IEC 61131-3 ST, Siemens SCL:
    :mod:`analysis.plc.st`): halves away from zero, the tie fixed after ``REAL_TO_DINT``.
    ``trig="subroutine"`` (the default on the S7-200, the only choice there): ATAN2 and ACOS
    are the generated subroutines (:func:`atan2_poly`, ``acos_via_atan2``); ``"native"``
    (the S7-300 default): ATAN with quadrant selects (:func:`atan2_from_atan`) and ACOS, which
    awlsim evaluates in double precision and stores as float32; ``"function"`` (the ST and
    SCL default): the same values, ATAN2 a generated function on ATAN.
    """

    def __init__(
        self, dialect: str = "s7-200", trig: str | None = None, degree: int = ATAN_DEGREE
    ) -> None:
        # the dialect's tie rule and trigonometry, as its printer class says (the registry
        # sits above this module: the printers print what the lowering, which imports this
        # module, writes)
        from analysis.plc.dialects import printer_class

        cls = printer_class(dialect)
        trig = cls.check_trig(trig)
        super().__init__(cls.rounding)
        self.dialect, self.trig, self.degree = dialect, trig, degree

    def atan2(self, y, x):
        y, x = np.asarray(y, np.float32), np.asarray(x, np.float32)
        with np.errstate(divide="ignore", invalid="ignore"):
            if self.trig == "subroutine":
                return atan2_poly(self, y, x, self.degree)
            return atan2_from_atan(self, y, x)

    def acos(self, c):
        if self.trig == "subroutine":
            return self.acos_via_atan2(np.asarray(c, np.float32))
        return super().acos(c)


def atan2_f32(
    y: npt.ArrayLike, x: npt.ArrayLike, degree: int = ATAN_DEGREE
) -> npt.NDArray[np.float32]:
    """The generated ATAN2 subroutine evaluated in float32 (finite arguments)."""
    y, x = np.broadcast_arrays(np.asarray(y, np.float32), np.asarray(x, np.float32))
    return np.asarray(PlcFloat32Ops("s7-200", degree=degree).atan2(y, x), np.float32)


def acos_f32(c: npt.ArrayLike, degree: int = ATAN_DEGREE) -> npt.NDArray[np.float32]:
    """The generated ACOS subroutine in float32: ``atan2(sqrt((1 - c)(1 + c)), c)``.

    The caller (the IK program) clips cos(theta3) to [-1, 1] before the call.
    """
    c = np.asarray(c, dtype=np.float32)
    if (np.abs(c) > 1).any():
        raise ValueError(f"acos argument outside [-1, 1]: max |c| = {float(np.abs(c).max())}")
    return np.asarray(PlcFloat32Ops("s7-200", degree=degree).acos(c), np.float32)


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

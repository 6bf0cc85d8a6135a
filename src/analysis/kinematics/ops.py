"""Math namespaces: one closed form, evaluated with numpy, float32, sympy, duals or a tracer.

Every closed form in :mod:`analysis.kinematics.arms` is written once, as a function of a
namespace ``m`` (the idea of spatialmath-python's float/sympy duality, taken one step
further). The same body runs with

============  ==============================================================================
``NumpyOps``  float64 arrays: the reference batch solver (:mod:`analysis.kinematics.arm`)
``Float32``   IEEE single precision, a PLC's REAL (:class:`Float32Ops`)
``SympyOps``  SymPy expressions, what the audit holds against the printed equations
              (:mod:`analysis.kinematics.symbolic`)
``DualOps``   forward-mode derivatives: Jacobians derived from the D-H chain
``TraceOps``  a recorder (:mod:`analysis.kinematics.trace`): the compiled kernel and the
              PLC program are generated from the recording
============  ==============================================================================

Base operations (each namespace implements them): ``+ - * /`` and unary minus on its
values, ``sqrt sin cos atan2 acos abs trunc sign``, comparisons ``lt le gt ge eq`` that give
conditions, ``and_ or_ not_`` on conditions, ``select(cond, a, b)`` (a where cond, else b)
and ``isfinite``. Everything else is *defined once, here*, in terms of those:
:meth:`Ops.wrap` (to (-pi, pi]), :meth:`Ops.clip`, :meth:`Ops.round_half_away` (the S7-200
``ROUND``), :meth:`Ops.degrees`, :meth:`Ops.acos_via_atan2`. A namespace may declare one
of them primitive (the PLC has a native ``ROUND``), never re-implement it with a
different formula. ``SympyOps`` treats ``wrap`` and ``clip`` as the identity: the
symbolic closed form describes the reachable set, where they act only on the
representation of an angle and on round-off.

``let(name, value)`` names an intermediate (readable generated code; identity elsewhere)
and ``section(title)`` marks a step of the derivation (a PLC network; no-op elsewhere).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["Dual", "DualOps", "Float32Ops", "NumpyOps", "Ops", "numpy_ops"]

TWO_PI = 2.0 * math.pi


class Ops:
    """Base of every namespace: the derived primitives, defined once.

    Subclasses provide the base operations listed in the module docstring.
    """

    pi = math.pi
    rounding = "half-away"

    def __init__(self, rounding: str = "half-away") -> None:
        if rounding not in ("half-away", "half-even"):
            raise ValueError(f"rounding {rounding!r}: expected 'half-away' or 'half-even'")
        self.rounding = rounding

    # --- naming and structure (no arithmetic meaning) ----------------------------------
    def let(self, name: str, value):
        """Name an intermediate ``value`` (for generated code); returns it unchanged."""
        return value

    def section(self, title: str) -> None:
        """Mark the start of a step of the derivation (a PLC network); no-op here."""

    # --- derived primitives: the only definitions in the project ------------------------
    def wrap(self, a):
        """Angle ``a`` [rad] with ``|a| < 3 pi`` wrapped to (-pi, pi].

        Two conditional shifts by 2 pi, exact for the sums of at most three principal
        angles that the closed forms build (an ``fmod`` would round once more).
        """
        a = self.select(self.gt(a, self.pi), a - TWO_PI, a)
        return self.select(self.le(a, -self.pi), a + TWO_PI, a)

    def clip(self, x, lo: float, hi: float):
        """``x`` limited to [lo, hi] (used on cos(theta) against round-off past +-1)."""
        x = self.select(self.lt(x, lo), lo, x)
        return self.select(self.gt(x, hi), hi, x)

    def round_half_away(self, x):
        """Nearest whole number, ties away from zero (the S7-200 ``ROUND``, eqs. 20-22).

        ``trunc(x)`` plus the exact fractional part compared with 1/2: ``floor(|x| + 0.5)``
        would round 0.49999999999999994 up, because ``|x| + 0.5`` rounds to 1.0 first.
        """
        whole = self.trunc(x)
        return whole + self.select(self.ge(self.abs(x - whole), 0.5), self.sign(x), 0.0)

    def round(self, x):
        """The pulse rounding of this namespace: :meth:`round_half_away` (the S7-200
        ``ROUND``), or the base operation ``rint`` (ties to even, the S7-300 ``RND``) if
        the namespace was made with ``rounding="half-even"``."""
        if self.rounding == "half-even":
            return self.rint(x)
        return self.round_half_away(x)

    def radians(self, x):
        """Degrees to radians as ``numpy.radians`` computes it: ``x * (pi / 180)``."""
        return x * (math.pi / 180.0)

    def degrees(self, x):
        """Radians to degrees as ``numpy.degrees`` computes it: ``x * (180 / pi)``."""
        return x * (180.0 / math.pi)

    def acos_via_atan2(self, c):
        """``acos(c) = atan2(sqrt((1 - c)(1 + c)), c)`` for c in [-1, 1].

        ``1 - c`` is exact for c in [0.5, 1] (Sterbenz), so the angle keeps full relative
        precision at the stretched and folded elbow; the square root is shared with the
        closed forms that need sin(acos c) = sqrt((1 - c)(1 + c)) as well.
        """
        return self.atan2(self.sqrt((1.0 - c) * (1.0 + c)), c)

    def any_(self, *conds):
        """Logical or of one or more conditions."""
        out = conds[0]
        for c in conds[1:]:
            out = self.or_(out, c)
        return out


class NumpyOps(Ops):
    """float64 numpy arrays (broadcasting): the reference evaluation of every closed form."""

    dtype = np.float64

    def const(self, x):
        return np.asarray(x, dtype=self.dtype)

    sqrt = staticmethod(np.sqrt)
    sin = staticmethod(np.sin)
    cos = staticmethod(np.cos)
    atan = staticmethod(np.arctan)
    atan2 = staticmethod(np.arctan2)
    acos = staticmethod(np.arccos)
    abs = staticmethod(np.abs)
    rint = staticmethod(np.rint)
    trunc = staticmethod(np.trunc)
    sign = staticmethod(np.sign)
    lt = staticmethod(np.less)
    le = staticmethod(np.less_equal)
    gt = staticmethod(np.greater)
    ge = staticmethod(np.greater_equal)
    eq = staticmethod(np.equal)
    and_ = staticmethod(np.logical_and)
    or_ = staticmethod(np.logical_or)
    not_ = staticmethod(np.logical_not)
    isfinite = staticmethod(np.isfinite)

    def select(self, cond, a, b):
        return np.where(cond, a, b)


numpy_ops = NumpyOps()
"""The shared float64 numpy namespace (stateless)."""


class Float32Ops(NumpyOps):
    """IEEE single precision, step by step: the REAL arithmetic of a PLC.

    Every value, constant and intermediate is a ``float32``; ``+ - * / sqrt`` are correctly
    rounded by IEEE 754 (and by awlsim, which rounds each double result to float32, an
    exact model for these operations). The transcendental functions are computed in
    float64 and rounded once (a correctly rounded library, which is what awlsim's native
    S7-300 ``SIN``/``COS``/``ATAN``/``ACOS`` give): numpy's own float32 ``arctan2``/``sin``
    are SIMD approximations whose last bits depend on the CPU (AVX2 vs AVX-512), so a
    model built on them would not reproduce on another machine. The S7-200 program's
    generated ATAN2/ACOS subroutines are modelled in :mod:`analysis.plc.model`.

    ``rounding`` picks the pulse rounding instruction: ``"half-away"`` (S7-200 ``ROUND``)
    or ``"half-even"`` (S7-300 ``RND``).
    """

    dtype = np.float32

    def __init__(self, rounding: str = "half-away") -> None:
        super().__init__(rounding)

    @staticmethod
    def _f32(fn):
        def wrapped(*args):
            wide = [np.asarray(a, dtype=np.float64) for a in args]
            return np.asarray(fn(*wide), dtype=np.float32)

        return staticmethod(wrapped)

    sin = _f32(np.sin)
    cos = _f32(np.cos)
    atan = _f32(np.arctan)
    atan2 = _f32(np.arctan2)
    acos = _f32(np.arccos)

    def sqrt(self, x):
        return np.sqrt(np.asarray(x, dtype=np.float32))

    def select(self, cond, a, b):
        return np.where(cond, np.float32(a) if np.isscalar(a) else a, b).astype(np.float32)

    def degrees(self, x):
        return x * np.float32(180.0 / math.pi)


class Dual:
    """A value and its derivatives with respect to k seeds: ``v + sum_i d_i eps_i``."""

    __slots__ = ("d", "v")

    def __init__(self, v, d):
        self.v, self.d = v, d

    def __add__(self, o):
        if isinstance(o, Dual):
            return Dual(self.v + o.v, [a + b for a, b in zip(self.d, o.d, strict=True)])
        return Dual(self.v + o, self.d)

    __radd__ = __add__

    def __sub__(self, o):
        if isinstance(o, Dual):
            return Dual(self.v - o.v, [a - b for a, b in zip(self.d, o.d, strict=True)])
        return Dual(self.v - o, self.d)

    def __rsub__(self, o):
        return Dual(o - self.v, [-a for a in self.d])

    def __mul__(self, o):
        if isinstance(o, Dual):
            return Dual(
                self.v * o.v, [a * o.v + self.v * b for a, b in zip(self.d, o.d, strict=True)]
            )
        return Dual(self.v * o, [a * o for a in self.d])

    __rmul__ = __mul__

    def __truediv__(self, o):
        if isinstance(o, Dual):
            q = self.v / o.v
            return Dual(q, [(a - q * b) / o.v for a, b in zip(self.d, o.d, strict=True)])
        return Dual(self.v / o, [a / o for a in self.d])

    def __neg__(self):
        return Dual(-self.v, [-a for a in self.d])


class DualOps(Ops):
    """Forward-mode differentiation on top of another namespace (numpy by default).

    Used to derive Jacobians from the D-H chain (:meth:`analysis.kinematics.arm.Arm.jacobian`)
    instead of writing derivatives by hand. Only the smooth operations the chains need are
    provided (``sin``, ``cos``, ``sqrt`` and arithmetic).
    """

    def __init__(self, base: Ops = numpy_ops) -> None:
        super().__init__()
        self.base = base

    def seed(self, values, k: int | None = None):
        """Duals for ``values`` with unit derivative along their own index."""
        n = len(values)
        return [
            Dual(v, [1.0 if i == j else 0.0 for j in range(n if k is None else k)])
            for i, v in enumerate(values)
        ]

    def sin(self, x):
        if not isinstance(x, Dual):
            return self.base.sin(x)
        c = self.base.cos(x.v)
        return Dual(self.base.sin(x.v), [a * c for a in x.d])

    def cos(self, x):
        if not isinstance(x, Dual):
            return self.base.cos(x)
        s = self.base.sin(x.v)
        return Dual(self.base.cos(x.v), [-a * s for a in x.d])

    def sqrt(self, x):
        if not isinstance(x, Dual):
            return self.base.sqrt(x)
        r = self.base.sqrt(x.v)
        return Dual(r, [a / (2.0 * r) for a in x.d])

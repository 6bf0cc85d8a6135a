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

Base operations: the one table :data:`OPS` (one :class:`OpSpec` per operation: its name,
arity, kind, the namespace method, the numpy and SymPy equivalents, the constant fold). The
namespaces here and in :mod:`analysis.kinematics.symbolic`, the recorder
(:mod:`analysis.kinematics.trace`), the compiled kernel's printer
(:mod:`analysis.kinematics.compiled`) and the PLC printers (:mod:`analysis.plc.dialects`,
:mod:`analysis.plc.st`) all take the vocabulary from it: a new operation is one row here plus
one method in each printer that can express it (the others refuse it by name, see
:class:`analysis.kinematics.printing.Printer`). In short: ``+ - * /`` and unary minus on
values, ``sqrt sin cos atan atan2 acos abs trunc sign rint``, comparisons ``lt le gt ge eq``
that give conditions, ``and_ or_ not_`` on conditions, ``select(cond, a, b)`` (a where cond,
else b) and ``isfinite``. Everything else is *defined once, here*, in terms of those:
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
import operator
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = [
    "OPS",
    "Dual",
    "DualOps",
    "Float32Ops",
    "NumpyOps",
    "OpSpec",
    "Ops",
    "numpy_ops",
]

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class OpSpec:
    """One operation of the vocabulary.

    Attributes
    ----------
    name : str
        The operation's name: a recorded node's ``op`` and a PLC IR instruction's.
    arity : int
    kind : {"arith", "function", "compare", "logic", "select", "derived"}
        ``arith``: a Python operator on values (``+ - * /``, unary ``-``); ``function``:
        value -> value; ``compare``: values -> condition; ``logic``: conditions ->
        condition; ``select``: (condition, value, value) -> value; ``derived``: defined
        once in :class:`Ops` from the others, recorded as one node only where a namespace
        keeps it primitive (a PLC's native ``ROUND`` and ``ACOS``).
    method : str
        The namespace attribute (``and_`` for ``and``: a Python keyword).
    numpy : str or None
        The numpy function of :class:`NumpyOps` (None: an operator, or written there).
    sympy : str or None
        The SymPy function of :class:`~analysis.kinematics.symbolic.SympyOps` (resolved
        there: importing SymPy is slow).
    fold : callable or None
        Evaluation on Python floats: the recorder folds operations on constants with it
        (None: never folded); for ``arith`` it is the operator itself (also on arrays,
        SymPy expressions and recorded nodes).
    symbol : str
        Infix symbol (``arith``, ``compare``), for the printers.
    dunder : str
        The Python operator method of a binary ``arith`` row (``add`` -> ``__add__`` and
        ``__radd__``), which recorded values define.
    rounded_once : bool
        Not correctly rounded by numpy in single precision: :class:`Float32Ops` computes it
        in float64 and rounds once (what awlsim and the ST engine do).
    """

    name: str
    arity: int
    kind: str
    method: str = ""
    numpy: str | None = None
    sympy: str | None = None
    fold: Callable | None = None
    symbol: str = ""
    rounded_once: bool = False
    dunder: str = ""

    def __post_init__(self) -> None:
        if not self.method:
            object.__setattr__(self, "method", self.name)


def _sign(a: float) -> float:
    return float((a > 0) - (a < 0))


OPS: dict[str, OpSpec] = {
    s.name: s
    for s in (
        OpSpec("add", 2, "arith", fold=operator.add, symbol="+", dunder="add"),
        OpSpec("sub", 2, "arith", fold=operator.sub, symbol="-", dunder="sub"),
        OpSpec("mul", 2, "arith", fold=operator.mul, symbol="*", dunder="mul"),
        OpSpec("div", 2, "arith", fold=operator.truediv, symbol="/", dunder="truediv"),
        OpSpec("neg", 1, "arith", fold=operator.neg, symbol="-"),
        OpSpec("sqrt", 1, "function", numpy="sqrt", sympy="sqrt", fold=math.sqrt),
        OpSpec("sin", 1, "function", numpy="sin", sympy="sin", fold=math.sin, rounded_once=True),
        OpSpec("cos", 1, "function", numpy="cos", sympy="cos", fold=math.cos, rounded_once=True),
        OpSpec(
            "atan", 1, "function", numpy="arctan", sympy="atan", fold=math.atan, rounded_once=True
        ),
        OpSpec(
            "atan2",
            2,
            "function",
            numpy="arctan2",
            sympy="atan2",
            fold=math.atan2,
            rounded_once=True,
        ),
        OpSpec(
            "acos", 1, "derived", numpy="arccos", sympy="acos", fold=math.acos, rounded_once=True
        ),
        OpSpec("abs", 1, "function", numpy="abs", sympy="Abs", fold=abs),
        OpSpec("trunc", 1, "function", numpy="trunc", fold=lambda a: float(math.trunc(a))),
        OpSpec("sign", 1, "function", numpy="sign", sympy="sign", fold=_sign),
        OpSpec("rint", 1, "function", numpy="rint"),
        OpSpec("round", 1, "derived"),
        OpSpec("lt", 2, "compare", numpy="less", sympy="Lt", symbol="<"),
        OpSpec("le", 2, "compare", numpy="less_equal", sympy="Le", symbol="<="),
        OpSpec("gt", 2, "compare", numpy="greater", sympy="Gt", symbol=">"),
        OpSpec("ge", 2, "compare", numpy="greater_equal", sympy="Ge", symbol=">="),
        OpSpec("eq", 2, "compare", numpy="equal", sympy="Eq", symbol="=="),
        OpSpec("and", 2, "logic", method="and_", numpy="logical_and", sympy="And"),
        OpSpec("or", 2, "logic", method="or_", numpy="logical_or", sympy="Or"),
        OpSpec("not", 1, "logic", method="not_", numpy="logical_not", sympy="Not"),
        OpSpec("select", 3, "select"),
        OpSpec("isfinite", 1, "function", numpy="isfinite"),
    )
}
"""The operations of every namespace, recording and printer (module docstring)."""

CONDITIONS = frozenset(n for n, s in OPS.items() if s.kind in ("compare", "logic"))
"""Operations whose result is a condition, not a value."""


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
    """float64 numpy arrays (broadcasting): the reference evaluation of every closed form.

    Its operations are the numpy functions of :data:`OPS`."""

    dtype = np.float64

    def const(self, x):
        return np.asarray(x, dtype=self.dtype)

    def select(self, cond, a, b):
        return np.where(cond, a, b)


for _s in OPS.values():
    if _s.numpy is not None:
        setattr(NumpyOps, _s.method, staticmethod(getattr(np, _s.numpy)))


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

    def select(self, cond, a, b):
        return np.where(cond, np.float32(a) if np.isscalar(a) else a, b).astype(np.float32)

    def degrees(self, x):
        return x * np.float32(180.0 / math.pi)


def _f32(fn):
    """``fn`` computed in float64 and rounded once to float32 (:class:`Float32Ops`)."""

    def wrapped(*args):
        wide = [np.asarray(a, dtype=np.float64) for a in args]
        return np.asarray(fn(*wide), dtype=np.float32)

    return staticmethod(wrapped)


def _real_args(fn):
    """``fn`` of its arguments as REALs (:class:`Float32Ops`). numpy's ``abs``, ``trunc``,
    ``sign`` or ``rint`` of a parameter (a Python float: the palletizer's inner radius
    ``|L1 - L2|``) is a float64, which would carry every expression it enters into double
    precision; the program holds it in a REAL. (Found by the PLC sweep's exact stops: the
    model was one ulp off awlsim on 2 of 1,078 palletizer targets.)"""

    def wrapped(*args):
        return fn(*(np.asarray(a, dtype=np.float32) for a in args))

    return staticmethod(wrapped)


for _s in OPS.values():
    if _s.rounded_once:
        setattr(Float32Ops, _s.method, _f32(getattr(np, _s.numpy)))
    elif _s.kind == "function" and _s.numpy and _s.method not in Float32Ops.__dict__:
        setattr(Float32Ops, _s.method, _real_args(getattr(np, _s.numpy)))
del _s


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

    def __rtruediv__(self, o):
        q = o / self.v
        return Dual(q, [-q * a / self.v for a in self.d])

    def __abs__(self):
        s = np.sign(self.v)
        return Dual(abs(self.v), [s * a for a in self.d])

    def __pow__(self, k):
        if isinstance(k, bool) or not isinstance(k, (int, float)) or k != int(k) or k < 0:
            raise TypeError(f"** {k!r}: a dual takes whole exponents >= 0")
        out = 1.0
        for _ in range(int(k)):
            out = self * out
        return out


class DualOps(Ops):
    """Forward-mode differentiation on top of another namespace (numpy by default).

    Used to derive Jacobians from the D-H chain (:meth:`analysis.kinematics.arm.Arm.jacobian`)
    instead of writing derivatives by hand. The operations the chains need are provided:
    arithmetic, ``sin``, ``cos``, ``sqrt``, ``atan2`` and ``acos`` (the picker's passive
    joints), ``abs``; comparisons act on the values and ``select`` carries the chosen
    derivatives.
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

    def atan2(self, y, x):
        if not isinstance(y, Dual) and not isinstance(x, Dual):
            return self.base.atan2(y, x)
        yv, xv = (a.v if isinstance(a, Dual) else a for a in (y, x))
        yd, xd = (a.d if isinstance(a, Dual) else None for a in (y, x))
        r2 = xv * xv + yv * yv
        k = len(yd or xd)
        d = [((xv * (yd[i] if yd else 0.0)) - yv * (xd[i] if xd else 0.0)) / r2 for i in range(k)]
        return Dual(self.base.atan2(yv, xv), d)

    def acos(self, c):
        if not isinstance(c, Dual):
            return self.base.acos(c)
        s = self.base.sqrt((1.0 - c.v) * (1.0 + c.v))
        return Dual(self.base.acos(c.v), [-a / s for a in c.d])

    # conditions and selections act on the values; a selection carries the chosen derivatives
    def _v(self, x):
        return x.v if isinstance(x, Dual) else x

    def lt(self, a, b):
        return self.base.lt(self._v(a), self._v(b))

    def le(self, a, b):
        return self.base.le(self._v(a), self._v(b))

    def gt(self, a, b):
        return self.base.gt(self._v(a), self._v(b))

    def ge(self, a, b):
        return self.base.ge(self._v(a), self._v(b))

    def eq(self, a, b):
        return self.base.eq(self._v(a), self._v(b))

    def and_(self, a, b):
        return self.base.and_(a, b)

    def or_(self, a, b):
        return self.base.or_(a, b)

    def not_(self, a):
        return self.base.not_(a)

    def abs(self, x):
        return abs(x)

    def select(self, cond, a, b):
        if not isinstance(a, Dual) and not isinstance(b, Dual):
            return self.base.select(cond, a, b)
        k = len(a.d if isinstance(a, Dual) else b.d)
        da = a.d if isinstance(a, Dual) else [0.0] * k
        db = b.d if isinstance(b, Dual) else [0.0] * k
        v = self.base.select(cond, self._v(a), self._v(b))
        return Dual(v, [self.base.select(cond, x, y) for x, y in zip(da, db, strict=True)])

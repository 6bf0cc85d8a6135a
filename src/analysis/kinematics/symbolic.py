"""The SymPy namespace: a closed form of :mod:`analysis.kinematics.arms` as formulas.

Kept apart from :mod:`analysis.kinematics.ops` because importing SymPy takes half a second,
which the command line and the numeric paths do not pay.
"""

from __future__ import annotations

import sympy as sp

from analysis.kinematics.ops import Ops

__all__ = ["SympyOps", "sympy_ops"]


class SympyOps(Ops):
    """SymPy expressions: the closed form as a formula, for the audit and the notebooks.

    ``wrap`` and ``clip`` are the identity (see the module docstring); ``select`` is a
    ``Piecewise``; conditions are SymPy relationals.
    """

    pi = sp.pi

    def const(self, x):
        return sp.sympify(x)

    sqrt = staticmethod(sp.sqrt)
    sin = staticmethod(sp.sin)
    cos = staticmethod(sp.cos)
    atan = staticmethod(sp.atan)
    atan2 = staticmethod(sp.atan2)
    acos = staticmethod(sp.acos)
    abs = staticmethod(sp.Abs)
    sign = staticmethod(sp.sign)
    lt = staticmethod(sp.Lt)
    le = staticmethod(sp.Le)
    gt = staticmethod(sp.Gt)
    ge = staticmethod(sp.Ge)
    eq = staticmethod(sp.Eq)
    and_ = staticmethod(sp.And)
    or_ = staticmethod(sp.Or)
    not_ = staticmethod(sp.Not)

    def trunc(self, x):
        return sp.sign(x) * sp.floor(sp.Abs(x))

    def isfinite(self, x):
        return sp.true

    def select(self, cond, a, b):
        return sp.Piecewise((a, cond), (b, True))

    def wrap(self, a):
        return a

    def clip(self, x, lo, hi):
        return x

    def degrees(self, x):
        return x * 180 / sp.pi


sympy_ops = SympyOps()

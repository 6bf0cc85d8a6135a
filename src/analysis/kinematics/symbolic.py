"""The SymPy namespace: a closed form of :mod:`analysis.kinematics.arms` as formulas.

Kept apart from :mod:`analysis.kinematics.ops` because importing SymPy takes half a second,
which the command line and the numeric paths do not pay.
"""

from __future__ import annotations

import sympy as sp

from analysis.kinematics.ops import OPS, Ops

__all__ = ["SympyOps", "sympy_ops"]


class SympyOps(Ops):
    """SymPy expressions: the closed form as a formula, for the audit and the notebooks.

    Its operations are the SymPy functions of :data:`~analysis.kinematics.ops.OPS`;
    ``wrap`` and ``clip`` are the identity (see the module docstring); ``select`` is a
    ``Piecewise``; conditions are SymPy relationals.
    """

    pi = sp.pi

    def const(self, x):
        return sp.sympify(x)

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


for _s in OPS.values():
    if _s.sympy is not None:
        setattr(SympyOps, _s.method, staticmethod(getattr(sp, _s.sympy)))
del _s

sympy_ops = SympyOps()

"""``sampled``: an equation evaluated on seeded valid configurations, angle-aware.

The domain (``spec["domain"]``, defined by the paper: :meth:`analysis.audit.context.Bespoke.
domain`) gives every symbol a value per sample: the joint angles of configurations from the arm
hook (:func:`analysis.audit.context.sample_q`), the pose the arm's forward kinematics gives
them, the link lengths, and quantities measured on the arm (an elevation, an included angle).
``lhs = rhs`` holds when both sides agree at every sample within ``tol`` (default 1e-9: float64
chains of a few transcendental calls on lengths of 1e2-1e3 mm err by ~1e-13; every printed
error found is >= 1e-3), modulo 2 pi when ``angle`` (default true). With ``residuals`` the text
defines its left-hand symbol (``phi = atan2(Py, Px)``) and each residual expression must vanish
once the symbol is replaced by the right-hand side. With ``defines`` the text is an expression
(eq. 18's printed numerator) held against the domain's value of that name. A side that is
undefined (NaN, a symbol without a value) at any sample is wrong there, and an equation whose
sides are the same function of their symbols (``theta1 = theta1``) says nothing: False.

Example: on the grabber's front-up samples ``theta1 = atan2(Py, Px)`` holds and
``theta1 = atan(Py/Px)`` fails at the first target with Px < 0, which the result names.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from analysis.audit.equivalence import expressions_agree
from analysis.audit.kinds.base import Result, kind
from analysis.audit.kinds.symbolic import equation
from analysis.validate import wrap_rad

__all__ = ["evaluate"]


def evaluate(expr: sp.Expr, values) -> np.ndarray | None:
    """``expr`` at every sample of ``values`` (None if a symbol has no value)."""
    names = sorted(s.name for s in expr.free_symbols)
    if any(n not in values for n in names):
        return None
    n = len(next(iter(v for v in values.values() if np.ndim(v))))
    f = sp.lambdify(names, expr, modules=[{"atan2": np.arctan2}, "numpy"])
    with np.errstate(all="ignore"):
        out = f(*(values[k] for k in names))
    return np.broadcast_to(np.asarray(out, dtype=float), (n,)).copy()


@kind("sampled")
def sampled(text: str, spec, ctx) -> Result:
    values = ctx.domain(spec["domain"])
    ns = spec.get("namespace", "main")
    if "defines" in spec:  # the text is an expression the paper prints for a named quantity
        lhs, rhs = sp.Symbol(spec["defines"]), ctx.paper.parse(text, ns)
    else:
        lhs, rhs = equation(text, ctx, ns)
    angle = spec.get("angle", True)
    if expressions_agree(lhs, rhs, angle=angle):  # true of anything: says nothing of the model
        return Result(False, {"why": "the two sides are the same function of their symbols"})
    if "residuals" in spec:
        if not isinstance(lhs, sp.Symbol):
            return Result(False, {"why": "the left-hand side must be the symbol defined"})
        res = [ctx.paper.parse(r, ns).subs(lhs, rhs) for r in spec["residuals"]]
        errs = [evaluate(r, values) for r in res]
        if any(e is None for e in errs):
            return Result(False, {"why": "a residual has a symbol without a value"})
        err = np.max(np.abs(np.stack(errs)), axis=0)
        a = b = None
    else:
        a, b = evaluate(lhs, values), evaluate(rhs, values)
        if a is None or b is None:
            return Result(False, {"why": "a symbol without a value in the domain"})
        err = np.abs(wrap_rad(a - b) if angle else a - b)
    err = np.where(np.isfinite(err), err, np.inf)
    bad = np.flatnonzero(err > spec.get("tol", 1e-9))
    out = {"n": len(err), "wrong": len(bad), "max_error": float(err.max())}
    if len(bad):
        i = int(bad[0])
        out["at"] = {k: float(v[i]) for k, v in values.items() if np.ndim(v)}
        if a is not None:
            conv = np.degrees if angle else (lambda v: v)
            out.update(got=float(conv(b[i])), want=float(conv(a[i])))
    return Result(not len(bad), out)

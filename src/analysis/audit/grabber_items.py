"""What the grabber audit's checks share: the :class:`Item` record, the derived matrices and
the verdict helpers.

The D-H matrices are derived from :mod:`analysis.kinematics.dh` in SymPy; a printed
expression holds when ``printed - derived`` has the exact normal form 0
(:func:`normal_form`, :func:`is_zero`); formulas with atan/acos are checked numerically on
seeded samples of :mod:`analysis.kinematics.arm`'s front-up solutions (:func:`samples`,
:func:`verify_angle`). The item families are built in :mod:`analysis.audit.grabber_checks`,
:mod:`analysis.audit.grabber_text_checks` and :mod:`analysis.audit.grabber_stl`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache

import numpy as np
import sympy as sp

from analysis.kinematics.arm import paper_arm
from analysis.kinematics.params import paper_params
from analysis.papers import grabber as paper

__all__ = [
    "ANGLE_TOL",
    "IX",
    "KINDS",
    "OWN_PREFIX",
    "PXYZ",
    "TH",
    "Item",
    "S",
    "angle_formula_error",
    "classify",
    "derived_matrices",
    "fk_subs",
    "fmt_p",
    "is_zero",
    "normal_form",
    "parse_eq",
    "samples",
    "sstr",
    "verify_angle",
    "verify_fk_identity",
]

KINDS: tuple[str, ...] = (
    "sign",
    "index",
    "label",
    "missing term",
    "branch/quadrant",
    "transcription",
    "unit",
    "PLC semantics",
    "cross-reference",
)
"""The kinds of discrepancy a register row may have."""
OWN_PREFIX = "paper-"
"""Id prefix of the items (and register rows) generated here."""
ANGLE_TOL = 1e-9
"""Tolerance [rad] for numeric identity checks of angle formulas: float64 round-off of
atan2/acos at |P| ~ 1e3 mm is ~1e-13 rad, far below; a wrong branch is off by >= 1e-3."""


@dataclass(frozen=True)
class Item:
    """One printed statement and its machine verdict.

    ``verdict`` is "holds", "wrong" or "undecidable"; ``kind`` and ``corrected`` are set
    for wrong items; ``verify`` decides whether a text (printed or corrected, same
    notation) is right.
    """

    id: str
    location: str
    printed: str
    derived: str
    verdict: str
    evidence: str
    kind: str = ""
    corrected: str = ""
    verify: Callable[[str], bool] = field(default=lambda text: False, repr=False, compare=False)

    @property
    def check(self) -> str:
        """The test that proves the verdict."""
        return f"tests/audit/test_grabber_audit.py::test_item_verdict[{self.id}]"


# --------------------------------------------------------------------------------------------
# derived objects
# --------------------------------------------------------------------------------------------
S = paper.SYMBOLS
TH = (S["theta1"], S["theta2"], S["theta3"])
PXYZ = (S["Px"], S["Py"], S["Pz"])
IX = sp.symbols("ix iy iz", real=True)
_SC = sp.symbols("s1 s2 s3 c1 c2 c3", real=True)
_TRIG_SUBS = {
    **{sp.sin(t): _SC[i] for i, t in enumerate(TH)},
    **{sp.cos(t): _SC[i + 3] for i, t in enumerate(TH)},
}


def _tsimp(M: sp.Matrix) -> sp.Matrix:
    """Entry-wise trigonometric simplification (much faster than Matrix.simplify here)."""
    return M.applyfunc(lambda e: sp.trigsimp(sp.expand(sp.expand_trig(e))))


def _rigid_inverse(A: sp.Matrix) -> sp.Matrix:
    """[R p; 0 1]^-1 = [R^T -R^T p; 0 1] (as :func:`analysis.kinematics.dh.inverse_transform`,
    symbolic)."""
    R, p = A[:3, :3], A[:3, 3]
    top = R.T.row_join(-R.T * p)
    return _tsimp(top.col_join(sp.Matrix([[0, 0, 0, 1]])))


@cache
def derived_matrices() -> dict[str, sp.Matrix]:
    """The matrices of sections 1.2-1.3 derived from the D-H table (Table 1/3, symbolic)."""
    A1, A2, A3 = paper_params().dh_table(symbolic=True).transforms_sym(TH)
    T3 = _tsimp(A1 * A2 * A3)
    inv = {k: _rigid_inverse(m) for k, m in (("A1inv", A1), ("A2inv", A2), ("A3inv", A3))}
    return {
        "A1": A1,
        "A2": A2,
        "A3": A3,
        **inv,
        "T3": T3,
        "eq4": _tsimp(A2 * A3),
        "eq12": _tsimp(inv["A3inv"] * inv["A2inv"] * inv["A1inv"]),
        "eq12_rhs": sp.eye(4),
    }


def fk_subs() -> dict:
    T3 = derived_matrices()["T3"]
    return dict(zip(PXYZ, (T3[0, 3], T3[1, 3], T3[2, 3]), strict=True))


def normal_form(expr) -> sp.Expr | None:
    """Canonical form of a trigonometric polynomial/rational expression in theta1..3.

    The sines and cosines are expanded into s_i, c_i and the numerator is reduced modulo
    s_i^2 + c_i^2 - 1 (a Groebner basis: the leading terms s_i^2 are pairwise coprime),
    so the result is 0 iff the expression vanishes identically. Returns ``None`` when the
    expression has other functions (atan, acos, ...).
    """
    expr = sp.expand(sp.expand_trig(sp.sympify(expr)))
    if expr == 0:
        return sp.Integer(0)
    num, den = sp.fraction(sp.together(expr))
    num = sp.expand(num).subs(_TRIG_SUBS)
    if num.atoms(sp.Function):
        return None
    gens = (*_SC, *sorted(num.free_symbols - set(_SC), key=str))
    _, rem = sp.reduced(
        num, [_SC[i] ** 2 + _SC[i + 3] ** 2 - 1 for i in range(3)], *gens, order="lex"
    )
    back = {v: k for k, v in _TRIG_SUBS.items()}
    return sp.factor(sp.expand(rem).subs(back)) / den if rem != 0 else sp.Integer(0)


def is_zero(expr) -> bool:
    """Exact test that ``expr`` vanishes identically (:func:`normal_form`, else simplify)."""
    nf = normal_form(expr)
    if nf is None:
        return sp.simplify(expr) == 0
    return nf == 0


def parse_eq(text: str) -> tuple[sp.Expr, sp.Expr]:
    if text.count("=") != 1:
        raise ValueError(f"equation {text!r} must contain exactly one '='")
    lhs, rhs = text.split("=")
    return paper.parse(lhs), paper.parse(rhs)


def classify(printed: sp.Expr, derived: sp.Expr) -> str:
    if printed.is_number and derived.is_number:
        return "transcription"
    if is_zero(printed + derived):
        return "sign"
    if printed == 0 and derived != 0:
        return "missing term"
    return "transcription"


def sstr(e) -> str:
    return sp.sstr(e)


# --------------------------------------------------------------------------------------------
# numeric samples for formulas with atan / acos (front-up: the paper's branch)
# --------------------------------------------------------------------------------------------
PROBES = np.array([[-100.0, 100.0, 600.0], [-200.0, -100.0, 700.0], [150.0, -250.0, 500.0]])
"""Targets outside Table 4's first quadrant, where single-argument tan^-1 fails (mm)."""


@cache
def samples() -> tuple[np.ndarray, np.ndarray]:
    """(P, theta) front-up pairs: Table 4's reachable rows, :data:`PROBES`, 200 seeded targets."""
    from analysis.audit.table4 import load_printed

    arm = paper_arm()
    t4 = load_printed()[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    rng = np.random.default_rng(2016)
    q = np.column_stack(
        [rng.uniform(-np.pi, np.pi, 200), rng.uniform(-1.4, 1.4, 200), rng.uniform(-2.9, -0.1, 200)]
    )
    P = np.vstack([t4, PROBES, arm.fk(q)])
    sol = arm.solve(P, ("front-up",))
    keep = sol.ok[:, 0]
    return P[keep], sol.theta[keep, 0, :]


def angle_formula_error(lhs: sp.Expr, rhs: sp.Expr) -> tuple[np.ndarray, np.ndarray]:
    """|wrapped lhs - rhs| [rad] over the samples, with the sample targets."""
    P, th = samples()
    prm = paper_params()
    syms = (*PXYZ, *TH, S["L1"], S["L2"], S["L3"])
    args = (P[:, 0], P[:, 1], P[:, 2], th[:, 0], th[:, 1], th[:, 2], prm.L1, prm.L2, prm.L3)
    with np.errstate(all="ignore"):
        f = sp.lambdify(syms, lhs - rhs, "numpy")
        d = np.asarray(f(*args), dtype=float) * np.ones(len(P))
    d = np.abs(np.mod(d + np.pi, 2 * np.pi) - np.pi)
    return np.where(np.isfinite(d), d, np.inf), P


def verify_angle(text: str) -> bool:
    lhs, rhs = parse_eq(text)
    err, _ = angle_formula_error(lhs, rhs)
    return bool(np.all(err < ANGLE_TOL))


def verify_fk_identity(text: str) -> bool:
    lhs, rhs = parse_eq(text)
    return is_zero((lhs - rhs).subs(fk_subs()))


def fmt_p(p) -> str:
    return "(" + ", ".join(f"{v:g}" for v in p) + ")"

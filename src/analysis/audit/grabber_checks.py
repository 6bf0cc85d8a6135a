"""The machine checks behind the errata register: one :class:`Item` per printed statement.

Each builder holds a family of printed items of :mod:`analysis.papers.grabber` against its
derivation: the D-H matrices (:mod:`analysis.kinematics.dh`, SymPy), FK identities, the angle
formulas (numeric, seeded samples of :mod:`analysis.kinematics.arm`'s front-up solutions), the
text's
claims, Tables 1, 3, 4 (:mod:`analysis.audit.table4`) and the STL
(:mod:`analysis.audit.grabber_stl`).
:func:`analysis.audit.register.audit` collects them. Verdicts are computed, never typed:
``simplify(printed - derived) == 0`` (here an exact normal form, :func:`_normal_form`), a
numeric counterexample, or recomputation.
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

__all__ = ["ANGLE_TOL", "KINDS", "OWN_PREFIX", "Item", "all_items", "derived_matrices"]

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
_IX = sp.symbols("ix iy iz", real=True)
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


def _fk_subs() -> dict:
    T3 = derived_matrices()["T3"]
    return dict(zip(PXYZ, (T3[0, 3], T3[1, 3], T3[2, 3]), strict=True))


def _normal_form(expr) -> sp.Expr | None:
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


def _is_zero(expr) -> bool:
    """Exact test that ``expr`` vanishes identically (:func:`_normal_form`, else simplify)."""
    nf = _normal_form(expr)
    if nf is None:
        return sp.simplify(expr) == 0
    return nf == 0


def _parse_eq(text: str) -> tuple[sp.Expr, sp.Expr]:
    if text.count("=") != 1:
        raise ValueError(f"equation {text!r} must contain exactly one '='")
    lhs, rhs = text.split("=")
    return paper.parse(lhs), paper.parse(rhs)


def _classify(printed: sp.Expr, derived: sp.Expr) -> str:
    if printed.is_number and derived.is_number:
        return "transcription"
    if _is_zero(printed + derived):
        return "sign"
    if printed == 0 and derived != 0:
        return "missing term"
    return "transcription"


def _sstr(e) -> str:
    return sp.sstr(e)


# --------------------------------------------------------------------------------------------
# numeric samples for formulas with atan / acos (front-up: the paper's branch)
# --------------------------------------------------------------------------------------------
PROBES = np.array([[-100.0, 100.0, 600.0], [-200.0, -100.0, 700.0], [150.0, -250.0, 500.0]])
"""Targets outside Table 4's first quadrant, where single-argument tan^-1 fails (mm)."""


@cache
def _samples() -> tuple[np.ndarray, np.ndarray]:
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


def _angle_formula_error(lhs: sp.Expr, rhs: sp.Expr) -> tuple[np.ndarray, np.ndarray]:
    """|wrapped lhs - rhs| [rad] over the samples, with the sample targets."""
    P, th = _samples()
    prm = paper_params()
    syms = (*PXYZ, *TH, S["L1"], S["L2"], S["L3"])
    args = (P[:, 0], P[:, 1], P[:, 2], th[:, 0], th[:, 1], th[:, 2], prm.L1, prm.L2, prm.L3)
    with np.errstate(all="ignore"):
        f = sp.lambdify(syms, lhs - rhs, "numpy")
        d = np.asarray(f(*args), dtype=float) * np.ones(len(P))
    d = np.abs(np.mod(d + np.pi, 2 * np.pi) - np.pi)
    return np.where(np.isfinite(d), d, np.inf), P


def _verify_angle(text: str) -> bool:
    lhs, rhs = _parse_eq(text)
    err, _ = _angle_formula_error(lhs, rhs)
    return bool(np.all(err < ANGLE_TOL))


def _verify_fk_identity(text: str) -> bool:
    lhs, rhs = _parse_eq(text)
    return _is_zero((lhs - rhs).subs(_fk_subs()))


def _fmt_p(p) -> str:
    return "(" + ", ".join(f"{v:g}" for v in p) + ")"


# --------------------------------------------------------------------------------------------
# item builders
# --------------------------------------------------------------------------------------------
def _matrix_items() -> list[Item]:
    D = derived_matrices()
    out = []
    for name, spec in paper.MATRICES.items():
        M = D[name]
        nrows = 3 if name == "T3" else 4
        for i in range(nrows):
            for j in range(4):
                text = spec["rows"][i][j]
                derived = M[i, j]
                pe = paper.parse(text)
                ok = _is_zero(pe - derived)
                loc = spec["location"] + (
                    f" {spec['names'][i][j]}" if name == "T3" else f" row {i + 1} col {j + 1}"
                )
                out.append(
                    Item(
                        id=f"{OWN_PREFIX}{name.replace('_', '-')}-r{i + 1}c{j + 1}",
                        location=loc,
                        printed=text,
                        derived=_sstr(derived),
                        verdict="holds" if ok else "wrong",
                        evidence="simplify(printed - derived) = "
                        + ("0" if ok else _sstr(sp.simplify(pe - derived))),
                        kind="" if ok else _classify(pe, derived),
                        corrected="" if ok else _sstr(derived),
                        verify=lambda t, d=derived: _is_zero(paper.parse(t) - d),
                    )
                )
    return out


def _f_items() -> list[Item]:
    D = derived_matrices()
    T = sp.Matrix(
        [
            [S["n_x"], S["o_x"], S["a_x"], S["Px"]],
            [S["n_y"], S["o_y"], S["a_y"], S["Py"]],
            [S["n_z"], S["o_z"], S["a_z"], S["Pz"]],
            [0, 0, 0, 1],
        ]
    )
    M = D["A1inv"] * T
    cols = {"n": 0, "o": 1, "a": 2, "P": 3}
    groups = [
        ("f11", ("n", "o", "a", "P")),
        ("f12", ("n", "o", "a")),
        ("f12", ("P",)),
        ("f13", ("n", "o", "a", "P")),
    ]
    out = []
    for fname, members in groups:
        k = int(fname[2]) - 1

        def verify(text, k=k, members=members):
            local = {**S, "ix": _IX[0], "iy": _IX[1], "iz": _IX[2]}
            f = sp.parse_expr(text, local_dict=local)
            for m in members:
                c = cols[m]
                sub = dict(zip(_IX, (T[0, c], T[1, c], T[2, c]), strict=True))
                if not _is_zero(f.subs(sub) - M[k, c]):
                    return False
            return True

        text = paper.F_FUNCTIONS[fname]
        derived = " ; ".join(f"{fname}({m}) = {_sstr(M[k, cols[m]])}" for m in members)
        ok = verify(text)
        corrected = ""
        if not ok:  # the homogeneous coordinate w is 0 for n, o, a: drop the constant term
            corrected = _sstr(sp.parse_expr(text, local_dict={**S, "iz": _IX[2]}).subs(S["L1"], 0))
        iset = ", ".join(members)
        out.append(
            Item(
                id=f"{OWN_PREFIX}eq3-{fname}-{''.join(members)}",
                location=f"eq. 3 {fname}(i), i = {iset}",
                printed=text,
                derived=derived,
                verdict="holds" if ok else "wrong",
                evidence="A1^-1 T3 entry by entry"
                + ("" if ok else f": {fname}(n) = {_sstr(M[k, 0])}, not {text}"),
                kind="" if ok else "missing term",
                corrected=corrected,
                verify=verify,
            )
        )
    return out


_FK_EQS = {
    "eq5": "sign",
    "eq7": "",
    "eq8": "",
    "eq9": "",
    "eq13": "index",
    "eq14": "transcription",
    "eq15": "",
    "eq16": "",
    "eq17": "",
}


def _derived_eq_text(key: str) -> str:
    """The derived form of a printed FK identity, from the derived matrices."""
    D = derived_matrices()
    P = sp.Matrix([*PXYZ, 1])
    if key == "eq5":
        return f"{_sstr((D['A1inv'] * P)[2])} = 0"
    if key in ("eq13", "eq14"):
        row = 0 if key == "eq13" else 1
        return f"{_sstr(sp.expand((D['eq12'] * P)[row]))} = 0"
    spec = paper.EQUATIONS[key]
    return f"{spec['lhs']} = {spec['rhs']}"


def _fk_eq_items() -> list[Item]:
    out = []
    for key, kind in _FK_EQS.items():
        spec = paper.EQUATIONS[key]
        text = f"{spec['lhs']} = {spec['rhs']}"
        lhs, rhs = _parse_eq(text)
        residual = _normal_form((lhs - rhs).subs(_fk_subs()))
        ok = residual == 0
        derived = _derived_eq_text(key)
        out.append(
            Item(
                id=f"{OWN_PREFIX}{key}",
                location=spec["location"],
                printed=text,
                derived=derived,
                verdict="holds" if ok else "wrong",
                evidence=f"with P = FK(theta) (eq. 2): lhs - rhs = {_sstr(residual)}",
                kind="" if ok else kind,
                corrected="" if ok else derived,
                verify=_verify_fk_identity,
            )
        )
    return out


def _atan2_text(key: str) -> str:
    num, den = paper._NUM, paper._DEN
    return {
        "eq6_phi": "phi = atan2(Py, Px)",
        "eq6": "theta1 = atan2(Py, Px)",
        "eq18": f"theta2 + theta3 = atan2({num}, {den})",
        "eq19": f"theta2 = atan2({num}, {den}) - theta3",
        "eq10": "theta3 = -" + paper.EQUATIONS["eq10"]["rhs"].replace("p_z", "Pz"),
    }[key]


def _verify_phi(text: str) -> bool:
    """phi must satisfy Px = rho cos(phi), Py = rho sin(phi) (text before eq. 6)."""
    _, rhs = _parse_eq(text)
    P, _ = _samples()
    with np.errstate(all="ignore"):
        phi = np.asarray(sp.lambdify(PXYZ, rhs, "numpy")(P[:, 0], P[:, 1], P[:, 2]), dtype=float)
    rho = np.hypot(P[:, 0], P[:, 1])
    return bool(
        np.allclose(rho * np.cos(phi), P[:, 0], atol=1e-9)
        and np.allclose(rho * np.sin(phi), P[:, 1], atol=1e-9)
    )


def _angle_items() -> list[Item]:
    out = []
    kinds = {
        "eq6_phi": "branch/quadrant",
        "eq6": "branch/quadrant",
        "eq10": "branch/quadrant",
        "eq18": "branch/quadrant",
        "eq19": "branch/quadrant",
    }
    for key, kind in kinds.items():
        spec = paper.EQUATIONS[key]
        text = f"{spec['lhs']} = {spec['rhs']}"
        if key == "eq10":
            text = text.replace("p_z", "Pz")  # the lowercase p is its own item (paper-eq10-pz)
        verify = _verify_phi if key == "eq6_phi" else _verify_angle
        if key == "eq6_phi":
            ok = verify(text)
            bad = None if ok else next(p for p in _samples()[0] if p[0] < 0)
        else:
            lhs, rhs = _parse_eq(text)
            err, P = _angle_formula_error(lhs, rhs)
            ok = bool(np.all(err < ANGLE_TOL))
            bad = None if ok else P[int(np.argmax(err >= ANGLE_TOL))]
        evidence = "holds at every sample (Table 4 rows, probes, 200 seeded targets)"
        if bad is not None:
            evidence = (
                f"counterexample at target {_fmt_p(bad)} mm (front-up, the paper's branch): "
                + _counter(key, text, bad)
            )
        printed = (
            text
            if key != "eq10"
            else paper.EQUATIONS[key]["lhs"] + " = " + paper.EQUATIONS[key]["rhs"]
        )
        out.append(
            Item(
                id=f"{OWN_PREFIX}{key.replace('_', '-')}",
                location=spec["location"],
                printed=printed,
                derived=_atan2_text(key),
                verdict="holds" if ok else "wrong",
                evidence=evidence,
                kind="" if ok else kind,
                corrected="" if ok else _atan2_text(key),
                verify=(lambda t, v=verify: v(t.replace("p_z", "Pz"))) if key == "eq10" else verify,
            )
        )
    return out


def _counter(key: str, text: str, p) -> str:
    arm = paper_arm()
    q = arm.ik(p)
    _, rhs = _parse_eq(text)
    prm = paper_params()
    val = float(
        rhs.subs(
            dict(
                zip(
                    (*PXYZ, *TH, S["L1"], S["L2"], S["L3"]),
                    (*p, *q, prm.L1, prm.L2, prm.L3),
                    strict=True,
                )
            )
        ).evalf()
    )
    want = {"eq6_phi": q[0], "eq6": q[0], "eq10": q[2], "eq18": q[1] + q[2], "eq19": q[1]}[key]
    if key == "eq6_phi":
        val = float(np.arctan(p[1] / p[0]))
        return (
            f"phi = tan^-1(Py/Px) = {np.degrees(val):.2f} deg gives rho cos(phi) = "
            f"{np.hypot(p[0], p[1]) * np.cos(val):.2f} mm, not Px = {p[0]:g} mm"
        )
    return f"printed formula gives {np.degrees(val):.2f} deg, the solution is {np.degrees(want):.2f} deg"  # noqa: E501


def _stl_items() -> list[Item]:
    from analysis.audit.grabber_stl import stl_items

    return stl_items(Item)


def all_items() -> list[Item]:
    """Every printed item with its computed verdict, in paper order (takes seconds)."""
    from analysis.audit.grabber_text_checks import table_items, text_items

    return [
        *_matrix_items(),
        *_f_items(),
        *_fk_eq_items(),
        *_angle_items(),
        *text_items(),
        *table_items(),
        *_stl_items(),
    ]

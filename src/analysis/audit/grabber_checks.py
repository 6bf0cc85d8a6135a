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

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache

import numpy as np
import sympy as sp

from analysis.kinematics.arm import paper_arm
from analysis.kinematics.params import data_dir, paper_params
from analysis.kinematics.pulses import angles_to_pulses
from analysis.papers import grabber as paper
from analysis.plc import stl_eval as stl

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


def _text_items() -> list[Item]:
    D = derived_matrices()
    out = []
    # eq. 4 label
    eq4 = paper.matrix("eq4")

    def verify_label(text: str) -> bool:
        names = re.findall(r"A_(\d)", text)
        if len(names) != 2:
            return False
        prod = D[f"A{names[0]}"] * D[f"A{names[1]}"]
        return all(_is_zero(e) for e in (prod - eq4))

    claim = paper.TEXT_CLAIMS["eq4_label"]
    ok = verify_label(claim["printed"])
    out.append(
        Item(
            f"{OWN_PREFIX}eq4-label",
            claim["location"],
            claim["printed"],
            "A_2 A_3 =",
            "holds" if ok else "wrong",
            "the printed matrix equals A2*A3 entry by entry; A3*A3 differs (e.g. row 1 col 4 "
            f"= {_sstr(sp.simplify((D['A3'] * D['A3'])[0, 3]))})",
            "" if ok else "label",
            "" if ok else "A_2 A_3 =",
            verify_label,
        )
    )
    # eq. 4 row 3 col 4 is a constant
    c = D["eq4"][2, 3]
    out.append(
        Item(
            f"{OWN_PREFIX}eq4-r3c4-constant",
            "text after eq. 4",
            paper.TEXT_CLAIMS["eq4_row3col4"]["printed"],
            f"(A2 A3)[3,4] = {c}",
            "holds" if not (c.free_symbols & set(TH)) else "wrong",
            f"(A2 A3)[3,4] = {c} has no joint variable",
            verify=lambda t: not (D["eq4"][2, 3].free_symbols & set(TH)),
        )
    )

    # cross-references: the equation referred to must define the named joint angle
    def defines(n: int, var: str) -> bool:
        spec = paper.EQUATIONS.get(f"eq{n}")
        return spec is not None and paper.parse(spec["lhs"]) == S[var]

    def verify_xref(text: str) -> bool:
        m = re.search(r"式\((\d+)\)", text)
        return bool(m) and defines(int(m.group(1)), "theta1")

    claim = paper.TEXT_CLAIMS["eq6_xref"]
    ok = verify_xref(claim["printed"])
    out.append(
        Item(
            f"{OWN_PREFIX}eq6-xref",
            claim["location"],
            claim["printed"],
            "结合工程实际, 取式(6)",
            "holds" if ok else "wrong",
            f"eq. 16 defines {paper.EQUATIONS['eq16']['lhs']}, not theta1; eq. 6 defines theta1",
            "" if ok else "cross-reference",
            "" if ok else "结合工程实际, 取式(6)",
            verify_xref,
        )
    )
    claim = paper.TEXT_CLAIMS["sec14_xref"]
    ok14 = all(defines(n, v) for n, v in zip(claim["refers_to"], claim["must_define"], strict=True))
    out.append(
        Item(
            f"{OWN_PREFIX}sec14-xref",
            claim["location"],
            claim["printed"],
            "eqs. 6, 10, 19 define theta1, theta3, theta2",
            "holds" if ok14 else "wrong",
            "left-hand sides of the printed eqs. 6, 10, 19",
            verify=lambda t: all(
                defines(int(n), v)
                for n, v in zip(re.findall(r"\d+", t), ("theta1", "theta3", "theta2"), strict=False)
            ),
        )
    )
    # sin(theta1 - phi) = 0 follows from the derived f13(P) = 0
    rho, phi = sp.symbols("rho", positive=True), S["phi"]
    f13 = (D["A1inv"] * sp.Matrix([*PXYZ, 1]))[2]
    sub = f13.subs({S["Px"]: rho * sp.cos(phi), S["Py"]: rho * sp.sin(phi)})
    ok = _is_zero(sub - rho * sp.sin(TH[0] - phi))
    out.append(
        Item(
            f"{OWN_PREFIX}theta1-two-solutions",
            paper.TEXT_CLAIMS["theta1_two_solutions"]["location"],
            paper.TEXT_CLAIMS["theta1_two_solutions"]["printed"],
            f"f13(P) = {_sstr(sp.simplify(sub))} = rho sin(theta1 - phi)",
            "holds" if ok else "wrong",
            "from the derived f13(P) of eq. 3 (not from the printed eq. 5, which gives sin(theta1 + phi))",  # noqa: E501
            verify=lambda t: ok,
        )
    )
    # eq. 10's lowercase p_z
    used = set().union(
        *(
            paper.parse(paper.EQUATIONS[k][s]).free_symbols
            for k in ("eq7", "eq8", "eq9")
            for s in ("lhs", "rhs")
        )
    )

    def verify_pz(text: str) -> bool:
        return paper.parse(text) in used

    out.append(
        Item(
            f"{OWN_PREFIX}eq10-pz",
            "eq. 10",
            "p_z",
            "Pz",
            "wrong" if not verify_pz("p_z") else "holds",
            "p_z appears nowhere else; eqs. 7-9 use Pz (notation only, same quantity)",
            "transcription",
            "Pz",
            verify_pz,
        )
    )
    # numbers in the running text, each checked by parsing the printed sentence
    from analysis.audit.table4 import load_printed

    prm = paper_params()
    r1 = load_printed().iloc[0]
    row1 = tuple(float(r1[c]) for c in ("x_mm", "y_mm", "z_mm"))
    movd = tuple(
        float(ins.args[0]) for ins in stl.parse_stl(paper.FIGURE_STL[3]) if ins.op == "MOVD"
    )

    def v_lengths(t: str) -> bool:
        return tuple(float(v) for v in re.findall(r"\d+", t)[:3]) == (prm.L1, prm.L2, prm.L3)

    def v_resolution(t: str) -> bool:
        m_ppr, m_res = re.search(r"细分数为 ([\d ]+\d)", t), re.search(r"([\d.]+)°", t)
        if not (m_ppr and m_res):
            return False
        ppr = int(m_ppr.group(1).replace(" ", ""))
        return ppr in prm.pulses_per_rev and abs(360 / ppr - float(m_res.group(1))) < 1e-12

    def v_target(t: str) -> bool:
        nums = tuple(float(v) for v in re.findall(r"\d+", t.split("(", 1)[-1])[:3])
        return nums == row1 == movd

    for key, ev, verify in (
        ("sec3_lengths", "equal to Table 3 (d1, a2, a3)", v_lengths),
        ("sec3_resolution", "360 / 4000 = 0.09 deg per pulse (Table 3 pulses/rev)", v_resolution),
        ("sec241_target", "= Table 4 row 1 target and Figure 3's three MOVD values", v_target),
    ):
        claim = paper.TEXT_CLAIMS[key]
        ok = verify(claim["printed"])
        out.append(
            Item(
                f"{OWN_PREFIX}{key.replace('_', '-')}",
                claim["location"],
                claim["printed"],
                ev,
                "holds" if ok else "wrong",
                ev,
                verify=verify,
            )
        )
    return out


def _verify_table1_row(text: str, i: int) -> bool:
    """A printed Table 1 row (``str(dict)``) must give cos/sin(alpha) and the printed A_i."""
    import ast

    from analysis.kinematics.dh import link_transform_sym

    row = ast.literal_eval(text)
    alpha = sp.rad(row["alpha_deg"])
    built = link_transform_sym(S[row["theta"]], paper.parse(row["d"]), paper.parse(row["a"]), alpha)
    return (
        sp.cos(alpha) == row["cos_alpha"]
        and sp.sin(alpha) == row["sin_alpha"]
        and all(_is_zero(e) for e in (built - derived_matrices()[f"A{i}"]))
        and all(_is_zero(e) for e in (built - paper.matrix(f"A{i}")))
    )


def _verify_table3_row(text: str, i: int) -> bool:
    """A printed Table 3 row: cos/sin vs alpha, 1.8 deg = 360/200 full steps, resolution =
    360 / pulses per rev (data/table3.csv), a and d as in the data file and section 3."""
    import ast

    import pandas as pd

    row = ast.literal_eval(text)
    c = pd.read_csv(data_dir() / "table3.csv").iloc[i - 1]
    alpha = np.radians(row["alpha_deg"])
    return bool(
        abs(np.cos(alpha) - row["cos_alpha"]) < 1e-12
        and abs(np.sin(alpha) - row["sin_alpha"]) < 1e-12
        and abs(360 / row["step_angle_deg"] - 200) < 1e-9
        and abs(360 / c["pulses_per_rev"] - row["resolution_deg"]) < 1e-12
        and float(c["a_mm"]) == row["a_mm"]
        and float(c["d_mm"]) == row["d_mm"]
    )


def _verify_pulse_eq(text: str) -> bool:
    """``c = theta/360 x N``: with theta in degrees, N must be the pulses per revolution and
    the rounded c must equal :func:`analysis.kinematics.pulses.angles_to_pulses` on Table 4's
    angles."""
    m = re.search(r"/\s*(\d+)\s*×\s*(\d+)", text)
    if not m:
        return False
    full, ppr = float(m.group(1)), int(m.group(2))
    _, th = _samples()
    deg = np.degrees(th[:9])
    c = np.copysign(np.floor(np.abs(deg / full * ppr) + 0.5), deg).astype(int)
    return ppr in paper_params().pulses_per_rev and np.array_equal(c, angles_to_pulses(th[:9], ppr))


def _table_items() -> list[Item]:
    out = []
    for i, row in enumerate(paper.TABLE1, start=1):
        verify = lambda t, i=i: _verify_table1_row(t, i)  # noqa: E731
        ok = verify(str(row))
        out.append(
            Item(
                f"{OWN_PREFIX}table1-row{i}",
                f"Table 1 row {i}",
                str(row),
                f"cos/sin(alpha) columns; the row's standard D-H transform = printed A_{i}",
                "holds" if ok else "wrong",
                "link_transform_sym(row) - derived A_i = 0 and - printed A_i = 0",
                verify=verify,
            )
        )
    for i, row in enumerate(paper.TABLE3, start=1):
        verify = lambda t, i=i: _verify_table3_row(t, i)  # noqa: E731
        ok = verify(str(row))
        out.append(
            Item(
                f"{OWN_PREFIX}table3-row{i}",
                f"Table 3 row {i}",
                str(row),
                "cos/sin = alpha; 1.8 deg = 360/200 full steps; 0.09 deg = 360/4000 = 1.8/20; "
                "same a, d as data/table3.csv",
                "holds" if ok else "wrong",
                "recomputed",
                verify=verify,
            )
        )
    for key, spec in paper.PULSE_EQUATIONS.items():
        ok = _verify_pulse_eq(spec["text"])
        out.append(
            Item(
                f"{OWN_PREFIX}{key}",
                spec["location"],
                spec["text"],
                "c = round(theta_deg / 360 * 4000)",
                "holds" if ok else "wrong",
                "theta in degrees; no rounding rule is printed (the STL uses ROUND: "
                "halves away from 0)",
                verify=_verify_pulse_eq,
            )
        )
    out.extend(_table4_items())
    return out


def _table4_items() -> list[Item]:
    from analysis.audit.table4 import cell_matches, summary

    s = summary()
    out = []
    for _, r in s.iterrows():
        n = int(r["row"])
        for j in (1, 2, 3):
            text = r[f"printed_theta{j}"]
            if text == "":
                ok = not bool(r["reachable"])
                out.append(
                    Item(
                        f"{OWN_PREFIX}table4-r{n}-theta{j}",
                        f"Table 4 row {n} theta{j}",
                        "无解",
                        f"unreachable: {r['outside_mm']:.2f} mm beyond L2 + L3",
                        "holds" if ok else "wrong",
                        r[f"cause{j}"],
                        verify=lambda t, ok=ok: (t == "无解") == ok,
                    )
                )
                continue
            ref = r["theta1_atan2_deg"] if j == 1 else r[f"theta{j}_deg"]
            ok = bool(r[f"cell{j}_ok"])
            kind = ""
            if not ok:
                kind = "branch/quadrant" if "tan^-1" in r[f"cause{j}"] else "transcription"
            out.append(
                Item(
                    f"{OWN_PREFIX}table4-r{n}-theta{j}",
                    f"Table 4 row {n} theta{j}",
                    text,
                    f"{ref:.4f}",
                    "holds" if ok else "wrong",
                    f"recomputed {ref:.4f} deg; "
                    + r[f"cause{j}"]
                    + (
                        f"; printed angles put the gripper {r['fk_error_mm']:.2f} mm from the target"  # noqa: E501
                        if not ok
                        else ""
                    ),
                    kind,
                    "" if ok else f"{ref:.2f}",
                    verify=lambda t, ref=ref: cell_matches(t, ref),
                )
            )
    return out


def _stl_items() -> list[Item]:
    from analysis.audit.grabber_stl import stl_items

    return stl_items(Item)


def all_items() -> list[Item]:
    """Every printed item with its computed verdict, in paper order (takes seconds)."""
    return [
        *_matrix_items(),
        *_f_items(),
        *_fk_eq_items(),
        *_angle_items(),
        *_text_items(),
        *_table_items(),
        *_stl_items(),
    ]

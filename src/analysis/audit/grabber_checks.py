"""The machine checks behind the errata register: one :class:`Item` per printed statement.

Each builder holds a family of printed items of :mod:`analysis.papers.grabber` against its
derivation: the D-H matrices (:mod:`analysis.kinematics.dh`, SymPy), FK identities, the angle
formulas (numeric, seeded samples of :mod:`analysis.kinematics.arm`'s front-up solutions), the
text's claims, Tables 1, 3, 4 (:mod:`analysis.audit.table4`) and the STL
(:mod:`analysis.audit.grabber_stl`).
:func:`analysis.audit.register.audit` collects them. Verdicts are computed, never typed:
``simplify(printed - derived) == 0`` (here an exact normal form,
:func:`~analysis.audit.grabber_items.normal_form`), a numeric counterexample, or recomputation.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from analysis.audit.grabber_items import (
    ANGLE_TOL,
    IX,
    OWN_PREFIX,
    PXYZ,
    TH,
    Item,
    S,
    angle_formula_error,
    classify,
    derived_matrices,
    fk_subs,
    fmt_p,
    is_zero,
    normal_form,
    parse_eq,
    samples,
    sstr,
    verify_angle,
    verify_fk_identity,
)
from analysis.audit.grabber_stl import stl_items
from analysis.audit.grabber_text_checks import table_items, text_items
from analysis.kinematics.arm import paper_arm
from analysis.kinematics.params import paper_params
from analysis.papers import grabber as paper

__all__ = ["all_items"]


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
                ok = is_zero(pe - derived)
                loc = spec["location"] + (
                    f" {spec['names'][i][j]}" if name == "T3" else f" row {i + 1} col {j + 1}"
                )
                out.append(
                    Item(
                        id=f"{OWN_PREFIX}{name.replace('_', '-')}-r{i + 1}c{j + 1}",
                        location=loc,
                        printed=text,
                        derived=sstr(derived),
                        verdict="holds" if ok else "wrong",
                        evidence="simplify(printed - derived) = "
                        + ("0" if ok else sstr(sp.simplify(pe - derived))),
                        kind="" if ok else classify(pe, derived),
                        corrected="" if ok else sstr(derived),
                        verify=lambda t, d=derived: is_zero(paper.parse(t) - d),
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
            local = {**S, "ix": IX[0], "iy": IX[1], "iz": IX[2]}
            f = sp.parse_expr(text, local_dict=local)
            for m in members:
                c = cols[m]
                sub = dict(zip(IX, (T[0, c], T[1, c], T[2, c]), strict=True))
                if not is_zero(f.subs(sub) - M[k, c]):
                    return False
            return True

        text = paper.F_FUNCTIONS[fname]
        derived = " ; ".join(f"{fname}({m}) = {sstr(M[k, cols[m]])}" for m in members)
        ok = verify(text)
        corrected = ""
        if not ok:  # the homogeneous coordinate w is 0 for n, o, a: drop the constant term
            corrected = sstr(sp.parse_expr(text, local_dict={**S, "iz": IX[2]}).subs(S["L1"], 0))
        iset = ", ".join(members)
        out.append(
            Item(
                id=f"{OWN_PREFIX}eq3-{fname}-{''.join(members)}",
                location=f"eq. 3 {fname}(i), i = {iset}",
                printed=text,
                derived=derived,
                verdict="holds" if ok else "wrong",
                evidence="A1^-1 T3 entry by entry"
                + ("" if ok else f": {fname}(n) = {sstr(M[k, 0])}, not {text}"),
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
        return f"{sstr((D['A1inv'] * P)[2])} = 0"
    if key in ("eq13", "eq14"):
        row = 0 if key == "eq13" else 1
        return f"{sstr(sp.expand((D['eq12'] * P)[row]))} = 0"
    spec = paper.EQUATIONS[key]
    return f"{spec['lhs']} = {spec['rhs']}"


def _fk_eq_items() -> list[Item]:
    out = []
    for key, kind in _FK_EQS.items():
        spec = paper.EQUATIONS[key]
        text = f"{spec['lhs']} = {spec['rhs']}"
        lhs, rhs = parse_eq(text)
        residual = normal_form((lhs - rhs).subs(fk_subs()))
        ok = residual == 0
        derived = _derived_eq_text(key)
        out.append(
            Item(
                id=f"{OWN_PREFIX}{key}",
                location=spec["location"],
                printed=text,
                derived=derived,
                verdict="holds" if ok else "wrong",
                evidence=f"with P = FK(theta) (eq. 2): lhs - rhs = {sstr(residual)}",
                kind="" if ok else kind,
                corrected="" if ok else derived,
                verify=verify_fk_identity,
            )
        )
    return out


def _atan2_text(key: str) -> str:
    num, den = paper.EQ18_NUM, paper.EQ18_DEN
    return {
        "eq6_phi": "phi = atan2(Py, Px)",
        "eq6": "theta1 = atan2(Py, Px)",
        "eq18": f"theta2 + theta3 = atan2({num}, {den})",
        "eq19": f"theta2 = atan2({num}, {den}) - theta3",
        "eq10": "theta3 = -" + paper.EQUATIONS["eq10"]["rhs"].replace("p_z", "Pz"),
    }[key]


def _verify_phi(text: str) -> bool:
    """phi must satisfy Px = rho cos(phi), Py = rho sin(phi) (text before eq. 6)."""
    _, rhs = parse_eq(text)
    P, _ = samples()
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
        verify = _verify_phi if key == "eq6_phi" else verify_angle
        if key == "eq6_phi":
            ok = verify(text)
            bad = None if ok else next(p for p in samples()[0] if p[0] < 0)
        else:
            lhs, rhs = parse_eq(text)
            err, P = angle_formula_error(lhs, rhs)
            ok = bool(np.all(err < ANGLE_TOL))
            bad = None if ok else P[int(np.argmax(err >= ANGLE_TOL))]
        evidence = "holds at every sample (Table 4 rows, probes, 200 seeded targets)"
        if bad is not None:
            evidence = (
                f"counterexample at target {fmt_p(bad)} mm (front-up, the paper's branch): "
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
    _, rhs = parse_eq(text)
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


def all_items() -> list[Item]:
    """Every printed item with its computed verdict, in paper order (takes seconds)."""
    return [
        *_matrix_items(),
        *_f_items(),
        *_fk_eq_items(),
        *_angle_items(),
        *text_items(),
        *table_items(),
        *stl_items(Item),
    ]

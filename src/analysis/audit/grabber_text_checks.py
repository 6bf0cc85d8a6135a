"""The text's claims and the tables of seed 000, held against their derivation.

Part of the grabber audit: :mod:`analysis.audit.grabber_checks` collects everything in
:func:`~analysis.audit.grabber_checks.all_items`): eq. 4's label, the cross-references, the
derivation's claims and the numbers of the running text (:func:`text_items`); Tables 1 and 3,
the pulse equations and Table 4 (:func:`table_items`).
"""

from __future__ import annotations

import re

import numpy as np
import sympy as sp

from analysis.audit.grabber_items import (
    OWN_PREFIX,
    PXYZ,
    TH,
    Item,
    S,
    derived_matrices,
    is_zero,
    samples,
    sstr,
)
from analysis.kinematics.params import data_dir, paper_params
from analysis.kinematics.pulses import angles_to_pulses
from analysis.papers import grabber as paper
from analysis.plc import stl_eval as stl

__all__ = ["table_items", "text_items"]


def text_items() -> list[Item]:
    """The running text's claims, in paper order."""
    return [*_label_items(), *_xref_items(), *_derivation_claim_items(), *_number_items()]


def _label_items() -> list[Item]:
    """Eq. 4's label (A_3 A_3 printed for A_2 A_3) and its constant entry."""
    D = derived_matrices()
    out = []
    eq4 = paper.matrix("eq4")

    def verify_label(text: str) -> bool:
        names = re.findall(r"A_(\d)", text)
        if len(names) != 2:
            return False
        prod = D[f"A{names[0]}"] * D[f"A{names[1]}"]
        return all(is_zero(e) for e in (prod - eq4))

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
            f"= {sstr(sp.simplify((D['A3'] * D['A3'])[0, 3]))})",
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

    return out


def _xref_items() -> list[Item]:
    """Cross-references: the equation referred to must define the named joint angle."""
    out = []

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
    return out


def _derivation_claim_items() -> list[Item]:
    """Claims of the derivation: theta1's two solutions (from f13(P) = 0), eq. 10's p_z."""
    D = derived_matrices()
    out = []
    rho, phi = sp.symbols("rho", positive=True), S["phi"]
    f13 = (D["A1inv"] * sp.Matrix([*PXYZ, 1]))[2]
    sub = f13.subs({S["Px"]: rho * sp.cos(phi), S["Py"]: rho * sp.sin(phi)})
    ok = is_zero(sub - rho * sp.sin(TH[0] - phi))
    out.append(
        Item(
            f"{OWN_PREFIX}theta1-two-solutions",
            paper.TEXT_CLAIMS["theta1_two_solutions"]["location"],
            paper.TEXT_CLAIMS["theta1_two_solutions"]["printed"],
            f"f13(P) = {sstr(sp.simplify(sub))} = rho sin(theta1 - phi)",
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
    return out


def _number_items() -> list[Item]:
    """Numbers in the running text, each checked by parsing the printed sentence."""
    from analysis.audit.table4 import load_printed

    out = []
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
        and all(is_zero(e) for e in (built - derived_matrices()[f"A{i}"]))
        and all(is_zero(e) for e in (built - paper.matrix(f"A{i}")))
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
    _, th = samples()
    deg = np.degrees(th[:9])
    c = np.copysign(np.floor(np.abs(deg / full * ppr) + 0.5), deg).astype(int)
    return ppr in paper_params().pulses_per_rev and np.array_equal(c, angles_to_pulses(th[:9], ppr))


def table_items() -> list[Item]:
    """Tables 1 and 3 row by row, the pulse equations (eqs. 20-22) and Table 4 cell by cell."""
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

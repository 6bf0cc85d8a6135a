"""Seed 004's register, part 2: the kinematics and the results (Table 5-4 and the 5-DOF
orientation, eq. 3.18), the readings the extraction leaves open, its damage, and what holds.
Built into the register by :func:`analysis.audit.gr1_causes.register`."""

from __future__ import annotations

import math
import re

import numpy as np
import sympy as sp

from analysis.audit import gr1_checks as chk
from analysis.audit import vb6
from analysis.audit.gr1_checks import numbers as _numbers
from analysis.audit.gr1_checks import printed_run as _printed_run
from analysis.audit.schema import Cause, Manifestation
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.kinematics.dh import DHRow, DHTable
from analysis.kinematics.status import Status
from analysis.papers import gr1_thesis as paper
from analysis.studies import gr1 as study

_arm = study.gr1_arm

__all__ = ["causes_open", "causes_results"]


# ---------------------------------------------------------------------------------------------
# Table 5-4, Table 5-3, eq. 3.18
# ---------------------------------------------------------------------------------------------
def _reaches(label: str):
    """verify: five joint angles [deg] in ``text`` put the hand at Table 5-3's position
    (within 0.05 mm: angles to 3 decimals move it by up to 0.02 mm)."""
    target = study.thesis_poses()[0 if label == "start" else 1, :3]

    def verify(text: str) -> bool:
        v = _numbers(text)
        if len(v) != 5:
            return False
        p = _arm().fk(np.radians(v))
        return float(np.linalg.norm(p - target)) <= 0.05

    return verify


def _table5_4() -> Cause:
    t = study.table5_4()
    proj, _ = study.project_orientation(_arm(), study.thesis_poses())
    q, names = study.first_within_limits(_arm(), proj)
    ms = []
    for k, label in enumerate(("start", "end")):
        printed = t[(t.pose == label) & (t.source == "printed")].iloc[0]
        fixed = t[(t.pose == label) & (t.source == names[k])].iloc[0]
        ang = ", ".join(f"{v:.3f}" for v in np.degrees(q[k]))
        ms.append(
            Manifestation(
                f"gr1-table5-4/{label}",
                f"Table 5-4, {label} row, p. 23",
                "(" + ", ".join(f"{v:g}" for v in paper.TABLE5_4["rows"][label]) + ")",
                f"({ang}) ({names[k]}, orientation projected)",
                f"Through the chain the printed angles put the hand {printed.miss_mm:.1f} mm "
                f"from Table 5-3's position (and {printed.turn_deg:.1f} deg off its "
                f"orientation). The correction reaches the position exactly; its orientation "
                f"is the nearest a 5-DOF arm can take ({fixed.turn_deg:.3f} deg away, see "
                f"gr1-five-dof); {names[k]} is the first branch within the assumed "
                f"joint limits.",
                _reaches(label),
            )
        )
    cells = chk.cells_matching(vb6.listing())
    return _cause(
        "gr1-table5-4",
        "Table 5-4's joint values do not put the hand at Table 5-3's positions: they are what "
        "the listing displays, defects included.",
        "error",
        "claim",
        f"The listing (cf3 repaired) reproduces all {cells} printed cells to the last digit "
        f"(analysis.audit.vb6); only the theta1 cells are right. The defects compound: "
        f"gr1-trig-degrees, gr1-r-sign, gr1-end-orientation, gr1-atan (cell by cell: "
        f"analysis.audit.gr1_checks.table5_4_cascade). Position misses: base height d1 = 0 "
        f"assumed, as the thesis's own c3 implies.",
        ms,
        lambda: cells == 10 and (t[t.source == "printed"].miss_mm > 100).all() and _all_fail(ms),
    )


def _orientation_ok(text: str) -> bool:
    """verify: six numbers (mm, deg) form a pose whose orientation the arm can take."""
    v = _numbers(text)
    if len(v) != 6:
        return False
    pose = np.array([*v[:3], *np.radians(v[3:])])
    return int(_arm().solve(pose).status) != Status.ORIENTATION


def _plane_condition(text: str) -> bool:
    """verify: the text states the 5-DOF condition s1 a_x - c1 a_y = 0 (which holds on
    every configuration of the chain)."""
    found = re.search(r"s1\s*a_x\s*-\s*c1\s*a_y\s*=\s*0", text) is not None
    return found and chk.equation_holds("sin(theta1)*a_x - cos(theta1)*a_y = 0", atol=1e-12)


def _five_dof() -> Cause:
    arm = _arm()
    poses = study.thesis_poses()
    proj, turn = study.project_orientation(arm, poses)
    status = arm.solve(poses).status.tolist()
    claim = paper.TEXT_CLAIMS["c4.2-any-pose"]
    ms = [
        Manifestation(
            "gr1-five-dof/claim",
            claim["location"],
            claim["printed"],
            "以上结果给出姿态满足 s1 a_x - c1 a_y = 0 (the approach vector in the arm plane) "
            "的位姿所需的关节值; a 5-DOF arm cannot take other orientations",
            "Five joints leave one orientation freedom out: the approach vector a stays in the "
            "vertical plane of the arm, s1 a_x - c1 a_y = 0 (held on 200 configurations). "
            "Section 4.2 computes theta234 and theta5 from any n, o, a without this condition.",
            _plane_condition,
        )
    ]
    for k, label in enumerate(("start", "end")):
        row = paper.TABLE5_3["rows"][label]
        ang = np.degrees(proj[k, 3:])
        ms.append(
            Manifestation(
                f"gr1-five-dof/table5-3-{label}",
                f"Table 5-3, {label} row, p. 23",
                "(" + ", ".join(f"{v:g}" for v in row) + ")",
                "(" + ", ".join([*(f"{v:g}" for v in row[:3]), *(f"{v:.3f}" for v in ang)]) + ")",
                f"The approach vector is {math.degrees(turn[k]):.3f} deg out of the arm plane at "
                f"theta1 = {math.degrees(math.atan2(row[1], row[0])):.3f} deg (status "
                f"{Status(status[k]).text}); the correction is the nearest orientation the arm "
                f"can take there (RPY in deg), {math.degrees(turn[k]):.3f} deg away.",
                _orientation_ok,
            )
        )
    return _cause(
        "gr1-five-dof",
        "The thesis treats the 5-DOF arm as if it could take any orientation: Table 5-3's "
        "are 69.1 and 60.7 deg out of its reach.",
        "error",
        "reasoning",
        "Residual rotation = angle between a and the arm plane (the projection is the nearest "
        "reachable orientation: tests/kinematics/test_gr1.py).",
        ms,
        lambda: status == [Status.ORIENTATION] * 2 and _all_fail(ms),
    )


def _eq318() -> Cause:
    ms = []
    for key, slug, corrected in (
        ("3.18b", "phi", "phi = atan2(n_y, n_x)"),
        ("3.18c", "psi", "psi = atan2(o_z, a_z)"),
    ):
        e = paper.EQUATIONS[key]
        ms.append(
            Manifestation(
                f"gr1-eq3-18/{slug}",
                e["location"],
                f"{e['lhs']} = {e['rhs']}",
                corrected,
                "Held against eq. 3.15 on 200 seeded rotations (beta within +-90 deg, as "
                "eq. 3.17's root requires): the printed form misses the angle, the corrected "
                "one returns it. The extraction may displace subscripts, but not turn n into o "
                "or o into a.",
                lambda t: chk.equation_holds(t, angle=True),
            )
        )
    return _cause(
        "gr1-eq3-18",
        "eq. 3.18 prints atan2(o_x, n_x) and atan2(a_y, a_z) for the RPY angles about z and x; "
        "they are atan2(n_y, n_x) and atan2(o_z, a_z).",
        "error",
        "transcription",
        "eq. 3.18's first line, atan2(-n_z, sqrt(n_x^2 + n_y^2)), and eq. 3.17 hold "
        "(gr1-ch3-holds).",
        ms,
    )


# ---------------------------------------------------------------------------------------------
# readings the extraction leaves open; its damage
# ---------------------------------------------------------------------------------------------
def _sec42_signs() -> Cause:
    e = paper.EQUATIONS["4.2-s2"]
    plus = e["rhs"].replace("- cos(theta234)*a4)", "+ cos(theta234)*a4)")
    m = Manifestation(
        "gr1-sec4-2-signs/s2",
        e["location"],
        f"sin(theta2) = {plus}",
        f"sin(theta2) = {e['rhs']}",
        "Every operator of section 4.2 is a '?' in the extraction. Read as the listing's θ2 "
        "statement ('+ Cos(θ234) * a4'), s2 (and c2, theta2) fail on the chain; read as its "
        "c3 statement ('-'), they hold. The print's own sign cannot be seen.",
        chk.equation_holds,
    )
    return _cause(
        "gr1-sec4-2-signs",
        "Section 4.2's signs before c234 a4 in s2, c2 and theta2 are lost; one reading holds, "
        "the listing's does not.",
        "uncertain",
        "sign",
        "gr1_thesis.UNCERTAIN['sec. 4.2 signs'].",
        [m],
    )


_ROW = re.compile(r"\(theta(\d),\s*([\w.]+),\s*([\w.]+),\s*(-?[\d.]+)\)")


def _dh_reproduces_sec42(text: str) -> bool:
    """verify: D-H rows '(thetaK, d, a, alpha_deg)' in the text give a chain on which
    section 4.2's c3 and tan(theta234) = o_z / (c1 o_x + s1 o_y) hold."""
    rows = _ROW.findall(text)
    if [r[0] for r in rows] != ["1", "2", "3", "4", "5"]:
        return False
    vals = dict(_arm().params)

    def num(s):
        return vals[s] if s in vals else float(s)

    try:
        table = DHTable(tuple(DHRow(math.radians(float(al)), num(a), num(d))
                              for _, d, a, al in rows))  # fmt: skip
    except (KeyError, ValueError):
        return False
    q = chk.configurations(100, 3)
    T = table.fk(q)
    t234 = q[:, 1] + q[:, 2] + q[:, 3]
    c1, s1 = np.cos(q[:, 0]), np.sin(q[:, 0])
    p, o = T[:, :3, 3], T[:, :3, 1]
    r = p[:, 0] * c1 + p[:, 1] * s1 - np.cos(t234) * vals["a4"]
    z = p[:, 2] - np.sin(t234) * vals["a4"]
    c3 = (r * r + z * z - vals["a2"] ** 2 - vals["a3"] ** 2) / (2 * vals["a2"] * vals["a3"])
    tan234 = o[:, 2] * np.cos(t234) - np.sin(t234) * (c1 * o[:, 0] + s1 * o[:, 1])
    return bool(np.allclose(c3, np.cos(q[:, 2]), atol=1e-9) and np.allclose(tan234, 0, atol=1e-9))


def _no_dh_table() -> Cause:
    corrected = (
        "(theta1, d1, 0, 90), (theta2, 0, a2, 0), (theta3, 0, a3, 0), (theta4, 0, a4, 90), "
        "(theta5, 0, 0, 0)  [theta_i, d_i, a_i, alpha_i in deg; d1 = 0 assumed]"
    )
    model_b = (
        "(theta1, d1, 0, 90), (theta2, 0, a2, 0), (theta3, 0, a3, 0), (theta4, 0, 0, 90), "
        "(theta5, a4, 0, 0)"
    )
    m = Manifestation(
        "gr1-no-dh-table/sec-4-1",
        paper.DH_TABLE["location"],
        "sec. 4.1 机器人正向运动学: a heading, no D-H table, no frames, no T",
        corrected,
        "Derived: this chain (model A, the roll axis z4 in the arm plane, perpendicular to the "
        "hand) makes section 4.2's c3, s2, c2, theta4 and the tangents of theta5 and theta234 "
        "hold; with the roll axis along the hand, (theta4, 0, 0, 90), (theta5, a4, 0, 0), c3 "
        "and tan(theta234) = o_z / (c1 o_x + s1 o_y) fail. Section 1.3 claims the D-H "
        "frames and the forward solution; the empty section is the thesis's or the "
        "extraction's (an image would leave no text) - the text cannot tell.",
        _dh_reproduces_sec42,
    )
    return _cause(
        "gr1-no-dh-table",
        "No D-H table or forward kinematics of the GR-1 appears (section 4.1 is empty), though "
        "section 1.3 says the thesis sets them up.",
        "uncertain",
        "claim",
        "data/arms/gr1.toml holds the derived rows.",
        [m],
        lambda: _all_fail([m]) and not _dh_reproduces_sec42(model_b),
    )


def _x_table5_4() -> Cause:
    """Table 5-4 (sec. 5.4.2) as extracted: the ten numbers against the listing's cells."""

    def cells_from(text: str):
        if "start" in text and "end" in text:
            part = text.split("end")
            return _numbers(part[0]) + _numbers(part[1])
        return _numbers(text)

    def reproduces(text: str) -> bool:
        v = cells_from(text)
        if len(v) != 10:
            return False
        shown = _printed_run()["text"]
        return all(shown[f"Text{13 + i}"] == vb6.vb_format(x, "####.###") for i, x in enumerate(v))

    ex = paper.TABLE5_4_EXTRACTED
    rows = paper.TABLE5_4["rows"]
    t54 = Manifestation(
        "gr1-x-table5-4/body",
        ex["location"],
        ex["printed_numbers"],
        "start ("
        + ", ".join(f"{v:g}" for v in rows["start"])
        + "); end ("
        + ", ".join(f"{v:g}" for v in rows["end"])
        + ")",
        "The ten numbers come out after the next paragraph, in the order (end, start) per "
        "joint; read row by row they do not fit (theta1 would be 56.31 for the start, where "
        "atan(231/151) = 56.828). The assignment reproduces what the listing displays, "
        "cell for cell.",
        reproduces,
    )
    return _cause(
        "gr1-x-table5-4",
        "The extraction scrambles Table 5-4: header order θ1 θ2 θ4 θ3 θ5, the ten numbers "
        "after the next paragraph.",
        "extraction",
        "extraction",
        "gr1_thesis.TABLE5_4 ('basis', 'uncertainty').",
        [t54],
    )


def _x_table5_3() -> Cause:
    """Table 5-3's lost angle headers (sec. 5.4.2)."""
    names = list(paper.TABLE5_3["columns"])

    def header_ok(text: str) -> bool:
        tokens = text.replace(",", " ").split()
        if sorted(tokens) != sorted(names):
            return False
        rows3 = paper.TABLE5_3["rows"]
        order = [tokens.index(n) for n in names]  # printed column -> listing input
        values = [rows3["start"][i] for i in order] + [rows3["end"][i] for i in order]
        out = vb6.run_command1({f"Text{i + 1}": str(v) for i, v in enumerate(values)})
        return out["text"] == _printed_run()["text"]

    t53 = Manifestation(
        "gr1-x-table5-3/headers",
        paper.TABLE5_3["location"],
        "? ? pz px py 控制点 ?",
        " ".join(names),
        "The three angle headers are '?' and the columns come out of order; with the "
        "listing's input order (px, py, pz, α, β, γ) Table 5-3 gives Table 5-4 exactly.",
        header_ok,
    )
    return _cause(
        "gr1-x-table5-3",
        "The extraction loses Table 5-3's angle headers.",
        "extraction",
        "extraction",
        "gr1_thesis.TABLE5_3 (note).",
        [t53],
    )


def _x_listing() -> Cause:
    """The appendix listing's joined lines (pp. 36-46)."""

    def parses(text: str) -> bool:
        try:
            vb6.VB6Form("Private Sub T_Click()\n" + text + "\nEnd Sub\n")
        except vb6.VB6SyntaxError:
            return False
        return True

    lines = Manifestation(
        "gr1-x-listing/lines",
        "appendix listing, pp. 36-46",
        "Px0 = Val(Text1.Text) Py0 = Val(Text2.Text) Pz0 = Val(Text3.Text)",
        "Px0 = Val(Text1.Text)\nPy0 = Val(Text2.Text)\nPz0 = Val(Text3.Text)",
        "The extraction joins each page's lines and puts page numbers inside the code "
        "(gr1_thesis.LISTING_RESTORATIONS); joined, the statements do not parse.",
        parses,
    )
    return _cause(
        "gr1-x-listing",
        "The extraction joins the listing's lines and inserts page numbers.",
        "extraction",
        "extraction",
        "Restored in gr1_thesis.LISTING.",
        [lines],
    )


def _x_symbols() -> Cause:
    """Chapter 3's Greek letters and operators lost (eqs. 3.17, 3.18a)."""
    e317, e318 = paper.EQUATIONS["3.17"], paper.EQUATIONS["3.18a"]
    symbols = [
        Manifestation(
            "gr1-x-symbols/eq3-17",
            e317["location"],
            e317["printed"],
            f"{e317['lhs']} = {e317['rhs']}",
            "Every Greek letter and operator of chapter 3 is a '?' in the extraction.",
            chk.equation_holds,
        ),
        Manifestation(
            "gr1-x-symbols/eq3-18a",
            e318["location"],
            e318["printed"],
            f"{e318['lhs']} = {e318['rhs']}",
            "As above; the reading holds on eq. 3.15 for beta in [-90, 90] deg.",
            lambda t: chk.equation_holds(t, angle=True),
        ),
    ]
    return _cause(
        "gr1-x-symbols",
        "The extraction turns chapter 3's Greek letters and operators into '?'.",
        "extraction",
        "extraction",
        "The readings in gr1_thesis.EQUATIONS and MATRICES hold where marked.",
        symbols,
    )


def _extraction() -> list[Cause]:
    """What the extraction damaged: Tables 5-4 and 5-3, the listing, chapter 3's symbols."""
    return [_x_table5_4(), _x_table5_3(), _x_listing(), _x_symbols()]


# ---------------------------------------------------------------------------------------------
# what holds
# ---------------------------------------------------------------------------------------------
def _ch3_holds() -> bool:
    """Chapter 3: eq. 3.15 is Rot(z) Rot(y) Rot(x) (eq. 3.14), eq. 3.19 is Rz Tz Tx Rx,
    eqs. 3.17 and 3.18a return the pitch."""
    s = paper.SYMBOLS
    rx = paper.matrix("3.5").subs(s["theta"], s["psi"])
    rz = paper.matrix("3.7").subs(s["theta"], s["phi"])
    eq315 = sp.simplify(rz * paper.matrix("3.6") * rx - paper.matrix("3.15")[:3, :3])
    th, d, a, al = s["theta_i"], s["d_i"], s["a_i"], s["alpha_i"]
    Rz = sp.Matrix(sp.BlockDiagMatrix(sp.rot_axis3(-th), sp.eye(1)))
    Rx = sp.Matrix(sp.BlockDiagMatrix(sp.rot_axis1(-al), sp.eye(1)))
    Tz, Tx = sp.eye(4), sp.eye(4)
    Tz[2, 3], Tx[0, 3] = d, a
    eq319 = sp.simplify(Rz * Tz * Tx * Rx - paper.matrix("3.19"))
    e317, e318 = paper.EQUATIONS["3.17"], paper.EQUATIONS["3.18a"]
    return (
        eq315 == sp.zeros(3, 3)
        and eq319 == sp.zeros(4, 4)
        and chk.equation_holds(f"{e317['lhs']} = {e317['rhs']}")
        and chk.equation_holds(f"{e318['lhs']} = {e318['rhs']}", angle=True)
    )


def _sec42_holds() -> bool:
    """Section 4.2's c3, s2, c2, theta4 and the tangents of theta5 and theta234."""
    E = paper.EQUATIONS
    keys = ("4.2-c3", "4.2-s2", "4.2-c2")
    ok = [chk.equation_holds(f"{E[k]['lhs']} = {E[k]['rhs']}") for k in keys]
    ok.append(chk.equation_holds("theta4 = theta234 - theta2 - theta3", angle=True))
    # the tangents hold (the quadrants do not: gr1-atan)
    t5 = "(sin(theta1)*n_x - cos(theta1)*n_y)/(sin(theta1)*o_x - cos(theta1)*o_y)"
    ok.append(chk.equation_holds(f"sin(theta5)/cos(theta5) = {t5}", atol=1e-6))
    t234 = "o_z/(cos(theta1)*o_x + sin(theta1)*o_y)"
    ok.append(chk.equation_holds(f"sin(theta234)/cos(theta234) = {t234}", atol=1e-6))
    return all(ok)


def _theta1_cells_holds() -> bool:
    """Table 5-4's theta1 cells are atan2(py, px) of Table 5-3."""
    rows = paper.TABLE5_3["rows"]
    got = [vb6.vb_format(math.degrees(math.atan2(r[1], r[0])), "####.###")
           for r in (rows["start"], rows["end"])]  # fmt: skip
    want = [vb6.vb_format(paper.TABLE5_4["rows"][k][0], "####.###") for k in ("start", "end")]
    return got == want


def _c235_holds() -> bool:
    """Table 2-3's C235 = 4 is the waist's change over its resolution."""
    df = study.printed_presets().set_index("counter")
    return int(df.loc["C235"].printed) == int(df.loc["C235"].as_pulses) == 4


def _cubic_holds() -> bool:
    """The cubic of eqs. 5.1-5.4 meets its four conditions, which determine it."""
    c = paper.CUBIC_SYMBOLS
    t, T, th0, thf = c["t"], c["t_f"], c["theta_0"], c["theta_f"]
    f = paper.parse(paper.CUBIC["listing_form"]["reading"].split("=", 1)[1], "cubic")
    d1 = sp.diff(f, t)
    conds = [f.subs(t, 0) - th0, f.subs(t, T) - thf, d1.subs(t, 0), d1.subs(t, T)]
    A = sp.Matrix([[1, 0, 0, 0], [0, 1, 0, 0], [1, T, T**2, T**3], [0, 1, 2 * T, 3 * T**2]])
    return all(sp.simplify(x) == 0 for x in conds) and sp.simplify(A.det() - T**4) == 0


def _holds() -> list[Cause]:
    """What holds: chapter 3, section 4.2, Table 5-4's theta1, C235, the cubic."""
    return [
        Cause(
            "gr1-ch3-holds",
            "Chapter 3 holds: eq. 3.15 is the product Rot(z) Rot(y) Rot(x) of eq. 3.14, eq. 3.19 "
            "is Rz Tz Tx Rx, eq. 3.17 and eq. 3.18's first line return the pitch.",
            "holds",
            "reasoning",
            "SymPy (3.15, 3.19) and 200 seeded rotations (3.17, 3.18a).",
            (),
            _ch3_holds,
        ),
        Cause(
            "gr1-sec4-2-holds",
            "Section 4.2's c3, s2, c2 (with '-' before c234 a4), theta4 = theta234 - theta2 - "
            "theta3 and the tangents of theta5 and theta234 hold on the chain of model A.",
            "holds",
            "reasoning",
            "200 seeded configurations; the quadrants are gr1-atan's.",
            (),
            _sec42_holds,
        ),
        Cause(
            "gr1-theta1-cells-hold",
            "Table 5-4's theta1 cells (56.828, 56.31) are atan2(py, px) of Table 5-3.",
            "holds",
            "reasoning",
            "Both poses lie in the first quadrant, where Atn(py/px) is right.",
            (),
            _theta1_cells_holds,
        ),
        Cause(
            "gr1-c235-holds",
            "Table 2-3's C235 = 4 is the waist's change over its resolution (0.518 / 0.14).",
            "holds",
            "reasoning",
            "The one preset computed as the text says.",
            (),
            _c235_holds,
        ),
        Cause(
            "gr1-cubic-holds",
            "The cubic of eqs. 5.1-5.4 (the listing's form) meets its four conditions, and "
            "they determine it uniquely (determinant t_f^4).",
            "holds",
            "reasoning",
            "SymPy; the claim c5.4.1-unique holds.",
            (),
            _cubic_holds,
        ),
    ]


def causes_results() -> list[Cause]:
    """Table 5-4, the 5-DOF orientation, eq. 3.18."""
    return [_table5_4(), _five_dof(), _eq318()]


def causes_open() -> list[Cause]:
    """Uncertain readings, extraction damage, and what holds."""
    return [_sec42_signs(), _no_dh_table(), *_extraction(), *_holds()]

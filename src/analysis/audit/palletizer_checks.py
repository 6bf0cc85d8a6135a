"""Seed 001 (Li & Hu 2021, palletizer) checked: every printed item of
:mod:`analysis.papers.palletizer` against a derivation or a run, as :class:`Finding` records.

Derivations
-----------
* Symbolic: the product of the five printed matrices of section 4.2 (eq. 9) is the
  reference for eq. 11; eq. 8 is held against the modified D-H link transform of
  :mod:`analysis.kinematics.dh` (Craig), and each printed matrix against eq. 8.
* Numeric: the printed IK chain (eqs. 1-6, 12) evaluated with each formula as printed or
  corrected (:func:`ik_chain`), the four elbow/waist solutions of the arm (:func:`all_ik`),
  forward kinematics by the D-H chain of the one description of the arm,
  ``data/arms/palletizer.toml`` (``load_arm("palletizer")``). The paper prints no length:
  L1, L2, L3, h are parameters (every function takes an :class:`~analysis.kinematics.arm.Arm`,
  e.g. ``Arm(arm.params.with_(L2=150.0))``), their default values are ASSUMED, in the
  isosceles family L1 = L2 = 200, L3 = 50, h = 70 mm, and every evidence text says so.
* The corrected IK itself is the shared closed form (:mod:`analysis.kinematics.arms.
  palletizer`, via :meth:`Arm.solve`); :func:`ik_chain` with every item fixed is an
  independent coding of it (the tests hold the two together), and :func:`fk_ik_pinocchio`
  closes the loop through Pinocchio.

Corrected IK (elbow above the shoulder-wrist line, waist facing the target)::

    rho = hypot(X0, Y0);  gamma = atan2(Y0, X0)                      (eqs. 1, 6)
    L4 = hypot(rho - L3, Z0 + h)                                     (eq. 2)
    alpha1 = acos((L1^2 + L4^2 - L2^2) / (2 L1 L4))                  (eq. 3)
    alpha2 = atan2(Z0 + h, rho - L3)      (H = Z0 + h; eq. 3 prints arcsin(H/L4'))
    beta1  = acos((L1^2 + L2^2 - L4^2) / (2 L1 L2))  (eq. 3 prints no arccos)
    alpha = alpha1 + alpha2 - pi/2  (eq. 4 prints pi/2 - alpha1 + alpha2);  beta = pi/2 - beta1
    theta = -alpha + beta                                            (eq. 5)
    theta1..4 = gamma, -pi/2 - alpha, pi/2 + beta, pi/2 - (theta2 + theta3)  (eq. 12)

The derivations and runs are in :mod:`analysis.audit.palletizer_derivations` and importable
from here; this module turns them into findings.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
import sympy as sp

from analysis.audit.findings import Finding

# the ``X as X`` imports: the derivations' other public names, importable from here as before
from analysis.audit.palletizer_derivations import (
    FIXES,
    QUADRANT_TARGETS,
    all_ik,
    assumed_lengths,
    derived_tool_position,
    eq8_checks,
    eq11_printed_position,
    eq11_residuals,
    fk_ik_pinocchio,
    gamma_eq6,
    ik_chain,
    lengths,
    level_configurations,
    miss,
    symbolic_table,
    uniqueness_counts,
    workspace_grid,
)
from analysis.audit.palletizer_derivations import TH as TH
from analysis.audit.palletizer_derivations import S as S
from analysis.kinematics.arm import Arm, load_arm

__all__ = [
    "FIXES",
    "QUADRANT_TARGETS",
    "all_ik",
    "assumed_lengths",
    "derived_tool_position",
    "eq11_printed_position",
    "eq11_residuals",
    "findings",
    "fk_ik_pinocchio",
    "gamma_eq6",
    "ik_chain",
    "lengths",
    "level_configurations",
    "quadrant_misses",
    "symbolic_table",
    "uniqueness_counts",
]


# --------------------------------------------------------------------------- findings
def _fmt(v) -> str:
    return np.array2string(np.asarray(v), precision=2, separator=", ", suppress_small=True)


def quadrant_misses(arm, fixed, **kw) -> npt.NDArray[np.float64]:
    return miss(arm, QUADRANT_TARGETS, ik_chain(arm, QUADRANT_TARGETS, fixed, **kw)["q"])


_EQ7 = (0.0, -np.pi / 2, np.pi / 2, np.pi / 2)
"""Eq. 7's joint angles theta1..theta4 [rad]: the initial pose of sec. 3."""


def _dh_findings(arm: Arm) -> list[Finding]:
    """eq. 11 against the product of the printed matrices (eq. 9), eq. 8 and the matrices."""
    all_fix = set(FIXES)
    dims = assumed_lengths(arm)
    G = QUADRANT_TARGETS
    out: list[Finding] = []
    # eq. 11
    res = eq11_residuals()
    q_eq7 = np.array(_EQ7)
    eq7_err = float(np.linalg.norm(eq11_printed_position(arm, q_eq7) - arm.fk(q_eq7)))
    q_g = ik_chain(arm, G, all_fix)["q"]
    m11 = miss(arm, G, q_g, eq11="printed")
    out.append(
        Finding(
            "pal-eq11-s4L3",
            "eq. 11, all three rows, second factor",
            "s4h - s4L3",
            "s4h - c4L3",
            "transcription",
            "against t14, t24, t34 of the product of the printed 0_1T..4_5T (eq. 9): "
            f"printed - derived = {sp.sstr(res[0]['residual'])} (row 1), "
            "zero in every row after s4L3 -> c4L3, i.e. an error of L3|s4 - c4| "
            f"in length: at eq. 7's pose {eq7_err:.3g} mm (= L3); at the corrected IK of the "
            f"four quadrant targets {_fmt(m11)} mm ({dims})",
        )
    )
    out.append(
        Finding(
            "pal-eq11-label",
            "eq. 11, row 2 label",
            "t34",
            "t24",
            "label",
            f"row 2 (s4L3 -> c4L3) equals derived {res[1]['matches']} of the printed "
            f"matrices' product; rows 1 and 3 equal {res[0]['matches']} and {res[2]['matches']}"
            "; the text after eq. 10 names t14, t24, t34 as the tip coordinates",
        )
    )

    # eq. 8
    e8 = eq8_checks()
    out.append(
        Finding(
            "pal-eq8-glyph",
            "eq. 8, rows 2-3: sin/cos of a_{i-1}",
            "-sin(a_im1), -d_i*sin(a_im1), sin(theta_i)*sin(a_im1), cos(theta_i)*sin(a_im1), "
            "cos(a_im1), d_i*cos(a_im1)",
            "the same with alpha_im1 for a_im1 inside sin/cos",
            "transcription",
            f"as printed == Craig's modified D-H: {e8['eq8 as printed == Craig']}; with alpha "
            f"for a: {e8['eq8 with alpha for a in sin/cos == Craig']}; 1_2T (a_1 = 0, "
            f"alpha_1 = -90 deg) from eq. 8 as printed: {e8['T12 from eq8 as printed']} "
            "(sin(a_1) = 0 would zero row 2 col 3, printed 1). Print or extraction: UNCERTAIN.",
        )
    )
    mats_ok = all(v for k, v in e8.items() if k.startswith("T") and "==" in k)
    out.append(
        Finding(
            "pal-matrices",
            "sec. 4.2, 0_1T .. 4_5T",
            "five matrices",
            "",
            "",
            f"each equals the modified D-H transform of the row alpha_(i-1) = 0, -90, 0, 0, 90 "
            f"deg, a_(i-1) = 0, 0, L1, L2, h, d_i = 0, 0, 0, 0, L3: {mats_ok} (Table 1 lost; "
            "the rows are read off these matrices)",
            "holds" if mats_ok else "wrong",
        )
    )
    return out


def _sign_findings(arm: Arm) -> list[Finding]:
    """The signs of eq. 12's theta4 and of eq. 4's alpha (both readings of H)."""
    all_fix = set(FIXES)
    dims = assumed_lengths(arm)
    out: list[Finding] = []
    # eq. 12 theta4 and eq. 7
    zero_motor = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2 - (-np.pi / 2) + np.pi / 2])
    home_tip = arm.fk(np.array(_EQ7))
    m_t4 = quadrant_misses(arm, all_fix - {"theta4"})
    out.append(
        Finding(
            "pal-eq12-theta4",
            "eq. 12, theta4",
            "theta4 = pi/2 - theta2 + theta3",
            "theta4 = pi/2 - (theta2 + theta3)  (= pi/2 - theta, theta of eq. 5)",
            "sign",
            "gripper parallel to the base (sec. 3, theta5 = 0) needs theta2 + theta3 + theta4 "
            "= pi/2, the value at eq. 7; as printed the sum is 3 pi/2 + 2 beta. At zero motor "
            f"angles eq. 12 gives theta4 = {np.degrees(zero_motor[3]):.0f} deg, eq. 7 says 90 "
            f"deg; tip {_fmt(arm.fk(zero_motor))} mm instead of {_fmt(home_tip)} mm. Only this "
            f"item printed: misses {_fmt(m_t4)} mm at the four quadrant targets ({dims}). "
            "Lost parentheses in the extraction cannot be excluded (UNCERTAIN).",
        )
    )

    # eq. 4 / eq. 12 sign of alpha, both readings of H
    m_a_h = quadrant_misses(arm, all_fix - {"alpha"}, H_reading="height")
    m_a_d = quadrant_misses(arm, all_fix - {"alpha", "alpha2", "H"}, H_reading="depth")
    m_init = miss(arm, home_tip, ik_chain(arm, home_tip, all_fix - {"alpha"})["q"])
    m_init_d = miss(
        arm,
        home_tip,
        ik_chain(arm, home_tip, all_fix - {"alpha", "alpha2", "H"}, H_reading="depth")["q"],
    )
    out.append(
        Finding(
            "pal-eq4-alpha",
            "eq. 4 (alpha) with eq. 12 (theta2)",
            "alpha = pi/2 - alpha1 + alpha2",
            "alpha = alpha1 + alpha2 - pi/2 (alpha2 = atan2(Z0 + h, rho - L3))",
            "sign",
            "eq. 12's theta2 = -pi/2 - alpha puts the upper arm at elevation pi/2 + alpha, the "
            "law of cosines at alpha1 + alpha2 (elbow up): one sign is wrong. Eq. 4 as printed "
            f"misses {_fmt(m_a_h)} mm with H = Z0 + h and {_fmt(m_a_d)} mm with H = -(Z0 + h) "
            f"at the quadrant targets; at the initial pose {float(m_init):.2f} mm (H = Z0 + h) "
            f"and {float(m_init_d):.2g} mm (H = -(Z0 + h), right only where alpha1 + alpha2 = "
            "pi/2, as at the initial pose). "
            "Equivalent fix: theta2 = -pi/2 + alpha in eq. 12 with H = -(Z0 + h), which then "
            "needs theta = alpha + beta in eq. 5; the correction above changes one equation "
            "and keeps eqs. 5 and 12 (theta1-theta3). With it alpha > 0 tilts the upper arm "
            "backwards while beta > 0 folds the forearm down, opposite senses, so the text's "
            "'both clockwise about +Y2, +Y3' needs +Y2 = -Y3 (Figure 2 lost).",
        )
    )
    return out


def _eq3_findings(arm: Arm, grid: npt.NDArray[np.float64]) -> list[Finding]:
    """eq. 3: the undefined H, alpha2's branch on the workspace ``grid``, beta1's arccos."""
    all_fix = set(FIXES)
    dims = assumed_lengths(arm)
    home_tip = arm.fk(np.array(_EQ7))
    out: list[Finding] = []
    # eq. 3: H, alpha2 branch, beta1 arccos
    out.append(
        Finding(
            "pal-eq3-H",
            "eq. 3, alpha2",
            "alpha2 = asin(H/L4p)  (H never defined)",
            "H = Z0 + h (the vertical leg of eq. 2's triangle)",
            "undefined symbol",
            "H appears only in eq. 3; eq. 2's triangle has legs sqrt(X0^2+Y0^2) - L3' and "
            "Z0 + h. The depth reading -(Z0 + h) flips alpha2's sign (see pal-eq4-alpha).",
        )
    )
    behind = np.array([[30.0, 10.0, 100.0]])
    m_a2 = miss(arm, behind, ik_chain(arm, behind, all_fix - {"alpha2"})["q"])
    m_grid = miss(arm, grid, ik_chain(arm, grid, all_fix - {"alpha2"})["q"])
    rho_g = np.hypot(grid[:, 0], grid[:, 1])
    wrong_a2 = m_grid > 1e-6
    out.append(
        Finding(
            "pal-eq3-alpha2",
            "eq. 3, alpha2",
            "alpha2 = asin(H/L4p)",
            "alpha2 = atan2(Z0 + h, sqrt(X0**2 + Y0**2) - L3)",
            "branch/quadrant",
            "arcsin returns the elevation of the shoulder-wrist line only while the wrist is in "
            "front of the base axis (rho > L3). On a grid of "
            f"{len(grid)} reachable targets it misses on {int(wrong_a2.sum())}, all with rho < "
            f"L3 (max rho there {rho_g[wrong_a2].max() if wrong_a2.any() else 0:.1f} mm); "
            f"e.g. G = (30, 10, 100) mm misses {float(m_a2[0]):.2f} mm ({dims})",
        )
    )
    m_b1 = quadrant_misses(arm, all_fix - {"beta1"})
    chain_home = ik_chain(arm, home_tip, all_fix - {"beta1"})["motor"]
    out.append(
        Finding(
            "pal-eq3-beta1",
            "eq. 3, beta1",
            "beta1 = (L1p**2 + L2p**2 - L4p**2)/(2*L1p*L2p)",
            "beta1 = acos((L1p**2 + L2p**2 - L4p**2)/(2*L1p*L2p))",
            "missing term",
            "as printed beta1 is a cosine, not an angle: at the initial pose (forearm "
            "perpendicular, L4^2 = L1^2 + L2^2) it gives beta1 = 0 and beta = pi/2 = "
            f"{np.degrees(chain_home[..., 2]):.1f} deg instead of 0; misses {_fmt(m_b1)} mm at "
            "the quadrant targets. The same run keeps arccos for alpha1 (UNCERTAIN: print or "
            "extraction).",
        )
    )
    return out


def _eq6_findings(arm: Arm) -> list[Finding]:
    """eqs. 1 and 6: the waist angle's quadrants over 360 azimuths."""
    all_fix = set(FIXES)
    out: list[Finding] = []
    # eqs. 1 and 6
    az = np.radians(np.arange(-179.5, 180.0, 1.0))
    xs, ys = 200 * np.cos(az), 200 * np.sin(az)
    ref = np.arctan2(ys, xs)
    wrong = {
        r: ~np.isclose(np.mod(gamma_eq6(xs, ys, r) - ref + np.pi, 2 * np.pi) - np.pi, 0.0)
        for r in ("signed", "acute")
    }
    quad = np.floor(np.mod(np.degrees(az), 360) / 90).astype(int) + 1
    bad_q = {r: sorted({int(k) for k in quad[w]}) for r, w in wrong.items()}
    m_g = quadrant_misses(arm, all_fix - {"gamma"})
    m_g_acute = quadrant_misses(arm, all_fix - {"gamma"}, arctan_reading="acute")
    out.append(
        Finding(
            "pal-eq6-quadrant",
            "eqs. 1 and 6",
            "gamma = Piecewise((gammap, X0 > 0), (pi - gammap, X0 <= 0 & Y0 > 0), "
            "(-pi/2 + gammap, X0 <= 0 & Y0 < 0)), gammap = atan(Y0/X0)",
            "gamma = atan2(Y0, X0)",
            "branch/quadrant",
            f"over 360 azimuths: signed arctan wrong on {int(wrong['signed'].sum())} (quadrants "
            f"{bad_q['signed']}), acute arctan|Y0/X0| wrong on {int(wrong['acute'].sum())} "
            f"(quadrants {bad_q['acute']}); quadrant 3 is wrong under both (-pi/2 + gamma' "
            "should be -pi + gamma'). Undefined at X0 = 0 (eq. 1 divides by zero) and for "
            f"X0 < 0, Y0 = 0 (no case). Quadrant targets miss {_fmt(m_g)} mm (signed) and "
            f"{_fmt(m_g_acute)} mm (acute).",
        )
    )
    return out


def _unique_findings(arm: Arm, grid: npt.NDArray[np.float64]) -> list[Finding]:
    """Sec. 2's unique pose: solutions counted per constraint at the workspace ``grid``."""
    dims = assumed_lengths(arm)
    out: list[Finding] = []
    # claims
    counts = uniqueness_counts(arm, grid)
    c_int = np.bincount(counts["interior<90"], minlength=5)
    c_dir = np.bincount(counts["between-directions<90"], minlength=5)
    c_up = np.bincount(counts["elbow-up"], minlength=5)
    c_all = np.bincount(counts["reachable"], minlength=5)
    c_stop = np.bincount(counts["stop"], minlength=5)
    n_stop = int(counts["stop+front"].sum())
    lim = np.degrees(arm.limits[2]) if arm.limits[2] else (-180.0, 180.0)
    out.append(
        Finding(
            "pal-claim-unique",
            "sec. 2, third paragraph",
            "小臂和大臂之間的夾角小於90°, 所以其抓取時的位置狀態是唯一的",
            "the included angle bounds no sign: the elbow-down mirror pose has the same angle. "
            f"A stop on the signed elbow angle, theta3 in [{lim[0]:g}, {lim[1]:g}] deg "
            "(data/arms/palletizer.toml), makes the pose unique with the waist facing the "
            "target (eq. 6); '<= 90 deg', since the initial pose has exactly 90 deg",
            "reasoning",
            f"{len(grid)} grid targets reachable by the front elbow-up branch ({dims}): "
            f"number of solutions (0-4) reaching each: {c_all.tolist()}; of these satisfying "
            f"'interior angle < 90 deg': {c_int.tolist()} (the limit removes "
            f"{c_int[0] / len(grid):.0%} of the targets); '|theta3| < 90 deg': "
            f"{c_dir.tolist()}; 'theta3 > 0': {c_up.tolist()}; with theta3 > 0 and eq. 6's "
            f"waist: 1 for all {int(counts['elbow-up+front'].sum())}. Under either unsigned "
            "reading of the angle the count is even (0, 2 or 4), never 1. With the signed stop "
            f"theta3 in [{lim[0]:g}, {lim[1]:g}] deg: {c_stop.tolist()}, 1 with the waist "
            f"facing the target for all {n_stop} targets it keeps (the waist-reversed pose, "
            "upper arm leaning back over the base, satisfies the stop too for "
            f"{int((counts['stop'] == 2).sum())} of them: only eq. 6's waist, or a limit on "
            "theta2 that the paper does not print, excludes it). The paper's own initial pose "
            "(forearm perpendicular to the upper arm, sec. 3) sits at exactly 90 deg, outside "
            "'< 90 deg'.",
        )
    )
    return out


def _claim_findings(arm: Arm, base: npt.NDArray[np.float64]) -> list[Finding]:
    """Secs. 3 and 5: the isosceles triangle, the exact result (``base``: the corrected
    chain's misses at the quadrant targets [mm]), the unit."""
    P = arm.params
    dims = assumed_lengths(arm)
    G = QUADRANT_TARGETS
    out: list[Finding] = []
    unreachable = np.array([500.0, 0.0, 0.0])
    L4_u = float(np.hypot(500.0 - P.L3, P.h))
    out.append(
        Finding(
            "pal-claim-isosceles",
            "sec. 3, before eq. 1 and after eq. 2",
            "一定可以構成 ... 等腰三角形",
            "a triangle with sides L1', L2', L4' exists iff |L1 - L2| <= L4 <= L1 + L2; it is "
            "isosceles for every target iff L1 = L2",
            "claim",
            "eq. 3 is the general law of cosines and needs no isosceles triangle; isosceles "
            "for all targets forces L1 = L2, which the paper never states (no length is "
            f"printed; the audit's default family is L1 = L2, {dims}: it satisfies the claim "
            "by assumption, not by the paper). No reach "
            f"check precedes eq. 3: G = {_fmt(unreachable)} mm gives L4 = {L4_u:.1f} mm > "
            f"L1 + L2 = {P.L1 + P.L2:g} mm and arccos of "
            f"{(P.L1**2 + L4_u**2 - P.L2**2) / (2 * P.L1 * L4_u):.3f}.",
        )
    )
    m_printed = quadrant_misses(arm, ())
    m_printed_11 = miss(arm, G, ik_chain(arm, G, ())["q"], eq11="printed")
    out.append(
        Finding(
            "pal-claim-exact",
            "sec. 5, last paragraph",
            "結果完全等於待抓取點Gi",
            "FK(IK(G)) = G holds only with eqs. 3, 4, 6, 11, 12 corrected (then to ~1e-13 mm in "
            "float64)",
            "claim",
            f"all formulas as printed: misses {_fmt(m_printed)} mm (D-H product) and "
            f"{_fmt(m_printed_11)} mm (eq. 11 as printed) at four quadrant targets (NaN: a "
            "printed formula undefined); corrected chain: "
            + (
                "below 1e-9 mm (float64 round-off)"
                if float(base.max()) < 1e-9
                else f"max {float(base.max()):.3g} mm"
            )
            + ". The paper's own targets and results are in the lost "
            "Tables 2-3, so its numbers cannot be recomputed.",
        )
    )
    out.append(
        Finding(
            "pal-claim-metres",
            "sec. 5, second paragraph",
            "表中Gi和Ti的單位為米(m)",
            "",
            "",
            "unit statement only: no length (L1, L2, L3, h) is printed in any unit, so metres "
            "vs millimetres cannot be checked against the arm (UNCERTAIN by LOST['lengths']).",
            "undecidable",
        )
    )
    return out


def _xref_findings() -> list[Finding]:
    """The two cross-references of secs. 4.1 and 5."""
    out: list[Finding] = []
    out.append(
        Finding(
            "pal-xref-section",
            "sec. 5, third paragraph",
            "第2節中的逆向解算方法",
            "第3節中的逆向解算方法",
            "cross-reference",
            "section 2 is the model simplification; the IK (eqs. 1-6) is section 3 "
            "'3逆向運動學解算', as the conclusion says ('根據第三節提出的幾何法').",
        )
    )
    out.append(
        Finding(
            "pal-xref-reference",
            "sec. 4.1",
            "參照第5篇文獻簡述的方法[6]",
            "參照第6篇文獻簡述的方法[6]",
            "cross-reference",
            "[6] is Owen, Introduction to Robotics (a D-H source); [5] is a beetle-antennae "
            "search IK paper, not a D-H method.",
        )
    )
    return out


def _holding_findings(arm: Arm, base: npt.NDArray[np.float64]) -> list[Finding]:
    """Eqs. 7, 2 and 5, which hold (``base`` as in :func:`_claim_findings`)."""
    all_fix = set(FIXES)
    home_tip = arm.fk(np.array(_EQ7))
    out: list[Finding] = []
    # items that hold
    q0 = ik_chain(arm, home_tip, all_fix)["q"]
    out.append(
        Finding(
            "pal-eq7",
            "eq. 7",
            "theta = [0, -pi/2, pi/2, pi/2, 0]",
            "",
            "",
            f"FK at eq. 7 = {_fmt(home_tip)} mm = (L2 + L3, 0, L1 - h): upper arm vertical, "
            "forearm perpendicular, gripper level (sec. 3's initial pose); the corrected IK of "
            f"that point returns {_fmt(np.degrees(q0))} deg",
            "holds",
        )
    )
    out.append(
        Finding(
            "pal-eq2",
            "eq. 2",
            "L4p = sqrt((sqrt(X0**2 + Y0**2) - L3p)**2 + (Z0 + h)**2)",
            "",
            "",
            "with the inferred grouping it is the shoulder-wrist distance of the level gripper "
            "(the corrected chain reaches every quadrant target "
            + ("within 1e-9 mm" if float(base.max()) < 1e-9 else f"to {float(base.max()):.3g} mm")
            + " using it)",
            "holds",
        )
    )
    out.append(
        Finding(
            "pal-eq5",
            "eq. 5",
            "theta = -alpha + beta",
            "",
            "",
            "with eq. 12's theta2 = -pi/2 - alpha, theta3 = pi/2 + beta, theta2 + theta3 = "
            "beta - alpha = theta, so the corrected theta4 = pi/2 - theta keeps the gripper level",
            "holds",
        )
    )
    return out


def findings(arm: Arm | None = None) -> list[Finding]:
    """Every checked item of seed 001, wrong ones with a correction, from the runs of
    :mod:`analysis.audit.palletizer_derivations`."""
    arm = arm if arm is not None else load_arm("palletizer")

    # sanity: everything corrected reaches every quadrant target
    base = quadrant_misses(arm, set(FIXES))
    if not np.all(base < 1e-9):  # pragma: no cover - guarded by the tests
        raise AssertionError(f"corrected chain misses {base}")
    grid = workspace_grid(arm)
    return [
        *_dh_findings(arm),
        *_sign_findings(arm),
        *_eq3_findings(arm, grid),
        *_eq6_findings(arm),
        *_unique_findings(arm, grid),
        *_claim_findings(arm, base),
        *_xref_findings(),
        *_holding_findings(arm, base),
    ]

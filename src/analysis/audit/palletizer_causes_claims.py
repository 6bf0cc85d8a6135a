"""Seed 001's register, the text: the claims of sections 2-5 (the triangle, the isosceles
arm, the unique pose, the exact solution, the cross-references), what the extraction lost and
what holds; :func:`causes` in the register's order (:mod:`analysis.audit.palletizer_causes`)."""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np
import sympy as sp

from analysis.audit import palletizer_checks as chk
from analysis.audit.palletizer_causes_ik import azimuths as _azimuths
from analysis.audit.palletizer_formulas import ATOL, S
from analysis.audit.palletizer_formulas import FUNCS as _FUNCS
from analysis.audit.palletizer_formulas import dims_text as _dims
from analysis.audit.palletizer_formulas import evaluate as _eval
from analysis.audit.palletizer_formulas import findings_by_id as _found
from analysis.audit.palletizer_formulas import palletizer_arm as _arm
from analysis.audit.palletizer_formulas import target_values as _values
from analysis.audit.schema import Cause, Manifestation
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.audit.schema import safe as _safe
from analysis.kinematics.arm import Arm, Status
from analysis.papers import palletizer as paper


# ---------------------------------------------------------------------------------------------
# claims
# ---------------------------------------------------------------------------------------------
@cache
def _claim_targets() -> np.ndarray:
    """Grid targets for the claims, the unreachable ones included (x, y in +-1.2 (L1 + L2 +
    L3), z in [-h, L1 + L2])."""
    arm = _arm()
    L1, L2, L3, h = chk.lengths(arm)
    r = 1.2 * (L1 + L2 + L3)
    xs = np.linspace(-r, r, 17)
    zs = np.linspace(-h, L1 + L2, 9)
    G = np.stack(np.meshgrid(xs, xs, zs, indexing="ij"), -1).reshape(-1, 3)
    return G[np.hypot(G[:, 0], G[:, 1]) > 1.0]


def _triangle() -> Cause:
    arm = _arm()
    G = _claim_targets()
    L1, L2, L3, h = chk.lengths(arm)
    L4 = np.hypot(np.hypot(G[:, 0], G[:, 1]) - L3, G[:, 2] + h)
    exists = ~np.isin(
        arm.solve(G, limits=False).status, [int(Status.OUT_OF_REACH), int(Status.INSIDE_REACH)]
    )

    def ok(text: str) -> bool:
        if "for every" in text:
            claimed = np.ones(len(G), bool)
        elif " iff " in text:
            e = sp.parse_expr(text.split(" iff ", 1)[1], local_dict={**S, **_FUNCS, "L4": S["L4"]})
            f = sp.lambdify([S["L1"], S["L2"], S["L4"]], e, "numpy")
            claimed = np.broadcast_to(np.asarray(f(L1, L2, L4), bool), exists.shape)
        else:
            return False
        return bool(np.array_equal(claimed, exists))

    f = _found()["pal-claim-isosceles"]
    return _cause(
        "pal-claim-triangle",
        "Sec. 3 says the triangle of upper arm, forearm and L4 'can always be formed'; it "
        "exists only for |L1 - L2| <= L4 <= L1 + L2, and no reach check precedes eq. 3.",
        "error",
        "claim",
        "No reach " + f.evidence.split("No reach ")[-1],
        [
            Manifestation(
                "pal-claim-triangle/sec3",
                "sec. 3, before eq. 1 ('一定可以構成')",
                "the triangle (L1', L2', L4') exists for every target G",
                "the triangle (L1', L2', L4') exists iff (Abs(L1 - L2) <= L4) & (L4 <= L1 + L2)",
                f"Held against the shared solver without joint limits on {len(G)} grid targets "
                f"(x, y within +-{1.2 * (L1 + L2 + L3):g} mm; {_dims()}): "
                f"{int((~exists).sum())} have no triangle.",
                _safe(ok),
                "pal-claim-isosceles",
            )
        ],
    )


def _isosceles() -> Cause:
    base = _arm()
    G = chk.QUADRANT_TARGETS

    def all_isosceles(arm: Arm) -> bool:
        L1, L2, L3, h = chk.lengths(arm)
        L4 = np.hypot(np.hypot(G[:, 0], G[:, 1]) - L3, G[:, 2] + h)
        sides = np.stack([np.full_like(L4, L1), np.full_like(L4, L2), L4], -1)
        d = np.abs(sides[:, [0, 0, 1]] - sides[:, [1, 2, 2]]).min(axis=-1)
        return bool((d < ATOL).all())

    arms = [base, Arm(base.params.with_(L2=150.0))]

    def ok(text: str) -> bool:
        if " iff " in text:
            cond = text.split(" iff ", 1)[1].strip()
            m = re.fullmatch(r"(L\d) = (L\d)", cond)
            if not m:
                return False
            claimed = [arm.params[m[1]] == arm.params[m[2]] for arm in arms]
        elif "for every" in text:
            claimed = [True for _ in arms]
        else:
            return False
        return claimed == [all_isosceles(a) for a in arms]

    return _cause(
        "pal-claim-isosceles",
        "Sec. 3 calls the triangle isosceles for any target; that needs L1 = L2, which the "
        "paper never states (no length is printed) and eq. 3 does not use.",
        "unsupported",
        "claim",
        _found()["pal-claim-isosceles"].evidence.split(" No reach")[0],
        [
            Manifestation(
                "pal-claim-isosceles/sec3",
                "sec. 3, before eq. 1 and after eq. 2 ('等腰三角形')",
                "the triangle (L1', L2', L4') is isosceles for every target",
                "the triangle (L1', L2', L4') is isosceles for every target iff L1 = L2",
                "Held on two arms, the assumed isosceles one and one with L2 = 150 mm "
                f"(assumed), at the four quadrant targets ({_dims()}).",
                _safe(ok),
                "pal-claim-isosceles",
            )
        ],
    )


def _unique_manifestations(grid: np.ndarray) -> list[Manifestation]:
    """Sec. 2's unique-pose claim: the bound's reasoning (counted over the four solutions at
    the ``grid`` targets) and the bound against sec. 3's initial pose (eq. 7)."""
    q = chk.all_ik(_arm(), grid)
    solved = np.isfinite(q).all(-1)
    t3 = np.where(solved, q[..., 2], np.nan)
    initial_included = 90.0  # sec. 3: forearm perpendicular to the upper arm (eq. 7)
    num = r"(-?\d+(?:\.\d+)?)"

    def unique(text: str) -> bool:
        """One pose per target that keeps any, under the constraint the text names."""
        branches = slice(0, 2) if "waist facing" in text else slice(0, 4)
        m = re.search(rf"theta3 in \[{num}, {num}\] deg", text)
        with np.errstate(invalid="ignore"):
            if m:
                lo, hi = np.radians(float(m[1])), np.radians(float(m[2]))
                keep = solved & (t3 >= lo - 1e-12) & (t3 <= hi + 1e-12)
            else:
                m = re.search(rf"included angle .*(<=|<) {num} deg", text)
                if not m:
                    return False
                inc = np.degrees(np.pi - np.abs(t3))
                bound = float(m[2])
                keep = solved & ((inc <= bound) if m[1] == "<=" else (inc < bound))
        n = keep[:, branches].sum(axis=1)
        return bool((n[n > 0] == 1).all() and (n > 0).any())

    def admits_initial_pose(text: str) -> bool:
        m = re.search(rf"(<=|<) {num} deg", text)
        if not m:
            return False
        bound = float(m[2])
        return initial_included <= bound if m[1] == "<=" else initial_included < bound

    return [
        Manifestation(
            "pal-claim-unique/reasoning",
            "sec. 2, third paragraph ('所以其抓取時的位置狀態是唯一的')",
            "included angle of forearm and upper arm < 90 deg => one pose per target",
            "theta3 in [90, 180] deg, waist facing the target (eq. 6) => one pose per target",
            f"Count of the four solutions (waist facing / reversed, elbow up / down) that each "
            f"constraint keeps, at {len(grid)} grid targets ({_dims()}): the unsigned angle "
            "keeps the mirror pose too (2 or 4 per target, never 1); the signed stop with the "
            "waist facing the target keeps exactly 1 wherever it keeps any.",
            _safe(unique),
            "pal-claim-unique",
        ),
        Manifestation(
            "pal-claim-unique/initial-pose",
            "sec. 2 (the bound) against sec. 3 (the initial pose)",
            "included angle of forearm and upper arm < 90 deg",
            "included angle of forearm and upper arm <= 90 deg",
            "Sec. 3's initial pose has the forearm perpendicular to the upper arm (eq. 7: "
            "theta3 = 90 deg): a strict bound excludes the paper's own starting pose.",
            _safe(admits_initial_pose),
            "pal-claim-unique",
        ),
    ]


def _unique() -> Cause:
    arm = _arm()
    grid = chk.workspace_grid(arm, 21)
    L1, L2, L3, h = chk.lengths(arm)
    f = _found()["pal-claim-unique"]
    ms = _unique_manifestations(grid)
    lim = np.degrees(arm.limits[2])

    def demo() -> bool:
        sol = arm.solve(grid, "all")
        rho = np.hypot(grid[:, 0], grid[:, 1])
        beyond = (np.hypot(rho - L3, grid[:, 2] + h) > math.hypot(L1, L2) + 1e-6) & (rho > 0)
        return (
            _all_fail(ms)
            and tuple(lim) == (90.0, 180.0)
            and not sol.ok[:, 1].any()
            and (sol.status[beyond] == Status.JOINT_LIMITS).all()
        )

    return _cause(
        "pal-claim-unique",
        "Sec. 2 infers a unique pose from 'forearm-upper arm angle < 90 deg'; an angle bound "
        "keeps the mirror pose, only a signed stop (and the waist facing the target) does.",
        "error",
        "reasoning",
        f.evidence + f" Encoded as the stop theta3 in [{lim[0]:g}, {lim[1]:g}] deg in "
        "data/arms/palletizer.toml: enforced by the shared solver and the generated PLC "
        "program (status 'joint-limits'); it limits the wrist to sqrt(L1^2 + L2^2) from the "
        "shoulder.",
        ms,
        demo,
    )


def _exact() -> Cause:
    arm = _arm()
    G = chk.QUADRANT_TARGETS
    f = _found()["pal-claim-exact"]
    pin = chk.fk_ik_pinocchio(arm, 10_000)

    def ok(text: str) -> bool:
        if "as printed" in text:
            for H in ("height", "depth"):
                for a in ("signed", "acute"):
                    q = chk.ik_chain(arm, G, (), H_reading=H, arctan_reading=a)["q"]
                    m = chk.miss(arm, G, q, eq11="printed")
                    if np.all(m < ATOL):  # NaN (a formula undefined) counts as a miss
                        return True
            return False
        if "corrected" in text:
            m = chk.miss(arm, G, chk.ik_chain(arm, G, chk.FIXES)["q"])
            return bool(np.all(m < ATOL))
        return False

    return _cause(
        "pal-claim-exact",
        "Sec. 5 reports that the IK angles put into the D-H formula 'exactly equal' the "
        "targets; with the equations as printed no target in any quadrant comes back.",
        "error",
        "claim",
        f.evidence + f" Corrected and through Pinocchio: {pin['n']:,} seeded level configurations, "
        f"max |FK(IK(G)) - G| below {ATOL:g} mm (float64 round-off; the digits depend on the "
        "machine).",
        [
            Manifestation(
                "pal-claim-exact/sec5",
                "sec. 5, last paragraph ('結果完全等於待抓取點Gi')",
                "FK by eq. 11 as printed of the IK by eqs. 1-6, 12 as printed = G_i, four "
                "quadrants, Z > 0",
                "FK by eq. 11 corrected of the IK by eqs. 1-6, 12 corrected = G_i, four "
                "quadrants, Z > 0",
                "Evaluated at four quadrant targets with Z > 0 (the paper's are in the lost "
                f"Tables 2-3; {_dims()}) under both readings of H and of eq. 1's arctan: the "
                "best printed reading still misses every target by millimetres.",
                _safe(ok),
                "pal-claim-exact",
            )
        ],
    )


def _exact_demo(cause: Cause) -> Cause:
    pin = chk.fk_ik_pinocchio(_arm(), 10_000)
    ms = cause.manifestations
    return Cause(
        cause.id,
        cause.title,
        cause.status,
        cause.kind,
        cause.evidence,
        ms,
        lambda: pin["all_ok"] and pin["max_err_mm"] < ATOL and _all_fail(ms),
    )


def _xrefs() -> list[Cause]:
    def section_ok(text: str) -> bool:
        m = re.search(r"第(\d)節", text)
        return bool(m) and "逆向" in paper.SECTIONS.get(int(m[1]), "")

    def reference_ok(text: str) -> bool:
        m = re.search(r"第(\d+)篇文獻.*\[(\d+)\]", text)
        if not m or m[1] != m[2]:
            return False
        return paper.REFERENCES.get(int(m[2]), {}).get("topic") == "D-H method"

    f_s, f_r = _found()["pal-xref-section"], _found()["pal-xref-reference"]
    return [
        _cause(
            "pal-xref-section",
            "Sec. 5 says the IK method is in section 2; it is section 3.",
            "error",
            "cross-reference",
            f_s.evidence,
            [
                Manifestation(
                    "pal-xref-section/sec5",
                    "sec. 5, third paragraph",
                    "第2節中的逆向解算方法",
                    "第3節中的逆向解算方法",
                    f"Sections as printed: 2 '{paper.SECTIONS[2]}', 3 '{paper.SECTIONS[3]}'.",
                    _safe(section_ok),
                    "pal-xref-section",
                )
            ],
        ),
        _cause(
            "pal-xref-reference",
            "Sec. 4.1 cites 'the 5th reference' as [6]; [6] (Owen) is the D-H source, [5] a "
            "search-based IK paper.",
            "error",
            "cross-reference",
            f_r.evidence,
            [
                Manifestation(
                    "pal-xref-reference/sec4-1",
                    "sec. 4.1",
                    "參照第5篇文獻簡述的方法[6]",
                    "參照第6篇文獻簡述的方法[6]",
                    f"[5] {paper.REFERENCES[5]['printed']}; [6] {paper.REFERENCES[6]['printed']}.",
                    _safe(reference_ok),
                    "pal-xref-reference",
                )
            ],
        ),
    ]


# ---------------------------------------------------------------------------------------------
# what the extraction lost
# ---------------------------------------------------------------------------------------------
def _lost() -> Cause:
    arm = _arm()
    desc = arm.description

    def lengths_ok(text: str) -> bool:
        vals = dict(re.findall(r"\b(L1|L2|L3|h) = (\d+(?:\.\d+)?) mm", text))
        if set(vals) != {"L1", "L2", "L3", "h"} or "assumed" not in text:
            return False
        v = {k: float(x) for k, x in vals.items()}
        if any(
            v[k] != desc.parameters[k].value or desc.parameters[k].status != "assumed" for k in v
        ):
            return False
        # the constraints the paper does state: isosceles (sec. 3), the initial pose and a
        # target in each quadrant with Z > 0 within reach and the elbow stop (secs. 3, 5)
        other = Arm(arm.params.with_(**v))
        G = np.vstack([chk.QUADRANT_TARGETS, [[v["L2"] + v["L3"], 0.0, v["L1"] - v["h"]]]])
        return v["L1"] == v["L2"] and bool((other.solve(G).status == Status.OK).all())

    def targets_ok(text: str) -> bool:
        pts = re.findall(r"\((-?\d+(?:\.\d+)?), (-?\d+(?:\.\d+)?), (-?\d+(?:\.\d+)?)\)", text)
        if len(pts) != 4 or "assumed" not in text:
            return False
        G = np.array(pts, dtype=float)
        quad = {(int(x > 0), int(y > 0)) for x, y, _ in G}
        return (
            len(quad) == 4
            and bool((G[:, 2] > 0).all())
            and bool((arm.solve(G).status == Status.OK).all())
        )

    q = ", ".join(f"({x:g}, {y:g}, {z:g})" for x, y, z in chk.QUADRANT_TARGETS)
    L1, L2, L3, h = chk.lengths(arm)
    return _cause(
        "pal-extraction-lost",
        "The extraction lost Tables 1-3 and Figures 1-7: no length, target, angle or result "
        "of the paper survives; the audit's numbers are assumed.",
        "extraction",
        "extraction",
        "analysis.papers.palletizer.LOST: "
        + "; ".join(f"{k}: {v}" for k, v in list(paper.LOST.items())[:5]),
        [
            Manifestation(
                "pal-extraction-lost/table1",
                "Table 1 (D-H parameters) and every length",
                "Table 1: body lost; L1, L2, L3, h never printed as numbers",
                f"L1 = {L1:g} mm, L2 = {L2:g} mm, L3 = {L3:g} mm, h = {h:g} mm: assumed "
                "(data/arms/palletizer.toml), isosceles family L1 = L2",
                "The assumed values must be the description's, marked assumed, isosceles (the "
                "paper's sec. 3 argument) and admit the initial pose and a target per quadrant "
                "within the elbow stop.",
                _safe(lengths_ok),
            ),
            Manifestation(
                "pal-extraction-lost/tables2-3",
                "Tables 2-3 (targets G1-G4, angles, FK results T1-T4, in m)",
                "Tables 2-3: bodies lost (four targets, one per quadrant, Z > 0)",
                f"four targets [mm], one per quadrant, Z > 0: {q}: assumed",
                "Sec. 5's layout (four quadrants, Z > 0) is all that survives; the stand-ins "
                "must follow it and be reachable within the stop.",
                _safe(targets_ok),
            ),
        ],
    )


# ---------------------------------------------------------------------------------------------
# what holds
# ---------------------------------------------------------------------------------------------
def _matrices_hold() -> Cause:
    e8 = chk.eq8_checks()
    mats = all(v for k, v in e8.items() if k.startswith("T") and "==" in k)
    return Cause(
        "pal-matrices-hold",
        "The five matrices 0_1T..4_5T (sec. 4.2) and their product order (eq. 9) are "
        "modified D-H transforms of one row set; data/arms/palletizer.toml is read off them.",
        "holds",
        "transcription",
        _found()["pal-matrices"].evidence,
        (),
        lambda: mats,
    )


def _eq2_holds() -> Cause:
    v = _values()

    def eq2() -> bool:
        e = paper.equation("eq2")[0][1]
        got = _eval(e, v)
        return got is not None and bool(np.abs(got - v["L4"]).max() < ATOL)

    return Cause(
        "pal-eq2-holds",
        "eq. 2 (radicals restored) is the shoulder-wrist distance of the level gripper.",
        "holds",
        "transcription",
        _found()["pal-eq2"].evidence
        + f"; equal to the distance measured on the arm at {len(v['X0'])} targets.",
        (),
        eq2,
    )


def _eq5_holds() -> Cause:
    def eq5() -> bool:
        t2, t3 = -sp.pi / 2 - S["alpha"], sp.pi / 2 + S["beta"]  # eq. 12
        theta = paper.equation("eq5")[0][1]
        return sp.simplify(theta - (t2 + t3)) == 0

    return Cause(
        "pal-eq5-holds",
        "eq. 5, theta = -alpha + beta, is theta2 + theta3 of eq. 12: the gripper angle that "
        "keeps it level.",
        "holds",
        "transcription",
        _found()["pal-eq5"].evidence,
        (),
        eq5,
    )


def _eq7_holds() -> Cause:
    arm = _arm()

    def eq7() -> bool:
        q = np.array([0.0, -np.pi / 2, np.pi / 2, np.pi / 2])
        L1, L2, L3, h = chk.lengths(arm)
        tip = arm.fk(q)
        back = arm.ik(tip)
        return bool(
            np.allclose(tip, [L2 + L3, 0, L1 - h], atol=ATOL) and np.allclose(back, q, atol=ATOL)
        )

    return Cause(
        "pal-eq7-holds",
        "eq. 7's angles (0, -90, 90, 90, 0 deg) are the initial pose of sec. 3, and the "
        "corrected IK returns them.",
        "holds",
        "transcription",
        _found()["pal-eq7"].evidence + f" ({_dims()})",
        (),
        eq7,
    )


def _quadrant_rule_holds() -> Cause:
    def quadrant_rule() -> bool:
        az = _azimuths()
        g = np.arctan2(az["Y0"], az["X0"])
        upper = az["Y0"] > 0
        lower = az["Y0"] < 0
        return bool((g[upper] > 0).all() and (g[lower] < 0).all())

    return Cause(
        "pal-quadrant-rule-holds",
        "Sec. 3: M1 turns left (gamma > 0) for targets in quadrants 1-2 and right in "
        "quadrants 3-4, as atan2 gives.",
        "holds",
        "claim",
        "atan2(Y0, X0) > 0 for all 180 azimuths with Y0 > 0 and < 0 for all 180 with "
        "Y0 < 0 (the rule of the text; eq. 6 breaks it, pal-eq6-quadrant).",
        (),
        quadrant_rule,
    )


def _holds() -> list[Cause]:
    """What holds: the matrices, eqs. 2, 5, 7 and the quadrant rule of sec. 3."""
    return [_matrices_hold(), _eq2_holds(), _eq5_holds(), _eq7_holds(), _quadrant_rule_holds()]


def causes() -> list[Cause]:
    """The causes of the claims, the extraction and what holds, in the register's order."""
    return [
        _triangle(),
        _isosceles(),
        _unique(),
        _exact_demo(_exact()),
        *_xrefs(),
        _lost(),
        *_holds(),
    ]

"""Seed 002's register, the claims: the 'random' samples, the reasoning from 10.4 mm against
the 200 mm opening, the solvability of section 3.2, R3 as a group, what the extraction lost and
what holds; :func:`causes` in the register's order (:mod:`analysis.audit.picker_causes`)."""

from __future__ import annotations

import math
import re

import numpy as np

from analysis.audit import picker_checks as chk
from analysis.audit import poe_checks
from analysis.audit.picker_checks import TIMES
from analysis.audit.picker_checks import assumed_dimensions as _assumed
from analysis.audit.picker_checks import default_picker as _picker
from analysis.audit.picker_checks import equation_display as _display
from analysis.audit.picker_checks import findings_by_id as _found
from analysis.audit.schema import Cause, Manifestation
from analysis.audit.schema import make_cause as _cause
from analysis.audit.schema import safe as _safe
from analysis.kinematics import picker as pk
from analysis.papers import picker as paper


# ---------------------------------------------------------------------------------------------
# claims and reasoning
# ---------------------------------------------------------------------------------------------
def _random() -> Cause:
    def ok(text: str) -> bool:
        # the five commanded configurations under every reading of the units
        ranks = {
            int(np.linalg.matrix_rank(pk.law_active(np.asarray(TIMES), r), tol=1e-9))
            for r in pk.READINGS
        }
        on_one_ray = ranks == {1}  # each a multiple of one vector: one path, no spread
        if "random" in text or "隨機" in text:
            return not on_one_ray
        return "one deterministic" in text and on_one_ray

    return _cause(
        "pick-claim-random",
        "The abstract says five sets of joint values were chosen at random; sec. 4 samples one "
        "deterministic law at t = 1..5 s.",
        "error",
        "claim",
        _found()["pick-claim-random"].evidence,
        [
            Manifestation(
                "pick-claim-random/abstract",
                "abstract",
                "隨機選取5組關節變量值 (five sets of joint values chosen at random)",
                "five samples t = 1, 2, 3, 4, 5 s of one deterministic joint law (sec. 4)",
                "Stacked as a 5 x 6 matrix the five configurations have rank 1 under every "
                "reading of the units: one direction in joint space, scaled by t or t²/2.",
                _safe(ok),
                "pick-claim-random",
            )
        ],
    )


def _opening() -> Cause:
    f = _found()["pick-reasoning-opening"]
    picker = _picker()
    hidden = {r: chk.mutation_errors(picker, r) for r in chk.PLAUSIBLE_READINGS}
    opening = paper.EXPERIMENT["jaw_opening_mm"]

    def ok(text: str) -> bool:
        """'error < bound => conclusion'. Concluding that eq. 22 is correct is valid only if
        every wrong model the experiment could meet (one element wrong) moves the marker by
        more than the bound at the five poses. Concluding that the trunk can be clamped needs
        the bound to be the clearance per side, (opening - d)/2, for the trunk diameters d
        it names: d < opening - 2 error."""
        m = re.search(r"error (\d+(?:\.\d+)?) mm < (.+?) => (.*)$", text)
        if not m:
            return False
        err, bound, conclusion = float(m[1]), m[2], m[3]
        if "correct" in conclusion and "not shown correct" not in conclusion:
            threshold = float(re.match(r"\(?(\d+(?:\.\d+)?)", bound)[1])
            return all(e > threshold for errs in hidden.values() for e in errs.values())
        if "clamp" not in conclusion:
            return False
        d = re.search(r"\(200 mm - d\)/2 .*for d < (\d+(?:\.\d+)?) mm", bound)
        return bool(d) and math.isclose(float(d[1]), opening - 2 * err)

    printed = "error 10.4 mm < 200 mm jaw opening => eq. 22 and the method correct"
    corrected = (
        "error 10.4 mm < (200 mm - d)/2 clearance per side for d < 179.2 mm => a trunk of "
        "diameter d can be clamped at these five poses (eq. 22 not shown correct beyond 10.4 mm)"
    )
    ms = [
        Manifestation(
            f"pick-reasoning-opening/{slug}",
            where,
            printed,
            corrected,
            f"Wrong models (one element wrong) whose largest per-axis change over the five "
            f"poses stays below 200 mm ({_assumed()}; joint values in degrees): "
            + "; ".join(f"{k} {e:.1f} mm" for k, e in hidden["value, deg"].items() if e < 200.0)
            + ". The trunk diameter d is not printed; 10.4 mm per side fits the jaw for "
            "d < 200 - 2 x 10.4 = 179.2 mm. The error is per axis: the distance may reach "
            f"sqrt(3) x 10.4 = {math.sqrt(3) * 10.4:.1f} mm.",
            _safe(ok),
            "pick-reasoning-opening",
        )
        for slug, where in (
            ("abstract", "abstract"),
            ("sec4", "sec. 4, after Table 2"),
            ("conclusion", "conclusion 3"),
        )
    ]
    return _cause(
        "pick-reasoning-opening",
        "10.4 mm 'far below the 200 mm jaw opening' is said to prove the FK equation correct; "
        "an opening is a clamping tolerance, and wrong models pass it.",
        "error",
        "reasoning",
        f.evidence,
        ms,
    )


def _solvable() -> Cause:
    sliders = len(paper.JOINTS["active"])

    def ok(text: str) -> bool:
        m = re.search(r"(\d+) moving links, (\d+) one-dof joints", text)
        if not m:
            return False
        return chk.planar_mobility(int(m[1]) + 1, int(m[2])) == sliders

    f = _found()["pick-claim-solvable"]
    return _cause(
        "pick-claim-solvable",
        "Sec. 3.2: given the sliders, the passive angles follow; the two chains as listed "
        "leave a planar loop of mobility 6, so eqs. 10-14 (lost) must add links not listed.",
        "uncertain",
        "reasoning",
        f.evidence,
        [
            Manifestation(
                "pick-claim-solvable/sec3-2",
                "sec. 3.2 (the chains of the parallel part)",
                "main + secondary chain as listed: 8 moving links, 9 one-dof joints",
                "with the fore-arm, link 5 and the triangle's pivot: 10 moving links, 14 "
                "one-dof joints",
                "Gruebler-Kutzbach for a planar mechanism, 3 n - 2 j (frame: the rotating "
                f"seat): the mobility must equal the {sliders} sliders for the passive angles "
                "to follow from them.",
                _safe(ok),
                "pick-claim-solvable",
            )
        ],
    )


def _r3() -> Cause:
    rng = np.random.default_rng(3)
    xs = rng.normal(size=(20, 3))

    def ok(text: str) -> bool:
        if "zero vector" in text:
            e = np.zeros(3)
        elif "every 3-vector" in text or "3維列向量" in text:
            e = rng.normal(size=3)  # any 3-vector would have to act as the identity
        else:
            return False
        return bool(np.all(xs + e == xs))

    return _cause(
        "pick-claim-r3",
        "Sec. 1.1 calls R3 'the group with 3-vectors as identity element'; (R3, +) has one "
        "identity, the zero vector.",
        "error",
        "claim",
        _found()["pick-claim-r3"].evidence,
        [
            Manifestation(
                "pick-claim-r3/sec1-1",
                "sec. 1.1",
                "R3是以3維列向量作為單位元素的群 (identity element: every 3-vector)",
                "R3 is the group (R3, +) with the zero vector as identity element",
                "e + x = x for all x holds only for e = 0 (checked on 20 random x).",
                _safe(ok),
                "pick-claim-r3",
            )
        ],
    )


# ---------------------------------------------------------------------------------------------
# what the extraction lost
# ---------------------------------------------------------------------------------------------
def _lost() -> Cause:
    picker = _picker()
    rep = pk.replay_experiment(picker=picker)["value, deg"]
    pts = rep["position"]
    point = r"\((-?\d+\.\d), (-?\d+\.\d), (-?\d+\.\d)\)"

    def table2_ok(text: str) -> bool:
        got = np.array(re.findall(point, text), dtype=float)
        if got.shape != (5, 3) or "assumed" not in text:
            return False
        return bool(np.abs(got - pts).max() <= 0.05 + 1e-9)  # printed to 0.1 mm

    def table1_ok(text: str) -> bool:
        names = set(re.findall(r"\b([a-zA-Z_]+) = -?\d", text))
        params = picker.params
        dims = {"x_A", "z_A", "g", "l_AD", "b", "l_DF", "d_s", "e_t", "f", "e_tool"}
        if not dims <= names or "assumed" not in text:
            return False
        values: dict[str, str] = {}
        for k, v in re.findall(r"\b([a-zA-Z_]+) = (-?\d+(?:\.\d+)?)", text):
            values.setdefault(k, v)  # the first value named: the dimension itself
        same = all(float(values[k]) == params[k] for k in dims)
        assumed = all(params.parameters[k].status == "assumed" for k in dims)
        loops = picker.loop_residuals(np.zeros(6))
        closed = max(float(v) for v in loops.values()) < 1e-9
        return same and assumed and closed and bool(rep["reachable"].all())

    dims_text = ", ".join(
        f"{k} = {picker.params[k]:g}"
        for k in ("x_A", "z_A", "g", "l_AD", "b", "l_DF", "d_s", "e_t", "f", "e_tool")
    )
    pts_text = ", ".join(f"({x:.1f}, {y:.1f}, {z:.1f})" for x, y, z in pts)
    return _cause(
        "pick-extraction-lost",
        "The extraction lost every displayed equation (1-22), Tables 1-2 and Figures 1-4: "
        "no dimension, no measured or computed position survives.",
        "extraction",
        "extraction",
        "analysis.papers.picker.LOST: "
        + "; ".join(f"{k}: {v}" for k, v in list(paper.LOST.items())[:3])
        + " "
        + _found()["pick-table2"].evidence,
        [
            Manifestation(
                "pick-extraction-lost/table1",
                "Table 1 (structure parameters: a, f and 'the others')",
                "Table 1: body lost (only the caption survives)",
                f"{dims_text} mm: assumed (data/arms/picker.toml, pantograph l_AD/g = l_DF/b = 4)",
                "The stand-ins must be the description's, marked assumed, assemble at the "
                "reference pose (loops closed to 1e-9 mm) and keep the replayed poses (joint "
                "values in degrees) within link 5's reach.",
                _safe(table1_ok),
            ),
            Manifestation(
                "pick-extraction-lost/table2",
                "Table 2 (per-axis errors at the five poses) and the computed positions",
                "Table 2: body lost (only the 10.4 mm maximum survives)",
                f"positions [mm] in S at t = 1..5 s, joint values in degrees: {pts_text}: "
                "assumed dimensions",
                "What the laws imply with the assumed dimensions (kinematics.picker."
                "replay_experiment); the measured ones are lost, so 10.4 mm cannot be "
                "recomputed.",
                _safe(table2_ok),
            ),
        ],
    )


# ---------------------------------------------------------------------------------------------
# what holds
# ---------------------------------------------------------------------------------------------
def _holds() -> list[Cause]:
    rows = poe_checks.cross_check(1000)
    found = _found()
    # the differences are float64 round-off, whose last digits depend on the machine's libm:
    # the register states the bound they are held to, not their digits
    summary = "; ".join(
        f"{r['arm']} {r['chain']} ({r['joints']}): "
        + ", ".join(k[:-5] for k, v in r.items() if k.endswith("[mm]") and np.isfinite(v))
        for r in rows
    )
    return [
        Cause(
            "pick-poe-holds",
            "The product-of-exponentials FK (secs. 1.1-1.2: revolute and prismatic twists, "
            "Rodrigues, g_st = prod exp(xi q) g_st(0)) is right: checked on every arm of the "
            "project.",
            "holds",
            "claim",
            f"analysis.kinematics.poe against independent routes, {rows[0]['n']} seeded "
            f"configurations per chain, every position difference below "
            f"{poe_checks.ATOL_MM:g} mm (float64 round-off) against: {summary}. The D-H arms "
            "(grabber, palletizer, gr1) also against their D-H product and "
            "Pinocchio built from the D-H rows; the picker (no D-H description: prismatic "
            "sliders) against Pinocchio built from its screws and its loop closure "
            "(tests/kinematics/test_poe.py and test_picker.py: 10,000 configurations each, "
            "1e-9 mm). The paper's own equations are lost: the method is what is checked.",
            (),
            lambda: (
                all(r["ok"] for r in rows)
                and {"grabber", "palletizer", "picker"} <= {r["arm"] for r in rows}
            ),
        ),
        Cause(
            "pick-topology-holds",
            "Sec. 2-4: 2P4R with six actuated joints (waist, two sliders, three wrist "
            "revolutes), exactly the six laws of sec. 4; 13 joints in the two chains.",
            "holds",
            "claim",
            found["pick-topology"].evidence,
            (),
            lambda: (
                len(paper.JOINTS["active"]) + 4 == 6 == len(paper.JOINTS["commanded"])
                and len(paper.JOINTS["active"]) + len(paper.JOINTS["passive"]) + 4 == 13
                and paper.TOPOLOGY["prismatic"] == 2
            ),
        ),
        Cause(
            "pick-xrefs-hold",
            "The other equation references (3, 4; 7, 8; 10, 11; 15, 16; 22) fit the count of "
            "displayed equations.",
            "holds",
            "cross-reference",
            found["pick-xref-7-8-15-16-22"].evidence,
            (),
            lambda: (
                _display(7) == "revolute twist"
                and _display(8) == "prismatic twist"
                and _display(22) == "p_e(theta)"
                and _display(15) == "theta3(x, z)"
            ),
        ),
    ]


def causes() -> list[Cause]:
    """The causes of the claims, the extraction and what holds, in the register's order."""
    return [_random(), _opening(), _solvable(), _r3(), _lost(), *_holds()]

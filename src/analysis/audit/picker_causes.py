"""Seed 002's register (Yang, Li, Gao 2016, the 2P4R camellia-fruit picker): the findings of
:mod:`analysis.audit.picker_checks` grouped into root causes, in the schema of
:mod:`analysis.audit.schema`, plus the product-of-exponentials method checked on every arm
of the project (:mod:`analysis.audit.poe_checks`).

The extraction lost every displayed equation, Tables 1-2 and Figures 1-4 of this paper, so
what can be checked is the running text: the units and words of the joint laws, the
equation cross-references (numbers counted from lead-ins, :data:`analysis.papers.picker.
EQUATION_NUMBERS`), the names of the chains, the claims and the reasoning from 10.4 mm. Each
manifestation's ``verify(text)`` puts the text in a small checkable form (coefficients and a
unit, an equation number, a chain name, a count of links and joints, a threshold and what it
is said to prove) and decides it by a count or a run of the reconstructed mechanism
(:mod:`analysis.kinematics.picker`, every dimension ASSUMED: ``data/arms/picker.toml``).
Verdicts that rest on a number of the reconstruction say so; most do not (a joint turning
125 rad in 5 s does so whatever the arm's lengths).
"""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np

from analysis.audit import picker_checks as chk
from analysis.audit import poe_checks
from analysis.audit.schema import Cause, Manifestation, Register
from analysis.kinematics import picker as pk
from analysis.kinematics import poe
from analysis.papers import picker as paper

__all__ = ["register"]

TIMES = tuple(paper.EXPERIMENT["times"])
LAWS = {
    k: float(v["expr"].split("*")[0]) for k, v in paper.EXPERIMENT["laws"].items()
}  # printed coefficients: omega1 -5, omega6 10, omega7 -10, omega8 -10, nu_x 15, nu_z 20
_ANGLE_LAWS = {"omega1": "1", "omega6": "6", "omega7": "7", "omega8": "8"}


def _safe(fn):
    """A verify predicate that answers False instead of raising on a malformed text."""

    def wrapped(text: str) -> bool:
        try:
            return bool(fn(text))
        except Exception:  # a text the predicate cannot read is not a right text
            return False

    return wrapped


def _all_fail(ms) -> bool:
    return all(not m.verify(m.printed) and m.verify(m.corrected) for m in ms)


def _cause(cid, title, status, kind, evidence, ms, demo=None) -> Cause:
    ms = tuple(ms)
    return Cause(cid, title, status, kind, evidence, ms, demo or (lambda: _all_fail(ms)))


@cache
def _picker() -> pk.Picker:
    return pk.load_picker()


@cache
def _found() -> dict:
    return {f.id: f for f in chk.findings(_picker())}


def _assumed() -> str:
    return "assumed dimensions of data/arms/picker.toml: " + ", ".join(_picker().params.assumed())


# ---------------------------------------------------------------------------------------------
# the joint laws (sec. 4)
# ---------------------------------------------------------------------------------------------
def _law_angles(text: str) -> np.ndarray | None:
    """The four joint angles [rad] at t = 1..5 s that a text of the joint laws commands.

    The text names ``omega<i> = c*t`` (angular velocities, integrated from the reference
    pose: c t^2 / 2) or ``theta<i> = c*t`` (joint values), with a unit in brackets:
    ``[rad/s]``, ``[deg/s]``, ``[rad]`` or ``[deg]``. The coefficients must be the printed
    ones (sec. 4); None if the text is not of this form.
    """
    found = re.findall(r"\b(omega|theta)(\d) = (-?\d+(?:\.\d+)?)\*t", text)
    unit = re.search(r"\[(rad/s|deg/s|rad|deg)\]", text)
    if not found or not unit or len({q for q, _, _ in found}) != 1:
        return None
    quantity = found[0][0]
    laws = {f"omega{i}": float(c) for _, i, c in found}
    if set(laws) != set(_ANGLE_LAWS) or any(laws[k] != LAWS[k] for k in laws):
        return None
    velocity = quantity == "omega"
    if velocity != unit[1].endswith("/s"):
        return None  # an angle with a rate unit, or a rate with an angle unit
    t = np.asarray(TIMES)
    shape = t**2 / 2 if velocity else t
    scale = math.pi / 180 if unit[1].startswith("deg") else 1.0
    return shape[:, None] * np.array([laws[k] for k in _ANGLE_LAWS]) * scale


def _plausible(text: str) -> bool:
    """Every commanded joint stays within half a turn over t = 1..5 s (no joint range is
    printed; a waist or wrist spinning tens of radians in a 5 s positioning test is not a
    test of positions): :data:`analysis.kinematics.picker.PLAUSIBLE_MAX_TURN`."""
    a = _law_angles(text)
    return a is not None and bool(np.abs(a).max() <= pk.PLAUSIBLE_MAX_TURN)


_LAW_TEXT = "theta1 = -5*t, theta6 = 10*t, theta7 = -10*t, theta8 = -10*t"


def _units() -> Cause:
    f = _found()["pick-units-omega"]
    rs = chk.reading_summary()
    rep = pk.replay_experiment(picker=_picker())
    ms = [
        Manifestation(
            "pick-units/omega-rad-s",
            "sec. 4, joint laws (ω_i the angular velocity of joint i, rad/s)",
            _LAW_TEXT.replace("theta", "omega") + " [rad/s], integrated from the reference pose",
            _LAW_TEXT.replace("theta", "omega") + " [deg/s], integrated from the reference pose",
            f"As printed the waist turns {rs['velocity, rad/s']['max_turn_rad'] / 2:.1f} rad "
            f"and the wrist {rs['velocity, rad/s']['max_turn_rad']:.0f} rad "
            f"({rs['velocity, rad/s']['max_turns']:.1f} turns) by t = 5 s, at up to "
            f"{rs['velocity, rad/s']['peak_speed_rpm']:.0f} rpm; in deg/s the largest angle is "
            f"{math.degrees(rs['velocity, deg/s']['max_turn_rad']):.0f} deg.",
            _safe(_plausible),
            "pick-units-omega",
        ),
        Manifestation(
            "pick-units/values-rad",
            "sec. 4, '5組關節變量值' (the laws read as joint values, with the printed rad)",
            _LAW_TEXT + " [rad] (joint values)",
            _LAW_TEXT + " [deg] (joint values)",
            "Read as joint values in rad the wrist stands at "
            f"{rs['value, rad']['max_turn_rad']:.0f} rad "
            f"({rs['value, rad']['max_turns']:.1f} turns) at t = 5 s; in degrees at "
            f"{math.degrees(rs['value, deg']['max_turn_rad']):.0f} deg. Sec. 4 calls the same "
            "laws angular velocities and '5組關節變量值' (five sets of joint values).",
            _safe(_plausible),
            "pick-units-omega",
        ),
    ]

    def demo() -> bool:
        ok = {k for k, v in rep.items() if v["plausible"]}
        return _all_fail(ms) and ok == set(chk.PLAUSIBLE_READINGS)

    return _cause(
        "pick-units",
        "Sec. 4's joint laws in rad/s (or as values in rad) spin the waist and wrist tens of "
        "radians in 5 s; only degrees give a positioning test.",
        "error",
        "unit",
        f.evidence + f" Replay of the laws at t = 1..5 s: {_assumed()}.",
        ms,
        demo,
    )


# ---------------------------------------------------------------------------------------------
# cross-references and names
# ---------------------------------------------------------------------------------------------
def _number(text: str, word: str) -> int | None:
    m = re.search(rf"{word}\((\d+)\)", text)
    return int(m[1]) if m else None


def _display(n: int | None) -> str:
    if n is None or not 1 <= n <= len(paper.EQUATION_NUMBERS):
        return ""
    return paper.EQUATION_NUMBERS[n - 1]["holds"]


def _xrefs() -> list[Cause]:
    S, _ = _picker().open_chain()
    wrist_kinds = set(poe.joint_kinds(S[5:8]))  # theta6..theta8, 'not yet solved' in sec. 3.3

    def eq18_ok(text: str) -> bool:
        return _display(_number(text, "方程")) == "p_e(theta)"

    def eq9_ok(text: str) -> bool:
        want = {"revolute": "revolute twist", "prismatic": "prismatic twist"}
        return (
            len(wrist_kinds) == 1 and _display(_number(text, "式")) == want[next(iter(wrist_kinds))]
        )

    f18, f9 = _found()["pick-xref-eq18"], _found()["pick-xref-eq9"]
    return [
        _cause(
            "pick-xref-eq18",
            "Sec. 3.4 calls the end-effector FK 'equation (18)'; sec. 4 calls it (22), which the "
            "count of displays supports.",
            "error",
            "cross-reference",
            f18.evidence,
            [
                Manifestation(
                    "pick-xref-eq18/sec3-4",
                    "sec. 3.4",
                    "獲得了混聯采摘機器人機械臂運動學正解方程(18)",
                    "獲得了混聯采摘機器人機械臂運動學正解方程(22)",
                    "Display 18 is the axis directions of sec. 3.3 "
                    f"({paper.EQUATION_NUMBERS[17]['leadin']}); display 22 is p_e(θ).",
                    _safe(eq18_ok),
                    "pick-xref-eq18",
                )
            ],
        ),
        _cause(
            "pick-xref-eq9",
            "Sec. 3.3 takes the remaining twists 'from eq. (9)', the POE product; twists come "
            "from eq. (7) (revolute), as sec. 3.2 itself says.",
            "error",
            "cross-reference",
            f9.evidence,
            [
                Manifestation(
                    "pick-xref-eq9/sec3-3",
                    "sec. 3.3",
                    "由式(9)可求得主動鏈中尚未求解的各關節運動旋量坐標",
                    "由式(7)可求得主動鏈中尚未求解的各關節運動旋量坐標",
                    f"The joints left in sec. 3.3 (θ6-θ8, the wrist) are {sorted(wrist_kinds)}; "
                    f"display 7 is the {_display(7)}, display 9 the {_display(9)}.",
                    _safe(eq9_ok),
                    "pick-xref-eq9",
                )
            ],
        ),
    ]


def _chain_names() -> Cause:
    active = set(paper.JOINTS["active"]) | {"theta1", "theta6", "theta7", "theta8"}
    main = [f"theta{i}" for i in range(1, 9)]  # the main chain of the open-chain model

    def zh_ok(text: str) -> bool:
        if "主運動鏈" in text or "副運動鏈" in text:
            return True  # the names sec. 3.1-3.2 define
        if "主動鏈" in text:  # 'active chain': every joint of it would be active
            return set(main) <= active
        return False

    def en_ok(text: str) -> bool:
        S, _ = _picker().open_chain()
        serial_open = S.shape[0] == 8  # one screw per joint from base to tool: an open chain
        if "closed chain" in text:
            return not serial_open
        return "open" in text and serial_open

    f_zh, f_en = _found()["pick-label-active-chain"], _found()["pick-label-english-closed"]
    return _cause(
        "pick-chain-names",
        "The main (open) chain that the POE is applied to is called the 'active chain' in sec. "
        "3.3 and 'the closed chain' in the English abstract.",
        "error",
        "label",
        f_zh.evidence + " " + f_en.evidence,
        [
            Manifestation(
                "pick-chain-names/sec3-3",
                "sec. 3.3 (twice)",
                "由於選擇垂直滑塊所在的運動鏈為主動鏈",
                "由於選擇垂直滑塊所在的運動鏈為主運動鏈",
                f"Passive joints of the main chain: {sorted(set(main) - active)} (sec. 3.2's α).",
                _safe(zh_ok),
                "pick-label-active-chain",
            ),
            Manifestation(
                "pick-chain-names/abstract",
                "English abstract",
                "the position of the end effector was got from the kinematics analysis of the "
                "closed chain by using ... product-of-exponential formula",
                "the position of the end effector was got from the kinematics analysis of the "
                "major (open) chain by using ... product-of-exponential formula",
                "The POE of sec. 3.3 runs over the main chain's eight joints from the base to "
                "the tool: a serial, open chain; the loop gives the passive angles.",
                _safe(en_ok),
                "pick-label-english-closed",
            ),
        ],
    )


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


def register() -> Register:
    """Seed 002's register (cached by :func:`analysis.audit.register.register`)."""
    causes = [
        _units(),
        *_xrefs(),
        _chain_names(),
        _random(),
        _opening(),
        _solvable(),
        _r3(),
        _lost(),
        *_holds(),
    ]
    return Register(
        "picker",
        "Yang Hanjiang, Li Lijun, Gao Zicheng, Trans. CSAE 2016 (seed 002): 2P4R "
        "camellia-fruit picker, screw theory",
        tuple(causes),
    )

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

This module holds the causes of the joint laws, the cross-references and the chain names and
builds the register; :mod:`analysis.audit.picker_causes_claims` has the claims, the
extraction and what holds.
"""

from __future__ import annotations

import math
import re

import numpy as np

from analysis.audit import picker_causes_claims
from analysis.audit import picker_checks as chk
from analysis.audit.picker_checks import TIMES
from analysis.audit.picker_checks import assumed_dimensions as _assumed
from analysis.audit.picker_checks import default_picker as _picker
from analysis.audit.picker_checks import equation_display as _display
from analysis.audit.picker_checks import findings_by_id as _found
from analysis.audit.schema import Cause, Manifestation, Register
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.audit.schema import safe as _safe
from analysis.kinematics import picker as pk
from analysis.kinematics import poe
from analysis.papers import picker as paper

__all__ = ["register"]

LAWS = {
    k: float(v["expr"].split("*")[0]) for k, v in paper.EXPERIMENT["laws"].items()
}  # printed coefficients: omega1 -5, omega6 10, omega7 -10, omega8 -10, nu_x 15, nu_z 20
_ANGLE_LAWS = {"omega1": "1", "omega6": "6", "omega7": "7", "omega8": "8"}


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


def register() -> Register:
    """Seed 002's register (cached by :func:`analysis.audit.register.register`)."""
    causes = [
        _units(),
        *_xrefs(),
        _chain_names(),
        *picker_causes_claims.causes(),
    ]
    return Register(
        "picker",
        "Yang Hanjiang, Li Lijun, Gao Zicheng, Trans. CSAE 2016 (seed 002): 2P4R "
        "camellia-fruit picker, screw theory",
        tuple(causes),
    )

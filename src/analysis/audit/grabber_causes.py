"""Seed 000's register: the wrong printed items grouped into root causes, plus the PLC, the
implementation and the claims audits.

Every wrong item of :func:`analysis.audit.grabber_audit.audit` appears exactly once, as a
manifestation of one cause (``tests/audit/test_register.py`` checks this). Causes beyond the
item audit: the executed listings (Figures 3-6 run byte-accurately), the overlapping operands
of Figure 5, the implementation of section 2 against Table 2 and the CPU 224, and the
paper's claims about its results. Their evidence is computed here, not typed.

This module holds the derivation's causes, the implementation and the claims and builds the
register; :mod:`analysis.audit.grabber_causes_stl` has the executed listings and the STL causes.
"""

from __future__ import annotations

import re
from functools import cache

import numpy as np

from analysis.audit import grabber_causes_stl
from analysis.audit.grabber_audit import audit
from analysis.audit.grabber_audit import from_item as _from_item
from analysis.audit.grabber_audit import single_cause as _single
from analysis.audit.grabber_causes_stl import paper_runs
from analysis.audit.schema import Cause, Manifestation, Register
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.audit.table4 import summary
from analysis.kinematics.arm import paper_arm
from analysis.papers import grabber as paper

__all__ = ["paper_runs", "register"]


# ---------------------------------------------------------------------------------------------
# the derivation (items of the audit grouped by cause)
# ---------------------------------------------------------------------------------------------
def _atan() -> Cause:
    ms = [
        _from_item("grabber-atan", "phi", "paper-eq6-phi"),
        _from_item("grabber-atan", "eq6", "paper-eq6"),
        _from_item("grabber-atan", "eq18", "paper-eq18"),
        _from_item("grabber-atan", "eq19", "paper-eq19"),
        _from_item("grabber-atan", "figure-4", "paper-fig4-quadrant"),
        _from_item("grabber-atan", "figure-5", "paper-fig5-atan"),
        _from_item("grabber-atan", "table4-r1", "paper-table4-r1-theta2"),
        _from_item("grabber-atan", "table4-r2", "paper-table4-r2-theta2"),
        _from_item("grabber-atan", "table4-r4", "paper-table4-r4-theta2"),
    ]

    def demo() -> bool:
        # quadrant II: tan^-1(Py/Px) points the waist 180 deg away; Table 4 rows 1, 2, 4
        # print theta2 + 180 deg, which puts the gripper hundreds of mm off
        p = np.array([-100.0, 100.0, 600.0])
        waist = np.arctan(p[1] / p[0])
        s = summary().set_index("row")
        return (
            abs(np.degrees(waist - paper_arm().ik(p)[0]) % 360 - 180) < 1e-9
            and (s.loc[[2, 4], "fk_error_mm"] > 400).all()
            and _all_fail(ms)
        )

    return _cause(
        "grabber-atan",
        "A single-argument arctangent tan^-1(y/x) stands where the angle's quadrant matters "
        "(theta1 in eq. 6, theta2 + theta3 in eq. 18).",
        "error",
        "branch/quadrant",
        "tan^-1 returns (-90, 90) deg: a target with Px < 0 gets the waist turned 180 deg the "
        "wrong way, and eq. 18's denominator is negative on the paper's own branch, so "
        "theta2 comes out 180 deg off, as Table 4 prints it in rows 1, 2 and 4. atan2 fixes "
        "all of them.",
        ms,
        demo,
    )


def _acos() -> Cause:
    return _cause(
        "grabber-acos-branch",
        "eq. 10 takes +acos (elbow down, theta3 > 0) while the paper's solution (Table 4) is "
        "elbow up, theta3 < 0.",
        "error",
        "branch/quadrant",
        "acos returns [0, 180] deg; the paper never states the sign choice it uses.",
        [
            _from_item("grabber-acos-branch", "eq10", "paper-eq10"),
            _from_item("grabber-acos-branch", "figure-6", "paper-fig6-branch"),
        ],
    )


def _eq12_ones() -> Cause:
    return _cause(
        "grabber-eq12-ones",
        "eq. 12: the third columns of both matrices carry their 1s in the wrong rows.",
        "error",
        "transcription",
        "The left matrix's row 3 is printed [s1, -c1, 1, 0] (A3^-1 A2^-1 A1^-1 has 0 there) "
        "and the right-hand side, which eq. 11 calls E, is printed with rows 2 and 3 of its "
        "third column swapped. One misplaced 1 in typesetting (or in the extraction: "
        "undecidable from the text) accounts for all three.",
        [
            _from_item("grabber-eq12-ones", "lhs-r3c3", "paper-eq12-r3c3"),
            _from_item("grabber-eq12-ones", "rhs-r2c3", "paper-eq12-rhs-r2c3"),
            _from_item("grabber-eq12-ones", "rhs-r3c3", "paper-eq12-rhs-r3c3"),
        ],
    )


def _derivation_errors() -> list[Cause]:
    """eqs. 2-14: the missing terms, signs, index and transcription slips of the derivation."""
    return [
        _single(
            "grabber-eq2-ax",
            "eq. 2 prints a_x = 0; A1 A2 A3 gives a_x = sin(theta1).",
            "error",
            "missing term",
            "The approach vector must be a unit vector orthogonal to n and o.",
            "ax",
            "paper-T3-r1c3",
        ),
        _single(
            "grabber-eq3-translation",
            "eq. 3 subtracts L1 from the z components of the direction vectors n, o, a.",
            "error",
            "missing term",
            "Only the position (homogeneous w = 1) is translated by A1^-1; n, o, a have w = 0.",
            "f12",
            "paper-eq3-f12-noa",
        ),
        _single(
            "grabber-eq5-sign",
            "eq. 5 prints sin(theta1) Px + cos(theta1) Py = 0; f13(P) is sin(theta1) Px - "
            "cos(theta1) Py.",
            "error",
            "sign",
            "The text after eq. 5 (sin(theta1 - phi) = 0) follows from the correct sign.",
            "eq5",
            "paper-eq5",
        ),
        _single(
            "grabber-eq12-sign",
            "eq. 12 row 2 col 2 lost its minus sign.",
            "error",
            "sign",
            "(A3^-1 A2^-1 A1^-1)[2,2] = -sin(theta1) sin(theta2 + theta3).",
            "r2c2",
            "paper-eq12-r2c2",
        ),
        _eq12_ones(),
        _single(
            "grabber-eq13-index",
            "eq. 13 ends in -L2 where the matrix gives -L3.",
            "error",
            "index",
            "Row 1 col 4 of eq. 12 is -L1 sin(theta23) - L2 cos(theta3) - L3.",
            "eq13",
            "paper-eq13",
        ),
        _single(
            "grabber-eq14-term",
            "eq. 14's Py term is sin(theta1) cos(theta23) Py; the product gives -sin(theta1) "
            "sin(theta23) Py.",
            "error",
            "transcription",
            "Row 2 of eq. 12 times P; eqs. 15-16, which the paper solves from eqs. 13-14, "
            "hold only with the correct term.",
            "eq14",
            "paper-eq14",
        ),
    ]


def _labels_and_notation() -> list[Cause]:
    """eqs. 4, 6, 10 and Table 4 row 9: a label, a cross-reference, notation, a table cell."""
    return [
        _single(
            "grabber-eq4-label",
            "The matrix of eq. 4 is labelled A_3 A_3; it is A_2 A_3.",
            "error",
            "label",
            "Entry by entry equal to A2 A3.",
            "label",
            "paper-eq4-label",
        ),
        _single(
            "grabber-eq6-xref",
            "The text before eq. 6 refers to eq. (16) for theta1; it means eq. (6).",
            "error",
            "cross-reference",
            "eq. 16 defines sin(theta2 + theta3).",
            "xref",
            "paper-eq6-xref",
        ),
        _single(
            "grabber-eq10-pz",
            "eq. 10 writes p_z where eqs. 7-9 write Pz: the same quantity.",
            "notation",
            "notation",
            "Eq. 3 itself names the columns with lower-case i = n, o, a, p: notation, not an "
            "error (and possibly the extraction's).",
            "pz",
            "paper-eq10-pz",
        ),
        _single(
            "grabber-table4-r9",
            "Table 4 row 9 prints theta3 = -91.20; the target gives -91.16 (as row 6, whose "
            "target has the same distance from the shoulder).",
            "error",
            "transcription",
            "No evaluation tried (rounding, truncation, float32, the printed formulas) "
            "reproduces -91.20; the printed angles miss the target by 0.15 mm.",
            "theta3",
            "paper-table4-r9-theta3",
        ),
    ]


def _derivation() -> list[Cause]:
    """The derivation's other causes (eqs. 2-14, Table 4 row 9), in the register's order."""
    return [*_derivation_errors(), *_labels_and_notation()]


# ---------------------------------------------------------------------------------------------
# the implementation of section 2 against Table 2 and the CPU 224
# ---------------------------------------------------------------------------------------------
def _listings() -> str:
    return "\n".join(paper.FIGURE_STL[f] for f in (3, 4, 5, 6))


def _generated() -> str:
    from analysis.plc.generate import generate

    return generate("s7-200")[0]


def _impl(cid, title, kind, evidence, location, printed, corrected, needle) -> Cause:
    """An implementation gap: ``needle(text)`` is True where a listing does the step."""
    m = Manifestation(f"{cid}/listing", location, printed, corrected, evidence, needle)

    def demo() -> bool:
        return not needle(_listings()) and needle(_generated()) and _all_fail([m])

    return _cause(cid, title, "omission", kind, evidence, [m], demo)


def _implementation() -> list[Cause]:
    io = {code: addr for _, code, addr in paper.TABLE2["inputs"]}
    return [
        _impl(
            "grabber-impl-start",
            "Nothing starts the computation or the motion: SB1 (I0.0, Table 2) appears in no "
            "listing; every network runs on '上电置1' in every scan.",
            "implementation",
            f"Section 2.1 says pressing SB1 ({io['SB1']}) starts the program; Figures 3-6 "
            "never read it, so a target typed in mid-move would be re-solved at once.",
            "Figures 3-6, sec. 2.1",
            "LD 上电置1 (every network)",
            "LD I0.0; EU; A V112.0 (SB1 rising edge, reach flag on)",
            lambda t: "I0.0" in t and "EU" in t,
        ),
        _impl(
            "grabber-impl-pulses",
            "The pulse counts never reach a motor: no PLS and no PTO set-up, and the CPU 224 "
            "has two PTO outputs (Q0.0, Q0.1) for three steppers.",
            "implementation",
            "Table 2 lists two pulse outputs and the relays KM1/KM2 (Q0.3/Q0.4): one channel "
            "must be switched between two drivers, a sequence the paper neither describes "
            "nor lists.",
            "Figures 3-6, Table 2, sec. 2.3",
            "ROUND VD16, VD16 (count computed, never output)",
            "MOVD |c|, SMD72; PLS 0 (and KM1/KM2 switching PTO1 between shoulder and elbow)",
            lambda t: "PLS" in t and "SMD72" in t,
        ),
        _impl(
            "grabber-impl-direction",
            "Counts are signed (c3 = -1724 for Table 4 row 1) but a PTO count is unsigned: the "
            "listings set no direction output (Q0.2, Q0.5, Q0.7).",
            "implementation",
            "The S7-200 PTO pulse count SMD72/SMD82 takes 1 .. 4,294,967,295; the sign must "
            "go to the driver's direction input, which Table 2 provides and no network sets.",
            "Figures 3-6, Table 2",
            "ROUND VD52, VD52 (c3 may be negative; no direction bit)",
            "LDD>= d, 0; = Q0.2 / Q0.5 / Q0.7 (direction from the sign); |d| to the PTO",
            lambda t: "Q0.7" in t and "Q0.2" in t,
        ),
        _impl(
            "grabber-impl-absolute",
            "The counts are absolute joint angles, a PTO makes relative moves, and no home "
            "position is defined: the listings never subtract where the arm is.",
            "implementation",
            "c = theta/360 x 4000 is the angle from the D-H zero (arm stretched horizontally); "
            "the move is c minus the current count, which needs a reference (homing) the paper "
            "never mentions.",
            "Figures 3-6, sec. 2.4",
            "c = theta / 360 x 4000 (absolute)",
            "d = c - position; position := c after the move (homing defines position 0)",
            # the move subtracts the position: '-D VD124, AC1' in STL, 'c - position' in words
            lambda t: re.search(r"-D\s+VD12[48]|c - position", t) is not None,
        ),
    ]


# ---------------------------------------------------------------------------------------------
# the claims about the results
# ---------------------------------------------------------------------------------------------
def _claims() -> list[Cause]:
    from analysis.studies.quantization import quantization_map, worst_case_box

    claims = paper.CLAIMS
    arm = paper_arm()
    rng = np.random.default_rng(2016)
    p = arm.shoulder + rng.uniform(-1, 1, (200_000, 3)) * arm.params.reach_outer
    err, _, ok = quantization_map(arm, p)
    worst = float(np.nanmax(err[ok]))
    q_stretched = np.array([[0.0, 0.0, 0.0]])
    bound = float(worst_case_box(arm, q_stretched, np.pi / np.array(arm.params.pulses_per_rev))
                  .exact_mm[0])  # fmt: skip
    accuracy = Manifestation(
        "grabber-claim-accuracy/claim",
        claims["accuracy"]["location"],
        "accuracy 0.09 deg per joint",
        f"resolution 0.09 deg per pulse (360/4000); rounding alone moves the gripper up to "
        f"{worst:.2f} mm (bound {bound:.2f} mm at full reach); accuracy not measured",
        f"0.09 deg = 360/4000 is the size of one pulse, a resolution. Rounding each joint to "
        f"whole pulses (eqs. 20-22) already puts the gripper up to {worst:.3f} mm off over "
        f"200,000 targets (worst case {bound:.3f} mm, arm stretched); backlash, missed steps "
        f"and link tolerances come on top, and the paper measures none of them.",
        lambda t: "resolution" in t and "mm" in t,
    )
    s = summary().set_index("row")
    miss = s.loc[[1, 2, 4], "fk_error_mm"]
    measured = Manifestation(
        "grabber-claim-table4/claim",
        claims["table4_measured"]["location"],
        "Table 4: actual navigation parameters after actual operation",
        "Table 4: angles computed from the formulas as printed (not measured)",
        f"Rows 1, 2 and 4 print theta2 180 deg off (eq. 18's single-argument tan^-1): driven "
        f"to, they put the gripper {miss.min():.0f}-{miss.max():.0f} mm from the target, "
        f"which an operated arm would have shown; row 8 prints theta1 = 68.2 deg for a "
        f"target out of reach, a computed number.",
        lambda t: "computed" in t,
    )
    efficient = Manifestation(
        "grabber-claim-efficiency/claim",
        claims["efficient_stable"]["location"],
        "efficient, stable, fast (高效性和稳定性, 响应速度快)",
        "no cycle time, repeatability or error is reported: unsupported",
        "The paper reports no time, no repeated measurement and no position error for any "
        "run; the only numbers of the experiment (Table 4) are computed angles.",
        lambda t: "unsupported" in t,
    )
    return [
        _cause(
            "grabber-claim-accuracy",
            "The paper calls the pulse resolution (0.09 deg) the navigation accuracy.",
            "error",
            "claim",
            "Resolution bounds what can be commanded, not where the gripper ends up.",
            [accuracy],
            lambda: worst > 0.5 and _all_fail([accuracy]),
        ),
        _cause(
            "grabber-claim-table4",
            "Table 4 is presented as measured 'after actual operation'; its errors show it "
            "was computed.",
            "error",
            "claim",
            "See grabber-atan for the cause of the 180 deg cells.",
            [measured],
            lambda: (miss > 300).all() and _all_fail([measured]),
        ),
        _cause(
            "grabber-claim-efficiency",
            "'Efficient, stable, fast' is claimed without a measurement.",
            "unsupported",
            "claim",
            "A verdict needs cycle times and repeated positioning errors.",
            [efficient],
            lambda: claims["efficient_stable"]["measurements"] == () and _all_fail([efficient]),
        ),
    ]


@cache
def register() -> Register:
    """Seed 000's register (takes seconds: the item audit and the executed listings)."""
    causes = [
        _atan(),
        _acos(),
        *_derivation(),
        *grabber_causes_stl.causes(),
        *_implementation(),
        *_claims(),
    ]
    reg = Register(
        "grabber",
        "Li Feng et al., Food & Machinery 2016 (seed 000): 3R material-grabbing robot",
        tuple(causes),
    )
    used = [m.source for c in reg.causes for m in c.manifestations if m.source]
    wrong = {it.id for it in audit() if it.verdict == "wrong"}
    if sorted(used) != sorted(wrong):
        raise RuntimeError(
            f"wrong audit items not in exactly one cause: missing {sorted(wrong - set(used))}, "
            f"repeated {sorted({u for u in used if used.count(u) > 1})}"
        )
    return reg

"""Seed 000's register, the STL: the paper's listings (Figures 3-6) executed byte-accurately
on the Table 4 targets (:func:`paper_runs`; awlsim agrees: tests/plc/test_plc_awlsim.py), the
overlapping operands of Figure 5, and the causes found in the listings; :func:`causes` in the
register's order (:mod:`analysis.audit.grabber_causes`)."""

from __future__ import annotations

import re
from functools import cache

import numpy as np

from analysis.audit.grabber_audit import from_item as _from_item
from analysis.audit.grabber_audit import single_cause as _single
from analysis.audit.grabber_stl import figure5_c2, figure5_repaired
from analysis.audit.schema import Cause, Manifestation
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.audit.table4 import load_printed
from analysis.kinematics.arm import paper_arm
from analysis.kinematics.pulses import angles_to_pulses
from analysis.papers import grabber as paper
from analysis.plc import stl_eval as stl
from analysis.plc.paper_listings import figure_text


# ---------------------------------------------------------------------------------------------
# executed listings (byte-accurate evaluator; awlsim agrees: tests/plc/test_plc_awlsim.py)
# ---------------------------------------------------------------------------------------------
@cache
def paper_runs() -> dict:
    """The paper's Figures 3-4 run on every Table 4 target, with IEEE denormals and with
    flush-to-zero REAL arithmetic, and Figure 5 (repaired) with and without its overlap."""
    p = load_printed()[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    ieee, ftz = [], []
    for t in p:
        run = stl.parse_stl(figure_text(3, t) + "\n" + figure_text(4, t))
        ieee.append(stl.evaluate(run).dint("VD16"))
        ftz.append(stl.evaluate(run, ftz=True).dint("VD16"))
    arm = paper_arm()
    ok = arm.solve(p, "front-up").ok[:, 0]
    good = np.where(ok[:, None], arm.solve(p, "front-up").theta[:, 0], 0.0)
    c_ok = np.where(ok[:, None], angles_to_pulses(good), 0)
    fig5 = figure5_repaired()
    separate = fig5.replace("VD106", "VD300")
    q1 = arm.ik(p[0])
    return {
        "targets": p,
        "c1_ieee": ieee,
        "c1_ftz": ftz,
        "c1_correct": c_ok[:, 0].tolist(),
        "reachable": ok.tolist(),
        "fig5_c2_overlap": figure5_c2(fig5, p[0], q1),
        "fig5_c2_separate": figure5_c2(separate, p[0], q1),
        "fig5_c2_correct": int(c_ok[0, 1]),
    }


def _executed_fig34() -> Cause:
    runs = paper_runs()
    ieee, ftz, good = runs["c1_ieee"], runs["c1_ftz"], runs["c1_correct"]
    fig3 = _from_item("grabber-int-inputs", "figure-3", "paper-fig3-movd")

    def v_counts(text: str) -> bool:
        nums = [int(v) for v in re.findall(r"-?\d+", text.split("=", 1)[-1])]
        want = [g for g, r in zip(good, runs["reachable"], strict=True) if r]
        return nums[: len(want)] == want

    executed = Manifestation(
        "grabber-int-inputs/executed",
        "Figures 3-4 executed (Table 4 rows 1-10; reachable rows)",
        "c1 = " + ", ".join(str(v) for v, r in zip(ieee, runs["reachable"], strict=True) if r),
        "c1 = " + ", ".join(str(v) for v, r in zip(good, runs["reachable"], strict=True) if r),
        "Run byte-accurately (IEEE single precision with denormals, as awlsim does): MOVD 100 "
        "stores 1.4e-43, so Py/Px is 1 (row 1) and c1 = ROUND(atan(1) [rad] / 360 * 4000) = 9. "
        "With flush-to-zero arithmetic the denormal inputs read as 0: /R of 0 by 0 is a "
        "division by zero, which sets SM1.3 and leaves VD12 (S7-200 System Manual, math "
        "instructions), ARCTAN of the flushed VD12 is 0, and c1 = "
        + ", ".join(sorted({str(v) for v in ftz}))
        + " for every row. Which one a real S7-200 gives is not settled by its manuals "
        "(denormals are outside the documented REAL range; CPU handling unconfirmed).",
        v_counts,
    )
    return _cause(
        "grabber-int-inputs",
        "Figure 3 writes the target with MOVD (a DINT's bits) into the REAL inputs the other "
        "figures read.",
        "error",
        "PLC semantics",
        "Every REAL computation downstream reads denormals instead of millimetres; the "
        "executed result depends on how the CPU treats denormals.",
        [fig3, executed],
        lambda: _all_fail([fig3, executed]) and ieee[0] == 9 and ieee != good,
    )


def _overlap() -> Cause:
    runs = paper_runs()
    pairs = stl.overlaps(stl.parse_stl(paper.FIGURE_STL[5]))

    def v_overlap(text: str) -> bool:
        addr = re.findall(r"VD\d+", text)
        if not addr:
            return False
        fig5 = figure5_repaired().replace("VD106", addr[0])
        prog = stl.parse_stl(fig5)
        return not stl.overlaps(prog) and figure5_c2(fig5, *_row1()) == runs["fig5_c2_separate"]

    m = Manifestation(
        "grabber-overlap/figure-5",
        "Figure 5",
        "VD106 (MOVR VD72, VD106; *R VD92, VD106) while VD104 holds k r",
        "VD300 (any double word that shares no byte with VD104)",
        f"VD104 is bytes 104-107 and VD106 bytes 106-109: {len(pairs)} overlapping pair(s) "
        f"{[(a, b) for a, b, _ in pairs]}. Writing VD106 replaces the two low-order bytes of "
        f"VD104 (16 of its 23 mantissa bits) before 'MOVR VD104, VD110' reads it; run "
        f"byte-accurately on Table 4 row 1 (Figure 5 repaired otherwise, single-argument "
        f"ARCTAN kept) c2 = {runs['fig5_c2_overlap']} instead of {runs['fig5_c2_separate']} "
        f"with separate addresses. In every reading of the interleaved columns the two "
        f"double words are live at once, so one of them is corrupted.",
        v_overlap,
    )
    return _cause(
        "grabber-overlap",
        "Figure 5 stores two quantities in double words that share bytes (VD104, VD106).",
        "error",
        "PLC semantics",
        "A name-keyed evaluation cannot see it; V memory is bytes.",
        [m],
        lambda: bool(pairs) and runs["fig5_c2_overlap"] != runs["fig5_c2_separate"],
    )


def _row1():
    p = load_printed()[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()[0]
    return p, paper_arm().ik(p)


# ---------------------------------------------------------------------------------------------
# the STL (Figures 3-6)
# ---------------------------------------------------------------------------------------------
def _stl_unit() -> Cause:
    """Figures 4-6 scale radians as degrees (eqs. 20-22)."""
    return _cause(
        "grabber-stl-degrees",
        "The listings turn joint angles into pulses as if ARCTAN/ARCCOS returned degrees: "
        "/360 x 4000 with no 180/pi.",
        "error",
        "unit",
        "Eqs. 20-22 take degrees; the S7-200 library's ARCTAN/ARCCOS (and its SIN/COS, which "
        "Figure 5 feeds with the same VD12) work in radians, so every count is 57.3 times "
        "too small.",
        [
            _from_item("grabber-stl-degrees", "figure-4", "paper-fig4-unit"),
            _from_item("grabber-stl-degrees", "figure-5", "paper-fig5-unit"),
            _from_item("grabber-stl-degrees", "figure-6", "paper-fig6-unit"),
        ],
    )


def _stl_semantics() -> tuple[Cause, Cause, Cause]:
    """Figure 4's in-place division of VD12, the missing reach check, the missing ARCTAN and
    ARCCOS subroutines."""
    vd12 = _single(
        "grabber-stl-vd12",
        "Figure 4 divides VD12 in place ('/R 360.0, VD12'), then Figures 5-6 read VD12 as theta1.",
        "error",
        "PLC semantics",
        "In-place S7-200 arithmetic (OUT := OUT op IN1) overwrites theta1 with theta1/360.",
        "figure-4",
        "paper-fig4-vd12",
    )
    reach = _single(
        "grabber-stl-reach",
        "No reach check: ARCCOS gets arguments beyond +-1 (Table 4 row 8, printed 无解) and "
        "nothing stops the motion.",
        "omission",
        "PLC semantics",
        "The paper knows the case (Table 4 row 8) but the listing has no branch for it.",
        "figures-5-6",
        "paper-stl-reach",
    )
    subs = _cause(
        "grabber-stl-subroutines",
        "ARCTAN and ARCCOS are called but never given; the S7-200 has no inverse "
        "trigonometric instruction.",
        "omission",
        "PLC semantics",
        "The generated ATAN2/ACOS subroutines (analysis.plc) fill the gap.",
        [
            Manifestation(
                "grabber-stl-subroutines/figures-4-6",
                "Figures 4-6 (CALL ARCTAN, CALL ARCCOS)",
                "CALL ARCTAN; CALL ARCCOS (no subroutine listed)",
                "SUBROUTINE_BLOCK ATAN2:SBR1; SUBROUTINE_BLOCK ACOS:SBR2 (generated)",
                "The listings of Figures 4-6 call two subroutines that the paper never prints.",
                lambda t: "SUBROUTINE_BLOCK" in t,
            )
        ],
        lambda: not any("SUBROUTINE" in f for f in paper.FIGURE_STL.values()),
    )
    return vd12, reach, subs


def _stl_uncertain() -> list[Cause]:
    """Readings of Figures 5-6 that the extraction leaves open."""
    return [
        _single(
            "grabber-fig5-order",
            "Figure 5 (theta2) reads VD48 before Figure 6 (theta3) writes it, if the figures "
            "run in the order printed.",
            "uncertain",
            "PLC semantics",
            "The paper does not say in which order the networks run; printed order is a "
            "presentation order as much as an execution order.",
            "order",
            "paper-fig5-order",
        ),
        _single(
            "grabber-fig5-vd68",
            "In the column order reconstructed for Figure 5, VD68 is overwritten before VD92 "
            "reads it.",
            "uncertain",
            "PLC semantics",
            "Depends on how the three interleaved printed columns are put back together.",
            "vd68",
            "paper-fig5-vd68",
        ),
        _single(
            "grabber-fig6-vdd0",
            "Figure 6 uses the operand VDD0, which is no S7-200 address.",
            "uncertain",
            "PLC semantics",
            "A typo for VD0 (Px) or for VD12 (theta1): the extraction cannot decide, and one "
            "operand cannot be both.",
            "vdd0",
            "paper-fig6-vdd0",
        ),
        _single(
            "grabber-fig6-2l2l3",
            "Figure 6's constants (as reconstructed) form 2 L2 L2 where eq. 10 needs 2 L2 L3.",
            "uncertain",
            "transcription",
            "Depends on the reconstruction of five interleaved columns.",
            "constants",
            "paper-fig6-2l2l3",
        ),
    ]


def _stl() -> list[Cause]:
    """The causes of Figures 3-6, in the register's order."""
    vd12, reach, subs = _stl_semantics()
    return [_executed_fig34(), _stl_unit(), vd12, _overlap(), reach, subs, *_stl_uncertain()]


def causes() -> list[Cause]:
    """The causes of Figures 3-6, in the register's order."""
    return _stl()

"""Seed 004's register, part 3: the FX2N program (Table 2-3's presets, the missing write,
the sequential on/off move against the planned cubic), the cubic's acceleration and the
work area. Built into the register by :func:`analysis.audit.gr1_causes.register`."""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np
import sympy as sp

from analysis.audit.gr1_checks import numbers as _numbers
from analysis.audit.schema import Cause, Manifestation
from analysis.audit.schema import all_fail as _all_fail
from analysis.audit.schema import make_cause as _cause
from analysis.papers import gr1_thesis as paper
from analysis.studies import gr1 as study

_arm = study.gr1_arm

__all__ = ["causes"]


# ---------------------------------------------------------------------------------------------
# the PLC: Table 2-3, the ladder, the move
# ---------------------------------------------------------------------------------------------
def _presets() -> Cause:
    df = study.printed_presets().set_index("counter")
    ms = []
    for c in ("C236", "C237", "C238", "C239"):
        row = df.loc[c]
        want = int(row.as_pulses)
        ms.append(
            Manifestation(
                f"gr1-presets/{c.lower()}",
                paper.TABLE2_3["location"],
                f"{c} {int(row.printed)}",
                f"{c} {want}",
                f"|Δθ| = {row.delta_deg:.3f} deg between the printed Table 5-4 rows; at Table "
                f"2-1's {study.RESOLUTION_DEG[int(c[-1]) - 5]:g} deg per pulse that is "
                f"{row.delta_deg / study.RESOLUTION_DEG[int(c[-1]) - 5]:.2f} pulses. The "
                f"printed value is the degree change rounded"
                + (" down (rounding gives 119)" if c == "C237" else "")
                + ".",
                (lambda w: lambda t: _numbers(t[4:]) == [w])(want),
            )
        )
    ok235 = int(df.loc["C235"].printed) == int(df.loc["C235"].as_pulses)
    return _cause(
        "gr1-presets",
        "Table 2-3's presets for C236-C239 are the joint angle changes in degrees, not the "
        "pulse counts the text derives them as (angle change / Table 2-1's resolution).",
        "error",
        "unit",
        "C235 = 4 is right (0.518 deg / 0.14 deg per pulse = 3.7): the waist's change is "
        "under a degree. The counters count encoder pulses (sec. 2.3.2), so C236 = 147 "
        "would stop the upper arm after 16.2 deg instead of 146.9.",
        ms,
        lambda: ok235 and _all_fail(ms),
    )


def _corrected_move():
    arm = _arm()
    proj, _ = study.project_orientation(arm, study.thesis_poses())
    q, names = study.first_within_limits(arm, proj)
    return arm, q, names


def _plc_write() -> Cause:
    _, q, names = _corrected_move()
    table = study.counter_presets(q[0], q[1])
    want = table["preset"].tolist()
    ladder = paper.LADDER["recoverable"]["counters"]
    m = Manifestation(
        "gr1-plc-write/ladder",
        paper.LADDER["location"],
        ", ".join(f"{c} {k}" for c, k in ladder.items()),
        ", ".join(f"{c} K{k}" for c, k in zip(table["counter"], want, strict=True)),
        "The ladder's counter constants are K1 .. K5 (placeholders), and the handler of the "
        "写入 PLC button that sec. 6.4 says writes the presets is not in the listing "
        "(neither is 输出). The correction is what the corrected joint values need "
        f"(start {names[0]}, end {names[1]}, orientations projected; "
        "analysis.studies.gr1.counter_presets), with the direction each needs: "
        + ", ".join(f"{c} {d}" for c, d in zip(table["counter"], table["direction"], strict=True))
        + ".",
        lambda t: [int(v) for v in re.findall(r"K(\d+)", t)] == want,
    )
    return _cause(
        "gr1-plc-write",
        "Nothing puts the presets into the PLC: the ladder counts to K1 .. K5, and the button "
        "that would write them has no code.",
        "omission",
        "implementation",
        "Sec. 2.3.4 and 6.4 describe the path (Table 5-4 -> Table 2-3 -> 写入 PLC -> C235 .. "
        "C239); the listing and the ladder stop short of it.",
        [m],
    )


@cache
def _fx2n() -> dict:
    arm, q, _ = _corrected_move()
    return study.fx2n_vs_cubic(arm, q[0], q[1])


def _schedule_deviation(text: str) -> float:
    """Largest distance [mm] of the hand from the planned (cubic) path when the joints move
    as ``text`` says: 'M1 -> M2 ...' one after another on/off, 'M1 + M2 ...' together on
    the cubic; inf if the text names no schedule of the five motors."""
    r = _fx2n()
    motors = re.findall(r"M(\d)", text)
    if sorted(motors) != ["1", "2", "3", "4", "5"]:
        return math.inf
    if "->" in text:
        return r["max_apart_mm"]
    if "+" in text:
        return float(study.nearest_point_distance(r["p_cubic"], r["p_cubic"]).max())
    return math.inf


def _fx2n_vs_cubic() -> Cause:
    r = _fx2n()
    claim = paper.TEXT_CLAIMS["c2.3.4-sequential"]
    m = Manifestation(
        "gr1-fx2n-vs-cubic/sequence",
        claim["location"] + "; the ladder",
        "M1 -> M2 -> M3 -> M4 -> M5: each motor on at full speed until its counter is full",
        "M1 + M2 + M3 + M4 + M5 together, each joint on its cubic (eqs. 5.3-5.7), T = 10 s",
        f"Modelled for the corrected Table 5-3 move at the printed no-load speed (3000 r/min, "
        f"12 encoder counts per motor turn: {', '.join(f'{v:g}' for v in r['speed_deg_s'])} "
        f"deg/s): the PLC's move takes {r['time_fx2n_s']:.2f} s instead of the planned "
        f"{r['time_cubic_s']:g} s, its hand path is {r['length_fx2n_mm']:.0f} mm long instead "
        f"of {r['length_cubic_mm']:.0f} mm and passes up to {r['max_apart_mm']:.0f} mm from "
        f"the planned one; speed and acceleration are steps, not the cubic's profile.",
        lambda t: _schedule_deviation(t) <= 1.0,
    )
    return _cause(
        "gr1-fx2n-vs-cubic",
        "The FX2N program never executes the planned cubic trajectories: it runs the motors "
        "one after another, on/off, until each counter is full.",
        "error",
        "implementation",
        "Chapter 5 plans coordinated, smooth joint motion; section 2.3.4 and the ladder "
        "implement a point-to-point sequence with on/off motors, which the cubic's timing "
        "never reaches.",
        [m],
        lambda: r["max_apart_mm"] > 50 and _all_fail([m]),
    )


def _cubic_acc() -> Cause:
    s = paper.CUBIC_SYMBOLS
    t, T, th0, thf = s["t"], s["t_f"], s["theta_0"], s["theta_f"]

    def smooth(text: str) -> bool:
        """theta(t) in the text: the four conditions 5.1-5.2 and zero end accelerations."""
        rhs = text.split("=", 1)[-1]
        try:
            f = paper.parse(rhs, "cubic")
        except ValueError:
            return False
        d1, d2 = sp.diff(f, t), sp.diff(f, t, 2)
        conds = [f.subs(t, 0) - th0, f.subs(t, T) - thf, d1.subs(t, 0), d1.subs(t, T),
                 d2.subs(t, 0), d2.subs(t, T)]  # fmt: skip
        return all(sp.simplify(c) == 0 for c in conds)

    printed = paper.CUBIC["listing_form"]["reading"].split("=", 1)[1].strip()
    _, q, _ = _corrected_move()
    from analysis.studies.trajectories import acceleration_jumps

    jumps = np.degrees(acceleration_jumps("cubic", q[0], q[1], study.DURATION_S))
    claim = paper.TEXT_CLAIMS["c5.4.2-acc"]
    m = Manifestation(
        "gr1-cubic-acc/claim",
        claim["location"] + "; the listing's cubic (Command3_Click)",
        f"theta(t) = {printed}",
        "theta(t) = theta_0 + (theta_f - theta_0)*(10*(t/t_f)**3 - 15*(t/t_f)**4 + 6*(t/t_f)**5)",
        "The cubic with zero end velocities has theta''(0) = 6 (theta_f - theta_0) / t_f^2 and "
        "theta''(t_f) = -6 (theta_f - theta_0) / t_f^2: the acceleration steps from 0 to that "
        "when the move starts and back when it stops, the jump the text says it avoids. For "
        "the corrected Table 5-3 move (10 s): "
        + ", ".join(f"{v:.2f}" for v in jumps)
        + " deg/s^2 per joint. A quintic (zero end accelerations too) meets the claim.",
        smooth,
    )
    return _cause(
        "gr1-cubic-acc",
        "Section 5.4.2 chooses the cubic so that the acceleration does not jump; the cubic's "
        "acceleration jumps at both ends.",
        "error",
        "claim",
        "Four conditions (eqs. 5.1-5.2) fix position and velocity only.",
        [m],
        lambda: (jumps[1:] > 1.0).all() and _all_fail([m]),
    )


def _work_area() -> Cause:
    ext = study.workspace_extents()
    free = study.workspace_extents(limits=False)

    def matches(text: str) -> bool:
        v = re.search(r"vertical\D*?(\d+(?:\.\d+)?)", text)
        h = re.search(r"horizontal\D*?(\d+(?:\.\d+)?)", text)
        if not (v and h):
            return False
        vert, hor = float(v.group(1)), float(h.group(1))
        heights = (ext["height_span_mm"], ext["z_max_mm"])  # a span, or above the shoulder
        widths = (ext["radius_mm"], ext["width_span_mm"])  # a radius, or a span
        return min(abs(vert - x) for x in heights) <= 1 and min(abs(hor - x) for x in widths) <= 1

    wa = paper.ARM["work_area"]
    m = Manifestation(
        "gr1-work-area/sec-2-1",
        wa["location"],
        f"vertical {wa['vertical_mm']} mm, horizontal {wa['horizontal_mm']} mm",
        f"vertical {ext['height_span_mm']:g} mm (span, {ext['z_min_mm']:g} .. "
        f"{ext['z_max_mm']:g} mm about the shoulder), horizontal {ext['radius_mm']:g} mm "
        f"(radius from the base axis)",
        f"The printed links reach {ext['reach_mm']:g} mm (a2 + a3 + a4) from the shoulder: "
        f"a radius of {ext['radius_mm']:g} mm and a height span of {ext['height_span_mm']:g} mm, "
        f"with the assumed limits and without ({free['radius_mm']:g}, "
        f"{free['height_span_mm']:g}). 600 mm read as a radius needs 71 mm more (fingers "
        f"are not dimensioned); 850 mm as a span is 208 mm short, as a height above a base "
        f"needs a base height the thesis does not print. No reading of either number follows "
        f"from section 2.1 d.",
        matches,
    )
    return _cause(
        "gr1-work-area",
        "The work area (850 mm vertically, 600 mm horizontally) follows from no printed "
        "dimension of the arm.",
        "unsupported",
        "claim",
        "analysis.studies.gr1.workspace_extents sweeps the chain within the limits.",
        [m],
    )


def causes() -> list[Cause]:
    """Table 2-3, the ladder, the move, the cubic, the work area."""
    return [_presets(), _fx2n_vs_cubic(), _cubic_acc(), _plc_write(), _work_area()]

"""Seed 002 (Yang, Li, Gao 2016, the 2P4R picker): runs of the reconstructed mechanism
(:mod:`analysis.kinematics.picker`, every dimension ASSUMED but the printed two) for the register's
checks (``data/registers/picker.toml``) and notebook 12.

* :func:`reading_summary`: the sec. 4 joint laws under each reading of their units
  (:data:`analysis.kinematics.picker.READINGS`): largest joint turn, peak joint speed.
* :func:`mutation_errors`: how far (per axis, as the paper reports its error) the five
  sec. 4 configurations move when one element of the model is wrong: the size of model error
  the 10.4 mm comparison could not see.
* :func:`misalignment_for`: the rotation of the measuring instrument's axes (sec. 4 says
  "parallel to S") that alone produces a given per-axis error at the five configurations.
* :func:`planar_mobility`: Gruebler counts of the chains as section 3.2 lists them.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from analysis.kinematics import picker as pk
from analysis.papers import picker as paper

__all__ = ["PLAUSIBLE_READINGS", "misalignment_for", "mutation_errors", "planar_mobility",
           "reading_summary"]  # fmt: skip

PLAUSIBLE_READINGS = ("value, deg", "velocity, deg/s")
MAX_ERR = paper.EXPERIMENT["max_abs_error_mm"]
TIMES = tuple(paper.EXPERIMENT["times"])
"""The sampling times of the experiment (sec. 4) [s]."""


def reading_summary(t: npt.ArrayLike = paper.EXPERIMENT["times"]) -> dict[str, dict]:
    """Per reading: the largest |joint angle| [rad] and [turns], the peak joint speed at the
    last sample [rad/s] and [rpm], the slider travel [mm] at the last sample."""
    t = np.asarray(t, dtype=float)
    out = {}
    for name, spec in pk.READINGS.items():
        a = pk.law_active(t, name)
        angles = a[:, [0, 2, 3, 4]]
        # speed: the law itself for the velocity readings, its slope for the value readings
        scale = math.pi / 180 if spec["angle_unit"] == "deg" else 1.0
        coef = np.array([-5.0, 10.0, -10.0, -10.0]) * scale
        speed = np.abs(coef) * (t[-1] if spec["integrate"] else 1.0)
        out[name] = {
            "max_turn_rad": float(np.abs(angles).max()),
            "max_turns": float(np.abs(angles).max() / (2 * math.pi)),
            "peak_speed_rad_s": float(speed.max()),
            "peak_speed_rpm": float(speed.max() * 60 / (2 * math.pi)),
            "slider_travel_mm": (float(a[-1, 5]), float(a[-1, 1])),
            "units_printed": spec["units_printed"],
        }
    return out


def _per_axis(p1, p2) -> float:
    return float(np.nanmax(np.abs(np.asarray(p1) - np.asarray(p2))))


def mutation_errors(picker: pk.Picker, reading: str) -> dict[str, float]:
    """Largest per-axis deviation [mm] over the five sec. 4 configurations (one reading)
    between the reconstruction and the reconstruction with one thing wrong (inf: the wrong
    model cannot even assemble, which a test would notice)."""
    t = np.asarray(paper.EXPERIMENT["times"], dtype=float)
    a = pk.law_active(t, reading)
    ref = picker.position(a)
    out = {}

    def flipped(i):
        b = a.copy()
        b[:, i] = -b[:, i]
        return picker.position(b)

    out["theta8 sign flipped (roll about the jaw axis)"] = _per_axis(flipped(4), ref)
    out["theta7 sign flipped"] = _per_axis(flipped(3), ref)
    out["theta1 sign flipped (waist)"] = _per_axis(flipped(0), ref)
    for name, delta in (("f", 10.0), ("e_tool", 10.0), ("l_DF", 10.0), ("z_A", 10.0)):
        other = pk.Picker(picker.params.with_(**{name: picker.params[name] + delta}))
        out[f"{name} off by {delta:g} mm"] = _per_axis(other.position(a), ref)
    swapped = a.copy()
    swapped[:, [1, 5]] = a[:, [5, 1]]
    try:
        out["sliders x and z swapped"] = _per_axis(picker.position(swapped), ref)
    except pk.UnreachableSliders:  # the swapped laws leave link 5's reach: detectable
        out["sliders x and z swapped"] = math.inf
    return out


def rotate_about_z(p, centre, eps):
    c, s = math.cos(eps), math.sin(eps)
    d = p - centre
    return centre + np.stack(
        [c * d[..., 0] - s * d[..., 1], s * d[..., 0] + c * d[..., 1], d[..., 2]], -1
    )


def misalignment_for(picker: pk.Picker, reading: str, error_mm: float = MAX_ERR) -> float:
    """Rotation [rad] of the instrument frame S' about its Z axis (origin (1500, 0, 0) in S)
    that alone gives ``error_mm`` as the largest per-axis error at the five configurations."""
    t = np.asarray(paper.EXPERIMENT["times"], dtype=float)
    p = picker.position(pk.law_active(t, reading))
    centre = np.asarray(paper.EXPERIMENT["instrument_origin_in_S_mm"])
    lo, hi = 0.0, 0.5
    for _ in range(100):  # bisection on a monotone function of eps (small angles)
        mid = (lo + hi) / 2
        if _per_axis(rotate_about_z(p, centre, mid), p) < error_mm:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def planar_mobility(links: int, one_dof_joints: int) -> int:
    """Gruebler-Kutzbach count for a planar mechanism: 3 (n - 1) - 2 j1, n counting the
    frame (here the rotating seat, the waist joint set aside)."""
    return 3 * (links - 1) - 2 * one_dof_joints

"""Which family a D-H chain belongs to, and the decisions its description makes.

:func:`classify` reads the joint axes of the chain at q = 0 (:mod:`.chain`) and either
returns a :class:`Structure` (the family, the numbers the closed form is built from, and
the decisions of the description's ``[derive]`` table) or raises :class:`NotDerivable`
with the reason. The families (the only ones derived; everything else keeps its
hand-written closed form):

============  =====================================================================  =====
family        joints                                                                 input
============  =====================================================================  =====
``3R``        a waist (axis 1) and two parallel axes not parallel to it (2 || 3):    point
              seed 000's grabber with any D-H lengths, offsets and twists
``4R-kept``   a waist and three parallel axes (2 || 3 || 4), the tool holding one    point
              orientation about them (``keep``): seed 001's palletizer family
``5R``        a waist, three parallel axes and a wrist roll across them              pose
              (2 || 3 || 4, 5 not parallel to 2): seed 004's GR-1 family
============  =====================================================================  =====

Decisions the D-H table does not make (``[derive]`` in the description; all optional but
``keep``)::

    [derive]
    forward = [1, 0, 0]   # base direction at q = 0 that the "front" branches face
                          # (default: where the tool points from the waist axis at q = 0)
    elbow = "target"      # "target": "up" = the elbow above the shoulder-wrist line, seen
                          # with the target's azimuth to the right (seeds 000, 004); "arm":
                          # the bend of front-up on both waist branches (seed 001)
    keep = { tool_axis = "x", direction = [0, 0, -1] }
                          # 4R-kept: the tool axis ("x", "y", "z" or a vector of the tool
                          # frame) held along this base direction, given at theta1 = 0 (it
                          # turns with the waist): the palletizer's gripper x pointing down
    orientation_tol_deg = 0.0057  # 5R: largest accepted angle of the roll axis out of
                          # the set the arm can reach (default 1e-4 rad, as the GR-1)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from analysis.kinematics.dh import exact_cos_sin

__all__ = ["FAMILIES", "NotDerivable", "Structure", "check_decisions", "classify"]

FAMILIES = ("3R", "4R-kept", "5R")
PARALLEL_TOL = 1e-9
"""Largest sine of the angle between two axes that counts as parallel. Axes of a D-H table
are exact at multiples of 90 deg (:func:`analysis.kinematics.dh.exact_cos_sin`) and otherwise
differ by round-off (~1e-16) or by a real angle."""
ACROSS_MIN = 1e-6
"""Smallest sine of the angle between the waist (or the wrist roll) and the parallel axes:
nearer than that the waist hardly moves the arm plane, and the closed form would divide by
it."""
_ELBOW = ("target", "arm")
_DECISIONS = {"forward", "elbow", "keep", "orientation_tol_deg"}
FAMILY_TEXT = (
    "the derivable families: 3 joints (a waist and two parallel axes: seed 000's), 4 (a "
    "waist and three parallel axes, one tool orientation kept: seed 001's), 5 (a waist, "
    "three parallel axes and a wrist roll: seed 004's)"
)


class NotDerivable(ValueError):
    """The chain is outside the derivable families; the message says why."""


@dataclass(frozen=True)
class Structure:
    """The numbers a derived closed form is built from (plain floats; see the module
    docstring of :mod:`analysis.kinematics.derive` for the symbols)."""

    family: str
    n: int
    waist: np.ndarray
    u: np.ndarray
    sigma: tuple
    rotation: np.ndarray
    roll: np.ndarray | None
    forward: np.ndarray | None
    elbow: str
    keep: tuple | None
    orientation_tol: float
    decisions: dict = field(default_factory=dict)


def _unit(v, where: str) -> np.ndarray:
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise NotDerivable(f"[derive] {where} = {v!r} is not a vector of 3 numbers") from None
    if a.shape != (3,) or not np.isfinite(a).all() or not np.linalg.norm(a) > 0:
        raise NotDerivable(f"[derive] {where} = {v!r} must be 3 finite numbers, not all 0")
    return a / np.linalg.norm(a)


def _sin(a, b) -> float:
    return float(np.linalg.norm(np.cross(a, b)))


def check_decisions(decisions) -> dict:
    """The ``[derive]`` table validated (unknown keys and bad values raise NotDerivable)."""
    d = dict(decisions or {})
    unknown = sorted(set(d) - _DECISIONS)
    if unknown:
        raise NotDerivable(
            f"[derive] has unknown key(s) {unknown}; expected some of {sorted(_DECISIONS)}"
        )
    if d.get("elbow", "target") not in _ELBOW:
        raise NotDerivable(f"[derive] elbow = {d['elbow']!r}: expected one of {_ELBOW}")
    if "orientation_tol_deg" in d:
        v = d["orientation_tol_deg"]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 < v < 90:
            raise NotDerivable(
                f"[derive] orientation_tol_deg = {v!r}: expected a number in (0, 90) deg"
            )
    return d


def _tool_axis(v) -> np.ndarray:
    if isinstance(v, str):
        if v not in ("x", "y", "z"):
            raise NotDerivable(f"[derive] keep.tool_axis = {v!r}: expected x, y, z or a vector")
        return np.eye(3)["xyz".index(v)]
    return _unit(v, "keep.tool_axis")


def classify(axes, rotation, decisions) -> Structure:
    """The family of a chain with joint ``axes`` (unit vectors at q = 0) and home tool
    ``rotation``, with the description's ``decisions``; NotDerivable otherwise."""
    d = check_decisions(decisions)
    n = len(axes)
    if n not in (3, 4, 5):
        raise NotDerivable(f"the chain has {n} joint(s); {FAMILY_TEXT}")
    w1, u = axes[0], axes[1]
    if _sin(w1, u) < ACROSS_MIN:
        raise NotDerivable(
            "joints 1 and 2 are parallel: the arm moves in one plane and cannot place a "
            f"point in space; {FAMILY_TEXT}"
        )
    n_par = 3 if n == 3 else 4
    for k in range(2, n_par):
        s = _sin(u, axes[k])
        if s > PARALLEL_TOL:
            angle = math.degrees(math.asin(min(s, 1.0)))
            raise NotDerivable(
                f"joints 2 and {k + 1} are not parallel (angle {angle:.4g} deg); {FAMILY_TEXT}"
            )
    sigma = tuple(float(np.sign(np.dot(u, axes[k]))) for k in range(1, n_par))
    family = {3: "3R", 4: "4R-kept", 5: "5R"}[n]
    roll = None
    if n == 5:
        roll = axes[4]
        if _sin(roll, u) < ACROSS_MIN:
            raise NotDerivable(
                "joint 5 is parallel to joints 2-4: four parallel axes leave the hand no roll "
                f"across them; {FAMILY_TEXT}"
            )
    keep = None
    if n == 4:
        if "keep" not in d:
            raise NotDerivable(
                "a 4-axis arm with three parallel axes holds its tool in one orientation "
                "about them, which the D-H table does not say: add [derive] keep = "
                '{ tool_axis = "x", direction = [0, 0, -1] } (the tool axis and the base '
                "direction it keeps; analysis.kinematics.derive.families)"
            )
        keep = _keep(d["keep"], u, rotation)
    elif "keep" in d:
        raise NotDerivable(f"[derive] keep applies to 4-axis arms; this chain has {n} joints")
    if n != 5 and "orientation_tol_deg" in d:
        raise NotDerivable("[derive] orientation_tol_deg applies to 5-axis arms only")
    forward = _unit(d["forward"], "forward") if "forward" in d else None
    tol = math.radians(d["orientation_tol_deg"]) if "orientation_tol_deg" in d else 1e-4
    return Structure(
        family, n, w1, u, sigma, rotation, roll, forward, d.get("elbow", "target"), keep, tol, d
    )


def _keep(spec, u, rotation) -> tuple:
    """The kept pitch psi [rad] about ``u`` and its cosine and sine: the rotation about the
    parallel axes that turns the tool axis (at q = 0) onto the kept direction (PK1)."""
    if not isinstance(spec, dict) or set(spec) != {"tool_axis", "direction"}:
        raise NotDerivable(
            f"[derive] keep = {spec!r}: expected {{ tool_axis = ..., direction = [x, y, z] }}"
        )
    t = rotation @ _tool_axis(spec["tool_axis"])
    goal = _unit(spec["direction"], "keep.direction")
    if abs(np.dot(u, t) - np.dot(u, goal)) > 1e-9:

        def deg(v):
            return math.degrees(math.acos(float(np.clip(np.dot(u, v), -1.0, 1.0))))

        raise NotDerivable(
            f"[derive] keep: the tool axis makes {deg(t):.4g} deg with the parallel axes and "
            f"the direction {spec['direction']} makes {deg(goal):.4g} deg: turning about them "
            "cannot bring one onto the other"
        )
    ta, ga = t - u * np.dot(u, t), goal - u * np.dot(u, goal)
    if np.linalg.norm(ta) < ACROSS_MIN:
        raise NotDerivable(
            "[derive] keep: the tool axis lies along the parallel axes, so every pitch keeps "
            "it; name a tool axis across them"
        )
    psi = math.atan2(float(np.dot(u, np.cross(ta, ga))), float(np.dot(ta, ga)))
    c, s = exact_cos_sin(psi)
    return psi, c, s

"""Which family a D-H chain belongs to, and the decisions its description makes.

:func:`classify` reads the joint axes of the chain at q = 0 (:mod:`.chain`) and either
returns a :class:`Structure` (the family, the numbers the closed form is built from, and
the decisions of the description's ``[derive]`` table) or raises :class:`NotDerivable`
with the reason. The families (the only ones derived; everything else keeps its
hand-written closed form):

- ``2R-planar``: two parallel revolute axes, a planar arm; input: the point's two coordinates
  across the axes (which must lie along a base axis).
- ``3R-planar``: three parallel revolute axes along the base z axis; the point's ``px, py``
  and the tool's turn ``alpha``.
- ``3R``: a waist (axis 1) and two parallel axes not parallel to it (2 || 3), a point: seed
  000's grabber with any D-H lengths, offsets and twists.
- ``4R-kept``: a waist and three parallel axes (2 || 3 || 4), the tool holding one
  orientation about them (``keep``), a point: seed 001's palletizer family.
- ``5R``: a waist, three parallel axes and a wrist roll across them (2 || 3 || 4, 5 not
  parallel to 2), a pose: seed 004's GR-1 family.
- ``SCARA``: two or three parallel revolute axes and a prismatic one along them, in any order
  (the Adept Cobra's R R P R), a point; with three revolute axes (along the base z axis) and
  ``alpha``, the tool's turn.
- ``6R-wrist``: a waist, two parallel axes and a spherical wrist (axes 4, 5, 6 through one
  point: Pieper's condition), a pose: the PUMA 560, KUKA, ABB, Fanuc arms.
- ``6R-parallel``: a waist, three parallel axes (2 || 3 || 4), axis 5 across them and axis 6
  across axis 5 and meeting it, a pose: the Universal Robots family.
- ``gantry``: three prismatic axes spanning space, a point; ``gantry-roll``: and a roll about
  the base z axis, a point and ``alpha``; ``gantry-wrist``: and a spherical wrist, a pose.

A point is ``px, py, pz`` [mm] (a planar arm: the two coordinates across its axes), a pose
the point and the RPY angles ``alpha, beta, gamma`` [rad] (:mod:`analysis.kinematics.rpy`:
``Rot(z, alpha) Rot(y, beta) Rot(x, gamma)``); ``alpha`` alone is the tool's turn about the
vertical, the one angle an arm whose rotations are all about the base z axis can set.

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

``forward`` and ``elbow`` apply to the families with a waist (3R, 4R-kept, 5R, 6R-wrist,
6R-parallel); the planar, SCARA and gantry families take no decision.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from analysis.kinematics.dh import exact_cos_sin

__all__ = ["FAMILIES", "NotDerivable", "Structure", "check_decisions", "classify"]

FAMILIES = ("2R-planar", "3R-planar", "3R", "4R-kept", "5R", "SCARA", "6R-wrist", "6R-parallel",
            "gantry", "gantry-roll", "gantry-wrist")  # fmt: skip
WAIST_FAMILIES = ("3R", "4R-kept", "5R", "6R-wrist", "6R-parallel")
"""The families solved by a waist and parallel axes (:mod:`.positioning`)."""
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
    "the derivable families (analysis.kinematics.derive.families): 2 or 3 parallel revolute "
    "axes (planar); a waist and two parallel axes (seed 000's); a waist, three parallel axes "
    "and one orientation kept (seed 001's) or a wrist roll (seed 004's); a SCARA (parallel "
    "revolute axes and a prismatic one along them); a waist, two parallel axes and a "
    "spherical wrist (PUMA); a waist, three parallel axes and two wrist axes (UR); a gantry "
    "(three prismatic axes) with no wrist, a vertical roll or a spherical wrist"
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
    axes: tuple = ()
    """Every joint's axis at q = 0 (unit vectors, :attr:`.chain.Home.axes`)."""
    kinds: tuple = ()
    """``"revolute"`` or ``"prismatic"`` per joint."""


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


def classify(axes, rotation, decisions, kinds=None) -> Structure:
    """The family of a chain with joint ``axes`` (unit vectors at q = 0) of ``kinds``
    (default: all revolute) and home tool ``rotation``, with the description's
    ``decisions``; NotDerivable otherwise, naming the rule the chain breaks."""
    d = check_decisions(decisions)
    axes = tuple(np.asarray(a, dtype=float) for a in axes)
    kinds = tuple(kinds) if kinds is not None else ("revolute",) * len(axes)
    n = len(axes)
    if not n:
        raise NotDerivable(f"the chain has no joint; {FAMILY_TEXT}")
    if "prismatic" in kinds:
        family = _prismatic_family(axes, kinds)
    elif n in (2, 3) and all(_sin(axes[0], a) <= PARALLEL_TOL for a in axes):
        family = f"{n}R-planar"
    elif n == 6:
        family = _six_family(axes)
    else:
        return _classify_waist(axes, rotation, d)
    return _plain(family, axes, kinds, rotation, d)


def _plain(family, axes, kinds, rotation, d) -> Structure:
    """The structure of a family whose closed form takes no decision (planar, SCARA,
    gantry) or only ``forward`` and ``elbow`` (6R)."""
    allowed = {"forward", "elbow"} if family in WAIST_FAMILIES else set()
    extra = sorted(set(d) - allowed)
    if extra:
        raise NotDerivable(f"[derive] {extra} do(es) not apply to the {family} family")
    n = len(axes)
    if family in ("2R-planar", "3R-planar", "SCARA"):
        u = next(a for a, k in zip(axes, kinds, strict=True) if k == "revolute")
        _vertical(family, u, n_rev=sum(k == "revolute" for k in kinds))
        sigma = tuple(float(np.sign(np.dot(u, a))) or 1.0 for a in axes)
    elif family in WAIST_FAMILIES:  # the parallel axes' senses, as the seed families
        u = axes[1]
        n_par = 3 if family == "6R-parallel" else 2
        sigma = tuple(float(np.sign(np.dot(u, axes[k]))) for k in range(1, 1 + n_par))
    else:
        u = axes[0]
        sigma = tuple(float(np.sign(np.dot(u, a))) or 1.0 for a in axes)
    roll = {"gantry-roll": 3, "6R-parallel": 4}.get(family)
    roll = axes[roll] if roll is not None else None
    forward = _unit(d["forward"], "forward") if "forward" in d else None
    return Structure(family, n, axes[0], u, sigma, rotation, roll, forward,
                     d.get("elbow", "target"), None, 1e-4, d, axes, kinds)  # fmt: skip


def _vertical(family: str, u, n_rev: int) -> None:
    """A planar arm's or a SCARA's parallel axes: along a base axis (a planar arm's point
    is given by the coordinates across it; a SCARA's lift is one coordinate), along z where
    the tool's turn is an input (RPY ``alpha``, the turn about z)."""
    along = [k for k in range(3) if abs(abs(u[k]) - 1.0) <= PARALLEL_TOL]
    if not along:
        raise NotDerivable(
            f"the {family} arm's parallel axes {_fmt(u)} lie along no base axis: the arm's "
            "plane is not a coordinate plane of the base frame"
        )
    if n_rev == 3 and along != [2]:
        raise NotDerivable(
            f"the {family} arm's parallel axes {_fmt(u)} are not vertical (the base z axis): "
            "the tool's turn about them is no RPY angle (alpha is the turn about z)"
        )


def _fmt(v) -> str:
    return "(" + ", ".join(f"{float(x):.4g}" for x in v) + ")"


def _prismatic_family(axes, kinds) -> str:
    """SCARA or gantry (module docstring), or NotDerivable."""
    n = len(axes)
    n_p = kinds.count("prismatic")
    if kinds[:3] == ("prismatic",) * 3 and n_p == 3:
        D = np.stack(axes[:3], axis=1)
        if abs(np.linalg.det(D)) < ACROSS_MIN:
            raise NotDerivable(
                "the three prismatic axes lie in one plane: they cannot place a point in space"
            )
        wrist = kinds[3:]
        if not wrist:
            return "gantry"
        if len(wrist) == 1:
            if _sin(axes[3], (0.0, 0.0, 1.0)) > PARALLEL_TOL:
                raise NotDerivable(
                    f"the gantry's roll axis {_fmt(axes[3])} is not vertical (the base z "
                    "axis): its angle is no RPY angle (alpha is the turn about z)"
                )
            return "gantry-roll"
        if len(wrist) == 3:
            _wrist_axes(axes[3:], "gantry")
            return "gantry-wrist"
        raise NotDerivable(
            f"a gantry with {len(wrist)} revolute joints after its three prismatic ones; "
            f"{FAMILY_TEXT}"
        )
    rev = [a for a, k in zip(axes, kinds, strict=True) if k == "revolute"]
    if n_p == 1 and len(rev) in (2, 3) and all(_sin(rev[0], a) <= PARALLEL_TOL for a in axes):
        return "SCARA"
    raise NotDerivable(
        f"a chain of {n} joints ({', '.join(kinds)}) with prismatic joints that is neither a "
        f"SCARA nor a gantry; {FAMILY_TEXT}"
    )


def _wrist_axes(axes, what: str) -> None:
    """Three wrist axes, each perpendicular to the next (where they meet: the closed form,
    :mod:`.wrist`; a wrist whose axes are not perpendicular cannot take every orientation
    and is not derived)."""
    for k in range(2):
        _perpendicular(axes[k], axes[k + 1], f"the {what}'s wrist axes {k + 4} and {k + 5}")


def _perpendicular(a, b, what: str) -> None:
    c = abs(float(np.dot(a, b)))
    if c > PARALLEL_TOL:
        angle = math.degrees(math.acos(min(c, 1.0)))
        raise NotDerivable(
            f"{what} make {angle:.4g} deg, not 90: the derived wrist needs them perpendicular "
            f"(every published wrist); {FAMILY_TEXT}"
        )


def _six_family(axes) -> str:
    """6R-wrist or 6R-parallel (module docstring), or NotDerivable."""
    w1, u = axes[0], axes[1]
    if _sin(w1, u) < ACROSS_MIN:
        raise NotDerivable(f"joints 1 and 2 of the six are parallel; {FAMILY_TEXT}")
    if _sin(u, axes[2]) > PARALLEL_TOL:
        angle = math.degrees(math.asin(min(_sin(u, axes[2]), 1.0)))
        raise NotDerivable(
            f"joints 2 and 3 of the six are not parallel (angle {angle:.4g} deg); {FAMILY_TEXT}"
        )
    if _sin(u, axes[3]) <= PARALLEL_TOL:
        _perpendicular(u, axes[4], "axis 5 and the parallel axes 2-4")
        _perpendicular(axes[4], axes[5], "axes 5 and 6")
        return "6R-parallel"
    _wrist_axes(axes[3:], "arm")
    return "6R-wrist"


def _classify_waist(axes, rotation, d) -> Structure:
    """The seed families: a waist and two (3R) or three (4R-kept, 5R) parallel axes."""
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
        family, n, w1, u, sigma, rotation, roll, forward, d.get("elbow", "target"), keep, tol, d,
        axes, ("revolute",) * n,
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

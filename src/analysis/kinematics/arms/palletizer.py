"""The seed-001 4-axis palletizer: the corrected geometric IK (eqs. 1-6, 12), written once.

Geometry (``data/arms/palletizer.toml``, modified D-H of eq. 8): the waist turns about the
vertical axis through the shoulder (L0 = 0); the upper arm (L1) and forearm (L2) move in the
vertical plane at azimuth gamma; the L-shaped gripper reaches L3 forward and h down and is
kept level (theta2 + theta3 + theta4 = pi/2, theta5 = 0). With ``rho = |(X0, Y0)|``::

    gamma  = atan2(Y0, X0)                               (eqs. 1 and 6, with atan2)
    w      = rho - L3,  zw = Z0 + h                      (the wrist in the arm plane)
    L4     = |(w, zw)|                                   (eq. 2)
    alpha1 = acos((L1^2 + L4^2 - L2^2) / (2 L1 L4))      (eq. 3)
    alpha2 = atan2(zw, w)                                (eq. 3 prints arcsin(H/L4))
    beta1  = acos((L1^2 + L2^2 - L4^2) / (2 L1 L2))      (eq. 3, "arccos" lost in print)

and, with eq. 12 corrected to keep the gripper level (theta4 = pi/2 - (theta2 + theta3)):

============  =======================  ===============  ==================================
branch        theta2                   theta3           theta4
============  =======================  ===============  ==================================
front-up      -(alpha1 + alpha2)       pi - beta1       alpha1 + alpha2 + beta1 - pi/2
front-down    alpha1 - alpha2          beta1 - pi       alpha2 - alpha1 - beta1 - pi/2
============  =======================  ===============  ==================================

theta1 = gamma for both. "front-up" (the elbow above the shoulder-wrist line) is the paper's
pose (eq. 4: alpha = alpha1 + alpha2 - pi/2, beta = pi/2 - beta1, motor angles -> D-H angles
by eq. 12). "back-up" and "back-down" turn the waist to gamma + pi and reach back over the
base: the same formulas with the wrist at w = -rho - L3 in the arm plane. These four are every
solution with the gripper level; section 2's claim that the pose is unique is audited against
them (:mod:`analysis.audit.papers.palletizer.method`). theta1, theta2, theta4 are wrapped to
(-pi, pi]; theta3 is not (branch-signed, continuous at the stretched arm).
Refused: out of reach (L4 > L1 + L2), inside the inner reach (L4 < |L1 - L2|), each for the
branch's own wrist; on the base axis (rho = 0: gamma undefined); and, in the isosceles family
L1 = L2, the wrist on the shoulder (L4 = 0: alpha2 undefined; status "degenerate"). The
description adds the elbow stop of sec. 2, theta3 in [90, 180] deg
(``data/arms/palletizer.toml``, reasons there), which the shared solver and the generated PLC
program apply after these refusals (status "joint limits"): with it only the "up" branches
solve, for wrist distances up to sqrt(L1^2 + L2^2).
"""

from __future__ import annotations

from analysis.kinematics.status import Status

__all__ = [
    "BRANCHES",
    "INPUTS",
    "INPUT_UNITS",
    "STARTUP_TARGET",
    "STATUSES",
    "check",
    "geometry",
    "ik",
    "refusal",
    "sample_q",
]

BRANCHES = ("front-up", "front-down", "back-up", "back-down")
"""The waist facing the grasp point (front, eqs. 1 and 6) or turned by pi (back: the arm
reaches over its base); the elbow above the shoulder-wrist line (up, theta3 > 0: the
paper's pose) or below it."""
INPUTS = ("px", "py", "pz")
"""The grasp point G = (X0, Y0, Z0) [mm] in the base frame."""
INPUT_UNITS = ("mm", "mm", "mm")
STATUSES = (Status.OUT_OF_REACH, Status.INSIDE_REACH, Status.BASE_AXIS, Status.DEGENERATE)
"""The wrist beyond L1 + L2 or inside |L1 - L2|, the grasp point on the base axis, the
wrist on the shoulder (L1 = L2)."""
STARTUP_TARGET = (100.0, 100.0, 600.0)
"""The grabber's Figure 3 target, kept as the first-scan example (out of the assumed
palletizer's reach: the first scan shows a refusal, status 1)."""


def check(P) -> None:
    """Reject lengths the closed form cannot use (ValueError naming the value)."""
    for name in ("L1", "L2"):
        if not P[name] > 0:
            raise ValueError(f"{name} = {P[name]} mm: link lengths must be > 0 mm")
    for name in ("L3", "h"):
        if not P[name] >= 0:
            raise ValueError(f"{name} = {P[name]} mm: the gripper offsets must be >= 0 mm")


def geometry(P) -> dict:
    """The shoulder (the base origin, L0 = 0) and the reach radii of the wrist [mm]."""
    return {
        "shoulder": (0.0, 0.0, 0.0),
        "reach_outer": P["L1"] + P["L2"],
        "reach_inner": abs(P["L1"] - P["L2"]),
    }


def ik(m, p, P, *, tol, axis_tol=None, theta1_on_axis=None):
    """The four solutions for grasp point ``p`` [mm] (corrected eqs. 1-6 and 12).

    Returns ``branches`` {name: (theta1..theta4)} [rad], ``refusals`` of the grasp point in
    priority order, ``branch_refusals`` {name: [...]} (the front and back wrists lie at
    different distances from the shoulder), and ``outside`` (signed distance of the nearer
    wrist outside its reach [mm]). ``tol`` is the distance tolerance at the reach shells,
    ``axis_tol`` (default ``tol``) at the base axis and the shoulder.

    Examples
    --------
    >>> from analysis.kinematics.ops import numpy_ops as m
    >>> P = {"L1": 200.0, "L2": 200.0, "L3": 50.0, "h": 70.0}
    >>> r = ik(m, (250.0, 0.0, 100.0), P, tol=1e-6)
    >>> [round(float(m.degrees(t)), 2) for t in r["branches"]["front-up"]]
    [0.0, -89.35, 97.98, 81.38]
    >>> [round(float(m.degrees(t)), 2) for t in r["branches"]["back-up"]]
    [180.0, 179.09, 60.91, -149.99]
    """
    x, y, z = p
    L1, L2, L3, h = P["L1"], P["L2"], P["L3"], P["h"]
    outer = m.let("outer", L1 + L2)
    inner = m.let("inner", m.abs(L1 - L2))
    axis_tol = tol if axis_tol is None else axis_tol
    m.section("reach box; gamma = atan2(Y0, X0) (eqs. 1, 6); the base axis")
    zw = m.let("zw", z + h)
    box = outer + L3 + tol
    out_box = m.any_(m.gt(m.abs(x), box), m.gt(m.abs(y), box), m.gt(m.abs(zw), outer + tol))
    rho = m.let("rho", m.sqrt(x * x + y * y))
    refusals = [(Status.OUT_OF_REACH, out_box)]
    on_axis = m.le(rho, axis_tol)
    gamma = m.atan2(y, x)
    if theta1_on_axis is None:
        refusals.append((Status.BASE_AXIS, on_axis))
    else:
        gamma = m.select(on_axis, theta1_on_axis, gamma)
    gamma = m.let("theta1", m.wrap(gamma))
    branches, branch_refusals, outside = {}, {}, {}
    # the wrist in the arm plane: the waist facing the grasp point (front) or turned by pi,
    # the arm reaching back over its base (back: the wrist lies rho + L3 behind the axis)
    for side, w_expr, theta1 in (
        ("front", rho - L3, gamma),
        ("back", -rho - L3, m.wrap(gamma + m.pi)),
    ):
        m.section(f"{side}: reach check |L1 - L2| <= L4 <= L1 + L2 (eq. 2)")
        w = m.let(f"w_{side}", w_expr)
        l4sq = m.let(f"L4sq_{side}", w * w + zw * zw)
        l4 = m.let(f"L4_{side}", m.sqrt(l4sq))
        beyond = m.let(f"beyond_{side}", l4 - outer)
        within = m.let(f"within_{side}", inner - l4)
        conds = [  # computed in priority order (the PLC program tests them in this order)
            (Status.OUT_OF_REACH, m.gt(beyond, tol)),
            (Status.INSIDE_REACH, m.gt(within, tol)),
        ]
        wrist_on_shoulder = m.le(l4, axis_tol)
        conds.append((Status.DEGENERATE, wrist_on_shoulder))
        m.section(f"{side}: alpha1, alpha2, beta1 (eq. 3)")
        l4safe = m.select(wrist_on_shoulder, 1.0, l4)
        ca1 = m.clip((L1 * L1 - L2 * L2 + l4sq) / (2.0 * L1 * l4safe), -1.0, 1.0)
        a1 = m.let(f"alpha1_{side}", m.acos(ca1))
        a2 = m.let(f"alpha2_{side}", m.atan2(zw, w))
        den = 2.0 * L1 * L2
        cb1 = m.clip(((L1 * L1 + L2 * L2) - l4sq) / den, -1.0, 1.0)
        # beta1 = acos(cb1) as atan2(sin, cos), sin from 1 -/+ cos(beta1) in factored form
        # ((L4 - |L1 - L2|)(L4 + |L1 - L2|) / den, ...): acos(cb1) loses half the digits where
        # cb1 nears 1, and with L1 = L2 that is the wrist near the shoulder, where an error in
        # beta1 moves the wrist by L1 times it (2.5e-6 mm at 2.5e-6 mm from the shoulder)
        om1 = m.clip((l4 - inner) * (l4 + inner) / den, 0.0, 2.0)
        op1 = m.clip((outer - l4) * (outer + l4) / den, 0.0, 2.0)
        b1 = m.let(f"beta1_{side}", m.atan2(m.sqrt(om1 * op1), cb1))
        m.section(f"{side}: D-H angles (eq. 12, gripper kept level)")
        s12 = m.let(f"alpha12_{side}", a1 + a2)
        branches[f"{side}-up"] = (
            theta1,
            m.let(f"theta2_{side}", m.wrap(-s12)),
            m.let(f"theta3_{side}", m.pi - b1),
            m.let(f"theta4_{side}", m.wrap((s12 + b1) - m.pi / 2)),
        )
        branches[f"{side}-down"] = (
            theta1,
            m.wrap(a1 - a2),
            b1 - m.pi,
            m.wrap(((a2 - a1) - b1) - m.pi / 2),
        )
        branch_refusals[f"{side}-up"] = branch_refusals[f"{side}-down"] = conds
        outside[side] = m.select(m.gt(beyond, within), beyond, within)
    out_f, out_b = outside["front"], outside["back"]
    return {
        "branches": branches,
        "refusals": refusals,
        "branch_refusals": branch_refusals,
        "outside": m.select(m.lt(out_f, out_b), out_f, out_b),
    }


def sample_q(rng, n: int, P, bounds):
    """Candidate configurations (n, 4) [rad] for :func:`analysis.kinematics.sampling.sample_q`:
    theta1..theta3 uniform within ``bounds`` (n_joints, 2), theta4 keeping the gripper
    level (theta2 + theta3 + theta4 = pi/2, sec. 3), wrapped to (-pi, pi]."""
    import numpy as np

    b = np.asarray(bounds, dtype=float)
    q = b[:3, 0] + rng.random((n, 3)) * (b[:3, 1] - b[:3, 0])
    t4 = np.mod(np.pi / 2 - q[:, 1] - q[:, 2] + np.pi, 2 * np.pi) - np.pi
    return np.concatenate([q, t4[:, None]], axis=1)


def refusal(status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
    """The one-line reason a grasp point is refused, and the limit crossed [mm]."""
    g = geometry(P)
    tgt = "(" + ", ".join(f"{float(v):g}" for v in p) + ")"
    if status == Status.OUT_OF_REACH:
        return (
            f"grasp point {tgt} mm puts the wrist {distance:.3f} mm beyond the reach of "
            f"{g['reach_outer']:g} mm (L1 + L2) from the shoulder"
        ), g["reach_outer"]
    if status == Status.INSIDE_REACH:
        return (
            f"grasp point {tgt} mm puts the wrist {distance:.3f} mm inside the inner reach "
            f"{g['reach_inner']:g} mm (|L1 - L2|) around the shoulder"
        ), g["reach_inner"]
    if status == Status.BASE_AXIS:
        return (
            f"grasp point {tgt} mm lies on the base axis (within {tol:g} mm): the waist "
            f"angle gamma is undefined (eq. 6 covers no such case); choose it"
        ), float("nan")
    if status == Status.DEGENERATE:
        return (
            f"grasp point {tgt} mm puts the wrist on the shoulder (L4 = 0, possible because "
            f"L1 = L2): alpha2 = atan2(zw, w) is undefined"
        ), 0.0
    raise ValueError(f"no message for status {status!r}")

"""The GR-1 5-DOF arm (seed 004): section 4.2's inverse kinematics corrected, written once.

Geometry (``data/arms/gr1.toml``, standard D-H, derived from section 4.2): the waist
(theta1) turns about the vertical base axis; the shoulder (theta2), elbow (theta3) and wrist
pitch (theta4) turn about parallel horizontal axes, so the upper arm (a2), forearm (a3) and
hand (a4) move in the vertical *arm plane* at azimuth theta1; the finger roll (theta5) turns
about the axis z4, which lies in the arm plane, perpendicular to the hand. The tool point
(the end of a4) does not move with theta5.

Inputs: the pose ``(px, py, pz)`` [mm] and the RPY angles ``(alpha, beta, gamma)`` [rad] of
eqs. 3.14-3.15 (:mod:`analysis.kinematics.rpy`), the thesis's Table 5-3 columns.

Corrected closed form (the errata register, ``data/registers/gr1.toml``, says what the
thesis printed)::

    theta1   = atan2(py, px)                   (prints arctan(py/px); + pi: "back")
    c1, s1   = px / rho, py / rho,  rho = |(px, py)|
    n, o, a  = the columns of RPY(alpha, beta, gamma)        (eq. 3.15)
    s1 a_x - c1 a_y = 0                        (a 5-DOF arm keeps a in its plane: not printed)
    theta234 = atan2(c1 a_x + s1 a_y, -a_z)    (prints arctan(o_z / (c1 o_x + s1 o_y)))
    theta5   = atan2(s1 n_x - c1 n_y, s1 o_x - c1 o_y)                  (prints arctan)
    r  = px c1 + py s1 - a4 c234,  z = pz - d1 - a4 s234                (the wrist)
    c3 = (r^2 + z^2 - a2^2 - a3^2) / (2 a2 a3),  theta3 = -/+ acos(c3)  (prints arctan(s3/c3))
    theta2 = atan2(z, r) - atan2(a3 s3, a2 + a3 c3)                     (prints arctan(s2/c2))
    theta4 = theta234 - theta2 - theta3

Branches
--------
============  ==================  ======================================
name          theta1              elbow
============  ==================  ======================================
front-up      atan2(py, px)       up: theta3 <= 0
front-down    atan2(py, px)       down: theta3 >= 0
back-up       atan2(py, px) + pi  up: theta3 >= 0 (the plane is mirrored)
back-down     atan2(py, px) + pi  down: theta3 <= 0
============  ==================  ======================================

"up": seen in the vertical plane of the pose with its azimuth pointing right, the elbow
lies left of the line from the shoulder to the wrist: above it when the wrist is in front
of the base axis (as for the paper's arm of seed 000), below it when the wrist lies behind.

Back branches keep the approach vector ``a`` but reverse the hand (theta234 -> -theta234,
theta5 -> theta5 + pi): their wrist lies at ``p + a4 x4`` instead of ``p - a4 x4``, so a pose
can be in reach of the front branches and not of the back ones, or the reverse. Those
conditions are per branch (``branch_refusals``: out of reach, inside the inner reach, wrist
on the shoulder); the pose is refused only if no branch is left
(:func:`analysis.kinematics.arm.solve_body`).

Orientation: a 5-DOF arm cannot turn its approach vector out of the arm plane. The thesis
ignores this (Table 5-3's orientations are 69.1 and 60.7 deg out of it). Decision: a pose
whose approach vector leaves the arm plane by more than ``orientation_tol``
(:data:`ORIENTATION_TOL_RAD` = 1e-4 rad, status ``orientation``) is **refused**; within the
tolerance the closed form takes the in-plane part of ``a`` (theta234) and the components of
``n``, ``o`` along the joint axis z1 (theta5). That projection is the reachable orientation
nearest to the requested one (the rotation between them is the smallest, and equals the
out-of-plane angle of ``a``: ``tests/kinematics/test_gr1.py`` checks both against a search
over theta234 and theta5), so ``orientation_tol=None`` gives the documented projection
without refusing. Why refuse by default: a silently rotated hand is a wrong pose; 1e-4 rad
is 19 times smaller than one wrist-pitch pulse (0.11 deg) and 100 times larger than the
float32 round-off of the check in the PLC program, so float64 and float32 agree on it.

Refusals, in the order computed (a PLC jumps at the first that holds): beyond the box
``|px|, |py|, |pz - d1| > a2 + a3 + a4`` (before any square: no REAL overflow), on the
base axis (rho <= tol: theta1 undefined unless ``theta1_on_axis`` is given), orientation
out of the plane; then per branch: wrist beyond ``a2 + a3``, inside ``|a2 - a3|``, on the
shoulder (``|a2 - a3| <= tol``: theta2 undefined). theta1, theta2, theta4, theta5 are
wrapped to (-pi, pi]; theta3 is -/+acos by branch (not wrapped).
"""

from __future__ import annotations

import math

from analysis.kinematics.rpy import rpy_columns
from analysis.kinematics.status import Status

__all__ = [
    "BRANCHES",
    "INPUTS",
    "INPUT_UNITS",
    "ORIENTATION_TOL_RAD",
    "STARTUP_TARGET",
    "STATUSES",
    "check",
    "geometry",
    "ik",
    "refusal",
]

BRANCHES = ("front-up", "front-down", "back-up", "back-down")
INPUTS = ("px", "py", "pz", "alpha", "beta", "gamma")
"""The pose: position [mm] and RPY angles [rad] (eqs. 3.14-3.15), Table 5-3's columns."""
INPUT_UNITS = ("mm", "mm", "mm", "rad", "rad", "rad")
"""Units of :data:`INPUTS` (the command line takes the angles in degrees)."""
STATUSES = (
    Status.OUT_OF_REACH,
    Status.INSIDE_REACH,
    Status.BASE_AXIS,
    Status.ORIENTATION,
    Status.DEGENERATE,
)
"""Beyond the box or a wrist beyond a2 + a3, a wrist inside |a2 - a3|, on the base axis, an
approach vector out of the arm plane, a wrist on the shoulder (a2 = a3)."""
PROJECTION_HINT = "orientation_tol=None gives the nearest reachable orientation"
"""The end of the orientation refusal: how a Python caller gets the nearest orientation (the
command line replaces it by that orientation, :mod:`analysis.app.cli`)."""
ORIENTATION_TOL_RAD = 1e-4
"""Largest angle [rad] between the approach vector and the arm plane that is accepted (and
projected away); beyond it the pose is refused with status ``orientation``."""
STARTUP_TARGET = None
"""No example pose is written on the PLC's first scan: the thesis's only poses (Table 5-3)
are out of reach of a 5-DOF arm's orientations."""


def check(P) -> None:
    """Reject lengths the closed form cannot use (ValueError naming the value)."""
    for name in ("a2", "a3"):
        if not P[name] > 0:
            raise ValueError(f"{name} = {P[name]} mm: link lengths must be > 0 mm")
    if not P["a4"] >= 0:
        raise ValueError(f"a4 = {P['a4']} mm: the hand length must be >= 0 mm")


def geometry(P) -> dict:
    """The shoulder, the wrist's reach radii around it and the tool's largest reach [mm]."""
    return {
        "shoulder": (0.0, 0.0, P["d1"]),
        "reach_outer": P["a2"] + P["a3"],
        "reach_inner": abs(P["a2"] - P["a3"]),
        "reach_tool": P["a2"] + P["a3"] + P["a4"],
    }


def ik(
    m,
    p,
    P,
    *,
    tol,
    axis_tol=None,
    margin_rad=0.0,
    theta1_on_axis=None,
    orientation_tol=ORIENTATION_TOL_RAD,
    precise=False,
):
    """All four branches for the pose ``p = (px, py, pz, alpha, beta, gamma)``.

    Parameters
    ----------
    m : namespace (:mod:`analysis.kinematics.ops`)
    p : 6 values of ``m``
        Position [mm] and RPY angles [rad] (eq. 3.14).
    P : mapping with a2, a3, a4, d1 [mm]
    tol : float or value of ``m``
        Distance tolerance [mm] at the reach shells (negative: refuse a band inside them).
    axis_tol : float, optional
        Distance [mm] from the base axis and of the wrist from the shoulder within which the
        pose is singular (default ``tol``).
    margin_rad : float
        Narrows ``orientation_tol`` (the PLC's band; see :mod:`analysis.kinematics.arms`).
    theta1_on_axis : float, optional
        Waist angle [rad] for poses on the base axis; None refuses them.
    orientation_tol : float or None
        Largest accepted out-of-plane angle of the approach vector [rad]; None projects
        every orientation onto the nearest reachable one without refusing.
    precise : bool
        theta3 from 1 -/+ c3 in factored form (the float64 backends; the solver body passes
        it); False: acos(c3), the PLC programs' form.

    Returns
    -------
    dict
        ``branches`` {name: (theta1 .. theta5)} [rad], ``refusals`` [(Status, condition)]
        of the pose, ``branch_refusals`` {name: [(Status, condition)]}, ``outside`` (signed
        distance of the nearer wrist outside its reach [mm]), ``off_plane`` (sine of the
        approach vector's angle to the arm plane) and ``wrist`` {"front"/"back": (r, z)}.

    Examples
    --------
    The pose of joint angles (40, 30, -60, 20, 10) deg comes back on the front-up branch:

    >>> import numpy as np
    >>> from analysis.kinematics.ops import numpy_ops as m
    >>> P = {"a2": 228.0, "a3": 228.0, "a4": 73.0, "d1": 0.0}
    >>> pose = (357.5884, 300.0523, -12.6763, 0.521, 0.1719, 3.111)
    >>> r = ik(m, pose, P, tol=1e-6, orientation_tol=1e-3)
    >>> [round(float(np.degrees(t)), 1) for t in r["branches"]["front-up"]]
    [40.0, 30.0, -60.0, 20.0, 10.0]
    """
    px, py, pz, alpha, beta, gamma = p
    a2, a3, a4, d1 = P["a2"], P["a3"], P["a4"], P["d1"]
    outer = m.let("outer", a2 + a3)
    inner = m.let("inner", m.abs(a2 - a3))
    refusals, z0 = _box(m, (px, py, pz), outer, a4, d1, tol)
    axis_tol = tol if axis_tol is None else axis_tol
    phi, theta1, c1, s1 = _waist(m, px, py, axis_tol, theta1_on_axis, refusals)
    off, t234, t5 = _hand(m, (alpha, beta, gamma), c1, s1, orientation_tol, margin_rad,
                          refusals)  # fmt: skip
    c234 = m.let("c234", m.cos(t234))
    s234 = m.let("s234", m.sin(t234))
    radial = m.let("radial", px * c1 + py * s1)
    lengths = (a2, a3, a4, outer, inner)
    sides = {}
    for side in ("front", "back"):
        sides[side] = _wrist(m, side, radial, z0, (c234, s234), lengths, tol, axis_tol, precise)
    branches, branch_refusals = _branches(m, phi, theta1, t234, t5, sides)
    out_f, out_b = sides["front"][4], sides["back"][4]
    return {
        "branches": branches,
        "refusals": refusals,
        "branch_refusals": branch_refusals,
        "outside": m.select(m.lt(out_f, out_b), out_f, out_b),
        "off_plane": off,
        "wrist": {s: v[5] for s, v in sides.items()},
    }


def _box(m, position, outer, a4, d1, tol):
    """The box ``|px|, |py|, |pz - d1| <= a2 + a3 + a4``, checked first: beyond
    it the pose is out of reach anyway, and inside it no square below overflows a REAL (not
    in the thesis: its sec. 4.2 takes every pose as reachable). Returns the refusals so far
    and ``z0 = pz - d1``."""
    px, py, pz = position
    m.section("box: |px|, |py|, |pz - d1| <= a2 + a3 + a4 (farther, no pose is reachable)")
    z0 = m.let("z0", pz - d1)
    box = (outer + a4) + tol
    out_box = m.any_(m.gt(m.abs(px), box), m.gt(m.abs(py), box), m.gt(m.abs(z0), box))
    return [(Status.OUT_OF_REACH, out_box)], z0


def _waist(m, px, py, axis_tol, theta1_on_axis, refusals):
    """theta1 = atan2(py, px) (sec. 4.2, p. 18, prints ``theta1 = arctan(py/px)``,
    ``theta1' = theta1 + 180``), and c1, s1 = px/rho, py/rho; on the base axis
    (rho <= axis_tol) theta1 is undefined: refused, or ``theta1_on_axis`` given.
    Returns (atan2(py, px) unwrapped, theta1, c1, s1)."""
    m.section("theta1 = atan2(py, px) (sec. 4.2 prints arctan(py/px)); the base axis")
    rho = m.let("rho", m.sqrt(px * px + py * py))
    on_axis = m.le(rho, axis_tol)
    phi = m.atan2(py, px)
    rho_safe = m.select(on_axis, 1.0, rho)
    c1, s1 = px / rho_safe, py / rho_safe
    if theta1_on_axis is None:
        refusals.append((Status.BASE_AXIS, on_axis))
    else:
        phi = m.select(on_axis, theta1_on_axis, phi)
        c1 = m.select(on_axis, m.cos(theta1_on_axis), c1)
        s1 = m.select(on_axis, m.sin(theta1_on_axis), s1)
    c1, s1 = m.let("cos_theta1", c1), m.let("sin_theta1", s1)
    return phi, m.let("theta1", m.wrap(phi)), c1, s1


def _hand(m, rpy, c1, s1, orientation_tol, margin_rad, refusals):
    """The hand's angles from the orientation n, o, a = the columns of RPY(alpha, beta,
    gamma) (eq. 3.15): theta234 = atan2(c1 ax + s1 ay, -az) (sec. 4.2, p. 18, prints
    ``theta234 = arctan(oz / (c1 ox + s1 oy))``) and theta5 = atan2(s1 nx - c1 ny,
    s1 ox - c1 oy) (p. 18, prints arctan). The approach vector must lie in the arm plane,
    ``s1 ax - c1 ay = 0`` (not printed): refused beyond ``orientation_tol`` narrowed by
    ``margin_rad``. Returns (s1 ax - c1 ay, theta234, theta5)."""
    m.section("orientation n, o, a (eq. 3.15); a must lie in the arm plane: s1 ax - c1 ay = 0")
    (nx, ny, _), (ox, oy, _), (ax, ay, az) = rpy_columns(m, *rpy)
    off = m.let("off_plane", s1 * ax - c1 * ay)
    if orientation_tol is not None:
        narrowed = float(orientation_tol) - float(margin_rad)
        if not narrowed > 0:
            raise ValueError(
                f"orientation_tol = {orientation_tol} rad leaves nothing after the margin "
                f"{margin_rad} rad"
            )
        limit = math.sin(min(narrowed, math.pi / 2))
        refusals.append((Status.ORIENTATION, m.gt(m.abs(off), limit)))
    m.section("theta234 = atan2(c1 ax + s1 ay, -az), theta5 = atan2(s1 nx - c1 ny, s1 ox - c1 oy)")
    t234 = m.let("theta234", m.atan2(c1 * ax + s1 * ay, -az))
    t5 = m.let("theta5", m.atan2(s1 * nx - c1 * ny, s1 * ox - c1 * oy))
    return off, t234, t5


def _wrist(m, side, radial, z0, hand, lengths, tol, axis_tol, precise):
    """One side's wrist (r, z) in the arm plane, its reach conditions, acos(c3) and the two
    angles of theta2 (sec. 4.2, p. 19): ``c3 = ((px c1 + py s1 - c234 a4)^2 + (pz - s234
    a4)^2 - a2^2 - a3^2) / (2 a2 a3)``, ``s3 = -/+ sqrt(1 - c3^2)``, ``theta3 =
    arctan(s3/c3)``; theta2 = atan2(z, r) -/+ atan2(a3 s3, a2 + a3 c3), the angle of the
    thesis's ``s2/c2`` quotient. The back side: c1, s1 -> -c1, -s1 and theta234 ->
    -theta234 (the hand reversed). Returns (conditions, acos(c3), atan2(z, r), the elbow
    angle, the signed distance outside the reach [mm], (r, z))."""
    (c234, s234), (a2, a3, a4, outer, inner) = hand, lengths
    # back: c1, s1 -> -c1, -s1 and theta234 -> -theta234 (the hand reversed)
    sign = ("", "-") if side == "front" else ("-", "+")
    m.section(f"{side}: wrist r = {sign[0]}(px c1 + py s1) - a4 c234, "
              f"z = pz - d1 {sign[1]} a4 s234; c3 (sec. 4.2)")  # fmt: skip
    if side == "front":
        r = m.let("r_front", radial - a4 * c234)
        z = m.let("z_front", z0 - a4 * s234)
    else:
        r = m.let("r_back", -radial - a4 * c234)
        z = m.let("z_back", z0 + a4 * s234)
    d2 = m.let(f"d2_{side}", r * r + z * z)
    d = m.let(f"d_{side}", m.sqrt(d2))
    beyond = m.let(f"beyond_{side}", d - outer)
    within = m.let(f"within_{side}", inner - d)
    conds = [
        (Status.OUT_OF_REACH, m.gt(beyond, tol)),
        (Status.INSIDE_REACH, m.gt(within, tol)),
        (Status.DEGENERATE, m.le(d, axis_tol)),
    ]
    den = 2.0 * a2 * a3
    c3 = m.let(f"c3_{side}", m.clip((d2 - (a2 * a2 + a3 * a3)) / den, -1.0, 1.0))
    if precise:
        # sin(theta3) >= 0 from 1 -/+ c3 in factored form, not from c3: with a2 = a3 the
        # wrist near the shoulder has c3 near -1, where 1 + c3 computed from c3 keeps half
        # the digits and an error in theta3 moves the wrist by a3 times it (2.0e-6 mm at
        # 2.0e-6 mm from the shoulder, solved with limits=False)
        om3 = m.clip((outer - d) * (outer + d) / den, 0.0, 2.0)  # 1 - c3
        op3 = m.clip((d - inner) * (d + inner) / den, 0.0, 2.0)  # 1 + c3
        s3 = m.sqrt(om3 * op3)
        t3 = m.let(f"acos_c3_{side}", m.atan2(s3, c3))  # acos(c3), in [0, pi]
    else:  # the PLC programs' form (their float32 model is bit-exact on awlsim)
        t3 = m.let(f"acos_c3_{side}", m.acos(c3))  # [0, pi]
        s3 = m.sqrt((1.0 - c3) * (1.0 + c3))  # sin(acos c3) >= 0
    m.section(f"{side}: theta2 = atan2(z, r) -/+ atan2(a3 s3, a2 + a3 c3)")
    base = m.let(f"atan2_zr_{side}", m.atan2(z, r))
    elbow = m.let(f"atan2_elbow_{side}", m.atan2(a3 * s3, a2 + a3 * c3))
    outside = m.select(m.gt(beyond, within), beyond, within)
    return conds, t3, base, elbow, outside, (r, z)


def _branches(m, phi, theta1, t234, t5, sides):
    """The four branches, waist front/back and elbow up/down, with theta4 = theta234 -
    theta2 - theta3 (sec. 4.2, p. 19). Returns ({name: (theta1 .. theta5)},
    {name: [(Status, condition)]})."""
    m.section("the branches: waist front/back, elbow up/down; theta4 = theta234 - theta2 - theta3")
    theta1_back = m.let("theta1_back", m.wrap(phi + m.pi))
    t5_back = m.let("theta5_back", m.wrap(t5 + m.pi))
    branches, branch_refusals = {}, {}
    for name in BRANCHES:
        side, elbow_up = name.split("-")[0], name.endswith("up")
        conds, t3, base, elbow, _, _ = sides[side]
        front = side == "front"
        # theta3 <= 0 is "up" on the front; the back plane's angles are mirrored
        theta3 = -t3 if front == elbow_up else t3
        theta2 = m.wrap(base + elbow if front == elbow_up else base - elbow)
        hand = t234 if front else -t234
        theta4 = m.wrap((hand - theta2) - theta3)
        branches[name] = (theta1 if front else theta1_back, theta2, theta3, theta4,
                          t5 if front else t5_back)  # fmt: skip
        branch_refusals[name] = conds
    return branches, branch_refusals


def refusal(status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
    """The one-line reason a pose is refused, naming the pose and the limit, and the limit
    [mm] (the radius crossed; NaN where no radius is crossed)."""
    import numpy as np

    from analysis.kinematics.ops import numpy_ops

    g = geometry(P)
    pose = tuple(float(v) for v in p)
    where = (
        f"pose ({', '.join(f'{v:g}' for v in pose[:3])}) mm, "
        f"RPY ({', '.join(f'{math.degrees(v):.4g}' for v in pose[3:])}) deg"
    )
    sh = "(" + ", ".join(f"{v:g}" for v in g["shoulder"]) + ")"
    with np.errstate(all="ignore"):
        sol = ik(numpy_ops, pose, dict(P), tol=tol, orientation_tol=None)
    dist = {s: float(np.hypot(*sol["wrist"][s])) for s in ("front", "back")}
    wrists = (
        f"front wrist {dist['front']:.3f} mm, back wrist {dist['back']:.3f} mm from the "
        f"shoulder at {sh} mm"
    )
    if status == Status.OUT_OF_REACH:
        box = g["reach_tool"] + tol
        z0 = pose[2] - P["d1"]
        if max(abs(pose[0]), abs(pose[1]), abs(z0)) > box:
            return (
                f"{where} is beyond the reach of {g['reach_tool']:g} mm (a2 + a3 + a4) around "
                f"the shoulder at {sh} mm in x, y or z: no configuration reaches it"
            ), g["reach_tool"]
        return (
            f"{where} needs the wrist beyond the reach of {g['reach_outer']:g} mm (a2 + a3): "
            f"{wrists}"
        ), g["reach_outer"]
    if status == Status.INSIDE_REACH:
        return (
            f"{where} needs the wrist inside the inner reach of {g['reach_inner']:g} mm "
            f"(|a2 - a3|): {wrists}"
        ), g["reach_inner"]
    if status == Status.BASE_AXIS:
        rho = math.hypot(pose[0], pose[1])
        return (
            f"{where} lies on the base axis (distance {rho:.3g} mm <= tolerance {tol:g} mm): "
            f"theta1 is undefined there; choose the waist angle to use (theta1_on_axis)"
        ), float("nan")
    if status == Status.ORIENTATION:
        angle = math.degrees(math.asin(min(1.0, abs(float(sol["off_plane"])))))
        azimuth = math.degrees(math.atan2(pose[1], pose[0]))
        return (
            f"{where} asks for an approach vector {angle:.3f} deg out of the arm plane at "
            f"azimuth {azimuth:.3f} deg; a 5-DOF arm keeps it in that plane (accepted: "
            f"{math.degrees(ORIENTATION_TOL_RAD):.2g} deg); {PROJECTION_HINT}"
        ), float("nan")
    if status == Status.DEGENERATE:
        return (
            f"{where} puts the wrist on the shoulder (a2 = a3): theta2 is undefined ({wrists})"
        ), 0.0
    raise ValueError(f"no message for status {status!r}")

"""The paper's 3R waist/shoulder/elbow arm (seed 000): the corrected closed form, written once.

Geometry (Table 1 / Table 3, standard D-H; ``data/arms/grabber.toml``): the waist turns about
the vertical base axis; the shoulder sits on that axis at height L1; the upper arm (L2) and
the forearm (L3) move in the vertical plane at azimuth theta1.

Corrected closed form (the errata register says what the paper printed)::

    theta1 = atan2(Py, Px)                                         (eq. 6, with atan2)
    r      = cos(theta1) Px + sin(theta1) Py = rho = |(Px, Py)|    (eq. 7; -rho "back")
    z      = Pz - L1                                               (eq. 8)
    c3     = cos(theta3) = (r^2 + z^2 - L2^2 - L3^2) / (2 L2 L3)   (eqs. 9-10)
    theta3 = -acos(c3) "up" or +acos(c3) "down"         (eq. 10 gives only the + branch)
    k = L2 c3 + L3,  s = L2 sin(theta3) = -/+ L2 sqrt((1 - c3)(1 + c3))
    theta2 = atan2(z k + r s, r k - z s) - theta3                  (eqs. 15-19, atan2)

Branches
--------
============  ===========================  ===========================================
name          theta1                       elbow
============  ===========================  ===========================================
front-up      atan2(Py, Px) (the paper's)  above the shoulder-wrist line: theta3 <= 0
front-down    atan2(Py, Px)                below: theta3 >= 0
back-up       atan2(Py, Px) + pi           above: theta3 >= 0
back-down     atan2(Py, Px) + pi           below: theta3 <= 0
============  ===========================  ===========================================

A back branch has ``r = -rho``: its eq. 18 has the front branch's numerator and the negated
denominator, so its theta2 + theta3 is pi minus the front one (mod 2 pi); the four branches
need two atan2 besides theta1's and acos's.

Conventions at the boundaries (the same in Python and in the generated PLC program):

- theta1 and theta2 are wrapped to (-pi, pi]; theta3 is *not* wrapped: it is -acos(c3) in
  [-pi, 0] or +acos(c3) in [0, pi] by branch, so a target moving through the folded-elbow
  sphere (|P - shoulder| = |L2 - L3|) keeps a continuous pulse count (-2000 at the fold for
  front-up, never a jump to +2000).
- On the base axis (rho <= tol) theta1 is undefined: the target is refused (status
  ``base-axis``) unless a waist angle ``theta1_on_axis`` is given, which both use; the target
  is then taken as on the axis (r = 0), so the arm reaches within rho <= tol of it.
- theta1 and theta2 turn through whole revolutions in this model (the paper gives no joint
  ranges), so wrapping them leaves a *wrap cut*: where a continuous path crosses +-pi the count
  jumps by one revolution (ppr). Within float32 error of the cut the PLC's REAL arithmetic
  may land on the other end than Python (e.g. c2 = +2000 against -2000): the same joint
  position, one revolution apart; :func:`analysis.plc.verify.compare` counts these apart from
  pulse errors. A motion layer that moves between absolute counts should move such a joint
  the shorter way round if the mechanism allows it.
- A target more than ``tol`` outside the reach shell is refused; within ``tol`` it is put on
  the shell (cos theta3 clipped to [-1, 1]).
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
]

BRANCHES = ("front-up", "front-down", "back-up", "back-down")
INPUTS = ("px", "py", "pz")
"""The target [mm], in the order of the paper's Figure 3 (VD0, VD4, VD8)."""
INPUT_UNITS = ("mm", "mm", "mm")
STATUSES = (Status.OUT_OF_REACH, Status.INSIDE_REACH, Status.BASE_AXIS)
"""Beyond L2 + L3, inside |L2 - L3| (around the shoulder), on the base axis."""
STARTUP_TARGET = (100.0, 100.0, 600.0)
"""The example target of the paper's Figure 3 (Table 4 row 1), written on the first scan."""


def check(P) -> None:
    """Reject lengths the closed form cannot use (ValueError naming the value)."""
    if not P["L1"] >= 0:
        raise ValueError(f"L1 = {P['L1']} mm is negative; the waist height must be >= 0 mm")
    for name in ("L2", "L3"):
        if not P[name] > 0:
            raise ValueError(f"{name} = {P[name]} mm: link lengths must be > 0 mm")


def geometry(P) -> dict:
    """Named points and radii: the shoulder (centre of the reach shell) and its radii [mm]."""
    return {
        "shoulder": (0.0, 0.0, P["L1"]),
        "reach_outer": P["L2"] + P["L3"],
        "reach_inner": abs(P["L2"] - P["L3"]),
    }


def ik(m, p, P, *, tol, axis_tol=None, theta1_on_axis=None):
    """All four branches for target ``p = (Px, Py, Pz)`` [mm] (corrected eqs. 6-19).

    Parameters
    ----------
    m : namespace (:mod:`analysis.kinematics.ops`)
    p : 3 values of ``m``
    P : mapping with L1, L2, L3 [mm] (numbers, or values of ``m``)
    tol : float or value of ``m``
        Distance tolerance [mm] at the reach shell (negative: refuse a band inside it).
    axis_tol : float, optional
        Distance [mm] from the base axis within which theta1 is undefined (default ``tol``).
    theta1_on_axis : float, optional
        Waist angle [rad] for targets on the base axis; None refuses them.

    Returns
    -------
    dict
        ``branches`` {name: (theta1, theta2, theta3)} [rad], ``refusals`` [(Status,
        condition), ...] in priority order, ``outside`` (signed distance outside the
        reach shell [mm]: > 0 unreachable).

    Examples
    --------
    Table 4 row 1 with numpy:

    >>> from analysis.kinematics.ops import numpy_ops as m
    >>> r = ik(m, (100.0, 100.0, 600.0), {"L1": 660.0, "L2": 310.0, "L3": 200.0}, tol=1e-6)
    >>> [round(float(m.degrees(t)), 2) for t in r["branches"]["front-up"]]
    [45.0, 10.21, -155.13]
    """
    x, y, pz = p
    L1, L2, L3 = P["L1"], P["L2"], P["L3"]
    outer = m.let("outer", L2 + L3)
    inner = m.let("inner", m.abs(L2 - L3))
    m.section("reach check: |L2 - L3| <= |P - (0, 0, L1)| <= L2 + L3 (eqs. 8-9)")
    z = m.let("z", pz - L1)  # eq. 8
    # the box first: beyond it a target is out of reach anyway, and inside it every square
    # below stays under (L2 + L3 + tol)^2 (a PLC leaves its output unchanged on a REAL overflow)
    box = outer + tol
    out_box = m.any_(m.gt(m.abs(x), box), m.gt(m.abs(y), box), m.gt(m.abs(z), box))
    rho2 = m.let("rho2", x * x + y * y)
    d2 = m.let("d2", rho2 + z * z)
    rho = m.let("rho", m.sqrt(rho2))
    d = m.let("d", m.sqrt(d2))
    beyond = m.let("beyond", d - outer)
    within = m.let("within", inner - d)
    refusals = [
        (Status.OUT_OF_REACH, m.or_(out_box, m.gt(beyond, tol))),
        (Status.INSIDE_REACH, m.gt(within, tol)),
    ]
    m.section("theta1 = atan2(Py, Px) (eq. 6; Fig. 4); the base axis")
    on_axis = m.le(rho, tol if axis_tol is None else axis_tol)
    phi = m.atan2(y, x)
    r = rho
    if theta1_on_axis is None:
        refusals.append((Status.BASE_AXIS, on_axis))
    else:  # taken as on the axis: r = 0 (eq. 7 at the given theta1), so it misses by rho <= tol
        phi = m.select(on_axis, theta1_on_axis, phi)
        r = m.let("r", m.select(on_axis, 0.0, rho))
    phi = m.let("theta1", m.wrap(phi))
    m.section("theta3 = -/+ acos((D^2 - L2^2 - L3^2) / (2 L2 L3)) (eqs. 9-10; Fig. 6)")
    c3 = m.let("cos_theta3", m.clip((d2 - (L2 * L2 + L3 * L3)) / (2.0 * L2 * L3), -1.0, 1.0))
    t3 = m.let("theta3", m.acos(c3))  # [0, pi]
    s3 = m.let("s3", m.sqrt((1.0 - c3) * (1.0 + c3)))  # sin(acos c3) >= 0
    m.section("theta2 = atan2(z k + r s, r k - z s) - theta3 (eqs. 15-19; Fig. 5)")
    k = m.let("k", L2 * c3 + L3)
    s = m.let("s", L2 * s3)
    t23u = m.let("theta23_up", m.atan2(z * k - r * s, r * k + z * s))  # theta3 = -t3
    t23d = m.let("theta23_down", m.atan2(z * k + r * s, r * k - z * s))  # theta3 = +t3
    m.section("the branch: waist front/back (theta1, theta1 + pi), elbow up/down")
    back = m.let("theta1_back", m.wrap(phi + m.pi))
    branches = {
        "front-up": (phi, m.let("theta2", m.wrap(t23u + t3)), -t3),
        "front-down": (phi, m.wrap(t23d - t3), t3),
        "back-up": (back, m.wrap((m.pi - t23u) - t3), t3),
        "back-down": (back, m.wrap((m.pi - t23d) + t3), -t3),
    }
    outside = m.select(m.gt(beyond, within), beyond, within)
    return {"branches": branches, "refusals": refusals, "outside": outside}


def refusal(status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
    """The one-line reason a target is refused, naming the target and the limit, and the
    limit [mm] (the radius crossed; NaN for the base axis)."""
    g = geometry(P)
    sh = _fmt(g["shoulder"])
    d = distance
    if status == Status.OUT_OF_REACH:
        D = g["reach_outer"] + d
        return (
            f"target {_fmt(p)} mm is {_mm(d)} mm beyond the reach of {g['reach_outer']:g} mm "
            f"(L2 + L3) around the shoulder at {sh} mm (it is {D:.3f} mm away)"
        ), g["reach_outer"]
    if status == Status.INSIDE_REACH:
        D = g["reach_inner"] - d
        return (
            f"target {_fmt(p)} mm is {_mm(d)} mm inside the inner reach radius of "
            f"{g['reach_inner']:g} mm (|L2 - L3|) around the shoulder at {sh} mm "
            f"(it is {D:.3f} mm away)"
        ), g["reach_inner"]
    if status == Status.BASE_AXIS:
        rho = (float(p[0]) ** 2 + float(p[1]) ** 2) ** 0.5
        return (
            f"target {_fmt(p)} mm lies on the base axis (distance {rho:.3g} mm <= tolerance "
            f"{tol:g} mm): theta1 is undefined there; choose the waist angle to use "
            f"(theta1_on_axis)"
        ), float("nan")
    raise ValueError(f"no message for status {status!r}")


def _mm(distance: float) -> str:
    """3 decimals, or 3 significant digits below 1e-3 mm (never "0.000 mm beyond")."""
    return f"{distance:.3f}" if abs(distance) >= 1e-3 else f"{distance:.3g}"


def _fmt(p) -> str:
    return "(" + ", ".join(f"{float(v):g}" for v in p) + ")"

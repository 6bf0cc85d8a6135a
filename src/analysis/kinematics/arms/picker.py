"""The 2P4R camellia-fruit picker of seed 002 (Yang, Li, Gao 2016): FK by POE and the
inverse kinematics, written once against a math namespace.

What is printed (:mod:`analysis.papers.picker`): the topology of section 2 (waist revolute;
a horizontal and a vertical slider on the rotating seat; fore-arm, main-arm link 5,
back-arm, back small-arm, triangle connector, lower and upper small-arms; a parallelogram
"fore-arm parallel to back-arm, link 5 parallel to lower small-arm"; a 3R wrist), the two
chains of section 3.2 (main: vertical slider, back-arm l_AD, lower small-arm l_DF;
secondary: horizontal slider, back small-arm l_C'E'', triangle b_EE'E'', upper small-arm
l_E'F'; the wrist base b_FF' as moving platform), the joint numbering (active
theta1, beta = [theta2, theta9] with theta2 = z on xi2 and theta9 = x on xi9, and the wrist
theta6..theta8; passive alpha = [theta3, theta4, theta5, theta10..theta13]; theta3, theta5
mapped from x, z by eqs. 15-16) and that the FK is a POE of the main chain with those
mappings substituted (eqs. 20-22, called "(18)" in sec. 3.4). The paper has no inverse
kinematics (sec. 5 announces it as future work): the one here is the reconstruction's.

What is inferred (Figure 3, Table 1 and eqs. 10-22 are lost; every dimension is in
``data/arms/picker.toml`` with ``status = "assumed"`` and a reason)::

    arm plane XZ at theta1 = 0 (x forward, z up); all passive axes along +Y
    A  = (x_A, z_A + z)            back-arm hinge on the vertical slider (theta2 = z)
    G  = A + g u(theta3)           link 5's hinge on the back-arm, u(p) = (sin p, cos p)
    D  = A + l_AD u(theta3)        back-arm top = lower small-arm hinge
    B  = (x_A + b + x, z_A + g)    fore-arm hinge on the horizontal slider (theta9 = x)
    |B - G| = b                    link 5 (the loop that fixes theta3)
    C  = B + (D - G) = D + (B - G) fore-arm top on the lower small-arm (parallelogram BGDC)
    F  = D + (l_DF / b)(C - D)     lower small-arm end = wrist-base hinge
    wrist base kept parallel to itself by the second parallelogram pair: C'E''EB and
    EE'F'F (E coaxial with C, C' = B - (d_s, 0) on the slider, E' = E + (0, e_t))
    wrist: xi6 (Z), xi7 (Y), xi8 (X) through W = F + (f, 0); tool marker P = W + (e_tool, 0)

At the reference pose (all theta = 0, Figure 3) the back-arm and fore-arm are vertical, link
5 and the lower small-arm horizontal.

Forward kinematics (:func:`fk`): the passive joints from the sliders (the role of eqs.
15-16), with d = B - A = (b + x, g - z)::

    theta3 = atan2(d_x, d_z) - acos((|d|^2 + g^2 - b^2) / (2 g |d|))   (Figure 3's assembly)
    psi    = atan2(-(B - G)_z, (B - G)_x)                               (lower small-arm)
    theta4 = psi - theta3,  theta5 = -psi                               (wrist base level)
    theta10 = theta3, theta11 = -theta3, theta12 = psi, theta13 = -psi  (secondary chain)

then the product of exponentials of the main chain (seed 002 eq. 9, the twists of eqs. 7-8:
:func:`analysis.kinematics.poe.exp6_entries`, the project's one Rodrigues formula)::

    g_st = exp(xi1 theta1) exp(xi2 z) exp(xi3 theta3) ... exp(xi8 theta8) g_st(0)

Inverse kinematics (:func:`ik`, the pose ``(px, py, pz)`` [mm] and RPY ``(alpha, beta,
gamma)`` [rad] of :mod:`analysis.kinematics.rpy`). The wrist base stays level (theta3 +
theta4 + theta5 = 0), so the tool's rotation is ``Rz(theta1 + theta6) Ry(theta7)
Rx(theta8)``: an RPY wrist, and the marker is ``W + e_tool n`` (n the tool's x axis). With
the pantograph proportion l_AD / g = l_DF / b = k (assumed; :func:`check` refuses other
proportions, for which no closed form of this kind exists: the slider solve becomes a
quartic) the wrist-base hinge is F = (1 - k) A + k B, linear in the sliders and
independent of theta3 (the "small stroke, large travel" of sec. 2)::

    n, o, a  = columns of RPY(alpha, beta, gamma)               (rpy_columns)
    W        = P - e_tool n                                     (the wrist centre)
    theta1   = atan2(W_y, W_x)          (+ pi: "back", the arm plane turned round)
    r        = +-|(W_x, W_y)|,  F = (r - f, W_z)                (the arm plane)
    theta9   = x = (F_x - x_A - k b) / k                        (horizontal slider)
    theta2   = z = (F_z - z_A - k g) / (1 - k)                  (vertical slider)
    theta7   = atan2(-n_z, +-|(n_x, n_y)|)                       (wrist pitch)
    theta6   = atan2(+-n_y, +-n_x) - theta1                      (wrist yaw)
    theta8   = atan2(+-o_z, +-a_z)                               (roll about the jaw axis)

Branches
--------
==============  ==================  ======================================================
name            theta1              wrist
==============  ==================  ======================================================
front           atan2(W_y, W_x)     |theta7| <= 90 deg (the reference pose's: all zero)
front-flip      atan2(W_y, W_x)     |theta7| >= 90 deg: theta6, theta8 turned by 180 deg
back            atan2 + pi          as front, the arm plane turned round (W behind)
back-flip       atan2 + pi          as front-flip
==============  ==================  ======================================================

The back branches put F behind the waist axis, so the horizontal slider must reach
x < -(x_A + k b + f) / k (-300 mm with the assumed dimensions, whose assumed stroke is -200
.. 250 mm): named because they solve the equations, refused by the strokes (status
``joint-limits``) for this reconstruction. Link 5's other assembly mode (theta3 = atan2 +
acos) is not a branch: with the pantograph it gives the same F, hence the same actuated
joints for the same pose (``tests/kinematics/test_picker_arm.py`` checks it).

Refusals, in the order computed (a PLC jumps at the first that holds): beyond the box (no
configuration reaches it; before any square, so no REAL overflows); the wrist centre on
the waist axis (theta1 undefined); the wrist singular (|theta7| within
:data:`WRIST_TOL_RAD` of 90 deg: only theta6 -+ theta8 is defined); then per side (front or
back) link 5's closure: |B - A| beyond g + b (out of reach), inside |g - b| (inside
reach), or A on B (g = b: the back-arm would turn freely; degenerate). ``outside`` is the
closure's margin [mm] in slider space (how far link 5 would have to stretch), the nearer
side's. theta1, theta6, theta7, theta8 are wrapped to (-pi, pi].
"""

from __future__ import annotations

import math

from analysis.kinematics.dh import compose_blocks, exact_add, exact_mul
from analysis.kinematics.poe import exp6_entries
from analysis.kinematics.rpy import rpy_columns
from analysis.kinematics.status import Status

__all__ = [
    "ACTIVE",
    "AXES",
    "BRANCHES",
    "INPUTS",
    "INPUT_UNITS",
    "LENGTHS",
    "PASSIVE",
    "STARTUP_TARGET",
    "STATUSES",
    "WRIST_TOL_RAD",
    "chains",
    "check",
    "fk",
    "fk_refusal",
    "geometry",
    "ik",
    "passive",
    "points",
    "refusal",
]

BRANCHES = ("front", "front-flip", "back", "back-flip")
INPUTS = ("px", "py", "pz", "alpha", "beta", "gamma")
"""The pose: the measured marker P [mm] in frame S (sec. 4) and the RPY angles [rad] of the
jaw (:mod:`analysis.kinematics.rpy`)."""
INPUT_UNITS = ("mm", "mm", "mm", "rad", "rad", "rad")
STATUSES = (Status.OUT_OF_REACH, Status.INSIDE_REACH, Status.BASE_AXIS, Status.DEGENERATE)
"""Link 5 cannot close (too far, too near), the wrist centre on the waist axis, the wrist
singular or A on B."""
ACTIVE = ("theta1", "theta2", "theta6", "theta7", "theta8", "theta9")
"""The actuated joints in array order: waist, vertical slider z [mm], wrist 6-8, horizontal
slider x [mm] (paper numbering; beta = [theta2, theta9] are the sliders)."""
PASSIVE = ("theta3", "theta4", "theta5", "theta10", "theta11", "theta12", "theta13")
"""The passive joints (the paper's alpha), in that order."""
LENGTHS = ("x_A", "z_A", "g", "l_AD", "b", "l_DF", "d_s", "e_t", "f", "e_tool")
AXES = {
    "vertical_guide": (0.0, 0.0, 1.0),
    "horizontal_guide": (1.0, 0.0, 0.0),
    "arm_axes": (0.0, 1.0, 0.0),
    "wrist_axis6": (0.0, 0.0, 1.0),
    "wrist_axis7": (0.0, 1.0, 0.0),
    "wrist_axis8": (1.0, 0.0, 0.0),
}
"""The axis directions the formulas model (the description's ``[axes]`` must equal them)."""
WRIST_TOL_RAD = 1e-3
"""Within this angle [rad] of theta7 = +-90 deg the wrist is refused as singular: there
theta6 and theta8 are separately ill-defined (an error e in the jaw axis moves them by
~e / cos theta7), and at 1e-3 rad a PLC's float32 arithmetic (relative error 6e-8) already
moves them by ~1e-4 rad, 0.08 pulse at 4000 pulses/rev."""
PANTOGRAPH_RTOL = 1e-12


# --------------------------------------------------------------------------------------------
# the mechanism, in any namespace
# --------------------------------------------------------------------------------------------
def points(P) -> dict:
    """The named points of the mechanism at the reference pose (Figure 3's, all theta = 0),
    ``(x, y, z)`` [mm] of numbers or values of a namespace, from the parameters ``P``."""
    xA, zA, g, lAD, b, lDF = (P[k] for k in ("x_A", "z_A", "g", "l_AD", "b", "l_DF"))
    ds, et, f, e_tool = P["d_s"], P["e_t"], P["f"], P["e_tool"]
    pts = {
        "O": (0.0, 0.0, 0.0),
        "A": (xA, 0.0, zA),
        "G": (xA, 0.0, zA + g),
        "D": (xA, 0.0, zA + lAD),
        "B": (xA + b, 0.0, zA + g),
        "C": (xA + b, 0.0, zA + lAD),
        "F": (xA + lDF, 0.0, zA + lAD),
    }
    pts["C'"] = (pts["B"][0] - ds, 0.0, pts["B"][2])
    pts["E"] = pts["C"]
    pts["E''"] = (pts["C"][0] - ds, 0.0, pts["C"][2])
    pts["E'"] = (pts["C"][0], 0.0, pts["C"][2] + et)
    pts["F'"] = (pts["F"][0], 0.0, pts["F"][2] + et)
    pts["W"] = (pts["F"][0] + f, 0.0, pts["F"][2])
    pts["P"] = (pts["W"][0] + e_tool, 0.0, pts["W"][2])
    return pts


def _revolute(w, q) -> tuple:
    """A revolute twist (omega, -omega x q) through point ``q`` (seed 002 eq. 7)."""
    # v = q x omega = -(omega x q); exact_mul drops the exact zeros of the axis directions
    v = (
        exact_add(exact_mul(q[1], w[2]), exact_mul(-1.0, exact_mul(q[2], w[1]))),
        exact_add(exact_mul(q[2], w[0]), exact_mul(-1.0, exact_mul(q[0], w[2]))),
        exact_add(exact_mul(q[0], w[1]), exact_mul(-1.0, exact_mul(q[1], w[0]))),
    )
    return (tuple(w), v)


def _prismatic(v) -> tuple:
    """A prismatic twist (0, v) (seed 002 eq. 8)."""
    return ((0.0, 0.0, 0.0), tuple(v))


def chains(P) -> dict:
    """The twists of both chains at the reference pose and their home frames.

    ``main``: xi1 .. xi8 (waist Z, vertical slider, theta3 at A, theta4 at D, theta5 at F,
    theta6 Z / theta7 Y / theta8 X at W), home ``main_home`` = the marker P (identity
    rotation, eq. 17's role). ``secondary``: xi1, xi9 (horizontal slider), xi10 .. xi13 at
    C', E'', E', F', home ``secondary_home`` = F' on the wrist base. Each twist is
    ``(omega, v)`` of numbers or namespace values.
    """
    pt, y = points(P), AXES["arm_axes"]
    main = [
        _revolute((0.0, 0.0, 1.0), (0.0, 0.0, 0.0)),
        _prismatic(AXES["vertical_guide"]),
        _revolute(y, pt["A"]),
        _revolute(y, pt["D"]),
        _revolute(y, pt["F"]),
        _revolute(AXES["wrist_axis6"], pt["W"]),
        _revolute(AXES["wrist_axis7"], pt["W"]),
        _revolute(AXES["wrist_axis8"], pt["W"]),
    ]
    secondary = [
        main[0],
        _prismatic(AXES["horizontal_guide"]),
        _revolute(y, pt["C'"]),
        _revolute(y, pt["E''"]),
        _revolute(y, pt["E'"]),
        _revolute(y, pt["F'"]),
    ]
    return {
        "main": main,
        "main_home": pt["P"],
        "secondary": secondary,
        "secondary_home": pt["F'"],
    }


def passive(m, z, x, P) -> dict:
    """The passive joints [rad] from the sliders z (theta2), x (theta9) [mm] (eqs. 15-16's
    role), in namespace ``m``: :data:`PASSIVE` by name, plus ``valid`` (link 5 closes) and
    ``R5`` = |B - A| [mm]. Figure 3's assembly mode (theta3 = atan2 - acos)."""
    g, b = P["g"], P["b"]
    dx = m.let("link5_dx", b + x)
    dz = m.let("link5_dz", g - z)
    R = m.let("R5", m.sqrt(dx * dx + dz * dz))
    valid = m.and_(m.le(R, g + b), m.and_(m.ge(R, m.abs(g - b)), m.gt(R, 0.0)))
    Rs = m.select(m.gt(R, 0.0), R, 1.0)
    c = m.clip((R * R + (g * g - b * b)) / (2.0 * g * Rs), -1.0, 1.0)
    t3 = m.let("theta3", m.atan2(dx, dz) - m.acos(c))
    bg_x = dx - g * m.sin(t3)  # B - G in the arm plane (x, z)
    bg_z = dz - g * m.cos(t3)
    psi = m.let("psi", m.atan2(-bg_z, bg_x))
    return {
        "theta3": t3,
        "theta4": psi - t3,
        "theta5": -psi,
        "theta10": t3,
        "theta11": -t3,
        "theta12": psi,
        "theta13": -psi,
        "valid": valid,
        "R5": R,
    }


def _exp(m, twist, th):
    """exp([xi] th) as a 3x4 block (:func:`analysis.kinematics.poe.exp6_entries`)."""
    w, v = twist
    return exp6_entries(w, v, th, m.sin, m.cos)


def _apply(T, p) -> tuple:
    """T (3x4 block) applied to point p."""
    return tuple(
        exact_add(
            exact_add(
                exact_add(exact_mul(T[i][0], p[0]), exact_mul(T[i][1], p[1])),
                exact_mul(T[i][2], p[2]),
            ),
            T[i][3],
        )
        for i in range(3)
    )


def _product(m, twists, values) -> list:
    """The prefix products exp(xi1 q1) ... exp(xi_k q_k), k = 1 .. len (3x4 blocks)."""
    out, T = [], None
    for tw, q in zip(twists, values, strict=True):
        E = _exp(m, tw, q)
        T = E if T is None else compose_blocks(T, E)
        out.append(T)
    return out


DRAWING = ("O", "A", "G", "B", "C", "D", "G", "D", "F", "W", "P")
"""The order :func:`fk` gives the points in: one polyline that draws every link (the seat
O-A, the back-arm A-G-D, link 5 G-B, the fore-arm B-C, the lower small-arm D-C-F, the wrist
F-W, the jaw W-P); the back-arm's upper part G-D is drawn twice."""


def fk(m, q, P) -> dict:
    """Forward kinematics by POE (seed 002 eqs. 9, 20-22) in namespace ``m``.

    ``q`` = (theta1, z, theta6, theta7, theta8, x) (:data:`ACTIVE`) [rad | mm]. Returns
    ``frames`` (the points of :data:`DRAWING` in frame S [mm], the marker P last),
    ``rotation`` (the jaw's 3x3 rows), ``valid`` (link 5 closes), ``points`` {name:
    point} and ``joints`` {name: value} for all thirteen joints.
    """
    t1, z, t6, t7, t8, x = q
    pas = passive(m, z, x, P)
    ch = chains(P)
    joints = {"theta1": t1, "theta2": z, "theta6": t6, "theta7": t7, "theta8": t8, "theta9": x}
    joints.update({k: pas[k] for k in PASSIVE})
    main_q = [joints[f"theta{j}"] for j in range(1, 9)]
    T = _product(m, ch["main"], main_q)
    home = points(P)
    carried = {"O": home["O"], "A": _apply(T[1], home["A"])}
    for name, k in (("G", 2), ("D", 2), ("C", 3), ("F", 3), ("W", 4)):
        carried[name] = _apply(T[k], home[name])
    carried["P"] = _apply(T[7], home["P"])
    S1 = _product(m, ch["secondary"][:2], [t1, x])
    carried["B"] = _apply(S1[1], home["B"])
    rot = tuple(tuple(T[7][i][j] for j in range(3)) for i in range(3))
    return {
        "frames": [carried[k] for k in DRAWING],
        "rotation": rot,
        "valid": pas["valid"],
        "points": carried,
        "joints": joints,
    }


def fk_refusal(q, P) -> str:
    """Why configuration ``q`` (6,) has no pose: link 5 cannot close."""
    g, b = P["g"], P["b"]
    z, x = float(q[1]), float(q[5])
    R = math.hypot(b + x, g - z)
    return (
        f"sliders z = {z:g} mm, x = {x:g} mm: |B - A| = {R:.3f} mm is outside "
        f"[{abs(g - b):g}, {g + b:g}] mm (link 5, b = {b:g} mm, cannot reach the back-arm at "
        f"g = {g:g} mm)"
    )


# --------------------------------------------------------------------------------------------
# the contract
# --------------------------------------------------------------------------------------------
def _pantograph(P) -> float:
    return P["l_AD"] / P["g"]


def check(P) -> None:
    """Reject parameters the closed form cannot use (ValueError naming the value): lengths
    must be positive (x_A, z_A any), the proportion l_AD / g = l_DF / b (the pantograph: the
    slider solve is linear only then) with k != 1, and the description's axes the modelled
    ones (:data:`AXES`)."""
    for name in LENGTHS:
        if name not in P:
            raise ValueError(f"picker: parameter {name} is missing")
        if name not in ("x_A", "z_A") and not P[name] > 0:
            raise ValueError(f"picker: {name} = {P[name]} mm must be > 0 mm")
    k1, k2 = P["l_AD"] / P["g"], P["l_DF"] / P["b"]
    if not math.isclose(k1, k2, rel_tol=PANTOGRAPH_RTOL):
        raise ValueError(
            f"picker: l_AD / g = {k1:.12g} differs from l_DF / b = {k2:.12g}; the closed-form "
            "IK needs this pantograph proportion (otherwise the wrist-base hinge depends on "
            "theta3 and the slider solve is a quartic)"
        )
    if math.isclose(k1, 1.0, rel_tol=1e-9):
        raise ValueError(
            f"picker: l_AD / g = {k1:g}: with k = 1 the vertical slider does not move the "
            "wrist (F = B), so it cannot be solved for"
        )
    desc = getattr(P, "description", None)
    for name, expected in AXES.items():
        spec = desc.axes.get(name) if desc is not None else None
        if desc is not None and spec is None:
            raise ValueError(f"picker: the description has no axis {name} (expected {expected})")
        if spec is not None and spec.value != expected:
            raise ValueError(
                f"picker: axis {name} = {list(spec.value)}; the closed form models {expected}"
            )


def geometry(P) -> dict:
    """The reference pose's points, the pantograph ratio k, link 5's reach (``link5_outer``
    = g + b, ``link5_inner`` = |g - b| [mm]) and the box beyond which no pose is reachable
    (``reach_box`` [mm], a bound on |px|, |py| and |pz - z_A|)."""
    k = _pantograph(P)
    g, b = P["g"], P["b"]
    # |x| <= g + 2 b and |z| <= 2 g + b where link 5 closes (|b + x|, |g - z| <= g + b)
    radial = abs(P["x_A"]) + k * b + k * (g + 2 * b) + P["f"]
    height = k * g + abs(1 - k) * (2 * g + b)
    return {
        **{k_: tuple(float(v) for v in p) for k_, p in points(P).items()},
        "pantograph": k,
        "link5_outer": g + b,
        "link5_inner": abs(g - b),
        "reach_box": radial + height + P["e_tool"],
    }


def STARTUP_TARGET(P) -> tuple[float, ...]:
    """The reference pose (all joints 0, Figure 3): the marker's position and RPY (0, 0, 0)."""
    from analysis.kinematics.ops import numpy_ops

    p = fk(numpy_ops, [0.0] * 6, P)["frames"][-1]
    return (*(float(v) for v in p), 0.0, 0.0, 0.0)


def ik(m, p, P, *, tol, axis_tol=None, margin_rad=0.0):
    """The four branches for the pose ``p = (px, py, pz, alpha, beta, gamma)``.

    Parameters
    ----------
    m : namespace (:mod:`analysis.kinematics.ops`)
    p : 6 values of ``m``
        Marker position [mm] and RPY angles [rad].
    P : mapping of the lengths [mm] (numbers or values of ``m``)
    tol : float or value of ``m``
        Tolerance [mm] at link 5's reach (negative: refuse a band inside it).
    axis_tol : float, optional
        Distance [mm] of the wrist centre from the waist axis, and of A from B, within
        which the pose is singular (default ``tol``).
    margin_rad : float
        Widens the wrist's singular band :data:`WRIST_TOL_RAD` (the PLC's band).

    Returns
    -------
    dict
        ``branches`` {name: (theta1, z, theta6, theta7, theta8, x)} [rad | mm],
        ``refusals`` of the pose, ``branch_refusals`` (link 5 per side), ``outside`` (the
        nearer side's link-5 margin [mm], > 0 beyond), ``sliders`` {"front"/"back": (z, x)}.

    Examples
    --------
    The reference pose (Figure 3) solves to all zeros on the front branch:

    >>> from analysis.kinematics.ops import numpy_ops as m
    >>> P = {"x_A": 100.0, "z_A": 400.0, "g": 250.0, "l_AD": 1000.0, "b": 250.0,
    ...      "l_DF": 1000.0, "d_s": 80.0, "e_t": 100.0, "f": 100.0, "e_tool": 150.0}
    >>> r = ik(m, (1350.0, 0.0, 1400.0, 0.0, 0.0, 0.0), P, tol=1e-6)
    >>> [round(float(v), 9) + 0.0 for v in r["branches"]["front"]]
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    """
    px, py, pz, alpha, beta, gamma = p
    xA, zA, g, b, f, e_tool = (P[k] for k in ("x_A", "z_A", "g", "b", "f", "e_tool"))
    axis_tol = tol if axis_tol is None else axis_tol
    k = m.let("k", P["l_AD"] / g)
    m.section("box: |px|, |py|, |pz - z_A| <= reach box (farther, no pose is reachable)")
    radial = m.abs(xA) + k * b + k * (g + 2.0 * b) + f
    box = (radial + (k * g + m.abs(1.0 - k) * (2.0 * g + b)) + e_tool) + tol
    out_box = m.any_(m.gt(m.abs(px), box), m.gt(m.abs(py), box), m.gt(m.abs(pz - zA), box))
    refusals = [(Status.OUT_OF_REACH, out_box)]
    m.section("jaw axes n, o, a (RPY); wrist centre W = P - e_tool n; theta1 = atan2(Wy, Wx)")
    (nx, ny, nz), (_, _, oz), (_, _, az) = rpy_columns(m, alpha, beta, gamma)
    wx = m.let("wx", px - e_tool * nx)
    wy = m.let("wy", py - e_tool * ny)
    wz = m.let("wz", pz - e_tool * nz)
    rho = m.let("rho", m.sqrt(wx * wx + wy * wy))
    refusals.append((Status.BASE_AXIS, m.le(rho, axis_tol)))
    theta1 = m.let("theta1", m.atan2(wy, wx))
    m.section("wrist: theta7 = atan2(-n_z, |n_xy|), theta1 + theta6 = atan2(n_y, n_x)")
    cb = m.let("cos_theta7", m.sqrt(nx * nx + ny * ny))
    lock = math.sin(min(WRIST_TOL_RAD + float(margin_rad), math.pi / 2))
    refusals.append((Status.DEGENERATE, m.le(cb, lock)))
    wrist = {  # wrapped: atan2 gives -pi for (-0.0, x < 0), the convention is (-pi, pi]
        "": (m.atan2(ny, nx), m.wrap(m.atan2(-nz, cb)), m.wrap(m.atan2(oz, az))),
        "-flip": (m.atan2(-ny, -nx), m.wrap(m.atan2(-nz, -cb)), m.wrap(m.atan2(-oz, -az))),
    }
    branches, branch_refusals, sliders, outside = {}, {}, {}, {}
    for side in ("front", "back"):
        m.section(f"{side}: sliders from F = (r - f, W_z) = (1 - k) A + k B (pantograph)")
        t1 = theta1 if side == "front" else m.let("theta1_back", m.wrap(theta1 + m.pi))
        fx = (rho if side == "front" else -rho) - f
        x = m.let(f"x_{side}", ((fx - xA) - k * b) / k)
        z = m.let(f"z_{side}", ((wz - zA) - k * g) / (1.0 - k))
        m.section(f"{side}: link 5 closes: |g - b| <= |B - A| <= g + b")
        dx, dz = b + x, g - z
        R = m.let(f"R5_{side}", m.sqrt(dx * dx + dz * dz))
        beyond = m.let(f"beyond_{side}", R - (g + b))
        within = m.let(f"within_{side}", m.abs(g - b) - R)
        conds = [
            (Status.OUT_OF_REACH, m.gt(beyond, tol)),
            (Status.INSIDE_REACH, m.gt(within, tol)),
            (Status.DEGENERATE, m.le(R, axis_tol)),
        ]
        outside[side] = m.select(m.gt(beyond, within), beyond, within)
        sliders[side] = (z, x)
        for suffix, (yaw, t7, t8) in wrist.items():
            name = side + suffix
            t6 = m.wrap(yaw - t1)
            branches[name] = (t1, z, t6, t7, t8, x)
            branch_refusals[name] = conds
    out_f, out_b = outside["front"], outside["back"]
    return {
        "branches": {b_: branches[b_] for b_ in BRANCHES},
        "refusals": refusals,
        "branch_refusals": branch_refusals,
        "outside": m.select(m.lt(out_f, out_b), out_f, out_b),
        "sliders": sliders,
    }


def refusal(status: Status, p, P, *, tol: float, distance: float) -> tuple[str, float]:
    """The one-line reason a pose is refused, naming the pose and the limit, and the limit
    [mm] (link 5's reach crossed; NaN where no length is crossed)."""
    import numpy as np

    from analysis.kinematics.ops import numpy_ops

    pose = tuple(float(v) for v in p)
    where = (
        f"pose ({', '.join(f'{v:g}' for v in pose[:3])}) mm, "
        f"RPY ({', '.join(f'{math.degrees(v):.4g}' for v in pose[3:])}) deg"
    )
    geo = geometry(P)
    with np.errstate(all="ignore"):
        sol = ik(numpy_ops, pose, dict(P), tol=tol)
    z, x = (float(v) for v in sol["sliders"]["front"])
    R = math.hypot(P["b"] + x, P["g"] - z)
    sliders = f"the front solution puts the sliders at z = {z:.3f} mm, x = {x:.3f} mm"
    if status == Status.OUT_OF_REACH:
        box = geo["reach_box"]
        if max(abs(pose[0]), abs(pose[1]), abs(pose[2] - P["z_A"])) > box + tol:
            return (
                f"{where} is beyond the reach box of {box:g} mm (|px|, |py|, |pz - z_A|): no "
                "configuration reaches it"
            ), box
        return (
            f"{where} needs link 5 to stretch {distance:.3f} mm beyond its reach g + b = "
            f"{geo['link5_outer']:g} mm ({sliders}: |B - A| = {R:.3f} mm)"
        ), geo["link5_outer"]
    if status == Status.INSIDE_REACH:
        return (
            f"{where} needs |B - A| {distance:.3f} mm inside |g - b| = {geo['link5_inner']:g} "
            f"mm, where link 5 cannot reach the back-arm ({sliders})"
        ), geo["link5_inner"]
    if status == Status.BASE_AXIS:
        W = [pose[i] - P["e_tool"] * float(c) for i, c in enumerate(_jaw_axis(pose))]
        rho = math.hypot(W[0], W[1])
        return (
            f"{where} puts the wrist centre on the waist axis (distance {rho:.3g} mm <= "
            f"tolerance {tol:g} mm): theta1 is undefined there"
        ), float("nan")
    if status == Status.DEGENERATE:
        n = _jaw_axis(pose)
        if math.hypot(n[0], n[1]) <= math.sin(WRIST_TOL_RAD):
            pitch = math.degrees(math.atan2(-n[2], math.hypot(n[0], n[1])))
            return (
                f"{where} points the jaw axis vertically (theta7 = {pitch:.4f} deg, within "
                f"{math.degrees(WRIST_TOL_RAD):.3g} deg of +-90): the wrist is singular, only "
                "theta6 -+ theta8 is defined"
            ), float("nan")
        return (
            f"{where} puts the back-arm's hinge A on the fore-arm's hinge B (g = b, "
            f"|B - A| = {R:.3g} mm): the back-arm would turn freely"
        ), 0.0
    raise ValueError(f"no message for status {status!r}")


def _jaw_axis(pose) -> tuple[float, float, float]:
    from analysis.kinematics.ops import numpy_ops

    n, _, _ = rpy_columns(numpy_ops, *pose[3:])
    return tuple(float(v) for v in n)

"""The six-axis wrists, in any namespace ``m``: what the last three joints do once the arm
has placed the solved point (:mod:`.positioning`).

Orientations are rotations about the axes at q = 0 (:mod:`.chain`): the tool's rotation is
``R(q) = Rot(w1, q1) ... Rot(w6, q6) R0``, ``R0`` the tool's at q = 0, so with the first
joints known the wrist's share ``Rot(w4, q4) Rot(w5, q5) Rot(w6, q6) = M``,
``M = Rot(w3, -q3) Rot(w2, -q2) Rot(w1, -q1) R R0^T``, is a rotation the subproblems
decompose (Murray, Li and Sastry, sec. 3.2):

- **spherical wrist** (6R-wrist, gantry-wrist: axes 4, 5, 6 through one point, each
  perpendicular to the next): ``Rot(w4, q4) Rot(w5, q5) w6 = M w6`` is PK2 (two rotations
  about meeting axes), two solutions, the wrist not flipped and flipped; then ``q6`` by PK1
  from what is left, ``Rot(w6, q6) w5 = Rot(w5, -q5) Rot(w4, -q4) M w5``;
- **the Universal Robots wrist** (6R-parallel: axes 2, 3, 4 parallel to ``u``, axis 5
  perpendicular to them, axis 6 perpendicular to axis 5): rotations about ``u`` keep ``u``,
  so ``u . Rot(w5, q5) w6 = u . a6`` (``a6`` axis 6 as the pose puts it, turned back by the
  waist) gives ``q5 = phi0 +- acos(u . a6)`` (PK3's cosine); ``Rot(w6, q6) (R0 R^T Rot(w1,
  q1) u) = Rot(w5, -q5) u`` gives ``q6`` (PK1); axis 5 as the pose then puts it gives the
  pitch of the parallel axes (:meth:`.positioning.WaistArm._pitch`).

Taking ``q6`` from what the pose leaves (not from its own entries of ``M``) keeps the pose
exact at any wrist angle: near the flip (axis 6 along axis 4, or along the parallel axes)
``q4`` is set only to ``eps / sin(q5)`` by round-off, and ``q6`` absorbs it, so the solution
still reaches the pose to round-off. On the flip itself ``q4 + q6`` (``q6 - q4``) is what
the pose fixes, not each: the branch is refused there (``degenerate``) within
:data:`WRIST_TOL_RAD` of it, widened by :data:`WRIST_BAND` times the PLC's angular margin.
"""

from __future__ import annotations

import math

import numpy as np

from analysis.kinematics.derive import subproblems as sp
from analysis.kinematics.derive.positioning import apply_columns, mat_vec, transpose_apply
from analysis.kinematics.dh import exact_cos_sin

__all__ = [
    "WRISTS",
    "WRIST_BAND",
    "WRIST_TOL_RAD",
    "flipped",
    "half_turn",
    "pick_noflip",
    "spherical",
    "ur_pitch",
    "ur_q5",
    "wrist_band",
]  # fmt: skip

WRISTS = ("noflip", "flip")
"""The wrist's two solutions: ``noflip`` the one whose middle joint (q5) has a sine >= 0,
``flip`` the other (q4 and q6 turned by about pi, q5 negated, where the wrist's axes are
perpendicular)."""
WRIST_TOL_RAD = 1e-9
"""The flip (the sine of the angle between the axes it aligns) counts as reached within this
[rad]: there float64 round-off leaves ``q4`` uncertain by ~1e-7 rad (``eps / sin``), as the
base axis is reached within 1e-6 mm of a 1e3 mm arm."""
WRIST_BAND = 50.0
"""The PLC's refusal band about the flip, in PLC angular margins (``margin_rad``, 2e-5 rad:
1e-3 rad): REAL arithmetic leaves ``q4`` and ``q6`` uncertain by ~6e-8 / sin(q5) rad (measured
on the ST engine), which stays below a tenth of a pulse of a 4000-pulse drive only from about
1e-3 rad."""


def wrist_band(margin_rad):
    """The flip's refusal band [rad] for a solve with the angular margin ``margin_rad``."""
    return WRIST_TOL_RAD + WRIST_BAND * margin_rad


def _turn_back(m, axes, qs, vec):
    """``Rot(w_k, -q_k) ... Rot(w_1, -q_1) vec`` for joints given as ``(cos, sin)``."""
    for w, (c, s) in zip(axes, qs, strict=True):
        vec = sp.rotate(tuple(w), vec, c, -s)
    return vec


def pick_noflip(m, sin_a, a, b):
    """Branches ``a`` and ``b`` (tuples of joint values; ``sin_a`` the sine of ``a``'s q5)
    named: ``noflip`` the one whose q5 has a sine >= 0 (``a`` where both do), ``flip`` the
    other."""
    first = m.ge(sin_a, 0.0)
    noflip = tuple(m.select(first, x, y) for x, y in zip(a, b, strict=True))
    flip = tuple(m.select(first, y, x) for x, y in zip(a, b, strict=True))
    return {"noflip": noflip, "flip": flip}


def spherical(m, axes, R0T, cols, turns, tag: str):
    """The spherical wrist of one arm branch: ``({"noflip": (q4, q5, q6), "flip": ...},
    flip)`` with ``flip`` the sine of the angle between axis 6 (where the pose puts it) and
    axis 4, 0 on the flip.

    ``axes`` are the six (or, for a gantry, the three wrist axes last of any count) joint
    axes at q = 0, ``turns`` the ``(cos, sin)`` of the joints before the wrist (their axes
    the first ``len(turns)`` of ``axes``, revolute; a gantry's prismatic joints turn nothing).
    """
    w4, w5, w6 = (tuple(a) for a in axes[-3:])
    first = axes[: len(turns)]
    v = _turn_back(m, first, turns, apply_columns(cols, mat_vec(R0T, w6)))  # M w6
    x = _turn_back(m, first, turns, apply_columns(cols, mat_vec(R0T, w5)))  # M w5
    alpha = m.let(f"wrist_along_{tag}", sp.dot(w4, v))
    gam = m.let(f"wrist_flip_{tag}", m.sqrt(sp.norm_sq(sp.cross(w4, v))))
    z = sp.add(sp.scale(alpha, w4), sp.scale(gam, tuple(np.cross(w4, w5))))
    q5, c5, s5 = sp.pk1_cs(m, w5, w6, z)
    q4, c4, s4 = sp.pk1_cs(m, w4, z, v)
    y = _turn_back(m, (w4, w5), ((c4, s4), (c5, s5)), x)
    q6 = m.wrap(sp.pk1(m, w6, w5, y))
    picked = pick_noflip(m, s5, (m.wrap(q4), m.wrap(q5), q6),
                         flipped(m, (w4, w5, w6), q4, q5, q6))  # fmt: skip
    for w in WRISTS:
        picked[w] = tuple(m.let(f"theta{4 + k}_{tag}_{w}", q) for k, q in enumerate(picked[w]))
    return picked, gam


def flipped(m, axes, q4, q5, q6) -> tuple:
    """The other solution of a wrist whose middle axis is perpendicular to the two others
    (``axes`` w4, w5, w6 at q = 0; ``q4, q5, q6`` one solution, q4 and q5 in (-3 pi, 3 pi)):
    ``(q4 + pi, -q5 - 2 phi, q6 + pi)`` wrapped, ``phi`` the angle about w5 from w4 to w6
    at q = 0 (0 where they are aligned, as on the PUMA).

    Why: Rot(w4, pi) turns w5 round, so ``Rot(w4, pi) Rot(w5, a) = Rot(w5, -a) Rot(w4, pi)``,
    and ``Rot(w4, pi) Rot(w6, pi) = Rot(w5, 2 phi)`` (two half turns about axes ``phi``
    apart, both across w5): ``Rot(w4, q4 + pi) Rot(w5, -q5 - 2 phi) Rot(w6, q6 + pi)`` is
    ``Rot(w4, q4) Rot(w5, q5) Rot(w6, q6)``. The two solutions of the subproblems (the
    rotation about w5 that puts w6 on either of the two directions that meet the pose) are
    these; deriving the second costs two additions instead of three atan2 and two square
    roots.
    """
    w4, w5, w6 = (np.asarray(a, dtype=float) for a in axes)
    phi = float(np.arctan2(np.dot(w5, np.cross(w4, w6)), np.dot(w4, w6)))
    c2, s2 = exact_cos_sin(2.0 * phi)
    two_phi = math.atan2(s2, c2)  # 2 phi in (-pi, pi], exactly 0 or pi where phi is square
    return (half_turn(m, m.wrap(q4)), m.wrap(-m.wrap(q5) - two_phi), half_turn(m, q6))


def half_turn(m, q):
    """``q + pi`` wrapped to (-pi, pi] (``q`` in (-2 pi, 2 pi)): a joint of the other wrist
    solution (:func:`flipped`; the UR wrist's q6 and pitch, the same relation with the
    parallel axes as w4)."""
    return m.wrap(q + np.pi)


def ur_q5(m, u, w5, w6, a6_1, tag: str):
    """The Universal Robots wrist's q5, ``phi0 + k atan2(|u x a6|, u . a6)`` for the
    not-flipped (``k = sign(cos phi0)``) and the flipped wrist (``-k``) (``a6_1``: axis 6
    where the pose puts it, turned back by the waist; ``phi0`` the angle about axis 5 from
    axis 6 to the parallel axes at q = 0: 0 or pi on every UR, where the not-flipped q5 has a
    sine >= 0), and the sine of the angle between axis 6 and the parallel axes (0 on the
    flip)."""
    s = m.let(f"wrist_flip_{tag}", m.sqrt(sp.norm_sq(sp.cross(u, a6_1))))
    c = sp.dot(u, a6_1)
    gam = m.atan2(s, c)
    phi0 = float(np.arctan2(np.dot(u, np.cross(w5, w6)), np.dot(u, w6)))
    c0, s0 = (float(v) for v in exact_cos_sin(phi0))
    k = 1.0 if c0 >= 0 else -1.0
    out = []
    for sign in (k, -k):  # cos and sin of phi0 + sign gamma (|a6| = 1: (c, s) are gamma's)
        ks = sp.mul(sign, s)
        out.append((m.wrap(phi0 + sign * gam), sp.mul(c0, c) - sp.mul(s0, ks),
                    sp.mul(s0, c) + sp.mul(c0, ks)))  # fmt: skip
    return tuple(out), s


def ur_pitch(m, cf, cols, c1, s1, cs5, tag: str):
    """q6 (PK1) and axis 5 where the pose puts it, turned back by the waist (for the pitch,
    :meth:`.positioning.WaistArm._pitch`), for one wrist solution (``cs5``: cos and sin of
    its q5)."""
    st = cf.structure
    w1, u, w5, w6 = cf._w1, cf._u, cf._w5, tuple(st.axes[5])
    u1 = sp.rotate(w1, u, c1, s1)
    x = mat_vec(st.rotation, transpose_apply(cols, u1))
    y = sp.rotate(w5, u, cs5[0], -cs5[1])
    q6, c6, s6 = sp.pk1_cs(m, w6, x, y)
    q6 = m.let(f"theta6_{tag}", m.wrap(q6))
    a5 = sp.rotate(w6, w5, c6, -s6)
    a5_1 = sp.rotate(w1, apply_columns(cols, mat_vec(cf._R0T, a5)), c1, -s1)
    return q6, a5_1

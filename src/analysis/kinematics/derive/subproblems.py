"""The Paden-Kahan subproblems, written once against a math namespace ``m``.

Vectors are 3-tuples whose entries are plain numbers (the joint axes: rotations of a D-H
chain at q = 0 depend on its twists and offsets only) or values of ``m`` (positions: the
lengths may be traced parameters, SymPy symbols or floats). Plain-number zeros and ones are
kept exact (:func:`analysis.kinematics.dh.exact_mul`), so a recorded closed form carries no
``0 * x`` terms of the structural zeros of a D-H table.

Subproblems (Murray, Li & Sastry, *A Mathematical Introduction to Robotic Manipulation*,
sec. 3.2; the names are Paden's and Kahan's), in the form the families of
:mod:`analysis.kinematics.derive` use them:

- **PK1** (:func:`pk1`): the rotation about a unit axis ``w`` that turns ``x`` onto ``y``
  (both seen from a point of the axis): ``atan2(w . (x' x y'), x' . y')`` with ``'`` the parts
  across ``w``; one solution. Used for the waist angle (no lateral offset), the shoulder,
  the parallel-axis pitch of a 5-DOF hand and its roll.
- **PK3** (:func:`pk3_cos`): the rotation about an axis that puts a point at a given distance
  from another: in the plane of the parallel axes this is the law of cosines of the elbow,
  ``cos(bend) = (d^2 - La^2 - Lb^2) / (2 La Lb)``; two solutions, +- the bend.
- **PK3 against a plane** (:func:`waist_offset`): the rotation about the waist axis that puts
  the target at a given signed distance ``l`` from the arm plane (the lateral offset of a
  shoulder): ``F = +-sqrt(rho^2 - l^2)`` along the forward direction; two solutions (Elias
  and Wen's "subproblem 4", the plane being the limit of PK3's sphere).
- **PK2** (two rotations about intersecting axes) is not needed by these families: their
  second axis is always parallel to the next one.

Every function is a few lines of arithmetic, comparisons and ``select``: the compiled
kernel vectorizes them and the PLC program lowers them to straight-line REAL code.
"""

from __future__ import annotations

from analysis.kinematics.dh import exact_add, exact_mul

__all__ = [
    "across",
    "add",
    "cross",
    "dot",
    "mul",
    "norm_sq",
    "pk1",
    "pk1_cs",
    "pk3_cos",
    "rotate",
    "scale",
    "sub",
    "waist_offset",
]


def mul(k, x):
    """``k x`` for a plain number ``k`` and a value of ``m``: exact where ``k`` is 0 or +-1,
    as the recorder simplifies it (a numpy ``0.0 * x`` is an array of zeros that would turn
    a constant it meets into a REAL of the PLC model, where the program folds it)."""
    return exact_mul(k, x)


def add(a, b) -> tuple:
    """a + b."""
    return tuple(exact_add(x, y) for x, y in zip(a, b, strict=True))


def sub(a, b) -> tuple:
    """a - b."""
    return tuple(exact_add(x, exact_mul(-1.0, y)) for x, y in zip(a, b, strict=True))


def scale(k, a) -> tuple:
    """k a (k a number or a value of ``m``)."""
    return tuple(exact_mul(k, x) for x in a)


def dot(a, b):
    """a . b, summed in index order (x, then y, then z)."""
    out = 0.0
    for x, y in zip(a, b, strict=True):
        out = exact_add(out, exact_mul(x, y))
    return out


def cross(a, b) -> tuple:
    """a x b."""
    return (
        exact_add(exact_mul(a[1], b[2]), exact_mul(-1.0, exact_mul(a[2], b[1]))),
        exact_add(exact_mul(a[2], b[0]), exact_mul(-1.0, exact_mul(a[0], b[2]))),
        exact_add(exact_mul(a[0], b[1]), exact_mul(-1.0, exact_mul(a[1], b[0]))),
    )


def norm_sq(a):
    """|a|^2."""
    return dot(a, a)


def across(w, a) -> tuple:
    """The part of ``a`` across the unit axis ``w``: ``a - w (w . a)``."""
    return sub(a, scale(dot(w, a), w))


def rotate(w, a, c, s) -> tuple:
    """``a`` turned about the unit axis ``w`` by the angle whose cosine and sine are ``c``,
    ``s`` (Rodrigues): ``a c + (w x a) s + w (w . a)(1 - c)``."""
    wa = dot(w, a)
    return add(
        add(scale(c, a), scale(s, cross(w, a))),
        scale(exact_mul(wa, exact_add(1.0, exact_mul(-1.0, c))), w),
    )


def pk1(m, w, x, y):
    """PK1: the angle [rad] of the rotation about the unit axis ``w`` that turns ``x`` onto
    the direction of ``y`` (their parts across ``w``), in (-pi, pi].

    ``atan2(w . (x y), x' . y')``, ``x' = x - w (w . x)``; ``x'`` need not be a unit vector.
    Where ``x'`` or ``y'`` is zero the angle is undefined (atan2(0, 0) = 0): the callers
    refuse those targets first.
    """
    return m.atan2(dot(w, cross(x, y)), dot(across(w, x), y))


def pk1_cs(m, w, x, y):
    """:func:`pk1` with the angle's cosine and sine: ``(angle, c, s)``, ``c, s`` the atan2
    arguments over their length (no trigonometry; ``(1, 0)`` where both are 0, the angle
    atan2(0, 0) = 0 then), for the rotations that follow."""
    ys, xs = dot(w, cross(x, y)), dot(across(w, x), y)
    r = m.sqrt(xs * xs + ys * ys)
    nonzero = m.gt(r, 0.0)
    safe = m.select(nonzero, r, 1.0)
    return m.atan2(ys, xs), m.select(nonzero, xs / safe, 1.0), ys / safe


def pk3_cos(m, d2, la2, lb2, la, lb, precise=False):
    """PK3 in the plane: the cosine of the bend at the elbow, from the squared distance
    ``d2`` of the wrist from the shoulder and the squared link lengths (law of cosines),
    clipped to [-1, 1] (a target on a reach sphere within the tolerance lies on it).

    Returns ``(c, gamma, s)``: the cosine, the bend ``gamma = acos(c)`` in [0, pi] and
    ``sin(gamma) = sqrt((1 - c)(1 + c)) >= 0``. The two solutions are the bends ``+gamma``
    and ``-gamma`` (the elbow on either side of the shoulder-wrist line).

    ``precise`` (the float64 backends): ``1 - c`` and ``1 + c`` are computed in factored form,
    ``(La + Lb - d)(La + Lb + d) / den`` and ``(d - |La - Lb|)(d + |La - Lb|) / den``, and
    ``gamma = atan2(s, c)``, as the palletizer's hand-written beta1
    (kinematics/arms/palletizer.py): from ``c`` they keep half the digits where ``c`` nears
    -1 or 1, and with La = Lb that is the wrist near the
    shoulder, where an error in the bend moves the wrist by La times it (a derived palletizer
    missed a target 2.0e-6 mm from its shoulder by 2.0e-6 mm against the 1e-6 mm tolerance;
    tests/hostile/test_hostile.py, class 7). Otherwise ``acos(c)`` and ``sqrt((1 - c)(1 + c))``,
    the PLC programs' form.
    """
    den = 2.0 * (la * lb)
    c = m.clip((d2 - (la2 + lb2)) / den, -1.0, 1.0)
    if not precise:
        return c, m.acos(c), m.sqrt((1.0 - c) * (1.0 + c))
    d = m.sqrt(d2)
    outer, inner = la + lb, m.abs(la - lb)
    om = m.clip((outer - d) * (outer + d) / den, 0.0, 2.0)  # 1 - c
    op = m.clip((d - inner) * (d + inner) / den, 0.0, 2.0)  # 1 + c
    s = m.sqrt(om * op)
    return c, m.atan2(s, c), s


def waist_offset(m, rho2, ell):
    """PK3 against a plane: the forward component ``sqrt(rho^2 - l^2) >= 0`` of a target at
    distance ``rho`` from the waist axis once the waist has turned it to the signed lateral
    distance ``l`` from the arm plane (``rho^2 < l^2``: the target lies inside the cylinder
    the offset keeps it out of; clipped to 0 there, the caller refuses it)."""
    t = rho2 - ell * ell
    return m.sqrt(m.select(m.lt(t, 0.0), 0.0, t))

"""A closed form derived from the D-H table, for the seed papers' families and the ones
engineers own (six-axis industrial arms, SCARAs, planar arms, gantries).

A description without ``closed_form`` (``data/arms/*.toml`` or a user's file) gets one
derived here (:func:`derive`, called by the loader, :func:`analysis.kinematics.loader.
load_arm`, which keeps it in the arm). The result is the same kind of closed form as the
hand-written ones (:mod:`analysis.kinematics.arms`): one body written against the math
namespace ``m``, so the derived arm gets the numpy solver, the compiled kernel, the float32
model, SymPy and the PLC programs without further code. Outside the families the
description still loads (its FK, Pinocchio model and URDF need no closed form) and asking
the arm for IK raises the reason, naming the family rule it breaks; a hand-written closed
form (``closed_form = "<module>"``) is the route for any other arm.

Method: subproblem decomposition (Paden-Kahan, :mod:`.subproblems`) on the chain's screws at
q = 0 (:mod:`.chain`). Every family has a waist (axis 1, direction ``w1``) and a set of
parallel axes (2 || 3 [|| 4], direction ``u``), so the decomposition is the same:

1. **the waist**. The solved point ``w`` (the target; a 5R arm: the point of the roll axis
   nearest the tool, where the pose puts it) keeps its component along ``u`` whatever the
   parallel joints do. With ``x = w - q1`` in the basis ``g1 = e x w1`` (forward), ``e``
   (``u`` across ``w1``, normalised) and ``w1``, the waist must turn ``x`` to the lateral
   offset ``l`` of the arm plane: PK3 against a plane, ``F = +-sqrt(rho^2 - l^2)`` forward,
   ``theta1 = atan2(F x_e - l x_g, F x_g + l x_e)``. Without a lateral offset (every seed
   arm: ``l = 0`` structurally) this is PK1, ``theta1 = atan2(x_e, x_g)`` and ``+ pi``, the
   seeds' ``atan2(Py, Px)`` (seed 000 eq. 6, seed 001 eqs. 1 and 6, seed 004 sec. 4.2).
   The point turned back to the arm plane at ``theta1 = 0`` is
   ``q1 + F g1 + l e + (w1 . x) w1``: no trigonometry.
2. **the kept pitch** (4R, 5R). The rotation of the last parallel link about ``u`` is the
   sum ``psi = sum sigma_i q_i`` (``sigma_i = +-1``: the axis along or against ``u``). 4R:
   ``psi`` is the description's decision (``[derive] keep``, PK1 at load: seed 001's
   "gripper kept level", eq. 12 corrected, is ``psi = pi/2``). 5R: PK1 turning the roll axis
   at q = 0 onto where the pose puts it; a roll axis out of the set the arm can reach is
   refused (``orientation``, as seed 004's closed form) or, with ``orientation_tol=None``,
   projected onto the nearest. A roll axis accepted within ``orientation_tol`` (default
   1e-4 rad) is projected as well, about the solved point: the tool point then misses its
   target by up to the tool offset times the sine of that angle (8.8e-3 mm measured on a
   random 5R arm, tests/hostile/test_hostile.py class 7; the GR-1's hand-written form keeps
   the tool point and turns the hand only). The solved point of the plane is then axis 4's point,
   ``w - R(u, psi)(w_home - q4_home)``.
3. **the elbow**: PK3, the law of cosines of the two links across the parallel axes
   (lengths ``La``, ``Lb``), ``cos(bend) = (d^2 - La^2 - Lb^2) / (2 La Lb)``, the bend
   ``+-acos``: seed 000 eqs. 9-10, seed 001 eq. 3, seed 004's c3.
4. **the shoulder**: PK1 about axis 2 from the arm at q2 = 0 (upper arm plus the bent
   forearm) onto the solved point: seed 000 eqs. 15-19, seed 001 eq. 3, seed 004's theta2.
5. the last parallel joint ``q4 = sigma_4 (psi - sigma_2 q2 - sigma_3 q3)`` (seed 001
   eq. 12, seed 004's theta4); 5R: the roll by PK1 about axis 5 (seed 004's theta5).

Branches, named as the seeds name them: the waist "front" (the forward direction faces
the target) or "back" (turned by about pi), the elbow "up" or "down". Which way is forward
and how "up" is seen on the back branches are decisions of the description (``[derive]``,
:mod:`.families`); the defaults reproduce seeds 000 and 004 and ``elbow = "arm"``
reproduces seed 001 (``tests/kinematics/test_derive.py`` holds each derived closed form
against the hand-written one, branch by branch).

Refusals, in the order computed (the PLC program jumps at the first that holds): out of the
reach box; for a 3R arm whose shoulder is on the waist axis, beyond or inside the reach
shells; inside the cylinder a lateral offset keeps the target out of; on the waist axis
(``base-axis``; ``theta1_on_axis`` chooses the waist angle); a 5R roll axis out of reach
(``orientation``); then per branch where the front and back solutions differ (4R, 5R): the
solved point beyond or inside its reach, on the shoulder axis (``degenerate``).

The six-axis families extend these steps (:mod:`.positioning` writes them, :mod:`.wrist`
the wrists): an arm with a spherical wrist (PUMA, KUKA, ABB, Fanuc; Pieper's condition) is
the 3R decomposition of its wrist centre, where the pose puts it, then the wrist by PK2 and
PK1 (eight branches: ``<side>-<elbow>-<wrist>``, the wrist ``noflip`` or ``flip``); an arm of
the Universal Robots family is the 4R decomposition of the point where axes 5 and 6 meet,
its pitch from the wrist (q5 from axis 6's angle to the parallel axes, q6 by PK1, the pitch
from axis 5) per wrist solution. The wrist flip (axis 6 along axis 4, or along the parallel
axes) is refused per branch (``degenerate``), the pose still exact on either side of it.
Planar arms and SCARAs (:mod:`.planar`) and gantries (:mod:`.gantry`) have closed forms of
their own on the same subproblems; :mod:`.families` lists every family and its inputs, and
:mod:`.forms` picks the class.

Angles: theta1, theta2 and the pitch joints are wrapped to (-pi, pi]; theta3 is not wrapped
where the forearm continues the upper arm at q = 0 (the seeds' case: ``-/+acos`` by branch,
continuous at the folded elbow), else wrapped.

Why derived here rather than by a library: EAIK (the ``bench`` extra) derives and solves
such decompositions in C++, but yields numbers, not a closed form the project's backends can
record (compiled kernel, float32 model, PLC programs); it is the oracle instead
(:mod:`.oracle`), with pyplcopen's own kinematics (:mod:`.plcopen_oracle`) and IK-Geo
(``make bench``). IKFast generates C++ and needs OpenRAVE.
"""

from __future__ import annotations

import hashlib
import json

from analysis.kinematics.derive.chain import home
from analysis.kinematics.derive.closed_form import DerivedClosedForm
from analysis.kinematics.derive.families import FAMILIES, NotDerivable, classify
from analysis.kinematics.derive.forms import build
from analysis.kinematics.ops import numpy_ops

__all__ = ["DERIVED", "FAMILIES", "DerivedClosedForm", "NotDerivable", "derive"]

DERIVED = "derived"
"""The name prefix of a derived closed form (``derived:<family>-<digest>``)."""


def _digest(*parts) -> str:
    text = json.dumps(parts, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _key(desc) -> tuple:
    return (desc.convention, [dict(r) for r in desc.rows], sorted(desc.parameters), desc.derive)


def derive(desc) -> DerivedClosedForm:
    """The closed form derived from the D-H rows of description ``desc`` (whatever its
    ``closed_form``), named ``derived:<family>-<digest of the structure>``; NotDerivable
    (a ValueError) with the reason for a chain outside the families.

    The loader (:func:`analysis.kinematics.loader.load_arm`) calls it once per description
    version and keeps the result in the arm: there is no registry to look it up in."""
    table = desc.dh_table()
    h = home(numpy_ops, table)
    structure = classify(h.axes, h.rotation, desc.derive, h.kinds)
    cf = build("derived:probe", desc, structure)
    cf.__name__ = f"{DERIVED}:{structure.family}-{_digest(_key(desc), cf.flags)}"
    return cf

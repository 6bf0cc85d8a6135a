"""A D-H chain at its home configuration: joint axes (plain numbers) and points on them.

What the derivation reads off a description (:mod:`analysis.kinematics.derive`): the chain's
frames at q = 0 from the one D-H composition (:func:`analysis.kinematics.dh.chain_transforms`),
in the POE picture of :mod:`analysis.kinematics.poe`:

- standard D-H (``A_i = Rz(theta_i) Tz Tx Rx``): joint i turns about z of frame i-1, through
  that frame's origin;
- modified D-H (``A_i = Rx Tx Rz(theta_i) Tz``): joint i turns about z of frame i, through its
  origin;

so that ``T(q) = exp([S1] q1) ... exp([Sn] qn) T(0)`` with the joint variables of the
description (``theta_i = q_i + theta_offset_i``). The axes and the home rotation depend on
the twists and offsets only, which are numbers of the table: they are plain floats here
(exact at multiples of 90 deg). The points and the home position are values of the
namespace ``m`` of the lengths (floats, traced parameters or SymPy symbols).

A prismatic joint moves along the same z axis a revolute one would turn about (its ``d``
grows with the joint value), so its axis is read off the same frame; :attr:`Home.kinds` says
which joint is which.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from analysis.kinematics.dh import DHTable, chain_transforms

__all__ = ["Home", "home"]


@dataclass(frozen=True)
class Home:
    """The chain at q = 0.

    Attributes
    ----------
    axes : tuple of ndarray, shape (3,)
        Unit direction of each joint axis in the base frame (plain floats): the axis a
        revolute joint turns about (positive angles by the right-hand rule), the direction a
        prismatic joint moves along (positive values).
    points : tuple of 3-tuples
        A point on each axis [mm] (values of ``m``): the origin of the D-H frame it is the
        z axis of.
    rotation : ndarray, shape (3, 3)
        Orientation of the last frame (the tool: fixed rows included), plain floats.
    position : 3-tuple
        Origin of the last frame [mm], values of ``m``.
    """

    axes: tuple
    points: tuple
    rotation: np.ndarray
    position: tuple
    kinds: tuple = ()
    """``"revolute"`` or ``"prismatic"`` per joint, in chain order."""


def home(m, table: DHTable) -> Home:
    """The home geometry of ``table`` (whose lengths are values of ``m``)."""
    frames = chain_transforms(m, table)
    identity = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]
    axes, points, kinds = [], [], []
    for k, row in enumerate(table.rows):
        if row.kind == "fixed":
            continue
        kinds.append(row.kind)
        if table.convention == "standard":
            T = frames[k - 1] if k else identity
        else:
            T = frames[k]
        axes.append(np.array([float(T[i][2]) for i in range(3)]))
        points.append((T[0][3], T[1][3], T[2][3]))
    T = frames[-1]
    R = np.array([[float(T[i][j]) for j in range(3)] for i in range(3)])
    return Home(tuple(axes), tuple(points), R, (T[0][3], T[1][3], T[2][3]), tuple(kinds))

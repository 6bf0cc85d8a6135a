"""A Pinocchio model built from a D-H table (standard or modified): the independent check.

Pinocchio (PyPI ``pin``, ``import pinocchio``) composes rigid-body placements with its
own SE(3) algebra, so agreement with :mod:`analysis.kinematics.dh` / :mod:`analysis.kinematics.arm`
is a
cross-check by an established implementation, not a re-run of the same formula. The
model is built from the very :class:`~analysis.kinematics.dh.DHTable` rows the rest of the project
uses: there is no second transcription of the geometry.

Mapping (each revolute row becomes one ``JointModelRZ``, each prismatic row one
``JointModelPZ``; ``M`` is a pending fixed placement carried to the next joint or to the
tool frame)::

    standard  A_i = Rz(theta_i) . [Tz(d) Tx(a) Rx(alpha)]
              joint placement = M . Rz(offset);  then M = Tz(d) Tx(a) Rx(alpha)
              prismatic: A_i = [Rz(offset) Tz(d)] . Tz(q_i) . [Tx(a) Rx(alpha)]
              joint placement = M . Rz(offset) Tz(d);  then M = Tx(a) Rx(alpha)
    modified  A_i = [Rx(alpha) Tx(a) Tz(d)] . Rz(theta_i)
              joint placement = M . Rx(alpha) Tx(a) Tz(d) Rz(offset);  then M = I
              (prismatic: the same placement, the joint Tz(q_i))

A ``fixed`` row (a tool frame) only extends ``M``. The last ``M`` becomes the operational
frame ``"tool"`` on the last joint, so ``oMf[tool]`` equals ``DHTable.fk``.

:func:`build_poe_model` builds the same kind of model from space-frame screw axes and a home
pose instead (revolute and prismatic joints, aligned or not), the independent check of
:mod:`analysis.kinematics.poe`; :class:`PinocchioPOE` evaluates it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import pinocchio as pin

from analysis.kinematics.dh import DHTable
from analysis.kinematics.poe import check_home, check_screws, joint_kinds

__all__ = ["PinocchioArm", "PinocchioPOE", "build_model", "build_poe_model"]

TOOL_FRAME = "tool"


def _rz(angle: float) -> pin.SE3:
    return pin.SE3(pin.utils.rotate("z", angle), np.zeros(3))


def _standard_fixed(row) -> pin.SE3:  # Tz(d) Tx(a) Rx(alpha)
    return pin.SE3(pin.utils.rotate("x", row.alpha), np.array([row.a, 0.0, row.d]))


def _modified_fixed(row) -> pin.SE3:  # Rx(alpha) Tx(a) Tz(d)
    R = pin.utils.rotate("x", row.alpha)
    return pin.SE3(R, np.array([row.a, 0.0, 0.0]) + R @ np.array([0.0, 0.0, row.d]))


def _tz(d: float) -> pin.SE3:
    return pin.SE3(np.eye(3), np.array([0.0, 0.0, d]))


def build_model(table: DHTable) -> pin.Model:
    """Pinocchio model of a D-H chain (paper Table 1; seed 001 eq. 8), one RZ joint per
    revolute row and one PZ joint per prismatic row, with an operational frame ``"tool"``
    at the end of the chain."""
    model = pin.Model()
    model.name = table.name or "dh-chain"
    parent = 0
    pending = pin.SE3.Identity()
    for i, row in enumerate(table.rows):
        if row.kind == "prismatic":
            R = pin.utils.rotate("x", row.alpha)
            if table.convention == "standard":
                place = pending * _rz(row.theta_offset) * _tz(row.d)
                after = pin.SE3(R, np.array([row.a, 0.0, 0.0]))
            else:
                place = pending * _modified_fixed(row) * _rz(row.theta_offset)
                after = pin.SE3.Identity()
            name = row.name or f"joint{i + 1}"
            parent = model.addJoint(parent, pin.JointModelPZ(), place, name)
            pending = after
            continue
        if table.convention == "standard":
            if row.kind == "revolute":
                parent = model.addJoint(
                    parent,
                    pin.JointModelRZ(),
                    pending * _rz(row.theta_offset),
                    row.name or f"joint{i + 1}",
                )
                pending = _standard_fixed(row)
            else:
                pending = pending * _rz(row.theta_offset) * _standard_fixed(row)
        else:
            fixed = _modified_fixed(row) * _rz(row.theta_offset)
            if row.kind == "revolute":
                parent = model.addJoint(
                    parent, pin.JointModelRZ(), pending * fixed, row.name or f"joint{i + 1}"
                )
                pending = pin.SE3.Identity()
            else:
                pending = pending * fixed
    if parent == 0:
        raise ValueError(f"D-H table {table.name!r} has no joint row: nothing to model")
    model.addFrame(pin.Frame(TOOL_FRAME, parent, pending, pin.FrameType.OP_FRAME))
    return model


@dataclass
class PinocchioArm:
    """A Pinocchio model plus its data, with per-configuration FK and Jacobian.

    Pinocchio evaluates one configuration per call, so the per-point loops below are the
    peer that the vectorized :mod:`analysis.kinematics.arm` is measured against (``make bench``).
    """

    table: DHTable

    def __post_init__(self) -> None:
        self.model = build_model(self.table)
        self.data = self.model.createData()
        self.tool_id = self.model.getFrameId(TOOL_FRAME)

    def placement(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Base-to-tool homogeneous transform (4, 4) for one configuration (n,) [rad]."""
        q = np.asarray(q, dtype=float)
        if q.shape != (self.model.nq,):
            raise ValueError(f"configuration has shape {q.shape}; expected ({self.model.nq},)")
        pin.framesForwardKinematics(self.model, self.data, q)
        return self.data.oMf[self.tool_id].homogeneous.copy()

    def _check(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        q = np.asarray(q, dtype=float)
        if q.ndim == 0 or q.shape[-1] != self.model.nq:
            nq = self.model.nq
            raise ValueError(f"configurations have shape {q.shape}; expected (..., {nq})")
        return q

    def fk(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Tool positions [mm] for configurations (..., n): a Python loop over points."""
        q = self._check(q)
        flat = q.reshape(-1, self.model.nq)
        out = np.empty((flat.shape[0], 3))
        for k, qk in enumerate(flat):
            pin.framesForwardKinematics(self.model, self.data, qk)
            out[k] = self.data.oMf[self.tool_id].translation
        return out.reshape(*q.shape[:-1], 3)

    def jacobian(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Positional Jacobian of the tool point [mm/rad], world-aligned, (..., 3, n)."""
        q = self._check(q)
        flat = q.reshape(-1, self.model.nq)
        out = np.empty((flat.shape[0], 3, self.model.nv))
        for k, qk in enumerate(flat):
            J = pin.computeFrameJacobian(
                self.model, self.data, qk, self.tool_id, pin.LOCAL_WORLD_ALIGNED
            )
            out[k] = J[:3]
        return out.reshape(*q.shape[:-1], 3, self.model.nv)


# --------------------------------------------------------------------------- screw axes
_AXIS_NAMES = "XYZ"
_FLIP = {  # rotation by pi about an axis orthogonal to k: maps local +k to world -k
    0: pin.utils.rotate("z", np.pi),
    1: pin.utils.rotate("z", np.pi),
    2: pin.utils.rotate("x", np.pi),
}
ALIGN_TOL = 1e-12
"""An axis counts as aligned with a base axis when its other two components are below this."""


def _aligned_axis(axis: npt.NDArray[np.float64]) -> tuple[int, float] | None:
    """(index, sign) of the base axis ``axis`` lies along, or None."""
    k = int(np.argmax(np.abs(axis)))
    others = np.delete(axis, k)
    if np.all(np.abs(others) <= ALIGN_TOL):
        return k, float(np.sign(axis[k]))
    return None


def build_poe_model(screws: npt.ArrayLike, M: npt.ArrayLike, name: str = "poe-chain") -> pin.Model:
    """Pinocchio model of a serial chain given by space-frame screw axes and a home pose.

    The independent check of :mod:`analysis.kinematics.poe` (seed 002 eq. 9). Joint i gets a
    frame F_i at the home configuration: origin on the axis (``omega x v``, the point
    nearest the base origin) for a revolute joint, at the previous joint's origin for a
    prismatic one. A joint whose axis lies along a base axis is ``JointModelRX/RY/RZ`` or
    ``PX/PY/PZ``; a negative direction (e.g. -y) keeps that joint type with F_i turned by pi
    about an orthogonal axis. Any other axis is ``RevoluteUnaligned``/``PrismaticUnaligned``
    with F_i parallel to the base frame. Placements are ``F_(i-1)^-1 F_i``, the tool frame
    ``"tool"`` sits at ``F_n^-1 M``. Since ``F exp([A] q) = exp([Ad_F A] q) F``, Pinocchio's
    ``oMf[tool]`` equals ``exp([S1]q1)...exp([Sn]qn) M``.

    Parameters
    ----------
    screws : array_like, shape (n, 6)
        Revolute or prismatic screw axes (omega, v), validated by
        :func:`analysis.kinematics.poe.check_screws`.
    M : array_like, shape (4, 4)
        Home pose of the tool frame [mm].
    """
    S = check_screws(screws)
    M = check_home(M)
    kinds = joint_kinds(S)
    model = pin.Model()
    model.name = name
    parent = 0
    prev = pin.SE3.Identity()
    for i, (row, kind) in enumerate(zip(S, kinds, strict=True)):
        axis = row[:3] if kind == "revolute" else row[3:]
        origin = np.cross(row[:3], row[3:]) if kind == "revolute" else prev.translation.copy()
        aligned = _aligned_axis(axis)
        if aligned is None:
            R = np.eye(3)
            joint = (
                pin.JointModelRevoluteUnaligned(axis.copy())
                if kind == "revolute"
                else pin.JointModelPrismaticUnaligned(axis.copy())
            )
        else:
            k, sign = aligned
            R = np.eye(3) if sign > 0 else _FLIP[k]
            prefix = "R" if kind == "revolute" else "P"
            joint = getattr(pin, f"JointModel{prefix}{_AXIS_NAMES[k]}")()
        frame = pin.SE3(R, origin)
        parent = model.addJoint(parent, joint, prev.inverse() * frame, f"joint{i + 1}")
        prev = frame
    model.addFrame(
        pin.Frame(TOOL_FRAME, parent, prev.inverse() * pin.SE3(M), pin.FrameType.OP_FRAME)
    )
    return model


@dataclass
class PinocchioPOE:
    """:func:`build_poe_model` plus data, with per-configuration placements (a loop over
    points: Pinocchio evaluates one configuration per call)."""

    screws: npt.ArrayLike
    M: npt.ArrayLike

    def __post_init__(self) -> None:
        self.model = build_poe_model(self.screws, self.M)
        self.data = self.model.createData()
        self.tool_id = self.model.getFrameId(TOOL_FRAME)

    def placements(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Base-to-tool transforms (..., 4, 4) [mm] for configurations (..., n)."""
        q = np.asarray(q, dtype=float)
        if q.ndim == 0 or q.shape[-1] != self.model.nq:
            raise ValueError(
                f"configurations have shape {q.shape}; expected (..., {self.model.nq})"
            )
        flat = q.reshape(-1, self.model.nq)
        out = np.empty((flat.shape[0], 4, 4))
        for k, qk in enumerate(flat):
            pin.framesForwardKinematics(self.model, self.data, qk)
            out[k] = self.data.oMf[self.tool_id].homogeneous
        return out.reshape(*q.shape[:-1], 4, 4)

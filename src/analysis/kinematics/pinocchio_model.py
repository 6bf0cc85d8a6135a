"""A Pinocchio model built from a D-H table (standard or modified): the independent check.

Pinocchio (PyPI ``pin``, ``import pinocchio``) composes rigid-body placements with its
own SE(3) algebra, so agreement with :mod:`analysis.kinematics.dh` / :mod:`analysis.kinematics.arm`
is a
cross-check by an established implementation, not a re-run of the same formula. The
model is built from the very :class:`~analysis.kinematics.dh.DHTable` rows the rest of the project
uses: there is no second transcription of the geometry.

Mapping (each revolute row becomes one ``JointModelRZ``; ``M`` is a pending fixed
placement carried to the next joint or to the tool frame)::

    standard  A_i = Rz(theta_i) . [Tz(d) Tx(a) Rx(alpha)]
              joint placement = M . Rz(offset);  then M = Tz(d) Tx(a) Rx(alpha)
    modified  A_i = [Rx(alpha) Tx(a) Tz(d)] . Rz(theta_i)
              joint placement = M . Rx(alpha) Tx(a) Tz(d) Rz(offset);  then M = I

A ``fixed`` row (a tool frame) only extends ``M``. The last ``M`` becomes the operational
frame ``"tool"`` on the last joint, so ``oMf[tool]`` equals ``DHTable.fk``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import pinocchio as pin

from analysis.kinematics.dh import DHTable

__all__ = ["PinocchioArm", "build_model"]

TOOL_FRAME = "tool"


def _rz(angle: float) -> pin.SE3:
    return pin.SE3(pin.utils.rotate("z", angle), np.zeros(3))


def _standard_fixed(row) -> pin.SE3:  # Tz(d) Tx(a) Rx(alpha)
    return pin.SE3(pin.utils.rotate("x", row.alpha), np.array([row.a, 0.0, row.d]))


def _modified_fixed(row) -> pin.SE3:  # Rx(alpha) Tx(a) Tz(d)
    R = pin.utils.rotate("x", row.alpha)
    return pin.SE3(R, np.array([row.a, 0.0, 0.0]) + R @ np.array([0.0, 0.0, row.d]))


def build_model(table: DHTable) -> pin.Model:
    """Pinocchio model of a D-H chain (paper Table 1; seed 001 eq. 8), one RZ joint per
    revolute row, with an operational frame ``"tool"`` at the end of the chain."""
    model = pin.Model()
    model.name = table.name or "dh-chain"
    parent = 0
    pending = pin.SE3.Identity()
    for i, row in enumerate(table.rows):
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
        raise ValueError(f"D-H table {table.name!r} has no revolute row: nothing to model")
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

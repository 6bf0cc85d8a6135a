"""The full pose an arm takes at joint values: position, orientation and every joint (issue
31 item 2), as one record (:class:`Pose`), one JSON shape and one sentence, which ``fk``, the
API and the explorer's FK line share (:func:`fk_document`, :func:`fk_sentence`).

The orientation is the tool frame's rotation matrix (the D-H chain's last frame, or the
closed form's tool rotation for a closed chain: :func:`analysis.kinematics.forward.
chain_points`) and its RPY angles in the convention ``ik`` takes (:func:`analysis.kinematics.
rpy.rpy_from_matrix`: seed 004's eq. 3.14, beta in [-90, 90] deg), so that ``ik`` given the
document's ``target`` answers the same configuration among its solutions (a round trip every
arm is tested on, tests/kinematics/test_pose.py). ``joint_states`` names every joint: the
given ones and, for a closed chain, the passive joints its closure sets (the picker's theta3
.. theta5 and theta10 .. theta13, from its closed form's ``fk``), in user units (deg | mm).

This is the pose of a configuration, not a solution: the branch a configuration lies on is
the explorer's to find (:meth:`analysis.kinematics.model.Arm.solve` of :attr:`Pose.target`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from analysis.kinematics.consistency import POSITION_INPUTS, RPY_INPUTS
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.rpy import rpy_from_matrix

__all__ = ["Pose", "fk_document", "fk_sentence", "pose"]


@dataclass(frozen=True)
class Pose:
    """The pose of joint values ``q`` (..., n).

    Attributes
    ----------
    position : ndarray, shape (..., 3)
        Tool point [mm] in the base frame.
    rotation : ndarray, shape (..., 3, 3)
        Tool frame's rotation (columns: its x, y, z axes in the base frame).
    rpy : ndarray, shape (..., 3)
        ``(alpha, beta, gamma)`` [rad] of :attr:`rotation`, the convention ``ik`` takes.
    joint_states : dict of str to ndarray (...,)
        Every joint by name [rad | mm]: the given ones, then a closed chain's passive ones.
    joint_units : dict of str to str
        "rad" or "mm" per joint of :attr:`joint_states`.
    """

    position: npt.NDArray[np.float64]
    rotation: npt.NDArray[np.float64]
    rpy: npt.NDArray[np.float64]
    joint_states: dict
    joint_units: dict


def pose(arm, q: npt.ArrayLike) -> Pose:
    """The :class:`Pose` of ``arm`` (an :class:`~analysis.kinematics.model.Arm`) at joint
    values ``q`` (..., n) [rad | mm] (checked as :meth:`Arm.fk` checks them).

    >>> import numpy as np
    >>> from analysis.kinematics.arm import load_arm
    >>> p = pose(load_arm("gr1"), np.radians([30.0, 40.0, -60.0, -70.0, 10.0]))
    >>> p.position.round(3).tolist(), np.degrees(p.rpy).round(3).tolist()
    ([336.804, 194.454, -4.425], [-60.0, 80.0, 90.0])
    """
    q = arm._q(q)  # shape, finiteness, magnitude; a closed chain's configuration exists
    shape = q.shape[:-1]
    with np.errstate(invalid="ignore"):
        out = arm._points(numpy_ops, q)  # the one FK: analysis.kinematics.forward

    def arr(v):
        return np.broadcast_to(np.asarray(v, dtype=float), shape) + 0.0

    position = np.stack([arr(c) for c in out["frames"][-1]], axis=-1)
    rotation = np.stack([np.stack([arr(v) for v in row], axis=-1) for row in out["rotation"]],
                        axis=-2)  # fmt: skip
    states = {n: q[..., j] for j, n in enumerate(arm.joint_names)}
    units = dict(zip(arm.joint_names, arm.joint_units, strict=True))
    for name, v in (out.get("joints") or {}).items():  # a closed chain names every joint
        if name not in states:
            states[name], units[name] = arr(v), "rad"  # the passive joints of a closure: hinges
    return Pose(position, rotation, rpy_from_matrix(rotation), states, units)


def _user(v: float, unit: str) -> float:
    return float(np.degrees(v)) if unit == "rad" else float(v)


def fk_document(arm, values: npt.ArrayLike) -> dict:
    """``fk --json``'s document for one configuration given in user units (deg | mm, the
    arm's :attr:`~analysis.kinematics.model.Arm.joint_user_units`): the one JSON shape of
    the full pose, every arm alike, which the explorer's FK line shows too.

    Keys: ``arm``; ``joint_names``, ``joint_units``, ``joint_values`` (as given); ``position_mm``;
    ``rpy_deg`` (the convention ``ik`` takes); ``rotation`` (3 rows); ``joint_states`` {name:
    value in deg | mm} (every joint, a closed chain's passive ones too); ``target`` and
    ``target_names``: the values ``ik`` takes for this pose, in its units (``ik`` given them
    returns this configuration among its solutions), or None for an arm without a closed form
    or whose inputs are neither the tool point nor RPY angles.

    >>> from analysis.kinematics.arm import paper_arm
    >>> doc = fk_document(paper_arm(), [45.0, 10.2087, -155.1291])
    >>> [round(v, 2) for v in doc["position_mm"]], doc["target_names"]
    ([100.0, 100.0, 600.0], ['x_mm', 'y_mm', 'z_mm'])
    """
    given = np.asarray(values, dtype=float)
    q = arm.joints_from_user(given)
    p = pose(arm, q)
    doc = {
        "arm": arm.name,
        "joint_names": list(arm.joint_names),
        "joint_units": list(arm.joint_user_units),
        "joint_values": [float(v) for v in given],
        "position_mm": [float(v) + 0.0 for v in p.position],
        "rpy_deg": [float(v) + 0.0 for v in np.degrees(p.rpy)],
        "rotation": [[float(v) + 0.0 for v in row] for row in p.rotation],
        "joint_states": {n: _user(v, p.joint_units[n]) + 0.0 for n, v in p.joint_states.items()},
        "target": None,
        "target_names": None,
    }
    cf = arm.closed_form
    if cf is not None and set(cf.inputs) <= set(POSITION_INPUTS + RPY_INPUTS):
        values_of = dict(zip(POSITION_INPUTS, doc["position_mm"], strict=True))
        values_of |= dict(zip(RPY_INPUTS, doc["rpy_deg"], strict=True))
        names = {"px": "x_mm", "py": "y_mm", "pz": "z_mm", "alpha": "alpha_deg",
                 "beta": "beta_deg", "gamma": "gamma_deg"}  # fmt: skip
        doc["target"] = [values_of[k] for k in cf.inputs]
        doc["target_names"] = [names[k] for k in cf.inputs]
    return doc


def fk_sentence(doc: dict) -> str:
    """The pose of :func:`fk_document` in words, one line (two for a closed chain: its
    passive joints), as ``fk`` prints it."""
    units = set(doc["joint_units"])
    if units == {"deg"}:
        given = "theta = (" + ", ".join(f"{v:.2f}" for v in doc["joint_values"]) + ") deg"
    else:
        each = zip(doc["joint_names"], doc["joint_values"], doc["joint_units"], strict=True)
        given = "q = (" + ", ".join(f"{n} {v:.2f} {u}" for n, v, u in each) + ")"
    text = (f"{given} -> P = ({', '.join(f'{v:.3f}' for v in doc['position_mm'])}) mm, "
            f"RPY = ({', '.join(f'{v:.3f}' for v in doc['rpy_deg'])}) deg")  # fmt: skip
    passive = {k: v for k, v in doc["joint_states"].items() if k not in doc["joint_names"]}
    if passive:
        text += "\n  passive joints: " + ", ".join(f"{k} = {v:.3f} deg" for k, v in passive.items())
    return text

"""Forward kinematics of an arm, from its description: the one place that chooses the chain.

An arm's FK comes from its D-H rows (:func:`analysis.kinematics.dh.chain_frames`: any serial
chain of revolute, prismatic and fixed rows, standard or modified D-H), with or without a
closed form; only an arm that is not a D-H chain (the picker's closed chain, a description
without rows) takes it from its closed form's ``fk``. Every backend's FK comes from
:func:`chain_points`: numpy (:meth:`analysis.kinematics.arm.Arm.fk`), duals
(:meth:`~analysis.kinematics.arm.Arm.jacobian`) and the compiled kernel
(:func:`analysis.kinematics.compiled.fk`).
"""

from __future__ import annotations

from collections.abc import Sequence

from analysis.kinematics.dh import DHTable, chain_transforms

__all__ = ["chain_points"]


def chain_points(m, desc, cf, P, qs: Sequence, table: DHTable | None = None) -> dict:
    """The arm's forward kinematics in namespace ``m``: ``frames`` (points ``(x, y, z)``,
    the tool point last), ``rotation`` (the tool's 3x3 rows), ``valid`` (a condition: the
    joint values have a pose) and, for a closed chain whose closed form names them,
    ``joints`` (every joint's value, the passive ones too), for joint values ``qs`` (one
    ``m`` value per joint).

    Parameters
    ----------
    desc : ArmDescription
        Its D-H rows give the chain (:meth:`~analysis.kinematics.description.ArmDescription.
        dh_table` with the values ``P``; ``table`` if given, built once by the caller).
    cf : ClosedForm or None
        Used only where the description has no rows (its ``fk``: a closed chain).
    """
    if not desc.has_rows:
        out = cf.fk(m, list(qs), P)
        return {"frames": list(out["frames"]), "rotation": out.get("rotation"),
                "valid": out.get("valid", True), "joints": out.get("joints")}  # fmt: skip
    table = table if table is not None else desc.dh_table(dict(P))
    Ts = chain_transforms(m, table, list(qs))
    frames = [(0.0, 0.0, 0.0), *((T[0][3], T[1][3], T[2][3]) for T in Ts)]
    rotation = [list(row[:3]) for row in Ts[-1]]
    return {"frames": frames, "rotation": rotation, "valid": True}

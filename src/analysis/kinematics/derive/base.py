"""What every derived closed form shares: its name and description, the targets a
configuration reaches, the PLC's first-scan target and the words that name a target.

:class:`FamilyForm` is the base of the derived closed forms (:mod:`.closed_form`,
:mod:`.planar`, :mod:`.gantry`): each family class adds ``BRANCHES``, ``INPUTS``,
``STATUSES``, ``check``, ``geometry``, ``ik`` and ``refusal`` (the contract of
:mod:`analysis.kinematics.arms`). The inputs are named as the loader's consistency check
reads them: ``px, py, pz`` the tool point [mm], ``alpha, beta, gamma`` the RPY angles of the
tool [rad] (:mod:`analysis.kinematics.rpy`).
"""

from __future__ import annotations

import math

import numpy as np

from analysis.kinematics.rpy import rpy_from_matrix

__all__ = ["POINT", "POSE", "FamilyForm", "fmt"]

POINT = ("px", "py", "pz")
POSE = ("px", "py", "pz", "alpha", "beta", "gamma")
RPY = POSE[3:]


def fmt(p) -> str:
    """``(x, y, z)`` of numbers, ``%g``."""
    return "(" + ", ".join(f"{float(v):g}" for v in p) + ")"


class FamilyForm:
    """The pieces every derived closed form has (module docstring).

    Parameters
    ----------
    name : str
        ``"derived:<family>-<digest>"`` (the compiled kernels are cached by it).
    description : ArmDescription
        The description it was derived from.
    structure : Structure
        The family and its numbers (:func:`analysis.kinematics.derive.families.classify`).
    """

    INPUTS: tuple = POINT

    def __init__(self, name: str, description, structure) -> None:
        self.__name__ = name
        self.description = description
        self.structure = structure
        self.family = structure.family

    @property
    def INPUT_UNITS(self) -> tuple:
        return tuple("rad" if k in RPY else "mm" for k in self.INPUTS)

    def inputs_of(self, T) -> np.ndarray:
        """The inputs (..., k) of tool transforms ``T`` (..., 4, 4) [mm, rad]."""
        T = np.asarray(T, dtype=float)
        values = {k: T[..., i, 3] for i, k in enumerate(POINT)}
        if set(RPY) & set(self.INPUTS):
            rpy = rpy_from_matrix(T[..., :3, :3])
            values |= {k: rpy[..., i] for i, k in enumerate(RPY)}
        return np.stack([values[k] for k in self.INPUTS], axis=-1)

    def where(self, p) -> str:
        """``target (x, y, z) mm`` or ``pose (x, y, z) mm, RPY (a, b, c) deg`` of inputs
        ``p`` (one target)."""
        p = [float(v) for v in p]
        mm = [v for v, k in zip(p, self.INPUTS, strict=True) if k in POINT]
        deg = [math.degrees(v) for v, k in zip(p, self.INPUTS, strict=True) if k in RPY]
        what = "pose" if len(deg) == 3 else "target"
        text = f"{what} {fmt(mm)} mm"
        if len(deg) == 3:
            text += f", RPY ({', '.join(f'{v:.4g}' for v in deg)}) deg"
        elif deg:
            text += f", alpha {deg[0]:.4g} deg"
        return text

    # --- the PLC's first-scan target ---------------------------------------------------
    def _adjust_q(self, q: np.ndarray) -> np.ndarray:
        """Candidate configurations made configurations of the arm (a 4R-kept arm holds its
        pitch); the identity here."""
        return q

    @property
    def STARTUP_TARGET(self):
        """The example target a generated PLC program writes on its first scan: the inputs
        of a seeded configuration within the joint limits that the default branch solves
        back, rounded (0.1 mm, 1e-6 rad); None if none of 200 does."""
        if not hasattr(self, "_startup"):
            self._startup = self._find_startup()
        return self._startup

    def _find_startup(self):
        from analysis.kinematics.ops import numpy_ops
        from analysis.kinematics.solution import DEFAULT_TOL_MM

        desc = self.description
        rev = [j.kind == "revolute" for j in desc.joints]
        lo = np.array([max(j.lower, -math.pi) if r else j.lower
                       for j, r in zip(desc.joints, rev, strict=True)])  # fmt: skip
        hi = np.array([min(j.upper, math.pi) if r else j.upper
                       for j, r in zip(desc.joints, rev, strict=True)])  # fmt: skip
        q = self._adjust_q(np.random.default_rng(0).uniform(lo, hi, (200, len(lo))))
        inputs = self.inputs_of(desc.dh_table().fk(q))
        p = np.where([k in RPY for k in self.INPUTS], np.round(inputs, 6), np.round(inputs, 1))
        with np.errstate(all="ignore"):
            r = self.ik(numpy_ops, tuple(p.T), desc.values, tol=DEFAULT_TOL_MM)
        b = self.BRANCHES[0]
        refused = np.zeros(len(p), dtype=bool)
        for _, cond in (*r["refusals"], *r.get("branch_refusals", {}).get(b, ())):
            refused |= np.broadcast_to(np.asarray(cond, dtype=bool), refused.shape)
        q = np.stack([np.broadcast_to(v, refused.shape) for v in r["branches"][b]], axis=-1)
        inside = np.all((q >= lo - 1e-12) & (q <= hi + 1e-12), axis=-1)
        good = np.flatnonzero(~refused & inside)
        return tuple(float(v) for v in p[good[0]]) if good.size else None

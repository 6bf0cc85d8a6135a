"""The picker of seed 002 for the audit: its dimensions with their statuses, the mechanism
at any dimensions, and the sec. 4 experiment replayed.

The mechanism's formulas are :mod:`analysis.kinematics.arms.picker` (the closed form: the
passive joints, the twists of both chains, the POE, the inverse kinematics), and the picker
as an arm like the others is ``load_arm("picker")`` (:class:`~analysis.kinematics.arm.Arm`:
``fk``, ``ik``, batch, the compiled kernel, PLC programs, the explorer). This module
writes no formula of its own; it gives the audit (:mod:`analysis.audit.picker_checks`,
notebook 12) what an :class:`Arm` does not:

- :class:`PickerParams`: every dimension of ``data/arms/picker.toml`` as one table (the
  lengths, the slider strokes of its ``[[joints]]``, the ``[axes]``), each with its status
  and note, and copies with a value changed (:meth:`PickerParams.with_`) *also* outside the
  pantograph proportion that the closed-form IK needs (the audit mutates single lengths);
- :class:`Picker`: the mechanism at such dimensions: the passive joints (raising
  :class:`UnreachableSliders` where link 5 cannot close), both chains' twists as arrays
  (for Pinocchio), the POE pose, the loop-closure residuals, the drawn points;
- the joint laws of sec. 4 (:data:`READINGS`, :func:`law_active`,
  :func:`replay_experiment`).

Units: mm and rad; active joint arrays are (..., 6) in the order :data:`ACTIVE`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from types import MappingProxyType

import numpy as np
import numpy.typing as npt

from analysis.kinematics import poe
from analysis.kinematics.arms import picker as cf
from analysis.kinematics.arms.picker import ACTIVE, PASSIVE
from analysis.kinematics.description import STATUSES, load_description
from analysis.kinematics.loader import load_arm
from analysis.kinematics.ops import numpy_ops
from analysis.paths import data_dir

__all__ = [
    "ACTIVE",
    "ACTIVE_UNITS",
    "PASSIVE",
    "PLAUSIBLE_MAX_TURN",
    "READINGS",
    "Parameter",
    "Picker",
    "PickerParams",
    "UnreachableSliders",
    "data_dir",
    "law_active",
    "load_picker",
    "load_picker_params",
    "replay_experiment",
]

ACTIVE_UNITS = ("rad", "mm", "rad", "rad", "rad", "mm")
_STROKES = {"x_min": ("theta9", 0), "x_max": ("theta9", 1),
            "z_min": ("theta2", 0), "z_max": ("theta2", 1)}  # fmt: skip


class UnreachableSliders(ValueError):
    """Slider positions for which link 5 cannot close (no back-arm angle exists)."""


@dataclass(frozen=True)
class Parameter:
    """One dimension: value, unit, status (``printed``/``assumed``/...), note."""

    name: str
    value: float | tuple[float, ...]
    unit: str
    status: str
    note: str

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"parameter {self.name}: status {self.status!r} not in {STATUSES}")
        if not self.note.strip():
            raise ValueError(
                f"parameter {self.name}: a one-line note (reason or location) is needed"
            )


@dataclass(frozen=True)
class PickerParams:
    """Every dimension of the reconstruction with its status (``data/arms/picker.toml``):
    the lengths and the jaw opening, the slider strokes (``x_min`` .. ``z_max``, from the
    joints' ``limits_mm``), the axis directions."""

    parameters: MappingProxyType
    source: str = ""

    def __getitem__(self, name: str) -> float:
        return self.parameters[name].value

    def __contains__(self, name: str) -> bool:
        return name in self.parameters

    def statuses(self) -> dict[str, str]:
        """``{name: status}`` for every parameter."""
        return {k: p.status for k, p in self.parameters.items()}

    def assumed(self) -> tuple[str, ...]:
        """Names of the assumed parameters (what any figure or table using them must say)."""
        return tuple(k for k, p in self.parameters.items() if p.status == "assumed")

    def with_(self, **values: float) -> PickerParams:
        """A copy with some values changed (each keeps its status and note)."""
        params = dict(self.parameters)
        for k, v in values.items():
            if k not in params:
                raise ValueError(f"unknown picker parameter {k!r}")
            p = params[k]
            params[k] = Parameter(k, v, p.unit, p.status, p.note)
        return PickerParams(MappingProxyType(params), self.source)


def load_picker_params(path: str | Path | None = None) -> PickerParams:
    """The dimensions of ``data/arms/picker.toml`` (or the description at ``path``).

    Raises ``ValueError`` naming the file and the entry for anything the description
    loader refuses, a missing length or stroke, a non-finite or non-positive length, or an
    axis other than the modelled one (the formulas assume these directions).
    """
    desc = load_description(str(path) if path is not None else "picker")
    params: dict[str, Parameter] = {}
    for name, p in desc.parameters.items():
        if not p.source.strip():
            raise ValueError(f"{desc.path}: parameter {name} has no note (its reason or location)")
        params[name] = Parameter(name, p.value, p.unit, p.status, p.source)
        if name in cf.LENGTHS and not (
            math.isfinite(p.value) and (p.value > 0 or name in ("x_A", "z_A"))
        ):
            raise ValueError(f"{desc.path}: {name} = {p.value} mm must be finite and > 0")
    missing = [k for k in (*cf.LENGTHS, "jaw_opening") if k not in params]
    joints = {j.name: j for j in desc.joints}
    for name, (joint, end) in _STROKES.items():
        j = joints.get(joint)
        if j is None or j.kind != "prismatic":
            missing.append(f"{name} (the stroke of prismatic joint {joint})")
            continue
        status, _, note = j.limits_status.partition(":")
        status = status.strip() if status.strip() in STATUSES else "assumed"
        side = ("lower", "upper")[end]
        params[name] = Parameter(
            name, (j.lower, j.upper)[end], "mm", status, f"{note.strip()} ({side} end)"
        )
    if missing:
        raise ValueError(f"{desc.path}: missing parameter(s) {missing}")
    for name, expected in cf.AXES.items():
        a = desc.axes.get(name)
        if a is None or a.value != expected:
            got = None if a is None else list(a.value)
            raise ValueError(f"{desc.path}: {name} = {got}; the reconstruction models {expected}")
        params[name] = Parameter(name, a.value, "-", a.status, a.note)
    return PickerParams(MappingProxyType(params), str(desc.path))


def _as_active(active: npt.ArrayLike) -> npt.NDArray[np.float64]:
    a = np.asarray(active, dtype=float)
    if a.ndim == 0 or a.shape[-1] != len(ACTIVE):
        raise ValueError(f"active joints have shape {a.shape}; expected (..., 6) = {ACTIVE}")
    if not np.isfinite(a).all():
        raise ValueError("active joint array contains NaN or inf")
    return a


def _array(vectors) -> npt.NDArray[np.float64]:
    return np.array([[float(v) for v in (*w, *v_)] for w, v_ in vectors]) + 0.0


@dataclass(frozen=True)
class Picker:
    """The reconstructed picker at dimensions ``params`` (any, the pantograph proportion
    included or not): passive joints, screws of both chains, POE pose, loop closure. Every
    formula is :mod:`analysis.kinematics.arms.picker`'s."""

    params: PickerParams
    points: dict = field(init=False, repr=False)

    def __post_init__(self) -> None:
        pts = {k: np.array(v, dtype=float) for k, v in cf.points(self._P).items()}
        object.__setattr__(self, "points", MappingProxyType(pts))

    @cached_property
    def _P(self) -> dict:
        return {k: self.params[k] for k in cf.LENGTHS}

    @cached_property
    def arm(self):
        """The picker as an :class:`~analysis.kinematics.arm.Arm` with these lengths (the
        closed-form IK needs the pantograph proportion: ValueError otherwise)."""
        base = load_arm("picker")
        return base.with_(**{k: self.params[k] for k in base.params})

    # ----------------------------------------------------------------------- screws
    def open_chain(self) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Main chain (the paper's 主運動鏈) as an open chain: screws xi1..xi8 (8, 6) and the
        tool home pose M = g_st(0) (4, 4), identity rotation at the marker P (eq. 17's role).

        Joint order theta1 (waist, Z), theta2 (vertical slider), theta3 (A), theta4 (D),
        theta5 (F), theta6 (Z at W), theta7 (Y at W), theta8 (X at W).
        """
        ch = cf.chains(self._P)
        M = np.eye(4)
        M[:3, 3] = ch["main_home"]
        return _array(ch["main"]), M

    def secondary_chain(self) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Secondary chain (副運動鏈) to the wrist base: screws xi1, xi9..xi13 (6, 6) and the
        home pose of a frame at F' on the wrist base (4, 4)."""
        ch = cf.chains(self._P)
        M = np.eye(4)
        M[:3, 3] = ch["secondary_home"]
        return _array(ch["secondary"]), M

    # ----------------------------------------------------------------------- passive joints
    def passive(self, z: npt.ArrayLike, x: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Passive joints (..., 7) = :data:`PASSIVE` [rad] from the sliders (eqs. 15-16's role).

        Raises :class:`UnreachableSliders` if link 5 cannot close (names the first
        offending pair and the limit).
        """
        z, x = np.broadcast_arrays(np.asarray(z, float), np.asarray(x, float))
        with np.errstate(invalid="ignore", divide="ignore"):
            pas = cf.passive(numpy_ops, z, x, self._P)
        bad = ~np.broadcast_to(pas["valid"], z.shape)
        if bad.any():
            k = tuple(np.argwhere(np.atleast_1d(bad))[0])
            zz, xx = (float(np.atleast_1d(v)[k]) for v in (z, x))
            raise UnreachableSliders(cf.fk_refusal([0.0, zz, 0, 0, 0, xx], self._P))
        return np.stack(np.broadcast_arrays(*(pas[k] for k in PASSIVE)), axis=-1)

    def joints(self, active: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """All thirteen joints theta1..theta13 (..., 13) [rad | mm] for active (..., 6)."""
        a = _as_active(active)
        t1, z, t6, t7, t8, x = np.moveaxis(a, -1, 0)
        t3, t4, t5, t10, t11, t12, t13 = np.moveaxis(self.passive(z, x), -1, 0)
        cols = (t1, z, t3, t4, t5, t6, t7, t8, x, t10, t11, t12, t13)
        return np.stack(np.broadcast_arrays(*cols), axis=-1)

    def main_q(self, active: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Main-chain joints theta1..theta8 (..., 8) for :meth:`open_chain`."""
        return self.joints(active)[..., :8]

    # ----------------------------------------------------------------------- kinematics
    def _fk(self, active) -> tuple[dict, tuple]:
        a = _as_active(active)
        self.passive(a[..., 1], a[..., 5])  # raises where link 5 cannot close
        with np.errstate(invalid="ignore"):
            return cf.fk(numpy_ops, list(np.moveaxis(a, -1, 0)), self._P), a.shape[:-1]

    def fk(self, active: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Tool pose (..., 4, 4) [mm] by POE of the main chain with the passive joints solved
        (the paper's p_e(theta), eq. 22 / "(18)"), for active joints (..., 6)."""
        out, shape = self._fk(active)
        T = np.zeros((*shape, 4, 4))
        for i in range(3):
            for j in range(3):
                T[..., i, j] = out["rotation"][i][j]
            T[..., i, 3] = out["frames"][-1][i]
        T[..., 3, 3] = 1.0
        return T

    def position(self, active: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Tool marker position (..., 3) [mm] in frame S."""
        return self.fk(active)[..., :3, 3]

    def loop_residuals(self, active: npt.ArrayLike) -> dict[str, npt.NDArray[np.float64]]:
        """How well the closed loops close at the solved passive joints, each (...,).

        ``secondary_position`` [mm] and ``secondary_rotation`` [-]: the frame at F' on the
        wrist base through the secondary chain (POE of theta1, theta9, theta10..13) against
        the same frame through the main chain (the structure equation, eq. 10's role).
        ``link5`` [mm]: | |B - G| - b | with G carried by the main chain, B by the slider.
        ``forearm_top`` [mm]: C on the lower small-arm (main chain) against C carried from B
        by a fore-arm turned with the back-arm (parallelogram).
        """
        q = self.joints(active)
        t1, z, t3, t4, t5 = (q[..., i] for i in range(5))
        x, t10, t11, t12, t13 = (q[..., i] for i in range(8, 13))
        S_main, _ = self.open_chain()
        S_sec, M_f = self.secondary_chain()
        T_main = poe.fk(S_main[:5], M_f, np.stack([t1, z, t3, t4, t5], axis=-1))
        T_sec = poe.fk(S_sec, M_f, np.stack([t1, x, t10, t11, t12, t13], axis=-1))
        pt = self.points

        def carry(S, qq, point):
            T = poe.fk(S, np.eye(4), qq)
            return np.einsum("...ij,j->...i", T[..., :3, :3], point) + T[..., :3, 3]

        G = carry(S_main[:3], np.stack([t1, z, t3], -1), pt["G"])
        B = carry(S_sec[:2], np.stack([t1, x], -1), pt["B"])
        C_main = carry(S_main[:4], np.stack([t1, z, t3, t4], -1), pt["C"])
        fore = np.array([poe.revolute_screw(cf.AXES["arm_axes"], pt["B"])])
        C_fore = carry(np.concatenate([S_sec[:2], fore]), np.stack([t1, x, t3], -1), pt["C"])
        return {
            "secondary_position": np.linalg.norm(T_main[..., :3, 3] - T_sec[..., :3, 3], axis=-1),
            "secondary_rotation": np.abs(T_main[..., :3, :3] - T_sec[..., :3, :3]).max((-2, -1)),
            "link5": np.abs(np.linalg.norm(B - G, axis=-1) - self.params["b"]),
            "forearm_top": np.linalg.norm(C_main - C_fore, axis=-1),
        }

    def points_at(self, active: npt.ArrayLike) -> dict[str, npt.NDArray[np.float64]]:
        """The named points of the arm (A, G, D, B, C, F, W, P) in frame S [mm], each
        (..., 3), for active joints (..., 6): each carried by the POE of the joints before
        its link (B by the secondary chain's waist and horizontal slider). For drawing."""
        out, shape = self._fk(active)
        return {
            k: np.stack([np.broadcast_to(c, shape) for c in v], axis=-1).astype(float)
            for k, v in out["points"].items()
            if k != "O"
        }

    def statuses(self) -> dict[str, str]:
        """Status of every dimension used (``printed``/``assumed``)."""
        return self.params.statuses()

    @property
    def pantograph_ratio(self) -> float | None:
        """k = l_AD / g if it equals l_DF / b (to 1e-12), else None."""
        p = self.params
        k1, k2 = p["l_AD"] / p["g"], p["l_DF"] / p["b"]
        return k1 if math.isclose(k1, k2, rel_tol=cf.PANTOGRAPH_RTOL) else None

    def random_active(self, rng: np.random.Generator, n: int) -> npt.NDArray[np.float64]:
        """n seeded valid configurations (n, 6): :meth:`Arm.sample_q` of :attr:`arm`."""
        return self.arm.sample_q(rng, n)


def load_picker(path: str | Path | None = None) -> Picker:
    """The picker of ``data/arms/picker.toml`` (assumed dimensions: see its statuses)."""
    return Picker(load_picker_params(path))


# --------------------------------------------------------------------------- experiment
READINGS: dict[str, dict] = {
    "velocity, rad/s": {
        "integrate": True,
        "angle_unit": "rad",
        "units_printed": True,
        "note": "as printed: omega_i [rad/s] and nu [mm/s] integrated from rest at the "
        "reference pose (t = 0)",
    },
    "value, rad": {
        "integrate": False,
        "angle_unit": "rad",
        "units_printed": False,
        "note": "'5組關節變量值' (joint values): -5t is theta1 itself [rad], 15t is x [mm]",
    },
    "velocity, deg/s": {
        "integrate": True,
        "angle_unit": "deg",
        "units_printed": False,
        "note": "omega in deg/s (not printed) integrated from rest",
    },
    "value, deg": {
        "integrate": False,
        "angle_unit": "deg",
        "units_printed": False,
        "note": "joint values with angles in degrees (not printed)",
    },
}
"""Readings of the sec. 4 joint laws omega1 = -5t, omega6 = 10t, omega7 = omega8 = -10t
[rad/s], nu_x = 15t, nu_z = 20t [mm/s] that the printed units and words allow, plus the
two degree readings the units do not allow."""

_LAW = {"theta1": -5.0, "theta2": 20.0, "theta6": 10.0, "theta7": -10.0, "theta8": -10.0}
_LAW["theta9"] = 15.0
PLAUSIBLE_MAX_TURN = np.pi
"""A waist or wrist of a cable-driven picker turning more than half a turn either way in a
5 s test is taken as implausible (no joint range is printed)."""


def law_active(t: npt.ArrayLike, reading: str) -> npt.NDArray[np.float64]:
    """Active joints (..., 6) [rad | mm] at times t [s] under one of :data:`READINGS`."""
    if reading not in READINGS:
        raise ValueError(f"unknown reading {reading!r}; expected one of {sorted(READINGS)}")
    spec = READINGS[reading]
    t = np.asarray(t, dtype=float)
    shape = t**2 / 2 if spec["integrate"] else t
    coef = np.array([_LAW[k] for k in ACTIVE])
    angle = np.array([u == "rad" for u in ACTIVE_UNITS])
    if spec["angle_unit"] == "deg":
        coef = np.where(angle, np.radians(coef), coef)
    return shape[..., None] * coef


def replay_experiment(
    t: npt.ArrayLike = (1.0, 2.0, 3.0, 4.0, 5.0),
    picker: Picker | None = None,
    instrument=(1500.0, 0.0, 0.0),
) -> dict[str, dict]:
    """Evaluate the sec. 4 joint laws at t [s] under every reading of :data:`READINGS`.

    ``picker`` defaults to :func:`load_picker` (assumed dimensions); ``instrument`` is the
    origin of the measuring instrument's frame S' in S [mm] (sec. 4: (1500, 0, 0)).

    Returns
    -------
    dict
        Per reading: ``active`` (n, 6) [rad | mm]; ``position`` (n, 3) [mm] in S (NaN where
        the sliders put link 5 out of reach); ``in_instrument`` (n, 3) [mm] in the measuring
        instrument's frame S' (origin (1500, 0, 0) in S, axes parallel, sec. 4);
        ``reachable`` (n,); ``max_turn`` [rad] the largest |angle|; ``within_strokes``;
        ``plausible`` (all reachable, within the assumed strokes, no joint beyond
        :data:`PLAUSIBLE_MAX_TURN`); ``units_printed``; ``note``; ``assumed`` (the names of
        the assumed dimensions behind the positions).
    """
    picker = picker if picker is not None else load_picker()
    t = np.atleast_1d(np.asarray(t, dtype=float))
    p = picker.params
    out = {}
    for name, spec in READINGS.items():
        a = law_active(t, name)
        with np.errstate(invalid="ignore", divide="ignore"):
            reach = np.asarray(cf.passive(numpy_ops, a[:, 1], a[:, 5], picker._P)["valid"])
        pos = np.full((len(t), 3), np.nan)
        if reach.any():
            pos[reach] = picker.position(a[reach])
        angles = a[:, [i for i, u in enumerate(ACTIVE_UNITS) if u == "rad"]]
        strokes = (
            (a[:, 1] >= p["z_min"]) & (a[:, 1] <= p["z_max"])
            & (a[:, 5] >= p["x_min"]) & (a[:, 5] <= p["x_max"])
        )  # fmt: skip
        max_turn = float(np.abs(angles).max())
        out[name] = {
            "active": a,
            "position": pos,
            "in_instrument": pos - np.asarray(instrument, float),
            "reachable": reach,
            "within_strokes": strokes,
            "max_turn": max_turn,
            "plausible": bool(reach.all() and strokes.all() and max_turn <= PLAUSIBLE_MAX_TURN),
            "units_printed": spec["units_printed"],
            "note": spec["note"],
            "assumed": picker.params.assumed(),
        }
    return out

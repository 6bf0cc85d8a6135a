"""The 2P4R camellia-fruit picker of seed 002 (Yang, Li, Gao 2016), reconstructed.

What is printed (``analysis.papers.picker``): the topology of section 2 (waist revolute; a
horizontal and a vertical slider on the rotating seat; fore-arm, main-arm link 5, back-arm,
back small-arm, triangle connector, lower and upper small-arms; a parallelogram "fore-arm
parallel to back-arm, link 5 parallel to lower small-arm"; a 3R wrist), the two chains of
section 3.2 (main: vertical slider, back-arm l_AD, lower small-arm l_DF; secondary:
horizontal slider, back small-arm l_C'E'', triangle b_EE'E'', upper small-arm l_E'F'; the
wrist base b_FF' as moving platform), the joint numbering (active beta = [theta2, theta9]
with theta2 = z on xi2 and theta9 = x on xi9; passive alpha = [theta3, theta4, theta5,
theta10..theta13]; theta3, theta5 mapped from x, z by eqs. 15-16) and that the FK is a POE
of the main chain with those mappings substituted (eqs. 20-22, called "(18)" in sec. 3.4).

What is inferred here (Figure 3, Table 1 and eqs. 10-22 are lost; every dimension is in
``data/arms/picker.toml`` with ``status = "assumed"`` and a reason)::

    arm plane XZ at theta1 = 0 (x forward, z up); all passive axes along +Y
    A  = (x_A, z_A + z)            back-arm hinge on the vertical slider (theta2 = z)
    G  = A + g u(theta3)           link 5's hinge on the back-arm, u(p) = (sin p, cos p)
    D  = A + l_AD u(theta3)        back-arm top = lower small-arm hinge
    B  = (x_A + b + x, z_A + g)    fore-arm hinge on the horizontal slider (theta9 = x)
    |B - G| = b                    link 5 (the loop that fixes theta3)
    C  = B + (D - G) = D + (B - G) fore-arm top on the lower small-arm (parallelogram BGDC)
    F  = D + (l_DF / b)(C - D)     lower small-arm end = wrist-base hinge
    wrist base kept parallel to itself by the second parallelogram pair: C'E''EB and
    EE'F'F (E coaxial with C, C' = B - (d_s, 0) on the slider, E' = E + (0, e_t))
    wrist: xi6 (Z), xi7 (Y), xi8 (X) through W = F + (f, 0); tool marker P = W + (e_tool, 0)

At the reference pose (all theta = 0, Figure 3) the back-arm and fore-arm are vertical,
link 5 and the lower small-arm horizontal. Closed form of the passive joints (the role of
eqs. 15-16), with d = B - A = (b + x, g - z)::

    theta3 = atan2(d_x, d_z) - acos((|d|^2 + g^2 - b^2) / (2 g |d|))   (reference branch)
    psi    = atan2(-(B - G)_z, (B - G)_x)                               (lower small-arm)
    theta4 = psi - theta3,  theta5 = -psi                               (wrist base level)
    theta10 = theta3, theta11 = -theta3, theta12 = psi, theta13 = -psi  (secondary chain)

With l_AD / g = l_DF / b = k (the assumed pantograph) F = (1 - k) A + k B + const: the end
point moves k x horizontally and -(k - 1) z vertically ("small stroke, large travel").

Checks: :meth:`Picker.loop_residuals` closes the secondary chain (POE of theta1, theta9,
theta10..theta13) onto the wrist base of the main chain, and link 5 and the fore-arm onto
their hinges; :meth:`Picker.open_chain` feeds Pinocchio
(:func:`analysis.kinematics.pinocchio_model.build_poe_model`).

Units: mm and rad; active joint arrays are (..., 6) in the order :data:`ACTIVE`.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType

import numpy as np
import numpy.typing as npt

from analysis.kinematics import poe
from analysis.kinematics.params import data_dir

__all__ = [
    "ACTIVE",
    "ACTIVE_UNITS",
    "PASSIVE",
    "READINGS",
    "Parameter",
    "Picker",
    "PickerParams",
    "UnreachableSliders",
    "load_picker",
    "load_picker_params",
    "replay_experiment",
]

ACTIVE = ("theta1", "theta2", "theta6", "theta7", "theta8", "theta9")
"""Active joints in array order: waist, vertical slider z, wrist 6-8, horizontal slider x
(paper numbering; beta = [theta2, theta9] are the sliders)."""
ACTIVE_UNITS = ("rad", "mm", "rad", "rad", "rad", "mm")
PASSIVE = ("theta3", "theta4", "theta5", "theta10", "theta11", "theta12", "theta13")
"""Passive joints (the paper's alpha), in that order."""

_LENGTHS = ("x_A", "z_A", "g", "l_AD", "b", "l_DF", "d_s", "e_t", "f", "e_tool")
_STROKES = ("x_min", "x_max", "z_min", "z_max")
_AXES = ("vertical_guide", "horizontal_guide", "arm_axes", "wrist_axis6", "wrist_axis7")
_EXPECTED_AXES = {
    "vertical_guide": (0.0, 0.0, 1.0),
    "horizontal_guide": (1.0, 0.0, 0.0),
    "arm_axes": (0.0, 1.0, 0.0),
    "wrist_axis6": (0.0, 0.0, 1.0),
    "wrist_axis7": (0.0, 1.0, 0.0),
    "wrist_axis8": (1.0, 0.0, 0.0),
}
STATUSES = ("printed", "assumed")


class UnreachableSliders(ValueError):
    """Slider positions for which link 5 cannot close (no back-arm angle exists)."""


@dataclass(frozen=True)
class Parameter:
    """One dimension of ``data/arms/picker.toml``: value, unit, ``printed``/``assumed``, note."""

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
    """All dimensions of the reconstruction with their statuses (``data/arms/picker.toml``)."""

    parameters: MappingProxyType
    source: str = ""

    def __getitem__(self, name: str) -> float:
        return self.parameters[name].value

    def statuses(self) -> dict[str, str]:
        """``{name: "printed" | "assumed"}`` for every parameter."""
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
    """Read ``data/arms/picker.toml`` (``[parameters] name = {value, unit, status, note}``).

    Raises ``ValueError`` naming the file and the entry for a missing field, an unknown
    status, a missing parameter, a non-finite or non-positive length, or an axis other
    than the modelled one (the model's formulas assume these directions).
    """
    path = Path(path) if path is not None else data_dir() / "arms" / "picker.toml"
    with path.open("rb") as fh:
        raw = tomllib.load(fh)
    table = raw.get("parameters")
    if not isinstance(table, dict):
        raise ValueError(f"{path}: no [parameters] table")
    params = {}
    for name, entry in table.items():
        missing = {"value", "unit", "status", "note"} - set(entry)
        if missing:
            raise ValueError(f"{path}: parameter {name} lacks {sorted(missing)}")
        value = entry["value"]
        value = tuple(float(v) for v in value) if isinstance(value, list) else float(value)
        try:
            params[name] = Parameter(name, value, entry["unit"], entry["status"], entry["note"])
        except ValueError as exc:
            raise ValueError(f"{path}: {exc}") from None
    need = set(_LENGTHS) | set(_STROKES) | set(_EXPECTED_AXES) | {"jaw_opening"}
    missing = need - set(params)
    if missing:
        raise ValueError(f"{path}: missing parameter(s) {sorted(missing)}")
    for name in _LENGTHS:
        v = params[name].value
        if not (math.isfinite(v) and (v > 0 or name in ("x_A", "z_A"))):
            raise ValueError(f"{path}: {name} = {v} mm must be finite and > 0")
    for name, expected in _EXPECTED_AXES.items():
        if params[name].value != expected:
            raise ValueError(
                f"{path}: {name} = {params[name].value}; the reconstruction models {expected}"
            )
    return PickerParams(MappingProxyType(params), str(path))


def _as_active(active: npt.ArrayLike) -> npt.NDArray[np.float64]:
    a = np.asarray(active, dtype=float)
    if a.ndim == 0 or a.shape[-1] != len(ACTIVE):
        raise ValueError(f"active joints have shape {a.shape}; expected (..., 6) = {ACTIVE}")
    if not np.isfinite(a).all():
        raise ValueError("active joint array contains NaN or inf")
    return a


@dataclass(frozen=True)
class Picker:
    """The reconstructed picker: screws of both chains at the reference pose, closed-form
    passive joints, POE forward kinematics, loop closure. Every length comes from
    :class:`PickerParams` (``assumed`` unless printed: see :meth:`statuses`)."""

    params: PickerParams
    points: dict = field(init=False, repr=False)

    def __post_init__(self) -> None:
        p = self.params
        xA, zA, g, lAD, b, lDF = (p[k] for k in ("x_A", "z_A", "g", "l_AD", "b", "l_DF"))

        def at(x, z):  # a point of the arm plane (y = 0) [mm]
            return np.array([x, 0.0, z])

        pts = {
            "A": at(xA, zA),
            "G": at(xA, zA + g),
            "D": at(xA, zA + lAD),
            "B": at(xA + b, zA + g),
            "C": at(xA + b, zA + lAD),
            "F": at(xA + lDF, zA + lAD),
        }
        pts["C'"] = pts["B"] - at(p["d_s"], 0.0)
        pts["E"] = pts["C"].copy()
        pts["E''"] = pts["C"] - at(p["d_s"], 0.0)
        pts["E'"] = pts["C"] + at(0.0, p["e_t"])
        pts["F'"] = pts["F"] + at(0.0, p["e_t"])
        pts["W"] = pts["F"] + at(p["f"], 0.0)
        pts["P"] = pts["W"] + at(p["e_tool"], 0.0)
        object.__setattr__(self, "points", MappingProxyType(pts))

    # ----------------------------------------------------------------------- screws
    def open_chain(self) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Main chain (the paper's 主運動鏈) as an open chain: screws xi1..xi8 (8, 6) and the
        tool home pose M = g_st(0) (4, 4), identity rotation at the marker P (eq. 17's role).

        Joint order theta1 (waist, Z), theta2 (vertical slider), theta3 (A), theta4 (D),
        theta5 (F), theta6 (Z at W), theta7 (Y at W), theta8 (X at W).
        """
        pt, y = self.points, self.params["arm_axes"]
        S = np.array(
            [
                poe.revolute_screw([0, 0, 1], [0, 0, 0]),
                poe.prismatic_screw(self.params["vertical_guide"]),
                poe.revolute_screw(y, pt["A"]),
                poe.revolute_screw(y, pt["D"]),
                poe.revolute_screw(y, pt["F"]),
                poe.revolute_screw(self.params["wrist_axis6"], pt["W"]),
                poe.revolute_screw(self.params["wrist_axis7"], pt["W"]),
                poe.revolute_screw(self.params["wrist_axis8"], pt["W"]),
            ]
        )
        M = np.eye(4)
        M[:3, 3] = pt["P"]
        return S, M

    def secondary_chain(self) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """Secondary chain (副運動鏈) to the wrist base: screws xi1, xi9..xi13 (6, 6) and the
        home pose of a frame at F' on the wrist base (4, 4)."""
        pt, y = self.points, self.params["arm_axes"]
        S = np.array(
            [
                poe.revolute_screw([0, 0, 1], [0, 0, 0]),
                poe.prismatic_screw(self.params["horizontal_guide"]),
                poe.revolute_screw(y, pt["C'"]),
                poe.revolute_screw(y, pt["E''"]),
                poe.revolute_screw(y, pt["E'"]),
                poe.revolute_screw(y, pt["F'"]),
            ]
        )
        M = np.eye(4)
        M[:3, 3] = pt["F'"]
        return S, M

    # ----------------------------------------------------------------------- passive joints
    def passive(self, z: npt.ArrayLike, x: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Passive joints (..., 7) = :data:`PASSIVE` [rad] from the sliders (eqs. 15-16's role).

        Parameters
        ----------
        z, x : array_like, broadcastable
            Vertical slider theta2 and horizontal slider theta9 [mm].

        Raises
        ------
        UnreachableSliders
            If link 5 cannot close: |B - A| outside [|g - b|, g + b] [mm] (names the first
            offending pair and the limit).
        """
        p = self.params
        z, x = np.broadcast_arrays(np.asarray(z, float), np.asarray(x, float))
        g, b = p["g"], p["b"]
        dx, dz = b + x, g - z
        R = np.hypot(dx, dz)
        lo, hi = abs(g - b), g + b
        bad = (R > hi) | (R < lo) | (R == 0)
        if np.any(bad):
            k = tuple(np.argwhere(np.atleast_1d(bad))[0])
            zz, xx, rr = (float(np.atleast_1d(v)[k]) for v in (z, x, R))
            raise UnreachableSliders(
                f"sliders z = {zz:g} mm, x = {xx:g} mm: |B - A| = {rr:.3f} mm is outside "
                f"[{lo:g}, {hi:g}] mm (link 5, b = {b:g} mm, cannot reach the back-arm at "
                f"g = {g:g} mm)"
            )
        c = np.clip((R**2 + g**2 - b**2) / (2 * g * R), -1.0, 1.0)
        theta3 = np.arctan2(dx, dz) - np.arccos(c)
        # B - G in the arm plane (x, z)
        bg_x = dx - g * np.sin(theta3)
        bg_z = dz - g * np.cos(theta3)
        psi = np.arctan2(-bg_z, bg_x)
        return np.stack([theta3, psi - theta3, -psi, theta3, -theta3, psi, -psi], axis=-1)

    def joints(self, active: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """All thirteen joints theta1..theta13 (..., 13) [rad | mm] for active (..., 6)."""
        a = _as_active(active)
        t1, z, t6, t7, t8, x = np.moveaxis(a, -1, 0)
        pas = self.passive(z, x)
        t3, t4, t5, t10, t11, t12, t13 = np.moveaxis(pas, -1, 0)
        cols = (t1, z, t3, t4, t5, t6, t7, t8, x, t10, t11, t12, t13)
        return np.stack(np.broadcast_arrays(*cols), axis=-1)

    def main_q(self, active: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Main-chain joints theta1..theta8 (..., 8) for :meth:`open_chain`."""
        return self.joints(active)[..., :8]

    # ----------------------------------------------------------------------- kinematics
    def fk(self, active: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Tool pose (..., 4, 4) [mm] by POE of the main chain with the passive joints solved
        (the paper's p_e(theta), eq. 22 / "(18)"), for active joints (..., 6)."""
        S, M = self.open_chain()
        return poe.fk(S, M, self.main_q(active))

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
        main5 = np.stack([t1, z, t3, t4, t5], axis=-1)
        T_main = poe.fk(S_main[:5], M_f, main5)
        T_sec = poe.fk(S_sec, M_f, np.stack([t1, x, t10, t11, t12, t13], axis=-1))
        pt = self.points

        def carry(S, qq, point):
            T = poe.fk(S, np.eye(4), qq)
            return np.einsum("...ij,j->...i", T[..., :3, :3], point) + T[..., :3, 3]

        G = carry(S_main[:3], np.stack([t1, z, t3], -1), pt["G"])
        B = carry(S_sec[:2], np.stack([t1, x], -1), pt["B"])
        C_main = carry(S_main[:4], np.stack([t1, z, t3, t4], -1), pt["C"])
        fore = np.array([poe.revolute_screw(self.params["arm_axes"], pt["B"])])
        S_fore = np.concatenate([S_sec[:2], fore])
        C_fore = carry(S_fore, np.stack([t1, x, t3], -1), pt["C"])
        return {
            "secondary_position": np.linalg.norm(T_main[..., :3, 3] - T_sec[..., :3, 3], axis=-1),
            "secondary_rotation": np.abs(T_main[..., :3, :3] - T_sec[..., :3, :3]).max((-2, -1)),
            "link5": np.abs(np.linalg.norm(B - G, axis=-1) - self.params["b"]),
            "forearm_top": np.linalg.norm(C_main - C_fore, axis=-1),
        }

    def points_at(self, active: npt.ArrayLike) -> dict[str, npt.NDArray[np.float64]]:
        """The named points of the arm (A, G, D, B, C, F, W, P) in frame S [mm], each
        (..., 3), for active joints (..., 6): each carried by the POE of the joints before
        its link (main chain; B by the secondary chain's waist and horizontal slider). For
        drawing the linkage."""
        q = self.joints(active)
        S_main, _ = self.open_chain()
        S_sec, _ = self.secondary_chain()
        pt = self.points
        main_q = q[..., :8]
        sec_q = q[..., [0, 8]]

        def carry(S, qq, point):
            T = poe.fk(S, np.eye(4), qq)
            return np.einsum("...ij,j->...i", T[..., :3, :3], point) + T[..., :3, 3]

        link = {"A": 2, "G": 3, "D": 3, "C": 4, "F": 4, "W": 5, "P": 8}
        out = {k: carry(S_main[:n], main_q[..., :n], pt[k]) for k, n in link.items()}
        out["B"] = carry(S_sec[:2], sec_q, pt["B"])
        return out

    def statuses(self) -> dict[str, str]:
        """Status of every dimension used (``printed``/``assumed``)."""
        return self.params.statuses()

    @property
    def pantograph_ratio(self) -> float | None:
        """k = l_AD / g if it equals l_DF / b (to 1e-12), else None."""
        p = self.params
        k1, k2 = p["l_AD"] / p["g"], p["l_DF"] / p["b"]
        return k1 if math.isclose(k1, k2, rel_tol=1e-12) else None

    def random_active(self, rng: np.random.Generator, n: int, margin: float = 0.02):
        """n seeded active configurations (n, 6): joints in [-pi, pi], sliders within the
        assumed strokes and at least ``margin`` of (g + b) inside link 5's reach (acos
        well-conditioned)."""
        p = self.params
        out = np.empty((0, 6))
        while len(out) < n:
            a = rng.uniform(-np.pi, np.pi, (2 * n, 6))
            a[:, 1] = rng.uniform(p["z_min"], p["z_max"], 2 * n)
            a[:, 5] = rng.uniform(p["x_min"], p["x_max"], 2 * n)
            R = np.hypot(p["b"] + a[:, 5], p["g"] - a[:, 1])
            span = p["g"] + p["b"]
            ok = (R < (1 - margin) * span) & (R > abs(p["g"] - p["b"]) + margin * span)
            out = np.concatenate([out, a[ok]])
        return out[:n]


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
        pos = np.full((len(t), 3), np.nan)
        reach = np.zeros(len(t), bool)
        for k in range(len(t)):  # a handful of samples; each may be unreachable
            try:
                pos[k] = picker.position(a[k])
                reach[k] = True
            except UnreachableSliders:
                pass
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

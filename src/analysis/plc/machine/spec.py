"""What a machine program needs of an arm, resolved once from its :class:`~analysis.kinematics.
arm.Arm`: one axis per joint (its unit, its step per pulse, its software limits, its velocity,
acceleration and jerk limits, how it homes), the machine's inputs and outputs (a contract,
issue 29 item 1) and its status codes with their alarm texts.

Every value comes from the arm description (``data/arms/<arm>.toml``): the motion limits and
homing of a joint are its ``max_velocity``, ``max_acceleration``, ``max_jerk`` and ``home``
entries (:class:`analysis.kinematics.description.JointSpec`), each with its provenance; a joint
without them is refused, naming the joint and the key (:meth:`JointSpec.require`). Units at the
PLC edge: a revolute joint in deg, deg/s, deg/s^2, deg/s^3; a prismatic one in mm, mm/s, ...
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from analysis.kinematics.status import Status

__all__ = [
    "HOME_APPROACH",
    "HOME_CREEP",
    "MACHINE_INPUTS",
    "MACHINE_OUTPUTS",
    "MACHINE_STATUS",
    "AxisSpec",
    "MachineSpec",
    "machine_spec",
]

HOME_APPROACH = 0.25
"""A reference switch is approached at this fraction of the joint's velocity limit
(assumed: no paper prints a homing speed; :mod:`.program`, item 4)."""
HOME_CREEP = 0.0625
"""The second search (from the far side of the edge) creeps at this fraction of the velocity
limit, or half a pulse per task cycle if that is slower (assumed, as above)."""

TARGET_NAMES = {
    "px": "TargetX",
    "py": "TargetY",
    "pz": "TargetZ",
    "alpha": "TargetAlpha",
    "beta": "TargetBeta",
    "gamma": "TargetGamma",
}
"""The closed form's input -> the machine's target input (mm, or deg for an angle)."""

MACHINE_INPUTS = ("Enable", "Home", "Start", "StopOK", "Reset", "Grip")
"""The machine's BOOL inputs (issue 29 item 1, a contract); the targets follow the arm."""
MACHINE_OUTPUTS = ("Homed", "Busy", "Done", "Error", "Status", "Gripper", "GripperClosed")
"""The machine's outputs: the contract's five, the gripper valve and its state after the
dwell."""

MACHINE_STATUS: dict[int, tuple[str, str, str]] = {
    100: (
        "not-powered",
        "Home or Start refused: Enable is FALSE or an axis is not powered",
        "Axes not powered: switch Enable on",
    ),
    101: (
        "not-homed",
        "Start refused: the axes are not homed",
        "Machine not homed: press Home first",
    ),
    102: (
        "stopped",
        "the stop circuit is open (StopOK FALSE): every axis stopped with its deceleration; "
        "nothing moves again until the circuit is closed, Reset, then Start",
        "Stop circuit open: close it, press Reset, then Start",
    ),
    103: (
        "axis-error",
        "an axis reported an error (a motion block's Error or MC_ReadAxisError): every axis "
        "stopped; nothing moves again until Reset, then Start",
        "Axis fault (AxisErrorID): remove the cause, press Reset, then Start",
    ),
    104: (
        "busy",
        "Home or Start refused: homing or the gripper's dwell is running",
        "Machine busy: wait for Done",
    ),
}
"""The machine's own status codes: code -> (word, meaning, alarm text). The IK block's codes
(0-7, :class:`~analysis.kinematics.status.Status`) pass through unchanged."""

IK_ALARM = {
    Status.OK: "",
    Status.OUT_OF_REACH: "Target refused: out of reach",
    Status.INSIDE_REACH: "Target refused: inside the inner reach",
    Status.BASE_AXIS: "Target refused: on the waist axis (waist angle undefined)",
    Status.JOINT_LIMITS: "Target refused: a joint would leave its limits",
    Status.DEGENERATE: "Target refused: a singular pose of the arm",
    Status.INVALID: "Target refused: not a finite number (NaN or inf)",
    Status.ORIENTATION: "Target refused: an orientation the arm cannot take",
}


@dataclass(frozen=True)
class AxisSpec:
    """One joint's axis at the PLC edge (deg or mm)."""

    name: str
    """The AXIS_REF variable: Axis1 .. AxisN."""
    joint: str
    kind: str
    """"revolute" or "prismatic"."""
    unit: str
    """"deg" or "mm"."""
    per_pulse: float
    """Joint travel per pulse (deg or mm): 360 / pulses_per_rev, or lead_mm / pulses_per_rev."""
    pulses_per_rev: int
    lower: float | None
    upper: float | None
    """Software limits (deg or mm); None for an unlimited revolute joint (moved the short
    way)."""
    max_velocity: float
    max_acceleration: float
    max_jerk: float
    """Per second, per second^2, per second^3 (deg or mm)."""
    home_mode: str
    """"switch" (a reference switch) or "set" (the present position is the home position)."""
    home_position: float
    provenance: dict

    @property
    def unlimited(self) -> bool:
        return self.lower is None


@dataclass(frozen=True)
class MachineSpec:
    """The machine of one arm (module docstring)."""

    arm: str
    title: str
    ik_inputs: tuple[str, ...]
    """The IK block's inputs (px, py, pz, alpha, beta, gamma)."""
    ik_units: tuple[str, ...]
    """Their units: "mm" or "rad"."""
    targets: tuple[str, ...]
    """The machine's target inputs, in the same order (TargetX, ...)."""
    axes: tuple[AxisSpec, ...]
    grip_dwell_s: float = 0.5
    """The gripper's closing/opening time [s] (assumed: no paper prints one)."""

    @property
    def target_units(self) -> tuple[str, ...]:
        return tuple("deg" if u == "rad" else u for u in self.ik_units)

    def status_codes(self, ik_codes) -> dict[int, dict[str, str]]:
        """Every status the machine writes: the IK block's ``ik_codes`` and its own."""
        out = {}
        for k in sorted(ik_codes):
            s = Status(k)
            out[k] = {"word": s.text, "meaning": f"IK: {s.text}", "alarm": IK_ALARM[s]}
        for k, (word, meaning, alarm) in MACHINE_STATUS.items():
            out[k] = {"word": word, "meaning": meaning, "alarm": alarm}
        return out


def _axis(index: int, joint) -> AxisSpec:
    revolute = joint.kind == "revolute"
    to_user = math.degrees if revolute else float
    if revolute:
        per_pulse = 360.0 / joint.pulses_per_rev
    else:
        per_pulse = float(joint.lead_mm) / joint.pulses_per_rev
    unlimited = bool(getattr(joint, "unlimited", False))
    rates = [to_user(joint.require(k)) for k in ("max_velocity", "max_acceleration", "max_jerk")]
    for key, value in zip(("max_velocity", "max_acceleration", "max_jerk"), rates, strict=True):
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"joint {joint.name}: {key} must be positive, got {value!r}")
    status = {
        k: getattr(joint, f"{k}_status", "")
        for k in ("max_velocity", "max_acceleration", "max_jerk", "home")
    }
    sources = dict(getattr(joint, "sources", {}) or {})
    return AxisSpec(
        name=f"Axis{index + 1}",
        joint=" ".join(str(joint.name).split()),
        kind=joint.kind,
        unit="deg" if revolute else "mm",
        per_pulse=per_pulse,
        pulses_per_rev=int(joint.pulses_per_rev),
        lower=None if unlimited else to_user(joint.lower),
        upper=None if unlimited else to_user(joint.upper),
        max_velocity=rates[0],
        max_acceleration=rates[1],
        max_jerk=rates[2],
        home_mode=str(joint.require("home_mode")),
        home_position=to_user(joint.require("home_position")),
        provenance={k: {"status": status[k], "source": sources.get(k, "")} for k in status},
    )


def machine_spec(arm) -> MachineSpec:
    """The machine of ``arm`` (an :class:`~analysis.kinematics.arm.Arm`); ValueError naming
    the joint and the key for a description without motion limits or homing, or an input
    the machine has no name for."""
    unknown = [n for n in arm.inputs if n not in TARGET_NAMES]
    if unknown:
        raise ValueError(
            f"arm {arm.name}: no machine input for the closed form's "
            f"{', '.join(unknown)} (known: {', '.join(TARGET_NAMES)})"
        )
    axes = tuple(_axis(k, j) for k, j in enumerate(arm.description.joints))
    return MachineSpec(
        arm=arm.name,
        title=" ".join(str(arm.description.title).split()),  # one line in every comment
        ik_inputs=tuple(arm.inputs),
        ik_units=tuple(arm.input_units),
        targets=tuple(TARGET_NAMES[n] for n in arm.inputs),
        axes=axes,
    )

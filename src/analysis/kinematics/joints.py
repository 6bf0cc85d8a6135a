"""The joints of an arm description: :class:`JointSpec` (kind, limits, drive, motion limits
and homing, each with its provenance) and the readers of a ``[[joints]]`` entry
(:func:`read_joint`) or, for an engineer's D-H table without one, of the rows' joints
(:func:`row_joints`); the format is :mod:`analysis.kinematics.description`'s.

The drive (pulses per revolution; a prismatic joint's lead) is optional: a D-H table has none,
and FK, IK, URDF and the explorer need none. It is read in one place, :attr:`JointSpec.
pulses_per_rev` and :attr:`JointSpec.lead_mm` (and :attr:`analysis.kinematics.params.Params.
pulses_per_rev`, built from them), which raise :class:`~analysis.kinematics.schema.NoDrive`
naming the joint and the missing key: what needs pulses refuses there, at the point of need.

Motion limits and homing (the shared contract, ../shared/design.md) are optional too:
:meth:`JointSpec.require` names what a machine program lacks.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

from analysis import validate
from analysis.kinematics import schema
from analysis.kinematics.schema import DescriptionError, NoDrive, Reader, source, status

__all__ = [
    "HOME_MODES",
    "JOINT_KINDS",
    "MOTION_KEYS",
    "NO_DRIVE",
    "RATE_KEYS",
    "JointSpec",
    "read_joint",
    "row_joints",
]

JOINT_KINDS = ("revolute", "prismatic")
NO_DRIVE = "no drive given"
"""What a text output says where pulses would be and the arm has no drive (``ik``, the
explorer); JSON says null, a batch CSV has no pulse columns."""
HOME_MODES = ("switch", "set")
"""How an axis is homed: "switch" (a reference switch is searched, MC_Home with a switch) or
"set" (the present position is declared to be the home position)."""
RATE_KEYS = ("max_velocity", "max_acceleration", "max_jerk")
MOTION_KEYS = (*RATE_KEYS, "home_mode", "home_position")
"""The joint values a machine program needs (:meth:`JointSpec.require`)."""
_RATE_UNIT = {"max_velocity": "/s", "max_acceleration": "/s2", "max_jerk": "/s3"}


def _rate_hint(key: str):
    return lambda j: (f'{key} = {{ value = ..., unit = "{"deg" if j.kind == "revolute" else "mm"}'
                      f'{_RATE_UNIT[key]}", status = ..., source = ... }}')  # fmt: skip


_MOTION_HINT = {
    **{k: _rate_hint(k) for k in RATE_KEYS},
    **dict.fromkeys(("home_mode", "home_position"), lambda j: 'home = { mode = "switch" | '
                    '"set", position = ..., status = ..., source = ... }'),
}  # fmt: skip


@dataclass(frozen=True)
class JointSpec:
    """One joint variable: its kind, limits [rad | mm] and, where the description gives one,
    its drive (pulses per revolution; a prismatic joint's lead).

    A revolute joint's pulse count is ``theta_deg / 360 * pulses_per_rev`` (eqs. 20-22 of
    seed 000); a prismatic joint's is ``q_mm / lead_mm * pulses_per_rev`` (a screw of lead
    ``lead_mm`` per motor revolution). An engineer's D-H table has no drive: then
    :attr:`pulses_per_rev` (and a prismatic joint's :attr:`lead_mm`) raise
    :class:`~analysis.kinematics.schema.NoDrive` naming the joint and the key, the one place
    every pulse count and PLC program reads them from (:attr:`has_drive` asks first).
    """

    name: str
    drive_pulses: int | None
    """Pulses per motor revolution as given, or None (no drive given)."""
    lower: float
    upper: float
    limits_status: str = ""
    pulses_status: str = "printed"
    """Provenance of ``pulses_per_rev`` ("printed", "derived", "assumed" or "measured")."""
    kind: str = "revolute"
    drive_lead: float | None = None
    """Travel per motor revolution [mm] of a prismatic joint as given, or None."""
    lead_status: str = ""
    max_velocity: float | None = None
    """Largest speed [rad/s | mm/s], or None where the description gives none."""
    max_acceleration: float | None = None
    """Largest acceleration [rad/s^2 | mm/s^2], or None."""
    max_jerk: float | None = None
    """Largest jerk [rad/s^3 | mm/s^3], or None."""
    home_mode: str | None = None
    """How the axis finds its zero: "switch" (a reference switch, searched) or "set" (the
    present position is set to :attr:`home_position`), or None."""
    home_position: float | None = None
    """The joint value at home [rad | mm], or None."""
    max_velocity_status: str = ""
    max_acceleration_status: str = ""
    max_jerk_status: str = ""
    home_status: str = ""
    sources: Mapping[str, str] = field(default_factory=dict, compare=False)
    """Where each motion value comes from (``source`` or ``note`` of its entry), by key."""
    file: str = field(default="", compare=False, repr=False)
    """The description's file name (what a :class:`NoDrive` names)."""

    @property
    def missing_drive(self) -> str | None:
        """The drive key the description does not give (``pulses_per_rev``, or a prismatic
        joint's ``lead_mm``), or None where the joint has its drive."""
        if self.drive_pulses is None:
            return "pulses_per_rev"
        if self.kind == "prismatic" and self.drive_lead is None:
            return "lead_mm"
        return None

    @property
    def has_drive(self) -> bool:
        """True if the description gives the joint's drive (pulse counts are defined)."""
        return self.missing_drive is None

    @property
    def pulses_per_rev(self) -> int:
        """Pulses per motor revolution; :class:`NoDrive` naming the joint and the missing key
        where the description gives no drive.

        >>> JointSpec("theta1", None, -1.0, 1.0).pulses_per_rev  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        analysis.kinematics.schema.NoDrive: joint theta1 pulses_per_rev: is missing: no drive ...
        """
        if self.missing_drive:
            raise NoDrive(self.file, self.name, self.missing_drive)
        return self.drive_pulses

    @property
    def lead_mm(self) -> float | None:
        """Travel per motor revolution [mm] of a prismatic joint (None for a revolute one);
        :class:`NoDrive` for a prismatic joint whose description gives none."""
        if self.kind == "prismatic" and self.drive_lead is None:
            raise NoDrive(self.file, self.name, "lead_mm")
        return self.drive_lead

    def require(self, key: str) -> float | str:
        """The motion value ``key`` (one of :data:`MOTION_KEYS`), or ValueError naming the
        joint and the key when the description gives none (a program that needs it refuses).

        >>> JointSpec("theta1", 4000, -1.0, 1.0).require("max_velocity")
        Traceback (most recent call last):
        ...
        ValueError: joint theta1 has no max_velocity: give max_velocity = { value = ...
        """
        if key not in MOTION_KEYS:
            raise ValueError(f"{key!r} is not a motion value ({', '.join(MOTION_KEYS)})")
        value = getattr(self, key)
        if value is None:
            raise ValueError(f"joint {self.name} has no {key}: give {_MOTION_HINT[key](self)} "
                             "in its [[joints]] entry")  # fmt: skip
        return value

    @property
    def unit(self) -> str:
        """The joint value's unit: "rad" (revolute) or "mm" (prismatic)."""
        return "rad" if self.kind == "revolute" else "mm"

    @property
    def unlimited(self) -> bool:
        """True if the limits allow every angle (a revolute joint turning a full turn or
        more; a prismatic joint always has a stroke)."""
        return self.kind == "revolute" and self.lower <= -math.pi and self.upper >= math.pi


def read_joint(r: Reader, number, file: str) -> JointSpec:
    """One ``[[joints]]`` entry; its drive (``pulses_per_rev``, a prismatic joint's
    ``lead_mm``) optional: without it the joint has no pulse count (:class:`JointSpec`).
    ``number(r, key)`` reads a number given bare, as ``{ value = ... }`` or from a table (the
    description's :meth:`~analysis.kinematics.description._Context.number`); ``file`` is the
    description's file name."""
    r.check_keys(schema.JOINT)
    name = r.ident("name")
    r.where = f"joint {name}"
    kind = r.choice("kind", JOINT_KINDS, "revolute")
    ppr = pspec = None
    if "pulses_per_rev" in r:
        pspec = r.sub("pulses_per_rev", schema.NUMBER_SPEC) if isinstance(
            r.raw("pulses_per_rev"), dict) else None  # fmt: skip
        if pspec is not None and "resolution_deg" in pspec:
            pspec.number("resolution_deg", lo=0.0, hi=360.0, unit="deg")
        try:
            ppr = validate.pulses_per_rev(number(r, "pulses_per_rev"), "")
        except validate.InvalidValue as exc:
            raise r.error("pulses_per_rev", str(exc).lstrip(" =")) from None
    lead = lead_status = None
    if kind == "revolute":
        for key in ("limits_mm", "lead_mm"):
            if key in r:
                raise r.error(key, "is for a prismatic joint (kind = \"prismatic\")")
        lo, hi = (math.radians(v) for v in (r.pair("limits_deg", r.angle_deg)
                                            if "limits_deg" in r else (-180.0, 180.0)))  # fmt: skip
    else:
        if "limits_deg" in r:
            raise r.error("limits_deg", "a prismatic joint's stroke is limits_mm")
        if "limits_mm" not in r:
            raise r.error("limits_mm", "is missing: a prismatic joint needs its stroke "
                          "(limits_mm = [lower, upper])")  # fmt: skip
        if ppr is not None and "lead_mm" not in r:
            raise r.error("lead_mm", "is missing: a prismatic joint's drive is pulses_per_rev "
                          "and lead_mm (the travel per motor revolution): give both or neither")
        lo, hi = r.pair("limits_mm", r.length)
        if "lead_mm" in r:
            if isinstance(r.raw("lead_mm"), dict):
                lead_status = status(r.sub("lead_mm", schema.NUMBER_SPEC))
            lead = number(r, "lead_mm")
            if not lead > 0 or lead > validate.MAX_LENGTH_MM:
                raise r.error("lead_mm", f"{lead:g} mm must be > 0 mm and at most "
                              f"{validate.MAX_LENGTH_MM:g} mm")  # fmt: skip
    given = (status(pspec) if pspec else "printed") if ppr is not None else ""
    return JointSpec(
        name, ppr, lo, hi, r.text("limits_status"), given, kind, lead, lead_status or "",
        **_motion(r, kind, lo, hi), file=file,
    )  # fmt: skip


def row_joints(file: str, rows: tuple) -> tuple[JointSpec, ...]:
    """The joints of a description without ``[[joints]]``: one per moving D-H row, named as
    the row names it (``joint``; else ``theta<i>``, or ``d<i>`` for a prismatic row, i
    counting the moving rows), revolute joints limited to one turn (-180..180 deg), no
    drive. A prismatic row's stroke is no part of a D-H table: it needs a ``[[joints]]``
    entry."""
    out = []
    for i, row in enumerate((r for r in rows if r.get("kind", "revolute") != "fixed"), 1):
        kind = row.get("kind", "revolute")
        name = row.get("joint") or f"{'theta' if kind == 'revolute' else 'd'}{i}"
        if kind == "prismatic":
            raise DescriptionError(file, "[[joints]]", f"is missing, and D-H row {name} is "
                                   "prismatic: its stroke is no part of a D-H table (give "
                                   "[[joints]] entries, one per joint, with limits_mm = "
                                   "[lower, upper] for this one)")  # fmt: skip
        out.append(JointSpec(name, None, -math.pi, math.pi, "", "", file=file))
    return tuple(out)


def _motion(r: Reader, kind: str, lo: float, hi: float) -> dict:
    """The joint's motion limits and homing (``max_velocity``, ``max_acceleration``,
    ``max_jerk``, ``home``), converted to the joint's units (rad | mm) by
    :func:`analysis.validate.rate`; absent keys stay None."""
    out: dict = {"sources": {}}
    for order, key in enumerate(RATE_KEYS, start=1):
        if key not in r:
            continue
        s = r.sub(key, schema.RATE)
        for need in ("value", "unit"):
            if need not in s:
                raise s.error(need, f"is missing ({key} = {{ value = ..., unit = ..., "
                              "status = ..., source = ... }})")  # fmt: skip
        try:
            out[key] = validate.rate(s.raw("value"), s.raw("unit"), "", order=order, kind=kind)
        except ValueError as exc:
            raise s.error("value", str(exc).lstrip(": =")) from None
        out[f"{key}_status"], out["sources"][key] = status(s), source(s)
    if "home" in r:
        s = r.sub("home", schema.HOME)
        mode = s.choice("mode", HOME_MODES)
        if "position" not in s:
            raise s.error("position", "is missing (deg | mm, within the joint's limits)")
        pos = (math.radians(s.angle_deg("position")) if kind == "revolute" else
               s.length("position"))  # fmt: skip
        if not lo <= pos <= hi:
            unit, show = ("deg", math.degrees) if kind == "revolute" else ("mm", float)
            raise s.error("position", f"{show(pos):g} {unit} is outside the joint's limits "
                          f"[{show(lo):g}, {show(hi):g}] {unit}")  # fmt: skip
        out["home_mode"], out["home_position"] = mode, pos
        out["home_status"], out["sources"]["home"] = status(s), source(s)
    return out

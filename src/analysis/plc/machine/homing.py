"""How the machine program homes each axis (:mod:`.program`, module docstring item 4): the
blocks it declares and calls per axis, as the arm description's ``home.mode`` says.

- ``set``: PLCopen Part 5 MC_HomeDirect (the present position declared the home position, no
  motion: the operator has put the axis on its mark);
- ``switch``: Part 5 MC_StepAbsoluteSwitch twice (the approach at :data:`~.spec.HOME_APPROACH`
  of the velocity limit, the direction from the switch's level, the edge latched; then the
  creep from the far side of the edge at :data:`~.spec.HOME_CREEP` of the limit or half a pulse
  per task cycle, whichever is slower, so the edge is seen to half a pulse), the position set
  to the home position, then MC_FinishHoming (soft limits watched again); each search gives up
  after the joint's range (DistanceLimit).

TIA Portal (:mod:`.program_scl`) has neither: MC_Home Mode 0 (set) or 3 (active homing with
the technology object's approach and referencing velocities and its reference cam).
"""

from __future__ import annotations

from analysis.plc.machine.spec import HOME_APPROACH, HOME_CREEP

__all__ = ["HOMING_STEP", "HomingMixin", "lreal"]

HOMING_STEP = 10
"""The sequence's homing step (``Phase``; :data:`.program.STEPS`)."""


def lreal(v: float) -> str:
    """An LREAL literal (17 significant digits: the binary64 value exactly)."""
    s = repr(float(v))
    if "e" in s or "E" in s:
        m, e = s.lower().split("e")
        return f"LREAL#{m if '.' in m else m + '.0'}E{int(e)}"
    return f"LREAL#{s}"


class HomingMixin:
    """The homing of :class:`.program.MachinePrinter` (module docstring); ``self.v`` names a
    variable in the dialect."""

    def home_blocks(self, a) -> list[tuple[str, str]]:
        """(instance prefix, block) of an axis' homing (module docstring, item 4)."""
        if a.home_mode == "set":
            return [("Homing", "MC_HomeDirect")]
        return [
            ("Homing", "MC_StepAbsoluteSwitch"),
            ("Creep", "MC_StepAbsoluteSwitch"),
            ("Finish", "MC_FinishHoming"),
            ("RefSwitch", "MC_REFERENCE_SIGNAL_REF"),
        ]

    def homed(self, a) -> str:
        """The axis' homing is done."""
        k = a.name[4:]
        return self.v(("Homing" if a.home_mode == "set" else "Finish") + k) + ".Done"

    def home_call(self, k: str, ax: str, a) -> list[str]:
        """Module docstring, item 4 (velocities per MotionTimeUnit; the creep speed from
        the task cycle: at most half a pulse per cycle)."""
        v, tu = self.v, self.v("Tu")
        home = f"{v('Phase')} = {HOMING_STEP}"
        if a.home_mode == "set":
            return [f"{v('Homing' + k)}(Axis := {ax}, Execute := {home}, SetPosition := "
                    f"{lreal(a.home_position)});"]  # fmt: skip
        reach = 360.0 if a.unlimited else a.upper - a.lower
        fast = a.max_velocity * HOME_APPROACH
        search = (
            "Direction := MC_HOME_DIRECTION#switch_positive, SwitchMode := "
            f"MC_SWITCH_MODE#edge_positive, ReferenceSignal := {v('RefSwitch' + k)}"
        )
        creep = (f"MIN({lreal(a.max_velocity * HOME_CREEP)}, {lreal(a.per_pulse / 2.0)} / "
                 f"{v('TaskCycle')})")  # fmt: skip
        return [
            f"{v('Homing' + k)}(Axis := {ax}, Execute := {home}, {search}, Velocity := "
            f"{lreal(fast)} * {tu}, SetPosition := {lreal(a.home_position)}, DistanceLimit := "
            f"{lreal(reach)});",
            f"{v('Creep' + k)}(Axis := {ax}, Execute := ({home}) AND {v('Homing' + k)}.Done, "
            f"{search}, Velocity := {creep} * {tu}, SetPosition := {lreal(a.home_position)}, "
            f"DistanceLimit := {lreal(4.0 * fast)} * {v('TaskCycle')} + "
            f"{lreal(4.0 * a.per_pulse)});",
            f"{v('Finish' + k)}(Axis := {ax}, Execute := ({home}) AND {v('Creep' + k)}.Done, "
            "Distance := LREAL#0.0);",
        ]

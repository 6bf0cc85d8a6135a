"""Each property the scenarios hold, broken once on purpose in the generated program: its
check must go red (and the unbroken program passes it: test_scenarios.py). A check that
cannot fail proves nothing."""

from __future__ import annotations

import pytest
from tests.plc.machine.conftest import machine, scenario_set

from analysis.plc.machine.program import lreal
from analysis.plc.machine.run import run_scenario
from analysis.plc.machine.scenarios import check

# (scenario, what to replace in the program, by what, a word of the failure expected)
BREAKS = {
    "final": ("move", "DINT_TO_LREAL(Ik.c2)", "DINT_TO_LREAL(Ik.c2 + 2)", "final theta2"),
    "velocity": (
        "move",
        "Velocity := NormV * Scale * Tu",
        "Velocity := NormV * Scale * Tu * LREAL#1.5",
        "velocity",
    ),
    "jump": (
        "move",
        "Jerk := NormJ * Scale * Tu * Tu * Tu",
        "Jerk := NormJ * Scale * Tu * Tu",
        "jerk",
    ),
    "together": ("move", "    Scale := Dist3;", "    Scale := Dist3 * LREAL#0.7;", "in proportion"),
    "short_way": (
        "wrap",
        "    Goal1 := Pos1 + (Dist1 - LREAL#360.0 * DINT_TO_LREAL("
        "LREAL_TO_DINT(Dist1 / LREAL#360.0)));",
        "",
        "final theta1",
    ),
    "stop": ("stop", "        StopLatched := TRUE;", "", "moved"),
    "stop_distance": (
        "stop",
        # the stop braking at half the waist's deceleration (the grabber's max_acceleration)
        "Stop1(Axis := Axis1, Execute := Phase = 40, Deceleration := {a} * Tu * Tu",
        "Stop1(Axis := Axis1, Execute := Phase = 40, Deceleration := {a} * LREAL#0.5 * Tu * Tu",
        "came to rest",
    ),
    # the unit move not aligned to whole cycles: the engine ends the joints cycles apart
    "aligned": ("move", "+ LREAL#0.75) * TaskCycle", "+ LREAL#0.0) * TaskCycle", "apart"),
    # half-cycle phases: the engine's correction quintic overshoots the goal and comes back
    "overshoot": ("move", "+ LREAL#0.75) * TaskCycle", "+ LREAL#0.5) * TaskCycle", "moved back"),
    # an axis error not latched: the other axes carry on when a drive fails
    "axis_error": ("axis_error", "IF Fault AND NOT FaultLatched THEN", "IF FALSE THEN", "Status"),
    # no dwell: the gripper reported closed at once, a Start accepted while it closes
    "dwell": ("handling", "(Phase = 50) AND GripTimer.Q", "(Phase = 50)", "GripperClosed"),
    "refusal": ("unreachable", "IF Ik.Error THEN", "IF FALSE THEN", "Status"),
    "homed": ("power_home", "ELSIF NOT Homed THEN", "ELSIF FALSE THEN", "moved"),
    # homing: one axis not homed (its encoder's stale count kept) yet Homed reported
    "home_skipped": (
        "move",
        ("Homing2(Axis := Axis2, Execute := Phase = 10,", "Homing1.Done AND Homing2.Done"),
        ("Homing2(Axis := Axis2, Execute := FALSE,", "Homing1.Done"),
        "the PLC reads",
    ),
    # a reference switch taken at the approach speed only (no creep from the far side):
    # the edge is seen to a cycle's travel, 40 pulses of the picker's screw
    "creep": ("power_home", "AND Creep2.Done", "AND Homing2.Done", "pulses off its home"),
    # the approach at 1.25 times the velocity limit
    "home_speed": (
        "power_home",
        "Velocity := LREAL#7.499999999999999 * Tu",
        "Velocity := LREAL#37.5 * Tu",
        "velocity",
    ),
    # the stop circuit watched only while the machine moves, and Reset clearing it whatever
    # the circuit says: after Reset, a Start goes with the wire still broken
    "wire_break": (
        "wire_break",
        ("IF NOT StopOK THEN", "        IF StopOK THEN\n            StopLatched := FALSE;"),
        ("IF NOT StopOK AND Busy THEN", "        IF TRUE THEN\n            StopLatched := FALSE;"),
        "moved",
    ),
}


ARM = {"creep": "picker", "home_speed": "gr1"}
"""The arm a break runs on (default the grabber; a reference switch needs another)."""


@pytest.mark.parametrize("prop", sorted(BREAKS))
def test_a_broken_program_fails_its_check(machine_engine, prop):
    name, old, new, word = BREAKS[prop]
    arm = ARM.get(prop, "grabber")
    _, spec, source, program, _ = machine(arm)
    decel = lreal(spec.axes[0].max_acceleration)
    old, new = (tuple(x.replace("{a}", decel) for x in v) if not isinstance(v, str)
                else v.replace("{a}", decel) for v in (old, new))  # fmt: skip
    broken = source
    for o, n in zip(*((x,) if isinstance(x, str) else x for x in (old, new)), strict=True):
        assert o in source, f"the program no longer holds {o!r}"
        broken = broken.replace(o, n)
    scenario = scenario_set(arm)[name]
    failures = check(
        scenario,
        run_scenario(broken, program, spec, scenario.rows),
        spec,
        arrive_s=None if prop == "aligned" else 10.0,
    )
    assert any(word in f for f in failures), failures

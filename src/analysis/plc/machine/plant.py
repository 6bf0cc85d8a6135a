"""The simulated machine the scenarios run on (:mod:`.run`): where each axis stands at power-up,
what its encoder reads then, where its reference switch is, and how long homing may take.

- A ``switch`` axis (the description's ``home.mode``) stands off its home position at
  power-up (half a second of its homing approach speed away, alternately below and above), its
  reference switch at the home position (the cam ON at and beyond it), its encoder reading a
  stale count (an incremental encoder: any value until homed).
- A ``set`` axis stands on its home mark (the description says the operator sets it there:
  a present position is declared home, nothing can check it), its encoder again reading a
  stale count: until homed, the PLC's position is wrong by that much.

Homing is what brings the PLC's position to the physical one: a scenario asserts that each
axis ends on its home position within one pulse (the physical position, held apart from the
program) and reads exactly its home position (the encoder), :func:`analysis.plc.machine.checks.
check_homed`.
"""

from __future__ import annotations

from analysis.plc.machine.profile import min_time, stop_distance
from analysis.plc.machine.spec import HOME_APPROACH, HOME_CREEP, MachineSpec

__all__ = ["homing_bound", "power_up"]

STALE = 3.0
"""The stale encoder count of axis k at power-up: ``STALE * (k + 1)`` joint units (deg or mm)
from its physical position, away from home, inside its software limits."""


def power_up(spec: MachineSpec) -> list[tuple[float, float, float | None]]:
    """(physical position, encoder position, switch position or None) of each axis."""
    out = []
    for k, a in enumerate(spec.axes):
        sign = -1.0 if k % 2 else 1.0
        start = a.home_position
        if a.home_mode == "switch":
            start -= sign * 0.5 * HOME_APPROACH * a.max_velocity
        coord = start - sign * STALE * (k + 1)  # farther off home, not back toward it
        if not a.unlimited:
            coord = min(max(coord, a.lower), a.upper)
        out.append((start, coord, a.home_position if a.home_mode == "switch" else None))
    return out


def homing_bound(spec: MachineSpec, cycle_s: float) -> float:
    """An upper bound [s] on the homing of every axis from :func:`power_up` (the axes home
    together): the approach (accelerate, cover the distance, brake, come back to the edge),
    the creep search from the far side of the edge, the same again, and 10 cycles for each
    step's hand-over."""
    worst = 0.0
    for a, (start, _, switch) in zip(spec.axes, power_up(spec), strict=True):
        if switch is None:
            continue
        acc, jerk = a.max_acceleration, a.max_jerk
        t = 0.0
        creep = min(a.max_velocity * HOME_CREEP, a.per_pulse / (2 * cycle_s))
        for v, d in ((HOME_APPROACH * a.max_velocity, abs(start - switch)), (creep, 0.0)):
            d = d + v * cycle_s * 2 if d else HOME_APPROACH * a.max_velocity * cycle_s * 2
            brake = stop_distance(v, 0.0, acc, jerk) + v * cycle_s
            t += min_time(d + brake, v, acc, jerk) + min_time(brake, v, acc, jerk)
        worst = max(worst, t)
    return 1.5 * worst + 30 * cycle_s

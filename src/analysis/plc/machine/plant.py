"""The simulated machine the scenarios run on (:mod:`.run`): where each axis stands at power-up,
what its encoder reads then, where its reference switch is, and how long homing may take.

- A ``switch`` axis (the description's ``home.mode``) stands off its home position at
  power-up (:data:`HOME_OFF_S` of its homing approach speed away, alternately below and
  above: far enough for the approach to reach its speed and cruise), its
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

__all__ = ["HOME_OFF_S", "homing_bound", "placed", "power_up", "power_up_axis"]

HOME_OFF_S = 2.0011
"""How far off home a ``switch`` axis stands at power-up: this many seconds of its homing
approach (:data:`~.spec.HOME_APPROACH` of its velocity limit). About 2 s: the approach ramps
up to its speed and cruises (an approach too fast for the velocity limit is seen); the odd
1.1 ms (0.275 of a 4 ms cycle) puts the switch between two cycles' positions, as it is on a
real axis (a search that takes the edge at the approach speed is seen off by part of a
cycle's travel; at a whole number of half cycles the ramped approach lands on the edge)."""

STALE = 3.0
"""The stale encoder count of axis k at power-up: ``STALE * (k + 1)`` joint units (deg or mm)
from its physical position, away from home, inside its software limits."""


def placed(
    k: int, start: float, home_mode: str, home: float, limits=None
) -> tuple[float, float, float | None]:
    """(physical position, encoder position, switch position or None) of axis ``k`` standing
    at ``start`` at power-up: its encoder reads a stale count (``STALE * (k + 1)`` off,
    away from home, inside its software ``limits`` (lower, upper), None: unlimited), its
    reference switch (a ``switch`` axis) at ``home``."""
    sign = -1.0 if k % 2 else 1.0
    coord = start - sign * STALE * (k + 1)
    if limits is not None:
        coord = min(max(coord, limits[0]), limits[1])
    return start, coord, home if home_mode == "switch" else None


def power_up_axis(
    k: int, home_mode: str, home: float, max_velocity: float, limits=None
) -> tuple[float, float, float | None]:
    """:func:`placed` at the power-up position of axis ``k`` (module docstring): a ``switch``
    axis :data:`HOME_OFF_S` of its homing approach off home (below for an even ``k``, above
    for an odd one), a ``set`` axis on its mark."""
    sign = -1.0 if k % 2 else 1.0
    off = HOME_OFF_S * HOME_APPROACH * max_velocity if home_mode == "switch" else 0.0
    start = home - sign * off
    return placed(k, start, home_mode, home, limits)


def power_up(spec: MachineSpec) -> list[tuple[float, float, float | None]]:
    """(physical position, encoder position, switch position or None) of each axis
    (:func:`power_up_axis`)."""
    out = []
    for k, a in enumerate(spec.axes):
        limits = None if a.unlimited else (a.lower, a.upper)
        out.append(power_up_axis(k, a.home_mode, a.home_position, a.max_velocity, limits))
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

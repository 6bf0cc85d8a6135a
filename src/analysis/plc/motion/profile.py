"""Acceleration ramps for the S7-200's multi-segment PTO profiles, from a joint's limits.

The S7-200 ramps a pulse train by changing the cycle time a fixed amount every pulse (the
profile table's "cycle time delta per pulse", integer units of the time base: S7-200 System
Manual A5E00066097-02 p.9-53, Table 9-15). A pulse of cycle ``T`` followed by one of
``T - delta`` accelerates by about ``delta / T**3`` (pulses/s^2): the same delta accelerates
harder the faster the joint runs. A ramp is therefore cut into ``m`` segments between the
start cycle ``T_0`` and the cycle at full speed ``T_m`` (geometric steps), each with the
largest whole delta that keeps ``delta / T**3`` within the joint's acceleration at the
segment's fastest pulse:

* ``f_max = max_velocity * pulses/rev / 360 deg``: ``T_m = ceil(1e6 / f_max)`` us, so no
  pulse is faster than the limit;
* the start frequency ``f_0 = sqrt(2 a)``, the speed constant acceleration ``a`` reaches
  after one pulse from rest (a stepper's start/stop frequency must be at least that; the
  jump from rest to ``f_0`` is the only one not limited);
* segment ``i`` (from ``T_{i-1}`` to ``T_i``): ``delta_i = floor(a T_i^3)`` us, and
  ``ceil((T_{i-1} - T_i) / delta_i)`` pulses, so that its last pulse is at most one delta
  slower than ``T_i`` (the next segment's first cycle) and no step between two pulses
  exceeds the acceleration;
* the deceleration is the ramp run backwards.

A move of ``n`` pulses uses ramp level ``K``, the largest with ``2 * cum_K < n`` (``cum_K``
the pulses of the first ``K`` segments): ``K`` segments up, the rest at the speed reached,
``K`` down. Level 0 is one segment at ``f_0``. Every profile therefore has 2K + 1 segments
(:meth:`Ramp.table`), stays within ``max_velocity`` and ``max_acceleration``, and is
:meth:`Ramp.duration` long. Jerk is not limited: the S7-200's segments change acceleration
in steps (the joint's ``max_jerk`` is used by the ST machine programs only).

The delta is a whole microsecond: above ``(a / 1 us)^(1/3)`` pulses/s even a delta of 1
accelerates harder than ``a``, so such a speed is refused with the joint's name
(:func:`ramp`). Why hand-written: the Position Control Wizard that computes such tables is
part of STEP 7-Micro/WIN; no library prints S7-200 profile tables.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

__all__ = ["Ramp", "ramp"]

PTO_MAX_HZ = 20_000
"""The CPU 224's PTO frequency limit (widely quoted, not read in the manual: the team's
STL reference marks it unconfirmed); a faster joint is refused."""


@dataclass(frozen=True)
class Ramp:
    """A joint's ramp in microseconds (module docstring).

    ``segments[i] = (initial cycle, delta, pulses)`` of acceleration segment ``i + 1``;
    ``plateau[k]`` the cycle after ``k`` segments (``plateau[0] = T_0``); ``cum[k]`` the
    pulses of the first ``k`` segments.
    """

    joint: str
    f_max: float
    accel: float
    segments: tuple[tuple[int, int, int], ...]
    plateau: tuple[int, ...]
    cum: tuple[int, ...]

    @property
    def levels(self) -> int:
        return len(self.segments)

    def level(self, n: int) -> int:
        """The ramp level of a move of ``n >= 1`` pulses: the largest ``K`` with
        ``2 cum_K < n``."""
        return max(k for k in range(self.levels + 1) if 2 * self.cum[k] < n)

    def table(self, n: int) -> list[tuple[int, int, int]]:
        """The profile of a move of ``n >= 1`` pulses: segments (initial cycle, delta,
        pulses), 2K + 1 of them."""
        k = self.level(n)
        up = list(self.segments[:k])
        down = [(c0 + (m - 1) * d, -d, m) for c0, d, m in reversed(up)]
        return [*up, (self.plateau[k], 0, n - 2 * self.cum[k]), *down]

    def duration(self, n: int) -> float:
        """Seconds from the first pulse of a move of ``n`` pulses to the end of its last."""
        return sum(m * c0 + d * m * (m - 1) / 2 for c0, d, m in self.table(n)) * 1e-6


def ramp(
    name: str, max_velocity: float, max_acceleration: float, pulses_per_rev: int, levels: int = 5
) -> Ramp:
    """The ramp of a revolute joint (module docstring).

    Parameters
    ----------
    name : str
        The joint, for messages.
    max_velocity, max_acceleration : float
        [rad/s], [rad/s^2] (:class:`~analysis.kinematics.description.JointSpec`).
    pulses_per_rev : int
    levels : int
        Acceleration segments ``m`` (1..40).

    >>> r = ramp("theta1", math.radians(90), math.radians(360), 4000)
    >>> r.f_max, r.plateau[0], r.plateau[-1]
    (1000.0, 11180, 1000)
    """
    if not 1 <= levels <= 40:
        raise ValueError(f"ramp levels = {levels}: 1..40 (a profile holds 255 segments)")
    per_rad = pulses_per_rev / (2 * math.pi)
    f_max, a = max_velocity * per_rad, max_acceleration * per_rad
    deg = math.degrees
    if f_max > PTO_MAX_HZ:
        raise ValueError(
            f"joint {name}: max_velocity {deg(max_velocity):g} deg/s is {f_max:.0f} pulses/s; "
            f"the CPU 224's PTO gives at most {PTO_MAX_HZ} pulses/s"
        )
    f_ok = (a / 1e-6) ** (1 / 3)  # delta = 1 us at this speed already accelerates by ``a``
    if f_max > f_ok:
        raise ValueError(
            f"joint {name}: at max_velocity {deg(max_velocity):g} deg/s ({f_max:.0f} pulses/s) "
            f"the PTO's smallest ramp step (1 us a pulse) accelerates by more than "
            f"max_acceleration {deg(max_acceleration):g} deg/s^2: at most {f_ok:.0f} pulses/s "
            f"({f_ok / per_rad * 180 / math.pi:.1f} deg/s) can be ramped"
        )
    t_min = math.ceil(1e6 / f_max)
    t_0 = min(65535, round(1e6 / math.sqrt(2 * a)))
    if t_0 <= t_min:  # the start frequency is already the top speed: no ramp
        return Ramp(name, 1e6 / t_min, a, (), (t_min,), (0,))
    cycles = [round(t_0 * (t_min / t_0) ** (i / levels)) for i in range(levels + 1)]
    cycles[-1] = t_min
    segs, plateau, cum = [], [t_0], [0]
    for t_from, t_to in itertools.pairwise(cycles):
        if t_to >= t_from:
            continue
        delta = math.floor(a * (t_to * 1e-6) ** 3 * 1e6)
        n = math.ceil((t_from - t_to) / delta)
        segs.append((t_from, -delta if n > 1 else 0, n))
        plateau.append(t_to)
        cum.append(cum[-1] + n)
    return Ramp(name, 1e6 / t_min, a, tuple(segs), tuple(plateau), tuple(cum))

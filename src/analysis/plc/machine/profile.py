"""Jerk-limited point-to-point profiles, computed in closed form apart from any PLC engine: the
numbers the machine scenarios are held to (:mod:`.scenarios`).

A rest-to-rest move of distance ``d`` with velocity, acceleration (= deceleration) and jerk
limits ``v, a, j`` takes at least :func:`min_time` (the seven-phase S-curve: jerk up,
constant acceleration, jerk down, cruise, and the mirror image); a stop from velocity ``v0``
and acceleration ``a0`` needs at least :func:`stop_distance` (jerk down to ``-a``, constant
deceleration, jerk back to zero at rest). :func:`sync_limits` is the synchronised move of
several joints as the machine program plans it (:mod:`.program`): one path parameter whose
limits are the smallest ``limit_i / d_i``, so every joint stays within its own limits and
all arrive together; :func:`sync_time` its duration.

Why by hand: the formulas are a page of algebra (e.g. Biagiotti and Melchiorri, Trajectory
Planning for Automatic Machines and Robots, 2008, sec. 3.4); a library (ruckig) would add a
compiled dependency for three functions, and the point is an implementation independent of
the engine's (pyplcopen's otg), not a second copy of one.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["min_time", "stop_distance", "sync_limits", "sync_time"]


def _ramp(dv: float, a: float, j: float) -> float:
    """Duration of a jerk-limited velocity change ``dv`` >= 0 from and to zero acceleration."""
    if dv <= 0.0:
        return 0.0
    if dv <= a * a / j:
        return 2.0 * math.sqrt(dv / j)
    return dv / a + a / j


def min_time(d: float, v: float, a: float, j: float) -> float:
    """The shortest rest-to-rest move of distance ``|d|`` within ``v, a, j`` [s]."""
    d = abs(float(d))
    if d == 0.0:
        return 0.0
    ta = _ramp(v, a, j)
    if d >= v * ta:  # reaches v: accelerate, cruise, decelerate
        return 2.0 * ta + (d - v * ta) / v
    # peak velocity vp < v, with d = vp * ramp(vp)
    vp = a * (-a / j + math.sqrt((a / j) ** 2 + 4.0 * d / a)) / 2.0
    if vp < a * a / j:
        vp = (d * math.sqrt(j) / 2.0) ** (2.0 / 3.0)
    return 2.0 * _ramp(vp, a, j)


def stop_distance(v0: float, a0: float, a: float, j: float) -> float:
    """The shortest distance [|unit|] to rest from velocity ``v0`` and acceleration ``a0``
    (same unit per second, per second^2) with deceleration ``a`` and jerk ``j``."""
    if v0 == 0.0 and a0 == 0.0:
        return 0.0
    s = 1.0 if v0 > 0 or (v0 == 0.0 and a0 > 0) else -1.0
    v0, a0 = abs(v0), a0 * s
    ap = a
    t2 = (v0 + a0 * a0 / (2 * j) - ap * ap / j) / ap
    if t2 < 0.0:
        ap = math.sqrt(max(j * v0 + a0 * a0 / 2.0, 0.0))
        t2 = 0.0
    dist, vel, acc = 0.0, v0, a0
    for jerk, dur in ((-j, (a0 + ap) / j), (0.0, t2), (j, ap / j)):
        dist += vel * dur + acc * dur**2 / 2.0 + jerk * dur**3 / 6.0
        vel += acc * dur + jerk * dur**2 / 2.0
        acc += jerk * dur
    return dist


def sync_limits(d, v, a, j) -> tuple[float, float, float]:
    """The path parameter's limits of a synchronised move of distances ``d`` (per joint)
    with joint limits ``v, a, j``: the smallest ``limit_i / |d_i|`` over the moving joints
    (joint i then moves with those times ``|d_i|``)."""
    d = np.abs(np.asarray(d, dtype=float))
    moving = d > 0
    if not moving.any():
        return math.inf, math.inf, math.inf
    return tuple(float(np.min(np.asarray(x, float)[moving] / d[moving])) for x in (v, a, j))


def sync_time(d, v, a, j) -> float:
    """Duration [s] of the synchronised move (:func:`sync_limits`)."""
    vn, an, jn = sync_limits(d, v, a, j)
    return 0.0 if math.isinf(vn) else min_time(1.0, vn, an, jn)

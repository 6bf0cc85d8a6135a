"""Seed 004's cubic joint trajectories (a handling-arm thesis, section 5.4.1, eqs. 5.1-5.7),
applied to the main paper's arm.

Cubic ``q(t) = a0 + a1 t + a2 t^2 + a3 t^3`` with q(0)=q0, q(T)=qf, zero end velocities:
a0 = q0, a1 = 0, a2 = 3 (qf-q0)/T^2, a3 = -2 (qf-q0)/T^3.

The other companion papers moved to the one-source design: seed 001's palletizer is
``data/arms/palletizer.toml`` with its closed form :mod:`analysis.kinematics.arms.palletizer`
(``load_arm("palletizer")``) and its audit :mod:`analysis.audit.palletizer_checks`; seed
002's product of exponentials is :mod:`analysis.kinematics.poe` (revolute and prismatic,
screws of any D-H chain by :func:`~analysis.kinematics.poe.screws_from_dh`).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from analysis.kinematics.pulses import angles_to_pulses

__all__ = [
    "cubic_coefficients",
    "cubic_trajectory",
    "peak_pulse_rates",
    "trajectory_pulses",
]


# --------------------------------------------------------------------------- seed 004
def _check_duration(duration: float) -> float:
    duration = float(duration)
    if not (math.isfinite(duration) and duration > 0):
        raise ValueError(f"duration T = {duration} s must be finite and > 0")
    return duration


def cubic_coefficients(q0: npt.ArrayLike, qf: npt.ArrayLike, duration: float):
    """Cubic coefficients (a0, a1, a2, a3), shape (4, ...), seed 004 eqs. 5.5-5.6.

    a0 = q0, a1 = 0, a2 = 3 (qf - q0) / T^2, a3 = -2 (qf - q0) / T^3 (zero end velocity).
    """
    T = _check_duration(duration)
    q0, qf = np.broadcast_arrays(np.asarray(q0, float), np.asarray(qf, float))
    if not (np.isfinite(q0).all() and np.isfinite(qf).all()):
        raise ValueError("trajectory end points contain NaN or inf (unsolved IK?)")
    dq = qf - q0
    return np.stack([q0, np.zeros_like(q0), 3 * dq / T**2, -2 * dq / T**3])


def cubic_trajectory(q0: npt.ArrayLike, qf: npt.ArrayLike, duration: float, t: npt.ArrayLike):
    """Position, velocity, acceleration of the cubic (seed 004 eqs. 5.3-5.4, 5.7-5.9).

    Parameters
    ----------
    q0, qf : array_like, shape (..., n)
        Start and end joint angles [rad].
    duration : float
        T [s], > 0.
    t : array_like, shape (m,)
        Sample times [s] in [0, T].

    Returns
    -------
    q, qd, qdd : ndarray, shape (m, ..., n)
        [rad], [rad/s], [rad/s^2].
    """
    T = _check_duration(duration)
    t = np.asarray(t, dtype=float)
    if t.ndim != 1 or not np.isfinite(t).all() or t.min() < 0 or t.max() > T:
        raise ValueError(f"sample times must be a 1-D array within [0, T = {T:g}] s")
    a0, a1, a2, a3 = cubic_coefficients(q0, qf, T)
    tt = t.reshape(-1, *([1] * a0.ndim))
    q = a0 + a1 * tt + a2 * tt**2 + a3 * tt**3
    return q, a1 + 2 * a2 * tt + 3 * a3 * tt**2, 2 * a2 + 6 * a3 * tt + 0 * tt


def peak_pulse_rates(q0: npt.ArrayLike, qf: npt.ArrayLike, duration: float, ppr=4000):
    """Peak pulse rate per joint [pulses/s]: |qd(T/2)| = 1.5 |qf - q0| / T, times ppr/2pi."""
    T = _check_duration(duration)
    dq = np.asarray(qf, float) - np.asarray(q0, float)
    return 1.5 * np.abs(dq) / T * np.asarray(ppr, float) / (2 * np.pi)


def trajectory_pulses(q0: npt.ArrayLike, qf: npt.ArrayLike, duration: float, t, ppr=4000):
    """Commanded pulse position (eqs. 20-22) along the cubic, int64 (m, ..., n), and the
    move's pulse count per joint ``angles_to_pulses(qf) - angles_to_pulses(q0)``."""
    q, _, _ = cubic_trajectory(q0, qf, duration, t)
    moves = angles_to_pulses(qf, ppr) - angles_to_pulses(q0, ppr)
    return angles_to_pulses(q, ppr), moves

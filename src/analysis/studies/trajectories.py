"""Joint trajectories between two configurations: the GR-1 thesis's cubic, a quintic, a
trapezoidal profile, and the one-joint-after-another on/off move its PLC program makes.

Seed 004 (the GR-1 thesis, section 5.4.1, eqs. 5.1-5.9) plans each joint with the cubic
``theta(t) = a0 + a1 t + a2 t^2 + a3 t^3`` under four conditions: theta(0) = theta0,
theta(T) = thetaf (eq. 5.1) and zero end velocities (eq. 5.2). Its solution (eqs. 5.5-5.6,
lost in the extraction; the VB6 listing's ``Y = a + (3 / (c * c)) * (b - a) * (X * X) -
(2 / (c * c * c)) * (b - a) * (X * X * X)``, T = c = 10 s) is::

    a0 = theta0, a1 = 0, a2 = 3 (thetaf - theta0) / T^2, a3 = -2 (thetaf - theta0) / T^3

Every profile here is ``q(t) = q0 + (qf - q0) s(t / T)`` with a normalized ``s`` on [0, 1]:

=============  =====================================  ===========  ======================
profile        s(tau)                                 peak s'      s'' at the ends
=============  =====================================  ===========  ======================
cubic          3 tau^2 - 2 tau^3 (eqs. 5.3-5.9)       1.5          +6, -6 (jumps from 0)
quintic        10 tau^3 - 15 tau^4 + 6 tau^5          1.875        0, 0 (continuous)
trapezoidal    parabolic blends of length b T,        1 / (1 - b)  +-1 / (b (1 - b)) (jumps,
               constant velocity between (LSPB)                    also at b and 1 - b)
=============  =====================================  ===========  ======================

``t`` is a 1-D array of times [s]; ``q0, qf`` have shape (..., n) (any leading shape);
results have shape (m, ..., n): no loop over time or joints. Angles in radians unless a
name ends in ``_deg``.

:func:`sequential_move` is the move the thesis's FX2N program makes (section 2.3.4, Figure
2-1, the ladder): each motor runs on/off at its speed until its counter is full, M1 first,
then M2 ... M5; :func:`analysis.audit.papers.gr1.thesis.fx2n_vs_cubic` compares it with the cubic.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from analysis.kinematics.pulses import angles_to_pulses

__all__ = [
    "PROFILES",
    "acceleration_jumps",
    "cubic_coefficients",
    "cubic_trajectory",
    "peak_pulse_rates",
    "peak_speed_factor",
    "profile",
    "pulse_rates",
    "sequential_move",
    "trajectory",
    "trajectory_pulses",
]

PROFILES = ("cubic", "quintic", "trapezoidal")
DEFAULT_BLEND = 1.0 / 3.0
"""Trapezoidal blend fraction b (acceleration time / T): 1/3 gives the cubic's peak
velocity (1.5 (qf - q0) / T) with 3/4 of its end acceleration."""


def _check_duration(duration: float) -> float:
    duration = float(duration)
    if not (math.isfinite(duration) and duration > 0):
        raise ValueError(f"duration T = {duration} s must be finite and > 0")
    return duration


def _check_times(t: npt.ArrayLike, T: float) -> npt.NDArray[np.float64]:
    t = np.asarray(t, dtype=float)
    if t.ndim != 1 or not np.isfinite(t).all() or (t.size and (t.min() < 0 or t.max() > T)):
        raise ValueError(f"sample times must be a 1-D array within [0, T = {T:g}] s")
    return t


def _check_ends(q0: npt.ArrayLike, qf: npt.ArrayLike):
    q0, qf = np.broadcast_arrays(np.asarray(q0, float), np.asarray(qf, float))
    if not (np.isfinite(q0).all() and np.isfinite(qf).all()):
        raise ValueError("trajectory end points contain NaN or inf (unsolved IK?)")
    return q0, qf


def _check_blend(blend: float) -> float:
    blend = float(blend)
    if not (0.0 < blend <= 0.5):
        raise ValueError(f"blend fraction b = {blend} must be in (0, 0.5]")
    return blend


# --------------------------------------------------------------------------- profiles
def profile(kind: str, tau: npt.ArrayLike, *, blend: float = DEFAULT_BLEND):
    """Normalized profile ``(s, s', s'')`` at ``tau`` in [0, 1] (derivatives in tau).

    Parameters
    ----------
    kind : {"cubic", "quintic", "trapezoidal"}
    tau : array_like
        Normalized time t / T.
    blend : float
        Trapezoidal only: acceleration time as a fraction of T, in (0, 1/2].

    Examples
    --------
    >>> [float(v) for v in profile("cubic", 0.5)]
    [0.5, 1.5, 0.0]
    """
    tau = np.asarray(tau, dtype=float)
    if kind == "cubic":
        return 3 * tau**2 - 2 * tau**3, 6 * tau - 6 * tau**2, 6 - 12 * tau
    if kind == "quintic":
        return (
            tau**3 * (10 - 15 * tau + 6 * tau**2),
            30 * tau**2 * (1 - tau) ** 2,
            60 * tau * (1 - tau) * (1 - 2 * tau),
        )
    if kind == "trapezoidal":
        b = _check_blend(blend)
        v = 1.0 / (1.0 - b)  # cruise velocity
        a = v / b  # blend acceleration
        rise, fall = tau < b, tau > 1.0 - b
        u = 1.0 - tau
        cruise = v * (tau - b / 2)
        s = np.where(rise, 0.5 * a * tau**2, np.where(fall, 1.0 - 0.5 * a * u**2, cruise))
        ds = np.where(rise, a * tau, np.where(fall, a * u, v))
        dds = np.where(rise, a, np.where(fall, -a, 0.0))
        return s, ds, dds
    raise ValueError(f"unknown profile {kind!r}; expected one of {', '.join(PROFILES)}")


def peak_speed_factor(kind: str, *, blend: float = DEFAULT_BLEND) -> float:
    """max s' of the normalized profile: peak velocity = factor |qf - q0| / T."""
    if kind == "cubic":
        return 1.5
    if kind == "quintic":
        return 1.875
    if kind == "trapezoidal":
        return 1.0 / (1.0 - _check_blend(blend))
    raise ValueError(f"unknown profile {kind!r}; expected one of {', '.join(PROFILES)}")


def trajectory(
    kind: str,
    q0: npt.ArrayLike,
    qf: npt.ArrayLike,
    duration: float,
    t: npt.ArrayLike,
    *,
    blend: float = DEFAULT_BLEND,
):
    """Position, velocity, acceleration of a profile from ``q0`` to ``qf`` in ``duration``.

    Parameters
    ----------
    kind : {"cubic", "quintic", "trapezoidal"}
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
    t = _check_times(t, T)
    q0, qf = _check_ends(q0, qf)
    s, ds, dds = profile(kind, t / T, blend=blend)
    shape = (-1, *([1] * q0.ndim))
    s, ds, dds = (x.reshape(shape) for x in (s, ds, dds))
    dq = qf - q0
    return q0 + dq * s, dq * ds / T, dq * dds / T**2


def cubic_coefficients(q0: npt.ArrayLike, qf: npt.ArrayLike, duration: float):
    """Cubic coefficients (a0, a1, a2, a3), shape (4, ...), seed 004 eqs. 5.5-5.6.

    a0 = q0, a1 = 0, a2 = 3 (qf - q0) / T^2, a3 = -2 (qf - q0) / T^3 (zero end velocity).
    """
    T = _check_duration(duration)
    q0, qf = _check_ends(q0, qf)
    dq = qf - q0
    return np.stack([q0, np.zeros_like(q0), 3 * dq / T**2, -2 * dq / T**3])


def cubic_trajectory(q0: npt.ArrayLike, qf: npt.ArrayLike, duration: float, t: npt.ArrayLike):
    """Position, velocity, acceleration of the cubic (seed 004 eqs. 5.3-5.4, 5.7-5.9):
    ``trajectory("cubic", ...)``, whose normalized profile 3 s^2 - 2 s^3 is the thesis's
    coefficients (:func:`cubic_coefficients`) divided through by (qf - q0). Parameters
    and results as :func:`trajectory`'s.
    """
    return trajectory("cubic", q0, qf, duration, t)


def acceleration_jumps(
    kind: str, q0: npt.ArrayLike, qf: npt.ArrayLike, duration: float, *, blend=DEFAULT_BLEND
) -> npt.NDArray[np.float64]:
    """Largest step of the acceleration [rad/s^2] per joint, shape (..., n), counting the
    steps from rest into the move and back (the arm stands still before and after).

    Cubic: 6 |qf - q0| / T^2 at both ends (eq. 5.4: 2 a2 at t = 0, 2 a2 + 6 a3 T at T);
    quintic: 0; trapezoidal: 1 / (b (1 - b)) |qf - q0| / T^2 at the four blend ends.
    """
    T = _check_duration(duration)
    q0, qf = _check_ends(q0, qf)
    factor = {"cubic": 6.0, "quintic": 0.0}.get(kind)
    if factor is None:
        if kind != "trapezoidal":
            raise ValueError(f"unknown profile {kind!r}; expected one of {', '.join(PROFILES)}")
        b = _check_blend(blend)
        factor = 1.0 / (b * (1.0 - b))
    return factor * np.abs(qf - q0) / T**2


# --------------------------------------------------------------------------- pulses
def pulse_rates(qd: npt.ArrayLike, resolution_deg: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Encoder pulse rate [pulses/s] = |joint speed| [deg/s] / resolution [deg/pulse].

    ``qd`` [rad/s] broadcasts against ``resolution_deg`` (one per joint, last axis).
    """
    res = np.asarray(resolution_deg, dtype=float)
    if not (np.isfinite(res).all() and (res > 0).all()):
        raise ValueError(f"resolution {resolution_deg!r} deg/pulse must be finite and > 0")
    return np.degrees(np.abs(np.asarray(qd, dtype=float))) / res


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


# --------------------------------------------------------------------------- the PLC's move
def sequential_move(
    q0: npt.ArrayLike,
    qf: npt.ArrayLike,
    speed: npt.ArrayLike,
    t: npt.ArrayLike,
    order: tuple[int, ...] | None = None,
):
    """One joint after another, each at constant speed, on/off (section 2.3.4's sequence).

    Parameters
    ----------
    q0, qf : array_like, shape (n,)
        Start and end joint angles [rad].
    speed : array_like, shape (n,)
        Joint speeds [rad/s], > 0 (a motor running at its speed, nothing else).
    t : array_like, shape (m,)
        Sample times [s], >= 0 (past the end the arm stands at ``qf``).
    order : tuple of int, optional
        The joints in the order they move (default 0, 1, ..., n - 1: M1 first).

    Returns
    -------
    q : ndarray, shape (m, n)
        Joint angles [rad].
    switch : ndarray, shape (n + 1,)
        The times [s] at which each motor starts, and the end of the move.
    """
    q0, qf = _check_ends(q0, qf)
    if q0.ndim != 1:
        raise ValueError(f"sequential_move takes one start and one end (n,), got {q0.shape}")
    v = np.broadcast_to(np.asarray(speed, dtype=float), q0.shape)
    if not (np.isfinite(v).all() and (v > 0).all()):
        raise ValueError(f"joint speeds {speed!r} rad/s must be finite and > 0")
    order = tuple(range(q0.size)) if order is None else tuple(order)
    if sorted(order) != list(range(q0.size)):
        raise ValueError(f"order {order} must name every joint 0 .. {q0.size - 1} once")
    t = np.asarray(t, dtype=float)
    if t.ndim != 1 or not np.isfinite(t).all() or (t.size and t.min() < 0):
        raise ValueError("sample times must be a 1-D array of finite times >= 0 s")
    durations = np.abs(qf - q0)[list(order)] / v[list(order)]
    switch = np.concatenate([[0.0], np.cumsum(durations)])
    q = np.empty((t.size, q0.size))
    for k, j in enumerate(order):  # a loop over the five joints, never over time
        frac = np.clip((t - switch[k]) / durations[k], 0.0, 1.0) if durations[k] > 0 else 1.0
        q[:, j] = q0[j] + (qf[j] - q0[j]) * frac
    return q, switch

"""Joint angle <-> stepper pulse conversion (paper eqs. 20-22), written once.

``c = theta_deg / 360 * pulses_per_rev`` (eqs. 20-22 print ``c = theta / 360 x 4000``); for
a prismatic joint driven through a screw of lead ``lead_mm`` per motor revolution, ``c =
q_mm / lead_mm * pulses_per_rev``; rounded to a whole pulse as the S7-200 ``ROUND``
instruction does: to nearest, halves away from zero (S7-200 System Manual p.115 confirms
"fraction >= 0.5 rounds up"; negative halves are not confirmed there). The S7-300 ``RND``
rounds halves to even instead: both rules are available. :func:`pulse_count` and
:func:`pulse_angle` are the formulas, in a math namespace; the numpy functions below, the
compiled quantization kernel, the float32 model and the PLC program all use them.
"""

from __future__ import annotations

from typing import Literal

import numpy as np
import numpy.typing as npt

from analysis.kinematics.ops import NumpyOps, numpy_ops
from analysis.validate import MAX_PULSES_PER_REV

__all__ = [
    "DINT_MAX",
    "angles_to_pulses",
    "pulse_angle",
    "pulse_count",
    "pulse_value",
    "pulse_values",
    "pulses_to_angles",
    "round_half_away",
]

Rounding = Literal["half-away", "half-even"]
DINT_MAX = 2**31 - 1
"""Largest pulse count a PLC's DINT holds (the S7 double integer)."""
_HALF_EVEN = NumpyOps("half-even")


def pulse_value(m, theta, pulses_per_rev, lead_mm=None):
    """Unrounded pulse count for joint angle ``theta`` [rad]: ``theta_deg / 360 * ppr``
    (eqs. 20-22 print ``c = theta / 360 x 4000``); for a prismatic joint (``lead_mm`` given)
    ``q_mm / lead_mm * ppr``."""
    if lead_mm is not None:
        return theta / lead_mm * pulses_per_rev
    return m.degrees(theta) / 360.0 * pulses_per_rev


def pulse_count(m, theta, pulses_per_rev, lead_mm=None):
    """Whole pulses for joint value ``theta`` [rad, or mm with ``lead_mm``], eqs. 20-22,
    with the namespace's rounding (``m.round``: ROUND halves away from zero, or RND halves
    to even)."""
    return m.round(m.let("count", pulse_value(m, theta, pulses_per_rev, lead_mm)))


def pulse_angle(m, c, pulses_per_rev, lead_mm=None):
    """Joint value [rad, or mm with ``lead_mm``] commanded by ``c`` whole pulses (inverse of
    eqs. 20-22)."""
    if lead_mm is not None:
        return c * lead_mm / pulses_per_rev
    return m.radians(c * 360.0 / pulses_per_rev)


def _per_joint(fn, values, ppr, lead_mm):
    """``fn(m, values, ppr, lead)`` with revolute joints (lead NaN or None) and prismatic
    ones (lead in mm) side by side along the last axis."""
    if lead_mm is None:
        return fn(numpy_ops, values, ppr)
    lead = np.asarray(lead_mm, dtype=float)
    prismatic = np.isfinite(lead)
    if not prismatic.any():
        return fn(numpy_ops, values, ppr)
    if not (lead[prismatic] > 0).all():
        raise ValueError(f"lead_mm = {lead_mm!r}: a prismatic joint's lead must be > 0 mm")
    return np.where(
        prismatic, fn(numpy_ops, values, ppr, np.where(prismatic, lead, 1.0)),
        fn(numpy_ops, values, ppr),
    )  # fmt: skip


def pulse_values(
    q: npt.ArrayLike, pulses_per_rev: npt.ArrayLike, *, lead_mm: npt.ArrayLike | None = None
) -> npt.NDArray[np.float64]:
    """Unrounded pulse counts (..., n) for joint values (..., n) [rad | mm]: eqs. 20-22 per
    revolute joint, ``q / lead * ppr`` per prismatic one (``lead_mm`` finite there)."""
    q = np.asarray(q, dtype=float)
    return _per_joint(pulse_value, q, np.asarray(pulses_per_rev, dtype=float), lead_mm)


def round_half_away(x: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Round to nearest, ties away from zero (S7-200 ROUND on positive halves)."""
    return numpy_ops.round_half_away(np.asarray(x, dtype=float))


def angles_to_pulses(
    theta: npt.ArrayLike,
    pulses_per_rev: npt.ArrayLike = 4000,
    *,
    rounding: Rounding = "half-away",
    lead_mm: npt.ArrayLike | None = None,
) -> npt.NDArray[np.int64]:
    """Whole pulse counts for joint angles (eqs. 20-22).

    Parameters
    ----------
    theta : array_like, shape (..., n) or broadcastable with ``pulses_per_rev``
        Joint angles [rad].
    pulses_per_rev : int or array_like
        Pulses per joint revolution (Table 3 / section 3: 4000, i.e. 0.09 deg per pulse),
        whole numbers in 1 .. 10^7.
    rounding : {"half-away", "half-even"}
        S7-200 ROUND or S7-300 RND tie rule.
    lead_mm : array_like, optional
        Per joint: the lead [mm per revolution] of a prismatic joint (its value in ``theta``
        is then in mm), NaN for a revolute one (:meth:`analysis.kinematics.arm.Arm.pulses`
        passes the description's).

    Raises ``ValueError`` for NaN/inf angles and for counts beyond a DINT (+-2147483647).

    Examples
    --------
    Table 4 row 1, front-up (45, 10.21, -155.13) deg -> (500, 113, -1724) pulses:

    >>> angles_to_pulses(np.radians([45.0, 10.2087, -155.1291])).tolist()
    [500, 113, -1724]
    """
    theta = np.asarray(theta, dtype=float)
    if not np.isfinite(theta).all():
        raise ValueError("joint angles contain NaN or inf; only solved angles convert to pulses")
    ppr = _check_ppr(pulses_per_rev)
    if rounding == "half-away":
        m = numpy_ops
    elif rounding == "half-even":
        m = _HALF_EVEN
    else:
        raise ValueError(f"unknown rounding {rounding!r}; expected 'half-away' or 'half-even'")
    if lead_mm is None:
        c = pulse_count(m, theta, ppr)
    else:
        value = _per_joint(pulse_value, theta, ppr, lead_mm)
        c = m.round(value)
    big = np.abs(c) > DINT_MAX
    if big.any():
        i = tuple(int(k) for k in np.argwhere(big)[0])
        raise ValueError(
            f"pulse count {c[i]:.6g} (theta = {np.degrees(theta[i] if theta.ndim else theta):.6g}"
            f" deg) is beyond the DINT range +-{DINT_MAX} that a PLC holds"
        )
    return c.astype(np.int64)


def pulses_to_angles(
    c: npt.ArrayLike, pulses_per_rev: npt.ArrayLike = 4000, *, lead_mm=None
) -> npt.NDArray[np.float64]:
    """Joint angles [rad] commanded by whole pulse counts (inverse of eqs. 20-22); with
    ``lead_mm`` (as for :func:`angles_to_pulses`) prismatic joints' values [mm]."""
    c = np.asarray(c, dtype=float)
    if not np.isfinite(c).all():
        raise ValueError("pulse counts contain NaN or inf")
    return _per_joint(pulse_angle, c, _check_ppr(pulses_per_rev), lead_mm)


def _check_ppr(pulses_per_rev: npt.ArrayLike) -> npt.NDArray[np.float64]:
    try:
        ppr = np.asarray(pulses_per_rev, dtype=float)
    except (TypeError, ValueError):
        ppr = np.asarray(np.nan)
    if not (
        np.isfinite(ppr) & (ppr >= 1) & (ppr <= MAX_PULSES_PER_REV) & (ppr == np.round(ppr))
    ).all():
        raise ValueError(
            f"pulses_per_rev = {pulses_per_rev!r} must be finite and positive: whole numbers "
            f"in 1 .. {MAX_PULSES_PER_REV:,}"
        )
    return ppr

"""Joint angle <-> stepper pulse conversion (paper eqs. 20-22).

``c = theta_deg / 360 * pulses_per_rev``, rounded to a whole pulse as the S7-200 ``ROUND``
instruction does: to nearest, halves away from zero (S7-200 System Manual p.115 confirms
"fraction >= 0.5 rounds up"; negative halves are not confirmed there, and the S7-300
``RND`` rounds halves to even instead: both rules are available here).
"""

from __future__ import annotations

from typing import Literal

import numpy as np
import numpy.typing as npt

__all__ = ["angles_to_pulses", "pulses_to_angles", "round_half_away"]

Rounding = Literal["half-away", "half-even"]


def round_half_away(x: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Round to nearest, ties away from zero (S7-200 ROUND on positive halves)."""
    x = np.asarray(x, dtype=float)
    # trunc + exact fractional part: floor(|x| + 0.5) would round 0.49999999999999994 up,
    # because |x| + 0.5 rounds to 1.0 in float64 before the floor.
    whole = np.trunc(x)
    return whole + np.where(np.abs(x - whole) >= 0.5, np.sign(x), 0.0)


def angles_to_pulses(
    theta: npt.ArrayLike,
    pulses_per_rev: npt.ArrayLike = 4000,
    *,
    rounding: Rounding = "half-away",
) -> npt.NDArray[np.int64]:
    """Whole pulse counts for joint angles (eqs. 20-22).

    Parameters
    ----------
    theta : array_like, shape (..., 3) or broadcastable with ``pulses_per_rev``
        Joint angles [rad].
    pulses_per_rev : int or array_like
        Pulses per joint revolution (Table 3 / section 3: 4000, i.e. 0.09 deg per pulse).
    rounding : {"half-away", "half-even"}
        S7-200 ROUND or S7-300 RND tie rule.

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
    exact = np.degrees(theta) / 360.0 * ppr
    if rounding == "half-away":
        return round_half_away(exact).astype(np.int64)
    if rounding == "half-even":
        return np.rint(exact).astype(np.int64)
    raise ValueError(f"unknown rounding {rounding!r}; expected 'half-away' or 'half-even'")


def pulses_to_angles(
    c: npt.ArrayLike, pulses_per_rev: npt.ArrayLike = 4000
) -> npt.NDArray[np.float64]:
    """Joint angles [rad] commanded by whole pulse counts (inverse of eqs. 20-22)."""
    c = np.asarray(c, dtype=float)
    if not np.isfinite(c).all():
        raise ValueError("pulse counts contain NaN or inf")
    return np.radians(c * 360.0 / _check_ppr(pulses_per_rev))


def _check_ppr(pulses_per_rev: npt.ArrayLike) -> npt.NDArray[np.float64]:
    ppr = np.asarray(pulses_per_rev, dtype=float)
    if not (np.isfinite(ppr) & (ppr > 0)).all():
        raise ValueError(f"pulses_per_rev = {pulses_per_rev!r} must be finite and positive")
    return ppr

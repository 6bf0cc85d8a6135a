"""Plots for the PLC execution results (notebook 07)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import numpy.typing as npt
from matplotlib.axes import Axes

from analysis.kinematics.pulses import round_half_away

__all__ = ["plot_rounding_margin"]


def plot_rounding_margin(
    exact: npt.ArrayLike,
    plc_real: npt.ArrayLike,
    ax: Axes | None = None,
    rounding: str = "half-away",
) -> Axes:
    """Distance of the exact pulse value to the nearest half pulse vs the float32 error.

    Parameters
    ----------
    exact : array_like, shape (N,)
        Unrounded pulse values from float64 Python (eqs. 20-22).
    plc_real : array_like, shape (N,)
        The PLC's float32 REAL fed to ROUND, same targets/joints.
    rounding : {"half-away", "half-even"}
        Tie rule of the PLC's rounding instruction (S7-200 ROUND / S7-300 RND).

    A PLC count differs from Python only when the float32 value reaches or crosses the
    half pulse: those points (marked) lie on or above the diagonal |error| = distance;
    on the diagonal the float32 value is exactly k + 1/2 and the tie rule decides.
    """
    exact = np.asarray(exact, dtype=float)
    real = np.asarray(plc_real, dtype=float)
    half = np.floor(exact) + 0.5
    dist = np.abs(exact - half)
    err = np.abs(real - exact)
    if rounding not in ("half-away", "half-even"):
        raise ValueError(f"rounding {rounding!r}: expected 'half-away' or 'half-even'")
    rnd = round_half_away if rounding == "half-away" else np.rint
    flip = rnd(exact) != rnd(real)
    ax = ax or plt.gca()
    tiny = 1e-12
    ax.loglog(
        np.maximum(dist[~flip], tiny),
        np.maximum(err[~flip], tiny),
        ".",
        ms=3,
        alpha=0.5,
        label="same pulse count",
    )
    ax.loglog(
        np.maximum(dist[flip], tiny),
        np.maximum(err[flip], tiny),
        "x",
        ms=5,
        color="C3",
        label=f"different pulse count ({int(flip.sum())})",
    )
    lim = [1e-8, 1.0]
    ax.plot(lim, lim, "k--", lw=0.8, label="|error| = distance")
    ax.set_xlim(lim)
    ax.set_xlabel("|exact - (k + 1/2)| [pulses]")
    ax.set_ylabel("|float32 PLC - exact| before ROUND [pulses]")
    ax.legend(loc="lower right")
    return ax

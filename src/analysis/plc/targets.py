"""The targets the papers print, and the columns of a targets table.

:data:`PAPER_TARGETS` holds, per closed form, the targets its paper prints (seed 000's
Table 4, seed 001's initial pose, seed 004's Table 5-3): the PLC sweeps
(:func:`analysis.plc.sweep.sweep_targets`) include them, and :func:`analysis.plc.verify.
compare` reads a targets table by :func:`input_columns`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import Arm
from analysis.papers.gr1_thesis import poses
from analysis.paths import data_dir

__all__ = ["PAPER_TARGETS", "input_columns", "table4_targets"]


def input_columns(arm: Arm) -> list[str]:
    """Target columns of a targets table for ``arm``: ``x_mm, y_mm, z_mm`` for a point
    (inputs px, py, pz), else the closed form's input names (the GR-1's pose)."""
    inputs = list(arm.inputs)
    return ["x_mm", "y_mm", "z_mm"] if inputs == ["px", "py", "pz"] else inputs


def table4_targets() -> npt.NDArray[np.float64]:
    """The ten Table 4 targets (x, y, z) [mm], shape (10, 3)."""
    t4 = pd.read_csv(data_dir() / "table4.csv")
    return t4[["x_mm", "y_mm", "z_mm"]].to_numpy(dtype=float)


def _table4(arm: Arm) -> npt.NDArray[np.float64]:
    return table4_targets()


def _table5_3(arm: Arm) -> npt.NDArray[np.float64]:
    return np.array(poses())  # the thesis's Table 5-3, as data


def _initial_pose(arm: Arm) -> npt.NDArray[np.float64]:
    """Seed 001 sec. 3: the initial pose, theta = (0, -90, 90, 90) deg (on the elbow stop)."""
    return arm.target(np.radians([[0.0, -90.0, 90.0, 90.0]]))


PAPER_TARGETS: dict[str, Callable[[Arm], npt.NDArray[np.float64]]] = {
    "grabber": _table4,
    "palletizer": _initial_pose,
    "gr1": _table5_3,
}
"""Per closed form, the targets its paper prints (seed 000's Table 4, seed 001's initial
pose, seed 004's Table 5-3); an arm with that closed form (any lengths) is swept on them
too."""

"""The arm API in one import: :class:`Arm` (:mod:`analysis.kinematics.model`), the loader
(:func:`load_arm`, :func:`paper_arm`: :mod:`analysis.kinematics.loader`), the numbers
(:class:`Params`), and the solver's record, errors and tolerances
(:mod:`analysis.kinematics.solution`).

Nothing in the package imports this module (it sits above the modules it gathers); code
inside :mod:`analysis.kinematics` imports those modules themselves.

>>> import numpy as np
>>> np.degrees(paper_arm().ik([100, 100, 600])).round(2).tolist()
[45.0, 10.21, -155.13]
"""

from __future__ import annotations

from analysis.kinematics.consistency import POSITION_INPUTS, RPY_INPUTS
from analysis.kinematics.loader import arm_of, derived_arm, load_arm, paper_arm
from analysis.kinematics.model import BRANCHES, Arm, NoClosedForm
from analysis.kinematics.params import Params
from analysis.kinematics.solution import (
    DEFAULT_TOL_MM,
    MAX_JOINT_DEG,
    MAX_JOINT_MM,
    MAX_TOL_MM,
    BaseAxisError,
    IKSolutions,
    OrientationError,
    UnreachableError,
    as_points,
    check_joints,
    check_theta1_on_axis,
    check_tol,
    solve_body,
)
from analysis.kinematics.status import Status

__all__ = [
    "BRANCHES",
    "DEFAULT_TOL_MM",
    "MAX_JOINT_DEG",
    "MAX_JOINT_MM",
    "MAX_TOL_MM",
    "POSITION_INPUTS",
    "RPY_INPUTS",
    "Arm",
    "BaseAxisError",
    "IKSolutions",
    "NoClosedForm",
    "OrientationError",
    "Params",
    "Status",
    "UnreachableError",
    "arm_of",
    "as_points",
    "check_joints",
    "check_theta1_on_axis",
    "check_tol",
    "derived_arm",
    "load_arm",
    "paper_arm",
    "solve_body",
]

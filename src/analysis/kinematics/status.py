"""Why a target has (or has no) solution: one code for Python, the compiled kernel and the PLC."""

from __future__ import annotations

import enum

__all__ = ["STATUS_TEXT", "Status"]


class Status(enum.IntEnum):
    """Per-target outcome of inverse kinematics (batch results, CSV output, PLC status word).

    The generated PLC programs write the same codes (``status`` in MAP.json).
    """

    OK = 0
    OUT_OF_REACH = 1  # farther than the reach allows
    INSIDE_REACH = 2  # nearer than the inner reach radius
    BASE_AXIS = 3  # on the waist axis: the waist angle is undefined (reachable otherwise)
    JOINT_LIMITS = 4  # reachable, but no requested branch is within the joint limits
    DEGENERATE = 5  # a closed form's own singular case (named by the arm)
    INVALID = 6  # NaN or inf in the input (the PLC's check; Python raises instead)
    ORIENTATION = 7  # an orientation the arm cannot take (a 5-DOF arm's missing freedom)

    @property
    def text(self) -> str:
        """The word used in CSV and JSON output."""
        return STATUS_TEXT[self]


STATUS_TEXT = {
    Status.OK: "ok",
    Status.OUT_OF_REACH: "out-of-reach",
    Status.INSIDE_REACH: "inside-reach",
    Status.BASE_AXIS: "base-axis",
    Status.JOINT_LIMITS: "joint-limits",
    Status.DEGENERATE: "degenerate",
    Status.INVALID: "invalid",
    Status.ORIENTATION: "orientation",
}

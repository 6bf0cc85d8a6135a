"""One closed form per arm, each written once against a math namespace.

A closed-form module provides ``BRANCHES`` (names, the default first), ``INPUTS`` (target
coordinate names), ``check(P)`` (reject unusable parameters), ``geometry(P)`` (named points
and radii for messages and figures), ``ik(m, p, P, *, tol, axis_tol=None, margin_rad=0.0,
theta1_on_axis=None, ...)`` returning the branches, the refusal conditions in priority order
and the signed distance outside the reach, and
``refusal(status, p, P, *, tol, distance)`` giving the one-line reason and the limit
crossed [mm]. Its arm is described by
``data/arms/<name>.toml`` (:mod:`analysis.kinematics.description`).

Tolerances: a target up to ``tol`` [mm] outside a reach shell is put on it; a target within
``axis_tol`` [mm] (default ``tol``) of a singular set (the base axis, a wrist on the shoulder)
is refused there or, with ``theta1_on_axis``, taken as on it; ``margin_rad`` [rad] narrows
any angular tolerance of the arm's own (the GR-1's orientation). The generated PLC programs
pass a negative ``tol``, a larger ``axis_tol`` and a positive ``margin_rad``
(:mod:`analysis.plc.model`): they refuse a band around every boundary, so float32
arithmetic never accepts what Python refuses.

To add an arm: write its description, and a module here with those five names.
"""

from __future__ import annotations

import importlib
from types import ModuleType

__all__ = ["closed_form"]

_REQUIRED = ("BRANCHES", "INPUTS", "check", "geometry", "ik", "refusal")


def closed_form(name: str) -> ModuleType:
    """The closed-form module ``analysis.kinematics.arms.<name>``, checked for its names, or
    the closed form derived from a description's D-H table (``derived:...``: what a
    description without ``closed_form`` gets, :mod:`analysis.kinematics.derive`)."""
    if name.startswith("derived:"):
        from analysis.kinematics.derive import lookup

        return lookup(name)
    if not name.isidentifier():
        raise ValueError(f"closed form {name!r} is not a module name")
    try:
        mod = importlib.import_module(f"analysis.kinematics.arms.{name}")
    except ModuleNotFoundError:
        raise ValueError(f"no closed form {name!r} in analysis.kinematics.arms") from None
    missing = [k for k in _REQUIRED if not hasattr(mod, k)]
    if missing:
        raise ValueError(f"closed form {name!r} lacks {', '.join(missing)}")
    return mod

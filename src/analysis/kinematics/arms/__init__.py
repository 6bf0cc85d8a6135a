"""One closed form per arm, each written once against a math namespace.

A closed-form module provides ``BRANCHES`` (names, the default first), ``INPUTS`` (target
coordinate names), ``check(P)`` (reject unusable parameters), ``geometry(P)`` (named points
and radii for messages and figures), ``ik(m, p, P, *, tol, ...)`` returning the branches,
the refusal conditions in priority order and the signed distance outside the reach, and
``refusal(status, p, P, *, tol, distance)`` giving the one-line reason and the limit
crossed [mm]. Its arm is described by
``data/arms/<name>.toml`` (:mod:`analysis.kinematics.description`).

To add an arm: write its description, and a module here with those five names.
"""

from __future__ import annotations

import importlib
from types import ModuleType

__all__ = ["closed_form"]

_REQUIRED = ("BRANCHES", "INPUTS", "check", "geometry", "ik", "refusal")


def closed_form(name: str) -> ModuleType:
    """The closed-form module ``analysis.kinematics.arms.<name>``, checked for its names."""
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

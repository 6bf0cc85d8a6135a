"""One derived closed-form class per family (:mod:`.families`): :func:`build` picks it."""

from __future__ import annotations

from analysis.kinematics.derive.closed_form import DerivedClosedForm
from analysis.kinematics.derive.families import WAIST_FAMILIES, Structure
from analysis.kinematics.derive.gantry import GantryArm
from analysis.kinematics.derive.planar import PlanarArm

__all__ = ["build"]


def build(name: str, description, structure: Structure):
    """The closed form of ``structure``'s family for ``description`` (NotDerivable where
    the chain's numbers break a rule the axes alone do not show: axes that must meet)."""
    if structure.family in WAIST_FAMILIES:
        return DerivedClosedForm(name, description, structure)
    if structure.family.startswith("gantry"):
        return GantryArm(name, description, structure)
    return PlanarArm(name, description, structure)

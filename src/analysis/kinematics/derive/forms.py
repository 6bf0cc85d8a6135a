"""One derived closed-form class per family (:mod:`.families`): :func:`build` picks it."""

from __future__ import annotations

from analysis.kinematics.derive.closed_form import DerivedClosedForm
from analysis.kinematics.derive.families import WAIST_FAMILIES, NotDerivable, Structure

__all__ = ["build"]


def build(name: str, description, structure: Structure):
    """The closed form of ``structure``'s family for ``description`` (NotDerivable where
    the chain's numbers break a rule the axes alone do not show: axes that must meet)."""
    if structure.family in WAIST_FAMILIES:
        return DerivedClosedForm(name, description, structure)
    raise NotDerivable(f"the {structure.family} family has no closed form yet")

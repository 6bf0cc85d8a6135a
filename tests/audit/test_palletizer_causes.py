"""Seed 001's register (analysis.audit.palletizer_causes) beyond the generic register tests:
the verify predicates decide by derivation or run, not by matching the correction's string.
Each accepts an equivalent form of the correction and rejects a plausible wrong alternative
(the other sign, the other reading, a neighbouring number), and never raises."""

from __future__ import annotations

import pytest

from analysis.audit import register as reg
from analysis.audit.schema import read_rows


def _reg():
    """The register, built where a test first needs it (cached per process), not at collection."""
    return reg.register("palletizer")


# the ids from the register file (test_register checks that it is what the audit generates)
MANIFESTATIONS = [r["id"] for r in read_rows(reg.register_path("palletizer")) if r["cause"]]


def verify(mid: str):
    return _reg().manifestation(mid).verify


@pytest.mark.parametrize(
    ("mid", "equivalent", "wrong"),
    [
        (
            "pal-eq11-s4l3/row3",
            # the corrected row 3, regrouped: -(s23)(c4 h + s4 L3 + L2) - c23 (s4 h - c4 L3) - s2 L1
            "t34 = -sin(theta2 + theta3)*(cos(theta4)*h + sin(theta4)*L3 + L2)"
            " - cos(theta2 + theta3)*(sin(theta4)*h - cos(theta4)*L3) - sin(theta2)*L1",
            "t34 = -sin(theta2 + theta3)*(cos(theta4)*h + sin(theta4)*L3 + L2)"
            " - cos(theta2 + theta3)*(sin(theta4)*h - cos(theta4)*L3) + sin(theta2)*L1",
        ),
        ("pal-eq6-quadrant/eq6-signed", "gamma = atan2(Y0, X0) + 2*pi", "gamma = atan2(X0, Y0)"),
        (
            "pal-eq3-alpha2/alpha2",
            "alpha2 = atan2(Z0 + h, sqrt(X0**2 + Y0**2) - L3)",
            "alpha2 = asin(-(Z0 + h)/L4p)",  # the depth reading of H
        ),
        (
            "pal-eq3-beta1/beta1",
            "beta1 = 2*asin(L4p/(2*L1p))",  # the isosceles form (L1 = L2 assumed)
            "beta1 = pi - acos((L1p**2 + L2p**2 - L4p**2)/(2*L1p*L2p))",
        ),
        (
            "pal-eq4-alpha/alpha",
            "alpha = alpha1 + alpha2 - pi/2 + 2*pi",
            "alpha = pi/2 - (alpha1 + alpha2)",  # right only with eq. 12's theta2 changed too
        ),
        (
            "pal-eq12-theta4/theta4",
            "theta4 = pi/2 - theta2 - theta3",
            "theta4 = pi/2 + theta2 - theta3",
        ),
        (
            "pal-claim-unique/reasoning",
            "theta3 in [0, 180] deg, waist facing the target (eq. 6) => one pose per target",
            "theta3 in [-180, 180] deg, waist facing the target (eq. 6) => one pose per target",
        ),
        (
            "pal-claim-unique/initial-pose",
            "included angle of forearm and upper arm <= 95 deg",
            "included angle of forearm and upper arm < 89.9 deg",
        ),
        (
            "pal-claim-triangle/sec3",
            "the triangle (L1', L2', L4') exists iff (L4 <= L1 + L2) & (L4 >= Abs(L1 - L2))",
            "the triangle (L1', L2', L4') exists iff (L4 <= L1)",
        ),
        ("pal-xref-section/sec5", "見第3節", "第4節中的逆向解算方法"),
        ("pal-xref-reference/sec4-1", "第6篇文獻[6]", "參照第5篇文獻簡述的方法[5]"),
        (
            "pal-extraction-lost/table1",
            "h = 70 mm, L3 = 50 mm, L2 = 200 mm, L1 = 200 mm: assumed",
            "L1 = 200 mm, L2 = 150 mm, L3 = 50 mm, h = 70 mm: assumed",
        ),
    ],
)
def test_verify_accepts_equivalents_and_rejects_alternatives(mid, equivalent, wrong):
    v = verify(mid)
    assert v(equivalent), f"{mid}: an equivalent correction is rejected"
    assert not v(wrong), f"{mid}: a wrong alternative passes"


@pytest.mark.parametrize("mid", MANIFESTATIONS)
def test_verify_never_raises_on_garbage(mid):
    for text in ("", "=", "gamma = (", "第節", "L1 = x mm", "theta3 in [a, b] deg", "∞"):
        assert verify(mid)(text) is False


def test_register_keeps_the_brief_items():
    ids = {c.id for c in _reg().causes}
    assert {
        "pal-eq11-s4l3",
        "pal-eq11-label",
        "pal-eq3-h",
        "pal-claim-isosceles",
        "pal-eq6-quadrant",
        "pal-eq12-theta4",
        "pal-eq4-alpha",
        "pal-claim-unique",
    } <= ids
    assert len(_reg().cause("pal-eq11-s4l3").manifestations) == 3
    assert _reg().cause("pal-eq11-label").manifestations[0].printed == "t34"
    counts = _reg().counts()
    assert counts["holds"] >= 5 and counts["extraction"] == 1
    # every evidence that rests on lengths says they are assumed
    for c in _reg().causes:
        for m in c.manifestations:
            if "mm" in m.evidence and "L1" in m.evidence:
                assert "assumed" in m.evidence, m.id

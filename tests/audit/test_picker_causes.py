"""Seed 002's register (analysis.audit.picker_causes) beyond the generic register tests:
each verify predicate accepts an equivalent correction, rejects a plausible wrong
alternative and never raises."""

from __future__ import annotations

import pytest

from analysis.audit import register as reg
from analysis.audit.schema import read_rows


def _reg():
    """The register, built where a test first needs it (cached per process), not at collection."""
    return reg.register("picker")


# the ids from the register file (test_register checks that it is what the audit generates)
MANIFESTATIONS = [r["id"] for r in read_rows(reg.register_path("picker")) if r["cause"]]
LAW = "theta1 = -5*t, theta6 = 10*t, theta7 = -10*t, theta8 = -10*t"


def verify(mid: str):
    return _reg().manifestation(mid).verify


@pytest.mark.parametrize(
    ("mid", "equivalent", "wrong"),
    [
        (
            "pick-units/omega-rad-s",
            LAW + " [deg] (joint values)",  # the other degree reading is plausible too
            LAW.replace("-5*t", "-0.05*t").replace("theta", "omega") + " [rad/s]",
        ),
        ("pick-units/values-rad", LAW + " [deg]", LAW + " [deg/s]"),  # a value with a rate unit
        ("pick-xref-eq18/sec3-4", "正解方程(22)", "正解方程(21)"),
        ("pick-xref-eq9/sec3-3", "由式(7)可求得", "由式(8)可求得"),  # 8: prismatic twist
        (
            "pick-reasoning-opening/sec4",
            "error 10.4 mm < (200 mm - d)/2 per side for d < 179.2 mm => the trunk can be clamped",
            # even a 5 mm bound cannot prove eq. 22: a flipped roll about the jaw axis moves
            # the marker (on that axis, assumed) by nothing
            "error 10.4 mm < 5 mm => eq. 22 correct",
        ),
        (
            "pick-claim-solvable/sec3-2",
            "12 moving links, 17 one-dof joints",  # 36 - 34 = 2 as well
            "9 moving links, 12 one-dof joints",  # 27 - 24 = 3
        ),
        ("pick-claim-r3/sec1-1", "identity element: the zero vector", "every 3-vector"),
        ("pick-chain-names/sec3-3", "副運動鏈", "主動鏈"),
    ],
)
def test_verify_accepts_equivalents_and_rejects_alternatives(mid, equivalent, wrong):
    v = verify(mid)
    assert v(equivalent), f"{mid}: an equivalent correction is rejected"
    assert not v(wrong), f"{mid}: a wrong alternative passes"


def test_replayed_positions_are_checked_to_the_printed_digit():
    m = _reg().manifestation("pick-extraction-lost/table2")
    assert m.verify(m.corrected)
    first = m.corrected.split("(")[1].split(",")[0]
    moved = m.corrected.replace(first, f"{float(first) + 0.2:.1f}", 1)
    assert not m.verify(moved)


@pytest.mark.parametrize("mid", MANIFESTATIONS)
def test_verify_never_raises_on_garbage(mid):
    for text in ("", "=>", "error x mm < y => z", "式()", "omega1 = *t [rad/s]", "∞"):
        assert verify(mid)(text) is False


def test_poe_is_checked_on_every_arm():
    c = _reg().cause("pick-poe-holds")
    assert c.status == "holds" and c.demonstrate()
    for arm in ("grabber", "palletizer", "picker"):
        assert arm in c.evidence

"""analysis.kinematics.pulses: joint angles <-> stepper pulses (paper eqs. 20-22, c = theta/360 *
4000).

The rounding reference is Python's ``decimal`` module applied to the exact binary value
of each float (ROUND_HALF_UP is "ties away from zero" there; ROUND_HALF_EVEN is banker's
rounding): an implementation independent of NumPy's.
"""

from __future__ import annotations

import decimal
import doctest

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles, round_half_away
from helpers import assert_allclose

PPR = 4000  # Table 3 / section 3 (细分数为 4 000)


def decimal_round(x: float, mode: str) -> int:
    return int(decimal.Decimal(x).quantize(decimal.Decimal(1), rounding=mode))


def test_table4_row1_front_up(arm):
    """Table 4 row 1 (100, 100, 600) mm, corrected front-up angles (45.00, 10.21,
    -155.13) deg -> eqs. 20-22 -> (500, 113, -1724) pulses."""
    theta = arm.ik([100.0, 100.0, 600.0])
    c = angles_to_pulses(theta, PPR)
    assert c.dtype == np.int64
    assert c.tolist() == [500, 113, -1724]
    # the same numbers by hand from eq. 20, c = theta_deg / 360 * 4000, to nearest
    exact = np.degrees(theta) / 360.0 * PPR
    assert [decimal_round(v, decimal.ROUND_HALF_UP) for v in exact] == [500, 113, -1724]


def test_per_joint_pulses_per_rev_broadcast():
    theta = np.radians([[90.0, 90.0, 90.0], [-45.0, 0.0, 360.0]])
    assert angles_to_pulses(theta, (4000, 2000, 800)).tolist() == [[1000, 500, 200], [-500, 0, 800]]


def test_round_half_away_ties_and_neighbours():
    x = [
        0.5,
        1.5,
        2.5,
        -0.5,
        -1.5,
        -2.5,
        0.49999999999999994,
        -0.49999999999999994,
        2.4999999999999996,
        1e15 + 0.5,
    ]
    assert round_half_away(x).tolist() == [1, 2, 3, -1, -2, -3, 0, 0, 2, 1e15 + 1]
    assert np.rint(x[:6]).tolist() == [0, 2, 2, -0, -2, -2]


@given(st.floats(min_value=-1e12, max_value=1e12, allow_nan=False))
def test_round_half_away_matches_decimal(x):
    assert round_half_away(x) == decimal_round(x, decimal.ROUND_HALF_UP)


@pytest.mark.parametrize(
    ("k", "away", "even"),
    [(1, 1, 0), (-1, -1, 0), (3, 2, 2), (5, 3, 2), (-5, -3, -2), (7, 4, 4)],
)
def test_tie_rules_on_angles(k, away, even):
    """theta = k * pi with 1 pulse per rev gives exactly k/2 pulses (degrees(k pi) is exact
    for these k, checked first): the two tie rules differ on odd k."""
    theta = k * np.pi
    assert np.degrees(theta) / 360.0 == k / 2, "not an exact tie: the test would not test ties"
    assert angles_to_pulses(theta, 1).item() == away
    assert angles_to_pulses(theta, 1, rounding="half-even").item() == even


@given(st.lists(st.floats(-4 * np.pi, 4 * np.pi, allow_nan=False), min_size=3, max_size=3))
def test_round_trip_within_half_a_pulse(theta):
    theta = np.array(theta)
    for rounding in ("half-away", "half-even"):
        c = angles_to_pulses(theta, PPR, rounding=rounding)
        back = pulses_to_angles(c, PPR)
        # half a pulse is pi / 4000 rad; 1e-12 rad allows the float round-off of the
        # degree <-> radian conversions at |theta| <= 4 pi
        assert np.all(np.abs(back - theta) <= np.pi / PPR + 1e-12)
        # and pulses are whole: converting back and again is the identity
        assert np.array_equal(angles_to_pulses(back, PPR, rounding=rounding), c)


def test_pulses_to_angles_values():
    assert_allclose(
        pulses_to_angles([4000, -1000, 1], 4000), [2 * np.pi, -np.pi / 2, 2 * np.pi / 4000], 1e-15
    )


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_angles_raise(bad):
    with pytest.raises(ValueError, match="NaN or inf"):
        angles_to_pulses([0.1, bad, 0.2])


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_non_finite_pulses_raise(bad):
    with pytest.raises(ValueError, match="NaN or inf"):
        pulses_to_angles([1, bad, 2])


@pytest.mark.parametrize("ppr", [0, -4000, np.nan, np.inf, (4000, 0, 4000)])
def test_bad_pulses_per_rev(ppr):
    with pytest.raises(ValueError, match=r"pulses_per_rev = .* must be finite and positive"):
        angles_to_pulses([0.1, 0.2, 0.3], ppr)
    with pytest.raises(ValueError, match=r"pulses_per_rev = .* must be finite and positive"):
        pulses_to_angles([1, 2, 3], ppr)


def test_unknown_rounding():
    with pytest.raises(ValueError, match="unknown rounding 'up'"):
        angles_to_pulses([0.1, 0.2, 0.3], rounding="up")


def test_docstring_examples():
    """angles_to_pulses' worked example: Table 4 row 1 -> (500, 113, -1724)."""
    import analysis.kinematics.pulses

    result = doctest.testmod(analysis.kinematics.pulses)
    assert result.attempted >= 1 and result.failed == 0

"""Seed 002's studies (analysis.audit.papers.picker.method): the reading summary of the joint
laws, the sensitivity of the sec. 4 comparison to model errors and
the instrument misalignment. Numbers that depend on the assumed dimensions are tested as properties
(e.g. a roll about the jaw axis cannot move a marker on that axis), not as magic values."""

from __future__ import annotations

import math

import numpy as np
import pytest

from analysis.audit.papers.picker import method as chk
from analysis.kinematics import picker as pk

PICKER = pk.load_picker()


def test_reading_summary_numbers():
    rs = chk.reading_summary()
    v = rs["velocity, rad/s"]
    assert v["units_printed"] and v["max_turn_rad"] == pytest.approx(125.0)  # 10 * 5^2 / 2
    assert v["peak_speed_rad_s"] == pytest.approx(50.0) and v["slider_travel_mm"] == (187.5, 250.0)
    assert rs["value, rad"]["max_turn_rad"] == pytest.approx(50.0)
    assert math.degrees(rs["value, deg"]["max_turn_rad"]) == pytest.approx(50.0)
    assert math.degrees(rs["velocity, deg/s"]["max_turn_rad"]) == pytest.approx(125.0)
    assert [k for k, x in rs.items() if x["max_turns"] < 0.5] == ["velocity, deg/s", "value, deg"]


@pytest.mark.parametrize("reading", chk.PLAUSIBLE_READINGS)
def test_mutation_errors_properties(reading):
    m = chk.mutation_errors(PICKER, reading)
    assert m["theta8 sign flipped (roll about the jaw axis)"] < 1e-9  # marker on the roll axis
    assert m["theta7 sign flipped"] > chk.MAX_ERR and m["theta1 sign flipped (waist)"] > 100
    for name in ("f", "e_tool", "l_DF", "z_A"):  # a 10 mm length error moves by <= 10 mm
        assert m[f"{name} off by 10 mm"] <= 10.0 + 1e-9


@pytest.mark.parametrize("reading", chk.PLAUSIBLE_READINGS)
def test_misalignment_reproduces_the_error(reading):
    eps = chk.misalignment_for(PICKER, reading)
    p = PICKER.position(pk.law_active(np.array([1.0, 2, 3, 4, 5]), reading))
    centre = np.array([1500.0, 0.0, 0.0])
    moved = chk.rotate_about_z(p, centre, eps)
    assert np.abs(moved - p).max() == pytest.approx(chk.MAX_ERR, abs=1e-6)
    assert 0 < eps < math.radians(5)


def test_planar_mobility():
    assert chk.planar_mobility(9, 9) == 6  # the two chains as sec. 3.2 lists them
    assert chk.planar_mobility(11, 14) == 2  # with fore-arm, link 5 and the triangle pivot
    assert chk.planar_mobility(4, 4) == 1  # a four-bar

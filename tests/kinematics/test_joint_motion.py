"""Joint motion limits and homing in arm descriptions (the shared contract of COMMON.md):
``max_velocity``, ``max_acceleration``, ``max_jerk`` and ``home`` on ``JointSpec``, in the
joint's units, converted and ranged by :mod:`analysis.validate`; absent keys None."""

from __future__ import annotations

import math

import pytest

from analysis.kinematics.description import load_description

BASE = """
name = "two"
title = "2R"
[parameters]
L1 = {{ value = 300.0, unit = "mm", status = "measured", source = "t" }}
[[rows]]
joint = "theta1"
a = "L1"
[[rows]]
joint = "s"
kind = "prismatic"
[[joints]]
name = "theta1"
pulses_per_rev = 4000
limits_deg = [-170, 170]
{rev}
[[joints]]
name = "s"
kind = "prismatic"
pulses_per_rev = 4000
lead_mm = 5.0
limits_mm = [0, 200]
{pri}
"""


def _load(tmp_path, rev="", pri=""):
    path = tmp_path / "two.toml"
    path.write_text(BASE.format(rev=rev, pri=pri))
    return load_description(path)


def test_absent_values_are_none_and_require_names_joint_and_key(tmp_path):
    desc = _load(tmp_path)
    j = desc.joints[0]
    assert (j.max_velocity, j.max_acceleration, j.max_jerk, j.home_mode, j.home_position) == (
        None,) * 5  # fmt: skip
    with pytest.raises(ValueError, match="joint theta1 has no max_jerk"):
        j.require("max_jerk")
    with pytest.raises(ValueError, match="joint s has no home_position"):
        desc.joints[1].require("home_position")


def test_values_converted_to_joint_units(tmp_path):
    rev = (
        'max_velocity = { value = 90.0, unit = "deg/s", status = "assumed", source = "x" }\n'
        'max_acceleration = { value = 2.0, unit = "rad/s2", status = "measured", source = "y" }\n'
        'max_jerk = { value = 3600.0, unit = "deg/s3", status = "assumed", source = "z" }\n'
        'home = { mode = "switch", position = -90.0, status = "assumed", source = "h" }\n'
    )
    pri = (
        'max_velocity = { value = 0.25, unit = "m/s", status = "assumed", source = "x" }\n'
        'max_acceleration = { value = 10, unit = "cm/s2", status = "assumed", source = "x" }\n'
        'home = { mode = "set", position = 20.0, status = "assumed", source = "h" }\n'
    )
    r, p = _load(tmp_path, rev, pri).joints
    assert r.max_velocity == pytest.approx(math.pi / 2, rel=1e-15)
    assert r.max_acceleration == 2.0
    assert r.max_jerk == pytest.approx(math.radians(3600.0), rel=1e-15)
    assert (r.home_mode, r.home_position) == ("switch", pytest.approx(-math.pi / 2))
    assert r.require("max_velocity") == r.max_velocity
    assert (r.max_velocity_status, r.max_acceleration_status, r.home_status) == (
        "assumed", "measured", "assumed")  # fmt: skip
    assert r.sources["max_velocity"] == "x" and r.sources["home"] == "h"
    assert (p.max_velocity, p.max_acceleration, p.max_jerk) == (250.0, 100.0, None)
    assert (p.home_mode, p.home_position) == ("set", 20.0)


@pytest.mark.parametrize(
    ("rev", "pri", "message"),
    [
        ('max_velocity = { value = 90.0, unit = "mm/s" }', "", "not one of deg/s, rad/s"),
        ("", 'max_velocity = { value = 9.0, unit = "deg/s" }', "not one of mm/s, cm/s"),
        ('max_velocity = { value = -1.0, unit = "deg/s" }', "", "must be > 0"),
        ('max_velocity = { value = 0.0, unit = "deg/s" }', "", "must be > 0"),
        ('max_jerk = { value = 1e30, unit = "deg/s3" }', "", "largest rate"),
        ('max_jerk = { value = "fast", unit = "deg/s3" }', "", "is text, not a number"),
        ('max_acceleration = { value = 1.0, unit = "deg/s3" }', "", "not one of deg/s2"),
        ("max_velocity = 90.0", "", "max_velocity: 90.0 must be a table"),
        ('home = { mode = "limit", position = 0.0 }', "", "home mode: 'limit' is not one of"),
        ('home = { mode = "set", position = 180.0 }', "", "outside the joint's limits"),
        ("", 'home = { mode = "set", position = -1.0 }', "outside the joint's limits"),
        ('home = { mode = "set" }', "", "home position: is missing"),
        ('max_velocity = { value = 1.0, unit = "deg/s", sorce = "x" }', "", "mean 'source'"),
        ('max_velocity = { value = 1.0, unit = "deg/s", status = "guessed" }', "", "status"),
    ],
)
def test_bad_values_refused_naming_joint_and_key(tmp_path, rev, pri, message):
    with pytest.raises(ValueError, match=message) as err:
        _load(tmp_path, rev, pri)
    assert "joint theta1" in str(err.value) or "joint s" in str(err.value)

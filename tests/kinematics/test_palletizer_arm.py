"""Seed 001's palletizer on the one-source design: data/arms/palletizer.toml read by the
loader, the elbow stop of sec. 2 enforced by the shared solver (numpy and the compiled
kernel) and the command line; the data file kept for notebook 04 equals the description.

The stop is theta3 in [90, 180] deg (the included angle of forearm and upper arm <= 90 deg,
elbow-up side; reasons in the TOML). With L1 = L2 = 200 mm (assumed) it admits the wrist up to
sqrt(L1^2 + L2^2) = 282.84 mm from the shoulder instead of L1 + L2 = 400 mm. Test targets sit
at least 0.5 mm from that sphere, where theta3 is 0.5 / 200 rad ~ 0.14 deg away from 90 deg:
float64 (error ~1e-13 rad) cannot put them on the wrong side, a missing check would.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from analysis.app.cli import main
from analysis.kinematics.arm import Status, load_arm
from analysis.kinematics.description import load_description

ARM = load_arm("palletizer")
L1, L2, L3, H = (ARM.params[k] for k in ("L1", "L2", "L3", "h"))
STOP = math.hypot(L1, L2)  # wrist distance where theta3 = 90 deg


def grasp_points(rng, wrist_dist, n):
    """Grasp points whose wrist (G + L3 back towards the axis, + h up) lies at the given
    distances (>= 5 mm) from the shoulder, elevation within +-1.2 rad, so in front of the base
    axis (wrist radius >= 5 cos 1.2 = 1.8 mm)."""
    phi = rng.uniform(-np.pi, np.pi, n)
    elev = rng.uniform(-1.2, 1.2, n)
    rho = wrist_dist * np.cos(elev) + L3
    zw = wrist_dist * np.sin(elev)
    return np.stack([rho * np.cos(phi), rho * np.sin(phi), zw - H], axis=-1)


def test_description_holds_the_stop_and_marks_every_number_assumed():
    desc = load_description("palletizer")
    limits = {j.name: (math.degrees(j.lower), math.degrees(j.upper)) for j in desc.joints}
    assert limits["theta3"] == pytest.approx((90.0, 180.0))
    assert all(limits[k] == pytest.approx((-180.0, 180.0)) for k in ("theta1", "theta2", "theta4"))
    assert "sec. 2" in desc.joints[2].limits_status
    assert set(desc.assumed) == {"L1", "L2", "L3", "h"}
    assert all(j.pulses_status == "assumed" for j in desc.joints)
    assert ARM.params["L1"] == ARM.params["L2"]  # the isosceles family is the default
    assert ARM.limits == (None, None, (math.pi / 2, math.pi), None)


@pytest.mark.parametrize("backend", ["numpy", "compiled"])
def test_the_shared_solver_enforces_the_elbow_stop(rng, backend):
    inside = grasp_points(rng, rng.uniform(5.0, STOP - 0.5, 400), 400)
    beyond = grasp_points(rng, rng.uniform(STOP + 0.5, L1 + L2 - 0.5, 400), 400)
    outside = grasp_points(rng, rng.uniform(L1 + L2 + 0.5, L1 + L2 + 50, 100), 100)
    front = ("front-up", "front-down")  # the waist facing the grasp point
    sol = ARM.solve(np.vstack([inside, beyond, outside]), front, backend=backend)
    assert (sol.status[:400] == Status.OK).all()
    assert (sol.status[400:800] == Status.JOINT_LIMITS).all()
    assert (sol.status[800:] == Status.OUT_OF_REACH).all()  # reach is checked first
    assert sol.ok[:400, 0].all() and not sol.ok[:, 1].any()  # elbow-down: never in the stop
    assert np.isnan(sol.theta[400:]).all()
    t3 = sol.theta[:400, 0, 2]
    assert ((t3 >= math.pi / 2) & (t3 <= math.pi)).all()
    # the same targets without the limits: both branches solve, elbow-down mirrors theta3
    free = ARM.solve(np.vstack([inside, beyond]), front, limits=False, backend=backend)
    assert (free.status == Status.OK).all() and free.ok.all()
    np.testing.assert_allclose(free.theta[:, 1, 2], -free.theta[:, 0, 2], atol=1e-12)
    np.testing.assert_allclose(free.theta[:400, 0], sol.theta[:400, 0], atol=0.0)
    # reaching back over the base: the wrist lies rho + L3 behind the axis; "back-up" is in
    # the stop exactly where that wrist is within sqrt(L1^2 + L2^2), "back-down" never
    P = np.vstack([inside, beyond, outside])
    back = ARM.solve(P, ("back-up", "back-down"), backend=backend)
    rho = np.hypot(P[:, 0], P[:, 1])
    d_back = np.hypot(rho + L3, P[:, 2] + H)
    far = np.abs(d_back - STOP) > 1e-6
    np.testing.assert_array_equal(back.ok[far, 0], (d_back < STOP)[far])
    assert not back.ok[:, 1].any()


def test_the_initial_pose_sits_on_the_stop_and_is_admitted():
    """Sec. 3's initial pose (upper arm vertical, forearm perpendicular, eq. 7) has theta3 =
    90 deg exactly: the printed '< 90' would refuse it, the closed stop admits it."""
    G = [L2 + L3, 0.0, L1 - H]
    q = ARM.ik(G)
    np.testing.assert_allclose(q, [0.0, -math.pi / 2, math.pi / 2, math.pi / 2], atol=1e-15)
    np.testing.assert_allclose(ARM.fk(q), G, atol=1e-12)


def test_ik_names_the_stop_and_the_cli_exits_2(capsys):
    G = [300.0, 0.0, 100.0]  # wrist (250, 170) mm from the shoulder: 302.3 mm, beyond 282.8
    w, zw = G[0] - L3, G[2] + H
    assert STOP < math.hypot(w, zw) < L1 + L2
    with pytest.raises(ValueError, match="joint limits of palletizer"):
        ARM.ik(G)
    assert ARM.solve(G, limits=False).status == Status.OK
    assert main(["ik", "300", "0", "100", "--arm", "palletizer"]) == 2
    assert "joint limits" in capsys.readouterr().err


def test_other_lengths_move_the_stop_with_them(rng):
    """Lengths are parameters: with L2 = 150 mm the stop is at sqrt(200^2 + 150^2) = 250 mm."""
    arm = ARM.with_(L2=150.0)
    stop = math.hypot(200.0, 150.0)
    d = np.array([stop - 0.5, stop + 0.5])
    g = np.array([[L3 + dd, 0.0, -H] for dd in d])  # wrist level with the shoulder
    assert arm.solve(g).status.tolist() == [Status.OK, Status.JOINT_LIMITS]

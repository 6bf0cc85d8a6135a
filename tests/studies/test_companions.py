"""Companion papers (seeds 001, 002, 004) against independent references: the D-H chain,
Pinocchio, pin.exp6, a linear solve of seed 004's constraint system, finite differences."""

import numpy as np
import pinocchio as pin
import pytest

from analysis.kinematics.pinocchio_model import PinocchioArm
from analysis.kinematics.pulses import angles_to_pulses
from analysis.studies.companions import (
    PRINTED_FORMULAS,
    cubic_coefficients,
    cubic_trajectory,
    exp_twist,
    gamma_printed,
    load_palletizer,
    palletizer_ik_printed,
    peak_pulse_rates,
    poe_fk,
    screw_axes,
    trajectory_pulses,
)

# Lengths are a few hundred mm; 1e-8 mm is far above float64 round-off (~1e-13 mm) and far
# below anything physical, so a wrong formula cannot pass.
ATOL_MM = 1e-8


@pytest.fixture(scope="module")
def pal():
    return load_palletizer()


def reachable_targets(pal, rng, n=400):
    """Seeded random grasp points with L4 strictly inside the reach (acos well-conditioned)."""
    G = rng.uniform([-450, -450, -300], [450, 450, 450], size=(4 * n, 3))
    rho = np.hypot(G[:, 0], G[:, 1])
    L4 = np.hypot(rho - pal.L3, G[:, 2] + pal.h)
    keep = (L4 < 0.99 * (pal.L1 + pal.L2)) & (L4 > 0.05 * (pal.L1 + pal.L2)) & (rho > 1)
    assert keep.sum() >= n
    return G[keep][:n]


# ----------------------------------------------------------------------------- seed 001
def test_palletizer_ik_round_trip(pal, rng):
    G = reachable_targets(pal, rng)
    np.testing.assert_allclose(pal.fk(pal.ik(G)), G, atol=ATOL_MM)


def test_palletizer_dh_matches_pinocchio(pal, rng):
    q = rng.uniform(-np.pi, np.pi, size=(50, 4))
    np.testing.assert_allclose(pal.fk(q), PinocchioArm(pal.table).fk(q), atol=ATOL_MM)


def test_palletizer_gripper_stays_level(pal, rng):
    """Section 3 assumption: the gripper stays parallel to the base (only turned by gamma)."""
    G = reachable_targets(pal, rng, 100)
    q = pal.ik(G)
    R = pal.table.fk(q)[:, :3, :3]
    R_home = pal.table.fk([0, -np.pi / 2, np.pi / 2, np.pi / 2])[:3, :3]
    c, s = np.cos(q[:, 0]), np.sin(q[:, 0])
    Rz = np.zeros((len(q), 3, 3))
    Rz[:, 0, 0], Rz[:, 0, 1], Rz[:, 1, 0], Rz[:, 1, 1], Rz[:, 2, 2] = c, -s, s, c, 1
    np.testing.assert_allclose(R, Rz @ R_home, atol=1e-12)


def test_palletizer_initial_pose_is_eq7(pal):
    """The initial pose (upper arm up, forearm forward) gives eq. 7's D-H angles."""
    G = [pal.L2 + pal.L3, 0.0, pal.L1 - pal.h]
    np.testing.assert_allclose(pal.motor_angles(G), 0.0, atol=1e-12)
    np.testing.assert_allclose(pal.ik(G), [0, -np.pi / 2, np.pi / 2, np.pi / 2], atol=1e-12)


def test_palletizer_ik_vectorized_shape(pal, rng):
    G = reachable_targets(pal, rng, 24).reshape(2, 3, 4, 3)
    q = pal.ik(G)
    assert q.shape == (2, 3, 4, 4)
    np.testing.assert_allclose(q[1, 2, 3], pal.ik(G[1, 2, 3]), atol=1e-15)


@pytest.mark.parametrize(
    ("target", "match"),
    [([0.0, 0.0, 100.0], "base axis"), ([500.0, 0.0, 130.0], "L4 = "), ([50.0, 0, -70.0], "L4")],
)
def test_palletizer_bad_targets_raise(pal, target, match):
    with pytest.raises(ValueError, match=match):
        pal.ik(target)


def test_gamma_printed_quadrants():
    """Eq. 6 as printed: right in quadrants 1 and 4 (signed arctan), wrong in 2 and 3."""
    x = np.array([200.0, -200.0, -200.0, 200.0])
    y = np.array([100.0, 100.0, -100.0, -100.0])
    truth = np.degrees(np.arctan2(y, x))
    signed = np.degrees(gamma_printed(x, y))
    acute = np.degrees(gamma_printed(x, y, "abs"))
    np.testing.assert_allclose(signed[[0, 3]], truth[[0, 3]], atol=1e-12)
    np.testing.assert_allclose(signed[[1, 2]], [206.56505118, -63.43494882], atol=1e-7)
    np.testing.assert_allclose(acute[[0, 1]], truth[[0, 1]], atol=1e-12)
    assert not np.isclose(acute[2], truth[2]) and not np.isclose(acute[3], truth[3])
    with pytest.raises(ValueError, match="undefined"):
        gamma_printed(-100.0, 0.0)


@pytest.mark.parametrize(
    ("formula", "target"),
    [
        ("gamma", [-200.0, -100.0, 80.0]),
        ("alpha2", [30.0, 10.0, 100.0]),  # wrist behind the base axis: rho < L3
        ("alpha", [250.0, 0.0, 130.0]),  # even the initial pose
        ("theta4", [250.0, 0.0, 130.0]),
    ],
)
def test_each_printed_formula_misses(pal, formula, target):
    assert np.linalg.norm(pal.fk(palletizer_ik_printed(pal, target, (formula,))) - target) > 10
    assert np.linalg.norm(pal.fk(palletizer_ik_printed(pal, target, ())) - target) < ATOL_MM


def test_printed_formula_names_checked(pal):
    assert set(PRINTED_FORMULAS) == {"gamma", "alpha2", "alpha", "theta4"}
    with pytest.raises(ValueError, match="unknown formula"):
        palletizer_ik_printed(pal, [250.0, 0, 130], ("beta",))


# ----------------------------------------------------------------------------- seed 002
def test_poe_equals_arm_dh_and_pinocchio(arm, rng):
    q = rng.uniform(-np.pi, np.pi, size=(60, 3))
    T = poe_fk(q)
    np.testing.assert_allclose(T[:, :3, 3], arm.fk(q), atol=ATOL_MM)
    np.testing.assert_allclose(T, arm.params.dh_table().fk(q), atol=ATOL_MM)
    pin_arm = PinocchioArm(arm.params.dh_table())
    for qk, Tk in zip(q[:10], T[:10], strict=True):
        np.testing.assert_allclose(Tk, pin_arm.placement(qk), atol=ATOL_MM)


def test_exp_twist_matches_pin_exp6(rng):
    S, _ = screw_axes()
    theta = rng.uniform(-4, 4, size=7)
    for Si in S:
        T = exp_twist(Si, theta)
        for th, Tk in zip(theta, T, strict=True):
            ref = pin.exp6(np.concatenate([Si[3:], Si[:3]]) * th).homogeneous  # (v, w)
            np.testing.assert_allclose(Tk, ref, atol=1e-9)


def test_home_pose_and_bad_screw(arm):
    np.testing.assert_allclose(
        poe_fk(np.zeros(3)), arm.params.dh_table().fk(np.zeros(3)), atol=1e-12
    )
    with pytest.raises(ValueError, match="unit omega"):
        exp_twist([0, 0, 2, 0, 0, 0], 0.1)
    with pytest.raises(ValueError, match=r"expected \(\.\.\., 3\)"):
        poe_fk(np.zeros(4))


# ----------------------------------------------------------------------------- seed 004
def test_cubic_coefficients_solve_the_constraint_system(rng):
    """Eq. 5.5: [1 0 0 0; 0 1 0 0; 1 T T^2 T^3; 0 1 2T 3T^2] a = (q0, 0, qf, 0)."""
    q0, qf, T = rng.uniform(-3, 3, 3), rng.uniform(-3, 3, 3), 2.7
    A = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [1, T, T**2, T**3], [0, 1, 2 * T, 3 * T**2]])
    ref = np.linalg.solve(A, np.stack([q0, np.zeros(3), qf, np.zeros(3)]))
    np.testing.assert_allclose(cubic_coefficients(q0, qf, T), ref, atol=1e-12)


def test_cubic_boundaries_and_derivatives(rng):
    q0, qf, T = rng.uniform(-3, 3, (2, 3)), rng.uniform(-3, 3, (2, 3)), 1.5
    t = np.linspace(0, T, 301)
    q, qd, qdd = cubic_trajectory(q0, qf, T, t)
    assert q.shape == qd.shape == qdd.shape == (301, 2, 3)
    np.testing.assert_allclose(q[0], q0, atol=1e-12)
    np.testing.assert_allclose(q[-1], qf, atol=1e-12)
    np.testing.assert_allclose(qd[[0, -1]], 0.0, atol=1e-12)
    # central differences, step 1e-5 s: truncation error ~ h^2 |q'''| ~ 1e-9 rad/s
    h, ti = 1e-5, t[1:-1]
    plus, minus = cubic_trajectory(q0, qf, T, ti + h), cubic_trajectory(q0, qf, T, ti - h)
    fd = (plus[0] - minus[0]) / (2 * h)
    np.testing.assert_allclose(qd[1:-1], fd, atol=1e-7)
    fdd = (plus[1] - minus[1]) / (2 * h)
    np.testing.assert_allclose(qdd[1:-1], fdd, atol=1e-6)


def test_peak_pulse_rate_is_sampled_maximum(arm):
    q0 = arm.ik([100.0, 100.0, 600.0])  # Table 4 rows 1 and 10, front-up
    qf = arm.ik([300.0, 300.0, 600.0])
    T = 2.0
    t = np.linspace(0, T, 2001)  # contains T/2, where |qd| peaks
    qd = cubic_trajectory(q0, qf, T, t)[1]
    sampled = np.abs(qd).max(axis=0) * 4000 / (2 * np.pi)
    np.testing.assert_allclose(peak_pulse_rates(q0, qf, T), sampled, rtol=1e-12)
    pulses, moves = trajectory_pulses(q0, qf, T, t)
    np.testing.assert_array_equal(pulses[0], angles_to_pulses(q0))
    np.testing.assert_array_equal(pulses[-1], angles_to_pulses(qf))
    np.testing.assert_array_equal(moves, pulses[-1] - pulses[0])
    # zero end velocity and a monotone cubic: the pulse position never overshoots
    lo, hi = np.minimum(pulses[0], pulses[-1]), np.maximum(pulses[0], pulses[-1])
    assert ((pulses >= lo) & (pulses <= hi)).all()


@pytest.mark.parametrize("T", [0.0, -1.0, np.inf, np.nan])
def test_bad_duration_raises(T):
    with pytest.raises(ValueError, match="duration T"):
        cubic_trajectory([0.0], [1.0], T, [0.0])


def test_bad_samples_raise():
    with pytest.raises(ValueError, match="within"):
        cubic_trajectory([0.0], [1.0], 1.0, [0.0, 1.5])
    with pytest.raises(ValueError, match="NaN"):
        cubic_coefficients([np.nan], [1.0], 1.0)

"""Seed 004's cubic trajectories (analysis.studies.companions) against independent
references: a linear solve of the constraint system, finite differences, sampled maxima.

Seed 001 (palletizer) and seed 002 (POE) moved: tests/audit/test_palletizer_checks.py,
tests/kinematics/test_palletizer_arm.py and tests/kinematics/test_poe.py."""

import numpy as np
import pytest

from analysis.kinematics.pulses import angles_to_pulses
from analysis.studies.companions import (
    cubic_coefficients,
    cubic_trajectory,
    peak_pulse_rates,
    trajectory_pulses,
)


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

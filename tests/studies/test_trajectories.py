"""analysis.studies.trajectories: the thesis's cubic (seed 004, eqs. 5.1-5.9), the quintic,
the trapezoid, pulse rates and the sequential on/off move, against independent references
(boundary conditions, central finite differences, sampled maxima, the VB6 listing's own
formula).

Tolerances: values are O(1) rad over O(10) s; float64 round-off is ~1e-15, so boundary
values are held to 1e-12. Central differences with h = 1e-5 s have truncation error
h^2 |q'''| / 6 ~ 1e-10 and round-off eps |q| / h ~ 1e-11: held to 1e-6 (a wrong
coefficient is off by > 1e-2).
"""

from __future__ import annotations

import numpy as np
import pytest

from analysis.studies import trajectories as tr

KINDS = tr.PROFILES


@pytest.mark.parametrize("kind", KINDS)
def test_profiles_meet_their_end_conditions(kind):
    s, ds, dds = tr.profile(kind, np.array([0.0, 1.0]))
    np.testing.assert_allclose(s, [0.0, 1.0], atol=1e-12)
    np.testing.assert_allclose(ds, [0.0, 0.0], atol=1e-12)
    if kind == "quintic":
        np.testing.assert_allclose(dds, [0.0, 0.0], atol=1e-12)
    else:  # the cubic and the trapezoid start and stop with a step of acceleration
        assert dds[0] > 1 and dds[1] < -1


@pytest.mark.parametrize("kind", KINDS)
def test_derivatives_against_central_differences(kind, rng):
    q0, qf, T = rng.uniform(-3, 3, (2, 5)), rng.uniform(-3, 3, (2, 5)), 10.0
    t = np.linspace(0.1, T - 0.1, 97)
    q, qd, qdd = tr.trajectory(kind, q0, qf, T, t)
    assert q.shape == qd.shape == qdd.shape == (97, 2, 5)
    h = 1e-5
    plus, minus = tr.trajectory(kind, q0, qf, T, t + h), tr.trajectory(kind, q0, qf, T, t - h)
    fd = (plus[0] - minus[0]) / (2 * h)
    fdd = (plus[1] - minus[1]) / (2 * h)
    np.testing.assert_allclose(qd, fd, atol=1e-6)
    if kind == "trapezoidal":  # acceleration is piecewise constant: skip the blend ends
        b = tr.DEFAULT_BLEND * T
        keep = (np.abs(t - b) > 2 * h) & (np.abs(t - (T - b)) > 2 * h)
        np.testing.assert_allclose(qdd[keep], fdd[keep], atol=1e-6)
    else:
        np.testing.assert_allclose(qdd, fdd, atol=1e-6)
    np.testing.assert_allclose(q[[0, -1]], tr.trajectory(kind, q0, qf, T, t[[0, -1]])[0])


@pytest.mark.parametrize("kind", KINDS)
def test_peak_speed_and_acceleration_jumps_are_the_sampled_ones(kind, rng):
    q0, qf, T = rng.uniform(-3, 3, 5), rng.uniform(-3, 3, 5), 7.0
    t = np.linspace(0, T, 70_001)  # contains T/2 and the blend ends at T/3, 2T/3
    _, qd, qdd = tr.trajectory(kind, q0, qf, T, t)
    peak = np.abs(qd).max(axis=0)
    np.testing.assert_allclose(peak, tr.peak_speed_factor(kind) * np.abs(qf - q0) / T, rtol=1e-9)
    # the arm stands still before and after: the jumps include |qdd(0+)| and |qdd(T-)|;
    # between samples a continuous acceleration changes by at most |jerk| dt (quintic:
    # 60 |dq| / T^3 x 1e-4 s < 1e-4 rad/s^2)
    steps = np.abs(np.diff(np.concatenate([np.zeros((1, 5)), qdd, np.zeros((1, 5))]), axis=0))
    big = steps.max(axis=0)
    np.testing.assert_allclose(big, tr.acceleration_jumps(kind, q0, qf, T), rtol=1e-3, atol=1e-4)


def test_cubic_is_the_thesis_and_the_listing(rng):
    """eqs. 5.5-5.6 (a linear solve of the four conditions) and the VB6 listing's
    'Y = a + (3 / (c * c)) * (b - a) * (X * X) - (2 / (c * c * c)) * (b - a) * (X * X * X)'."""
    q0, qf, T = rng.uniform(-3, 3, 5), rng.uniform(-3, 3, 5), 10.0
    A = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [1, T, T**2, T**3], [0, 1, 2 * T, 3 * T**2]])
    ref = np.linalg.solve(A, np.stack([q0, np.zeros(5), qf, np.zeros(5)]))
    np.testing.assert_allclose(tr.cubic_coefficients(q0, qf, T), ref, atol=1e-12)
    t = np.linspace(0, T, 10_001)
    X = t[:, None]
    listing = q0 + (3 / T**2) * (qf - q0) * (X * X) - (2 / T**3) * (qf - q0) * (X * X * X)
    q, qd, qdd = tr.cubic_trajectory(q0, qf, T, t)
    np.testing.assert_allclose(q, listing, atol=1e-12)
    for got, want in zip(tr.trajectory("cubic", q0, qf, T, t), (q, qd, qdd), strict=True):
        np.testing.assert_allclose(got, want, atol=1e-12)


def test_pulse_rates():
    """A joint moving 146.9 deg in 10 s on the cubic peaks at 1.5 x 14.69 deg/s = 22.04
    deg/s: 200.4 pulses/s at Table 2-1's 0.11 deg per pulse."""
    q0, qf = np.radians([0.0, -66.006]), np.radians([0.0, 80.922])
    t = np.linspace(0, 10, 1001)
    _, qd, _ = tr.cubic_trajectory(q0, qf, 10.0, t)
    rates = tr.pulse_rates(qd, [0.14, 0.11])
    assert rates.shape == (1001, 2)
    np.testing.assert_allclose(rates.max(axis=0), [0.0, 1.5 * 146.928 / 10 / 0.11], rtol=1e-12)
    with pytest.raises(ValueError, match="resolution"):
        tr.pulse_rates(qd, [0.14, 0.0])


def test_sequential_move_runs_one_joint_at_a_time(rng):
    q0, qf = rng.uniform(-2, 2, 5), rng.uniform(-2, 2, 5)
    speed = rng.uniform(0.5, 2.0, 5)
    _, switch = tr.sequential_move(q0, qf, speed, np.zeros(1))
    np.testing.assert_allclose(np.diff(switch), np.abs(qf - q0) / speed, rtol=1e-12)
    t = np.linspace(0, switch[-1] + 1.0, 20_001)
    q, _ = tr.sequential_move(q0, qf, speed, t)
    np.testing.assert_allclose(q[0], q0, atol=0)
    np.testing.assert_allclose(q[-1], qf, atol=1e-12)
    moving = np.abs(np.diff(q, axis=0)) > 1e-15
    assert (moving.sum(axis=1) <= 2).all()  # at most a hand-over sample shares two joints
    first = [int(np.argmax(moving[:, j])) for j in range(5)]
    assert first == sorted(first)  # M1 first, then M2 ...
    rev, sw = tr.sequential_move(q0, qf, speed, t, order=(4, 3, 2, 1, 0))
    np.testing.assert_allclose(rev[-1], qf, atol=1e-12)
    assert sw[-1] == pytest.approx(switch[-1])


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: tr.trajectory("cubic", 0.0, 1.0, 0.0, [0.0]), "duration"),
        (lambda: tr.trajectory("cubic", 0.0, 1.0, 1.0, [2.0]), "within"),
        (lambda: tr.trajectory("cubic", np.nan, 1.0, 1.0, [0.0]), "NaN"),
        (lambda: tr.trajectory("septic", 0.0, 1.0, 1.0, [0.0]), "unknown profile"),
        (lambda: tr.profile("trapezoidal", 0.5, blend=0.7), "blend"),
        (lambda: tr.sequential_move([0.0], [1.0], [0.0], [0.0]), "speeds"),
        (lambda: tr.sequential_move([0.0, 1.0], [1.0, 0.0], 1.0, [0.0], (0, 0)), "order"),
        (lambda: tr.cubic_coefficients(0.0, 1.0, np.inf), "duration"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()

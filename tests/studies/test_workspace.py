"""analysis.studies.workspace: reachable set, volume, sections, limits, dexterity maps."""

import math

import matplotlib as mpl
import numpy as np
import pandas as pd
import pytest

from analysis.kinematics.arm import paper_arm
from analysis.kinematics.params import data_dir
from analysis.studies import workspace as W


def test_shell_volume_is_the_table3_shell(arm):
    # Table 3: L2 = 310, L3 = 200 mm -> radii 510 and 110 mm, written out independently
    assert W.shell_volume(arm) == pytest.approx(4 / 3 * math.pi * (510.0**3 - 110.0**3), rel=1e-15)


def test_monte_carlo_volume_brackets_the_analytic_one(arm):
    est = W.monte_carlo_volume(arm, 400_000, seed=5)
    exact = W.shell_volume(arm)
    assert est.ci_low_mm3 < exact < est.ci_high_mm3
    assert est.hits == round(est.volume_mm3 / est.box_mm3 * est.n)
    # 95 % Wilson half-width ~ 1.96 standard errors
    assert (est.ci_high_mm3 - est.ci_low_mm3) / 2 == pytest.approx(1.96 * est.stderr_mm3, rel=0.01)
    with pytest.raises(ValueError, match="confidence"):
        W.monte_carlo_volume(arm, 10, confidence=1.0)
    with pytest.raises(ValueError, match="positive"):
        W.monte_carlo_volume(arm, 0)


def test_unlimited_reachable_is_the_shell(arm, rng):
    p = W.sample_box(arm, 100_000, rng)
    D = np.sqrt(p[:, 0] ** 2 + p[:, 1] ** 2 + (p[:, 2] - 660.0) ** 2)
    expected = (D >= 110.0) & (D <= 510.0)
    got = W.reachable(arm, p)
    # points within 1e-6 mm of a sphere may go either way (the reach tolerance)
    near = (np.abs(D - 510.0) < 1e-5) | (np.abs(D - 110.0) < 1e-5)
    np.testing.assert_array_equal(got[~near], expected[~near])
    np.testing.assert_array_equal(W.reachable(arm, p, W.JointLimits()), got)


def test_sample_shell_is_uniform_in_the_shell(arm, rng):
    p = W.sample_shell(arm, 200_000, rng)
    D = np.linalg.norm(p - arm.shoulder, axis=-1)
    assert (D >= 110.0 - 1e-9).all() and (D <= 510.0 + 1e-9).all()
    # half the shell's volume lies below the radius with D^3 = (R^3 + r^3) / 2
    frac = np.mean(D**3 < (510.0**3 + 110.0**3) / 2)
    assert abs(frac - 0.5) < 4 * math.sqrt(0.25 / p.shape[0])
    # isotropic: mean direction ~ 0
    assert np.abs((p - arm.shoulder).mean(axis=0)).max() < 4 * 510 / math.sqrt(p.shape[0])


def test_joint_limits_validation_and_wrapping():
    with pytest.raises(ValueError, match="above its upper"):
        W.JointLimits((0.0, 1.0, 0.0), (1.0, 0.0, 1.0))
    with pytest.raises(ValueError, match="NaN"):
        W.JointLimits((np.nan, 0.0, 0.0), (1.0, 1.0, 1.0))
    with pytest.raises(ValueError, match="3 lower"):
        W.JointLimits((0.0, 0.0), (1.0, 1.0))
    lim = W.JointLimits.from_degrees((-20, -20, -20), (20, 20, 400))
    q = np.radians(
        [
            [350.0, 0.0, 0.0],
            [30.0, 0.0, 0.0],
            [-370.0, 10.0, 123.0],
            [0.0, 21.0, 0.0],
            [0.0, 0.0, np.nan],
        ]
    )
    np.testing.assert_array_equal(lim.contains(q), [True, False, True, False, False])
    assert W.JointLimits().unlimited and not lim.unlimited
    assert lim.theta1_on_axis() == 0.0
    assert W.JointLimits.from_degrees((10, 0, 0), (80, 1, 1)).theta1_on_axis() == pytest.approx(
        math.radians(10)
    )


def test_reachable_with_limits_hand_cases(arm):
    # (-300, 0, 660): front theta1 = 180 deg, back theta1 = 0 deg
    p = np.array([[-300.0, 0.0, 660.0]])
    half = W.JointLimits.from_degrees((-90, -360, -360), (90, 360, 360))
    narrow = W.JointLimits.from_degrees((10, -360, -360), (80, 360, 360))
    assert W.reachable(arm, p, half).tolist() == [True]  # by a back branch
    assert W.reachable(arm, p, narrow).tolist() == [False]


def test_reachable_with_limits_agrees_with_forward_sampling(arm, rng):
    lim = W.JointLimits.from_degrees((-170, 0, -150), (170, 180, 150))
    lo, hi = np.array(lim.lower), np.array(lim.upper)
    q = lo + (hi - lo) * rng.uniform(0, 1, (50_000, 3))
    # every pose inside the limits puts the gripper at a point the map calls reachable
    assert W.reachable(arm, arm.fk(q), lim).all()
    # and the limited set is a subset of the shell
    p = W.sample_box(arm, 50_000, rng)
    limited, free = W.reachable(arm, p, lim), W.reachable(arm, p)
    assert not (limited & ~free).any() and limited.sum() < free.sum()


def test_manipulability_and_condition_against_numpy_linalg(arm, rng):
    q = rng.uniform(-np.pi, np.pi, (2000, 3))
    J = arm.jacobian(q)
    np.testing.assert_allclose(
        W.manipulability(arm, q), np.abs(np.linalg.det(J)), rtol=1e-9, atol=1e-6
    )
    np.testing.assert_allclose(W.condition_number(arm, q), np.linalg.cond(J), rtol=1e-9)
    # singular sets: stretched / folded elbow and the base axis
    sing = np.array([[0.3, 0.4, 0.0], [0.3, 0.4, np.pi], [0.0, np.pi / 2, 0.0]])
    assert W.manipulability(arm, sing) == pytest.approx([0, 0, 0], abs=1e-9)
    assert (W.condition_number(arm, sing) > 1e12).all()


def test_sections_and_table4_targets(arm):
    g = W.section_grid(arm, "xy", 301, level_mm=600.0)
    assert g.points.shape == (301, 301, 3) and (g.points[..., 2] == 600.0).all()
    c = W.section_circles(arm, "xy", 600.0)
    assert c["outer"] == pytest.approx(math.sqrt(510**2 - 60**2)) and c["inner"] == pytest.approx(
        math.sqrt(110**2 - 60**2)
    )
    cell = (g.u[1] - g.u[0]) * (g.v[1] - g.v[0])
    area = W.reachable(arm, g.points).sum() * cell
    assert area == pytest.approx(
        math.pi * (c["outer"] ** 2 - c["inner"] ** 2), rel=0.01
    )  # grid resolution
    assert W.section_circles(arm, "xz", 0.0) == {
        "centre_u": 0.0,
        "centre_v": 660.0,
        "outer": 510.0,
        "inner": 110.0,
    }
    assert W.section_circles(arm, "xy", 1300.0)["outer"] is None
    with pytest.raises(ValueError, match="plane"):
        W.section_grid(arm, "yz")
    t4 = pd.read_csv(data_dir() / "table4.csv", dtype=str)
    p = t4[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    np.testing.assert_array_equal(W.reachable(arm, p), (t4["status"] == "solved").to_numpy())


def test_workspace_maps_nan_exactly_where_unreachable(arm):
    g = W.section_grid(arm, "xz", 81)
    m = W.workspace_maps(arm, g.points)
    np.testing.assert_array_equal(np.isfinite(m.manipulability), m.reachable)
    np.testing.assert_array_equal(np.isfinite(m.condition) | np.isinf(m.condition), m.reachable)
    np.testing.assert_array_equal(m.reachable, W.reachable(arm, g.points))
    ok = m.reachable
    np.testing.assert_allclose(arm.fk(m.q[ok]), g.points[ok], atol=1e-9)
    # |det J| = L2 L3 |sin theta3| r <= L2 L3 (L2 + L3)
    assert np.nanmax(m.manipulability) <= 310 * 200 * 510


def test_other_arm_geometry():
    arm = paper_arm().with_(L2=200.0, L3=310.0)  # links swapped: same shell
    assert W.shell_volume(arm) == pytest.approx(4 / 3 * math.pi * (510.0**3 - 110.0**3))


def test_plot_helpers_return_axes_and_keep_rcparams(arm):
    before = dict(mpl.rcParams)
    g = W.section_grid(arm, "xy", 41)
    m = W.workspace_maps(arm, g.points)
    ax = W.plot_section(arm, g, m.manipulability, label="w")
    W.plot_targets([[100, 100, 600], [200, 500, 600]], ["1", "8"], [True, False], ax=ax)
    assert isinstance(ax, mpl.axes.Axes)
    assert dict(mpl.rcParams) == before
    mpl.pyplot.close("all")

"""analysis.studies.quantization: rounding to whole pulses (eqs. 20-22) in mm at the gripper."""

import math

import numpy as np
import pandas as pd
import pytest

from analysis.kinematics.params import data_dir
from analysis.kinematics.pulses import round_half_away
from analysis.studies import quantization as Q
from analysis.studies import workspace as W

H = math.pi / 4000  # half a pulse at 4000 pulses/rev [rad] (0.045 deg)


@pytest.fixture(scope="module")
def table4():
    t = pd.read_csv(data_dir() / "table4.csv", dtype=str)
    return t, t[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()


def test_table4_pulses_match_the_printed_angles(arm, table4):
    t, p = table4
    r = Q.quantization_error(arm, p)
    solved = (t["status"] == "solved").to_numpy()
    np.testing.assert_array_equal(r.ok, solved)
    # c = round(theta_deg / 360 * 4000) from the paper's printed theta1, theta3 (all rows)
    # and theta2 (rows not misprinted: 3, 5, 6, 7, 9, 10)
    for col, j in (("theta1_deg", 0), ("theta3_deg", 2)):
        printed = round_half_away(t.loc[solved, col].astype(float).to_numpy() / 360 * 4000)
        np.testing.assert_array_equal(r.pulses[solved, j], printed)
    good2 = t["row"].isin(["3", "5", "6", "7", "9", "10"]).to_numpy()
    printed2 = round_half_away(t.loc[good2, "theta2_deg"].astype(float).to_numpy() / 360 * 4000)
    np.testing.assert_array_equal(r.pulses[good2, 1], printed2)
    assert r.pulses[0].tolist() == [500, 113, -1724]
    assert np.isnan(r.error_mm[~solved]).all() and (r.pulses[~solved] == 0).all()
    # FK of the commanded angles really is error_mm away from the target
    np.testing.assert_allclose(
        np.linalg.norm(arm.fk(r.q_commanded[solved]) - p[solved], axis=-1), r.error_mm[solved]
    )


def test_error_within_worst_case_and_bounds(arm, rng):
    p = W.sample_shell(arm, 50_000, rng)
    r = Q.quantization_error(arm, p)
    assert r.ok.all()
    wc = Q.worst_case_box(arm, r.q_exact, Q.half_step_rad(arm))
    # rounding residuals are within half a pulse, so the error is within the box maximum
    resid = np.abs(r.q_commanded - r.q_exact)
    assert (resid <= H * (1 + 1e-9)).all()
    assert (r.error_mm <= wc.exact_mm * (1 + 1e-9)).all()
    # first order vs exact: second-order terms are ~h^2 L ~ 3e-4 mm, i.e. < 1e-3 relative
    np.testing.assert_allclose(wc.exact_mm, wc.linear_corner_mm, rtol=1e-3)
    assert (wc.bound_mm >= wc.linear_corner_mm * (1 - 1e-12)).all()
    # closed forms: |J cols| = (r, D, L3) -> bound h (r + D + L3); corner max at full reach
    rho = np.hypot(p[:, 0], p[:, 1])
    D = np.linalg.norm(p - arm.shoulder, axis=-1)
    np.testing.assert_allclose(wc.bound_mm, H * (rho + D + 200.0), rtol=1e-9)
    assert wc.exact_mm.max() <= H * math.hypot(510.0, 710.0) * (1 + 1e-3)


def test_corners_hold_the_box_maximum(arm, rng):
    q = Q.quantization_error(arm, W.sample_shell(arm, 400, rng)).q_exact
    h = Q.half_step_rad(arm)
    grid = Q.box_grid_max(arm, q, h, m=5)
    exact = Q.worst_case_box(arm, q, h).exact_mm
    assert (grid <= exact * (1 + 1e-12)).all()
    with pytest.raises(ValueError, match="NaN"):
        Q.worst_case_box(arm, [[np.nan, 0, 0]], h)


def test_fast_map_equals_reference_pipeline(arm, rng):
    p = W.sample_box(arm, 100_000, rng)
    ref = Q.quantization_error(arm, p)
    err, c, ok = Q.quantization_map(arm, p)
    np.testing.assert_array_equal(ok, ref.ok)
    np.testing.assert_array_equal(c[ok], ref.pulses[ok])
    np.testing.assert_allclose(err[ok], ref.error_mm[ok], rtol=0, atol=1e-9)
    assert np.isnan(err[~ok]).all()


def test_error_statistics(arm):
    s = Q.error_stats([0.1, 0.2, np.nan, 0.3], [True, True, False, True])
    assert (s.n, s.max_mm, s.mean_mm) == (3, 0.3, pytest.approx(0.2))
    assert s.rms_mm == pytest.approx(math.sqrt((0.01 + 0.04 + 0.09) / 3))
    with pytest.raises(ValueError, match="no target"):
        Q.error_stats([np.nan], [False])
    with pytest.raises(ValueError, match="pulses_per_rev"):
        Q.quantization_error(arm, [100, 100, 600], pulses_per_rev=-5)


def test_scaling_with_pulses_and_lengths(arm, rng):
    p = W.sample_shell(arm, 40_000, rng)
    by = Q.stats_by_ppr(arm, p, [200, 4000, 25600])
    # error ~ half step ~ 1/ppr: ratios 20 and 128 within the noise of rounding residuals
    assert by[200].mean_mm / by[4000].mean_mm == pytest.approx(20, rel=0.05)
    assert by[200].mean_mm / by[25600].mean_mm == pytest.approx(128, rel=0.05)
    ls = Q.stats_by_length_scale(arm, [0.5, 1.0, 2.0], n=40_000, seed=3)
    assert ls[2.0].mean_mm / ls[1.0].mean_mm == pytest.approx(2.0, rel=0.05)
    assert ls[0.5].mean_mm / ls[1.0].mean_mm == pytest.approx(0.5, rel=0.05)


def test_joint_shares(arm, rng):
    sh = Q.joint_shares(arm, W.sample_shell(arm, 40_000, rng))
    assert sh["variance_share"].sum() == pytest.approx(1.0)
    # first order: E|e|^2 = sum_j E|J_j|^2 h^2 / 3, so shares of E(alone_j^2) match
    assert (sh["alone_max_mm"] <= H * np.array([510.0, 510.0, 200.0]) * (1 + 1e-3)).all()
    assert np.argmax(sh["variance_share"]) == 1  # the shoulder: lever arm D >= r, L3


def test_float32_pipeline(arm, rng, table4):
    _, p4 = table4
    c32, t32 = Q.pulses_float32(arm, p4)
    assert t32.dtype == np.float32 and c32.dtype == np.int64
    r4 = Q.quantization_error(arm, p4)
    np.testing.assert_array_equal(c32[r4.ok], r4.pulses[r4.ok])  # all ten targets agree
    p = W.sample_shell(arm, 200_000, rng)
    r = Q.quantization_error(arm, p)
    c32, t32 = Q.pulses_float32(arm, p)
    # float32 angles carry ~1e-7 relative error; near the stretched elbow acos amplifies it
    far = np.abs(np.linalg.norm(p - arm.shoulder, axis=-1) - 510.0) > 1.0
    assert np.abs(t32[far] - r.q_exact[far]).max() < 1e-4
    diff = np.abs(c32 - r.pulses)
    assert diff.max() <= 1
    assert 0 < (diff > 0).any(-1).mean() < 0.01

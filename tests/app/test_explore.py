"""Tests for analysis.app.explore: pose_report against independent references, and the widget
explorer driven programmatically (headless: no kernel, no frontend, MPLBACKEND=Agg).

References: the paper's Table 4 (data/table4.csv), the D-H chain (DHTable.fk, not Arm.fk),
the library's own exceptions (their messages must reach the user verbatim), a Jacobian
determinant taken numerically with np.linalg.det, and eqs. 20-22 written out with math.
"""

import base64
import doctest
import math

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest

import analysis.app.explore
from analysis.app.explore import PoseReport, build_explorer, pose_report
from analysis.kinematics.arm import BRANCHES, BaseAxisError, UnreachableError
from analysis.kinematics.params import data_dir
from analysis.studies.quantization import quantization_error

# Table 4 prints angles to 2 decimals: half a unit in the last place, plus float slack.
PRINT_TOL_DEG = 0.005 + 1e-9
# Closed form vs the D-H matrix chain: both float64 over |p| ~ 1e3 mm -> ~1e-12 mm.
FK_TOL_MM = 1e-9


@pytest.fixture(scope="module")
def table4():
    return pd.read_csv(data_dir() / "table4.csv", dtype=str).set_index("row")


def _target(table4, row):
    return [float(table4.loc[row, k]) for k in ("x_mm", "y_mm", "z_mm")]


def _pulses(theta_deg, ppr=4000):
    """Eqs. 20-22 written out: c = theta/360 * ppr, halves rounded away from zero."""
    x = theta_deg / 360.0 * ppr
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


# --- pose_report -------------------------------------------------------------------------
def test_row1_front_up_matches_table4_and_pulses(arm, table4):
    rep = pose_report(arm, _target(table4, "1"))
    assert rep.reachable and rep.error is None and rep.branch == "front-up"
    row = rep.row()
    # theta1 and theta3 as printed; theta2 printed 190.20 is the paper's erratum (+180 deg),
    # the corrected value is 10.21 (docs/errata); check both the print and the correction.
    assert abs(row["theta1_deg"] - float(table4.loc["1", "theta1_deg"])) <= PRINT_TOL_DEG
    assert abs(row["theta3_deg"] - float(table4.loc["1", "theta3_deg"])) <= PRINT_TOL_DEG
    assert abs(row["theta2_deg"] - 10.21) <= PRINT_TOL_DEG
    assert abs((row["theta2_deg"] + 180.0) - float(table4.loc["1", "theta2_deg"])) < 0.01 + 1e-9
    assert [int(row[c]) for c in ("c1", "c2", "c3")] == [500, 113, -1724]
    assert [int(row[c]) for c in ("c1", "c2", "c3")] == [
        _pulses(row[f"theta{j}_deg"]) for j in (1, 2, 3)
    ]
    assert "pulses (500, 113, -1724)" in rep.message


@pytest.mark.parametrize("row", ["1", "2", "5", "7", "10"])
def test_all_branches_against_dh_chain_and_solve(arm, table4, row):
    p = np.array(_target(table4, row))
    rep = pose_report(arm, p)
    assert list(rep.table.index) == list(BRANCHES)
    assert not rep.table.isna().any().any()
    sol = arm.solve(p)
    q = np.radians(rep.table[["theta1_deg", "theta2_deg", "theta3_deg"]].to_numpy())
    np.testing.assert_allclose(q, sol.theta, rtol=0, atol=1e-12)
    # every branch reaches the target through the D-H matrices (independent of Arm.fk)
    tip = arm.params.dh_table().fk(q)[..., :3, 3]
    np.testing.assert_allclose(tip, np.broadcast_to(p, tip.shape), rtol=0, atol=FK_TOL_MM)
    # back branches are the front poses re-coordinated (waist + 180 deg, shoulder flipped):
    # same elbow point, different joints
    elbows = arm.elbow(q)
    np.testing.assert_allclose(elbows[2:], elbows[:2], rtol=0, atol=FK_TOL_MM)
    for b in BRANCHES:
        qe = quantization_error(arm, p, branch=b)
        got = rep.table.loc[b]
        assert [int(got[c]) for c in ("c1", "c2", "c3")] == qe.pulses.tolist()
        assert got["error_mm"] == pytest.approx(float(qe.error_mm), rel=0, abs=1e-12)
        # manipulability = |det J| with J taken from the Jacobian numerically
        detj = abs(np.linalg.det(arm.jacobian(np.radians(got.iloc[:3].to_numpy(float)))))
        assert got["w_mm3"] == pytest.approx(detj, rel=1e-9)
    # whole pulses move each joint by at most half a step h = pi/4000 rad, so the error is
    # at most sum_j |J_j| h plus a second-order term ~ h^2 (L2 + L3) ~ 3e-4 mm (slack 1e-3)
    h = np.pi / np.asarray(arm.params.pulses_per_rev, dtype=float)
    bound = np.linalg.norm(arm.jacobian(q), axis=-2) @ h
    assert (rep.table["error_mm"].to_numpy() <= bound + 1e-3).all()
    assert (rep.table["error_mm"] > 0).all()  # Table 4 targets are not on the pulse grid


def test_row8_unreachable_uses_library_message(arm, table4):
    p = _target(table4, "8")
    assert table4.loc["8", "status"] == "无解"
    rep = pose_report(arm, p)
    expected = math.dist(p, (0.0, 0.0, arm.params.L1)) - (arm.params.L2 + arm.params.L3)
    assert rep.outside_mm == pytest.approx(expected, abs=1e-9)
    assert round(rep.outside_mm, 3) == 31.849
    assert not rep.reachable and rep.error == "UnreachableError"
    with pytest.raises(UnreachableError) as exc:
        arm.ik(p)
    assert rep.message == str(exc.value) and "31.849 mm beyond" in rep.message
    assert rep.table.empty and rep.to_html() == ""
    with pytest.raises(KeyError):
        rep.row()


def test_inside_inner_reach(arm):
    rep = pose_report(arm, [0.0, 50.0, 660.0])
    assert not rep.reachable and rep.error == "UnreachableError"
    assert rep.outside_mm == pytest.approx(arm.params.reach_inner - 50.0, abs=1e-12)
    assert "inside the inner reach" in rep.message and rep.table.empty


def test_base_axis(arm):
    p = [0.0, 0.0, 800.0]
    rep = pose_report(arm, p, "back-down")
    with pytest.raises(BaseAxisError) as exc:
        arm.ik(p)
    assert rep.error == "BaseAxisError" and rep.message == str(exc.value)
    assert not rep.reachable and rep.table.empty
    assert rep.outside_mm < 0  # inside the shell: only theta1 is undefined
    rep = pose_report(arm, p, theta1_on_axis=0.3)
    assert rep.reachable and not rep.table.isna().any().any()
    np.testing.assert_allclose(rep.table["theta1_deg"].iloc[:2], np.degrees(0.3), atol=1e-12)
    np.testing.assert_allclose(rep.table["w_mm3"], 0.0, atol=1e-6)  # singular on the axis


def test_bad_input(arm):
    with pytest.raises(ValueError, match="unknown branch 'sideways'"):
        pose_report(arm, [100, 100, 600], "sideways")
    with pytest.raises(ValueError, match=r"got \(2, 3\)"):
        pose_report(arm, [[100, 100, 600]] * 2)
    with pytest.raises(ValueError, match="non-finite"):
        pose_report(arm, [100, np.nan, 600])


def test_html_marks_chosen_branch_and_has_no_nan(arm):
    html = pose_report(arm, [200, 200, 600], "back-up").to_html()
    assert "&#9654; back-up" in html and "&#9654; front-up" not in html
    assert "nan" not in html.lower()


def test_docstring_examples():
    result = doctest.testmod(analysis.app.explore)
    assert result.attempted >= 3 and result.failed == 0


# --- the widget explorer -----------------------------------------------------------------
def _png(ex):
    (out,) = ex.plot.outputs
    return base64.b64decode(out["data"]["image/png"])


def test_explorer_builds_at_row1(arm):
    n_figs = len(plt.get_fignums())
    ex = build_explorer(arm)
    assert len(plt.get_fignums()) == n_figs  # draws off pyplot: nothing leaks
    R, L1 = arm.params.reach_outer, arm.params.L1
    assert (ex.x.min, ex.x.max, ex.y.min, ex.y.max) == (-R, R, -R, R)
    assert (ex.z.min, ex.z.max) == (L1 - R, L1 + R)
    assert ex.branch.value == "front-up" and ex.fk_mode.value is False
    assert isinstance(ex.report, PoseReport)
    assert "pulses (500, 113, -1724)" in ex.message.value
    for s in ("45.00", "10.21", "-155.13", "&#9654; front-up"):
        assert s in ex.table.value
    assert _png(ex).startswith(b"\x89PNG\r\n\x1a\n")
    assert ex.joint_box.layout.display == "none"


def test_explorer_sliders_update_message_table_plot(arm):
    ex = build_explorer(arm)
    ex.x.value, ex.y.value = 200.0, 500.0  # Table 4 row 8
    assert "31.849 mm beyond the reach" in ex.message.value
    assert ex.table.value == "" and ex.plot.outputs == ()
    assert "nan" not in ex.message.value.lower()
    ex.x.value, ex.y.value, ex.z.value = 0.0, 0.0, 800.0
    assert "base axis" in ex.message.value and "FK mode" in ex.message.value
    assert ex.table.value == "" and ex.plot.outputs == ()
    ex.x.value, ex.y.value, ex.z.value = 300.0, 300.0, 600.0  # row 10
    assert ex.report.row()["c1"] == 500 and len(ex.plot.outputs) == 1
    ex.branch.value = "back-down"
    assert ex.message.value.count("back-down:") == 1 and "&#9654; back-down" in ex.table.value
    want = pose_report(arm, [300, 300, 600], "back-down").to_html()
    assert ex.table.value == want


def test_explorer_fk_mode(arm):
    ex = build_explorer(arm)
    ex.fk_mode.value = True
    assert ex.joint_box.layout.display is None and ex.xyz_box.layout.display == "none"
    assert (ex.t1.value, ex.t2.value, ex.t3.value) == (45.0, 10.21, -155.13)
    ex.t1.value, ex.t2.value, ex.t3.value = 30.0, 20.0, -60.0
    p = arm.params.dh_table().fk(np.radians([30.0, 20.0, -60.0]))[:3, 3]
    assert "FK: gripper at (" + ", ".join(f"{v:.2f}" for v in p) + ") mm" in ex.message.value
    np.testing.assert_allclose(ex.report.target, p, atol=FK_TOL_MM)
    np.testing.assert_allclose(
        ex.report.row().iloc[:3].to_numpy(float), [30.0, 20.0, -60.0], atol=1e-9
    )
    # straight up the base axis: theta1 comes from the slider, never a NaN or an error
    ex.t2.value, ex.t3.value = 90.0, 0.0
    assert ex.report.reachable and "nan" not in ex.table.value.lower()
    assert ex.report.row()["theta1_deg"] == pytest.approx(30.0, abs=1e-9)
    ex.t2.value, ex.t3.value = 20.0, -60.0
    ex.fk_mode.value = False  # back to IK: the xyz sliders take the FK point (whole mm)
    assert [ex.x.value, ex.y.value, ex.z.value] == [float(round(v)) for v in p]
    assert ex.xyz_box.layout.display is None and "FK" not in ex.message.value

"""Tests for analysis.app.explore: pose_report against independent references, and the widget
explorer driven programmatically (headless: no kernel, no frontend, MPLBACKEND=Agg).

References: the paper's Table 4 (data/table4.csv), the D-H chain (DHTable.fk, not Arm.fk),
the library's own exceptions (their messages must reach the user verbatim), a Jacobian
determinant taken numerically with np.linalg.det, and eqs. 20-22 written out with math.
"""

import doctest
import json
import math

import numpy as np
import pandas as pd
import pytest

import analysis.app.explore
import analysis.app.explore_logic
from analysis.app.arm3d import PLOTLY_MIME
from analysis.app.arm3d_frames import frame_transforms
from analysis.app.explore import (
    PoseReport,
    available_arms,
    build_explorer,
    default_target,
    num,
    plain_message,
    pose_report,
    target_from_joints,
)
from analysis.app.explore_logic import FK_CAPTION, IK_CAPTION
from analysis.kinematics.arm import BRANCHES, BaseAxisError, UnreachableError, load_arm
from analysis.kinematics.params import data_dir
from analysis.kinematics.status import STATUS_TEXT, Status
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
    tip = arm.dh_table().fk(q)[..., :3, 3]
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
    assert rep.status == Status.OUT_OF_REACH and rep.status_text == "out-of-reach"
    with pytest.raises(UnreachableError) as exc:
        arm.ik(p)
    assert rep.message == str(exc.value) and "31.849 mm beyond" in rep.message
    assert rep.table.empty
    # the explorer keeps its table's place: every branch, no number, the target's status
    html = rep.to_html("every branch for this target")
    assert html.count("<tr") == 1 + len(arm.branches) and html.count(">out-of-reach<") == 4
    assert ">every branch for this target</caption>" in html and "nan" not in html.lower()
    with pytest.raises(KeyError):
        rep.row()


def test_row8_explained_with_the_nearest_reachable_target(arm, table4):
    """The explorer's sentence (analysis.app.explain): the distance beyond the reach and the
    reachable target nearest row 8 on the line from the shoulder, which is on the shell."""
    from analysis.app.explain import explain

    p = _target(table4, "8")
    rep = pose_report(arm, p)
    e = explain(arm, p, rep.status, rep.outside_mm, "front-up")
    assert e.word == "out-of-reach" and "is 31.849 mm beyond the reach" in e.sentence
    assert plain_message(rep) == str(e)
    n = np.asarray(e.nearest)
    shoulder = np.array([0.0, 0.0, arm.params.L1])
    reach = arm.params.L2 + arm.params.L3
    assert np.linalg.norm(n - shoulder) == pytest.approx(reach, abs=1e-6)
    direction = (np.asarray(p) - shoulder) / np.linalg.norm(np.asarray(p) - shoulder)
    np.testing.assert_allclose(n, shoulder + reach * direction, atol=1e-6)
    assert arm.solve(n, ("front-up",)).ok[0]
    assert e.sentence.endswith(f": ({n[0]:.3f}, {n[1]:.3f}, {n[2]:.3f}) mm")


def test_inside_inner_reach(arm):
    rep = pose_report(arm, [0.0, 50.0, 660.0])
    assert not rep.reachable and rep.error == "UnreachableError"
    assert rep.outside_mm == pytest.approx(arm.geometry["reach_inner"] - 50.0, abs=1e-12)
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


def test_html_has_units_no_wrapping_and_scaled_manipulability(arm):
    rep = pose_report(arm, [100, 100, 600])
    html = rep.to_html()
    assert "white-space:nowrap" in html
    for head in ("θ1 [°]", "c3 [pulses]", "pulse error [mm]", "w [10⁶ mm³/rad³]", "status"):
        assert f">{head}</th>" in html
    assert "w_mm3" not in html and "e+06" not in html  # no raw ids, no 3.688e+06
    w = rep.table.loc["front-up", "w_mm3"] / 1e6
    assert f">{w:.3f}<" in html and ">ok<" in html
    assert html.count("<tr") == 1 + len(BRANCHES)


def test_num_never_prints_negative_zero():
    assert num(-0.0, 1) == "0.0" and num(-0.04, 1) == "0.0" and num(-1e-12, 3) == "0.000"
    assert num(-0.05, 1) == "-0.1" and num(12.3456, 2) == "12.35"


def test_plain_message_names_no_python_argument_or_flag(arm):
    for target in ([0, 0, 800], [200, 500, 600], [100, 100, 600], [0, 50, 660]):
        rep = pose_report(arm, target)
        text = plain_message(rep)
        assert text.startswith(STATUS_TEXT[rep.status] + " — ")
        assert "theta1_on_axis" not in text and "--" not in text and "-0.0" not in text
    assert "tick “allow θ1 on the base axis”" in plain_message(pose_report(arm, [0, 0, 800]))


def test_palletizer_generic(table4):
    """Another arm through the same code: 4 joints, 2 branches, inputs px, py, pz."""
    pal = load_arm("palletizer")
    p = default_target(pal)
    rep = pose_report(pal, p)
    assert rep.reachable and list(rep.table.index) == list(pal.branches)
    assert rep.branch == pal.branches[0]
    ok = (rep.table["status"] == "ok").to_numpy()
    assert ok[0] and set(rep.table["status"]) <= {"ok", "joint-limits"}  # words, not codes
    t = rep.table[ok]
    q = np.radians(t[[f"theta{j}_deg" for j in range(1, 5)]].to_numpy(float))
    np.testing.assert_allclose(pal.fk(q), np.broadcast_to(p, q[:, :3].shape), atol=FK_TOL_MM)
    # manipulability sqrt(det(J J^T)) of the 3x4 Jacobian, from its singular values
    s = np.linalg.svd(pal.jacobian(q), compute_uv=False)
    np.testing.assert_allclose(t["w_mm3"], s.prod(axis=-1), rtol=1e-9)
    assert "nan" not in rep.to_html().lower()
    far = pose_report(pal, [2000.0, 0.0, 0.0])
    assert far.status_text == "out-of-reach" and far.table.empty


def test_available_arms_lists_what_loads():
    ok, skipped = available_arms()
    assert {"grabber", "palletizer"} <= set(ok)
    assert ok["grabber"] == load_arm("grabber").description.title
    assert not set(ok) & set(skipped)
    for name, why in skipped.items():
        with pytest.raises(ValueError):
            load_arm(name)
        assert why


def test_docstring_examples():
    result = doctest.testmod(analysis.app.explore_logic)
    assert result.attempted >= 3 and result.failed == 0


# --- the widget explorer -----------------------------------------------------------------
def _tip(ex):
    """The arm trace's last point in the 3D view (the gripper), or None (no arm drawn)."""
    arms = [t for t in ex.figure.data if t.name == "arm" and t.x]
    return None if not arms else [arms[0].x[-1], arms[0].y[-1], arms[0].z[-1]]


def test_explorer_builds_at_row1(arm):
    ex = build_explorer(arm, [100, 100, 600])
    x, _, z = ex.target_sliders
    assert x.min <= -arm.geometry["reach_outer"] and x.max >= arm.geometry["reach_outer"]
    assert z.min <= arm.params.L1 - arm.geometry["reach_outer"]
    assert z.max >= arm.params.L1 + arm.geometry["reach_outer"]
    assert x.step <= 0.1 and x.layout.width == "640px"  # 1200 mm over 640 px, 0.1 mm steps
    assert [s.description for s in ex.joint_sliders] == ["θ1 [°]", "θ2 [°]", "θ3 [°]"]
    assert ex.joint_sliders[0].style.description_width == "120px"  # labels not cut
    assert ex.branch.value == "front-up" and ex.fk_mode.value is False
    assert isinstance(ex.report, PoseReport)
    assert "pulses (500, 113, -1724)" in ex.message.value
    for s in ("45.00", "10.21", "-155.13", "&#9654; front-up"):
        assert s in ex.table.value
    assert _tip(ex) == pytest.approx([100, 100, 600], abs=1e-3)
    assert ex.joint_box.layout.display == "none"
    assert ex.arm_picker.value == "grabber"
    assert {"grabber", "palletizer"} <= {v for _, v in ex.arm_picker.options}


def test_explorer_bundle_is_deterministic_and_meaningful(arm):
    a, b = build_explorer(arm, [100, 100, 600]), build_explorer(arm, [100, 100, 600])
    assert a.bundle == b.bundle  # no random div id: nbval can compare the stored output
    spec = a.bundle[PLOTLY_MIME]
    assert json.loads(json.dumps(spec)) == spec  # plain JSON
    assert spec["layout"]["uirevision"] == "grabber"  # redraws keep the user's camera
    assert 'class="plotly-graph-div"' in a.bundle["text/html"]
    assert "<script src" not in a.bundle["text/html"]  # plotly.js is never fetched
    assert "45.00, 10.21, -155.13" in a.bundle["text/plain"]


def test_explorer_sliders_update_message_table_plot(arm):
    ex = build_explorer(arm, [100, 100, 600])
    x, y, z = ex.target_sliders
    x.value, y.value = 200.0, 500.0  # Table 4 row 8
    assert "31.849 mm beyond the reach" in ex.message.value
    assert "out-of-reach" in ex.message.value
    assert "nearest reachable on the line" in ex.message.value
    # no layout shift: the table keeps its rows, without numbers
    assert ex.table.value.count(">out-of-reach<") == len(arm.branches) and _tip(ex) is None
    assert "nan" not in ex.message.value.lower()
    x.value, y.value, z.value = 0.0, 0.0, 800.0
    assert "base axis" in ex.message.value and "allow θ1 on the base axis" in ex.message.value
    assert "theta1_on_axis" not in ex.message.value and "--" not in ex.message.value
    assert ex.table.value.count(">base-axis<") == len(arm.branches) and _tip(ex) is None
    ex.on_axis.value = True  # the check box supplies theta1 from its slider
    assert ex.on_axis_deg.layout.display is None
    ex.on_axis_deg.value = 30.0
    assert ex.report.reachable and ex.report.row()["theta1_deg"] == pytest.approx(30.0)
    assert _tip(ex) == pytest.approx([0, 0, 800], abs=1e-3)
    ex.on_axis.value = False
    x.value, y.value, z.value = 300.0, 300.0, 600.0  # row 10
    assert ex.report.row()["c1"] == 500 and _tip(ex) == pytest.approx([300, 300, 600], abs=1e-3)
    ex.branch.value = "back-down"
    assert ex.message.value.count("back-down:") == 1 and "&#9654; back-down" in ex.table.value
    assert ex.table.value == pose_report(arm, [300, 300, 600], "back-down").to_html(IK_CAPTION)


def test_explorer_fk_mode(arm):
    ex = build_explorer(arm, [100, 100, 600])
    ex.fk_mode.value = True
    assert ex.joint_box.layout.display is None and ex.target_box.layout.display == "none"
    t1, t2, t3 = ex.joint_sliders
    assert (t1.value, t2.value, t3.value) == (45.0, 10.21, -155.13)
    t1.value, t2.value, t3.value = 30.0, 20.0, -60.0
    p = arm.dh_table().fk(np.radians([30.0, 20.0, -60.0]))[:3, 3]
    assert "tool at (" + ", ".join(f"{v:.2f}" for v in p) + ") mm" in ex.message.value
    assert "FK: joints (30.00°, 20.00°, -60.00°) → pulses (333, 222, -667)" in ex.message.value
    assert ex.message.value.endswith("branch: front-up</div>")
    assert f">{FK_CAPTION}</caption>" in ex.table.value
    np.testing.assert_allclose(ex.report.target, p, atol=FK_TOL_MM)
    np.testing.assert_allclose(ex.report.angles_deg(), [30.0, 20.0, -60.0], atol=1e-9)
    # straight up the base axis: theta1 comes from the slider, never a NaN or an error
    t2.value, t3.value = 90.0, 0.0
    assert ex.report.reachable and "nan" not in ex.table.value.lower()
    assert ex.report.row()["theta1_deg"] == pytest.approx(30.0, abs=1e-9)
    # the stretched arm: on the reach shell, never "-0.00"
    t1.value, t2.value, t3.value = 0.0, 0.0, 0.0
    assert "tool at (510.00, 0.00, 660.00) mm" in ex.message.value
    assert "-0.0" not in ex.message.value and "-0.00" not in ex.table.value
    t1.value, t2.value, t3.value = 30.0, 20.0, -60.0
    ex.fk_mode.value = False  # back to IK: the target sliders take the FK point
    np.testing.assert_allclose([s.value for s in ex.target_sliders], p, atol=1e-9)
    assert ex.target_box.layout.display is None and "FK" not in ex.message.value


def test_explorer_switches_arms(arm):
    ex = build_explorer(arm, [100, 100, 600])
    ex.arm_picker.value = "palletizer"
    pal = load_arm("palletizer")
    assert ex.arm.name == "palletizer" and tuple(ex.branch.options) == pal.branches
    assert len(ex.joint_sliders) == pal.n_joints == 4
    assert ex.report.reachable and ex.report.branch == pal.branches[0]
    np.testing.assert_allclose(ex.report.target, default_target(pal))
    assert ex.figure.layout.uirevision == "palletizer"
    ex.fk_mode.value = True
    assert [s.description for s in ex.joint_sliders] == [f"θ{j} [°]" for j in range(1, 5)]
    ex.arm_picker.value = "grabber"
    assert len(ex.joint_sliders) == 3 and ex.branch.value == "front-up"


def test_explorer_display_is_one_widget_with_the_3d_view_inside(arm):
    """One widget output (the 3D view is its last child, a widget that redraws itself), a
    plain-text line for readers without a kernel, and a pose sent to the view at every change
    for the controls' values it was computed for."""
    from analysis.app.arm3d import Arm3DWidget

    ex = build_explorer(arm, [100, 100, 600])
    data = ex._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in data
    assert data["text/plain"].startswith("Explorer of the 3R material-grabbing robot")
    assert isinstance(ex.children[-1], Arm3DWidget) and ex.children[-1] is ex.view
    ids = ex.view.controls
    assert ids["inputs"] == [f"IPY_MODEL_{s.model_id}" for s in ex.target_sliders]
    assert ids["branch"] == f"IPY_MODEL_{ex.branch.model_id}" and ids["units"] == ["mm"] * 3
    assert "arm.solve = function" in ex.view.kinematics  # printed, for the browser
    names = [t["name"] for t in ex.view.figure["data"]]
    assert names[:3] == ["base axis", "arm", "target"]
    assert [n.split()[0] for n in names[3:]] == ["joint", "link", "tool"]  # arm3d_frames
    ex.target_sliders[0].value = 150.0
    pose = ex.view.pose
    assert pose["key"] == ex.pose_key() and pose["key"][2] == 150.0
    q = np.radians(ex.report.angles_deg())
    np.testing.assert_allclose(pose["frames"], arm.frames(q), atol=1e-6)
    # the frames the view draws its joint axes, link frames and tool frame from (3x4 blocks)
    np.testing.assert_allclose(pose["transforms"], frame_transforms(arm, q)[:, :3], atol=1e-6)
    assert pose["target"] == [150.0, 100.0, 600.0] and "front-up" in pose["title"]
    assert _tip(ex)[0] == pytest.approx(150.0)
    ex.target_sliders[1].value = 500.0  # out of reach: no arm, the target still drawn
    assert ex.view.pose["frames"] is None and "no solution" in ex.view.pose["title"]
    assert ex.view.pose["transforms"] is None


def test_the_3d_view_sends_plotly_js_on_request_and_never_stores_it(arm):
    from analysis.app.arm3d import PLOTLY_JS

    ex = build_explorer(arm, [100, 100, 600])
    sent = []
    ex.view.send = lambda content, buffers=None: sent.append((content, buffers))
    ex.view._on_message(ex.view, {"type": "plotly?"}, [])
    ((content, buffers),) = sent
    assert content == {"type": "plotly"} and buffers[0] == PLOTLY_JS.read_bytes()
    ex.view._on_message(ex.view, {"type": "other"}, [])
    assert len(sent) == 1
    state = json.dumps(ex.view.get_state())
    assert len(state) < 100_000 and "Plotly, Inc." not in state  # a small widget state


def test_explorer_takes_a_pose_arm():
    """The GR-1 (5 joints, a pose of 6 inputs: point and RPY angles) through the same code."""
    gr1 = load_arm("gr1")
    p = default_target(gr1)
    rep = pose_report(gr1, p)
    assert rep.reachable and rep.status_text == "ok"
    q = np.radians(rep.angles_deg())
    np.testing.assert_allclose(target_from_joints(gr1, q), p, atol=1e-6)
    ex = build_explorer("gr1")
    assert [s.description for s in ex.target_sliders][3:] == ["α [°]", "β [°]", "γ [°]"]
    assert len(ex.joint_sliders) == 5 and ex.report.reachable
    ex.fk_mode.value = True  # FK gives the whole pose: the table is still there
    assert ex.report is not None and ex.report.reachable and ex.table.value
    ex.joint_sliders[3].value = 20.0
    np.testing.assert_allclose(ex.report.angles_deg()[3], 20.0, atol=1e-6)
    ex.fk_mode.value = False
    assert ex.report.reachable
    ex.target_sliders[3].value = 40.0  # an orientation out of the arm plane
    assert ex.report.status_text == "orientation"
    assert ex.table.value.count(">orientation<") == len(gr1.branches)


@pytest.mark.parametrize(
    ("name", "q_deg"), [("gr1", [30.0, 40.0, -60.0, -70.0, 10.0]), ("picker", None)]
)
def test_fk_line_shows_the_full_pose_of_fk_json(name, q_deg, capsys):
    """Issue 31 item 3: the explorer's FK line is ``fk --json``'s pose (the tool point, its
    RPY angles, a closed chain's passive joints) to the two decimals it shows."""
    from analysis.app.cli import main
    from analysis.app.explore_logic import fk_line, num

    a = load_arm(name)
    if q_deg is None:  # the picker: a configuration of its first branch
        sol = a.solve(default_target(a), a.branches[:1])
        q_deg = a.joints_to_user(sol.theta[0, 0]).round(6).tolist()
    assert main(["fk", *map(str, q_deg), "--arm", name, "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    line = fk_line(a, a.joints_from_user(q_deg), None)
    pose = (f"tool at ({', '.join(num(v, 2) for v in doc['position_mm'])}) mm, "
            f"RPY ({', '.join(num(v, 2) for v in doc['rpy_deg'])})°")  # fmt: skip
    assert pose in line, (pose, line)
    for k, v in doc["joint_states"].items():
        if k not in doc["joint_names"]:
            assert f"θ{k[5:]} = {num(v, 2)}°" in line, (k, line)
    assert ("passive joints" in line) == (name == "picker")

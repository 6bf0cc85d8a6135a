"""Tests for analysis.app.arm3d: the plotly figure of an arm and its MIME bundle."""

import json

import numpy as np
import pytest

from analysis.app.arm3d import PLOTLY_MIME, arm_figure, figure_bundle, workspace_box
from analysis.kinematics.arm import load_arm


@pytest.mark.parametrize("name", ["grabber", "palletizer"])
def test_workspace_box_holds_sampled_poses(name):
    arm = load_arm(name)
    box = workspace_box(arm)
    assert workspace_box(arm) == box  # seeded
    lim = np.array([v if v is not None else (-np.pi, np.pi) for v in arm.limits])
    q = np.random.default_rng(1).uniform(lim[:, 0], lim[:, 1], (2000, arm.n_joints))
    pts = arm.frames(q).reshape(-1, 3)
    assert (pts >= np.array(box.lo) - 1e-9).all() and (pts <= np.array(box.hi) + 1e-9).all()
    assert box.lo[0] == -box.hi[0] and box.lo[1] == -box.hi[1]


def test_workspace_box_rejects_bad_arguments(arm):
    with pytest.raises(ValueError, match="samples = 1"):
        workspace_box(arm, samples=1)
    with pytest.raises(ValueError, match="pad = 2"):
        workspace_box(arm, pad=2)
    with pytest.raises(ValueError, match="grid_mm = 0"):
        workspace_box(arm, grid_mm=0)


def test_arm_figure_links_through_frames_and_equal_scales(arm):
    q = np.radians([45.0, 10.2087, -155.1291])
    fig = arm_figure(arm, q, [100, 100, 600], title="row 1")
    names = [t.name for t in fig.data]
    assert names[:3] == ["base axis", "arm", "target"]  # then the frames (test_arm3d_frames)
    assert [n.split()[0] for n in names[3:]] == ["joint", "link", "tool"]
    pts = np.column_stack([fig.data[1].x, fig.data[1].y, fig.data[1].z])
    np.testing.assert_allclose(pts, arm.frames(q), atol=1e-3)  # rounded to 1 um
    scene = fig.layout.scene
    spans = [scene[f"{k}axis"].range[1] - scene[f"{k}axis"].range[0] for k in "xyz"]
    ratios = [scene.aspectratio[k] for k in "xyz"]
    np.testing.assert_allclose(np.divide(ratios, spans), ratios[0] / spans[0], rtol=1e-3)
    assert arm_figure(arm, None, [200, 500, 600]).data[-1].name == "target"
    assert "arm" not in [t.name for t in arm_figure(arm, None).data]


def test_bundle_is_plain_json_with_stable_div_id(arm):
    fig = arm_figure(arm, np.zeros(3))
    a, b = figure_bundle(fig, "k", "text"), figure_bundle(fig, "k", "text")
    assert a == b and a["text/plain"] == "text"
    assert json.loads(json.dumps(a[PLOTLY_MIME])) == a[PLOTLY_MIME]
    assert "bdata" not in json.dumps(a[PLOTLY_MIME])  # readable numbers, not base64 arrays
    other = figure_bundle(arm_figure(arm, np.ones(3)), "k", "text")
    assert other["text/html"] != a["text/html"]
    assert a["text/html"].count("Plotly.newPlot") == 1 and "cdn" not in a["text/html"].lower()


def test_trajectory_figure_plays_the_gr1_cubic_through_forward_kinematics():
    """Issue 31 item 3: a trajectory (seed 004's cubic between the thesis's start and end
    joints, Table 5-4) played with a time slider: each animation frame's arm ends at the
    tool point that the D-H table's FK (apart from the explorer's) gives at its time."""
    from analysis.app.arm3d import trajectory_figure
    from analysis.audit.papers.gr1.thesis import printed_joints
    from analysis.kinematics.arm import load_arm
    from analysis.studies.trajectories import cubic_trajectory

    arm = load_arm("gr1")
    q0, qf = printed_joints()
    t = np.linspace(0.0, 2.0, 201)
    q = cubic_trajectory(q0, qf, 2.0, t)[0]
    fig = trajectory_figure(arm, t, q, frames=21)
    steps = fig.layout.sliders[0].steps
    assert len(fig.frames) == len(steps) == 21
    assert [s.label for s in steps] == [f.name for f in fig.frames] == [f"{v:.2f}" for v in t[::10]]
    dh = arm.dh_table()
    for f, k in zip(fig.frames, range(0, 201, 10), strict=True):
        tr = f.data[list(f.traces).index(1)]  # the arm (the frames: test_arm3d_frames)
        tip = dh.fk(q[k])[:3, 3]
        np.testing.assert_allclose([tr.x[-1], tr.y[-1], tr.z[-1]], tip, atol=2e-3)
    path = next(tr for tr in fig.data if tr.name == "tool path")
    assert len(path.x) == len(t)
    with pytest.raises(ValueError, match="expected \\(201, 5\\)"):
        trajectory_figure(arm, t, q[:, :4])


def test_trajectory_notes_follow_the_frames():
    """One line per sample, shown under the title at each animation frame, escaped."""
    from analysis.app.arm3d import trajectory_figure

    arm = load_arm("grabber")
    notes = [f"Busy <{k}>" for k in range(5)]
    fig = trajectory_figure(arm, np.arange(5.0), np.zeros((5, 3)), frames=3, notes=notes)
    assert [f.layout.annotations[0].text for f in fig.frames] == [
        "Busy &lt;0&gt;", "Busy &lt;2&gt;", "Busy &lt;4&gt;"
    ]  # fmt: skip
    assert fig.layout.annotations[0].text == "Busy &lt;0&gt;"
    with pytest.raises(ValueError, match="notes: 2 lines; expected one per sample \\(5\\)"):
        trajectory_figure(arm, np.arange(5.0), np.zeros((5, 3)), notes=notes[:2])

"""Joint axes, link frames and the tool frame drawn in the 3D views (analysis.app.arm3d_frames,
issue 31 item 3), held to the arm's forward kinematics computed apart from the drawing:

* every frame equals the D-H table's own product of link matrices truncated at that row
  (``DHTable.fk``: ``link_transform`` and ``@``, not the chain the drawing evaluates), the
  origins equal :meth:`Arm.frames`, and the tool frame equals ``fk --json``'s pose
  (:func:`analysis.kinematics.pose.fk_document`) on every seed arm and a six-axis arm;
* each drawn joint axis is the one the joint turns about or slides along: the tool point's
  velocity from the positional Jacobian (forward-mode duals, :meth:`Arm.jacobian`) equals
  ``z x (p - o)`` for a revolute joint and ``z`` for a prismatic one, standard and modified D-H;
* what the figures draw is those frames: the tool triad of :func:`arm_figure` and of every
  animation frame of :func:`trajectory_figure`.
"""

import numpy as np
import pytest

from analysis.app.arm3d import arm_figure, trajectory_figure, workspace_box
from analysis.app.arm3d_frames import frame_spec, frame_transforms, segments
from analysis.kinematics.arm import load_arm
from analysis.kinematics.dh import DHTable
from analysis.kinematics.pose import fk_document

SEEDS = ("grabber", "palletizer", "picker", "gr1")  # seeds 000, 001, 002, 004
CHAINS = ("grabber", "palletizer", "gr1", "puma560", "cobra600", "gantry")


def _q(arm, n: int, seed: int = 3) -> np.ndarray:
    return arm.sample_q(np.random.default_rng(seed), n)


@pytest.mark.parametrize("name", [*SEEDS, "puma560"])
def test_frames_are_the_forward_kinematics(name):
    arm = load_arm(name)
    q = _q(arm, 16)
    T = frame_transforms(arm, q)
    tool = T[:, -1]
    for k in range(0, 16, 5):  # the tool frame: fk --json's pose, as a user gets it
        doc = fk_document(arm, arm.joints_to_user(q[k]))
        np.testing.assert_allclose(tool[k, :3, :3], doc["rotation"], rtol=0, atol=1e-12)
        np.testing.assert_allclose(tool[k, :3, 3], doc["position_mm"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(tool[:, 3], np.broadcast_to([0, 0, 0, 1], (16, 4)))
    R = T[..., :3, :3]
    np.testing.assert_allclose(R @ np.swapaxes(R, -1, -2), np.broadcast_to(np.eye(3), R.shape),
                               atol=1e-12)  # fmt: skip
    if not arm.description.has_rows:  # the picker's closed chain: its tool frame alone
        assert T.shape == (16, 1, 4, 4)
        np.testing.assert_allclose(tool, arm.tool_transform(q), atol=1e-9)
        return
    table = arm.table
    assert T.shape == (16, len(table.rows) + 1, 4, 4)
    np.testing.assert_array_equal(T[:, 0], np.broadcast_to(np.eye(4), (16, 4, 4)))
    np.testing.assert_allclose(T[..., :3, 3], arm.frames(q), rtol=0, atol=1e-9)
    moving = np.cumsum([row.kind != "fixed" for row in table.rows])
    for i in range(1, len(table.rows) + 1):  # each frame: the table's matrices up to row i
        part = DHTable(table.rows[:i], table.convention)
        np.testing.assert_allclose(T[:, i], part.fk(q[:, : moving[i - 1]]), rtol=0, atol=1e-9)


@pytest.mark.parametrize("name", CHAINS)
def test_each_joint_axis_is_the_one_the_joint_moves_about(name):
    arm = load_arm(name)
    q = _q(arm, 8, seed=5)
    T = frame_transforms(arm, q)
    J = arm.jacobian(q)  # (8, 3, n): dp/dq_j, duals (apart from the frames)
    p = T[:, -1, :3, 3]
    axes = {}
    for s in frame_spec(arm, 1000.0):
        if s["kind"] == "axes":
            axes |= dict.fromkeys(s["frames"], s["joint"])
    kinds = arm.table.joint_kinds
    assert sorted(axes.values()) == sorted(kinds)  # one axis per joint, of its kind
    for j, f in enumerate(sorted(axes)):  # joint j's axis, in chain order
        o, z = T[:, f, :3, 3], T[:, f, :3, 2]
        want = z if kinds[j] == "prismatic" else np.cross(z, p - o)
        np.testing.assert_allclose(J[:, :, j], want, rtol=0, atol=1e-6, err_msg=f"joint {j + 1}")


def test_segments_draw_axes_and_triads():
    arm = load_arm("grabber")
    q = np.radians([45.0, 10.2087, -155.1291])
    T = frame_transforms(arm, q)
    spec = {s["name"].split()[0]: s for s in frame_spec(arm, 1000.0)}
    tool = segments(spec["tool"], T)  # o, o + L x, gap, o, o + L y, gap, o, o + L z, gap
    L = spec["tool"]["length"]
    assert tool.shape == (9, 3) and np.isnan(tool[2::3]).all()
    np.testing.assert_allclose(tool[0::3], np.broadcast_to(T[-1, :3, 3], (3, 3)))
    np.testing.assert_allclose((tool[1::3] - tool[0::3]) / L, T[-1, :3, :3].T, atol=1e-12)
    axes = segments(spec["joint"], T)  # centred on the joint, along its z, + end's arrowhead
    La, (back, side) = spec["joint"]["length"], spec["joint"]["head"]
    start, tip = axes[0::7], axes[1::7]
    assert axes.shape == (7 * 3, 3) and np.isnan(axes[3::7]).all() and np.isnan(axes[6::7]).all()
    np.testing.assert_allclose((start + tip) / 2, T[:3, :3, 3], atol=1e-9)
    np.testing.assert_allclose(tip - start, La * T[:3, :3, 2], atol=1e-9)
    np.testing.assert_array_equal(axes[4::7], tip)
    for barb, sign in ((axes[2::7], 1), (axes[5::7], -1)):
        want = tip - back * La * T[:3, :3, 2] + sign * side * La * T[:3, :3, 0]
        np.testing.assert_allclose(barb, want, atol=1e-9)
    batch = segments(spec["link"], frame_transforms(arm, np.stack([q, q])))
    np.testing.assert_array_equal(batch[1], segments(spec["link"], T))
    with pytest.raises(ValueError, match="span_mm = 0"):
        frame_spec(arm, 0.0)


def _tool_triad(xs, ys, zs, length):
    pts = np.column_stack([xs, ys, zs]).astype(float)
    return pts[0], (pts[[1, 4, 7]] - pts[0]).T / length  # origin, rotation (columns x y z)


@pytest.mark.parametrize("name", ["grabber", "gr1", "picker"])
def test_the_figures_draw_the_tool_frame(name):
    """Front and back branches of the grabber (the same tool point, 2,000 waist pulses apart)
    draw different tool frames; each drawn triad is the FK's within the figure's 1 um."""
    arm = load_arm(name)
    q = _q(arm, 1, seed=7)[0]
    fig = arm_figure(arm, q)
    (tr,) = [t for t in fig.data if t.name.startswith("tool frame")]
    L = tr.meta["arm3d"]["length"]
    assert L == pytest.approx(0.13 * workspace_box(arm).span.max())
    o, R = _tool_triad(tr.x, tr.y, tr.z, L)
    doc = fk_document(arm, arm.joints_to_user(q))
    np.testing.assert_allclose(o, doc["position_mm"], atol=1e-3)
    np.testing.assert_allclose(R, doc["rotation"], atol=1e-3 / L * 2)
    if name == "grabber":
        sol = arm.solve(arm.fk(q), ("front-up", "back-up"))
        front, back = (arm_figure(arm, sol.theta[k]) for k in (0, 1))
        arm_trace = [
            np.column_stack([f.data[1].x, f.data[1].y, f.data[1].z]) for f in (front, back)
        ]
        np.testing.assert_allclose(*arm_trace, atol=1e-3)  # the stick figures: the same
        tools = [next(t for t in f.data if t.name.startswith("tool frame")) for f in (front, back)]
        ends = [np.array(t.x, dtype=float)[[1, 4, 7]] for t in tools]  # the axes' tips: x
        assert np.abs(ends[0] - ends[1]).max() > 10  # mm: the pictures differ


def test_trajectory_frames_move_the_joint_axes_and_frames():
    arm = load_arm("gr1")
    t = np.linspace(0.0, 1.0, 11)
    q = np.linspace(np.zeros(5), np.radians([40.0, 30.0, -50.0, 20.0, 90.0]), 11)
    fig = trajectory_figure(arm, t, q, frames=11)
    names = [tr.name for tr in fig.data]
    k_tool = next(k for k, n in enumerate(names) if n.startswith("tool frame"))
    L = fig.data[k_tool].meta["arm3d"]["length"]
    for f, qk in zip(fig.frames, q, strict=True):
        assert set(f.traces) == {k for k, tr in enumerate(fig.data) if tr.meta} | {1}
        tr = f.data[list(f.traces).index(k_tool)]
        o, R = _tool_triad(tr.x, tr.y, tr.z, L)
        T = arm.tool_transform(qk)
        np.testing.assert_allclose(o, T[:3, 3], atol=1e-3)
        np.testing.assert_allclose(R, T[:3, :3], atol=1e-4)

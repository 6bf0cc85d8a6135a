"""The GR-1 arm (seed 004): its description, chain, closed form (all backends), branches,
refusals and the orientation projection, against independent references.

References: elementary rotations written out in tests/helpers.py (eqs. 3.5-3.7, 3.14),
the textbook product Rz Tz Tx Rx (eq. 3.19) for each row, Pinocchio built from the same D-H
rows, the generating joint angles of seeded configurations, a brute-force search over the
wrist angles, and the thesis's printed Table 2-1 and section 2.1 (gr1_thesis).

Tolerances
----------
``MM = 1e-9`` mm for positions: coordinates are <= 529 mm (a2 + a3 + a4), float64 round-off
is eps x 529 ~ 1.2e-13 mm per operation and the closed form takes a few dozen (measured
worst over 10,000 configurations: 2.5e-13 mm). ``RAD = 1e-9`` rad for rotations and
recovered angles (measured 8e-13 rad, and 3.2e-11 rad at theta3 = 3e-5 rad, where acos has
the condition number 1 / |sin theta3|); a wrong sign, branch or quadrant is off by
degrees.
"""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest

from analysis.audit.papers.gr1.thesis import gr1_arm, pose_of, thesis_poses
from analysis.kinematics import compiled, rpy
from analysis.kinematics.arm import BaseAxisError, OrientationError, Status, UnreachableError
from analysis.kinematics.arms import gr1 as cf
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.pinocchio_model import PinocchioArm
from analysis.papers import gr1_thesis as paper
from helpers import angle_diff, assert_allclose, assert_points_close, reference_link, rot_x, rot_z

MM = 1e-9
RAD = 1e-9
N = 10_000


@pytest.fixture(scope="module")
def arm():
    return gr1_arm()


@pytest.fixture(scope="module")
def configs(arm):
    """10,000 seeded configurations within the description's (assumed) limits."""
    rng = np.random.default_rng(20070602)
    lo = np.array([lim[0] if lim else -np.pi for lim in arm.limits])
    hi = np.array([lim[1] if lim else np.pi for lim in arm.limits])
    return rng.uniform(lo, hi, (N, 5))


def rot_y(angle):
    a = np.asarray(angle, float)
    out = np.zeros((*a.shape, 4, 4))
    c, s = np.cos(a), np.sin(a)
    out[..., 0, 0], out[..., 0, 2], out[..., 1, 1] = c, s, 1.0
    out[..., 2, 0], out[..., 2, 2], out[..., 3, 3] = -s, c, 1.0
    return out


# --- the description ---------------------------------------------------------------------------
def test_description_records_what_is_printed_and_what_is_assumed(arm):
    d = arm.description
    assert {k: p.status for k, p in d.parameters.items()} == {
        "a2": "printed",
        "a3": "printed",
        "a4": "printed",
        "d1": "assumed",
    }
    dims = paper.ARM["dimensions"]
    assert (d.values["a2"], d.values["a3"], d.values["a4"]) == (
        dims["upper_arm_mm"],
        dims["lower_arm_mm"],
        dims["hand_mm"],
    )
    assert d.values["d1"] == 0.0
    # Table 2-1: 360 / resolution, nearest whole (0.24 deg gives exactly 1500)
    res = [r[2] for r in paper.TABLE2_1["rows"]]
    assert [j.pulses_per_rev for j in d.joints] == [round(360 / r) for r in res]
    assert [j.pulses_per_rev for j in d.joints] == [2571, 3273, 3273, 3273, 1500]
    # limits: the printed spans; full turns unrestricted, the others assumed symmetric
    spans = [None, 200, 270, 270, None]
    for j, span in zip(d.joints, spans, strict=True):
        if span is None:
            assert j.unlimited and j.limits_status.startswith("printed")
        else:
            assert math.isclose(math.degrees(j.upper - j.lower), span)
            assert math.isclose(j.lower, -j.upper) and j.limits_status.startswith("assumed")


def test_chain_is_the_textbook_product_of_eq_3_19(arm, configs):
    """Each row's A_i equals Rz(theta) Tz(d) Tx(a) Rx(alpha) (eq. 3.19) with the rows of
    model A: (theta1, d1, 0, 90), (theta2, 0, a2, 0), (theta3, 0, a3, 0), (theta4, 0, a4, 90),
    (theta5, 0, 0, 0)."""
    P = arm.params
    rows = [(P.d1, 0.0, 90), (0.0, P.a2, 0), (0.0, P.a3, 0), (0.0, P.a4, 90), (0.0, 0.0, 0)]
    q = configs[:500]
    T = np.broadcast_to(np.eye(4), (len(q), 4, 4))
    for j, (d, a, alpha) in enumerate(rows):
        T = T @ reference_link(q[:, j], d, a, math.radians(alpha), "standard")
    assert_allclose(arm.table.fk(q), T, atol=1e-12, name="D-H chain")


def test_pinocchio_equals_the_chain_on_10000_configurations(arm, configs):
    pin = PinocchioArm(arm.table)
    T_pin = np.array([pin.placement(q) for q in configs])
    T = arm.table.fk(configs)
    assert_points_close(T_pin[:, :3, 3], T[:, :3, 3], MM, "Pinocchio vs D-H position")
    assert_allclose(T_pin[:, :3, :3], T[:, :3, :3], RAD, "Pinocchio vs D-H rotation")
    assert_points_close(arm.fk(configs), T[:, :3, 3], MM, "Arm.fk vs D-H")
    assert_points_close(compiled.fk(arm, configs), T[:, :3, 3], MM, "compiled FK")
    assert_allclose(arm.jacobian(configs[:50]), pin.jacobian(configs[:50]), 1e-9, "Jacobian")


# --- RPY (eqs. 3.14-3.18) ----------------------------------------------------------------------
def test_rpy_is_rz_ry_rx_and_its_inverse(rng):
    a = rng.uniform([-np.pi, -np.pi / 2 + 1e-3, -np.pi], [np.pi, np.pi / 2 - 1e-3, np.pi], (500, 3))
    R = (rot_z(a[:, 0]) @ rot_y(a[:, 1]) @ rot_x(a[:, 2]))[:, :3, :3]
    assert_allclose(rpy.matrix_from_rpy(a), R, 1e-15, "eq. 3.15")
    assert_allclose(rpy.rpy_from_matrix(R), a, 1e-9, "eq. 3.18 corrected")
    T = rpy.transform_from_pose(np.c_[rng.uniform(-500, 500, (500, 3)), a])
    assert_allclose(rpy.transform_from_pose(rpy.pose_from_transform(T)), T, 1e-12, "pose")
    turn = rng.uniform(1e-6, np.pi - 1e-6, 500)
    assert_allclose(rpy.rotation_angle(R, R @ rot_x(turn)[:, :3, :3]), turn, 1e-12, "angle")
    with pytest.raises(ValueError, match="expected"):
        rpy.matrix_from_rpy([1.0, 2.0])


@pytest.mark.parametrize("beta_deg", [90.0, -90.0, 90.0 - 1e-9, -90.0 + 1e-9])
def test_rpy_inverse_at_gimbal_lock_gives_the_same_rotation(rng, beta_deg):
    """At beta = +-90 deg only gamma -+ alpha is defined: eq. 3.18's atan2 of two round-off
    zeros used to give an alpha and a gamma of different rotations (up to 180 deg apart)."""
    a = rng.uniform(-np.pi, np.pi, (500, 3))
    a[:, 1] = math.radians(beta_deg)
    R = rpy.matrix_from_rpy(a)
    back = rpy.rpy_from_matrix(R)
    assert_allclose(rpy.rotation_angle(R, rpy.matrix_from_rpy(back)), 0.0, 1e-6, "round trip")
    assert_allclose(back[:, 1], a[:, 1], 1e-6, "beta")


# --- the closed form: FK(IK(pose)) = pose, all backends -----------------------------------------
def test_ik_of_fk_recovers_every_configuration(arm, configs):
    T = arm.table.fk(configs)
    pose = pose_of(arm, configs)
    sol = arm.solve(pose)
    assert (sol.status == Status.OK).all() and sol.ok.any(axis=1).all()
    back = arm.table.fk(np.where(sol.ok[..., None], sol.theta, 0.0))
    err_mm = np.linalg.norm(back[..., :3, 3] - T[:, None, :3, 3], axis=-1)[sol.ok]
    err_rad = rpy.rotation_angle(back[..., :3, :3], T[:, None, :3, :3])[sol.ok]
    assert err_mm.max() <= MM and err_rad.max() <= RAD, (err_mm.max(), err_rad.max())
    assert np.isnan(sol.theta[~sol.ok]).all()  # NaN exactly where no solution
    # the generating configuration is one of the ok branches
    d = np.abs(angle_diff(sol.theta, configs[:, None, :])).max(axis=-1)
    found = np.nanmin(np.where(sol.ok, d, np.inf), axis=1)
    assert found.max() <= 1e-9, found.max()


def test_compiled_equals_numpy(arm, configs, rng):
    pose = np.concatenate(
        [
            pose_of(arm, configs),  # reachable
            np.c_[rng.uniform(-700, 700, (N, 3)), rng.uniform(-np.pi, np.pi, (N, 3))],  # mostly not
            thesis_poses(),
            [[0.0, 0.0, 200.0, 0.0, 0.0, 0.0], [1e30, 0.0, 0.0, 0.0, 0.0, 0.0]],
        ]
    )
    ref, got = arm.solve(pose), arm.solve(pose, backend="compiled")
    np.testing.assert_array_equal(got.status, ref.status)
    np.testing.assert_array_equal(got.ok, ref.ok)
    assert_allclose(got.outside_mm, ref.outside_mm, 1e-9, "outside")
    assert np.isnan(got.theta[~got.ok]).all()
    # a few ulp: the kernel's branch-free atan2 is within 2 ulp of libm's
    assert np.abs(angle_diff(got.theta[got.ok], ref.theta[ref.ok])).max() <= 1e-12
    codes = set(np.unique(ref.status).tolist())
    assert codes >= {0, 1, 3, 7}, codes


# --- branches ------------------------------------------------------------------------------------
def test_branch_geometry(arm, configs):
    pose = pose_of(arm, configs[:2000])
    sol = arm.solve(pose, limits=False)
    p = pose[:, :3]
    u = p[:, :2] / np.linalg.norm(p[:, :2], axis=-1, keepdims=True)  # the pose's azimuth
    a = rpy.matrix_from_rpy(pose[:, 3:])[:, :, 2]  # approach vector
    for i, b in enumerate(arm.branches):
        ok = sol.ok[:, i]
        q = sol.theta[ok, i]
        # theta1: front = atan2(py, px), back = that + pi
        want = np.arctan2(p[ok, 1], p[ok, 0]) + (0.0 if b.startswith("front") else np.pi)
        assert np.abs(angle_diff(q[:, 0], want)).max() <= RAD, b
        frames = arm.frames(q)
        sh, el, wrist, tool = frames[:, 1], frames[:, 2], frames[:, 3], frames[:, -1]
        # the hand (wrist -> tool, a4 long) is perpendicular to the approach vector
        hand = tool - wrist
        assert_allclose(np.linalg.norm(hand, axis=-1), arm.params.a4, 1e-9, "hand length")
        assert np.abs((hand * a[ok]).sum(-1)).max() <= 1e-9, b
        # "up": the elbow lies left of the line shoulder -> wrist, seen in the vertical plane
        # with the pose's azimuth to the right (above it when the wrist is in front)
        r_w, z_w = ((wrist - sh)[:, :2] * u[ok]).sum(-1), (wrist - sh)[:, 2]
        r_e, z_e = ((el - sh)[:, :2] * u[ok]).sum(-1), (el - sh)[:, 2]
        side = r_w * z_e - z_w * r_e
        sign = 1.0 if b.endswith("up") else -1.0
        assert (sign * side >= -1e-6).all(), b
    # the front and back wrists lie 2 a4 apart along the hand: p -/+ a4 x4
    both = sol.ok[:, 0] & sol.ok[:, 2]
    wf = arm.frames(sol.branch("front-up")[both])[:, 3]
    wb = arm.frames(sol.branch("back-up")[both])[:, 3]
    mid = (wf + wb) / 2
    assert_points_close(mid, p[both], 1e-9, "front and back wrists around the tool point")
    assert_allclose(np.linalg.norm(wf - wb, axis=-1), 2 * arm.params.a4, 1e-9, "2 a4")


def test_front_and_back_reach_differ(arm):
    """The hand level and straight ahead (theta234 = 0, approach vector down): the front
    wrist is 449 mm from the shoulder, the back wrist (p + a4 x4) 449 + 2 x 73 = 595 mm,
    beyond a2 + a3 = 456 mm: only the front branches solve it."""
    q = np.radians([30.0, 10.0, -20.0, 10.0, 20.0])
    sol = arm.solve(pose_of(arm, q), limits=False)
    assert sol.status == Status.OK and sol.ok.tolist() == [True, True, False, False]
    assert_allclose(sol.branch("front-up"), q, RAD)
    only = arm.solve(pose_of(arm, q), ["back-up", "back-down"])
    assert only.status == Status.OUT_OF_REACH  # the requested branches' reason
    front = 2 * 228 * math.cos(math.radians(10))
    with pytest.raises(UnreachableError, match=f"back wrist {front + 2 * 73:.3f} mm"):
        arm.ik(pose_of(arm, q), "back-up")


# --- refusals, the projection, bad input ----------------------------------------------------------
def test_table5_3_poses_are_refused_for_their_orientation(arm):
    sol = arm.solve(thesis_poses())
    assert sol.status.tolist() == [Status.ORIENTATION] * 2
    assert Status(7).text == "orientation"
    with pytest.raises(OrientationError, match=r"approach vector 69\.137 deg out of the arm plane"):
        arm.ik(thesis_poses()[0])
    with pytest.raises(ValueError, match=r"60\.733 deg"):
        arm.ik(thesis_poses()[1])


def test_projection_is_the_nearest_reachable_orientation(arm, rng):
    """orientation_tol=None keeps the in-plane part of a and the z1 parts of n, o: no
    (theta234, theta5) on a 2-deg grid, refined on 0.1-deg then 0.005-deg grids around its
    best, does better, and the turn equals the out-of-plane angle of a (16 seeded poses here;
    3,000 random rotations by the same search while designing the closed form)."""
    poses = np.c_[rng.uniform(100, 300, (16, 3)), rng.uniform(-np.pi, np.pi, (16, 3))]
    sol = cf.ik(numpy_ops, tuple(poses.T), arm.params, tol=1e-6, orientation_tol=None)
    q = np.stack(sol["branches"]["front-up"], axis=-1)
    R_req = rpy.matrix_from_rpy(poses[:, 3:])
    turn = rpy.rotation_angle(R_req, arm.table.fk(q)[:, :3, :3])
    assert_allclose(turn, np.arcsin(np.abs(sol["off_plane"])), 1e-9, "turn = out-of-plane angle")
    B = (rot_z(q[:, 0]) @ rot_x(np.pi / 2))[:, :3, :3]

    def reachable(k, a234, a5):  # Rz(theta1) Rx(90) Rz(theta234) Rx(90) Rz(theta5)
        return B[k] @ (rot_z(a234) @ rot_x(np.pi / 2) @ rot_z(a5))[..., :3, :3]

    def search(k, c234, c5, half, step):  # the best of a grid around (c234, c5), deg
        f = np.radians(np.arange(-half, half + step / 2, step))
        a234, a5 = np.meshgrid(c234 + f, c5 + f, indexing="ij")
        err = rpy.rotation_angle(R_req[k], reachable(k, a234, a5))
        i, j = np.unravel_index(np.argmin(err), err.shape)
        return a234[i, j], a5[i, j], err[i, j]

    for k in range(len(poses)):
        a234, a5, _ = search(k, 0.0, 0.0, 180.0, 2.0)
        a234, a5, _ = search(k, a234, a5, 2.5, 0.1)
        *_, best = search(k, a234, a5, 0.15, 0.005)
        assert turn[k] <= best + 1e-12, (k, turn[k], best)
        assert best - turn[k] <= 1e-3  # the search finds it too (to its grid)


def test_orientation_tolerance_boundary(arm, configs):
    """Reachable poses turned about the in-plane axis a x z1 (which tips the approach vector
    out of the arm plane) by 0.5 and 2 times the tolerance: projected, then refused."""
    q = configs[:20]
    T = arm.table.fk(q)
    R = T[:, :3, :3]
    z1 = np.stack([np.sin(q[:, 0]), -np.cos(q[:, 0]), np.zeros(len(q))], axis=-1)
    axis = np.cross(R[:, :, 2], z1)
    axis /= np.linalg.norm(axis, axis=-1, keepdims=True)
    K = np.zeros((len(q), 3, 3))
    K[:, 0, 1], K[:, 0, 2], K[:, 1, 2] = -axis[:, 2], axis[:, 1], -axis[:, 0]
    K -= np.swapaxes(K, 1, 2)
    for factor, status in ((0.5, Status.OK), (2.0, Status.ORIENTATION)):
        angle = factor * cf.ORIENTATION_TOL_RAD
        turn = np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K
        pose = np.c_[T[:, :3, 3], rpy.rpy_from_matrix(turn @ R)]
        sol = arm.solve(pose)
        assert (sol.status == status).all(), (factor, sol.status)
        if status == Status.OK:  # projected back: the generating configuration again
            d = np.abs(angle_diff(sol.theta, q[:, None])).max(-1)
            assert np.nanmin(np.where(sol.ok, d, np.inf), axis=1).max() <= 1e-3


def test_refusals_and_messages(arm):
    reach = arm.geometry["reach_tool"]
    with pytest.raises(UnreachableError, match=r"beyond the reach of 529 mm \(a2 \+ a3 \+ a4\)"):
        arm.ik([600.0, 10.0, 0.0, 0.0, 0.0, 0.0])
    sol = arm.solve([[0.0, 0.0, 300.0, 0.1, 0.2, 0.3], [1e-7, 0.0, 300.0, 0.0, 0.0, 0.0]])
    assert sol.status.tolist() == [Status.BASE_AXIS] * 2
    with pytest.raises(BaseAxisError, match="base axis"):
        arm.ik([0.0, 0.0, 300.0, 0.0, 0.0, 0.0])
    # on the base axis with a chosen waist angle: solved (elbow down, hand upright)
    q = np.radians([0.0, 60.0, 60.0, -30.0, 0.0])
    p = pose_of(arm, q)
    assert np.hypot(*p[:2]) < 1e-12
    p[:2] = 0.0
    got = cf.ik(numpy_ops, tuple(p), arm.params, tol=1e-6, theta1_on_axis=0.0)
    assert_allclose(np.stack(got["branches"]["front-down"]), q, 1e-9, "on-axis solution")
    # wrist on the shoulder (a2 = a3, folded elbow): degenerate on that branch
    q = np.radians([10.0, 40.0, 180.0, -150.0, 0.0])  # the hand points forward: front
    sol = arm.solve(pose_of(arm, q), ["front-up"], limits=False)
    assert sol.status == Status.DEGENERATE
    with pytest.raises(ValueError, match="wrist on the shoulder"):
        arm.raise_for(pose_of(arm, q), int(sol.status), float(sol.outside_mm), tol=1e-6)
    # inside the inner reach: only with a2 != a3
    # (100, 0, 0) mm with the approach vector down: the front wrist 27 mm from the shoulder,
    # inside |a2 - a3| = 128 mm; the back wrist 173 mm out: the back branches solve it
    short = arm.with_(a3=100.0)
    pose = [100.0, 0.0, 0.0, 0.0, 0.0, np.pi]
    assert short.solve(pose, ["front-up"], limits=False).status == Status.INSIDE_REACH
    with pytest.raises(UnreachableError, match=r"inside the inner reach of 128 mm"):
        short.ik(pose, "front-up")
    assert short.solve(pose, limits=False).ok.tolist() == [False, False, True, True]
    assert reach == 529.0


def test_joint_limits_from_the_description(arm):
    """theta4 = 160 deg is outside the assumed +-135 deg: no branch within the limits."""
    q = np.radians([20.0, 30.0, -40.0, 160.0, 5.0])
    p = pose_of(arm, q)
    free = arm.solve(p, limits=False)
    assert free.ok[0] and and_close(free.branch("front-up"), q)
    sol = arm.solve(p)
    assert not sol.ok[0]
    assert arm.solve(p, ["front-up"]).status == Status.JOINT_LIMITS
    assert compiled.solve(arm, p[None], ("front-up",), tol=1e-6, limits=arm.limits).status[0] == 4


def and_close(a, b) -> bool:
    return bool(np.abs(angle_diff(a, b)).max() <= RAD)


def test_bad_input(arm):
    with pytest.raises(ValueError, match=r"expected \(\.\.\., 6\)"):
        arm.solve([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="non-finite"):
        arm.solve([[1.0, 2.0, 3.0, np.nan, 0.0, 0.0]])
    with pytest.raises(ValueError, match="link lengths"):
        arm.with_(a2=0.0)
    with pytest.raises(ValueError, match="hand length"):
        arm.with_(a4=-1.0)
    with pytest.raises(ValueError, match="tol"):
        arm.solve(thesis_poses(), tol=-1.0)


@pytest.mark.parametrize("module", [cf, rpy])
def test_doctests(module):
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0 and result.attempted > 0

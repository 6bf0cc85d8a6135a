"""The picker of seed 002 as an arm (``load_arm("picker")``): its one closed form through the
shared API, held against references that share none of its IK.

- FK(IK): every solved branch of 10,000 sampled poses reaches the pose (position and
  rotation); every sampled configuration is a solution of its own pose, on the branch its
  wrist pitch names.
- Pinocchio on the open-chain equivalent (the main chain's eight screws, the passive joints
  solved): its own SE(3) algebra against the arm's POE pose.
- The loop closure: the secondary chain, link 5 and the fore-arm close onto the main chain.
- A planar-vector construction of the mechanism (``test_picker.planar_reference``: circles,
  rotation matrices, no screws) against ``Arm.fk``.
- The compiled backend and the SymPy namespace against numpy; the Jacobian against central
  differences; each refusal with its status and message.

Tolerances: 1e-9 mm for positions (lengths ~1e3 mm through a dozen float64 rigid motions:
round-off ~1e-12 mm), 1e-12 for rotation entries, 1e-9 rad / mm for joint values.
"""

from __future__ import annotations

import numpy as np
import pytest

from analysis.kinematics import picker as pk
from analysis.kinematics.arm import UnreachableError, load_arm
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.pinocchio_model import PinocchioPOE
from analysis.kinematics.rpy import matrix_from_rpy
from analysis.kinematics.status import Status
from helpers import assert_allclose, assert_points_close, assert_transform_close

from .test_picker import planar_reference

ARM = load_arm("picker")
PICKER = pk.load_picker()
N = 10_000
ATOL_MM = 1e-9


@pytest.fixture(scope="module")
def configs():
    return ARM.sample_q(np.random.default_rng(2016), N)


@pytest.fixture(scope="module")
def solved(configs):
    targets = ARM.target(configs)
    return targets, ARM.solve(targets)


def test_contract():
    """Six actuated joints (two sliders in mm), a pose of six inputs, four named branches, the
    refusals it can give, the reference pose as the PLC's first-scan target."""
    assert ARM.joint_names == pk.ACTIVE
    assert ARM.joint_units == ("rad", "mm", "rad", "rad", "rad", "mm")
    assert ARM.inputs == ("px", "py", "pz", "alpha", "beta", "gamma")
    assert ARM.branches == ("front", "front-flip", "back", "back-flip")
    assert ARM.closed_form.chain == "closed" and not ARM.description.has_rows
    assert set(ARM.closed_form.status_words) == {
        "out-of-reach", "inside-reach", "base-axis", "degenerate",
    }  # fmt: skip
    assert Status.JOINT_LIMITS in ARM.statuses  # the assumed slider strokes
    assert_allclose(ARM.startup_target, [*ARM.fk(np.zeros(6)), 0, 0, 0], 0.0, "start-up")
    assert set(ARM.description.assumed) >= set(pk.cf.LENGTHS)


def test_fk_of_ik_reaches_every_pose(configs, solved):
    """FK(IK): position within 1e-9 mm, rotation entries within 1e-12, on every branch that
    solves; each sampled configuration is among its pose's solutions."""
    targets, sol = solved
    assert (sol.status == Status.OK).all()
    R = matrix_from_rpy(targets[:, 3:])
    worst = {}
    for i, b in enumerate(ARM.branches):
        ok = sol.ok[:, i]
        if not ok.any():
            continue
        T = ARM.tool_transform(sol.theta[ok, i])
        pos = np.linalg.norm(T[:, :3, 3] - targets[ok, :3], axis=-1).max()
        rot = np.abs(T[:, :3, :3] - R[ok]).max()
        worst[b] = (pos, rot)
        assert pos < ATOL_MM and rot < 1e-12, (b, pos, rot)
    assert set(worst) == {"front", "front-flip"}  # both wrists solve every sampled pose
    # the back branches put F behind the waist: beyond the assumed stroke of the slider x
    assert not sol.ok[:, 2:].any()
    front = np.abs(configs[:, 3]) <= np.pi / 2
    d = sol.theta[:, 0, :] - configs
    d[:, [0, 2, 3, 4]] = np.mod(d[:, [0, 2, 3, 4]] + np.pi, 2 * np.pi) - np.pi
    assert np.abs(d[front]).max() < 1e-9 and front.sum() > 0.3 * N
    d = sol.theta[:, 1, :] - configs
    d[:, [0, 2, 3, 4]] = np.mod(d[:, [0, 2, 3, 4]] + np.pi, 2 * np.pi) - np.pi
    assert np.abs(d[~front]).max() < 1e-9 and (~front).sum() > 0.3 * N


def test_pinocchio_on_the_open_chain_equivalent(configs):
    """The main chain as an open chain (eight screws, the passive joints solved) built into
    Pinocchio: its placements equal the arm's POE pose."""
    S, M = PICKER.open_chain()
    pin = PinocchioPOE(S, M)
    q = configs[:3000]
    assert_transform_close(
        pin.placements(PICKER.main_q(q)), ARM.tool_transform(q), 1e-12, ATOL_MM, "Pinocchio"
    )


def test_loops_close(configs):
    res = PICKER.loop_residuals(configs)
    for key in ("secondary_position", "link5", "forearm_top"):
        assert res[key].max() < ATOL_MM, (key, res[key].max())
    assert res["secondary_rotation"].max() < 1e-12


def test_planar_construction_equals_arm_fk(configs):
    assert_points_close(planar_reference(PICKER, configs), ARM.fk(configs), ATOL_MM)


def test_the_other_assembly_mode_is_the_same_actuated_configuration(configs):
    """Link 5 closes twice (theta3 = atan2 -/+ acos); with the pantograph the wrist-base hinge
    F = D + (l_DF / b)(B - G) is the same for both, so the other assembly mode is not an IK
    branch (module docstring). Computed here by plain vectors."""
    p = PICKER.params
    z, x = configs[:, 1], configs[:, 5]
    A = np.stack([np.full_like(z, p["x_A"]), p["z_A"] + z], -1)
    B = np.stack([p["x_A"] + p["b"] + x, np.full_like(x, p["z_A"] + p["g"])], -1)
    d = B - A
    R = np.linalg.norm(d, axis=-1)
    c = (R**2 + p["g"] ** 2 - p["b"] ** 2) / (2 * p["g"] * R)
    F = []
    for sign in (-1.0, 1.0):
        t3 = np.arctan2(d[:, 0], d[:, 1]) + sign * np.arccos(c)
        u = np.stack([np.sin(t3), np.cos(t3)], -1)
        G, D = A + p["g"] * u, A + p["l_AD"] * u
        F.append(D + p["l_DF"] / p["b"] * (B - G))
    assert np.abs(F[0] - F[1]).max() < ATOL_MM
    assert np.abs(np.arccos(np.clip(c, -1, 1))).min() > 1e-3  # the two modes differ


def test_compiled_backend_equals_numpy(solved, configs):
    from analysis.kinematics import compiled

    targets, sol = solved
    comp = ARM.solve(targets, backend="compiled")
    np.testing.assert_array_equal(comp.status, sol.status)
    np.testing.assert_array_equal(comp.ok, sol.ok)
    assert np.nanmax(np.abs(comp.theta - sol.theta)) < 1e-9
    assert np.abs(compiled.fk(ARM, configs) - ARM.fk(configs)).max() < ATOL_MM


def test_sympy_namespace_gives_the_same_branches():
    """The closed form evaluated with SymPy (exact formulas) at a pose equals numpy's."""
    import sympy as sp

    from analysis.kinematics.symbolic import sympy_ops

    pose = (1300.0, 50.0, 1350.0, 0.2, 0.3, -0.4)
    P = dict(ARM.params)
    sym = ARM.closed_form.solve(sympy_ops, tuple(sp.Float(v) for v in pose), P, tol=1e-6)
    num = ARM.closed_form.solve(numpy_ops, pose, P, tol=1e-6)
    for b in ("front", "front-flip"):
        got = [float(sp.N(v)) for v in sym.branches[b]]
        want = [float(v) for v in num.branches[b]]
        d = np.array(got) - np.array(want)
        d[[0, 2, 3, 4]] = np.mod(d[[0, 2, 3, 4]] + np.pi, 2 * np.pi) - np.pi
        assert np.abs(d).max() < 1e-9, (b, got, want)


def test_jacobian_against_central_differences(configs):
    q = configs[:40]
    J = ARM.jacobian(q)
    h = 1e-6  # rad or mm; central differences: error ~h^2 * |third derivative| ~1e-9
    num = np.stack([(ARM.fk(q + h * e) - ARM.fk(q - h * e)) / (2 * h) for e in np.eye(6)], axis=-1)
    assert np.abs(J - num).max() < 1e-5
    assert_allclose(J[:, :, 5], np.stack([4 * np.cos(q[:, 0]), 4 * np.sin(q[:, 0]),
                                          0 * q[:, 0]], -1), 1e-9, "dP/dx = k")  # fmt: skip


def _status(pose) -> int:
    return int(ARM.solve(np.asarray(pose, dtype=float), ARM.branches).status)


def test_each_refusal_with_its_status_and_message():
    ref = np.array(ARM.startup_target)  # the reference pose: all joints 0
    # beyond the reach box
    with pytest.raises(UnreachableError, match="beyond the reach box"):
        ARM.ik([1e5, 0, 0, 0, 0, 0])
    # link 5 stretched: x = 300 mm moves F by k x = 1200 mm forward, |B - A| = |(b + x, g)|
    # = |(550, 250)| = 604.152 mm > g + b = 500 mm
    far = ref + np.array([1200.0, 0, 0, 0, 0, 0])
    assert _status(far) == Status.OUT_OF_REACH
    with pytest.raises(UnreachableError, match=r"link 5 to stretch 104\.152 mm beyond"):
        ARM.ik(far)
    # the wrist centre on the waist axis: W = (0, 0, 1000)
    assert _status([150.0, 0.0, 1000.0, 0, 0, 0]) == Status.BASE_AXIS
    # the jaw axis vertical: theta7 = 90 deg (and just outside the singular band: solved)
    with pytest.raises(ValueError, match="points the jaw axis vertically"):
        ARM.ik([*ref[:3], 0.0, np.pi / 2, 0.0])
    tol = pk.cf.WRIST_TOL_RAD
    assert _status([1300.0, 0.0, 1400.0, 0.0, np.pi / 2 - 0.5 * tol, 0.0]) == Status.DEGENERATE
    assert _status([1300.0, 0.0, 1400.0, 0.0, np.pi / 2 - 2.0 * tol, 0.0]) == Status.OK
    # the vertical slider beyond its assumed stroke (z = 310 mm > 300 mm), link 5 closes
    low = ref + np.array([0.0, 0.0, -3 * 310.0, 0, 0, 0])
    assert _status(low) == Status.JOINT_LIMITS
    with pytest.raises(ValueError, match="within the joint limits of picker"):
        ARM.ik(low)
    with pytest.raises(ValueError, match="has no base-axis singularity"):
        ARM.solve(ref, theta1_on_axis=0.0)


def test_fk_refuses_sliders_where_link5_cannot_close():
    # |B - A| = |(b + x, g - z)|: (510, 250) -> 567.979 mm; (490, 0) -> 490 mm
    with pytest.raises(ValueError, match=r"x = 260 mm: \|B - A\| = 567\.979 mm is outside"):
        ARM.fk([0.0, 0.0, 0.0, 0.0, 0.0, 260.0])
    assert not ARM.valid_q([0.0, 0.0, 0.0, 0.0, 0.0, 260.0])
    assert ARM.valid_q([0.0, 250.0, 0.0, 0.0, 0.0, 240.0])


def test_pulses_per_joint_kind():
    """Angles by eqs. 20-22 (4000 pulses/rev, assumed), sliders through the 10 mm lead
    (assumed): 400 pulses per mm."""
    q = np.array([np.pi / 2, 12.5, -np.pi / 4, 0.0, np.pi, -3.0])
    assert ARM.pulses(q).tolist() == [1000, 5000, -500, 0, 2000, -1200]
    assert_allclose(ARM.from_pulses(ARM.pulses(q)), q, 1e-12, "round trip")

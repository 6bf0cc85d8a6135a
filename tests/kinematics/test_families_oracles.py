"""The derived closed forms of the families engineers own against independent oracles:

1. EAIK (the bench extra; skipped, saying so, without it): the same solution sets on random
   arms of every revolute family, standard and modified D-H, and on the PUMA 560 and UR5
   (analysis.kinematics.derive.oracle);
2. pyplcopen's own kinematics (core/kin of the ST engine's sdist, built by make st-engine:
   tools/st-engine/kin_oracle.cpp; skipped, saying so, without it): its Scara, CartesianGantry
   and SphericalWrist6R on the arms they model, every derived branch seeded and random seeds
   (analysis.kinematics.derive.plcopen_oracle); its SerialChain's FK on the PUMA 560 and UR5;
3. Pinocchio: the FK of every published arm's D-H rows.

Counted as today's bench does: equal solution sets, disagreements (must be 0) and
one-side-empty targets.
"""

from __future__ import annotations

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm
from analysis.kinematics.derive import plcopen_oracle as po
from analysis.kinematics.derive.oracle import available as eaik_available
from analysis.kinematics.derive.samples_more import random_family_arm

pytestmark = pytest.mark.slow  # oracles in other processes and libraries: make test only

REVOLUTE_FAMILIES = ("2R-planar", "3R-planar", "6R-wrist", "6R-parallel")

needs_eaik = pytest.mark.skipif(
    not eaik_available(), reason="EAIK is not installed (the bench extra: make bench)"
)
needs_plcopen = pytest.mark.skipif(
    not po.available(), reason="pyplcopen's kinematics driver is not built (make st-engine, g++)"
)


@needs_eaik
@pytest.mark.parametrize("conv", ["standard", "modified"])
@pytest.mark.parametrize("fam", REVOLUTE_FAMILIES)
def test_eaik_same_solution_sets_on_random_arms(fam, conv, tmp_path):
    from analysis.kinematics.derive.oracle import compare_solution_sets

    for k in range(2):
        rng = np.random.default_rng(5100 + 7 * k + len(fam) + (conv == "modified"))
        path = tmp_path / f"{fam}-{conv}-{k}.toml"
        path.write_text(random_family_arm(rng, fam, conv, path.stem), encoding="utf-8")
        arm = load_arm(str(path))
        q = rng.uniform(arm.bounds[:, 0], arm.bounds[:, 1], (20, arm.n_joints))
        a = compare_solution_sets(arm, q)
        assert a.disagree == 0, (fam, conv, k, a.first_mismatch)
        assert a.max_residual_mm < 1e-6
        # the UR family too: its parallel axes given to EAIK pointing one way (the test below)
        assert a.all_equal, a


@needs_eaik
def test_the_oracles_take_anti_parallel_axes_for_parallel_ones():
    """The finding behind the random UR-family arms' "oracle empty" (issue 32): EAIK 1.2.2 and
    IK-Geo 1.0.3 accept a set of parallel axes of which one points the other way, but solve it
    as if all pointed one way. Inside the oracles alone (their own FK gives the poses): the
    UR5 as H/P solves; the same robot with joint 3's axis written the other way does not; with
    the axes turned round by axis_senses (as the oracle adapters do) it does again."""
    from eaik.IK_HP import HPRobot

    from analysis.kinematics.derive.chain import home
    from analysis.kinematics.derive.oracle import axis_senses
    from analysis.kinematics.ops import numpy_ops

    h = home(numpy_ops, load_arm("ur5").table)
    pts = np.array([[float(c) for c in p] for p in (*h.points, h.position)]) / 1e3  # m
    P = np.diff(pts, axis=0, prepend=np.zeros((1, 3)))
    q = np.random.default_rng(32).uniform(-np.pi, np.pi, (20, 6))

    def reached(H, senses):
        robot = HPRobot(H * senses[:, None], P)  # the tool frame at q = 0: identity
        poses = [robot.fwdKin(x * senses) for x in q]  # the same configurations
        return sum(min(np.abs(robot.fwdKin(s) - T).max() for s in robot.IK(T).Q) < 1e-9
                   for T in poses)  # fmt: skip

    H = np.array(h.axes)
    assert (axis_senses(H) == 1).all() and reached(H, np.ones(6)) == len(q)
    H[2] *= -1  # the same robot, joint 3 counted the other way
    assert axis_senses(H).tolist() == [1, 1, -1, 1, 1, 1]
    assert reached(H, np.ones(6)) == 0  # EAIK: not one pose
    assert reached(H, axis_senses(H)) == len(q)


@needs_eaik
@pytest.mark.parametrize("name", ["puma560", "ur5", "planar2r"])
def test_eaik_same_solution_sets_on_the_published_arms(name, rng):
    from analysis.kinematics.derive.oracle import compare_solution_sets

    arm = load_arm(name)
    a = compare_solution_sets(arm, rng.uniform(-np.pi, np.pi, (100, arm.n_joints)))
    assert a.all_equal, a


@needs_plcopen
def test_plcopen_scara_gantry_and_wrist(tmp_path, rng):
    """pyplcopen's Scara (2R + Z), CartesianGantry and SphericalWrist6R, each on random
    dimensions: the same solution sets as the derived closed forms, FK equal."""
    for k in range(3):
        l1, l2 = (float(v) for v in rng.uniform(150.0, 400.0, 2))
        path = tmp_path / f"scara{k}.toml"
        path.write_text(po.scara_text(l1, l2), encoding="utf-8")
        arm = load_arm(str(path))
        assert arm.closed_form.family == "SCARA"
        q = rng.uniform([-3.0, -3.0, -200.0], [3.0, 3.0, 200.0], (200, 3))
        mech = f"scara {l1!r} {l2!r} 1"
        fk = np.array(po.run(mech, [f"fk {po._fmt(x)}" for x in q]))
        assert np.abs(fk - arm.target(q)).max() < 1e-9
        a = po.compare_seeded(arm, mech, arm.target(q), rng)
        assert a.all_equal and a.disagree == 0, a
    offset = rng.uniform(-300.0, 300.0, 3)
    path = tmp_path / "gantry.toml"
    path.write_text(po.gantry_text(offset), encoding="utf-8")
    arm = load_arm(str(path))
    assert arm.closed_form.family == "gantry"
    q = rng.uniform(-500.0, 500.0, (200, 3))
    a = po.compare_seeded(arm, f"gantry 3 1 1 1 {po._fmt(offset)}", arm.target(q), rng)
    assert a.all_equal, a
    for k in range(2):
        d1, a2, d4, d6 = (float(v) for v in rng.uniform(100.0, 500.0, 4))
        path = tmp_path / f"wrist{k}.toml"
        path.write_text(po.wrist6r_text(d1, a2, d4, d6), encoding="utf-8")
        arm = load_arm(str(path))
        assert arm.closed_form.family == "6R-wrist"
        q = rng.uniform(-3.0, 3.0, (150, 6))
        mech = f"wrist6r {d1!r} {a2!r} {d4!r} {d6!r}"
        fk = np.array(po.run(mech, [f"fk {po._fmt(x)}" for x in q]))
        T = arm.table.fk(q)
        assert np.abs(fk[:, :3] - T[:, :3, 3]).max() < 1e-9
        assert np.abs(fk[:, 3:].reshape(-1, 3, 3) - T[:, :3, :3]).max() < 1e-12
        a = po.compare_seeded(arm, mech, arm.target(q), rng)
        assert a.all_equal and a.solutions == 8 * len(q), a


@needs_plcopen
@pytest.mark.parametrize("name", ["puma560", "ur5"])
def test_plcopen_serial_chain_fk(name, rng):
    arm = load_arm(name)
    q = rng.uniform(-np.pi, np.pi, (2000, 6))
    assert np.abs(po.fk_chain(arm.table, q) - arm.table.fk(q)).max() < 1e-9


@pytest.mark.parametrize("name", ["puma560", "ur5", "cobra600", "planar2r", "gantry"])
def test_pinocchio_fk_of_the_published_arms(name, rng):
    """Pinocchio's model of the same rows (analysis.kinematics.pinocchio_model) puts the tool
    where the description's FK does, 1,000 configurations."""
    import pinocchio as pin

    from analysis.kinematics.pinocchio_model import TOOL_FRAME, build_model

    arm = load_arm(name)
    model = build_model(arm.table)
    data = model.createData()
    fid = model.getFrameId(TOOL_FRAME)
    q = rng.uniform(arm.bounds[:, 0], arm.bounds[:, 1], (1000, arm.n_joints))
    T = arm.table.fk(q)
    worst = 0.0
    for i in range(len(q)):  # the model is in mm, as the rows
        pin.framesForwardKinematics(model, data, q[i])
        M = data.oMf[fid].homogeneous
        worst = max(worst, np.abs(M[:3, 3] - T[i, :3, 3]).max(),
                    1e3 * np.abs(M[:3, :3] - T[i, :3, :3]).max())  # fmt: skip
    assert worst < 1e-9

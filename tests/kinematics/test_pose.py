"""The full pose (issue 31 item 2): ``fk`` and :func:`analysis.kinematics.pose.pose` give the
tool point, its orientation (rotation and RPY in the convention ``ik`` takes) and every joint,
in one JSON shape for every arm; a round trip ``fk`` -> ``ik`` through the command line
returns the configuration among the solutions, for every arm that has a closed form. The
references are independent of the pose module: Pinocchio's frame placement built from the D-H
rows (``oMf``), the picker's POE chain with its passive joints solved apart
(:class:`analysis.kinematics.picker.Picker`), and :func:`analysis.kinematics.rpy.
matrix_from_rpy` for the angles."""

from __future__ import annotations

import json

import numpy as np
import pytest

from analysis.app.cli import main
from analysis.kinematics.arm import derived_arm, load_arm
from analysis.kinematics.pose import fk_document
from analysis.kinematics.rpy import matrix_from_rpy

ARMS = ("grabber", "palletizer", "gr1", "picker")
KEYS = {"arm", "joint_names", "joint_units", "joint_values", "position_mm", "rpy_deg",
        "rotation", "joint_states", "target", "target_names"}  # fmt: skip


def _cli(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def _arm(name):
    return derived_arm(name.split(":")[1]) if name.startswith("derived:") else load_arm(name)


@pytest.mark.parametrize("name", ARMS)
def test_fk_then_ik_returns_the_configuration(name, capsys):
    """For seeded configurations: ``fk --json`` gives a target, ``ik --branch all --json`` of
    that target has the configuration among its solutions (angles modulo a turn, 1e-6)."""
    arm, where = load_arm(name), name
    q = arm.joints_to_user(arm.sample_q(np.random.default_rng(11), 6))
    angle = np.array([u == "deg" for u in arm.joint_user_units])
    for row in q:
        code, out, err = _cli(capsys, "fk", *map(repr, map(float, row)), "--arm", where, "--json")
        doc = json.loads(out)
        assert code == 0 and set(doc) == KEYS, err
        code, out, err = _cli(capsys, "ik", *map(repr, doc["target"]), "--arm", where,
                              "--branch", "all", "--json")  # fmt: skip
        assert code == 0, err
        sols = json.loads(out)["solutions"]
        got = np.array([s.get("theta_deg", s.get("joint_values")) for s in sols])
        d = got - row
        d = np.where(angle, (d + 180.0) % 360.0 - 180.0, d)
        assert (np.abs(d).max(axis=-1) < 1e-6).any(), (row, got)


@pytest.mark.parametrize("name", ["derived:grabber", "derived:palletizer", "derived:gr1"])
def test_derived_arms_round_trip_in_the_api(name):
    """The derived closed forms (no description file of their own): the same round trip in
    the API, :func:`fk_document`'s target solved by :meth:`Arm.solve`."""
    arm = _arm(name)
    q = arm.sample_q(np.random.default_rng(12), 40)
    docs = [fk_document(arm, arm.joints_to_user(row)) for row in q]
    targets = arm.from_user(np.array([d["target"] for d in docs]))
    sol = arm.solve(targets)
    d = sol.theta - q[:, None, :]
    d = np.where(np.array([u == "rad" for u in arm.joint_units]), np.angle(np.exp(1j * d)), d)
    assert ((np.abs(d) < 1e-7).all(axis=-1) & sol.ok).any(axis=-1).all()


@pytest.mark.parametrize("name", ["grabber", "palletizer", "gr1"])
def test_pose_equals_pinocchio(name):
    """Position and rotation against Pinocchio's frame placement of the same rows."""
    from analysis.kinematics.pinocchio_model import PinocchioArm

    arm = load_arm(name)
    q = arm.sample_q(np.random.default_rng(13), 50)
    p = arm.pose(q)
    pin = PinocchioArm(arm.table)
    T = np.array([pin.placement(row) for row in q])
    np.testing.assert_allclose(p.position, T[:, :3, 3], atol=1e-9)
    np.testing.assert_allclose(p.rotation, T[:, :3, :3], atol=1e-12)
    np.testing.assert_allclose(matrix_from_rpy(p.rpy), p.rotation, atol=1e-12)


def test_the_picker_names_its_passive_joints():
    """The picker's joint_states: its 6 given joints and the 7 passive ones of the closure,
    equal to the POE model's own solution (Picker.joints, written apart)."""
    from analysis.kinematics.picker import load_picker

    arm = load_arm("picker")
    q = arm.sample_q(np.random.default_rng(14), 20)
    p = arm.pose(q)
    assert list(p.joint_states) == [*arm.joint_names, "theta3", "theta4", "theta5", "theta10",
                                    "theta11", "theta12", "theta13"]  # fmt: skip
    ref = load_picker().joints(q)  # theta1 .. theta13
    for j in range(13):
        np.testing.assert_allclose(p.joint_states[f"theta{j + 1}"], ref[:, j], atol=1e-12)
    T = load_picker().fk(q)
    np.testing.assert_allclose(p.position, T[:, :3, 3], atol=1e-9)
    np.testing.assert_allclose(p.rotation, T[:, :3, :3], atol=1e-12)


def test_one_json_shape_and_one_sentence(capsys):
    """Every arm the same keys; the sentence gives the pose; an arm without a closed form
    (a planar 2R given by its rows) has its pose and no target."""
    for name in ARMS:
        arm = load_arm(name)
        q = arm.joints_to_user(arm.sample_q(np.random.default_rng(15), 1)[0])
        code, out, _ = _cli(capsys, "fk", *map(repr, map(float, q)), "--arm", name, "--json")
        assert code == 0 and set(json.loads(out)) == KEYS
    code, out, _ = _cli(capsys, "fk", "45", "10.21", "-155.13")
    assert out == ("theta = (45.00, 10.21, -155.13) deg -> P = (100.000, 100.000, 600.006) mm, "
                   "RPY = (-135.000, 35.080, -90.000) deg\n"), out


def test_a_chain_without_a_closed_form_has_its_pose(tmp_path, capsys):
    """A planar 2R given by its rows (solved where a derived family covers it) and a chain
    no closed form solves (a twisted 2R with a prismatic joint): both have their pose; the
    latter no target."""
    path = tmp_path / "two.toml"
    rows = ('[[rows]]\njoint = "theta1"\na = "L1"\n[[rows]]\njoint = "theta2"\na = "L2"\n'
            '[[joints]]\nname = "theta1"\npulses_per_rev = 4000\n'
            '[[joints]]\nname = "theta2"\npulses_per_rev = 4000\n')  # fmt: skip
    path.write_text('name = "two"\n[parameters]\nL1 = 300.0\nL2 = 200.0\n' + rows, "utf-8")
    code, out, err = _cli(capsys, "fk", "30", "40", "--arm", str(path), "--json")
    doc = json.loads(out)
    assert code == 0 and set(doc) == KEYS, err
    c, s = np.cos(np.radians([30.0, 70.0])), np.sin(np.radians([30.0, 70.0]))
    tip = [300 * c[0] + 200 * c[1], 300 * s[0] + 200 * s[1], 0.0]
    np.testing.assert_allclose(doc["position_mm"], tip, atol=1e-9)
    np.testing.assert_allclose(doc["rpy_deg"], [70.0, 0.0, 0.0], atol=1e-12)
    assert (doc["target"] is None) == (load_arm(str(path)).closed_form is None)
    odd = tmp_path / "odd.toml"
    odd.write_text(
        'name = "odd"\n[parameters]\nL1 = 300.0\n'
        '[[rows]]\njoint = "theta1"\nalpha_deg = 90\na = "L1"\n'
        '[[rows]]\njoint = "s"\nkind = "prismatic"\nalpha_deg = 30\n'
        '[[rows]]\njoint = "theta3"\nalpha_deg = 60\na = 50\n'
        '[[joints]]\nname = "theta1"\npulses_per_rev = 4000\n'
        '[[joints]]\nname = "s"\nkind = "prismatic"\npulses_per_rev = 4000\nlead_mm = 5\n'
        'limits_mm = [0, 300]\n'
        '[[joints]]\nname = "theta3"\npulses_per_rev = 4000\n', "utf-8")  # fmt: skip
    arm = load_arm(str(odd))
    assert arm.closed_form is None and arm.no_ik
    code, out, err = _cli(capsys, "fk", "10", "100", "20", "--arm", str(odd), "--json")
    doc = json.loads(out)
    assert code == 0 and doc["target"] is None, err
    np.testing.assert_allclose(doc["position_mm"], arm.table.fk(arm.joints_from_user(
        [10.0, 100.0, 20.0]))[:3, 3], atol=1e-12)  # fmt: skip

"""URDF out (analysis.kinematics.urdf, ``python -m analysis urdf``): Pinocchio reads each file
back (buildModelFromUrdf) and its forward kinematics equals the project's on 10,000 seeded
configurations per arm; the picker's closed chain is its open-chain equivalent (POE of both
chains) and closes where the loop closure says; joint types and limits are the
description's; every assumed value is in a comment.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin
import pytest

from analysis.app.cli import main
from analysis.kinematics import poe
from analysis.kinematics.arm import load_arm
from analysis.kinematics.derive.samples import random_arm
from analysis.kinematics.description import load_description
from analysis.kinematics.picker import load_picker
from analysis.kinematics.urdf import arm_urdf, pinocchio_configuration

N = 10_000
D_H_ARMS = ("grabber", "palletizer", "gr1")


def _placements(model, cfg, frame: str) -> np.ndarray:
    """Pinocchio's placement of ``frame`` [mm] for configurations (N, nq) (a loop: one
    configuration per call)."""
    data = model.createData()
    fid = model.getFrameId(frame)
    out = np.empty((len(cfg), 4, 4))
    for k, q in enumerate(cfg):
        pin.framesForwardKinematics(model, data, q)
        out[k] = data.oMf[fid].homogeneous
    out[:, :3, 3] *= 1000.0
    return out


def _round_trip(path, arm, rng) -> tuple[float, float]:
    model = pin.buildModelFromUrdf(str(path))
    joints = arm.description.joints
    lo = np.array([max(j.lower, -np.pi) for j in joints])
    hi = np.array([min(j.upper, np.pi) for j in joints])
    q = rng.uniform(lo, hi, (N, len(joints)))
    got = _placements(model, pinocchio_configuration(model, [j.name for j in joints], q), "tool")
    want = arm.table.fk(q)
    return np.abs(got[:, :3, 3] - want[:, :3, 3]).max(), np.abs(
        got[:, :3, :3] - want[:, :3, :3]
    ).max()


def _tree(text: str) -> ET.Element:
    return ET.fromstring(text, parser=ET.XMLParser(target=ET.TreeBuilder(insert_comments=True)))


@pytest.mark.parametrize("name", D_H_ARMS)
def test_pinocchio_reads_the_urdf_back_and_its_fk_is_ours(name, tmp_path, rng):
    path = tmp_path / f"{name}.urdf"
    assert main(["urdf", "--arm", name, "-o", str(path)]) == 0
    pos, rot = _round_trip(path, load_arm(name), rng)
    assert pos < 1e-9 and rot < 1e-12, (pos, rot)  # mm; round-off of 17-digit numbers


@pytest.mark.parametrize("name", D_H_ARMS)
def test_joint_types_limits_and_assumed_values(name):
    desc = load_description(name)
    root = _tree(arm_urdf(name))
    joints = {j.get("name"): j for j in root.iter("joint")}
    comments = " ".join(c.text for c in root.iter(ET.Comment))
    for spec in desc.joints:
        j = joints[spec.name]
        if spec.unlimited:
            assert j.get("type") == "continuous" and j.find("limit") is None
        else:
            lim = j.find("limit")
            assert j.get("type") == "revolute"
            assert np.isclose(float(lim.get("lower")), spec.lower)
            assert np.isclose(float(lim.get("upper")), spec.upper)
            assert spec.limits_status.split(":")[0] in comments
        assert f"{spec.name}: {spec.pulses_per_rev} pulses per revolution" in comments
    for p in desc.parameters.values():
        mark = "ASSUMED" if p.status == "assumed" else p.status
        assert f"{p.name} = {p.value:g} {p.unit} [{mark}]" in comments
    assert joints["tool_joint"].get("type") == "fixed"
    assert "metres" in comments


def test_picker_open_chain_with_the_closure_stated(rng):
    """The picker's tree: the main chain's tool and the secondary chain's F' are the POE of
    each chain for any joint values; with the passive joints of the loop closure the two F'
    frames coincide."""
    pk = load_picker()
    text = arm_urdf("picker")
    model = pin.buildModelFromXML(text)
    names = [f"theta{i}" for i in range(1, 14)]
    S, M = pk.open_chain()
    S2, M2 = pk.secondary_chain()
    q = rng.uniform(-np.pi, np.pi, (N // 2, 13))
    q[:, 1] = rng.uniform(-200.0, 300.0, len(q))  # the sliders [mm]
    q[:, 8] = rng.uniform(-200.0, 250.0, len(q))
    closed = pk.joints(pk.random_active(rng, N // 2))
    q = np.concatenate([q, closed])
    cfg = pinocchio_configuration(model, names, q)
    tool = _placements(model, cfg, "tool")
    sec = _placements(model, cfg, "closure_secondary")
    main_fp = _placements(model, cfg, "closure_main")
    assert np.abs(tool - poe.fk(S, M, q[:, :8])).max() < 1e-9
    assert np.abs(sec - poe.fk(S2, M2, np.concatenate([q[:, :1], q[:, 8:]], axis=1))).max() < 1e-9
    gap = np.abs(main_fp - sec)
    assert gap[N // 2 :].max() < 1e-9  # closed where the passive joints close the loop
    assert gap[: N // 2].max() > 1.0  # and not for arbitrary joint values
    comments = " ".join(c.text for c in _tree(text).iter(ET.Comment))
    assert "CLOSED CHAIN" in comments and "passive" in comments
    assert model.nq == 24 and model.nv == 13  # 11 continuous revolutes (cos, sin), 2 sliders
    for name, lo, hi in (("theta2", "z_min", "z_max"), ("theta9", "x_min", "x_max")):
        iq = model.idx_qs[model.getJointId(name)]  # the slider strokes, in metres
        got = model.lowerPositionLimit[iq], model.upperPositionLimit[iq]
        assert np.allclose(got, (pk.params[lo] / 1000, pk.params[hi] / 1000)), (name, got)


@pytest.mark.parametrize("family", ["3R", "4R-kept", "5R"])
def test_a_users_arm_gets_urdf_too(family, tmp_path, rng):
    path = tmp_path / "mine.toml"
    path.write_text(random_arm(np.random.default_rng(3), family, "modified", "mine"), "utf-8")
    out = tmp_path / "mine.urdf"
    assert main(["urdf", "--arm", str(path), "-o", str(out)]) == 0
    pos, rot = _round_trip(out, load_arm(str(path)), rng)
    assert pos < 1e-9 and rot < 1e-12, (pos, rot)
    assert f"derived from these rows ({family} family)" in out.read_text("utf-8")


def test_urdf_command_line(tmp_path, capsys):
    assert main(["urdf", "--arm", "gr1"]) == 0  # to stdout
    text = capsys.readouterr().out
    assert text.startswith("<?xml") and '<robot name="gr1">' in text
    out = tmp_path / "sub" / "g.urdf"
    assert main(["urdf", "--arm", "gr1", "-o", str(out)]) == 2  # no directory made unasked
    assert "--mkdir creates it" in capsys.readouterr().err and not out.parent.exists()
    assert main(["urdf", "--arm", "gr1", "-o", str(out), "--json", "--mkdir"]) == 0
    assert '"joints": 5' in capsys.readouterr().out and out.read_text("utf-8") == text
    assert main(["urdf", "--arm", "no-such-arm"]) == 2
    assert "no arm 'no-such-arm'" in capsys.readouterr().err
    bad = tmp_path / "bad.toml"
    bad.write_text("name = [", "utf-8")
    assert main(["urdf", "--arm", str(bad), "-o", str(out)]) == 2
    assert "not valid TOML" in capsys.readouterr().err
    assert out.read_text("utf-8") == text  # the old file is untouched


def _prismatic_arm(rng: np.random.Generator, convention: str) -> str:
    """A user's arm with a prismatic D-H row: a waist, a lift (prismatic, random stroke, twist
    and offsets), an elbow and a tool row; random lengths. Outside the derived families (a
    prismatic joint), so it names no closed form: URDF needs none."""
    a = rng.uniform(20, 300, 4).round(3)
    d = rng.uniform(-200, 200, 4).round(3)
    lo = round(float(rng.uniform(-300, 0)), 1)
    hi = round(lo + float(rng.uniform(50, 600)), 1)
    alpha = rng.choice([0.0, 90.0, -90.0, round(float(rng.uniform(-180, 180)), 2)], 4)
    off = rng.choice([0.0, 90.0, round(float(rng.uniform(-180, 180)), 2)], 4)
    rows = ""
    for k, (joint, kind) in enumerate(
        [("theta1", "revolute"), ("q2", "prismatic"), ("theta3", "revolute"), ("tool", "fixed")]
    ):
        rows += (f'\n[[rows]]\njoint = "{joint}"\nkind = "{kind}"\nalpha_deg = {alpha[k]}\n'
                 f"a = {a[k]}\nd = {d[k]}\ntheta_offset_deg = {off[k]}\n")  # fmt: skip
    return f"""
name = "slider_arm"
title = "a user's arm with a lift"
convention = "{convention}"
{rows}
[[joints]]
name = "theta1"
pulses_per_rev = 4000
limits_deg = [-170, 170]

[[joints]]
name = "q2"
kind = "prismatic"
pulses_per_rev = 3200
lead_mm = 5.0
limits_mm = [{lo}, {hi}]

[[joints]]
name = "theta3"
pulses_per_rev = 4000
"""


@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_prismatic_row_is_a_prismatic_joint_pinocchio_reads_back(convention, seed, tmp_path):
    """``urdf --arm PATH`` of an arm with a prismatic row: the joint is ``prismatic`` with its
    stroke as limits (metres), Pinocchio reads the file (buildModelFromUrdf) and its FK equals
    the D-H chain's on 1,000 configurations within the limits (before, the row was written as
    part of a fixed transform: the lift did not move)."""
    rng = np.random.default_rng(seed)
    path = tmp_path / "slider_arm.toml"
    path.write_text(_prismatic_arm(rng, convention), encoding="utf-8")
    out = tmp_path / "slider_arm.urdf"
    assert main(["urdf", "--arm", str(path), "-o", str(out)]) == 0
    joint = ET.parse(out).getroot().find("joint[@name='q2']")
    assert joint is not None and joint.get("type") == "prismatic"
    desc = load_description(str(path))
    spec = desc.joints[1]
    lim = joint.find("limit")
    assert float(lim.get("lower")) == pytest.approx(spec.lower * 1e-3)
    assert float(lim.get("upper")) == pytest.approx(spec.upper * 1e-3)
    model = pin.buildModelFromUrdf(str(out))
    data = model.createData()
    bounds = np.array([(-np.pi, np.pi), (spec.lower, spec.upper), (-np.pi, np.pi)])
    q = bounds[:, 0] + rng.random((1000, 3)) * (bounds[:, 1] - bounds[:, 0])
    want = desc.dh_table().fk(q)[:, :3, 3]
    cfg = pinocchio_configuration(model, [j.name for j in desc.joints], q)
    fid = model.getFrameId("tool")
    got = np.empty_like(want)
    for k, c in enumerate(cfg):
        pin.framesForwardKinematics(model, data, c)
        got[k] = data.oMf[fid].translation * 1000.0
    assert np.abs(got - want).max() < 1e-9

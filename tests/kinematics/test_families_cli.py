"""The published arms through every command (``python -m analysis``): fk, ik (one branch and
``--branch all``), batch, stl in every dialect (with the machine program where the dialect
carries it), urdf; in-process through :func:`analysis.app.cli.main`. The values are held
against the Python API (itself against FK: test_families.py)."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from analysis.app.cli import main
from analysis.kinematics.arm import load_arm
from analysis.plc.dialects import DIALECTS
from analysis.plc.machine.program import machine_name
from analysis.plc.machine.spec import machine_spec

ARMS = ("planar2r", "cobra600", "puma560", "ur5", "gantry")


def _user_target(arm, q) -> list[str]:
    t = arm.target(q)
    return [repr(float(np.degrees(v) if u == "rad" else v))
            for v, u in zip(t, arm.input_units, strict=True)]  # fmt: skip


@pytest.mark.parametrize("name", ARMS)
def test_fk_and_ik_all(name, capsys, rng):
    arm = load_arm(name)
    q = arm.sample_q(rng, 1, branch=arm.branches[0])[0]
    user_q = [repr(float(v)) for v in arm.joints_to_user(q)]
    assert main(["fk", *user_q, "--arm", name, "--json"]) == 0
    fk = json.loads(capsys.readouterr().out)
    assert np.allclose(fk["position_mm"], arm.fk(q), atol=1e-9)
    assert main(["ik", *_user_target(arm, q), "--arm", name, "--branch", "all", "--json"]) == 0
    ik = json.loads(capsys.readouterr().out)
    got = next(s for s in ik["solutions"] if s["branch"] == arm.branches[0])
    values = got.get("theta_deg", got.get("joint_values"))  # deg, or deg and mm mixed
    assert np.allclose(arm.joints_from_user(values), q, atol=1e-9)
    assert len(ik["solutions"]) >= 1


@pytest.mark.parametrize("name", ARMS)
def test_batch_every_branch(name, tmp_path, rng):
    arm = load_arm(name)
    q = arm.sample_q(rng, 5)
    names = {"px": "x", "py": "y", "pz": "z"}
    cols = [f"{names.get(k, k)}_{'deg' if u == 'rad' else 'mm'}"
            for k, u in zip(arm.inputs, arm.input_units, strict=True)]  # fmt: skip
    src = tmp_path / "in.csv"
    src.write_text(",".join(cols) + "\n" + "".join(",".join(_user_target(arm, x)) + "\n"
                                                   for x in q), encoding="utf-8")  # fmt: skip
    out = tmp_path / "out.csv"
    assert main(["ik", "--arm", name, "--input", str(src), "--output", str(out),
                 "--branch", "all"]) == 0  # fmt: skip
    rows = list(csv.DictReader(out.open(encoding="utf-8")))
    assert len(rows) == 5 * len(arm.branches)
    assert {r["branch"] for r in rows} == set(arm.branches)
    assert all(r["status"] in ("ok", "joint-limits", "degenerate", "out-of-reach") for r in rows)


@pytest.mark.slow  # 25 programs, the six-axis ones recorded from eight-branch closed forms
@pytest.mark.parametrize("dialect", sorted(DIALECTS))
@pytest.mark.parametrize("name", ARMS)
def test_stl_every_dialect(name, dialect, tmp_path):
    out, mp = tmp_path / "prog.txt", tmp_path / "map.json"
    assert main(["stl", "--arm", name, "--dialect", dialect, "-o", str(out),
                 "--map", str(mp)]) == 0  # fmt: skip
    doc = json.loads(mp.read_text(encoding="utf-8"))
    assert doc["dialect"] == dialect and len(doc["outputs"]) >= load_arm(name).n_joints
    assert out.stat().st_size > 1000
    if dialect in ("st", "scl", "plcopen-xml"):  # the machine program beside the IK block
        text = out.read_text(encoding="utf-8")
        spec = machine_spec(load_arm(name))
        assert machine_name(spec) in text and len(spec.axes) == load_arm(name).n_joints
        assert text.lower().count("mc_moveabsolute") >= len(spec.axes)  # one per axis


@pytest.mark.parametrize("name", ARMS)
def test_urdf(name, tmp_path):
    import pinocchio as pin

    out = tmp_path / f"{name}.urdf"
    assert main(["urdf", "--arm", name, "-o", str(out)]) == 0
    model = pin.buildModelFromUrdf(str(out))
    assert model.nq >= load_arm(name).n_joints


def test_readme_published_arms_commands(tmp_path, monkeypatch, capsys):
    """The README's published-arm commands, literally (its ``bash`` block in "One source per
    arm"): PUMA 560's eight branches, a UR5 through its own URDF, the Cobra's ST program."""
    from pathlib import Path

    readme = (Path(__file__).parents[2] / "README.md").read_text(encoding="utf-8")
    section = readme.split("## One source per arm (and how to add one)")[1].split("\n## ")[0]
    (block,) = [b.split("\n", 1)[1] for b in section.split("```")[1::2] if b.startswith("bash")]
    monkeypatch.chdir(tmp_path)
    for line in block.strip().splitlines():
        for command in line.split("&&"):
            argv = command.split()
            assert argv[:3] == ["python", "-m", "analysis"], line
            assert main(argv[3:]) == 0, (line, capsys.readouterr().err)
    out = capsys.readouterr().out
    assert "puma560 has 8 branches; 8 of the 8 requested solve this target" in out
    assert "RPY = (-90.000, 0.000, 90.000) deg" in out  # UR5 at (0, -90, 90, 0, 90, 0) deg
    assert (tmp_path / "cobra.st").stat().st_size > 1000


@pytest.mark.parametrize("name", ARMS)
def test_the_explorers_data(name):
    """The explorer on the published arms: its model (a start target whose report solves,
    every reported branch's joints reaching the target by the rows' FK), the widget (a slider
    per input and per joint, its FK mode's line) and the site's JS module."""
    from analysis.app.explore import build_explorer
    from analysis.app.explore_js import arm_module_js
    from analysis.app.explore_logic import default_target, pose_report

    arm = load_arm(name)
    p = default_target(arm)
    rep = pose_report(arm, p)
    assert rep.reachable and rep.status_text == "ok"
    sol = arm.solve(p[None])
    assert np.allclose(arm.target(sol.theta[0][sol.ok[0]]), p, atol=1e-6)
    ex = build_explorer(name)
    assert (len(ex.target_sliders), len(ex.joint_sliders)) == (len(arm.inputs), arm.n_joints)
    assert ex.report.reachable
    ex.fk_mode.value = True
    assert "FK: joints (" in ex.message.value
    js = arm_module_js(arm)
    assert all(b in js for b in arm.branches)

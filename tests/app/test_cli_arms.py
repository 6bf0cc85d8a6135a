"""``python -m analysis arms`` lists every file of data/arms/, the picker's dimensions-only
description included (it has no D-H rows; the command used to stop on it)."""

import json

from analysis.app.cli import main


def test_arms_lists_every_description(capsys):
    assert main(["arms"]) == 0
    out = capsys.readouterr().out
    lines = {line.split()[0]: line for line in out.splitlines()}
    assert set(lines) >= {"grabber", "palletizer", "picker"}
    assert "L1 = 200 mm (assumed)" in lines["palletizer"]
    assert "x_A = 100 mm (assumed)" in lines["picker"]
    assert main(["arms", "--json"]) == 0
    docs = {d["name"]: d for d in json.loads(capsys.readouterr().out)}
    assert (
        docs["picker"]["joints"] == [] and docs["picker"]["parameters"]["g"]["status"] == "assumed"
    )


def test_ik_takes_the_gr1_pose_with_angles_in_degrees(capsys):
    """`ik X Y Z ALPHA BETA GAMMA --arm gr1`: the pose of a configuration's FK comes back as
    that configuration (angles in degrees at the command line, radians inside)."""
    import json

    import numpy as np

    from analysis.app.cli import main
    from analysis.kinematics import rpy
    from analysis.kinematics.arm import load_arm

    arm = load_arm("gr1")
    q = np.radians([30.0, 20.0, -40.0, 10.0, 15.0])
    pose = rpy.pose_from_transform(arm.table.fk(q))
    args = [f"{v:.9f}" for v in (*pose[:3], *np.degrees(pose[3:]))]
    assert main(["ik", *args, "--arm", "gr1", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    np.testing.assert_allclose(doc["solutions"][0]["theta_deg"], np.degrees(q), atol=1e-6)
    assert main(["ik", *args[:5], "--arm", "gr1"]) == 2
    err = capsys.readouterr().err
    assert "gr1 takes 6 values" in err and "alpha [deg]" in err

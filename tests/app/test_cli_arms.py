"""``python -m analysis arms`` lists every file of data/arms/, the picker included (a closed
chain without D-H rows; the command used to stop on it, then listed it with 0 joints)."""

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
    assert docs["picker"]["joints"] == ["theta1", "theta2", "theta6", "theta7", "theta8", "theta9"]
    assert docs["picker"]["parameters"]["g"]["status"] == "assumed"
    assert "(6 joints)" in lines["picker"]


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


def test_an_unreachable_gr1_orientation_names_the_nearest_one_as_a_command(capsys):
    """The library's message ends with the Python way to project (orientation_tol=None); the
    command line replaces it by the nearest orientation, which then solves."""
    assert main(["ik", "300", "100", "50", "0", "90", "10", "--arm", "gr1"]) == 2
    err = capsys.readouterr().err
    assert "28.435 deg out of the arm plane" in err and "orientation_tol" not in err
    command = err.split("away: python -m analysis ")[1].split()
    assert command[:4] == ["ik", "300", "100", "50"] and command[-4:] == [
        "--arm",
        "gr1",
        "--branch",
        "all",
    ]
    assert main([*command, "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["reachable"] is True


def test_batch_takes_gr1_poses_with_angles_in_degrees(tmp_path):
    """``ik --input`` with the GR-1: columns x_mm, y_mm, z_mm, alpha_deg, beta_deg, gamma_deg;
    each row solves as the single pose does."""
    import numpy as np

    from analysis.kinematics import rpy
    from analysis.kinematics.arm import load_arm

    arm = load_arm("gr1")
    q = np.radians([[30.0, 20.0, -40.0, 10.0, 15.0], [-50.0, 60.0, -70.0, 20.0, -5.0]])
    pose = rpy.pose_from_transform(arm.table.fk(q))
    src, out = tmp_path / "poses.csv", tmp_path / "solved.csv"
    rows = [[*p[:3], *np.degrees(p[3:])] for p in pose]
    head = "x_mm,y_mm,z_mm,alpha_deg,beta_deg,gamma_deg"
    src.write_text(head + "\n" + "\n".join(",".join(f"{v:.12g}" for v in r) for r in rows) + "\n")
    assert main(["ik", "--arm", "gr1", "--input", str(src), "--output", str(out)]) == 0
    lines = out.read_text().splitlines()
    assert lines[0].startswith(head + ",branch,reachable,theta1_deg")
    got = np.array([[float(v) for v in line.split(",")[8:13]] for line in lines[1:]])
    np.testing.assert_allclose(got, np.degrees(arm.solve(pose).theta[:, 0]), atol=1e-7)
    np.testing.assert_allclose(got, np.degrees(q), atol=1e-6)
    src.write_text("x_mm,y_mm,z_mm\n300,0,200\n")  # a point is not a pose
    assert main(["ik", "--arm", "gr1", "--input", str(src), "--output", str(out)]) == 2

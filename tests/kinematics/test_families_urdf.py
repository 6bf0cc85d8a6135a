"""Arms from a URDF (analysis.kinematics.urdf_in, ``--arm robot.urdf``): the chain converted to
modified D-H rows, its FK equal to Pinocchio's on the same file (10,000 configurations), the
derived closed form where a family applies, and one-line refusals otherwise; a URDF is
untrusted input (issue 27): no DTD or entity, bounded, strict.

The URDFs: the project's own writer on every published arm (``python -m analysis urdf``), a
UR5 in the frames ROS-Industrial's ``ur_description`` uses (a base frame turned by pi, joint
frames turned by pi/2, side frames ``base`` and ``ft_frame``, the tool ``tool0`` behind a
``flange``), written here from the UR5's D-H numbers, and random chains (any origins and
axes; revolute, continuous, prismatic and fixed joints).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm
from analysis.kinematics.status import Status
from analysis.kinematics.urdf_in import MAX_BYTES, description_text, read_urdf

PUMA_POSE = (40.663, -144.828, 1529.703, 116.431, 23.352, -18.634)


def _joint(name, kind, parent, child, xyz=(0, 0, 0), rpy=(0, 0, 0), axis=(0, 0, 1), lim=None):
    out = [f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>',
           f'<origin xyz="{" ".join(repr(float(v)) for v in xyz)}" '
           f'rpy="{" ".join(repr(float(v)) for v in rpy)}"/>']  # fmt: skip
    if kind != "fixed":
        out.append(f'<axis xyz="{" ".join(repr(float(v)) for v in axis)}"/>')
    if lim is not None:
        out.append(f'<limit lower="{lim[0]!r}" upper="{lim[1]!r}" effort="1" velocity="2"/>')
    return "".join(out) + "</joint>"


def _robot(name, joints) -> str:
    links = sorted({j.split('link="')[1].split('"')[0] for j in joints}
                   | {j.split('link="')[2].split('"')[0] for j in joints})  # fmt: skip
    return (f'<?xml version="1.0"?>\n<robot name="{name}">\n'
            + "".join(f'<link name="{k}"/>\n' for k in links) + "\n".join(joints) + "\n</robot>\n")


def ur5_ros_style() -> str:
    """A UR5 in ur_description's frames, from the D-H numbers (m): d1 0.089159, a2 -0.425,
    a3 -0.39225, d4 0.10915, d5 0.09465, d6 0.0823."""
    pi, h = math.pi, math.pi / 2
    lim = (-2 * pi, 2 * pi)
    return _robot("ur5_ros", [
        _joint("base_link-base_fixed_joint", "fixed", "base_link", "base", rpy=(0, 0, pi)),
        _joint("base_link-base_link_inertia", "fixed", "base_link", "base_link_inertia",
               rpy=(0, 0, pi)),
        _joint("shoulder_pan_joint", "revolute", "base_link_inertia", "shoulder_link",
               xyz=(0, 0, 0.089159), lim=lim),
        _joint("shoulder_lift_joint", "revolute", "shoulder_link", "upper_arm_link",
               rpy=(h, 0, 0), lim=lim),
        _joint("elbow_joint", "revolute", "upper_arm_link", "forearm_link", xyz=(-0.425, 0, 0),
               lim=(-pi, pi)),
        _joint("wrist_1_joint", "revolute", "forearm_link", "wrist_1_link",
               xyz=(-0.39225, 0, 0.10915), lim=lim),
        _joint("wrist_2_joint", "revolute", "wrist_1_link", "wrist_2_link",
               xyz=(0, -0.09465, 0), rpy=(h, 0, 0), lim=lim),
        _joint("wrist_3_joint", "revolute", "wrist_2_link", "wrist_3_link",
               xyz=(0, 0.0823, 0), rpy=(h, pi, pi), lim=lim),
        _joint("wrist_3-flange", "fixed", "wrist_3_link", "flange", rpy=(0, -h, -h)),
        _joint("flange-tool0", "fixed", "flange", "tool0", rpy=(h, 0, h)),
        _joint("wrist_3-ft_frame", "fixed", "wrist_3_link", "ft_frame", rpy=(pi, 0, 0)),
    ])  # fmt: skip


def random_chain(rng, n: int) -> str:
    """A serial chain of ``n`` moving joints with random origins and axes, fixed joints
    between some, a side frame off the base and a tool."""
    kinds = rng.choice(["revolute", "continuous", "prismatic"], n, p=[0.5, 0.25, 0.25])
    joints = [_joint("side", "fixed", "base_link", "camera", xyz=rng.normal(size=3))]
    parent = "base_link"
    for i, kind in enumerate(kinds):
        if rng.random() < 0.3:
            joints.append(_joint(f"fix{i}", "fixed", parent, f"mount{i}",
                                 xyz=rng.uniform(-0.3, 0.3, 3), rpy=rng.uniform(-3, 3, 3)))
            parent = f"mount{i}"
        axis = rng.normal(size=3)
        lim = (-2.0, 2.5) if kind == "revolute" else (-0.3, 0.4) if kind == "prismatic" else None
        joints.append(_joint(f"j{i + 1}", kind, parent, f"link{i + 1}",
                             xyz=rng.uniform(-0.4, 0.4, 3), rpy=rng.uniform(-3, 3, 3),
                             axis=axis / np.linalg.norm(axis), lim=lim))
        parent = f"link{i + 1}"
    joints.append(_joint("tool_joint", "fixed", parent, "tool0", xyz=rng.uniform(-0.2, 0.2, 3),
                         rpy=rng.uniform(-3, 3, 3)))
    return _robot("random_chain", joints)  # fmt: skip


def _pinocchio_fk(path, tool: str, q: np.ndarray, kinds) -> np.ndarray:
    """Pinocchio's FK (N, 4, 4) [mm] of the URDF at ``path``, tool link ``tool``, joint values
    ``q`` (N, n) [rad | mm] in chain order (a continuous joint is (cos, sin) in Pinocchio)."""
    import pinocchio as pin

    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    fid = model.getFrameId(tool)
    out = np.zeros((len(q), 4, 4))
    for i in range(len(q)):
        x = pin.neutral(model)
        for j in range(1, model.njoints):
            jm, v = model.joints[j], q[i, j - 1]
            if jm.nq == 2:
                x[jm.idx_q: jm.idx_q + 2] = (math.cos(v), math.sin(v))
            else:
                x[jm.idx_q] = v / 1000.0 if kinds[j - 1] == "prismatic" else v
        pin.framesForwardKinematics(model, data, x)
        out[i] = data.oMf[fid].homogeneous
    out[:, :3, 3] *= 1000.0
    return out


def _assert_fk_equal(path, n_q: int, rng):
    arm = load_arm(str(path))
    chain = read_urdf(path)
    kinds = [j.kind for j in chain.joints if j.kind != "fixed"]
    lo, hi = arm.bounds[:, 0], arm.bounds[:, 1]
    q = rng.uniform(lo, hi, (n_q, arm.n_joints))
    T = arm.table.fk(q)
    P = _pinocchio_fk(path, chain.tool, q, kinds)
    assert np.abs(T[:, :3, 3] - P[:, :3, 3]).max() < 1e-9
    assert np.abs(T[:, :3, :3] - P[:, :3, :3]).max() < 1e-12
    return arm


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("urdf")


@pytest.mark.slow  # 10,000 configurations through Pinocchio per arm: make test only
@pytest.mark.parametrize("name", ["puma560", "ur5", "cobra600", "planar2r", "gantry"])
def test_the_writers_urdf_reads_back(name, folder, rng):
    """``urdf --arm NAME`` then ``--arm NAME.urdf``: Pinocchio's FK of the file equals the
    converted description's (10,000 configurations), and the same family is derived."""
    from analysis.kinematics.urdf import arm_urdf

    path = folder / f"{name}.urdf"
    path.write_text(arm_urdf(name), encoding="utf-8")
    arm = _assert_fk_equal(path, 10_000, rng)
    assert arm.closed_form.family == load_arm(name).closed_form.family


def test_puma_from_its_urdf_gives_all_eight_branches(folder):
    from analysis.kinematics.urdf import arm_urdf

    path = folder / "puma560.urdf"
    path.write_text(arm_urdf("puma560"), encoding="utf-8")
    arm, ref = load_arm(str(path)), load_arm("puma560")
    p = np.r_[PUMA_POSE[:3], np.radians(PUMA_POSE[3:])]
    a, b = arm.solve(p[None]), ref.solve(p[None])
    assert a.ok.all() and b.ok.all()
    assert np.abs(np.angle(np.exp(1j * (a.theta - b.theta)))).max() < 1e-9


@pytest.mark.slow
def test_a_ur5_in_ros_frames(folder, rng):
    """A UR5 in ur_description's frames: FK equal to Pinocchio's, the UR family derived, all
    eight branches of a pose reach it (1e-6 mm, 1e-9 rad), the tool frame tool0 (behind the
    flange, beside the side frame ft_frame)."""
    path = folder / "ur5_ros.urdf"
    path.write_text(ur5_ros_style(), encoding="utf-8")
    arm = _assert_fk_equal(path, 10_000, rng)
    assert read_urdf(path).tool == "tool0"
    # the side frame first in the file: still tool0 (not the first leaf found)
    text = ur5_ros_style()
    side = text[text.index('<joint name="wrist_3-ft_frame"'):text.index("</joint>",
                text.index('<joint name="wrist_3-ft_frame"')) + len("</joint>")]  # fmt: skip
    first = text.replace(side, "").replace('<joint name="wrist_3-flange"',
                                           side + '\n<joint name="wrist_3-flange"')  # fmt: skip
    (folder / "ur5_side_first.urdf").write_text(first, encoding="utf-8")
    assert read_urdf(folder / "ur5_side_first.urdf").tool == "tool0"
    assert arm.closed_form.family == "6R-parallel" and len(arm.branches) == 8
    q = rng.uniform(-np.pi, np.pi, (300, 6))
    T = arm.table.fk(q)
    sol = arm.solve(arm.target(q), limits=False)
    Tb = arm.table.fk(np.nan_to_num(sol.theta))
    assert np.linalg.norm(Tb[..., :3, 3] - T[:, None, :3, 3], axis=-1)[sol.ok].max() < 1e-6
    assert np.abs(Tb[..., :3, :3] - T[:, None, :3, :3]).max(axis=(-1, -2))[sol.ok].max() < 1e-9
    assert sol.ok.sum(axis=1).min() >= 2  # a UR5 pose has 2 to 8 solutions


@pytest.mark.parametrize("seed", [0, pytest.param(1, marks=pytest.mark.slow),
                                  pytest.param(2, marks=pytest.mark.slow),
                                  pytest.param(3, marks=pytest.mark.slow)])
def test_random_chains_fk_equals_pinocchio(seed, folder):
    rng = np.random.default_rng(seed)
    path = folder / f"chain{seed}.urdf"
    path.write_text(random_chain(rng, int(rng.integers(2, 8))), encoding="utf-8")
    _assert_fk_equal(path, 500 if seed == 0 else 2_500, rng)


# --------------------------------------------------------------------------- refusals
def _refused(folder, text: str, name="bad.urdf") -> str:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ValueError) as err:
        description_text(path)
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith(name)
    return msg


def test_refusals_name_the_reason(folder):
    ok = [_joint("a", "revolute", "base", "l1", lim=(-1, 1)),
          _joint("b", "revolute", "l1", "l2", axis=(0, 1, 0), lim=(-1, 1))]  # fmt: skip
    tree = [*ok, _joint("c", "revolute", "l1", "l3", lim=(-1, 1))]
    assert "branches with moving joints" in _refused(folder, _robot("t", tree))
    floating = [*ok, _joint("f", "floating", "l2", "l4")]
    assert "'floating'" in _refused(folder, _robot("t", floating))
    planar = [*ok, _joint("p", "planar", "l2", "l4")]
    assert "'planar'" in _refused(folder, _robot("t", planar))
    mimic = _robot("t", ok).replace('<axis xyz="0.0 1.0 0.0"/>',
                                    '<axis xyz="0 1 0"/><mimic joint="a"/>')  # fmt: skip
    assert "mimics" in _refused(folder, mimic)
    two_tools = [*ok, _joint("t1", "fixed", "l2", "tcp_a"), _joint("t2", "fixed", "l2", "tcp_b")]
    assert "no tool frame" in _refused(folder, _robot("t", two_tools))
    limit = '<limit lower="-1" upper="1" effort="1" velocity="2"/>'
    no_limit = _robot("t", ok).replace(limit, "", 1)
    assert "needs <limit" in _refused(folder, no_limit)
    assert "nothing moves" in _refused(folder, _robot("t", [_joint("x", "fixed", "a", "b")]))
    assert "not defined" in _refused(folder, _robot("t", ok).replace('<link name="l2"/>', ""))
    assert "unknown element <sensor>" in _refused(
        folder, _robot("t", ok).replace("</robot>", "<sensor/></robot>"))
    nan = _robot("t", ok).replace('xyz="0.0 0.0 0.0"', 'xyz="0 0 x"', 1)
    assert "not a number" in _refused(folder, nan)
    twice = _robot("t", ok).replace('name="b"', 'name="a"')
    assert "appear more than once" in _refused(folder, twice)


def test_untrusted_xml_is_refused(folder):
    """A DTD (billion laughs, an external entity) is refused before anything expands; a file
    over the bound is not read; a device or a folder is not a URDF."""
    laughs = ('<?xml version="1.0"?><!DOCTYPE r [<!ENTITY a "aaaaaaaaaa">'
              '<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;">]>'
              '<robot name="&c;"/>')  # fmt: skip
    assert "refused" in _refused(folder, laughs)
    external = ('<?xml version="1.0"?><!DOCTYPE r [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
                '<robot name="&x;"/>')
    msg = _refused(folder, external)
    assert "refused" in msg and "root:" not in msg
    big = folder / "big.urdf"
    big.write_bytes(b"<robot>" + b" " * (MAX_BYTES + 10) + b"</robot>")
    with pytest.raises(ValueError, match="larger than"):
        description_text(big)
    with pytest.raises(ValueError, match="not a regular file"):
        description_text(folder)
    assert "not well-formed" in _refused(folder, "<robot><link></robot>")


def with_drive(urdf, pulses_per_rev: int = 4000):
    """The description of the URDF at ``urdf`` with a drive added, as a user gives one (a
    URDF has none): ``arms --arm robot.urdf --toml``, then ``pulses_per_rev`` in every
    ``[[joints]]`` entry; written next to it, its path."""
    from analysis.kinematics.description import description_toml

    text = description_toml(urdf).replace("[[joints]]\n", f"[[joints]]\npulses_per_rev = "
                                          f"{pulses_per_rev}\n")  # fmt: skip
    path = urdf.with_suffix(".toml")
    path.write_text(text, encoding="utf-8")
    return path


def test_cli_takes_a_urdf(folder, capsys):
    """``--arm robot.urdf`` through the commands: fk, ik --branch all (no drive given: no
    pulses), stl (refused in one line naming the joint and the key: a URDF has no drive, and
    none is invented); with the drive added to its description (``arms --toml``), stl."""
    from analysis.app.cli import main
    from analysis.kinematics.urdf import arm_urdf

    path = folder / "puma_cli.urdf"
    path.write_text(arm_urdf("puma560"), encoding="utf-8")
    assert main(["fk", "10", "20", "30", "40", "50", "60", "--arm", str(path), "--json"]) == 0
    assert main(["ik", *map(str, PUMA_POSE), "--arm", str(path), "--branch", "all"]) == 0
    text = capsys.readouterr().out
    assert "8 of the 8 requested solve" in text and text.count("pulses: no drive given") == 8
    out = folder / "puma.st"
    assert main(["stl", "--arm", str(path), "--dialect", "st", "--no-motion", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "puma_cli.urdf: joint theta1 pulses_per_rev: is missing" in err
    assert err.count("\n") == 1 and not out.exists()
    assert main(["arms", "--arm", str(path), "--toml"]) == 0
    assert capsys.readouterr().out == description_text(path)
    # the IK block alone: a URDF gives velocities, no accelerations for the machine program
    assert main(["stl", "--arm", str(with_drive(path)), "--dialect", "st", "--no-motion", "-o",
                 str(out)]) == 0  # fmt: skip
    assert "FUNCTION_BLOCK" in out.read_text()
    assert main(["ik", "0", "0", "0", "0", "0", "0", "--arm", str(path)]) == 2
    assert Status.INSIDE_REACH  # the refusal's words are the CLI's (exit 2, one line)


def _eight_branch_ros_ur5(path, rng) -> np.ndarray:
    """A configuration of the ROS-frames UR5 whose pose has all eight branches within the
    joint ranges (sampled, seeded)."""
    arm = load_arm(str(path))
    q = rng.uniform(-np.pi / 2, np.pi / 2, (200, 6))
    sol = arm.solve(arm.target(q))
    return q[np.flatnonzero(sol.ok.all(axis=1))[0]]


@pytest.mark.parametrize("source", ["puma560", "ur5", "puma560.urdf", "ur5_ros.urdf"])
def test_done_when_eight_branches_through_the_cli(source, folder, capsys, rng):
    """Issue 32's bar, from a shell's point of view: the PUMA 560 and the UR5 from their
    published D-H tables and from a URDF (the writer's PUMA; a UR5 in ROS-Industrial's
    frames), ``ik POSE --arm ... --branch all --json``: eight branches, each one's joint values
    (as printed) reaching the pose within 1e-6 mm and 1e-9 rad by Pinocchio's FK of a URDF of
    the arm (the one loaded, or the writer's for a D-H table) and by the D-H rows' FK."""
    from analysis.app.cli import main
    from analysis.kinematics.rpy import transform_from_pose
    from analysis.kinematics.urdf import arm_urdf

    from .test_families import UR5_POSE, _rotation_error

    name = source.split(".")[0].removesuffix("_ros")
    path = folder / f"{name}_done.urdf"
    path.write_text(ur5_ros_style() if source == "ur5_ros.urdf" else arm_urdf(name), "utf-8")
    chain = read_urdf(path)
    kinds = [j.kind for j in chain.joints if j.kind != "fixed"]
    arm_arg = str(path) if source.endswith(".urdf") else name
    if source == "ur5_ros.urdf":  # its base is not the D-H table's: a pose of its own
        q0 = _eight_branch_ros_ur5(path, rng)
        assert main(["fk", *map(repr, np.degrees(q0).tolist()), "--arm", arm_arg, "--json"]) == 0
        pose = json.loads(capsys.readouterr().out)["target"]
    else:
        pose = PUMA_POSE if name == "puma560" else UR5_POSE
    assert main(["ik", *map(repr, map(float, pose)), "--arm", arm_arg, "--branch", "all",
                 "--json"]) == 0  # fmt: skip
    doc = json.loads(capsys.readouterr().out)
    assert [s["branch"] for s in doc["solutions"]] == list(load_arm(arm_arg).branches)
    q = np.radians([s["theta_deg"] for s in doc["solutions"]])
    assert q.shape == (8, 6) and len({tuple(np.round(x, 6)) for x in q}) == 8
    want = transform_from_pose(np.r_[pose[:3], np.radians(pose[3:])])
    for T in (_pinocchio_fk(path, chain.tool, q, kinds), load_arm(arm_arg).table.fk(q)):
        assert np.abs(T[:, :3, 3] - want[:3, 3]).max() < 1e-6
        assert _rotation_error(T[:, :3, :3], want[:3, :3]).max() < 1e-9

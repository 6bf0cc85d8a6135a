"""An arm given by its D-H table alone (issue 32: "a 2R planar arm given by its D-H table gets
nothing, not even fk"): no drive, or no ``[[joints]]`` at all.

An engineer's D-H table has no drive data (pulses per revolution, a screw's lead). Such a
description loads, and every command that needs no drive answers as the same arm with a
drive does, in every number but the pulses, through the real command line
(:func:`analysis.app.cli.main`): ``fk``, ``ik --branch all`` (JSON), the batch, ``urdf`` and
``arms``. Where pulses would be, ``ik`` says "no drive given" (JSON: ``"pulses": null``), the
batch CSV has no pulse columns, the URDF's comment says so. What needs a drive (``stl`` in
every dialect, the machine program, pulse counts, the quantization studies) refuses in one
line naming the joint and the missing key, from the one place a drive is read
(:attr:`analysis.kinematics.joints.JointSpec.pulses_per_rev`, :attr:`analysis.kinematics.
params.Params.pulses_per_rev`).

The arms: Corke's 2R planar (``data/arms/planar2r.toml``), a 3R planar arm written here, the
Cobra 600 SCARA and the PUMA 560 (``data/arms``), each with its drive and motion keys taken
out; and, for the all-revolute ones, the D-H rows alone (no ``[[joints]]``), against the same
rows with joints that carry only a drive.
"""

from __future__ import annotations

import csv
import io
import json
import re
from pathlib import Path

import numpy as np
import pytest

from analysis.app.cli import main
from analysis.kinematics.arm import load_arm
from analysis.kinematics.schema import DescriptionError, NoDrive
from analysis.paths import data_dir

DRIVE_KEYS = ("pulses_per_rev", "lead_mm", "max_velocity", "max_acceleration", "max_jerk",
              "home")  # fmt: skip

PLANAR_3R = """
name = "planar3r"
title = "3R planar arm"
convention = "standard"

[parameters]
L1 = { value = 400.0, unit = "mm", status = "assumed" }
L2 = { value = 300.0, unit = "mm", status = "assumed" }
L3 = { value = 100.0, unit = "mm", status = "assumed" }

[[rows]]
joint = "theta1"
a = "L1"

[[rows]]
joint = "theta2"
a = "L2"

[[rows]]
joint = "theta3"
a = "L3"
""" + "".join(f'\n[[joints]]\nname = "theta{i}"\npulses_per_rev = 4000\n' for i in (1, 2, 3))


def _text(name: str) -> str:
    return PLANAR_3R if name == "planar3r" else (data_dir() / "arms" / f"{name}.toml").read_text()


def without_drive(text: str) -> str:
    """The description without its drive and motion keys (one line each in data/arms)."""
    keys = "|".join(DRIVE_KEYS)
    return "".join(line for line in text.splitlines(keepends=True)
                   if not re.match(rf"\s*({keys})\s*=", line))  # fmt: skip


def rows_only(text: str) -> str:
    """The description without its ``[[joints]]`` tables (the D-H table alone)."""
    blocks = re.split(r"(?m)^(?=\[)", text)
    return "".join(b for b in blocks if not b.startswith("[[joints]]"))


def with_bare_drive(text: str) -> str:
    """The rows, and joints named as the rows name them with only a drive: the arm a
    rows-only description must equal."""
    names = re.findall(r'(?m)^joint\s*=\s*"(\w+)"', rows_only(text))
    return rows_only(text) + "".join(f'\n[[joints]]\nname = "{n}"\npulses_per_rev = 3600\n'
                                     for n in names)  # fmt: skip


# (arm, variant): "no drive" against the arm as published; "rows only" (no [[joints]], all
# joints revolute) against the same rows with a bare drive
CASES = [(a, "no drive") for a in ("planar2r", "planar3r", "cobra600", "puma560")] + [
    (a, "rows only") for a in ("planar2r", "planar3r", "puma560")
]
FAST = {("planar2r", "no drive")}
"""The cases make test-fast runs (every case: make test)."""


def run(capsys, *argv) -> tuple[int, str, str]:
    capsys.readouterr()
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(params=[c if c in FAST else pytest.param(c, marks=pytest.mark.slow)
                        for c in CASES],
                ids=[f"{a}-{v.replace(' ', '-')}" for a, v in CASES])  # fmt: skip
def pair(request, tmp_path):
    """Two descriptions of one arm, both ``arm.toml`` in folders of their own: with a drive,
    and without."""
    name, variant = request.param
    text = _text(name)
    drive, bare = ((text, without_drive(text)) if variant == "no drive" else
                   (with_bare_drive(text), rows_only(text)))  # fmt: skip
    assert "pulses_per_rev" not in bare
    assert variant == "no drive" or "[[joints]]" not in bare
    paths = []
    for folder, body in (("drive", drive), ("bare", bare)):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "arm.toml").write_text(body, encoding="utf-8")
        paths.append(tmp_path / folder / "arm.toml")
    return name, paths[0], paths[1]


def _targets(arm, k: int = 6) -> np.ndarray:
    """Targets the arm reaches (FK of valid configurations, seeded), in user units."""
    q = arm.sample_q(np.random.default_rng(7), k)
    t = arm.target(q)
    angle = np.array([u == "rad" for u in arm.input_units])
    return np.where(angle, np.degrees(t), t)


def test_a_dh_table_alone_answers_every_command_but_pulses(pair, capsys, tmp_path):
    _, drive, bare = pair
    arm, arm_bare = load_arm(str(drive)), load_arm(str(bare))
    assert arm.has_drive and not arm_bare.has_drive
    assert arm_bare.joint_names == arm.joint_names and arm_bare.limits == arm.limits
    # fk: the whole document
    q = arm.joints_to_user(arm.sample_q(np.random.default_rng(3), 3))
    for values in q.tolist():
        docs = [json.loads(run(capsys, "fk", *map(repr, values), "--arm", p, "--json")[1])
                for p in (drive, bare)]  # fmt: skip
        assert docs[0] == docs[1]
    # ik --branch all: every branch, status and angle; pulses null without a drive
    targets = _targets(arm)
    for t in targets.tolist():
        outs = [run(capsys, "ik", *map(repr, t), "--arm", p, "--branch", "all", "--json")
                for p in (drive, bare)]  # fmt: skip
        assert outs[0][0] == outs[1][0] == 0, outs
        d, b = (json.loads(o[1]) for o in outs)
        assert d["solutions"] and all(isinstance(s["pulses"], list) for s in d["solutions"])
        assert all(s["pulses"] is None for s in b["solutions"])
        for s in d["solutions"]:
            s["pulses"] = None
        assert d == b
        text = run(capsys, "ik", *map(repr, t), "--arm", bare, "--branch", "all")[1]
        assert text.count("pulses: no drive given") == len(b["solutions"]), text
    # batch: the same CSV without the pulse columns c1 .. cn
    from analysis.app.batch import input_columns

    src = tmp_path / "targets.csv"
    rows = [*targets.tolist(), [9e5] * targets.shape[1]]  # and one out of reach
    src.write_text(",".join(input_columns(arm)) + "\n" + "".join(
        ",".join(map(repr, r)) + "\n" for r in rows))  # fmt: skip
    tables, said = [], []
    for p, out in ((drive, tmp_path / "d.csv"), (bare, tmp_path / "b.csv")):
        code, doc, _ = run(capsys, "ik", "--input", src, "--output", out, "--arm", p,
                           "--branch", "all", "--json")  # fmt: skip
        assert code == 0
        said.append(json.loads(doc))
        tables.append(list(csv.DictReader(io.StringIO(out.read_text()))))
    # the summary says whether pulse columns were written, and is otherwise the same
    assert said[0].pop("pulses") is True and said[1].pop("pulses") is False
    assert {k: v for k, v in said[0].items() if k not in ("output", "arm")} == {
        k: v for k, v in said[1].items() if k not in ("output", "arm")}
    err = run(capsys, "ik", "--input", src, "--output", tmp_path / "t.csv", "--arm", bare)[2]
    assert err.rstrip().endswith("(no drive given: no pulse columns)"), err
    pulses = [f"c{j + 1}" for j in range(arm.n_joints)]
    assert set(pulses) <= set(tables[0][0]) and not set(pulses) & set(tables[1][0])
    assert [{k: v for k, v in r.items() if k not in pulses} for r in tables[0]] == tables[1]
    assert len(tables[1]) == len(rows) * len(arm.branches)
    # urdf: the same file but the drive's comment lines
    urdfs = [run(capsys, "urdf", "--arm", p)[1] for p in (drive, bare)]
    keep = [[ln for ln in u.splitlines() if "pulses per revolution" not in ln
             and "no drive given" not in ln] for u in urdfs]  # fmt: skip
    assert keep[0] == keep[1] and urdfs[1].count("no drive given") == arm.n_joints
    # arms: the same listing, pulses_per_rev null
    docs = [json.loads(run(capsys, "arms", "--arm", p, "--json")[1])[0] for p in (drive, bare)]
    assert docs[1].pop("pulses_per_rev") is None and docs[0].pop("pulses_per_rev")
    assert docs[0] == docs[1]


@pytest.mark.parametrize("name", ["planar2r", *(pytest.param(n, marks=pytest.mark.slow)
                                                 for n in ("cobra600", "puma560"))])
def test_what_needs_a_drive_refuses_in_one_line_naming_the_joint(name, capsys, tmp_path):
    """stl in every dialect (the machine program, and the IK block alone), the pulse counts,
    the quantization study and the machine's spec: NoDrive, one line naming the joint and the
    key; nothing written. A description with motion limits and homing but no pulses refuses
    the same (the machine reads its drive from the same place)."""
    from analysis.plc.dialects import DIALECTS
    from analysis.plc.generate import generate
    from analysis.plc.machine.spec import machine_spec
    from analysis.studies.quantization import half_step_rad

    text = _text(name)
    only_pulses = "".join(ln for ln in text.splitlines(keepends=True)
                          if not ln.startswith("pulses_per_rev"))  # fmt: skip
    for body in (without_drive(text), only_pulses):
        path = tmp_path / "arm.toml"
        path.write_text(body, encoding="utf-8")
        arm = load_arm(str(path))
        first = arm.joint_names[0]
        needle = f"arm.toml: joint {first} pulses_per_rev: is missing: no drive given"
        for dialect in DIALECTS:
            for extra in ([], ["--no-motion"]):
                out, mp = tmp_path / f"p.{dialect}", tmp_path / "p.json"
                code, stdout, err = run(capsys, "stl", "--dialect", dialect, "--arm", path,
                                        "-o", out, "--map", mp, *extra)  # fmt: skip
                assert code == 2 and err.startswith("python -m analysis stl: error: ")
                assert needle in err and err.count("\n") == 1 and not stdout, err
                assert not out.exists() and not mp.exists()
        q = arm.sample_q(np.random.default_rng(1), 2)
        calls = ((generate, arm, "st"), (arm.pulses, q), (arm.from_pulses, np.zeros_like(q)),
                 (half_step_rad, arm), (machine_spec, arm))  # fmt: skip
        for call, *args in calls:
            with pytest.raises(NoDrive, match=f"joint {first} pulses_per_rev: is missing"):
                call(*args)


def test_a_prismatic_joint_s_drive_is_both_keys_or_none(tmp_path):
    """A prismatic joint's drive is pulses_per_rev and lead_mm: pulses without the lead is
    refused at load (naming lead_mm); the lead alone is no drive (pulses_per_rev named
    where one is needed). Its stroke is no part of a D-H table: rows alone with a prismatic
    row are refused naming the rule."""
    text = _text("cobra600")
    path = tmp_path / "arm.toml"
    path.write_text("".join(ln for ln in text.splitlines(keepends=True)
                            if not ln.startswith("lead_mm")))  # fmt: skip
    with pytest.raises(DescriptionError, match=r"joint d3 lead_mm: is missing: a prismatic "
                       "joint's drive is pulses_per_rev and lead_mm"):  # fmt: skip
        load_arm(str(path))
    path.write_text("".join(ln for ln in text.splitlines(keepends=True)
                            if not ln.startswith("pulses_per_rev")))  # fmt: skip
    arm = load_arm(str(path))
    assert not arm.has_drive and arm.description.joints[2].lead_mm == 10.0
    with pytest.raises(NoDrive, match="joint theta1 pulses_per_rev: is missing"):
        arm.pulses(np.zeros(4))
    path.write_text(rows_only(text))
    with pytest.raises(DescriptionError, match=r"\[\[joints\]\]: is missing, and D-H row d3 "
                       "is prismatic: its stroke is no part of a D-H table"):  # fmt: skip
        load_arm(str(path))


def test_the_schema_stays_strict_without_a_drive(tmp_path):
    """No drive loosens nothing else: an unknown or misspelt key, a bad type, a joint count
    that is not the rows', a description with neither rows nor joints: one line each."""
    base = without_drive(_text("planar2r"))
    cases = {
        "pulses_per_revs = 4000": "pulses_per_revs: unknown key; did you mean 'pulses_per_rev'",
        'pulses_per_rev = "4000"': "pulses_per_rev: ",
        "pulses_per_rev = 0": "pulses_per_rev: ",
        "pulses_per_rev = 4000.5": "pulses_per_rev: ",
    }
    path = tmp_path / "arm.toml"
    for line, needle in cases.items():
        path.write_text(base.replace('name = "theta1"\n', f'name = "theta1"\n{line}\n', 1))
        with pytest.raises(DescriptionError, match=re.escape(needle)) as exc:
            load_arm(str(path))
        assert "\n" not in str(exc.value) and str(exc.value).startswith("arm.toml: ")
    path.write_text(rows_only(base) + '\n[[joints]]\nname = "theta1"\n')
    with pytest.raises(DescriptionError, match="1 joints for 2 moving rows"):
        load_arm(str(path))
    head = base[: base.index("[[rows]]")]
    path.write_text('closed_form = "grabber"\n' + head)
    with pytest.raises(DescriptionError, match=r"\[\[joints\]\]: is missing"):
        load_arm(str(path))


def test_joints_out_of_the_rows_order_are_refused(tmp_path):
    """A [[joints]] entry names the joint its moving row names: entries swapped (theta2's
    stop given to theta1) are refused, naming both, where they used to load."""
    text = _text("planar2r").replace('name = "theta1"', 'name = "TMP"').replace(
        'name = "theta2"', 'name = "theta1"').replace('name = "TMP"', 'name = "theta2"')
    path = tmp_path / "arm.toml"
    path.write_text(text)
    with pytest.raises(DescriptionError, match=r"arm.toml: \[\[joints\]\] 1 name: 'theta2', "
                       "but moving D-H row 1 names its joint 'theta1'"):  # fmt: skip
        load_arm(str(path))


def test_rows_name_the_joints_or_take_the_d_h_names(tmp_path):
    """Without [[joints]], each moving row's joint is named as the row names it, else
    theta<i> (the D-H table's name): revolute, one turn either way, no drive."""
    text = rows_only(_text("planar3r")).replace('joint = "theta2"\n', "")
    path = tmp_path / "arm.toml"
    path.write_text(text)
    arm = load_arm(str(path))
    assert arm.joint_names == ("theta1", "theta2", "theta3") and arm.limits == (None,) * 3
    assert not arm.has_drive and arm.closed_form is not None  # derived: the 3R planar family
    q = np.radians([[30.0, -40.0, 20.0]])
    c, s = np.cos(np.radians([30, -10, 10])), np.sin(np.radians([30, -10, 10]))
    want = [400 * c[0] + 300 * c[1] + 100 * c[2], 400 * s[0] + 300 * s[1] + 100 * s[2]]
    assert np.allclose(arm.table.fk(q)[0, :2, 3], want, atol=1e-9)


def test_the_explorer_s_data_without_a_drive(tmp_path):
    """The explorer's data work (analysis.app.explore_logic): the same angles, no pulse
    columns, "pulses: no drive given" in its sentences."""
    from analysis.app.explore_logic import fk_line, plain_message, pose_report

    path = tmp_path / "arm.toml"
    path.write_text(without_drive(_text("planar2r")))
    arm, bare = load_arm("planar2r"), load_arm(str(path))
    reps = [pose_report(a, [1200.0, 500.0]) for a in (arm, bare)]
    assert reps[0].table.drop(columns=["c1", "c2", "error_mm"]).equals(
        reps[1].table.drop(columns=["error_mm"]))  # fmt: skip
    assert "c1" not in reps[1].table and "c1 [pulses]" not in reps[1].formatted()
    assert "pulses: no drive given" in plain_message(reps[1])
    q = np.radians([30.0, 40.0])
    assert "→ pulses: no drive given;" in fk_line(bare, q, reps[1])
    assert fk_line(bare, q, reps[1]).split(";")[1:] == fk_line(arm, q, reps[0]).split(";")[1:]


@pytest.mark.slow  # node, twice
def test_the_explorer_s_javascript_without_a_drive(tmp_path):
    """The arm's JavaScript module (analysis.app.explore_js, run by node where installed)
    solves as the arm with a drive and gives null pulses."""
    import shutil
    import subprocess

    from analysis.app.explore_js import arm_module_js

    path = tmp_path / "arm.toml"
    path.write_text(without_drive(_text("planar2r")))
    arm, bare = load_arm("planar2r"), load_arm(str(path))
    node = shutil.which("node")
    if node is None:
        pytest.skip("node is not installed: the arm's JavaScript module is not run here")
    out = []
    for a in (arm, bare):
        js = tmp_path / "m.js"
        js.write_text(f"const arm = {arm_module_js(a)};\nconst s = arm.solve([1200, 500]);\n"
                      "console.log(JSON.stringify([s.branches.righty.q, s.branches.righty.c, "
                      "arm.pulses([0.1, 0.2]), arm.pulses_per_rev]));\n")  # fmt: skip
        run_ = subprocess.run([node, str(js)], capture_output=True, text=True, timeout=60)
        out.append(json.loads(run_.stdout))
    assert out[0][0] == out[1][0] and out[0][1] == arm.pulses(np.array(out[0][0])).tolist()
    assert out[1][1:] == [None, None, None]


# --------------------------------------------------------------------------------------------
# the .py closed form: next to the description only (issue 27 item 3)
# --------------------------------------------------------------------------------------------
CLOSED_FORM = (data_dir().parent / "src" / "analysis" / "kinematics" / "arms" / "grabber.py")


@pytest.mark.parametrize("where", ["next to it", "a link next to it", "subfolder",
                                   "a link into a subfolder", "a link out", "dotdot"])  # fmt: skip
def test_a_py_closed_form_is_read_only_next_to_the_description(where, tmp_path):
    """``closed_form = "x.py"``: a plain file name in the description's own folder (the
    tables' rule), a link there resolving there; a subfolder, ``..`` and a link out or down
    are refused before anything is read (a marker file shows whether it ran)."""
    folder = tmp_path / "arm"
    (folder / "sub").mkdir(parents=True)
    marker = tmp_path / "ran"
    code = CLOSED_FORM.read_text() + f"\nopen({str(marker)!r}, 'w').write('x')\n"
    for place in (folder, folder / "sub", tmp_path):
        (place / "cf.py").write_text(code)
    name = {"next to it": "cf.py", "subfolder": "sub/cf.py", "dotdot": "../cf.py"}.get(where)
    if name is None:
        name = "link.py"
        target = {"a link next to it": folder / "cf.py", "a link out": tmp_path / "cf.py",
                  "a link into a subfolder": folder / "sub" / "cf.py"}[where]  # fmt: skip
        (folder / "link.py").symlink_to(target)
    desc = (data_dir() / "arms" / "grabber.toml").read_text()
    (folder / "arm.toml").write_text(desc.replace('closed_form = "grabber"',
                                                  f'closed_form = "{name}"'))  # fmt: skip
    if where in ("next to it", "a link next to it"):
        assert load_arm(str(folder / "arm.toml")).ik([100, 100, 600]).shape == (3,)
        assert marker.exists()
        return
    rule = {"subfolder": "a plain file name (no subfolder)", "dotdot": "no '..'"}.get(
        where, "resolves (through a symbolic link) outside the description's folder")
    with pytest.raises(DescriptionError, match=re.escape(rule)):
        load_arm(str(folder / "arm.toml"))
    assert not marker.exists(), "a file not next to the description was run"


def test_readme_says_what_an_arm_without_a_drive_does():
    readme = (Path(__file__).parents[2] / "README.md").read_text()
    for needle in ("no drive given", '"pulses": null', "arms --arm robot.urdf --toml"):
        assert needle in readme, needle

"""A user's own arm through every path, or refused clearly (issue 21 item 3).

The arms here are written as a user would: a description in the user's own folder (``--arm
PATH``), a closed form next to it or in ``analysis.kinematics.arms`` (the README's "add an
arm" steps, followed literally), 1 to 6 inputs, revolute and prismatic joints. Each goes
through ``fk``, ``ik`` (single and batch), the compiled backend, ``stl`` in every dialect,
the explorer's model and Pinocchio; what a closed form gets wrong is refused when the arm
loads, with the missing or malformed piece named.

Nothing here depends on the list of files in ``data/arms``: the data folder is a copy
(``ANALYSIS_DATA_DIR``) where a test adds or breaks a file.
"""

from __future__ import annotations

import json
import shutil
import textwrap
from pathlib import Path

import numpy as np
import pytest

from analysis.app.cli import main
from analysis.kinematics import arms as arms_pkg
from analysis.kinematics.arm import load_arm
from analysis.kinematics.status import Status
from analysis.paths import PROJECT

README = PROJECT / "README.md"

# --------------------------------------------------------------------------------------------
# a planar 2R arm with two inputs, its closed form written by the user
# --------------------------------------------------------------------------------------------
PLANAR_2R = '''
"""A planar 2R arm: two inputs (px, py), elbow up or down."""
from analysis.kinematics.status import Status

BRANCHES = ("elbow-up", "elbow-down")
INPUTS = ("px", "py")
INPUT_UNITS = ("mm", "mm")
STATUSES = (Status.OUT_OF_REACH, Status.INSIDE_REACH, Status.DEGENERATE)
STARTUP_TARGET = (300.0, 100.0)


def check(P):
    for k in ("a1", "a2"):
        if not P[k] > 0:
            raise ValueError(f"{k} = {P[k]} mm must be > 0 mm")


def geometry(P):
    return {"reach_outer": P["a1"] + P["a2"], "reach_inner": abs(P["a1"] - P["a2"])}


def ik(m, p, P, *, tol, axis_tol=None):
    x, y = p
    a1, a2 = P["a1"], P["a2"]
    outer = a1 + a2
    inner = abs(a1 - a2)                      # Python's abs(): every backend takes it
    out_box = m.or_(m.gt(abs(x), outer + tol), m.gt(abs(y), outer + tol))
    d2 = x**2 + y**2                          # and **
    d = m.sqrt(d2)
    c2 = m.clip((d2 - (a1 * a1 + a2 * a2)) / (2.0 * a1 * a2), -1.0, 1.0)
    t2 = m.acos(c2)
    branches = {}
    for name, sign in (("elbow-up", -1.0), ("elbow-down", 1.0)):
        q2 = sign * t2
        q1 = m.wrap(m.atan2(y, x) - m.atan2(a2 * m.sin(q2), a1 + a2 * m.cos(q2)))
        branches[name] = (q1, q2)
    beyond, within = d - outer, inner - d
    refusals = [
        (Status.OUT_OF_REACH, m.or_(out_box, m.gt(beyond, tol))),
        (Status.INSIDE_REACH, m.gt(within, tol)),
        (Status.DEGENERATE, m.le(d, tol if axis_tol is None else axis_tol)),
    ]
    return {"branches": branches, "refusals": refusals,
            "outside": m.select(m.gt(beyond, within), beyond, within)}


def refusal(status, p, P, *, tol, distance):
    g = geometry(P)
    limit = g["reach_outer"] if status == Status.OUT_OF_REACH else g["reach_inner"]
    return f"target {tuple(float(v) for v in p)} mm: {status.text} by {distance:.3f} mm", limit
'''

PLANAR_2R_TOML = """
name = "planar2r"
title = "a planar 2R arm of mine"
closed_form = "{closed_form}"
convention = "standard"

[parameters]
a1 = {{ value = 300.0, unit = "mm", status = "measured", source = "tape measure" }}
a2 = {{ value = 200.0, unit = "mm", status = "measured", source = "tape measure" }}

[[rows]]
link = "upper"
joint = "theta1"
alpha_deg = 0
a = "a1"
d = 0

[[rows]]
link = "fore"
joint = "theta2"
alpha_deg = 0
a = "a2"
d = 0

[[joints]]
name = "theta1"
pulses_per_rev = 4000

[[joints]]
name = "theta2"
pulses_per_rev = 4000
limits_deg = [-170, 170]
"""

# a 1-input arm: one prismatic joint (a lift), D-H row kind "prismatic", input pz
LIFT = """
from analysis.kinematics.status import Status

BRANCHES = ("up",)
INPUTS = ("pz",)
INPUT_UNITS = ("mm",)
STATUSES = ()
STARTUP_TARGET = None


def check(P):
    pass


def geometry(P):
    return {}


def ik(m, p, P, *, tol):
    (z,) = p
    return {"branches": {"up": (z - P["d0"],)}, "refusals": [], "outside": z * 0.0 - 1.0}


def refusal(status, p, P, *, tol, distance):
    raise ValueError(f"no message for status {status!r}")
"""

LIFT_TOML = """
name = "lift"
title = "a one-axis lift"
closed_form = "lift.py"

[parameters]
d0 = { value = 150.0, unit = "mm", status = "assumed", note = "base height" }

[[rows]]
joint = "q1"
kind = "prismatic"
alpha_deg = 0
a = 0
d = "d0"

[[joints]]
name = "q1"
kind = "prismatic"
pulses_per_rev = 3200
lead_mm = 5.0
limits_mm = [0, 800]
"""


def _folder(tmp_path: Path, toml: str, module: str | None, name: str) -> Path:
    """A user's folder with their description (and closed form)."""
    folder = tmp_path / "my_arms"
    folder.mkdir(exist_ok=True)
    if module is not None:
        (folder / f"{name}.py").write_text(textwrap.dedent(module), encoding="utf-8")
    path = folder / f"{name}.toml"
    path.write_text(toml, encoding="utf-8")
    return path


@pytest.fixture
def planar(tmp_path) -> Path:
    return _folder(tmp_path, PLANAR_2R_TOML.format(closed_form="planar2r.py"), PLANAR_2R,
                   "planar2r")  # fmt: skip


@pytest.fixture
def data_copy(tmp_path, monkeypatch) -> Path:
    """A copy of data/ that the test may change, as ANALYSIS_DATA_DIR."""
    data = tmp_path / "data"
    shutil.copytree(PROJECT / "data", data)
    monkeypatch.setenv("ANALYSIS_DATA_DIR", str(data))
    return data


def _json(capsys, *argv) -> dict:
    assert main([*argv, "--json"]) == 0, capsys.readouterr()
    return json.loads(capsys.readouterr().out)


# --------------------------------------------------------------------------------------------
# the README's steps
# --------------------------------------------------------------------------------------------
def _readme_section() -> str:
    text = README.read_text(encoding="utf-8")
    return text.split("## One source per arm (and how to add one)")[1].split("\n## ")[0]


def _blocks(section: str, lang: str) -> list[str]:
    return [b.split("\n", 1)[1] for b in section.split("```")[1::2] if b.startswith(lang)]


def test_readme_step_a_toml_alone_for_a_3r_arm_with_other_lengths(tmp_path, monkeypatch, capsys):
    """The README's TOML and commands, literally: a description in my own folder with
    ``closed_form = "grabber"`` and other lengths is all a 3R arm needs (fk, ik, stl by
    ``--arm PATH``); then batch, the other dialect and the compiled backend on it. The README
    names the backend as the API does ("compiled")."""
    section = _readme_section()
    assert 'backend="compiled"' in section
    (toml,) = _blocks(section, "toml")
    (commands,) = _blocks(section, "sh")
    where = toml.splitlines()[0].lstrip("# ").strip()
    assert where == "my_arms/mine.toml" and 'closed_form = "grabber"' in toml
    monkeypatch.chdir(tmp_path)
    (tmp_path / "my_arms").mkdir()
    (tmp_path / where).write_text(toml, encoding="utf-8")
    for line in commands.strip().splitlines():
        argv = line.split()
        assert argv[:3] == ["python", "-m", "analysis"]
        assert main(argv[3:]) == 0, (line, capsys.readouterr().err)
    out = capsys.readouterr().out
    assert "theta = (30.00, 20.00, -50.00) deg -> P = " in out and "front-up" in out
    arm = load_arm(where)
    assert (arm.name, arm.params.L2, arm.description.parameters["L2"].status) == (
        "mine", 400.0, "measured",
    )  # fmt: skip
    assert "L2 = 400 mm" in (tmp_path / "mine.awl").read_text()
    q = np.radians([30.0, 20.0, -50.0])
    doc = _json(capsys, "ik", *(f"{v:.9f}" for v in arm.fk(q)), "--arm", where)
    np.testing.assert_allclose(doc["solutions"][0]["theta_deg"], np.degrees(q), atol=1e-6)
    assert doc["solutions"][0]["pulses"] == arm.pulses(q).tolist()
    _json(capsys, "stl", "--dialect", "s7-200", "--arm", where, "-o", "mine200.awl",
          "--map", "mine200.json")  # fmt: skip
    t = arm.fk(arm.sample_q(np.random.default_rng(3), 200))
    sol, ref = arm.solve(t, backend="compiled"), arm.solve(t)
    np.testing.assert_array_equal(sol.status, ref.status)
    np.testing.assert_allclose(np.nan_to_num(sol.theta), np.nan_to_num(ref.theta), atol=1e-12)


def test_readme_step_b_a_new_closed_form_in_the_package(data_copy, tmp_path, monkeypatch, capsys):
    """Step B, literally: data/arms/<name>.toml and kinematics/arms/<name>.py (the package's
    folder extended with a temporary one); then load_arm, numpy and compiled, ``ik/stl
    --arm <name>``, ``arms``; and the picker's register does not change (errata --check)."""
    pkg_dir = tmp_path / "pkg"
    pkg_dir.mkdir()
    (pkg_dir / "planar2r.py").write_text(textwrap.dedent(PLANAR_2R), encoding="utf-8")
    monkeypatch.setattr(arms_pkg, "__path__", [*arms_pkg.__path__, str(pkg_dir)])
    (data_copy / "arms" / "planar2r.toml").write_text(
        PLANAR_2R_TOML.format(closed_form="planar2r"), encoding="utf-8"
    )
    try:
        arm = load_arm("planar2r")
        p = np.array([[300.0, 100.0], [420.0, -150.0], [10.0, 5.0], [900.0, 0.0]])
        numpy_sol, compiled_sol = arm.solve(p), arm.solve(p, backend="compiled")
        np.testing.assert_array_equal(numpy_sol.status, compiled_sol.status)
        assert numpy_sol.status.tolist() == [0, 0, Status.INSIDE_REACH, Status.OUT_OF_REACH]
        doc = _json(capsys, "ik", "300", "100", "--arm", "planar2r", "--branch", "all")
        assert [s["branch"] for s in doc["solutions"]] == ["elbow-up", "elbow-down"]
        listed = {d["name"]: d for d in _json(capsys, "arms")}
        assert listed["planar2r"]["joints"] == ["theta1", "theta2"]
        assert listed["planar2r"]["parameters"]["a1"]["status"] == "measured"
        out = tmp_path / "p.awl"
        _json(capsys, "stl", "--dialect", "s7-300", "--arm", "planar2r", "-o", str(out),
              "--map", str(tmp_path / "p.json"))  # fmt: skip
        assert main(["errata", "--check", "--paper", "picker"]) == 0
        assert "up to date" in capsys.readouterr().out
    finally:
        import sys

        sys.modules.pop("analysis.kinematics.arms.planar2r", None)
        arms_pkg.from_module.cache_clear()


# --------------------------------------------------------------------------------------------
# a planar 2R arm with two inputs, in the user's own folder
# --------------------------------------------------------------------------------------------
def test_planar_2r_through_every_path(planar, tmp_path, capsys):
    """fk, ik, batch, compiled, stl in both dialects (its STARTUP_TARGET has two values: the
    old default of three crashed the emitter), the explorer's model and widget, Pinocchio."""
    from analysis.app.explore import Explorer
    from analysis.app.explore_logic import default_target, pose_report
    from analysis.kinematics.pinocchio_model import PinocchioArm

    arm = load_arm(str(planar))
    assert arm.inputs == ("px", "py") and arm.startup_target == (300.0, 100.0)
    q = arm.sample_q(np.random.default_rng(7), 500)
    t = arm.target(q)
    sol = arm.solve(t)
    ok = sol.ok.any(axis=-1)
    assert ok.all()
    for b in range(2):  # FK(IK) = the target on every branch that solves
        good = sol.ok[:, b]
        np.testing.assert_allclose(arm.target(sol.theta[good, b]), t[good], atol=1e-9)
    comp = arm.solve(t, backend="compiled")
    np.testing.assert_allclose(np.nan_to_num(comp.theta), np.nan_to_num(sol.theta), atol=1e-12)
    pin = PinocchioArm(arm.table)
    np.testing.assert_allclose(pin.fk(q[:50]), arm.fk(q[:50]), atol=1e-9)
    for dialect in ("s7-200", "s7-300"):
        doc = _json(capsys, "stl", "--dialect", dialect, "--arm", str(planar),
                    "-o", str(tmp_path / "2r.awl"), "--map", str(tmp_path / "2r.json"))  # fmt: skip
        assert doc["lines"] > 50
        mmap = json.loads((tmp_path / "2r.json").read_text())
        assert list(mmap["inputs"]) == ["px", "py"]
    rep = pose_report(arm, default_target(arm))
    assert rep.reachable and list(rep.table.columns[:2]) == ["theta1_deg", "theta2_deg"]
    ex = Explorer(str(planar))
    assert len(ex.target_sliders) == 2 and "ok" in ex.message.value
    ex.fk_mode.value = True
    assert "FK: joints (" in ex.message.value
    src, out = tmp_path / "t.csv", tmp_path / "o.csv"
    src.write_text("x_mm,y_mm\n300,100\n900,0\n")
    assert main(["ik", "--arm", str(planar), "--input", str(src), "--output", str(out)]) == 0
    lines = out.read_text().splitlines()
    assert lines[0].startswith("x_mm,y_mm,branch,reachable,theta1_deg,theta2_deg,c1,c2")
    assert lines[2].split(",")[-2] == "out-of-reach"  # status, then the (empty) reason


def test_a_one_input_prismatic_lift(tmp_path, capsys):
    """One input, one prismatic D-H row: fk and ik in mm, pulses through the lead, Pinocchio
    (a PZ joint), the PLC program with one input."""
    from analysis.kinematics.pinocchio_model import PinocchioArm

    path = _folder(tmp_path, LIFT_TOML, LIFT, "lift")
    arm = load_arm(str(path))
    assert arm.joint_units == ("mm",) and arm.joint_labels == ("q1_mm",)
    q = arm.sample_q(np.random.default_rng(1), 100)
    assert ((q >= 0) & (q <= 800)).all()
    np.testing.assert_allclose(arm.fk(q)[:, 2], q[:, 0] + 150.0, atol=1e-12)
    np.testing.assert_allclose(PinocchioArm(arm.table).fk(q), arm.fk(q), atol=1e-12)
    assert arm.pulses([[12.5]]).tolist() == [[8000]]  # 12.5 mm / 5 mm * 3200
    doc = _json(capsys, "ik", "400", "--arm", str(path))
    assert doc["solutions"][0]["joint_values"] == [250.0]
    assert doc["solutions"][0]["pulses"] == [160_000]
    assert main(["ik", "1000", "--arm", str(path)]) == 2  # beyond the 800 mm stroke
    assert "joint limits" in capsys.readouterr().err
    fk = _json(capsys, "fk", "250", "--arm", str(path))
    assert fk["position_mm"] == [0.0, 0.0, 400.0] and fk["joint_units"] == ["mm"]
    _json(capsys, "stl", "--dialect", "s7-200", "--arm", str(path), "-o", str(tmp_path / "l.awl"),
          "--map", str(tmp_path / "l.json"))  # fmt: skip


# --------------------------------------------------------------------------------------------
# refused clearly
# --------------------------------------------------------------------------------------------
def _broken(tmp_path, replace: tuple[str, str], module: str = PLANAR_2R) -> Path:
    bad = module.replace(*replace)
    assert bad != module
    return _folder(tmp_path, PLANAR_2R_TOML.format(closed_form="planar2r.py"), bad, "planar2r")


@pytest.mark.parametrize(
    ("replace", "message"),
    [
        (('INPUT_UNITS = ("mm", "mm")\n', ""), r"lacks INPUT_UNITS \(units of INPUTS"),
        (("STARTUP_TARGET = (300.0, 100.0)\n", ""), "lacks STARTUP_TARGET"),
        (
            ("STARTUP_TARGET = (300.0, 100.0)", "STARTUP_TARGET = (100.0, 100.0, 600.0)"),
            r"STARTUP_TARGET = \(100.0, 100.0, 600.0\) must be None or 2 finite numbers",
        ),
        (
            ('INPUT_UNITS = ("mm", "mm")', 'INPUT_UNITS = ("mm", "deg")'),
            "INPUT_UNITS = .* must give one of",
        ),
        (("STATUSES = (", "STATUSES = (Status.OK, "), r"STATUSES lists \['OK'\], which the shared"),
        (
            ("(Status.DEGENERATE, m.le", "(Status.BASE_AXIS, m.le"),
            "refuses with BASE_AXIS, which STATUSES does not list",
        ),
        (
            ("    x, y = p\n", "    x, y = p\n    if x > 0:\n        pass\n"),
            "cannot be recorded for the compiled and PLC backends .TypeError: '>' not supported",
        ),
        (
            ("branches[name] = (q1, q2)", "branches[name] = (q1,)"),
            "gives 1 joint values per branch; the description has 2 joints",
        ),
        (
            ("def ik(m, p, P, *, tol, axis_tol=None)", "def ik(m, p, P, tol, axis_tol=None)"),
            "ik must take the keyword argument tol",
        ),
        (
            ("import Status\n", "import Status\nraise RuntimeError('oops')\n"),
            "does not import: RuntimeError: oops",
        ),
    ],
)
def test_a_broken_closed_form_is_refused_when_the_arm_loads(tmp_path, replace, message):
    with pytest.raises(ValueError, match=message):
        load_arm(str(_broken(tmp_path, replace)))


def test_a_closed_form_file_leaves_nothing_next_to_the_description(planar, monkeypatch):
    """Loading a ``.py`` closed form runs it but writes nothing: no ``__pycache__`` with its
    bytecode in the user's folder (issue 27.6: nothing created that was not asked for), even
    where Python would write bytecode (PYTHONDONTWRITEBYTECODE unset)."""
    import sys

    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    before = sorted(p.name for p in planar.parent.iterdir())
    arm = load_arm(str(planar))
    assert np.isfinite(arm.fk(np.radians([30.0, 40.0]))).all()
    assert sorted(p.name for p in planar.parent.iterdir()) == before


def test_a_closed_form_file_is_read_bounded(tmp_path):
    """A ``.py`` closed form larger than the loader reads (1 MiB, as a description) is
    refused in one line naming the limit, before any of it runs."""
    from analysis.kinematics.arms import CLOSED_FORM_BYTES

    marker = tmp_path / "ran"
    code = f"open({str(marker)!r}, 'w').write('x')\n" + "#" * CLOSED_FORM_BYTES + "\n"
    path = _folder(tmp_path, PLANAR_2R_TOML.format(closed_form="planar2r.py"),
                   code + PLANAR_2R, "planar2r")  # fmt: skip
    with pytest.raises(ValueError, match=r"larger than 1,048,576 bytes"):
        load_arm(str(path))
    assert not marker.exists()


def test_theta1_on_axis_for_an_arm_without_it_is_an_error(planar):
    arm = load_arm(str(planar))
    with pytest.raises(ValueError, match="has no base-axis singularity"):
        arm.solve([300.0, 100.0], theta1_on_axis=0.0)


def test_arms_lists_every_arm_when_one_description_is_broken(data_copy, capsys):
    """A status other than printed/derived/assumed/measured breaks only that arm: ``arms``
    lists the others and says why the one does not load; "measured" is a status."""
    good = (data_copy / "arms" / "palletizer.toml").read_text(encoding="utf-8")
    (data_copy / "arms" / "broken.toml").write_text(
        good.replace('status = "assumed"', 'status = "guessed"', 1), encoding="utf-8"
    )
    (data_copy / "arms" / "measured.toml").write_text(
        good.replace('status = "assumed"', 'status = "measured"'), encoding="utf-8"
    )
    assert main(["arms"]) == 0
    out = capsys.readouterr().out
    lines = {line.split()[0]: line for line in out.splitlines()}
    assert {"grabber", "palletizer", "picker", "gr1", "measured"} <= set(lines)
    assert "not loadable" in lines["broken"] and "status: 'guessed'" in lines["broken"]
    docs = {d["name"]: d for d in _json(capsys, "arms")}
    assert docs["measured"]["parameters"]["L1"]["status"] == "measured"
    assert "error" in docs["broken"] and "error" not in docs["palletizer"]


def test_arm_by_path_errors_name_the_file(tmp_path, capsys):
    missing = tmp_path / "nowhere.toml"
    assert main(["ik", "1", "2", "3", "--arm", str(missing)]) == 2
    assert f"no arm description {str(missing)!r}: no such file" in capsys.readouterr().err
    assert main(["ik", "1", "2", "3", "--arm", "nosuch"]) == 2
    err = capsys.readouterr().err
    assert "no arm 'nosuch'" in err and "grabber" in err and "path of a description" in err

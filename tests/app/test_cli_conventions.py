"""Issue 23 item 5 (the command line's conventions) and issue 19's reproductions, one by one,
as a user types them (in-process: ``analysis.app.cli.main``). The classes behind them are
closed by the properties of tests/hostile."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from analysis.app.cli import main
from analysis.kinematics.arm import load_arm
from analysis.paths import data_dir


def run(capsys, *argv: str) -> tuple[int, str, str]:
    try:
        code = main(list(argv))
    except SystemExit as exc:
        code = exc.code
    out, err = capsys.readouterr()
    return code, out, err


def test_version(capsys):
    code, out, _ = run(capsys, "--version")
    assert code == 0 and out.startswith("python -m analysis 0.")


def test_a_leading_minus_needs_no_double_dash(capsys):
    code, _, err = run(capsys, "ik", "-1e3", "0", "600")
    assert code == 2 and "target (-1000, 0, 600) mm is 491.798 mm beyond the reach" in err
    code, out, _ = run(capsys, "ik", "-1.5e2", "2.2e2", "4.8e2", "--json")
    assert code == 0 and json.loads(out)["target"] == [-150.0, 220.0, 480.0]


def test_stl_without_map_and_to_stdout(tmp_path, capsys):
    prog = tmp_path / "p.awl"
    code, out, _ = run(capsys, "stl", "--dialect", "s7-300", "-o", str(prog))
    assert code == 0 and prog.exists() and "no MAP.json" in out
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.awl"]
    code, out, err = run(capsys, "stl", "--dialect", "s7-300", "-o", "-")
    assert code == 0 and out == prog.read_text() and "wrote -" in err
    code, out, _ = run(capsys, "stl", "--dialect", "s7-300", "-o", "-", "--json")
    assert code == 2 and "cannot share it" in json.loads(out)["error"]


def test_stl_layout_that_is_not_a_map_is_one_line(tmp_path, capsys):
    layout = tmp_path / "L.json"
    for text, needle in (("[]", "a memory map is a JSON object"), ("{", "not valid JSON"),
                         ('{"inputs": 3}', "L.json")):  # fmt: skip
        layout.write_text(text)
        code, _, err = run(capsys, "stl", "--dialect", "s7-300", "-o", str(tmp_path / "p.awl"),
                           "--layout", str(layout))  # fmt: skip
        assert code == 2 and needle in err and err.count("\n") == 1, err
    assert not (tmp_path / "p.awl").exists()


def test_stl_theta1_on_axis_and_params_never_bake_inf(tmp_path, capsys):
    prog = tmp_path / "p.awl"
    code, _, err = run(capsys, "stl", "--dialect", "s7-300", "-o", str(prog),
                       "--theta1-on-axis", "1e308")  # fmt: skip
    assert code == 0, err
    assert "inf" not in prog.read_text().lower().replace("information", "")
    t3 = tmp_path / "t3.csv"
    t3.write_text((data_dir() / "table3.csv").read_text().replace(",660,", ",1e200,"))
    code, _, err = run(capsys, "stl", "--dialect", "s7-300", "-o", str(tmp_path / "q.awl"),
                       "--params", str(t3))  # fmt: skip
    assert code == 2 and "L1 = 1e+200 mm is beyond 1e+06 mm" in err


def test_errata_json(capsys):
    code, out, err = run(capsys, "errata", "--check", "--paper", "picker", "--json")
    assert (code, json.loads(out)) == (0, {"up_to_date": True, "stale": [], "findings": []}), err
    code, out, _ = run(capsys, "errata", "--paper", "picker", "--json")
    rows = json.loads(out)["picker"]
    assert code == 0 and any(r["id"] == "pick-units" for r in rows)


def test_delimiter_sniffed_or_hinted(tmp_path, capsys):
    src = tmp_path / "in.csv"
    src.write_text("x_mm;y_mm;z_mm\n100;100;600\n")
    out = tmp_path / "o.csv"
    code, _, err = run(capsys, "ik", "--input", str(src), "--output", str(out))
    assert code == 0 and "1 solved" in err
    code, _, err = run(capsys, "ik", "--input", str(src), "--output", str(out),
                       "--delimiter", ",")  # fmt: skip
    assert code == 2 and "looks ';'-separated" in err and "--delimiter ';'" in err


def test_fk_hints_at_radians(capsys):
    code, out, err = run(capsys, "fk", "0.785", "0.178", "-2.707")
    assert code == 0 and "note:" in err and "(44.98, 10.20, -155.10)" in err
    code, out, err = run(capsys, "fk", "0.785", "0.178", "-2.707", "--json")
    assert code == 0 and "note" not in out and json.loads(out)["joint_values"][0] == 0.785
    code, _, err = run(capsys, "fk", "45", "10.21", "-155.13")
    assert code == 0 and err == ""


def test_branch_all_says_how_many_and_why_one_is_missing(capsys):
    code, out, _ = run(capsys, "ik", "250", "0", "100", "--arm", "palletizer", "--branch", "all")
    assert code == 0
    assert "palletizer has 4 branches; 1 of the 4 requested solve this target" in out
    assert "front-down no solution: joint-limits (theta3 = -97.98 deg outside [90, 180] deg)" in out
    code, out, _ = run(capsys, "ik", "250", "0", "100", "--arm", "palletizer", "--branch", "all",
                       "--json")  # fmt: skip
    doc = json.loads(out)
    assert doc["branches"] == 4 and [m["branch"] for m in doc["missing"]] == [
        "front-down", "back-up", "back-down"]  # fmt: skip


def test_output_dash_never_makes_a_file_named_dash(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    src = tmp_path / "in.csv"
    src.write_text("x_mm,y_mm,z_mm\n100,100,600\n")
    code, out, _ = run(capsys, "ik", "--input", str(src), "--output", "-")
    assert code == 0 and out.startswith("x_mm,y_mm,z_mm,branch") and not (tmp_path / "-").exists()


# --- issue 19's reproductions -----------------------------------------------------------------
def test_json_is_valid_and_warnings_stay_off_stdout(capsys):
    code, out, err = run(capsys, "ik", "1e200", "0", "0", "--json")
    assert code == 2 and "Infinity" not in out and "NaN" not in out
    assert json.loads(out)["error"].startswith("target: px = 1e+200 mm is beyond")
    assert err == ""


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (lambda a: a.solve([10**400, 0, 0]), "beyond the float range"),
        (lambda a: a.solve([0, 0, 900], theta1_on_axis=1j), "is complex"),
        (lambda a: a.solve([100, 100, 600], branches=None), "branches = None"),
        (lambda a: a.solve(np.array([100 + 1j, 100, 600])), "holds complex"),
        (lambda a: a.solve(np.ma.masked_array([100.0, 100, 600], [0, 1, 0])), "masked"),
        (lambda a: a.with_(L2=1e200, L3=1e200).solve([[100, 100, 600]]),
         r"L2 = 1e\+200 mm is beyond 1e\+06 mm, the largest length"),
    ],
)
def test_the_api_raises_value_errors_naming_the_value(call, needle):
    with pytest.raises(ValueError, match=needle):
        call(load_arm())


def test_arm_descriptions_with_holes_are_one_line_errors(tmp_path, capsys):
    base = (data_dir() / "arms" / "palletizer.toml").read_text()
    cases = {
        # no drive is no hole for ik (an engineer's D-H table): stl refuses it, naming the key
        "no pulses_per_rev": (base.replace('pulses_per_rev = { value = 3200, status = "assumed" }',
                                           "", 1), "joint theta1 pulses_per_rev: is missing"),
        "no joint name": (base.replace('name = "theta1"\n', "", 1), "1 name: None is not text"),
        "a list for a number": (base.replace("alpha_deg = -90", "alpha_deg = [-90]", 1),
                                "is not a real number"),
        "a list for a length": (base.replace("L1 = { value = 200.0", "L1 = { value = [200.0]", 1),
                                "[200.0] (list) is not a real number"),
        "a string for a limit": (
            base.replace("limits_deg = [-180, 180]", 'limits_deg = ["-180", 180]', 1), "is text"
        ),
    }
    (tmp_path / "arms").mkdir()
    for name, (text, needle) in cases.items():
        path = tmp_path / "arms" / "palletizer.toml"
        path.write_text(text)
        command = ["ik", "250", "0", "100"]
        if name == "no pulses_per_rev":
            assert run(capsys, *command, "--arm", str(path))[0] == 0
            command = ["stl", "--dialect", "st", "-o", str(tmp_path / "p.st")]
        code, _, err = run(capsys, *command, "--arm", str(path))
        assert code == 2 and needle in err and err.count("\n") == 1, (name, err)


def test_theta1_on_axis_in_the_api_wraps():
    arm = load_arm()
    sol = arm.solve([0.0, 0.0, 900.0], theta1_on_axis=4 * math.pi + 0.5)
    assert sol.theta[0, 0] == pytest.approx(0.5, abs=1e-12)

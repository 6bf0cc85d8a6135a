"""The command line contract (README): outputs, exit status 2 and one-line reasons."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from analysis.app.cli import main
from analysis.kinematics.arm import BRANCHES
from analysis.kinematics.params import data_dir


def run(capsys, *argv: str) -> tuple[int, str, str]:
    try:
        code = main(list(argv))
    except SystemExit as exc:  # argparse errors and --help
        code = exc.code
    out, err = capsys.readouterr()
    return code, out, err


def test_module_entry_point_runs_as_documented():
    """`python -m analysis ik 100 100 600 --json` in a real subprocess (the README command)."""
    proc = subprocess.run(
        [sys.executable, "-m", "analysis", "ik", "100", "100", "600", "--json"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr
    doc = json.loads(proc.stdout)
    assert doc["target"] == [100.0, 100.0, 600.0]
    assert doc["reachable"] is True
    (sol,) = doc["solutions"]
    assert sol["branch"] == "front-up"
    # issue 2: front-up (45.00, 10.21, -155.13) deg
    assert np.round(sol["theta_deg"], 2).tolist() == [45.0, 10.21, -155.13]
    # eqs. 20-22: theta / 360 * 4000, rounded: 500, 113.4 -> 113, -1723.66 -> -1724
    assert sol["pulses"] == [500, 113, -1724]


def test_ik_unreachable_exits_2_with_distance(capsys):
    code, out, err = run(capsys, "ik", "200", "500", "600")
    assert code == 2 and out == ""
    assert err.count("\n") == 1, "the reason must be one line"
    assert "31.849 mm beyond the reach of 510 mm" in err


def test_ik_inside_inner_radius(capsys):
    code, _, err = run(capsys, "ik", "0", "50", "660")
    assert code == 2
    assert "inside the inner reach radius of 110 mm" in err


def test_ik_base_axis_needs_theta1(capsys):
    code, _, err = run(capsys, "ik", "0", "0", "900")
    assert code == 2 and "base axis" in err and "--theta1-on-axis" in err
    code, out, _ = run(
        capsys, "ik", "0", "0", "900", "--theta1-on-axis", "30", "--json", "--branch", "all"
    )
    assert code == 0
    sols = json.loads(out)["solutions"]
    assert [s["branch"] for s in sols] == list(BRANCHES)
    assert sols[0]["theta_deg"][0] == pytest.approx(30.0)
    assert sols[2]["theta_deg"][0] == pytest.approx(-150.0)


def test_ik_all_branches_round_trip_through_fk(capsys):
    code, out, _ = run(capsys, "ik", "-150", "220", "480", "--branch", "all", "--json")
    assert code == 0
    for sol in json.loads(out)["solutions"]:
        code, fk_out, _ = run(capsys, "fk", *map(str, sol["theta_deg"]), "--json")
        assert code == 0
        np.testing.assert_allclose(json.loads(fk_out)["position_mm"], [-150, 220, 480], atol=1e-9)


def test_fk_text_and_json(capsys):
    code, out, _ = run(capsys, "fk", "0", "0", "0", "--json")
    assert code == 0
    # stretched horizontal arm: (L2 + L3, 0, L1) from Table 3
    np.testing.assert_allclose(json.loads(out)["position_mm"], [510.0, 0.0, 660.0], atol=1e-12)
    code, out, _ = run(capsys, "fk", "90", "90", "0")
    assert code == 0 and "(0.000, 0.000, 1170.000) mm" in out.replace("-0.000", "0.000")


@pytest.mark.parametrize(
    "argv, needle",
    [
        (("ik", "nan", "1", "2"), "'nan' is not a finite number"),
        (("ik", "inf", "1", "2"), "'inf' is not a finite number"),
        (("ik", "abc", "1", "2"), "'abc' is not a number"),
        (("ik", "1", "2"), "give a target X Y Z"),
        (("fk", "1", "2", "x"), "'x' is not a number"),
        (("ik", "1", "2", "3", "--branch", "sideways"), "unknown branch"),
        (("ik", "--input", "only.csv"), "needs both --input"),
    ],
)
def test_bad_arguments_exit_2_one_line(capsys, argv, needle):
    code, _, err = run(capsys, *argv)
    assert code == 2
    assert needle in err
    assert err.strip().count("\n") == 0 or "usage:" in err  # argparse prints usage + one error line
    assert err.strip().splitlines()[-1].count(needle) == 1


def test_batch_table4_all_branches(tmp_path, capsys, arm):
    out_csv = tmp_path / "out.csv"
    code, _, err = run(
        capsys,
        "ik",
        "--input",
        str(data_dir() / "table4.csv"),
        "--output",
        str(out_csv),
        "--branch",
        "all",
    )
    assert code == 0, err
    df = pd.read_csv(out_csv)
    assert len(df) == 10 * 4
    assert list(df.columns[-10:]) == [
        "branch",
        "reachable",
        "theta1_deg",
        "theta2_deg",
        "theta3_deg",
        "c1",
        "c2",
        "c3",
        "status",
        "reason",
    ]
    # the input's own printed-angle columns are kept, renamed, not overwritten
    assert "input_theta2_deg" in df.columns
    row8 = df[df["row"] == 8]
    assert (~row8["reachable"]).all() and row8[["theta1_deg", "c1"]].isna().all().all()
    assert set(row8["status"]) == {"out-of-reach"}
    ok = df[df["reachable"]]
    assert not ok[["theta1_deg", "theta2_deg", "theta3_deg", "c1", "c2", "c3"]].isna().any().any()
    # every batch solution lands on its target (FK independent of the CSV path)
    p = arm.fk(np.radians(ok[["theta1_deg", "theta2_deg", "theta3_deg"]].to_numpy()))
    np.testing.assert_allclose(
        p, ok[["x_mm", "y_mm", "z_mm"]].to_numpy(), atol=1e-9
    )  # the angles in full (the shortest text of each float)
    fu = ok[ok["branch"] == "front-up"].set_index("row")
    assert fu.loc[1, ["c1", "c2", "c3"]].tolist() == [500, 113, -1724]


@pytest.mark.parametrize(
    "content, needle",
    [
        ("x_mm,y_mm\n1,2\n", "missing required column(s) z_mm"),
        ("x_mm,y_mm,z_mm\n1,2,abc\n", "line 2 column z_mm: 'abc' is not a number"),
        ("x_mm,y_mm,z_mm\n1,2,3\n4,,6\n", "line 3 column y_mm: empty cell"),
        ("x_mm,y_mm,z_mm\n1,2,nan\n", "column z_mm: 'nan' is not a finite number"),
        ("x_mm,y_mm,z_mm\n1,2,inf\n", "column z_mm: 'inf' is not a finite number"),
        ("", "no header line"),
        ("x_mm,y_mm,z_mm\n\n1,2,3\n7,200,0,700\n", "line 4: 4 field(s) where the header"),
        ("x_mm,x_mm,z_mm\n1,2,3\n", "column 'x_mm' appears twice"),
    ],
)
def test_batch_bad_csv_exit_2(tmp_path, capsys, content, needle):
    """--strict: the first bad row stops the batch, naming line and column; nothing written."""
    src = tmp_path / "in.csv"
    src.write_text(content)
    argv = ("ik", "--input", str(src), "--output", str(tmp_path / "o.csv"), "--strict")
    code, _, err = run(capsys, *argv)
    assert code == 2
    assert needle in err and err.count("\n") == 1
    assert not (tmp_path / "o.csv").exists()


def test_batch_goes_on_past_a_bad_row(tmp_path, capsys):
    """Without --strict a bad row is status 'invalid' with its reason; the others solve."""
    src = tmp_path / "in.csv"
    src.write_text("x_mm,y_mm,z_mm,note\n100,100,600,a\n1,2,abc,b\n4,,6,c\n1e300,0,0,d\n")
    out = tmp_path / "o.csv"
    code, _, err = run(capsys, "ik", "--input", str(src), "--output", str(out))
    assert code == 0, err
    assert "4 targets, 1 solved, 3 invalid" in err
    df = pd.read_csv(out, dtype=str, keep_default_na=False)
    assert df["status"].tolist() == ["ok", "invalid", "invalid", "invalid"]
    assert df["reason"][0] == ""
    assert "line 3 column z_mm: 'abc' is not a number" in df["reason"][1]
    assert "line 4 column y_mm: empty cell" in df["reason"][2]
    assert "line 5 column x_mm: x_mm = 1e+300 mm is beyond +-3.403e+38 mm" in df["reason"][3]
    assert df["z_mm"].tolist() == ["600", "abc", "6", "0"]  # echoed as given
    assert df["note"].tolist() == ["a", "b", "c", "d"]


def test_batch_missing_file(tmp_path, capsys):
    code, _, err = run(
        capsys, "ik", "--input", str(tmp_path / "nope.csv"), "--output", str(tmp_path / "o.csv")
    )
    assert code == 2 and "No such file" in err


def test_bad_params_file_exit_2(tmp_path, capsys):
    bad = tmp_path / "t3.csv"
    text = (data_dir() / "table3.csv").read_text().replace(",310,", ",-310,")
    bad.write_text(text)
    code, _, err = run(capsys, "ik", "100", "100", "600", "--params", str(bad))
    assert code == 2 and "L2 = -310.0 mm" in err


@pytest.mark.parametrize("command", ["fk", "ik", "report"])
def test_every_command_has_help(capsys, command):
    code, out, _ = run(capsys, command, "--help")
    assert code == 0 and "usage:" in out


def test_errata_subcommand_passes_options_through(capsys):
    """`python -m analysis errata --check --paper picker`: that committed register matches its
    audit, and the README block (every paper's rows) is not judged from one paper. (Every
    register and the README block without --paper: tests/audit/test_register.py and
    test_readme_errata.py.)"""
    code, out, err = run(capsys, "errata", "--check", "--paper", "picker")
    assert (code, out.strip()) == (0, "up to date"), err
    assert err == "" or err.startswith("errata: recomputing the registers"), err  # cache cold
    code, _, err = run(capsys, "errata", "--check", "--paper", "nobody")
    assert code == 2 and "no paper 'nobody'; expected one of grabber" in err


def test_errata_for_one_paper_generates_its_register_and_never_the_readme(monkeypatch):
    from analysis.audit import register as reg

    assert list(reg.generated(["picker"])) == [reg.register_path("picker")]
    monkeypatch.setattr(reg, "available", lambda: ["picker"])  # all papers: the README too
    assert list(reg.generated(["picker"])) == [
        reg.register_path("picker"),
        reg.PROJECT / "README.md",
    ]

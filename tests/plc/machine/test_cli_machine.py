"""``python -m analysis stl-run PROGRAM --dialect st|plcopen-xml --scenario S.csv --trace T.csv``
(issue 29 item 3, a contract): the program as ``stl`` prints it, a scenario, a trace with one
row per cycle; bad input is one line and exit 2."""

from __future__ import annotations

import csv
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from tests.plc.machine.conftest import machine, scenario_set

from analysis.app.cli import main
from analysis.plc.machine.scenarios import Trace, check

ROOT = Path(__file__).resolve().parents[3]


def _run(capsys, *argv):
    code = main(["stl-run", *map(str, argv)])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.fixture(scope="module")
def grabber(tmp_path_factory, machine_engine):
    d = tmp_path_factory.mktemp("machine")
    for dialect, suffix in (("st", "st"), ("plcopen-xml", "xml")):
        rc = main(
            [
                "stl",
                "--dialect",
                dialect,
                "-o",
                str(d / f"g.{suffix}"),
                "--map",
                str(d / f"g.{suffix}.json"),
            ]
        )
        assert rc == 0
    (d / "move.csv").write_text(scenario_set("grabber")["move"].csv(), encoding="utf-8")
    return d


@pytest.mark.parametrize("suffix", ["st", "xml"])
def test_scenario_to_trace(grabber, capsys, suffix):
    dialect = "st" if suffix == "st" else "plcopen-xml"
    trace = grabber / f"t-{suffix}.csv"
    code, _, err = _run(
        capsys,
        grabber / f"g.{suffix}",
        "--dialect",
        dialect,
        "--scenario",
        grabber / "move.csv",
        "--trace",
        trace,
        "--map",
        grabber / f"g.{suffix}.json",
    )
    assert code == 0, err
    text = trace.read_text("utf-8")
    head = next(csv.reader([text.split("\n", 1)[0]]))
    assert head == [
        "t_s",
        "q1",
        "q2",
        "q3",
        "v1",
        "v2",
        "v3",
        "Homed",
        "Busy",
        "Done",
        "Error",
        "Status",
        "Gripper",
        "GripperClosed",
        "AxisErrorID",
        "plc_q1",
        "plc_q2",
        "plc_q3",
    ]
    sc = scenario_set("grabber")["move"]
    tr = Trace.from_csv(text)
    assert len(tr.t) == round((sc.end_s + 2.0) / 0.004) + 1 and tr.t[1] == 0.004
    assert check(sc, tr, machine("grabber")[1]) == []


def test_cycle_and_settle(grabber, capsys):
    trace = grabber / "t2.csv"
    code, _, err = _run(
        capsys,
        grabber / "g.st",
        "--dialect",
        "st",
        "--scenario",
        grabber / "move.csv",
        "--trace",
        trace,
        "--cycle-ms",
        "2",
        "--settle-s",
        "0.5",
    )
    assert code == 0, err
    tr = Trace.from_csv(trace.read_text("utf-8"))
    assert tr.t[1] == 0.002 and tr.t[-1] == pytest.approx(
        scenario_set("grabber")["move"].end_s + 0.5, abs=0.002
    )
    assert "Pos1" in tr.outputs  # without a map: every variable the scenario does not write


@pytest.mark.parametrize(
    ("rows", "word"),
    [
        ("0,Enable,TRUE\n0.1,Foo,TRUE\n", "'Foo' is not a variable of MACHINE_GRABBER"),
        ("0.5,Enable,TRUE\n0.1,Start,TRUE\n", "row 2: t_s = 0.1 goes back in time"),
        ("0,Enable,yes\n", "a BOOL is TRUE or FALSE"),
        ("0,TargetX,1e39\n", "beyond the largest REAL"),
        ("0,Status,1.5\n", "a INT is a whole number"),
        ("-1,Enable,TRUE\n", "before 0"),
        ("0,Axis1,1\n", "AXIS_REF"),
    ],
)
def test_bad_scenarios(grabber, capsys, tmp_path, rows, word):
    (tmp_path / "s.csv").write_text("t_s,name,value\n" + rows, encoding="utf-8")
    code, _, err = _run(
        capsys,
        grabber / "g.st",
        "--dialect",
        "st",
        "--scenario",
        tmp_path / "s.csv",
        "--trace",
        tmp_path / "t.csv",
    )
    assert code == 2 and word in err and err.count("\n") == 1, err
    assert not (tmp_path / "t.csv").exists()


def test_compile_error_names_line_and_column(capsys, tmp_path, machine_engine):
    (tmp_path / "p.st").write_text(
        "PROGRAM P\nVAR\n    x : INT;\nEND_VAR\nx := y + 1;\nEND_PROGRAM\n", encoding="utf-8"
    )
    code, _, err = _run(capsys, tmp_path / "p.st", "--dialect", "st", "--read", "x")
    assert code == 2 and "line 5 col 6" in err and "unknown_identifier" in err, err


def test_engine_fault_names_the_fault_and_the_cycle(capsys, tmp_path, machine_engine):
    (tmp_path / "p.st").write_text(
        "PROGRAM P\nVAR\n    n : DINT := 3;\n    x : DINT;\nEND_VAR\n"
        "n := n - 1;\nx := 10 / n;\nEND_PROGRAM\n",
        encoding="utf-8",
    )
    (tmp_path / "s.csv").write_text("t_s,name,value\n0.1,x,0\n", encoding="utf-8")
    code, _, err = _run(
        capsys,
        tmp_path / "p.st",
        "--dialect",
        "st",
        "--scenario",
        tmp_path / "s.csv",
        "--trace",
        tmp_path / "t.csv",
    )
    assert code == 2 and "division_by_zero at cycle 2" in err, err


def test_one_scan_and_the_ik_block_alone(capsys, tmp_path, machine_engine):
    """Without a scenario: one scan, --set/--read; a source without a PROGRAM (the IK block
    on its own, stl --no-motion) runs through a harness (Table 4 row 1: 500 pulses)."""
    rc = main(["stl", "--dialect", "st", "--no-motion", "-o", str(tmp_path / "ik.st")])
    assert rc == 0
    capsys.readouterr()
    code, out, err = _run(
        capsys,
        tmp_path / "ik.st",
        "--dialect",
        "st",
        "--set",
        "px=100.0",
        "--set",
        "py=100.0",
        "--set",
        "pz=600.0",
        "--read",
        "c1",
        "--read",
        "reachable:BOOL",
        "--json",
    )
    assert code == 0, err
    assert out.strip() == '{"values": {"c1": 500, "reachable": true}}'


def test_s7_dialects_refuse_a_scenario(capsys, tmp_path):
    code, _, err = _run(
        capsys,
        tmp_path / "x.awl",
        "--dialect",
        "s7-200",
        "--scenario",
        tmp_path / "s.csv",
        "--trace",
        tmp_path / "t.csv",
    )
    assert code == 2 and "--scenario applies to --dialect st and plcopen-xml" in err


@pytest.mark.slow
def test_the_contract_from_a_shell(grabber, tmp_path):
    """The issue's command line in a subprocess, as a user types it."""
    r = subprocess.run(
        [
            sys.executable,
            "-m",
            "analysis",
            "stl-run",
            str(grabber / "g.st"),
            "--dialect",
            "st",
            "--scenario",
            str(grabber / "move.csv"),
            "--trace",
            str(tmp_path / "t.csv"),
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "t.csv").read_text("utf-8")
    assert text.startswith("t_s,q1,q2,q3,v1,v2,v3,")
    # without MAP.json: the PROGRAM's own variables by their names (the machine's outputs
    # among them), never the engine's names for the variables inside its block instances
    head = text.split("\n", 1)[0].split(",")[7:]
    assert head[-3:] == ["plc_q1", "plc_q2", "plc_q3"]  # what the PLC reads, last
    head = head[:-3]
    for name in ("Homed", "Busy", "Done", "Error", "Status", "Gripper", "GripperClosed"):
        assert name in head
    source = (grabber / "g.st").read_text("utf-8")
    assert all(re.search(rf"\b{n}\s*:", source) for n in head), head


@pytest.fixture(scope="module")
def gr1_files(tmp_path_factory, machine_engine):
    d = tmp_path_factory.mktemp("gr1")
    assert main(["stl", "--dialect", "st", "--arm", "gr1", "-o", str(d / "gr1.st"),
                 "--map", str(d / "gr1.json")]) == 0  # fmt: skip
    (d / "home.csv").write_text(scenario_set("gr1")["power_home"].csv(), encoding="utf-8")
    return d


def _started(capsys, d, *start):
    trace = d / f"t-{len(start) and start[-1].replace(',', '_')}.csv"
    code, _, err = _run(capsys, d / "gr1.st", "--dialect", "st", "--map", d / "gr1.json",
                        "--scenario", d / "home.csv", "--trace", trace, *start)  # fmt: skip
    assert code == 0, err
    return Trace.from_csv(trace.read_text("utf-8"))


@pytest.mark.slow
def test_start_where_a_machine_is_switched_on(gr1_files, capsys):
    """By default the axes stand where the scenarios' plant has them at power-up (every
    reference-switch axis off home, every encoder stale: plc_qK), so Home does real work:
    each axis ends on its home position and the PLC reads it there (the scenario's checks,
    homing held to the limits). ``--start home``: on home, read exactly (as before the
    option); ``--start q1,...``: there, the encoders stale."""
    from analysis.plc.machine.plant import power_up

    spec, sc = machine("gr1")[1], scenario_set("gr1")["power_home"]
    tr = _started(capsys, gr1_files)
    assert np.allclose(tr.q[0], [s for s, _, _ in power_up(spec)])
    assert np.allclose(tr.pos[0], [c for _, c, _ in power_up(spec)])
    assert all(abs(tr.q[0, k] - a.home_position) > 1.0 for k, a in enumerate(spec.axes))
    assert check(sc, tr, spec) == []
    home = np.array([a.home_position for a in spec.axes])
    tr = _started(capsys, gr1_files, "--start", "home")
    assert np.array_equal(tr.q[0], home) and np.array_equal(tr.pos[0], home)
    tr = _started(capsys, gr1_files, "--start", "10,-12.5,7,-3,11")  # within the plant's reach
    assert np.array_equal(tr.q[0], [10, -12.5, 7, -3, 11]) and np.all(tr.pos[0] != tr.q[0])
    assert check(sc, tr, spec) == []  # homed from there too


@pytest.mark.parametrize(
    ("start", "word"),
    [
        ("20,-10", "2 positions for 5 axes (Axis1, Axis2, Axis3, Axis4, Axis5)"),
        ("20,-10,300,0,45", "theta3 = 300 deg is outside its limits -135..135 deg"),
        ("20,-10,nan,0,45", "theta3 'nan' is not a finite number"),
        ("somewhere", "power-up or home, or one position per axis"),
    ],
)
def test_a_bad_start_is_one_line(start, word):
    """parse_start on the GR-1's MAP.json axes: one line naming the value and the limit
    (test_a_bad_start_from_a_shell: the same through stl-run, exit 2, no trace)."""
    from analysis.plc.machine.offline import _axis_rows, parse_start

    rows = _axis_rows({}, machine("gr1")[4])
    with pytest.raises(ValueError, match=re.escape(word)) as err:
        parse_start(start, rows)
    assert "\n" not in str(err.value)
    assert parse_start(None, rows) == "power-up" and parse_start(" Home", rows) == "home"
    assert parse_start("1, -2,3,4e0,5", rows) == (1.0, -2.0, 3.0, 4.0, 5.0)


@pytest.mark.slow
def test_a_bad_start_from_a_shell(gr1_files, capsys, tmp_path):
    start, word = "20,-10,300,0,45", "theta3 = 300 deg is outside its limits -135..135 deg"
    code, _, err = _run(capsys, gr1_files / "gr1.st", "--dialect", "st", "--map",
                        gr1_files / "gr1.json", "--scenario", gr1_files / "home.csv",
                        "--trace", tmp_path / "t.csv", "--start", start)  # fmt: skip
    assert code == 2 and word in err and err.count("\n") == 1, err
    assert not (tmp_path / "t.csv").exists()

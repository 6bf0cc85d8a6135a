"""A machine run played in the 3D view (analysis.app.arm3d_trace, issue 31 item 3): a trace
that ``stl-run --dialect st --scenario --trace`` writes on the ST engine, read strictly and
drawn with a time slider, held to numbers computed apart (the lenient reader of the machine's
tests, the arm's FK); and every refusal of a hostile trace, one line naming row, column and
limit."""

import numpy as np
import pytest

from analysis.app import arm3d_trace
from analysis.app.arm3d_trace import machine_run_figure, read_trace
from analysis.kinematics.arm import load_arm
from analysis.plc.machine.scenarios import Trace

GOOD = "t_s,q1,q2,q3,v1,v2,v3,Busy,Status\n0,0,0,0,0,0,0,FALSE,0\n0.004,1,2,3,0,0,0,TRUE,101\n"


@pytest.mark.slow
def test_a_machine_run_plays_as_the_engine_ran_it(tmp_path, machine_engine, capsys):
    """The grabber's 'move' scenario through the CLI as a user runs it; the trace read back
    equals the machine tests' own reader, and each animation frame draws the arm and its tool
    frame where FK puts them at that row, with that row's outputs under the title."""
    from analysis.app.cli import main
    from analysis.kinematics.arm import paper_arm
    from analysis.plc.machine.scenarios import scenarios

    arm = paper_arm()
    prog, scen, out = tmp_path / "g.st", tmp_path / "move.csv", tmp_path / "t.csv"
    assert main(["stl", "--dialect", "st", "-o", str(prog), "--map", str(tmp_path / "g.json")]) == 0
    scen.write_text(scenarios(arm)["move"].csv(), encoding="utf-8")
    argv = ["stl-run", str(prog), "--dialect", "st", "--map", str(tmp_path / "g.json"),
            "--scenario", str(scen), "--trace", str(out)]  # fmt: skip
    assert main(argv) == 0, capsys.readouterr().err
    trace = read_trace(out, arm)
    ref = Trace.from_csv(out.read_text("utf-8"))
    np.testing.assert_array_equal(trace.t, ref.t)
    np.testing.assert_array_equal(trace.q, ref.q)
    np.testing.assert_array_equal(trace.v, ref.v)
    assert list(trace.outputs) == list(ref.outputs)
    np.testing.assert_array_equal(trace.pos, ref.pos)  # plc_q1..plc_qN: what the PLC reads
    for k, v in trace.outputs.items():
        np.testing.assert_array_equal(np.asarray(v, dtype=float), ref.outputs[k], err_msg=k)
    assert trace.outputs["Busy"].dtype == bool and trace.outputs["Busy"].any()
    fig = machine_run_figure(arm, trace, frames=31)
    names = [tr.name for tr in fig.data]
    k_tool = next(k for k, n in enumerate(names) if n.startswith("tool frame"))
    L = fig.data[k_tool].meta["arm3d"]["length"]
    moved = 0
    for f in fig.frames:  # its row: one of the cycles its label (t in s, 2 dp) rounds
        tr = f.data[list(f.traces).index(k_tool)]
        pts = np.array([tr.x, tr.y, tr.z], dtype=float).T
        o, R = pts[0], (pts[[1, 4, 7]] - pts[0]).T / L
        note = f.layout.annotations[0].text
        rows = np.flatnonzero(np.abs(trace.t - float(f.name)) <= 0.005 + 1e-9)
        T = arm.tool_transform(np.radians(trace.q[rows]))  # FK apart from the figure
        fits = [r for r, Tr in zip(rows, T, strict=True)
                if np.abs(o - Tr[:3, 3]).max() <= 1e-3 and np.abs(R - Tr[:3, :3]).max() <= 1e-4
                and note.startswith(f"t = {trace.t[r]:.2f} s · Status ")
                and f"Busy {'TRUE' if trace.outputs['Busy'][r] else 'FALSE'}" in note]  # fmt: skip
        assert fits, (f.name, note, o, rows)
        moved += "Busy TRUE" in note
    assert moved  # the frames caught the machine moving


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "t_s,q1,q2,q3,q4,v1,v2,v3,v4\n0" + ",0" * 8 + "\n1" + ",0" * 8 + "\n",
            "4 joint position columns (q1, q2, q3, q4); the arm has 3",
        ),
        ("t_s,q1,q2,v1,v2\n0,0,0,0,0\n1,0,0,0,0\n", "2 joint position columns"),
        ("t_s,v1,v2,v3,q1,q2,q3\n0,0,0,0,0,0,0\n1,0,0,0,0,0,0\n", "expected t_s,q1,q2,q3,v1,v2,v3"),
        (GOOD.replace("0.004,", "0,"), "row 2, column t_s: 0 s does not come after 0 s"),
        (GOOD.replace("0.004,1,", "0.004,x,"), "column q1"),
        (GOOD.replace("0.004,1,", "0.004,nan,"), "column q1"),
        (GOOD.replace("0.004,1,", "0.004,4000,"), "row 2, column q1: 4000 deg is beyond +-3600"),
        (GOOD.replace(",101\n", ",TRUE\n"), "row 2, column Status: 'TRUE' in a column of numbers"),
        (GOOD.replace(",101\n", ",1e\n"), "row 2, column Status"),
        (GOOD.replace("TRUE,101", "TRUE"), "line 3"),  # a field short
        ("t_s,q1,q2,q3,v1,v2,v3\n0,0,0,0,0,0,0\n", "1 rows; a run to play has 2 .."),
    ],
)
def test_a_hostile_trace_is_refused_in_one_line(tmp_path, text, message):
    path = tmp_path / "t.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ValueError) as err:
        read_trace(path, load_arm("grabber"))
    assert message in str(err.value) and "\n" not in str(err.value), str(err.value)


def test_limits_and_files(tmp_path, monkeypatch):
    arm = load_arm("grabber")
    path = tmp_path / "t.csv"
    path.write_text(GOOD, encoding="utf-8")
    got = read_trace(path, arm)
    # the status words: the machine's own (MAP.json's status table) and the IK block's
    assert arm3d_trace._fmt("Status", 101.0) == "Status 101 (not-homed)"
    assert arm3d_trace._fmt("Status", 1.0) == "Status 1 (out-of-reach)"
    assert arm3d_trace._fmt("Busy", np.bool_(True)) == "Busy TRUE"
    assert got.q.tolist() == [[0, 0, 0], [1, 2, 3]] and got.outputs["Busy"].tolist() == [0, 1]
    monkeypatch.setattr(arm3d_trace, "MAX_TRACE_ROWS", 1)
    with pytest.raises(ValueError, match=r"2 rows; a run to play has 2 \.\. 1"):
        read_trace(path, arm)
    monkeypatch.setattr(arm3d_trace, "MAX_TRACE_BYTES", 10)
    with pytest.raises(ValueError, match=f"has {len(GOOD)} bytes: at most 10"):
        read_trace(path, arm)
    with pytest.raises(ValueError, match="not a regular file"):
        read_trace(tmp_path, arm)
    with pytest.raises(ValueError, match="cannot read the trace"):
        read_trace(tmp_path / "none.csv", arm)
    with pytest.raises(ValueError, match="the trace has 3 joints; arm gr1 has 5"):
        machine_run_figure(load_arm("gr1"), got)

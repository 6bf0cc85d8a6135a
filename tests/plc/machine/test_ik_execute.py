"""The IK block's PLCopen interface (issue 29 item 1): Execute (rising edge: solve the target
once), Done, Busy, Error, ErrorID (the status of a refused target), held while Execute stays
TRUE and cleared when it falls; the target read at the edge only. On the ST engine, cycle by
cycle (Table 4 row 1: 500 pulses; row 8: out of reach)."""

from __future__ import annotations

import numpy as np

from analysis.kinematics.arm import paper_arm
from analysis.plc.generate import generate
from analysis.plc.st_engine import run_machine

HARNESS = """
PROGRAM P
VAR
    Execute : BOOL;
    px : REAL;
    py : REAL;
    pz : REAL;
    ik : IK_GRABBER;
    Done : BOOL;
    Busy : BOOL;
    Error : BOOL;
    ErrorID : DINT;
    c1 : DINT;
END_VAR
ik(Execute := Execute, px := px, py := py, pz := pz);
Done := ik.Done;
Busy := ik.Busy;
Error := ik.Error;
ErrorID := ik.ErrorID;
c1 := ik.c1;
END_PROGRAM
"""


def test_execute_done_error(machine_engine):
    source = generate(paper_arm(), "st", motion=False).program + HARNESS
    writes = [(0, "px", 100.0), (0, "py", 100.0), (0, "pz", 600.0), (2, "Execute", 1.0),
              (4, "px", -100.0),  # changed while Execute is TRUE: not read
              (6, "Execute", 0.0), (8, "px", 200.0), (8, "py", 500.0), (9, "Execute", 1.0),
              (11, "Execute", 0.0)]  # fmt: skip
    run = run_machine(source, "P", [], writes, ["Done", "Busy", "Error", "ErrorID", "c1"],
                      n_cycles=13)  # fmt: skip
    done, busy, error, eid, c1 = (run[n] for n in ("Done", "Busy", "Error", "ErrorID", "c1"))
    assert not done[:2].any() and done[2:6].all() and not done[6:].any()
    assert (c1[2:9] == 500).all()  # solved at the edge, held through the change of px
    assert not error[:9].any() and error[9:11].all() and not error[11:].any()
    assert (eid[9:11] == 1).all() and (eid[11:] == 0).all()  # out of reach
    assert (c1[9:] == 500).all()  # a refused target leaves the counts
    assert not busy.any() and np.all(run.faults == 0)

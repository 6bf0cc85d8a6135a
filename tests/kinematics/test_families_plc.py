"""The derived arms' PLC programs executed on the ST engine (pyplcopen's IEC 61131-3 compiler
and VM) against the float64 closed form, over the one sweep generator's targets
(analysis.plc.sweep.sweep_targets: configurations, a box, half pulses, wrap cuts, the reach,
singular-set and joint-limit boundaries, bad and huge inputs), as the seed arms' programs are
(tests/plc/test_st_engine.py):

- the float32 model of the program (analysis.plc.model.predict) reproduces the engine bit for
  bit, status and counts;
- statuses and the reach flag agree with Python's (its refusal band), a refused target leaves
  its outputs alone, nothing Python refuses is accepted;
- no count is off by more than one, and every one that is off is explained: the float32 and
  the exact value straddle a half pulse, or the wrap cut.

The six-axis programs are printed for an S7-1500 / CODESYS (ST and SCL); their counts stay
within a REAL's exact whole numbers (2^24). What does not fit an S7-200:
test_what_an_s7_200_cannot_hold.
"""

from __future__ import annotations

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm
from analysis.plc import st_engine
from analysis.plc.ir import build_program
from analysis.plc.st import block_name, emit_st
from analysis.plc.sweep import sweep_targets
from analysis.plc.verify import compare, input_columns

SENTINEL = -999_999
ARMS = ("puma560", "ur5", "cobra600", "planar2r", "gantry")


@pytest.fixture(scope="module")
def engine():
    try:
        return st_engine.engine_path()
    except st_engine.EngineMissing as exc:
        pytest.skip(str(exc))


@pytest.fixture(scope="module", params=ARMS)
def case(request):
    arm = load_arm(request.param)
    return arm, sweep_targets(arm)


@pytest.mark.slow  # a sweep of about 1,100 targets per arm on the engine: make test only
def test_st_on_the_engine_equals_the_closed_form(case, engine):
    arm, targets = case
    prog = build_program(arm, None, "function")
    text = emit_st(prog, units=arm.input_units, default_branch=arm.branches[0])
    xyz = targets[input_columns(arm)].to_numpy(dtype=float)
    res, run = st_engine.sweep(text, block_name(prog, arm.branches[0]), prog.inputs,
                               len(prog.outputs), xyz, SENTINEL, engine)  # fmt: skip
    assert (run.faults == 0).all()
    c = compare(res, targets, arm, None, "st", SENTINEL, "function")
    assert c.model_exact
    assert c.status_mismatch == 0 and c.flag_mismatch == 0 and c.unchanged_ok
    assert c.unsafe == 0
    assert c.all_explained, c.mismatch_table
    t = c.mismatch_table
    step = t[~t["cut"]]
    assert (step["plc"] - step["python"]).abs().max() <= 1 if len(step) else True


@pytest.mark.parametrize("name", ARMS)
def test_counts_fit_a_real(name):
    """Every joint's largest count (its range in pulses, eqs. 20-22) is a whole number a REAL
    holds exactly (|c| <= 2^24), so the program's REAL arithmetic counts every pulse."""
    arm = load_arm(name)
    hi = np.abs(arm.bounds).max(axis=1)
    assert (np.abs(arm.pulse_values(arm.bounds.T)) <= 2**24).all()
    assert (np.abs(arm.pulse_values(hi[None])) <= 2**24).all()


def test_what_an_s7_200_cannot_hold():
    """The six-axis IK block is printed for the S7-200 too (its REAL instructions and the
    ATAN2/ACOS subroutines), but the S7-200 has two pulse-train outputs (Q0.0, Q0.1 on a CPU
    224XP) for six joints: the machine program's six axes do not fit it (tests of the machine
    program: tests/plc/machine). Here: the program and its memory map are printed and fit
    the CPU's V memory."""
    from analysis.plc.generate import generate

    for name in ("puma560", "ur5"):
        text, map_text = generate(load_arm(name), "s7-200")
        assert "SBR" in text or "CALL" in text
        assert '"dialect": "s7-200"' in map_text

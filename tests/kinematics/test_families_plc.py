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
test_what_an_s7_200_holds_and_what_it_cannot.
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


@pytest.fixture(scope="module", params=[*ARMS, "puma560.urdf", "ur5_ros.urdf"])
def case(request, tmp_path_factory):
    """A published arm by name, or loaded from a URDF (the writer's PUMA 560; a UR5 in
    ROS-Industrial's frames, tests/kinematics/test_families_urdf.py: the URDF's description
    with a drive added, as a user gives one), and its sweep."""
    source = request.param
    if source.endswith(".urdf"):
        from analysis.kinematics.urdf import arm_urdf

        from .test_families_urdf import ur5_ros_style, with_drive

        path = tmp_path_factory.mktemp("urdf") / source
        path.write_text(ur5_ros_style() if source.startswith("ur5") else arm_urdf("puma560"),
                        encoding="utf-8")  # fmt: skip
        source = str(with_drive(path))  # a URDF has no drive: its description, with one
    arm = load_arm(source)
    return arm, sweep_targets(arm)


@pytest.mark.slow  # builds the sweeps the next test runs
def test_the_sweep_has_the_seed_arms_kinds(case):
    """Every arm's sweep has the seed arms' kinds: half pulses, wrap cuts, a reach boundary
    (out of reach or a joint's stroke, 1e-3 .. 1 mm either side), and the six-axis arms'
    singular sets (the wrist flip: position and orientation rays)."""
    arm, targets = case
    kinds = set(targets["kind"])
    assert {"config", "box", "half-pulse", "cut", "bad", "huge"} <= kinds, kinds
    assert kinds & {"out-of-reach-1mm", "joint-limits-1mm"}, kinds
    if arm.n_joints == 6:
        assert {"flip-1mm", "flip-tol"} <= kinds and kinds & {"out-of-reach-1mm"}, kinds


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


@pytest.mark.slow
@pytest.mark.parametrize("name", ["puma560", "ur5"])
def test_what_an_s7_200_holds_and_what_it_cannot(name):
    """The six-axis IK block fits an S7-200 (README, "Six axes on an S7-200"): printed in its
    REAL instructions with the ATAN2/ACOS subroutines (it has no ATAN), within a CPU 224's V
    memory, and run on the S7-200 evaluator (analysis.plc.stl_eval) over every third target
    of each sweep kind: no count off by more than one where both accept, each explained, a
    refused target's outputs unchanged. What it cannot hold is the machine: the CPU's two
    pulse-train outputs (Q0.0, Q0.1) drive two of the six axes, and the PLCopen motion
    blocks have no S7-200 form (the machine program is printed for st, scl, plcopen-xml).

    Measured: on two PUMA targets exactly at theta3's limit (-135 deg) the program (the
    evaluator and awlsim alike) accepts what Python refuses: the float32 model of the
    S7-200 program computes theta3 one ulp beyond the limit, the program on it. Such a
    target is only allowed at a joint limit, within 1e-6 rad of it."""
    import json

    from analysis.plc.generate import generate
    from analysis.plc.memmap import MemoryMap
    from analysis.plc.runner import S7200Runner

    arm = load_arm(name)
    text, map_text = generate(arm, "s7-200")
    doc = json.loads(map_text)
    assert doc["dialect"] == "s7-200" and "CALL   SBR" in text and "ATAN " not in text
    assert max(m["last"] for m in doc["memory"] if m["area"] == "V") < 8192  # CPU 224
    frame = sweep_targets(arm)
    rows = np.sort(np.concatenate([np.flatnonzero(frame["kind"] == k)[::3]
                                   for k in frame["kind"].unique()]))  # fmt: skip
    sub = frame.iloc[rows].reset_index(drop=True)
    xyz = sub[input_columns(arm)].to_numpy(dtype=float)
    runner = S7200Runner(text, MemoryMap.from_dict(doc))
    res = runner.solve(xyz, sentinel=SENTINEL)
    assert not runner.stopped and len(set(res.status.tolist())) >= 4
    c = compare(res, sub, arm, None, "s7-200", SENTINEL, "subroutine")
    assert c.flag_mismatch == 0 and c.unchanged_ok and c.all_explained, c.mismatch_table
    t = c.mismatch_table
    step = t[~t["cut"]]
    assert (step["plc"] - step["python"]).abs().max() <= 1 if len(step) else True
    # accepted where Python refuses: only at a joint limit, within 1e-6 rad of it
    finite = np.flatnonzero(np.isfinite(xyz).all(axis=1))  # NaN/inf: refused (status 6)
    assert (res.status[np.setdiff1d(np.arange(len(xyz)), finite)] != 0).all()
    py = arm.solve(xyz[finite], [arm.branches[0]])
    odd = finite[(res.status[finite] == 0) & ~py.ok[:, 0]]
    assert len(odd) <= c.unsafe <= 2
    q = arm.solve(xyz[odd], [arm.branches[0]], limits=False).theta[:, 0]
    lo, hi = arm.bounds[:, 0], arm.bounds[:, 1]
    assert (np.minimum(np.abs(q - lo), np.abs(q - hi)).min(axis=1) < 1e-6).all()


@pytest.mark.slow
@pytest.mark.parametrize("name", ["puma560", "planar2r", "gantry"])
def test_machine_program_with_six_axes(name, machine_engine):
    """The machine program (analysis.plc.machine: PLCopen motion blocks beside the IK block)
    of the six-axis PUMA 560 and of the planar arm and the gantry through every scenario
    on the ST engine, held to the scenarios' own checks."""
    from analysis.plc.generate import generate
    from analysis.plc.machine.program import machine_name
    from analysis.plc.machine.run import run_scenario
    from analysis.plc.machine.scenarios import check, scenarios
    from analysis.plc.machine.spec import machine_spec

    arm = load_arm(name)
    spec = machine_spec(arm)
    text, _ = generate(arm, "st")
    for key, sc in scenarios(arm).items():
        tr = run_scenario(text, machine_name(spec), spec, sc.rows)
        assert check(sc, tr, spec) == [], (name, key)

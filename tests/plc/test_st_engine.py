"""The generated IEC 61131-3 ST executed on the ST engine of pyplcopen's sdist (issue 22).

Every arm (the grabber, the palletizer, the GR-1, the picker), on the same held-out sweeps as
its awlsim tests (the one sweep generator, analysis.plc.sweep.sweep_targets):

- the float32 model of the program (analysis.plc.model.predict with the ST dialect: REAL
  arithmetic, the native ATAN/ACOS or the polynomial subroutines, ROUND halves away from zero)
  reproduces the engine bit for bit, status and pulses;
- statuses, reach flag and "refused leaves c1..cn alone" agree with Python exactly;
- a count differs from Python only by a half-pulse straddle or at the wrap cut (explained);
- against awlsim: with trig "subroutine" the ST pulses equal the S7-200 program's on awlsim
  bit for bit; with "function" they equal the S7-300 program's (native ATAN/ACOS) except where
  the float32 count is exactly k + 1/2, where S7-300 RND rounds to even and the ST block away
  from zero (counted one by one).
The awlsim results come from analysis.plc.runner.sweep with the awlsim tests' arguments, so
under `make test` (ANALYSIS_AWLSIM_MEMO) they are the memoized runs of those tests.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm
from analysis.plc import st_engine
from analysis.plc.generate import generate
from analysis.plc.ir import build_program
from analysis.plc.st import block_name, emit_st
from analysis.plc.sweep import sweep_targets
from analysis.plc.verify import compare, input_columns

SENTINEL = -999_999


@pytest.fixture(scope="module", params=["grabber", "gr1", "palletizer", "picker"])
def case(request):
    arm = load_arm(request.param)
    return arm, sweep_targets(arm)


def _st_run(arm, targets, trig, engine, branch=None):
    prog = build_program(arm, branch, trig)
    text = emit_st(prog, units=arm.input_units, default_branch=arm.branches[0])
    xyz = targets[input_columns(arm)].to_numpy(dtype=float)
    fb = block_name(prog, arm.branches[0])
    res, run = st_engine.sweep(text, fb, prog.inputs, len(prog.outputs), xyz, SENTINEL, engine)
    return res, run


@pytest.mark.parametrize("trig", ["function", "subroutine"])
def test_st_on_the_engine_equals_python_and_the_model(case, trig, engine):
    arm, targets = case
    res, run = _st_run(arm, targets, trig, engine)
    assert (run.faults == 0).all()  # no scan faulted (no NaN reached an integer conversion)
    c = compare(res, targets, arm, None, "st", SENTINEL, trig)
    assert c.model_exact  # the float32 model = the engine, status and pulses, bit for bit
    assert c.status_mismatch == 0 and c.flag_mismatch == 0 and c.unchanged_ok
    assert c.unsafe == 0
    assert c.all_explained, c.mismatch_table
    t = c.mismatch_table
    step = t[~t["cut"]]
    assert (step["plc"] - step["python"]).abs().max() <= 1 if len(step) else True
    assert (step["kind"] == "half-pulse").any(), step
    assert c.max_real_error < 0.5


def _s7_programs(arm):
    """(dialect, AWL for awlsim, memory map) of the S7-200 and S7-300 programs exactly as
    their awlsim tests run them (the same memo key: tests/plc/test_plc_awlsim.py builds the
    grabber's without the motion networks; the others test what ``stl`` writes)."""
    from analysis.plc.emit import emit_s7200, emit_s7300
    from analysis.plc.memmap import MemoryMap, default_map
    from analysis.plc.translate import translate_s7200

    if arm.name == "grabber":
        P = arm
        yield "s7-200", translate_s7200(emit_s7200(build_program(P))).awl, default_map("s7-200")
        yield "s7-300", emit_s7300(build_program(P, None, "native")), default_map("s7-300")
        return
    for dialect in ("s7-200", "s7-300"):
        text, map_text = generate(arm, dialect)
        awl = translate_s7200(text).awl if dialect == "s7-200" else text
        yield dialect, awl, MemoryMap.from_dict(json.loads(map_text))


@pytest.mark.slow
def test_st_pulses_against_awlsim(case, engine):
    """ST (trig subroutine) = the S7-200 program on awlsim; ST (function) = the S7-300
    native program on awlsim except at exact float32 ties (RND: to even)."""
    from analysis.plc.runner import sweep

    arm, targets = case
    xyz = targets[input_columns(arm)].to_numpy(dtype=float)
    for dialect, awl, mmap in _s7_programs(arm):
        trig = "subroutine" if dialect == "s7-200" else "function"
        s7 = sweep(awl, mmap, xyz, sentinel=SENTINEL).result
        st, _ = _st_run(arm, targets, trig, engine)
        np.testing.assert_array_equal(st.status, s7.status)
        np.testing.assert_array_equal(st.reachable, s7.reachable)
        ok = st.reachable
        differ = (st.pulses != s7.pulses) & ok[:, None]
        if dialect == "s7-200":
            assert not differ.any(), np.argwhere(differ)
        else:
            # each difference: the engine's float32 count is exactly k + 1/2 (the model's)
            from analysis.plc.approx import PlcFloat32Ops
            from analysis.plc.model import predict

            m = predict(arm, xyz, ops=PlcFloat32Ops("st", "function"))
            with np.errstate(invalid="ignore"):  # a refused target's count may be inf
                frac = np.abs(m.counts - np.trunc(m.counts))
            assert (frac[differ] == 0.5).all()
            assert (np.abs(st.pulses - s7.pulses)[differ] == 1).all()


def test_engine_refuses_a_broken_program(engine):
    """The engine is a real compiler: a program with a type error is refused, naming it."""
    arm = load_arm("grabber")
    prog = build_program(arm, None, "function")
    text = emit_st(prog, units=arm.input_units, default_branch=arm.branches[0])
    broken = text.replace("REAL_TO_DINT(count)", "count", 1)  # REAL into a DINT
    with pytest.raises(ValueError, match="ST engine refused"):
        st_engine.sweep(broken, "IK_GRABBER", prog.inputs, 3, [[100.0, 100.0, 600.0]], None, engine)
    res, _ = st_engine.sweep(
        text, "IK_GRABBER", prog.inputs, 3, [[100.0, 100.0, 600.0]], None, engine
    )
    assert res.pulses.tolist() == [[500, 113, -1724]]  # Table 4 row 1

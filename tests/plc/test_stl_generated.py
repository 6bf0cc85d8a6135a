"""The generator's S7-200 programs (every arm) executed on the S7-200 evaluator, against
the same text translated to AWL on awlsim, over the same seeded sweeps the awlsim tests use
(issue 22: "the generator's S7-200 output runs in it for every arm").

Arms: the grabber, the palletizer, the GR-1, the picker, and a TOML-only arm whose closed
form is derived from its D-H table (analysis.kinematics.derive: the random 3R arm of
tests/kinematics/test_random_arms.py). Targets: the one sweep generator
(analysis.plc.sweep.sweep_targets), as each arm's awlsim test calls it.

The awlsim side is the call the arm's awlsim test makes (``analysis.plc.runner.sweep``: in
``make test`` read from ANALYSIS_AWLSIM_MEMO, executed once per run); the evaluator (pure
Python, one scan per target) runs every third target of each kind, compared with the same
rows of that run. The two engines share no code: the evaluator reads the Micro/WIN text
itself; awlsim runs the translation. Status, reach flag and every pulse count must be equal,
target by target.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm, paper_arm
from analysis.plc.emit import emit_s7200, emit_s7300
from analysis.plc.generate import generate
from analysis.plc.ir import build_program
from analysis.plc.memmap import MemoryMap, default_map
from analysis.plc.runner import S7200Runner, sweep
from analysis.plc.sweep import sweep_targets
from analysis.plc.translate import translate_s7200
from analysis.plc.verify import input_columns

pytestmark = pytest.mark.slow  # seconds per arm on the evaluator
pytest.importorskip("awlsim")
SENTINEL = -999_999
ARMS = ["grabber", "palletizer", "gr1", "picker", "derived-3R"]


def derived_arm(folder):
    """The TOML-only 3R arm of tests/kinematics/test_random_arms.py (seed 11, modified
    D-H, no closed_form: derived), and the branch its awlsim test runs (the one most
    configurations within the joint limits solve)."""
    from analysis.kinematics.derive.samples import random_arm

    path = folder / "arm.toml"
    path.write_text(random_arm(np.random.default_rng(11), "3R", "modified", "arm"), "utf-8")
    arm = load_arm(str(path))
    q = arm.sample_q(np.random.default_rng(12), 200)
    return arm, arm.branches[int(np.argmax(arm.solve(arm.target(q)).ok.sum(axis=0)))]


def _case(name, folder):
    """(arm, branch, S7-200 text, map, S7-300 program with the same ATAN2/ACOS or None), as
    the arm's awlsim test generates them."""
    if name == "grabber":
        arm = paper_arm()
        text = emit_s7200(build_program(arm, "front-up"))  # as test_plc_awlsim.py
        s7300 = emit_s7300(build_program(arm, "front-up", "subroutine"))
        return arm, "front-up", text, default_map("s7-200"), (s7300, default_map("s7-300"))
    arm, branch = derived_arm(folder) if name == "derived-3R" else (load_arm(name), None)
    branch = branch or arm.branches[0]
    text, mjson = generate(arm, "s7-200", branch, "subroutine")
    s7300 = None
    if name == "gr1":  # test_gr1_plc.py runs the S7-300 subroutine variant too
        t3, m3 = generate(arm, "s7-300", branch, "subroutine")
        s7300 = t3, MemoryMap.from_dict(json.loads(m3))
    return arm, branch, text, MemoryMap.from_dict(json.loads(mjson)), s7300


@pytest.mark.parametrize("name", ARMS)
def test_generated_programs_on_the_evaluator(name, tmp_path):
    arm, branch, text, mmap, s7300 = _case(name, tmp_path)
    frame = sweep_targets(arm, branch=branch)
    targets = frame[input_columns(arm)].to_numpy(dtype=float)
    # every third target of each kind on the evaluator
    rows = np.sort(np.concatenate([np.flatnonzero(frame["kind"] == k)[::3]
                                   for k in frame["kind"].unique()]))  # fmt: skip
    if name == "derived-3R":  # no awlsim test of this arm's sweep to share: those rows only
        targets, rows = targets[rows], np.arange(len(rows))
    theirs = sweep(translate_s7200(text).awl, mmap, targets, sentinel=SENTINEL)
    runner = S7200Runner(text, mmap)
    doc = json.loads(generate(arm, "s7-200", branch, motion=False).map)
    counts = [int(doc["work"][k][2:]) for k in sorted(doc["work"]) if k.startswith("count")]
    ours = runner.solve(targets[rows], sentinel=SENTINEL, reals=tuple(sorted(counts)))
    assert len(frame) > 1000 and len(rows) > 300
    assert not runner.stopped and not theirs.stopped
    np.testing.assert_array_equal(ours.status, theirs.result.status[rows])
    np.testing.assert_array_equal(ours.reachable, theirs.result.reachable[rows])
    np.testing.assert_array_equal(ours.pulses, theirs.result.pulses[rows])
    assert len(set(ours.status.tolist())) >= 4  # solved and refused targets both
    # the S7-300 program (the same ATAN2/ACOS subroutines) on awlsim: equal but where the
    # REAL handed to the rounding is exactly k + 1/2, which RND rounds to even and the
    # S7-200's ROUND away from zero
    if s7300 is None:
        return
    other = sweep(*s7300, targets, sentinel=SENTINEL).result
    np.testing.assert_array_equal(ours.status, other.status[rows])
    differ = ours.pulses != other.pulses[rows]
    real = ours.reals[:, : differ.shape[1]][differ]
    # (every third target: the rows may hold no exact tie; the full sweep's ties are
    # counted in test_st_engine.py and test_plc_awlsim.py)
    assert differ.sum() <= 30 and (real - np.floor(real) == 0.5).all()
    assert (np.abs(ours.pulses - other.pulses[rows])[differ] == 1).all()

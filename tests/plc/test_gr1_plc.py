"""The GR-1's PLC programs (generated from its one closed form) executed on awlsim against
Python: status and pulses for 1,044 seeded poses (analysis.plc.pose_targets), every branch.

Python's reference is Arm.solve (float64) on the poses rounded to float32 (as REAL inputs
hold them), with the dialect's tie rule. The float32 model of the program
(analysis.plc.model.predict) must reproduce awlsim bit for bit; a pulse may differ from
Python by one only where the float32 value and the exact value lie on opposite sides of
the same half pulse (``compare(...).all_explained``).
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from analysis.kinematics.status import Status
from analysis.plc.generate import generate
from analysis.plc.memmap import MemoryMap, default_map
from analysis.plc.model import predict
from analysis.plc.pose_targets import pose_sweep_targets
from analysis.plc.runner import AwlRunner, sweep
from analysis.plc.translate import translate_s7200
from analysis.plc.verify import compare
from analysis.studies.gr1 import gr1_arm, project_orientation, thesis_poses

pytestmark = pytest.mark.slow  # seconds per test: run first (tests/conftest.py)

pytest.importorskip("awlsim")
SENTINEL = -999_999
ARM = gr1_arm()
COLS = list(ARM.inputs)


def _source(variant: str, branch: str):
    """AWL source, memory map and trig mode of the program ``plc.generate`` writes (the
    ``stl`` command's path); the S7-200 text translated to AWL for awlsim."""
    dialect = "s7-300" if variant.startswith("s7-300") else "s7-200"
    trig = "native" if variant == "s7-300-native" else "subroutine"
    text, map_json = generate(dialect, branch, trig, params=ARM.params)
    mmap = MemoryMap.from_dict(json.loads(map_json))
    src = text if dialect == "s7-300" else translate_s7200(text).awl
    assert mmap == default_map(dialect, COLS, 5)
    return src, mmap, trig


@pytest.fixture(scope="module")
def targets():
    return pose_sweep_targets(ARM)


@pytest.mark.parametrize(
    ("variant", "branch"),
    [
        ("s7-300-native", "front-up"),
        ("s7-300-subroutine", "front-up"),
        ("s7-200-translated", "front-up"),
        ("s7-200-translated", "front-down"),
        ("s7-200-translated", "back-up"),
        ("s7-200-translated", "back-down"),
    ],
)
def test_sweep_matches_python(variant, branch, targets):
    src, mmap, trig = _source(variant, branch)
    # executed on awlsim once per `make test` (notebook 10 runs the S7-300 front-up program)
    done = sweep(src, mmap, targets[COLS].to_numpy(), sentinel=SENTINEL)
    res = done.result
    dialect = "s7-300" if variant.startswith("s7-300") else "s7-200"
    cmp = compare(res, targets, ARM, branch, dialect, SENTINEL, trig)
    assert cmp.n == 1044 and not done.stopped  # no REAL compare saw a NaN
    assert cmp.model_exact  # the float32 model = awlsim, status and pulses, bit for bit
    assert cmp.status_mismatch == 0 and cmp.flag_mismatch == 0 and cmp.unchanged_ok
    # every status this program can give occurs (front-up: 519 ok, 150 out of reach, 5 on
    # the axis, 195 beyond the assumed limits, 169 orientation; 6 not finite)
    seen = set(np.unique(res.status).tolist())
    assert {0, 1, 3, 4, 6, 7} <= seen, seen
    # float32 lands on the other side of a half pulse only on the half-pulse poses, within
    # one pulse, each explained by the model; the REAL error before ROUND stays far below
    # half a pulse (measured 0.037 pulse, at a wrist 1e-3 mm inside the reach shell where
    # acos is ill-conditioned)
    assert cmp.max_abs_diff <= 1
    assert cmp.all_explained, cmp.mismatch_table
    assert set(cmp.mismatch_table["kind"]) <= {"half-pulse"}, cmp.mismatch_table
    assert (cmp.mismatch_table["dist_half"] < 1e-3).all()
    assert cmp.max_real_error < 0.05
    # measured (front-up) 44 of the 150 half-pulse poses on the S7-300, 51 on the S7-200
    assert cmp.pulse_mismatch <= 75


def test_table5_3_on_the_plc():
    """Table 5-3 as printed: refused with the orientation status; its nearest reachable
    poses: start beyond the assumed wrist limit on front-up (status 4), end solved."""
    src, mmap, _ = _source("s7-300-native", "front-up")
    poses = np.concatenate([thesis_poses(), project_orientation(ARM, thesis_poses())[0]])
    res = AwlRunner(src, mmap).solve(poses, sentinel=SENTINEL)
    assert res.status.tolist() == [Status.ORIENTATION, Status.ORIENTATION, 4, 0]
    sol = ARM.solve(poses[3], ["front-up"])
    expect = np.rint(np.degrees(sol.theta[0]) / 360 * np.array(ARM.params.pulses_per_rev))
    assert np.abs(res.pulses[3] - expect).max() <= 1  # half-pulse straddles allowed
    assert res.pulses[0].tolist() == [SENTINEL] * 5  # refused: outputs unchanged


def test_generate_for_a_pose_arm():
    """generate() names six REAL inputs and five DINT counts; no example pose on startup
    (the closed form's STARTUP_TARGET is None), so the first scan sees zeros: base axis."""
    for dialect in ("s7-300", "s7-200"):
        text, map_json = generate(dialect, params=ARM.params)
        m = json.loads(map_json)
        assert list(m["inputs"]) == COLS and [f"c{k}" for k in range(1, 6)] == [
            k for k in m["outputs"] if k.startswith("c")
        ]
        assert "OB 100" not in text and "SM0.1" not in text
        mmap = MemoryMap.from_dict(m)
        src = text if dialect == "s7-300" else translate_s7200(text).awl
        r = AwlRunner(src, mmap)
        assert r.read_dint(mmap.outputs["status"]) == Status.BASE_AXIS


def test_model_predicts_awlsim_on_the_s7200_subroutines(targets):
    """predict() with the S7-200's generated ATAN2/ACOS (the default model) = awlsim."""
    pts = targets[COLS].to_numpy()[:300]
    src, mmap, _ = _source("s7-200-translated", "front-down")
    res = AwlRunner(src, mmap).solve(pts, sentinel=SENTINEL)
    model = predict(ARM.params, pts, "front-down")
    np.testing.assert_array_equal(model.status, res.status)
    np.testing.assert_array_equal(model.pulses[model.reachable], res.pulses[res.reachable])

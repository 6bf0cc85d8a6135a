"""The generated program keeps Python's boundary conventions, as properties (issue 13, item 4).

Hypothesis draws targets on and around the folded-elbow sphere, the outer reach sphere, the
base axis and the wrap cut of theta1/theta2, for every branch and both dialects, and holds
the float32 model of the generated program (:func:`analysis.plc.model.predict`) to Python
(:func:`analysis.plc.verify.compare`): the same status for every target (refused targets
included), and counts that differ only by a half-pulse straddle or, one revolution apart, at
the wrap cut. The model equals awlsim bit for bit on the same kinds of target
(``tests/plc/test_plc_awlsim.py``: sweep kinds ``inner-1mm``, ``outer-1mm``, ``axis``, ``cut``),
which is what makes it a stand-in for the PLC here; awlsim itself is too slow for thousands of
hypothesis examples.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given
from hypothesis import strategies as st

from analysis.kinematics.arm import BRANCHES, paper_arm
from analysis.kinematics.status import Status
from analysis.plc.approx import PlcFloat32Ops
from analysis.plc.model import predict
from analysis.plc.runner import RunResult
from analysis.plc.verify import compare

pytestmark = pytest.mark.slow  # seconds per test: run first (tests/conftest.py)

ARM = paper_arm()
SENTINEL = -999_999
DIALECTS = [("s7-200", None), ("s7-300", "native")]
OFFSETS = [0.0, 1e-9, -1e-9, 5e-7, -5e-7, 1e-6, -1e-6, 2e-6, -2e-6, 1e-4, -1e-4, 1e-2]


def _model_run(targets, branch, dialect, trig, theta1_on_axis=None) -> RunResult:
    """What the PLC returns according to the float32 model (outputs unchanged if refused)."""
    m = predict(
        ARM,
        targets,
        branch,
        ops=PlcFloat32Ops(dialect, trig),
        theta1_on_axis=theta1_on_axis,
    )
    pulses = np.where(m.reachable[:, None], m.pulses, SENTINEL)
    return RunResult(pulses, m.reachable, status=m.status)


def _check(targets, branch, dialect, trig, theta1_on_axis=None):
    df = pd.DataFrame(targets, columns=["x_mm", "y_mm", "z_mm"]).assign(kind="hypothesis")
    run = _model_run(targets, branch, dialect, trig, theta1_on_axis)
    cmp = compare(run, df, ARM, branch, dialect, SENTINEL, trig, theta1_on_axis=theta1_on_axis)
    assert cmp.status_mismatch == 0 and cmp.flag_mismatch == 0, (targets, run.status)
    assert cmp.all_explained, cmp.mismatch_table
    assert cmp.max_real_error < 0.05
    return run


directions = st.tuples(st.floats(-np.pi, np.pi), st.floats(-1.5, 1.5))


def _unit(azimuth, elevation):
    return np.array(
        [
            np.cos(elevation) * np.cos(azimuth),
            np.cos(elevation) * np.sin(azimuth),
            np.sin(elevation),
        ]
    )


@given(
    direction=directions,
    sphere=st.sampled_from(["inner", "outer"]),
    branch=st.sampled_from(BRANCHES),
    dialect=st.sampled_from(DIALECTS),
)
def test_reach_spheres_same_status_and_counts_as_python(direction, sphere, branch, dialect):
    """Across the folded-elbow and stretched spheres: refused where Python refuses, and no
    count a revolution off (the fold once gave PLC -2000 where Python gave +2000)."""
    radius = ARM.geometry["reach_inner" if sphere == "inner" else "reach_outer"]
    D = radius + np.array(OFFSETS)
    _check(ARM.shoulder + D[:, None] * _unit(*direction), branch, *dialect)


@given(
    height=st.floats(-505.0, 505.0).filter(lambda z: abs(z) > 111.0),
    azimuth=st.floats(-np.pi, np.pi),
    branch=st.sampled_from(BRANCHES),
    dialect=st.sampled_from(DIALECTS),
    waist=st.one_of(st.none(), st.floats(-np.pi, np.pi)),
)
def test_base_axis_same_status_and_waist_as_python(height, azimuth, branch, dialect, waist):
    """Within the tolerance of the axis the PLC refuses (status base-axis) exactly where Python
    does, and with a waist angle both solve it at that angle."""
    rho = np.abs(np.array(OFFSETS))
    t = np.stack(
        [rho * np.cos(azimuth), rho * np.sin(azimuth), np.full_like(rho, ARM.params.L1 + height)],
        axis=1,
    )
    run = _check(t, branch, *dialect, theta1_on_axis=waist)
    if waist is None:  # the refused ones are the base-axis ones, and only those
        assert set(run.status.tolist()) <= {Status.OK, Status.BASE_AXIS}


@given(
    q=st.tuples(st.floats(-np.pi, np.pi), st.floats(-np.pi, np.pi), st.floats(0.3, 2.8)),
    joint=st.sampled_from([0, 1]),
    elbow=st.sampled_from([-1.0, 1.0]),
    offset=st.sampled_from(OFFSETS),
    branch=st.sampled_from(BRANCHES),
    dialect=st.sampled_from(DIALECTS),
)
def test_wrap_cut_only_whole_revolutions_at_plus_minus_180(
    q, joint, elbow, offset, branch, dialect
):
    """A joint at +-180 deg: the PLC may count it at the other end (one revolution), never
    anything else."""
    q = np.array([q[0], q[1], elbow * q[2]])
    q[joint] = np.pi + offset
    _check(ARM.fk(q)[None], branch, *dialect)

"""The REAL namespace (analysis.kinematics.ops.Float32Ops): every op keeps float32.

A float64 anywhere (a Python float parameter through ``abs``, once) carries the expressions it
enters into double precision, and the float32 model then differs from the PLC by an ulp."""

from __future__ import annotations

import numpy as np
import pytest

from analysis.kinematics.ops import OPS, Float32Ops

F32 = Float32Ops()


@pytest.mark.parametrize("x", [-2.5, 3, np.float64(-0.1), np.array([-1.0, 2.0])])
def test_abs_of_a_python_or_float64_number_is_a_real(x):
    y = F32.abs(x)
    assert np.asarray(y).dtype == np.float32
    assert np.all(y == np.float32(np.abs(x)))


@pytest.mark.parametrize("x", [0.5, -2.7])
def test_every_numeric_op_of_python_floats_is_a_real(x):
    checked = []
    for name, spec in OPS.items():
        fn = getattr(F32, spec.method, None)
        if fn is None or spec.kind in ("compare", "logic") or name == "isfinite":
            continue
        with np.errstate(all="ignore"):
            y = fn(*[x] * spec.arity)
        assert np.asarray(y).dtype == np.float32, name
        checked.append(name)
    assert {"abs", "trunc", "sign", "rint", "sqrt", "atan2", "select"} <= set(checked), checked
    assert np.asarray(F32.round(x)).dtype == np.float32

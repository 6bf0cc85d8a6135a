"""The output pool (analysis.kinematics.pool): blocks come back only when every array over
them is gone, are reused by size, and the pool keeps no more than its cap."""

from __future__ import annotations

import gc
import os
import subprocess
import sys

import numpy as np
import pytest

from analysis.kinematics import pool

pytest.importorskip("numba")
N = 200_000  # theta alone: 4 branches x 3 joints x 8 B x N = 19 MB, pooled


def _block_address(a: np.ndarray) -> int:
    """Address of the pooled block under a (possibly reshaped) result array."""
    while isinstance(a, np.ndarray):
        a = a.base
    assert type(a).__name__ == "_Exported", type(a)
    return a.__array_interface__["data"][0]


def test_a_released_result_is_reused_and_a_live_one_never(arm, rng):
    pool.clear()
    p = rng.uniform(-600, 600, (N, 3))
    first = arm.solve(p, "all", backend="compiled")
    expected = first.theta.copy()
    kept = first.theta[:, 2]  # a view keeps the whole block alive
    addr = _block_address(first.theta)
    del first
    gc.collect()
    second = arm.solve(p + 1.0, "all", backend="compiled")
    assert not np.shares_memory(kept, second.theta)
    released = {addr, _block_address(second.theta)}
    np.testing.assert_array_equal(kept, expected[:, 2])  # untouched by the second call
    del kept, second
    gc.collect()
    assert pool.retained_bytes() > 0
    third = arm.solve(p, "all", backend="compiled")
    np.testing.assert_array_equal(third.theta, expected)
    assert _block_address(third.theta) in released  # a block of a result that is gone


def test_pooled_results_equal_the_numpy_path(arm, rng):
    p = rng.uniform(-700, 700, (N, 3))
    for _ in range(2):  # the second call runs on reused blocks
        fast = arm.solve(p, "all", backend="compiled")
        ref = arm.solve(p, "all")
        np.testing.assert_array_equal(fast.status, ref.status)
        np.testing.assert_array_equal(fast.ok, ref.ok)
        np.testing.assert_allclose(fast.theta, ref.theta, atol=1e-12, equal_nan=True)
        del fast
        gc.collect()


def test_small_arrays_are_not_pooled_and_the_cap_holds():
    small = pool.empty((10, 3))
    assert small.base is None  # a plain np.empty
    assert pool.retained_bytes() <= pool.MAX_BYTES


@pytest.mark.parametrize(("value", "message"), [("-1", "must be >= 0"), ("lots", "whole number")])
def test_a_bad_pool_size_is_refused_naming_it(value, message):
    env = {**os.environ, "ANALYSIS_POOL_BYTES": value}
    run = subprocess.run([sys.executable, "-c", "import analysis.kinematics.pool"],
                         env=env, capture_output=True, text=True)  # fmt: skip
    assert run.returncode != 0 and message in run.stderr and value in run.stderr


def test_size_zero_turns_the_pool_off():
    code = (
        "import numpy as np; from analysis.kinematics import pool; a = pool.empty((1 << 20,));"
        "print(pool.MAX_BYTES, type(a.base).__name__)"
    )
    env = {**os.environ, "ANALYSIS_POOL_BYTES": "0"}
    run = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert run.stdout.split() == ["0", "NoneType"], run.stderr

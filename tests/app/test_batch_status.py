"""Per-branch status (issue 19): a branch without a solution says its true reason, in the batch
CSV (``ik --input --output --branch all``), on the command line (``ik --branch all --json``,
its ``missing`` list) and in :attr:`IKSolutions.branch_status` (numpy and compiled).

Before, a branch of a solvable target that had no solution was written "joint-limits" whatever
its reason: the GR-1's back wrist beyond the reach, or on the shoulder, was reported as a joint
limit. The oracle is independent of the batch code: the status of the same target solved for
that one branch alone (what a one-branch PLC program reports), and the same branch solved
without joint limits (a joint-limits row must be solvable without them, a refusal not).
"""

from __future__ import annotations

import contextlib
import csv
import io
import json

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from analysis.app.batch import input_columns, solve_csv
from analysis.app.cli import main
from analysis.kinematics.arm import load_arm
from analysis.kinematics.status import Status

ARMS = ("grabber", "palletizer", "gr1", "picker")


def _targets(arm, rng, n):
    """Targets of valid configurations, half of them moved by up to 20 % of their size (so
    that one branch may leave the reach or its limits while another stays)."""
    p = arm.target(arm.sample_q(rng, n))
    move = rng.normal(size=p[:, :3].shape) * 0.2 * np.abs(p[:, :3]).max()
    p[: n // 2, :3] += move[: n // 2]
    return p


def _oracle(arm, p):
    """(status per target and branch, solvable without joint limits per target and branch)."""
    one = np.stack([arm.solve(p, [b]).status for b in arm.branches], axis=-1)
    free = arm.solve(p, "all", limits=False).ok
    return one, free


def _check(arm, sol, p):
    one, free = _oracle(arm, p)
    np.testing.assert_array_equal(sol.branch_status, one)
    assert ((sol.branch_status == Status.OK) == sol.ok).all()
    jl = sol.branch_status == Status.JOINT_LIMITS
    assert free[jl].all()  # a joint-limits branch has a solution without the limits
    refused = (sol.branch_status != Status.OK) & ~jl
    assert not free[refused].any()  # a refused branch has none at all


@pytest.mark.parametrize("name", ARMS)
def test_branch_status_is_each_branch_true_reason(name):
    arm = load_arm(name)

    @settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(seed=st.integers(0, 2**32 - 1))
    def prop(seed):
        p = _targets(arm, np.random.default_rng(seed), 64)
        _check(arm, arm.solve(p), p)

    prop()


@pytest.mark.parametrize("name", ("grabber", "gr1"))
def test_compiled_branch_status_equals_numpy(name):
    arm = load_arm(name)
    p = _targets(arm, np.random.default_rng(3), 2000)
    a, b = arm.solve(p), arm.solve(p, backend="compiled")
    np.testing.assert_array_equal(a.branch_status, b.branch_status)


def _gr1_back_out_of_reach():
    """A GR-1 pose solved by a front branch whose back wrist is out of reach."""
    arm = load_arm("gr1")
    p = _targets(arm, np.random.default_rng(11), 400)
    sol = arm.solve(p)
    k = [arm.branches.index(b) for b in ("back-up", "back-down")]
    hit = np.flatnonzero(sol.ok.any(-1) & (sol.branch_status[:, k] == Status.OUT_OF_REACH).all(-1))
    assert hit.size, "no such pose drawn"
    return arm, p[hit[0]]


def test_batch_rows_say_each_branch_true_reason(tmp_path):
    """The issue's case in the batch CSV, then every arm's rows against the oracle."""
    _, pose = _gr1_back_out_of_reach()
    for name in ARMS:
        arm = load_arm(name)
        p = _targets(arm, np.random.default_rng(5), 200)
        if name == "gr1":
            p = np.vstack([pose, p])
        src, dst = tmp_path / f"{name}.csv", tmp_path / f"{name}_out.csv"
        user = np.where(np.array(arm.user_units) == "deg", np.degrees(p), p)
        with src.open("w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(input_columns(arm))
            w.writerows(user.tolist())
        solve_csv(arm, src, dst, branch="all")
        with dst.open() as fh:
            rows = list(csv.DictReader(fh))
        got = np.array([Status[r["status"].upper().replace("-", "_")] for r in rows])
        got = got.reshape(len(p), len(arm.branches))
        one, _ = _oracle(arm, arm.from_user(user))
        np.testing.assert_array_equal(got, one, err_msg=name)
        if name == "gr1":
            row = {r["branch"]: r["status"] for r in rows[: len(arm.branches)]}
            assert row["back-up"] == row["back-down"] == "out-of-reach", row


def test_command_line_missing_branches_say_their_reason():
    _, pose = _gr1_back_out_of_reach()
    user = [*pose[:3], *np.degrees(pose[3:])]
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(["ik", *map(repr, map(float, user)), "--arm", "gr1", "--branch", "all",
                     "--json"])  # fmt: skip
    assert code == 0, err.getvalue()
    doc = json.loads(out.getvalue())
    missing = {m["branch"]: m for m in doc["missing"]}
    assert missing["back-up"]["status"] == missing["back-down"]["status"] == "out-of-reach"
    assert "beyond" in missing["back-up"]["reason"] or "reach" in missing["back-up"]["reason"]

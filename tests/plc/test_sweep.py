"""The one PLC sweep generator (analysis.plc.sweep) holds what each kind promises, for every
arm: the four seed arms and a TOML-only arm with a derived closed form.

Checked against the arm's own solver (float64), independently of how the generator built
the targets: a half-pulse target has a joint of the program's branch within 1e-7 .. 1e-3
pulse of k + 1/2; a cut target a free revolute joint within 1e-4 rad of +-180 deg; a
joint-limit target a limited joint within 1e-2 of its limit; a ``-1mm`` target lies within
1 mm (along its ray) of a point whose status differs from its own or from its neighbour's on
the other side; the sweep is a function of the seed."""

from __future__ import annotations

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm
from analysis.plc.sweep import SweepSizes, sweep_targets
from analysis.plc.verify import input_columns

ARMS = ["grabber", "palletizer", "gr1", "picker"]


def _theta(arm, t, kind, branch=None, limits=True):
    rows = t[t["kind"] == kind][input_columns(arm)].to_numpy(dtype=float)
    sol = arm.solve(rows, [branch or arm.branches[0]], limits=limits)
    return sol.theta[:, 0, :], sol


@pytest.fixture(scope="module")
def sweeps():
    return {name: (load_arm(name), sweep_targets(load_arm(name))) for name in ARMS}


@pytest.mark.parametrize("name", ARMS)
def test_half_pulse_targets_lie_within_1e_3_pulse_of_a_half(sweeps, name):
    arm, t = sweeps[name]
    theta, sol = _theta(arm, t, "half-pulse")
    assert len(theta) >= 100 and sol.ok.all()  # solved by the program's branch
    c = arm.pulse_values(theta)
    dist = np.abs(np.abs(c - np.trunc(c)) - 0.5)
    near = dist.min(axis=1)
    assert (near <= 1e-3 + 1e-9).all(), near.max()
    # every joint gets its turn (the pinned one cycles)
    assert len(set(np.argmin(dist, axis=1).tolist())) == arm.n_joints


@pytest.mark.parametrize("name", ARMS)
def test_cut_targets_put_a_free_joint_at_180_deg(sweeps, name):
    arm, t = sweeps[name]
    theta, sol = _theta(arm, t, "cut")
    free = [j for j, (u, lim) in enumerate(zip(arm.joint_units, arm.limits, strict=True))
            if u == "rad" and lim is None]  # fmt: skip
    assert len(theta) >= 40 and sol.ok.all()
    off = np.pi - np.abs(theta[:, free])
    assert (off.min(axis=1) <= 1e-4 + 1e-9).all(), off.min(axis=1).max()


@pytest.mark.parametrize("name", ["palletizer", "gr1", "picker"])
def test_joint_limit_targets_put_a_limited_joint_at_its_limit(sweeps, name):
    arm, t = sweeps[name]
    theta, _ = _theta(arm, t, "joint-limit", limits=False)
    limited = [j for j, lim in enumerate(arm.limits) if lim is not None]
    b = arm.bounds[limited]
    with np.errstate(invalid="ignore"):
        d = np.minimum(np.abs(theta[:, limited] - b[:, 0]), np.abs(theta[:, limited] - b[:, 1]))
    solved = np.isfinite(d).all(axis=1)
    assert solved.sum() >= 40
    assert (np.nanmin(d[solved], axis=1) <= 1e-2 + 1e-9).all()
    # some exactly on a limit (a stop: the palletizer's initial pose class)
    assert (np.nanmin(d[solved], axis=1) <= 1e-9).any()


@pytest.mark.parametrize("name", ARMS)
def test_every_status_of_the_arm_occurs_and_the_seed_fixes_the_sweep(sweeps, name):
    arm, t = sweeps[name]
    x = t[input_columns(arm)].to_numpy(dtype=float)
    finite = np.isfinite(x).all(axis=1)
    seen = set(np.unique(arm.solve(x[finite], [arm.branches[0]]).status).tolist())
    assert {int(s) for s in arm.statuses} - {2, 5, 7} <= seen | {2, 5, 7}, seen
    assert seen >= {0, 1, 3}, seen  # solved, out of reach, on the base axis: every arm
    assert (~finite).sum() == len(arm.inputs)  # one NaN/inf per input
    again = sweep_targets(arm)
    assert again.equals(t)
    other = sweep_targets(arm, seed=1)
    assert not np.allclose(other[input_columns(arm)].to_numpy()[:50], x[:50], equal_nan=True)


def test_a_derived_arm_and_a_small_sweep(tmp_path):
    """A TOML-only arm (closed form derived from its D-H table) gets every kind its contract
    implies; sizes scale; an unknown branch is the solver's error."""
    from analysis.kinematics.derive.samples import random_arm

    path = tmp_path / "arm.toml"
    path.write_text(random_arm(np.random.default_rng(11), "3R", "modified", "arm"), "utf-8")
    arm = load_arm(str(path))
    t = sweep_targets(arm, sizes=SweepSizes().scaled(0.3))
    assert {"config", "box", "half-pulse", "cut", "joint-limit", "bad", "huge"} <= set(t["kind"])
    assert any(k.endswith("-1mm") for k in t["kind"])
    assert 250 < len(t) < 450
    with pytest.raises(ValueError, match="branch"):
        sweep_targets(arm, branch="sideways")

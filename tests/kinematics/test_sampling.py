"""analysis.kinematics.sampling: Arm.sample_q, the one sampler of valid configurations.

For every seed arm: the configurations lie within the joint limits, their targets are
solved with the margins (outside every refusal band), each configuration is one of its own
target's IK solutions (of the requested branch, if named); a seed gives one sequence. The
reference for "solves back" is a second, independent check: FK(q) against FK of the solved
angles, not the sampler's own comparison.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm
from analysis.kinematics.sampling import SAMPLE_MARGIN_MM, SAMPLE_MARGIN_RAD, sample_q
from analysis.kinematics.status import Status

ARMS = ("grabber", "palletizer", "gr1", "picker")


@pytest.mark.parametrize("name", ARMS)
def test_valid_configurations_of_every_seed_arm(name):
    arm = load_arm(name)
    q = arm.sample_q(np.random.default_rng(5), 300)
    assert q.shape == (300, arm.n_joints)
    assert ((q >= arm.bounds[:, 0]) & (q <= arm.bounds[:, 1])).all()
    target = arm.target(q)
    banded = arm.solve(target, margin_mm=SAMPLE_MARGIN_MM, margin_rad=SAMPLE_MARGIN_RAD)
    assert (banded.status == Status.OK).all()
    # one of the solutions reaches FK(q) with the same joint values (up to whole turns)
    sol = arm.solve(target)
    angle = np.array([u == "rad" for u in arm.joint_units])
    d = sol.theta - q[:, None, :]
    d = np.where(angle, np.mod(d + np.pi, 2 * np.pi) - np.pi, d)
    same = sol.ok & (np.abs(d) < 1e-9).all(axis=-1)
    assert same.any(axis=-1).all()
    np.testing.assert_array_equal(q, arm.sample_q(np.random.default_rng(5), 300))


@pytest.mark.parametrize(("name", "branch"), [("grabber", "back-down"), ("picker", "front-flip")])
def test_a_named_branch(name, branch):
    arm = load_arm(name)
    q = arm.sample_q(np.random.default_rng(1), 200, branch=branch)
    sol = arm.solve(arm.target(q), [branch])
    assert sol.ok.all()
    angle = np.array([u == "rad" for u in arm.joint_units])
    d = sol.theta[:, 0] - q
    d = np.where(angle, np.mod(d + np.pi, 2 * np.pi) - np.pi, d)
    assert np.abs(d).max() < 1e-9


def test_the_margin_keeps_targets_off_the_reach_shells():
    """The grabber's targets lie at least margin_mm inside its reach shells."""
    arm = load_arm("grabber")
    q = arm.sample_q(np.random.default_rng(2), 2000, margin_mm=0.5)
    d = np.linalg.norm(arm.fk(q) - arm.shoulder, axis=-1)
    geo = arm.geometry
    assert d.max() <= geo["reach_outer"] - 0.5 and d.min() >= geo["reach_inner"] + 0.5
    assert np.hypot(*arm.fk(q)[:, :2].T).min() >= 0.5  # off the base axis too


def test_bad_arguments_and_an_arm_of_no_valid_configuration():
    arm = load_arm("grabber")
    with pytest.raises(ValueError, match=r"expected a numpy\.random\.Generator"):
        arm.sample_q(np.random.RandomState(1), 3)
    with pytest.raises(ValueError, match=r"n = -1: expected a whole number >= 0"):
        arm.sample_q(np.random.default_rng(1), -1)
    with pytest.raises(ValueError, match="unknown branch"):
        arm.sample_q(np.random.default_rng(1), 3, branch="sideways")
    assert arm.sample_q(np.random.default_rng(1), 0).shape == (0, 3)
    # a hook that proposes only configurations outside the limits: refused with counts
    outside = dataclasses.replace(
        arm.closed_form, propose=lambda rng, n, P, bounds: np.full((n, 3), 10.0)
    )
    arm = dataclasses.replace(arm, closed_form=outside)  # a new Arm: the loaded one is shared
    with pytest.raises(ValueError, match=r"only 0 of \d+ candidate configurations solve back"):
        sample_q(arm, np.random.default_rng(1), 5)

"""The boundary conventions of the 3R closed form, as properties (issue 13, item 4).

``analysis.kinematics.arms.grabber`` ("Conventions at the boundaries"): theta3 is never
wrapped, so a target moving through the folded-elbow sphere keeps a continuous theta3 count;
theta1 and theta2 are wrapped to (-pi, pi] and jump by one revolution only on the wrap cut;
the base axis is refused (status ``base-axis``) unless a waist angle is given.
``tests/plc/test_conventions_plc.py`` holds the generated PLC program to the same.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from analysis.kinematics.arm import DEFAULT_TOL_MM, paper_arm
from analysis.kinematics.pulses import angles_to_pulses
from analysis.kinematics.status import Status

ARM = paper_arm()
PPR = 4000
# distances from the folded-elbow sphere into the shell [mm]: from 0.9 tol on the refused side
# (put on the sphere) to 1e-3 mm into the reachable shell
FOLD_STEPS = np.array([-0.9, -0.5, -1e-3, 0.0, 1e-3, 0.5, 1.0, 2.0, 10.0, 1e3]) * DEFAULT_TOL_MM


def _direction(azimuth, elevation):
    return np.array(
        [
            np.cos(elevation) * np.cos(azimuth),
            np.cos(elevation) * np.sin(azimuth),
            np.sin(elevation),
        ]
    )


@given(
    azimuth=st.floats(-np.pi, np.pi),
    # |elevation| <= 1.4 rad keeps the fold points >= 18 mm from the base axis
    elevation=st.floats(-1.4, 1.4),
)
def test_the_fold_keeps_every_count_continuous_but_at_the_wrap_cut(azimuth, elevation):
    """Across |P - shoulder| = L2 - L3 no count jumps; theta3 stays on its branch's side.

    (The fold once gave theta3 = +pi on one side and -pi 1e-7 mm away: c3 +2000 / -2000.)"""
    D = ARM.geometry["reach_inner"] + FOLD_STEPS  # from just inside (within tol) outwards
    p = ARM.shoulder + D[:, None] * _direction(azimuth, elevation)
    sol = ARM.solve(p)
    assert (sol.status == Status.OK).all(), (sol.status, D)
    c = angles_to_pulses(sol.theta, PPR)  # (steps, 4 branches, 3)
    for b, name in enumerate(ARM.branches):
        c3 = c[:, b, 2]
        up = (name.endswith("up")) == name.startswith("front")  # theta3 <= 0
        assert ((c3 <= 0) if up else (c3 >= 0)).all(), (name, c3)
        assert np.abs(np.diff(c3)).max() <= 2, (name, c3)  # never the 4000 of a wrap
        for j in (0, 1):
            step = np.diff(c[:, b, j])
            lap = np.round(step / PPR) * PPR
            assert np.abs(step - lap).max() <= 2, (name, j, c[:, b, j])
            # a whole revolution only where the path crosses +-pi (the wrap cut): both ends
            # of the jump within a few pulses of +-ppr/2
            jumped = np.nonzero(lap)[0]
            ends = np.abs(c[np.concatenate([jumped, jumped + 1]), b, j])
            assert (ends >= PPR // 2 - 3).all(), (name, j, c[:, b, j])


@given(
    height=st.floats(-505.0, 505.0).filter(lambda z: abs(z) > 111.0),
    radius=st.sampled_from([0.0, 1e-9, 1e-7, 0.9e-6, 1.1e-6, 1e-5, 1e-3]),
    azimuth=st.floats(-np.pi, np.pi),
    waist=st.floats(-np.pi, np.pi),
)
def test_base_axis_refused_within_the_tolerance_or_solved_with_the_given_waist(
    height, radius, azimuth, waist
):
    p = np.array([radius * np.cos(azimuth), radius * np.sin(azimuth), ARM.params.L1 + height])
    on_axis = radius <= DEFAULT_TOL_MM
    sol = ARM.solve(p[None])
    assert sol.status[0] == (Status.BASE_AXIS if on_axis else Status.OK)
    assert np.isnan(sol.theta[0]).all() == on_axis
    given_waist = ARM.solve(p[None], theta1_on_axis=waist)
    assert given_waist.status[0] == Status.OK
    if on_axis:  # the given waist angle (front) and waist + pi (back), wrapped
        front = np.angle(np.exp(1j * waist))
        back = np.angle(np.exp(1j * (waist + np.pi)))
        expected = [front, front, back, back]
        diff = np.angle(np.exp(1j * (given_waist.theta[0, :, 0] - expected)))
        assert np.abs(diff).max() < 1e-12, (given_waist.theta[0, :, 0], expected)
    # on the axis within the tolerance the target is taken as on it: reached within tol
    miss = np.linalg.norm(ARM.fk(given_waist.theta[0]) - p, axis=-1)
    assert miss.max() <= (DEFAULT_TOL_MM if on_axis else 0.0) + 1e-9, miss

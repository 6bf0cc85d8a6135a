"""Valid configurations of any arm: the one seeded sampler (``Arm.sample_q``).

A configuration is *valid* when the arm's closed form solves it back: it lies within the
joint limits, its target (:meth:`analysis.kinematics.arm.Arm.target`) is outside every
refusal band (a margin inside each reach shell, around each singular set, off each angular
tolerance: :func:`~analysis.kinematics.solution.refusal_options`), and one of the IK
solutions of that target (of the requested branch, if one is named) is the configuration
itself. Every test, audit and PLC sweep that needs "seeded valid configurations" draws them
here, for every arm, instead of writing its own ranges.

Method: rejection sampling, vectorized per round (no loop over points): candidates uniform
within :attr:`~analysis.kinematics.arm.Arm.bounds` (the joint limits; one turn where a
joint is unrestricted), or from the closed form's ``sample_q`` hook where uniform draws are
not configurations of the arm (the palletizer keeps its gripper level: its theta4 follows
from theta2 and theta3); candidates without a pose (the picker's link 5 not closing) are
dropped; the rest are solved with the margins and kept where a solution equals the
candidate to :data:`SOLVE_BACK_TOL` (angles compared modulo a turn). Rounds repeat until
``n`` are kept; the kept ones are in the order drawn, so a seed gives one sequence.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["SAMPLE_MARGIN_MM", "SAMPLE_MARGIN_RAD", "SOLVE_BACK_TOL", "candidates", "sample_q"]

SAMPLE_MARGIN_MM = 0.01
"""Default band [mm] kept clear of every reach shell and singular set: ten times the band
the generated PLC programs refuse (:data:`analysis.plc.model.PLC_MARGIN_MM`, 1e-3 mm), so a
sampled target is solved by the PLC's float32 arithmetic too."""
SAMPLE_MARGIN_RAD = 4e-5
"""Default band [rad] kept clear of every angular tolerance (the GR-1's orientation, the
picker's wrist singularity): twice the PLC's (2e-5 rad); the GR-1 accepts an orientation
1e-4 rad out of its arm plane, so a band must stay below that."""
SOLVE_BACK_TOL = 1e-7
"""A solution equals the candidate when every joint agrees to this [rad | mm]: float64
round-off through FK and IK is ~1e-12 here (away from the refusal bands), a different
branch differs by far more than this."""
MAX_ROUNDS = 64


def _uniform(rng: np.random.Generator, n: int, bounds: npt.NDArray[np.float64]):
    return bounds[:, 0] + rng.random((n, len(bounds))) * (bounds[:, 1] - bounds[:, 0])


def candidates(
    arm, rng: np.random.Generator, n: int, bounds: npt.ArrayLike | None = None
) -> npt.NDArray[np.float64]:
    """``n`` candidate configurations (n, n_joints) within ``bounds`` (n_joints, 2) (default
    :attr:`~analysis.kinematics.arm.Arm.bounds`): the closed form's ``sample_q`` hook, or
    uniform draws; not yet checked against the solver (:func:`sample_q` does that). A bound
    with lower = upper pins a joint (the hook may derive a joint from others instead: the
    palletizer's theta4; check the result).

    >>> import numpy as np
    >>> from analysis.kinematics.arm import load_arm
    >>> arm = load_arm("palletizer")
    >>> b = arm.bounds.copy(); b[2] = np.pi
    >>> q = candidates(arm, np.random.default_rng(0), 3, b)
    >>> level = np.exp(1j * q[:, 1:].sum(axis=1))  # theta2 + theta3 + theta4 = pi/2 (mod 2 pi)
    >>> bool((q[:, 2] == np.pi).all()), bool(np.allclose(level, 1j))
    (True, True)
    """
    b = arm.bounds if bounds is None else np.asarray(bounds, dtype=float)
    propose = arm.closed_form.propose
    q = propose(rng, n, arm.params, b) if propose else _uniform(rng, n, b)
    return np.asarray(q, dtype=float).reshape(n, arm.n_joints)


def sample_q(
    arm,
    rng: np.random.Generator,
    n: int,
    *,
    branch: str | None = None,
    margin_mm: float = SAMPLE_MARGIN_MM,
    margin_rad: float = SAMPLE_MARGIN_RAD,
) -> npt.NDArray[np.float64]:
    """``n`` valid configurations (n, n_joints) [rad | mm] of ``arm``, seeded by ``rng``.

    Parameters
    ----------
    arm : Arm
    rng : numpy.random.Generator
    n : int
        How many (0 or more).
    branch : str, optional
        Keep only configurations that are this branch's solution of their own target
        (default: any branch's).
    margin_mm, margin_rad : float
        The refusal band kept clear [mm, rad] (:data:`SAMPLE_MARGIN_MM`,
        :data:`SAMPLE_MARGIN_RAD`; at most 1 mm and 0.1 rad).

    Raises
    ------
    ValueError
        For a bad ``n``, an unknown branch, or an arm of which too few candidates are valid
        (the message says how many of how many draws).

    Examples
    --------
    >>> import numpy as np
    >>> from analysis.kinematics.arm import load_arm
    >>> arm = load_arm("grabber")
    >>> q = arm.sample_q(np.random.default_rng(1), 4, branch="front-up")
    >>> q.shape, bool((q[:, 2] <= 0).all())
    ((4, 3), True)
    """
    if not isinstance(rng, np.random.Generator):
        raise ValueError(f"rng = {rng!r}: expected a numpy.random.Generator (default_rng(seed))")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0:
        raise ValueError(f"n = {n!r}: expected a whole number >= 0")
    names = arm.branch_names(branch or "all")
    n = int(n)
    bounds = arm.bounds
    angle = np.array([u == "rad" for u in arm.joint_units])
    kept: list[npt.NDArray[np.float64]] = []
    have = drawn = 0
    for _ in range(MAX_ROUNDS):
        if have >= n:
            break
        k = max(64, 2 * (n - have))
        q = candidates(arm, rng, k, bounds)
        drawn += k
        inside = ((q >= bounds[:, 0]) & (q <= bounds[:, 1])).all(axis=1)
        q = q[inside]
        q = q[arm.valid_q(q)]
        if not len(q):
            continue
        sol = arm.solve(arm.target(q), names, margin_mm=margin_mm, margin_rad=margin_rad)
        diff = sol.theta - q[:, None, :]
        diff = np.where(angle, np.mod(diff + np.pi, 2 * np.pi) - np.pi, diff)
        back = sol.ok & (np.abs(diff) <= SOLVE_BACK_TOL).all(axis=-1)
        good = q[back.any(axis=-1)]
        kept.append(good)
        have += len(good)
    if have < n:
        raise ValueError(
            f"arm {arm.name}: only {have} of {drawn} candidate configurations solve back "
            f"(needed {n}); the joint limits may leave little of the reachable set, or the "
            "closed form needs a sample_q hook (analysis.kinematics.arms)"
        )
    return np.concatenate(kept)[:n] if kept else np.empty((0, arm.n_joints))

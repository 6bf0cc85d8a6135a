"""EAIK as the oracle of the derived closed forms: the same solution sets, arm by arm.

EAIK (Ostermeier, Külz and Althoff, RA-L 2025; PyPI ``eaik``, the ``bench`` extra, never a
runtime dependency) derives a subproblem decomposition of its own for 1R-6R chains and
solves it in C++. It is given each arm through Pinocchio's model of the D-H rows
(:func:`analysis.kinematics.pinocchio_model.build_model`: the joint frames at q = 0, whose z
axes are the joint axes, and the tool frame), so neither this project's screws nor its
derivation enter it.

What is compared, per configuration ``q`` (a tool pose ``T = FK(q)``):

- **3R** (a position solver): EAIK solves poses, and a 3R chain reaches only a 3-dimensional
  set of them. The chain is extended by a spherical wrist at the tool point (three
  perpendicular axes through it, a 6R arm EAIK solves completely) and given the position with
  a random orientation: the first three joints of EAIK's exact solutions (up to 8: each
  position solution with two wrist solutions) are the 3R arm's position solutions.
- **4R-kept, 5R, 2R-planar** (fewer joints than a pose has freedoms): EAIK solves the 6D
  pose of each derived branch; its exact solutions must be exactly the derived branches that
  reach that same pose (a 4-axis arm's front and back branches hold the tool turned by pi
  about the waist, so they are different poses; a 5-axis arm's back branches reverse the
  hand; a planar arm's righty and lefty branches turn the tool differently).
- **6R-wrist, 6R-parallel, 3R-planar** (the target fixes the whole pose): EAIK solves the
  pose; its exact solutions must be exactly the derived branches.

**Axis senses.** A joint axis parallel to an earlier one is given to the oracles pointing
the same way as that one (:func:`axis_senses`: the frame turned by pi about its x axis, the
joint's value negated on the way back), the same robot. EAIK 1.2.2 (and IK-Geo 1.0.3's
``three_parallel_two_intersecting``) take anti-parallel axes as parallel but solve them as if
they pointed the same way (the sum of the three parallel turns): on the UR5 itself, with
joint 3's axis written the other way (``h3 -> -h3``), neither reaches one of 50 poses of
its own forward kinematics, within ~1.8 m (``tests/kinematics/test_families_oracles.py``).
That was the "oracle empty" of the random UR-family arms: 12 of 20 had a parallel twist of
180 deg.

Prismatic joints (SCARA, gantries) are outside EAIK (revolute chains only): pyplcopen's
kinematics is their oracle (:mod:`.plcopen_oracle`).

Solutions are compared as sets of joint vectors modulo 2 pi (:data:`ANGLE_TOL` rad). An
EAIK solution counts where EAIK's own forward kinematics reaches the pose
(:data:`POSE_TOL`), not by its least-squares flag: on seed 001's palletizer family (EAIK
classifies it "4R-THIRD_FOURTH_INTERSECTING") EAIK 1.2.2 returns the exact solutions of a
pose but flags all but one of them ``is_LS`` (measured: :attr:`Agreement.flagged_ls`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

__all__ = [
    "ANGLE_TOL",
    "POSE_TOL",
    "Agreement",
    "available",
    "axis_senses",
    "compare_solution_sets",
    "eaik_model",
    "eaik_robot",
]

ANGLE_TOL = 1e-6
"""Largest joint difference [rad] (modulo 2 pi) of two solutions counted as the same. The
derived closed forms and EAIK each reach their solutions to ~1e-12 rad away from
singularities; 1e-6 rad tells distinct solutions apart unless they nearly coincide (a target
within ~1e-9 mm of a reach boundary, which random configurations do not produce)."""


POSE_TOL = 1e-6
"""Largest deviation of an EAIK solution's pose from the requested one (rotation entries
[-], position [mm] / 1000) for it to count as a solution. EAIK reaches its solutions of the
4R-kept family to ~2e-8 (measured), its other candidates miss by more than 7e-2."""


WHOLE_POSE = ("6R-wrist", "6R-parallel", "3R-planar")
"""Families whose target fixes the tool's whole pose: every branch reaches the same one."""


def available() -> bool:
    """True if EAIK is installed (``make bench`` installs it; ``make test`` skips without)."""
    try:
        import eaik  # noqa: F401
    except ImportError:
        return False
    return True


def _joint_frames(arm) -> list[np.ndarray]:
    """Pinocchio's joint frames at q = 0 (z = the joint axis) and the tool frame (4, 4)."""
    import pinocchio as pin

    from analysis.kinematics.pinocchio_model import TOOL_FRAME, build_model

    model = build_model(arm.table)
    data = model.createData()
    pin.framesForwardKinematics(model, data, np.zeros(model.nq))
    frames = [data.oMi[j].homogeneous.copy() for j in range(1, model.njoints)]
    frames.append(data.oMf[model.getFrameId(TOOL_FRAME)].homogeneous.copy())
    return frames


_WRIST = np.linalg.qr(np.array([[0.3, 0.8, -0.5], [0.9, -0.2, 0.4], [0.1, 0.6, 0.8]]))[0]
"""Three perpendicular axes of the spherical wrist added to a 3R arm (a generic basis: no
axis along one of the arm's)."""


PARALLEL_TOL = 1e-9
"""Largest |h_i x h_j| of two joint axes taken as parallel by :func:`axis_senses`."""


def axis_senses(axes) -> np.ndarray:
    """+1 or -1 per joint axis (unit vectors): -1 where the axis is parallel to the one
    before it but, that one's sense applied, points the other way. Turning those axes round
    (and their joint values with them) describes the same robot with every run of parallel
    axes pointing one way, as the oracles' solvers assume (module docstring); axes parallel
    to a non-neighbour (the UR5's first and fifth) keep their sense, which they solve.

    >>> axis_senses(np.array([[0, 0, 1], [0, 1, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1.0]]))
    array([ 1.,  1., -1.,  1.,  1.])
    """
    h = np.asarray(axes, dtype=float)
    senses = np.ones(len(h))
    for i in range(1, len(h)):
        if np.linalg.norm(np.cross(h[i], h[i - 1])) < PARALLEL_TOL:
            senses[i] = senses[i - 1] * np.sign(np.dot(h[i], h[i - 1]))
    return senses


def eaik_robot(arm):
    """EAIK's model of ``arm`` (:func:`eaik_model`) where every axis keeps its sense (the
    published arms: raises otherwise, as its solutions would need mapping back)."""
    robot, senses = eaik_model(arm)
    if (senses < 0).any():
        raise ValueError(f"{arm.name}: axes turned round for EAIK; use eaik_model")
    return robot


def eaik_model(arm):
    """EAIK's model of ``arm`` (a 3R arm with the spherical wrist at its tool point) and
    the sense (+1 / -1) each joint's axis was given (:func:`axis_senses`): EAIK's joint
    values times the senses are the arm's."""
    from eaik.IK_Homogeneous import HomogeneousRobot

    frames = _joint_frames(arm)
    if arm.closed_form.family == "3R":
        tool = frames[-1]
        wrist = []
        for k in range(3):
            T = np.eye(4)
            z = _WRIST[:, k]
            x = np.cross(z, _WRIST[:, (k + 1) % 3])
            T[:3, :3] = np.stack([x, np.cross(z, x), z], axis=1)
            T[:3, 3] = tool[:3, 3]
            wrist.append(T)
        ee = np.eye(4)
        ee[:3, 3] = tool[:3, 3]
        frames = [*frames[:-1], *wrist, ee]
    senses = axis_senses([f[:3, 2] for f in frames[:-1]])
    turn = np.diag([1.0, -1.0, -1.0, 1.0])  # pi about x: z (the joint axis) turned round
    frames = [f @ turn if s < 0 else f for f, s in zip(frames, [*senses, 1.0], strict=True)]
    return HomogeneousRobot(np.array(frames)), senses


def _wrap(a):
    return np.angle(np.exp(1j * a))


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return bool(np.abs(_wrap(a - b)).max() < ANGLE_TOL)


def _unique(sols: list[np.ndarray]) -> list[np.ndarray]:
    out: list[np.ndarray] = []
    for s in sols:
        if not any(_same(s, t) for t in out):
            out.append(s)
    return out


def _match(a: list[np.ndarray], b: list[np.ndarray]) -> bool:
    return len(a) == len(b) and all(any(_same(x, y) for y in b) for x in a)


def _verdict(ours: list[np.ndarray], theirs: list[np.ndarray]) -> str:
    """ "equal", "empty" (EAIK found none), "subset" (EAIK found some of ours) or
    "disagree" (EAIK found one we lack)."""
    if not theirs:
        return "empty"
    if not all(any(_same(t, o) for o in ours) for t in theirs):
        return "disagree"
    return "equal" if _match(ours, theirs) else "subset"


@dataclass(frozen=True)
class Agreement:
    """The solution sets of one arm compared with EAIK's over ``n`` configurations."""

    family: str
    n: int
    equal: int
    """Configurations whose solution sets are equal."""
    eaik_empty: int
    """Configurations where EAIK returns no exact solution for some pose the derived
    branches reach (EAIK 1.2.2 does so on whole arms of the 4R and 5R families, while the
    derived solutions reach the pose: ``max_residual_mm``)."""
    eaik_subset: int
    """Configurations where EAIK's exact solutions are some of the derived ones but not all
    (EAIK 1.2.2 returns one of two exact solutions of a pose on some 4R arms, and the other
    when asked for the pose of the other branch: it misses solutions, the derived ones reach
    the pose, ``max_residual_mm``)."""
    disagree: int
    """Configurations where EAIK has an exact solution the derived closed form lacks: must
    be 0."""
    solutions: int
    """Derived solutions compared (joint vectors)."""
    flagged_ls: int
    """EAIK solutions that reach the pose but carry its least-squares flag."""
    max_residual_mm: float
    """Largest |FK(derived solution) - target| [mm] (the project's FK; position part)."""
    first_mismatch: str = ""

    @property
    def all_equal(self) -> bool:
        return self.equal == self.n


def _exact(robot, pose, sols, senses) -> tuple[list, int]:
    """EAIK's solutions that reach ``pose`` by EAIK's forward kinematics (as the arm's joint
    values: times ``senses``), and how many of them it flagged least-squares."""
    out, flagged = [], 0
    scale = np.ones((4, 4))
    scale[:3, 3] = 1e-3  # mm -> m: one tolerance for rotation and position
    for s, ls in zip(sols.Q, sols.is_LS, strict=True):
        if (np.abs(robot.fwdKin(s) - pose) * scale).max() < POSE_TOL:
            out.append(np.asarray(s) * senses)
            flagged += bool(ls)
    return out, flagged


def compare_solution_sets(arm, q: npt.ArrayLike, seed: int = 0) -> Agreement:
    """Compare the derived branches of the tool poses ``FK(q)`` (``q`` (N, n) within the
    family: a 4R-kept configuration holds the kept pitch) with EAIK's solutions."""
    q = np.atleast_2d(np.asarray(q, dtype=float))
    family = arm.closed_form.family
    robot, senses = eaik_model(arm)
    T = arm.table.fk(q)
    p = arm.closed_form.inputs_of(T)
    sol = arm.solve(p, limits=False)
    rng = np.random.default_rng(seed)
    tally = dict.fromkeys(("equal", "empty", "subset", "disagree"), 0)
    count = flagged = 0
    first = ""
    for i in range(len(q)):
        ours = [sol.theta[i, b] for b in range(len(sol.branches)) if sol.ok[i, b]]
        count += len(ours)
        verdicts = []
        if family == "3R":
            pose = np.eye(4)
            R = np.linalg.qr(rng.normal(size=(3, 3)))[0]
            pose[:3, :3] = R * np.sign(np.linalg.det(R))
            pose[:3, 3] = T[i, :3, 3]
            theirs, f = _exact(robot, pose, robot.IK(pose), senses)
            flagged += f
            verdicts.append(_verdict(_unique(ours), _unique([s[:3] for s in theirs])))
        elif family in WHOLE_POSE:
            theirs, f = _exact(robot, T[i], robot.IK(T[i]), senses)
            flagged += f
            verdicts.append(_verdict(_unique(ours), _unique(theirs)))
        else:
            Tb = arm.table.fk(np.array(ours)) if ours else np.zeros((0, 4, 4))
            for k in range(len(ours)):
                theirs, f = _exact(robot, Tb[k], robot.IK(Tb[k]), senses)
                flagged += f
                same = [ours[j] for j in range(len(ours)) if np.abs(Tb[j] - Tb[k]).max() < 1e-7]
                verdicts.append(_verdict(_unique(same), _unique(theirs)))
        # the configuration's verdict is its worst pose's (none derived: we missed q)
        order = ("disagree", "subset", "empty", "equal")
        worst = next((v for v in order if v in verdicts), "disagree")
        tally[worst] += 1
        if worst == "disagree" and not first:
            first = f"configuration {np.round(q[i], 6).tolist()}: {len(ours)} derived solutions"
    reached = np.where(
        sol.ok[..., None], arm.table.fk(np.nan_to_num(sol.theta))[..., :3, 3], np.nan
    )
    res = float(np.nanmax(np.linalg.norm(reached - T[:, None, :3, 3], axis=-1)))
    return Agreement(
        family, len(q), tally["equal"], tally["empty"], tally["subset"], tally["disagree"],
        count, flagged, res, first,
    )  # fmt: skip

"""An arm's closed form held against its own description at load time (issue 27 item 2).

A description may name any closed form (``closed_form = "grabber"``, a ``.py`` file next to
it) while its D-H rows describe another arm: a twist of -90 deg, a theta offset, a ``d``, a
tool row, two lengths swapped. The closed form would then answer "reachable" with angles that
the arm, moved by them, does not take to the target. :func:`check` refuses such an arm when
it loads: on seeded configurations within the joint limits (the closed form's ``sample_q``
hook where uniform draws are not configurations of the arm: the palletizer's level gripper)
it computes the target from the description's chain (:func:`analysis.kinematics.forward.
chain_points`: the FK of the rows), solves it with the closed form (every branch, joint
limits off) and requires

1. **FK of the IK reaches the target**: every solution the closed form gives puts the tool
   on the target within :data:`MISS_MM` (and, for a pose, the orientation within
   :data:`MISS_RAD`; a closed form that accepts an orientation within its own tolerance
   ``ORIENTATION_TOL_RAD`` and projects it, the derived 5R arms, within
   :data:`PROJECTION_TURN` times that tolerance and the tool offset times its sine), and
2. **IK of FK recovers the branch**: for at least :data:`RECOVER_SHARE` of the
   configurations one of the solutions is the configuration itself (within
   :data:`RECOVER_TOL`, angles modulo a turn) — the few left are targets the closed form
   refuses within a band of a boundary (a reach shell, a singular set).

The error names the largest miss: the configuration, where the rows put the tool, where the
closed form's solution puts it and by how much. The check runs once per description version,
closed form and parameter values (a cache: its cost is one vectorized solve of
:data:`SAMPLES` targets, a few milliseconds).

A closed form whose inputs are neither the tool point nor RPY angles cannot be held to the
chain this way (nothing says what its inputs mean); only the joint count is checked then.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from analysis.kinematics.forward import chain_points
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.rpy import rotation_angle, rpy_from_matrix
from analysis.kinematics.solution import DEFAULT_TOL_MM, solve_body

__all__ = ["MISS_MM", "MISS_RAD", "POSITION_INPUTS", "RECOVER_SHARE", "RPY_INPUTS", "SAMPLES",
           "check", "joint_bounds", "pose_of"]  # fmt: skip

POSITION_INPUTS = ("px", "py", "pz")
"""Closed-form inputs that are the tool point's coordinates x, y, z [mm]."""
RPY_INPUTS = ("alpha", "beta", "gamma")
"""Closed-form inputs that are the tool's orientation as RPY angles [rad]
(:mod:`analysis.kinematics.rpy`)."""
SAMPLES = 256
"""Configurations drawn per check (seeded)."""
MISS_MM = 1e-3
"""Largest accepted distance [mm] between the target and where a solution puts the tool:
the generated PLC programs' refusal band; a closed form of another arm misses by tens to
hundreds of millimetres (issue 27's variants: 40 to 1,010 mm), float64 round-off near a
singular set by 1e-8 mm."""
MISS_RAD = 1e-6
"""Largest accepted angle [rad] between the requested orientation and a solution's."""
PROJECTION_TURN = 4.0
"""How far [in units of its ``ORIENTATION_TOL_RAD``] a pose arm's solution may turn the hand
from the requested orientation, where the closed form accepts an orientation within that
tolerance and projects it (the derived 5R arms with a lateral offset, on their back
branches): measured up to 2.2 on random 5R arms (``derive.samples.random_arm``, 2,000
configurations each)."""
RECOVER_TOL = 1e-6
"""A solution is the configuration itself when every joint agrees to this [rad | mm]."""
RECOVER_SHARE = 0.9
"""Share of the configurations whose own solution the closed form must return."""


def joint_bounds(desc) -> np.ndarray:
    """(n, 2) bounds of every joint [rad | mm]: its limits, one turn where unrestricted."""
    return np.array([(max(j.lower, -math.pi), min(j.upper, math.pi)) if j.kind == "revolute"
                     else (j.lower, j.upper) for j in desc.joints])  # fmt: skip


def pose_of(desc, cf, P, q: np.ndarray, table=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tool points (..., 3) [mm], rotations (..., 3, 3) and the valid mask (...,) of joint
    values ``q`` (..., n), from :func:`~analysis.kinematics.forward.chain_points`."""
    shape = q.shape[:-1]
    with np.errstate(invalid="ignore"):
        out = chain_points(numpy_ops, desc, cf, P, list(np.moveaxis(q, -1, 0)), table)
    point = np.stack([np.broadcast_to(c, shape) for c in out["frames"][-1]], axis=-1)
    rot = out["rotation"]
    R = np.full((*shape, 3, 3), np.nan)
    if rot is not None:
        for i, row in enumerate(rot):
            for j, v in enumerate(row):
                R[..., i, j] = v
    valid = np.broadcast_to(np.asarray(out["valid"], dtype=bool), shape)
    return point.astype(float), R, valid


def _targets(cf, point, R) -> np.ndarray:
    values = dict(zip(POSITION_INPUTS, np.moveaxis(point, -1, 0), strict=True))
    if set(RPY_INPUTS) & set(cf.inputs):
        values |= dict(zip(RPY_INPUTS, np.moveaxis(rpy_from_matrix(R), -1, 0), strict=True))
    return np.stack([values[k] for k in cf.inputs], axis=-1)


def _fmt(v, unit: str = "") -> str:
    return "(" + ", ".join(f"{x:.6g}" for x in v) + ")" + (f" {unit}" if unit else "")


def check(desc, cf, P) -> None:
    """Refuse closed form ``cf`` for description ``desc`` with parameters ``P`` where it
    disagrees with the description's chain (module docstring): ValueError naming the file,
    the closed form and the largest miss. Cached per (description, closed form, values)."""
    _check(desc, cf, tuple(P.items()))


@lru_cache(maxsize=512)
def _check(desc, cf, items: tuple) -> None:
    if not set(cf.inputs) <= set(POSITION_INPUTS + RPY_INPUTS):
        return
    P = dict(items)
    where = f"closed form {cf.name!r}"
    rng = np.random.default_rng(20270101)
    b = joint_bounds(desc)
    if cf.propose is not None:
        q = np.asarray(cf.propose(rng, SAMPLES, P, b), dtype=float)
    else:
        q = b[:, 0] + rng.random((SAMPLES, len(b))) * (b[:, 1] - b[:, 0])
    table = desc.dh_table(P) if desc.has_rows else None
    point, R, valid = pose_of(desc, cf, P, q, table)
    keep = valid & np.isfinite(point).all(axis=-1)
    q, point, R = q[keep], point[keep], R[keep]
    if not len(q):
        return
    target = _targets(cf, point, R)
    with np.errstate(invalid="ignore", divide="ignore"):
        r = solve_body(numpy_ops, cf, tuple(np.moveaxis(target, -1, 0)), P, cf.branches,
                       tol=DEFAULT_TOL_MM)  # fmt: skip
    revolute = np.array([j.kind == "revolute" for j in desc.joints])
    pose_in = bool(set(RPY_INPUTS) & set(cf.inputs))
    cols = [POSITION_INPUTS.index(k) for k in cf.inputs if k in POSITION_INPUTS]
    # a pose arm may accept an orientation within its tolerance and project it (the derived
    # 5R arms: the hand then turns by up to PROJECTION_TURN times it, the tool point moves
    # by the tool offset times the sine of that)
    tol_rad = float(getattr(cf, "ORIENTATION_TOL_RAD", 0.0) or 0.0)
    turn_ok = MISS_RAD + PROJECTION_TURN * tol_rad if pose_in else 0.0
    miss_ok = MISS_MM + float(cf.geometry(P).get("tool_offset", 0.0)) * math.sin(turn_ok)
    worst = (0.0, None)
    recovered = np.zeros(len(q), dtype=bool)
    for name in cf.branches:
        ok = np.broadcast_to(np.asarray(r[f"ok:{name}"], dtype=bool), (len(q),))
        qb = np.stack([np.broadcast_to(r[f"q:{name}:{j}"], (len(q),))
                       for j in range(len(b))], axis=-1)  # fmt: skip
        if not ok.any():
            continue
        diff = np.where(revolute, np.angle(np.exp(1j * (qb - q))), qb - q)
        recovered |= ok & (np.abs(diff).max(axis=-1) <= RECOVER_TOL)
        pb, Rb, _ = pose_of(desc, cf, P, np.where(ok[:, None], qb, q), table)
        miss = np.linalg.norm(pb[:, cols] - point[:, cols], axis=-1)
        score = miss / miss_ok
        if pose_in:
            turn = rotation_angle(Rb, R)
            score = np.maximum(score, turn / turn_ok)
        score = np.where(ok, np.nan_to_num(score, nan=np.inf), 0.0)
        i = int(np.argmax(score))
        if score[i] > 1.0 and score[i] > worst[0]:
            turned = f", turned {math.degrees(float(turn[i])):.4g} deg" if pose_in else ""
            worst = (float(score[i]), (name, i, float(miss[i]), turned, qb[i], pb[i]))
    if worst[1] is not None:
        name, i, miss, turned, qb, pb = worst[1]
        raise ValueError(
            f"{where} does not solve this description's D-H rows: at q = "
            f"{_fmt(_user(q[i], revolute))} the rows put the tool at {_fmt(point[i], 'mm')}; "
            f"its {name} solution q = {_fmt(_user(qb, revolute))} puts it at "
            f"{_fmt(pb, 'mm')}, {miss:.4g} mm off{turned} (the largest miss of {len(q)} "
            "sampled configurations; joint values in deg | mm): the closed form is another "
            "arm's; fix the rows or name the closed form that fits them"
        )
    share = float(recovered.mean())
    if share < RECOVER_SHARE:
        i = int(np.argmin(recovered))
        raise ValueError(
            f"{where} does not solve this description's D-H rows: it returns the "
            f"configuration itself for {recovered.sum()} of {len(q)} sampled configurations "
            f"(at least {RECOVER_SHARE:.0%} needed); e.g. q = {_fmt(_user(q[i], revolute))} "
            f"(deg | mm) puts the tool at {_fmt(point[i], 'mm')} and no solution is q"
        )


def _user(q, revolute) -> np.ndarray:
    return np.where(revolute, np.degrees(q), q)

"""The one PLC sweep generator: seeded test targets of any arm, labelled by kind.

Every arm's generated programs (the grabber, the palletizer, the GR-1, the picker, an arm
derived from its D-H table) are executed on awlsim, on the ST engine and in the S7-200
evaluator over :func:`sweep_targets` and compared with Python by
:func:`analysis.plc.verify.compare`. The targets are built from the typed arm contract only
(:class:`analysis.kinematics.arm.Arm`): its valid configurations
(:meth:`~analysis.kinematics.arm.Arm.sample_q`), its branches, joint limits, joint units,
pulses per revolution (eqs. 20-22) and its solver's statuses. Nothing here knows an arm by
name except :data:`PAPER_TARGETS` (the targets a paper prints, as data).

Kinds (in this order; a kind may be empty for an arm that has no such boundary):

``paper``
    The arm's start-up target and the targets its paper prints (:data:`PAPER_TARGETS`).
``config``
    Targets of valid configurations (any branch): within the reach and the joint limits.
``box``
    Positions uniform in a box 1.2 times the extent of the reachable positions (orientation
    inputs: those of valid configurations, mostly not takeable at that position).
``<status>-1mm``
    Each boundary of the reachable set that a target crosses when its position moves in
    its own vertical half-plane (the plane of the base axis: the arm's plane, so a pose's
    orientation stays takeable; a planar arm's own plane), found by bisection on the solver's
    status and named by the status there (``out-of-reach-1mm``, ``inside-reach-1mm``,
    ``joint-limits-1mm``, ...): 1e-3 .. 1 mm on either side of it. Horizontal rays along the
    waist's direction, half of them each way (joint limits ignored), find the axis, where
    the waist flips (``base-axis-1mm``; five exactly on the crossing; ``flip-1mm`` where the
    arm's waist turns fast there without a refusal: an offset shoulder).
``<status>-tol``
    The same for the angle inputs (a pose arm): the orientation moved from a takeable one
    until the status changes or the solution flips (``orientation-tol``: the GR-1's
    tolerance about its arm plane; ``degenerate-tol``: the picker's wrist at +-90 deg),
    then 1e-5 .. 1e-2 rad on either side, five exactly on it.
``joint-limit``
    A limited joint exactly at a limit (a sixth of the rows: configurations drawn with that
    bound pinned, :func:`analysis.kinematics.sampling.candidates`, so a coupled joint stays
    coupled), or one of the program's branch (cycling) pinned 1e-7 .. 1e-2 [rad | mm]
    inside or outside it.
``half-pulse``
    One joint (cycling over all) of the program's branch pinned within 1e-7 .. 1e-3 pulse of
    k + 1/2: where float32 arithmetic may round to the other side.
``cut``
    One revolute joint without limits (cycling) pinned at +-180 deg (the wrap cut of
    (-180, 180]), or within 1e-9 .. 1e-4 rad of it: float32 may give the same position
    one revolution apart.
``bad``, ``huge``
    NaN/inf in each input in turn; finite values whose squares overflow a REAL.

Pinning a joint: for an arm whose joints are independent, the configuration with joint j
set to the value is itself the answer; for one whose closed form couples joints (the
palletizer keeps its gripper level), the target of that configuration solves back to a
different j. :func:`pin_joint` therefore solves for the joint-space step ``s`` along joint
j with which the program's branch, solving the target of ``q + s e_j``, gives exactly the
value (secant iterations, every row at once), and keeps the rows that converge.

Method and cost: every step is a numpy operation over all rows (no loop over points); the
bisections take 48 solves of a few hundred targets. The default sizes give about 1,000 to
1,200 targets per arm, built in 0.1 s (the grabber) to 1.3 s (the picker; measured on a
loaded machine, sample_q's rejection rounds dominate).
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import Arm
from analysis.kinematics.status import STATUS_TEXT, Status
from analysis.plc.targets import PAPER_TARGETS, input_columns

__all__ = [
    "PAPER_TARGETS",
    "SweepSizes",
    "boundary_targets",
    "pin_joint",
    "sweep_targets",
]

BISECTIONS = 48
"""Bisection steps on a ray: from a bracket of up to 2^12 mm to below 1e-10 mm."""
PIN_ITERATIONS = 8
PIN_TOL = 1e-11
"""A pinned joint is kept where the branch's solution is the value to this [rad | mm]:
1e-7 pulse (the smallest half-pulse offset) is 1.6e-10 rad at 4000 pulses/rev."""


@dataclass(frozen=True)
class SweepSizes:
    """Targets drawn per kind (a kind may keep fewer: the rows that did not converge or
    are not of the kind are dropped, never replaced, so a seed gives one sweep)."""

    config: int = 250
    box: int = 250
    boundary: int = 240
    angle: int = 120
    joint_limit: int = 60
    axis: int = 60
    half: int = 150
    cut: int = 60

    def scaled(self, factor: float) -> SweepSizes:
        """Every size times ``factor`` (rounded; at least 1 where it was not 0)."""
        sizes = {f.name: getattr(self, f.name) for f in fields(self)}
        return SweepSizes(**{k: max(1, round(v * factor)) if v else 0 for k, v in sizes.items()})


def _wrap(a):
    return np.mod(a + np.pi, 2 * np.pi) - np.pi


def pin_joint(
    arm: Arm,
    branch: str,
    q0: npt.NDArray[np.float64],
    joint: npt.NDArray[np.int64],
    value: npt.NDArray[np.float64],
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.bool_]]:
    """Targets whose ``branch`` solution has joint ``joint[i]`` at ``value[i]``, and where.

    Parameters
    ----------
    q0 : (n, n_joints)
        Valid configurations of ``branch`` (:meth:`Arm.sample_q`), the starting points.
    joint : (n,) int
    value : (n,) [rad | mm]
        Revolute values are compared modulo one turn (a value of pi is met by -pi).

    Returns
    -------
    targets : (n, k)
        The arm's inputs (rows that did not converge hold a valid target, masked out).
    ok : (n,) bool
        Converged to :data:`PIN_TOL` (joint limits not applied; the solver's refusals are).
    """
    n = len(q0)
    rows = np.arange(n)
    revolute = np.array([u == "rad" for u in arm.joint_units])[joint]
    span = (arm.bounds[:, 1] - arm.bounds[:, 0])[joint]

    def resid(s):
        q = q0.copy()
        q[rows, joint] += s
        valid = arm.valid_q(q)
        q = np.where(valid[:, None], q, q0)
        p = arm.target(q)
        sol = arm.solve(p, [branch], limits=False)
        th = sol.theta[:, 0, :][rows, joint]
        d = th - value
        d = np.where(revolute, _wrap(d), d)
        good = valid & sol.ok[:, 0] & np.isfinite(d)
        return np.where(good, d, np.nan), p

    step0 = value - q0[rows, joint]
    step0 = np.where(revolute, _wrap(step0), step0)
    s_prev, h_prev = np.zeros(n), np.where(revolute, _wrap(-step0), -step0)
    s, (h, p) = step0, resid(step0)
    best_p, best_h = p, np.abs(h)
    for _ in range(PIN_ITERATIONS):
        if not (np.abs(h) > PIN_TOL).any():
            break
        with np.errstate(all="ignore"):
            slope = (h - h_prev) / (s - s_prev)
            s_new = np.where(np.abs(h) > PIN_TOL, s - h / slope, s)
        s_new = np.where(np.isfinite(s_new), s_new, s)
        s_new = np.where(revolute, _wrap(s_new), np.clip(s_new, -span, span))
        s_prev, h_prev = s, h
        s, (h, p) = s_new, resid(s_new)
        better = np.abs(h) < np.where(np.isnan(best_h), np.inf, best_h)
        best_p = np.where(better[:, None], p, best_p)
        best_h = np.where(better, np.abs(h), best_h)
    return best_p, np.nan_to_num(best_h, nan=np.inf) <= PIN_TOL


JUMP_RAD = 0.5
"""A solution that moves a revolute joint by more than this [rad] between two points of a
ray (0.02 rad apart on an angle ray; the waist against the ray's start on a ray towards
the base axis) crossed a singular set: the branch's solution flipped (the waist by pi on
the base axis, the picker's wrist at +-90 deg)."""


def _event(arm, branch, p, ref, *, limits, joints):
    """Mask of points ``p`` (..., k) refused, or whose solution moved ``joints`` by more
    than :data:`JUMP_RAD` from ``ref`` (..., n) (None: status only); and their solutions."""
    sol = arm.solve(p, [branch], limits=limits)
    theta = sol.theta[..., 0, :]
    out = sol.status != 0
    if ref is not None and len(joints):
        with np.errstate(invalid="ignore"):
            moved = np.abs(_wrap(theta[..., joints] - ref[..., joints])) > JUMP_RAD
        out |= moved.any(axis=-1)
    return out, theta


def boundary_targets(
    arm: Arm,
    branch: str,
    start: npt.NDArray[np.float64],
    direction: npt.NDArray[np.float64],
    rng: np.random.Generator,
    *,
    angle: bool,
    waist: bool = False,
    exact: int = 0,
    limits: bool = True,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """Targets on either side of the first boundary along rays, and the status there.

    ``start`` (n, k) are targets the branch solves, ``direction`` (n, k) the rays' unit
    steps. Position rays (``angle`` False) are searched at 1, 2, 4, ..., 4096 mm, angle rays
    every 0.02 rad up to 4 rad. A boundary is the first refused point or, where the solution
    flips (:data:`JUMP_RAD`: every revolute joint on an angle ray between neighbouring
    points; with ``waist`` the waist against the start), the flip; :data:`BISECTIONS`
    halvings put it at ``t`` (to ~1e-10 of the bracket). The targets are at ``t -+
    10^U(-3, 0)`` mm (angle rays: ``t -+ 10^U(-5, -2)`` rad), the first ``exact`` at ``t``
    itself (``waist``: the first ``exact`` whose waist flipped there); the status is the
    solver's at ``t``. ``limits=False``: the joint limits are no
    boundary (the singular sets and tolerances behind a slider's stroke, searched and named
    without them). Rays that meet no boundary are dropped.
    """
    steps = np.linspace(0.02, 4.0, 200) if angle else 2.0 ** np.arange(13)
    revolute = np.flatnonzero(np.array(arm.joint_units) == "rad")
    joints = revolute if angle else (revolute[:1] if waist else revolute[:0])
    theta0 = arm.solve(start, [branch], limits=limits).theta[:, 0, :]
    pts = start[:, None, :] + steps[None, :, None] * direction[:, None, :]
    sol = arm.solve(pts, [branch], limits=limits)
    theta = sol.theta[:, :, 0, :]
    prev = np.concatenate([theta0[:, None], theta[:, :-1]], axis=1) if angle else theta0[:, None]
    with np.errstate(invalid="ignore"):
        moved = np.abs(_wrap(theta[..., joints] - prev[..., joints])) > JUMP_RAD
    event = (sol.status != 0) | moved.any(axis=-1)
    hit = event.any(axis=1)
    j = np.argmax(event, axis=1)
    lo = np.where(j > 0, steps[np.maximum(j - 1, 0)], 0.0)
    hi = steps[j]
    start, direction, lo, hi = start[hit], direction[hit], lo[hit], hi[hit]
    ref = theta0[hit]
    if angle:  # the solution at lo: compared with it, a flip is a jump
        ref = np.where((j[hit] > 0)[:, None], theta[hit, np.maximum(j[hit] - 1, 0)], ref)
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        out, th = _event(arm, branch, start + mid[:, None] * direction, ref, limits=limits,
                         joints=joints)  # fmt: skip
        lo, hi = np.where(out, lo, mid), np.where(out, mid, hi)
        if angle:
            ref = np.where(out[:, None], ref, th)
    sol = arm.solve(start + hi[:, None] * direction, [branch], limits=limits)
    at = sol.status.astype(np.int64)
    m = len(start)
    side = rng.choice([-1.0, 1.0], m)
    off = 10.0 ** (rng.uniform(-5, -2, m) if angle else rng.uniform(-3, 0, m))
    t = hi + side * off
    # the exact ones: on a flip of the waist (the base axis) if that is what is searched
    flipped = at != 0
    if waist:
        with np.errstate(invalid="ignore"):
            flipped = np.abs(_wrap(sol.theta[:, 0, 0] - ref[:, 0])) > JUMP_RAD
        flipped |= at == Status.BASE_AXIS
    on = np.flatnonzero(flipped if waist else np.ones(m, dtype=bool))[:exact]
    t[on] = hi[on]
    return start + t[:, None] * direction, at


def _clear(arm: Arm, branch: str, p) -> npt.NDArray[np.bool_]:
    """Targets the branch solves with twice the programs' refusal band
    (:data:`analysis.plc.model.PLC_MARGIN_MM`, ``PLC_MARGIN_RAD``): a half pulse or a cut
    that the PLC solves too (a free elbow's +-180 deg is the folded arm, refused)."""
    from analysis.plc.model import PLC_MARGIN_MM, PLC_MARGIN_RAD

    sol = arm.solve(p, [branch], margin_mm=2 * PLC_MARGIN_MM, margin_rad=2 * PLC_MARGIN_RAD)
    return sol.ok[:, 0]


def _half_plane_rays(p, rng, position):
    """Unit steps (n, k) in the vertical half-plane of each target's position (radial and
    vertical components only), zero on the angle inputs; a planar arm's (two position
    inputs): any direction in its plane."""
    n = len(p)
    if len(position) == 2:
        a = rng.uniform(-np.pi, np.pi, n)
        d = np.zeros_like(p)
        d[:, position[0]], d[:, position[1]] = np.cos(a), np.sin(a)
        return d
    xyz = p[:, position]
    rho = np.hypot(xyz[:, 0], xyz[:, 1])
    er = np.stack([xyz[:, 0], xyz[:, 1]], -1) / np.where(rho > 0, rho, 1.0)[:, None]
    a = rng.uniform(-np.pi, np.pi, n)
    d = np.zeros_like(p)
    d[:, position[0]] = np.cos(a) * er[:, 0]
    d[:, position[1]] = np.cos(a) * er[:, 1]
    d[:, position[2]] = np.sin(a)
    return d


@dataclass(frozen=True)
class _Sweep:
    """What every kind of :func:`sweep_targets` needs: the arm, the program's branch, the
    seeded generator (drawn in the kinds' order: one seed gives one sweep), the sizes, the
    input columns by kind (``position``: px, py, pz; ``angle``: inputs in rad)."""

    arm: Arm
    branch: str
    rng: np.random.Generator
    sz: SweepSizes
    position: list[int]
    angle: npt.NDArray[np.intp]

    @property
    def k(self) -> int:
        return len(self.arm.inputs)


Parts = list[tuple[str, npt.NDArray[np.float64]]]


def _paper(s: _Sweep) -> npt.NDArray[np.float64]:
    """The arm's start-up target and the targets its paper prints."""
    arm = s.arm
    paper = [np.asarray(arm.startup_target, dtype=float)[None]] if arm.startup_target else []
    make = PAPER_TARGETS.get(arm.closed_form.name)
    if make is not None:
        paper.append(np.asarray(make(arm), dtype=float).reshape(-1, s.k))
    return np.concatenate(paper) if paper else np.empty((0, s.k))


def _box(s: _Sweep, cfg: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Positions uniform in a box 1.2 times the extent of the reachable ones ``cfg``."""
    n = s.sz.box
    lo, hi = cfg.min(axis=0), cfg.max(axis=0)
    centre, half = (lo + hi) / 2, 0.6 * (hi - lo) + 1.0
    box = cfg[s.rng.integers(0, len(cfg), n)].copy() if len(cfg) else np.zeros((n, s.k))
    for c in s.position:
        box[:, c] = centre[c] + s.rng.uniform(-2 * half[c], 2 * half[c], n) / 2
    return box


def _boundaries(s: _Sweep) -> Parts:
    """The boundaries crossed in the vertical half-plane (positions), toward the base axis
    along the waist's direction, then in the angles; named by the status there."""
    arm, branch, rng, position, angle = s.arm, s.branch, s.rng, s.position, s.angle
    n_b, n_x, n_a = s.sz.boundary, s.sz.axis, s.sz.angle
    q_b = arm.sample_q(rng, n_b + n_x + n_a, branch=branch)
    start = arm.target(q_b)
    found: list[tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], str]] = []
    if len(position) in (2, 3) and n_b:
        st = start[:n_b]
        found.append((*boundary_targets(arm, branch, st, _half_plane_rays(st, rng, position),
                                        rng, angle=False), "1mm"))  # fmt: skip
    if len(position) == 3 and n_x and arm.joint_units[0] == "rad":
        st = start[n_b : n_b + n_x]
        # the point whose azimuth the waist takes lies along +-e(theta1) (a back branch
        # faces away): every other ray the other way
        t1 = q_b[n_b : n_b + n_x, 0]
        sign = np.where(np.arange(len(st)) % 2 == 0, -1.0, 1.0)
        d = np.zeros_like(st)
        d[:, position[0]], d[:, position[1]] = sign * np.cos(t1), sign * np.sin(t1)
        found.append((*boundary_targets(arm, branch, st, d, rng, angle=False, waist=True,
                                        exact=5, limits=False), "1mm"))  # fmt: skip
    if len(angle) and n_a:
        st = start[n_b + n_x :]
        d = np.zeros_like(st)
        d[:, angle] = rng.normal(size=(len(st), len(angle)))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        found.append((*boundary_targets(arm, branch, st, d, rng, angle=True, exact=5,
                                        limits=False), "tol"))  # fmt: skip
    parts: Parts = []
    for pts, at, suffix in found:
        for code in np.unique(at):
            name = STATUS_TEXT[Status(int(code))] if code else "flip"
            parts.append((f"{name}-{suffix}", pts[at == code]))
    return parts


def _on_limits(s: _Sweep, limited: list[int], n_exact: int) -> npt.NDArray[np.float64]:
    """Targets with a limited joint exactly at a limit: candidate configurations with that
    bound pinned (the closed form's own sampler keeps coupled joints coupled) that the
    program's branch solves as this configuration (or refuses: a stop on a singular set,
    the palletizer's folded elbow), not another branch's."""
    from analysis.kinematics.sampling import candidates

    arm = s.arm
    on = []
    for i in range(2 * len(limited)):  # each bound of each limited joint (a few)
        j, end = limited[i // 2], i % 2
        b = arm.bounds.copy()
        b[j] = arm.bounds[j, end]
        q = candidates(arm, s.rng, 4 * n_exact, b)
        q = q[(q[:, j] == b[j, 0]) & arm.valid_q(q)]
        p = arm.target(q)
        sol = arm.solve(p, [s.branch], limits=False)
        d = np.abs(sol.theta[:, 0, j] - b[j, 0])
        d = np.minimum(d, 2 * np.pi - d) if arm.joint_units[j] == "rad" else d
        on.append(p[~sol.ok[:, 0] | (d <= PIN_TOL)])
    on_limit = np.concatenate(on)
    return on_limit[s.rng.permutation(len(on_limit))[:n_exact]]


def _joint_limit(s: _Sweep) -> Parts:
    """A limited joint exactly at its limit (a sixth of the rows), or the program's branch
    pinned 1e-7 .. 1e-2 inside or outside it."""
    arm, rng = s.arm, s.rng
    limited = [j for j, lim in enumerate(arm.limits) if lim is not None]
    if not (limited and s.sz.joint_limit):
        return []
    on_limit = _on_limits(s, limited, max(1, s.sz.joint_limit // 6))
    n = s.sz.joint_limit - len(on_limit)
    q0 = arm.sample_q(rng, 2 * n, branch=s.branch)
    j = np.array(limited)[np.arange(2 * n) % len(limited)]
    end = rng.integers(0, 2, 2 * n)
    off = rng.choice([-1.0, 1.0], 2 * n) * 10.0 ** rng.uniform(-7, -2, 2 * n)
    value = arm.bounds[j, end] + off
    p, ok = pin_joint(arm, s.branch, q0, j, value)
    return [("joint-limit", np.concatenate([on_limit, p[ok][:n]]))]


def _half_pulse(s: _Sweep) -> Parts:
    """One joint (cycling) within 1e-7 .. 1e-3 pulse of k + 1/2."""
    arm, rng, n = s.arm, s.rng, s.sz.half
    if not n:
        return []
    q0 = arm.sample_q(rng, 2 * n, branch=s.branch)
    j = np.arange(2 * n) % arm.n_joints
    c = arm.pulse_values(q0)[np.arange(2 * n), j]
    delta = rng.choice([-1.0, 1.0], 2 * n) * 10.0 ** rng.uniform(-7, -3, 2 * n)
    half = np.zeros_like(q0)
    half[np.arange(2 * n), j] = np.floor(c) + 0.5 + delta
    value = arm.from_pulses(half)[np.arange(2 * n), j]
    p, ok = pin_joint(arm, s.branch, q0, j, value)
    ok &= _clear(arm, s.branch, p)
    return [("half-pulse", p[ok][:n])]


def _cut(s: _Sweep) -> Parts:
    """A revolute joint without limits at the wrap cut +-180 deg, or within 1e-9 .. 1e-4
    rad of it."""
    arm, rng = s.arm, s.rng
    free = [j for j, (u, lim) in enumerate(zip(arm.joint_units, arm.limits, strict=True))
            if u == "rad" and lim is None]  # fmt: skip
    if not (free and s.sz.cut):
        return []
    n, m = s.sz.cut, 4 * s.sz.cut
    q0 = arm.sample_q(rng, m, branch=s.branch)
    j = np.array(free)[np.arange(m) % len(free)]
    off = rng.choice([-1.0, 0.0, 1.0], m) * 10.0 ** rng.uniform(-9, -4, m)
    p, ok = pin_joint(arm, s.branch, q0, j, np.pi + off)
    ok &= _clear(arm, s.branch, p)
    return [("cut", p[ok][:n])]


def _bad_huge(s: _Sweep, base: npt.NDArray[np.float64]) -> Parts:
    """NaN/inf in each input in turn (around ``base``), and finite values whose squares
    overflow a REAL."""
    k, angle = s.k, s.angle
    bad = np.tile(base, (k, 1))
    bad[np.arange(k), np.arange(k)] = np.array([np.nan, np.inf, -np.inf])[np.arange(k) % 3]
    mm = np.flatnonzero(np.array(s.arm.input_units) == "mm")
    huge = np.zeros((3 + bool(len(angle)), k))
    for row, vals in enumerate(([1e20, -1e20, 1e3], [3e38, 0.0, 0.0], [-1e30, 1e30, -1e30])):
        huge[row, mm] = np.resize(vals, len(mm))
    if len(angle):
        huge[3, mm] = base[mm]
        huge[3, angle[0]] = 1e30
    return [("bad", bad), ("huge", huge)]


def sweep_targets(
    arm: Arm,
    *,
    branch: str | None = None,
    seed: int = 20160501,
    sizes: SweepSizes | None = None,
) -> pd.DataFrame:
    """Seeded test targets of ``arm`` for its program of ``branch`` (default the arm's
    first), labelled by kind (module docstring).

    Returns
    -------
    DataFrame
        Columns ``kind`` and :func:`analysis.plc.targets.input_columns` (``x_mm, y_mm,
        z_mm`` for a point, else the inputs' names), in the order of the kinds.

    Examples
    --------
    >>> from analysis.kinematics.arm import load_arm
    >>> t = sweep_targets(load_arm("grabber"), sizes=SweepSizes().scaled(0.1))
    >>> sorted(set(t["kind"]))[:4]
    ['bad', 'base-axis-1mm', 'box', 'config']
    """
    branch = branch or arm.branches[0]
    arm.branch_names(branch)  # an unknown branch: the solver's error
    inputs = list(arm.inputs)
    s = _Sweep(
        arm, branch, np.random.default_rng(seed), sizes or SweepSizes(),
        [inputs.index(c) for c in ("px", "py", "pz") if c in inputs],
        np.flatnonzero(np.array(arm.input_units) == "rad"),
    )  # fmt: skip
    parts: Parts = [("paper", _paper(s))]
    # valid configurations of any branch: within the reach and the limits
    cfg = arm.target(arm.sample_q(s.rng, s.sz.config))
    parts += [("config", cfg), ("box", _box(s, cfg))]
    parts += _boundaries(s) + _joint_limit(s) + _half_pulse(s) + _cut(s)
    parts += _bad_huge(s, cfg[0] if len(cfg) else np.zeros(s.k))
    cols = input_columns(arm)
    frames = [pd.DataFrame(p, columns=cols).assign(kind=kind) for kind, p in parts if len(p)]
    return pd.concat(frames, ignore_index=True)[["kind", *cols]]

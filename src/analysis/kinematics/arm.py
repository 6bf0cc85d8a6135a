"""An arm: its description, its closed form, and the numeric kinematics derived from them.

:class:`Arm` ties together one description (``data/arms/<name>.toml``, read by
:mod:`analysis.kinematics.description`) and one closed form
(:mod:`analysis.kinematics.arms`). Nothing here is specific to an arm:

- forward kinematics and frame origins come from the D-H chain (:func:`chain_frames`, the
  one formula of :mod:`analysis.kinematics.dh` composed in a math namespace);
- the Jacobian is that chain differentiated by forward-mode duals
  (:class:`~analysis.kinematics.ops.DualOps`), not written by hand;
- :meth:`Arm.solve` runs the closed form and the shared solver body (:func:`solve_body`:
  statuses, joint limits, NaN where no solution) with numpy, or the compiled kernel
  generated from the very same body (:mod:`analysis.kinematics.compiled`).

Angles in radians, lengths in mm; joint arrays have shape ``(..., n)``, targets
``(..., 3)``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from types import ModuleType
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from analysis.kinematics.arms import closed_form
from analysis.kinematics.description import (
    MAX_PULSES_PER_REV,
    ArmDescription,
    check_pulses_per_rev,
    load_description,
)
from analysis.kinematics.dh import DHTable, chain_frames
from analysis.kinematics.ops import DualOps, Ops, numpy_ops
from analysis.kinematics.status import Status

__all__ = [
    "BRANCHES",
    "DEFAULT_TOL_MM",
    "MAX_JOINT_DEG",
    "MAX_TOL_MM",
    "Arm",
    "BaseAxisError",
    "IKSolutions",
    "Params",
    "Status",
    "UnreachableError",
    "as_points",
    "check_joints",
    "check_tol",
    "load_arm",
    "paper_arm",
    "solve_body",
]

BRANCHES: tuple[str, ...] = ("front-up", "front-down", "back-up", "back-down")
"""The paper's arm's branches (``analysis.kinematics.arms.grabber.BRANCHES``)."""
DEFAULT_TOL_MM = 1e-6
"""Default distance tolerance [mm]: targets this close outside the reach shell are put on
the shell (cos theta3 clipped to +-1), and targets this close to the base axis count as on
it. 1 nm is far below any mechanical meaning and far above float64 round-off at this
scale (|p| ~ 1e3 mm, eps * |p| ~ 2e-13 mm)."""
MAX_TOL_MM = 1.0
"""Largest accepted tolerance [mm]: a solution "on the shell" may miss the target by up to
the tolerance, and more than a millimetre would pass a visibly wrong pose as solved."""
MAX_JOINT_DEG = 3600.0
"""Largest accepted |joint angle| [deg] (ten turns): beyond it an input is a mistake of unit
or of digits, not a pose."""


class UnreachableError(ValueError):
    """The target lies outside the reachable set; ``distance_mm`` says how far."""

    def __init__(
        self,
        message: str,
        target,
        distance_mm: float,
        limit_mm: float = math.nan,
        status: Status = Status.OUT_OF_REACH,
    ):
        super().__init__(message)
        self.target = tuple(float(v) for v in target)
        self.distance_mm = float(distance_mm)
        self.limit_mm = float(limit_mm)
        self.status = Status(status)


class BaseAxisError(ValueError):
    """The target is on the base axis, where the waist angle is undefined."""

    def __init__(self, message: str, target):
        super().__init__(message)
        self.target = tuple(float(v) for v in target)


class IKSolutions(NamedTuple):
    """Batch IK result for targets of shape (...,) + (3,) and B branches of n joints.

    Attributes
    ----------
    theta : ndarray, shape (..., B, n)
        Joint angles [rad] (see the closed form for wrapping). NaN exactly where ``ok``
        is False.
    ok : ndarray of bool, shape (..., B)
        True where the branch has a solution within the joint limits.
    status : ndarray of int8, shape (...,)
        :class:`Status` code per target.
    outside_mm : ndarray, shape (...,)
        Signed distance outside the reachable set [mm]: > 0 unreachable (by that much),
        <= 0 reachable (its magnitude is the margin to the nearer boundary).
    branches : tuple of str
        Branch names along axis -2 of ``theta``.
    """

    theta: npt.NDArray[np.float64]
    ok: npt.NDArray[np.bool_]
    status: npt.NDArray[np.int8]
    outside_mm: npt.NDArray[np.float64]
    branches: tuple[str, ...]

    @property
    def reachable(self) -> npt.NDArray[np.bool_]:
        """Targets inside the reachable set within the tolerance ``solve`` used (base-axis
        and joint-limit targets included): consistent with ``status``."""
        return (self.status != Status.OUT_OF_REACH) & (self.status != Status.INSIDE_REACH)

    def branch(self, name: str) -> npt.NDArray[np.float64]:
        """Angles of one branch, shape (..., n)."""
        return self.theta[..., self.branches.index(name), :]


def as_points(
    p: npt.ArrayLike, name: str = "target", inputs: Sequence[str] = ("x", "y", "z")
) -> npt.NDArray[np.float64]:
    """Validate and convert targets to a float array of shape (..., k), k = len(inputs)
    (default (..., 3) = x, y, z [mm]).

    Raises ``ValueError`` naming the offending value for text, wrong shapes, NaN or inf.
    """
    try:
        arr = np.asarray(p, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} {p!r} is not numeric: {exc}") from None
    k = len(inputs)
    if arr.ndim == 0 or arr.shape[-1] != k:
        what = "(x, y, z) in mm" if k == 3 else "(" + ", ".join(inputs) + ")"
        raise ValueError(f"{name} has shape {arr.shape}; expected (..., {k}) = {what}")
    bad = ~np.isfinite(arr)
    if bad.any():
        idx = np.argwhere(bad)[0]
        where = "" if arr.ndim == 1 else f" at index {tuple(int(i) for i in idx[:-1])}"
        raise ValueError(
            f"{name}{where} has a non-finite coordinate: {arr[tuple(idx[:-1])].tolist()}"
        )
    return arr


def check_joints(q: npt.ArrayLike, n: int, name: str = "joint array") -> npt.NDArray[np.float64]:
    """Validate joint angles (..., n) [rad]: numeric, finite, within +-:data:`MAX_JOINT_DEG`."""
    try:
        q = np.asarray(q, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} {q!r} is not numeric: {exc}") from None
    if q.ndim == 0 or q.shape[-1] != n:
        raise ValueError(f"{name} has shape {q.shape}; expected (..., {n})")
    bad = ~np.isfinite(q) | (np.abs(q) > math.radians(MAX_JOINT_DEG))
    if bad.any():
        idx = tuple(int(i) for i in np.argwhere(bad)[0])
        v = q[idx]
        what = "is not finite" if not np.isfinite(v) else "is beyond"
        raise ValueError(
            f"{name}: theta{idx[-1] + 1} = {math.degrees(v) if np.isfinite(v) else v:g} deg "
            f"{what} (accepted: finite, |theta| <= {MAX_JOINT_DEG:g} deg, ten turns)"
        )
    return q


def check_tol(tol) -> float:
    """A distance tolerance [mm] in 0 .. :data:`MAX_TOL_MM`, else ValueError."""
    if not (
        isinstance(tol, (int, float, np.floating, np.integer))
        and not isinstance(tol, bool)
        and math.isfinite(tol)
        and 0 <= tol <= MAX_TOL_MM
    ):
        raise ValueError(
            f"tol = {tol!r} mm: the tolerance must be a finite number >= 0 mm "
            f"and <= {MAX_TOL_MM:g} mm"
        )
    return float(tol)


# --------------------------------------------------------------------------------------------
# parameters
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Params(Mapping):
    """The numbers of one arm: parameter values [mm] and pulses per revolution per joint.

    A read-only mapping of parameter names to values that also allows attribute access
    (``P.L1``) and, for named geometry of the closed form, ``P.reach_outer`` etc.
    """

    arm: str
    data: Mapping[str, float]
    pulses_per_rev: tuple[int, ...]
    description: ArmDescription = field(compare=False, repr=False, default=None)
    extra: Mapping = field(default_factory=dict)
    """Informational items of the paper's tables (e.g. Table 3's step angles)."""

    def __post_init__(self) -> None:
        desc = self.description or load_description(self.arm)
        object.__setattr__(self, "description", desc)
        vals = {}
        for k, v in dict(self.data).items():
            if k not in desc.parameters:
                raise ValueError(f"arm {self.arm}: unknown parameter {k!r}")
            if isinstance(v, bool) or not isinstance(v, (int, float, np.floating, np.integer)):
                raise ValueError(f"{k} = {v!r} mm is not a finite number")
            if not math.isfinite(v):
                raise ValueError(f"{k} = {v!r} mm is not a finite number")
            vals[k] = float(v)
        missing = set(desc.parameters) - set(vals)
        if missing:
            raise ValueError(f"arm {self.arm}: missing parameter(s) {sorted(missing)}")
        object.__setattr__(self, "data", vals)
        ppr = self.pulses_per_rev
        if hasattr(ppr, "tolist"):
            ppr = ppr.tolist()
        n = len(desc.joints)
        try:
            if not isinstance(ppr, (list, tuple)) or len(ppr) != n:
                raise ValueError
            ppr = tuple(check_pulses_per_rev(v, "pulses_per_rev") for v in ppr)
        except ValueError:
            raise ValueError(
                f"pulses_per_rev = {self.pulses_per_rev!r}: need {n} whole numbers in "
                f"1 .. {MAX_PULSES_PER_REV:,}, one per joint"
            ) from None
        object.__setattr__(self, "pulses_per_rev", ppr)
        closed_form(desc.closed_form).check(self)

    @classmethod
    def from_description(cls, desc: ArmDescription) -> Params:
        return cls(desc.name, desc.values, tuple(j.pulses_per_rev for j in desc.joints), desc)

    def __getitem__(self, key: str) -> float:
        return self.data[key]

    def __iter__(self):
        return iter(self.data)

    def __len__(self) -> int:
        return len(self.data)

    def __getattr__(self, name: str):
        if name.startswith("_") or name in (
            "arm",
            "data",
            "pulses_per_rev",
            "description",
            "extra",
        ):
            raise AttributeError(name)
        if name in self.data:
            return self.data[name]
        if name in self.extra:
            return self.extra[name]
        geo = closed_form(self.description.closed_form).geometry(self)
        if name in geo:
            return geo[name]
        raise AttributeError(f"arm {self.arm} has no parameter or geometry {name!r}")

    def with_(self, **changes) -> Params:
        """A copy with some values (or ``pulses_per_rev``) changed, validated again."""
        ppr = changes.pop("pulses_per_rev", self.pulses_per_rev)
        return Params(self.arm, {**self.data, **changes}, ppr, self.description, self.extra)

    def dh_table(self, symbolic: bool = False) -> DHTable:
        """The D-H chain with these values (or with the parameters' SymPy symbols)."""
        return self.description.dh_table(self.data, symbolic=symbolic)


# --------------------------------------------------------------------------------------------
# the shared solver body
# --------------------------------------------------------------------------------------------
def solve_body(
    m: Ops,
    cf: ModuleType,
    p,
    P,
    names: Sequence[str],
    *,
    tol,
    limits: Sequence[tuple[float, float] | None] = (),
    **options,
) -> dict:
    """Closed form + statuses + joint limits + NaN masking, in namespace ``m``.

    Written once for every arm and backend: :meth:`Arm.solve` runs it with numpy, the
    compiled kernel is generated from its recording, the PLC program from the closed form
    it calls. Returns ``status`` (float code), ``outside``, and per branch ``b`` the
    condition ``ok:b`` and the angles ``q:b:j`` (NaN where not ok).

    A closed form may also return ``branch_refusals`` {branch: [(Status, condition), ...]}
    for what only some branches cannot do (the GR-1's front and back wrists lie at
    different points, so one may be out of reach while the other is not): a branch is ok
    where none of its own conditions holds. A target that passes the closed form's
    refusals but has no ok branch gets the first requested branch's reason (its first
    true condition, else ``JOINT_LIMITS``), which is what a one-branch PLC program reports.
    """
    sol = cf.ik(m, p, P, tol=tol, **options)
    status = 0.0
    for code, cond in reversed(sol["refusals"]):
        status = m.select(cond, float(code), status)
    good = m.eq(status, 0.0)
    out = {"outside": sol["outside"]}
    per_branch = sol.get("branch_refusals", {})
    has_branch = any(per_branch.get(b) for b in names)
    any_ok = None
    first_reason = None
    for b in names:
        q = sol["branches"][b]
        ok = good
        reason = 0.0
        if per_branch.get(b):
            for code, cond in reversed(per_branch[b]):
                reason = m.select(cond, float(code), reason)
            ok = m.and_(ok, m.eq(reason, 0.0))
        within = None
        for qj, lim in zip(q, limits or [None] * len(q), strict=True):
            if lim is not None:
                inside = m.and_(m.ge(qj, lim[0]), m.le(qj, lim[1]))
                ok = m.and_(ok, inside)
                within = inside if within is None else m.and_(within, inside)
        if has_branch and within is not None:
            stop = m.not_(within) if isinstance(reason, float) else (
                m.and_(m.eq(reason, 0.0), m.not_(within))
            )  # fmt: skip
            reason = m.select(stop, float(Status.JOINT_LIMITS), reason)
        out[f"ok:{b}"] = ok
        for j, qj in enumerate(q):
            out[f"q:{b}:{j}"] = m.select(ok, qj, math.nan)
        any_ok = ok if any_ok is None else m.or_(any_ok, ok)
        first_reason = reason if first_reason is None else first_reason
    if has_branch:
        status = m.select(m.and_(good, m.not_(any_ok)), first_reason, status)
    elif any(lim is not None for lim in limits):
        status = m.select(m.and_(good, m.not_(any_ok)), float(Status.JOINT_LIMITS), status)
    out["status"] = status
    return out


# --------------------------------------------------------------------------------------------
# the arm
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Arm:
    """An arm with parameters ``params`` (its description and closed form follow from them).

    Use :func:`load_arm` (by name) or :func:`paper_arm` (the paper's Table 3 arm).
    """

    params: Params

    # --- identity -----------------------------------------------------------------------
    @property
    def name(self) -> str:
        return self.params.arm

    @property
    def description(self) -> ArmDescription:
        return self.params.description

    @cached_property
    def closed_form(self) -> ModuleType:
        return closed_form(self.description.closed_form)

    @property
    def branches(self) -> tuple[str, ...]:
        """Branch names; the first is the default (the paper's choice)."""
        return tuple(self.closed_form.BRANCHES)

    @property
    def inputs(self) -> tuple[str, ...]:
        """Names of the closed form's inputs (the target: px, py, pz; more for a pose)."""
        return tuple(self.closed_form.INPUTS)

    @property
    def n_joints(self) -> int:
        return len(self.description.joints)

    @cached_property
    def table(self) -> DHTable:
        """The D-H chain with this arm's parameter values."""
        return self.params.dh_table()

    @cached_property
    def geometry(self) -> dict:
        """Named points and radii of the closed form (e.g. the shoulder)."""
        return self.closed_form.geometry(self.params)

    @property
    def shoulder(self) -> npt.NDArray[np.float64]:
        """The shoulder point [mm] (arms whose closed form names one)."""
        return np.array(self.geometry["shoulder"], dtype=float)

    @cached_property
    def limits(self) -> tuple[tuple[float, float] | None, ...]:
        """Joint limits [rad] per joint, None where unrestricted."""
        return tuple(None if j.unlimited else (j.lower, j.upper) for j in self.description.joints)

    # --- forward kinematics, from the chain ----------------------------------------------
    def frames(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Origins of the chain's frames 0..n [mm], shape (..., n_rows + 1, 3): the base,
        each link's end (D-H), the tool. For drawing the arm."""
        q = check_joints(q, self.n_joints)
        origins = chain_frames(numpy_ops, self.table, list(np.moveaxis(q, -1, 0)))
        shape = q.shape[:-1]
        return np.stack(
            [np.stack([np.broadcast_to(c, shape) for c in o], axis=-1) for o in origins], axis=-2
        )

    def fk(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """End point [mm], shape (..., 3), for joint angles (..., n) [rad]: the position
        column of the chain's product of link transforms (for the paper's arm, eq. 2).

        Examples
        --------
        Table 4 row 1, corrected angles (45, 10.21, -155.13) deg, lands on (100, 100, 600):

        >>> paper_arm().fk(np.radians([45.0, 10.2087, -155.1291])).round(2).tolist()
        [100.0, 100.0, 600.0]
        """
        q = check_joints(q, self.n_joints)
        end = chain_frames(numpy_ops, self.table, list(np.moveaxis(q, -1, 0)))[-1]
        return np.stack([np.broadcast_to(c, q.shape[:-1]) for c in end], axis=-1).astype(float)

    def elbow(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Origin of frame 2 (the paper's arm: the elbow) [mm], shape (..., 3)."""
        return self.frames(q)[..., 2, :]

    def jacobian(self, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Positional Jacobian dP/dq [mm/rad], shape (..., 3, n); column j is dP/dq_j.

        The chain of :meth:`fk` differentiated by forward-mode duals (exact to round-off).
        """
        q = check_joints(q, self.n_joints)
        m = DualOps(numpy_ops)
        qs = m.seed(list(np.moveaxis(q, -1, 0)))
        end = chain_frames(m, self.table, qs)[-1]
        shape = q.shape[:-1]
        cols = [
            np.stack(
                [np.broadcast_to(c.d[j] if hasattr(c, "d") else 0.0, shape) for c in end], axis=-1
            )
            for j in range(self.n_joints)
        ]
        return np.stack(cols, axis=-1).astype(float)

    # --- reach ---------------------------------------------------------------------------
    def outside_distance(self, p: npt.ArrayLike) -> npt.NDArray[np.float64]:
        """Signed distance [mm] of targets outside the reachable set (> 0: unreachable)."""
        return self.solve(p, self.branches[:1]).outside_mm

    def is_reachable(self, p: npt.ArrayLike, tol: float = DEFAULT_TOL_MM) -> npt.NDArray[np.bool_]:
        """Mask of targets within ``tol`` mm of the reachable set (..., )."""
        return self.solve(p, self.branches[:1], tol=tol).reachable

    # --- inverse kinematics --------------------------------------------------------------
    def branch_names(self, branches: str | Sequence[str]) -> tuple[str, ...]:
        """Validated branch names (``"all"`` for every branch)."""
        if isinstance(branches, str):
            branches = self.branches if branches == "all" else (branches,)
        names = tuple(branches)
        unknown = [b for b in names if b not in self.branches]
        if unknown or not names:
            raise ValueError(
                f"unknown branch {unknown or names!r}; expected 'all' or from "
                f"{', '.join(self.branches)}"
            )
        return names

    def solve(
        self,
        p: npt.ArrayLike,
        branches: str | Sequence[str] = "all",
        *,
        theta1_on_axis: npt.ArrayLike | None = None,
        tol: float = DEFAULT_TOL_MM,
        limits: bool = True,
        backend: str = "numpy",
        out: IKSolutions | None = None,
    ) -> IKSolutions:
        """Batch closed-form IK; never raises for unreachable targets.

        Parameters
        ----------
        p : array_like, shape (..., 3)
            Targets [mm].
        branches : str or sequence of str
            Branch names or ``"all"``.
        theta1_on_axis : array_like, optional
            Waist angle [rad] for targets on the base axis (broadcast against
            ``p[..., 0]``). Without it such targets get ``Status.BASE_AXIS``.
        tol : float
            Distance tolerance [mm] (0 .. :data:`MAX_TOL_MM`).
        limits : bool
            Apply the description's joint limits (branches outside them are not ok).
        backend : {"numpy", "compiled"}
            "compiled" runs the kernel generated from the same closed form
            (:mod:`analysis.kinematics.compiled`); it needs Numba and ``theta1_on_axis=None``.
        out : IKSolutions, optional
            Preallocated result (compiled backend; see :func:`~analysis.kinematics.compiled.
            allocate`), reused to avoid touching fresh memory.
        """
        names = self.branch_names(branches)
        p = as_points(p, inputs=self.inputs)
        tol = check_tol(tol)
        lim = self.limits if limits else ()
        if theta1_on_axis is not None:
            t = np.asarray(theta1_on_axis, dtype=float)
            if not np.isfinite(t).all():
                raise ValueError(f"theta1_on_axis = {theta1_on_axis!r} rad is not finite")
        if backend == "compiled":
            if theta1_on_axis is not None:
                raise ValueError("the compiled backend takes no theta1_on_axis; use numpy")
            from analysis.kinematics import compiled

            return compiled.solve(self, p, names, tol=tol, limits=lim, out=out)
        if backend != "numpy":
            raise ValueError(f"backend {backend!r}: expected 'numpy' or 'compiled'")
        opts = {} if theta1_on_axis is None else {"theta1_on_axis": theta1_on_axis}
        with np.errstate(invalid="ignore", divide="ignore"):
            r = solve_body(
                numpy_ops,
                self.closed_form,
                tuple(p[..., k] for k in range(p.shape[-1])),
                self.params,
                names,
                tol=tol,
                limits=lim,
                **opts,
            )
        shape = p.shape[:-1]
        theta = np.stack(
            [
                np.stack(
                    [np.broadcast_to(r[f"q:{b}:{j}"], shape) for j in range(self.n_joints)], -1
                )
                for b in names
            ],
            axis=-2,
        ).astype(float)
        ok = np.stack([np.broadcast_to(r[f"ok:{b}"], shape) for b in names], axis=-1)
        status = np.broadcast_to(r["status"], shape).astype(np.int8)
        outside = np.broadcast_to(r["outside"], shape).astype(float)
        return IKSolutions(theta, ok.copy(), status, outside, names)

    def ik(
        self,
        p: npt.ArrayLike,
        branch: str | None = None,
        *,
        theta1_on_axis: float | None = None,
        tol: float = DEFAULT_TOL_MM,
    ) -> npt.NDArray[np.float64]:
        """Closed-form IK for one target and one branch (default: the paper's); raises.

        Returns
        -------
        ndarray, shape (n,)
            Joint angles [rad].

        Raises
        ------
        UnreachableError
            The target is outside the reachable set; the message says by how much.
        BaseAxisError
            The target is on the base axis and ``theta1_on_axis`` was not given.

        Examples
        --------
        Table 4 row 1 (100, 100, 600) mm -> (45.00, 10.21, -155.13) deg; the paper prints
        190.20 for theta2 (see the errata register):

        >>> np.degrees(paper_arm().ik([100, 100, 600])).round(2).tolist()
        [45.0, 10.21, -155.13]
        """
        branch = branch or self.branches[0]
        if branch not in self.branches:
            raise ValueError(
                f"unknown branch {branch!r}; expected one of {', '.join(self.branches)}"
            )
        return self.ik_all(p, theta1_on_axis=theta1_on_axis, tol=tol, branches=(branch,))[branch]

    def ik_all(
        self,
        p: npt.ArrayLike,
        *,
        theta1_on_axis: float | None = None,
        tol: float = DEFAULT_TOL_MM,
        branches: Sequence[str] | None = None,
    ) -> dict[str, npt.NDArray[np.float64]]:
        """All IK solutions of one target, ``{branch: angles}`` [rad]; raises like :meth:`ik`.

        Branches outside the joint limits are left out; if none is left, ValueError.
        """
        p = as_points(p, inputs=self.inputs)
        if p.shape != (len(self.inputs),):
            raise ValueError(
                f"ik takes one target of shape ({len(self.inputs)},), got {p.shape}; "
                "use solve() for batches"
            )
        names = self.branch_names(branches or "all")
        sol = self.solve(p, names, theta1_on_axis=theta1_on_axis, tol=tol)
        self.raise_for(p, int(sol.status), float(sol.outside_mm), tol=tol)
        return {b: sol.theta[i] for i, b in enumerate(names) if sol.ok[i]}

    def check_target(self, p: npt.ArrayLike, *, tol: float = DEFAULT_TOL_MM, allow_axis=False):
        """Raise :class:`UnreachableError` or :class:`BaseAxisError` for one bad target."""
        p = as_points(p, inputs=self.inputs)
        sol = self.solve(p, self.branches, tol=tol, theta1_on_axis=0.0 if allow_axis else None)
        self.raise_for(p, int(sol.status), float(sol.outside_mm), tol=tol)

    def raise_for(self, p, status: int, outside: float, *, tol: float) -> None:
        """Raise the error that ``status`` means for target ``p`` (nothing if OK)."""
        status = Status(status)
        if status == Status.OK:
            return
        if status == Status.JOINT_LIMITS:
            raise ValueError(
                f"target {tuple(float(v) for v in p)} mm is reachable, but no requested branch "
                f"is within the joint limits of {self.name}"
            )
        message, limit = self.closed_form.refusal(status, p, self.params, tol=tol, distance=outside)
        if status in (Status.OUT_OF_REACH, Status.INSIDE_REACH):
            raise UnreachableError(message, p, outside, limit, status)
        if status == Status.BASE_AXIS:
            raise BaseAxisError(message, p)
        raise ValueError(message)


def load_arm(name: str = "grabber", tables: dict | None = None) -> Arm:
    """The arm described by ``data/arms/<name>.toml`` (see :func:`load_description`)."""
    return Arm(Params.from_description(load_description(name, tables)))


def paper_arm() -> Arm:
    """The arm of the paper (seed 000), parameters from ``data/table3.csv``."""
    return load_arm("grabber")

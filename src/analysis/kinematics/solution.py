"""What every arm's solver shares: tolerances, errors, the result record, input checks, and
the solver body that the numpy path and the compiled kernel both run.

:func:`solve_body` turns a closed form's output (:mod:`analysis.kinematics.arms`) into
statuses (:mod:`analysis.kinematics.status`), joint-limit masks and NaN where no solution,
in any namespace (:mod:`analysis.kinematics.ops`): :class:`analysis.kinematics.arm.Arm`
calls it with numpy, :mod:`analysis.kinematics.compiled` records it into a kernel.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from analysis import validate
from analysis.kinematics.ops import Ops
from analysis.kinematics.status import Status
from analysis.validate import MAX_JOINT_DEG, MAX_TOL_MM

__all__ = [
    "DEFAULT_TOL_MM",
    "JOINT_STOP_SLACK_RAD",
    "MAX_JOINT_DEG",
    "MAX_JOINT_MM",
    "MAX_TOL_MM",
    "ROUNDOFF_REL",
    "BaseAxisError",
    "IKSolutions",
    "OrientationError",
    "UnreachableError",
    "as_points",
    "check_joints",
    "check_theta1_on_axis",
    "check_tol",
    "collect",
    "decision_tol",
    "raise_refusal",
    "refusal_options",
    "solve_body",
    "status_of",
]

DEFAULT_TOL_MM = 1e-6
"""Default distance tolerance [mm]: targets this close outside the reach shell are put on
the shell (cos theta3 clipped to +-1), and targets this close to the base axis count as on
it. It is the true bound of the position error: every ok solution of :meth:`Arm.solve`
(numpy and compiled) reaches its target within it, float64 round-off included
(:data:`ROUNDOFF_REL`; tests/hostile/test_hostile.py draws the boundaries of every arm).
1 nm is far below any mechanical meaning and far above float64 round-off at this scale
(|p| ~ 1e3 mm, eps * |p| ~ 2e-13 mm)."""
ROUNDOFF_REL = 64 * 2.0**-52
"""Relative float64 round-off allowed for in the reach decisions (64 ulps, 1.4e-14): a target
is solved only where it lies within ``tol`` minus ``ROUNDOFF_REL`` times the scale of the
problem (the target's coordinates and the arm's lengths summed, 1 mm added: 3.5e-11 mm for
the paper's arm at (100, 100, 600)) outside a reach boundary, so that a solution reaches its
target within ``tol`` itself, round-off included (:func:`solve_body`). Measured at the
boundaries (tests/hostile/test_hostile.py, class 7): without it a target exactly ``tol``
outside the shell was solved with a position error of tol + 1.8e-13 mm."""
JOINT_STOP_SLACK_RAD = 1e-12
"""A joint angle this far past a stop counts as on it (and is returned as the stop): the
backends compute the same angle to a few ulps apart (the compiled ``atan2`` is not libm's,
4.4e-16 rad per ulp near pi), so without it a pose exactly on a stop (the GR-1's theta3 =
-135 deg) could be ok on one backend and "joint-limits" on the other. 1e-12 rad moves a
point 1 m out by 1e-9 mm. The PLC programs apply the limits as described (no band)."""
MAX_JOINT_MM = 1e5
"""Largest accepted |prismatic joint value| [mm] (100 m): beyond it an input is a mistake of
unit or of digits."""


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


class OrientationError(ValueError):
    """The pose's position is reachable, its orientation is not (a 5-DOF arm: the approach
    vector leaves the arm plane); the message says by how much."""

    def __init__(self, message: str, target):
        super().__init__(message)
        self.target = tuple(float(v) for v in target)


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
    branch_status : ndarray of int8, shape (..., B)
        :class:`Status` code per target and branch: 0 where ``ok``, else the branch's true
        reason (the target's refusal, the branch's own, e.g. the GR-1's back wrist out of
        reach, or ``JOINT_LIMITS``), from :func:`status_of`.
    """

    theta: npt.NDArray[np.float64]
    ok: npt.NDArray[np.bool_]
    status: npt.NDArray[np.int8]
    outside_mm: npt.NDArray[np.float64]
    branches: tuple[str, ...]
    branch_status: npt.NDArray[np.int8] | None = None

    @property
    def reachable(self) -> npt.NDArray[np.bool_]:
        """Targets inside the reachable set within the tolerance ``solve`` used (base-axis
        and joint-limit targets included): consistent with ``status``."""
        return (self.status != Status.OUT_OF_REACH) & (self.status != Status.INSIDE_REACH)

    def branch(self, name: str) -> npt.NDArray[np.float64]:
        """Angles of one branch, shape (..., n)."""
        return self.theta[..., self.branches.index(name), :]


def as_points(
    p: npt.ArrayLike,
    name: str = "target",
    inputs: Sequence[str] = ("x", "y", "z"),
    *,
    finite: bool = True,
    units: Sequence[str] | None = None,
) -> npt.NDArray[np.float64]:
    """Validate and convert targets to a float array of shape (..., k), k = len(inputs)
    (default (..., 3) = x, y, z [mm]), through :mod:`analysis.validate`: real numbers only
    (complex, masked and boolean input refused), finite, coordinates ("mm") within
    +-:data:`~analysis.validate.MAX_COORD_MM`, angles ("rad") within
    +-:data:`~analysis.validate.MAX_ANGLE_RAD`.

    Raises ``ValueError`` (:class:`~analysis.validate.InvalidValue`) naming the offending value
    and the limit. ``finite=False``: the type and shape only; the caller checks the values
    itself, as the compiled kernel does in its input copy.
    """
    arr = validate.real_array(p, name, finite=False)
    k = len(inputs)
    if arr.ndim == 0 or arr.shape[-1] != k:
        what = "(x, y, z) in mm" if k == 3 else "(" + ", ".join(inputs) + ")"
        raise validate.InvalidValue(
            f"{name} has shape {arr.shape}; expected (..., {k}) = {what}", name
        )
    if not finite:
        return arr
    if not np.isfinite(arr.sum()):  # one pass: NaN or inf make the sum non-finite
        bad = ~np.isfinite(arr)  # (or the sum overflowed: then nothing is bad)
        if bad.any():
            idx = np.argwhere(bad)[0]
            where = "" if arr.ndim == 1 else f" at index {tuple(int(i) for i in idx[:-1])}"
            raise validate.InvalidValue(
                f"{name}{where} has a non-finite coordinate: {arr[tuple(idx[:-1])].tolist()}",
                name,
            )
    validate.check_inputs(arr, units or ("mm",) * k, inputs, name)
    return arr


def check_joints(
    q: npt.ArrayLike, n: int, name: str = "joint array", units: Sequence[str] | None = None
) -> npt.NDArray[np.float64]:
    """Validate joint values (..., n): real, finite, angles [rad] within
    +-:data:`MAX_JOINT_DEG` and, where ``units`` says "mm" (a prismatic joint), lengths
    within +-:data:`MAX_JOINT_MM`."""
    q = validate.real_array(q, name, finite=False)
    if q.ndim == 0 or q.shape[-1] != n:
        raise validate.InvalidValue(f"{name} has shape {q.shape}; expected (..., {n})", name)
    mm = np.array([u == "mm" for u in units]) if units is not None else np.zeros(n, bool)
    limit = math.radians(MAX_JOINT_DEG)
    if not q.size or (not mm.any() and -limit <= q.min() and q.max() <= limit):
        return q  # NaN fails both comparisons: one pass each
    bound = np.where(mm, MAX_JOINT_MM, limit)
    bad = ~np.isfinite(q) | (np.abs(q) > bound)
    if bad.any():
        idx = tuple(int(i) for i in np.argwhere(bad)[0])
        v, j = float(q[idx]), idx[-1]
        what = "is not finite" if not math.isfinite(v) else "is beyond"
        if mm[j]:
            raise validate.InvalidValue(
                f"{name}: q{j + 1} = {v:g} mm {what} (accepted: finite, |q| <= "
                f"{MAX_JOINT_MM:g} mm for a prismatic joint)",
                name,
            )
        raise validate.InvalidValue(
            f"{name}: theta{j + 1} = {math.degrees(v) if math.isfinite(v) else v:g} deg "
            f"{what} (accepted: finite, |theta| <= {MAX_JOINT_DEG:g} deg, ten turns)",
            name,
        )
    return q


def check_tol(tol) -> float:
    """A distance tolerance [mm] in 0 .. :data:`MAX_TOL_MM`, else ValueError."""
    try:
        return validate.tolerance_mm(tol, "tol")
    except ValueError:
        raise validate.InvalidValue(
            f"tol = {tol!r} mm: the tolerance must be a finite number >= 0 mm "
            f"and <= {MAX_TOL_MM:g} mm",
            "tol",
            tol,
        ) from None


# --------------------------------------------------------------------------------------------
# parameters
# --------------------------------------------------------------------------------------------


def refusal_options(tol: float, margin_mm: float = 0.0, margin_rad: float = 0.0) -> dict:
    """The closed-form tolerances for a solve with a refusal band of ``margin_mm`` [mm].

    Without a margin: ``tol`` at the reach shells and the singular sets. With one: a target
    is refused within ``margin_mm`` inside a shell (``tol = -margin_mm``) and within
    ``max(tol, margin_mm)`` of a singular set, and angular tolerances shrink by
    ``margin_rad`` (:mod:`analysis.kinematics.arms`). The generated PLC programs solve with
    such a band (:mod:`analysis.plc.model`).

    >>> refusal_options(1e-6)
    {'tol': 1e-06, 'axis_tol': 1e-06, 'margin_rad': 0.0}
    >>> refusal_options(1e-6, 1e-3, 2e-5)
    {'tol': -0.001, 'axis_tol': 0.001, 'margin_rad': 2e-05}
    """
    if not 0.0 <= margin_mm <= MAX_TOL_MM:
        raise ValueError(f"margin_mm = {margin_mm!r} mm: expected 0 .. {MAX_TOL_MM:g} mm")
    if not 0.0 <= margin_rad <= 0.1:
        raise ValueError(f"margin_rad = {margin_rad!r} rad: expected 0 .. 0.1 rad")
    if margin_mm == 0.0:
        return {"tol": tol, "axis_tol": tol, "margin_rad": margin_rad}
    return {"tol": -margin_mm, "axis_tol": max(tol, margin_mm), "margin_rad": margin_rad}


def status_of(m: Ops, refusals: Sequence, default=0.0):
    """The status code of the first refusal whose condition holds, else ``default``.

    ``refusals`` is ``[(Status, condition), ...]`` in priority order (a closed form's, or a
    branch's); the one function that turns refusals into a status, in any namespace: the
    shared solver body (Python, the compiled kernel) and the float32 model of the PLC
    programs (:func:`analysis.plc.model.predict`) call it, and the programs test the
    conditions in the same order (:mod:`analysis.plc.ir`).

    >>> from analysis.kinematics.ops import numpy_ops
    >>> import numpy as np
    >>> x = np.array([0.5, 2.0, -1.0])
    >>> status_of(numpy_ops, [(Status.OUT_OF_REACH, x > 1), (Status.BASE_AXIS, x < 0)]).tolist()
    [0.0, 1.0, 3.0]
    """
    status = default
    for code, cond in reversed(tuple(refusals)):
        status = m.select(cond, float(code), status)
    return status


def decision_tol(m: Ops, cf, p, P, tol):
    """The tolerance the closed form decides with: ``tol - ROUNDOFF_REL * scale``, the scale
    being the sum of the magnitudes of the target's coordinates (its "mm" inputs) and of the
    arm's lengths, plus 1 mm (:data:`ROUNDOFF_REL`). In namespace ``m`` (the compiled kernel
    records it; ``tol`` may be one of its values).

    >>> from analysis.kinematics.ops import numpy_ops
    >>> from analysis.kinematics.loader import paper_arm
    >>> arm = paper_arm()
    >>> t = decision_tol(numpy_ops, arm.closed_form, (100.0, 100.0, 600.0), arm.params, 1e-6)
    >>> 0 < 1e-6 - float(t) < 1e-10
    True
    """
    scale = 1.0
    for v, unit in zip(p, cf.input_units, strict=True):
        if unit == "mm":
            scale = scale + m.abs(v)
    for v in P.values():
        scale = scale + m.abs(v)
    return tol - ROUNDOFF_REL * scale


def solve_body(
    m: Ops,
    cf,
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
    it calls. ``cf`` is a :class:`~analysis.kinematics.arms.ClosedForm`; ``options`` go to
    its :meth:`~analysis.kinematics.arms.ClosedForm.solve`. Returns ``status`` (float
    code), ``outside``, and per branch ``b`` the condition ``ok:b`` and the angles ``q:b:j``
    (NaN where not ok).

    A closed form's ``branch_refusals`` hold what only some branches cannot do (the GR-1's
    front and back wrists lie at different points, so one may be out of reach while the
    other is not): a branch is ok where none of its own conditions holds. A target that
    passes the closed form's refusals but has no ok branch gets the first requested
    branch's reason (its first true condition, else ``JOINT_LIMITS``), which is what a
    one-branch PLC program reports. ``status:b`` is each branch's own status
    (:func:`status_of` over the target's refusals, the branch's and its joint limits).

    The tolerance is the true one: the closed form decides its reach with ``tol`` less the
    round-off of the problem's scale (:func:`decision_tol`; its singular sets with ``tol``
    itself, or the ``axis_tol`` given), so an ok solution reaches its target within ``tol`` on every
    backend (float64 round-off included), and with ``precise=True``: the better conditioned
    formulas a closed form has for float64 (:data:`analysis.kinematics.arms.OPTIONS`). The
    generated PLC programs call the closed form with their own band and without it
    (:mod:`analysis.plc.model`).
    """
    # the singular sets keep ``tol`` itself (a target on the base axis with tol = 0 is on it)
    options = {"axis_tol": tol, **options}
    sol = cf.solve(m, p, P, tol=decision_tol(m, cf, p, P, tol), precise=True, **options)
    status = status_of(m, sol.refusals)
    good = m.eq(status, 0.0)
    out = {"outside": sol.outside}
    has_branch = any(sol.branch_refusals[b] for b in names)
    any_ok = None
    first_reason = None
    for b in names:
        q = sol.branches[b]
        ok = good
        reason = 0.0
        if sol.branch_refusals[b]:
            reason = status_of(m, sol.branch_refusals[b])
            ok = m.and_(ok, m.eq(reason, 0.0))
        within = None
        for qj, lim in zip(q, limits or [None] * len(q), strict=True):
            if lim is not None:
                lo, hi = lim[0] - JOINT_STOP_SLACK_RAD, lim[1] + JOINT_STOP_SLACK_RAD
                inside = m.and_(m.ge(qj, lo), m.le(qj, hi))
                ok = m.and_(ok, inside)
                within = inside if within is None else m.and_(within, inside)
        # the branch's own status, by the one refusal-to-status function: the target's
        # refusals, then the branch's, then its joint limits (0 where the branch is ok)
        own = [*sol.refusals, *sol.branch_refusals[b]]
        if within is not None:
            own.append((Status.JOINT_LIMITS, m.not_(within)))
        out[f"status:{b}"] = status_of(m, own)
        if has_branch and within is not None:
            stop = m.not_(within) if isinstance(reason, float) else (
                m.and_(m.eq(reason, 0.0), m.not_(within))
            )  # fmt: skip
            reason = m.select(stop, float(Status.JOINT_LIMITS), reason)
        out[f"ok:{b}"] = ok
        for j, (qj, lim) in enumerate(zip(q, limits or [None] * len(q), strict=True)):
            if lim is not None:  # within the slack past a stop: the stop itself
                qj = m.clip(qj, lim[0], lim[1])
            out[f"q:{b}:{j}"] = m.select(ok, qj, math.nan)
        any_ok = ok if any_ok is None else m.or_(any_ok, ok)
        first_reason = reason if first_reason is None else first_reason
    if has_branch:
        status = m.select(m.and_(good, m.not_(any_ok)), first_reason, status)
    elif any(lim is not None for lim in limits):
        status = m.select(m.and_(good, m.not_(any_ok)), float(Status.JOINT_LIMITS), status)
    out["status"] = status
    return out


def collect(r: dict, names: Sequence[str], shape: tuple, n_joints: int) -> IKSolutions:
    """The numpy solver body's output ``r`` (:func:`solve_body`) for targets of ``shape``
    as an :class:`IKSolutions` (every array broadcast to the targets' shape)."""
    theta = np.stack(
        [np.stack([np.broadcast_to(r[f"q:{b}:{j}"], shape) for j in range(n_joints)], -1)
         for b in names], axis=-2,
    ).astype(float)  # fmt: skip
    ok = np.stack([np.broadcast_to(r[f"ok:{b}"], shape) for b in names], axis=-1)
    status = np.broadcast_to(r["status"], shape).astype(np.int8)
    outside = np.broadcast_to(r["outside"], shape).astype(float)
    branch_status = np.stack(
        [np.broadcast_to(r[f"status:{b}"], shape) for b in names], axis=-1
    ).astype(np.int8)
    return IKSolutions(theta, ok.copy(), status, outside, tuple(names), branch_status)


def raise_refusal(cf, arm: str, P, p, status: int, outside: float, *, tol: float) -> None:
    """Raise the error that ``status`` means for target ``p`` of arm ``arm`` (closed form
    ``cf``, parameters ``P``): nothing if OK, :class:`UnreachableError`,
    :class:`BaseAxisError`, :class:`OrientationError` or ValueError with the closed form's
    one-line reason (``refusal``)."""
    status = Status(status)
    if status == Status.OK:
        return
    if status == Status.JOINT_LIMITS:
        values = ", ".join(
            f"{name} = {math.degrees(v) if u == 'rad' else v:g} {'deg' if u == 'rad' else u}"
            for name, v, u in zip(cf.inputs, map(float, p), cf.input_units, strict=True)
        )
        raise ValueError(
            f"target ({values}) is reachable, but no requested branch is within the joint "
            f"limits of {arm}"
        )
    message, limit = cf.refusal(status, p, P, tol=tol, distance=outside)
    if status in (Status.OUT_OF_REACH, Status.INSIDE_REACH):
        raise UnreachableError(message, p, outside, limit, status)
    if status == Status.BASE_AXIS:
        raise BaseAxisError(message, p)
    if status == Status.ORIENTATION:
        raise OrientationError(message, p)
    raise ValueError(message)


def check_theta1_on_axis(value) -> float | npt.NDArray[np.float64]:
    """The waist angle for targets on the base axis [rad]: real, finite, within ten turns
    (:func:`analysis.validate.angle_rad`), wrapped to (-pi, pi] (the README's convention)."""
    if np.ndim(value) == 0 and not isinstance(value, np.ma.MaskedArray):
        return validate.wrap_rad(validate.angle_rad(value, "theta1_on_axis"))
    arr = validate.real_array(value, "theta1_on_axis")
    if arr.size and np.abs(arr).max() > validate.MAX_ANGLE_RAD:
        validate.angle_rad(float(arr.flat[np.abs(arr).argmax()]), "theta1_on_axis")
    return validate.wrap_rad(arr)

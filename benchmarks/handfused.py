"""Fast batch kinematics: the corrected closed form (eqs. 6-19) compiled with Numba.

An exact alternative implementation of :meth:`analysis.kinematics.arm.Arm.solve` (all four branches)
and :meth:`analysis.kinematics.arm.Arm.fk`, for workspace and quantization maps over millions of
targets. It evaluates the same formula sequence as ``Arm.solve`` (module docstring of
:mod:`analysis.kinematics.arm`), target by target, in one fused compiled loop split over the CPU
cores (``numba.prange``), instead of numpy's one-temporary-array-per-operation passes.
``tests/kinematics/test_fastik.py`` holds it against ``Arm.solve`` (statuses equal, angles to
1e-12 rad) on seeded random, boundary and base-axis targets.

Why Numba: ``make bench`` measured ``Arm.solve`` (pure numpy) at about 1.2 million
targets/s for all four branches on the 2-core machine, an order below the 10 million/s
target; the work is transcendental-bound (one atan2, one acos and four atan2 + sin/cos
per target), so a numpy reformulation cannot close a 10x gap, while a fused loop runs
each target once, in registers, on both cores.

Numba is optional at run time: if it cannot be imported, every function here falls back
to the numpy implementation in :mod:`analysis.kinematics.arm` with identical results (only slower).
Functions are compiled on first call; the on-disk cache is optional (see ``_jit``).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from analysis.kinematics.arm import BRANCHES, DEFAULT_TOL_MM, Arm, IKSolutions, Status, as_points

try:  # pragma: no cover - exercised by whichever environment runs the tests
    import numba

    HAVE_NUMBA = True
except ImportError:  # pragma: no cover
    numba = None
    HAVE_NUMBA = False

__all__ = ["HAVE_NUMBA", "fk", "ik_front_up_pulses", "solve_all"]

_TWO_PI = 2.0 * math.pi
_OK, _OUT, _INSIDE, _AXIS = (
    int(s) for s in (Status.OK, Status.OUT_OF_REACH, Status.INSIDE_REACH, Status.BASE_AXIS)
)
# The kernels write the branches in this order (see analysis.kinematics.arm._BRANCH_SIGNS).
assert BRANCHES == ("front-up", "front-down", "back-up", "back-down")


def _jit(**kw):
    """``numba.njit``: IEEE arithmetic (no fastmath), numpy error model, or a no-op.

    Compiled code is cached on disk where Numba finds a writable place (``__pycache__``
    or ``NUMBA_CACHE_DIR``), which saves the ~10 s compile on later runs; without one the
    functions simply compile on first call. Nothing depends on the cache existing.
    """
    if not HAVE_NUMBA:
        return lambda f: f
    opts = dict(fastmath=False, nogil=True, error_model="numpy", **kw)

    def decorate(f):
        try:
            return numba.njit(cache=True, **opts)(f)
        except RuntimeError:  # "cannot cache function ...: no locator available"
            return numba.njit(cache=False, **opts)(f)

    return decorate


def _prange(n):  # replaced by numba.prange inside compiled code
    return range(n)


if HAVE_NUMBA:
    _prange = numba.prange

# The kernels below are written without data-dependent branches (every value is computed,
# then chosen with a conditional expression) so that LLVM can turn them into vector
# selects: a branchy kernel measured 3x slower.


@_jit(inline="always")
def _wrap_scalar(a):
    """Wrap an angle with |a| < 3 pi to (-pi, pi] (``analysis.kinematics.arm._wrap`` to ~1 ulp).

    One conditional add of +-2 pi instead of a floating-point modulo (an fmod call per
    angle cost as much as the rest of the IK).
    """
    a = a - _TWO_PI if a > math.pi else a
    a = a + _TWO_PI if a <= -math.pi else a
    a = a - _TWO_PI if a > math.pi else a
    return a


# Cephes atan rational approximation (S. L. Moshier, Cephes Math Library, atan.c:
# atan(x) = x + x^3 P(x^2) / Q(x^2) on [0, 0.66], peak relative error 2.6e-18), with its
# published coefficients. glibc's atan2 (36 ns a call here, scalar, with slow paths) was
# the bottleneck; this branch-free version takes about 8 ns and stays within 2 ulp of it
# (tests/kinematics/test_fastik.py), far inside the 1e-12 rad the IK is held to.
_ATAN_P = (
    -8.750608600031904122785e-1,
    -1.615753718733365076637e1,
    -7.500855792314704667340e1,
    -1.228866684490136173410e2,
    -6.485021904942025371773e1,
)
_ATAN_Q = (
    2.485846490142306297962e1,
    1.650270098316988542046e2,
    4.328810604912902668951e2,
    4.853903996359136964868e2,
    1.945506571482613964425e2,
)
_MOREBITS = 6.123233995736765886130e-17  # pi/2 - float(pi/2)
_PIO2 = math.pi / 2.0
_PIO4 = math.pi / 4.0


@_jit(inline="always")
def _atan2(y, x):
    """atan2(y, x) in [-pi, pi], signs as libm (incl. y = -0.0 and x = -0.0)."""
    ay = abs(y)
    ax = abs(x)
    mx = max(ax, ay)
    t = min(ax, ay) / mx
    t = 0.0 if mx == 0.0 else t
    big = t > 0.66  # Cephes: atan(t) = pi/4 + atan((t - 1) / (t + 1))
    xr = (t - 1.0) / (t + 1.0)
    xx = xr if big else t
    z = xx * xx
    num = ((((_ATAN_P[0] * z + _ATAN_P[1]) * z + _ATAN_P[2]) * z + _ATAN_P[3]) * z + _ATAN_P[4]) * z
    den = ((((z + _ATAN_Q[0]) * z + _ATAN_Q[1]) * z + _ATAN_Q[2]) * z + _ATAN_Q[3]) * z + _ATAN_Q[4]
    r = xx * (num / den) + xx
    a = (_PIO4 + (r + 0.5 * _MOREBITS)) if big else r
    a = ((_PIO2 - a) + _MOREBITS) if ay > ax else a
    neg = (x < 0.0) | ((x == 0.0) & (math.copysign(1.0, x) < 0.0))
    a = ((math.pi - a) + 2.0 * _MOREBITS) if neg else a
    return math.copysign(a, y)


@_jit(inline="always")
def _acos(c):
    """acos(c) for -1 <= c <= 1 as atan2(sqrt((1 - c)(1 + c)), c)."""
    return _atan2(math.sqrt((1.0 - c) * (1.0 + c)), c)


@_jit(parallel=True)
def _solve_kernel(p, L1, L2, L3, tol, theta, ok, status, outside):  # pragma: no cover - compiled
    router = L2 + L3
    rinner = abs(L2 - L3)
    nan = np.nan
    for i in _prange(p.shape[0]):
        xi = p[i, 0]
        yi = p[i, 1]
        z = p[i, 2] - L1
        rho2 = xi * xi + yi * yi  # as Arm.solve, operation for operation: bit-equal c3
        rho = math.sqrt(rho2)
        D2 = rho2 + z * z
        D = math.sqrt(D2)
        outside[i] = max(D - router, rinner - D)
        st = _AXIS if rho <= tol else _OK
        st = _OUT if D - router > tol else st
        st = _INSIDE if rinner - D > tol else st
        status[i] = st
        good = st == _OK
        phi = _atan2(yi, xi)
        c3 = (D2 - L2 * L2 - L3 * L3) / (2.0 * L2 * L3)  # eqs. 9-10
        c3 = min(max(c3, -1.0), 1.0)
        t3m = _acos(c3)
        # cos(+-t3m) = c3 and sin(+-t3m) = +-sqrt((1 - c3)(1 + c3)): k is shared by all
        # branches, s only changes sign (front-up: t3 = -t3m, s = -s0).
        k = L2 * c3 + L3
        s0 = L2 * math.sqrt((1.0 - c3) * (1.0 + c3))
        # eq. 18 with atan2, front branches (r = +rho); a back branch (r = -rho) has the
        # same numerator and the negated denominator, so its angle is pi - front's.
        t23u = _atan2(z * k - rho * s0, rho * k + z * s0)  # front-up, t3 = -t3m
        t23d = _atan2(z * k + rho * s0, rho * k - z * s0)  # front-down, t3 = +t3m
        t1f = _wrap_scalar(phi) if good else nan
        t1b = _wrap_scalar(phi + math.pi) if good else nan
        pos = t3m if good else nan
        neg = _wrap_scalar(-t3m) if good else nan  # folded elbow: -pi -> pi, as Arm.solve
        theta[i, 0, 0] = t1f
        theta[i, 0, 1] = _wrap_scalar(t23u + t3m) if good else nan  # eq. 19
        theta[i, 0, 2] = neg
        theta[i, 1, 0] = t1f
        theta[i, 1, 1] = _wrap_scalar(t23d - t3m) if good else nan
        theta[i, 1, 2] = pos
        theta[i, 2, 0] = t1b  # back-up: t3 = +t3m, t23 = pi - t23u
        theta[i, 2, 1] = _wrap_scalar(math.pi - t23u - t3m) if good else nan
        theta[i, 2, 2] = pos
        theta[i, 3, 0] = t1b  # back-down: t3 = -t3m, t23 = pi - t23d
        theta[i, 3, 1] = _wrap_scalar(math.pi - t23d + t3m) if good else nan
        theta[i, 3, 2] = neg
        ok[i, 0] = good
        ok[i, 1] = good
        ok[i, 2] = good
        ok[i, 3] = good


@_jit(parallel=True)
def _fk_kernel(q, L1, L2, L3, out):  # pragma: no cover - compiled
    for i in _prange(q.shape[0]):
        t1 = q[i, 0]
        t2 = q[i, 1]
        t23 = t2 + q[i, 2]
        r = L2 * math.cos(t2) + L3 * math.cos(t23)
        out[i, 0] = math.cos(t1) * r
        out[i, 1] = math.sin(t1) * r
        out[i, 2] = L1 + L2 * math.sin(t2) + L3 * math.sin(t23)


@_jit(inline="always")
def _round_half_away(v):
    """As :func:`analysis.kinematics.pulses.round_half_away`: trunc plus the exact fractional part
    (floor(|v| + 0.5) would round 0.49999999999999994 up)."""
    whole = np.trunc(v)
    return whole + (math.copysign(1.0, v) if abs(v - whole) >= 0.5 else 0.0)


@_jit(parallel=True)
def _quant_kernel(p, L1, L2, L3, ppr, tol, pulses, err, ok):  # pragma: no cover - compiled
    """Front-up IK -> pulses (eqs. 20-22, half away) -> angles -> FK -> error [mm]."""
    router = L2 + L3
    rinner = abs(L2 - L3)
    deg = 180.0 / math.pi  # numpy's degrees(): x * (180 / pi)
    rad = math.pi / 180.0  # numpy's radians(): x * (pi / 180)
    for i in _prange(p.shape[0]):
        xi = p[i, 0]
        yi = p[i, 1]
        zi = p[i, 2]
        z = zi - L1
        rho2 = xi * xi + yi * yi  # as Arm.solve, operation for operation: bit-equal c3
        rho = math.sqrt(rho2)
        D2 = rho2 + z * z
        D = math.sqrt(D2)
        good = not (rho <= tol or D - router > tol or rinner - D > tol)
        ok[i] = good
        phi = _atan2(yi, xi)
        c3 = min(max((D2 - L2 * L2 - L3 * L3) / (2.0 * L2 * L3), -1.0), 1.0)
        t3 = _wrap_scalar(-_acos(c3))  # folded elbow: -pi -> pi, as Arm.solve
        k = L2 * c3 + L3
        s0 = L2 * math.sqrt((1.0 - c3) * (1.0 + c3))
        t23 = _atan2(z * k - rho * s0, rho * k + z * s0)
        t1 = _wrap_scalar(phi)
        t2 = _wrap_scalar(t23 - t3)
        c1 = _round_half_away(t1 * deg / 360.0 * ppr[0]) if good else 0.0
        c2 = _round_half_away(t2 * deg / 360.0 * ppr[1]) if good else 0.0
        c3p = _round_half_away(t3 * deg / 360.0 * ppr[2]) if good else 0.0
        pulses[i, 0] = np.int64(c1)
        pulses[i, 1] = np.int64(c2)
        pulses[i, 2] = np.int64(c3p)
        q1 = (c1 * 360.0 / ppr[0]) * rad
        q2 = (c2 * 360.0 / ppr[1]) * rad
        q3 = (c3p * 360.0 / ppr[2]) * rad
        q23 = q2 + q3
        r = L2 * math.cos(q2) + L3 * math.cos(q23)
        dx = math.cos(q1) * r - xi
        dy = math.sin(q1) * r - yi
        dz = L1 + L2 * math.sin(q2) + L3 * math.sin(q23) - zi
        e = math.sqrt(dx * dx + dy * dy + dz * dz)
        err[i] = e if good else np.nan


def _check_tol(tol) -> None:
    if not (
        isinstance(tol, (int, float, np.floating, np.integer)) and math.isfinite(tol) and tol >= 0
    ):
        raise ValueError(f"tol = {tol!r} mm: the tolerance must be a finite number >= 0 mm")


def _flat(p: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    return np.ascontiguousarray(p.reshape(-1, 3), dtype=np.float64)


def solve_all(arm: Arm, p: npt.ArrayLike, *, tol: float = DEFAULT_TOL_MM) -> IKSolutions:
    """All four IK branches for targets (..., 3) [mm]; equals ``arm.solve(p, "all", tol=tol)``.

    Same contract as :meth:`analysis.kinematics.arm.Arm.solve` with ``branches="all"`` and no
    ``theta1_on_axis`` (base-axis targets get ``Status.BASE_AXIS``): ``theta`` (..., 4, 3)
    [rad] wrapped to (-pi, pi], NaN exactly where ``ok`` is False.

    Examples
    --------
    Table 4 row 1, (100, 100, 600) mm, front-up -> (45.00, 10.21, -155.13) deg:

    >>> np.degrees(solve_all(paper_arm(), [100, 100, 600]).branch("front-up")).round(2).tolist()
    [45.0, 10.21, -155.13]
    """
    p = as_points(p)
    _check_tol(tol)
    if not HAVE_NUMBA:
        return arm.solve(p, BRANCHES, tol=tol)
    lead = p.shape[:-1]
    n = int(np.prod(lead, dtype=np.int64))
    flat = _flat(p)
    theta = np.empty((n, 4, 3))
    ok = np.empty((n, 4), dtype=bool)
    status = np.empty(n, dtype=np.int8)
    outside = np.empty(n)
    P = arm.params
    _solve_kernel(
        flat, float(P.L1), float(P.L2), float(P.L3), float(tol), theta, ok, status, outside
    )
    return IKSolutions(
        theta.reshape(*lead, 4, 3),
        ok.reshape(*lead, 4),
        status.reshape(lead),
        outside.reshape(lead),
        BRANCHES,
    )


def fk(arm: Arm, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Gripper points (..., 3) [mm] for joint angles (..., 3) [rad]; equals ``arm.fk(q)``.

    The P column of eq. 2 (T3 = A1 A2 A3), compiled and split over the cores.
    """
    q = np.asarray(q, dtype=float)
    if q.ndim == 0 or q.shape[-1] != 3:
        raise ValueError(f"joint array has shape {q.shape}; expected (..., 3)")
    if not HAVE_NUMBA:
        return arm.fk(q)
    flat = _flat(q)
    out = np.empty((flat.shape[0], 3))
    P = arm.params
    _fk_kernel(flat, float(P.L1), float(P.L2), float(P.L3), out)
    return out.reshape(q.shape)


def ik_front_up_pulses(
    arm: Arm,
    p: npt.ArrayLike,
    pulses_per_rev: npt.ArrayLike | None = None,
    *,
    tol: float = DEFAULT_TOL_MM,
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float64], npt.NDArray[np.bool_]]:
    """Fused quantization pipeline for the paper's front-up branch, one pass per target.

    front-up IK (corrected eqs. 6-19) -> whole pulses (eqs. 20-22, ROUND half away from
    zero, as :func:`analysis.kinematics.pulses.angles_to_pulses`) -> commanded angles -> FK (eq. 2)
    -> distance to the target.

    Parameters
    ----------
    arm : Arm
    p : array_like, shape (..., 3)
        Targets [mm].
    pulses_per_rev : array_like of 3, optional
        Pulses per revolution per joint; default ``arm.params.pulses_per_rev`` (4000).

    Returns
    -------
    pulses : ndarray of int64, shape (..., 3)
        Pulse counts (0 where not ok).
    error_mm : ndarray, shape (...,)
        End-point error [mm] of the quantized pose (NaN where not ok).
    ok : ndarray of bool, shape (...,)
        Targets with a front-up solution (reachable, off the base axis).
    """
    p = as_points(p)
    _check_tol(tol)
    ppr = np.broadcast_to(
        np.asarray(
            arm.params.pulses_per_rev if pulses_per_rev is None else pulses_per_rev, dtype=float
        ),
        (3,),
    ).copy()
    if not (np.isfinite(ppr).all() and (ppr > 0).all()):
        raise ValueError(f"pulses_per_rev = {ppr.tolist()} must be positive and finite")
    lead = p.shape[:-1]
    if not HAVE_NUMBA:
        from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles

        sol = arm.solve(p, ("front-up",), tol=tol)
        ok = sol.ok[..., 0]
        q = np.where(ok[..., None], sol.theta[..., 0, :], 0.0)
        c = np.where(ok[..., None], angles_to_pulses(q, ppr), 0)
        err = np.linalg.norm(arm.fk(pulses_to_angles(c, ppr)) - p, axis=-1)
        return c, np.where(ok, err, np.nan), ok
    flat = _flat(p)
    n = flat.shape[0]
    pulses = np.empty((n, 3), dtype=np.int64)
    err = np.empty(n)
    ok = np.empty(n, dtype=bool)
    P = arm.params
    _quant_kernel(flat, float(P.L1), float(P.L2), float(P.L3), ppr, float(tol), pulses, err, ok)
    return pulses.reshape(*lead, 3), err.reshape(lead), ok.reshape(lead)

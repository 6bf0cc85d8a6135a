"""Where the paper's arm can reach: the reachable set, its sections, volume and singular sets.

The arm (Table 1 / Table 3) puts the gripper at distance D from the shoulder point
(0, 0, L1) with |L2 - L3| <= D <= L2 + L3 (eqs. 9-10: |cos theta3| <= 1), at any azimuth
(eq. 6). Without joint limits (the paper gives none, so that is the default here) the
reachable set is exactly that spherical shell; with limits it is the set of targets that
have at least one IK branch (:data:`analysis.kinematics.arm.BRANCHES`) inside the limits.

Singular sets (|det J| = L2 L3 |sin(theta3) r|, see :meth:`analysis.kinematics.arm.Arm.jacobian`):
the
base axis (r = 0: theta1 undefined), the outer sphere D = L2 + L3 (elbow stretched,
theta3 = 0) and the inner sphere D = |L2 - L3| (elbow folded, theta3 = pi).

Everything takes targets of shape (..., 3) [mm]; angles in radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import matplotlib as mpl
import matplotlib.pyplot as plt
import numpy as np
import numpy.typing as npt

from analysis.kinematics.arm import BRANCHES, DEFAULT_TOL_MM, Arm, as_points

__all__ = [
    "JointLimits",
    "SectionGrid",
    "VolumeEstimate",
    "WorkspaceMaps",
    "condition_number",
    "manipulability",
    "monte_carlo_volume",
    "plot_section",
    "plot_targets",
    "reachable",
    "sample_box",
    "sample_shell",
    "section_circles",
    "section_grid",
    "shell_volume",
    "workspace_maps",
]

_TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class JointLimits:
    """Per-joint angle limits [rad], ``lower[j] <= theta_j <= upper[j]``.

    The paper gives no joint limits, so the default is unlimited (-inf, inf) for all three
    joints. A joint angle is within limits if *some* equivalent angle theta + 2 pi k is,
    so limits may span more than (-pi, pi] (e.g. a waist with +-270 deg of travel).
    """

    lower: tuple[float, float, float] = (-math.inf, -math.inf, -math.inf)
    upper: tuple[float, float, float] = (math.inf, math.inf, math.inf)

    def __post_init__(self) -> None:
        lo, hi = tuple(float(v) for v in self.lower), tuple(float(v) for v in self.upper)
        if len(lo) != 3 or len(hi) != 3:
            raise ValueError(
                f"joint limits need 3 lower and 3 upper values, got {self.lower!r}, {self.upper!r}"
            )
        for j, (a, b) in enumerate(zip(lo, hi, strict=True)):
            if math.isnan(a) or math.isnan(b):
                raise ValueError(f"joint {j + 1} limit is NaN: ({a}, {b}) rad")
            if a > b:
                raise ValueError(
                    f"joint {j + 1} lower limit {a} rad is above its upper limit {b} rad"
                )
        object.__setattr__(self, "lower", lo)
        object.__setattr__(self, "upper", hi)

    @classmethod
    def from_degrees(cls, lower_deg, upper_deg) -> JointLimits:
        """Limits given in degrees.

        Example: ``JointLimits.from_degrees((-170, 0, -150), (170, 180, 150))``.
        """
        return cls(
            tuple(math.radians(v) for v in lower_deg), tuple(math.radians(v) for v in upper_deg)
        )

    @property
    def unlimited(self) -> bool:
        """True if every joint can make a full turn (no constraint at all)."""
        return all(b - a >= _TWO_PI for a, b in zip(self.lower, self.upper, strict=True))

    def contains(self, q: npt.ArrayLike) -> npt.NDArray[np.bool_]:
        """Mask (...,) of joint vectors (..., 3) [rad] within the limits (modulo 2 pi).

        NaN angles (no solution) are never within limits.
        """
        q = np.asarray(q, dtype=float)
        if q.ndim == 0 or q.shape[-1] != 3:
            raise ValueError(f"joint array has shape {q.shape}; expected (..., 3)")
        inside = np.isfinite(q).all(axis=-1)
        for j in range(3):
            lo, hi = self.lower[j], self.upper[j]
            if hi - lo >= _TWO_PI:
                continue
            # is there an integer k with lo <= q + 2 pi k <= hi ?
            k = np.ceil((lo - q[..., j]) / _TWO_PI)
            inside &= q[..., j] + _TWO_PI * k <= hi
        return inside

    def theta1_on_axis(self) -> float:
        """A waist angle within the limits (the one nearest 0), for base-axis targets."""
        return float(min(max(0.0, self.lower[0]), self.upper[0]))


def reachable(
    arm: Arm, p: npt.ArrayLike, limits: JointLimits | None = None, *, tol: float = DEFAULT_TOL_MM
) -> npt.NDArray[np.bool_]:
    """Mask (...,) of targets (..., 3) [mm] that some IK branch reaches within ``limits``.

    Without limits this is the shell test ``|L2 - L3| <= D <= L2 + L3`` (base axis
    included). With limits every branch of the corrected closed form (eqs. 6-19) is
    solved and tested; on the base axis the waist takes :meth:`JointLimits.theta1_on_axis`.
    """
    p = as_points(p)
    if limits is None or limits.unlimited:
        return arm.is_reachable(p, tol=tol)
    sol = arm.solve(p, BRANCHES, theta1_on_axis=limits.theta1_on_axis(), tol=tol)
    return (sol.ok & limits.contains(sol.theta)).any(axis=-1)


# --- sampling and volume -------------------------------------------------------------
def shell_volume(arm: Arm) -> float:
    """Analytic reachable volume without joint limits [mm^3]: 4/3 pi (R^3 - r^3).

    R = L2 + L3, r = |L2 - L3| (Table 3: 510 and 110 mm -> 5.500e8 mm^3 = 0.550 m^3).
    """
    R, r = arm.geometry["reach_outer"], arm.geometry["reach_inner"]
    return 4.0 / 3.0 * math.pi * (R**3 - r**3)


def sample_box(arm: Arm, n: int, rng: np.random.Generator) -> npt.NDArray[np.float64]:
    """``n`` targets uniform in the cube of side 2 (L2 + L3) around the shoulder, (n, 3) [mm]."""
    if n <= 0:
        raise ValueError(f"n = {n} samples must be positive")
    R = arm.geometry["reach_outer"]
    return arm.shoulder + rng.uniform(-R, R, (int(n), 3))


def sample_shell(arm: Arm, n: int, rng: np.random.Generator) -> npt.NDArray[np.float64]:
    """``n`` targets uniform in the reachable shell (volume measure), (n, 3) [mm].

    Direction uniform on the sphere (normalised Gaussians); radius by inverting the
    CDF (D^3 - r^3) / (R^3 - r^3).
    """
    if n <= 0:
        raise ValueError(f"n = {n} samples must be positive")
    R, r = arm.geometry["reach_outer"], arm.geometry["reach_inner"]
    u = rng.standard_normal((int(n), 3))
    u /= np.linalg.norm(u, axis=-1, keepdims=True)
    D = np.cbrt(r**3 + rng.uniform(0.0, 1.0, int(n)) * (R**3 - r**3))
    return arm.shoulder + u * D[:, None]


class VolumeEstimate(NamedTuple):
    """Monte Carlo estimate of a reachable volume [mm^3] with a confidence interval."""

    volume_mm3: float
    ci_low_mm3: float
    ci_high_mm3: float
    stderr_mm3: float
    hits: int
    n: int
    box_mm3: float
    confidence: float


def monte_carlo_volume(
    arm: Arm,
    n: int = 1_000_000,
    *,
    seed: int = 0,
    limits: JointLimits | None = None,
    confidence: float = 0.95,
    chunk: int = 250_000,
) -> VolumeEstimate:
    """Reachable volume by uniform sampling of the bounding cube (seeded).

    The hit fraction is binomial; the interval is Wilson's score interval at
    ``confidence`` (two-sided), scaled by the cube volume. Chunked to bound memory.
    """
    if not 0.0 < confidence < 1.0:
        raise ValueError(f"confidence = {confidence} must be strictly between 0 and 1")
    if n <= 0:
        raise ValueError(f"n = {n} samples must be positive")
    rng = np.random.default_rng(seed)
    hits = 0
    done = 0
    while done < n:  # loop over chunks, not points
        m = min(chunk, n - done)
        hits += int(reachable(arm, sample_box(arm, m, rng), limits).sum())
        done += m
    box = (2.0 * arm.geometry["reach_outer"]) ** 3
    from statistics import NormalDist

    zq = NormalDist().inv_cdf(0.5 + confidence / 2.0)
    ph = hits / n
    denom = 1.0 + zq * zq / n
    centre = (ph + zq * zq / (2 * n)) / denom
    half = zq * math.sqrt(ph * (1 - ph) / n + zq * zq / (4 * n * n)) / denom
    return VolumeEstimate(
        volume_mm3=box * ph,
        ci_low_mm3=box * (centre - half),
        ci_high_mm3=box * (centre + half),
        stderr_mm3=box * math.sqrt(ph * (1 - ph) / n),
        hits=hits,
        n=int(n),
        box_mm3=box,
        confidence=confidence,
    )


# --- sections --------------------------------------------------------------------------
class SectionGrid(NamedTuple):
    """A regular grid on a plane: axis coordinates u (nu,), v (nv,) [mm], points (nv, nu, 3)."""

    u: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    points: npt.NDArray[np.float64]
    plane: str
    level_mm: float


def section_grid(
    arm: Arm,
    plane: str = "xz",
    n: int = 401,
    *,
    level_mm: float | None = None,
    margin_mm: float = 20.0,
) -> SectionGrid:
    """Points on a section plane covering the reach shell.

    ``plane="xz"``: the vertical plane through the base axis (y = ``level_mm``, default 0),
    u = x, v = z. ``plane="xy"``: the horizontal plane z = ``level_mm`` (default 600 mm,
    the height of all Table 4 targets), u = x, v = y.
    """
    if n < 2:
        raise ValueError(f"n = {n} grid points per axis must be at least 2")
    R = arm.geometry["reach_outer"] + margin_mm
    L1 = arm.params.L1
    if plane == "xz":
        level = 0.0 if level_mm is None else float(level_mm)
        u = np.linspace(-R, R, n)
        v = np.linspace(L1 - R, L1 + R, n)
        U, V = np.meshgrid(u, v)
        pts = np.stack([U, np.full_like(U, level), V], axis=-1)
    elif plane == "xy":
        level = 600.0 if level_mm is None else float(level_mm)
        u = np.linspace(-R, R, n)
        v = np.linspace(-R, R, n)
        U, V = np.meshgrid(u, v)
        pts = np.stack([U, V, np.full_like(U, level)], axis=-1)
    else:
        raise ValueError(
            f"unknown plane {plane!r}; expected 'xz' (vertical, through the base axis) or 'xy'"
        )
    return SectionGrid(u, v, pts, plane, level)


def section_circles(arm: Arm, plane: str, level_mm: float) -> dict[str, float | None]:
    """Radii [mm] and centre of the shell's boundary circles (the stretched and folded
    singular sets) in a section: ``{"centre_u", "centre_v", "outer", "inner"}`` (None
    where the plane misses that sphere)."""
    R, r, L1 = arm.geometry["reach_outer"], arm.geometry["reach_inner"], arm.params.L1
    if plane == "xz":
        off, cu, cv = abs(level_mm), 0.0, L1
    elif plane == "xy":
        off, cu, cv = abs(level_mm - L1), 0.0, 0.0
    else:
        raise ValueError(f"unknown plane {plane!r}; expected 'xz' or 'xy'")
    rad = {
        k: (math.sqrt(v * v - off * off) if v > off else None)
        for k, v in (("outer", R), ("inner", r))
    }
    return {"centre_u": cu, "centre_v": cv, **rad}


# --- dexterity maps --------------------------------------------------------------------
def manipulability(arm: Arm, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Yoshikawa manipulability w = sqrt(det(J J^T)) = |det J| [mm^3/rad^3], shape (...,).

    For this arm |det J| = L2 L3 |sin(theta3)| |r| (r = L2 cos theta2 + L3 cos(theta2 +
    theta3), the signed distance from the base axis): zero on the singular sets.
    """
    q = np.asarray(q, dtype=float)
    L2, L3 = arm.params.L2, arm.params.L3
    r = L2 * np.cos(q[..., 1]) + L3 * np.cos(q[..., 1] + q[..., 2])
    return np.abs(L2 * L3 * np.sin(q[..., 2]) * r)


def condition_number(arm: Arm, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """2-norm condition number sigma_max / sigma_min of the positional Jacobian, (...,).

    All columns are in mm/rad, so the ratio is unit-free. inf on the singular sets.
    """
    s = np.linalg.svd(arm.jacobian(q), compute_uv=False)
    with np.errstate(divide="ignore"):
        return np.where(s[..., -1] > 0, s[..., 0] / s[..., -1], np.inf)


class WorkspaceMaps(NamedTuple):
    """Per-target maps over a grid, shapes (...,); NaN exactly where ``reachable`` is False."""

    reachable: npt.NDArray[np.bool_]
    q: npt.NDArray[np.float64]
    manipulability: npt.NDArray[np.float64]
    condition: npt.NDArray[np.float64]


def workspace_maps(
    arm: Arm, p: npt.ArrayLike, branch: str = "front-up", *, tol: float = DEFAULT_TOL_MM
) -> WorkspaceMaps:
    """Reachability, IK angles (..., 3), manipulability and condition number for targets.

    The dexterity values depend only on the elbow angle and the distance from the base
    axis, so all four branches give the same numbers; ``branch`` picks the angles.
    Base-axis targets take theta1 = 0 (their manipulability is 0 and condition inf).
    """
    p = as_points(p)
    sol = arm.solve(p, (branch,), theta1_on_axis=0.0, tol=tol)
    ok = sol.ok[..., 0]
    q = sol.theta[..., 0, :]
    w = np.where(ok, manipulability(arm, np.where(ok[..., None], q, 0.0)), np.nan)
    c = np.where(ok, condition_number(arm, np.where(ok[..., None], q, 0.0)), np.nan)
    return WorkspaceMaps(ok, q, w, c)


# --- plots -------------------------------------------------------------------------------
def plot_section(
    arm: Arm,
    grid: SectionGrid,
    values: npt.ArrayLike,
    *,
    ax: mpl.axes.Axes | None = None,
    label: str = "",
    cmap: str | None = None,
    norm=None,
    singular: bool = True,
    colorbar: bool = True,
) -> mpl.axes.Axes:
    """Colour map of ``values`` (nv, nu) on a section with the reach circles and base axis.

    NaN cells (unreachable) are left blank. The outer (stretched) and inner (folded)
    singular circles are dashed; the base axis is a dotted line (xz) or a dot (xy).
    ``colorbar=False`` draws no colour bar (a mask of one value needs none).
    """
    if ax is None:
        ax = plt.figure().add_subplot()
    vals = np.asarray(values, dtype=float)
    mesh = ax.pcolormesh(
        grid.u,
        grid.v,
        np.ma.masked_invalid(vals),
        shading="nearest",
        cmap=cmap,
        norm=norm,
        rasterized=True,
    )
    if colorbar:
        ax.figure.colorbar(mesh, ax=ax, label=label)
    if singular:
        circ = section_circles(arm, grid.plane, grid.level_mm)
        names = {"outer": "stretched", "inner": "folded"}
        for key, style in (("outer", "-"), ("inner", "--")):
            if circ[key] is not None:
                ax.add_patch(
                    mpl.patches.Circle(
                        (circ["centre_u"], circ["centre_v"]),
                        circ[key],
                        fill=False,
                        ls=style,
                        color="C3",
                        lw=1.2,
                        label=f"{names[key]} elbow, r = {circ[key]:.1f} mm",
                    )
                )
        if grid.plane == "xz":
            ax.axvline(0.0, color="C1", ls=":", lw=1.5, label="base axis (x = y = 0)")
        else:
            ax.plot([0.0], [0.0], "o", color="C1", ms=4, label="base axis")
    ax.set_aspect("equal")
    names = {"xz": ("x [mm]", "z [mm]"), "xy": ("x [mm]", "y [mm]")}[grid.plane]
    ax.set_xlabel(names[0])
    ax.set_ylabel(names[1])
    return ax


def plot_targets(
    points: npt.ArrayLike,
    labels,
    reachable_mask: npt.ArrayLike,
    *,
    ax: mpl.axes.Axes | None = None,
    plane: str = "xy",
) -> mpl.axes.Axes:
    """Overlay labelled targets (n, 3) [mm] on a section: reachable as dots, others as crosses."""
    if ax is None:
        ax = plt.figure().add_subplot()
    pts = as_points(points).reshape(-1, 3)
    ok = np.asarray(reachable_mask, dtype=bool).reshape(-1)
    iu, iv = (0, 1) if plane == "xy" else (0, 2)
    ax.scatter(
        pts[ok, iu], pts[ok, iv], s=25, color="k", zorder=3, label="Table 4 target (reachable)"
    )
    if (~ok).any():
        ax.scatter(
            pts[~ok, iu],
            pts[~ok, iv],
            s=60,
            marker="x",
            color="C3",
            zorder=3,
            label="Table 4 target (unreachable)",
        )
    for (u, v), text in zip(pts[:, [iu, iv]], labels, strict=True):
        ax.annotate(str(text), (u, v), xytext=(4, 4), textcoords="offset points", fontsize=10)
    return ax

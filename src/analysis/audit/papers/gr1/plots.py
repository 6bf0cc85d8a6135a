"""Figures of the GR-1 study (notebook 10): the arm in its plane, hand paths, the work area.

Each helper follows the project's rule (:mod:`analysis.app.plotting`): ``plot_*(..., ax=None)
-> Axes``, drawing on the given or a new Axes, never showing, saving or touching rcParams.
Assumed values are named in the labels the helpers write (``ASSUMED``).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import numpy.typing as npt

from analysis.kinematics.arm import Arm

__all__ = ["ASSUMED", "plot_arm_plane", "plot_hand_paths", "plot_joint_moves", "plot_work_area"]

ASSUMED = "assumed: d1 = 0 mm, joint limits = printed spans placed symmetrically"
"""The caption line every GR-1 figure that uses the assumed values carries."""


def _plane(arm: Arm, q: npt.ArrayLike, azimuth: float) -> npt.NDArray[np.float64]:
    """Frame origins of configuration q projected on the vertical plane at ``azimuth``:
    (n_frames, 2) = (distance along the azimuth, height) [mm]."""
    pts = arm.frames(q)
    u = np.array([np.cos(azimuth), np.sin(azimuth), 0.0])
    return np.stack([pts @ u, pts[:, 2]], axis=-1)


def plot_arm_plane(
    arm: Arm,
    q: npt.ArrayLike,
    *,
    ax=None,
    target: npt.ArrayLike | None = None,
    azimuth: float | None = None,
    label: str | None = None,
    color: str = "C0",
    style: str = "-o",
):
    """The arm at joint angles q (5,) [rad] in its vertical plane: base, shoulder, elbow,
    wrist, tool (the D-H frame origins; the hand a4 from wrist to tool), and the approach
    vector as an arrow at the tool. ``target`` (3,) [mm] is drawn as a cross in the same
    plane (its distance from the plane is not shown)."""
    if ax is None:
        ax = plt.figure().add_subplot()
    q = np.asarray(q, dtype=float)
    azimuth = q[0] if azimuth is None else azimuth
    pts = _plane(arm, q, azimuth)
    ax.plot(pts[:, 0], pts[:, 1], style, color=color, lw=2.5, ms=4, label=label)
    a = arm.table.fk(q)[:3, 2]
    u = np.array([np.cos(azimuth), np.sin(azimuth), 0.0])
    ax.annotate(
        "",
        xy=(pts[-1, 0] + 40 * (a @ u), pts[-1, 1] + 40 * a[2]),
        xytext=(pts[-1, 0], pts[-1, 1]),
        arrowprops={"arrowstyle": "->", "color": color},
    )
    if target is not None:
        t = np.asarray(target, dtype=float)
        ax.plot(t[:2] @ u[:2], t[2], "x", color="C3", ms=9, mew=2)
    ax.set_xlabel("along the arm's azimuth [mm]")
    ax.set_ylabel("height above the shoulder [mm]")
    ax.set_aspect("equal")
    return ax


def plot_joint_moves(t_a, q_a, t_b, q_b, *, labels=("a", "b"), ax=None):
    """Joint angles [deg] over time of two moves (m, 5) and (k, 5) [rad], joint by joint."""
    if ax is None:
        ax = plt.figure().add_subplot()
    for j in range(np.asarray(q_a).shape[1]):
        ax.plot(t_a, np.degrees(q_a[:, j]), color=f"C{j}", lw=2, label=f"theta{j + 1} {labels[0]}")
        ax.plot(t_b, np.degrees(q_b[:, j]), "--", color=f"C{j}", lw=1.5)
    ax.plot([], [], "k-", label=labels[0])
    ax.plot([], [], "k--", label=labels[1])
    ax.set_xlabel("time [s]")
    ax.set_ylabel("joint angle [deg]")
    return ax


def plot_hand_paths(paths: dict, *, view: str = "xy", ax=None):
    """Hand paths {label: (m, 3) [mm]} seen from above (``view="xy"``) or from the side
    (``"xz"``), with start (o) and end (s) marked."""
    if ax is None:
        ax = plt.figure().add_subplot()
    i, j = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}[view]
    for k, (label, p) in enumerate(paths.items()):
        p = np.asarray(p, dtype=float)
        ax.plot(p[:, i], p[:, j], color=f"C{k}", lw=2 - 0.5 * k, label=label)
        ax.plot(p[0, i], p[0, j], "o", color=f"C{k}")
        ax.plot(p[-1, i], p[-1, j], "s", color=f"C{k}")
    ax.set_xlabel(f"{view[0]} [mm]")
    ax.set_ylabel(f"{view[1]} [mm]")
    ax.set_aspect("equal", adjustable="datalim")
    return ax


def plot_work_area(section: dict, extents: dict, printed: tuple[float, float], *, ax=None):
    """Tool points in the arm plane ({"free", "limited"}: (n, 2) of (r, z) [mm]), the reach
    circle, and the printed work area (vertical, horizontal) [mm] as the two readings: a box
    of span 850 x 600 centred on the shoulder and a radius/height of 600/850."""
    if ax is None:
        ax = plt.figure().add_subplot()
    free, lim = section["free"], section["limited"]
    ax.plot(free[:, 0], free[:, 1], ".", ms=0.6, color="0.75", label="no limits")
    ax.plot(lim[:, 0], lim[:, 1], ".", ms=0.6, color="C0", label="assumed limits")
    th = np.linspace(-np.pi, np.pi, 361)
    R = extents["reach_mm"]
    ax.plot(R * np.cos(th), R * np.sin(th), "k-", lw=1, label=f"reach {R:g} mm")
    v, h = printed
    ax.plot([-h / 2, h / 2, h / 2, -h / 2, -h / 2], [-v / 2, -v / 2, v / 2, v / 2, -v / 2],
            "C3--", lw=1.5, label=f"printed as spans ({v:g} x {h:g})")  # fmt: skip
    ax.plot([-h, h, h, -h, -h], [-v, -v, v, v, -v], "C1:", lw=1.5,
            label=f"printed as radius {h:g} / height {v:g}")  # fmt: skip
    ax.set_xlabel("radius in the arm plane [mm]")
    ax.set_ylabel("height above the shoulder [mm]")
    ax.set_aspect("equal")
    return ax

"""The GR-1 thesis (seed 004) recomputed: Table 5-4, the counter presets of Table 2-3, the work
area of section 2.1 and the move the FX2N program makes, against the corrected arm.

The arm is ``data/arms/gr1.toml`` with its closed form :mod:`analysis.kinematics.arms.gr1`
(:func:`gr1_arm`). Values the thesis prints come from :mod:`analysis.papers.gr1_thesis`;
everything else is computed here. What rests on an assumption says so:

- the base height d1 = 0 and the joint limits (the printed spans placed symmetrically about
  the D-H zero) are assumed in the arm's description;
- Table 5-3's orientations cannot be taken by a 5-DOF arm (:func:`project_orientation`): the
  corrected joint values are those of the nearest reachable orientation, at the printed
  position;
- joint speeds (:func:`joint_speeds_deg_s`) assume the motor runs at its printed no-load
  speed (3000 r/min) and the counter sees all 12 encoder signals per motor revolution
  (sec. 2.3.2): an upper bound of the speed.

Angles in radians unless a name ends in ``_deg``; lengths in mm; poses are (..., 6) =
(px, py, pz, alpha, beta, gamma) with RPY angles (eq. 3.14).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import Arm, load_arm
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.rpy import matrix_from_rpy, pose_from_transform, rotation_angle
from analysis.papers import gr1_thesis as paper
from analysis.studies.trajectories import profile, sequential_move

__all__ = [
    "COUNTERS",
    "COUNTS_PER_MOTOR_REV",
    "DURATION_S",
    "NO_LOAD_RPM",
    "RESOLUTION_DEG",
    "counter_presets",
    "first_within_limits",
    "fx2n_vs_cubic",
    "gr1_arm",
    "nearest_point_distance",
    "pose_of",
    "printed_joints",
    "printed_presets",
    "project_orientation",
    "table5_4",
    "thesis_poses",
    "workspace_extents",
    "workspace_section",
]

RESOLUTION_DEG: tuple[float, ...] = tuple(float(r[2]) for r in paper.TABLE2_1["rows"])
"""Table 2-1: degrees per encoder pulse of joints 1-5 (0.14, 0.11, 0.11, 0.11, 0.24)."""
COUNTERS: tuple[str, ...] = tuple(paper.TABLE2_3["counter_of_joint"][j] for j in range(1, 6))
"""The FX2N high-speed counter of each joint (Table 2-3, Figure 2-1): C235 .. C239."""
NO_LOAD_RPM = float(paper.MOTOR["no_load_speed_rpm"])
"""Section 2.1: the motors' no-load speed, 3000 r/min."""
COUNTS_PER_MOTOR_REV = int(paper.ENCODER["signals_per_rev"])
"""Section 2.3.2: 12 encoder signals per motor revolution (6 holes, channels A and B)."""
DURATION_S = float(paper.CUBIC["duration_s"])
"""The cubic's duration, 10 s (the listing's ``c = 10``)."""


@cache
def gr1_arm() -> Arm:
    """The GR-1 arm of ``data/arms/gr1.toml``."""
    return load_arm("gr1")


def thesis_poses() -> npt.NDArray[np.float64]:
    """Table 5-3's start and end poses, shape (2, 6): mm and RPY angles [rad] (printed in
    degrees; the angle headers are lost, the listing's order alpha, beta, gamma is read)."""
    return np.array(paper.poses())


def printed_joints() -> npt.NDArray[np.float64]:
    """Table 5-4 as printed (cells as assigned in ``gr1_thesis.TABLE5_4``), (2, 5) [rad]."""
    rows = paper.TABLE5_4["rows"]
    return np.radians(np.array([rows["start"], rows["end"]], dtype=float))


def pose_of(arm: Arm, q: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The pose (..., 6) the chain takes at joint angles q (..., 5) [rad] (D-H FK + eq. 3.18)."""
    return pose_from_transform(arm.table.fk(q))


def project_orientation(arm: Arm, poses: npt.ArrayLike):
    """The nearest pose the arm can take at the same position, and how far it turned.

    The closed form with ``orientation_tol=None`` keeps the in-plane part of the approach
    vector and the components of n, o along the joint axis: the reachable orientation
    nearest the requested one (the rotation between them is the out-of-plane angle of a).

    Returns
    -------
    projected : ndarray, shape (..., 6)
        Position unchanged, RPY angles of the nearest reachable orientation [rad].
    residual : ndarray, shape (...)
        Angle of the rotation from the requested to the projected orientation [rad].
    """
    p = np.asarray(poses, dtype=float)
    with np.errstate(all="ignore"):
        sol = arm.closed_form.ik(
            numpy_ops, tuple(p[..., k] for k in range(6)), arm.params, tol=0.0,
            orientation_tol=None,
        )  # fmt: skip
    q = np.stack(np.broadcast_arrays(*sol["branches"][arm.branches[0]]), axis=-1)
    R = arm.table.fk(q)[..., :3, :3]  # theta2 + theta3 + theta4 = theta234 on any branch
    projected = np.concatenate([p[..., :3], pose_from_transform(arm.table.fk(q))[..., 3:]], -1)
    return projected, rotation_angle(matrix_from_rpy(p[..., 3:]), R)


def first_within_limits(arm: Arm, poses: npt.ArrayLike):
    """For each pose the first branch (in the arm's order) that solves it within the joint
    limits: angles (..., 5) [rad] (NaN if none) and branch names (object array)."""
    sol = arm.solve(poses)
    first = np.argmax(sol.ok, axis=-1)
    any_ok = sol.ok.any(axis=-1)
    q = np.take_along_axis(sol.theta, first[..., None, None], axis=-2)[..., 0, :]
    names = np.where(any_ok, np.array(arm.branches, dtype=object)[first], None)
    return np.where(any_ok[..., None], q, np.nan), names


# --------------------------------------------------------------------------- Table 5-4
def table5_4(arm: Arm | None = None) -> pd.DataFrame:
    """Table 5-4 as printed and corrected, one row per pose and solution.

    Columns: ``pose`` (start/end), ``source`` (``printed`` or a branch), ``theta1_deg`` ..
    ``theta5_deg``, ``within_limits`` (assumed limits; printed rows: not applicable),
    ``miss_mm`` (distance of the FK position from Table 5-3's), ``turn_deg`` (rotation from
    Table 5-3's orientation to the one the angles give).
    """
    arm = arm or gr1_arm()
    poses = thesis_poses()
    proj, _ = project_orientation(arm, poses)
    with np.errstate(all="ignore"):
        sol = arm.closed_form.ik(
            numpy_ops, tuple(proj[:, k] for k in range(6)), arm.params, tol=1e-6
        )
    ok = arm.solve(proj).ok
    rows = []
    R_req = matrix_from_rpy(poses[:, 3:])
    sources = [("printed", printed_joints(), np.array([None, None]))]
    for i, b in enumerate(arm.branches):
        sources.append((b, np.stack(sol["branches"][b], axis=-1), ok[:, i]))
    for name, q, within in sources:
        T = arm.table.fk(q)
        miss = np.linalg.norm(T[:, :3, 3] - poses[:, :3], axis=-1)
        turn = np.degrees(rotation_angle(R_req, T[:, :3, :3]))
        for k, label in enumerate(("start", "end")):
            rows.append(
                {
                    "pose": label,
                    "source": name,
                    **{f"theta{j + 1}_deg": float(np.degrees(q[k, j])) for j in range(5)},
                    "within_limits": within[k],
                    "miss_mm": float(miss[k]),
                    "turn_deg": float(turn[k]),
                }
            )
    return pd.DataFrame(rows)


# --------------------------------------------------------------------------- Table 2-3
def counter_presets(
    q0: npt.ArrayLike, qf: npt.ArrayLike, resolution_deg: npt.ArrayLike = RESOLUTION_DEG
) -> pd.DataFrame:
    """The FX2N counter presets a move from q0 to qf (5,) [rad] needs (sec. 2.3.4: preset =
    angle change / resolution, Table 2-1), one row per counter C235 .. C239.

    Columns: ``counter``, ``joint``, ``motor``, ``delta_deg`` (signed change),
    ``direction`` (+/-: which of the ladder's two output pairs runs), ``resolution_deg``,
    ``pulses_exact``, ``preset`` (``K`` value: nearest whole pulse), ``moved_deg`` (what the
    counter lets the joint turn, signed) and ``error_deg`` (moved - delta).
    """
    q0, qf = np.asarray(q0, dtype=float), np.asarray(qf, dtype=float)
    if q0.shape != (5,) or qf.shape != (5,) or not np.isfinite([*q0, *qf]).all():
        raise ValueError(f"q0, qf must be 5 finite joint angles [rad], got {q0!r}, {qf!r}")
    res = np.broadcast_to(np.asarray(resolution_deg, dtype=float), q0.shape)
    delta = np.degrees(qf - q0)
    exact = np.abs(delta) / res
    preset = np.floor(exact + 0.5).astype(np.int64)
    moved = np.sign(delta) * preset * res
    motors = [m for _, m, _ in paper.TABLE2_1["rows"]]
    return pd.DataFrame(
        {
            "counter": COUNTERS,
            "joint": [f"theta{j + 1}" for j in range(5)],
            "motor": motors,
            "delta_deg": delta,
            "direction": np.where(delta >= 0, "+", "-"),
            "resolution_deg": res,
            "pulses_exact": exact,
            "preset": preset,
            "moved_deg": moved,
            "error_deg": moved - delta,
        }
    )


def printed_presets() -> pd.DataFrame:
    """Table 2-3 as printed against what Table 2-1 and the printed Table 5-4 give.

    Columns: ``counter``, ``printed``, ``delta_deg`` (|end - start| of printed Table 5-4),
    ``as_pulses`` (nearest whole of delta / resolution: the text's rule), ``as_degrees``
    (delta rounded to a whole degree), ``matches`` ("pulses", "degrees", "neither").
    """
    q = printed_joints()
    df = counter_presets(q[0], q[1])
    printed = [paper.TABLE2_3["presets"][c] for c in COUNTERS]
    deg = np.abs(df["delta_deg"].to_numpy())
    as_deg = np.floor(deg + 0.5).astype(int)
    pulses = df["preset"].to_numpy()
    match = np.where(pulses == printed, "pulses", np.where(as_deg == printed, "degrees", "neither"))
    return pd.DataFrame(
        {
            "counter": COUNTERS,
            "printed": printed,
            "delta_deg": deg,
            "as_pulses": pulses,
            "as_degrees": as_deg,
            "matches": match,
        }
    )


# --------------------------------------------------------------------------- workspace
def workspace_extents(arm: Arm | None = None, *, step_deg: float = 5.0, limits: bool = True):
    """Extent of the tool point's reach: radius from the base axis and height range [mm].

    theta1 and theta5 do not change the radius or the height, so the planar chain
    (theta2, theta3, theta4) is swept on a grid of ``step_deg`` within the description's
    (assumed) limits, or over full turns if ``limits`` is False; the grid contains the
    stretched poses (0 and +-90 deg), where the extremes lie.

    Returns
    -------
    dict
        ``radius_mm`` (largest distance from the base axis), ``z_min_mm``, ``z_max_mm``,
        ``height_span_mm``, ``width_span_mm`` (2 x radius), ``reach_mm`` (a2 + a3 + a4).
    """
    arm = arm or gr1_arm()
    lo, hi = [], []
    for j in (1, 2, 3):
        lim = arm.limits[j] if limits else None
        lo.append(np.degrees(lim[0]) if lim else -180.0)
        hi.append(np.degrees(lim[1]) if lim else 180.0)
    axes = [np.arange(a, b + step_deg / 2, step_deg) for a, b in zip(lo, hi, strict=True)]
    t2, t3, t4 = np.meshgrid(*(np.radians(a) for a in axes), indexing="ij")
    q = np.stack([np.zeros_like(t2), t2, t3, t4, np.zeros_like(t2)], axis=-1).reshape(-1, 5)
    p = arm.fk(q)
    radius = float(np.abs(p[:, 0]).max())  # theta1 = 0: the arm plane is the x-z plane
    z0 = arm.params["d1"]
    out = {
        "radius_mm": radius,
        "z_min_mm": float(p[:, 2].min() - z0),
        "z_max_mm": float(p[:, 2].max() - z0),
        "reach_mm": arm.geometry["reach_tool"],
    }
    out["height_span_mm"] = out["z_max_mm"] - out["z_min_mm"]
    out["width_span_mm"] = 2 * radius
    return out


def workspace_section(arm: Arm | None = None, *, n: int = 60_000, seed: int = 2007):
    """Tool points (r, z) [mm] in the arm plane of ``n`` seeded configurations within the
    (assumed) limits and without limits: ``{"limited": (n, 2), "free": (n, 2)}``."""
    arm = arm or gr1_arm()
    rng = np.random.default_rng(seed)
    out = {}
    for key, use in (("limited", True), ("free", False)):
        lim = [arm.limits[j] if use and arm.limits[j] else (-np.pi, np.pi) for j in range(5)]
        lo, hi = np.array(lim).T
        q = rng.uniform(lo, hi, (n, 5))
        q[:, 0] = 0.0
        p = arm.fk(q)
        out[key] = np.stack([p[:, 0], p[:, 2] - arm.params["d1"]], axis=-1)
    return out


# --------------------------------------------------------------------------- the FX2N move
def joint_speeds_deg_s(
    resolution_deg: npt.ArrayLike = RESOLUTION_DEG,
    rpm: float = NO_LOAD_RPM,
    counts_per_motor_rev: int = COUNTS_PER_MOTOR_REV,
) -> npt.NDArray[np.float64]:
    """Joint speed [deg/s] of a motor at ``rpm``: rpm / 60 x counts per motor revolution x
    degrees per count (3000 r/min, 12 counts, 0.11 deg: 66 deg/s)."""
    return rpm / 60.0 * counts_per_motor_rev * np.asarray(resolution_deg, dtype=float)


def nearest_point_distance(path: npt.ArrayLike, reference: npt.ArrayLike):
    """For each point of ``path`` (m, 3) the distance [mm] to the nearest point of the
    polyline ``reference`` (k, 3) (segments, not only vertices)."""
    P = np.asarray(path, dtype=float)[:, None, :]
    A = np.asarray(reference, dtype=float)[:-1][None]
    B = np.asarray(reference, dtype=float)[1:][None]
    AB = B - A
    L2 = np.maximum((AB * AB).sum(-1), 1e-300)
    s = np.clip(((P - A) * AB).sum(-1) / L2, 0.0, 1.0)
    return np.linalg.norm(P - (A + s[..., None] * AB), axis=-1).min(axis=1)


def fx2n_vs_cubic(
    arm: Arm,
    q0: npt.ArrayLike,
    qf: npt.ArrayLike,
    *,
    duration: float = DURATION_S,
    resolution_deg: npt.ArrayLike = RESOLUTION_DEG,
    rpm: float = NO_LOAD_RPM,
    counts_per_motor_rev: int = COUNTS_PER_MOTOR_REV,
    samples: int = 2001,
) -> dict:
    """The move the thesis plans (every joint on its cubic, together, ``duration`` s) against
    the move its FX2N program makes (section 2.3.4, Figure 2-1, the ladder): M1 runs at
    full speed until C235 reaches its preset, then M2 until C236, ... M5.

    The counters stop each joint after ``preset`` whole pulses (:func:`counter_presets`),
    so the PLC's move ends at q0 + sign x preset x resolution, not exactly at qf.

    Returns
    -------
    dict
        ``t_cubic`` (m,), ``q_cubic`` (m, 5), ``p_cubic`` (m, 3) the planned move and its
        hand path; ``t_fx2n``, ``q_fx2n``, ``p_fx2n`` the PLC's; ``switch`` (6,) the motor
        start times and the end; ``speed_deg_s`` (5,); ``presets`` (DataFrame);
        ``time_cubic_s``, ``time_fx2n_s``; ``length_cubic_mm``, ``length_fx2n_mm``;
        ``max_apart_mm`` (largest distance of a PLC hand point from the planned path);
        ``end_error_mm`` (PLC end point vs qf's).
    """
    q0, qf = np.asarray(q0, dtype=float), np.asarray(qf, dtype=float)
    t = np.linspace(0.0, duration, samples)
    s = profile("cubic", t / duration)[0][:, None]
    q_cubic = q0 + (qf - q0) * s
    presets = counter_presets(q0, qf, resolution_deg)
    q_end = q0 + np.radians(presets["moved_deg"].to_numpy())
    speed = joint_speeds_deg_s(resolution_deg, rpm, counts_per_motor_rev)
    _, switch = sequential_move(q0, q_end, np.radians(speed), np.zeros(1))
    t_seq = np.linspace(0.0, switch[-1], samples)
    q_fx2n, _ = sequential_move(q0, q_end, np.radians(speed), t_seq)
    p_cubic, p_fx2n = arm.fk(q_cubic), arm.fk(q_fx2n)

    def length(p):
        return float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum())

    return {
        "t_cubic": t,
        "q_cubic": q_cubic,
        "p_cubic": p_cubic,
        "t_fx2n": t_seq,
        "q_fx2n": q_fx2n,
        "p_fx2n": p_fx2n,
        "switch": switch,
        "speed_deg_s": speed,
        "presets": presets,
        "time_cubic_s": float(duration),
        "time_fx2n_s": float(switch[-1]),
        "length_cubic_mm": length(p_cubic),
        "length_fx2n_mm": length(p_fx2n),
        "max_apart_mm": float(nearest_point_distance(p_fx2n, p_cubic).max()),
        "end_error_mm": float(np.linalg.norm(p_fx2n[-1] - arm.fk(qf))),
    }

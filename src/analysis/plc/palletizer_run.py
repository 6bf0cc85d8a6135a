"""The palletizer's generated PLC program (seed 001) executed on awlsim against Python.

The program is what ``python -m analysis stl --arm palletizer`` writes
(:func:`analysis.plc.generate.generate` with the arm's parameters, all of them *assumed*:
``data/arms/palletizer.toml``): the corrected closed form of
:mod:`analysis.kinematics.arms.palletizer`, its refusals, the elbow stop of sec. 2 (theta3 in
[90, 180] deg, status 4 "joint limits") and the pulse conversion at 3200 pulses/rev
(assumed). :func:`run` executes it on awlsim, one OB1 cycle per target, and compares with
:meth:`Arm.solve` plus :func:`~analysis.kinematics.pulses.angles_to_pulses` through
:func:`analysis.plc.verify.compare` (statuses, reach flag, pulses; each differing count must
straddle a half pulse and be reproduced by the float32 model
:func:`analysis.plc.model.predict`).

The targets (:func:`sweep_targets`) are the palletizer's own: the reach of this arm is a
sphere of the *wrist* (the grasp point moved L3 towards the base axis and h up), so the grid,
the shells and the half-pulse points are built in wrist coordinates or by forward kinematics
of level configurations, not with the main arm's sweep (:func:`analysis.plc.verify.
sweep_targets`).
"""

from __future__ import annotations

import json
from typing import NamedTuple

import numpy as np
import numpy.typing as npt
import pandas as pd

from analysis.kinematics.arm import Arm
from analysis.plc.memmap import MemoryMap
from analysis.plc.runner import RunResult, sweep
from analysis.plc.verify import Comparison, compare

__all__ = [
    "SENTINEL",
    "PlcRun",
    "cut_targets",
    "half_pulse_targets",
    "program",
    "real_errors",
    "run",
    "sweep_targets",
]

SENTINEL = -999_999
"""Written to c1..c4 before each cycle: a refused target must leave it there."""


def _grasp(arm: Arm, wrist_dist, elev, phi) -> npt.NDArray[np.float64]:
    """Grasp points whose wrist lies at ``wrist_dist`` [mm] from the shoulder, at elevation
    ``elev`` and azimuth ``phi`` [rad] (the wrist may be behind the base axis)."""
    P = arm.params
    w = wrist_dist * np.cos(elev)
    zw = wrist_dist * np.sin(elev)
    rho = w + P["L3"]  # > 0 required: the wrist plane faces the target
    return np.stack([rho * np.cos(phi), rho * np.sin(phi), zw - P["h"]], axis=-1)


def half_pulse_targets(arm: Arm, n: int, rng: np.random.Generator) -> npt.NDArray[np.float64]:
    """Targets whose exact pulse value of one joint lies within 1e-7 .. 1e-3 pulse of k + 1/2.

    Level configurations inside the elbow stop (:func:`analysis.studies.palletizer.
    level_configurations`); joint j = 0, 1, 2, 3 in turn is moved to ``(k + 1/2 + delta)``
    pulses (theta4 through theta2, since the gripper stays level: theta4 = pi/2 - theta2 -
    theta3), and the target is the forward kinematics. These are the targets where float32
    arithmetic may legitimately round to the other side.
    """
    from analysis.studies.palletizer import level_configurations

    ppr = np.asarray(arm.params.pulses_per_rev, dtype=float)
    out = []
    while sum(len(o) for o in out) < n:
        q = level_configurations(arm, n, rng, margin_deg=5.0)
        j = np.arange(n) % 4
        delta = rng.choice([-1.0, 1.0], n) * 10.0 ** rng.uniform(-7, -3, n)
        for i in range(n):
            jj = j[i]
            c = q[i, jj] / (2 * np.pi) * ppr[jj]
            q[i, jj] = (np.floor(c) + 0.5 + delta[i]) * 2 * np.pi / ppr[jj]
            if jj == 3:  # keep the gripper level: move theta2 instead
                q[i, 1] = np.pi / 2 - q[i, 2] - q[i, 3]
            else:
                q[i, 3] = np.mod(np.pi / 2 - q[i, 1] - q[i, 2] + np.pi, 2 * np.pi) - np.pi
        p = arm.fk(q)
        lo, hi = arm.limits[2]
        keep = (
            (p[:, 0] * np.cos(q[:, 0]) + p[:, 1] * np.sin(q[:, 0]) > 1.0)
            & (q[:, 2] > lo + 1e-3)
            & (q[:, 2] < hi - 1e-3)
        )
        out.append(p[keep])
    return np.concatenate(out)[:n]


def cut_targets(arm: Arm, n: int, rng: np.random.Generator) -> npt.NDArray[np.float64]:
    """Targets where theta1, theta2 or theta4 (the wrapped joints of the closed form) is
    +-180 deg, or within 1e-9 .. 1e-4 rad of it: level configurations inside the elbow stop
    with that joint set there (theta2 or theta4 moved with it, to keep the gripper level),
    the waist facing the target. Float32 and float64 may wrap such an angle to opposite ends
    of (-180, 180]: the same joint position, counted one revolution apart."""
    from analysis.studies.palletizer import level_configurations

    out = []
    lo, hi = arm.limits[2]
    k = 0
    while sum(len(o) for o in out) < n:
        q = level_configurations(arm, 4 * n, rng, margin_deg=5.0)
        j = np.array([0, 1, 3])[(np.arange(len(q)) + k) % 3]
        off = rng.choice([-1.0, 0.0, 1.0], len(q)) * 10.0 ** rng.uniform(-9, -4, len(q))
        rows = np.arange(len(q))
        q[rows, j] = np.pi + off
        two = j == 1
        q[two, 3] = np.pi / 2 - q[two, 1] - q[two, 2]
        four = j == 3
        q[four, 1] = np.pi / 2 - q[four, 2] - q[four, 3]
        q = (q + np.pi) % (2 * np.pi) - np.pi  # the same positions, angles in [-pi, pi)
        q[:, 2] = np.where(q[:, 2] < 0, q[:, 2] + 2 * np.pi, q[:, 2])  # theta3 unwrapped
        p = arm.fk(q)
        keep = (p[:, 0] * np.cos(q[:, 0]) + p[:, 1] * np.sin(q[:, 0]) > 1.0) & (
            (q[:, 2] > lo + 1e-3) & (q[:, 2] < hi - 1e-3)
        )
        out.append(p[keep])
        k += 1
    return np.concatenate(out)[:n]


def sweep_targets(
    arm: Arm, n_random: int = 600, seed: int = 20210401, n_half: int = 160, n_cut: int = 60
) -> pd.DataFrame:
    """Test targets for the palletizer program, labelled by kind.

    Kinds: ``initial-pose`` (sec. 3: theta3 = 90 deg, exactly on the stop), ``random``
    (wrist uniform in a ball of radius 1.1 (L1 + L2) around the shoulder, elevation within
    +-80 deg, in front of the base axis: ok, joint limits and out of reach),
    ``stop-1mm`` (wrist 1e-3 .. 1 mm inside or outside the stop sphere sqrt(L1^2 + L2^2)),
    ``outer-1mm`` (the same about L1 + L2), ``shoulder`` (wrist within 1 mm of the shoulder,
    exactly on it for one: L4 = 0, status "degenerate" when L1 = L2), ``axis`` (0 .. 1 mm from
    the base axis, 5 exactly on it: status "base axis"), ``half-pulse``
    (:func:`half_pulse_targets`), ``bad`` (NaN/inf), ``huge`` (finite, squares overflow
    float32) and ``cut`` (:func:`cut_targets`, drawn last so the other kinds do not change).

    Returns
    -------
    DataFrame
        Columns ``kind, x_mm, y_mm, z_mm``.
    """
    rng = np.random.default_rng(seed)
    P = arm.params
    L1, L2, L3, h = P["L1"], P["L2"], P["L3"], P["h"]
    outer, stop = L1 + L2, float(np.hypot(L1, L2))
    parts = [("initial-pose", np.array([[L2 + L3, 0.0, L1 - h]]))]
    d = 1.1 * outer * rng.uniform(0, 1, n_random) ** (1 / 3)
    d = np.maximum(d, 2.0)
    parts.append(
        (
            "random",
            _grasp(
                arm,
                d,
                rng.uniform(-1.4, 1.4, n_random),
                rng.uniform(-np.pi, np.pi, n_random),
            ),
        )
    )

    def shell(radius: float, n: int) -> npt.NDArray[np.float64]:
        off = rng.choice([-1.0, 1.0], n) * 10.0 ** rng.uniform(-3, 0, n)
        return _grasp(arm, radius + off, rng.uniform(-1.4, 1.4, n), rng.uniform(-np.pi, np.pi, n))

    parts.append(("stop-1mm", shell(stop, 120)))
    parts.append(("outer-1mm", shell(outer, 60)))
    near = 10.0 ** rng.uniform(-3, 0, 19)
    parts.append(
        (
            "shoulder",
            np.vstack(
                [
                    [[L3, 0.0, -h]],
                    _grasp(arm, near, rng.uniform(-1.4, 1.4, 19), rng.uniform(-3, 3, 19)),
                ]
            ),
        )
    )
    n_ax = 60
    rho = np.concatenate([[0.0] * 5, 10.0 ** rng.uniform(-3, 0, n_ax - 5)])
    phi = rng.uniform(-np.pi, np.pi, n_ax)
    z = rng.uniform(-h - 0.9 * stop, -h + 0.9 * stop, n_ax)  # wrist within the stop
    z = np.where(np.abs(z + h) < L3 + 5.0, -h + np.sign(z + h + 1e-9) * (L3 + 5.0), z)
    parts.append(("axis", np.stack([rho * np.cos(phi), rho * np.sin(phi), z], axis=1)))
    parts.append(("half-pulse", half_pulse_targets(arm, n_half, rng)))
    parts.append(("bad", np.array([[np.nan, 100, 50], [100, np.inf, 50], [100, 100, -np.inf]])))
    parts.append(("huge", np.array([[1e20, -1e20, 50.0], [3e38, 0.0, 0.0], [-1e30, 1e30, -1e30]])))
    if n_cut:
        parts.append(("cut", cut_targets(arm, n_cut, rng)))
    rows = [pd.DataFrame(p, columns=["x_mm", "y_mm", "z_mm"]).assign(kind=k) for k, p in parts]
    df = pd.concat(rows, ignore_index=True)
    return df[["kind", "x_mm", "y_mm", "z_mm"]]


def program(arm: Arm, dialect: str = "s7-200", branch: str | None = None) -> tuple[str, str]:
    """The program text and its MAP.json, exactly as ``python -m analysis stl --arm <arm>
    --dialect <dialect>`` writes them (default trigonometry of the dialect)."""
    from analysis.plc.generate import generate

    return generate(dialect, branch=branch, params=arm.params)


class PlcRun(NamedTuple):
    """One program executed on awlsim over a target set, and its comparison with Python."""

    comparison: Comparison
    result: RunResult
    targets: pd.DataFrame
    stopped: bool
    """True if a REAL compare saw a NaN (an S7-200 CPU would stop)."""

    def status_table(self) -> pd.DataFrame:
        """Targets per kind and PLC status code (rows: kind; columns: status)."""
        t = self.targets.assign(status=self.result.status)
        return pd.crosstab(t["kind"], t["status"])


def run(
    arm: Arm,
    dialect: str = "s7-200",
    targets: pd.DataFrame | None = None,
    branch: str | None = None,
    text: tuple[str, str] | None = None,
) -> PlcRun:
    """Execute the arm's program on awlsim (S7-200 STL through the project's translation to
    AWL; S7-300 AWL as is) over ``targets`` (default :func:`sweep_targets`) and compare.

    ``text`` may pass ``(program text, MAP.json text)`` as written by the command line;
    by default :func:`program` generates them.
    """
    from analysis.plc.translate import translate_s7200

    branch = branch or arm.branches[0]
    targets = sweep_targets(arm) if targets is None else targets
    src, map_text = text if text is not None else program(arm, dialect, branch)
    mmap = MemoryMap.from_dict(json.loads(map_text))
    awl = translate_s7200(src).awl if dialect == "s7-200" else src
    xyz = targets[["x_mm", "y_mm", "z_mm"]].to_numpy(dtype=float)
    done = sweep(awl, mmap, xyz, sentinel=SENTINEL)
    trig = "subroutine" if "ATAN2/ACOS: generated subroutines" in src else "native"
    cmp = compare(done.result, targets, arm, branch, dialect, SENTINEL, trig)
    return PlcRun(cmp, done.result, targets, done.stopped)


def real_errors(arm: Arm, targets: pd.DataFrame, dialect: str = "s7-200") -> pd.DataFrame:
    """Largest |float32 value handed to ROUND - exact pulse value| [pulses] per target kind
    and joint, modulo one revolution (at the wrap cut the two may be a turn apart), over the
    targets both Python and the program solve (the float32 model of the program,
    :func:`analysis.plc.model.predict`, which reproduces awlsim bit for bit)."""
    from analysis.plc.approx import PlcFloat32Ops
    from analysis.plc.model import predict
    from analysis.plc.verify import reference_pulses

    xyz = targets[["x_mm", "y_mm", "z_mm"]].to_numpy(dtype=float)
    rounding = "half-away" if dialect == "s7-200" else "half-even"
    _, ok, _, exact = reference_pulses(arm, xyz, arm.branches[0], rounding)
    model = predict(arm.params, xyz, arm.branches[0], ops=PlcFloat32Ops(dialect))
    both = ok & model.reachable
    ppr = np.asarray(arm.params.pulses_per_rev, dtype=float)
    diff = model.counts.astype(float) - exact
    err = np.abs(diff - ppr * np.round(diff / ppr))  # modulo one revolution (the wrap cut)
    cols = [f"c{j + 1}" for j in range(err.shape[1])]
    df = pd.DataFrame(err[both], columns=cols).assign(kind=targets["kind"].to_numpy()[both])
    return df.groupby("kind").max()

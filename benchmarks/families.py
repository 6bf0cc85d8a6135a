"""``make bench``: the families engineers own, derived from D-H tables (analysis.kinematics.
derive): the six-axis kernels against EAIK and IK-Geo, and every family against its oracles.

- ``sixaxis``: the PUMA 560 (family 6R-wrist) and the UR5 (6R-parallel), all eight branches,
  on the same seeded poses: the compiled kernel (``Arm.solve(backend="compiled")``: generated
  from the derived closed form, Numba, the machine's threads), its numpy evaluation, EAIK's
  batched IK (C++, ``IK_batched`` on as many worker threads) and IK-Geo (the Rust ``ik-geo``
  wheel, one ``get_ik`` call per pose: it has no batch call; on the first 5,000 of the
  poses, the others on all 200,000); poses per second of wall time,
  interleaved rounds, the median kept. The kernel's first call compiles it (about 10 s of
  CPU for an eight-branch kernel; then read from the disk cache): reported apart.
- ``agreement``: solution sets compared as today's bench does (equal sets, the oracle empty
  or a subset, disagreements: must be 0), per family and D-H convention: EAIK on random arms
  of every revolute family (analysis.kinematics.derive.samples_more) and on the published
  arms, IK-Geo on the PUMA 560, the UR5 and random arms of both six-axis families (an
  oracle's candidates count where they reach the pose: EAIK's by its FK, IK-Geo's by the
  rows'; each run of parallel axes is given to both pointing one way, which their
  three-parallel solvers assume: analysis.kinematics.derive.oracle), pyplcopen's kinematics
  on the arms it models
  (analysis.kinematics.derive.plcopen_oracle), pyplcopen's SerialChain FK on the
  published six-axis arms, and Pinocchio's FK of every published family arm's D-H rows.
"""

from __future__ import annotations

import os
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

from analysis.kinematics import compiled
from analysis.kinematics.arm import load_arm
from analysis.kinematics.derive import plcopen_oracle as po
from analysis.kinematics.derive.chain import home
from analysis.kinematics.derive.oracle import (
    POSE_TOL,
    axis_senses,
    compare_solution_sets,
    eaik_robot,
)
from analysis.kinematics.derive.oracle import (
    available as eaik_available,
)
from analysis.kinematics.derive.positioning import meet
from analysis.kinematics.derive.samples_more import random_family_arm
from analysis.kinematics.ops import numpy_ops
from analysis.kinematics.rpy import pose_from_transform

SIX = {"puma560": "6R-wrist", "ur5": "6R-parallel"}
"""The published six-axis arms and their families."""
IKGEO = {"6R-wrist": "spherical_two_parallel", "6R-parallel": "three_parallel_two_intersecting"}
"""IK-Geo's decomposition of each six-axis family."""
REVOLUTE = ("2R-planar", "3R-planar", "6R-wrist", "6R-parallel")


def ikgeo_robot(arm):
    """IK-Geo's model of ``arm`` (a POE: the axes at q = 0, each parallel set pointing one
    way (:func:`~analysis.kinematics.derive.oracle.axis_senses`: its three-parallel solver
    assumes it, as EAIK's does), and the offsets between points on them, the points where
    the wrist axes meet taken as IK-Geo's decompositions require), the tool's rotation at
    q = 0 and the axes' senses; or None without the wheel."""
    try:
        from ik_geo import Robot
    except ImportError:
        return None
    h = home(numpy_ops, arm.table)
    senses = axis_senses(h.axes)
    H = np.array(h.axes) * senses[:, None]
    pts = [np.array([float(c) for c in p]) for p in h.points]
    if arm.closed_form.family == "6R-wrist":
        w = np.array([float(c) for c in meet(h.points[3], H[3], h.points[4], H[4])])
        pts[3] = pts[4] = pts[5] = w
    else:
        c = np.array([float(c) for c in meet(h.points[4], H[4], h.points[5], H[5])])
        pts[4] = pts[5] = c
    tool = np.array([float(c) for c in h.position])
    P = [pts[0], *(pts[i + 1] - pts[i] for i in range(5)), tool - pts[5]]
    decomposition = getattr(Robot, IKGEO[arm.closed_form.family])
    return decomposition(H.tolist(), np.array(P).tolist()), h.rotation, senses


def _ikgeo_solve(robot, R0, senses, T):
    """IK-Geo's exact solutions of poses ``T`` (its rotation the transpose of ours, the
    tool's rotation at q = 0 taken off) as the arm's joint values (times ``senses``)."""
    return [[np.asarray(s[0]) * senses for s in robot.get_ik((t[:3, :3] @ R0.T).T, t[:3, 3])
             if not s[1]] for t in T]  # fmt: skip


def sixaxis(n: int = 200_000, n_peer: int = 20_000, rounds: int = 5, seed: int = 32) -> dict:
    """Rates [poses/s] and their ratios on the published six-axis arms (module docstring):
    the compiled kernel, numpy and EAIK on the same ``n`` poses, IK-Geo (a Python loop of
    one call per pose) on the first ``n_peer // 4``; the load average is recorded with them
    (the machine is shared)."""
    out = {}
    threads = compiled.threads()
    for name in SIX:
        arm = load_arm(name)
        rng = np.random.default_rng(seed)
        q = rng.uniform(-np.pi, np.pi, (n, 6))
        T = arm.table.fk(q)
        p = pose_from_transform(T)
        t0 = time.perf_counter()
        arm.solve(p[:10], limits=False, backend="compiled")
        first = time.perf_counter() - t0
        c = arm.solve(p[:n_peer], limits=False, backend="compiled")
        r = arm.solve(p[:n_peer], limits=False)
        same = {"statuses_equal": bool((c.status == r.status).all() and (c.ok == r.ok).all()),
                "max_angle_diff_rad": float(np.nanmax(np.abs(c.theta - r.theta)))}  # fmt: skip
        cases = {  # each case binds this arm's objects (default arguments)
            "compiled": (n, lambda a=arm, p=p: a.solve(p, limits=False, backend="compiled")),
            "numpy": (n, lambda a=arm, p=p: a.solve(p, limits=False)),
        }
        if eaik_available():
            poses = [T[i] for i in range(n)]
            robot = eaik_robot(arm)
            cases["eaik"] = (n, lambda r=robot, x=poses: r.IK_batched(x, threads))
        geo = ikgeo_robot(arm)
        if geo is not None:
            m = n_peer // 4
            cases["ikgeo"] = (m, lambda g=geo, x=T[:m]: _ikgeo_solve(*g, x))
        times = {k: [] for k in cases}
        load = os.getloadavg()[0]
        for _ in range(rounds):
            for k, (_, fn) in cases.items():
                t0 = time.perf_counter()
                fn()
                times[k].append(time.perf_counter() - t0)
        rate = {k: cases[k][0] / statistics.median(v) for k, v in times.items()}
        out[name] = {
            "family": arm.closed_form.family,
            "branches": len(arm.branches),
            "rates_poses_per_s": rate,
            "compiled / eaik": rate["compiled"] / rate["eaik"] if "eaik" in rate else None,
            "compiled / ikgeo": rate["compiled"] / rate["ikgeo"] if "ikgeo" in rate else None,
            "compiled / numpy": rate["compiled"] / rate["numpy"],
            "first_compiled_call_s": first,
            "compiled = numpy": same,
            "threads": threads,
            "load_average_1min": (load, os.getloadavg()[0]),
        }
    return out


def _tally(rows: dict, key: str, a) -> None:
    zero = dict.fromkeys(("arms", "configurations", "equal", "oracle_empty", "oracle_subset",
                          "disagree", "solutions"), 0)  # fmt: skip
    row = rows.setdefault(key, {"family": a.family, **zero, "max_fk_ik_residual_mm": 0.0})
    row["arms"] += 1
    row["configurations"] += a.n
    row["equal"] += a.equal
    row["oracle_empty"] += a.eaik_empty
    row["oracle_subset"] += a.eaik_subset
    row["disagree"] += a.disagree
    row["solutions"] += a.solutions
    row["max_fk_ik_residual_mm"] = max(row["max_fk_ik_residual_mm"], a.max_residual_mm)


def _ikgeo_one(rows: dict, key: str, arm, n_q: int, rng) -> bool:
    from analysis.kinematics.derive.oracle import Agreement, _unique, _verdict

    geo = ikgeo_robot(arm)
    if geo is None:
        return False
    q = rng.uniform(-np.pi, np.pi, (n_q, 6))
    T = arm.table.fk(q)
    sol = arm.solve(pose_from_transform(T), limits=False)
    theirs = _ikgeo_solve(*geo, T)
    scale = np.ones((4, 4))
    scale[:3, 3] = 1e-3  # mm -> m: one tolerance for rotation and position (as EAIK's)
    tally = dict.fromkeys(("equal", "empty", "subset", "disagree"), 0)
    for i in range(n_q):
        ours = [sol.theta[i, b] for b in range(8) if sol.ok[i, b]]
        # IK-Geo's candidates that reach the pose (the rows' FK): where its decomposition's
        # assumptions do not hold it returns numbers that miss it by centimetres
        exact = [s for s in theirs[i]
                 if (np.abs(arm.table.fk(s) - T[i]) * scale).max() < POSE_TOL]  # fmt: skip
        tally[_verdict(_unique(ours), _unique(exact))] += 1
    reached = np.where(sol.ok[..., None], arm.table.fk(np.nan_to_num(sol.theta))[..., :3, 3],
                       np.nan)  # fmt: skip
    res = float(np.nanmax(np.linalg.norm(reached - T[:, None, :3, 3], axis=-1)))
    _tally(rows, key, Agreement(arm.closed_form.family, n_q, tally["equal"], tally["empty"],
           tally["subset"], tally["disagree"], int(sol.ok.sum()), 0, res))  # fmt: skip
    return True


def _ikgeo_agreement(rows: dict, folder: Path, n_arms: int, n_q: int, rng) -> None:
    """IK-Geo on the published six-axis arms and on random arms of both six-axis families
    (standard and modified D-H): the second oracle where EAIK answers nothing exact."""
    for name in SIX:
        if not _ikgeo_one(rows, f"IK-Geo {name}", load_arm(name), 10 * n_q, rng):
            rows["IK-Geo"] = {"skipped": "ik-geo is not installed (requirements-bench.lock)"}
            return
    for fam in IKGEO:
        for conv in ("standard", "modified"):
            for k in range(n_arms):
                path = folder / f"g{fam[3]}{conv[0]}{k}.toml"
                path.write_text(random_family_arm(rng, fam, conv, path.stem), encoding="utf-8")
                _ikgeo_one(rows, f"IK-Geo {fam} {conv}", load_arm(str(path)), n_q, rng)


def _plcopen_agreement(rows: dict, folder: Path, n_q: int, rng) -> None:
    if not po.available():
        rows["pyplcopen"] = {"skipped": "the driver is not built (make st-engine)"}
        return
    for k in range(5):
        l1, l2 = (float(v) for v in rng.uniform(150.0, 400.0, 2))
        path = folder / f"scara{k}.toml"
        path.write_text(po.scara_text(l1, l2), encoding="utf-8")
        arm = load_arm(str(path))
        q = rng.uniform([-3.0, -3.0, -200.0], [3.0, 3.0, 200.0], (n_q, 3))
        _tally(rows, "pyplcopen Scara", po.compare_seeded(arm, f"scara {l1!r} {l2!r} 1",
                                                          arm.target(q), rng))  # fmt: skip
        offset = rng.uniform(-300.0, 300.0, 3)
        path = folder / f"gantry{k}.toml"
        path.write_text(po.gantry_text(offset), encoding="utf-8")
        arm = load_arm(str(path))
        q = rng.uniform(-500.0, 500.0, (n_q, 3))
        _tally(rows, "pyplcopen CartesianGantry", po.compare_seeded(
            arm, f"gantry 3 1 1 1 {po._fmt(offset)}", arm.target(q), rng))  # fmt: skip
        dims = [float(v) for v in rng.uniform(100.0, 500.0, 4)]
        path = folder / f"wrist{k}.toml"
        path.write_text(po.wrist6r_text(*dims), encoding="utf-8")
        arm = load_arm(str(path))
        q = rng.uniform(-3.0, 3.0, (n_q, 6))
        _tally(rows, "pyplcopen SphericalWrist6R", po.compare_seeded(
            arm, "wrist6r " + " ".join(repr(d) for d in dims), arm.target(q), rng))  # fmt: skip
    for name in SIX:
        arm = load_arm(name)
        q = rng.uniform(-np.pi, np.pi, (10_000, 6))
        rows[f"pyplcopen SerialChain FK {name}"] = {
            "configurations": len(q),
            "max_abs_diff": float(np.abs(po.fk_chain(arm.table, q) - arm.table.fk(q)).max()),
        }


def _pinocchio_fk(rows: dict, n_q: int, rng) -> None:
    """FK of every published family arm against Pinocchio's model of its D-H rows
    (analysis.kinematics.pinocchio_model: one placement per configuration)."""
    from analysis.kinematics.pinocchio_model import PinocchioArm

    for name in ("planar2r", "cobra600", "puma560", "ur5", "gantry"):
        arm = load_arm(name)
        q = rng.uniform(arm.bounds[:, 0], arm.bounds[:, 1], (n_q, arm.n_joints))
        pin = PinocchioArm(arm.table)
        P = np.stack([pin.placement(x) for x in q])
        T = arm.table.fk(q)
        rows[f"Pinocchio FK {name}"] = {
            "family": arm.closed_form.family,
            "configurations": n_q,
            "max_position_diff_mm": float(np.abs(P[:, :3, 3] - T[:, :3, 3]).max()),
            "max_rotation_diff": float(np.abs(P[:, :3, :3] - T[:, :3, :3]).max()),
        }


def agreement(n_arms: int = 10, n_q: int = 30, seed: int = 2032) -> dict:
    """Solution sets against EAIK, IK-Geo and pyplcopen (module docstring)."""
    rows: dict = {}
    rng = np.random.default_rng(seed)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        if eaik_available():
            for fam in REVOLUTE:
                for conv in ("standard", "modified"):
                    for k in range(n_arms):
                        path = folder / f"a{fam[0]}{conv[0]}{k}.toml"
                        path.write_text(random_family_arm(rng, fam, conv, path.stem),
                                        encoding="utf-8")  # fmt: skip
                        arm = load_arm(str(path))
                        q = rng.uniform(arm.bounds[:, 0], arm.bounds[:, 1], (n_q, arm.n_joints))
                        _tally(rows, f"EAIK {fam} {conv}", compare_solution_sets(arm, q))
            for name in (*SIX, "planar2r"):
                arm = load_arm(name)
                q = rng.uniform(-np.pi, np.pi, (10 * n_q, arm.n_joints))
                _tally(rows, f"EAIK {name}", compare_solution_sets(arm, q))
        else:
            rows["EAIK"] = {"skipped": "EAIK is not installed (requirements-bench.lock)"}
        _ikgeo_agreement(rows, folder, n_arms, n_q, rng)
        _plcopen_agreement(rows, folder, n_q, rng)
    _pinocchio_fk(rows, 10_000, rng)
    return rows

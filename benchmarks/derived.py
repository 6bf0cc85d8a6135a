"""``make bench``: the closed forms derived from D-H tables (analysis.kinematics.derive).

- ``eaik_agreement``: EAIK's solution sets against the derived ones (analysis.kinematics.
  derive.oracle) on the seed arms and on random arms of each family and D-H convention
  (analysis.kinematics.derive.samples), counted per family: configurations whose sets are
  equal, where EAIK returns no exact solution or only some of the derived ones (the derived
  ones still reach the pose: the largest FK(IK) residual is reported), and disagreements
  (EAIK has a solution the derived closed form lacks: must be 0). Without EAIK (the
  bench extra) the section says so.
- ``derived_kernels``: the compiled kernel generated from each seed arm's derived closed form
  against its numpy evaluation (largest angle difference, statuses) and against the
  hand-written closed form's kernel (rate ratio, same targets, same process).
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

from analysis.kinematics.arm import derived_arm, load_arm
from analysis.kinematics.derive.oracle import available, compare_solution_sets
from analysis.kinematics.derive.samples import random_arm
from analysis.kinematics.rpy import pose_from_transform

FAMILIES = ("3R", "4R-kept", "5R")


def _kept(arm, q):
    st = arm.closed_form.structure
    if st.family == "4R-kept":
        s, psi = st.sigma, st.keep[0]
        q[:, 3] = np.angle(np.exp(1j * s[2] * (psi - s[0] * q[:, 1] - s[1] * q[:, 2])))
    return q


def eaik_agreement(n_arms: int = 20, n_q: int = 50, seed: int = 2026) -> dict:
    """Per family and convention: arms, configurations, equal sets, EAIK empty, disagreements,
    derived solutions compared, EAIK solutions flagged least-squares although exact, the
    largest FK(IK) residual [mm]; the seed arms apart."""
    if not available():
        return {"skipped": "EAIK is not installed (requirements-bench.lock)"}
    out: dict = {}
    rng = np.random.default_rng(seed)
    with tempfile.TemporaryDirectory() as folder:
        cases = [(name, derived_arm(name)) for name in ("grabber", "palletizer", "gr1")]
        for fam in FAMILIES:
            for conv in ("standard", "modified"):
                for k in range(n_arms):
                    path = Path(folder) / f"a{fam[0]}{conv[0]}{k}.toml"  # an identifier
                    path.write_text(random_arm(rng, fam, conv, path.stem), encoding="utf-8")
                    cases.append((f"{fam} {conv}", load_arm(str(path))))
        for key, arm in cases:
            q = _kept(arm, rng.uniform(-np.pi, np.pi, (n_q, arm.n_joints)))
            a = compare_solution_sets(arm, q, seed=len(out))
            row = out.setdefault(key, {"family": a.family, "arms": 0, "arms_all_equal": 0,
                                       "configurations": 0, "equal": 0, "eaik_empty": 0,
                                       "eaik_subset": 0, "disagree": 0, "solutions": 0,
                                       "eaik_flagged_ls": 0,
                                       "max_fk_ik_residual_mm": 0.0})  # fmt: skip
            row["arms"] += 1
            row["arms_all_equal"] += a.all_equal
            row["configurations"] += a.n
            row["equal"] += a.equal
            row["eaik_empty"] += a.eaik_empty
            row["eaik_subset"] += a.eaik_subset
            row["disagree"] += a.disagree
            row["solutions"] += a.solutions
            row["eaik_flagged_ls"] += a.flagged_ls
            row["max_fk_ik_residual_mm"] = max(row["max_fk_ik_residual_mm"], a.max_residual_mm)
    return out


def derived_kernels(n: int = 200_000, rounds: int = 3) -> dict:
    """The derived closed forms' compiled kernels: equal to numpy, and their rate against
    the hand-written kernel of the same arm (interleaved rounds, median)."""
    out = {}
    rng = np.random.default_rng(7)
    for name in ("grabber", "palletizer", "gr1"):
        hand, der = load_arm(name), derived_arm(name)
        q = _kept(der, rng.uniform(-np.pi, np.pi, (n, hand.n_joints)))
        T = hand.table.fk(q)
        p = T[:, :3, 3] if len(hand.inputs) == 3 else pose_from_transform(T)
        t0 = time.perf_counter()
        c = der.solve(p[:10], backend="compiled")  # compiles (or reads the disk cache)
        first = time.perf_counter() - t0
        hand.solve(p[:10], backend="compiled")
        c, r = der.solve(p, backend="compiled"), der.solve(p)
        times: dict[str, list[float]] = {"derived": [], "hand": []}
        for _ in range(rounds):
            for key, arm in (("derived", der), ("hand", hand)):
                t0 = time.perf_counter()
                arm.solve(p, backend="compiled")
                times[key].append(time.perf_counter() - t0)
        med = {k: statistics.median(v) for k, v in times.items()}
        out[name] = {
            "family": der.closed_form.family,
            "statuses_equal": bool((c.status == r.status).all()),
            "max_angle_diff_rad": float(np.nanmax(np.abs(c.theta - r.theta))),
            "first_call_s": first,
            "derived / hand-written (rate)": med["hand"] / med["derived"],
        }
    return out

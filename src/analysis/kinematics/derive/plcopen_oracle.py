"""pyplcopen's own kinematics as the oracle of the SCARA, gantry and spherical-wrist closed
forms, and of the FK of any revolute D-H chain.

pyplcopen (the sdist whose ST engine :mod:`analysis.plc.st_engine` runs) carries analytic
kinematics of its own in ``core/kin``: ``Scara`` (a planar 2R arm and a Z slide),
``CartesianGantry`` (a slide per coordinate), ``SphericalWrist6R`` (waist, shoulder and
elbow about horizontal axes, a ZYZ wrist: eight branches, the one nearest a seed returned)
and ``SerialChain`` (FK of a standard or modified D-H table, IK by damped least squares).
``make st-engine`` builds ``tools/st-engine/kin_oracle.cpp`` against them into the venv
(``analysis-kin-oracle``; tests skip, saying why, without it).

Each of :func:`scara_text`, :func:`gantry_text`, :func:`wrist6r_text` writes the description
(``data/arms`` format, no ``closed_form``: the closed form is derived) of the arm pyplcopen's
mechanism models, with the same joint variables; :func:`compare_seeded` then holds the
derived solutions against pyplcopen's, target by target: every derived branch is given to
pyplcopen as the seed (its inverse returns the solution on the seed's branch, within a small
joint step), and pyplcopen is also seeded at random configurations (it returns the nearest
branch's solution, any step), so a solution pyplcopen finds that the derivation lacks shows
as a disagreement. Counted as :class:`analysis.kinematics.derive.oracle.Agreement` is:
equal solution sets, targets where pyplcopen finds none of a branch the derivation reaches
(``eaik_empty``: the field's name is EAIK's, the meaning "the oracle is empty"), targets
where it finds some (``eaik_subset``), and disagreements.
"""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np

__all__ = ["available", "compare_seeded", "driver", "fk_chain", "gantry_text", "run",
           "scara_text", "wrist6r_text"]  # fmt: skip

ANGLE_TOL = 1e-6
"""Largest joint difference [rad | mm] of two solutions counted as the same."""
MAX_REQUESTS = 200_000


def driver() -> Path:
    """The built driver (``make st-engine``), next to the interpreter."""
    return Path(sys.executable).parent / "analysis-kin-oracle"


def available() -> bool:
    return driver().is_file()


def run(mechanism: str, requests: list[str]) -> list[list[float] | None]:
    """Answers of the driver to ``requests`` on ``mechanism`` (module docstring): the numbers
    of each ``ok`` line, None for ``err``."""
    if len(requests) > MAX_REQUESTS:
        raise ValueError(f"{len(requests)} requests: at most {MAX_REQUESTS}")
    text = mechanism + "\n" + "\n".join(requests) + "\n"
    done = subprocess.run([str(driver())], input=text, capture_output=True, text=True,
                          timeout=600, check=False)  # fmt: skip
    if done.returncode != 0:
        raise RuntimeError(f"kin_oracle failed ({done.returncode}): {done.stderr.strip()[:200]}")
    out = []
    for line in done.stdout.splitlines():
        head, *rest = line.split()
        if head == "bad":
            raise RuntimeError(f"kin_oracle refused a request: {line}")
        out.append([float(v) for v in rest] if head == "ok" else None)
    if len(out) != len(requests):
        raise RuntimeError(f"kin_oracle answered {len(out)} of {len(requests)} requests")
    return out


def _fmt(v) -> str:
    return " ".join(repr(float(x)) for x in v)


def _toml(name: str, rows: list[tuple], joints: list[tuple], convention: str) -> str:
    out = [f'name = "{name}"', f'title = "pyplcopen {name}"', 'paper = "none: an oracle"',
           f'convention = "{convention}"']  # fmt: skip
    for joint, kind, alpha, a, d, off in rows:
        out += ["", "[[rows]]", f'joint = "{joint}"', f'kind = "{kind}"',
                f"alpha_deg = {float(alpha)!r}", f"a = {float(a)!r}", f"d = {float(d)!r}",
                f"theta_offset_deg = {float(off)!r}"]  # fmt: skip
    for name_, kind, lim in joints:
        out += ["", "[[joints]]", f'name = "{name_}"', "pulses_per_rev = 4000"]
        if kind == "prismatic":
            out += ['kind = "prismatic"', "lead_mm = 10.0", f"limits_mm = [{lim[0]!r}, {lim[1]!r}]"]
    return "\n".join(out) + "\n"


def scara_text(l1: float, l2: float) -> str:
    """pyplcopen's ``Scara(l1, l2, with_z=True)``: ``x = l1 c1 + l2 c12``, ``z = q3``."""
    rows = [("q1", "revolute", 0.0, l1, 0.0, 0.0), ("q2", "revolute", 0.0, l2, 0.0, 0.0),
            ("q3", "prismatic", 0.0, 0.0, 0.0, 0.0)]  # fmt: skip
    return _toml("scara", rows, [("q1", "revolute", None), ("q2", "revolute", None),
                                 ("q3", "prismatic", (-1e4, 1e4))], "standard")  # fmt: skip


def gantry_text(offset) -> str:
    """pyplcopen's ``CartesianGantry(3, scale=(1, 1, 1), offset)``: coordinate ``k`` =
    ``q_k + offset_k``; as a modified D-H table (a base row turning x onto y, then slides
    along x, y and z, each row's ``d`` its offset)."""
    o = [float(v) for v in offset]
    rows = [("base", "fixed", 0.0, 0.0, 0.0, 90.0), ("q1", "prismatic", 90.0, 0.0, o[0], 90.0),
            ("q2", "prismatic", 90.0, 0.0, o[1], 90.0), ("q3", "prismatic", 90.0, 0.0, o[2], 0.0)]
    return _toml("gantry", rows, [(f"q{i}", "prismatic", (-1e4, 1e4)) for i in (1, 2, 3)],
                 "modified")  # fmt: skip


def wrist6r_text(d1: float, a2: float, d4: float, d6: float) -> str:
    """pyplcopen's ``SphericalWrist6R(d1, a2, d4, d6)``: ``R = Rz(q1) Ry(q2 + q3) Rz(q4)
    Ry(q5) Rz(q6)``, the wrist centre ``(c1 r, s1 r, d1 + z)`` with ``r = a2 s2 + d4 s23``,
    ``z = a2 c2 + d4 c23`` (angles from the vertical), the tool ``d6`` along its z axis; as a
    modified D-H table with the same joint variables (derivation: tests/kinematics/
    test_families_oracles.py holds the two FKs equal)."""
    rows = [("q1", "revolute", 0.0, 0.0, d1, 0.0), ("q2", "revolute", -90.0, 0.0, 0.0, -90.0),
            ("q3", "revolute", 0.0, a2, 0.0, 90.0), ("q4", "revolute", 90.0, 0.0, d4, 0.0),
            ("q5", "revolute", -90.0, 0.0, 0.0, 0.0), ("q6", "revolute", 90.0, 0.0, 0.0, 0.0),
            ("tool", "fixed", 0.0, 0.0, d6, 0.0)]  # fmt: skip
    return _toml("wrist6r", rows, [(f"q{i}", "revolute", None) for i in range(1, 7)], "modified")


def fk_chain(table, q: np.ndarray) -> np.ndarray:
    """pyplcopen's ``SerialChain`` FK (4, 4) [mm] of a D-H table of revolute rows only (no
    fixed or prismatic row: what ``SerialChain`` models) at joint values ``q`` (N, n)."""
    rows = table.rows
    if any(r.kind != "revolute" for r in rows):
        raise ValueError("SerialChain models revolute rows only")
    conv = "std" if table.convention == "standard" else "mod"
    spec = " ".join(_fmt((r.a, r.alpha, r.d, r.theta_offset)) for r in rows)
    answers = run(f"chain {conv} {len(rows)} {spec}", [f"fk {_fmt(x)}" for x in q])
    T = np.zeros((len(q), 4, 4))
    for i, a in enumerate(answers):
        T[i, :3, 3] = a[:3]
        T[i, :3, :3] = np.reshape(a[3:], (3, 3))
        T[i, 3, 3] = 1.0
    return T


def _same(a, b, revolute) -> bool:
    d = np.asarray(a, float) - np.asarray(b, float)
    d = np.where(revolute, np.angle(np.exp(1j * d)), d)
    return bool(np.abs(d).max() < ANGLE_TOL)


def compare_seeded(arm, mechanism: str, targets: np.ndarray, rng, random_seeds: int = 4):
    """The derived solutions of ``targets`` (the arm's inputs, (N, k)) against pyplcopen's
    ``mechanism`` (its first line), seeded as the module docstring says: an
    :class:`~analysis.kinematics.derive.oracle.Agreement`."""
    from analysis.kinematics.derive.oracle import Agreement

    sol = arm.solve(targets, limits=False)
    revolute = np.array([u == "rad" for u in arm.joint_units])
    pose = len(arm.inputs) == 6
    T = arm.table.fk(np.nan_to_num(sol.theta[:, 0])) if pose else None
    if pose:
        from analysis.kinematics.rpy import transform_from_pose

        T = transform_from_pose(targets)
    reqs, owner = [], []
    for i in range(len(targets)):
        if pose:
            head = _fmt(T[i, :3, 3]) + " " + _fmt(T[i, :3, :3].ravel())
        else:
            head = _fmt(targets[i, :3])
        ours = [sol.theta[i, b] for b in range(len(arm.branches)) if sol.ok[i, b]]
        seeds = [(s, 1e-3) for s in ours]
        seeds += [(rng.uniform(-math.pi, math.pi, arm.n_joints), 10.0) for _ in range(random_seeds)]
        for s, step in seeds:
            reqs.append(f"ik {head} {_fmt(s)}" + (f" {step!r}" if pose else ""))
            owner.append(i)
    answers = run(mechanism, reqs)
    tally = dict.fromkeys(("equal", "empty", "subset", "disagree"), 0)
    first = ""
    for i in range(len(targets)):
        ours = [sol.theta[i, b] for b in range(len(arm.branches)) if sol.ok[i, b]]
        got = [np.asarray(a) for a, o in zip(answers, owner, strict=True) if o == i and a]
        theirs = []
        for g in got:
            if not any(_same(g, t, revolute) for t in theirs):
                theirs.append(g)
        extra = [t for t in theirs if not any(_same(t, o, revolute) for o in ours)]
        found = sum(any(_same(o, t, revolute) for t in theirs) for o in ours)
        if extra:
            tally["disagree"] += 1
            first = first or f"target {np.round(targets[i], 6).tolist()}: {extra[0].tolist()}"
        elif not theirs and ours:
            tally["empty"] += 1
        elif found < len(ours):
            tally["subset"] += 1
        else:
            tally["equal"] += 1
    ok = sol.ok
    reached = arm.target(np.nan_to_num(sol.theta[ok]))[:, : min(3, targets.shape[1])]
    want = targets[np.nonzero(ok)[0], : reached.shape[1]]
    res = float(np.abs(reached - want).max()) if ok.any() else 0.0
    return Agreement(arm.closed_form.family, len(targets), tally["equal"], tally["empty"],
                     tally["subset"], tally["disagree"], int(ok.sum()), 0, res, first)  # fmt: skip

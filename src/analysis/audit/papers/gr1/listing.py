"""The GR-1 thesis's VB6 listing run on known configurations (seed 004): the truth the
listing's variables should hold, Table 5-3 typed into the form, and Table 5-4 after each
repair of the listing's defects in turn (:func:`table5_4_cascade`).

The truth is a configuration ``q`` [deg] of a chain of the GR-1's form and the pose its D-H
product gives (:func:`truth`); :func:`listing_env` presets the listing's variables as the
listing holds them (positions in mm, RPY and joint angles in degrees, ``PI = 3.141593``).
The errata register (``data/registers/gr1.toml``) checks the listing's statements with the
``vb6`` kind on these; notebook 10 shows the cascade.
"""

from __future__ import annotations

import itertools
import math
import re
from functools import cache

import numpy as np

from analysis.audit import vb6
from analysis.audit.kinds.table import cell_matches
from analysis.audit.papers.gr1 import thesis as st
from analysis.audit.papers.gr1.thesis import gr1_arm
from analysis.kinematics.arm import Arm
from analysis.kinematics.rpy import matrix_from_rpy, rpy_from_matrix
from analysis.papers import gr1_thesis as paper
from analysis.papers import load
from analysis.validate import wrap_rad

__all__ = [
    "LISTING_REPAIRS", "PI_LISTING", "PRINCIPAL", "REPAIRS", "approach_theta234", "atan2_statement",
    "atn_parts", "cells_matching", "equation_holds", "listing", "listing_env", "listing_statement",
    "numbers", "printed_cells", "printed_run", "radians_in_trig", "repaired_listing",
    "run_command1", "table5_3_inputs", "table5_4_cascade", "truth",
]  # fmt: skip

PI_LISTING = 3.141593
"""The listing's ``PI = 3.141593``."""
PRINCIPAL = (40.0, 30.0, 60.0, -50.0, 20.0)
"""A configuration [deg] where every single-argument arctangent of the thesis is right: only
the defect under test shows."""


def truth(q_deg, arm: Arm | None = None) -> dict[str, float]:
    """The pose and angles of configuration ``q_deg`` (5,) [deg]: ``px py pz`` [mm],
    ``alpha beta gamma`` [deg] (RPY, eq. 3.18), ``theta1`` .. ``theta5``, ``theta234``
    (wrapped to (-180, 180]) [deg], ``c3`` and the columns ``n_x`` .. ``a_z`` (eq. 3.16)."""
    arm = arm or gr1_arm()
    q = np.radians(np.asarray(q_deg, dtype=float))
    T = arm.table.fk(q)
    rpy = np.degrees(rpy_from_matrix(T[:3, :3]))
    out = {"px": T[0, 3], "py": T[1, 3], "pz": T[2, 3], "alpha": rpy[0], "beta": rpy[1],
           "gamma": rpy[2], "c3": math.cos(q[2]),
           "theta234": math.degrees(wrap_rad(float(q[1] + q[2] + q[3])))}  # fmt: skip
    out.update({f"theta{j + 1}": float(q_deg[j]) for j in range(5)})
    for k, col in enumerate("noa"):
        for i, ax in enumerate("xyz"):
            out[f"{col}_{ax}"] = T[i, k]
    return {k: float(v) for k, v in out.items()}


def listing_env(q_start_deg, q_end_deg=None, arm: Arm | None = None) -> dict[str, float]:
    """The listing's variables for a start (and end) configuration, as it holds them:
    ``a2 a3 a4 PI``, ``Px0 Py0 Pz0`` [mm], ``α0 β0 γ0`` [deg], ``θ1 .. θ5 θ234`` [deg],
    ``c3``; ``Px1 .. γ1, θf1 .. θf234, cf3`` for the end (default: the start)."""
    arm = arm or gr1_arm()
    P = arm.params
    env = {"a2": P["a2"], "a3": P["a3"], "a4": P["a4"], "PI": PI_LISTING}
    for q, k, f in ((q_start_deg, "0", ""), (q_end_deg or q_start_deg, "1", "f")):
        t = truth(q, arm)
        env.update({f"Px{k}": t["px"], f"Py{k}": t["py"], f"Pz{k}": t["pz"]})
        env.update({f"α{k}": t["alpha"], f"β{k}": t["beta"], f"γ{k}": t["gamma"]})
        env.update({f"θ{f}{j}": t[f"theta{j}"] for j in (1, 2, 3, 4, 5)})
        env.update({f"θ{f}234": t["theta234"], "cf3" if f else "c3": t["c3"]})
    return env


LISTING_REPAIRS: list[dict[str, str]] = [
    {
        "location": "appendix 程序清单 p. 37, Command1_Click, the cf3 statement",
        "printed": "Py1 * Sin(θf1) Cos(θf234) * a4",
        "repaired": "Py1 * Sin(θf1) - Cos(θf234) * a4",
        "why": (
            "as printed the statement is a VB6 syntax error (two operands with no operator), "
            "so the form would not compile; the same statement for the start pose (c3) has "
            "'- Cos(θ234) * a4' at this place, and with '-' the listing reproduces the printed "
            "Table 5-4 end-pose theta3 = -45.244 (tests/audit/test_vb6.py)"
        ),
    }
]
"""The one edit needed to run the printed listing; everything else runs as printed."""


def listing(*, repaired: bool = True) -> str:
    """The thesis's VB6 listing (``data/papers/gr1.toml``, record ``listing``), with
    :data:`LISTING_REPAIRS` applied when ``repaired`` (the default; as printed it does not
    compile)."""
    src = paper.LISTING
    if repaired:
        for rep in LISTING_REPAIRS:
            if src.count(rep["printed"]) != 1:
                raise ValueError(f"repair target {rep['printed']!r} not found exactly once")
            src = src.replace(rep["printed"], rep["repaired"])
    return src


def run_command1(inputs: dict, **options: bool) -> dict:
    """Run ``Command1_Click`` (the "计算" button) of the repaired listing on ``inputs``.

    ``inputs`` maps ``Text1`` ... ``Text12`` (start px, py, pz, alpha, beta, gamma, then the
    end pose, the order of Table 5-3) to what is typed. Returns :func:`analysis.audit.vb6.run`'s
    dict.

    Example (Table 5-3 start and end poses; printed Table 5-4 start theta1 is 56.828)::

        >>> out = run_command1({"Text1": "151", "Text2": "231", "Text3": "250", "Text4": "32",
        ...                     "Text5": "45", "Text6": "60", "Text7": "200", "Text8": "300",
        ...                     "Text9": "178", "Text10": "20", "Text11": "50", "Text12": "80"})
        >>> out["text"]["Text13"], out["text"]["Text14"]
        ('56.828', '-66.006')
    """
    return vb6.run(listing(), "Command1_Click", inputs, **options)


def listing_statement(prefix: str, *, repaired: bool = False) -> str:
    """The one line of the listing (as printed, or with the cf3 repair) starting ``prefix``."""
    lines = [ln for ln in listing(repaired=repaired).splitlines() if ln.startswith(prefix)]
    if len(lines) != 1:
        raise ValueError(f"{len(lines)} listing lines start with {prefix!r}")
    return lines[0]


def equation_holds(text: str, *, angle: bool = False, atol: float = 1e-9) -> bool:
    """Does ``lhs = rhs`` (SymPy text over the thesis's symbols) hold on the register's 200
    seeded configurations of the chain (the ``sampled`` kind, domain ``chain``)?"""
    from analysis.audit.context import context
    from analysis.audit.kinds import check

    spec = {"kind": "sampled", "domain": "chain", "angle": angle, "tol": atol}
    return check(spec, text, context("gr1")).ok


# --------------------------------------------------------------------------- repairs
def atn_parts(statement: str) -> tuple[str, str]:
    """The numerator and denominator of the ``Atn(A / B)`` in a listing statement."""
    from analysis.audit.kinds.listing import atn_operands

    def unwrap(s: str) -> str:
        depth = 0
        for i, ch in enumerate(s):
            depth += {"(": 1, ")": -1}.get(ch, 0)
            if depth == 0 and i < len(s) - 1:
                return s
        return s[1:-1] if s.startswith("(") else s

    return tuple(unwrap(p) for p in atn_operands(statement))  # type: ignore[return-value]


def atan2_statement(name: str, y: str, x: str) -> str:
    """VB6 setting ``name`` [deg] to atan2(y, x) with the listing's functions (VB6 has no
    Atan2): the half-angle form 2 Atn(y / (r + x)), r = Sqr(x^2 + y^2), and 180 deg where
    r + x = 0 (y = 0, x <= 0; at the origin every angle is a solution)."""
    return "\n".join([
        f"Yn = {y}: Xd = {x}: Rr = Sqr(Xd * Xd + Yn * Yn)", "If Rr + Xd > 0 Then",
        f"{name} = (180 / PI) * 2 * Atn(Yn / (Rr + Xd))", "Else", f"{name} = 180", "End If",
    ])  # fmt: skip


def _replace_line(src: str, prefix: str, new: str) -> str:
    lines = src.splitlines()
    hits = [i for i, ln in enumerate(lines) if ln.startswith(prefix)]
    if len(hits) != 1:
        raise ValueError(f"{len(hits)} listing lines start with {prefix!r}")
    lines[hits[0]] = new
    return "\n".join(lines) + "\n"


def radians_in_trig(text: str) -> str:
    """``Sin(x)`` -> ``Sin(x * PI / 180)`` (and Cos) for every name x: degrees converted."""
    return re.sub(r"\b(Sin|Cos)\((\w+)\)", r"\1(\2 * PI / 180)", text)


def _units(src: str) -> str:
    head, sep, tail = src.partition("Private Sub Command3_Click()")
    return radians_in_trig(head) + sep + tail


def _sign(src: str) -> str:
    return re.sub(r"\+ Cos\((θf?234(?: \* PI / 180)?)\) \* a4", r"- Cos(\1) * a4", src)


def _end_orientation(src: str) -> str:
    for prefix in ("θf5 = ", "θf234 = "):
        line = next(ln for ln in src.splitlines() if ln.startswith(prefix))
        new = line.replace("α0", "α1").replace("β0", "β1").replace("γ0", "γ1")
        src = _replace_line(src, prefix, new)
    return src


def approach_theta234(f: str = "", k: str = "0") -> str:
    """theta234 = atan2(c1 a_x + s1 a_y, -a_z) as VB6 over the listing's variables (eq.
    3.15's approach vector from alpha, beta, gamma)."""
    c1, s1 = f"Cos(θ{f}1)", f"Sin(θ{f}1)"
    a, b, g = f"α{k}", f"β{k}", f"γ{k}"
    ax = f"Cos({a}) * Sin({b}) * Cos({g}) + Sin({a}) * Sin({g})"
    ay = f"Sin({a}) * Sin({b}) * Cos({g}) - Cos({a}) * Sin({g})"
    return atan2_statement(f"θ{f}234", f"{c1} * ({ax}) + {s1} * ({ay})", f"-Cos({b}) * Cos({g})")


def _quadrants(src: str) -> str:
    for f, k in (("", "0"), ("f", "1")):
        for j in ("1", "5", "2"):
            line = next(ln for ln in src.splitlines() if ln.startswith(f"θ{f}{j} = "))
            src = _replace_line(src, f"θ{f}{j} = ", atan2_statement(f"θ{f}{j}", *atn_parts(line)))
        c3 = "cf3" if f else "c3"
        new = atan2_statement(f"θ{f}3", f"Sqr(Abs(1 - {c3} * {c3}))", c3)
        src = _replace_line(src, f"θ{f}3 = ", new)
        src = _replace_line(src, f"θ{f}234 = ", radians_in_trig(approach_theta234(f, k)))
    return src


REPAIRS: dict[str, object] = {
    "printed": lambda s: s,
    "+ radians into Sin/Cos": _units,
    "+ '-' before Cos(θ234) * a4 in θ2": _sign,
    "+ end orientation α1, β1, γ1": _end_orientation,
    "+ atan2 quadrants, θ234 from a": _quadrants,
}
"""The listing's defects repaired one after another (cumulative), in the order of the
register's causes gr1-trig-degrees, gr1-r-sign, gr1-end-orientation, gr1-atan (the cf3
operator, gr1-cf3-operator, is restored in every step: as printed nothing runs)."""


def repaired_listing(upto: str) -> str:
    """The listing with the repairs of :data:`REPAIRS` applied up to and including ``upto``."""
    if upto not in REPAIRS:
        raise ValueError(f"unknown repair {upto!r}; expected one of {list(REPAIRS)}")
    src = listing()
    for name, fn in REPAIRS.items():
        src = fn(src)
        if name == upto:
            return src
    raise AssertionError("unreachable")  # pragma: no cover


def table5_3_inputs() -> dict[str, str]:
    """Table 5-3 typed into Text1 .. Text12 (start px, py, pz, alpha, beta, gamma, end)."""
    rows = paper.TABLE5_3["rows"]
    return {f"Text{i + 1}": str(v) for i, v in enumerate(rows["start"] + rows["end"])}


def table5_4_cascade():
    """Table 5-4 as the listing computes it after each cumulative repair of :data:`REPAIRS`:
    one row per step, columns ``start theta1`` .. ``end theta5`` [deg]."""
    import pandas as pd

    rows = []
    for step in REPAIRS:
        out = vb6.run(repaired_listing(step), "Command1_Click", table5_3_inputs())
        loc = {k: float(vb6.to_number(v).value) for k, v in out["locals"].items()
               if k.startswith("θ") and v.type != vb6.EMPTY}  # fmt: skip
        row = {"step": step}
        row.update({f"start theta{j}": loc[f"θ{j}"] for j in range(1, 6)})
        row.update({f"end theta{j}": loc[f"θf{j}"] for j in range(1, 6)})
        rows.append(row)
    return pd.DataFrame(rows).set_index("step")


def numbers(text: str) -> list[float]:
    """The numbers in a text, in order."""
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?", text)]


@cache
def printed_run() -> dict:
    """The listing (cf3 repaired) on Table 5-3: what the 计算 button displays."""
    return vb6.run(listing(), "Command1_Click", table5_3_inputs())


def printed_cells() -> tuple[float, ...]:
    """Table 5-4 as printed, start theta1 .. theta5 then end."""
    rows = paper.TABLE5_4["rows"]
    return (*rows["start"], *rows["end"])


def cells_matching(src: str, **options) -> int:
    """How many of Table 5-4's ten printed cells the listing ``src`` displays for Table 5-3."""
    out = vb6.run(src, "Command1_Click", table5_3_inputs(), **options)["text"]
    cells = dict(zip([f"Text{i}" for i in range(13, 23)], printed_cells(), strict=True))
    return sum(out[b] == vb6.vb_format(v, "####.###") for b, v in cells.items())


# --------------------------------------------------------------------------- the register's data
def chain_values(arm: Arm, n: int = 200, seed: int = 2007) -> dict[str, np.ndarray]:
    """Every kinematic symbol of the thesis on ``n`` seeded configurations of ``arm`` (the arm
    hook ``Arm.sample_q`` where it exists, else uniform within the limits) that are front
    solutions of their own pose (atan2(py, px) is their theta1): joint angles, pose, columns
    n, o, a, RPY angles (phi, theta, psi), the link lengths and sec. 4.2's c1, s1 ... c234,
    s234."""
    from analysis.audit.context import sample_q

    rng = np.random.default_rng(seed)
    try:
        q = sample_q(arm, rng, 3 * n)
    except ValueError:  # no hook yet: the closed form takes poses, not positions
        q = np.column_stack([rng.uniform(*(lh or (-np.pi, np.pi)), 3 * n) for lh in arm.limits])
    P = arm.params
    t2, t23, t234 = q[:, 1], q[:, 1] + q[:, 2], q[:, 1] + q[:, 2] + q[:, 3]
    q = q[P["a2"] * np.cos(t2) + P["a3"] * np.cos(t23) + P["a4"] * np.cos(t234) > 1.0][:n]
    T = arm.table.fk(q)
    rpy = rpy_from_matrix(T[:, :3, :3])
    v = {f"theta{j + 1}": q[:, j] for j in range(5)}
    v["theta234"] = wrap_rad(q[:, 1] + q[:, 2] + q[:, 3])
    v.update(px=T[:, 0, 3], py=T[:, 1, 3], pz=T[:, 2, 3], phi=rpy[:, 0], theta=rpy[:, 1],
             psi=rpy[:, 2], **{k: float(P[k]) for k in ("a2", "a3", "a4")})  # fmt: skip
    v.update({f"{c}_{x}": T[:, i, k] for k, c in enumerate("noa") for i, x in enumerate("xyz")})
    for j in ("1", "2", "3", "234"):  # sec. 4.2's c_i, s_i: cos and sin of the joint angle
        v[f"c{j}"], v[f"s{j}"] = np.cos(v[f"theta{j}"]), np.sin(v[f"theta{j}"])
    return v


@cache
def listing_variants() -> dict[str, object]:
    """The listing (cf3 repaired) on Table 5-3: how many printed cells it reproduces as
    printed, with Sin/Cos in degrees and with theta234 Double; whether another end
    orientation changes the end cells; whether it shows joint values for an unreachable
    start (600, 10, 0) mm; whether the printed cf3 line parses; the end theta3 it shows."""
    run = printed_run()["text"]
    other = run_command1(dict(table5_3_inputs(), Text10="-70", Text11="10", Text12="5"))
    shown = run_command1(dict(table5_3_inputs(), Text1="600", Text2="10", Text3="0"))["text"]
    double = listing().replace("θ234 As Single", "θ234 As Double")
    try:
        parses = bool(vb6.VB6Form(listing(repaired=False)))
    except vb6.VB6SyntaxError:
        parses = False
    ends = [f"Text{i}" for i in range(18, 23)]
    return {
        "as_printed": cells_matching(listing()),
        "trig_in_degrees": cells_matching(listing(), trig_degrees=True),
        "all_double": cells_matching(double.replace("θf234 As Single", "θf234 As Double")),
        "end_orientation_read": [other["text"][b] for b in ends] != [run[b] for b in ends],
        "far_pose_shown": all(shown[f"Text{i}"] not in ("", ".") for i in range(13, 18)),
        "far_pose_reachable": bool(gr1_arm().solve([600.0, 10, 0, 0, 0, 0]).ok.any()),
        "printed_cf3_parses": parses, "end_theta3_shown": float(run["Text20"]),
    }  # fmt: skip


def ladder_sections() -> list[tuple[str, list[str]]]:
    """The ladder's operands (pp. 31-35, as extracted) cut at the start inputs X20 / X21:
    (start input, operands) per section."""
    toks = " ".join(paper.LADDER_EXTRACTED[p] for p in range(31, 36)).split()
    cut = [i for i, t in enumerate(toks) if t in ("X20", "X21")] + [len(toks)]
    return [(toks[a], toks[a:b]) for a, b in itertools.pairwise(cut)]


@cache
def corrected_move():
    """Table 5-3's poses, orientation projected, on the first branch within the assumed
    limits: (q (2, 5) [rad], branch names, counter presets, orientation turn [rad])."""
    arm = gr1_arm()
    proj, turn = st.project_orientation(arm, st.thesis_poses())
    q, names = st.first_within_limits(arm, proj)
    return q, names, st.counter_presets(q[0], q[1]), turn


@cache
def alternative_presets() -> list[str]:
    """The counter presets of every other move between Table 5-3's poses (orientation
    projected) on branches within the assumed limits: the corrected move's presets are one of
    these (its branches are the arm's first within the limits). One text per move: the branches
    and the five presets C235 .. C239."""
    arm = gr1_arm()
    proj, _ = st.project_orientation(arm, st.thesis_poses())
    sol = arm.solve(proj)
    names = corrected_move()[1]
    out = []
    for i, a in enumerate(arm.branches):
        for j, b in enumerate(arm.branches):
            if not (sol.ok[0, i] and sol.ok[1, j]) or (a, b) == tuple(names):
                continue
            k = st.counter_presets(sol.theta[0, i], sol.theta[1, j])["preset"]
            out.append(f"{a} -> {b}: " + ", ".join(str(int(v)) for v in k))
    return out


def relative_move_misses(spread_deg=None, n: int = 200, seed: int = 169) -> dict[str, np.ndarray]:
    """Where the corrected move, made relative (the counters count changes from wherever the
    arm stands), ends: from ``n`` starts within +-``spread_deg`` per joint of Table 5-3's
    start (default: +-half a count, the arm homed there): the miss [mm] from the planned end,
    and the one-count tolerance (every joint one count off, first order)."""
    arm, rng = gr1_arm(), np.random.default_rng(seed)
    q, _, presets, _ = corrected_move()
    res = np.radians(np.asarray(st.RESOLUTION_DEG))
    half = res / 2 if spread_deg is None else np.full(5, np.radians(spread_deg))
    q0 = q[0] + rng.uniform(-1, 1, (n, 5)) * half
    end = arm.fk(q0 + np.radians(presets["moved_deg"].to_numpy()))
    tol = float(np.linalg.norm(np.abs(arm.jacobian(q[1])) @ res))
    return {"miss_mm": np.linalg.norm(end - arm.fk(q[1]), axis=-1), "tolerance_mm": np.full(n, tol)}


@cache
def move_facts() -> dict[str, object]:
    """The numbers the register's evidence cites about the corrected move, the PLC's move
    and the printed Table 5-4 (base height d1 = 0 and the limits assumed)."""
    from analysis.studies.trajectories import acceleration_jumps, profile

    q, names, presets, turn = corrected_move()
    t = st.table5_4().set_index(["pose", "source"])
    fx = st.fx2n_vs_cubic(gr1_arm(), q[0], q[1], samples=1001)  # 1001: path lengths to 0.1 %
    s = profile("cubic", np.linspace(0.0, 1.0, 1001))[0][:, None]  # all joints together
    together = gr1_arm().fk(q[0] + (q[1] - q[0]) * s)
    d1 = [np.linalg.norm(gr1_arm().with_(d1=float(h)).fk(st.printed_joints()[0])
                         - st.thesis_poses()[0, :3]) for h in np.linspace(-200, 200, 81)]  # fmt: skip  # noqa: E501
    free = st.workspace_extents(limits=False)

    def join(xs, f="{:.3f}"):
        return ", ".join(f.format(x) for x in xs)

    return {
        "start": names[0], "end": names[1], "turn_start": math.degrees(turn[0]),
        "turn_end": math.degrees(turn[1]), "miss_start": t.loc[("start", "printed")].miss_mm,
        "miss_end": t.loc[("end", "printed")].miss_mm, "min_miss_start_d1": float(min(d1)),
        "presets": join(zip(presets.counter, presets.preset, strict=True), "{0[0]} {0[1]}"),
        "directions": join(zip(presets.counter, presets.direction, strict=True), "{0[0]} {0[1]}"),
        "q_start": join(np.degrees(q[0])), "q_end": join(np.degrees(q[1])),
        "speeds": join(fx["speed_deg_s"], "{:g}"), "time_fx2n": fx["time_fx2n_s"],
        "length_fx2n": fx["length_fx2n_mm"], "length_cubic": fx["length_cubic_mm"],
        "apart": fx["max_apart_mm"], "free_radius": free["radius_mm"],
        "apart_together": float(st.nearest_point_distance(together, fx["p_cubic"]).max()),
        "jumps": join(np.degrees(acceleration_jumps("cubic", q[0], q[1], st.DURATION_S)), "{:.2f}"),
        "reach": gr1_arm().geometry["reach_tool"], "free_span": free["height_span_mm"],
        **st.workspace_extents(),
    }  # fmt: skip


# --------------------------------------------------------------------------- the register's domains
def paper_():
    return load("gr1")




def any_poses() -> dict[str, np.ndarray]:
    """100 poses at reachable positions, half with the chain's own orientation, half with a
    random one: does the arm's closed form solve each, and does its approach vector lie in
    the arm's vertical plane (|s1 a_x - c1 a_y| <= 1e-4, the arm's tolerance)?"""
    arm, rng = gr1_arm(), np.random.default_rng(5)
    q = np.column_stack([rng.uniform(*(lh or (-np.pi, np.pi)), 100) for lh in arm.limits])
    pose = st.pose_of(arm, q)
    pose[50:, 3:] = rng.uniform(-np.pi / 2, np.pi / 2, (50, 3))
    a, t1 = matrix_from_rpy(pose[:, 3:])[:, :, 2], np.arctan2(pose[:, 1], pose[:, 0])
    return {"solved": arm.solve(pose).ok.any(axis=-1),
            "plane": np.abs(np.sin(t1) * a[:, 0] - np.cos(t1) * a[:, 1]) <= 1e-4}  # fmt: skip



def automatic_sections() -> dict[str, np.ndarray]:
    """The ladder's automatic sections (started by X20): how many inputs each reads besides
    the start input."""
    secs = [s for start, s in ladder_sections() if start == "X20"]
    return {"other_inputs": np.array([len({t for t in s if t[0] == "X"} - {"X20"}) for s in secs])}



def table5_4_cells() -> dict[str, np.ndarray]:
    """Table 5-4's ten cells: does each give the corrected joint value (at its decimals,
    modulo a turn)?"""
    q, rows = np.degrees(corrected_move()[0]), paper_().table_rows("table5_4")
    right = []
    for k, r in enumerate(("start", "end")):
        for j in range(5):
            cell = str(rows[r][f"theta{j + 1}"])
            right.append(cell_matches(cell, q[k, j] + 360 * round((float(cell) - q[k, j]) / 360)))
    return {"right": np.array(right)}



def control_path() -> dict[str, np.ndarray]:
    """The path of secs. 2.3.4 and 6.4, step by step, as printed: joint values computed
    (Command1_Click); Table 2-3 from Table 5-4 by the text's rule; a procedure for each of
    sec. 6.2's buttons (the write button's among them); counters with set values a PC can
    write (not K constants)."""
    df, subs = st.printed_presets(), vb6.VB6Form(listing()).subs
    buttons = paper_().record("c6.2-buttons").text.split(":")[-1].split("、")
    ladder = paper_().record("ladder")["recoverable"]["counters"]
    return {"implemented": np.array([
        "command1_click" in subs, bool((df.printed == df.as_pulses).all()),
        len(subs) >= len(buttons), all(not k.startswith("K") for k in ladder.values())])}  # fmt: skip  # noqa: E501



def partner_citations() -> dict[str, np.ndarray]:
    """The results taken from a group-mate's report (sec. 4.2's IK, the PLC sizing, the
    wiring): does the reference list hold a thesis or report ([D], [R]) to resolve them to?"""
    refs = [r.text for k, r in paper_().records.items() if k.startswith("references.")]
    return {"resolves": np.array([any(t in r for r in refs for t in ("[D]", "[R]"))] * 3)}


def sec42_holds_on(rows) -> bool:
    """Do section 4.2's c3 and tan(theta234) = o_z / (c1 o_x + s1 o_y) hold on the chain of
    D-H ``rows`` (d, a [mm], alpha [rad]; standard convention), at 100 seeded configurations?
    Model A (data/arms/gr1.toml) makes them hold; the roll axis along the hand does not."""
    from analysis.kinematics.dh import DHRow, DHTable

    P = gr1_arm().params
    table = DHTable(tuple(DHRow(alpha, a, d) for d, a, alpha in rows))
    q = np.random.default_rng(3).uniform(-np.pi, np.pi, (100, 5))
    T, t234, c1, s1 = table.fk(q), q[:, 1] + q[:, 2] + q[:, 3], np.cos(q[:, 0]), np.sin(q[:, 0])
    r = T[:, 0, 3] * c1 + T[:, 1, 3] * s1 - np.cos(t234) * P["a4"]
    z = T[:, 2, 3] - np.sin(t234) * P["a4"]
    c3 = (r * r + z * z - P["a2"] ** 2 - P["a3"] ** 2) / (2 * P["a2"] * P["a3"])
    o = T[:, :3, 1]
    tan = o[:, 2] * np.cos(t234) - np.sin(t234) * (c1 * o[:, 0] + s1 * o[:, 1])
    return bool(np.allclose(c3, np.cos(q[:, 2]), atol=1e-9) and np.allclose(tan, 0, atol=1e-9))

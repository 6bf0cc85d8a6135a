"""Seed 004's definitions for its checks (``data/registers/gr1.toml``): the GR-1's chain
(``data/arms/gr1.toml``, d1 = 0 and the joint limits assumed), its VB6 listing
(:mod:`analysis.audit.vb6`, run by the ``vb6`` kind on the presets of :mod:`.listing`) and the
FX2N program's operand census. The studies behind the domains and facts: :mod:`.thesis`,
:mod:`.listing`."""

from __future__ import annotations

import math
import re
from functools import cache

import numpy as np
import sympy as sp

from analysis.audit import vb6
from analysis.audit.context import Bespoke, context
from analysis.audit.kinds import Result
from analysis.audit.papers.gr1 import listing as gl
from analysis.audit.papers.gr1 import thesis as st
from analysis.kinematics.arm import Arm
from analysis.kinematics.dh import link_transform_sym

B = Bespoke("gr1")
_NUM = r"-?\d+(?:\.\d+)?"


def _tuple(text: str, k: int):
    """``k`` numbers written '(a, b, ...)' or one a line (a printed table row), else None."""
    t = text.strip()
    if re.fullmatch(rf"\((?:{_NUM}, ){{{k - 1}}}{_NUM}\)", t) or re.fullmatch(rf"(?:{_NUM}\n){{{k - 1}}}{_NUM}", t):  # noqa: E501
        return [float(v) for v in re.findall(_NUM, t)]
    return None


def _paper():
    return context("gr1").paper


@cache
def _probe() -> Arm:
    """A chain of the GR-1's form with a3 = 200 mm: with the GR-1's a2 = a3 = 228 mm a
    formula with a2 and a3 swapped would pass."""
    return st.gr1_arm().with_(a3=200.0)


# --- domains ----------------------------------------------------------------------------------
B.domain("chain")(lambda: gl.chain_values(_probe()))
B.domain("listing_variants")(lambda: {k: np.array([v]) for k, v in gl.listing_variants().items()})
B.domain("power_up_starts")(lambda: gl.relative_move_misses(spread_deg=10.0))
B.domain("homed_starts")(lambda: gl.relative_move_misses())
B.domain("any_poses")(gl.any_poses)
B.domain("automatic_sections")(gl.automatic_sections)
B.domain("table5_4_cells")(gl.table5_4_cells)
B.domain("control_path")(gl.control_path)
B.domain("partner_citations")(gl.partner_citations)


# --- values, matrices, facts ------------------------------------------------------------------
B.value("vb6_env")(lambda config, end: (gl.listing_env(config, end or None, _probe()), None))
B.fact("move")(gl.move_facts)
B.fact("variants")(gl.listing_variants)
B.fact("other_presets")(lambda: "; ".join(gl.alternative_presets()) or "none")


@B.value("pulses")
def _pulses(row, column):
    """Table 2-3's cell: |delta theta| of the printed Table 5-4 over Table 2-1's resolution."""
    df = st.printed_presets().set_index("counter")
    return float(df.loc[row].delta_deg / st.RESOLUTION_DEG[st.COUNTERS.index(row)])


@B.value("joint_value")
def _joint(row, column):
    """The corrected joint value [deg] of Table 5-4's cell."""
    return float(np.degrees(gl.corrected_move()[0][("start", "end").index(row), int(column[-1]) - 1]))  # noqa: E501


def _rot(axis: int, angle) -> sp.Matrix:
    return sp.Matrix(sp.BlockDiagMatrix(getattr(sp, f"rot_axis{axis}")(-angle), sp.eye(1)))


@B.matrix("rpy")
def _rpy():
    """Rot(z, phi) Rot(y, theta) Rot(x, psi), eq. 3.14's order, homogeneous."""
    s = _paper().symbols()
    return _rot(3, s["phi"]) * _rot(2, s["theta"]) * _rot(1, s["psi"])


B.matrix("dh_link")(lambda: link_transform_sym(*(_paper().symbols()[k] for k in ("theta_i", "d_i", "a_i", "alpha_i"))))  # noqa: E501


# --- predicates -------------------------------------------------------------------------------
def _nearest_pose(pose: str):
    """Table 5-3's ``pose`` with its orientation projected to the nearest the arm can take
    (position unchanged): the pose the corrected joint values must give."""
    proj, _ = st.project_orientation(st.gr1_arm(), st.thesis_poses())
    return proj[("start", "end").index(pose)]


def _pose_miss(q_deg, want) -> tuple[float, float]:
    """Position miss [mm] and orientation miss [deg] of joint values ``q_deg`` from pose
    ``want`` (mm, rad)."""
    from analysis.kinematics.rpy import matrix_from_rpy, rotation_angle

    T = st.gr1_arm().table.fk(np.radians(q_deg))
    turn = rotation_angle(matrix_from_rpy(np.asarray(want[3:])), T[:3, :3])
    return float(np.linalg.norm(T[:3, 3] - want[:3])), float(np.degrees(turn))


@B.predicate("reaches")
def _reaches(text, ctx, pose):
    """Five joint angles [deg] put the hand at Table 5-3's position (0.05 mm: three decimals
    move it by up to 0.02 mm) in the nearest orientation the arm can take there (0.01 deg):
    every angle, theta5 too, is decided."""
    v = _tuple(text, 5)
    if v is None:
        return Result(False, {"why": "not five angles"})
    target = st.thesis_poses()[("start", "end").index(pose), :3]
    miss = float(np.linalg.norm(st.gr1_arm().fk(np.radians(v)) - target))
    _, turn = _pose_miss(v, _nearest_pose(pose))
    return Result(miss <= 0.05 and turn <= 0.01, {"miss_mm": miss, "turn_deg": turn})


@B.predicate("orientation_ok")
def _orientation_ok(text, ctx, pose):
    """Six numbers (mm, deg): Table 5-3's ``pose`` with the orientation the 5-DOF arm can take
    nearest the printed one: the printed position, a pose the arm solves, within 0.01 deg of
    the projection (three decimals of the RPY angles)."""
    from analysis.kinematics.rpy import matrix_from_rpy, rotation_angle

    v = _tuple(text, 6)
    if v is None:
        return Result(False, {"why": "not six numbers"})
    want = _nearest_pose(pose)
    solved = bool(st.gr1_arm().solve(np.array([*v[:3], *np.radians(v[3:])])).ok.any())
    at = float(np.linalg.norm(np.asarray(v[:3]) - want[:3]))
    turn = float(np.degrees(rotation_angle(matrix_from_rpy(np.radians(v[3:])),
                                           matrix_from_rpy(want[3:]))))  # fmt: skip
    return Result(solved and at <= 1e-9 and turn <= 0.01, {"turn_deg": turn})


@B.predicate("format_readable")
def _format(text, ctx):
    """The θf1 display as Command3_Click reads it back (listing lines 59-62, with Text13 =
    "1"): joint values 0 and -24.683 deg must come back as those numbers."""
    src = f"Private Sub T_Click()\nText13.Text = \"1\"\n{text}\n{_paper().text('listing:59-62')}\nEnd Sub\n"  # noqa: E501
    for v in (0.0, -24.683):
        try:
            d = vb6.to_number(vb6.VB6Form(src).call("T_Click", {"θf1": v})["d"]).value
        except (vb6.VB6Error, vb6.VB6SyntaxError, KeyError):
            return False
        if abs(float(d) - v) > 5e-4:
            return False
    return True


@B.predicate("end_conditions")
def _end_conditions(text, ctx, acceleration=False):
    """A joint trajectory in the listing's form ('Y = ...' over a, b, c, X: start, end,
    duration, time) meets eqs. 5.1-5.2, and with ``acceleration`` zero end accelerations."""
    s = _paper().symbols("cubic")
    t, T, th0, thf = s["t"], s["t_f"], s["theta_0"], s["theta_f"]
    body = text.strip()
    if not re.fullmatch(r"Y = [\w\s()+\-*/^.]+", body):
        return False
    names = {"a": "theta_0", "b": "theta_f", "c": "t_f", "X": "t", "^": "**"}
    f = _paper().parse(re.sub(r"\b[abcX]\b|\^", lambda m: names[m[0]], body[4:]), "cubic")
    d1, d2 = sp.diff(f, t), sp.diff(f, t, 2)
    conds = [f.subs(t, 0) - th0, f.subs(t, T) - thf, d1.subs(t, 0), d1.subs(t, T)]
    conds += [d2.subs(t, 0), d2.subs(t, T)] if acceleration else []
    return all(sp.simplify(c) == 0 for c in conds)


@B.predicate("schedule")
def _schedule(text, ctx):
    """'M1 -> M2 -> ...' (one after another, on/off at the motors' speed, sec. 2.3.4) or
    'M1 + M2 + ...' (together, each on its cubic): the largest distance [mm] of the hand from
    the planned path (every joint on its cubic, together, eqs. 5.1-5.4), within 1 mm?"""
    m = re.fullmatch(r"M1( -> | \+ )M2\1M3\1M4\1M5", text.strip())
    if not m:
        return Result(False, {"why": "not five motors one after another or together"})
    apart = gl.move_facts()["apart"] if m[1] == " -> " else gl.move_facts()["apart_together"]
    return Result(apart <= 1.0, {"apart_mm": apart})


@B.predicate("counter_setting")
def _counter_setting(text, ctx):
    """C235-C239 count to 32-bit set values the PC can write (D registers, pairs apart),
    written with the corrected move's presets."""
    m = re.fullmatch(r"((?:C23\d [DK]\d+, )*C23\d [DK]\d+); the PC writes ((?:D\d+ = \d+, )*D\d+ = \d+)"  # noqa: E501
                     r" before each move, and resets the counters", text.strip())
    if not m:
        return Result(False, {"why": "not 'C235 D200, ...; the PC writes D200 = ..., ...'"})
    sets = dict(re.findall(r"(C23\d) ([DK]\d+)", m[1]))
    writes = {f"D{a}": int(v) for a, v in re.findall(r"D(\d+) = (\d+)", m[2])}
    presets = dict(zip(st.COUNTERS, gl.corrected_move()[2].preset, strict=True))
    if sorted(sets) != list(st.COUNTERS) or any(not v.startswith("D") for v in sets.values()):
        return Result(False, {"why": "a set value the PC cannot write"})
    regs = [int(sets[c][1:]) for c in st.COUNTERS]
    if any(r % 2 for r in regs) or len({r // 2 for r in regs}) != 5:
        return Result(False, {"why": "32-bit set values overlap"})
    return Result(all(writes.get(sets[c]) == presets[c] for c in st.COUNTERS), {})


@B.predicate("direction_bits")
def _direction_bits(text, ctx):
    """Every direction bit the ladder reads (M11-M15, beside M8235-M8239) written for the
    move, one polarity for all: the bit tells a joint moving + from one moving -."""
    read = sorted({t for _, sec in gl.ladder_sections() for t in sec if re.fullmatch(r"M1\d", t)})
    m = re.fullmatch(r"((?:M1\d = [01], )*M1\d = [01]), written by the PC with the set values", text.strip())  # noqa: E501
    bits = dict(re.findall(r"(M1\d) = ([01])", m[1])) if m else {}
    if sorted(bits) != read:
        return False
    down = [d == "-" for d in gl.corrected_move()[2].direction]
    vals = [bits[b] == "1" for b in read]
    return vals in (down, [not d for d in down])


@B.predicate("work_area")
def _work_area(text, ctx):
    """'vertical V mm ... horizontal H mm' (optionally 'finger F mm', 'base B mm'): H is the
    links' radius plus the finger, V their height above the shoulder plus the base."""
    m = re.fullmatch(r"vertical (\d+) mm(?: above the floor with a base (\d+) mm high)?, horizontal (\d+) mm"  # noqa: E501
                     r"(?: with a finger (\d+) mm long)?(?: \(the links' reach\))?", text.strip())
    if not m:
        return False
    v = dict(zip(("vertical", "base", "horizontal", "finger"), (float(x or 0) for x in m.groups()), strict=True))  # noqa: E501
    ext = st.workspace_extents()
    return (abs(v["horizontal"] - ext["radius_mm"] - v["finger"]) <= 1
            and abs(v["vertical"] - ext["z_max_mm"] - v["base"]) <= 1)  # fmt: skip


@B.predicate("dh_rows")
def _dh_rows(text, ctx):
    """D-H rows '(thetaK, d, a, alpha_deg)' (lengths by name or in mm): a chain on which sec.
    4.2's c3 and tan(theta234) hold (analysis.audit.papers.gr1.listing.sec42_holds_on)."""
    row = r"\(theta(\d), ([\w.]+), ([\w.]+), (-?[\d.]+)\)"
    rows = re.findall(row, text)
    if not re.fullmatch(rf"{row}(?:, {row}){{4}}", text.strip()) or [r[0] for r in rows] != list("12345"):  # noqa: E501
        return False
    P = dict(st.gr1_arm().params)
    try:
        return gl.sec42_holds_on([(P[d] if d in P else float(d), P[a] if a in P else float(a),
                                   math.radians(float(al))) for _, d, a, al in rows])  # fmt: skip
    except ValueError:
        return False


@B.predicate("table5_4_cells")
def _t54(text, ctx):
    """Ten numbers 'start (...); end (...)': the cells the listing displays, in order."""
    m = re.fullmatch(r"start (\(.*\)); end (\(.*\))", text.strip())
    v = (_tuple(m[1], 5) or []) + (_tuple(m[2], 5) or []) if m else []
    shown = gl.printed_run()["text"]
    return len(v) == 10 and all(shown[f"Text{13 + i}"] == vb6.vb_format(x, "####.###") for i, x in enumerate(v))  # noqa: E501


@B.predicate("table5_3_header")
def _t53(text, ctx):
    """Table 5-3's column names in the order whose values, typed in, give Table 5-4."""
    rec = _paper().record("table5_3")
    names, tokens = list(rec["columns"]), text.replace(",", " ").split()
    if sorted(tokens) != sorted(names):
        return False
    order = [tokens.index(n) for n in names]
    vals = [rec["rows"][k][i] for k in ("start", "end") for i in order]
    return gl.run_command1({f"Text{i + 1}": str(v) for i, v in enumerate(vals)})["text"] == gl.printed_run()["text"]  # noqa: E501


@B.predicate("restored")
def _restored(text, ctx, of):
    """Statements of the extracted run ``of`` (a stretch of it, blanks aside), one a line,
    each VB6 of the modelled subset."""
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    if len(lines) < 2 or " ".join(" ".join(lines).split()) not in " ".join(_paper().text(of).split()):  # noqa: E501
        return False
    try:
        form = vb6.VB6Form("Private Sub T_Click()\n" + "\n".join(lines) + "\nEnd Sub\n")
    except vb6.VB6SyntaxError:
        return False
    return len(form.subs["t_click"][1]) == len(lines)


# --- the records' own checks (data/papers/gr1.toml, issue 30.1) -------------------------------
for _axis, _name in ((1, "rot_x"), (2, "rot_y"), (3, "rot_z")):
    B.matrix(_name)(lambda a=_axis: getattr(sp, f"rot_axis{a}")(-_paper().symbols()["theta"]))
"""Eqs. 3.5-3.7: the rotations about x, y, z by theta (SymPy's rot_axis turns the frame, hence
the minus: the point rotated)."""


def _cubic(solved: bool) -> dict:
    """Section 5.4.1's cubic as a substitution: theta(t) -> a0 + a1 t + a2 t^2 + a3 t^3 (eq.
    5.3), with ``solved`` a0 .. a3 too, from eqs. 5.1-5.2 (eq. 5.6: a0 = theta_0, a1 = 0,
    a2 = 3 (theta_f - theta_0) / t_f^2, a3 = -2 (theta_f - theta_0) / t_f^3)."""
    s = _paper().symbols("cubic")
    t, T, th0, thf = s["t"], s["t_f"], s["theta_0"], s["theta_f"]
    a = [s[f"a{i}"] for i in range(4)]
    out = {s["theta"]: sp.Lambda(t, sum(c * t**i for i, c in enumerate(a)))}
    if solved:
        d = thf - th0
        out.update(zip(a, (th0, 0, 3 * d / T**2, -2 * d / T**3), strict=True))
    return out


B.substitution("cubic")(lambda: _cubic(False))
B.substitution("cubic_solved")(lambda: _cubic(True))


@B.domain("cubic_system")
def _cubic_system():
    """Eqs. 5.1-5.2 as a linear system in a0 .. a3 (eq. 5.5): its rank."""
    s = _paper().symbols("cubic")
    t, T = s["t"], s["t_f"]
    coeffs = [s[f"a{i}"] for i in range(4)]
    f = sum(c * t**i for i, c in enumerate(coeffs))
    rows = [f.subs(t, 0), f.subs(t, T), sp.diff(f, t).subs(t, 0), sp.diff(f, t).subs(t, T)]
    M = sp.Matrix([[sp.diff(r, c) for c in coeffs] for r in rows])
    return {"rank": np.array([M.rank()])}


@B.domain("cubic_acc")
def _cubic_acc():
    """The acceleration steps [deg/s^2] of the corrected move's cubics at its ends (at rest
    before and after): what sec. 5.4.2 says must not jump."""
    from analysis.studies.trajectories import acceleration_jumps

    q = gl.corrected_move()[0]
    return {"jump_deg_s2": np.degrees(np.abs(acceleration_jumps("cubic", q[0], q[1], st.DURATION_S)))}  # noqa: E501


@B.domain("plan_constraints")
def _plan_constraints():
    """The constraints sec. 5.4.2's plan puts on each joint's move (``c5.2.1-cp.constraints``:
    the printed eqs. 5.1-5.2), each read from its printed left-hand side: the time it holds at
    (theta or its derivative at 0 or t_f); ``on_path``: between the end points, which is what
    the thesis's own sec. 5.3 calls a path constraint (CP) and PTP lacks."""
    paper = _paper()
    s = paper.symbols("cubic")
    theta, on_path = s["theta"], []
    for rid in paper.record("c5.2.1-cp")["constraints"]:
        lhs = paper.parse(paper.record(rid)["lhs"], "cubic")
        if isinstance(lhs, sp.Subs) and isinstance(lhs.expr, sp.Derivative) and lhs.expr.expr.func == theta:  # noqa: E501
            at = lhs.point[0]
        elif getattr(lhs, "func", None) == theta:
            at = lhs.args[0]
        else:
            raise ValueError(f"gr1:{rid}: {lhs} is not theta or its rate at a time")
        on_path.append(at not in (0, s["t_f"]))
    return {"on_path": np.array(on_path)}


@B.fact()
def cp_path() -> dict:
    """The corrected move's tool path (the cubics of sec. 5.4.2, Table 5-3's poses with the
    orientation projected, gl.corrected_move): its largest distance [mm] from the straight
    segment between its end positions, and that segment's length [mm]."""
    from analysis.studies.trajectories import cubic_trajectory

    q = gl.corrected_move()[0]
    t = np.linspace(0.0, st.DURATION_S, 201)
    P = st.gr1_arm().fk(cubic_trajectory(q[0], q[1], st.DURATION_S, t)[0])
    off = st.nearest_point_distance(P, np.stack([P[0], P[-1]]))
    return {"off_line_mm": float(off.max()), "chord_mm": float(np.linalg.norm(P[-1] - P[0]))}


@B.domain("contents_pages")
def _contents_pages():
    """The contents' entries (``contents.pages``): is each heading on the page the contents
    list for it?"""
    rows = _paper().record("contents.pages")["entries"]
    if any(len(r) != 3 or not all(isinstance(x, int) and x > 0 for x in r[1:]) for r in rows):
        raise ValueError("gr1:contents.pages: each entry is [title, listed page, body page]")
    return {"on_listed_page": np.array([listed == body for _, listed, body in rows])}


@B.domain("presets")
def _presets():
    """Table 2-3's presets against the pulses the text derives them as (|delta theta| of Table
    5-4 over Table 2-1's resolution)."""
    df = st.printed_presets()
    return {"printed": df.printed.to_numpy(float), "pulses": df.delta_deg.to_numpy(float)
            / np.asarray(st.RESOLUTION_DEG)}  # fmt: skip


@B.domain("encoder")
def _encoder():
    """Sec. 2.3.2's encoder: holes, channels and the signals per revolution it states."""
    e = _paper().record("encoder")
    return {"holes": np.array([e["holes"]]), "channels": np.array([len(e["channels"])]),
            "signals": np.array([e["signals_per_rev"]])}  # fmt: skip


@B.domain("sec5_4_2")
def _sec542():
    """What section 5.4.2 computes: from Table 5-3 (a pose: position and RPY angles) to Table
    5-4 (joint values), the inverse problem, or the reverse."""
    given = set(_paper().record("table5_3")["columns"])
    found = set(_paper().record("table5_4")["columns"])
    pose, joints = {"px", "py", "pz"} <= given, all(c.startswith("theta") for c in found)
    return {"pose_from_joints": np.array([not pose and joints]),
            "joints_from_pose": np.array([pose and joints])}  # fmt: skip


@B.domain("buttons")
def _buttons():
    """Sec. 6.2's five buttons against the listing's event procedures (one per button with
    code: Command1 计算, Command3 轨迹规划, Command4 清除)."""
    named = _paper().record("c6.2-buttons").text.split(":")[-1].rstrip("。").split("、")
    procs = [k for k in vb6.VB6Form(gl.listing()).subs if re.fullmatch(r"command\d+_click", k)]
    return {"has_code": np.arange(len(named)) < len(procs)}


@B.domain("gui_runs")
def _gui_runs():
    """The printed input check (record gui_check) run on pose pairs: does it leave the
    trajectory button enabled, and are both positions within the arm's reach (a2 + a3 + a4
    from the shoulder; d1 = 0 assumed)?"""
    pairs = [((151.0, 231.0, 250.0), (200.0, 300.0, 178.0)),  # Table 5-3, both within reach
             ((450.0, 0.0, 100.0), (-450.0, 0.0, 100.0)),  # both within reach, 900 mm apart
             ((600.0, 10.0, 0.0), (600.0, 10.0, 0.0)),  # both beyond the reach, one spot
             ((151.0, 231.0, 250.0), (1100.0, 0.0, 178.0))]  # the end beyond the reach
    P = st.gr1_arm().params
    reach = P["a2"] + P["a3"] + P["a4"]
    block = _paper().text("gui_check")
    enabled, reachable = [], []
    for p0, p1 in pairs:
        form = vb6.VB6Form(f"Private Sub T_Click()\nCommand3.Value = True\n{block}\nEnd Sub\n")
        form.call("T_Click", dict(zip(("Px0", "Py0", "Pz0", "Px1", "Py1", "Pz1"), (*p0, *p1), strict=True)))  # noqa: E501
        enabled.append(form.control("Command3").props["Enabled"].value is True)
        reachable.append(all(float(np.linalg.norm(p)) <= reach for p in (p0, p1)))
    return {"enabled": np.array(enabled), "reachable": np.array(reachable)}


@B.value("nearest_orientation")
def _nearest_orientation(row, column):
    """Table 5-3's RPY cell [deg] of the nearest orientation the arm can take at the printed
    position (gr1-five-dof)."""
    proj, _ = st.project_orientation(st.gr1_arm(), st.thesis_poses())
    k = ("alpha", "beta", "gamma").index(column)
    return float(np.degrees(proj[("start", "end").index(row), 3 + k]))


@B.predicate("listing_table5_4")
def _listing_table5_4(text, ctx):
    """The whole listing (the record, its one repair of the cf3 operator applied, gr1-cf3-
    operator) typed with Table 5-3: does the 计算 button display the corrected Table 5-4 (the
    nearest reachable orientation; every cell to the listing's three decimals, modulo a
    turn)?"""
    src = text
    for rep in gl.LISTING_REPAIRS:
        src = src.replace(rep["printed"], rep["repaired"])
    try:
        shown = vb6.run(src, "Command1_Click", gl.table5_3_inputs())["text"]
    except (vb6.VB6Error, vb6.VB6SyntaxError) as exc:
        return Result(False, {"why": str(exc)})
    q = np.degrees(gl.corrected_move()[0]).ravel()
    got = [float(shown[f"Text{13 + i}"] or "nan") for i in range(10)]
    right = [abs(math.remainder(g - w, 360.0)) <= 5e-4 for g, w in zip(got, q, strict=True)]
    return Result(all(right), {"right": sum(right)})

"""Seed 000's definitions for its checks (``data/registers/grabber.toml``): the D-H matrices of
Table 1, the forward kinematics, the sample domains (from the arm hook and the printed tables),
Table 4 recomputed, the listings' operand census and executed scans, and the facts the evidence
names. Arm: ``data/arms/grabber.toml`` (Table 3, printed); the angles are its closed form's."""

from __future__ import annotations

import numpy as np
import sympy as sp

from analysis.audit.context import Bespoke, context, sample_q
from analysis.validate import wrap_rad

B = Bespoke("grabber")
_RNG = 2016


def _arm():
    from analysis.kinematics.arm import paper_arm

    return paper_arm()


def _paper():
    return context("grabber").paper


def _S(name):
    return _paper().symbols()[name]


# --- matrices and substitutions (Table 1, sec. 1.2) -----------------------------------------
def _links():
    from analysis.kinematics.arm import paper_arm

    th = [_S(f"theta{i}") for i in (1, 2, 3)]
    return paper_arm().dh_table(symbolic=True).transforms_sym(th)


def _inverse(A: sp.Matrix) -> sp.Matrix:
    """[R p; 0 1]^-1 = [R^T -R^T p; 0 1]."""
    R, p = A[:3, :3], A[:3, 3]
    return R.T.row_join(-R.T * p).col_join(sp.Matrix([[0, 0, 0, 1]]))


for _i in range(3):
    B.matrix(f"A{_i + 1}")(lambda i=_i: _links()[i])
    B.matrix(f"A{_i + 1}inv")(lambda i=_i: _inverse(_links()[i]))


@B.matrix("T")
def _pose():
    rows = [[f"{v}_{ax}" for v in "noa"] + [f"P{ax}"] for ax in "xyz"]
    return sp.Matrix([[_S(n) for n in r] for r in rows] + [[0, 0, 0, 1]])


@B.matrix("E")
def _eye():
    return sp.eye(4)


@B.substitution("fk")
def _fk():
    T = context("grabber").product(["A1", "A2", "A3"])
    return {_S("Px"): T[0, 3], _S("Py"): T[1, 3], _S("Pz"): T[2, 3]}


# --- domains ----------------------------------------------------------------------------------
def _values(P, theta) -> dict:
    prm = _arm().params
    from analysis.kinematics.pulses import angles_to_pulses

    t1, t2, t3 = theta.T
    r = np.cos(t1) * P[:, 0] + np.sin(t1) * P[:, 1]
    z = P[:, 2] - prm.L1
    c = angles_to_pulses(theta)
    return {
        "Px": P[:, 0], "Py": P[:, 1], "Pz": P[:, 2], "p_z": P[:, 2],
        "theta1": t1, "theta2": t2, "theta3": t3,
        "theta23": wrap_rad(t2 + t3),
        # eq. 18's numerator and denominator, from the solution, not from the printed form:
        # (z^2 + r^2) times the sine and cosine of theta2 + theta3 (the wrist's own direction)
        "num": (z**2 + r**2) * np.sin(t2 + t3), "den": (z**2 + r**2) * np.cos(t2 + t3),
        "c1": c[:, 0], "c2": c[:, 1], "c3": c[:, 2], "L1": prm.L1, "L2": prm.L2, "L3": prm.L3,
    }  # fmt: skip


@B.domain("front-up")
def _front():
    """Table 4's reachable rows, targets in quadrants II-IV, and 200 seeded configurations."""
    arm = _arm()
    q = sample_q(arm, np.random.default_rng(_RNG), 200)
    probes = np.array([[-100.0, 100.0, 600.0], [-200.0, -100.0, 700.0], [150.0, -250.0, 500.0]])
    return _values(*_gs().front_up(np.vstack([_gs().targets_table4(), probes, arm.fk(q)])))


@B.domain("table4")
def _table4():
    return _values(*_gs().front_up(_gs().targets_table4()))


@B.domain("quadrants")
def _quadrants():
    az = np.radians([30.0, 120.0, 150.0, 210.0, 260.0, 300.0])
    P = np.stack([250 * np.cos(az), 250 * np.sin(az), np.full(6, 650.0)], axis=-1)
    return _values(*_gs().front_up(P))


@B.domain("sec241")
def _example():
    target = _paper().record("sec241_target")["target"]
    return _values(*_gs().front_up(np.array([target], dtype=float)))


@B.domain("reach_probes")
def _reach():
    arm, prm = _arm(), _arm().params
    P = np.vstack([_gs().targets_table4(), [[0.0, 600.0, 660.0], [50.0, 0.0, 660.0], [300, 300, 300]]])  # noqa: E501
    rho2 = P[:, 0] ** 2 + P[:, 1] ** 2
    arg = ((P[:, 2] - prm.L1) ** 2 + rho2 - prm.L2**2 - prm.L3**2) / (2 * prm.L2 * prm.L3)
    return {"reachable": arm.is_reachable(P), "acos_arg": arg}


# --- the printed listings, executed (analysis.audit.papers.grabber.listings) ----------------------
B.domain("listings")(lambda: {k: np.array([v]) for k, v in _gs().census().items()})
B.domain("hmi_targets")(lambda: _gs().hmi_targets())
B.domain("table4_rows")(lambda: _gs().table4_rows())
B.fact("executed")(lambda: _gs().executed())
B.fact("movd")(lambda: _gs().movd_damage())
B.fact("modes")(lambda: {k: int(v[0]) for k, v in _modes().items()})
for _name in ("workspace", "stl_constants", "random_poses", "printed_data"):
    B.domain(_name)(lambda n=_name: getattr(_gs(), n.replace("-", "_"))())
B.domain("z600_line")(lambda: _z600())


def _gs():
    from analysis.audit.papers.grabber import listings

    return listings


def _text(rid: str) -> str:
    return _gs().text(rid)


def _z600():
    """Targets at z = 600 mm (Table 4's plane) from the base axis to the reach: does the printed
    eq. 19 give the solution's theta2 there? The line carries ``rho_star``, where eq. 18's
    denominator changes sign (bisected to 1e-9 mm), and targets 1e-6 mm either side of it."""
    rho_star = _z600_crossing()
    rho = np.concatenate([np.linspace(1.0, 509.0, 509), rho_star + np.array([-1e-6, 1e-6])])
    P, th = _gs().front_up(np.stack([rho, np.zeros_like(rho), np.full_like(rho, 600.0)], -1))
    v = _values(P, th)
    printed = np.arctan(v["num"] / v["den"]) - v["theta3"]
    ok = np.abs(wrap_rad(printed - v["theta2"])) < 1e-9
    return {"rho": P[:, 0], "eq19_ok": ok, "rho_star": np.full(len(ok), rho_star)}


def _z600_crossing() -> float:
    """The distance from the base axis [mm] at which, on z = 600 mm, eq. 18's denominator
    -(Pz - L1) L2 sin(theta3) + r (L2 cos(theta3) + L3) changes sign (the front-up solution)."""

    def den(r):
        P, th = _gs().front_up(np.array([[r, 0.0, 600.0]]))
        return float(_values(P, th)["den"][0])

    lo, hi = 100.0, 500.0  # within the reach of z = 600 mm (93 to 506 mm from the axis)
    if np.sign(den(lo)) == np.sign(den(hi)):
        raise ValueError("eq. 18's denominator keeps its sign on z = 600 mm")
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if np.sign(den(mid)) == np.sign(den(lo)) else (lo, mid)
    return (lo + hi) / 2


B.fact("z600_crossing")(_z600_crossing)


PTO_OUTPUTS = {"CPU 224": 2}
"""Pulse-train outputs of the S7-200 CPUs the paper names: two generators, Q0.0 and Q0.1
(/work/shared/stl_reference.md, sec. 1.6, and analysis.plc.motion, which shares them among
three steppers)."""


@B.domain("hardware")
def _hardware():
    """The hardware sec. 2.3 names: the CPU's pulse-train outputs and the stepper motors."""
    cpu, motors = _paper().record("cpu")["cpu"], _paper().record("motors")["steppers"]
    return {"pto_outputs": np.array([PTO_OUTPUTS[cpu]]), "steppers": np.array([motors])}


@B.domain("ik_citations")
def _ik_citations():
    """The works the introduction cites as robot inverse-kinematics research ([6], [8]-[11];
    [10] and [11] are not in the extracted list), as our reading of each printed entry records
    it (``references.N``: ``subject``, ``on_kinematics``, ``beyond_print``)."""
    refs = [_paper().record(f"references.{k}") for k in (6, 8, 9)]
    for r in refs:
        if not isinstance(r.get("on_kinematics"), bool) or not str(r.get("beyond_print", "")).strip():  # noqa: E501
            raise ValueError(f"grabber:{r.id}: no reading (on_kinematics, beyond_print)")
    return {"on_kinematics": np.array([r["on_kinematics"] for r in refs])}


@B.domain("claimed_modes")
def _modes():
    """The modes secs. 2.1-2.2 claim (manual, automatic, cyclic, single run; each quoted): can
    anything the paper prints select it? An input of Table 2 our reading says selects it
    (``table2.devices``) and that the listings read (the operand census)."""
    modes, devices, reads = _gs().claimed_modes(), _gs().input_devices(), _gs().input_reads()
    selectors = [d for d in devices if d["selects"]]
    read = sum(v > 0 for v in reads.values())
    n = len(modes)
    return {"selectable": np.array([any(m in d["selects"] and reads[d["address"]] > 0 for d in devices) for m in modes]),  # noqa: E501
            "mode_inputs": np.full(n, len(selectors)), "table2_inputs": np.full(n, len(devices)),
            "inputs_read": np.full(n, read)}  # fmt: skip


@B.domain("sensing_inputs")
def _sensing():
    """Table 2's inputs, as our reading records each (``table2.devices``): does its kind of
    device sense something (a position, a target, a limit) rather than an operator's press?"""
    return {"senses": np.array([_gs().DEVICES[d["device"]] for d in _gs().input_devices()])}


# --- values and facts -------------------------------------------------------------------------
@B.value("front_up_deg")
def _cell(row: str, column: str) -> float:
    """Table 4 recomputed: theta1 by atan2 (defined for every target off the axis), theta2 and
    theta3 of the front-up solution, NaN out of reach."""
    p = np.array([float(_paper().table_rows("table4")[row][k]) for k in ("x_mm", "y_mm", "z_mm")])
    if column == "theta1_deg":
        return float(np.degrees(np.arctan2(p[1], p[0])))
    sol = _arm().solve(p[None], ("front-up",))
    j = int(column[5]) - 1
    return float(np.degrees(sol.theta[0, 0, j])) if sol.ok[0, 0] else float("nan")


def _alpha_trig(table: str, row: str, column: str) -> float:
    """Tables 1 and 3 recomputed: cos or sin of the row's printed alpha; Table 3's resolution,
    360 deg over sec. 3's pulses per turn."""
    if column == "resolution_deg":
        return 360 / _paper().record("sec3_resolution")["pulses_per_rev"]
    alpha = np.radians(float(_paper().table_rows(table)[row]["alpha_deg"]))
    return float(np.cos(alpha) if column.startswith("cos") else np.sin(alpha))


for _t in ("table1", "table3"):
    B.value(f"{_t}_recomputed")(lambda row, column, t=_t: _alpha_trig(t, row, column))


@B.fact()
def table4_fk():
    from analysis.audit.papers.grabber import table4

    return table4.summary().set_index("row")["fk_error_mm"].to_dict()


@B.fact()
def vdd0_readings():
    """eq. 10's argument for Table 4 row 1 when VDD0 is one address everywhere in Figure 6."""
    prm, (x, y, z) = _arm().params, _gs().targets_table4()[0]
    t1 = np.arctan2(y, x)

    def arg(t, X):
        s = (z - prm.L1) ** 2 + (np.cos(t) * X) ** 2 + 2 * np.cos(t) * np.sin(t) * X * y
        return (s + (np.sin(t) * y) ** 2 - prm.L2**2 - prm.L3**2) / (2 * prm.L2 * prm.L3)

    return {"VD0": arg(x, x), "VD12": arg(t1, t1), "mixed": arg(t1, x)}


@B.fact()
def tip_error():
    return float(context("grabber").domain("workspace")["tip_error_mm"].max())


@B.fact()
def px0():
    """ARCTAN(Py) [deg] for targets on the y axis: VD12 keeps Py where /R divides by zero."""
    return {py: float(np.degrees(np.arctan(np.float32(py)))) for py in (1, 10, 50, 300)}


@B.predicate()
def library_calls(text: str, ctx):
    """The text is CALLs the figures print, each of an Arcusfunctions routine (ARCSIN, ARCCOS,
    ARCTAN: IN, OUT), and the evaluator's routine gives the radians the library states."""
    from analysis.audit.kinds import Result
    from analysis.plc import stl_eval as stl

    calls = stl.parse_stl(text)
    printed = {(i.op, i.args) for f in (4, 5, 6) for i in stl.parse_stl(_text(f"figure{f}"))}
    ok = bool(calls) and all(
        i.op in ("CALL ARCSIN", "CALL ARCCOS", "CALL ARCTAN") and (i.op, i.args) in printed
        for i in calls
    )  # fmt: skip
    x = np.array([0.5, -0.25])
    for i in calls if ok else ():
        fn = {"CALL ARCTAN": np.arctan, "CALL ARCCOS": np.arccos, "CALL ARCSIN": np.arcsin}[i.op]
        got = [stl.real(stl.evaluate([i], stl.real_memory(**{i.args[0]: v})), i.args[1]) for v in x]
        ok &= bool(np.allclose(got, fn(x), rtol=1e-6))
    return Result(ok, {"calls": len(calls)})

"""Seed 000's printed STL listings (Figures 3-6) as data and executed: the operand census, the
scans an HMI would drive, Table 4's theta1 as the listings give it. The register's domains and
facts (``data/registers/grabber.toml``, :mod:`analysis.audit.papers.grabber.checks`) and notebook 07
read them; the listings run on :mod:`analysis.plc.stl_eval` (byte-accurate S7-200 REALs)."""

from __future__ import annotations

from functools import cache

import numpy as np

from analysis.audit.context import sample_q
from analysis.kinematics.arm import paper_arm
from analysis.papers import load
from analysis.plc import stl_eval

__all__ = [
    "DEVICES", "MODES", "census", "claimed_modes", "executed", "fig4_repaired", "front_up",
    "hmi_targets", "input_devices", "input_reads", "movd_damage", "printed_data", "random_poses",
    "stl_constants", "table4_rows", "targets_table4", "text", "workspace",
]  # fmt: skip


def _paper():
    return load("grabber")


def targets_table4() -> np.ndarray:
    """Table 4's targets (10, 3) [mm], as printed."""
    rows = _paper().table_rows("table4")
    return np.array([[float(r[k]) for k in ("x_mm", "y_mm", "z_mm")] for r in rows.values()])


def front_up(P):
    """The targets the front-up branch reaches, and their angles (n, 3) [rad]."""
    sol = paper_arm().solve(P, ("front-up",))
    ok = sol.ok[:, 0]
    return P[ok], sol.theta[ok, 0]


DEVICES = {"push button": False, "selector switch": False, "reference switch": True,
           "limit switch": True, "sensor": True, "encoder": True}
"""The kinds of input device a reading of Table 2 may name, and whether each senses anything
(a position, a target, a limit) rather than an operator's hand."""
MODES = ("manual", "automatic", "cyclic", "single run")
"""The modes of operation secs. 2.1-2.2 claim (``sec22_modes.claimed``)."""
_DEVICE_KEYS = {"address", "name", "device", "selects", "beyond_print"}


def input_devices(paper=None) -> list[dict]:
    """Our reading of each input Table 2 lists (``table2.devices``), one per printed input, in
    its order; ValueError naming the input for a reading that is not the printed row (address
    and name), leaves the vocabulary (:data:`DEVICES`, :data:`MODES`) or does not say what it
    adds to the table."""
    paper = paper or _paper()
    rec = paper.record("table2")
    printed = {addr: name for name, _code, addr in rec["inputs"]}
    out = []
    for d in rec.get("devices", ()):
        where = f"grabber:table2 input {d.get('address')}"
        if set(d) != _DEVICE_KEYS:
            raise ValueError(f"{where}: keys {sorted(set(d) ^ _DEVICE_KEYS)} unknown or missing")
        if printed.get(d["address"]) != d["name"]:
            raise ValueError(f"{where}: {d['name']!r} is not the printed row")
        if d["device"] not in DEVICES or not set(d["selects"]) <= set(MODES):
            raise ValueError(f"{where}: device {d['device']!r} or modes {d['selects']} not in {sorted(DEVICES)}, {MODES}")  # noqa: E501
        if not d["beyond_print"].strip():
            raise ValueError(f"{where}: say what the reading adds to the printed table")
        out.append(d)
    if [d["address"] for d in out] != list(printed):
        raise ValueError(f"grabber:table2: readings for {[d['address'] for d in out]}, printed inputs {list(printed)}")  # noqa: E501
    return out


def claimed_modes(paper=None) -> list[str]:
    """The modes secs. 2.1-2.2 claim (``sec22_modes.claimed``), each quoted from its record."""
    paper = paper or _paper()
    out = []
    for c in paper.record("sec22_modes")["claimed"]:
        if c["mode"] not in MODES or c["quote"] not in paper.record(c["of"]).text:
            raise ValueError(f"grabber:sec22_modes: {c['mode']!r} ({c['quote']!r}) is not a mode {MODES} quoted from {c['of']}")  # noqa: E501
        out.append(c["mode"])
    return out


@cache
def _operands() -> tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]:
    """The operands Figures 3-6 read and write, and their instructions, in print order."""
    from analysis.plc import stl_eval as stl

    reads, writes, ops = [], [], []
    for f in (3, 4, 5, 6):
        for ins in stl.parse_stl(_paper().text(f"figure{f}")):
            ops.append(ins.op)
            w, r = stl.defs_uses(ins)
            reads += [*r, *(a for a in ins.args if ins.op in ("LD", "A", "AN", "O"))]
            writes += list(w)
    return tuple(reads), tuple(writes), tuple(ops)


def input_reads() -> dict[str, int]:
    """How often Figures 3-6 read each input Table 2 lists, by address."""
    reads = _operands()[0]
    return {addr: reads.count(addr) for _name, _code, addr in _paper().group("TABLE2")["inputs"]}


def census() -> dict[str, int]:
    """The printed Figures 3-6's operand census: reads of the start (SB1) and stop (SB2)
    inputs, PLS instructions, PTO setup writes (SM), writes of the direction outputs, count
    subtractions, and Table 2's inputs our reading takes for reference or limit switches
    (:func:`input_devices`)."""
    reads, writes, ops = _operands()
    inputs = {code: addr for name_, code, addr in _paper().group("TABLE2")["inputs"]}
    direction = [a for n_, _, a in _paper().group("TABLE2")["outputs"] if n_ == "方向信号"]
    return {
        "start_reads": reads.count(inputs["SB1"]), "stop_reads": reads.count(inputs["SB2"]),
        "pls": ops.count("PLS"), "pto_setup": sum(a.startswith("SM") for a in writes),
        "direction_writes": sum(writes.count(a) for a in direction),
        "count_subtractions": sum(op in ("-D", "-I") for op in ops),
        "reference_inputs": sum(d["device"] in ("reference switch", "limit switch") for d in input_devices()),  # noqa: E501
    }  # fmt: skip


def fig4_repaired() -> str:
    """Figure 4 with only the unit and the in-place division repaired (grabber-stl-degrees,
    grabber-stl-vd12), to run its scans with the other defects out of the way."""
    lines = [ln for ln in text("figure4").splitlines() if not ln.startswith("/R     360.0")]
    i = next(k for k, ln in enumerate(lines) if ln.startswith("MOVR   VD12, VD16"))
    return "\n".join([*lines[: i + 1], "*R 57.29578, VD16", "/R 360.0, VD16", *lines[i + 1 :]])


def text(rid: str) -> str:
    """A listing as printed (the transcription's // notes dropped)."""
    return "\n".join(ln.split("//")[0].rstrip() for ln in _paper().text(rid).splitlines())


def hmi_targets() -> dict[str, np.ndarray]:
    """Figures 3-4 (MOVR inputs, Figure 4 repaired) run over scans: the power-up scan, then an
    HMI writes another Table 4 target (one whose c1 differs) into VD0-VD8 and the program scans
    again. 上电置1 read as SM0.0 (every network every scan) and SM0.1 (the first scan only)."""
    from analysis.kinematics.pulses import angles_to_pulses
    from analysis.plc import stl_eval as stl

    fig3 = text("figure3").replace("MOVD   100,", "MOVR   100.0,").replace("MOVD   600,", "MOVR   600.0,")  # noqa: E501
    scan = stl.parse_stl(fig3 + "\n" + fig4_repaired())
    first = stl.evaluate(scan)
    P, th = front_up(targets_table4())
    want = angles_to_pulses(th)[:, 0]
    other = want != first.dint("VD16")  # targets the compiled-in one does not already solve
    P, want = P[other], want[other]
    sm00, sm01 = [], []
    for p in P:
        mem = first.copy()
        for a, v in zip(("VD0", "VD4", "VD8"), p, strict=True):
            mem.set_real(a, v)
        sm00.append(stl.evaluate(scan, mem).dint("VD16"))
        sm01.append(mem.dint("VD16"))  # SM0.1: no network runs after the first scan
    return {"follows_sm00": np.array(sm00) == want, "follows_sm01": np.array(sm01) == want,
            "c1_sm00": np.array(sm00), "c1_wanted": want}  # fmt: skip


def table4_rows() -> dict[str, np.ndarray]:
    """Every printed row: theta1 as the printed listings give it (Figures 3-4 executed on the
    row's target, byte-accurately) and as eq. 6 gives it, against the printed cell."""
    from analysis.audit.kinds.table import cell_matches
    from analysis.plc import stl_eval as stl
    from analysis.plc.paper_listings import figure_text

    rows = list(_paper().table_rows("table4").values())
    P = targets_table4()
    listing, formula, config = [], [], []
    for p, r in zip(P, rows, strict=True):
        run = stl.parse_stl(figure_text(3, p) + "\n" + figure_text(4, p))
        c1 = stl.evaluate(run).dint("VD16")
        listing.append(cell_matches(r["theta1_deg"], c1 * 360 / 4000))
        formula.append(cell_matches(r["theta1_deg"], np.degrees(np.arctan(p[1] / p[0]))))
        config.append((round(float(np.hypot(p[0], p[1])), 6), p[2]))
    reach = paper_arm().is_reachable(P)
    first = [config.index(c) == i and reach[i] for i, c in enumerate(config)]
    same = [int((P == p).all(axis=1).sum()) for p in P]
    return {"listing_theta1_matches": np.array(listing), "formula_theta1_matches": np.array(formula),  # noqa: E501
            "new_configuration": np.array(first), "repeats": np.array(same),
            "Pz": P[:, 2], "Px": P[:, 0]}  # fmt: skip


@cache
def executed() -> dict[str, list[int]]:
    """Figures 3-4 run byte-accurately on every Table 4 target, IEEE and flush-to-zero."""
    from analysis.plc import stl_eval as stl
    from analysis.plc.paper_listings import figure_text

    out = {"ieee": [], "ftz": []}
    for p in targets_table4():
        run = stl.parse_stl(figure_text(3, p) + "\n" + figure_text(4, p))
        out["ieee"].append(stl.evaluate(run).dint("VD16"))
        out["ftz"].append(stl.evaluate(run, ftz=True).dint("VD16"))
    return out


@cache
def movd_damage() -> dict[str, list]:
    """The whole printed program (Figures 3, 4, 6, 5 in one scan, byte-accurately, Figure 6's
    VDD0 read as theta1 and Px) on every Table 4 target, Figure 3 as printed (MOVD of integers)
    and with MOVR: what MOVD itself changes. Figure 4's c1 (VD16) is the same both ways (Py/Px of
    two denormals is exact); Pz - L1 (VD72 in Figure 5, VD176 in Figure 6) becomes -660 (the
    denormal Pz vanishes against 660), so theta2 and theta3 are computed for Pz = 0."""
    from analysis.plc import stl_eval as stl
    from analysis.plc.paper_listings import figure_text

    vdd0 = {"COS": "VD12", "SIN": "VD12", "*R": "VD0", "MOVR": "VD0"}
    keys = ("c1_movd", "c1_movr", "vd72_movd", "vd72_movr", "vd176_movd", "vd176_movr")
    out: dict[str, list] = {k: [] for k in (*keys, "pz_minus_l1")}
    for p in targets_table4():
        for how, real in (("movd", False), ("movr", True)):
            run = "\n".join(figure_text(f, p, real, vdd0) for f in (3, 4, 6, 5))
            mem = stl.evaluate(stl.parse_stl(run))
            out[f"c1_{how}"].append(mem.dint("VD16"))
            out[f"vd72_{how}"].append(float(mem.real("VD72")))
            out[f"vd176_{how}"].append(float(mem.real("VD176")))
        out["pz_minus_l1"].append(float(p[2]) - 660.0)
    return out


def workspace() -> dict[str, np.ndarray]:
    """Rounding to whole pulses (eqs. 20-22) on 200 seeded configurations: the commanded joint
    angle's error [deg]; the gripper's error [mm] at 50,000 seeded targets."""
    from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles

    arm = paper_arm()
    rng = np.random.default_rng(2016)
    q = sample_q(arm, rng, 200)
    dq = np.abs(pulses_to_angles(angles_to_pulses(q)) - q).max(axis=-1)
    p = arm.shoulder + rng.uniform(-1, 1, (50_000, 3)) * arm.geometry["reach_outer"]
    P, th = front_up(p)
    err = np.linalg.norm(arm.fk(pulses_to_angles(angles_to_pulses(th))) - P, axis=-1)
    tip = np.resize(err, len(q))
    tip[0] = err.max()
    return {"joint_error_deg": np.degrees(dq), "tip_error_mm": tip}


def stl_constants() -> dict[str, np.ndarray]:
    """The STL's pulses-per-revolution constant changed, the drivers left at sec. 3's 4000:
    the largest joint error over angles in [-180, 180] deg (every half pulse among them)."""
    s = np.array([1000.0, 2000.0, 4000.0, 8000.0, 16000.0, 40000.0])
    half = (np.arange(-2000, 2000) + 0.5) * 360 / 4000  # every half pulse: rounding's worst
    th = np.radians(np.concatenate([np.linspace(-180, 180, 1441), half]))
    moved = np.round(th[None] * s[:, None] / (2 * np.pi)) * 2 * np.pi / 4000
    return {"stl": s, "max_error_deg": np.degrees(np.abs(moved - th[None]).max(axis=1))}


def random_poses() -> dict[str, np.ndarray]:
    """200 seeded rotations (uniform): can the arm's hand take them? (a_z of A1 A2 A3 is 0.)"""
    q = np.random.default_rng(2016).normal(size=(200, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)  # uniform unit quaternions (w, x, y, z)
    a_z = 1 - 2 * (q[:, 1] ** 2 + q[:, 2] ** 2)  # the rotation's (3, 3) entry
    return {"orientation_reachable": np.abs(a_z) < 1e-9}


def printed_data() -> dict[str, np.ndarray]:
    """Printed numbers against each other: sec. 3's arm lengths and Table 3's (d1, a2, a3);
    sec. 3's resolution and 360 deg over its pulses per turn; sec. 2.4.1's example target,
    Table 4 row 1's and the values Figure 3 moves into VD0-VD8."""
    p, t3 = _paper(), _paper().table_rows("table3")
    res = p.record("sec3_resolution")
    fig3 = {a[1]: float(a[0]) for ins in stl_eval.parse_stl(text("figure3")) if ins.op == "MOVD" for a in [ins.args]}  # noqa: E501
    return {"sec3_lengths": np.array(p.record("sec3_lengths")["values"]),
            "table3_lengths": np.array([float(t3["1"]["d_mm"]), float(t3["2"]["a_mm"]), float(t3["3"]["a_mm"])]),  # noqa: E501
            "resolution_deg": res["resolution_deg"], "turn_over_pulses": 360 / res["pulses_per_rev"],  # noqa: E501
            "example_target": np.array(p.record("sec241_target")["target"]), "table4_row1": targets_table4()[0],  # noqa: E501
            "figure3_target": np.array([fig3[a] for a in ("VD0", "VD4", "VD8")])}  # fmt: skip

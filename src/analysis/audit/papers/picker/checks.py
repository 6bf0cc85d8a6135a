"""Seed 002's definitions for its checks (``data/registers/picker.toml``). The extraction lost
every displayed equation, Tables 1-2 and Figures 1-4; what is checked is the running text, the
topology and the experiment's design, against the reconstructed mechanism
(:mod:`analysis.kinematics.picker`, ``data/arms/picker.toml``, every dimension ASSUMED but the
two the text prints). Studies the notebook shows: :mod:`analysis.audit.papers.picker.method`."""

from __future__ import annotations

import math
import re

import numpy as np

from analysis.audit.context import Bespoke, context
from analysis.audit.kinds import Result

B = Bespoke("picker")


def _pk():
    from analysis.kinematics import picker as pk

    return pk


def _paper():
    return context("picker").paper


# --- domains ----------------------------------------------------------------------------------
@B.domain("law_samples")
def _laws():
    """The five sec. 4 configurations (t = 1..5 s) under every reading of the laws' units: the
    rank of the 5 x 6 matrix they stack to, and the largest joint turn [rad]."""
    pk, t = _pk(), np.array(_paper().group("EXPERIMENT")["times"])
    a = {r: pk.law_active(t, r) for r in pk.READINGS}
    return {"rank": np.array([np.linalg.matrix_rank(v) for v in a.values()]),
            "max_turn_rad": np.array([float(np.abs(v[:, [0, 2, 3, 4]]).max()) for v in a.values()])}  # fmt: skip  # noqa: E501


@B.domain("wrong_models")
def _wrong():
    """Models with one element wrong, joint values in degrees: the largest per-axis change of
    the five sec. 4 positions (inf: the wrong model cannot assemble, which a test would see)."""
    from analysis.audit.papers.picker import method as st

    errs = st.mutation_errors(_pk().load_picker(), "value, deg")
    return {"change_mm": np.array(list(errs.values()))}


@B.domain("topology")
def _topology():
    """Sec. 2's type (2P4R, 6 DOF) against sec. 4's commanded laws and sec. 3.2's sliders."""
    top, j = _paper().group("TOPOLOGY"), _paper().group("JOINTS")
    laws = _paper().group("EXPERIMENT")["laws"]
    return {k: np.array([v]) for k, v in {
        "dof": top["dof"], "prismatic": top["prismatic"], "revolute": top["revolute"],
        "laws": len(laws), "slider_laws": sum(v["unit"] == "mm/s" for v in laws.values()),
        "sliders": len(j["sliders"])}.items()}  # fmt: skip


@B.domain("slider_pairs")
def _pairs():
    """200 seeded slider settings (x, z) at which link 5 closes the loop A-G-B: how many
    assemblies (the two intersections of |AG| = g, |GB| = b) close it to 1e-9 mm, and how many
    of them lie on one branch (the sign of the arccos fixed, as a closure equation that picks
    the assembly as built would fix it)."""
    p = _pk().load_picker().params
    g, b = p["g"], p["b"]
    rng = np.random.default_rng(2016)
    x, z = rng.uniform(-100, 200, 600), rng.uniform(-100, 200, 600)
    dx, dz = b + x, g - z  # B - A in the arm plane, as the reconstruction has it
    R = np.hypot(dx, dz)
    c = (R**2 + g**2 - b**2) / (2 * g * R)
    keep = np.abs(c) < 1
    dx, dz, c = dx[keep][:200], dz[keep][:200], c[keep][:200]
    n, on_branch = np.zeros(len(c), int), np.zeros(len(c), int)
    for s in (1, -1):
        t3 = np.arctan2(dx, dz) - s * np.arccos(c)
        closes = np.abs(np.hypot(dx - g * np.sin(t3), dz - g * np.cos(t3)) - b) < 1e-9
        n += closes
        on_branch += closes & (s == 1)  # a sign fixed once (the assembly as built) keeps one
    return {"n_assemblies": n, "n_on_branch": on_branch}


@B.domain("prior_methods")
def _prior():
    """The works the introduction reviews ([14]-[18]), each as our reading of the text's words
    for it records it (:func:`analysis.audit.papers.picker.readings.prior_methods`): the same
    method as the paper's contribution?"""
    from analysis.audit.papers.picker.readings import prior_methods

    return prior_methods(context("picker").paper)


@B.domain("structure_claims")
def _structure():
    """Sec. 2's and conclusion 1's claims for the parallelogram arm (stiffness, a large work
    stroke from a small drive stroke, strength under vibration), each as recorded with what
    would show it: is it reported anywhere in the paper, and could the test hardware of sec. 4,
    as our reading of each device records it, have measured it?"""
    from analysis.audit.papers.picker.readings import structure_claims

    return structure_claims(context("picker").paper)


@B.fact()
def test_hardware() -> dict:
    """The test platform of sec. 4 as recorded (``test_platform.devices``): how many devices,
    and what any of them measures."""
    from analysis.audit.papers.picker.readings import test_devices

    devices = test_devices(context("picker").paper)
    measures = sorted({m for d in devices for m in d["measures"]})
    return {"devices": len(devices), "measures": ", ".join(measures) or "nothing"}


@B.domain("r3")
def _r3():
    """Candidate identity elements e of (R3, +): the zero vector and five seeded nonzero
    3-vectors; for each, whether x + e = x at 20 seeded x (``is_identity``) and whether e is
    the zero vector (``is_zero``)."""
    rng = np.random.default_rng(3)
    x = rng.normal(size=(20, 3))
    e = np.vstack([np.zeros(3), rng.normal(size=(5, 3))])
    return {"is_identity": np.array([bool(np.all(x + v == x)) for v in e]),
            "is_zero": np.array([bool(np.all(v == 0)) for v in e])}  # fmt: skip


@B.domain("assumed")
def _assumed():
    """The reconstruction's stand-ins against what the text states: the printed dimensions
    (jaw opening, instrument origin) as printed, the rest marked assumed, the loops closed at
    the reference pose and at the five sec. 4 poses (joint values in degrees)."""
    pk = _pk()
    picker = pk.load_picker()
    rep = pk.replay_experiment(picker=picker)["value, deg"]
    loops = picker.loop_residuals(np.zeros((1, 6)))
    return {"marked_assumed": np.array([len(picker.params.assumed()) >= 10]),
            "assembles": np.array([float(np.max(loops["secondary_position"])) < 1e-9]),
            "replayed": np.array([bool(rep["reachable"].all())])}  # fmt: skip


@B.domain("poe_routes")
def _poe():
    from analysis.audit.papers.picker.poe_checks import cross_check

    return {"ok": np.array([r["ok"] for r in cross_check(n=200)])}


# --- values and predicates --------------------------------------------------------------------
@B.value("wrist_twist")
def _wrist_twist():
    """What display holds the twists of the joints sec. 3.3 has still to solve (the wrist,
    theta6-theta8): the kind of those joints in the reconstruction, then the display count."""
    from analysis.kinematics import poe

    S, _ = _pk().load_picker().open_chain()
    kinds = set(poe.joint_kinds(S[5:8]))
    return f"{kinds.pop()} twist" if len(kinds) == 1 else "mixed"


_LAW_TEXT = re.compile(r"\b(omega|theta)(\d) = (-?\d+(?:\.\d+)?)\*t")


@B.predicate()
def plausible_laws(text: str, ctx):
    """A text of the sec. 4 laws ('omega1 = -5*t, ... [rad/s], integrated' or 'theta1 = -5*t,
    ... [deg]'), with the printed coefficients: does every joint stay within half a turn over
    t = 1..5 s (no joint range is printed; kinematics.picker.PLAUSIBLE_MAX_TURN)?"""
    law = r"(?:omega|theta)\d = -?\d+\*t"
    shape = rf"(?:{law}, ){{3}}{law} \[(rad/s|deg/s|rad|deg)\](?:, integrated from the reference pose| \(joint values\))?"  # noqa: E501
    if not re.fullmatch(shape, text.strip()):
        return Result(False, {"why": "not four laws, a unit and how they are read"})
    found = _LAW_TEXT.findall(text)
    unit = re.search(r"\[(rad/s|deg/s|rad|deg)\]", text)
    printed = {k: float(v["expr"].split("*")[0]) for k, v in _paper().group("EXPERIMENT")["laws"].items()}  # noqa: E501
    laws = {f"omega{i}": float(c) for _, i, c in found}
    if (not found or not unit or len({q for q, _, _ in found}) != 1 or len(found) != 4
            or len(laws) != 4 or any(printed.get(k) != v for k, v in laws.items())):  # fmt: skip
        return Result(False, {"why": "not the printed laws with a unit"})
    velocity = found[0][0] == "omega"
    if velocity != unit[1].endswith("/s") or velocity != ("integrated" in text):
        return Result(False, {"why": "an angle with a rate unit, or the reverse"})
    t = np.array(_paper().group("EXPERIMENT")["times"])
    shape = t**2 / 2 if velocity else t
    scale = math.pi / 180 if unit[1].startswith("deg") else 1.0
    turn = float(np.abs(shape[:, None] * np.array(list(laws.values())) * scale).max())
    return Result(turn <= _pk().PLAUSIBLE_MAX_TURN, {"max_turn_rad": turn})


@B.predicate()
def chain_name(text: str, ctx):
    """The printed sentence of sec. 3.3 with the name it gives the vertical slider's chain: the
    name must be the one sec. 3.2 defines for that chain (the printed definition)."""
    frame = ctx.paper.text("main_chain_called_active")
    m = re.fullmatch(re.escape(frame.rsplit("為", 1)[0]) + r"為(\S+鏈)", text.strip())
    run = re.sub(r"\([a-zāáǎàēéěèīíǐìōóǒòūúǔùǖǘǚǜü]+\)", "", ctx.paper.text("extracted.chains"))
    defined = re.search(r"垂直導軌滑塊所在的運動鏈為(\S+?鏈)", run)  # pinyin glosses dropped
    return Result(bool(m and defined) and m[1] == defined[1], {})


@B.predicate()
def english_chain(text: str, ctx):
    """The English abstract's sentence naming the chain the POE is applied to: 'closed' or
    'open' must be what the reconstruction's main chain is (one screw per joint from the base
    to the tool: a serial, open chain)."""
    frame = ctx.paper.text("english_closed_chain")
    head, tail = frame.split("the closed chain")
    m = re.fullmatch(re.escape(head) + r"the (major \(open\)|closed|open|major) chain" + re.escape(tail), text.strip())  # noqa: E501
    S, _ = _pk().load_picker().open_chain()
    is_open = S.shape[0] == 8
    return Result(bool(m) and ("open" in m[1] or m[1] == "major") == is_open, {})


@B.predicate()
def mobility(text: str, ctx):
    """'N moving links, M one-dof joints' (the parallel part, frame: the rotating seat): does
    the planar Gruebler count 3 N - 2 M equal the two sliders, so that the passive angles
    follow from them? 'main + secondary chain as listed' must count what sec. 3.2 lists: the
    links of both chains and the platform, the sliders and the passive joints."""
    m = re.fullmatch(r"(?:(main \+ secondary chain as listed|with [\w ,'-]+): )?(\d+) moving links, (\d+) one-dof joints", text.strip())  # noqa: E501
    if not m:
        return Result(False, {"why": "not 'N moving links, M one-dof joints'"})
    n, j = int(m[2]), int(m[3])
    if m[1] and m[1].startswith("main"):
        chains, joints = ctx.paper.group("CHAINS"), ctx.paper.group("JOINTS")
        listed = (len(chains["main"]) + len(chains["secondary"]) + 1,
                  len(joints["active"]) + len(joints["passive"]))  # fmt: skip
        if (n, j) != listed:
            return Result(False, {"why": f"sec. 3.2 lists {listed[0]} links, {listed[1]} joints"})
    dof = 3 * n - 2 * j
    return Result(dof == len(ctx.paper.group("JOINTS")["active"]), {"mobility": dof})

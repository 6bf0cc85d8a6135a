"""Seed 001's definitions for its checks (``data/registers/palletizer.toml``): the printed
matrices' product, Craig's link transform, sample domains on the arm of
``data/arms/palletizer.toml`` (every length ASSUMED: the paper prints none; one domain adds an
arm with L1 != L2 so that no check can lean on the assumed L1 = L2) and the facts the evidence
names. The printed method as a model is :mod:`analysis.audit.papers.palletizer.method`."""

from __future__ import annotations

import numpy as np

from analysis.audit.context import Bespoke, context

B = Bespoke("palletizer")


def _arm(**changes):
    from analysis.kinematics.arm import load_arm

    arm = load_arm("palletizer")
    return arm.with_(**changes) if changes else arm


def _S(name):
    return context("palletizer").paper.symbols()[name]


def _st():
    from analysis.audit.papers.palletizer import method as st

    return st


# --- matrices ---------------------------------------------------------------------------------
@B.matrix("craig")
def _craig():
    from analysis.kinematics.dh import link_transform_sym

    args = (_S("theta_i"), _S("d_i"), _S("a_im1"), _S("alpha_im1"))
    return link_transform_sym(*args, "modified")


@B.matrix("standard")
def _standard():
    from analysis.kinematics.dh import link_transform_sym

    return link_transform_sym(_S("theta_i"), _S("d_i"), _S("a_im1"), _S("alpha_im1"), "standard")


for _k, _name in enumerate(("T01", "T12", "T23", "T34", "T45")):
    B.matrix(f"dh_{_name}")(
        lambda k=_k: _st().symbolic_table().transforms_sym([_S(f"theta{i}") for i in range(1, 5)])[k]  # noqa: E501
    )


@B.substitution("eq12")
def _eq12():
    """theta = theta2 + theta3 with eq. 12's printed theta2, theta3 (the level gripper)."""
    paper = context("palletizer").paper
    parts = {p["lhs"]: paper.parse(p["rhs"]) for p in paper.record("eq12")["parts"]}
    return {_S("theta"): parts["theta2"] + parts["theta3"]}


# --- domains ----------------------------------------------------------------------------------
def _values(arm, G) -> dict:
    """Per target: the inputs, the lengths (primed = unprimed, sec. 3) and, measured on the
    forward kinematics of the arm's own IK: the shoulder-wrist distance L4, the included elbow
    angle beta1, the elevation alpha2 of the shoulder-wrist line, alpha (eq. 12: theta2 =
    -pi/2 - alpha), theta1..theta4; alpha1 by the law of cosines from that L4."""
    st = _st()
    L1, L2, L3, h = st.lengths(arm)
    q = arm.solve(G).branch(arm.branches[0])
    f = arm.frames(q)
    a, b, sw = f[:, 2] - f[:, 3], f[:, 4] - f[:, 3], f[:, 4] - f[:, 2]
    rho = np.hypot(G[:, 0], G[:, 1])
    L4 = np.linalg.norm(sw, axis=-1)
    return {
        "X0": G[:, 0], "Y0": G[:, 1], "Z0": G[:, 2], "L1": L1, "L2": L2, "L3": L3, "h": h,
        "L1p": L1, "L2p": L2, "L3p": L3, "L4p": L4, "L4": L4, "rho": rho,
        "alpha1": np.arccos((L1**2 + L4**2 - L2**2) / (2 * L1 * L4)),
        "beta1": np.arccos(np.sum(a * b, -1) / np.linalg.norm(a, axis=-1) / np.linalg.norm(b, axis=-1)),  # noqa: E501
        "alpha2": np.arctan2(sw[:, 2], (sw[:, 0] * G[:, 0] + sw[:, 1] * G[:, 1]) / rho),
        "alpha": -q[:, 1] - np.pi / 2, "beta": q[:, 2] - np.pi / 2, "gamma": q[:, 0],
        **{f"theta{i + 1}": q[:, i] for i in range(4)},  # the motor angles by eq. 12
    }  # fmt: skip


def _targets_on(arm, seed: int) -> dict:
    from analysis.kinematics.arm import Status

    st = _st()
    L1, L2, L3, h = st.lengths(arm)
    q = st.level_configurations(arm, 400, np.random.default_rng(seed))
    extra = np.vstack([st.QUADRANT_TARGETS, [[30.0, 10.0, 100.0], [L2 + L3, 0.0, L1 - h]]])
    G = np.vstack([arm.fk(q), extra])
    v = _values(arm, G[arm.solve(G).status == Status.OK])
    n = len(v["X0"])
    return {k: np.broadcast_to(np.asarray(x, dtype=float), (n,)) for k, x in v.items()}


@B.domain("targets")
def _targets():
    """On the assumed arm and on one with L2 = 150 mm (so that no check leans on the assumed
    L1 = L2: a formula with L1 and L2 swapped fails): 400 seeded level configurations each arm
    solves back (within its elbow stop), the four quadrant targets, a target whose wrist is
    behind the base axis and the initial pose."""
    a, b = _targets_on(_arm(), 20210401), _targets_on(_arm(L2=150.0), 20210402)
    return {k: np.concatenate([a[k], b[k]]) for k in a}


@B.domain("front")
def _front():
    v = context("palletizer").domain("targets")
    keep = v["rho"] > v["L3"] + 1.0  # the wrist in front of the base axis
    return {k: (x[keep] if np.ndim(x) else x) for k, x in v.items()}


def _azimuths(reading: str):
    az = np.radians(np.arange(-179.5, 180.0, 1.0))
    x = np.concatenate([200 * np.cos(az), [0.0, 0.0, 150.0, -150.0]])
    y = np.concatenate([200 * np.sin(az), [150.0, -150.0, 0.0, 0.0]])
    with np.errstate(divide="ignore", invalid="ignore"):
        g = np.arctan(y / x) if reading == "signed" else np.arctan(np.abs(y / x))
    return {"X0": x, "Y0": y, "gamma": np.arctan2(y, x), "gammap": g}


B.domain("azimuths-signed")(lambda: _azimuths("signed"))
B.domain("azimuths-acute")(lambda: _azimuths("acute"))


B.domain("claim_grid")(lambda: _st().claim_grid())
B.domain("arm_family")(lambda: _st().arm_family())
B.domain("wrong_models")(lambda: _st().wrong_models())
B.domain("target_pairs")(lambda: _st().target_pairs())
B.domain("senses")(lambda: _st().senses())


@B.domain("unique_grid")
def _unique():
    """At workspace grid targets, how many of the four solutions each constraint keeps."""
    arm, st = _arm(), _st()
    c = st.uniqueness_counts(arm, st.workspace_grid(arm, 21))
    return {"n_included_lt90": c["interior<90"], "n_stop_front": c["stop+front"],
            "n_solutions": c["reachable"]}  # fmt: skip


@B.domain("initial_pose")
def _initial():
    """Eq. 7's pose: the included angle of forearm and upper arm [deg], and whether the
    corrected IK of its tip returns it."""
    paper = context("palletizer").paper
    t3 = float(paper.parse(paper.record("eq7")["parts"][2]["rhs"]))
    arm = _arm()
    q = np.array([float(paper.parse(p["rhs"])) for p in paper.record("eq7")["parts"][:4]])
    back = arm.ik(arm.fk(q))
    f = arm.frames(q[None])[0]  # frames 2 (shoulder), 3 (elbow), 4 (wrist) of the chain
    upper, fore = f[3] - f[2], f[4] - f[3]
    return {"included_deg": np.array([180.0 - np.degrees(abs(t3))]),
            "ik_returns_eq7": np.array([bool(np.allclose(back, q, atol=1e-9))]),
            "upper_arm_vertical": np.array([bool(np.allclose(upper[:2], 0, atol=1e-9))]),
            "forearm_perpendicular": np.array([bool(abs(upper @ fore) < 1e-9)])}  # fmt: skip


@B.domain("quadrant_targets")
def _quadrants():
    """The four quadrant targets (Z > 0): misses [mm] of the printed chain (the best of the
    readings of H and of eq. 1's arctan; NaN: a formula undefined counts as a miss) and of the
    corrected chain, both through eq. 11 as printed / the matrices' product."""
    arm, st = _arm(), _st()
    G = st.QUADRANT_TARGETS
    best = np.full(len(G), np.inf)
    for H in ("height", "depth"):
        for a in ("signed", "acute"):
            m = st.miss(arm, G, st.ik_chain(arm, G, (), H_reading=H, arctan_reading=a)["q"], eq11="printed")  # noqa: E501
            best = np.fmin(best, np.where(np.isfinite(m), m, np.inf))
    fixed = st.miss(arm, G, st.ik_chain(arm, G, st.FIXES)["q"])
    return {"miss_printed_mm": best, "miss_corrected_mm": fixed}


@B.domain("quadrant3")
def _quadrant3():
    """Targets in quadrant 3 (X0 < 0, Y0 < 0, every whole azimuth, 200 mm from the base axis):
    eq. 6's waist angle under both readings of eq. 1's gamma' (signed arctan(Y0/X0), acute
    arctan|Y0/X0|) against the target's azimuth atan2(Y0, X0) [deg, the smaller error of the two
    readings], and the distance [mm] from the target to the vertical plane the waist turns the
    arm into: a lower bound on any miss, since the chain (d_i = 0, sec. 4.2) keeps the gripper
    in that plane whatever the lengths (no length enters)."""
    az = np.radians(np.arange(-179.5, -90.0, 1.0))
    x, y = 200.0 * np.cos(az), 200.0 * np.sin(az)
    err = []
    for gp in (np.arctan(y / x), np.arctan(np.abs(y / x))):
        gamma = -np.pi / 2 + gp  # eq. 6's case X0 <= 0, Y0 < 0
        err.append(np.abs((gamma - np.arctan2(y, x) + np.pi) % (2 * np.pi) - np.pi))
    worst = np.minimum(*err)
    return {"X0": x, "Y0": y, "rho_mm": np.hypot(x, y), "waist_error_deg": np.degrees(worst),
            "plane_miss_mm": np.hypot(x, y) * np.abs(np.sin(worst))}  # fmt: skip


@B.domain("assumed")
def _assumed():
    """The assumed stand-ins against what the paper does state: lengths from the description
    marked assumed, isosceles (sec. 3), the initial pose and one target per quadrant, Z > 0,
    within the elbow stop (sec. 5)."""
    from analysis.kinematics.arm import Status

    arm, st = _arm(), _st()
    d = arm.description
    L1, L2, L3, h = st.lengths(arm)
    G = np.vstack([st.QUADRANT_TARGETS, [[L2 + L3, 0.0, L1 - h]]])
    quads = {(int(x > 0), int(y > 0)) for x, y, _ in st.QUADRANT_TARGETS}
    return {"marked_assumed": np.array([all(d.parameters[k].status == "assumed" for k in ("L1", "L2", "L3", "h"))]),  # noqa: E501
            "isosceles": np.array([L1 == L2]), "solved": np.array([bool((arm.solve(G).status == Status.OK).all())]),  # noqa: E501
            "quadrants": np.array([len(quads)]), "z_positive": np.array([bool((st.QUADRANT_TARGETS[:, 2] > 0).all())])}  # noqa: E501


@B.domain("citations")
def _citations():
    """Sec. 3 cites the D-H method as [2]; sec. 4 dates it 1955: does [2] carry that year?"""
    import re

    paper = context("palletizer").paper
    year = re.search(r"(\d{4})年", paper.record("dh_method").text)[1]
    return {"dh_year_matches": np.array([year in paper.record("references.2").text])}


@B.domain("own_test_citations")
def _own_test():
    """Sec. 5 cites [9] for the coding test of this paper's method (C++ on Linux): can a work of
    [9]'s year report it (not before the paper's own year), in the language the text names?"""
    import re

    paper = context("palletizer").paper
    own = int(re.search(r"(\d{4})", paper.title)[1])
    ref = paper.record("references.9").text
    year = int(re.findall(r"(\d{4})", ref)[-1])
    return {"cited_year": np.array([year]), "paper_year": np.array([own]),
            "can_report": np.array([year >= own]), "names_cpp": np.array(["C++" in ref])}


# --- predicates and facts ---------------------------------------------------------------------
@B.predicate()
def eq11_label(text: str, ctx):
    """A label 'tij' names the product's entry that eq. 11's printed row 2 is, but for its L3
    terms (the s4L3 slip): printed - entry vanishes with L3 = 0."""
    import re

    from analysis.audit.kinds import Result
    from analysis.audit.kinds.symbolic import is_zero

    m = re.fullmatch(r"t([1-4])([1-4])", text.strip())
    if not m:
        return Result(False, {"why": "not a label t<i><j>"})
    M = ctx.product(["@T01", "@T12", "@T23", "@T34", "@T45"])
    row = ctx.paper.parse(ctx.paper.record("eq11")["parts"][1]["rhs"])
    return Result(is_zero((row - M[int(m[1]) - 1, int(m[2]) - 1]).subs(_S("L3"), 0)), {})


@B.predicate()
def convention(text: str, ctx):
    """The D-H convention eq. 8 is ('standard': Denavit-Hartenberg 1955 / Paul, or 'modified':
    Craig), decided on the cells eq. 8-glyph does not touch (row 1 and row 2 cols 1-2)."""
    from analysis.audit.kinds import Result
    from analysis.audit.kinds.symbolic import is_zero

    name = text.strip()
    if name not in ("standard", "modified"):
        return Result(False, {"why": "not a D-H convention"})
    M, P = ctx.matrix(name if name == "standard" else "craig"), ctx.paper.matrix("eq8")
    cells = [(0, 0), (0, 1), (0, 2), (0, 3), (1, 0), (1, 1)]
    return Result(all(is_zero(P[i, j] - M[i, j]) for i, j in cells), {})


@B.fact()
def dims():
    return _st().assumed_lengths(_arm())


@B.fact()
def quadrant_miss():
    """The printed chain's largest miss [mm] over the four stand-in quadrant targets (the best
    reading of H and of eq. 1's arctan; assumed lengths)."""
    return float(np.max(context("palletizer").domain("quadrant_targets")["miss_printed_mm"]))


@B.fact()
def own_test():
    d = {k: int(v[0]) for k, v in _own_test().items()}
    return {**d, "gap": d["paper_year"] - d["cited_year"]}

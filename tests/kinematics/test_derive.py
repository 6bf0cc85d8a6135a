"""Closed forms derived from the D-H table (analysis.kinematics.derive) against three oracles.

1. The hand-written closed forms of the seed arms (grabber, palletizer, gr1): the derived
   closed form of the same description (its [derive] decisions) gives the same branches,
   named alike, the same angles, statuses and distances, on configurations of the arm and on
   targets all over and outside its reach.
2. FK(IK): on random arms of each family, standard and modified D-H (samples.random_arm), the
   configuration a target was made from is among the derived branches, and every branch
   reaches the target (the project's FK, itself held against Pinocchio).
3. EAIK (the bench extra; skipped, saying so, without it): the same solution sets.

Outside the families a description loads (FK, URDF) and asking for its closed form raises
the reason; the hand-written route stays.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from analysis.kinematics.arm import NoClosedForm, derived_arm, load_arm
from analysis.kinematics.derive import NotDerivable, derive
from analysis.kinematics.derive.oracle import available as eaik_available
from analysis.kinematics.derive.samples import random_arm
from analysis.kinematics.description import load_description
from analysis.kinematics.rpy import pose_from_transform
from analysis.kinematics.status import Status

SEEDS = ("grabber", "palletizer", "gr1")
FAMILIES = ("3R", "4R-kept", "5R")
CONVENTIONS = ("standard", "modified")


def _kept(arm, q):
    """Configurations of a 4R-kept arm: the last parallel joint holds the kept pitch."""
    st = arm.closed_form.structure
    if st.family == "4R-kept":
        s, psi = st.sigma, st.keep[0]
        q = q.copy()
        q[:, 3] = np.angle(np.exp(1j * s[2] * (psi - s[0] * q[:, 1] - s[1] * q[:, 2])))
    return q


def _targets(arm, q):
    T = arm.table.fk(q)
    return T[:, :3, 3] if len(arm.inputs) == 3 else pose_from_transform(T)


@pytest.fixture(scope="module")
def seed_pairs():
    """(hand-written, derived) arms of each seed description (derived once)."""
    return {name: (load_arm(name), derived_arm(name)) for name in SEEDS}


@pytest.fixture(scope="module")
def user_arms(tmp_path_factory):
    """Random arms of each family and convention, written as a user would (a TOML with no
    closed_form), loaded by path: four per (family, convention)."""
    folder = tmp_path_factory.mktemp("arms")
    arms = {}
    for i, (fam, conv) in enumerate((f, c) for f in FAMILIES for c in CONVENTIONS):
        for k in range(4):
            rng = np.random.default_rng(7000 + 10 * i + k)
            path = folder / f"{fam}-{conv}-{k}.toml"
            name = "arm_" + path.stem.replace("-", "_")  # an identifier (the schema's rule)
            path.write_text(random_arm(rng, fam, conv, name=name), encoding="utf-8")
            arms[(fam, conv, k)] = load_arm(str(path))
    return arms


# --------------------------------------------------------------------------- 1. seed arms
@pytest.mark.parametrize("name", SEEDS)
def test_seed_arm_derived_branches_equal_hand_written(name, seed_pairs, rng):
    hand, der = seed_pairs[name]
    assert der.branches == hand.branches and der.inputs == hand.inputs
    assert der.closed_form.family == {"grabber": "3R", "palletizer": "4R-kept", "gr1": "5R"}[name]
    q = _kept(der, rng.uniform(-np.pi, np.pi, (3000, hand.n_joints)))
    p = _targets(hand, q)
    a, b = hand.solve(p, limits=False), der.solve(p, limits=False)
    assert (a.status == b.status).all() and (a.ok == b.ok).all()
    assert a.ok.any(axis=1).all()  # every configuration solves back (its own branch at least)
    # the same angle on the same branch name: no 2 pi apart either (wrapping conventions)
    assert np.abs(a.theta - b.theta)[a.ok].max() < 1e-9
    # every derived branch reaches the target
    reach = der.table.fk(np.nan_to_num(b.theta))
    assert np.abs(reach[..., :3, 3] - hand.table.fk(q)[:, None, :3, 3])[b.ok].max() < 1e-8


@pytest.mark.parametrize("name", SEEDS)
def test_seed_arm_derived_refusals_equal_hand_written(name, seed_pairs, rng):
    """Targets all over and beyond the reach, on the base axis, with the PLC's band: the
    same status (in the same priority), the same signed distance and joint-limit masks."""
    hand, der = seed_pairs[name]
    R = hand.geometry["reach_outer"] + 150.0
    p = rng.uniform(-R, R, (6000, 3)) + hand.shoulder
    p[:40, :2] = 0.0  # on the base axis
    if len(hand.inputs) == 6:  # poses: reachable ones moved, some turned out of the plane
        q = rng.uniform(-np.pi, np.pi, (6000, 5))
        pose = _targets(hand, q)
        pose[:, :3] += rng.normal(0.0, 120.0, (6000, 3))
        pose[:2000, 3:] += rng.normal(0.0, 3e-4, (2000, 3))
        pose[:40, :2] = 0.0
        p = pose
    for kw in ({}, {"margin_mm": 1e-3, "margin_rad": 2e-5}, {"theta1_on_axis": 0.3}):
        a, b = hand.solve(p, **kw), der.solve(p, **kw)
        assert (a.status == b.status).all(), kw
        assert (a.ok == b.ok).all() and np.allclose(a.outside_mm, b.outside_mm, atol=1e-9)
        both = a.ok & b.ok
        assert np.abs(np.angle(np.exp(1j * (a.theta - b.theta)))[both]).max() < 1e-7
    seen = set(np.unique(b.status).tolist())
    assert {Status.OK, Status.OUT_OF_REACH} <= seen


def test_derived_grabber_is_table4_in_sympy(seed_pairs):
    """The same derived closed form as formulas (the SymPy backend): Table 4 row 1."""
    import sympy as sp

    from analysis.kinematics.symbolic import sympy_ops

    der = seed_pairs["grabber"][1]
    x, y, z = sp.symbols("px py pz", real=True)
    P = {k: sp.Symbol(k, positive=True) for k in der.params}
    q = der.closed_form.ik(sympy_ops, (x, y, z), P, tol=sp.Float(1e-6))["branches"]["front-up"]
    assert q[0] == sp.atan2(y, x)  # eq. 6 with atan2
    vals = {x: 100, y: 100, z: 600, **{P[k]: v for k, v in der.params.items()}}
    deg = [math.degrees(float(sp.N(e.subs(vals)))) for e in q]
    assert np.allclose(deg, [45.0, 10.2087, -155.1291], atol=1e-4)


# --------------------------------------------------------------------------- 2. FK(IK)
@pytest.mark.parametrize("conv", CONVENTIONS)
@pytest.mark.parametrize("fam", FAMILIES)
def test_random_arms_solve_back_their_configurations(fam, conv, user_arms, rng):
    for k in range(4):
        arm = user_arms[(fam, conv, k)]
        assert arm.closed_form.family == fam
        q = _kept(arm, rng.uniform(-np.pi, np.pi, (300, arm.n_joints)))
        T = arm.table.fk(q)
        sol = arm.solve(_targets(arm, q), limits=False)
        assert (sol.status == Status.OK).all()
        dq = np.abs(np.angle(np.exp(1j * (sol.theta - q[:, None, :])))).max(axis=-1)
        assert (np.nan_to_num(dq, nan=9.0) < 1e-7).any(axis=1).all()  # q is a branch
        reach = arm.table.fk(np.nan_to_num(sol.theta))
        miss = np.linalg.norm(reach[..., :3, 3] - T[:, None, :3, 3], axis=-1)[sol.ok]
        bound = 1e-8
        if fam == "5R":
            # a branch whose roll axis the pose puts within orientation_tol of its reach is
            # the nearest reachable pose: the tool point misses by at most about that angle
            # times its distance from the roll axis (twice, for the bound)
            lever = arm.geometry["tool_offset"]
            bound += 2.0 * arm.closed_form.ORIENTATION_TOL_RAD * lever
        assert miss.max() < bound, (fam, conv, k, miss.max())


def test_random_arms_backends_agree(user_arms, rng):
    """The numpy path and the float32 model of the PLC program agree on random arms (the
    compiled kernel: tests/kinematics/test_random_arms.py)."""
    from analysis.kinematics.pulses import angles_to_pulses
    from analysis.plc.model import predict

    for fam in FAMILIES:
        arm = user_arms[(fam, "modified", 0)]
        q = _kept(arm, rng.uniform(-np.pi, np.pi, (400, arm.n_joints)))
        p = _targets(arm, q)
        ref = arm.solve(p, arm.branches[:1], margin_mm=1e-3, margin_rad=2e-5)
        from analysis.kinematics.ops import Float32Ops

        model = predict(arm, p, ops=Float32Ops())
        ok = ref.ok[:, 0] & model.reachable
        assert (ok == ref.ok[:, 0]).mean() > 0.99
        c = angles_to_pulses(ref.theta[ok, 0], np.asarray(arm.params.pulses_per_rev))
        d = np.abs(model.pulses[ok] - c)
        ppr = np.asarray(arm.params.pulses_per_rev)
        assert ((d <= 1) | (d == ppr)).all()  # a half-pulse tie or the wrap cut, no more


# --------------------------------------------------------------------------- refusals
OUTSIDE = {
    "seven joints": ([(90, 0, 300, 0)] + [(90, 50, 0, 0)] * 6, "7 joint"),
    "six joints, 2 across 3": ([(90, 0, 300, 0)] + [(90, 50, 0, 0)] * 5, "2 and 3 of the six"),
    "axes 2, 3 not parallel": ([(90, 0, 300, 0), (35, 250, 0, 0), (0, 200, 0, 0)], "not parallel"),
    "planar, then across": ([(0, 100, 0, 0), (0, 250, 0, 0), (90, 200, 0, 0), (0, 100, 0, 0)],
                            "joints 1 and 2 are parallel"),
    "two joints": ([(90, 0, 300, 0), (0, 250, 0, 0)], "2 joint"),
    "4R without keep": ([(90, 0, 300, 0), (0, 250, 0, 0), (0, 200, 0, 0), (90, 50, 0, 0)], "keep"),
}  # fmt: skip


def _toml(rows, closed_form: str | None = None) -> str:
    head = 'name = "user"\ntitle = "a user arm"\npaper = "none"\n'
    if closed_form:
        head += f'closed_form = "{closed_form}"\n'
    body = "".join(
        f'\n[[rows]]\njoint = "theta{i + 1}"\nalpha_deg = {al}\na = {a}\nd = {d}\n'
        f"theta_offset_deg = {off}\n"
        for i, (al, a, d, off) in enumerate(rows)
    )
    joints = "".join(
        f'\n[[joints]]\nname = "theta{i + 1}"\npulses_per_rev = 4000\n' for i in range(len(rows))
    )
    return head + body + joints


@pytest.mark.parametrize("case", sorted(OUTSIDE))
def test_outside_the_families_refused_with_the_reason(case, tmp_path):
    rows, reason = OUTSIDE[case]
    path = tmp_path / "user.toml"
    path.write_text(_toml(rows), encoding="utf-8")
    arm = load_arm(str(path))  # the arm loads: FK, URDF need no IK
    assert arm.closed_form is None and np.isfinite(arm.fk(np.zeros(arm.n_joints))).all()
    with pytest.raises(NoClosedForm, match=reason) as err:
        arm.solve(arm.fk(np.zeros(arm.n_joints)))
    assert "names no closed_form" in str(err.value) and 'closed_form = "<module>"' in str(err.value)


def test_hand_written_route_stays(tmp_path):
    """A description naming its closed form keeps it, derivable or not."""
    path = tmp_path / "user.toml"
    rows = [(90, 0, "L1", 0), (0, "L2", 0, 0), (0, "L3", 0, 0)]
    text = _toml(rows, "grabber").replace("d = L1", 'd = "L1"')
    text = text.replace("a = L2", 'a = "L2"').replace("a = L3", 'a = "L3"')
    text += "\n[parameters]\nL1 = 600.0\nL2 = 300.0\nL3 = 250.0\n"
    path.write_text(text, encoding="utf-8")
    arm = load_arm(str(path))
    assert arm.description.closed_form == "grabber"
    assert arm.closed_form.__name__ == "analysis.kinematics.arms.grabber"
    assert arm.closed_form.name == "grabber"


@pytest.mark.parametrize(
    ("derive_table", "message"),
    [
        ({"elbow": "sideways"}, "elbow"),
        ({"colour": 1}, "unknown key"),
        ({"forward": [0, 0, 0]}, "not all 0"),
        ({"keep": {"tool_axis": "x", "direction": [0, 0, -1]}}, "4-axis arms"),
        ({"orientation_tol_deg": 0.01}, "5-axis"),
    ],
)
def test_derive_decisions_are_checked(derive_table, message):
    desc = dataclasses.replace(load_description("grabber"), derive=derive_table)
    with pytest.raises(NotDerivable, match=message):
        derive(desc)


def test_keep_must_be_holdable():
    desc = load_description("palletizer")
    for keep, message in (
        ({"tool_axis": "y", "direction": [0, 0, -1]}, "cannot bring"),
        ({"tool_axis": "x", "direction": [0, 1, 0]}, "cannot bring"),
        ({"tool_axis": "up"}, "expected"),
    ):
        d = dataclasses.replace(desc, derive={"elbow": "arm", "keep": keep})
        with pytest.raises(NotDerivable, match=message):
            derive(d)


def test_derived_arm_params_change_reaches_the_closed_form(seed_pairs):
    """The lengths are the parameters' at every call (Params.with_), not numbers frozen when
    the closed form was derived."""
    der = seed_pairs["grabber"][1]
    longer = der.with_(L2=400.0)
    q = np.radians([30.0, 20.0, -70.0])
    p = longer.fk(q)
    assert np.allclose(longer.ik(p), q, atol=1e-12)
    assert not np.allclose(der.fk(q), p)


# --------------------------------------------------------------------------- 3. EAIK
@pytest.mark.skipif(
    not eaik_available(), reason="EAIK is not installed (the bench extra: make bench)"
)
def test_eaik_same_solution_sets(seed_pairs, user_arms, rng):
    """EAIK's solution sets equal the derived ones wherever EAIK solves; where EAIK returns no
    exact solution (it does so on whole 4R and 5R arms, see analysis.kinematics.derive.
    oracle) the derived solutions still reach the pose."""
    from analysis.kinematics.derive.oracle import compare_solution_sets

    solved = dict.fromkeys(FAMILIES, 0)  # arms EAIK solves at every configuration
    for name, (_, arm) in seed_pairs.items():  # the seed arms: EAIK solves them all
        a = compare_solution_sets(arm, _kept(arm, rng.uniform(-np.pi, np.pi, (30, arm.n_joints))))
        assert a.all_equal, (name, a)
    for arm in user_arms.values():
        q = _kept(arm, rng.uniform(-np.pi, np.pi, (15, arm.n_joints)))
        a = compare_solution_sets(arm, q)
        assert a.disagree == 0, (arm.name, a.first_mismatch)
        assert a.max_residual_mm < 1e-6
        solved[a.family] += a.all_equal
    assert min(solved.values()) >= 2, solved  # of 8 per family


def test_kept_pitch_sampler_hook(user_arms, rng):
    """A 4R-kept arm's candidate configurations (the contract's sample_q hook) hold its
    pitch: each solves back on one of its branches."""
    arm = user_arms[("4R-kept", "standard", 0)]
    cf = arm.closed_form
    assert not hasattr(user_arms[("3R", "standard", 0)].closed_form, "sample_q")
    q = cf.sample_q(rng, 200, arm.params, np.array([[-np.pi, np.pi]] * 4))
    sol = arm.solve(_targets(arm, q), limits=False)
    dq = np.abs(np.angle(np.exp(1j * (sol.theta - q[:, None, :])))).max(axis=-1)
    assert (np.nan_to_num(dq, nan=9.0) < 1e-7).any(axis=1).all()
    assert set(cf.STATUSES) == {
        Status.OUT_OF_REACH,
        Status.INSIDE_REACH,
        Status.BASE_AXIS,
        Status.DEGENERATE,
    }

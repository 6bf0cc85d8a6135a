"""analysis.kinematics.poe: exp6 against an independent matrix exponential, POE FK against
the D-H chains of the project and against Pinocchio, the Jacobian against differences.

Tolerances: 1e-9 mm for positions and 1e-12 for rotation entries. Every route composes at
most ~10 float64 rigid motions with lengths and slides <= ~1e3 mm, so round-off is ~1e-12
mm; a wrong sign or a wrong axis point is off by millimetres (see the mutation tests, which
show each comparison can fail).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

from analysis.audit.papers.picker.poe_checks import dh_arm_names
from analysis.kinematics import poe
from analysis.kinematics.arm import load_arm, paper_arm
from analysis.kinematics.dh import DHTable
from analysis.kinematics.params import paper_params
from analysis.kinematics.pinocchio_model import PinocchioPOE, build_poe_model
from helpers import assert_allclose, assert_transform_close

N_CONFIGS = 10_000
ATOL_MM = 1e-9
ATOL_ROT = 1e-12


def expm_reference(A: np.ndarray) -> np.ndarray:
    """exp(A) of one square matrix by scaling and squaring with a 30-term Taylor series:
    no Rodrigues, no closed form, so it checks :func:`poe.exp6` independently."""
    norm = np.abs(A).sum(axis=1).max()
    k = max(0, int(np.ceil(np.log2(norm))) + 1) if norm > 0 else 0
    B = A / 2**k
    E, term = np.eye(len(A)), np.eye(len(A))
    for j in range(1, 30):
        term = term @ B / j
        E = E + term
    for _ in range(k):
        E = E @ E
    return E


def se3_matrix(S, theta) -> np.ndarray:
    w, v = np.asarray(S[:3]) * theta, np.asarray(S[3:]) * theta
    return np.array(
        [[0, -w[2], w[1], v[0]], [w[2], 0, -w[0], v[1]], [-w[1], w[0], 0, v[2]], [0, 0, 0, 0]]
    )


def random_screws(rng, n, prismatic_every=3):
    out = []
    for i in range(n):
        if i % prismatic_every == 1:
            out.append(poe.prismatic_screw(rng.normal(size=3)))
        else:
            out.append(poe.revolute_screw(rng.normal(size=3), rng.uniform(-500, 500, 3)))
    return np.array(out)


def random_q(rng, kinds, shape):
    scale = np.array([np.pi if k == "revolute" else 800.0 for k in kinds])
    return rng.uniform(-1, 1, (*shape, len(kinds))) * scale


def main_arm_screws() -> tuple[np.ndarray, np.ndarray]:
    """The main paper's arm (Table 3) read off its home pose by hand: stretched along +x at
    height L1; waist +z through the origin, shoulder and elbow -y (the D-H z1 = Rx(90 deg) z)
    through (0, 0, L1) and (L2, 0, L1); tool at (L2 + L3, 0, L1) turned Rx(90 deg)."""
    P = paper_params()
    S = np.array(
        [
            poe.revolute_screw([0, 0, 1], [0, 0, 0]),
            poe.revolute_screw([0, -1, 0], [0, 0, P.L1]),
            poe.revolute_screw([0, -1, 0], [P.L2, 0, P.L1]),
        ]
    )
    M = np.eye(4)
    M[:3, :3] = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
    M[:3, 3] = [P.L2 + P.L3, 0.0, P.L1]
    return S, M


def dh_tables() -> dict[str, DHTable]:
    """Every D-H arm of the project: each description in data/arms/ with D-H rows."""
    return {name: load_arm(name).table for name in dh_arm_names()}


def test_every_dh_arm_is_covered():
    assert set(dh_tables()) >= {"grabber", "palletizer"}


# --------------------------------------------------------------------------- exp6
def test_exp6_equals_series_exponential_for_both_kinds(rng):
    S = random_screws(rng, 12)
    th = rng.uniform(-7, 7, 12) * np.where(np.linalg.norm(S[:, :3], axis=1) > 0, 1, 100)
    E = poe.exp6(S, th)
    ref = np.stack([expm_reference(se3_matrix(s, t)) for s, t in zip(S, th, strict=True)])
    assert_transform_close(E, ref, 1e-11, 1e-9, "exp6 vs Taylor expm")


@given(
    w=st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(lambda w: np.linalg.norm(w) > 0.1),
    q=st.lists(st.floats(-500, 500), min_size=3, max_size=3),
    a=st.floats(-10, 10),
    b=st.floats(-10, 10),
    prismatic=st.booleans(),
)
def test_exp6_is_a_one_parameter_group(w, q, a, b, prismatic):
    """exp(S a) exp(S b) = exp(S (a + b)), exp(S 0) = I, and R is a rotation."""
    S = poe.prismatic_screw(w) if prismatic else poe.revolute_screw(w, q)
    Ea, Eb, Eab = poe.exp6(S, a), poe.exp6(S, b), poe.exp6(S, a + b)
    assert_transform_close(Ea @ Eb, Eab, 1e-12, 1e-9, "group law")
    assert_transform_close(poe.exp6(S, 0.0), np.eye(4), 0.0, 0.0, "exp(0)")
    R = Ea[:3, :3]
    assert_allclose(R.T @ R, np.eye(3), 1e-12, "R^T R")
    assert np.linalg.det(R) > 0


def test_exp6_revolute_keeps_its_axis_points_fixed(rng):
    for _ in range(20):
        w, q = rng.normal(size=3), rng.uniform(-500, 500, 3)
        S = poe.revolute_screw(w, q)
        on_axis = q + rng.uniform(-100, 100) * S[:3]
        T = poe.exp6(S, rng.uniform(-np.pi, np.pi))
        assert_allclose(T[:3, :3] @ on_axis + T[:3, 3], on_axis, 1e-9, "axis point moved")


def test_exp6_prismatic_translates_by_v_theta(rng):
    S = poe.prismatic_screw([0.0, 0.6, 0.8])
    th = rng.uniform(-900, 900, (4, 5))
    E = poe.exp6(S, th)
    assert E.shape == (4, 5, 4, 4)
    assert_allclose(E[..., :3, :3], np.broadcast_to(np.eye(3), (4, 5, 3, 3)), 0.0, "R = I")
    assert_allclose(E[..., :3, 3], th[..., None] * [0.0, 0.6, 0.8], 1e-12, "p = v theta")


def test_exp6_vectorised_equals_per_point(rng):
    S = random_screws(rng, 5)
    q = random_q(rng, poe.joint_kinds(S), (3, 7))
    T = poe.fk(S, np.eye(4), q)
    assert T.shape == (3, 7, 4, 4)
    for idx in np.ndindex(3, 7):
        assert_allclose(T[idx], poe.fk(S, np.eye(4), q[idx]), 0.0, f"point {idx}")


def test_symbolic_and_numeric_paths_agree(rng):
    S = random_screws(rng, 4)
    q = random_q(rng, poe.joint_kinds(S), ())
    M = poe.fk(random_screws(rng, 2), np.eye(4), rng.uniform(-1, 1, 2))
    T_sym = poe.fk_sym(S.tolist(), M.tolist(), q.tolist())
    assert_transform_close(np.array(T_sym, dtype=float), poe.fk(S, M, q), 1e-12, 1e-9, "sym")


def test_symbolic_poe_of_the_main_arm_equals_its_symbolic_dh_product():
    """Exact: POE with symbolic L1..L3 (seed 002 eq. 9, the arm's screws read off its home
    pose as in main_arm_screws) equals A1 A2 A3 of Table 1 (main paper eq. 2)."""
    L1, L2, L3 = sp.symbols("L1 L2 L3", positive=True)
    S = [[0, 0, 1, 0, 0, 0], [0, -1, 0, L1, 0, 0], [0, -1, 0, L1, 0, -L2]]
    M = [[1, 0, 0, L2 + L3], [0, 0, -1, 0], [0, 1, 0, L1], [0, 0, 0, 1]]
    q = sp.symbols("theta1:4", real=True)
    A1, A2, A3 = paper_arm().dh_table(symbolic=True).transforms_sym(q)
    diff = (poe.fk_sym(S, M, q) - A1 * A2 * A3).applyfunc(lambda e: sp.simplify(sp.expand_trig(e)))
    assert diff == sp.zeros(4, 4)


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    ("screws", "match"),
    [
        ([[0, 0, 2, 0, 0, 0]], r"screw 0 .*\|omega\| = 2; a revolute screw needs \|omega\| = 1"),
        ([[0, 0, 1, 0, 0, 0], [0, 0, 0, 0, 0, 3]], r"screw 1 .*prismatic screw needs \|v\| = 1"),
        ([[0, 0, 1, 0, 0, 5]], r"screw 0 .*pitch .* only revolute"),
        ([[0, 0, 1, 0, 0, np.nan]], r"screw 0 .* NaN"),
        ([[0, 0, 1, 0, 0]], r"expected \(n, 6\)"),
    ],
)
def test_bad_screws_raise_naming_the_screw_and_the_limit(screws, match):
    with pytest.raises(ValueError, match=match):
        poe.check_screws(screws)
    with pytest.raises(ValueError):
        poe.fk(screws, np.eye(4), np.zeros(len(screws)))


def test_prismatic_screws_are_accepted():
    """A prismatic screw (0, v) slides by v theta (the first look's exp_twist rejected it)."""
    S = [0, 0, 0, 0, 0, 1]
    assert_allclose(poe.exp6(S, 250.0)[:3, 3], [0, 0, 250.0], 0.0, "slide")


def test_exp6_equals_pinocchio_exp6(rng):
    """pin.exp6 of the twist (v, w) theta (Pinocchio orders linear first), both kinds."""
    import pinocchio as pin

    S = random_screws(rng, 9)
    theta = rng.uniform(-4, 4, 9) * np.where(np.linalg.norm(S[:, :3], axis=1) > 0, 1, 100)
    for Si, th in zip(S, theta, strict=True):
        ref = pin.exp6(np.concatenate([Si[3:], Si[:3]]) * th).homogeneous
        assert_transform_close(poe.exp6(Si, th), ref, 1e-12, 1e-9, "exp6 vs pin.exp6")


def test_bad_joint_arrays_and_home_poses():
    S = np.array([[0, 0, 1, 0, 0, 0], [0, 0, 0, 1, 0, 0]], float)
    with pytest.raises(ValueError, match=r"expected \(\.\.\., 2\)"):
        poe.fk(S, np.eye(4), np.zeros(3))
    with pytest.raises(ValueError, match="NaN"):
        poe.fk(S, np.eye(4), [0.0, np.inf])
    bad = np.eye(4)
    bad[0, 0] = 1.1
    with pytest.raises(ValueError, match="not a rigid transform"):
        poe.fk(S, bad, [0.0, 0.0])
    with pytest.raises(ValueError, match="is zero"):
        poe.revolute_screw([0, 0, 0], [1, 2, 3])


# --------------------------------------------------------------------------- POE vs D-H
@pytest.mark.parametrize("name", dh_arm_names())
def test_poe_equals_dh_fk_for_every_dh_arm(rng, name):
    """Screws read off the D-H frames at q = 0 only; the pose at 10,000 seeded q is then
    computed by POE and by the D-H product: two independent routes, one pose."""
    table = dh_tables()[name]
    S, M = poe.screws_from_dh(table)
    assert S.shape == (table.n_joints, 6)
    q = rng.uniform(-2 * np.pi, 2 * np.pi, (N_CONFIGS, table.n_joints))
    assert_transform_close(poe.fk(S, M, q), table.fk(q), ATOL_ROT, ATOL_MM, f"{name}: POE vs D-H")


def test_screws_from_dh_of_table3_are_the_hand_derived_screws():
    S, M = poe.screws_from_dh(paper_arm().dh_table())
    S_c, M_c = main_arm_screws()
    assert_allclose(S, S_c, 1e-12, "screws")
    assert_allclose(M, M_c, 1e-12, "M")


@pytest.mark.parametrize("name", dh_arm_names())
def test_mutated_screw_breaks_the_dh_agreement(rng, name):
    """The comparison above can fail: one flipped axis moves the tool by millimetres, or turns
    it (the GR-1's last joint rolls the hand about the tool axis: only the orientation moves)."""
    table = dh_tables()[name]
    S, M = poe.screws_from_dh(table)
    S = S.copy()
    S[-1] = -S[-1]
    q = rng.uniform(-np.pi, np.pi, (200, table.n_joints))
    T_poe, T_dh = poe.fk(S, M, q), table.fk(q)
    moved = np.linalg.norm(T_poe[..., :3, 3] - T_dh[..., :3, 3], axis=-1)
    turned = np.linalg.norm(T_poe[..., :3, :3] - T_dh[..., :3, :3], axis=(-2, -1))
    assert moved.max() > 1.0 or turned.max() > 0.1, (moved.max(), turned.max())


# --------------------------------------------------------------------------- POE vs Pinocchio
def prismatic_chain(rng):
    """Aligned (both signs) and unaligned prismatic and revolute joints: PZ, PX(-),
    RevoluteUnaligned, PrismaticUnaligned, RY(-), RZ."""
    S = np.array(
        [
            poe.prismatic_screw([0, 0, 1]),
            poe.prismatic_screw([-1, 0, 0]),
            poe.revolute_screw(rng.normal(size=3), rng.uniform(-300, 300, 3)),
            poe.prismatic_screw(rng.normal(size=3)),
            poe.revolute_screw([0, -1, 0], [400.0, 0.0, 250.0]),
            poe.revolute_screw([0, 0, 1], [520.0, 30.0, 0.0]),
        ]
    )
    M = poe.fk(random_screws(rng, 3), np.eye(4), rng.uniform(-1, 1, 3))
    M[:3, 3] += [600.0, 40.0, 300.0]
    return S, M


def test_pinocchio_joint_types_follow_the_axes(rng):
    S, M = prismatic_chain(rng)
    names = [j.shortname() for j in build_poe_model(S, M).joints[1:]]
    assert names == [
        "JointModelPZ",
        "JointModelPX",
        "JointModelRevoluteUnaligned",
        "JointModelPrismaticUnaligned",
        "JointModelRY",
        "JointModelRZ",
    ]
    names = [j.shortname() for j in build_poe_model(*main_arm_screws()).joints[1:]]
    assert names == ["JointModelRZ", "JointModelRY", "JointModelRY"]


@pytest.mark.parametrize("which", ["main arm (3R)", "prismatic chain", *dh_arm_names()])
def test_poe_equals_pinocchio_on_10000_configurations(rng, which):
    """(a) the main paper's arm, screws read off by hand; (b) a chain with prismatic
    joints; every D-H arm of data/arms/ via screws_from_dh."""
    if which == "main arm (3R)":
        S, M = main_arm_screws()
    elif which == "prismatic chain":
        S, M = prismatic_chain(rng)
    else:
        S, M = poe.screws_from_dh(dh_tables()[which])
    q = random_q(rng, poe.joint_kinds(S), (N_CONFIGS,))
    pp = PinocchioPOE(S, M)
    assert pp.model.nq == len(S)
    assert_transform_close(pp.placements(q), poe.fk(S, M, q), ATOL_ROT, ATOL_MM, which)


def test_mutated_pinocchio_model_disagrees(rng):
    S, M = prismatic_chain(rng)
    q = random_q(rng, poe.joint_kinds(S), (200,))
    S_bad = S.copy()
    S_bad[1] = -S_bad[1]
    err = np.abs(PinocchioPOE(S_bad, M).placements(q) - poe.fk(S, M, q)).max()
    assert err > 1.0


# --------------------------------------------------------------------------- Jacobian
def fd_point_jacobian(S, M, q, h):
    cols = []
    for j in range(len(S)):
        dq = np.zeros(len(S))
        dq[j] = h[j]
        p_plus = poe.fk(S, M, q + dq)[..., :3, 3]
        p_minus = poe.fk(S, M, q - dq)[..., :3, 3]
        cols.append((p_plus - p_minus) / (2 * h[j]))
    return np.stack(cols, axis=-1)


def test_point_jacobian_equals_central_differences(rng):
    S, M = prismatic_chain(rng)
    kinds = poe.joint_kinds(S)
    q = random_q(rng, kinds, (500,))
    h = np.array([1e-6 if k == "revolute" else 1e-4 for k in kinds])
    J = poe.point_jacobian(S, M, q)
    assert J.shape == (500, 3, len(S))
    # central differences: truncation ~ h^2 |p| ~ 1e-9, round-off eps |p| / h ~ 1e-7 mm/rad
    assert_allclose(J, fd_point_jacobian(S, M, q, h), 1e-5, "POE J vs central differences")


def test_point_jacobian_of_the_main_arm_equals_arm_jacobian(rng, arm):
    S, M = main_arm_screws()
    q = rng.uniform(-np.pi, np.pi, (1000, 3))
    assert_allclose(poe.point_jacobian(S, M, q), arm.jacobian(q), 1e-9, "J vs Arm.jacobian")


def test_space_jacobian_first_column_is_the_first_screw_and_twist_is_consistent(rng):
    """J_s qdot is the spatial twist: d/dt T T^-1 = [J_s qdot] (finite difference in time)."""
    S, M = prismatic_chain(rng)
    q = random_q(rng, poe.joint_kinds(S), ())
    qd = rng.normal(size=len(S))
    J = poe.space_jacobian(S, q)
    assert_allclose(J[:, 0], S[0], 0.0, "first column")
    dt = 1e-7
    Td = (poe.fk(S, M, q + qd * dt) - poe.fk(S, M, q - qd * dt)) / (2 * dt)
    V = Td @ np.linalg.inv(poe.fk(S, M, q))
    twist = np.array([V[2, 1], V[0, 2], V[1, 0], *V[:3, 3]])
    assert_allclose(J @ qd, twist, 1e-4, "spatial twist")

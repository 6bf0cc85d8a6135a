"""Seed 001's studies (analysis.audit.papers.palletizer.method): the symbolic verdicts on eqs. 8
and 11, the printed IK chain item by item, the four-solution
enumeration (the register's checks are tests/audit/test_registers.py).

Numeric tolerance 1e-9 mm: lengths are a few hundred mm (assumed, data/arms/palletizer.toml:
the paper prints none), float64 round-off ~1e-13 mm; every printed error is >= several mm (the
tests show which). The checks take the lengths as parameters: the verdicts are also tested on
a non-isosceles arm (L2 = 150 mm).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

from analysis.audit.papers.palletizer import method as chk
from analysis.kinematics.arm import load_arm
from helpers import assert_points_close

ATOL_MM = 1e-9
PAL = load_arm("palletizer")


@pytest.fixture(scope="module")
def pal():
    return load_arm("palletizer")



def test_eq11_rows_against_the_product_of_the_printed_matrices():
    res = chk.eq11_residuals()
    assert [r["label"] for r in res] == ["t14", "t34", "t34"]
    assert [r["matches"] for r in res] == [["t14"], ["t24"], ["t34"]]
    assert all(r["fixed_by_c4L3"] for r in res)
    L3, th = sp.Symbol("L3", positive=True), sp.Symbol("theta4", real=True)
    for r in res:
        assert r["residual_vs_match"] != 0
        # the residual is proportional to L3 (sin theta4 - cos theta4): zero at theta4 = pi/4
        assert sp.simplify(r["residual_vs_match"].subs(th, sp.pi / 4)) == 0
        assert L3 in r["residual_vs_match"].free_symbols


def test_eq11_printed_error_is_L3_times_sin_minus_cos(pal, rng):
    q = rng.uniform(-np.pi, np.pi, (1000, 4))
    err = np.linalg.norm(chk.eq11_printed_position(pal, q) - pal.fk(q), axis=-1)
    np.testing.assert_allclose(
        err, pal.params.L3 * np.abs(np.sin(q[:, 3]) - np.cos(q[:, 3])), atol=1e-9
    )


def test_symbolic_table_matches_the_arm_description(pal):
    """The D-H rows read off the printed matrices, with the description's lengths, are the
    chain of data/arms/palletizer.toml."""
    sym = chk.symbolic_table()
    S = chk.S
    subs = {
        S["L1"]: pal.params.L1,
        S["L2"]: pal.params.L2,
        S["L3"]: pal.params.L3,
        S["h"]: pal.params.h,
    }
    q = np.array([0.3, -1.1, 0.7, 2.0])
    T_sym = sp.eye(4)
    for A in sym.transforms_sym(q.tolist(), exact=False):
        T_sym = T_sym * A
    np.testing.assert_allclose(np.array(T_sym.subs(subs), float), pal.table.fk(q), atol=1e-9)


def test_eq8_verdicts():
    v = chk.eq8_checks()
    assert v["eq8 as printed == Craig"] is False
    assert v["eq8 with alpha for a in sin/cos == Craig"] is True
    assert v["T12 from eq8 as printed"] is False
    assert all(v[f"{m} == modified D-H row"] for m in ("T01", "T12", "T23", "T34", "T45"))


def reachable(pal, rng, n=500):
    G = rng.uniform([-420, -420, 0], [420, 420, 330], (8 * n, 3))
    q = chk.all_ik(pal, G)[:, 0]
    rho = np.hypot(G[:, 0], G[:, 1])
    L4 = np.hypot(rho - pal.params.L3, G[:, 2] + pal.params.h)
    keep = np.isfinite(q).all(-1) & (L4 < 0.99 * (pal.params.L1 + pal.params.L2)) & (rho > 1)
    return G[keep][:n]


def test_corrected_chain_reaches_and_each_printed_item_misses(pal, rng):
    G = reachable(pal, rng)
    q = chk.ik_chain(pal, G, chk.FIXES)["q"]
    assert_points_close(pal.fk(q), G, ATOL_MM, "corrected chain")
    front = G[np.hypot(G[:, 0], G[:, 1]) > pal.params.L3 + 1]
    for item in ("alpha", "theta4"):  # wrong on every target
        m = chk.miss(pal, front, chk.ik_chain(pal, front, set(chk.FIXES) - {item})["q"])
        assert np.nanmin(m) > 1.0, item
    # beta1 without arccos is right only near the fixed point cos(b) = b (b = 0.739 rad)
    m = chk.miss(pal, front, chk.ik_chain(pal, front, set(chk.FIXES) - {"beta1"})["q"])
    assert np.mean(m > 1.0) > 0.95 and np.median(m) > 100.0
    gam = chk.miss(pal, G, chk.ik_chain(pal, G, set(chk.FIXES) - {"gamma"})["q"])
    assert (gam[G[:, 0] > 0] < 1e-6).all() and (gam[(G[:, 0] < 0) & (G[:, 1] < 0)] > 1).all()


def test_ik_chain_matches_the_shared_closed_form(pal, rng):
    """Two independent codings of the corrected IK agree: ik_chain with every item fixed and
    the shared solver (analysis.kinematics.arms.palletizer via Arm.solve, limits off so that
    targets beyond the elbow stop are compared too). 1e-12 rad: both are float64 chains of
    a few transcendental calls on the same inputs."""
    G = reachable(pal, rng)
    ref = pal.solve(G, "front-up", limits=False).branch("front-up")
    np.testing.assert_allclose(chk.ik_chain(pal, G, chk.FIXES)["q"], ref, atol=1e-12)


@given(
    x=st.floats(-420, 420),
    y=st.floats(-420, 420),
    z=st.floats(0, 330),
)
def test_all_four_solutions_reach_and_are_level(x, y, z):
    pal = PAL
    G = np.array([x, y, z])
    q = chk.all_ik(pal, G)
    ok = np.isfinite(q).all(-1)
    if ok.any():
        assert_points_close(pal.fk(q[ok]), np.broadcast_to(G, (ok.sum(), 3)), 1e-8, "branch")
        level = q[ok, 1] + q[ok, 2] + q[ok, 3] - np.pi / 2  # 0 modulo 2 pi (theta2, 4 wrapped)
        assert np.allclose(np.angle(np.exp(1j * level)), 0.0, atol=1e-12)
        t3 = q[ok, 2]
        # up/down pairs share the interior elbow angle: the '< 90 deg' limit cannot split them
        for k in (0, 2):
            if ok[k] and ok[k + 1]:
                assert np.isclose(abs(q[k, 2]), abs(q[k + 1, 2]))
        assert (np.abs(t3) <= np.pi + 1e-12).all()


def test_uniqueness_counts_are_even_for_the_angle_limit(pal):
    grid = chk.workspace_grid(pal, 21)
    c = chk.uniqueness_counts(pal, grid)
    for key in ("reachable", "interior<90", "between-directions<90"):
        assert set(np.unique(c[key])) <= {0, 2, 4}, key
    assert set(np.unique(c["elbow-up"])) <= {1, 2}
    assert (c["elbow-up+front"] == 1).all()


def test_gamma_eq6_readings():
    x = np.array([200.0, -200.0, -200.0, 200.0, 0.0, -5.0])
    y = np.array([100.0, 100.0, -100.0, -100.0, 7.0, 0.0])
    ref = np.arctan2(y, x)
    s, a = chk.gamma_eq6(x, y, "signed"), chk.gamma_eq6(x, y, "acute")
    assert np.isclose(s[[0, 3]], ref[[0, 3]]).all() and not np.isclose(s[[1, 2]], ref[[1, 2]]).any()
    assert np.isclose(a[[0, 1]], ref[[0, 1]]).all() and not np.isclose(a[[2, 3]], ref[[2, 3]]).any()
    assert np.isnan(s[4:]).all() and np.isnan(a[4:]).all()
    with pytest.raises(ValueError, match="reading"):
        chk.gamma_eq6(1.0, 1.0, "degrees")


def test_ik_chain_rejects_unknown_items(pal):
    with pytest.raises(ValueError, match="unknown item"):
        chk.ik_chain(pal, [100.0, 0.0, 50.0], ("eq99",))
    with pytest.raises(ValueError, match="H_reading"):
        chk.ik_chain(pal, [100.0, 0.0, 50.0], (), H_reading="up")


@pytest.mark.parametrize("L2", [200.0, 150.0])
def test_fk_of_ik_through_pinocchio_on_10000_configurations(L2):
    """G = Pinocchio FK of 10,000 seeded level configurations inside the elbow stop; the
    shared solver's IK of G, through Pinocchio again, returns G within 1e-9 mm (observed
    ~1e-12: float64 on lengths <= 400 mm; the margin of 2 deg to the fold keeps acos
    well-conditioned) and the very angles it started from (the IK is unique there). L2 = 150:
    the non-isosceles family works the same."""
    arm = load_arm("palletizer")
    arm = arm if L2 == arm.params.L2 else arm.with_(L2=L2)
    r = chk.fk_ik_pinocchio(arm, 10_000)
    assert r["n"] == 10_000 and r["all_ok"] and r["status"] == {0: 10_000}
    assert r["max_err_mm"] < ATOL_MM
    assert r["max_dq_rad"] < 1e-10


def test_level_configurations_face_the_target_and_keep_the_gripper_level(pal, rng):
    q = chk.level_configurations(pal, 500, rng)
    np.testing.assert_allclose(
        np.mod(q[:, 1:].sum(axis=1) - np.pi / 2 + 1, 2 * np.pi) - 1, 0, atol=1e-12
    )
    p = pal.fk(q)
    assert (p[:, 0] * np.cos(q[:, 0]) + p[:, 1] * np.sin(q[:, 0]) > 1.0).all()
    assert ((q[:, 2] > np.pi / 2) & (q[:, 2] < np.pi)).all()


def test_the_stop_makes_the_front_solution_unique(pal):
    """Under the signed stop each kept target has exactly one solution with the waist facing
    it; unsigned readings of the angle give even counts (the mirror pose), never 1."""
    grid = chk.workspace_grid(pal, 21)
    c = chk.uniqueness_counts(pal, grid)
    assert set(np.unique(c["stop"])) <= {0, 1, 2}
    kept = c["stop"] > 0
    assert (c["stop+front"][kept] == 1).all() and (c["stop+front"][~kept] == 0).all()
    assert (c["stop"] == 2).any()  # the waist-reversed pose also fits the stop somewhere

"""analysis.kinematics.arm: the paper's 3R arm. FK (eq. 2), closed-form IK (corrected eqs. 6-19, all
four branches), Jacobian, reach and base-axis handling, Table 4.

Independent references: the D-H chain of :mod:`analysis.kinematics.dh` (FK), SymPy derivatives of
eq. 2's P column (Jacobian, det J), central finite differences, Pinocchio, geometric
facts (distance to the shoulder, which side of the shoulder-wrist line the elbow is on),
and the paper's printed Table 4 (data/table4.csv, read as text).

Tolerances
----------
``ATOL_MM = 1e-9`` mm for positions: coordinates are <= ~1.2e3 mm, float64 round-off is
eps * 1e3 ~ 2e-13 mm per operation, and the closed form takes a few dozen operations
(measured worst case over 4e5 random targets: 9e-13 mm). 1e-9 mm is ~1e-12 relative,
while any wrong sign or quadrant is off by millimetres.
``ATOL_RAD = 1e-9`` rad for recovered angles, valid away from the singularities listed
at :func:`regular`: there acos has a condition number <= 1 / |sin theta3| <= 1e4.
"""

from __future__ import annotations

import doctest
import math
import re

import numpy as np
import pandas as pd
import pytest
import sympy as sp
from hypothesis import assume, given
from hypothesis import strategies as st

from analysis.kinematics.arm import (
    BRANCHES,
    DEFAULT_TOL_MM,
    Arm,
    BaseAxisError,
    IKSolutions,
    Status,
    UnreachableError,
    as_points,
    paper_arm,
)
from analysis.kinematics.params import data_dir
from analysis.kinematics.pinocchio_model import PinocchioArm
from helpers import (
    angle_diff,
    assert_allclose,
    assert_angles_close,
    assert_points_close,
    contains_angles,
)

ATOL_MM = 1e-9
ATOL_RAD = 1e-9
TOL = 1e-6  # mm, the documented reach / base-axis tolerance (DEFAULT_TOL_MM)
FRONT = {"front-up": True, "front-down": True, "back-up": False, "back-down": False}
UP = {"front-up": True, "front-down": False, "back-up": True, "back-down": False}


# --- helpers -------------------------------------------------------------------------------


def shell_point(arm: Arm, D, azimuth, elevation):
    """Point at distance D [mm] from the shoulder in direction (azimuth, elevation) [rad]."""
    D, azimuth, elevation = np.broadcast_arrays(
        *(np.asarray(v, float) for v in (D, azimuth, elevation))
    )
    u = np.stack(
        [
            np.cos(elevation) * np.cos(azimuth),
            np.cos(elevation) * np.sin(azimuth),
            np.sin(elevation),
        ],
        axis=-1,
    )
    return arm.shoulder + D[..., None] * u


def elbow_side(arm: Arm, q, p):
    """Twice the signed area of (shoulder, wrist p, elbow) in the vertical plane through
    the target's azimuth, oriented so that > 0 means the elbow is ABOVE the shoulder-wrist
    line (the normal to the line with a positive z component). Needs p off the base axis.
    |value| = L2 L3 |sin theta3|."""
    p = np.asarray(p, float)
    e = arm.elbow(q)
    u = p[..., :2] / np.linalg.norm(p[..., :2], axis=-1, keepdims=True)  # target azimuth
    r_p, z_p = np.sum(p[..., :2] * u, axis=-1), p[..., 2] - arm.params.L1  # r_p > 0
    r_e, z_e = np.sum(e[..., :2] * u, axis=-1), e[..., 2] - arm.params.L1
    return r_p * z_e - z_p * r_e


def regular(arm: Arm, q):
    """Configurations away from the IK singularities: the wrist at least 1e-3 mm off the
    base axis (theta1 defined) and |sin theta3| >= 1e-4 (elbow neither stretched nor
    folded, where the up and down branches merge and acos loses digits)."""
    L2, L3 = arm.params.L2, arm.params.L3
    r = L2 * np.cos(q[..., 1]) + L3 * np.cos(q[..., 1] + q[..., 2])
    return (np.abs(r) >= 1e-3) & (np.abs(np.sin(q[..., 2])) >= 1e-4)


def check_solutions(arm: Arm, p, sol: IKSolutions, atol_mm=ATOL_MM):
    """Every ok branch lands on p; NaN exactly where not ok."""
    assert np.isnan(sol.theta[~sol.ok]).all()
    assert np.isfinite(sol.theta[sol.ok]).all()
    reached = arm.fk(np.where(sol.ok[..., None], sol.theta, 0.0))  # fk refuses NaN
    err = np.linalg.norm(reached - np.asarray(p)[..., None, :], axis=-1)
    assert (err[sol.ok] <= atol_mm).all(), (
        f"max FK(IK(p)) error {err[sol.ok].max():.3e} mm > {atol_mm:g}"
    )


# --- FK -------------------------------------------------------------------------------------


def test_fk_equals_dh_chain(arm, rng):
    """Eq. 2's P column (hand-written fast path) equals T3 = A1 A2 A3 from the D-H rows."""
    q = rng.uniform(-2 * np.pi, 2 * np.pi, (5000, 3))
    T = arm.dh_table().fk(q)
    assert_points_close(arm.fk(q), T[..., :3, 3], ATOL_MM, "fk vs D-H chain")
    A = arm.dh_table().transforms(q)
    assert_points_close(arm.elbow(q), (A[:, 0] @ A[:, 1])[..., :3, 3], ATOL_MM, "elbow vs A1 A2")


def test_fk_shapes(arm, rng):
    q = rng.uniform(-np.pi, np.pi, (2, 3, 4, 3))
    assert arm.fk(q).shape == (2, 3, 4, 3)
    assert arm.fk(q[0, 0, 0]).shape == (3,)
    assert arm.elbow(q).shape == (2, 3, 4, 3)
    assert arm.jacobian(q).shape == (2, 3, 4, 3, 3)
    for bad in ([0.1, 0.2], np.zeros((4, 2)), 0.5):
        with pytest.raises(ValueError, match=r"expected \(\.\.\., 3\)"):
            arm.fk(bad)


def test_fk_link_lengths(arm, rng):
    """|elbow - shoulder| = L2 and |wrist - elbow| = L3 for every configuration."""
    q = rng.uniform(-np.pi, np.pi, (2000, 3))
    assert_allclose(
        np.linalg.norm(arm.elbow(q) - arm.shoulder, axis=-1), arm.params.L2, ATOL_MM, "L2"
    )
    assert_allclose(np.linalg.norm(arm.fk(q) - arm.elbow(q), axis=-1), arm.params.L3, ATOL_MM, "L3")


# --- IK property tests -------------------------------------------------------------------


@given(
    D=st.floats(110.0, 510.0),
    azimuth=st.floats(-np.pi, np.pi),
    elevation=st.floats(-np.pi / 2, np.pi / 2),
)
def test_fk_of_ik_is_p_for_all_four_branches(arm, D, azimuth, elevation):
    """FK(IK(p)) = p for all four branches over the reachable shell, with the branches'
    defining properties checked geometrically."""
    p = shell_point(arm, D, azimuth, elevation)
    sol = arm.solve(p)
    rho = math.hypot(p[0], p[1])
    if rho <= TOL:  # on the base axis: no theta1 without the caller's choice
        assert sol.status == Status.BASE_AXIS and not sol.ok.any() and np.isnan(sol.theta).all()
        sol = arm.solve(p, theta1_on_axis=azimuth)
        check_solutions(arm, p, sol, ATOL_MM + 2 * rho)
        assert sol.ok.all()
        return
    assert sol.status == Status.OK and sol.ok.all() and sol.outside_mm <= TOL
    check_solutions(arm, p, sol)
    phi = math.atan2(p[1], p[0])
    side = elbow_side(arm, sol.theta, p)
    for b, name in enumerate(sol.branches):
        t1, _, t3 = sol.theta[b]
        assert_angles_close(t1, phi if FRONT[name] else phi + np.pi, 1e-12, f"{name} theta1")
        if abs(side[b]) > 1e-6:  # elbow not on the shoulder-wrist line (stretched/folded)
            assert (side[b] > 0) == UP[name], f"{name}: elbow side {side[b]}"
            assert (t3 < 0) == (FRONT[name] == UP[name]), f"{name}: theta3 = {t3}"
    assert (sol.theta >= -np.pi).all() and (sol.theta <= np.pi).all()


@given(
    t1=st.floats(-np.pi, np.pi),
    t2=st.floats(-np.pi, np.pi),
    t3=st.floats(-np.pi, np.pi),
)
def test_ik_of_fk_contains_q(arm, t1, t2, t3):
    """IK(FK(q)) contains q modulo 2 pi, except at the singularities of :func:`regular`."""
    q = np.array([t1, t2, t3])
    assume(regular(arm, q))
    sol = arm.solve(arm.fk(q))
    assert sol.ok.all()
    assert contains_angles(sol.theta, q, ATOL_RAD), f"q = {q} not among\n{sol.theta}"


def test_ik_of_fk_batch(arm, rng):
    """The same property on 2e5 seeded random configurations in one vectorized call; the
    singular set is excluded explicitly and must be tiny."""
    q = rng.uniform(-np.pi, np.pi, (200_000, 3))
    keep = regular(arm, q)
    assert keep.mean() > 0.999
    sol = arm.solve(arm.fk(q))
    check_solutions(arm, arm.fk(q), sol)
    found = contains_angles(sol.theta[keep], q[keep], ATOL_RAD)
    assert found.all(), f"{(~found).sum()} configurations not recovered, e.g. {q[keep][~found][:3]}"
    # each q appears exactly once: the four branches are distinct away from singularities
    err = np.abs(angle_diff(sol.theta[keep], q[keep][:, None, :])).max(axis=-1)
    assert ((err <= ATOL_RAD).sum(axis=-1) == 1).all()


@given(
    L1=st.just(0.0) | st.floats(1e-3, 2000.0),  # a non-zero length >= 1 micrometre (validate)
    L2=st.floats(1.0, 2000.0),
    L3=st.floats(1.0, 2000.0),
    t1=st.floats(-np.pi, np.pi),
    t2=st.floats(-np.pi, np.pi),
    t3=st.floats(-np.pi, np.pi),
)
def test_ik_of_fk_other_arms(L1, L2, L3, t1, t2, t3):
    """The closed form holds for any link lengths (not only Table 3), incl. L3 > L2."""
    arm = paper_arm().with_(L1=L1, L2=L2, L3=L3)
    q = np.array([t1, t2, t3])
    r = L2 * math.cos(t2) + L3 * math.cos(t2 + t3)
    assume(abs(r) >= 1e-3 * (L2 + L3) and abs(math.sin(t3)) >= 1e-4)
    p = arm.fk(q)
    sol = arm.solve(p)
    assert sol.ok.all()
    scale = L1 + L2 + L3  # errors scale with the arm
    check_solutions(arm, p, sol, ATOL_MM * scale / 1e3 + 1e-12 * scale)
    assert contains_angles(sol.theta, q, ATOL_RAD * 10)


# --- reach boundary sweeps ----------------------------------------------------------------

DIRECTIONS = [
    (0.3, 0.2),
    (2.5, -0.9),
    (-1.7, 1.2),
    (np.pi / 4, 0.0),
    (-3.0, -1.4),
]  # azimuth, elevation
STEPS_MM = [
    *(k * 1e-3 for k in range(-5, 6)),
    -2e-6,
    -1.1e-6,
    -0.9e-6,
    -0.5e-6,
    0.5e-6,
    0.9e-6,
    1.1e-6,
    2e-6,
]


@pytest.mark.parametrize("boundary", ["outer", "inner"])
@pytest.mark.parametrize(("azimuth", "elevation"), DIRECTIONS)
def test_sweep_across_reach_boundary(arm, boundary, azimuth, elevation):
    """Targets from 5e-3 mm inside to 5e-3 mm outside the shell in 1e-3 mm steps, plus
    steps around the 1e-6 mm tolerance. delta > 0 is outside (beyond L2 + L3, or nearer
    than |L2 - L3| to the shoulder)."""
    geo = arm.geometry
    deltas = np.array(STEPS_MM)
    D = geo["reach_outer"] + deltas if boundary == "outer" else geo["reach_inner"] - deltas
    p = shell_point(arm, D, azimuth, elevation)
    sol = arm.solve(p)
    # the signed distance outside the shell is delta (p is built to ~1e-13 mm)
    assert_allclose(sol.outside_mm, deltas, 1e-9, "outside_mm")
    inside = deltas <= TOL
    bad_status = Status.OUT_OF_REACH if boundary == "outer" else Status.INSIDE_REACH
    assert (sol.status == np.where(inside, Status.OK, bad_status)).all(), sol.status
    assert (sol.ok == inside[:, None]).all()
    # reachable agrees with the tolerance solve applied (it once compared outside_mm with 0:
    # a target 5e-7 mm outside was solved, ok=True, yet reachable=False)
    assert (sol.reachable == inside).all()
    assert (arm.is_reachable(p) == inside).all()
    # solved targets land on p, or on the shell within the tolerance when just outside
    check_solutions(arm, p, sol, ATOL_MM + TOL)
    strictly = deltas <= 0
    assert_points_close(
        arm.fk(sol.theta[strictly]), p[strictly][:, None, :], ATOL_MM, "inside the shell"
    )
    reached = arm.fk(sol.theta[inside])
    on_shell = np.linalg.norm(reached - arm.shoulder, axis=-1)
    radius = arm.geometry["reach_outer"] if boundary == "outer" else arm.geometry["reach_inner"]
    expected_D = np.where(deltas[inside] > 0, radius, D[inside])[:, None]
    assert_allclose(
        on_shell, np.broadcast_to(expected_D, on_shell.shape), ATOL_MM, "distance to shoulder"
    )
    # scalar API: raises with the distance for every target beyond the tolerance
    for delta, target, ok in zip(deltas, p, inside, strict=True):
        if ok:
            assert_points_close(arm.fk(arm.ik(target)), target, ATOL_MM + TOL)
            continue
        with pytest.raises(UnreachableError) as info:
            arm.ik(target)
        err = info.value
        assert isinstance(err, ValueError)
        assert err.distance_mm == pytest.approx(delta, abs=1e-9)
        assert err.limit_mm == radius
        word = "beyond the reach" if boundary == "outer" else "inside the inner reach"
        # the message states the distance: 3 decimals, 3 significant digits below 1e-3 mm
        m = re.search(rf"is ([-0-9.e]+) mm {word}", str(err))
        assert m, str(err)
        assert float(m.group(1)) == pytest.approx(delta, rel=5e-3), str(err)


def test_documented_default_tolerance():
    assert DEFAULT_TOL_MM == TOL


def test_tolerance_is_a_keyword(arm):
    p = shell_point(arm, arm.geometry["reach_outer"] + 5e-4, 0.4, 0.3)
    assert arm.solve(p).status == Status.OUT_OF_REACH
    sol = arm.solve(p, tol=1e-3)
    assert sol.status == Status.OK
    check_solutions(arm, p, sol, 5e-4 + ATOL_MM)
    assert arm.ik(p, tol=1e-3).shape == (3,)
    with pytest.raises(UnreachableError, match=r"0\.001 mm beyond"):
        arm.ik(shell_point(arm, arm.geometry["reach_outer"] + 1e-3 + 1e-6, 0.4, 0.3), tol=1e-3)


# --- base axis sweeps ---------------------------------------------------------------------

RHOS_MM = [0.0, 1e-12, 1e-9, 5e-7, 0.9e-6, 1.1e-6, 2e-6, 1e-5, 1e-3, 1.0]


@pytest.mark.parametrize("height", [300.0, -250.0, 150.0, 509.0])  # z - L1 [mm], all reachable
def test_sweep_towards_base_axis(arm, height):
    """Targets at horizontal distance rho from the base axis: rho <= 1e-6 mm is the axis
    (BaseAxisError / Status.BASE_AXIS unless theta1_on_axis is given)."""
    phi = -2.2
    rho = np.array(RHOS_MM)
    p = np.stack(
        [rho * np.cos(phi), rho * np.sin(phi), np.full_like(rho, arm.params.L1 + height)], axis=-1
    )
    on_axis = rho <= TOL
    sol = arm.solve(p)
    assert (sol.status == np.where(on_axis, Status.BASE_AXIS, Status.OK)).all(), sol.status
    assert (sol.ok == ~on_axis[:, None]).all()
    assert sol.reachable.all()  # on the axis but within reach: only theta1 is missing
    check_solutions(arm, p, sol)
    # theta1 = atan2(Py, Px) off the axis, even 1.1e-6 mm from it
    assert_angles_close(sol.branch("front-up")[~on_axis, 0], phi, 1e-9, "front theta1")
    assert_angles_close(sol.branch("back-down")[~on_axis, 0], phi + np.pi, 1e-9, "back theta1")

    chosen = 0.7
    sol2 = arm.solve(p, theta1_on_axis=chosen)
    assert (sol2.status == Status.OK).all() and sol2.ok.all() and np.isfinite(sol2.theta).all()
    # the chosen theta1 puts the wrist within 2 rho of p (rho <= 1e-6 mm) on the axis
    check_solutions(arm, p, sol2, ATOL_MM + 2 * TOL)
    for b, name in enumerate(sol2.branches):
        expected = np.where(
            on_axis, chosen if FRONT[name] else chosen + np.pi, phi if FRONT[name] else phi + np.pi
        )
        assert_angles_close(sol2.theta[:, b, 0], expected, 1e-9, f"{name} theta1")

    for target, axis in zip(p, on_axis, strict=True):
        if not axis:
            assert_points_close(arm.fk(arm.ik(target)), target, ATOL_MM)
            continue
        with pytest.raises(
            BaseAxisError, match=r"lies on the base axis.*theta1 is undefined.*theta1_on_axis"
        ) as info:
            arm.ik(target)
        assert isinstance(info.value, ValueError)
        assert info.value.target == tuple(target)
        every = arm.ik_all(target, theta1_on_axis=chosen)
        assert set(every) == set(BRANCHES)
        assert_angles_close(every["front-up"][0], chosen, 0.0)
        assert_angles_close(every["back-up"][0], chosen + np.pi, 1e-15)
        assert_points_close(arm.fk(np.array(list(every.values()))), target, ATOL_MM + 2 * TOL)


def test_base_axis_batch_mask_and_array_theta1(arm):
    """Batch: a mask, not an exception; theta1_on_axis broadcasts per target."""
    L1 = arm.params.L1
    p = np.array(
        [[0, 0, L1 + 300], [100, 100, 600], [0, 0, L1 - 200], [0, 0, L1 + 600], [0, 0, L1 + 50]],
        float,
    )
    sol = arm.solve(p)
    assert sol.status.tolist() == [
        Status.BASE_AXIS,
        Status.OK,
        Status.BASE_AXIS,
        Status.OUT_OF_REACH,
        Status.INSIDE_REACH,
    ]
    assert sol.ok.tolist() == [[False] * 4, [True] * 4, [False] * 4, [False] * 4, [False] * 4]
    assert not np.isnan(sol.theta[1]).any() and np.isnan(sol.theta[[0, 2, 3, 4]]).all()
    sol2 = arm.solve(p, theta1_on_axis=np.array([0.1, 9.9, -0.4, 0.0, 0.0]))
    assert sol2.status.tolist() == [
        Status.OK,
        Status.OK,
        Status.OK,
        Status.OUT_OF_REACH,
        Status.INSIDE_REACH,
    ]
    assert_angles_close(sol2.branch("front-down")[[0, 2], 0], [0.1, -0.4], 1e-15)
    assert_angles_close(sol2.branch("front-down")[1, 0], np.pi / 4, 1e-15)  # off-axis ignores it
    check_solutions(arm, p, sol2)


def test_base_axis_out_of_reach_raises_unreachable_first(arm):
    L1 = arm.params.L1
    with pytest.raises(UnreachableError, match=r"90\.000 mm beyond"):
        arm.ik([0.0, 0.0, L1 + 600.0])
    with pytest.raises(UnreachableError, match=r"60\.000 mm inside the inner reach"):
        arm.ik([0.0, 0.0, L1 + 50.0], theta1_on_axis=0.0)


# --- Table 4 --------------------------------------------------------------------------------


def table4() -> pd.DataFrame:
    return pd.read_csv(data_dir() / "table4.csv", dtype=str, keep_default_na=False)


def printed_matches(value_deg: float, printed: str) -> bool:
    """True if value rounds to the printed text at the printed number of decimals (the
    paper drops trailing zeros: '45' and '17.5' are read at 0 and 1 decimals)."""
    decimals = len(printed.split(".")[1]) if "." in printed else 0
    return abs(value_deg - float(printed)) <= 0.5 * 10.0**-decimals + 1e-9


def test_table4_file_is_verbatim():
    df = table4()
    assert len(df) == 10 and df["row"].tolist() == [str(i) for i in range(1, 11)]
    assert (df["z_mm"] == "600").all()
    row8 = df[df["row"] == "8"].iloc[0]
    assert row8["status"] == "无解" and row8["theta2_deg"] == "" and row8["theta3_deg"] == ""
    assert (df.loc[df["row"] != "8", "status"] == "solved").all()


@pytest.mark.parametrize("row", [r for r in range(1, 11) if r != 8])
def test_table4_reachable_rows(arm, row):
    """Each reachable Table 4 target solves in all branches and round-trips; front-up
    theta1 matches the printed value in every row and theta3 in rows 1-7 and 10
    (row 2 prints -131.7, one decimal; row 9 is a misprint, see below)."""
    rec = table4().iloc[row - 1]
    p = np.array([float(rec["x_mm"]), float(rec["y_mm"]), float(rec["z_mm"])])
    every = arm.ik_all(p)
    assert_points_close(arm.fk(np.array(list(every.values()))), p, ATOL_MM, f"row {row}")
    t1, _, t3 = np.degrees(every["front-up"])
    assert printed_matches(t1, rec["theta1_deg"]), (t1, rec["theta1_deg"])
    assert t1 == pytest.approx(math.degrees(math.atan2(p[1], p[0])), abs=1e-12)
    assert t3 < 0
    if row != 9:
        assert printed_matches(t3, rec["theta3_deg"]), (t3, rec["theta3_deg"])


def test_table4_misprints_are_what_the_audit_says(arm):
    """The rows where the paper's numbers are not the correct angles, and why.

    - theta2 in rows 1, 2, 4 is the correct theta2 + 180 deg: eq. 18's single-argument
      arctangent picks the wrong quadrant when its denominator is negative; the other
      rows' theta2 match the printed value.
    - theta3 in row 9 (-91.20) differs from row 6 (-91.16) although both targets are the
      same distance from the shoulder (x and y swapped), so theta3 must be equal: the
      correct value is -91.155 deg -> -91.16.
    """
    df = table4().set_index("row")
    q = {
        r: np.degrees(arm.ik([float(df.loc[str(r), c]) for c in ("x_mm", "y_mm", "z_mm")]))
        for r in (1, 2, 3, 4, 5, 6, 7, 9, 10)
    }
    for r in (1, 2, 4):
        assert not printed_matches(q[r][1], df.loc[str(r), "theta2_deg"])
        assert abs(float(df.loc[str(r), "theta2_deg"]) - (q[r][1] + 180.0)) <= 0.01
    for r in (3, 5, 6, 7, 9, 10):
        assert printed_matches(q[r][1], df.loc[str(r), "theta2_deg"]), (r, q[r][1])
    assert q[9][2] == pytest.approx(q[6][2], abs=1e-9)
    assert not printed_matches(q[9][2], df.loc["9", "theta3_deg"])
    assert printed_matches(q[9][2], df.loc["6", "theta3_deg"])


def test_table4_row8_unreachable(arm):
    """Row 8 (200, 500, 600): the paper prints 无解 (no solution); the target is
    sqrt(200^2 + 500^2 + 60^2) - 510 = 31.85 mm beyond the reach."""
    expected = math.sqrt(200**2 + 500**2 + (600 - 660) ** 2) - (310 + 200)
    with pytest.raises(UnreachableError) as info:
        arm.ik([200.0, 500.0, 600.0])
    assert info.value.distance_mm == pytest.approx(expected, abs=1e-9)
    assert expected == pytest.approx(31.85, abs=0.005)
    m = re.search(r"([0-9.]+) mm beyond the reach of 510 mm", str(info.value))
    assert m and float(m.group(1)) == pytest.approx(expected, abs=5e-4), str(info.value)
    assert "(200, 500, 600)" in str(info.value)
    # batch over the whole table: a mask, row 8 marked
    df = table4()
    p = df[["x_mm", "y_mm", "z_mm"]].astype(float).to_numpy()
    sol = arm.solve(p)
    assert sol.status.tolist() == [
        Status.OUT_OF_REACH if r == "8" else Status.OK for r in df["row"]
    ]
    assert sol.outside_mm[7] == pytest.approx(expected, abs=1e-9)
    check_solutions(arm, p, sol)


# --- branch selection API ------------------------------------------------------------------


def test_branch_selection(arm):
    p = np.array([[100.0, 100.0, 600.0], [300.0, -200.0, 800.0]])
    full = arm.solve(p, "all")
    assert full.branches == BRANCHES and full.theta.shape == (2, 4, 3)
    one = arm.solve(p, "back-down")
    assert one.branches == ("back-down",) and one.theta.shape == (2, 1, 3)
    assert_allclose(one.branch("back-down"), full.branch("back-down"), 0.0)
    two = arm.solve(p, ["back-up", "front-up"])
    assert two.branches == ("back-up", "front-up")
    assert_allclose(two.theta, full.theta[:, [2, 0]], 0.0)
    assert_allclose(arm.ik(p[1], "front-down"), full.branch("front-down")[1], 0.0)
    with pytest.raises(ValueError, match="unknown branch 'elbow-up'"):
        arm.ik(p[0], "elbow-up")
    with pytest.raises(ValueError, match="unknown branch"):
        arm.solve(p, ["front-up", "sideways"])
    with pytest.raises(ValueError, match="unknown branch"):
        arm.solve(p, [])


def test_solve_shapes(arm, rng):
    q = rng.uniform(-np.pi, np.pi, (3, 4, 3))
    sol = arm.solve(arm.fk(q))
    assert sol.theta.shape == (3, 4, 4, 3) and sol.ok.shape == (3, 4, 4)
    assert sol.status.shape == (3, 4) and sol.outside_mm.shape == (3, 4)
    assert sol.ok.dtype == bool
    single = arm.solve([100.0, 100.0, 600.0])
    assert single.theta.shape == (4, 3) and single.status.shape == ()


# --- bad input -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("target", "message"),
    [
        ([np.nan, 100.0, 600.0], r"non-finite coordinate: \[nan, 100.0, 600.0\]"),
        ([100.0, np.inf, 600.0], r"non-finite coordinate: \[100.0, inf, 600.0\]"),
        ([100.0, 100.0, -np.inf], r"non-finite coordinate: \[100.0, 100.0, -inf\]"),
        ("abc", r"target 'abc' is not numeric"),
        (["100", "x", "600"], r"target \['100', 'x', '600'\] is not numeric"),
        ([100.0, None, 600.0], r"is not numeric: None \(NoneType\) is not a real number"),
        ([100.0 + 1j, 100.0, 600.0], r"is not numeric: it holds complex"),
        (np.ma.masked_array([1.0, 2.0, 3.0], [0, 1, 0]), r"a masked array is refused"),
        ([10**400, 0, 0], r"beyond the float range"),
        ([True, 100.0, 600.0], r"a boolean is not a number"),
        ([100.0, 100.0], r"shape \(2,\); expected \(\.\.\., 3\)"),
        ([1.0, 2.0, 3.0, 4.0], r"shape \(4,\); expected \(\.\.\., 3\)"),
        (600.0, r"shape \(\); expected \(\.\.\., 3\)"),
        ([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]], r"ik takes one target of shape \(3,\), got \(2, 3\)"),
    ],
)
def test_ik_bad_input(arm, target, message):
    with pytest.raises(ValueError, match=message):
        arm.ik(target)


@pytest.mark.parametrize("method", ["solve", "is_reachable"])
def test_batch_bad_input_names_the_target(arm, method):
    p = np.array([[100.0, 100.0, 600.0], [100.0, 100.0, 600.0], [1.0, np.nan, 3.0]])
    with pytest.raises(
        ValueError, match=r"target at index \(2,\) has a non-finite coordinate: \[1.0, nan, 3.0\]"
    ):
        getattr(arm, method)(p)
    with pytest.raises(ValueError, match=r"shape \(3, 2\)"):
        getattr(arm, method)(np.zeros((3, 2)))


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"theta1_on_axis": np.nan}, r"theta1_on_axis = nan rad is not finite"),
        ({"theta1_on_axis": np.inf}, r"theta1_on_axis = inf rad is not finite"),
        ({"tol": np.nan}, r"tol = nan mm: the tolerance must be a finite number >= 0"),
        ({"tol": -1e-6}, r"tol = -1e-06 mm: the tolerance must be a finite number >= 0"),
        ({"tol": "1e-6"}, r"tol = '1e-6' mm"),
    ],
)
def test_bad_options_raise_instead_of_silent_nan(arm, options, message):
    """A NaN waist angle for an on-axis target used to come back as a NaN solution with
    status OK; a NaN tolerance used to mark out-of-reach targets OK."""
    on_axis = [0.0, 0.0, arm.params.L1 + 300.0]
    with pytest.raises(ValueError, match=message):
        arm.solve(on_axis, **options)
    with pytest.raises(ValueError, match=message):
        arm.ik(on_axis, **options)


def test_as_points():
    assert as_points([1, 2, 3]).dtype == np.float64
    assert as_points(np.zeros((0, 3))).shape == (0, 3)
    with pytest.raises(ValueError, match="waypoint at index"):
        as_points([[0, 0, 0], [np.inf, 0, 0]], name="waypoint")


# --- Jacobian -------------------------------------------------------------------------------


def sympy_P():
    t1, t2, t3 = sp.symbols("theta1:4", real=True)
    L1, L2, L3 = sp.symbols("L1 L2 L3", positive=True)
    t23 = t2 + t3
    r = L3 * sp.cos(t23) + L2 * sp.cos(t2)  # eq. 2, P column as printed
    P = sp.Matrix([sp.cos(t1) * r, sp.sin(t1) * r, L3 * sp.sin(t23) + L2 * sp.sin(t2) + L1])
    return P, (t1, t2, t3), (L1, L2, L3)


def test_jacobian_vs_sympy_and_its_determinant(arm, rng):
    """J = dP/dq of eq. 2 (SymPy), and det J = -L2 L3 sin(theta3) r, r = L2 c2 + L3 c23
    (the sign matters: a module docstring had it without the minus)."""
    P, q_sym, L_sym = sympy_P()
    J_sym = P.jacobian(q_sym)
    det = sp.factor(sp.simplify(J_sym.det()))
    _, t2, t3 = q_sym
    _, L2, L3 = L_sym
    assert (
        sp.simplify(det - (-L2 * L3 * sp.sin(t3) * (L2 * sp.cos(t2) + L3 * sp.cos(t2 + t3)))) == 0
    )
    values = dict(zip(L_sym, (arm.params.L1, arm.params.L2, arm.params.L3), strict=True))
    f_J = sp.lambdify(q_sym, J_sym.subs(values), "numpy")
    q = rng.uniform(-np.pi, np.pi, (300, 3))
    J = arm.jacobian(q)
    for k in range(len(q)):
        assert_allclose(J[k], np.array(f_J(*q[k]), float), 1e-9, "J vs sympy")
    L2v, L3v = arm.params.L2, arm.params.L3
    r = L2v * np.cos(q[:, 1]) + L3v * np.cos(q[:, 1] + q[:, 2])
    # det ~ L2 L3 r ~ 3e7 mm^3/rad^3: relative 1e-12
    assert_allclose(np.linalg.det(J), -L2v * L3v * np.sin(q[:, 2]) * r, 0.0, "det J", rtol=1e-9)


def test_jacobian_vs_central_differences(arm, rng):
    """Central differences with h = 1e-6 rad: truncation h^2/6 |P'''| <= 1e-12 * 510 mm
    and round-off eps |P| / h ~ 2e-7 mm/rad, so 1e-5 mm/rad is a safe bound while a wrong
    entry is off by up to ~500 mm/rad."""
    h = 1e-6
    q = rng.uniform(-np.pi, np.pi, (2000, 3))
    J = arm.jacobian(q)
    for j in range(3):
        dq = np.zeros(3)
        dq[j] = h
        fd = (arm.fk(q + dq) - arm.fk(q - dq)) / (2 * h)
        assert_allclose(J[..., :, j], fd, 1e-5, f"column {j}")


def test_jacobian_vs_pinocchio(arm, rng):
    """The same Jacobian from Pinocchio's frame Jacobian (LOCAL_WORLD_ALIGNED, linear part)
    of a model built from the D-H rows: agreement to 1e-9 mm/rad (entries <= 510 mm/rad)."""
    pin_arm = PinocchioArm(arm.dh_table())
    q = rng.uniform(-np.pi, np.pi, (2000, 3))
    assert_allclose(arm.jacobian(q), pin_arm.jacobian(q), 1e-9, "J vs Pinocchio")


def test_jacobian_singular_where_ik_is(arm, rng):
    """det J vanishes exactly on the IK singularities: base axis (r = 0) and sin theta3 = 0."""
    t2 = rng.uniform(-np.pi, np.pi, 50)
    stretched = np.stack([rng.uniform(-np.pi, np.pi, 50), t2, np.zeros(50)], axis=-1)
    folded = stretched + np.array([0.0, 0.0, np.pi])
    L2, L3 = arm.params.L2, arm.params.L3
    # on the axis: r = L2 cos t2 + L3 cos(t2 + t3) = (L2 + L3 cos t3) cos t2 - L3 sin t3 sin t2
    # = R cos(t2 + delta) with delta = atan2(L3 sin t3, L2 + L3 cos t3): zero at t2 = pi/2 - delta
    t3 = rng.uniform(-np.pi, np.pi, 50)
    delta = np.arctan2(L3 * np.sin(t3), L2 + L3 * np.cos(t3))
    on_axis = np.stack([rng.uniform(-np.pi, np.pi, 50), np.pi / 2 - delta, t3], axis=-1)
    assert_allclose(np.hypot(*arm.fk(on_axis)[:, :2].T), 0.0, 1e-9, "wrist on the base axis")
    for q in (stretched, folded, on_axis):
        assert_allclose(np.linalg.det(arm.jacobian(q)), 0.0, 1e-6 * L2 * L3 * (L2 + L3), "det J")


def test_equal_links_shoulder_point():
    """L2 = L3: the inner radius is 0 and the shoulder itself is reachable (elbow folded,
    on the base axis): BASE_AXIS without a waist angle, solved with one."""
    arm = paper_arm().with_(L1=0.0, L2=100.0, L3=100.0)
    sol = arm.solve([0.0, 0.0, 0.0])
    assert sol.status == Status.BASE_AXIS and sol.reachable
    sol = arm.solve([0.0, 0.0, 0.0], theta1_on_axis=0.3)
    assert sol.ok.all()
    check_solutions(arm, np.zeros(3), sol)
    assert_allclose(np.abs(sol.theta[:, 2]), np.pi, 1e-12, "folded elbow")


def test_docstring_examples():
    """The worked examples in analysis.kinematics.arm's docstrings (Table 4 row 1) are true."""
    import analysis.kinematics.arm

    result = doctest.testmod(analysis.kinematics.arm, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 2 and result.failed == 0

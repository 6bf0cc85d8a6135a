"""analysis.kinematics.compiled: the kernels generated from the closed form equal the numpy
evaluation of the same closed form (analysis.kinematics.arm) exactly.

Angles are compared modulo 2 pi: both wrap to (-pi, pi], and an angle within an ulp of
+-pi may land on either end. Tolerance 1e-12 rad: the two paths evaluate the same recorded
operations except atan2 (libm vs the kernel's Cephes version, 2 ulp) and acos (libm vs
atan2(sqrt((1 - c)(1 + c)), c)); the worst case seen is ~1e-13 rad, near the folded elbow
where acos is ill-conditioned.
"""

import numpy as np
import pytest

from analysis.kinematics import compiled
from analysis.kinematics.arm import BRANCHES, Status
from analysis.kinematics.pinocchio_model import PinocchioArm
from analysis.kinematics.pulses import angles_to_pulses, pulses_to_angles
from analysis.studies import quantization as Q

ANGLE_TOL = 1e-12  # rad, see module docstring
MM_TOL = 1e-9  # mm: float64 round-off on ~1e3 mm lengths is ~1e-13; margin for sqrt vs hypot


def angle_diff(a, b):
    return np.abs(np.mod(a - b + np.pi, 2 * np.pi) - np.pi)


def assert_same_solutions(ref, got):
    assert got.branches == ref.branches == BRANCHES
    assert got.theta.shape == ref.theta.shape
    np.testing.assert_array_equal(got.status, ref.status)
    np.testing.assert_array_equal(got.ok, ref.ok)
    np.testing.assert_array_equal(np.isnan(got.theta), np.isnan(ref.theta))
    np.testing.assert_array_equal(np.isnan(got.theta).any(-1), ~got.ok)
    d = angle_diff(got.theta[ref.ok], ref.theta[ref.ok])
    assert d.size == 0 or d.max() <= ANGLE_TOL, f"max angle difference {d.max():.3g} rad"
    np.testing.assert_allclose(got.outside_mm, ref.outside_mm, rtol=0, atol=MM_TOL)
    # wrapped like Arm.solve: theta1, theta2 in (-pi, pi]; theta3 = -+acos(...) is not
    # wrapped by Arm.solve either, so the folded elbow gives theta3 = -pi on two branches
    ok_t = got.theta[got.ok]
    assert (ok_t[:, :2] > -np.pi).all() and (ok_t <= np.pi).all() and (ok_t[:, 2] >= -np.pi).all()


def boundary_targets(arm):
    """Targets on and around every boundary: shell spheres, base axis, atan2 cuts."""
    P = arm.params
    R, r, L1 = arm.geometry["reach_outer"], arm.geometry["reach_inner"], P.L1
    tol = 1e-6
    rng = np.random.default_rng(7)
    u = rng.standard_normal((400, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    pts = []
    for radius in (
        R,
        R - tol / 2,
        R + tol / 2,
        R - 2 * tol,
        R + 2 * tol,
        r,
        r + tol / 2,
        r - tol / 2,
        r + 2 * tol,
        r - 2 * tol,
        R - 1e-3,
        r + 1e-3,
    ):
        pts.append(arm.shoulder + u * radius)
    # axis-aligned points on the spheres (exactly representable distances)
    for radius in (R, r):
        for s in (1.0, -1.0):
            pts.append(
                np.array(
                    [
                        [s * radius, 0.0, L1],
                        [0.0, s * radius, L1],
                        [s * radius, -0.0, L1],
                        [0.0, 0.0, L1 + s * radius],
                    ]
                )
            )
    # base axis and near it
    z = np.linspace(L1 - R, L1 + R, 41)
    for rho in (0.0, tol / 2, tol, 2 * tol, 1e-3):
        pts.append(np.stack([np.full_like(z, rho), np.zeros_like(z), z], axis=-1))
        pts.append(np.stack([np.zeros_like(z), -np.full_like(z, rho), z], axis=-1))
    # atan2 branch cuts: y = +-0 with x < 0, x = +-0, the Table 4 plane
    pts.append(
        np.array(
            [
                [-300.0, 0.0, 600.0],
                [-300.0, -0.0, 600.0],
                [0.0, 300.0, 600.0],
                [-0.0, -300.0, 600.0],
                [100, 100, 600],
                [200, 500, 600],
                [300, 300, 600],
                [510.0, 0.0, 660.0],
            ]
        )
    )
    return np.concatenate(pts)


def test_compiled_solve_equals_arm_solve_random(arm, rng):
    p = arm.shoulder + rng.uniform(-1.1, 1.1, (200_000, 3)) * arm.geometry["reach_outer"]
    ref, got = arm.solve(p, "all"), arm.solve(p, backend="compiled")
    assert_same_solutions(ref, got)
    # the sample really exercises every status
    assert {int(s) for s in np.unique(ref.status)} == {
        int(Status.OK),
        int(Status.OUT_OF_REACH),
        int(Status.INSIDE_REACH),
    }


def test_compiled_solve_equals_arm_solve_boundaries(arm):
    p = boundary_targets(arm)
    ref, got = arm.solve(p, "all"), arm.solve(p, backend="compiled")
    assert_same_solutions(ref, got)
    assert set(np.unique(ref.status).tolist()) == {0, 1, 2, 3}  # the statuses this arm has


@pytest.mark.parametrize("tol", [1e-9, 1e-6, 1e-2])
def test_compiled_solve_tolerance_is_passed_through(arm, tol):
    p = boundary_targets(arm)
    assert_same_solutions(arm.solve(p, "all", tol=tol), arm.solve(p, backend="compiled", tol=tol))


def test_compiled_solve_other_arm_and_shapes(arm, rng):
    other = arm.with_(L1=100.0, L2=150.0, L3=420.0)  # L3 > L2
    p = other.shoulder + rng.uniform(-600, 600, (5, 7, 3))
    ref, got = other.solve(p, "all"), other.solve(p, backend="compiled")
    assert got.theta.shape == (5, 7, 4, 3) and got.status.shape == (5, 7)
    assert_same_solutions(ref, got)
    one = arm.solve([100.0, 100.0, 600.0], backend="compiled")
    assert one.theta.shape == (4, 3)
    # Table 4 row 1: theta1 = 45 and theta3 = -155.13 deg as printed (2 decimals); theta2 is
    # misprinted there (190.20, see the errata), so it is checked by FK instead
    np.testing.assert_allclose(
        np.degrees(one.branch("front-up"))[[0, 2]], [45.0, -155.13], atol=0.005
    )
    np.testing.assert_allclose(
        arm.fk(one.theta), np.tile([100.0, 100.0, 600.0], (4, 1)), rtol=0, atol=MM_TOL
    )


def test_compiled_solve_rejects_bad_input(arm):
    with pytest.raises(ValueError, match="shape"):
        arm.solve([1.0, 2.0], backend="compiled")
    with pytest.raises(ValueError, match="non-finite"):
        arm.solve([[1.0, np.nan, 600.0]], backend="compiled")


def test_fk_equals_arm_fk_and_pinocchio(arm, rng):
    q = rng.uniform(-2 * np.pi, 2 * np.pi, (100_000, 3))
    np.testing.assert_allclose(compiled.fk(arm, q), arm.fk(q), rtol=0, atol=MM_TOL)
    pin = PinocchioArm(arm.dh_table())
    np.testing.assert_allclose(compiled.fk(arm, q[:200]), pin.fk(q[:200]), rtol=0, atol=MM_TOL)
    assert compiled.fk(arm, q.reshape(10, 10_000, 3)).shape == (10, 10_000, 3)
    with pytest.raises(ValueError, match="shape"):
        compiled.fk(arm, np.zeros((4, 2)))


@pytest.mark.skipif(not compiled.HAVE_NUMBA, reason="compiled helpers only exist with numba")
def test_atan2_acos_helpers_match_libm():
    """The kernel's atan2 and acos (= atan2(sqrt((1 - c)(1 + c)), c)) against libm."""
    kern = compiled.build(
        lambda m, v: {"a": m.atan2(v["y"], v["x"]), "c": m.acos(v["c"])},
        ("y", "x", "c"),
        (),
        {"a": "f8", "c": "f8"},
    )

    rng = np.random.default_rng(3)
    n = 400_000
    y = rng.standard_normal(n) * 10.0 ** rng.uniform(-6, 6, n)
    x = rng.standard_normal(n) * 10.0 ** rng.uniform(-6, 6, n)
    special = [
        (0.0, 1.0),
        (-0.0, 1.0),
        (0.0, -1.0),
        (-0.0, -1.0),
        (1.0, 0.0),
        (-1.0, 0.0),
        (1.0, -0.0),
        (0.0, 0.0),
        (-0.0, -0.0),
        (1.0, 1.0),
        (-1.0, -1.0),
        (1e-300, -1.0),
        (3.0, 3.0 * (1 + 2**-52)),
    ]
    y[: len(special)], x[: len(special)] = zip(*special, strict=True)
    c = np.concatenate(
        [rng.uniform(-1, 1, n - 8), [1.0, -1.0, 0.0, -0.0, 1 - 2**-53, -1 + 2**-53, 0.5, -0.5]]
    )
    o1, o2 = np.empty(n), np.empty(n)
    kern.run(np.stack([y, x, c], axis=1), [], [o1, o2])
    py = compiled.atan2_reference()  # the same source as plain Python
    np.testing.assert_array_equal(
        [py(a, b) for a, b in zip(y[:2000], x[:2000], strict=True)], o1[:2000]
    )
    ref1, ref2 = np.arctan2(y, x), np.arccos(c)
    two_ulp = 2 * np.spacing(np.maximum(np.abs(ref1), np.finfo(float).tiny))
    assert (np.abs(o1 - ref1) <= two_ulp).all()
    np.testing.assert_array_equal(np.signbit(o1), np.signbit(ref1))  # signed zeros and pi
    assert np.abs(o2 - ref2).max() <= 4.5e-16  # 2 ulp of pi


def test_quantization_map_equals_numpy_pipeline(arm, rng):
    """The compiled rounding kernel (analysis.studies.quantization.rounding_body) equals the
    same body run with numpy and the separate numpy functions (solve, pulses, fk)."""
    p = arm.shoulder + rng.uniform(-1.05, 1.05, (100_000, 3)) * arm.geometry["reach_outer"]
    p = np.concatenate([p, boundary_targets(arm)])
    for ppr in ((4000, 4000, 4000), (200, 1600, 25600)):
        err, c, ok = Q.quantization_map(arm, p, pulses_per_rev=ppr)
        same = Q.quantization_error(arm, p, pulses_per_rev=ppr)
        np.testing.assert_array_equal(ok, same.ok)
        np.testing.assert_array_equal(c, same.pulses)
        np.testing.assert_allclose(err[ok], same.error_mm[ok], rtol=0, atol=MM_TOL)
        sol = arm.solve(p, "front-up")
        np.testing.assert_array_equal(ok, sol.ok[:, 0])
        q = sol.theta[ok, 0, :]
        cref = angles_to_pulses(q, np.asarray(ppr))
        # a pulse count may differ only where the exact count sits within 1e-9 of a half
        differ = (c[ok] != cref).any(-1)
        exact = np.degrees(q) / 360 * np.asarray(ppr)
        near_half = (np.abs(np.abs(exact - np.trunc(exact)) - 0.5) < 1e-9).any(-1)
        assert not (differ & ~near_half).any()
        eref = np.linalg.norm(arm.fk(pulses_to_angles(cref, np.asarray(ppr))) - p[ok], axis=-1)
        np.testing.assert_allclose(err[ok][~differ], eref[~differ], rtol=0, atol=MM_TOL)
        assert np.isnan(err[~ok]).all() and (c[~ok] == 0).all()
    with pytest.raises(ValueError, match="pulses_per_rev"):
        Q.quantization_map(arm, p[:3], pulses_per_rev=(4000, 0, 4000))


def test_rounding_matches_pulses_module_on_hard_cases(arm):
    """0.49999999999999994 and exact halves round as analysis.kinematics.pulses.round_half_away
    (the same generic definition, compiled)."""
    from analysis.kinematics.pulses import round_half_away

    if not compiled.HAVE_NUMBA:
        pytest.skip("compiled helper only exists with numba")
    kern = compiled.build(lambda m, v: {"r": m.round(v["v"])}, ("v",), (), {"r": "f8"})

    v = np.array(
        [
            0.49999999999999994,
            -0.49999999999999994,
            0.5,
            -0.5,
            1.5,
            -1.5,
            2.5,
            -2.5,
            1723.5,
            -1723.5000000000002,
            0.0,
            -0.0,
        ]
    )
    o = np.empty_like(v)
    kern.run(v[:, None], [], [o])
    np.testing.assert_array_equal(o, round_half_away(v))


def test_tol_is_validated(arm):
    for bad in (-1.0, np.nan, np.inf, "1"):
        with pytest.raises(ValueError, match="tol"):
            arm.solve([100.0, 100.0, 600.0], backend="compiled", tol=bad)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_compiled_solve_refuses_non_finite_targets_like_numpy(arm, bad):
    """The compiled path counts non-finite inputs in its input copy (no separate pass) and
    raises the numpy path's error, naming the same target."""
    p = np.tile([100.0, 100.0, 600.0], (1000, 1))
    p[617, 1] = bad
    with pytest.raises(ValueError) as numpy_err:
        arm.solve(p)
    with pytest.raises(ValueError) as compiled_err:
        arm.solve(p, backend="compiled")
    assert str(compiled_err.value) == str(numpy_err.value)
    assert "index (617,)" in str(compiled_err.value)

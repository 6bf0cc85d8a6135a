"""analysis.kinematics.picker: the reconstructed 2P4R picker of seed 002.

Independent checks: (1) the secondary chain, link 5 and the fore-arm close onto the main
chain (loop residuals, POE of other screws); (2) Pinocchio on the open-chain equivalent;
(3) a plain planar-vector construction of the same mechanism (no screws, no exp maps).

Tolerances: 1e-9 mm for positions (lengths ~1e3 mm, a dozen float64 rigid motions: round-off
~1e-12 mm), 1e-12 for rotation entries. The mutation tests show each check can fail.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from analysis.kinematics import picker as pk
from analysis.kinematics import poe
from analysis.kinematics.pinocchio_model import PinocchioPOE
from helpers import assert_allclose, assert_points_close, assert_transform_close

N_CONFIGS = 10_000
ATOL_MM = 1e-9
PICKER = pk.load_picker()


def rot(axis: str, angle):
    c, s = np.cos(angle), np.sin(angle)
    o, z = np.ones_like(angle), np.zeros_like(angle)
    m = {
        "x": [[o, z, z], [z, c, -s], [z, s, c]],
        "y": [[c, z, s], [z, o, z], [-s, z, c]],
        "z": [[c, -s, z], [s, c, z], [z, z, o]],
    }[axis]
    return np.moveaxis(np.array(m), (0, 1), (-2, -1))


def planar_reference(picker: pk.Picker, active):
    """Tool marker position by plain vectors: solve link 5 by intersecting two circles,
    build the parallelogram, turn the wrist with rotation matrices, turn the waist."""
    p = picker.params
    a = np.asarray(active, float)
    t1, z, t6, t7, t8, x = np.moveaxis(a, -1, 0)
    A = np.stack([np.full_like(z, p["x_A"]), p["z_A"] + z], -1)  # (x, z) in the arm plane
    B = np.stack([p["x_A"] + p["b"] + x, np.full_like(x, p["z_A"] + p["g"])], -1)
    # circle (A, g) meets circle (B, b): the intersection on the reference side
    d = B - A
    R = np.linalg.norm(d, axis=-1)
    along = (R**2 + p["g"] ** 2 - p["b"] ** 2) / (2 * R)
    h = np.sqrt(p["g"] ** 2 - along**2)
    e = d / R[..., None]
    n = np.stack([-e[..., 1], e[..., 0]], -1)  # e turned +90 deg (towards the back at ref)
    G = A + along[..., None] * e + h[..., None] * n
    u = (G - A) / p["g"]
    D = A + p["l_AD"] * u
    C = D + (B - G)
    F = D + p["l_DF"] / p["b"] * (C - D)
    W = np.stack([F[..., 0] + p["f"], np.zeros_like(z), F[..., 1]], -1)
    wrist = rot("z", t6) @ rot("y", t7) @ rot("x", t8)
    P = W + np.einsum("...ij,j->...i", wrist, [p["e_tool"], 0.0, 0.0])
    return np.einsum("...ij,...j->...i", rot("z", t1), P)


@pytest.fixture(scope="module")
def configs():
    return PICKER.random_active(np.random.default_rng(2016), N_CONFIGS)


def test_reference_pose_is_figure_3():
    """All theta = 0: every passive joint 0, back-arm and fore-arm vertical, tool at M."""
    q = PICKER.joints(np.zeros(6))
    assert_allclose(q, np.zeros(13), 1e-15, "reference joints")
    S, M = PICKER.open_chain()
    assert_transform_close(PICKER.fk(np.zeros(6)), M, 1e-15, 1e-12, "reference pose")
    assert S.shape == (8, 6)
    assert PICKER.pantograph_ratio == 4.0


def test_loops_close_on_10000_configurations(configs):
    res = PICKER.loop_residuals(configs)
    for key in ("secondary_position", "link5", "forearm_top"):
        assert res[key].max() < ATOL_MM, (key, res[key].max())
    assert res["secondary_rotation"].max() < 1e-12


def test_pinocchio_open_chain_equals_poe_fk(configs):
    S, M = PICKER.open_chain()
    pin = PinocchioPOE(S, M)
    assert [j.shortname() for j in pin.model.joints[1:]] == [
        "JointModelRZ",
        "JointModelPZ",
        "JointModelRY",
        "JointModelRY",
        "JointModelRY",
        "JointModelRZ",
        "JointModelRY",
        "JointModelRX",
    ]
    assert_transform_close(
        pin.placements(PICKER.main_q(configs)), PICKER.fk(configs), 1e-12, ATOL_MM, "Pinocchio"
    )


def test_planar_vector_construction_equals_poe(configs):
    assert_points_close(planar_reference(PICKER, configs), PICKER.position(configs), ATOL_MM)


def test_wrist_base_stays_parallel_to_itself(configs):
    """theta3 + theta4 + theta5 = 0 and the secondary chain's angles sum to 0."""
    q = PICKER.joints(configs)
    assert_allclose(q[:, 2] + q[:, 3] + q[:, 4], 0.0, 1e-12, "main chain")
    assert_allclose(q[:, 9:13].sum(axis=1), 0.0, 1e-12, "secondary chain")


def test_pantograph_end_point_is_linear_in_the_sliders(rng):
    """With the assumed l_AD / g = l_DF / b = 4, the wrist centre moves 4 x forward and
    3 z down: the 'small stroke, large travel' of sec. 2."""
    a = PICKER.random_active(rng, 500)
    a[:, [0, 2, 3, 4]] = 0.0
    p0 = PICKER.position(np.zeros(6))
    expected = p0 + np.stack([4 * a[:, 5], np.zeros(500), -3 * a[:, 1]], -1)
    assert_points_close(PICKER.position(a), expected, ATOL_MM, "pantograph")


def test_without_the_pantograph_proportion_loops_still_close_but_linearity_fails(rng):
    """The mechanism (FK, loops) at any dimensions; the closed-form IK refuses them."""
    other = pk.Picker(PICKER.params.with_(g=200.0))
    assert other.pantograph_ratio is None
    with pytest.raises(ValueError, match=r"l_AD / g = 5 differs from l_DF / b = 4"):
        other.arm  # noqa: B018
    a = PICKER.random_active(rng, 4000)
    a = a[np.hypot(250.0 + a[:, 5], 200.0 - a[:, 1]) < 450.0][:2000]  # link 5 closes (g = 200)
    res = other.loop_residuals(a)
    assert max(res["secondary_position"].max(), res["link5"].max()) < ATOL_MM
    assert_points_close(planar_reference(other, a), other.position(a), ATOL_MM)
    a[:, [0, 2, 3, 4]] = 0.0
    lin = other.position(np.zeros(6)) + np.stack([4 * a[:, 5], 0 * a[:, 5], -3 * a[:, 1]], -1)
    assert np.linalg.norm(other.position(a) - lin, axis=-1).max() > 1.0


def test_mutations_are_caught(configs):
    """A wrong relation among the passive joints breaks the loop closure; a wrong axis point
    breaks the planar reference."""
    q = PICKER.joints(configs[:300])
    S_main, _ = PICKER.open_chain()
    S_sec, M_f = PICKER.secondary_chain()
    main = poe.fk(S_main[:5], M_f, q[:, :5])
    wrong = q[:, [0, 8, 9, 10, 11, 12]].copy()
    wrong[:, 4] = -wrong[:, 4]  # theta12 = -psi instead of psi
    sec = poe.fk(S_sec, M_f, wrong)
    assert np.linalg.norm(main[:, :3, 3] - sec[:, :3, 3], axis=-1).max() > 1.0
    moved = pk.Picker(PICKER.params.with_(l_DF=1010.0))
    assert (
        np.linalg.norm(
            planar_reference(PICKER, configs[:300]) - moved.position(configs[:300]), axis=-1
        ).max()
        > 1.0
    )


def test_passive_branch_is_continuous_from_the_reference_pose():
    """Along straight slider paths from (0, 0) the closed form never jumps (the assembly
    mode of Figure 3 is kept): steps of 0.5 mm change theta3 by < 0.01 rad."""
    p = PICKER.params
    s = np.linspace(0.0, 1.0, 2001)[:, None]
    for z_end, x_end in (
        (p["z_max"], p["x_max"]),
        (p["z_min"], p["x_min"]),
        (p["z_max"], p["x_min"]),
    ):
        try:
            q = PICKER.passive(s[:, 0] * z_end, s[:, 0] * x_end)
        except pk.UnreachableSliders:
            continue
        assert np.abs(np.diff(q[:, 0])).max() < 0.01


@given(
    z=st.floats(-200, 300),
    x=st.floats(-200, 250),
    t=st.lists(st.floats(-np.pi, np.pi), min_size=4, max_size=4),
)
@settings(max_examples=100)  # 12 ms each (six POE products)
def test_reachable_sliders_close_every_loop(z, x, t):
    a = np.array([t[0], z, t[1], t[2], t[3], x])
    try:
        res = PICKER.loop_residuals(a)
    except pk.UnreachableSliders as exc:
        assert "outside" in str(exc)
        p = PICKER.params
        R = np.hypot(p["b"] + x, p["g"] - z)
        assert R > p["g"] + p["b"] or R < abs(p["g"] - p["b"]) or R == 0
        return
    assert max(res["secondary_position"], res["link5"], res["forearm_top"]) < 1e-8


def test_unreachable_sliders_and_bad_arrays_raise():
    with pytest.raises(
        pk.UnreachableSliders,
        match=r"z = -300 mm, x = 300 mm: \|B - A\| = .* outside \[0, 500\] mm",
    ):
        PICKER.passive(-300.0, 300.0)
    with pytest.raises(ValueError, match=r"expected \(\.\.\., 6\)"):
        PICKER.fk(np.zeros(5))
    with pytest.raises(ValueError, match="NaN"):
        PICKER.fk([0, np.nan, 0, 0, 0, 0])


def test_vectorised_shapes():
    a = PICKER.random_active(np.random.default_rng(1), 12).reshape(3, 4, 6)
    assert PICKER.fk(a).shape == (3, 4, 4, 4)
    assert PICKER.joints(a).shape == (3, 4, 13)
    assert PICKER.loop_residuals(a)["link5"].shape == (3, 4)


# --------------------------------------------------------------------------- parameters
def test_every_dimension_has_a_status_and_a_reason():
    st_ = PICKER.statuses()
    assert set(st_.values()) <= {"printed", "assumed"}
    assert list(st_)[:11] == [*pk.cf.LENGTHS, "jaw_opening"]
    for name, p in PICKER.params.parameters.items():
        assert p.note.strip(), name
    assert st_["jaw_opening"] == "printed" and st_["vertical_guide"] == "printed"
    for name in ("x_A", "z_A", "g", "l_AD", "b", "l_DF", "d_s", "e_t", "f", "e_tool"):
        assert st_[name] == "assumed", name
    assert "l_AD" in PICKER.params.assumed()


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "picker.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_loader_rejects_bad_files(tmp_path):
    good = (pk.data_dir() / "arms" / "picker.toml").read_text(encoding="utf-8")
    with pytest.raises(ValueError, match="x_A status: 'guessed' is not one of printed"):
        pk.load_picker_params(
            _write(tmp_path, good.replace('status = "assumed"', 'status = "guessed"', 1))
        )
    with pytest.raises(ValueError, match="x_A nope: unknown key; did you mean 'note'"):
        pk.load_picker_params(
            _write(tmp_path, good.replace(', note = "vertical guide', ', nope = "x', 1))
        )
    with pytest.raises(ValueError, match="models"):
        pk.load_picker_params(
            _write(tmp_path, good.replace("value = [0.0, 1.0, 0.0]", "value = [0.0, 0.0, 1.0]", 1))
        )
    with pytest.raises(ValueError, match=r"g = -250\.0 mm"):
        pk.load_picker_params(
            _write(tmp_path, good.replace("g = { value = 250.0", "g = { value = -250.0"))
        )
    with pytest.raises(ValueError, match="missing parameter"):
        pk.load_picker_params(_write(tmp_path, good.replace("\ne_tool =", "\ne_tool_mm =")))


# --------------------------------------------------------------------------- experiment
def test_joint_laws_under_each_reading():
    t5 = pk.law_active(5.0, "velocity, rad/s")
    assert_allclose(t5, [-62.5, 250.0, 125.0, -125.0, -125.0, 187.5], 1e-12, "integrated")
    v5 = pk.law_active(5.0, "value, rad")
    assert_allclose(v5, [-25.0, 100.0, 50.0, -50.0, -50.0, 75.0], 1e-12, "values")
    d5 = pk.law_active(5.0, "value, deg")
    assert_allclose(np.degrees(d5[[0, 2, 3, 4]]), [-25.0, 50.0, -50.0, -50.0], 1e-12, "deg")
    with pytest.raises(ValueError, match="unknown reading"):
        pk.law_active(1.0, "value, grad")


def test_replay_experiment_flags_the_readings():
    rep = pk.replay_experiment(picker=PICKER)
    assert set(rep) == set(pk.READINGS)
    assert [k for k, v in rep.items() if v["units_printed"]] == ["velocity, rad/s"]
    assert {k for k, v in rep.items() if v["plausible"]} == {"velocity, deg/s", "value, deg"}
    for v in rep.values():
        assert v["position"].shape == (5, 3) and v["reachable"].all()
        assert "l_AD" in v["assumed"]
        assert_allclose(v["in_instrument"], v["position"] - [1500.0, 0.0, 0.0], 0.0, "S'")
    # t = 2 s: t^2/2 = t, so the integrated and the value readings coincide
    assert_allclose(
        rep["velocity, rad/s"]["position"][1], rep["value, rad"]["position"][1], 1e-9, "t=2"
    )
    one = pk.replay_experiment(2.0)  # default picker, scalar time
    assert_allclose(one["value, deg"]["position"], rep["value, deg"]["position"][1:2], 0.0, "t")


def test_points_at_keep_the_links_and_end_at_the_marker(configs):
    """The drawn linkage: P is the POE tool position, link 5 and C-D have length b, the
    back-arm l_AD, BGDC is a parallelogram (C - D = B - G), W - F = f horizontally."""
    a = configs[:500]
    pts = PICKER.points_at(a)
    p = PICKER.params
    assert_points_close(pts["P"], PICKER.position(a), ATOL_MM, "marker")
    for (u, v), length in {("B", "G"): p["b"], ("C", "D"): p["b"], ("D", "A"): p["l_AD"]}.items():
        d = np.linalg.norm(pts[u] - pts[v], axis=-1)
        assert np.abs(d - length).max() < ATOL_MM, (u, v)
    assert_points_close(pts["C"] - pts["D"], pts["B"] - pts["G"], ATOL_MM, "parallelogram")
    assert np.abs(np.linalg.norm(pts["W"] - pts["F"], axis=-1) - p["f"]).max() < ATOL_MM
    assert np.abs(pts["W"][:, 2] - pts["F"][:, 2]).max() < ATOL_MM

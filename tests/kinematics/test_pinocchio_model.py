"""analysis.kinematics.pinocchio_model: Pinocchio, an independent rigid-body library, built from the
same D-H rows, agrees with analysis FK (full placement) and Jacobian.

Tolerance: 1e-9 mm for positions and 1e-12 for rotation entries. Both sides compose a
handful of float64 rigid motions with lengths <= ~1e3 mm (round-off ~1e-13 mm); a
mis-ordered D-H product is off by millimetres.
"""

from __future__ import annotations

import numpy as np
import pytest

from analysis.kinematics.arm import load_arm, paper_arm
from analysis.kinematics.dh import DHRow, DHTable
from analysis.kinematics.pinocchio_model import PinocchioArm, build_model
from helpers import assert_allclose, assert_points_close, assert_transform_close

N_CONFIGS = 10_000
ATOL_MM = 1e-9
ATOL_ROT = 1e-12


def placements(pa: PinocchioArm, q):
    return np.stack([pa.placement(qk) for qk in q])


def fd_jacobian(table: DHTable, q, h=1e-6):
    """Central differences of the D-H chain's tool position [mm/rad], (N, 3, n)."""
    cols = []
    for j in range(table.n_joints):
        dq = np.zeros(table.n_joints)
        dq[j] = h
        cols.append((table.fk(q + dq)[..., :3, 3] - table.fk(q - dq)[..., :3, 3]) / (2 * h))
    return np.stack(cols, axis=-1)


def palletizer() -> DHTable:
    return load_arm("palletizer").table


@pytest.mark.parametrize("which", ["paper", "palletizer"])
def test_pinocchio_fk_and_placement_on_10000_configurations(rng, arm, which):
    """Pinocchio FK == analysis FK to 1e-9 mm on 10,000 seeded random configurations, for
    the paper's arm (Table 3, standard D-H) and seed 001's palletizer (modified D-H), and
    the whole base-to-tool placement (rotation too) agrees."""
    table = paper_arm().dh_table() if which == "paper" else palletizer()
    pa = PinocchioArm(table)
    assert pa.model.nq == table.n_joints
    q = rng.uniform(-2 * np.pi, 2 * np.pi, (N_CONFIGS, table.n_joints))
    T = table.fk(q)
    assert_points_close(pa.fk(q), T[..., :3, 3], ATOL_MM, f"{which}: Pinocchio vs DHTable.fk")
    if which == "paper":
        assert_points_close(pa.fk(q), arm.fk(q), ATOL_MM, "Pinocchio vs Arm.fk (eq. 2)")
    assert_transform_close(placements(pa, q), T, ATOL_ROT, ATOL_MM, f"{which}: placement")


@pytest.mark.parametrize("which", ["paper", "palletizer"])
def test_pinocchio_jacobian(rng, arm, which):
    table = paper_arm().dh_table() if which == "paper" else palletizer()
    pa = PinocchioArm(table)
    q = rng.uniform(-np.pi, np.pi, (1000, table.n_joints))
    J = pa.jacobian(q)
    assert J.shape == (1000, 3, table.n_joints)
    # central differences, h = 1e-6 rad: round-off eps |p| / h ~ 2e-7 mm/rad dominates
    assert_allclose(J, fd_jacobian(table, q), 1e-5, f"{which}: Pinocchio J vs central differences")
    if which == "paper":
        assert_allclose(J, arm.jacobian(q), 1e-9, "Pinocchio J vs Arm.jacobian")


def random_table(rng, convention, n_rows):
    """Random rows (lengths +-500 mm, angles +-pi, theta offsets) with a fixed row in the
    middle and a fixed tool row at the end."""
    rows = []
    for i in range(n_rows):
        kind = "fixed" if i in (n_rows // 2, n_rows - 1) else "revolute"
        rows.append(
            DHRow(
                alpha=rng.uniform(-np.pi, np.pi),
                a=rng.uniform(-500, 500),
                d=rng.uniform(-500, 500),
                theta_offset=rng.uniform(-np.pi, np.pi),
                kind=kind,
                name=f"r{i}",
            )
        )
    return DHTable(tuple(rows), convention, f"random-{convention}")


@pytest.mark.parametrize("convention", ["standard", "modified"])
@pytest.mark.parametrize("seed", range(5))
def test_builder_on_random_tables(convention, seed):
    """Theta offsets, a fixed row mid-chain and a fixed tool row: the builder must place
    each in the right frame (placements and Jacobians agree with the D-H chain)."""
    rng = np.random.default_rng(1000 + seed)
    table = random_table(rng, convention, 6)
    assert table.n_joints == 4
    pa = PinocchioArm(table)
    assert [pa.model.names[i] for i in range(1, pa.model.njoints)] == ["r0", "r1", "r2", "r4"]
    q = rng.uniform(-np.pi, np.pi, (500, 4))
    assert_transform_close(
        placements(pa, q), table.fk(q), ATOL_ROT, ATOL_MM, f"{convention} placement"
    )
    assert_allclose(
        pa.jacobian(q), fd_jacobian(table, q), 2e-5, f"{convention} J vs central differences"
    )


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_fixed_row_first(rng, convention):
    rows = (
        DHRow(alpha=0.4, a=30.0, d=12.0, theta_offset=0.3, kind="fixed"),
        DHRow(alpha=-0.8, a=100.0, d=5.0, theta_offset=1.0),
        DHRow(alpha=0.0, a=50.0, d=0.0),
    )
    table = DHTable(rows, convention)
    pa = PinocchioArm(table)
    q = rng.uniform(-np.pi, np.pi, (200, 2))
    assert_transform_close(placements(pa, q), table.fk(q), ATOL_ROT, ATOL_MM)


def test_model_structure():
    model = build_model(paper_arm().dh_table())
    assert model.nq == 3 and model.nv == 3
    assert [model.names[i] for i in range(1, model.njoints)] == ["waist", "shoulder", "elbow"]
    assert [model.joints[i].shortname() for i in range(1, 4)] == ["JointModelRZ"] * 3
    assert model.existFrame("tool")


def test_no_revolute_row():
    with pytest.raises(ValueError, match="has no joint row"):
        build_model(DHTable((DHRow(0.0, 10.0, 0.0, kind="fixed"),), "standard", "tool-only"))


@pytest.mark.parametrize("q", [[0.1, 0.2], np.zeros((4, 2)), np.zeros(6), 0.3])
def test_bad_configuration_shapes(q):
    pa = PinocchioArm(paper_arm().dh_table())
    for method in (pa.fk, pa.jacobian):
        with pytest.raises(ValueError, match=r"expected \(\.\.\., 3\)"):
            method(q)
    with pytest.raises(ValueError, match=r"expected \(3,\)"):
        pa.placement(q)

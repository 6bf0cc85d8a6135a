"""analysis.kinematics.dh: D-H link transforms (standard: the paper's Table 1 / section 1.2;
modified:
seed 001's palletizer, its eq. 8), numeric and symbolic.

References used here, each independent of the library's single formula:
- products of elementary motions written out in ``helpers`` (Rz Tz Tx Rx / Rx Tx Rz Tz);
- the six matrices printed in the paper's section 1.2 (A1, A1^-1, A2, A2^-1, A3, A3^-1)
  and the entries of eq. 2, transcribed below from the paper text;
- the five matrices 0_1T .. 4_5T printed in seed 001 (after its eq. 8), transcribed below.
"""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
import sympy as sp

from analysis.kinematics.arm import paper_arm
from analysis.kinematics.dh import (
    DHRow,
    DHTable,
    inverse_transform,
    link_transform,
    link_transform_sym,
)
from analysis.kinematics.params import paper_params
from helpers import (
    assert_allclose,
    assert_sym_equal,
    assert_transform_close,
    reference_link,
    sym_reference_link,
)

# Tolerances: every matrix entry is a product of at most a few sin/cos (|.| <= 1, error
# ~1 ulp) and lengths of at most ~1e3 mm here, so float64 agreement is ~1e-13 mm and
# ~1e-15 in rotations; 1e-12 / 1e-9 mm leave a wide margin while any wrong sign or
# swapped entry is off by O(1).
ATOL_ROT = 1e-12
ATOL_MM = 1e-9

c = sp.cos
s = sp.sin
th1, th2, th3, th4 = sp.symbols("theta1:5", real=True)
L1, L2, L3 = sp.symbols("L1 L2 L3", positive=True)

# --- the paper, section 1.2, transcribed from the text ---------------------------------
PAPER_A = {
    "A1": sp.Matrix([[c(th1), 0, s(th1), 0], [s(th1), 0, -c(th1), 0], [0, 1, 0, L1], [0, 0, 0, 1]]),
    "A1^-1": sp.Matrix(
        [[c(th1), s(th1), 0, 0], [0, 0, 1, -L1], [s(th1), -c(th1), 0, 0], [0, 0, 0, 1]]
    ),
    "A2": sp.Matrix(
        [
            [c(th2), -s(th2), 0, L2 * c(th2)],
            [s(th2), c(th2), 0, L2 * s(th2)],
            [0, 0, 1, 0],
            [0, 0, 0, 1],
        ]
    ),
    "A2^-1": sp.Matrix(
        [[c(th2), s(th2), 0, -L2], [-s(th2), c(th2), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    ),
    "A3": sp.Matrix(
        [
            [c(th3), -s(th3), 0, L3 * c(th3)],
            [s(th3), c(th3), 0, L3 * s(th3)],
            [0, 0, 1, 0],
            [0, 0, 0, 1],
        ]
    ),
    "A3^-1": sp.Matrix(
        [[c(th3), s(th3), 0, -L3], [-s(th3), c(th3), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    ),
}

# --- seed 001 (palletizer), the five matrices after eq. 8, transcribed ------------------
# In seed 001 the symbols L1, L2 are the arm lengths (a_2, a_3), L3 the tool drop (d_5)
# and h the tool reach (a_4); theta5 = 0.
pL1, pL2, pL3, ph = sp.symbols("L1 L2 L3 h", positive=True)
SEED001_T = [
    sp.Matrix([[c(th1), -s(th1), 0, 0], [s(th1), c(th1), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
    sp.Matrix([[c(th2), -s(th2), 0, 0], [0, 0, 1, 0], [-s(th2), -c(th2), 0, 0], [0, 0, 0, 1]]),
    sp.Matrix([[c(th3), -s(th3), 0, pL1], [s(th3), c(th3), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
    sp.Matrix([[c(th4), -s(th4), 0, pL2], [s(th4), c(th4), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
    sp.Matrix([[1, 0, 0, ph], [0, 0, -1, -pL3], [0, 1, 0, 0], [0, 0, 0, 1]]),
]


def seed001_symbolic_table() -> DHTable:
    """Seed 001's modified D-H table with its symbolic lengths (Craig layout)."""
    return DHTable(
        (
            DHRow(alpha=0.0, a=0.0, d=0.0, name="theta1"),
            DHRow(alpha=-math.pi / 2, a=0.0, d=0.0, name="theta2"),
            DHRow(alpha=0.0, a=pL1, d=0.0, name="theta3"),
            DHRow(alpha=0.0, a=pL2, d=0.0, name="theta4"),
            DHRow(alpha=math.pi / 2, a=ph, d=pL3, kind="fixed", name="tool"),
        ),
        "modified",
    )


def random_rows(rng, n):
    """theta, d, a, alpha (n,) with lengths in [-500, 500] mm and angles in [-2 pi, 2 pi]."""
    return (
        rng.uniform(-2 * np.pi, 2 * np.pi, n),
        rng.uniform(-500, 500, n),
        rng.uniform(-500, 500, n),
        rng.uniform(-2 * np.pi, 2 * np.pi, n),
    )


# --- numeric single links ----------------------------------------------------------------


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_link_transform_equals_product_of_elementary_motions(rng, convention):
    theta, d, a, alpha = random_rows(rng, 5000)
    T = link_transform(theta, d, a, alpha, convention)
    assert T.shape == (5000, 4, 4)
    assert_transform_close(T, reference_link(theta, d, a, alpha, convention), ATOL_ROT, ATOL_MM)


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_numeric_equals_sympy_on_random_rows(rng, convention):
    """The SymPy path, evaluated, equals the NumPy path; and the SymPy matrix equals the
    symbolic product of elementary motions exactly."""
    t, d, a, al = sp.symbols("t d a al", real=True)
    M = link_transform_sym(t, d, a, al, convention)
    assert_sym_equal(M, sym_reference_link(t, d, a, al, convention), f"{convention} link")
    f = sp.lambdify((t, d, a, al), M, "numpy")
    for theta, dd, aa, alpha in zip(*random_rows(rng, 200), strict=True):
        expected = np.array(f(theta, dd, aa, alpha), dtype=float)
        assert_transform_close(
            link_transform(theta, dd, aa, alpha, convention), expected, ATOL_ROT, ATOL_MM
        )


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_link_transform_is_a_rigid_motion(rng, convention):
    theta, d, a, alpha = random_rows(rng, 1000)
    R = link_transform(theta, d, a, alpha, convention)[..., :3, :3]
    assert_allclose(
        R @ np.swapaxes(R, -1, -2), np.broadcast_to(np.eye(3), R.shape), ATOL_ROT, "R R^T"
    )
    assert_allclose(np.linalg.det(R), 1.0, ATOL_ROT, "det R")


def test_link_transform_broadcasts():
    theta = np.linspace(-1, 1, 6).reshape(2, 3)
    T = link_transform(theta, 660.0, 0.0, np.pi / 2)
    assert T.shape == (2, 3, 4, 4)
    for idx in np.ndindex(2, 3):
        assert_transform_close(T[idx], link_transform(theta[idx], 660.0, 0.0, np.pi / 2), 0.0, 0.0)
    # (n,) d against (2, 1) theta -> (2, n)
    T2 = link_transform(np.array([[0.1], [0.2]]), np.array([1.0, 2.0, 3.0]), 0.0, 0.0)
    assert T2.shape == (2, 3, 4, 4)
    assert_allclose(T2[..., 2, 3], [[1.0, 2.0, 3.0]] * 2, 0.0, "d column")


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_inverse_transform(rng, convention):
    theta, d, a, alpha = random_rows(rng, 2000)
    T = link_transform(theta, d, a, alpha, convention).reshape(20, 100, 4, 4)
    Tinv = inverse_transform(T)
    assert Tinv.shape == T.shape
    eye = np.broadcast_to(np.eye(4), T.shape)
    # |p| <= ~710 mm: the product's translation carries ~1e-13 mm of round-off
    assert_transform_close(Tinv @ T, eye, ATOL_ROT, ATOL_MM, "T^-1 T")
    assert_transform_close(T @ Tinv, eye, ATOL_ROT, ATOL_MM, "T T^-1")
    assert_transform_close(Tinv, np.linalg.inv(T), 1e-12, 1e-9, "vs numpy.linalg.inv")


# --- the paper's matrices (section 1.2) ------------------------------------------------


def paper_symbolic_transforms():
    table = paper_arm().dh_table(symbolic=True)
    A = table.transforms_sym((th1, th2, th3))
    return table, A


def test_symbolic_table_uses_the_papers_symbols():
    table, A = paper_symbolic_transforms()
    assert table.convention == "standard"
    assert A[0].free_symbols == {th1, L1}
    assert A[1].free_symbols == {th2, L2}
    assert A[2].free_symbols == {th3, L3}


@pytest.mark.parametrize("i", [1, 2, 3])
def test_paper_printed_A_i_and_inverse_are_right(i):
    """All six printed matrices of section 1.2 are right (A_i and A_i^-1, i = 1..3)."""
    _, A = paper_symbolic_transforms()
    Ai = A[i - 1]
    assert_sym_equal(Ai, PAPER_A[f"A{i}"], f"A{i} vs printed")
    inv = sp.simplify(Ai.inv())
    assert_sym_equal(inv, PAPER_A[f"A{i}^-1"], f"A{i}^-1 vs printed")
    assert_sym_equal(
        sp.simplify(PAPER_A[f"A{i}^-1"] * PAPER_A[f"A{i}"]), sp.eye(4), f"printed A{i}^-1 A{i}"
    )


def test_paper_A_i_numeric_matches_printed(rng):
    """Numeric transforms and inverse_transform against the printed matrices evaluated at
    Table 3's lengths and random angles."""
    P = paper_params()
    table = paper_arm().dh_table()
    q = rng.uniform(-np.pi, np.pi, (50, 3))
    A = table.transforms(q)
    subs_len = {L1: P.L1, L2: P.L2, L3: P.L3}
    for i in (1, 2, 3):
        f = sp.lambdify((th1, th2, th3), PAPER_A[f"A{i}"].subs(subs_len), "numpy")
        finv = sp.lambdify((th1, th2, th3), PAPER_A[f"A{i}^-1"].subs(subs_len), "numpy")
        for k in range(len(q)):
            assert_transform_close(
                A[k, i - 1], np.array(f(*q[k]), float), ATOL_ROT, ATOL_MM, f"A{i}"
            )
            assert_transform_close(
                inverse_transform(A[k, i - 1]),
                np.array(finv(*q[k]), float),
                ATOL_ROT,
                ATOL_MM,
                f"A{i}^-1",
            )


def test_paper_eq2_entries_and_the_a_x_erratum():
    """T3 = A1 A2 A3 (eq. 1) against eq. 2's printed n, o, a, P entries.

    All printed entries hold except a_x: the paper prints a_x = 0, but the third column of
    A1 A2 A3 is (sin theta1, -cos theta1, 0). The test encodes the correct value.
    """
    _, A = paper_symbolic_transforms()
    T3 = sp.simplify(A[0] * A[1] * A[2])
    t23 = th2 + th3
    printed = {
        (0, 0): c(th1) * c(t23), (1, 0): s(th1) * c(t23), (2, 0): s(t23),
        (0, 1): -c(th1) * s(t23), (1, 1): -s(th1) * s(t23), (2, 1): c(t23),
        (1, 2): -c(th1), (2, 2): 0,
        (0, 3): L3 * c(th1) * c(t23) + L2 * c(th1) * c(th2),
        (1, 3): L3 * s(th1) * c(t23) + L2 * s(th1) * c(th2),
        (2, 3): L3 * s(t23) + L2 * s(th2) + L1,
    }  # fmt: skip
    for (i, j), value in printed.items():
        assert sp.simplify(T3[i, j] - value) == 0, f"T3[{i},{j}] = {T3[i, j]} != printed {value}"
    assert sp.simplify(T3[0, 2] - s(th1)) == 0
    assert sp.simplify(T3[0, 2]) != 0, "a_x is sin(theta1), not the printed 0"


# --- modified D-H: seed 001's palletizer -------------------------------------------------


def test_seed001_symbolic_matrices_match_printed():
    A = seed001_symbolic_table().transforms_sym((th1, th2, th3, th4))
    assert len(A) == 5
    for k, (got, printed) in enumerate(zip(A, SEED001_T, strict=True)):
        assert_sym_equal(got, printed, f"{k}_{k + 1}T")


def test_palletizer_description_matches_seed001_printed_matrices(rng):
    """data/arms/palletizer.toml's modified D-H rows equal seed 001's matrices with the
    description's assumed lengths (L1 = L2 = 200, h = 70, L3 = 50 mm)."""
    from analysis.kinematics.arm import load_arm

    table = load_arm("palletizer").table
    assert table.n_joints == 4 and len(table.rows) == 5 and table.rows[-1].kind == "fixed"
    values = {pL1: 200, pL2: 200, pL3: 50, ph: 70}
    q = rng.uniform(-np.pi, np.pi, (40, 4))
    A = table.transforms(q)
    fs = [sp.lambdify((th1, th2, th3, th4), M.subs(values), "numpy") for M in SEED001_T]
    for k in range(len(q)):
        T = np.eye(4)
        for i, f in enumerate(fs):
            Mi = np.array(f(*q[k]), float)
            assert_transform_close(A[k, i], Mi, ATOL_ROT, ATOL_MM, f"{i}_{i + 1}T")
            T = T @ Mi
        assert_transform_close(table.fk(q[k]), T, ATOL_ROT, ATOL_MM, "0_5T (eq. 9)")


# --- DHTable ------------------------------------------------------------------------------


def test_table_fk_shapes_and_product(rng):
    table = paper_arm().dh_table()
    q = rng.uniform(-np.pi, np.pi, (4, 5, 3))
    T = table.fk(q)
    assert T.shape == (4, 5, 4, 4)
    assert table.transforms(q).shape == (4, 5, 3, 4, 4)
    assert table.fk(q[0, 0]).shape == (4, 4)
    ref = np.eye(4)
    for theta, row in zip(q[1, 2], table.rows, strict=True):
        ref = ref @ reference_link(theta, row.d, row.a, row.alpha, "standard")
    assert_transform_close(T[1, 2], ref, ATOL_ROT, ATOL_MM)


def test_theta_offsets_and_fixed_rows(rng):
    rows = (
        DHRow(alpha=0.3, a=10.0, d=5.0, theta_offset=0.7),
        DHRow(alpha=-1.1, a=200.0, d=0.0, theta_offset=0.0, kind="fixed"),
        DHRow(alpha=0.0, a=100.0, d=-20.0, theta_offset=-2.0),
    )
    for convention in ("standard", "modified"):
        table = DHTable(rows, convention)
        assert table.n_joints == 2
        q = rng.uniform(-np.pi, np.pi, (30, 2))
        theta = table.joint_angles(q)
        assert_allclose(
            theta, np.stack([q[:, 0] + 0.7, np.zeros(30), q[:, 1] - 2.0], axis=-1), 1e-15
        )
        ref = np.eye(4)
        for i, row in enumerate(rows):
            ref = ref @ reference_link(theta[:, i], row.d, row.a, row.alpha, convention)
        assert_transform_close(table.fk(q), ref, ATOL_ROT, ATOL_MM, convention)
        # symbolic path with the same offsets and the fixed row
        syms = sp.symbols("q1 q2", real=True)
        f = sp.lambdify(syms, sp.prod(table.transforms_sym(syms, exact=False)), "numpy")
        assert_transform_close(
            table.fk(q[0]), np.array(f(*q[0]), float), ATOL_ROT, ATOL_MM, "sympy"
        )


def test_transforms_sym_exact_twist():
    """With exact=True a 90 deg twist gives exact 0 and 1 (no 6.1e-17 residue)."""
    A1 = paper_arm().dh_table().transforms_sym()[0]
    assert A1[2, 1] == 1 and A1[2, 2] == 0 and A1[0, 1] == 0
    A1_float = paper_arm().dh_table().transforms_sym(exact=False)[0]
    assert A1_float[2, 2] != 0  # cos(pi/2) in floating point: shows why exact is the default


# --- errors --------------------------------------------------------------------------------


def test_unknown_convention():
    with pytest.raises(ValueError, match="unknown D-H convention 'craig'"):
        link_transform(0.0, 0.0, 0.0, 0.0, "craig")
    with pytest.raises(ValueError, match="unknown D-H convention 'craig'"):
        link_transform_sym(0, 0, 0, 0, "craig")
    with pytest.raises(ValueError, match="unknown D-H convention 'Standard'"):
        DHTable((DHRow(0.0, 1.0, 0.0),), "Standard")


def test_wrong_joint_count():
    table = paper_arm().dh_table()
    for q in ([0.1, 0.2], [0.1, 0.2, 0.3, 0.4], np.zeros((5, 2)), 0.3):
        with pytest.raises(ValueError, match=r"expected \(\.\.\., 3\)"):
            table.fk(q)
    with pytest.raises(ValueError, match="2 joint symbols given; the table has 3 joints"):
        table.transforms_sym(sp.symbols("a b"))


def test_bad_rows():
    with pytest.raises(ValueError, match="at least one row"):
        DHTable((), "standard")
    with pytest.raises(ValueError, match="d = nan is not finite"):
        DHRow(alpha=0.0, a=1.0, d=float("nan"), name="j")
    with pytest.raises(ValueError, match="a = inf is not finite"):
        DHRow(alpha=0.0, a=float("inf"), d=0.0)
    with pytest.raises(ValueError, match="kind 'sliding'"):
        DHRow(alpha=0.0, a=1.0, d=0.0, kind="sliding")


def _write(tmp_path, text):
    path = tmp_path / "table.csv"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("alpha_deg,a_mm\n0,1\n", "missing column.*d_mm"),
        ("a_mm,d_mm\n0,1\n", "missing column.*alpha_deg"),
        ("alpha_deg,a_mm,d_mm\n0,abc,1\n", "line 2: could not convert string to float: 'abc'"),
        ("alpha_deg,a_mm,d_mm\n0,1,1\n90,,1\n", "line 3"),
        ("alpha_deg,a_mm,d_mm\n0,1,nan\n", "line 2: .*d = nan is not finite"),
        ("alpha_deg,a_mm,d_mm,kind\n0,1,1,slider\n", "line 2: .*kind 'slider'"),
        ("alpha_deg,a_mm,d_mm\n", "at least one row"),
    ],
)
def test_bad_csv(tmp_path, text, message):
    with pytest.raises(ValueError, match=message):
        DHTable.from_csv(_write(tmp_path, text), "standard")


def test_csv_round_trip(tmp_path):
    path = _write(
        tmp_path,
        "joint,kind,alpha_deg,a_mm,d_mm,theta_offset_deg\nj1,revolute,90,0,660,0\nj2,,0,310,0,-90\n",
    )
    table = DHTable.from_csv(path, "standard")
    assert table.name == "table"
    assert [r.name for r in table.rows] == ["j1", "j2"]
    assert [r.kind for r in table.rows] == ["revolute", "revolute"]
    assert_allclose([r.alpha for r in table.rows], [np.pi / 2, 0.0], 1e-15)
    assert_allclose([r.theta_offset for r in table.rows], [0.0, -np.pi / 2], 1e-15)


def test_docstring_examples():
    import analysis.kinematics.dh

    result = doctest.testmod(analysis.kinematics.dh)
    assert result.attempted >= 1 and result.failed == 0

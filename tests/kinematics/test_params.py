"""analysis.kinematics.params: an arm's numbers (Params), the paper's Table 3 read from
data/table3.csv, and the parameter checks (analysis.validate's, the closed form's when the arm
takes them: Arm.with_)."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import sympy as sp

from analysis.kinematics.arm import paper_arm
from analysis.kinematics.params import ArmParams, Params, data_dir, load_table3, paper_params


def _arm(P: Params):
    """The paper's arm with the numbers ``P`` (what ``--params`` does)."""
    return paper_arm().with_(**P, pulses_per_rev=P.pulses_per_rev)


def test_table3_values():
    """Table 3 / section 3 as printed: 660, 310, 200 mm; 1.8 deg steps; 4000 pulses/rev
    (0.09 deg resolution = 360 / 4000)."""
    P = load_table3()
    assert (P.L1, P.L2, P.L3) == (660.0, 310.0, 200.0)
    assert P.pulses_per_rev == (4000, 4000, 4000)
    assert P.step_angle_deg == (1.8, 1.8, 1.8)
    assert P.resolution_deg == (0.09, 0.09, 0.09)
    for ppr, res in zip(P.pulses_per_rev, P.resolution_deg, strict=True):
        assert math.isclose(360.0 / ppr, res, abs_tol=1e-12)
    assert paper_params() == P
    geo = paper_arm().geometry
    assert (geo["reach_outer"], geo["reach_inner"]) == (510.0, 110.0)


def test_params_are_numbers():
    """Params holds numbers only: no description, no closed form, no geometry."""
    P = paper_params()
    assert dict(P) == {"L1": 660.0, "L2": 310.0, "L3": 200.0}
    with pytest.raises(AttributeError, match="no parameter 'reach_outer'"):
        _ = P.reach_outer
    with pytest.raises(ValueError, match=r"unknown parameter\(s\) \['L4'\]"):
        P.with_(L4=1.0)


def test_dh_table_numeric_and_symbolic():
    arm = paper_arm()
    table = arm.dh_table()
    assert table.convention == "standard" and table.n_joints == 3
    assert [(r.a, r.d) for r in table.rows] == [(0.0, 660.0), (310.0, 0.0), (200.0, 0.0)]
    assert [r.alpha for r in table.rows] == [math.pi / 2, 0.0, 0.0]
    sym = arm.dh_table(symbolic=True)
    assert sym.rows[0].alpha == sp.pi / 2
    assert {str(sym.rows[0].d), str(sym.rows[1].a), str(sym.rows[2].a)} == {"L1", "L2", "L3"}
    assert all(v.is_positive for v in (sym.rows[0].d, sym.rows[1].a, sym.rows[2].a))


def test_reach_inner_when_forearm_is_longer():
    assert _arm(ArmParams(L1=0.0, L2=100.0, L3=250.0)).geometry["reach_inner"] == 150.0


def test_with_revalidates():
    P = paper_params()
    assert P.with_(L2=400.0).L2 == 400.0 and P.with_(L2=400.0).L3 == P.L3
    with pytest.raises(ValueError, match="L3 = 0"):
        paper_arm().with_(L3=0.0)


def test_data_dir_env_override(tmp_path, monkeypatch):
    monkeypatch.setenv("ANALYSIS_DATA_DIR", str(tmp_path))
    assert data_dir() == tmp_path
    monkeypatch.setenv("ANALYSIS_DATA_DIR", str(tmp_path / "nope"))
    with pytest.raises(FileNotFoundError, match="nope"):
        data_dir()


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"L2": -310.0}, r"L2 = -310.0 mm: link lengths must be > 0"),
        ({"L2": 0.0}, r"L2 = 0.0 mm: link lengths must be > 0"),
        ({"L3": -1}, r"L3 = -1.0 mm: link lengths must be > 0"),
        ({"L3": 0}, r"L3 = 0.0 mm: link lengths must be > 0"),
        ({"L1": -660.0}, r"L1 = -660.0 mm is negative"),
        ({"L1": float("nan")}, r"L1 = nan mm is not finite"),
        ({"L2": float("inf")}, r"L2 = inf mm is not finite"),
        ({"L3": -float("inf")}, r"L3 = -inf mm is not finite"),
        ({"L2": "310"}, r"L2 = '310' is text, not a number"),
        ({"L2": True}, r"L2 = True is a boolean, not a number"),
        ({"L2": 1 + 0j}, r"L2 = \(1\+0j\) is complex"),
        ({"L2": 1e200}, r"L2 = 1e\+200 mm is beyond 1e\+06 mm, the largest length"),
        ({"L2": 1e-200}, r"L2 = 1e-200 mm: a non-zero length must be at least 0.001 mm"),
        ({"L2": 10**400}, r"L2 = 1000.* is beyond the float range"),
        ({"pulses_per_rev": (4000, 0, 4000)}, r"pulses_per_rev = \(4000, 0, 4000\)"),
        ({"pulses_per_rev": (4000, 4000, -4000)}, r"pulses_per_rev = \(4000, 4000, -4000\)"),
        ({"pulses_per_rev": (4000, 4000.5, 4000)}, r"pulses_per_rev = \(4000, 4000.5, 4000\)"),
        ({"pulses_per_rev": (4000, 4000)}, r"pulses_per_rev = \(4000, 4000\)"),
        ({"pulses_per_rev": (4000, float("nan"), 4000)}, r"pulses_per_rev = \(4000, nan, 4000\)"),
        ({"pulses_per_rev": (4000, float("inf"), 4000)}, r"pulses_per_rev = \(4000, inf, 4000\)"),
        ({"pulses_per_rev": ("4000", 4000, 4000)}, r"pulses_per_rev = \('4000', 4000, 4000\)"),
        ({"pulses_per_rev": 4000}, r"pulses_per_rev = 4000"),
    ],
)
def test_invalid_params_name_the_value(changes, message):
    base = {"L1": 660.0, "L2": 310.0, "L3": 200.0}
    with pytest.raises(ValueError, match=message):
        _arm(ArmParams(**{**base, **changes}))


def test_numpy_scalars_are_accepted():
    """Lengths read with NumPy/pandas arrive as NumPy scalars and must be accepted."""
    P = ArmParams(
        L1=np.float64(660),
        L2=np.int64(310),
        L3=np.float32(200),
        pulses_per_rev=np.array([4000] * 3),
    )
    assert (P.L1, P.L2, P.L3, P.pulses_per_rev) == (660.0, 310.0, 200.0, (4000, 4000, 4000))
    assert all(type(p) is int for p in P.pulses_per_rev)


# --- malformed table3.csv ------------------------------------------------------------------


@pytest.fixture
def table3():
    return pd.read_csv(data_dir() / "table3.csv")


def _save(df, tmp_path):
    path = tmp_path / "table3.csv"
    df.to_csv(path, index=False)
    return path


def test_round_trip_of_the_fixture(table3, tmp_path):
    assert load_table3(_save(table3, tmp_path)) == load_table3()


@pytest.mark.parametrize(
    "column", ["alpha_deg", "a_mm", "d_mm", "cos_alpha", "pulses_per_rev", "step_angle_deg"]
)
def test_missing_column(table3, tmp_path, column):
    with pytest.raises(ValueError, match=f"missing column.*{column}"):
        load_table3(_save(table3.drop(columns=column), tmp_path))


def test_wrong_alpha(table3, tmp_path):
    table3.loc[1, "alpha_deg"] = 90
    with pytest.raises(
        ValueError, match=r"alpha_deg = \[90.0, 90.0, 0.0\]; the closed-form IK needs \[90, 0, 0\]"
    ):
        load_table3(_save(table3, tmp_path))


def test_cos_sin_disagree_with_alpha(table3, tmp_path):
    table3.loc[0, "sin_alpha"] = 0
    with pytest.raises(ValueError, match="link waist: cos/sin columns disagree with alpha"):
        load_table3(_save(table3, tmp_path))


def test_wrong_row_count(table3, tmp_path):
    with pytest.raises(ValueError, match="2 rows; the arm has 3 links"):
        load_table3(_save(table3.iloc[:2], tmp_path))


def test_wrong_topology(table3, tmp_path):
    table3.loc[1, "d_mm"] = 5
    with pytest.raises(ValueError, match=r"need a_1 = 0 and d_2 = d_3 = 0"):
        load_table3(_save(table3, tmp_path))


@pytest.mark.parametrize(
    ("column", "row", "value", "message"),
    [
        ("a_mm", 1, -310, r"L2 = -310.0 mm: link lengths must be > 0"),
        ("a_mm", 2, 0, r"L3 = 0.0 mm: link lengths must be > 0"),
        ("d_mm", 0, -660, r"L1 = -660.0 mm is negative"),
        ("a_mm", 1, float("nan"), r"line 3 column a_mm: empty; a number is required"),
        ("cos_alpha", 0, float("nan"), r"line 2 column cos_alpha: empty"),
        ("step_angle_deg", 0, -1.8, r"step_angle_deg: -1.8 deg must be > 0"),
        ("resolution_deg", 2, float("inf"), r"column resolution_deg: 'inf' is not a finite"),
        ("pulses_per_rev", 2, 0, r"pulses_per_rev = \(4000, 4000, 0\)"),
    ],
)
def test_bad_values_in_table3(table3, tmp_path, column, row, value, message):
    table3[column] = table3[column].astype(float)
    table3.loc[row, column] = value
    with pytest.raises(ValueError, match=message):
        _arm(load_table3(_save(table3, tmp_path)))


def test_text_in_a_number_column(table3, tmp_path):
    table3["a_mm"] = table3["a_mm"].astype(object)
    table3.loc[1, "a_mm"] = "three hundred"
    with pytest.raises(ValueError, match="three hundred"):
        load_table3(_save(table3, tmp_path))

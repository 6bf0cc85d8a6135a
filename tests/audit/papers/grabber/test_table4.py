"""Table 4 recomputed (analysis.audit.papers.grabber.table4), checked against Pinocchio and
plain geometry."""

import numpy as np
import pytest

from analysis.audit.papers.grabber import table4
from analysis.kinematics.arm import paper_arm
from analysis.kinematics.params import paper_params
from analysis.kinematics.pinocchio_model import PinocchioArm


@pytest.fixture(scope="module")
def summary():
    return table4.summary()


def test_row8_unreachable_by_geometry(summary):
    r = summary.set_index("row").loc[8]
    prm = paper_params()
    d = np.linalg.norm([200.0, 500.0, 600.0 - prm.L1]) - (prm.L2 + prm.L3)
    assert not r["reachable"] and r["outside_mm"] == pytest.approx(d, abs=1e-9)
    assert r["outside_mm"] == pytest.approx(31.85, abs=0.005)
    assert r["theta1_atan2_deg"] == pytest.approx(68.20, abs=0.005)  # printed 68.2: defined anyway
    assert r["verdict"].startswith("unreachable")


def test_fk_of_printed_angles_matches_pinocchio(summary):
    pa = PinocchioArm(paper_arm().dh_table())
    ok = summary["fk_error_mm"].notna().to_numpy()
    q = np.radians(
        summary.loc[ok, ["printed_theta1", "printed_theta2", "printed_theta3"]]
        .astype(float)
        .to_numpy()
    )
    fk = pa.fk(q)
    np.testing.assert_allclose(
        summary.loc[ok, ["fk_printed_x_mm", "fk_printed_y_mm", "fk_printed_z_mm"]], fk, atol=1e-9
    )  # two FK implementations, float64 round-off only


def test_verdicts_and_causes(summary):
    s = summary.set_index("row")
    assert list(s.index[s["verdict"] == "wrong"]) == [1, 2, 4, 9]
    for row in (1, 2, 4):
        assert not s.loc[row, "cell2_ok"]
        assert "tan^-1" in s.loc[row, "cause2"]
        assert float(s.loc[row, "printed_theta2"]) - s.loc[row, "theta2_deg"] == pytest.approx(
            180.0, abs=0.01
        )
        assert s.loc[row, "fk_error_mm"] > 300.0
    assert s.loc[9, "cause3"].startswith("undecidable")
    assert s.loc[9, "theta3_deg"] == pytest.approx(
        s.loc[6, "theta3_deg"], abs=1e-12
    )  # same geometry
    for row in (3, 5, 6, 7, 10):
        assert s.loc[row, "fk_error_mm"] < 0.1  # two-decimal angles: < 0.005 deg * 510 mm ~ 0.05 mm


def test_printed_formulas_reproduce_the_190_and_205(summary):
    p = summary[["x_mm", "y_mm", "z_mm"]].to_numpy()[[0, 1, 3]]
    lit = table4.printed_formulas(p)
    np.testing.assert_allclose(lit[:, 1], [190.2087, 205.1399, 205.1399], atol=1e-4)


def test_printed_formulas_float32_close_and_px0_refused():
    p = np.array([[100.0, 300.0, 600.0]])
    np.testing.assert_allclose(
        table4.printed_formulas(p, dtype=np.float32), table4.printed_formulas(p), atol=1e-3
    )
    with pytest.raises(ValueError, match="Px = 0"):
        table4.printed_formulas([[0.0, 100.0, 600.0]])


def test_all_branches_reach_the_target(summary, arm):
    from analysis.kinematics.arm import BRANCHES

    ok = summary["reachable"].to_numpy()
    p = summary[["x_mm", "y_mm", "z_mm"]].to_numpy()[ok]
    for b in BRANCHES:
        q = np.radians(summary.loc[ok, [f"{b}_theta{j}_deg" for j in (1, 2, 3)]].to_numpy())
        np.testing.assert_allclose(arm.fk(q), p, atol=1e-9)

"""analysis.audit.papers.gr1.thesis: Table 5-4 recomputed, the counter presets, the work area
and the FX2N move, against independent references (the VB6 test's FK misses, hand computations from
Table 2-1, the planar chain's analytic reach, the sequential model's own timing).

Tolerances: positions 1e-9 mm (float64 on a 529 mm chain, see tests/kinematics/test_gr1.py);
printed numbers to their printed digits.
"""

from __future__ import annotations

import numpy as np
import pytest

from analysis.audit.papers.gr1 import thesis as S
from analysis.kinematics.status import Status


@pytest.fixture(scope="module")
def arm():
    return S.gr1_arm()


def test_table5_4_printed_and_corrected(arm):
    t = S.table5_4(arm).set_index(["pose", "source"])
    # the printed angles miss Table 5-3's positions (as tests/audit/test_vb6.py measures)
    assert t.loc[("start", "printed"), "miss_mm"] == pytest.approx(503.995, abs=1e-3)
    assert t.loc[("end", "printed"), "miss_mm"] == pytest.approx(173.290, abs=1e-3)
    for pose, turn in (("start", 69.137), ("end", 60.733)):
        for b in arm.branches:  # every branch reaches the position, none the orientation
            assert t.loc[(pose, b), "miss_mm"] <= 1e-9
            assert t.loc[(pose, b), "turn_deg"] == pytest.approx(turn, abs=1e-3)
    assert t.loc[("start", "front-down"), "within_limits"]
    assert not t.loc[("start", "front-up"), "within_limits"]  # theta4 = 168.2 > 135 (assumed)
    assert t.loc[("end", "front-up"), "within_limits"]


def test_projection_is_idempotent_and_solvable(arm):
    proj, turn = S.project_orientation(arm, S.thesis_poses())
    np.testing.assert_allclose(np.degrees(turn), [69.137, 60.733], atol=1e-3)
    again, turn2 = S.project_orientation(arm, proj)
    np.testing.assert_allclose(again, proj, atol=1e-12)
    assert np.abs(turn2).max() <= 1e-12
    assert arm.solve(S.thesis_poses()).status.tolist() == [Status.ORIENTATION] * 2
    q, names = S.first_within_limits(arm, proj)
    assert names.tolist() == ["front-down", "front-up"]
    np.testing.assert_allclose(S.pose_of(arm, q), proj, atol=1e-9)


def test_printed_presets_are_degrees_except_c235():
    df = S.printed_presets().set_index("counter")
    assert df["matches"].tolist() == ["pulses", "degrees", "neither", "degrees", "degrees"]
    # by hand: 146.928 / 0.11 = 1335.7; 118.526 / 0.11 = 1077.5 (rounds to 119 deg, printed 118)
    assert df["as_pulses"].tolist() == [4, 1336, 1078, 283, 65]
    assert df.loc["C237", "as_degrees"] == 119


def test_counter_presets(arm):
    q0 = np.radians([56.828, 18.737, 35.722, 132.437, 123.517])
    qf = np.radians([56.310, 40.999, -15.127, -129.070, 51.131])
    df = S.counter_presets(q0, qf)
    assert df["counter"].tolist() == ["C235", "C236", "C237", "C238", "C239"]
    assert df["preset"].tolist() == [4, 202, 462, 2377, 302]
    assert df["direction"].tolist() == ["-", "+", "-", "-", "-"]
    # a counter stops the joint within half a pulse of the change
    assert (np.abs(df["error_deg"]) <= df["resolution_deg"] / 2 + 1e-12).all()
    with pytest.raises(ValueError, match="5 finite"):
        S.counter_presets(q0[:4], qf[:4])


def test_workspace_extents(arm):
    for limits in (True, False):
        e = S.workspace_extents(arm, limits=limits)
        # the planar chain stretched: a2 + a3 + a4 = 529 mm out, up and down
        assert e["radius_mm"] == pytest.approx(529.0, abs=1e-9)
        assert (e["z_min_mm"], e["z_max_mm"]) == pytest.approx((-529.0, 529.0), abs=1e-9)
        assert e["height_span_mm"] == e["width_span_mm"] == pytest.approx(1058.0, abs=1e-9)
    sec = S.workspace_section(arm, n=5000)
    assert np.hypot(*sec["free"].T).max() <= 529.0 + 1e-9


def test_fx2n_move(arm):
    proj, _ = S.project_orientation(arm, S.thesis_poses())
    q, _ = S.first_within_limits(arm, proj)
    r = S.fx2n_vs_cubic(arm, q[0], q[1])
    np.testing.assert_allclose(S.joint_speeds_deg_s(), [84.0, 66.0, 66.0, 66.0, 144.0])
    moved = np.abs(r["presets"]["moved_deg"].to_numpy())
    assert r["time_fx2n_s"] == pytest.approx((moved / r["speed_deg_s"]).sum(), rel=1e-12)
    assert r["time_cubic_s"] == 10.0
    np.testing.assert_allclose(r["p_cubic"][[0, -1]], arm.fk(q), atol=1e-9)
    np.testing.assert_allclose(r["p_fx2n"][0], arm.fk(q[0]), atol=1e-9)
    # the counters stop each joint within half a pulse: the hand ends < 1 mm off
    assert 0 < r["end_error_mm"] < 1.0
    # one motor at a time
    moving = np.abs(np.diff(r["q_fx2n"], axis=0)) > 1e-12
    assert (moving.sum(axis=1) <= 2).all()
    assert r["max_apart_mm"] > 50 and r["length_fx2n_mm"] > r["length_cubic_mm"]


@pytest.mark.parametrize(("old", "new", "on_path"), [
    ('lhs = "theta(t_f)"', 'lhs = "theta(t_f/2)"', [False, True, False, False]),  # a via point
    ('lhs = "Subs(Derivative(theta(t), t), t, t_f)"', 'lhs = "Subs(Derivative(theta(t), t), t, t_f/3)"', [False, False, False, True]),  # noqa: E501
    ('lhs = "theta(t_f)"', 'lhs = "t_f"', None),  # not a constraint on the joint: refused
])  # fmt: skip
def test_cp_claim_is_decided_by_where_the_printed_constraints_hold(tmp_path, monkeypatch, old, new, on_path):  # noqa: E501
    """gr1-claim-cp: the plan's constraints, read from eqs. 5.1-5.2's printed left-hand sides,
    all hold at the end points (a PTP move, not CP); a constraint moved between the ends makes
    the claim's check hold, so the register's row would explain nothing."""
    from analysis.audit import register as reg
    from analysis.audit.context import Context, bespoke, context
    from analysis.audit.papers.gr1 import checks
    from analysis.papers import load_file

    assert context("gr1").domain("plan_constraints")["on_path"].tolist() == [False] * 4
    src = (reg.data_dir() / "papers" / "gr1.toml").read_text(encoding="utf-8")
    assert src.count(old) == 1, old
    path = tmp_path / "gr1.toml"
    path.write_text(src.replace(old, new), encoding="utf-8")
    paper = load_file(path.resolve())
    ctx = Context(paper, bespoke("gr1", paper))
    monkeypatch.setattr(checks, "context", lambda _name: ctx)
    if on_path is None:
        with pytest.raises(ValueError, match=r"gr1:5.1b: t_f is not theta or its rate at a time"):
            ctx.domain("plan_constraints")
        return
    assert ctx.domain("plan_constraints")["on_path"].tolist() == on_path
    from analysis.audit.kinds import check

    assert check({"kind": "claim"}, paper.record("c5.2.1-cp")["check"]["reading"], ctx).ok

"""The printed STL (Figures 3-6) executed whole: which cause each wrong number comes from
(issue 30, item 5: evidence from the right cause)."""

from __future__ import annotations

import numpy as np

from analysis.audit import register as reg
from analysis.audit.papers.grabber import listings


def test_movd_damages_figures_5_and_6_not_figure_4():
    """MOVD's own damage: Pz - L1 = -660 mm in Figures 5-6 (the denormal Pz vanishes against
    660), where MOVR gives Pz - 660; Figure 4's c1 is the same either way (Py/Px of two
    denormals is exact), so c1 = 9 is the radians-as-degrees cause's."""
    d = {k: np.asarray(v) for k, v in listings.movd_damage().items()}
    assert (d["vd72_movd"] == -660.0).all() and (d["vd176_movd"] == -660.0).all()
    assert np.allclose(d["vd72_movr"], d["pz_minus_l1"]) and np.allclose(d["vd176_movr"], d["pz_minus_l1"])  # noqa: E501
    assert (d["c1_movd"] == d["c1_movr"]).all() and d["c1_movr"][0] == 9
    r = reg.register("grabber")
    assert "9 pulses" in r.cause("grabber-stl-degrees").consequence
    assert "9 pulses" not in r.cause("grabber-int-inputs").consequence


def test_figure5_fragment_executes_its_round():
    """The fragment runs inside its network's LPS: ROUND executes and c2 is a count (run alone,
    its LPP pops an empty stack and VD122 keeps a REAL's bits, 1073571786)."""
    m = reg.register("grabber").manifestation("grabber-stl-degrees/figure-5")
    got = m.result(m.checked).values
    assert got["first"]["VD122"] == 2 and got["want"]["VD122"] == 113.0
    alone = {k: v for k, v in m.spec.items() if k != "enter"}
    from analysis.audit.context import context
    from analysis.audit.kinds import check

    assert check(alone, m.checked, context("grabber")).values["first"]["VD122"] == 1073571786
    assert got["wrong"] <= got["n"]  # rows against rows


def test_every_fragment_that_pops_the_stack_runs_inside_its_network():
    """A printed fragment with LPP/LRD (which read the logic stack its network pushed) is run
    after the instructions it sits inside (check key 'enter'): otherwise the instruction after
    the pop does not execute and the row would report a value nothing computed."""
    for m in reg.register("grabber").manifestations:
        if m.spec.get("kind") != "stl" or m.spec.get("mode") == "order":
            continue
        ops = [ln.split()[0] for ln in m.checked.splitlines() if ln.strip()]
        if {"LPP", "LRD"} & set(ops):
            assert "LPS" in ops[: ops.index(next(o for o in ops if o in ("LPP", "LRD")))] or (
                "LPS" in m.spec.get("enter", "")), m.id

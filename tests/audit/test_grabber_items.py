"""The exact zero test and the samples behind the audit's verdicts
(analysis.audit.grabber_items), and the item families (analysis.audit.grabber_checks)."""

import numpy as np
import sympy as sp

from analysis.audit import grabber_checks
from analysis.audit import grabber_items as pc

t1, t2, t3 = pc.TH


def test_normal_form_zero_only_for_identities():
    assert pc.normal_form(sp.sin(t1) ** 2 + sp.cos(t1) ** 2 - 1) == 0
    assert pc.normal_form(sp.sin(t2 + t3) - sp.sin(t2) * sp.cos(t3) - sp.cos(t2) * sp.sin(t3)) == 0
    assert pc.normal_form(sp.cos(2 * t3) - 1 + 2 * sp.sin(t3) ** 2) == 0
    assert pc.normal_form(sp.sin(t1) * sp.cos(t1)) != 0
    assert pc.normal_form(sp.atan(t1)) is None  # other functions: caller falls back to simplify
    assert pc.is_zero(sp.atan(sp.tan(t1 / 7)) - t1 / 7) in (True, False)  # no exception


def test_is_zero_agrees_with_numeric_evaluation(rng):
    exprs = [
        (sp.cos(t1) * sp.cos(t2 + t3) - sp.sin(t2 + t3) * 0, False),
        (sp.sin(t1 + t2) ** 2 + sp.cos(t1 + t2) ** 2 - 1, True),
        ((sp.sin(t3) ** 2 - 1) / (sp.cos(t3) ** 2) + 1, True),
    ]
    for e, zero in exprs:
        assert pc.is_zero(e) is zero
        f = sp.lambdify((t1, t2, t3), e, "numpy")
        vals = np.array([f(*q) for q in rng.uniform(-3, 3, size=(20, 3))])
        # 1e-8: the 1/cos^2 term amplifies float64 round-off near cos(theta3) = 0
        assert np.allclose(vals, 0.0, atol=1e-8) is zero


def test_samples_are_front_up_solutions(arm):
    P, th = pc.samples()
    assert len(P) > 200
    np.testing.assert_allclose(arm.fk(th), P, atol=1e-9)  # mm, float64 round-off
    assert (th[:, 2] < 0).all()  # front-up: elbow angle negative


def test_kinds_and_check_names():
    items = grabber_checks.all_items()
    assert {it.kind for it in items if it.verdict == "wrong"} <= set(pc.KINDS)
    assert all(it.id.startswith(pc.OWN_PREFIX) for it in items)

"""The shared check kinds (analysis.audit.kinds) against values computed by hand.

Each kind runs in a small stand-in context (:class:`Ctx`: a few symbols, a named domain), so
the expected verdicts and numbers follow from the inputs on paper, not from any register.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from analysis.audit import harness
from analysis.audit.kinds import Result, check
from analysis.audit.kinds.listing import assigned, run_statement
from analysis.audit.kinds.symbolic import is_zero, normal_form
from analysis.audit.kinds.table import cell_matches, decimals
from analysis.papers import parse

x, y, th = sp.symbols("x y theta", real=True)
SYMS = {"x": x, "y": y, "theta": th, "phi": sp.Symbol("phi", real=True)}


class _Paper:
    id = "test"

    def parse(self, text, namespace="main"):
        return parse(text, SYMS)

    def text(self, ref):
        return {"caps": "图 1-1 a\n图 1-1 b", "line": "y = Atn(x)"}[ref]


class Ctx:
    """A stand-in for analysis.audit.context.Context: the test's symbols and domains."""

    paper = _Paper()

    def __init__(self, domains=None, matrices=None, values=None):
        self._d, self._m, self._v = domains or {}, matrices or {}, values or {}

    def domain(self, name):
        return self._d[name]

    def product(self, names):
        M = sp.eye(len(self._m[names[0]].row(0)))
        for n in names:
            M = M * self._m[n]
        return M.applyfunc(lambda e: sp.expand(sp.expand_trig(e)))

    def matrix(self, name):
        return self._m[name]

    def value(self, name, *args):
        return self._v[name](*args)


# --- symbolic -----------------------------------------------------------------------------------
def test_is_zero_and_normal_form_by_hand():
    assert is_zero(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1)
    assert is_zero(sp.sin(2 * x) - 2 * sp.sin(x) * sp.cos(x))
    assert is_zero(sp.cos(x + y) - sp.cos(x) * sp.cos(y) + sp.sin(x) * sp.sin(y))
    assert not is_zero(sp.sin(x) - sp.cos(x))
    assert not is_zero(sp.sin(x) ** 2 - sp.cos(x) ** 2)  # = -cos(2x)
    # sin^3 = sin (1 - cos^2): the normal form keeps sin to the first power only
    assert sp.expand(normal_form(sp.sin(x) ** 3) - sp.sin(x) * (1 - sp.cos(x) ** 2)) == 0


def test_identity_and_matrix_kinds():
    R = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
    ctx = Ctx(matrices={"R": R})
    assert check({"kind": "identity"}, "sin(2*theta) = 2*sin(theta)*cos(theta)", ctx).ok
    assert not check({"kind": "identity"}, "sin(2*theta) = sin(theta)*cos(theta)", ctx).ok
    # R(theta)^2 = R(2 theta): cell (1, 1) is cos(2 theta), cell (1, 2) is -sin(2 theta)
    spec = {"kind": "matrix", "product": ["R", "R"], "cells": [[1, 1], [1, 2]]}
    assert check(spec, "cos(2*theta); -sin(2*theta)", ctx).ok
    assert not check(spec, "cos(theta)**2; -sin(2*theta)", ctx).ok
    assert not check(spec, "cos(2*theta)", ctx).ok  # two cells asked, one given


# --- sampled ------------------------------------------------------------------------------------
def test_sampled_finds_the_quadrant_misses_counted_by_hand():
    """Eight points around the unit square: atan(y/x) is wrong exactly where x < 0 (three
    points: (-1, 1), (-1, 0), (-1, -1)); at x = 0 it is +-pi/2 like atan2."""
    xs = np.array([1.0, 1, 0, -1, -1, -1, 0, 1])
    ys = np.array([0.0, 1, 1, 1, 0, -1, -1, -1])
    ctx = Ctx(domains={"square": {"x": xs, "y": ys, "phi": np.arctan2(ys, xs)}})
    ok = check({"kind": "sampled", "domain": "square"}, "phi = atan2(y, x)", ctx)
    bad = check({"kind": "sampled", "domain": "square"}, "phi = atan(y/x)", ctx)
    assert ok.ok and ok.n == 8 and ok.wrong == 0
    assert not bad.ok and bad.wrong == 3 and bad.at == {"x": -1.0, "y": 1.0, "phi": pytest.approx(3 * math.pi / 4)}  # noqa: E501
    # modulo 2 pi when angle-aware (the default): phi + 2 pi is the same angle
    assert check({"kind": "sampled", "domain": "square"}, "phi = atan2(y, x) + 2*pi", ctx).ok
    assert not check({"kind": "sampled", "domain": "square", "angle": False}, "phi = atan2(y, x) + 2*pi", ctx).ok  # noqa: E501


# --- table --------------------------------------------------------------------------------------
def test_table_cells_at_the_printed_decimals():
    assert decimals("190.20") == 2 and decimals("45") == 0
    assert cell_matches("10.21", 10.2087) and not cell_matches("190.20", 10.2087)
    assert not cell_matches("10.2", 10.2087, places=2)  # the printed cell fixes two decimals
    assert cell_matches("-91.16", -91.164) and not cell_matches("-91.20", -91.164)
    assert cell_matches("3.1", 3.19, mode="truncate") and not cell_matches("3.2", 3.19, mode="truncate")  # noqa: E501
    assert [decimals(t) for t in ("45", "17.5", "190.20", "-131.71")] == [0, 1, 2, 2]
    assert cell_matches("17.5", 17.4915) and not cell_matches("17.49", 17.4849)
    assert cell_matches("190.20", 190.2087, "truncate") and not cell_matches("190.20", 190.2087)
    assert not cell_matches("无解", 1.0)  # a word never matches a number
    with pytest.raises(ValueError, match="mode"):
        cell_matches("1", 1.0, "floor")


# --- claims -------------------------------------------------------------------------------------
@pytest.mark.parametrize(("text", "ok"), [
    ("forall d: v > 0", True), ("forall d: v > 1", False), ("exists d: v > 2", True),
    ("exists d: v > 3", False), ("count d: v > 1 = 2", True), ("count d: v > 1 = 3", False),
    ("max d: v = 3.0", True), ("max d: v = 3.1", False), ("min d: v**2 = 1", True),
    ("forall d: Eq(w, v > 1)", True), ("forall nowhere: v > 0", False), ("v > 0", False),
])  # fmt: skip
def test_claims_over_a_domain_by_hand(text, ok):
    ctx = Ctx(domains={"d": {"v": np.array([1.0, 2.0, 3.0]), "w": np.array([False, True, True])}})
    assert check({"kind": "claim"}, text, ctx).ok is ok


# --- listings executed --------------------------------------------------------------------------
def test_stl_fragment_against_an_expected_output():
    """*R 2.0 doubles the REAL in VD0: 2 x for x = 1.5 and -2.25 (float32 exact)."""
    ctx = Ctx(domains={"xs": {"x": np.array([1.5, -2.25])}})
    spec = {"kind": "stl", "domain": "xs", "inputs": {"VD0": "x"}, "expect": {"VD0": "2*x"}}
    assert check(spec, "*R 2.0, VD0", ctx).ok
    assert not check(spec, "*R 3.0, VD0", ctx).ok
    assert not check(spec, "nonsense", ctx).ok


def test_vb6_statements_run_with_vb_semantics():
    assert run_statement("y = 2 * x + 1", {"x": 3.0})[0] == 7.0
    assert assigned("a = 1: b = a * 2") == "b"
    assert run_statement("y = Atn(x)", {"x": 1.0})[0] == pytest.approx(math.pi / 4)
    assert run_statement("If x > 1 Then\nExit Sub\nEnd If\ny = 1", {"x": 2.0})[0] is None
    env = {"x": 1.0}
    ctx = Ctx(values={"vb6_env": lambda config, end: (dict(env, y=math.pi / 4), None)})
    spec = {"kind": "vb6", "config": [0.0], "expect": "y", "angle": False, "tol": 1e-12}
    assert check(spec, "y = Atn(x)", ctx).ok  # Atn(1) = pi/4 (radians: VB6's Atn)
    assert not check(spec, "y = Atn(x) * 2", ctx).ok
    assert not check(spec, "z = Atn(x)", ctx).ok  # the statement must assign y


def test_vb6_controls_block():
    """A CommandButton's default property is Value: 'Command3 = False' leaves it enabled."""
    spec = {"kind": "vb6", "mode": "controls", "cases": [{"set": {"d": 2.0}, "enabled": False},
                                                          {"set": {"d": 0.5}, "enabled": True}]}  # fmt: skip  # noqa: E501
    ctx = Ctx()
    assert check(spec, "If d > 1 Then\nCommand3.Enabled = False\nEnd If", ctx).ok
    assert not check(spec, "If d > 1 Then\nCommand3 = False\nEnd If", ctx).ok


# --- labels, numbering, bespoke -----------------------------------------------------------------
def test_numbering():
    ctx = Ctx()
    assert check({"kind": "numbering", "of": "caps"}, "图 1-1 a\n图 1-2 b", ctx).ok
    assert not check({"kind": "numbering", "of": "caps"}, "图 1-1 a\n图 1-1 b", ctx).ok  # twice 1-1
    assert not check({"kind": "numbering", "of": "caps"}, "图 1-1 a\n图 1-3 b", ctx).ok  # a gap
    assert not check({"kind": "numbering", "of": "caps"}, "图 1-1 a\n图 1-2 c", ctx).ok
    assert not check({"kind": "numbering", "of": "caps"}, "图 1-1 a", ctx).ok  # one left out


def test_a_text_a_kind_cannot_read_is_not_right():
    assert check({"kind": "identity"}, "", Ctx()) == Result(False, {"why": "empty"})
    assert not check({"kind": "identity"}, "x = = y", Ctx()).ok
    assert not check({"kind": "sampled", "domain": "missing"}, "x = y", Ctx()).ok


# --- the mutation harness -----------------------------------------------------------------------
def test_harness_edits_are_single_edits_of_each_kind():
    e = harness.edits("theta1 = 2*x + 3*sin(L4p) < 1e-6", ["theta1", "x", "L4p", "y"])
    assert all(e[k] for k in harness.EDIT_KINDS)
    assert "theta2 = 2*x + 3*sin(L4p) < 1e-6" in e["index"]
    assert "theta1 = 2*x + 3*sin(L3p) < 1e-6" in e["index"]  # a digit inside a name
    assert "theta1 = 2*x + 3*cos(L4p) < 1e-6" in e["trig"]
    assert "theta1 = 2*x + 3*sin(L4p) < 1e+6" in e["threshold"]
    assert "theta1 = 2*x + 3*sin(L4p) <= 1e-6" in e["threshold"]
    assert "theta1 = 2*y + 3*sin(L4p) < 1e-6" in e["symbol"]
    assert all(t != "theta1 = 2*x + 3*sin(L4p) < 1e-6" for ts in e.values() for t in ts)

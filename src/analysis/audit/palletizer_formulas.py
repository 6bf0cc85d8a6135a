"""Tools of seed 001's register (:mod:`analysis.audit.palletizer_causes`): formulas in the
printed notation (SymPy text in the symbols of :data:`analysis.papers.palletizer.SYMBOLS`)
parsed and evaluated on targets the palletizer solves, and the builders of causes whose
``verify`` answers False instead of raising.

The targets and every number that depends on the lengths use the arm of
``data/arms/palletizer.toml``, whose every length is ASSUMED (the paper prints none).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy as sp

from analysis.audit import palletizer_checks as chk
from analysis.kinematics.arm import Arm, Status, load_arm
from analysis.papers import palletizer as paper

S = paper.SYMBOLS
FUNCS = {
    "atan": sp.atan,
    "atan2": sp.atan2,
    "asin": sp.asin,
    "acos": sp.acos,
    "sqrt": sp.sqrt,
    "sin": sp.sin,
    "cos": sp.cos,
    "Abs": sp.Abs,
    "pi": sp.pi,
    "Piecewise": sp.Piecewise,
}
ATOL = 1e-9
"""Numeric agreement [mm or rad] for a formula to count as right: float64 chains of a few
transcendental calls on lengths of a few hundred mm err by ~1e-13; every printed error
found is >= 1e-3 (most are degrees or millimetres)."""


# ---------------------------------------------------------------------------------------------
# parsing and evaluation
# ---------------------------------------------------------------------------------------------
def parse_formula(text: str) -> sp.Expr | None:
    """A SymPy expression of a text ("lhs = rhs" gives rhs), or None if it is not one."""
    rhs = text.split(" = ", 1)[1] if " = " in text else text
    try:
        expr = sp.parse_expr(rhs, local_dict={**S, **FUNCS}, evaluate=True)
    except Exception:  # any parse failure means: not a formula of this notation
        return None
    if not isinstance(expr, sp.Basic) or {s.name for s in expr.free_symbols} - set(S):
        return None
    return expr


@cache
def palletizer_arm() -> Arm:
    return load_arm("palletizer")


@cache
def _targets() -> np.ndarray:
    """Grasp points [mm] the arm solves with its elbow stop: a 21-step grid of the workspace,
    the four quadrant targets, a point whose wrist is behind the base axis (rho < L3) and the
    initial pose (sec. 3)."""
    arm = palletizer_arm()
    L1, L2, L3, h = chk.lengths(arm)
    grid = chk.workspace_grid(arm, 21)
    extra = np.vstack([chk.QUADRANT_TARGETS, [[30.0, 10.0, 100.0], [L2 + L3, 0.0, L1 - h]]])
    G = np.vstack([grid, extra])
    return G[arm.solve(G).status == Status.OK]


@cache
def target_values() -> dict[str, np.ndarray]:
    """Per target: the inputs, the lengths (primed = unprimed, sec. 3), and, measured on the
    forward kinematics of the shared solver's angles (theta1..theta4, also returned): the
    shoulder-wrist distance L4 (= L4'; eq. 2 is held against it in pal-eq2-holds), the
    included elbow angle beta1, the elevation of the shoulder-wrist line; alpha1 by the law
    of cosines from that L4 (not in dispute)."""
    arm = palletizer_arm()
    G = _targets()
    L1, L2, L3, h = chk.lengths(arm)
    q = arm.solve(G).branch("front-up")
    frames = arm.frames(q)
    shoulder, elbow, wrist = frames[:, 2], frames[:, 3], frames[:, 4]
    a, b = shoulder - elbow, wrist - elbow
    included = np.arccos(
        np.sum(a * b, -1) / np.linalg.norm(a, axis=-1) / np.linalg.norm(b, axis=-1)
    )
    sw = wrist - shoulder  # the shoulder-wrist line, measured on the arm
    radial = np.hypot(G[:, 0], G[:, 1])
    w_dir = (sw[:, 0] * G[:, 0] + sw[:, 1] * G[:, 1]) / radial
    L4 = np.linalg.norm(sw, axis=-1)
    a1 = np.arccos((L1**2 + L4**2 - L2**2) / (2 * L1 * L4))
    return {
        "X0": G[:, 0],
        "Y0": G[:, 1],
        "Z0": G[:, 2],
        "L1": L1,
        "L2": L2,
        "L3": L3,
        "h": h,
        "L1p": L1,
        "L2p": L2,
        "L3p": L3,
        "L4p": L4,
        "L4": L4,
        "alpha1": a1,
        "beta1": included,
        "elevation": np.arctan2(sw[:, 2], w_dir),
        **{f"theta{i + 1}": q[:, i] for i in range(4)},
    }


def evaluate(expr: sp.Expr, values: dict) -> np.ndarray | None:
    """Evaluate ``expr`` on the target values (None if a symbol has no value or the result
    is not finite everywhere: a formula undefined at a target is not right there)."""
    names = sorted(s.name for s in expr.free_symbols)
    if any(n not in values for n in names):
        return None
    f = sp.lambdify([S[n] for n in names], expr, "numpy")
    n_pts = len(values["X0"]) if "X0" in values else 1
    with np.errstate(all="ignore"):
        out = np.broadcast_to(np.asarray(f(*(values[n] for n in names)), dtype=float), (n_pts,))
    return out if np.isfinite(out).all() else None


def angles_close(a, b, tol: float = ATOL) -> bool:
    return bool(
        np.all(np.abs(np.mod(np.asarray(a) - np.asarray(b) + np.pi, 2 * np.pi) - np.pi) < tol)
    )


@cache
def findings_by_id() -> dict:
    return {f.id: f for f in chk.findings(palletizer_arm())}


def dims_text() -> str:
    return chk.assumed_lengths(palletizer_arm())

"""The symbols of the GR-1 thesis's chapters 3-5 and the parser of the transcribed SymPy
strings (the notation is described in :mod:`analysis.papers.gr1_thesis`)."""

from __future__ import annotations

import sympy as sp

_KIN_NAMES = (
    "theta1 theta2 theta3 theta4 theta5 theta234 px py pz "
    "n_x n_y n_z o_x o_y o_z a_x a_y a_z phi theta psi "
    "theta_i d_i a_i alpha_i theta1_alt theta5_alt theta234_alt"
)
SYMBOLS: dict[str, sp.Symbol] = {
    **{name: sp.Symbol(name, real=True) for name in _KIN_NAMES.split()},
    **{name: sp.Symbol(name, positive=True) for name in ("a2", "a3", "a4")},
}
"""Symbols of chapters 3-4 by name: joint angles, link lengths ``a2 a3 a4``, target, the
orientation columns ``n o a``, the RPY angles ``phi theta psi``, the generic D-H
parameters ``theta_i d_i a_i alpha_i`` of eq. 3.19 and ``theta1_alt theta5_alt
theta234_alt`` for the second solutions printed as θ1', θ5', θ234' (section 4.2)."""

CUBIC_SYMBOLS: dict[str, sp.Symbol] = {
    name: sp.Symbol(name, real=True)
    for name in ("t", "t_f", "theta_0", "theta_f", "a0", "a1", "a2", "a3")
}
"""Symbols of section 5.4.1 (eqs. 5.1-5.4): time, duration, end angles, coefficients."""

_FUNCTIONS = {
    "sin": sp.sin,
    "cos": sp.cos,
    "atan": sp.atan,
    "atan2": sp.atan2,
    "sqrt": sp.sqrt,
    "Function": sp.Function,
    "Derivative": sp.Derivative,
}


def parse(text: str, symbols: str = "kinematics") -> sp.Expr:
    """Parse one transcribed expression over :data:`SYMBOLS` (``symbols="kinematics"``) or
    :data:`CUBIC_SYMBOLS` (``symbols="cubic"``; ``theta(t)`` is a function there).

    Raises ``ValueError`` naming the text if it does not parse or uses an unknown name.
    """
    if symbols == "kinematics":
        local: dict = dict(SYMBOLS)
    elif symbols == "cubic":
        local = dict(CUBIC_SYMBOLS)
        local["theta"] = sp.Function("theta")
    else:
        raise ValueError(f"symbols must be 'kinematics' or 'cubic', not {symbols!r}")
    local.update(_FUNCTIONS)
    try:
        expr = sp.parse_expr(text, local_dict=local, evaluate=True)
    except Exception as exc:  # sympy raises many types for bad syntax
        raise ValueError(f"cannot parse transcribed expression {text!r}: {exc}") from None
    known = set(SYMBOLS) if symbols == "kinematics" else set(CUBIC_SYMBOLS)
    unknown = {s.name for s in expr.free_symbols} - known
    if unknown:
        raise ValueError(f"expression {text!r} uses unknown name(s) {sorted(unknown)}")
    return expr

"""The symbols of seed 001's transcription and the parser of its SymPy strings (the notation
is described in :mod:`analysis.papers.palletizer`)."""

from __future__ import annotations

import sympy as sp

# --- symbols ------------------------------------------------------------------------------
_NAMES_REAL = (
    "theta1 theta2 theta3 theta4 theta5 gamma gammap alpha beta theta alpha1 alpha2 beta1 "
    "X0 Y0 Z0 H theta_i alpha_im1"
)
_NAMES_POSITIVE = "L1 L2 L3 L4 h L1p L2p L3p L4p"
_NAMES_ANY = "a_im1 d_i"  # lengths of eq. 8 may be zero
SYMBOLS: dict[str, sp.Symbol] = {
    s.name: s
    for s in (
        *sp.symbols(_NAMES_REAL, real=True),
        *sp.symbols(_NAMES_POSITIVE, positive=True),
        *sp.symbols(_NAMES_ANY, real=True),
    )
}
"""Every symbol the transcription uses, by name."""

_FUNCTIONS = {
    "atan": sp.atan,
    "asin": sp.asin,
    "acos": sp.acos,
    "sqrt": sp.sqrt,
    "cos": sp.cos,
    "sin": sp.sin,
    "pi": sp.pi,
    "Piecewise": sp.Piecewise,
}


def parse(text: str) -> sp.Expr:
    """Parse one transcribed expression with :data:`SYMBOLS` (``atan``, ``asin``, ``acos``,
    ``sqrt``, ``Piecewise`` allowed).

    Raises ``ValueError`` naming the text if it does not parse or uses an unknown name.
    """
    local = {**SYMBOLS, **_FUNCTIONS}
    try:
        expr = sp.parse_expr(text, local_dict=local, evaluate=True)
    except Exception as exc:  # sympy raises many types for bad syntax
        raise ValueError(f"cannot parse transcribed expression {text!r}: {exc}") from None
    unknown = {s.name for s in expr.free_symbols} - set(SYMBOLS)
    if unknown:
        raise ValueError(f"expression {text!r} uses unknown name(s) {sorted(unknown)}")
    return expr

"""Seed 001 as printed (Li Zhaoxiang, Hu Jie 2021, the 4-axis palletizer): the module view of
``data/papers/palletizer.toml`` (:mod:`analysis.papers`): ``EQUATIONS``, ``MATRICES``,
``CLAIMS``, ``SECTIONS``, ``REFERENCES``, ``LOST``, ``UNCERTAIN``, ``SOURCE``; ``equation(key)``
gives a printed equation's parts as SymPy pairs."""

import sympy as sp

from analysis.papers import legacy, load


def equation(key: str) -> list[tuple[sp.Expr, sp.Expr]]:
    """The parts of a printed equation as ``(lhs, rhs)`` SymPy pairs (not for eqs. 8-10, which
    are matrix equations: use ``matrix()``); eq. 11's left-hand sides are the symbols t14 ..."""
    paper = load("palletizer")
    if key in ("eq8", "eq9", "eq10"):
        raise ValueError(f"{key} is a matrix equation; use matrix() and MATRICES")
    out = []
    for p in paper.record(key)["parts"]:
        lhs = sp.Symbol(p["lhs"], real=True) if key == "eq11" else paper.parse(p["lhs"])
        out.append((lhs, paper.parse(p["rhs"])))
    return out


__getattr__ = legacy("palletizer", equation=equation)

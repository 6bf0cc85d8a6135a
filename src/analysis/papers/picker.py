"""Seed 002 as printed (Yang, Li, Gao 2016, the 2P4R picker): the module view of
``data/papers/picker.toml`` (:mod:`analysis.papers`): ``TOPOLOGY``, ``CHAINS``, ``JOINTS``,
``EXPERIMENT``, ``EQUATION_NUMBERS``, ``CROSS_REFERENCES``, ``CLAIMS``, ``LOST``,
``UNCERTAIN``, ``EXTRACTED``, ``SOURCE``; ``joint_law(name)`` a law of section 4 in ``t``."""

import sympy as sp

from analysis.papers import legacy, load


def joint_law(name: str) -> sp.Expr:
    """A joint law of ``EXPERIMENT`` as a SymPy expression in ``t`` (printed form)."""
    laws = load("picker").group("EXPERIMENT")["laws"]
    if name not in laws:
        raise ValueError(f"unknown joint law {name!r}; expected one of {sorted(laws)}")
    return sp.parse_expr(laws[name]["expr"], local_dict={"t": sp.Symbol("t", nonnegative=True)})


__getattr__ = legacy("picker", joint_law=joint_law)

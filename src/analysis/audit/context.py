"""What a paper's checks compute against: its printed records, its arm and the few things a
paper defines for itself (:class:`Bespoke`: named domains, matrices, substitutions, values,
predicates and facts, in ``analysis.audit.papers.<paper>.checks``, at most 250 lines each).

:func:`context` builds one :class:`Context` per paper and caches what it computes (a domain is
sampled once per process). Valid configurations come from the arm hook
``Arm.sample_q(rng, n)`` (:func:`sample_q`: seeded, within the joint limits, solved back to
themselves by the arm's closed form on the named branch).
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cache, reduce

import numpy as np
import sympy as sp

from analysis import papers
from analysis.audit.bespoke import Bespoke

__all__ = ["Bespoke", "Context", "Product", "context", "sample_q"]


@dataclass
class Context:
    """A paper, its bespoke definitions and the caches of what they compute."""

    paper: papers.Paper
    bespoke: Bespoke
    _cache: dict = field(default_factory=dict, repr=False)

    def _cached(self, table: str, name: str, *args):
        key = (table, name, args)
        if key not in self._cache:
            fns = getattr(self.bespoke, table)
            if name not in fns:
                raise ValueError(f"{self.paper.id}: no {table[:-1]} {name!r}")
            self._cache[key] = fns[name](*args)
        return self._cache[key]

    def domain(self, name: str) -> Mapping[str, np.ndarray]:
        return self._cached("domains", name)

    def substitution(self, name: str) -> Mapping:
        return self._cached("substitutions", name)

    def value(self, name: str, *args) -> float:
        return self._cached("values", name, *args)

    def fact(self, name: str):
        return self._cached("facts", name)

    def predicate(self, name: str) -> Callable:
        if name not in self.bespoke.predicates:
            raise ValueError(f"{self.paper.id}: no predicate {name!r}")
        return self.bespoke.predicates[name]

    def matrix(self, name: str) -> sp.Matrix:
        if name.startswith("@"):
            return self.paper.matrix(name[1:])
        return self._cached("matrices", name)

    def product(self, names) -> Product:
        """The product of named matrices; each entry expanded (trigonometric functions of sums
        too) when it is first read, ``M[i, j]`` (``M.full()``: every entry)."""
        names = [names] if isinstance(names, str) else list(names)
        key = ("product", tuple(names))
        if key not in self._cache:
            self._cache[key] = Product(reduce(lambda a, b: a * b, (self.matrix(n) for n in names)))
        return self._cache[key]

    def facts(self) -> dict:
        return {k: self.fact(k) for k in self.bespoke.facts}


class Product:
    """A matrix product whose entries are expanded when first read (a check reads a few)."""

    def __init__(self, M: sp.Matrix) -> None:
        self._M, self._done = M, {}
        self.shape = M.shape

    def __getitem__(self, ij):
        if ij not in self._done:
            self._done[ij] = sp.expand(sp.expand_trig(self._M[ij]))
        return self._done[ij]

    def full(self) -> sp.Matrix:
        return sp.Matrix(self.shape[0], self.shape[1], lambda i, j: self[i, j])


@cache
def context(paper: str) -> Context:
    """The context of ``paper`` (cached for the process): its printed records and what its home
    ``analysis.audit.papers.<paper>.checks`` defines (``B``); a paper without a home is checked
    by the shared kinds alone."""
    return Context(papers.load(paper), bespoke(paper))


def bespoke(paper: str, printed: papers.Paper | None = None) -> Bespoke:
    """What ``analysis.audit.papers.<paper>.checks`` registers (``B``); for a paper without a
    home that prints its arm as a D-H table (``[paper.model]``), what that model defines
    (:mod:`analysis.audit.model`); else nothing."""
    home = f"analysis.audit.papers.{paper}"
    if importlib.util.find_spec(home) is not None:
        return importlib.import_module(f"{home}.checks").B
    printed = printed or papers.load(paper)
    if "model" in printed.meta:
        from analysis.audit.model import bespoke as model_bespoke

        return model_bespoke(printed)
    return Bespoke(paper)


def sample_q(arm, rng: np.random.Generator, n: int, branch: str | None = None) -> np.ndarray:
    """``n`` seeded configurations (n, n_joints) [rad] of ``arm`` that its closed form solves
    back to themselves on ``branch`` (default: the arm's first, the paper's): the arm hook
    :meth:`analysis.kinematics.arm.Arm.sample_q`."""
    return np.asarray(arm.sample_q(rng, n, branch=branch or arm.branches[0]), dtype=float)

"""What one paper defines for its checks (:class:`Bespoke`), by name: its home's
``analysis.audit.papers.<paper>.checks`` fills one, :mod:`analysis.audit.model` another from a
printed D-H table; :mod:`analysis.audit.context` reads them."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

__all__ = ["Bespoke"]


@dataclass
class Bespoke:
    """What one paper defines for its checks, each registered by name."""

    paper: str
    domains: dict[str, Callable] = field(default_factory=dict)
    matrices: dict[str, Callable] = field(default_factory=dict)
    substitutions: dict[str, Callable] = field(default_factory=dict)
    values: dict[str, Callable] = field(default_factory=dict)
    predicates: dict[str, Callable] = field(default_factory=dict)
    facts: dict[str, Callable] = field(default_factory=dict)

    def _add(self, table: str, name: str | None = None):
        def deco(fn):
            getattr(self, table)[name or fn.__name__] = fn
            return fn

        return deco

    def domain(self, name=None):
        """``fn() -> {symbol name: array}``: a named set of samples (sampled, claim, stl)."""
        return self._add("domains", name)

    def matrix(self, name=None):
        """``fn() -> sympy.Matrix``: a named matrix for products."""
        return self._add("matrices", name)

    def substitution(self, name=None):
        """``fn() -> {symbol: expression}``."""
        return self._add("substitutions", name)

    def value(self, name=None):
        """``fn(row, column) -> float``: a recomputed table cell."""
        return self._add("values", name)

    def predicate(self, name=None):
        """``fn(text, ctx) -> Result``: a check no kind expresses."""
        return self._add("predicates", name)

    def fact(self, name=None):
        """``fn() -> value``: a computed number an evidence template names."""
        return self._add("facts", name)

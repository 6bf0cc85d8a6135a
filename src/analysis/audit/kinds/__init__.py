"""The shared check kinds: each decides a text by an independent computation, written once.

A register row names its kind and parameters (``check = {kind = "sampled", domain = ...}`` in
``data/registers/<paper>.toml``); :func:`check` runs it on a text and returns a :class:`Result`
(the verdict and the values it computed, which fill the row's evidence template). A text the
kind cannot read (it does not parse, it names nothing the paper has) is not a right text: the
verdict is False, never an exception. No kind reads the register's own words: each decides from
the paper's printed data (``analysis.papers``) and a computation (the arm, SymPy, the S7-200
evaluator, the VB6 interpreter).

Kinds (one module each): ``identity``, ``matrix``, ``label`` (:mod:`.symbolic`); ``sampled``
(:mod:`.sampled`); ``table`` (:mod:`.table`); ``stl``, ``vb6`` (:mod:`.listing`); ``xref``,
``symbol`` (:mod:`.text`); ``claim`` (:mod:`.claim`); ``bespoke`` (a predicate a paper registers
by name, where no kind fits).
"""

from __future__ import annotations

from analysis.audit.kinds import claim, listing, sampled, symbolic, table, text  # noqa: F401
from analysis.audit.kinds.base import KINDS, Result, check, kind

__all__ = ["KINDS", "Result", "check", "kind"]

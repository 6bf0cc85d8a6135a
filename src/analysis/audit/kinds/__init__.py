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

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

__all__ = ["KINDS", "Result", "check", "kind"]

KINDS: dict[str, Callable] = {}
"""Kind name -> ``fn(text, spec, ctx) -> Result``."""


@dataclass(frozen=True)
class Result:
    """A verdict and the values the check computed (for evidence templates)."""

    ok: bool
    values: Mapping = field(default_factory=dict)

    def __bool__(self) -> bool:
        return self.ok

    def __getattr__(self, name: str):  # {printed.residual} in a template
        try:
            v = self.values[name]
        except KeyError:
            raise AttributeError(name) from None
        return v() if callable(v) else v  # a value costly to show is computed when asked


def kind(name: str):
    """Register a kind under ``name``."""

    def deco(fn):
        KINDS[name] = fn
        return fn

    return deco


def check(spec: Mapping, text: str, ctx) -> Result:
    """Run the kind ``spec["kind"]`` on ``text`` in a paper's context; a text it cannot read
    gives ``Result(False, {"why": ...})``."""
    fn = KINDS[spec["kind"]]
    if not isinstance(text, str) or not text.strip():
        return Result(False, {"why": "empty"})
    try:
        return fn(text, spec, ctx)
    except Exception as exc:  # a text the kind cannot read is not a right text
        return Result(False, {"why": f"{type(exc).__name__}: {exc}"[:300]})


def _load() -> None:
    from analysis.audit.kinds import claim, listing, sampled, symbolic, table, text  # noqa: F401


_load()

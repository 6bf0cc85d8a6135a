"""The registry of check kinds and their verdict (:class:`Result`); the kinds themselves are
the sibling modules (:mod:`analysis.audit.kinds`), each registering with :func:`kind`."""

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

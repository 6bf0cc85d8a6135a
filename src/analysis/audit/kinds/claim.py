"""``claim``: a claim as a quantified predicate over a named domain.

The text is ``<quantifier> <domain>: <body>``:

- ``forall D: P`` / ``exists D: P`` - the predicate P holds at every / some sample of D;
- ``count D: P = N`` - P holds at exactly N samples;
- ``max D: E = V`` / ``min D: E = V`` - the largest / smallest value of E over D is V: within
  the check's stated ``tol``, else within half a unit of V's last decimal but never more than
  5e-4 of |V| (1e-9 for V = 0), so that V must be the computed value, not a rounding of it:
  ``max workspace: joint_error_deg = 0.045`` holds for 0.04499, ``... = 0`` and ``... = 0.04``
  do not.

P and E are SymPy text over the domain's names (a domain is a named set of samples the paper
defines: :meth:`analysis.audit.context.Bespoke.domain`; its arrays may be measured values,
booleans the arm decides, counts): comparisons, ``&``, ``|``, ``~``, ``Eq(a, b)``, ``Abs`` and
the functions of :data:`analysis.papers.FUNCTIONS`. A domain the paper does not define, a name
the domain lacks, or a value undefined at a sample (NaN) makes the claim unreadable: False.

Example (seed 001): ``forall claim_grid: triangle_exists`` fails (some targets are out of
reach), ``forall claim_grid: Eq(triangle_exists, (Abs(L1 - L2) <= L4) & (L4 <= L1 + L2))``
holds on a grid over two arms (one with L1 != L2, so that L1 and L2 cannot be swapped).
"""

from __future__ import annotations

import re

import numpy as np
import sympy as sp

from analysis.audit.kinds.base import Result, kind
from analysis.audit.kinds.table import decimals
from analysis.papers import parse

__all__ = ["body_values", "evaluate_claim", "parse_claim"]

_CLAIM = re.compile(r"^(forall|exists|count|max|min) ([\w-]+): (.+)$", re.S)
_VALUE = re.compile(r"^(.+?) = (-?\d+(?:\.\d+)?)$", re.S)


def _values(expr: sp.Basic, domain) -> np.ndarray:
    names = sorted(s.name for s in expr.free_symbols)
    missing = [n for n in names if n not in domain]
    if missing:
        raise ValueError(f"the domain has no {missing}")
    n = len(next(iter(v for v in domain.values() if np.ndim(v))))
    f = sp.lambdify(names, expr, "numpy")
    with np.errstate(all="ignore"):
        out = np.asarray(f(*(domain[k] for k in names)))
    out = np.broadcast_to(out, (n,))
    if out.dtype != bool and not np.isfinite(out.astype(float)).all():
        raise ValueError("undefined at a sample")
    return out


def parse_claim(text: str) -> tuple[str, str, str, str | None]:
    """``(quantifier, domain, body, number)`` of a claim text (``number`` None for forall and
    exists); ValueError if the text is not a claim."""
    m = _CLAIM.match(text.strip())
    if not m:
        raise ValueError(f"{text!r} is not '<quantifier> <domain>: <body>'")
    quant, dname, body = m.groups()
    if quant in ("count", "max", "min"):
        v = _VALUE.match(body)
        if not v:
            raise ValueError(f"{quant} needs '<body> = <number>'")
        return quant, dname, v[1], v[2]
    return quant, dname, body, None


def body_values(body: str, domain) -> np.ndarray:
    """The claim's body at every sample of ``domain`` (a mapping name -> array)."""
    return _values(parse(body, {k: sp.Symbol(k) for k in domain}), domain)


def evaluate_claim(text: str, ctx, tol: float | None = None) -> Result:
    """The claim decided on its domain; a maximum or minimum within ``tol`` of the number
    stated (default: half a unit of its last decimal, at most 5e-4 of it, 1e-9 at 0)."""
    quant, dname, body, number = parse_claim(text)
    value = body_values(body, ctx.domain(dname))
    if quant in ("forall", "exists", "count"):
        if value.dtype != bool:
            raise ValueError("the predicate is not true or false at each sample")
        n_true = int(value.sum())
        if quant == "count":
            return Result(n_true == int(number) and "." not in number, {"count": n_true, "n": len(value)})  # noqa: E501
        ok = bool(value.all()) if quant == "forall" else bool(value.any())
        return Result(ok, {"count": n_true, "n": len(value)})
    x = float(np.max(value) if quant == "max" else np.min(value))
    if tol is None:
        v = abs(float(number))
        tol = min(0.5 * 10.0 ** -decimals(number), 5e-4 * v) + 1e-12 if v else 1e-9
    tol = float(tol)
    return Result(abs(x - float(number)) <= tol, {"value": x, "n": len(value), "tol": tol})


@kind("claim")
def claim(text: str, spec, ctx) -> Result:
    return evaluate_claim(text, ctx, spec.get("tol"))

"""Does a text say what a correction says? The equivalence every ``verify`` decides with.

A check kind (:mod:`analysis.audit.kinds`) decides whether a text is *true* of the paper's
model; :func:`same` decides whether it is *the same statement* as the correction, in the
notation of the kind, so that a tautology, an unrelated true statement, a comment appended or a
threshold moved is never taken for the correction:

- an equation ``lhs = rhs`` (``identity``, ``sampled``): the same equation, ``lhs - rhs`` equal
  to the correction's (or to its negative: the sides swapped), identically: exactly by
  :func:`~analysis.audit.kinds.symbolic.is_zero` or at 24 seeded points of the whole space of its
  symbols (not of the check's domain, where unrelated quantities coincide), modulo 2 pi for an
  angle;
- matrix cells (``matrix``): each cell the same expression, in the same order (a label such as
  ``t14 =`` the same label);
- a claim ``<quantifier> <domain>: <body>`` (``claim``): the same quantifier over the same domain,
  the same number (a count exactly; a maximum or minimum within the check's ``tol``) and the
  same body: a predicate the same truth function of its comparisons (proved by SymPy's
  ``simplify_logic``: a threshold moved, or '<' for '<=', is another predicate), a quantity the
  same value at every sample of the domain and at 64 seeded points where every name takes a
  value independently of the others (so ``x`` is not ``y`` where the domain has x = y);
- a table cell (``table``): the same number at the same decimals, or the same word;
- an STL fragment (``stl``): the same instructions with the same operands (numbers by value);
- VB6 statements (``vb6``): the same tokens (numbers by value; VB6's own ``'`` comments are
  blanks to VB6);
- anything else (a sentence, a list of headings, a predicate's text): the same text, blanks
  aside.

A text that cannot be read in the notation is not the same statement. The numeric test is
Schwartz-Zippel's: two different analytic functions agree at a handful of random points with
probability zero; where one side is defined and the other is not, they differ.
"""

from __future__ import annotations

import math
import random
from collections.abc import Mapping
from decimal import Decimal, InvalidOperation
from functools import lru_cache

import numpy as np
import sympy as sp

from analysis.papers import parse

__all__ = ["expressions_agree", "normalized", "same"]

_POINTS = 24


def normalized(text: str) -> str:
    """The text with its blanks collapsed (the notation of sentences and lists)."""
    return " ".join(str(text).split())


def _values(sym: sp.Symbol, rng: random.Random) -> float:
    return rng.uniform(0.3, 3.0) if sym.is_positive else rng.uniform(-3.0, 3.0)


@lru_cache(maxsize=4096)
def _evaluator(names: tuple, expr):
    """``expr`` as a function of ``names`` on Python floats: its real value, or None where it
    is undefined (a domain error, a division by zero, a complex value)."""
    fn = sp.lambdify(names, expr, "math")

    def at(args):
        try:
            v = complex(fn(*args))
        except (ValueError, ZeroDivisionError, OverflowError, TypeError):
            return None
        if not (math.isfinite(v.real) and math.isfinite(v.imag)) or abs(v.imag) > 1e-12:
            return None
        return v.real

    return at


@lru_cache(maxsize=256)
def _points(names: tuple) -> tuple:
    rng = random.Random(20160301)
    return tuple(tuple(_values(s, rng) for s in names) for _ in range(_POINTS))


def expressions_agree(a, b, *, angle: bool = False) -> bool:
    """Are SymPy expressions ``a`` and ``b`` the same function (modulo 2 pi when ``angle``)?
    Agreement at :data:`_POINTS` seeded points of the space of their symbols (each drawn
    apart: a positive symbol in [0.3, 3], any other in [-3, 3]; where one is defined and the
    other not, they differ), or, where too few points are defined or a function cannot be
    evaluated, an exactly zero difference (:func:`~analysis.audit.kinds.symbolic.is_zero`)."""
    from analysis.audit.kinds.symbolic import is_zero

    a, b = sp.sympify(a), sp.sympify(b)
    if a == b:
        return True
    names = tuple(sorted(a.free_symbols | b.free_symbols, key=str))
    try:
        fa, fb = _evaluator(names, a), _evaluator(names, b)
    except (TypeError, NameError, SyntaxError, KeyError):  # an undefined function
        return not angle and is_zero(a - b)
    compared = 0
    for args in _points(names):
        va, vb = fa(args), fb(args)
        if (va is None) != (vb is None):
            return False
        if va is None:
            continue
        diff = math.remainder(va - vb, 2 * math.pi) if angle else va - vb
        if abs(diff) > 1e-9 * (1.0 + abs(va)):
            return False
        compared += 1
    return compared >= 6 or (not angle and is_zero(a - b))


def _equation(text: str, ctx, ns: str):
    from analysis.audit.kinds.symbolic import equation

    lhs, rhs = equation(text, ctx, ns)
    return lhs - rhs


def _same_equation(text: str, ref: str, spec, ctx) -> bool:
    ns = spec.get("namespace", "main")
    if "defines" in spec:  # expressions of one named quantity
        return expressions_agree(ctx.paper.parse(text, ns), ctx.paper.parse(ref, ns))
    angle = spec["kind"] == "sampled" and spec.get("angle", True)
    d_t, d_r = _equation(text, ctx, ns), _equation(ref, ctx, ns)
    return expressions_agree(d_t, d_r, angle=angle) or expressions_agree(d_t, -d_r, angle=angle)


def _same_cells(text: str, ref: str, spec, ctx) -> bool:
    from analysis.audit.kinds.symbolic import cells

    if "of_column" in spec:
        return expressions_agree(ctx.paper.parse(text), ctx.paper.parse(ref))
    if "label" in spec:
        (lt, _, text), (lr, _, ref) = text.partition("="), ref.partition("=")
        if normalized(lt) != normalized(lr):
            return False
    n = len(spec["cells"])
    return all(
        expressions_agree(ctx.paper.parse(a), ctx.paper.parse(b))
        for a, b in zip(cells(text, n), cells(ref, n), strict=True)
    )


def _body_values(body: str, domain, points) -> np.ndarray:
    from analysis.audit.kinds.claim import body_values

    return np.concatenate([body_values(body, domain), body_values(body, points)])


def _independent_points(domain, n: int = 64) -> dict:
    """``n`` seeded points where every name of ``domain`` takes a value drawn apart from the
    others: a boolean at random, a number from the values the domain gives that name, or
    uniformly over their span."""
    rng = np.random.default_rng(20160301)
    out = {}
    for k, v in domain.items():
        v = np.asarray(v)
        if v.dtype == bool:
            out[k] = rng.random(n) < 0.5
            continue
        flat = v.astype(float).ravel()
        flat = flat[np.isfinite(flat)]
        if not len(flat):
            out[k] = np.full(n, np.nan)
            continue
        lo, hi = float(flat.min()), float(flat.max())
        picks = rng.choice(flat, n)
        spread = rng.uniform(lo - 1.0, hi + 1.0, n)
        out[k] = np.where(rng.random(n) < 0.5, picks, spread)
    return out


def _same_claim(text: str, ref: str, spec, ctx) -> bool:
    from analysis.audit.kinds.claim import parse_claim

    qt, dt, bt, nt = parse_claim(text)
    qr, dr, br, nr = parse_claim(ref)
    if (qt, dt) != (qr, dr) or (nt is None) != (nr is None):
        return False
    if nt is not None:
        if qt == "count" and ("." in nt or int(nt) != int(nr)):
            return False
        if qt != "count" and abs(float(nt) - float(nr)) > float(spec.get("tol", 0.0)):
            return False
    domain = ctx.domain(dt)
    names = {k: sp.Symbol(k) for k in domain}
    et, er = parse(bt, names), parse(br, names)
    if isinstance(et, sp.logic.boolalg.Boolean) or isinstance(er, sp.logic.boolalg.Boolean):
        # a predicate: the same truth function of its atoms (comparisons are atoms, so a
        # threshold moved or a '<' made '<=' is another predicate), proved
        from sympy.logic.inference import satisfiable

        return not satisfiable(sp.Xor(et, er))
    points = _independent_points(domain)
    a, b = _body_values(bt, domain, points), _body_values(br, domain, points)
    if a.dtype == bool or b.dtype == bool:
        return False
    return bool(np.allclose(a, b, rtol=1e-9, atol=1e-12, equal_nan=True))


def _number(text: str) -> tuple[Decimal, int]:
    d = Decimal(text.strip())
    if not d.is_finite():
        raise InvalidOperation(text)
    return d, d.as_tuple().exponent


def _same_cell(text: str, ref: str, spec, ctx) -> bool:
    none = spec.get("none")
    if none is not None and (text.strip() == none or ref.strip() == none):
        return text.strip() == ref.strip()
    return _number(text) == _number(ref)


def _operand(arg: str):
    try:
        return float(arg)
    except ValueError:
        return arg.upper()


def _same_stl(text: str, ref: str, spec, ctx) -> bool:
    from analysis.audit.kinds.listing import instructions

    if spec.get("mode") == "order":
        return normalized(text) == normalized(ref)

    def ops(t):
        return [(i.op, tuple(_operand(a) for a in i.args)) for i in instructions(t)]

    return ops(text) == ops(ref)


def _same_vb6(text: str, ref: str, spec, ctx) -> bool:
    from analysis.audit.vb6 import tokenize

    def toks(t):
        out = [(k.kind, float(k.text.rstrip("!#&%")) if k.kind == "num" else k.text.casefold())
               for k in tokenize(t)]  # fmt: skip
        while out and out[0][0] == "nl":  # leading and trailing blank lines are blanks
            out.pop(0)
        return [x for i, x in enumerate(out) if not (x[0] == "nl" and i and out[i - 1][0] == "nl")]

    return toks(text) == toks(ref)


_BY_KIND = {
    "identity": _same_equation, "sampled": _same_equation, "matrix": _same_cells,
    "claim": _same_claim, "table": _same_cell, "stl": _same_stl, "vb6": _same_vb6,
}  # fmt: skip


def same(text: str, reference: str, spec: Mapping, ctx) -> bool:
    """Does ``text`` say what ``reference`` says, in the notation of ``spec["kind"]``? (Never
    raises: a text that cannot be read is not the same statement.)"""
    if not isinstance(text, str) or not isinstance(reference, str) or not text.strip():
        return False
    if normalized(text) == normalized(reference):
        return True
    fn = _BY_KIND.get(spec.get("kind"))
    if fn is None:
        return False
    try:
        return bool(fn(text, reference, spec, ctx))
    except Exception:
        return False


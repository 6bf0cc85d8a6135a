"""Symbolic kinds: an identity (``identity``), a matrix cell against a chain product
(``matrix``), a label naming the factors of a printed product (``label``); and the one exact
zero test of the audit (:func:`is_zero`).

:func:`is_zero` decides whether an expression vanishes identically. A numeric probe at two
rational points (30 digits) rejects most non-zeros at once; a trigonometric polynomial is then
reduced to a normal form (:func:`normal_form`: every sin/cos of a symbol replaced by s, c and the
numerator reduced modulo s^2 + c^2 - 1, a Groebner basis since the leading terms s^2 are pairwise
coprime), which is 0 exactly when the expression is; anything else falls back to
``sympy.simplify``. Example: ``is_zero(sin(x)**2 + cos(x)**2 - 1)`` is True,
``is_zero(sin(x) - cos(x))`` False.
"""

from __future__ import annotations

import re

import sympy as sp

from analysis.audit.kinds.base import Result, kind

__all__ = ["cells", "equation", "is_zero", "normal_form"]


def _trig_symbols(expr: sp.Expr) -> list[sp.Symbol]:
    return sorted(
        {a for f in expr.atoms(sp.sin, sp.cos) for a in f.args if isinstance(a, sp.Symbol)},
        key=str,
    )


def normal_form(expr) -> sp.Expr | None:
    """The canonical form of a rational trigonometric polynomial (None: other functions)."""
    num, den = sp.fraction(sp.together(sp.sympify(expr)))
    num = sp.expand(sp.expand_trig(num))
    if num == 0:
        return sp.Integer(0)
    angles = _trig_symbols(num)
    s = sp.symbols(f"_s0:{len(angles)}", real=True)
    c = sp.symbols(f"_c0:{len(angles)}", real=True)
    subs = {**{sp.sin(a): s[i] for i, a in enumerate(angles)}}
    subs.update({sp.cos(a): c[i] for i, a in enumerate(angles)})
    num = num.subs(subs)
    if num.atoms(sp.Function):
        return None
    gens = [*s, *c, *sorted(num.free_symbols - set(s) - set(c), key=str)]
    try:  # the remainder modulo {s^2 + c^2 - 1}, by polynomial division (lex order)
        if not s:
            raise sp.PolynomialError("no sin/cos: nothing to reduce")
        basis = [sp.Poly(si**2 + ci**2 - 1, *gens) for si, ci in zip(s, c, strict=True)]
        num = sp.reduced(sp.Poly(num, *gens), basis, *gens, order="lex")[1].as_expr()
    except sp.PolynomialError:  # not a polynomial in the other symbols (a root): term by term
        for si, ci in zip(s, c, strict=True):  # s^2 -> 1 - c^2
            p = sp.Poly(num, si)
            num = sp.expand(sum(
                coeff * si ** (k % 2) * (1 - ci**2) ** (k // 2) for (k,), coeff in p.terms()
            ))  # fmt: skip
    back = {v: k for k, v in subs.items()}
    return sp.factor(num.subs(back)) / den if num != 0 else sp.Integer(0)


def _probe(expr: sp.Expr, seed: int) -> float | None:
    """|expr| at a random point (float; lengths and angles O(1)); None if undefined there."""
    import math
    import random

    names = sorted(expr.free_symbols, key=str)
    rng = random.Random(seed)
    try:
        f = sp.lambdify(names, expr, "math")
        return abs(complex(f(*(0.3 + rng.random() for _ in names))))
    except (TypeError, ValueError, ZeroDivisionError, OverflowError, NameError):
        return None
    except Exception:
        return None
    finally:
        math.isfinite(0.0)


def is_zero(expr) -> bool:
    """Does ``expr`` vanish identically? (exact; see the module docstring)"""
    expr = sp.sympify(expr)
    if expr == 0:
        return True
    for seed in (0, 5):  # a clear non-zero at a random point decides at once
        v = _probe(expr, seed)
        if v is not None and v > 1e-6:
            return False
    nf = normal_form(expr)
    if nf is not None:
        return nf == 0
    return sp.simplify(expr) == 0


def _numeric_residual(residual: sp.Expr, subs) -> float:
    """|residual| at two random points, the substituted symbols computed from theirs."""
    import math
    import random

    rng = random.Random(3)
    worst = 0.0
    names = sorted(residual.free_symbols | {x for e in subs.values() for x in e.free_symbols}, key=str)  # noqa: E501
    f = sp.lambdify(names, residual, "math")
    g = {k: (sorted(e.free_symbols, key=str), sp.lambdify(sorted(e.free_symbols, key=str), e, "math"))  # noqa: E501
         for k, e in subs.items()}  # fmt: skip
    for _ in range(2):
        vals = {x: 0.3 + rng.random() for x in names}
        for k, (args, fn) in g.items():
            vals[k] = fn(*(vals[a] for a in args))
        try:
            worst = max(worst, abs(complex(f(*(vals[x] for x in names)))))
        except (ValueError, ZeroDivisionError, OverflowError):
            return 0.0  # undefined at the point: decide exactly
        if not math.isfinite(worst):
            return 0.0
    return worst


def equation(text: str, ctx, namespace: str = "main") -> tuple[sp.Expr, sp.Expr]:
    """``lhs = rhs`` parsed with the paper's parser (ValueError if it is not one)."""
    eqs = [m.start() for m in re.finditer(r"(?<![<>!=])=(?!=)", text)]
    if len(eqs) != 1:
        raise ValueError(f"{text!r} is not one equation 'lhs = rhs'")
    lhs, rhs = text[: eqs[0]], text[eqs[0] + 1 :]
    return ctx.paper.parse(lhs, namespace), ctx.paper.parse(rhs, namespace)


@kind("identity")
def identity(text: str, spec, ctx) -> Result:
    """``lhs = rhs`` holds identically, after the substitution ``spec["substitute"]`` (a name
    the paper's context defines, e.g. ``fk``: the target by the arm's forward kinematics)."""
    lhs, rhs = equation(text, ctx, spec.get("namespace", "main"))
    residual = lhs - rhs
    if spec.get("substitute") and is_zero(residual):  # true before the substitution: says nothing
        return Result(False, {"residual": "0", "why": "holds whatever the substitution"})
    if spec.get("substitute"):
        subs = ctx.substitution(spec["substitute"])
        if any(isinstance(k, sp.FunctionClass) for k in subs):  # theta(t) -> a Lambda: applied
            fns = {k: v for k, v in subs.items() if isinstance(k, sp.FunctionClass)}
            rest = {k: v for k, v in subs.items() if k not in fns}
            residual = residual.subs(fns).doit().subs(rest)
            ok = is_zero(residual)
            return Result(ok, {"residual": "0" if ok else sp.sstr(sp.simplify(residual))})
        if _numeric_residual(residual, subs) > 1e-6:  # a clear non-zero, without expanding
            return Result(False, {"residual": lambda: sp.sstr(sp.factor(sp.expand(
                sp.expand_trig(residual.subs(subs)))))})  # fmt: skip
        residual = residual.subs(subs)
    ok = is_zero(residual)
    return Result(ok, {"residual": "0" if ok else sp.sstr(sp.factor(sp.expand(residual)))})


def cells(text: str, n: int) -> list[str]:
    """The ``n`` cells of a text (';'-, comma- or line-separated; ValueError if not n)."""
    parts = [p.strip() for p in re.split(r"[;\n]|,(?![^()]*\))", text)] if n > 1 else [text.strip()]
    if len(parts) != n or not all(parts):
        raise ValueError(f"{text!r}: {n} cell(s) expected")
    return parts


@kind("matrix")
def matrix(text: str, spec, ctx) -> Result:
    """Cells of a printed matrix against the product ``spec["product"]`` (names of the
    context's matrices: the arm's link transforms, their inverses, printed matrices ``@id``),
    cell by cell (``cells``: 1-based [row, column]; several cells are ';'-separated in the
    text). With ``of_column`` the text is one function of a column vector (ix, iy, iz), checked
    at each listed column of the product's right factor."""
    M = ctx.product(spec["product"])
    if "of_column" in spec:
        i = spec["row"] - 1
        ix = [ctx.paper.symbols()[k] for k in ("ix", "iy", "iz")]
        f = ctx.paper.parse(text)
        T = ctx.product([spec["product"][-1]])
        entries = set().union(*(T[r, c].free_symbols for r in range(3) for c in range(T.shape[1])))
        if f.free_symbols & entries:  # a function of the column (ix, iy, iz), not of one column
            return Result(False, {"why": f"names {sorted(map(str, f.free_symbols & entries))}"})
        bad = []
        for j in spec["of_column"]:
            col = dict(zip(ix, (T[0, j - 1], T[1, j - 1], T[2, j - 1]), strict=True))
            if not is_zero(f.subs(col) - M[i, j - 1]):
                bad.append(j)
        return Result(not bad, {"columns_wrong": bad})
    spec_cells = spec["cells"]
    if "label" in spec:  # "t14 = ...": the label must name the cell
        label, _, text = text.partition("=")
        if label.strip() != "".join([spec["label"], *map(str, spec_cells[0])]):
            return Result(False, {"why": f"the label {label.strip()!r} names another cell"})
    texts = cells(text, len(spec_cells))
    wrong = []
    for (i, j), t in zip(spec_cells, texts, strict=True):
        d = ctx.paper.parse(t) - M[i - 1, j - 1]
        if not is_zero(d):
            wrong.append((i, j, d))

    def shown(e) -> str:  # for evidence only, when a template asks: the normal form's
        nf = normal_form(e)  # factors, each small one trigonometrically simplified
        nf = e if nf is None else nf
        parts = sp.Mul.make_args(nf)
        return sp.sstr(sp.Mul(*(sp.trigsimp(f) if sp.count_ops(f) < 40 else f for f in parts)))

    return Result(not wrong, {
        "derived": lambda: "; ".join(shown(M[i - 1, j - 1]) for i, j in spec_cells),
        "difference": lambda: "; ".join(f"[{i},{j}]: {shown(d)}" for i, j, d in wrong),
    })  # fmt: skip


@kind("label")
def label(text: str, spec, ctx) -> Result:
    """A label naming a product of the context's matrices (``A_2 A_3``) for the printed matrix
    ``spec["of"]``: the named product must equal it entry by entry."""
    m = re.fullmatch(r"\s*((?:[A-Z]_?\d\s+)*[A-Z]_?\d)\s*=\s*", text)
    names = re.findall(r"([A-Z])_?(\d)", m[1]) if m else []
    if len(names) != spec.get("factors", 2):
        return Result(False, {"why": "not 'A_i A_j =': a product of named matrices"})
    M = ctx.product([f"{a}{n}" for a, n in names]).full()
    printed = ctx.paper.matrix(spec["of"])
    ok = all(is_zero(e) for e in (M - printed))
    return Result(ok, {})

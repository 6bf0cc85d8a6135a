"""Printed against derived, typeset: both as LaTeX, with the sub-expressions that differ marked.

The registers hold each checked item's printed and derived (corrected) form as SymPy text
(``analysis.audit.register.compare``). For a reader, the two are typeset (MathJax on the site
and in JupyterLab) and the parts that differ are boxed with ``\\colorbox``, so that eq. 2's
a_x reads ``0`` against ``sin(theta1)`` with both boxed, and a term with the wrong sign is
boxed on both sides while the terms that agree are not.

Which parts differ (:func:`differing_parts`) is decided structurally, with the audit's own
test of equality (:func:`analysis.audit.kinds.symbolic.is_zero`): two sums are compared term
by term (terms equal on both sides are matched and left unmarked), two products factor by
factor, two applications of the same function argument by argument; where exactly one
term, factor or argument is left on each side, the comparison goes on inside it, otherwise
what is left is marked whole.
"""

from __future__ import annotations

import re

import pandas as pd
import sympy as sp
from sympy.printing.latex import LatexPrinter

__all__ = ["MARK", "TypesetTable", "differing_parts", "marked_latex", "typeset_comparison"]

MARK = r"\colorbox{#ffd6d6}{$\displaystyle %s$}"
"""How a differing sub-expression is typeset: a light red box (MathJax's color extension,
autoloaded; standard LaTeX with the xcolor package)."""


def _same(a: sp.Expr, b: sp.Expr) -> bool:
    from analysis.audit.kinds.symbolic import is_zero

    return bool(is_zero(sp.sympify(a) - sp.sympify(b)))


def _unmatched(a: list, b: list) -> tuple[list, list]:
    """The items of ``a`` and of ``b`` left once every item equal on both sides is paired."""
    rest = list(b)
    only_a = []
    for t in a:
        k = next((i for i, u in enumerate(rest) if _same(t, u)), None)
        if k is None:
            only_a.append(t)
        else:
            rest.pop(k)
    return only_a, rest


def differing_parts(printed: sp.Expr, derived: sp.Expr) -> tuple[list[sp.Expr], list[sp.Expr]]:
    """The sub-expressions of ``printed`` and of ``derived`` that differ (empty if equal).

    >>> x, y = sp.symbols("P_x P_y")
    >>> th = sp.Symbol("theta1")
    >>> differing_parts(x * sp.sin(th) + y * sp.cos(th), x * sp.sin(th) - y * sp.cos(th))
    ([P_y*cos(theta1)], [-P_y*cos(theta1)])
    >>> differing_parts(sp.sqrt(x + 1), sp.sqrt(x - 1))  # inside a power: the term
    ([1], [-1])
    >>> differing_parts(sp.Integer(0), sp.sin(th))  # eq. 2, a_x
    ([0], [sin(theta1)])
    """
    printed, derived = sp.sympify(printed), sp.sympify(derived)
    if _same(printed, derived):
        return [], []
    if printed.func is derived.func and printed.func in (sp.Add, sp.Mul):
        only_p, only_d = _unmatched(list(printed.args), list(derived.args))
        numbers = any(t.is_Number for t in only_p + only_d)
        if printed.func is sp.Mul and numbers:  # a sign or a factor of 2: the whole product
            return [printed], [derived]
        if printed.func is sp.Add:  # the terms that differ, whole (a term is what one reads)
            return only_p, only_d
        if len(only_p) == len(only_d) == 1:
            return differing_parts(only_p[0], only_d[0])
        if only_p and only_d:
            return only_p, only_d
    elif (
        printed.func is derived.func
        and printed.args
        and len(printed.args) == len(derived.args)
        and not printed.is_Atom
    ):
        pairs = [(a, b) for a, b in zip(printed.args, derived.args, strict=True) if not _same(a, b)]
        if len(pairs) == 1:
            return differing_parts(*pairs[0])
    return [printed], [derived]


class _MarkingPrinter(LatexPrinter):
    """SymPy's LaTeX printer, boxing (:data:`MARK`) every sub-expression in ``marked``."""

    def __init__(self, marked: list[sp.Expr], mark: str = MARK) -> None:
        super().__init__({})
        self._marked = marked
        self._mark = mark
        self._inside: list = []  # marked expressions being printed (boxed once, not again)

    def _is_marked(self, expr) -> bool:
        return any(expr == m for m in self._marked) and not any(expr == e for e in self._inside)

    def _print(self, expr, **kwargs) -> str:
        if not self._is_marked(expr):
            return super()._print(expr, **kwargs)
        self._inside.append(expr)
        try:
            return self._mark % super()._print(expr, **kwargs)
        finally:
            self._inside.pop()

    def _print_Symbol(self, expr, style="plain") -> str:
        # the registers' Px, Py, Pz: P_x, as the papers print them
        if re.fullmatch(r"[A-Z][a-z]", expr.name):
            return f"{expr.name[0]}_{{{expr.name[1]}}}"
        return super()._print_Symbol(expr, style=style)

    def _print_Add(self, expr, order=None) -> str:  # sympy's, boxing a marked negative term
        tex = ""
        for i, term in enumerate(self._as_ordered_terms(expr, order=order)):
            boxed = False
            if i and term.could_extract_minus_sign():
                tex += " - "
                boxed, term = self._is_marked(term), -term
            elif i:
                tex += " + "
            term_tex = self._print(term)
            if self._needs_add_brackets(term):
                term_tex = rf"\left({term_tex}\right)"
            tex += self._mark % term_tex if boxed else term_tex
        return tex


def marked_latex(printed, derived, *, mark: str = MARK) -> tuple[str, str]:
    """LaTeX of ``printed`` and of ``derived`` (SymPy expressions or their text), each with
    its parts that differ from the other boxed (``mark % tex``).

    >>> p, d = marked_latex("Px + Py = 0", "Px - Py = 0")  # eq. 5's sign, shortened
    >>> print(p)
    P_{x} + \\colorbox{#ffd6d6}{$\\displaystyle P_{y}$} = 0
    >>> print(d)
    P_{x} - \\colorbox{#ffd6d6}{$\\displaystyle P_{y}$} = 0
    """
    sides_p, sides_d = _sides(printed), _sides(derived)
    if len(sides_p) != len(sides_d):
        raise ValueError(f"{printed!r} and {derived!r}: not the same number of '=' sides")
    tex_p, tex_d = [], []
    for p, d in zip(sides_p, sides_d, strict=True):
        only_p, only_d = differing_parts(p, d)
        tex_p.append(_MarkingPrinter(only_p, mark).doprint(p))
        tex_d.append(_MarkingPrinter(only_d, mark).doprint(d))
    return " = ".join(tex_p), " = ".join(tex_d)


def _sides(text) -> list[sp.Expr]:
    """``"lhs = rhs"`` (the registers' text of a printed equation) as [lhs, rhs]; an expression
    as [it]. Raises ``ValueError`` for what is not one SymPy expression per side."""
    parts = [text] if isinstance(text, sp.Basic) else str(text).split(" = ")
    out = []
    for part in parts:
        e = part if isinstance(part, sp.Basic) else sp.sympify(part)
        if not isinstance(e, sp.Expr):
            raise ValueError(f"{part!r} is not a SymPy expression")
        out.append(e)
    return out


def typeset_comparison(table, columns: tuple[str, str] = ("printed", "derived")):
    """``table`` (a DataFrame with the SymPy text of the printed and the derived form, as
    :func:`analysis.audit.register.compare` gives) with both columns as inline maths
    ``\\(...\\)``, the differing parts boxed; a row whose text is not one SymPy expression (a
    matrix, a word) keeps its text. Its HTML (:class:`TypesetTable`) asks MathJax to typeset
    it: the report site's notebook pages otherwise leave outputs alone."""
    out = TypesetTable(table.copy())
    a, b = columns
    for idx, row in table.iterrows():
        try:
            p, d = marked_latex(row[a], row[b])
        except (sp.SympifyError, SyntaxError, TypeError, ValueError, AttributeError):
            continue
        out.at[idx, a], out.at[idx, b] = rf"\({p}\)", rf"\({d}\)"
    return out


class TypesetTable(pd.DataFrame):
    """A DataFrame whose HTML is marked for MathJax (``class="mathjax_process"``): MyST-NB marks
    a notebook's page ``mathjax_ignore`` and MathJax then typesets only what is so marked.
    JupyterLab typesets HTML outputs anyway. Its plain-text form is the DataFrame's."""

    @property
    def _constructor(self):
        return TypesetTable

    def _repr_html_(self) -> str | None:
        with pd.option_context("display.max_colwidth", None):  # LaTeX cut short breaks
            html = super()._repr_html_()
        return None if html is None else f'<div class="mathjax_process">{html}</div>'

"""Tables with the paper's wrong cells marked, for the notebooks and the report site; and the
one rule for a table cell of one word on the site (:func:`keep_words_whole`).

:func:`marked` wraps a DataFrame and a boolean mask of the same shape (True: the cell is wrong,
as the audit decided it, e.g. Table 4's printed angles against the corrected closed form). It
shows as HTML with those cells highlighted (JupyterLab and the site: pandas' Styler, with a
fixed table id so that the stored output is the same in every run, which nbval compares), and
as text with each wrong cell followed by `` ✗`` (the PDF, a terminal, nbval's text/plain).
pandas' own Styler is used rather than hand-written HTML; its repr is an address, which would
differ in every run, so the text form is written here.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass

import numpy as np
import pandas as pd

WRONG_CSS = "background-color: #fde2e1; color: #8a0010; font-weight: 600"
"""The highlight of a wrong cell, inline (JupyterLab has no site style sheet): the colours of
the front page's ``td.wrong-cell`` (docs/site/_static/report.css)."""

MARK = " ✗"
"""What follows a wrong cell in the text form."""


@dataclass(frozen=True)
class MarkedTable:
    """A DataFrame with its wrong cells marked (:func:`marked`)."""

    frame: pd.DataFrame
    wrong: pd.DataFrame
    name: str
    precision: int | None = None

    @property
    def n_wrong(self) -> int:
        """How many cells are marked."""
        return int(self.wrong.to_numpy().sum())

    def _format(self, v) -> str:
        if self.precision is not None and isinstance(v, float | np.floating):
            return f"{v:.{self.precision}f}"
        return str(v)

    def _text_frame(self) -> pd.DataFrame:
        shown = self.frame.map(self._format)
        return shown.where(~self.wrong, shown + MARK)

    def __repr__(self) -> str:
        return self._text_frame().to_string()

    def _repr_html_(self) -> str:
        styler = self.frame.style.set_uuid(self.name)
        styler = styler.apply(lambda _: np.where(self.wrong.to_numpy(), WRONG_CSS, ""), axis=None)
        styler = styler.set_td_classes(self.wrong.replace({True: "wrong-cell", False: ""}))
        styler = styler.format(self._format)  # the values as the text form shows them
        caption = f"{self.n_wrong} wrong cell{'s' if self.n_wrong != 1 else ''} highlighted"
        return styler.set_caption(caption).to_html()


def marked(frame: pd.DataFrame, wrong, *, name: str, precision: int | None = None) -> MarkedTable:
    """``frame`` with the cells where ``wrong`` is True highlighted.

    ``wrong``: a boolean DataFrame (or array) of ``frame``'s shape, or a dict of column ->
    boolean Series/array for the columns that can be wrong (the others are never marked).
    ``name``: the table's id in the HTML (letters, digits, ``-`` and ``_``), unique in its
    notebook. ``precision``: decimals shown for floats.

    >>> t = marked(pd.DataFrame({"printed": [1.0, 2.0], "derived": [1.0, 2.5]}),
    ...            {"printed": [False, True]}, name="demo", precision=1)
    >>> print(t)
      printed derived
    0     1.0     1.0
    1   2.0 ✗     2.5
    >>> t.n_wrong, 'class="data row1 col0 wrong-cell"' in t._repr_html_()
    (1, True)
    """
    if not name or not all(c.isalnum() or c in "-_" for c in name):
        raise ValueError(f"table name {name!r}: letters, digits, '-' and '_' only")
    if isinstance(wrong, dict):
        unknown = set(wrong) - set(frame.columns)
        if unknown:
            raise ValueError(f"marked: no column {sorted(unknown)} in the table")
        mask = pd.DataFrame(False, index=frame.index, columns=frame.columns)
        for col, w in wrong.items():
            if isinstance(w, pd.Series):  # by index label, not by position
                w = w.reindex(frame.index).eq(True)
            mask[col] = np.asarray(w, dtype=bool)
    else:
        arr = np.asarray(wrong, dtype=bool)
        if arr.shape != frame.shape:
            raise ValueError(f"marked: mask shape {arr.shape} is not the table's {frame.shape}")
        mask = pd.DataFrame(arr, index=frame.index, columns=frame.columns)
    return MarkedTable(frame, mask.astype(bool), name, precision)


NOWRAP = "nowrap"
"""The class of a cell that holds one word (``docs/site/_static/report.css``: on one line)."""
_CELL = re.compile(r"<(td|th)(\s[^<>]*)?>(.*?)</\1\s*>", re.S | re.I)
_CLASS = re.compile(r"""(\sclass\s*=\s*)(["'])(.*?)\2""", re.S | re.I)
_TAG = re.compile(r"<[^<>]*>")


def keep_words_whole(page: str) -> str:
    """``page`` (HTML) with every table cell that holds one word (text without white space: an
    id such as ``grabber-stl-degrees``, a severity, a count, a header like ``severity``) given
    the class :data:`NOWRAP`, so that it is never broken across lines, not even at a hyphen.
    Cells with a nested table, MathJax or no text are left as they are.

    Applied to every page of the report site and of its printed form (``docs/site/conf.py``):
    the notebooks' pandas tables, the generated pages' tables, the register.

    >>> keep_words_whole('<tr><th>severity</th><td class="x">wrong-result</td><td>a b</td></tr>')
    '<tr><th class="nowrap">severity</th><td class="x nowrap">wrong-result</td><td>a b</td></tr>'
    """

    def mark(m: re.Match) -> str:
        tag, attrs, inner = m[1], m[2] or "", m[3]
        if "<table" in inner.lower() or "\\(" in inner or "$" in inner:
            return m[0]
        text = html.unescape(_TAG.sub("", inner)).strip()
        if not text or re.search(r"\s", text):
            return m[0]
        c = _CLASS.search(attrs)
        if c is None:
            attrs = f'{attrs} class="{NOWRAP}"'
        elif NOWRAP not in c[3].split():
            attrs = attrs[: c.start()] + f"{c[1]}{c[2]}{c[3]} {NOWRAP}{c[2]}" + attrs[c.end() :]
        return f"<{tag}{attrs}>{inner}</{tag}>"

    return _CELL.sub(mark, page)

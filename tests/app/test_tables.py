"""analysis.app.tables.marked: exactly the wrong cells are highlighted, in HTML and in text."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from analysis.app.tables import MARK, marked


def _highlighted(html: str) -> set[tuple[int, int]]:
    return {
        (int(r), int(c)) for r, c in re.findall(r'class="data row(\d+) col(\d+) wrong-cell"', html)
    }


def test_the_html_highlights_exactly_the_masked_cells():
    rng = np.random.default_rng(3)
    df = pd.DataFrame(rng.normal(size=(6, 4)), columns=list("abcd"))
    mask = rng.random((6, 4)) < 0.3
    t = marked(df, mask, name="t1", precision=3)
    html = t._repr_html_()
    assert _highlighted(html) == {(int(r), int(c)) for r, c in zip(*np.nonzero(mask), strict=True)}
    assert f"{mask.sum()} wrong cell" in html
    # the inline style (JupyterLab has no site CSS) is on the same cells
    styled = set(re.findall(r"#T_t1_row(\d+)_col(\d+)", html))
    assert {(int(r), int(c)) for r, c in styled} == _highlighted(html)
    # the same table in every run (nbval compares the stored HTML)
    assert html == marked(df, mask, name="t1", precision=3)._repr_html_()


def test_the_text_marks_each_wrong_cell_once():
    df = pd.DataFrame({"printed": ["45", "190.20"], "derived": [45.0, 10.2087]}, index=[1, 2])
    t = marked(df, {"printed": pd.Series([True, False], index=[2, 1])}, name="t2")
    text = repr(t)
    assert text.count(MARK) == 1
    assert "190.20" + MARK in text and "45" + MARK not in text  # by index label, not position


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"wrong": {"nope": [True, False]}, "name": "x"}, r"no column \['nope'\]"),
        ({"wrong": np.zeros((3, 2), bool), "name": "x"}, "shape"),
        ({"wrong": np.zeros((2, 2), bool), "name": "a b"}, "letters, digits"),
    ],
)
def test_bad_masks_and_names_are_refused(kwargs, message):
    df = pd.DataFrame({"a": [1, 2], "b": [3, 4]})
    with pytest.raises(ValueError, match=message):
        marked(df, **kwargs)

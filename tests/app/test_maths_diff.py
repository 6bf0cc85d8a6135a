"""Printed against derived, typeset with the differing parts boxed (analysis.app.maths_diff)."""

from __future__ import annotations

import re

import pandas as pd
import pytest

from analysis.app.maths_diff import MARK, differing_parts, marked_latex, typeset_comparison

_BOX = re.escape(MARK.split("%s")[0]) + r"(.*?)\$\}"


def boxed(tex: str) -> list[str]:
    """The LaTeX inside each box of ``tex``."""
    return [m.strip() for m in re.findall(_BOX, tex)]


def test_eq2_ax_printed_0_derived_sin_theta1_both_boxed():
    p, d = marked_latex("0", "sin(theta1)")
    assert boxed(p) == ["0"]
    assert boxed(d) == [r"\sin{\left(\theta_{1} \right)}"]


def test_only_the_term_that_differs_is_boxed():
    # eq. 13 as printed ends in -L2 where the derivation gives -L3; L2*cos(theta3) is right
    printed = "Px*cos(theta1) - L2*cos(theta3) - L2 = 0"
    derived = "Px*cos(theta1) - L2*cos(theta3) - L3 = 0"
    p, d = marked_latex(printed, derived)
    assert boxed(p) == ["L_{2}"] and boxed(d) == ["L_{3}"]
    assert r"L_{2} \cos{\left(\theta_{3} \right)}" in p.replace(MARK % "L_{2}", "")
    assert p.endswith("= 0") and d.endswith("= 0")


def test_a_wrong_sign_boxes_the_term_on_both_sides():
    p, d = marked_latex("Px*sin(theta1) + Py*cos(theta1)", "Px*sin(theta1) - Py*cos(theta1)")
    assert boxed(p) == boxed(d) == [r"P_{y} \cos{\left(\theta_{1} \right)}"]
    assert "+ " + MARK % r"P_{y} \cos{\left(\theta_{1} \right)}" in p
    assert "- " + MARK % r"P_{y} \cos{\left(\theta_{1} \right)}" in d


def test_equal_forms_have_no_box():
    assert differing_parts("cos(a)**2 + sin(a)**2", "1") == ([], [])
    p, d = marked_latex("cos(a)**2 + sin(a)**2", "1")
    assert boxed(p) == boxed(d) == []


def test_a_different_function_is_boxed_whole():
    p, d = marked_latex("theta1 = atan(Py/Px)", "theta1 = atan2(Py, Px)")
    assert p.startswith(r"\theta_{1} = ") and len(boxed(p)) == len(boxed(d)) == 1
    assert "atan" in boxed(p)[0] and "atan" in boxed(d)[0] and "_{2}" in boxed(d)[0]


def test_typeset_comparison_keeps_what_is_not_an_expression():
    t = pd.DataFrame(
        {"printed": ["0", "结合工程实际, 取式(16)"], "derived": ["sin(theta1)", "取式(6)"]}
    )
    out = typeset_comparison(t)
    assert out.printed[0].startswith(r"\(") and out.printed[0].endswith(r"\)")
    assert out.printed[1] == t.printed[1] and out.derived[1] == t.derived[1]
    with pytest.raises(ValueError, match="not the same number of '=' sides"):
        marked_latex("a = b", "a")


def test_the_typeset_table_asks_mathjax_to_typeset_it():
    t = pd.DataFrame({"verdict": ["wrong", "holds"], "printed": ["0", "1"], "derived": ["x", "1"]})
    out = typeset_comparison(t)
    for shown in (out, out.query("verdict != 'holds'")):
        assert shown._repr_html_().startswith('<div class="mathjax_process">')
    assert repr(out) == repr(pd.DataFrame(out))  # nbval compares the plain text


def test_long_maths_is_never_cut_short():
    long = " + ".join(f"x{i}*sin(theta{i})" for i in range(30))
    t = pd.DataFrame({"printed": [long], "derived": [long.replace("x7", "y7")]})
    with pd.option_context("display.max_colwidth", 50):
        html = typeset_comparison(t)._repr_html_()
    assert "..." not in html and html.count(r"\(") == html.count(r"\)") == 2

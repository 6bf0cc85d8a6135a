"""The transcription of the paper (analysis.papers.grabber): it parses, it matches the data files,
and the reconstruction of the STL figures stays faithful to the extracted text."""

import re
from collections import Counter

import pandas as pd
import pytest
import sympy as sp

from analysis.kinematics.arm import paper_arm
from analysis.kinematics.params import data_dir
from analysis.papers import grabber as paper


def test_every_transcribed_expression_parses():
    for name in paper.MATRICES:
        M = paper.matrix(name)
        assert M.shape == (4, 4), name
    for key, spec in paper.EQUATIONS.items():
        for side in ("lhs", "rhs"):
            assert isinstance(paper.parse(spec[side]), sp.Expr), (key, side)


def test_parse_rejects_unknown_names_and_bad_syntax():
    with pytest.raises(ValueError, match="unknown name"):
        paper.parse("theta4 + 1")
    with pytest.raises(ValueError, match="cannot parse"):
        paper.parse("cos(theta1")
    with pytest.raises(ValueError, match=r"no record|not a matrix"):
        paper.matrix("A4")


def test_symbols_are_those_of_the_dh_table():
    """The printed items must use the very symbols the symbolic D-H table uses."""

    A1, _, _ = paper_arm().dh_table(symbolic=True).transforms_sym()
    assert A1.free_symbols == {paper.SYMBOLS["theta1"], paper.SYMBOLS["L1"]}


def test_table3_transcription_equals_data_file():
    df = pd.read_csv(data_dir() / "table3.csv")
    for row, (_, rec) in zip(paper.TABLE3, df.iterrows(), strict=True):
        for col in (
            "alpha_deg",
            "a_mm",
            "d_mm",
            "cos_alpha",
            "sin_alpha",
            "step_angle_deg",
            "resolution_deg",
        ):
            assert float(rec[col]) == float(row[col]), col


def test_figure_keys_and_exact_figures_3_4():
    assert sorted(paper.FIGURE_STL) == [3, 4, 5, 6] == sorted(paper.FIGURE_STL_EXTRACTED)
    for k in (3, 4):  # extracted line by line: the reconstruction must be the same code
        code = [re.sub(r"\s+", "", ln.split("//")[0]) for ln in paper.FIGURE_STL[k].splitlines()]
        extracted = [re.sub(r"\s+", "", ln) for ln in paper.FIGURE_STL_EXTRACTED[k].splitlines()]
        assert [c for c in code if c] == [e for e in extracted if e]


_INSN = re.compile(r"(MOVR|MOVD|\+R|-R|\*R|/R|COS|SIN)\s+([\w.]+),\s*(VDD?\d+)")


@pytest.mark.parametrize("fig", [5, 6])
def test_reconstruction_is_faithful_to_extraction(fig):
    """Every certain instruction of the reconstruction occurs in the extracted text at least
    as often, and every instruction found in the extraction is in the reconstruction."""
    extracted = Counter(m.groups() for m in _INSN.finditer(paper.FIGURE_STL_EXTRACTED[fig]))
    certain, anyline = Counter(), Counter()
    for ln in paper.FIGURE_STL[fig].splitlines():
        code, _, comment = ln.partition("//")
        if not code.strip() and comment.strip().startswith("? printed, not placed:"):
            code = comment.split(":", 1)[1]  # printed but left out of the program on purpose
        m = _INSN.search(code)
        if m:
            anyline[m.groups()] += 1
            if not comment.strip().startswith("?"):
                certain[m.groups()] += 1
    too_many = {k: v for k, v in certain.items() if v > extracted[k]}
    missing = {k: v for k, v in extracted.items() if anyline[k] < v}
    assert not too_many, f"unmarked instructions not in the extraction: {too_many}"
    assert not missing, f"extracted instructions missing from the reconstruction: {missing}"


def test_uncertain_lines_are_declared():
    """Figures with '// ?' lines are listed in UNCERTAIN, and vice versa."""
    marked = {k for k, v in paper.FIGURE_STL.items() if "// ?" in v}
    assert marked == {5, 6}
    assert {"Figure 5", "Figure 6"} <= set(paper.UNCERTAIN)

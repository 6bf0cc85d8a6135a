"""The transcription of seed 001 (analysis.papers.palletizer): it parses, it is faithful to
the extracted runs (restorations only add what the extraction demonstrably drops), it is
data only, and the printed items behave as printed (eq. 11 is checked against the printed
matrices in tests/audit/test_palletizer_checks.py)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import sympy as sp

from analysis.papers import palletizer as paper
from helpers import seed_file

PACKAGE = Path(paper.__file__).parent


def test_every_equation_1_to_12_is_transcribed_and_parses():
    assert sorted(paper.EQUATIONS, key=lambda k: int(k[2:])) == [f"eq{i}" for i in range(1, 13)]
    for key, spec in paper.EQUATIONS.items():
        assert spec["extracted"].startswith("[") or key == "eq6", key
        assert spec["location"] == f"eq. {key[2:]}"
        if key not in ("eq8", "eq9", "eq10"):
            for lhs, rhs in paper.equation(key):
                assert isinstance(lhs, sp.Expr) and isinstance(rhs, sp.Basic), key
    for name in paper.MATRICES:
        assert paper.matrix(name).shape == (4, 4)


def test_parse_rejects_unknown_names_and_bad_syntax():
    with pytest.raises(ValueError, match="unknown name"):
        paper.parse("theta7 + 1")
    with pytest.raises(ValueError, match="cannot parse"):
        paper.parse("cos(theta1")
    with pytest.raises(ValueError, match=r"no record|not a matrix"):
        paper.matrix("T56")
    with pytest.raises(ValueError, match="matrix equation"):
        paper.equation("eq8")


def test_extracted_runs_occur_verbatim_in_the_seed():
    """Skipped where the seed (outside the repository) is not mounted."""
    seed = seed_file(paper.SOURCE)
    if not seed.is_file():
        pytest.skip(f"{seed} not available")
    text = seed.read_text(encoding="utf-8")
    for key, spec in paper.EQUATIONS.items():
        run = spec["extracted"].removesuffix("(10)")
        assert run in text, key
    for name, spec in paper.MATRICES.items():
        assert spec["extracted"] in text, name
    for key, claim in paper.CLAIMS.items():
        assert claim["extracted"], key
        for run in claim["extracted"]:
            assert run in text, key
    assert "小于900" in paper.CLAIMS["unique_pose"]["extracted"][0]  # '90°', degree sign lost


_GLYPHS = [
    (r"cos\(theta(\d|_i)\)", lambda m: "cosθ" + m.group(1).replace("_", "")),
    (r"sin\(theta(\d|_i)\)", lambda m: "sinθ" + m.group(1).replace("_", "")),
    (r"cos\(alpha_im1\)", lambda m: "cosαi-1"),
    (r"sin\(a_im1\)", lambda m: "sinai-1"),
    (r"cos\(a_im1\)", lambda m: "cosai-1"),
    (r"a_im1", lambda m: "ai-1"),
    (r"d_i", lambda m: "di"),
    (r"\*", lambda m: ""),
]


def glyphs(entry: str) -> str:
    for pattern, repl in _GLYPHS:
        entry = re.sub(pattern, repl, entry)
    return entry


@pytest.mark.parametrize("name", sorted(paper.MATRICES))
def test_matrix_rows_flatten_to_the_extracted_run(name):
    """Each transcribed matrix, written back in the extraction's glyphs and flattened row by
    row, is exactly the extracted run: nothing added, dropped or reordered."""
    spec = paper.MATRICES[name]
    body = spec["extracted"][1:-1].split("=", 1)[1]
    flat = "".join(glyphs(e) for row in spec["rows"] for e in row)
    assert flat == body


def test_eq11_restoration_only_adds_parentheses():
    """Removing every parenthesis and space from the plain reading gives the extracted run
    minus its parentheses: the restoration adds parentheses and nothing else."""
    spec = paper.EQUATIONS["eq11"]
    printed = re.sub(r"[()\s;]", "", spec["printed"])
    extracted = re.sub(r"[()]", "", spec["extracted"][1:-1])
    assert printed == extracted
    assert [p["label"] for p in spec["parts"]] == ["t14", "t34", "t34"]


def _from_plain(text: str) -> sp.Expr:
    """Plain eq. 11 notation (c1, s4, juxtaposition) -> SymPy, independently of the module's
    transcription strings."""
    tokens = re.findall(r"[cs]\d|L\d|h|[()+\-]", text.replace(" ", ""))
    out, prev_operand = [], False
    for tok in tokens:
        operand = tok not in "+-)" and tok != ")"
        if tok in ("+", "-"):
            out.append(tok)
            prev_operand = False
            continue
        if tok == ")":
            out.append(tok)
            prev_operand = True
            continue
        if prev_operand:
            out.append("*")
        if tok == "(":
            out.append(tok)
            prev_operand = False
            continue
        if tok[0] in "cs" and len(tok) == 2:
            out.append(f"{'cos' if tok[0] == 'c' else 'sin'}(theta{tok[1]})")
        else:
            out.append(tok)
        prev_operand = operand
    return paper.parse("".join(out))


def test_eq11_transcription_equals_its_plain_reading():
    rows = [r.split("=", 1)[1] for r in paper.EQUATIONS["eq11"]["printed"].split(";")]
    for (_, rhs), plain in zip(paper.equation("eq11"), rows, strict=True):
        assert sp.expand(rhs - _from_plain(plain)) == 0


def test_eq12_as_printed_contradicts_eq7_at_zero_motor_angles():
    """Eq. 7 is the pose where all motor angles are 0 (sec. 3: initial pose); eq. 12 at
    gamma = alpha = beta = 0 must reproduce it. theta1..theta3 do, theta4 does not."""
    S = paper.SYMBOLS
    zero = {S["gamma"]: 0, S["alpha"]: 0, S["beta"]: 0}
    eq7 = dict(paper.equation("eq7"))
    got = {}
    for lhs, rhs in paper.equation("eq12"):
        got[lhs] = sp.simplify(rhs.subs(zero).subs(got))
    for k in ("theta1", "theta2", "theta3"):
        assert got[S[k]] == eq7[S[k]], k
    assert got[S["theta4"]] == 3 * sp.pi / 2 != eq7[S["theta4"]]


def test_eq6_has_no_case_for_the_negative_x_axis():
    ((_lhs, rhs),) = paper.equation("eq6")
    S = paper.SYMBOLS
    assert rhs.subs({S["X0"]: -1, S["Y0"]: 0, S["gammap"]: 0}) is sp.nan
    assert rhs.subs({S["X0"]: 1, S["Y0"]: 0, S["gammap"]: 0}) == 0


def test_eq3_uses_H_which_nothing_defines():
    H = paper.SYMBOLS["H"]
    users = [
        k
        for k in paper.EQUATIONS
        if k not in ("eq8", "eq9", "eq10")
        for lhs, rhs in paper.equation(k)
        if H in rhs.free_symbols
    ]
    defined = [
        k
        for k in paper.EQUATIONS
        if k not in ("eq8", "eq9", "eq10")
        for lhs, _ in paper.equation(k)
        if lhs == H
    ]
    assert users == ["eq3"] and defined == []


def test_lost_and_uncertain_name_the_tables_figures_and_lengths():
    for item in ("Table 1", "Table 2", "Table 3", "Figure 7", "lengths", "targets"):
        assert item in paper.LOST
    for item in ("eq. 3 H", "eq. 2 grouping", "eq. 12 parentheses", "eq. 8 glyph"):
        assert item in paper.UNCERTAIN
    assert paper.CLAIMS["targets_in_metres"]["unit"] == "m"
    assert paper.CLAIMS["unique_pose"]["limit_deg"] == 90.0


def test_sections_and_references_are_those_printed():
    """SECTIONS and REFERENCES (used by the cross-reference checks): the IK is section 3, the
    D-H source is reference [6]; against the seed where it is mounted (the English section
    titles and the Latin-script references survive the extraction unchanged)."""
    assert "逆向" in paper.SECTIONS[3] and "逆向" not in paper.SECTIONS[2]
    assert [n for n, r in paper.REFERENCES.items() if r["topic"] == "D-H method"] == [2, 6]
    seed = seed_file(paper.SOURCE)
    if not seed.is_file():
        pytest.skip(f"{seed} not available")
    text = seed.read_text(encoding="utf-8")
    for n, title in paper.SECTIONS.items():
        english = title.split(" (", 1)[1].rstrip(")")
        assert re.search(rf"\n{n}[^\n]*\({re.escape(english)}\)", text), (n, english)
    assert "[6] Tony Owen. Introduction to Robotics[J]. Robotica,1991,9(4)." in text
    assert "[2] Hartenburg R.S.,Denavit J." in text

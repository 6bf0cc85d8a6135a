"""The one papers schema (analysis.papers, data/papers/<paper>.toml): every paper, the picker
included, is the same records with a type and a location; every expression parses with the one
parser; references into the records resolve; the extracted runs are the seed's own text."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import pytest

from analysis import papers
from helpers import seed_file


@pytest.mark.parametrize("name", papers.PAPERS)
def test_every_paper_is_the_same_records(name):
    paper = papers.load(name)  # validates: types, locations, fields, expressions parse
    assert paper.id == name and paper.title and paper.source.endswith(".txt")
    types = {r.type for r in paper.records.values()}
    assert types <= set(papers.TYPES)
    assert {"claim", "lost" if name != "grabber" else "claim", "uncertain"} <= types
    for rec in paper.records.values():
        assert rec.location.strip(), rec.id


@pytest.mark.parametrize("name", papers.PAPERS)
def test_extracted_runs_are_the_seeds_text(name):
    """Skipped where the seed (outside the repository) is not mounted."""
    paper = papers.load(name)
    seed = seed_file(paper.source)
    if not seed.is_file():
        pytest.skip(f"{seed} not available")
    text = seed.read_text(encoding="utf-8")
    flat = " ".join(text.split())  # runs kept as tokens (seed 004's ladder) match the layout
    keys = {str(r.get("key")) for r in paper.records.values() if r.type == "extracted"}
    runs = []
    for r in paper.records.values():
        named = r.get("extracted", ())
        named = [named] if isinstance(named, str) else list(named)
        runs += [(r.id, x) for x in named if x not in keys]  # else: a reference, below
        runs += [(r.id, x) for x in r.get("runs", ())]
        if r.type == "extracted" and isinstance(r.get("text"), str):
            runs += [(r.id, x) for x in r["text"].splitlines() if x.strip()]
        bad = [x for x in named if x not in keys and not isinstance(x, str)]
        assert not bad, r.id
    assert runs
    missing = [
        rid
        for rid, run in runs
        if run.removesuffix("(10)").strip() not in text and " ".join(run.split()) not in flat
    ]
    missing = sorted(set(missing))
    # seed 000's figures 5-6 are kept as the extraction's interleaved columns, line by line
    assert all(
        all(line.strip() in text for line in paper.record(rid)["extracted"].splitlines())
        for rid in missing
    ), missing


def test_references_resolve_to_the_printed_text():
    g = papers.load("grabber")
    assert g.text("eq12[3,3]") == "1"  # the surplus 1 of eq. 12 (left matrix, row 3)
    assert g.text("table4[1].theta2_deg") == "190.20"
    assert g.text("eq6") == "theta1 = atan(Py/Px)"
    assert g.text("figure3:2-2").split()[:2] == ["LD", "上电置1"]
    assert papers.load("palletizer").text("eq3#2") == "alpha2 = asin(H/L4p)"
    for bad in ("eq99", "eq12[5,1]", "figure3:1-999", "table4[11].theta1_deg", "eq6["):
        with pytest.raises((ValueError, IndexError)):
            g.text(bad)


def test_one_parser_for_every_paper():
    for name in papers.PAPERS:
        paper = papers.load(name)
        with pytest.raises(ValueError, match="unknown name"):
            paper.parse("nobody_defines_this + 1")
        with pytest.raises(ValueError, match="cannot parse"):
            paper.parse("cos(")
        with pytest.raises(ValueError):
            paper.parse("__import__('os')")


def test_the_papers_package_is_data_only():
    """analysis.papers imports the standard library, SymPy and analysis.paths only."""
    names = set()
    for path in sorted(Path(papers.__file__).parent.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names |= {a.name for a in node.names}
            elif isinstance(node, ast.ImportFrom):
                names.add(node.module or "")
    outside = {n for n in names if n.split(".")[0] not in sys.stdlib_module_names}
    inside = {"analysis.papers", "analysis.papers.catalog", "analysis.papers.data",
              "analysis.paths"}  # fmt: skip
    assert outside <= {"sympy", *inside}, outside

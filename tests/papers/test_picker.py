"""The transcription of seed 002 (analysis.papers.picker): data only, every structured item
rests on a verbatim run of the seed, and the structured values agree with those runs."""

from __future__ import annotations

import re

import pytest
import sympy as sp

from analysis.papers import picker as paper
from helpers import seed_file


def test_extracted_runs_occur_verbatim_in_the_seed():
    seed = seed_file(paper.SOURCE)
    if not seed.is_file():
        pytest.skip(f"{seed} not available")
    text = seed.read_text(encoding="utf-8")
    for key, runs in paper.EXTRACTED.items():
        for run in runs:
            assert run in text, key


def _refs():
    for name, obj in (
        ("TOPOLOGY", paper.TOPOLOGY),
        ("CHAINS", paper.CHAINS),
        ("JOINTS", paper.JOINTS),
        ("EXPERIMENT", paper.EXPERIMENT),
    ):
        for key in obj["extracted"]:
            yield name, key
    for name, d in paper.DIMENSIONS.items():
        yield name, d["extracted"]
    for name, c in paper.CLAIMS.items():
        for key in c["extracted"]:
            yield name, key
    for ref in paper.CROSS_REFERENCES:
        if "extracted" in ref:
            yield ref["location"], ref["extracted"]


def test_every_item_points_at_an_extracted_run():
    for owner, key in _refs():
        assert key in paper.EXTRACTED, (owner, key)


def _clean(key: str) -> str:
    """A run without the pinyin readings the extraction inserts (e.g. 聯(lián))."""
    text = "".join(paper.EXTRACTED[key])
    return re.sub(r"\([a-zāáǎàēéěèīíǐìōóǒòūúǔùǖǘǚǜü]+\)", "", text)


def test_joint_laws_and_units_match_the_run():
    run = _clean("joint_laws")
    printed = dict(re.findall(r"([ων][\dxz]+)=(-?\d+)t", run))
    laws = paper.EXPERIMENT["laws"]
    name = {"ω1": "omega1", "ω6": "omega6", "ω7": "omega7", "ω8": "omega8"}
    name |= {"νx": "nu_x", "νz": "nu_z"}
    assert {name[k]: int(v) for k, v in printed.items()} == {
        k: int(sp.Poly(paper.joint_law(k)).coeffs()[0]) for k in laws
    }
    assert "角速度,rad/s" in run and "mm/s" in run and "t為時間變量,s" in run
    assert all(v["unit"] == "rad/s" for k, v in laws.items() if k.startswith("omega"))
    assert all(v["unit"] == "mm/s" for k, v in laws.items() if k.startswith("nu"))
    assert "1、2、3、4、5 s" in _clean("samples")
    assert paper.EXPERIMENT["times"] == (1.0, 2.0, 3.0, 4.0, 5.0)
    with pytest.raises(ValueError, match="unknown joint law"):
        paper.joint_law("omega2")


def test_numbers_match_the_runs():
    assert f"{paper.EXPERIMENT['max_abs_error_mm']} mm" in _clean("max_error")
    assert "X、Y、Z軸上" in _clean("max_error")  # per axis
    assert f"{paper.EXPERIMENT['jaw_opening_mm']:.0f} mm的最大開度" in _clean("proof_by_opening")
    assert "(1 500,0,0)" in _clean("instrument")
    assert paper.EXPERIMENT["instrument_origin_in_S_mm"] == (1500.0, 0.0, 0.0)
    assert "(22)" in _clean("xref_eq22") and paper.EXPERIMENT["fk_equation"] == 22


def test_active_and_passive_joints_match_the_run():
    run = _clean("active_passive")
    beta = re.search(r"β=\[([^\]]+)\]", run).group(1)
    alpha = re.search(r"α=\[([^\]]+)\]", run).group(1)
    as_names = lambda s: tuple(f"theta{n}" for n in re.findall(r"θ(\d+)", s))  # noqa: E731
    assert as_names(beta) == paper.JOINTS["active"]
    assert as_names(alpha) == paper.JOINTS["passive"]
    run = _clean("slider_variables")
    assert "x為水平滑塊的位移量" in run and "ξ9" in run and "z為豎直滑塊的位移量" in run
    assert paper.JOINTS["sliders"]["theta9"]["name"] == "x"


def test_topology_counts():
    top = paper.TOPOLOGY
    assert top["type"] == "2P4R" and top["prismatic"] + top["revolute"] == top["dof"] == 6
    assert len(top["parts"]) == 12
    # the experiment commands exactly the six actuated joints
    commanded = {paper.EXPERIMENT["laws"][k]["joint"] for k in paper.JOINTS["commanded"]}
    assert commanded == {"theta1", "theta2", "theta6", "theta7", "theta8", "theta9"}
    assert len(paper.JOINTS["active"]) + len(paper.JOINTS["passive"]) + 4 == 13
    assert "2P4R6自由度" in _clean("dof")


def test_equation_numbers_and_cross_references():
    numbers = [e["n"] for e in paper.EQUATION_NUMBERS]
    assert numbers == list(range(1, 23))
    for ref in paper.CROSS_REFERENCES:
        assert all(1 <= n <= 22 for n in ref["refers_to"]), ref
    held = {e["n"]: e["holds"] for e in paper.EQUATION_NUMBERS}
    assert held[22] == "p_e(theta)" and held[18] != "p_e(theta)"
    assert held[7] == "revolute twist" and held[8] == "prismatic twist"


def test_lost_and_uncertain():
    for item in ("eqs. 1-22", "Table 1", "Table 2", "Figure 3"):
        assert item in paper.LOST
    for item in ("equation numbers", "joint laws", "link 5 and the triangle"):
        assert item in paper.UNCERTAIN
    assert all("value" not in d for d in paper.DIMENSIONS.values())  # no value printed

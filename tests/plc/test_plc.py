"""analysis.plc: IR, emitters (golden files), approximations, memory map, CLI, translator."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from analysis.kinematics.arm import BRANCHES, paper_arm
from analysis.plc.approx import acos_f32, atan2_f32, atan_coefficients, measure_errors
from analysis.plc.emit import emit_s7200, fmt_real
from analysis.plc.generate import generate
from analysis.plc.ir import build_program
from analysis.plc.memmap import MemoryMap, default_map, parse_address
from analysis.plc.translate import translate_s7200

GOLDEN = Path(__file__).parent / "golden"
PAPER = paper_arm()
ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("dialect", ["s7-200", "s7-300"])
def test_emitted_text_matches_golden(dialect):
    # golden files reviewed by eye once, then frozen; regenerate deliberately if the IR changes
    text, mjson = generate(PAPER, dialect)
    assert text == (GOLDEN / f"plc_{dialect}_front-up.awl").read_text(
        encoding="utf-8", errors="strict"
    ).replace("\r\n", "\n").replace("\n", "\r\n" if dialect == "s7-200" else "\n")
    assert json.loads(mjson) == json.loads((GOLDEN / f"plc_{dialect}_map.json").read_text())


def test_golden_s7200_has_paper_structure():
    text = (GOLDEN / "plc_s7-200_front-up.awl").read_bytes().decode()
    assert "\r\n" in text  # Micro/WIN text: CRLF
    # the start-up writes nothing into the HMI's inputs (issue 22): no Figure 3 network
    assert "VD0" in text and not any(
        ln.split()[-1] in ("VD0", "VD4", "VD8") for ln in text.splitlines() if ln.startswith("MOV")
    )
    paper = generate(PAPER, "s7-200", startup_target="paper").program
    assert "LD     SM0.1\r\nMOVR   100.0, VD0\r\nMOVR   100.0, VD4\r\nMOVR   600.0, VD8" in paper
    for needle in (
        "ORGANIZATION_BLOCK MAIN:OB1",
        "SUBROUTINE_BLOCK ATAN2:SBR1",
        "SUBROUTINE_BLOCK ACOS:SBR2",
        "ROUND  ",
        "MOVB   16#A0, SMB67",
        "PLS    1",
    ):
        assert needle in text
    # no inverse trigonometry and no integer move into the REAL inputs (Figure 3's MOVD)
    assert "ATAN " not in text and "ACOS " not in text and "MOVD   100, VD0" not in text


def test_no_link_length_typed_into_emitters():
    p = paper_arm().with_(L2=321.0, L3=123.0)
    text = emit_s7200(build_program(p))
    # the lengths come from the parameters: L2, L2 + L3 (the reach) and L2^2 + L3^2 (eq. 10)
    assert "321.0" in text and "444.0" in text and str(321.0**2 + 123.0**2) in text
    assert "310.0" not in text


def test_map_json_names_every_address():
    _, mjson = generate(PAPER, "s7-200")
    d = json.loads(mjson)
    assert d["inputs"] == {"px": "VD0", "py": "VD4", "pz": "VD8"}  # Figure 3
    assert d["outputs"] == {
        "c1": "VD100",
        "c2": "VD104",
        "c3": "VD108",
        "reachable": "V112.0",
        "status": "VD116",
    }
    mm = MemoryMap.from_dict(d)
    assert mm == default_map("s7-200")


@pytest.mark.parametrize(
    "bad",
    [
        {"dialect": "s7-200", "inputs": {"px": "MD0", "py": "VD4", "pz": "VD8"}},
        {"dialect": "s7-300", "inputs": {"px": "MD1", "py": "MD4", "pz": "MD8"}},
        {"dialect": "s7-300", "inputs": {"px": "MD0", "py": "MD0", "pz": "MD8"}},
    ],
)
def test_bad_maps_raise(bad):
    d = json.loads(generate(PAPER, bad["dialect"]).map)
    d["inputs"] = bad["inputs"]
    with pytest.raises(ValueError, match=r"M|V|overlap|multiple"):
        MemoryMap.from_dict(d)


def test_parse_address():
    assert parse_address("VD12", "s7-200") == ("D", 12, None)
    assert parse_address("M112.0", "s7-300") == ("X", 112, 0)
    with pytest.raises(ValueError, match="beyond"):
        parse_address("MD4096", "s7-300")


def test_atan_coefficients_near_taylor():
    c = atan_coefficients()
    assert c[0] == pytest.approx(1.0, abs=1e-6)
    assert c[1] == pytest.approx(-1 / 3, rel=1e-4)  # minimax perturbs the Taylor terms slightly


def test_approximation_error_below_half_pulse():
    err = measure_errors(4000, n=200_001)
    for e in err.values():
        # float32 holds pi to 8.7e-8 rad; the routine must stay within a few ulps of it,
        # far below half a pulse (0.045 deg = 7.9e-4 rad)
        assert e.max_rad < 1e-6
        assert e.max_pulses < 0.01


def test_atan2_f32_quadrants_and_origin():
    y = np.array([0.0, 1.0, 1.0, -1.0, -1.0, 0.0, 0.0, 2.0], np.float32)
    x = np.array([0.0, 1.0, -1.0, -1.0, 1.0, -1.0, 1.0, 0.0], np.float32)
    np.testing.assert_allclose(atan2_f32(y, x), np.arctan2(y, x), atol=5e-7)
    np.testing.assert_allclose(acos_f32([-1, 0, 1]), [math.pi, math.pi / 2, 0], atol=5e-7)
    with pytest.raises(ValueError, match="outside"):
        acos_f32([1.5])


def test_build_program_rejects_bad_options():
    with pytest.raises(ValueError, match="branch"):
        build_program(paper_arm(), "left")
    with pytest.raises(ValueError, match="ATAN"):
        emit_s7200(build_program(paper_arm(), trig="native"))


@pytest.mark.parametrize(
    "v,txt", [(100.0, "100.0"), (1e-12, "9.99999996e-13"), (-math.pi, "-3.14159274"), (0.0, "0.0")]
)
def test_fmt_real(v, txt):
    assert fmt_real(v) == txt


def test_translator_rejects_unknown_operand():
    with pytest.raises(ValueError, match="VDD0"):
        translate_s7200(
            "ORGANIZATION_BLOCK MAIN:OB1\nBEGIN\nNetwork 1\nLD SM0.0\nCOS VDD0, VD180\n"
            "END_ORGANIZATION_BLOCK\n"
        )


@pytest.mark.parametrize("branch", BRANCHES)
def test_all_branches_emit(branch):
    text, _ = generate(PAPER, "s7-300", branch)
    assert f"branch {branch}" in text


def test_cli_stl(tmp_path):
    out, mp = tmp_path / "p.awl", tmp_path / "m.json"
    cmd = [
        sys.executable,
        "-m",
        "analysis",
        "stl",
        "--dialect",
        "s7-200",
        "-o",
        str(out),
        "--map",
        str(mp),
    ]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert out.read_bytes() == generate(PAPER, "s7-200").program.encode()
    assert json.loads(mp.read_text())["outputs"]["c1"] == "VD100"
    r = subprocess.run(
        [*cmd[:5], "s7-200", "--trig", "native", "-o", str(out), "--map", str(mp)],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and "S7-200" in r.stderr


def test_plot_rounding_margin_marks_changed_counts():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from analysis.plc.plots import plot_rounding_margin

    fig, ax = plt.subplots()
    exact = np.array([10.49999, 10.2, -3.50001])
    real = np.array([10.5, 10.2, -3.5])  # half-away: 11 vs 10 (changed), 10, -4 vs -4
    assert plot_rounding_margin(exact, real, ax=ax) is ax
    assert "(1)" in ax.get_legend().get_texts()[1].get_text()
    with pytest.raises(ValueError, match="rounding"):
        plot_rounding_margin(exact, real, ax=ax, rounding="up")
    plt.close(fig)


def test_custom_layout_round_trip_and_execution(tmp_path):
    # a user map with the outputs moved above the default work area (CLI --layout)
    from analysis.plc.runner import AwlRunner

    d = json.loads(generate(PAPER, "s7-300").map)
    d["inputs"] = {"px": "MD20", "py": "MD24", "pz": "MD28"}
    d["outputs"] = {"c1": "MD400", "c2": "MD404", "c3": "MD408", "reachable": "M412.3"}
    (tmp_path / "layout.json").write_text(json.dumps(d))
    mm = MemoryMap.from_json(tmp_path / "layout.json")
    assert mm.work_base == 416
    text, mjson = generate(PAPER, "s7-300", mmap=mm)
    assert json.loads(mjson)["outputs"]["reachable"] == "M412.3"
    r = AwlRunner(text, mm)
    res = r.solve([[100.0, 100.0, 600.0], [200.0, 500.0, 600.0]], sentinel=7)
    assert res.pulses.tolist() == [[500, 113, -1724], [7, 7, 7]]
    assert res.reachable.tolist() == [True, False]


@pytest.mark.parametrize("arm_name", ["grabber", "palletizer"])
@pytest.mark.parametrize("dialect", ["s7-200", "s7-300"])
def test_generated_listings_have_no_overlapping_operands(arm_name, dialect):
    """The byte-level check of analysis.plc.stl_eval.overlaps on every generated program:
    no two addresses share a byte (the paper's Figure 5 has VD104/VD106; see the register)."""
    from analysis.kinematics.arm import load_arm
    from analysis.papers import grabber as paper
    from analysis.plc import stl_eval

    text, _ = generate(load_arm(arm_name), dialect)
    area = "V" if dialect == "s7-200" else "M"
    v_text = text.replace(f"{area}D", "VD") if area == "M" else text
    instrs = stl_eval.parse_stl(v_text)
    assert len(instrs) > 100
    assert stl_eval.overlaps(instrs) == []
    fig5 = stl_eval.overlaps(stl_eval.parse_stl(paper.FIGURE_STL[5]))
    assert [(a, b) for a, b, _ in fig5] == [("VD104", "VD106")]

"""The GR-1 thesis transcription (analysis.papers.gr1_thesis) is complete and self-consistent.

These tests check the data against itself and against the extraction it came from (the
restored listing against the extracted one, Table 5-4's cells against the ten extracted
numbers); they do not judge the thesis, which is analysis.audit's job.
"""

from __future__ import annotations

import math
import re

import pytest
import sympy as sp

from analysis.audit.kinds.symbolic import is_zero
from analysis.papers import gr1_thesis as g


@pytest.mark.parametrize("key", sorted(g.EQUATIONS))
def test_every_equation_parses(key):
    eq = g.EQUATIONS[key]
    kind = eq.get("symbols", "kinematics")
    assert isinstance(g.parse(eq["lhs"], kind), sp.Basic)
    assert isinstance(g.parse(eq["rhs"], kind), sp.Basic)
    assert eq["location"] and eq["printed"]


@pytest.mark.parametrize("name", sorted(g.MATRICES))
def test_every_matrix_parses(name):
    m = g.matrix(name)
    assert m.shape in ((3, 3), (4, 4))


def test_parse_names_the_bad_input():
    with pytest.raises(ValueError, match="unknown name"):
        g.parse("theta9 + 1")
    with pytest.raises(ValueError, match="cannot parse"):
        g.parse("cos(theta1")
    with pytest.raises(ValueError, match="symbols must be"):
        g.parse("t", symbols="other")
    with pytest.raises(ValueError, match=r"no record|not a matrix"):
        g.matrix("3.99")


def test_eq_3_15_is_the_product_of_eq_3_14():
    """The sign reading of eq. 3.15 equals Rot(z, phi) Rot(y, theta) Rot(x, psi)."""
    s = g.SYMBOLS
    rx = g.matrix("3.5").subs(s["theta"], s["psi"])
    ry = g.matrix("3.6")
    rz = g.matrix("3.7").subs(s["theta"], s["phi"])
    product = rz * ry * rx
    printed = g.matrix("3.15")[:3, :3]
    assert sp.simplify(product - printed) == sp.zeros(3, 3)


def test_eq_3_19_is_rot_z_trans_z_trans_x_rot_x():
    s = g.SYMBOLS
    th, d, a, al = s["theta_i"], s["d_i"], s["a_i"], s["alpha_i"]
    rz = sp.Matrix(sp.BlockDiagMatrix(sp.rot_axis3(-th), sp.eye(1)))
    rx = sp.Matrix(sp.BlockDiagMatrix(sp.rot_axis1(-al), sp.eye(1)))
    tz, tx = sp.eye(4), sp.eye(4)
    tz[2, 3], tx[0, 3] = d, a
    assert sp.simplify(rz * tz * tx * rx - g.matrix("3.19")) == sp.zeros(4, 4)


def test_section_4_2_position_readings_invert_the_planar_chain():
    """c3, s2, c2 as read (signs '?' in the print) hold for the chain the listing assumes:
    r = a2 c2 + a3 c23 + a4 c234, z = a2 s2 + a3 s23 + a4 s234 (no base height)."""
    s = g.SYMBOLS
    t1, t2, t3, t234 = s["theta1"], s["theta2"], s["theta3"], s["theta234"]
    a2, a3, a4 = s["a2"], s["a3"], s["a4"]
    r = a2 * sp.cos(t2) + a3 * sp.cos(t2 + t3) + a4 * sp.cos(t234)
    z = a2 * sp.sin(t2) + a3 * sp.sin(t2 + t3) + a4 * sp.sin(t234)
    sub = {s["px"]: r * sp.cos(t1), s["py"]: r * sp.sin(t1), s["pz"]: z}
    # sec. 4.2's notation: c_i, s_i the cosine and sine of joint i (s3 the root with s3 > 0)
    sub.update({s[f"{f}{j}"]: fn(s[f"theta{j}"]) for j in ("1", "2", "3", "234")
                for f, fn in (("c", sp.cos), ("s", sp.sin))})  # fmt: skip
    for key, truth in (("4.2-c3", sp.cos(t3)), ("4.2-s2", sp.sin(t2)), ("4.2-c2", sp.cos(t2))):
        rhs = g.parse(g.EQUATIONS[key]["rhs"]).subs(sub)
        assert is_zero(rhs - truth), key  # exact: sin/cos reduced modulo s^2 + c^2 - 1
        assert not is_zero(rhs - truth + a2 / 1000), key  # and it can say no


def test_arm_dimensions_and_work_area_as_printed():
    dims = g.ARM["dimensions"]
    assert (dims["upper_arm_mm"], dims["lower_arm_mm"], dims["hand_mm"]) == (228, 228, 73)
    assert "228mm" in dims["printed"] and "73mm" in dims["printed"]
    wa = g.ARM["work_area"]
    assert (wa["vertical_mm"], wa["horizontal_mm"]) == (850, 600)
    assert "垂直方向:850mm" in wa["printed"] and "水平方向:600mm" in wa["printed"]
    assert g.ARM["dof"]["value"] == 5
    assert g.ENCODER["signals_per_rev"] == g.ENCODER["holes"] * len(g.ENCODER["channels"])


def test_table2_1_five_axes_one_motor_each():
    rows = g.TABLE2_1["rows"]
    assert [r[1] for r in rows] == ["M1", "M2", "M3", "M4", "M5"]
    assert [r[2] for r in rows] == [0.14, 0.11, 0.11, 0.11, 0.24]
    for r in rows:
        assert str(r[2]) in g.TABLE2_1["printed"]


def test_tables_2_2_and_2_3_name_the_same_counters():
    presets = g.TABLE2_3["presets"]
    assert presets == {"C235": 4, "C236": 147, "C237": 118, "C238": 31, "C239": 16}
    assert list(presets) == list(g.TABLE2_2["inputs"]) == list(g.PLC["high_speed_counters"]["used"])
    assert list(g.TABLE2_2["inputs"].values()) == ["X0", "X1", "X2", "X3", "X4"]
    assert set(g.TABLE2_2["inputs"].values()) <= set(g.PLC["high_speed_counters"]["inputs"])
    assert list(g.TABLE2_3["counter_of_joint"].values()) == list(presets)
    for name, value in presets.items():
        assert f"{name} {value}" in g.TABLE2_3["printed"]


def test_table5_3_rows_as_printed():
    rows = g.TABLE5_3["rows"]
    for label, word in (("start", "起点"), ("end", "终点")):
        assert f"{word} " + " ".join(str(v) for v in rows[label]) in g.TABLE5_3["printed"]


def test_table5_4_cells_use_each_extracted_number_once():
    start, end = g.TABLE5_4["rows"]["start"], g.TABLE5_4["rows"]["end"]
    numbers = g.TABLE5_4_EXTRACTED["numbers"]
    assert sorted(start + end) == sorted(numbers)
    # the stated reading: column by column, end value first
    assert tuple(x for pair in zip(end, start, strict=True) for x in pair) == numbers
    assert " ".join(f"{x:g}" for x in numbers) == g.TABLE5_4_EXTRACTED["printed_numbers"]


def test_table5_4_theta1_is_atan_of_table5_3_without_the_listing():
    """theta1 = atan(py/px) fixes which of 56.31 / 56.828 is the start (the pair order)."""
    for label in ("start", "end"):
        px, py = g.TABLE5_3["rows"][label][:2]
        assert round(math.degrees(math.atan(py / px)), 3) == g.TABLE5_4["rows"][label][0]


def _apply_restorations(extracted: str) -> str:
    text = extracted.replace("轨迹规划界面 VB 程序如下: ", "", 1)
    pages = next(r for r in g.LISTING_RESTORATIONS if r["what"] == "page footers")
    for ctx in pages["contexts"]:
        assert text.count(ctx) == 1, ctx
        number = re.search(r" (\d\d) ?$", ctx).group(1)
        text = text.replace(ctx, ctx.replace(" " + number, "", 1))
    joined = " ".join(text.split())
    return re.sub(r"(?<!= )([θαβγ]) (f?\d)", r"\1\2", joined)


def test_listing_differs_from_the_extraction_only_by_the_restorations():
    restored = " ".join(g.LISTING.split())
    assert _apply_restorations(g.LISTING_EXTRACTED) == restored
    n_greek = len(re.findall(r"(?<!= )([θαβγ]) (f?\d)", g.LISTING_EXTRACTED))
    assert n_greek == 18  # the count LISTING_RESTORATIONS states


def test_listing_has_the_three_event_procedures_once():
    subs = re.findall(r"^Private Sub (\w+)\(\)$", g.LISTING, flags=re.M)
    assert subs == ["Command1_Click", "Command3_Click", "Command4_Click"]
    assert g.LISTING.count("End Sub") == 3
    first = "Dim a2, a3, a4, PI, a, b, c, d, h, m, n, max, min As Double"
    assert g.LISTING.splitlines()[0] == first
    assert "Py1 * Sin(θf1) Cos(θf234) * a4" in g.LISTING  # kept as printed
    assert g.GUI_CHECK["printed"] in g.LISTING


def test_ladder_operands_match_tables_2_2_and_2_3():
    tokens = " ".join(g.LADDER_EXTRACTED.values()).split()
    for counter, k in g.LADDER["recoverable"]["counters"].items():
        assert counter in tokens and k in tokens
    for relay in g.LADDER["recoverable"]["direction_relays"]:
        assert relay in tokens
    for pairs in g.LADDER["recoverable"]["motor_output_pairs"].values():
        for y1, y2 in pairs:
            assert y1 in tokens and y2 in tokens
    assert tokens[-1] == "END"


def test_claims_lost_and_uncertain_are_filled_in():
    for cid, claim in g.TEXT_CLAIMS.items():
        assert claim["location"] and claim["printed"] and claim["statement"], cid
    assert g.LADDER["sequence_claim"] in g.TEXT_CLAIMS
    assert g.CUBIC["claim"] in g.TEXT_CLAIMS
    assert set(g.GUI_CHECK["text_claims"]) <= set(g.TEXT_CLAIMS)
    assert "printed" not in g.DH_TABLE and "sec. 4.1" in g.LOST
    assert len(g.LOST) >= 10 and len(g.UNCERTAIN) >= 10
    assert all(isinstance(v, str) and v for v in (*g.LOST.values(), *g.UNCERTAIN.values()))
    assert set(g.CUBIC["equations"]) <= set(g.EQUATIONS)
    assert sorted(g.CUBIC["lost"]) == ["5.5", "5.6", "5.7", "5.8", "5.9"]

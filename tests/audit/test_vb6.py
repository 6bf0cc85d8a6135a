"""The VB6 interpreter (analysis.audit.vb6): one test per modelled VB6 rule, then the GR-1
thesis's listing run as printed on Table 5-3 and held against Table 5-4 cell by cell.

Each rule test is chosen so that a plain-Python reading gives a different answer (float64
everywhere, Dim types applied to every name, math.atan2, degrees-aware trig, ...).
"""

from __future__ import annotations

import math

import pytest

from analysis.audit import vb6
from analysis.audit.papers.gr1 import listing as gl
from analysis.papers import gr1_thesis as g

pytestmark = pytest.mark.slow  # seconds per test: run first (tests/conftest.py)


def snippet(body: str, **options: bool) -> dict[str, vb6.Value]:
    """Run ``body`` as the body of an event procedure and return its locals."""
    form = vb6.VB6Form("Private Sub T_Click()\n" + body + "\nEnd Sub\n", **options)
    return form.call("T_Click")


def values(body: str, **options: bool) -> dict[str, tuple[str, object]]:
    return {k: (v.type, v.value) for k, v in snippet(body, **options).items()}


# --------------------------------------------------------------------------- VB6 rules


def test_dim_list_types_only_the_last_name():
    out = values("Dim a, b, c As Single\na = 0.1\nb = 0.1\nc = 0.1")
    assert out["a"] == ("Double", 0.1) and out["b"] == ("Double", 0.1)  # Variants
    assert out["c"] == ("Single", 0.10000000149011612)
    naive = values("Dim a, b, c As Single\na = 0.1", dim_types_all=True)
    assert naive["a"] == ("Single", 0.10000000149011612) and naive["b"] == ("Single", 0.0)


def test_dim_variant_starts_empty_and_typed_starts_zero():
    out = values("Dim a, d As Double\nx = a\ny = d")
    assert out["x"] == ("Empty", None) and out["y"] == ("Double", 0.0)


def test_as_double_keeps_float64():
    assert values("Dim d As Double\nd = 16777217.1")["d"] == ("Double", 16777217.1)


def test_single_rounds_to_float32_at_every_assignment():
    out = values("Dim s As Single\ns = 16777217\nt = s + 1\ns = s + 1")
    assert out["t"] == ("Single", 16777216.0)  # Single + Integer stays Single (float32)
    assert out["s"] == ("Single", 16777216.0)
    assert values("Dim s As Single\ns = 1 / 3")["s"][1] == 0.3333333432674408


def test_integer_is_16_bit_and_rounds_half_to_even():
    assert [values(f"Dim k As Integer\nk = {x}")["k"][1] for x in (2.5, 3.5, -2.5, 0.5)] == [
        2,
        4,
        -2,
        0,
    ]
    with pytest.raises(vb6.VB6Error, match="Overflow") as err:
        snippet("Dim k As Integer\nk = 32768")
    assert err.value.number == 6


def test_typed_integer_overflow_raises_but_variant_integer_promotes():
    with pytest.raises(vb6.VB6Error) as err:
        snippet("Dim k As Integer\nk = 200\nk = k * 200")
    assert err.value.number == 6
    out = values("a = 228\nb = a * a\nc = 2 * a * a")  # the listing's a2 * a2, 2 * a2 * a3
    assert out["a"] == ("Integer", 228)
    assert out["b"] == ("Long", 51984) and out["c"] == ("Long", 103968)


def test_division_of_integers_is_single_per_the_vb6_reference():
    out = values("x = 3 / 100\ny = 3 / 100.0")
    assert out["x"] == ("Single", 0.029999999329447746)  # VB6 reference, '/ Operator'
    assert out["y"] == ("Double", 0.03)


def test_variant_string_arithmetic():
    out = values('a = "56.828"\nb = "56.31"\nd = a + (b - a)\ne = a + b\nf = b - a')
    assert out["f"] == ("Double", 56.31 - 56.828)  # String - String: both to Double
    assert out["d"] == ("Double", 56.31)  # String Variant + Double Variant: add
    assert out["e"] == ("String", "56.82856.31")  # String + String: concatenate


def test_empty_string_in_arithmetic_is_a_type_mismatch():
    with pytest.raises(vb6.VB6Error) as err:
        snippet('a = ""\nb = "1"\nd = b - a')
    assert err.value.number == 13


def test_val_reads_the_leading_number_ignoring_blanks():
    out = values('x = Val("  12.5abc")\ny = Val("1 2")\nz = Val("")\nw = Val("-66.006")')
    assert out == {
        "x": ("Double", 12.5),
        "y": ("Double", 12.0),
        "z": ("Double", 0.0),
        "w": ("Double", -66.006),
    }
    assert vb6.vb_val("1e2x") == 100.0 and vb6.vb_val("&H10") == 16.0


def test_atn_takes_one_argument_in_radians():
    out = values("x = Atn(1) * 4\ny = Atn(-1 / -1)")
    assert out["x"] == ("Double", math.pi)
    assert out["y"] == ("Double", math.pi / 4)  # not atan2(-1, -1) = -3 pi / 4
    with pytest.raises(vb6.VB6SyntaxError, match="one argument"):
        snippet("x = Atn(1, 2)")


def test_sin_and_cos_take_radians():
    out = values("y = Sin(90)\nz = Cos(180)")
    assert out["y"] == ("Double", math.sin(90.0))  # 0.894, not 1
    assert out["z"] == ("Double", math.cos(180.0))
    assert values("y = Sin(90)", trig_degrees=True)["y"] == ("Double", 1.0)  # counterfactual


def test_sqr_of_a_negative_number_raises():
    assert values("x = Sqr(4)")["x"] == ("Double", 2.0)
    with pytest.raises(vb6.VB6Error) as err:
        snippet("x = Sqr(-1)")
    assert err.value.number == 5


def test_abs_fix_int_keep_the_argument_type():
    out = values("x = Fix(-2.5)\ny = Int(-2.5)\nz = Abs(-3)\nw = Abs(-2.5)")
    assert out == {
        "x": ("Double", -2.0),
        "y": ("Double", -3.0),
        "z": ("Integer", 3),
        "w": ("Double", 2.5),
    }


def test_format_hash_style():
    cases = {
        56.30992626496152: "56.31",  # trailing zeros dropped (Table 5-4's 56.31)
        -9.074462565022452: "-9.074",
        0.5: ".5",  # no leading zero with '#'
        0.0: ".",
        1234.56789: "1234.568",
        0.0625: ".063",  # half away from zero (0.0625 is exact in binary)
    }
    for x, text in cases.items():
        assert vb6.vb_format(x, "####.###") == text, x
    assert vb6.vb_format(2.5, "0") == "3" and vb6.vb_format(0.5, "0.00") == "0.50"
    with pytest.raises(ValueError, match="outside the modelled subset"):
        vb6.vb_format(1.0, "$#,##0.00")


def test_division_by_zero_raises():
    with pytest.raises(vb6.VB6Error) as err:
        snippet("x = 1 / 0")
    assert err.value.number == 11
    with pytest.raises(vb6.VB6Error) as err:
        snippet("x = 0 / 0")
    assert err.value.number == 6


def test_greek_identifiers_are_names_and_case_insensitive():
    out = values("θ1 = 5\nΘ2 = θ1 * 2\nα0 = Θ1 + 1")
    assert out["θ1"] == ("Integer", 5) and out["Θ2"] == ("Integer", 10)
    assert out["α0"] == ("Integer", 6)


def test_for_loops_single_counter_and_fractional_step():
    out = values("Dim i As Single\nn = 0\nFor i = 1 To 10\nn = n + 1\nNext i")
    assert out["n"] == ("Integer", 10) and out["i"] == ("Single", 11.0)
    out = values("n = 0\nFor X = 0 To 10 Step 0.001\nn = n + 1\nNext")
    assert out["n"] == ("Integer", 10001)  # the listing's drawing loop
    assert out["X"][1] == pytest.approx(10.001, abs=1e-9)


def test_command_button_default_property_is_value_not_enabled():
    out = values(
        "Command3.Enabled = True\nCommand3 = False\nx = Command3.Enabled\ny = Command3.Value"
    )
    assert out["x"] == ("Boolean", True) and out["y"] == ("Boolean", False)


def test_textbox_text_is_a_string_and_dim_is_hoisted():
    form = vb6.VB6Form("Private Sub T_Click()\nx = Text1.Text\nDim y As Double\ny = x\nEnd Sub\n")
    form.set_text({"Text1": "1.5"})
    out = form.call("T_Click")
    assert (out["x"].type, out["y"].type, out["y"].value) == ("String", "Double", 1.5)
    with pytest.raises(ValueError, match="not a TextBox"):
        form.set_text({"Command1": "x"})
    with pytest.raises(ValueError, match="no procedure"):
        form.call("Command9_Click")


def test_unsupported_syntax_is_refused_naming_the_line():
    with pytest.raises(vb6.VB6SyntaxError, match="line 2"):
        vb6.VB6Form("Private Sub T_Click()\nSelect Case x\nEnd Sub\n")
    with pytest.raises(vb6.VB6SyntaxError, match="not modelled"):
        snippet("x = MsgBox(1)")


# --------------------------------------------------------------------------- the listing

TABLE53 = g.TABLE5_3["rows"]
INPUTS = {f"Text{i + 1}": str(v) for i, v in enumerate(TABLE53["start"] + TABLE53["end"])}
PRINTED_CELLS = {  # Table 5-4 as assigned in gr1_thesis.TABLE5_4, by output TextBox
    **dict(
        zip(
            ("Text13", "Text14", "Text15", "Text16", "Text17"),
            g.TABLE5_4["rows"]["start"],
            strict=True,
        )
    ),
    **dict(
        zip(
            ("Text18", "Text19", "Text20", "Text21", "Text22"),
            g.TABLE5_4["rows"]["end"],
            strict=True,
        )
    ),
}


@pytest.fixture(scope="module")
def as_printed():
    return gl.run_command1(INPUTS)


def test_the_printed_listing_does_not_compile():
    with pytest.raises(vb6.VB6SyntaxError, match=r"line 46: expected \) \(near 'Cos'\)"):
        vb6.VB6Form(gl.listing(repaired=False))
    assert len(gl.LISTING_REPAIRS) == 1


@pytest.mark.parametrize("box", sorted(PRINTED_CELLS, key=lambda s: int(s[4:])))
def test_listing_reproduces_every_table5_4_cell(as_printed, box):
    assert as_printed["text"][box] == vb6.vb_format(PRINTED_CELLS[box], "####.###")


def test_listing_values_before_formatting(as_printed):
    loc = {k: v.value for k, v in as_printed["locals"].items()}
    measured = {
        "θ1": 56.82816535671563,
        "θ2": -66.00632789543378,
        "θ3": 73.2819911928754,
        "θ4": -83.8607691934377,
        "θ5": -9.074462565022452,
        "θ234": -76.5851058959961,
        "c3": 0.28766142662141725,
        "θf1": 56.30992626496152,
        "θf2": 80.92187301792202,
        "θf3": -45.24409542052774,
        "θf4": -52.73828441807299,
        "θf5": -24.68262697105649,
        "θf234": -17.06050682067871,
        "cf3": -0.7040878465804895,
    }
    for name, value in measured.items():
        assert loc[name] == pytest.approx(value, abs=1e-9), name
    types = {k: v.type for k, v in as_printed["locals"].items()}
    assert types["θ234"] == types["γ0"] == types["θf234"] == "Single"
    assert types["θ1"] == types["α0"] == types["Px0"] == "Double"  # Variants holding Double
    assert types["c3"] == "Double"


def test_table5_4_depends_on_the_exact_vb_types_and_pi():
    """Counterfactual readings reproduce fewer printed cells (measured): the print is a
    fingerprint of Single θ234, Variant θ1..θ5, PI = 3.141593 and degrees into Sin/Cos."""

    def matches(source: str, **options: bool) -> int:
        text = vb6.run(source, "Command1_Click", INPUTS, **options)["text"]
        return sum(text[b] == vb6.vb_format(v, "####.###") for b, v in PRINTED_CELLS.items())

    src = gl.listing()
    assert matches(src) == 10
    assert matches(src, dim_types_all=True) == 7
    assert matches(src.replace("As Single", "As Double")) == 8
    assert matches(src.replace("PI = 3.141593", "PI = 3.14159265358979")) == 3
    assert matches(src, trig_degrees=True) == 2  # only θ1 and θf1 survive


def test_end_pose_ignores_its_own_orientation(as_printed):
    other = dict(INPUTS, Text10="-70", Text11="10", Text12="5")
    out = gl.run_command1(other)
    ends = ("Text18", "Text19", "Text20", "Text21", "Text22")
    assert [out["text"][b] for b in ends] == [as_printed["text"][b] for b in ends]
    assert "α1" in out["locals"] and out["locals"]["α1"].value == -70.0


def test_gui_check_uses_the_default_property(as_printed):
    assert as_printed["controls"]["Command3"]["props"]["Enabled"].value is True
    far = dict(INPUTS, Text7="1100", Text8="0")  # 1006 mm from the start, horizontally
    out = gl.run_command1(far)
    props = out["controls"]["Command3"]["props"]
    assert props["Enabled"].value is True  # not greyed: 'Command3 = False' sets Value
    assert ("Command3", "Value", False) in out["writes"]
    high = dict(INPUTS, Text9="900")  # |dz| = 650 > 600
    assert gl.run_command1(high)["controls"]["Command3"]["props"]["Enabled"].value is False


def test_unreachable_target_passes_the_check_and_still_gives_numbers():
    """(600, 10, 0) mm is 600.1 mm from the shoulder, beyond 228 + 228 + 73 = 529 mm; the
    check compares start with end only, and degrees in Sin/Cos keep c3 inside [-1, 1]."""
    far = dict(INPUTS, Text1="600", Text2="10", Text3="0", Text7="600", Text8="10", Text9="0")
    out = gl.run_command1(far)
    assert out["controls"]["Command3"]["props"]["Enabled"].value is True
    assert out["locals"]["c3"].value == pytest.approx(0.7116641922908243, abs=1e-12)
    assert [out["text"][f"Text{i}"] for i in range(13, 18)] == [
        ".955",
        "-24.756",
        "44.63",
        "-4.611",
        "13.485",
    ]
    # and where |c3| > 1, Sqr(Abs(1 - c3 * c3)) hides it: a pose 2 m away is "solved"
    out = gl.run_command1(dict(INPUTS, Text7="2000", Text8="0", Text9="0"))
    assert out["locals"]["cf3"].value == pytest.approx(39.34130266121716, abs=1e-9)
    assert out["text"]["Text20"] == "44.991"


def test_zero_angle_prints_a_dot_and_breaks_the_trajectory_button():
    """Format(0, "####.###") is "." ; Command3_Click then computes b - a with b = "."."""
    out = gl.run_command1(dict(INPUTS, Text7="2000", Text8="0", Text9="0"))
    assert out["text"]["Text18"] == "."  # θf1 = Atn(0 / 2000) = 0
    with pytest.raises(vb6.VB6Error) as err:
        vb6.run(gl.listing(), "Command3_Click", form=out["form"])
    assert err.value.number == 13


def test_px_zero_raises_division_by_zero():
    with pytest.raises(vb6.VB6Error) as err:
        gl.run_command1(dict(INPUTS, Text1="0"))
    assert err.value.number == 11
    with pytest.raises(vb6.VB6Error) as err:  # empty form: Val("") / Val("") = 0 / 0
        gl.run_command1({})
    assert err.value.number == 6


def _fk_mm(theta_deg, a2=228.0, a3=228.0, a4=73.0):
    """Position of the planar chain the listing's c3 assumes (no base height: assumed)."""
    t1, t2, t3, t4, _ = (math.radians(x) for x in theta_deg)
    r = a2 * math.cos(t2) + a3 * math.cos(t2 + t3) + a4 * math.cos(t2 + t3 + t4)
    z = a2 * math.sin(t2) + a3 * math.sin(t2 + t3) + a4 * math.sin(t2 + t3 + t4)
    return (r * math.cos(t1), r * math.sin(t1), z)


def test_printed_joint_values_miss_the_table5_3_positions():
    """Table 5-4 (= the listing's output) put through the chain lands far from Table 5-3."""
    misses = {}
    for label in ("start", "end"):
        p = _fk_mm(g.TABLE5_4["rows"][label])
        misses[label] = math.dist(p, TABLE53[label][:3])
    assert misses["start"] == pytest.approx(503.995, abs=1e-3)
    assert misses["end"] == pytest.approx(173.290, abs=1e-3)


def test_command3_trajectory_after_command1(as_printed):
    out = vb6.run(gl.listing(), "Command3_Click", form=as_printed["form"])
    loc = out["locals"]
    # d = a + 3(b - a) - 2(b - a) should equal b; 3 / (c * c) is a Single, so it misses
    assert out["module"]["d"].value == pytest.approx(-24.68299747055955, abs=1e-12)
    assert out["module"]["d"].value != -24.683
    assert loc["m1"].type == "String" and loc["n5"].type == "Double"  # only n5 is typed
    psets = [e for e in out["controls"]["Picture2"]["log"] if e[0] == "pset"]
    assert len(psets) == 10001
    (x0, y0), (x1, y1) = psets[0][1], psets[-1][1]
    assert (x0, y0) == (0, pytest.approx(-66.006))
    assert x1 == pytest.approx(10.0, abs=1e-12)  # 10000 steps of 0.001 sum to 9.9999999999999
    assert y1 == pytest.approx(80.92197619029878, abs=1e-12)  # Single 3/100, 2/1000: 2.4e-5 short


def test_command4_clears_every_textbox(as_printed):
    out = vb6.run(gl.listing(), "Command4_Click", form=as_printed["form"])
    assert set(out["text"].values()) == {""} and len(out["text"]) == 22

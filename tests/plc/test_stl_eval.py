"""The minimal S7-200 STL reader/evaluator used by the audit (analysis.plc.stl_eval)."""

import struct

import numpy as np
import pytest

from analysis.papers import grabber as paper
from analysis.plc import stl_eval as stl


def test_parse_call_with_and_without_comma():
    a = stl.parse_stl("CALL ARCTAN, VD12, VD12")[0]
    b = stl.parse_stl("CALL ARCTAN VD12, VD12")[0]
    assert a.op == b.op == "CALL ARCTAN" and a.args == b.args == ("VD12", "VD12")


def test_movd_stores_bits_and_movr_converts():
    """S7-200 System Manual (MOVD, MOVR): MOVD 100 is 16#00000064, a denormal as REAL;
    MOVR 100.0 is 100.0."""
    m = stl.evaluate(stl.parse_stl("MOVD 100, VD0\nMOVR 100.0, VD4"))
    assert m["VD0"] == 0x64
    assert stl.real(m, "VD0") == struct.unpack(">f", bytes([0, 0, 0, 0x64]))[0]
    assert 1e-43 < stl.real(m, "VD0") < 2e-43
    assert stl.real(m, "VD4") == 100.0


@pytest.mark.parametrize(("op", "expected"), [("+R", 7.0), ("-R", 3.0), ("*R", 10.0), ("/R", 2.5)])
def test_in_place_arithmetic(op, expected):
    """S7-200 System Manual (math instructions): 'op IN1, OUT' computes OUT := OUT op IN1."""
    m = stl.evaluate(stl.parse_stl(f"{op} VD4, VD0"), stl.real_memory(VD0=5.0, VD4=2.0))
    assert stl.real(m, "VD0") == expected


def test_round_halves_away_and_float32():
    m = stl.evaluate(
        stl.parse_stl("ROUND VD0, VD4\nROUND VD8, VD12"), stl.real_memory(VD0=2.5, VD8=-2.5)
    )
    assert (stl.dint(m, "VD4"), stl.dint(m, "VD12")) == (3, -3)
    m = stl.evaluate(stl.parse_stl("MOVR 0.1, VD0"))
    assert stl.real(m, "VD0") == float(np.float32(0.1))


def test_invalid_operand_found_and_refused():
    prog = stl.parse_stl(paper.FIGURE_STL[6])
    bad = {a for _, a in stl.invalid_operands(prog)}
    assert bad == {"VDD0"}
    with pytest.raises(ValueError, match="VDD0"):
        stl.evaluate(prog)


def test_defs_uses():
    w, r = stl.defs_uses(stl.parse_stl("-R VD48, VD118")[0])
    assert w == {"VD118"} and r == {"VD48", "VD118"}
    w, r = stl.defs_uses(stl.parse_stl("MOVR 310.0, VD68")[0])
    assert w == {"VD68"} and r == set()


def test_figure4_as_printed_gives_9_pulses_for_row1():
    """Figure 4 with REAL inputs (100, 100, 600): ARCTAN in radians scaled as degrees."""
    m = stl.evaluate(
        stl.parse_stl(paper.FIGURE_STL[4]), stl.real_memory(VD0=100.0, VD4=100.0, VD8=600.0)
    )
    assert stl.dint(m, "VD16") == round(np.pi / 4 / 360 * 4000) == 9

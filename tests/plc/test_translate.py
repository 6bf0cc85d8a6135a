"""analysis.plc.translate (S7-200 STL -> AWL for awlsim): issue 22 item 4.

Each test runs a small S7-200 program translated on awlsim and checks what the S7-200
System Manual says it leaves (the evaluator agrees: tests/plc/test_stl_awlsim_agreement.py).
"""

from __future__ import annotations

import math

import pytest

from analysis.plc.memmap import default_map
from analysis.plc.stl_eval import StlError
from analysis.plc.translate import Layout, translate_s7200

pytest.importorskip("awlsim")


def _ob1(*lines: str) -> str:
    return (
        "ORGANIZATION_BLOCK MAIN:OB1\nBEGIN\nNetwork 1\n"
        + "\n".join(lines)
        + ("\nEND_ORGANIZATION_BLOCK\n")
    )


def _awl(text: str, **reals):
    from analysis.plc.runner import AwlRunner

    tr = translate_s7200(text)
    r = AwlRunner(tr.awl, default_map("s7-200"), first_scan=False)
    for addr, v in reals.items():
        r.write_real(int(addr[2:]), v)
    r.cycle()
    return r, tr


@pytest.mark.parametrize("x", [math.nan, math.inf, -math.inf, 3.0e9, -3.0e9])
def test_round_and_trunc_of_an_invalid_value_leave_the_output(x):
    """S7-200 System Manual p.115: SM1.1 and the output is not affected. (The translation
    wrote the REAL's bits: ROUND(NaN) = 2143289344.)"""
    r, _tr = _awl(
        _ob1(
            "LD SM0.0",
            "MOVD 77, VD4",
            "MOVD 78, VD8",
            "ROUND VD0, VD4",
            "TRUNC VD0, VD8",
            "LD SM1.1",
            "= V12.0",
        ),
        VD0=x,
    )
    assert (r.read_dint(4), r.read_dint(8)) == (77, 78)
    assert r.read_bit(12, 0)


def test_a_zero_resolution_typed_on_the_hmi_gives_no_preset():
    """A counter preset computed as ROUND(distance / resolution) with the resolution 0.0:
    the division sets SM1.3 and ENO = 0, so with AENO the ROUND does not run and the old
    preset stays (the translation gave 2139095041, ROUND of +inf as bits)."""
    text = _ob1(
        "LD SM0.0", "MOVR VD0, VD8", "/R VD4, VD8", "AENO", "ROUND VD8, VD12", "LD SM1.3", "= V16.0"
    )
    from analysis.plc.runner import AwlRunner

    r = AwlRunner(translate_s7200(text).awl, default_map("s7-200"), first_scan=False)
    r.write_real(0, 518.0)
    r.write_real(4, 0.0)
    r.write_dint(12, 4)  # the preset from before
    r.cycle()
    assert r.read_dint(12) == 4 and r.read_bit(16, 0)
    r.write_real(4, 0.14)
    r.cycle()
    assert r.read_dint(12) == 3700  # 518 / 0.14 = 3700.0000, rounded


def test_aeno_reads_the_last_box_not_a_stale_overflow():
    """After a failed SQRT, a good MOVR sets ENO = 1 again: AENO keeps the power flow (the
    translation ANDed awlsim's OV, still set by the SQRT, and gave 0)."""
    r, _ = _awl(
        _ob1(
            "LD SM0.0",
            "SQRT VD0, VD4",
            "MOVR 1.0, VD8",
            "AENO",
            "= V12.0",
            "LD SM0.0",
            "SQRT VD0, VD4",
            "AENO",
            "= V12.1",
        ),
        VD0=-1.0,
    )
    assert r.read_bit(12, 0) and not r.read_bit(12, 1)


def test_v_memory_is_translated_whole_without_aliasing():
    """VD1600 was AC0; from VB2048 up a translation failed at run time. Now V n is M n up to
    the CPU's last V byte, the other areas above it."""
    text = _ob1(
        "LD SM0.0", "MOVD 11, AC0", "MOVD 22, VD1600", "MOVD AC0, VD4000", "MOVD VD1600, VD8188"
    )
    r, tr = _awl(text)
    assert (r.read_dint(1600), r.read_dint(4000), r.read_dint(8188)) == (22, 11, 22)
    assert tr.layout == Layout.for_cpu("CPU 224") and tr.layout.ac >= 8192
    with pytest.raises(StlError, match=r"line 5 .*VD8192 is beyond the CPU 224's V memory"):
        translate_s7200(_ob1("LD SM0.0", "MOVD 1, VD8192"))
    big = translate_s7200(_ob1("LD SM0.0", "MOVD 1, VD10236"), cpu="CPU 226")
    assert "MD 10236" in big.awl and big.layout.sm == 10240


def test_real_literals_into_real_moves_or_refused_with_the_line():
    """MOVR 100, VD0 stored the bit pattern 16#64 (1.4E-43): the paper's MOVD bug, back."""
    with pytest.raises(StlError, match=r"line 5 .*MOVR 100, VD0.*integer constant"):
        translate_s7200(_ob1("LD SM0.0", "MOVR 100, VD0"))
    r, _ = _awl(_ob1("LD SM0.0", "MOVR 100.0, VD0", "MOVR -2.5E-3, VD4"))
    assert (r.read_real(0), r.read_real(4)) == (100.0, pytest.approx(-2.5e-3))


@pytest.mark.parametrize(
    ("line", "why"),
    [
        ("FOR VW0, 1, 10", "FOR/NEXT loops are not translated"),
        ("MOVD &VB100, AC1", "pointers are not translated"),
        ("SLW VW0, 2", "shifts and rotates are not translated"),
        ("LD SM0.5", "SM0 clock"),
        ("MOVR LD0, VD0", "direct L addresses"),
    ],
)
def test_what_is_not_translated_is_refused_with_the_line(line, why):
    text = _ob1("LD SM0.0", line, "NEXT" if line.startswith("FOR") else "NOP 0")
    with pytest.raises(StlError, match=rf"line 5 .*{why}"):
        translate_s7200(text)

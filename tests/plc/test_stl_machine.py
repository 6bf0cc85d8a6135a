"""The S7-200 evaluator (analysis.plc.stl_eval.S7200) on the semantics the System Manual
states, on programs written as a Micro/WIN programmer writes them, and on the mistakes such
a programmer makes (refused with the line, the block and the network).

Expected values come from the manual's rules (each test names its rule), from arithmetic
done here by hand, or from awlsim running the project's AWL translation of the same text.
"""

from __future__ import annotations

import math
import struct

import pytest

from analysis.plc.stl_eval import S7200, StlError, instruction_table, load_program


def _ob1(*lines: str, extra: str = "") -> str:
    body = "\r\n".join(lines)
    return (
        "ORGANIZATION_BLOCK MAIN:OB1\r\nTITLE=test\r\nBEGIN\r\nNetwork 1\r\n"
        f"{body}\r\nEND_ORGANIZATION_BLOCK\r\n{extra}"
    )


def _run(text: str, scans: int = 1, **values) -> S7200:
    cpu = S7200(load_program(text))
    for addr, v in values.items():
        typ = "REAL" if isinstance(v, float) else "BOOL" if "." in addr else "DINT"
        cpu.write(typ, addr, v)
    cpu.scan(scans)
    return cpu


# ---------------------------------------------------------------------------------------
# the reproductions (issue 22: "silently mis-evaluates")
def test_power_flow_off_skips_a_box():
    """LD V90.0 (0) then MOVR 9.0, VD92: a box runs only with power flow (the top of the
    stack); ENO of a skipped box is 0."""
    cpu = _run(_ob1("LD     V90.0", "MOVR   9.0, VD92", "AENO", "=      V91.0"))
    assert cpu.read("REAL", "VD92") == 0.0 and not cpu.read("BOOL", "V91.0")
    cpu = _run(_ob1("LD     V90.0", "MOVR   9.0, VD92"), **{"V90.0": True})
    assert cpu.read("REAL", "VD92") == 9.0


def test_round_of_a_value_beyond_dint_leaves_the_output():
    """S7-200 System Manual p.115: not a valid REAL or too large -> SM1.1, output not
    affected, ENO = 0 (so AENO turns the power flow off)."""
    cpu = _run(
        _ob1(
            "LD     SM0.0", "ROUND  VD0, VD4", "AENO", "=      V8.0", "LD     SM1.1", "=      V8.1"
        ),
        VD0=-3.0e9,
        VD4=1234,
    )
    assert cpu.read("DINT", "VD4") == 1234  # the old evaluator wrote 1294967296
    assert not cpu.read("BOOL", "V8.0") and cpu.read("BOOL", "V8.1")
    for x in (math.nan, math.inf, -math.inf, 2147483648.0):
        cpu = _run(_ob1("LD SM0.0", "ROUND VD0, VD4", "TRUNC VD0, VD8"), VD0=x, VD4=7, VD8=8)
        assert (cpu.read("DINT", "VD4"), cpu.read("DINT", "VD8")) == (7, 8), x


@pytest.mark.parametrize(
    ("x", "rounded"),
    [(2.5, 3), (-2.5, -3), (0.49999997, 0), (-0.5, -1), (1555.5, 1556), (2.4999998, 2)],
)
def test_round_rounds_halves_up_in_magnitude(x, rounded):
    """S7-200 System Manual p.115: a fraction of 0.5 or more rounds up (away from zero for
    negative values: assumed, the manual gives no negative example)."""
    assert _run(_ob1("LD SM0.0", "ROUND VD0, VD4"), VD0=x).read("DINT", "VD4") == rounded


def test_division_by_zero_sets_sm13_and_leaves_the_operand():
    """S7-200 System Manual p.154: /R by 0.0 sets SM1.3 and changes nothing else."""
    cpu = _run(
        _ob1("LD SM0.0", "MOVR 5.0, VD0", "/R 0.0, VD0", "AENO", "= V4.0", "LD SM1.3", "= V4.1")
    )
    assert cpu.read("REAL", "VD0") == 5.0  # the old evaluator gave +inf
    assert not cpu.read("BOOL", "V4.0") and cpu.read("BOOL", "V4.1")


def test_real_operands_need_real_widths_and_constants():
    for text, why in (
        ("MOVR   1.0, VW0", "VW0 is a word"),
        ("MOVR   100, VD0", "integer constant"),
        ("*R     4000, VD16", "integer constant"),
        ("MOVD   100.0, VD0", "REAL constant"),
        ("+I     VD0, VW2", "VD0 is a double word"),
    ):
        with pytest.raises(StlError, match=why) as exc:
            load_program(_ob1("LD SM0.0", text))
        assert exc.value.line == 6 and exc.value.block == "MAIN (OB1)" and exc.value.network == 1


def test_operand_errors_name_the_line_instruction_and_network():
    text = _ob1("LD     SM0.0", "Network 2 // scale", "LD     SM0.0", "MOVR   9.0 VD92")
    with pytest.raises(StlError) as exc:
        load_program(text)
    msg = str(exc.value)
    assert exc.value.line == 8 and exc.value.network == 2
    assert "line 8" in msg and "network 2" in msg and "MOVR   9.0 VD92" in msg
    assert "comma" in msg  # the old evaluator raised a bare IndexError


# ---------------------------------------------------------------------------------------
# semantics by rule
def test_real_errors_leave_the_output_and_set_sm11():
    """SQRT of a negative, LN of 0, NaN or infinite operands: SM1.1, output unaltered
    (S2M p.157, p.154); a good MOVR after a failed SQRT gives ENO = 1 again (AENO reads the
    last box's ENO)."""
    cpu = _run(
        _ob1(
            "LD SM0.0",
            "SQRT VD0, VD4",
            "LD SM1.1",
            "= V20.0",
            "LD SM0.0",
            "LN VD8, VD12",
            "+R VD16, VD24",
            "MOVR VD0, VD28",
            "AENO",
            "= V20.1",
        ),
        VD0=-1.0,
        VD4=3.0,
        VD8=0.0,
        VD12=4.0,
        VD16=math.nan,
        VD24=5.0,
    )
    assert [cpu.read("REAL", a) for a in ("VD4", "VD12", "VD24")] == [3.0, 4.0, 5.0]
    assert cpu.read("BOOL", "V20.0") and cpu.read("BOOL", "V20.1")


def test_real_overflow_leaves_the_output():
    cpu = _run(_ob1("LD SM0.0", "*R 10.0, VD0", "LD SM1.1", "= V4.0"), VD0=3.0e38)
    assert cpu.read("REAL", "VD0") == pytest.approx(3.0e38) and cpu.read("BOOL", "V4.0")
    assert cpu.events["overflow"] == 1


def test_integer_math_overflow_and_status_bits():
    """+I/+D overflow: SM1.1, output not written; *D, /D; SM1.0 zero, SM1.2 negative
    (MWH s7-28hir.htm, s7-29u0i.htm)."""
    cpu = S7200(load_program(_ob1("LD SM0.0", "+I 1, VW0", "LD SM1.1", "= V10.0")))
    cpu.write("INT", "VW0", 32767)
    cpu.scan()
    assert cpu.read("INT", "VW0") == 32767 and cpu.read("BOOL", "V10.0")
    cpu = _run(
        _ob1(
            "LD SM0.0",
            "-D 5, VD4",
            "LD SM1.2",
            "= V10.1",
            "LD SM0.0",
            "/D 0, VD4",
            "LD SM1.3",
            "= V10.2",
            "LD SM0.0",
            "MOVD -7, VD12",
            "/D 2, VD12",
        ),
        VD4=2,
    )
    assert cpu.read("DINT", "VD4") == -3 and cpu.read("BOOL", "V10.1")
    assert cpu.read("BOOL", "V10.2") and cpu.read("DINT", "VD12") == -3  # towards zero


def test_mul_and_div_use_the_low_word_of_out():
    """MUL: 16 x 16 -> 32 bits; DIV: remainder in the high word, quotient in the low word
    (manualshelf p.252)."""
    cpu = _run(_ob1("LD SM0.0", "MOVD 300, VD0", "MUL 1000, VD0", "MOVD 17, VD4", "DIV 5, VD4"))
    assert cpu.read("DINT", "VD0") == 300_000
    assert cpu.read("INT", "VW4") == 2 and cpu.read("INT", "VW6") == 3


def test_logic_stack():
    """LPS/LRD/LPP branch a rung; ALD/OLD combine; LDS copies a level (manualshelf
    p.370)."""
    text = _ob1(
        "LD V0.0",
        "LPS",
        "A V0.1",
        "= V1.0",
        "LRD",
        "AN V0.1",
        "= V1.1",
        "LPP",
        "= V1.2",
        "LD V0.2",
        "LD V0.3",
        "O V0.4",
        "ALD",
        "= V1.3",
        "LD V0.2",
        "LD V0.3",
        "OLD",
        "= V1.4",
        "LD V0.0",
        "LD V0.3",
        "LDS 1",
        "= V1.5",
    )
    cpu = _run(text, **{"V0.0": True, "V0.2": True, "V0.4": True})
    got = [cpu.read("BOOL", f"V1.{k}") for k in range(6)]
    assert got == [False, True, True, True, True, True]


def test_first_scan_bit_and_edges():
    """SM0.1 is on in the first scan only; EU gives no edge in the first scan (the state is
    recorded, SMART p.157), then one scan per rising edge."""
    text = _ob1("LD SM0.1", "INCW VW0", "LD V4.0", "EU", "INCW VW2")
    cpu = S7200(load_program(text))
    cpu.write("BOOL", "V4.0", True)
    cpu.scan()
    cpu.scan()
    assert cpu.read("INT", "VW0") == 1 and cpu.read("INT", "VW2") == 0
    cpu.write("BOOL", "V4.0", False)
    cpu.scan()
    cpu.write("BOOL", "V4.0", True)
    cpu.scan(3)
    assert cpu.read("INT", "VW2") == 1


def test_nan_in_a_real_compare_stops_the_cpu_and_says_where():
    """S7-200 System Manual p.96: a NaN in a Compare Real is a fatal error."""
    cpu = _run(
        _ob1("LD SM0.0", "INCW VW8", "LDR< VD0, 1.0", "= V4.0", "LD SM0.0", "INCW VW10"),
        VD0=math.nan,
    )
    assert cpu.fault is not None and cpu.fault.line == 7 and "NaN" in str(cpu.fault)
    assert cpu.read("INT", "VW8") == 1 and cpu.read("INT", "VW10") == 0  # stopped there
    cpu.scan(5)
    assert cpu.read("INT", "VW8") == 1  # and stays in STOP


def test_memory_limits_follow_the_cpu():
    """V memory: VB0-VB8191 on a CPU 224, VB0-VB10239 on a CPU 226; SMB0-SMB29 are
    read-only."""
    with pytest.raises(StlError, match=r"VD8190 is beyond the CPU 224's V memory"):
        load_program(_ob1("LD SM0.0", "MOVD 1, VD8190"))
    cpu = S7200(load_program(_ob1("LD SM0.0", "MOVD 1, VD10236"), cpu="CPU 226"))
    cpu.scan()
    assert cpu.read("DINT", "VD10236") == 1
    with pytest.raises(StlError, match="read-only"):
        load_program(_ob1("LD SM0.0", "R SM0.1, 1"))


def test_constants_symbols_and_accumulators():
    cpu = _run(
        _ob1(
            "LD Always_On:SM0.0",
            "MOVD 16#7F800000, AC0",
            "MOVB 2#101, VB4",
            "MOVW 16#FFFF, VW6",
            "MOVD AC0, VD8",
            "MOVB 16#FF, AC0",
            "MOVD AC0, VD12",
        )
    )
    assert cpu.read("DWORD", "VD8") == 0x7F800000 and cpu.read("BYTE", "VB4") == 5
    assert cpu.read("INT", "VW6") == -1
    assert cpu.read("DWORD", "VD12") == 0x7F8000FF  # a byte written to AC0: its low 8 bits


def test_instruction_table_names_a_source_for_every_instruction():
    rows = instruction_table()
    assert len(rows) > 100 and all(src for _, _, src in rows)
    ops = {r[0] for r in rows}
    for need in (
        "LDR>=",
        "AR<",
        "OR=",
        "JMP",
        "LBL",
        "CALL",
        "MOVB",
        "MOVW",
        "MOVD",
        "MOVR",
        "+I",
        "*D",
        "/R",
        "ROUND",
        "TRUNC",
        "DTR",
        "ITD",
        "SQRT",
        "SIN",
        "COS",
        "LN",
        "EXP",
        "AENO",
        "EU",
        "ED",
        "LPS",
        "ALD",
        "PLS",
    ):
        assert need in ops, need


# ---------------------------------------------------------------------------------------
# programs as an S7-200 programmer writes them (Micro/WIN text form)
CONVEYOR = """ORGANIZATION_BLOCK MAIN:OB1
TITLE=Conveyor: start/stop latch, part counter, box-full lamp
BEGIN
Network 1 // belt latch: Start I0.0, Stop I0.1 (NC), E-stop I0.2 (NC)
LD     I0.0
O      Q0.0
A      I0.1
A      I0.2
=      Q0.0
Network 2 // count parts on the photo eye I0.3 while the belt runs
LD     Q0.0
A      I0.3
EU
INCW   VW10
Network 3 // box full at the preset VW12: lamp Q0.1 on, belt off
LDW>=  VW10, VW12
S      Q0.1, 1
R      Q0.0, 1
Network 4 // box changed (I0.4): count to 0, lamp off
LD     I0.4
MOVW   0, VW10
R      Q0.1, 1
END_ORGANIZATION_BLOCK
"""


class _Both:
    """One program on the evaluator and, translated, on awlsim: every step on both."""

    def __init__(self, text: str) -> None:
        pytest.importorskip("awlsim")
        from analysis.plc.memmap import default_map
        from analysis.plc.runner import AwlRunner
        from analysis.plc.translate import translate_s7200

        self.cpu = S7200(load_program(text))
        self.tr = translate_s7200(text)
        self.awl = AwlRunner(self.tr.awl, default_map("s7-200"), first_scan=False)

    def _byte(self, area: str, n: int) -> int:
        return self.tr.layout.byte(area, n)

    def write(self, typ: str, addr: str, value) -> None:
        self.cpu.write(typ, addr, value)
        area = addr.rstrip("0123456789.").rstrip("BWD")
        rest = addr[len(area) :]
        if typ == "BOOL":
            byte, bit = (int(x) for x in rest.split("."))
            self.awl.write_bit(self._byte(area, byte), bit, value)
        else:
            fmt = {"INT": ">h", "DINT": ">i", "REAL": ">f", "BYTE": ">B"}[typ]
            off = self._byte(area, int(rest.lstrip("BWD")))
            data = struct.pack(fmt, value)
            self.awl.mem[off : off + len(data)] = data

    def scan(self) -> None:
        self.cpu.scan()
        self.awl.cycle()

    def read(self, typ: str, addr: str):
        ours = self.cpu.read(typ, addr)
        area = addr.rstrip("0123456789.").rstrip("BWD")
        rest = addr[len(area) :]
        if typ == "BOOL":
            byte, bit = (int(x) for x in rest.split("."))
            theirs = self.awl.read_bit(self._byte(area, byte), bit)
        else:
            fmt = {"INT": ">h", "DINT": ">i", "REAL": ">f", "BYTE": ">B"}[typ]
            off = self._byte(area, int(rest.lstrip("BWD")))
            theirs = struct.unpack(fmt, bytes(self.awl.mem[off : off + struct.calcsize(fmt)]))[0]
        assert ours == theirs, (addr, ours, theirs)
        return ours


@pytest.mark.slow
def test_a_conveyor_program_on_the_evaluator_and_on_awlsim():
    plc = _Both(CONVEYOR)
    plc.write("INT", "VW12", 3)  # the box takes three parts
    plc.write("BOOL", "I0.1", True)  # Stop and E-stop are normally closed
    plc.write("BOOL", "I0.2", True)
    plc.scan()
    assert not plc.read("BOOL", "Q0.0")
    plc.write("BOOL", "I0.0", True)
    plc.scan()
    plc.write("BOOL", "I0.0", False)
    plc.scan()
    assert plc.read("BOOL", "Q0.0")  # latched
    for _ in range(3):  # three parts pass the eye
        plc.write("BOOL", "I0.3", True)
        plc.scan()
        plc.scan()  # a part stays in front of the eye for two scans: counted once
        plc.write("BOOL", "I0.3", False)
        plc.scan()
    assert plc.read("INT", "VW10") == 3
    assert plc.read("BOOL", "Q0.1") and not plc.read("BOOL", "Q0.0")  # full: lamp, belt off
    plc.write("BOOL", "I0.4", True)
    plc.scan()
    assert plc.read("INT", "VW10") == 0 and not plc.read("BOOL", "Q0.1")


SCALING = """ORGANIZATION_BLOCK MAIN:OB1
TITLE=Tank level and temperature from two raw analog values
BEGIN
Network 1 // raw 0..32000 -> engineering units
LD     SM0.0
CALL   SCALE, VW0, 0.0, 5000.0, VD100, V110.0
CALL   SCALE, VW2, -50.0, 150.0, VD104, V110.1
Network 2 // high level alarm above 4500 mm
LDR>   VD100, 4500.0
=      V110.2
Network 3 // counts for a display, rounded
LD     SM0.0
ROUND  VD104, VD112
END_ORGANIZATION_BLOCK
SUBROUTINE_BLOCK SCALE:SBR0
TITLE=RAW 0..32000 -> LO..HI; ERR and OUT unchanged when RAW is outside
VAR_INPUT
RAW:INT;
LO:REAL;
HI:REAL;
END_VAR
VAR_IN_OUT
OUT:REAL;
END_VAR
VAR_OUTPUT
ERR:BOOL;
END_VAR
VAR
TMP:DINT;
SPAN:REAL;
END_VAR
BEGIN
Network 1 // raw out of range: error, keep the last value
LDW<   #RAW, 0
OW>    #RAW, 32000
=      #ERR
CRET
Network 2 // OUT := LO + RAW / 32000 * (HI - LO)
LD     SM0.0
ITD    #RAW, #TMP
DTR    #TMP, #OUT
/R     32000.0, #OUT
MOVR   #HI, #SPAN
-R     #LO, #SPAN
*R     #SPAN, #OUT
+R     #LO, #OUT
END_SUBROUTINE_BLOCK
"""


@pytest.mark.slow
def test_a_scaling_subroutine_with_parameters_and_locals():
    plc = _Both(SCALING)
    plc.write("INT", "VW0", 29440)  # 4600 mm
    plc.write("INT", "VW2", 8000)  # 0 degC
    plc.scan()
    assert plc.read("REAL", "VD100") == pytest.approx(4600.0)
    assert plc.read("REAL", "VD104") == pytest.approx(0.0, abs=1e-6)
    assert plc.read("BOOL", "V110.2") and not plc.read("BOOL", "V110.0")
    plc.write("INT", "VW2", 20000)  # 75 degC
    plc.write("INT", "VW0", -5)  # a broken wire: the level keeps its last value
    plc.scan()
    assert plc.read("BOOL", "V110.0") and plc.read("REAL", "VD100") == pytest.approx(4600.0)
    assert plc.read("DINT", "VD112") == 75


TABLE_SUM = """ORGANIZATION_BLOCK MAIN:OB1
TITLE=Average of a table of ten INTs (VW200..VW218) with a pointer and FOR/NEXT
BEGIN
Network 1
LD     SM0.0
MOVD   &VB200, AC1
MOVD   0, VD300
FOR    VW310, 1, 10
Network 2
LD     SM0.0
ITD    *AC1, AC2
+D     AC2, VD300
+D     2, AC1
Network 3
NEXT
Network 4
LD     SM0.0
DTR    VD300, VD304
/R     10.0, VD304
END_ORGANIZATION_BLOCK
"""


def test_pointers_and_a_for_loop():
    cpu = S7200(load_program(TABLE_SUM))
    for k in range(10):
        cpu.write("INT", f"VW{200 + 2 * k}", (k + 1) * (-1) ** k * 100)
    cpu.scan()
    assert cpu.read("DINT", "VD300") == sum((k + 1) * (-1) ** k * 100 for k in range(10))
    assert cpu.read("REAL", "VD304") == -50.0 and cpu.read("INT", "VW310") == 11
    from analysis.plc.translate import translate_s7200

    with pytest.raises(StlError, match=r"line 6 .*not translated"):
        translate_s7200(TABLE_SUM)  # awlsim has no counterpart here: refused, with the line


@pytest.mark.parametrize(
    ("body", "line", "why"),
    [
        (["LD SM0.0", "JMP 5"], 6, "no LBL 5"),
        (["LD SM0.0", "CALL SBR3, VD0"], 6, "SBR3 is not defined"),
        (["LD T37", "= Q0.0"], 5, "timers are not modelled"),
        (["LD SM0.0", "COS VDD0, VD180"], 6, "not an S7-200 address"),
        (["LD SM0.0", "+R VD4"], 6, "takes 2 operand"),
        (["LD SM0.0", "CALLARCTAN, VD114,"], 6, "unknown instruction CALLARCTAN"),
        (["LD SM0.0", "DI_R VD0, VD4"], 6, "in STL it is DTR"),
        (["LD SM0.0", "RET"], 6, "CRET"),
        (["LD SM0.0", "MOVB 300, VB0"], 6, "does not fit a byte"),
        (["LD SM0.0", "S V0.0, 0"], 6, "1..255"),
    ],
)
def test_mistakes_are_refused_with_the_line(body, line, why):
    with pytest.raises(StlError, match=why) as exc:
        load_program(_ob1(*body))
    assert exc.value.line == line and f"line {line}" in str(exc.value)


def test_block_structure_errors():
    with pytest.raises(StlError, match="not closed"):
        load_program("ORGANIZATION_BLOCK MAIN:OB1\nBEGIN\nLD SM0.0\n")
    bad = "ORGANIZATION_BLOCK MAIN:OB1\nBEGIN\nEND_ORGANIZATION_BLOCK\nLD SM0.0\n"
    with pytest.raises(StlError, match=r"line 4.*outside a block"):
        load_program(bad)
    sub = "SUBROUTINE_BLOCK S:SBR0\nVAR_INPUT\nX REAL;\nEND_VAR\nBEGIN\nEND_SUBROUTINE_BLOCK\n"
    with pytest.raises(StlError, match=r"line 9.*name:TYPE"):
        load_program(_ob1("LD SM0.0") + sub)
    big = "".join(f"X{k}:REAL;\n" for k in range(17))
    with pytest.raises(StlError, match="68 bytes of L memory"):
        load_program(
            _ob1("LD SM0.0") + f"SUBROUTINE_BLOCK S:SBR0\nVAR\n{big}END_VAR\nBEGIN\n"
            "END_SUBROUTINE_BLOCK\n"
        )


def test_call_passes_by_value_and_nests_eight_deep():
    """CALL copies IN to L memory and OUT back after the return, so IN and OUT may be the
    same address (the paper's CALL ARCCOS, VD48, VD48); a ninth nested level is not made
    (error 0008, ENO = 0; manualshelf p.324)."""
    sbr = """SUBROUTINE_BLOCK DEEP:SBR0
VAR_IN_OUT
N:INT;
END_VAR
VAR_OUTPUT
Y:REAL;
END_VAR
BEGIN
Network 1
LD     SM0.0
INCW   #N
MOVR   2.5, #Y
CALL   DEEP, #N, VD20
END_SUBROUTINE_BLOCK
SUBROUTINE_BLOCK SQ:SBR1
VAR_INPUT
X:REAL;
END_VAR
VAR_OUTPUT
R:REAL;
END_VAR
BEGIN
Network 1
LD     SM0.0
MOVR   #X, #R
*R     #X, #R
END_SUBROUTINE_BLOCK
"""
    cpu = _run(_ob1("LD SM0.0", "CALL DEEP, VW0, VD4", "CALL SQ, VD8, VD8") + sbr, VD8=3.0)
    assert cpu.read("INT", "VW0") == 8  # levels 1..8 each incremented it; the ninth is refused
    assert cpu.events["nesting"] == 1 and cpu.read("REAL", "VD8") == 9.0


def test_the_reference_example_of_the_text_form_runs():
    """The Micro/WIN text form of the team's STL reference notes (section 1.7): OB1 calling a
    subroutine named IK_J1 with REAL IN and OUT parameters."""
    text = """ORGANIZATION_BLOCK MAIN:OB1
TITLE=IK demo
BEGIN
Network 1 // compute joint 1
// comment line
LD     SM0.0
CALL   SBR_0, VD100, VD104, VD200
END_ORGANIZATION_BLOCK
SUBROUTINE_BLOCK IK_J1:SBR0
TITLE=
VAR_INPUT
X:REAL;
Y:REAL;
END_VAR
VAR_OUTPUT
J1:REAL;
END_VAR
BEGIN
Network 1
LD     SM0.0
MOVR   #Y, #J1
/R     #X, #J1
END_SUBROUTINE_BLOCK
"""
    cpu = _run(text, VD100=4.0, VD104=10.0)
    assert cpu.read("REAL", "VD200") == 2.5

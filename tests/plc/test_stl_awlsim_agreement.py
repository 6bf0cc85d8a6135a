"""The S7-200 evaluator against awlsim on the overlapping subset (issue 22 item 3).

Random straight-line S7-200 programs (bit logic with the logic stack and power flow, the
compares, moves, integer and REAL arithmetic, the numeric functions, ROUND/TRUNC/DTR/ITD,
AENO and reads of the SM1 bits) run once on the evaluator and once translated to AWL
(:func:`analysis.plc.translate.translate_s7200`) on awlsim; the V memory they touch, and the
SM1 bits when the program reads them, must be the same byte for byte. Operands include NaN,
infinities, zero divisors and values that overflow INT and DINT, so the error rules (output
unchanged, SM1.1/SM1.3, ENO) are compared too.

Outside the subset, by construction (awlsim 0.77.1, observed): a REAL result
beyond +-3.4E38 from finite operands (awlsim saturates without OV, the CPU sets SM1.1), a
denormal REAL (awlsim stores 0, the CPU's handling is unknown) and SIN/COS/TAN (awlsim
snaps results within 1e-7 of -1, 0, 1). The evaluator counts the first two, and an example
where they occur is discarded (``assume``); the trigonometric functions are checked on the
generated programs instead (test_generated_programs_on_the_evaluator).
"""

from __future__ import annotations

import math
import struct

import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from analysis.plc.memmap import default_map
from analysis.plc.stl_eval import S7200, load_program
from analysis.plc.translate import translate_s7200

pytestmark = pytest.mark.slow  # awlsim: about 3 s for the examples below
pytest.importorskip("awlsim")

REALS = [f"VD{4 * k}" for k in range(8)]  # VD0..VD28
DINTS = [f"VD{32 + 4 * k}" for k in range(4)]  # VD32..VD44
INTS = [f"VW{48 + 2 * k}" for k in range(4)]  # VW48..VW54
BYTES = ["VB56", "VB57"]
BITS = [f"V60.{k}" for k in range(8)]
V_BYTES = 64

_real_values = st.one_of(
    st.sampled_from([0.0, -0.0, 1.0, -1.0, 0.5, -2.5, 2.5, 3.0e9, -3.0e9, 1e-3]),
    st.sampled_from([math.nan, math.inf, -math.inf]),
    st.floats(-1e4, 1e4, width=32, allow_subnormal=False),
)
_int_values = st.one_of(
    st.sampled_from([0, 1, -1, 32767, -32768, 2**31 - 1, -(2**31)]),
    st.integers(-(2**31), 2**31 - 1),
)
_short_values = st.one_of(st.sampled_from([0, 1, -1, 32767, -32768]), st.integers(-32768, 32767))


def _real_const(x: float) -> str:
    return repr(float(struct.unpack(">f", struct.pack(">f", x))[0]))


_real_opnd = st.one_of(
    st.sampled_from(REALS),
    st.floats(-100, 100, width=32, allow_subnormal=False)
    .filter(lambda x: x == 0 or abs(x) > 1e-6)
    .map(_real_const),
)
_dint_opnd = st.one_of(st.sampled_from(DINTS), st.integers(-1000, 1000).map(str))
_int_opnd = st.one_of(st.sampled_from(INTS), st.integers(-300, 300).map(str))


@st.composite
def _statement(draw) -> list[str]:
    kind = draw(
        st.sampled_from(
            [
                "bit",
                "bit",
                "stack",
                "cmp",
                "mov",
                "real",
                "real",
                "func",
                "dint",
                "int",
                "conv",
                "aeno",
                "sm1",
                "incdec",
                "logic",
            ]
        )
    )
    bit = draw(st.sampled_from(BITS))
    if kind == "bit":
        contact = draw(st.sampled_from(["LD", "LDN", "A", "AN", "O", "ON"]))
        coil = draw(st.sampled_from(["=", "=", "S", "R"]))
        target = draw(st.sampled_from(BITS))
        return [f"{contact} {bit}", f"{coil} {target}" + ("" if coil == "=" else ", 1")]
    if kind == "stack":
        return [
            draw(st.sampled_from(["LPS", "LRD", "LPP", "ALD", "OLD", "NOT", "LDS 1", "LD SM0.0"]))
        ]
    if kind == "cmp":
        t = draw(st.sampled_from(["R", "D", "W", "B"]))
        a, b = {
            "R": (draw(st.sampled_from(REALS)), draw(_real_opnd)),
            "D": (draw(st.sampled_from(DINTS)), draw(_dint_opnd)),
            "W": (draw(st.sampled_from(INTS)), draw(_int_opnd)),
            "B": (draw(st.sampled_from(BYTES)), str(draw(st.integers(0, 255)))),
        }[t]
        how = draw(st.sampled_from(["LD", "A", "O"]))
        c = draw(st.sampled_from(["=", "<>", "<", "<=", ">", ">="]))
        return [f"{how}{t}{c} {a}, {b}"]
    if kind == "mov":
        op = draw(st.sampled_from(["MOVR", "MOVD", "MOVW", "MOVB"]))
        src, dst = {
            "MOVR": (draw(_real_opnd), draw(st.sampled_from(REALS))),
            "MOVD": (draw(_dint_opnd), draw(st.sampled_from(DINTS))),
            "MOVW": (draw(_int_opnd), draw(st.sampled_from(INTS))),
            "MOVB": (str(draw(st.integers(0, 255))), draw(st.sampled_from(BYTES))),
        }[op]
        return [f"{op} {src}, {dst}"]
    if kind == "real":
        op = draw(st.sampled_from(["+R", "-R", "*R", "/R"]))
        return [f"{op} {draw(_real_opnd)}, {draw(st.sampled_from(REALS))}"]
    if kind == "func":
        op = draw(st.sampled_from(["SQRT", "LN", "EXP"]))
        return [f"{op} {draw(st.sampled_from(REALS))}, {draw(st.sampled_from(REALS))}"]
    if kind == "dint":
        op = draw(st.sampled_from(["+D", "-D", "*D", "/D"]))
        return [f"{op} {draw(_dint_opnd)}, {draw(st.sampled_from(DINTS))}"]
    if kind == "int":
        op = draw(st.sampled_from(["+I", "-I", "*I", "/I"]))
        return [f"{op} {draw(_int_opnd)}, {draw(st.sampled_from(INTS))}"]
    if kind == "conv":
        op = draw(st.sampled_from(["ROUND", "TRUNC", "DTR", "ITD", "DTI"]))
        src, dst = {
            "ROUND": (draw(st.sampled_from(REALS)), draw(st.sampled_from(DINTS))),
            "TRUNC": (draw(st.sampled_from(REALS)), draw(st.sampled_from(DINTS))),
            "DTR": (draw(st.sampled_from(DINTS)), draw(st.sampled_from(REALS))),
            "ITD": (draw(st.sampled_from(INTS)), draw(st.sampled_from(DINTS))),
            "DTI": (draw(st.sampled_from(DINTS)), draw(st.sampled_from(INTS))),
        }[op]
        return [f"{op} {src}, {dst}"]
    if kind == "incdec":
        op = draw(st.sampled_from(["INCW", "DECW", "INCD", "DECD"]))
        return [f"{op} {draw(st.sampled_from(INTS if op.endswith('W') else DINTS))}"]
    if kind == "logic":
        op = draw(st.sampled_from(["ANDD", "ORD", "XORD", "ANDW", "ORW", "XORW"]))
        pool = DINTS if op.endswith("D") else INTS
        return [f"{op} {draw(st.sampled_from(pool))}, {draw(st.sampled_from(pool))}"]
    if kind == "aeno":
        return ["AENO"]
    return [f"LD SM1.{draw(st.integers(0, 3))}", f"= {bit}"]


@st.composite
def _program(draw):
    body = ["LD SM0.0"]
    for s in draw(st.lists(_statement(), min_size=3, max_size=14)):
        body += s
    reals = draw(st.lists(_real_values, min_size=8, max_size=8))
    dints = draw(st.lists(_int_values, min_size=4, max_size=4))
    ints = draw(st.lists(_short_values, min_size=4, max_size=4))
    rest = draw(st.lists(st.integers(0, 255), min_size=4, max_size=4))
    return body, reals, dints, ints, rest


def _text(body: list[str]) -> str:
    lines = ["ORGANIZATION_BLOCK MAIN:OB1", "TITLE=random", "BEGIN", "Network 1"]
    return "\r\n".join([*lines, *body, "END_ORGANIZATION_BLOCK"]) + "\r\n"


def _image(reals, dints, ints, rest) -> bytes:
    b = bytearray(V_BYTES)
    for k, v in enumerate(reals):
        struct.pack_into(">f", b, 4 * k, v)
    for k, v in enumerate(dints):
        struct.pack_into(">i", b, 32 + 4 * k, v)
    for k, v in enumerate(ints):
        struct.pack_into(">h", b, 48 + 2 * k, v)
    b[56], b[57], b[60], b[61] = rest
    return bytes(b)


def _run_both(body, image):
    from analysis.plc.runner import AwlRunner

    text = _text(body)
    cpu = S7200(load_program(text))
    cpu.mem["V"][:V_BYTES] = image
    cpu.scan()
    tr = translate_s7200(text)
    r = AwlRunner(tr.awl, default_map("s7-200"), first_scan=False)
    r.mem[:V_BYTES] = image
    r.cycle()
    sm1 = any("SM1." in s for s in body)
    ours = bytes(cpu.mem["V"][:V_BYTES]), (cpu.mem["SM"][1] & 0x0F if sm1 else None), cpu.stopped
    theirs = (
        bytes(r.mem[:V_BYTES]),
        (r.mem[tr.layout.sm + 1] & 0x0F if sm1 else None),
        r.stopped,
    )
    return cpu, ours, theirs


@settings(
    max_examples=int(__import__("os").environ.get("H22B_N", 45)),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(_program())
@example(
    (["LD SM0.0", "ROUND VD0, VD32", "AENO", "= V60.0"], [-3.0e9] * 8, [7] * 4, [0] * 4, [0] * 4)
)  # ROUND of -3.0E9: output unchanged, ENO 0 (issue 22)
@example((["LD V60.0", "MOVR 9.0, VD4"], [0.0] * 8, [0] * 4, [0] * 4, [0] * 4))  # no power
@example(
    (
        ["LD SM0.0", "MOVR 5.0, VD0", "/R 0.0, VD0", "LD SM1.3", "= V60.1"],
        [0.0] * 8,
        [0] * 4,
        [0] * 4,
        [0] * 4,
    )
)  # 5.0 /R 0.0: SM1.3, VD0 unchanged
@example(
    (
        ["LD SM0.0", "SQRT VD0, VD4", "MOVR 1.0, VD8", "AENO", "= V60.2"],
        [-1.0] * 8,
        [0] * 4,
        [0] * 4,
        [0] * 4,
    )
)  # AENO after a good MOVR: 1 (a stale OV gave 0)
@example(
    (
        ["LD SM0.0", "ROUND VD0, VD32", "TRUNC VD4, VD36"],
        [math.nan, math.inf] * 4,
        [5] * 4,
        [0] * 4,
        [0] * 4,
    )
)  # ROUND(NaN), TRUNC(inf): outputs unchanged
@example(
    (
        ["LD SM0.0", "LD V60.0", "LD SM0.0", "LDS 1", "INCW VW48"],
        [0.0] * 8,
        [0] * 4,
        [0] * 4,
        [0] * 4,
    )
)  # LDS copies a level that is off: the box after it is skipped
@example(
    (
        ["LD SM0.0", "+R 0.0, VD20", "ROUND VD0, VD32", "LD SM1.0", "= V60.0"],
        [-3.0e9] + [0.0] * 7,
        [0] * 4,
        [0] * 4,
        [0] * 4,
    )
)  # ROUND's error: SM1.1 only
@example(
    (
        ["LD SM0.0", "EXP VD12, VD0", "LD SM1.0", "= V60.0"],
        [0.0, 0.0, 0.0, -104.0] + [0.0] * 4,
        [0] * 4,
        [0] * 4,
        [0] * 4,
    )
)  # e^-104 is below the REAL range: discarded
def test_random_programs_leave_the_same_memory(prog):
    body, reals, dints, ints, rest = prog
    cpu, ours, theirs = _run_both(body, _image(reals, dints, ints, rest))
    # outside the subset (module docstring): a REAL overflow of finite operands, a denormal
    assume(cpu.events["overflow"] == 0 and cpu.events["denormal"] == 0)
    assert ours == theirs, _text(body)

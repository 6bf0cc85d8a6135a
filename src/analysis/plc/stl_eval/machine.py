"""An S7-200 CPU that runs STEP 7-Micro/WIN STL programs, scan by scan.

What it models (each instruction's source is in :data:`INSTRUCTIONS`, listed by
:func:`instruction_table`). Sources: [S2M] the S7-200 Programmable Controller System Manual
(manualslib.com/manual/801761, its page numbers); [manualshelf] its older edition
C79000-G7076-C233-01 (manualshelf.com, page-NNN); [MWH] the STEP 7-Micro/WIN 32 help (its
file names); [SMART] the S7-200 SMART System Manual V2.3; "~" marks a rule assumed or taken
from a secondary source, not read in a manual page:

Memory
    V, M, SM, I, Q, S, L (64 bytes per call level), AC0-AC3, sized by the target CPU
    (:data:`analysis.plc.memmap.CPUS`, CPU 224 by default). Big-endian: VD100 is VB100 (most
    significant) .. VB103; V100.0 is the least significant bit of VB100 [S2M p.42]. An
    accumulator read as a byte or word is its low 8 or 16 bits; a byte or word written to
    it changes only those bits (~ the manual's "accumulators can be accessed as bytes,
    words or double words"; what happens to the high bits is assumed). SMB0-SMB29 are
    read-only for the program [S2M appendix D, SM memory]. Timers, counters, high-speed
    counters and analog I/O are not modelled: an instruction naming T, C, HC, AIW or AQW is
    refused with its line.
Logic
    The 9-level logic stack (LD pushes, A/O combine into the top, ALD/OLD/LPS/LRD/LPP/LDS;
    the bottom is lost on a push, filled with 0 on a pop) [S2M p.83, manualshelf p.370].
    Box instructions run only with power flow (top of stack = 1); each sets ENO, which
    AENO ANDs into the top [SMART 7.1]. A skipped box sets ENO = 0.
Numbers
    REAL is IEEE-754 binary32; ``+R -R *R /R SQRT`` are correctly rounded (a float64
    result rounded once to binary32 is exact for these operations); SIN, COS, TAN, LN, EXP
    are computed in float64 and rounded once (the CPU's library is not documented).
    Overflow, an illegal input (NaN or infinity) or an illegal value (SQRT of a negative, LN
    of a non-positive) sets SM1.1, clears SM1.0/SM1.2, ENO = 0 and leaves the output
    unchanged [S2M p.154, p.157; MWH s7-29x9r.htm]; division by zero sets SM1.3, ENO = 0
    and changes nothing else [same]. Integer overflow likewise (the output is not written)
    [MWH s7-28hir.htm, s7-29u0i.htm]. ROUND/TRUNC of a value outside DINT, a NaN or an
    infinity set SM1.1 and leave the output [S2M p.115]. A NaN in a REAL compare is a
    fatal error: the CPU goes to STOP [S2M p.96]; here :attr:`S7200.fault` says where.
    Denormal REALs (outside the documented range, behaviour ✘ unknown) are kept as IEEE
    does; ``ftz=True`` flushes them to zero instead.
Program
    OB1 every scan; subroutines by ``CALL`` with IN, IN_OUT, OUT parameters copied by value
    into the callee's L memory from LB0 (bits packed, bytes/words/double words on byte
    boundaries) and back after the return [manualshelf p.324]; at most 8 nested levels
    (error 0008: ENO = 0, the call is not made) [same]; the logic stack is saved at the
    call, the callee starts with its top = 1, and the stack is restored at the return (~
    S7-200 System Manual, Call Subroutine; page not retrieved). OUT and TEMP locals are
    not initialised at a call: they hold what the last call at that depth left (~
    tecnoplc.com). ``JMP n``/``LBL n`` within one block [S2M, Jump]; ``FOR``/``NEXT``;
    ``CRET``, ``END``, ``STOP``. SM0.0 is always on, SM0.1 and SM0.3 are on in the first
    scan only, SM0.5 is a 1 s clock and SM0.4 a 1 min clock of the simulated time
    (``scan_ms`` per scan), SM0.6 alternates every scan [S2M p.496]. EU/ED detect no edge in
    the first scan an instance runs (it records the state) [SMART p.157, MWH s7-23wkr.htm].
Motion
    ``PLS 0|1`` starts a single-segment pulse train of SMD72/SMD82 pulses when the control
    byte SMB67/SMB77 enables it and clears the idle bit SM66.7/SM76.7; :meth:`S7200.pto_done`
    (or ``pto_scans``) finishes it. With the enable bit cleared, PLS aborts the train
    [MWH s7-24yeq.htm]. The pulses themselves are not simulated.

Why hand-written (design.md asks for an established library where one fits): awlsim runs
S7-300/400 AWL, a different machine (RLO and accumulators instead of a logic stack and
in-place two-operand math, V memory, SM bits, different REAL error rules), and no S7-200
simulator is installable from the registries. The project's translation to AWL
(:mod:`analysis.plc.translate`) is cross-checked against this evaluator on random programs
(``tests/plc/test_stl_machine.py``).
"""

from __future__ import annotations

import math
import struct
from collections.abc import Callable
from dataclasses import dataclass

from analysis.plc.memmap import CPUS, DEFAULT_CPU
from analysis.plc.stl_eval.syntax import Block, Program, StlError, Stmt, parse_program

__all__ = [
    "INSTRUCTIONS",
    "S7200",
    "TYPES",
    "Fault",
    "Library",
    "instruction_table",
    "load_program",
]

TYPES = ("BOOL", "BYTE", "INT", "WORD", "DINT", "DWORD", "REAL")
_U8 = struct.Struct(">B")
_U16 = struct.Struct(">H")
_I16 = struct.Struct(">h")
_U32 = struct.Struct(">I")
_I32 = struct.Struct(">i")
_F32 = struct.Struct(">f")
_FMT = {"B": _U8, "W": _U16, "I": _I16, "D": _U32, "L": _I32, "R": _F32}
_SIZE = {"B": 1, "W": 2, "I": 2, "D": 4, "L": 4, "R": 4}
_TINY = 1.1754943508222875e-38
FLT_MAX = 3.4028234663852886e38


@dataclass(frozen=True)
class Fault:
    """Why the CPU went to STOP, and where."""

    reason: str
    line: int
    block: str
    network: int
    text: str

    def __str__(self) -> str:
        return str(
            StlError(
                self.reason, line=self.line, block=self.block, network=self.network, text=self.text
            )
        )


@dataclass(frozen=True)
class Library:
    """A library subroutine (e.g. Siemens' "Arcusfunctions" ARCTAN): REAL inputs, REAL
    outputs, computed by ``fn`` (float64, rounded to REAL). Micro/WIN links libraries into
    the program; the paper calls ARCTAN and ARCCOS without listing them."""

    inputs: tuple[str, ...]
    outputs: tuple[str, ...]
    fn: Callable
    source: str


# ------------------------------------------------------------------------------------------
# operands
_AREAS = {"V", "M", "SM", "I", "Q", "S", "L"}
_REFUSED_AREAS = {
    "T": "timers are not modelled by this evaluator",
    "C": "counters are not modelled by this evaluator",
    "HC": "high-speed counters are not modelled by this evaluator",
    "AIW": "analog inputs are not modelled by this evaluator",
    "AQW": "analog outputs are not modelled by this evaluator",
}
_PTR_AREA = {"V": 1, "M": 2, "I": 3, "Q": 4, "SM": 5, "S": 6}
_PTR_NAME = {v: k for k, v in _PTR_AREA.items()}
_INT_RE = r"[+-]?\d+"
_REAL_RE = r"[+-]?(?:\d+\.\d*|\.\d+)(?:[Ee][+-]?\d+)?|[+-]?\d+[Ee][+-]?\d+"


def _parse_const(a: str):
    """(kind, value) of a constant, or None. kind: "int", "real", "hex", "bin"."""
    import re

    if re.fullmatch(_REAL_RE, a):
        return "real", float(a)
    if re.fullmatch(_INT_RE, a):
        return "int", int(a)
    m = re.fullmatch(r"16#([0-9A-Fa-f]+)", a)
    if m:
        return "hex", int(m.group(1), 16)
    m = re.fullmatch(r"2#([01]+)", a)
    if m:
        return "bin", int(m.group(1), 2)
    return None


@dataclass(frozen=True)
class _Opnd:
    """A resolved operand: kind in {"mem", "bit", "ac", "const", "ptr", "addr", "num"}."""

    kind: str
    area: str = ""
    off: int = 0
    bit: int = 0
    width: str = ""
    value: object = None
    ptr: _Opnd | None = None
    text: str = ""


# operand classes an instruction takes: letter = data type, suffix ">" written, "^" both
_WIDTH_OF = {"b": "B", "w": "W", "i": "I", "d": "D", "l": "L", "r": "R"}


class _Resolver:
    """Turns operand text into :class:`_Opnd` for one block (its locals) and one CPU."""

    def __init__(self, cpu, block: Block, frame: dict[str, tuple]):
        self.cpu, self.block, self.frame = cpu, block, frame

    def area_size(self, area: str) -> int:
        return 64 if area == "L" else self.cpu.areas[area]

    def check_range(self, area: str, off: int, size: int, a: str) -> None:
        n = self.area_size(area)
        if off + size > n:
            raise ValueError(
                f"operand {a} is beyond the {self.cpu.name}'s {area} memory "
                f"({area}B0-{area}B{n - 1})"
            )

    def operand(self, a: str, cls: str) -> _Opnd:
        import re

        t = cls[0]
        write = len(cls) > 1
        au = a.upper()
        if not a:
            raise ValueError("an operand is missing (two commas, or a comma at the end)")
        if a.startswith("#"):
            name = a[1:]
            if name not in self.frame:
                raise ValueError(f"{a} is not a local variable of {self.block.label}")
            vtype, off, bit = self.frame[name]
            if t == "x":
                if vtype != "BOOL":
                    raise ValueError(f"{a} is {vtype}; this operand is a bit (BOOL)")
                return _Opnd("bit", "L", off, bit, text=a)
            want = _WIDTH_OF[t]
            size = {"BYTE": 1, "WORD": 2, "INT": 2, "DWORD": 4, "DINT": 4, "REAL": 4}.get(vtype)
            if (
                size != _SIZE[want]
                or (t == "r" and vtype != "REAL")
                or (t in "li" and vtype in ("REAL", "WORD", "DWORD"))
            ):
                raise ValueError(f"{a} is {vtype}; this operand needs a {_TYPE_WORD[t]}")
            return _Opnd("mem", "L", off, width=want, text=a)
        for area, why in _REFUSED_AREAS.items():
            if re.fullmatch(area + r"\d+", au) or (
                area in ("T", "C") and re.fullmatch(area + r"\d+", au)
            ):
                raise ValueError(f"operand {a}: {why}")
        c = _parse_const(a)
        if c is not None:
            if write:
                raise ValueError(f"operand {a} is a constant; this operand is written")
            return self.const(a, c, t)
        if a.startswith("&"):
            if t not in "dl" or write:
                raise ValueError(f"{a} (an address) can only be read as a double word")
            m = re.fullmatch(r"&(V|M|I|Q|SM|S)B(\d+)", au)
            if not m:
                raise ValueError(f"{a}: an address is &VBn, &MBn, &IBn, &QBn, &SMBn or &SBn")
            self.check_range(m.group(1), int(m.group(2)), 1, a)
            return _Opnd("addr", m.group(1), int(m.group(2)), text=a)
        if a.startswith("*"):
            if t == "x":
                raise ValueError(f"{a}: a pointer addresses bytes, words or double words")
            ptr = self.operand(a[1:], "d")
            if (
                ptr.kind not in ("mem", "ac")
                or ptr.width != "D"
                or ptr.area not in ("V", "L", "AC")
            ):
                raise ValueError(f"{a}: a pointer is *VDn, *ACn or *LDn")
            return _Opnd("ptr", width=_WIDTH_OF[t], ptr=ptr, text=a)
        m = re.fullmatch(r"AC([0-3])", au)
        if m:
            if t == "x":
                raise ValueError(f"{a}: an accumulator is not a bit")
            return _Opnd("ac", "AC", int(m.group(1)) * 4, width=_WIDTH_OF[t], text=a)
        m = re.fullmatch(r"(SM|V|M|I|Q|S|L)(\d+)\.(\d+)", au)
        if m:
            if t != "x":
                raise ValueError(f"operand {a} is a bit; this operand needs a {_TYPE_WORD[t]}")
            if int(m.group(3)) > 7:
                raise ValueError(f"operand {a}: bit numbers are 0..7")
            area, off = m.group(1), int(m.group(2))
            self.check_range(area, off, 1, a)
            if write:
                self.check_writable(area, off, a)
            return _Opnd("bit", area, off, int(m.group(3)), text=a)
        m = re.fullmatch(r"(SM|V|M|I|Q|S|L)([BWD])(\d+)", au)
        if m:
            area, w, off = m.group(1), m.group(2), int(m.group(3))
            if t == "x":
                raise ValueError(
                    f"operand {a} is a {_WIDTH_WORD[w]}; this operand is a bit (e.g. {area}{off}.0)"
                )
            want = _WIDTH_OF[t]
            if _SIZE[want] != {"B": 1, "W": 2, "D": 4}[w]:
                raise ValueError(
                    f"operand {a} is a {_WIDTH_WORD[w]}; this operand needs a "
                    f"{_TYPE_WORD[t]} ({_EXAMPLE[t]})"
                )
            self.check_range(area, off, _SIZE[want], a)
            if write:
                self.check_writable(area, off, a)
            return _Opnd("mem", area, off, width=want, text=a)
        if re.fullmatch(r"VDD\d+", au):
            raise ValueError(f"operand {a} is not an S7-200 address (VD, VW, VB or V n.b)")
        raise ValueError(
            f"operand {a!r} is not an address, a constant or a local (#name) of {self.block.label}"
        )

    def check_writable(self, area: str, off: int, a: str) -> None:
        if area == "SM" and off < 30:
            raise ValueError(f"operand {a}: SMB0-SMB29 are read-only for the program")

    def const(self, a: str, c, t: str) -> _Opnd:
        kind, v = c
        if t == "x":
            raise ValueError(f"operand {a} is a constant; this operand is a bit address")
        if t == "r":
            if kind != "real":
                raise ValueError(
                    f"operand {a} is an integer constant; a REAL operand needs a REAL "
                    f"constant ({a}.0): a REAL and a DINT of the same number have "
                    "different bits"
                    if kind == "int"
                    else f"operand {a}: a REAL operand needs a REAL constant"
                )
            if v != 0 and not (_TINY <= abs(v) <= FLT_MAX):
                raise ValueError(f"REAL constant {a} is outside +-1.175495E-38..3.402823E+38")
            return _Opnd("const", value=_F32.unpack(_F32.pack(v))[0], text=a)
        if kind == "real":
            raise ValueError(
                f"operand {a} is a REAL constant; this operand needs a {_TYPE_WORD[t]}"
            )
        lo, hi = {
            "b": (0, 255),
            "w": (-32768, 65535),
            "i": (-32768, 65535),
            "d": (-(2**31), 2**32 - 1),
            "l": (-(2**31), 2**32 - 1),
        }[t]
        if kind in ("hex", "bin"):
            lo = 0
        if not lo <= v <= hi:
            raise ValueError(f"constant {a} does not fit a {_TYPE_WORD[t]} ({lo}..{hi})")
        bits = v & ((1 << (8 * _SIZE[_WIDTH_OF[t]])) - 1)
        # store the value as the type reads it
        width = _WIDTH_OF[t]
        fmt = _FMT[width]
        raw = bits.to_bytes(_SIZE[width], "big")
        return _Opnd("const", value=fmt.unpack(raw)[0], text=a)


_TYPE_WORD = {
    "x": "bit",
    "b": "byte (B)",
    "w": "word (W)",
    "i": "word (INT)",
    "d": "double word (D)",
    "l": "double word (DINT)",
    "r": "double word (REAL)",
}
_WIDTH_WORD = {"B": "byte", "W": "word", "D": "double word"}
_EXAMPLE = {
    "b": "e.g. VB0",
    "w": "e.g. VW0",
    "i": "e.g. VW0",
    "d": "e.g. VD0",
    "l": "e.g. VD0",
    "r": "e.g. VD0",
}


# ------------------------------------------------------------------------------------------
# the instruction table: mnemonic -> (operand classes, builder name, semantics source)
_SRC_BIT = "S2M p.83 (contacts, coils, logic stack); manualshelf p.370"
_SRC_MATH_R = "S2M p.154 (Add/Subtract/Multiply/Divide, SM bits and ENO); MWH s7-29x9r.htm"
_SRC_MATH_I = "S2M p.154; MWH s7-28hir.htm (INT), s7-29u0i.htm (DINT): overflow -> not written"
_SRC_FN = "S2M p.157 (numeric functions: SM1.1 overflow/illegal, output unaltered)"
_SRC_CONV = "S2M p.115 (ROUND/TRUNC: invalid or too large -> SM1.1, output not affected)"
_SRC_MOV = "S2M p.115 example, MWH moves (MOVB/W/D/R copy 8/16/32/32 bits, no conversion)"
_SRC_CMP = "manualshelf p.186 (compare contacts); S2M p.96 (NaN in Compare Real: fatal)"

INSTRUCTIONS: dict[str, tuple[tuple[str, ...], str, str]] = {}


def _ins(names, classes, builder, source):
    for n in names.split():
        INSTRUCTIONS[n] = (tuple(classes), builder, source)


_ins("LD A O LDN AN ON LDI AI OI LDNI ANI ONI", ("x",), "contact", _SRC_BIT)
_ins("= =I", ("x>",), "coil", _SRC_BIT)
_ins("S R SI RI", ("x>", "b"), "setreset", _SRC_BIT + "; S/R bit, N: N bits from bit")
_ins("NOT ALD OLD LPS LRD LPP AENO", (), "stack", _SRC_BIT + "; SMART 7.1 (AENO)")
_ins("NOP", ("n",), "stack", "~ S7-200 NOP N, N = 0..255 (page not retrieved)")
_ins("LDS", ("n",), "stack", "manualshelf p.370 (Load Stack)")
_ins("EU ED", (), "edge", "MWH s7-23wkr.htm; SMART p.157 (no edge on the first scan)")
for _t, _cls in (("B", "b"), ("W", "i"), ("D", "l"), ("R", "r")):
    for _c in ("=", "<>", "<", "<=", ">", ">="):
        _ins(f"LD{_t}{_c} A{_t}{_c} O{_t}{_c}", (_cls, _cls), "compare", _SRC_CMP)
_ins("MOVB", ("b", "b>"), "move", _SRC_MOV)
_ins("MOVW", ("w", "w>"), "move", _SRC_MOV)
_ins("MOVD", ("d", "d>"), "move", _SRC_MOV)
_ins("MOVR", ("r", "r>"), "move", _SRC_MOV)
_ins("BMB", ("b", "b>", "b"), "blockmove", "~ MWH Block Move, N = 1..255 (page not retrieved)")
_ins("BMW", ("w", "w>", "b"), "blockmove", "~ MWH Block Move, N = 1..255 (page not retrieved)")
_ins("BMD", ("d", "d>", "b"), "blockmove", "~ MWH Block Move, N = 1..255 (page not retrieved)")
_ins("SWAP", ("w^",), "swap", "~ MWH Swap Bytes (page not retrieved)")
_ins("+R -R *R /R", ("r", "r^"), "math_r", _SRC_MATH_R)
_ins("+I -I *I /I", ("i", "i^"), "math_i", _SRC_MATH_I)
_ins("+D -D *D /D", ("l", "l^"), "math_d", _SRC_MATH_I)
_ins("MUL", ("i", "l^"), "mul", "manualshelf p.252 (MUL: 16 x 16 -> 32 bits)")
_ins("DIV", ("i", "l^"), "div", "manualshelf p.252 (DIV: remainder high word, quotient low)")
_ins("SQRT LN EXP SIN COS TAN", ("r", "r>"), "func", _SRC_FN)
_ins(
    "INCB DECB",
    ("b^",),
    "incdec",
    "~ Increment/Decrement: the Add rule assumed (S2M p.154; INC page not retrieved)",
)
_ins(
    "INCW DECW",
    ("i^",),
    "incdec",
    "~ Increment/Decrement: the Add rule assumed (S2M p.154; INC page not retrieved)",
)
_ins(
    "INCD DECD",
    ("l^",),
    "incdec",
    "~ Increment/Decrement: the Add rule assumed (S2M p.154; INC page not retrieved)",
)
_ins(
    "ANDB ORB XORB", ("b", "b^"), "logic", "~ MWH logic operations, SM1.0 zero (page not retrieved)"
)
_ins(
    "ANDW ORW XORW", ("w", "w^"), "logic", "~ MWH logic operations, SM1.0 zero (page not retrieved)"
)
_ins(
    "ANDD ORD XORD", ("d", "d^"), "logic", "~ MWH logic operations, SM1.0 zero (page not retrieved)"
)
_ins("INVB", ("b^",), "invert", "~ MWH Invert, SM1.0 zero (page not retrieved)")
_ins("INVW", ("w^",), "invert", "~ MWH Invert, SM1.0 zero (page not retrieved)")
_ins("INVD", ("d^",), "invert", "~ MWH Invert, SM1.0 zero (page not retrieved)")
_ins(
    "SLB SRB RLB RRB",
    ("b^", "b"),
    "shift",
    "~ MWH Shift/Rotate: SM1.0 zero, SM1.1 last bit out (page not retrieved)",
)
_ins(
    "SLW SRW RLW RRW",
    ("w^", "b"),
    "shift",
    "~ MWH Shift/Rotate: SM1.0 zero, SM1.1 last bit out (page not retrieved)",
)
_ins(
    "SLD SRD RLD RRD",
    ("d^", "b"),
    "shift",
    "~ MWH Shift/Rotate: SM1.0 zero, SM1.1 last bit out (page not retrieved)",
)
_ins("ROUND TRUNC", ("r", "l>"), "round", _SRC_CONV)
_ins("DTR", ("l", "r>"), "convert", "S2M p.115 (DTR: DINT -> REAL)")
_ins("ITD", ("i", "l>"), "convert", "S2M p.115 (ITD: INT -> DINT, sign extended)")
_ins(
    "DTI",
    ("l", "i>"),
    "convert",
    "~ DTI: SM1.1 outside INT, output unchanged (as ROUND, S2M p.115; assumed)",
)
_ins("BTI", ("b", "i>"), "convert", "~ BTI: unsigned byte -> INT (page not retrieved)")
_ins("ITB", ("i", "b>"), "convert", "~ ITB: SM1.1 outside 0..255 (page not retrieved)")
_ins(
    "JMP",
    ("n",),
    "jump",
    "S7-200 help (virtualPLC mirror): a jump is taken with the top of stack 1",
)
_ins("LBL", ("n",), "label", "S7-200 help (virtualPLC mirror): jump and label in one block")
_ins("CALL", (), "call", "manualshelf p.324 (Call Subroutine with parameters)")
_ins("CRET", (), "cret", "MWH s7-250fn.htm (CRET: conditional return)")
_ins("END", (), "end", "~ S7-200 END, conditional end of the main program (page not retrieved)")
_ins("STOP", (), "stop", "~ S7-200 STOP: the CPU to STOP (page not retrieved)")
_ins("WDR", (), "stack", "~ WDR: no effect here (no watchdog modelled)")
_ins("FOR", ("i>", "i", "i"), "for", "~ S7-200 FOR INDX, INIT, FINAL (page not retrieved)")
_ins("NEXT", (), "next", "~ S7-200 NEXT (page not retrieved)")
_ins(
    "PLS",
    ("n",),
    "pls",
    "MWH s7-24yeq.htm (PTO single segment, SMB67/SMB77, SMD72/SMD82, SM66.7/SM76.7)",
)

_REFUSED_OPS = {
    **dict.fromkeys(
        "TON TOF TONR CTU CTD CTUD HDEF HSC".split(),
        "timers and counters are not modelled by this evaluator",
    ),
    **dict.fromkeys(
        "ATCH DTCH ENI DISI RETI CRETI CEVNT".split(),
        "interrupts are not modelled by this evaluator",
    ),
    **dict.fromkeys(
        "LSCR SCRT SCRE CSCRE".split(), "sequence control relays are not modelled by this evaluator"
    ),
    **dict.fromkeys("XMT RCV NETR NETW GPA SPA".split(), "communication is not modelled"),
    "RET": "Micro/WIN appends the unconditional return; write CRET for a conditional one",
    "MEND": "Micro/WIN appends the unconditional end; write END for a conditional one",
    "DI_R": "DI_R is the LAD/FBD box; in STL it is DTR",
    "I_DI": "I_DI is the LAD/FBD box; in STL it is ITD",
    "DI_I": "DI_I is the LAD/FBD box; in STL it is DTI",
    "ADD_R": "ADD_R is the LAD/FBD box; in STL it is +R",
    "SUB_R": "SUB_R is the LAD/FBD box; in STL it is -R",
    "MUL_R": "MUL_R is the LAD/FBD box; in STL it is *R",
    "DIV_R": "DIV_R is the LAD/FBD box; in STL it is /R",
    "MOV_R": "MOV_R is the LAD/FBD box; in STL it is MOVR",
}


def instruction_table() -> list[tuple[str, str, str]]:
    """(mnemonic, operands, semantics source) of every instruction the evaluator runs."""
    words = {
        "x": "bit",
        "b": "B",
        "w": "W",
        "i": "INT",
        "d": "D",
        "l": "DINT",
        "r": "REAL",
        "n": "n",
    }
    out = []
    for k, (cls, _, src) in INSTRUCTIONS.items():
        ops = ", ".join(words[c[0]] + {">": " out", "^": " in/out"}.get(c[1:], "") for c in cls)
        if k == "CALL":
            ops = "SBRn|name, IN.., IN_OUT.., OUT.."
        out.append((k, ops, src))
    return out


# ------------------------------------------------------------------------------------------
@dataclass
class _Pou:
    block: Block
    frame: dict  # local name -> (type, byte, bit)
    params: list  # (section, name, type, byte, bit)
    size: int
    code: list  # compiled: list of (stmt, classes, operands, builder)
    labels: dict


def _layout(block: Block) -> tuple[dict, list, int]:
    """L memory of a block's locals: IN, IN_OUT, OUT, TEMP in order; bits packed into
    bytes, other types from the next byte (manualshelf p.324)."""
    order = {"IN": 0, "IN_OUT": 1, "OUT": 2, "TEMP": 3}
    frame, params = {}, []
    byte, bit = 0, None  # bit: next free bit in the current bit byte, or None
    sizes = {"BYTE": 1, "WORD": 2, "INT": 2, "DWORD": 4, "DINT": 4, "REAL": 4}
    last = -1
    for v in block.vars:
        if order[v.section] < last:
            raise StlError(
                f"{v.section} declared after a later section (order: VAR_INPUT, VAR_IN_OUT, "
                "VAR_OUTPUT, VAR)",
                line=v.line,
                block=block.label,
            )
        last = order[v.section]
        if v.name in frame:
            raise StlError(f"local {v.name} declared twice", line=v.line, block=block.label)
        if v.type == "BOOL":
            if bit is None or bit == 8:
                bit, bbyte = 0, byte
                byte += 1
            frame[v.name] = ("BOOL", bbyte, bit)
            bit += 1
        elif v.type in sizes:
            bit = None
            frame[v.name] = (v.type, byte, 0)
            byte += sizes[v.type]
        else:
            raise StlError(
                f"local {v.name}: type {v.type} is not one of {', '.join(TYPES)}",
                line=v.line,
                block=block.label,
            )
        if v.section != "TEMP":
            params.append((v.section, v.name, *frame[v.name]))
        if byte > 64:
            raise StlError(
                f"the locals need {byte} bytes of L memory; the S7-200 has 64 per block",
                line=v.line,
                block=block.label,
            )
    if block.kind == "OB" and params:
        raise StlError(
            "the main program has no parameters (only VAR / VAR_TEMP locals)",
            line=block.line,
            block=block.label,
        )
    return frame, params, byte


def load_program(
    text: str | Program,
    *,
    symbols: dict[str, str] | None = None,
    libraries: dict[str, Library] | None = None,
    cpu: str | None = None,
    source: str = "program",
):
    """Parse and check a program (every instruction, operand and call), ready to run.

    Returns a :class:`Loaded` that :class:`S7200` runs. Raises :class:`StlError` naming the
    line, the block, the network and the statement for anything the CPU would not run.
    """
    prog = (
        text if isinstance(text, Program) else parse_program(text, symbols=symbols, source=source)
    )
    return Loaded(prog, dict(libraries or {}), CPUS[cpu or DEFAULT_CPU["s7-200"]])


class Loaded:
    """A checked program: blocks compiled to operand descriptors for one CPU."""

    def __init__(self, prog: Program, libraries: dict[str, Library], cpu) -> None:
        if cpu.dialect != "s7-200":
            raise ValueError(f"{cpu.name} is not an S7-200 CPU")
        self.program, self.libraries, self.cpu = prog, libraries, cpu
        self.pous: dict[str, _Pou] = {}
        for b in prog.blocks:
            frame, params, size = _layout(b)
            key = f"{b.kind}{b.number}"
            if key in self.pous:
                raise StlError(f"{key} defined twice", line=b.line, block=b.label)
            self.pous[key] = _Pou(b, frame, params, size, [], {})
        self.names = {p.block.name.upper(): k for k, p in self.pous.items() if k[:3] == "SBR"}
        for pou in self.pous.values():
            self._compile(pou)

    def sbr_key(self, name: str) -> str | None:
        u = name.upper()
        if u in self.names:
            return self.names[u]
        import re

        m = re.fullmatch(r"SBR_?(\d+)", u)
        if m and f"SBR{int(m.group(1))}" in self.pous:
            return f"SBR{int(m.group(1))}"
        return None

    def _compile(self, pou: _Pou) -> None:
        b = pou.block
        res = _Resolver(self.cpu, b, pou.frame)
        fors = []
        for idx, st in enumerate(b.code):

            def err(msg, st=st):
                return StlError(msg, line=st.line, block=b.label, network=st.network, text=st.text)

            op = st.op
            if op in _REFUSED_OPS:
                raise err(f"{op}: {_REFUSED_OPS[op]}")
            if op not in INSTRUCTIONS:
                hint = ""
                for k in ("CALL", "ROUND", "MOVR", "MOVD"):
                    if op.startswith(k) and op != k:
                        hint = f" (a space is missing: {k} {op[len(k) :]}...?)"
                raise err(f"unknown instruction {op}{hint}")
            classes, builder, _ = INSTRUCTIONS[op]
            if op == "CALL":
                pou.code.append((st, (), self._call_operands(st, res, err), builder))
                continue
            if len(st.args) != len(classes):
                raise err(
                    f"{op} takes {len(classes)} operand(s), {len(st.args)} given"
                    + (" (a comma is missing?)" if len(st.args) < len(classes) else "")
                )
            opnds = []
            for a, cls in zip(st.args, classes, strict=True):
                if cls == "n":
                    try:
                        v = int(a)
                    except ValueError:
                        raise err(f"operand {a!r} must be a whole number") from None
                    lim = {
                        "LDS": (1, 8),
                        "PLS": (0, 1),
                        "JMP": (0, 255),
                        "LBL": (0, 255),
                        "NOP": (0, 255),
                    }[op]
                    if not lim[0] <= v <= lim[1]:
                        raise err(f"{op} {a}: the operand is {lim[0]}..{lim[1]}")
                    opnds.append(_Opnd("num", value=v, text=a))
                    continue
                try:
                    opnds.append(res.operand(a, cls))
                except ValueError as exc:
                    raise err(str(exc)) from None
            if op in ("S", "R", "SI", "RI"):
                n = opnds[1]
                if n.kind != "const" or not 1 <= int(n.value) <= 255:
                    raise err(f"{op}: the number of bits is a constant 1..255")
            if op in ("BMB", "BMW", "BMD"):
                n = opnds[2]
                if n.kind == "const" and not 1 <= int(n.value) <= 255:
                    raise err(f"{op}: N is 1..255")
            if op == "LBL":
                if opnds[0].value in pou.labels:
                    raise err(f"label {opnds[0].value} defined twice in {b.label}")
                pou.labels[opnds[0].value] = idx
            if op == "FOR":
                fors.append(idx)
            if op == "NEXT":
                if not fors:
                    raise err("NEXT without FOR")
                fors.pop()
            if op == "END" and b.kind != "OB":
                raise err("END (conditional end) is for the main program; a subroutine uses CRET")
            if op == "CRET" and b.kind == "OB":
                raise err("CRET returns from a subroutine; the main program uses END")
            pou.code.append((st, classes, opnds, builder))
        if fors:
            st = b.code[fors[-1]]
            raise StlError(
                "FOR without NEXT", line=st.line, block=b.label, network=st.network, text=st.text
            )
        if len(fors) > 8:
            raise StlError("FOR loops nest 8 deep at most", block=b.label)
        for st, _, opnds, builder in pou.code:
            if builder == "jump" and opnds[0].value not in pou.labels:
                raise StlError(
                    f"JMP {opnds[0].value}: no LBL {opnds[0].value} in {b.label} (a jump "
                    "stays within its block)",
                    line=st.line,
                    block=b.label,
                    network=st.network,
                    text=st.text,
                )

    def _call_operands(self, st: Stmt, res: _Resolver, err):
        if not st.args:
            raise err("CALL needs a subroutine (CALL SBR0 or CALL name, parameters...)")
        target, actuals = st.args[0], st.args[1:]
        key = self.sbr_key(target)
        if key is None:
            lib = self.libraries.get(target.upper()) or self.libraries.get(target)
            if lib is None:
                raise err(f"subroutine {target} is not defined in this program")
            params = [("IN", n, "REAL", 0, 0) for n in lib.inputs] + [
                ("OUT", n, "REAL", 0, 0) for n in lib.outputs
            ]
        else:
            params = self.pous[key].params
        if len(actuals) != len(params):
            names = ", ".join(f"{s} {n}:{t}" for s, n, t, _, _ in params) or "none"
            raise err(f"{target} takes {len(params)} parameter(s) ({names}), {len(actuals)} given")
        ops = []
        for a, (section, name, typ, _, _) in zip(actuals, params, strict=True):
            cls = {
                "BOOL": "x",
                "BYTE": "b",
                "WORD": "w",
                "INT": "i",
                "DWORD": "d",
                "DINT": "l",
                "REAL": "r",
            }[typ]
            if section != "IN":
                cls += ">"
            try:
                ops.append(res.operand(a, cls))
            except ValueError as exc:
                raise err(f"parameter {name} ({section} {typ}): {exc}") from None
        return (key, target, params, ops)


# ------------------------------------------------------------------------------------------
class _Stop(Exception):
    pass


class _Return(Exception):
    pass


class _EndScan(Exception):
    pass


class _Pto:
    """One pulse train output: the pulse counts started (``log``), a one-entry pipeline."""

    def __init__(self) -> None:
        self.log: list[int] = []
        self.busy = False
        self.queued: int | None = None
        self.scans = 0


class S7200:
    """An S7-200 CPU in RUN with one program loaded (:func:`load_program`).

    Parameters
    ----------
    program : Loaded or str
        The program (text is loaded with the other keyword arguments' defaults).
    ftz : bool
        Flush denormal REAL operands and results to zero (default: IEEE gradual underflow).
    scan_ms : float
        Simulated scan time [ms] for the clock bits SM0.4 and SM0.5.
    pto_scans : int, optional
        Finish every pulse train after this many scans (default: only :meth:`pto_done`).
    fragment : bool
        Run a listing that is one network without its first contact: the scan begins with
        power flow on, as after ``LD SM0.0`` (the paper's figures and the audit's pieces).

    Use :meth:`write` / :meth:`read` (type and address, as in ``--set VD0=100.0``) and
    :meth:`scan`. After a fatal error :attr:`fault` says where and the CPU stays in STOP.
    """

    def __init__(
        self,
        program,
        *,
        ftz: bool = False,
        scan_ms: float = 10.0,
        pto_scans: int | None = None,
        symbols=None,
        libraries=None,
        cpu=None,
        fragment: bool = False,
    ) -> None:
        if isinstance(program, str):
            program = load_program(program, symbols=symbols, libraries=libraries, cpu=cpu)
        self.loaded = program
        c = program.cpu
        self.mem = {a: bytearray(c.areas[a]) for a in ("V", "M", "SM", "I", "Q", "S")}
        self.mem["AC"] = bytearray(16)
        self.frames = [bytearray(64) for _ in range(9)]  # main + 8 nested subroutine levels
        self.depth = 0
        self.s = 0  # logic stack, bit 0 = top
        self.eno = 0
        self.ftz = ftz
        self.fragment = fragment
        self.scan_ms = scan_ms
        self.pto_scans = pto_scans
        self.scans = 0
        self.fault: Fault | None = None
        self.stopped_by: str | None = None
        self.events = {"denormal": 0, "overflow": 0}
        self.pto = [_Pto(), _Pto()]
        self._edges: dict[int, int] = {}
        self._first = True
        self._for: list = []
        self._code = {k: self._bind(p) for k, p in program.pous.items()}
        self.mem["SM"][66] |= 0x80  # both PTO channels idle at power-up
        self.mem["SM"][76] |= 0x80

    # --- public memory access ---------------------------------------------------------
    def _addr(self, typ: str, addr: str) -> tuple[str, int, int | None]:
        import re

        typ = typ.upper()
        if typ not in TYPES:
            raise ValueError(f"type {typ!r} is not one of {', '.join(TYPES)}")
        a = addr.strip().upper()
        if typ == "BOOL":
            m = re.fullmatch(r"(SM|V|M|I|Q|S)(\d+)\.([0-7])", a)
            if not m:
                raise ValueError(f"{addr!r} is not a bit address (e.g. V116.0, I0.0, Q0.1)")
            area, off, bit = m.group(1), int(m.group(2)), int(m.group(3))
            size = 1
        else:
            w = {"BYTE": "B", "INT": "W", "WORD": "W", "DINT": "D", "DWORD": "D", "REAL": "D"}[typ]
            m = re.fullmatch(r"AC([0-3])", a)
            if m:
                n = int(m.group(1))
                return "AC", 4 * n + 4 - {"B": 1, "W": 2, "D": 4}[w], None
            m = re.fullmatch(r"(SM|V|M|I|Q|S)([BWD])(\d+)", a)
            if not m or m.group(2) != w:
                raise ValueError(f"{addr!r} is not a {typ} address (e.g. {_ADDR_EXAMPLE[typ]})")
            area, off, bit = m.group(1), int(m.group(3)), None
            size = {"B": 1, "W": 2, "D": 4}[w]
        n = len(self.mem[area])
        if off + size > n:
            raise ValueError(
                f"{addr} is beyond the {self.loaded.cpu.name}'s {area} memory "
                f"({area}B0-{area}B{n - 1})"
            )
        return area, off, bit

    def read(self, typ: str, addr: str):
        """The value at ``addr`` as ``typ`` (BOOL, BYTE, INT, WORD, DINT, DWORD, REAL)."""
        area, off, bit = self._addr(typ, addr)
        buf = self.mem[area]
        typ = typ.upper()
        if typ == "BOOL":
            return bool(buf[off] >> bit & 1)
        fmt = {"BYTE": _U8, "INT": _I16, "WORD": _U16, "DINT": _I32, "DWORD": _U32, "REAL": _F32}[
            typ
        ]
        return fmt.unpack_from(buf, off)[0]

    def write(self, typ: str, addr: str, value) -> None:
        """Store ``value`` at ``addr`` as ``typ`` (ValueError if it does not fit)."""
        area, off, bit = self._addr(typ, addr)
        buf = self.mem[area]
        typ = typ.upper()
        if typ == "BOOL":
            if value not in (0, 1, True, False):
                raise ValueError(f"{addr} = {value!r}: a BOOL is 0 or 1")
            buf[off] = (buf[off] | 1 << bit) if value else (buf[off] & ~(1 << bit) & 0xFF)
            return
        fmt = {"BYTE": _U8, "INT": _I16, "WORD": _U16, "DINT": _I32, "DWORD": _U32, "REAL": _F32}[
            typ
        ]
        try:
            if typ == "REAL":
                fmt.pack_into(buf, off, float(value))
            else:
                if isinstance(value, float) and not value.is_integer():
                    raise struct.error
                fmt.pack_into(buf, off, int(value))
        except (struct.error, OverflowError, ValueError):
            raise ValueError(f"{addr} = {value!r} does not fit a {typ}") from None

    # --- running ----------------------------------------------------------------------
    @property
    def stopped(self) -> bool:
        return self.fault is not None or self.stopped_by is not None

    def scan(self, n: int = 1) -> None:
        """Run ``n`` scans of the main program (nothing once the CPU is in STOP)."""
        for _ in range(n):
            if self.stopped:
                return
            sm = self.mem["SM"]
            t = self.scans * self.scan_ms
            b0 = 0x01 | (0x80)  # SM0.0 always on, SM0.7 RUN switch position
            if self._first:
                b0 |= 0x02 | 0x08  # SM0.1 first scan, SM0.3 power-up
            if (t % 60000.0) >= 30000.0:
                b0 |= 0x10  # SM0.4: 1 min clock
            if (t % 1000.0) >= 500.0:
                b0 |= 0x20  # SM0.5: 1 s clock
            if self.scans % 2:
                b0 |= 0x40  # SM0.6: scan clock
            sm[0] = b0
            self.s = 1 if self.fragment else 0
            self.depth = 0
            try:
                self._run("OB1")
            except _EndScan:
                pass
            except _Stop:
                pass
            self._first = False
            self.scans += 1
            if self.pto_scans is not None:
                for ch, p in enumerate(self.pto):
                    if p.busy:
                        p.scans += 1
                        if p.scans >= self.pto_scans:
                            self.pto_done(ch)

    def pto_done(self, ch: int) -> None:
        """The pulse train on channel ``ch`` (0: Q0.0, 1: Q0.1) has finished: the queued
        one starts, or the channel becomes idle (SM66.7 / SM76.7)."""
        p = self.pto[ch]
        sm = self.mem["SM"]
        idle = 66 + 10 * ch
        if p.queued is not None:
            p.log.append(p.queued)
            p.queued, p.scans = None, 0
            return
        p.busy = False
        sm[idle] |= 0x80

    def _run(self, key: str) -> None:
        code, _labels = self._code[key]
        pc, n = 0, len(code)
        loops, self._for = self._for, []  # FOR/NEXT loops are per block invocation
        try:
            while pc < n:
                r = code[pc]()
                pc = pc + 1 if r is None else r
        finally:
            self._for = loops

    # --- binding the compiled program to this CPU's memory ----------------------------
    def _bind(self, pou: _Pou):
        code = []
        for idx, (st, classes, opnds, builder) in enumerate(pou.code):
            fn = getattr(self, "_b_" + builder)(st, classes, opnds, pou, idx)
            code.append(fn)
        return code, pou.labels

    def _where(self, st: Stmt, pou: _Pou):
        return st.line, pou.block.label, st.network, st.text

    def _buf(self, o: _Opnd):
        """(callable returning the buffer, offset) of a memory operand."""
        if o.area == "L":
            frames = self.frames
            return (lambda: frames[self.depth]), o.off
        buf = self.mem[o.area if o.kind != "ac" else "AC"]
        return (lambda: buf), o.off

    def getter(self, o: _Opnd, t: str):
        """A function returning operand ``o`` read as type letter ``t``."""
        if o.kind == "const":
            v = o.value
            return lambda: v
        if o.kind == "bit":
            getb, off = self._buf(o)
            bit = o.bit
            if o.area == "L":
                return lambda: getb()[off] >> bit & 1
            buf = getb()
            return lambda: buf[off] >> bit & 1
        w = _WIDTH_OF.get(t, t)
        fmt = _FMT[w]
        if o.kind == "addr":
            v = _PTR_AREA[o.area] << 24 | o.off
            return lambda: v
        if o.kind == "ptr":
            pget = self.getter(o.ptr, "D")
            size = _SIZE[w]
            mem = self.mem

            def read_ptr():
                p = pget()
                area = _PTR_NAME.get(p >> 24)
                off = p & 0xFFFFFF
                if area is None or off + size > len(mem[area]):
                    raise _BadPointer(p)
                return fmt.unpack_from(mem[area], off)[0]

            return read_ptr
        off = o.off
        if o.kind == "ac":
            off = o.off + 4 - _SIZE[w]
        if o.area == "L":
            getb, _ = self._buf(o)
            unpack = fmt.unpack_from
            return lambda: unpack(getb(), off)[0]
        buf = self.mem["AC" if o.kind == "ac" else o.area]
        unpack = fmt.unpack_from
        return lambda: unpack(buf, off)[0]

    def setter(self, o: _Opnd, t: str):
        """A function storing a value of type letter ``t`` into operand ``o``; REAL values
        are rounded to binary32 (OverflowError beyond its range)."""
        if o.kind == "bit":
            getb, off = self._buf(o)
            bit = o.bit
            mask, inv = 1 << bit, ~(1 << bit) & 0xFF

            def set_bit(v):
                b = getb()
                b[off] = b[off] | mask if v else b[off] & inv

            return set_bit
        w = _WIDTH_OF.get(t, t)
        fmt = _FMT[w]
        if o.kind == "ptr":
            pget = self.getter(o.ptr, "D")
            size = _SIZE[w]
            mem = self.mem

            def write_ptr(v):
                p = pget()
                area = _PTR_NAME.get(p >> 24)
                off = p & 0xFFFFFF
                if area is None or off + size > len(mem[area]) or (area == "SM" and off < 30):
                    raise _BadPointer(p)
                fmt.pack_into(mem[area], off, v)

            return write_ptr
        off = o.off
        if o.kind == "ac":
            off = o.off + 4 - _SIZE[w]
        pack = fmt.pack_into
        if o.area == "L":
            getb, _ = self._buf(o)
            return lambda v: pack(getb(), off, v)
        buf = self.mem["AC" if o.kind == "ac" else o.area]
        return lambda v: pack(buf, off, v)

    # SM1.x status bits
    def _status(self, zero: bool, neg: bool) -> None:
        sm = self.mem["SM"]
        sm[1] = (sm[1] & ~0x0F) | (0x01 if zero else 0) | (0x04 if neg else 0)

    def _overflow(self, clear_div: bool = True) -> None:
        sm = self.mem["SM"]
        sm[1] = (sm[1] & ~(0x0F if clear_div else 0x07)) | 0x02
        self.eno = 0

    def _sm11(self) -> None:
        """An error of an instruction that affects SM1.1 only (ROUND, TRUNC, DTI, ITB: S2M
        p.115 lists no other SM bit): SM1.1 on, ENO = 0, the other bits as they were."""
        self.mem["SM"][1] |= 0x02
        self.eno = 0

    def _divzero(self) -> None:
        self.mem["SM"][1] |= 0x08
        self.eno = 0

    def _fatal(self, st, pou, reason) -> None:
        self.fault = Fault(reason, *self._where(st, pou))
        raise _Stop

    def _box(self, fn, st, pou):
        """Wrap a box body: runs with power flow, ENO = 0 when skipped, pointer faults."""
        cpu = self

        def run():
            if not cpu.s & 1:
                cpu.eno = 0
                return None
            try:
                fn()
            except _BadPointer as exc:
                # non-fatal error 0006: ENO = 0, nothing written (S2M: indirect address)
                cpu.eno = 0
                cpu.events.setdefault("bad pointer", 0)
                cpu.events["bad pointer"] += 1
                cpu.last_error = f"line {st.line}: bad pointer {exc.args[0]:#010x} (error 0006)"
            return None

        return run

    # --- builders: one per kind of instruction ----------------------------------------
    def _b_contact(self, st, classes, o, pou, idx):
        g = self.getter(o[0], "x")
        op = _CONTACT[st.op]
        if st.op.endswith("I") and o[0].area != "I":
            raise StlError(
                f"{st.op} (immediate) reads a physical input: its operand is I n.b",
                line=st.line,
                block=pou.block.label,
                network=st.network,
                text=st.text,
            )
        cpu = self
        if op == "LD":

            def f():
                cpu.s = ((cpu.s << 1) | g()) & 0x1FF
        elif op == "LDN":

            def f():
                cpu.s = ((cpu.s << 1) | (g() ^ 1)) & 0x1FF
        elif op == "A":

            def f():
                cpu.s &= ~1 | g()
        elif op == "AN":

            def f():
                cpu.s &= ~1 | (g() ^ 1)
        elif op == "O":

            def f():
                cpu.s |= g()
        elif op == "ON":

            def f():
                cpu.s |= g() ^ 1
        else:  # pragma: no cover - the table lists no other contact
            raise AssertionError(op)
        return f

    def _b_coil(self, st, classes, o, pou, idx):
        s = self.setter(o[0], "x")
        cpu = self

        def f():
            s(cpu.s & 1)

        return f

    def _b_setreset(self, st, classes, o, pou, idx):
        first, n = o[0], int(o[1].value)
        bits = []
        for k in range(n):
            b = first.bit + k
            bits.append(_Opnd("bit", first.area, first.off + b // 8, b % 8, text=first.text))
        res = _Resolver(self.loaded.cpu, pou.block, pou.frame)
        for b in bits:
            try:
                res.check_range(b.area, b.off, 1, first.text)
                if b.area == "SM":
                    res.check_writable(b.area, b.off, first.text)
            except ValueError as exc:
                raise StlError(
                    f"{st.op} {first.text}, {n}: {exc}",
                    line=st.line,
                    block=pou.block.label,
                    network=st.network,
                    text=st.text,
                ) from None
        setters = [self.setter(b, "x") for b in bits]
        v = 1 if st.op.startswith("S") else 0
        cpu = self

        def f():
            if cpu.s & 1:
                for s in setters:
                    s(v)

        return f

    def _b_stack(self, st, classes, o, pou, idx):
        cpu = self
        op = st.op
        if op == "NOT":

            def f():
                cpu.s ^= 1
        elif op == "ALD":

            def f():
                s = cpu.s
                cpu.s = ((s >> 1) & ~1) | (s & (s >> 1) & 1)
        elif op == "OLD":

            def f():
                s = cpu.s
                cpu.s = ((s >> 1) & ~1) | ((s | (s >> 1)) & 1)
        elif op == "LPS":

            def f():
                s = cpu.s
                cpu.s = ((s << 1) | (s & 1)) & 0x1FF
        elif op == "LRD":

            def f():
                s = cpu.s
                cpu.s = (s & ~1) | ((s >> 1) & 1)
        elif op == "LPP":

            def f():
                cpu.s >>= 1
        elif op == "LDS":
            n = o[0].value

            def f():
                s = cpu.s
                cpu.s = ((s << 1) | ((s >> n) & 1)) & 0x1FF
        elif op == "AENO":

            def f():
                cpu.s &= ~1 | cpu.eno
        else:  # NOP, WDR

            def f():
                return None

        return f

    def _b_edge(self, st, classes, o, pou, idx):
        cpu = self
        key = id(st)
        rising = st.op == "EU"

        def f():
            top = cpu.s & 1
            prev = cpu._edges.get(key)
            cpu._edges[key] = top
            if prev is None and cpu._first:
                prev = top  # the first scan records the state: no edge (SMART p.157)
            elif prev is None:
                prev = 0
            hit = (top and not prev) if rising else (prev and not top)
            cpu.s = (cpu.s & ~1) | (1 if hit else 0)

        return f

    def _b_compare(self, st, classes, o, pou, idx):
        t = classes[0]
        ga, gb = self.getter(o[0], t), self.getter(o[1], t)
        kind = st.op[:2] if st.op.startswith("LD") else st.op[0]
        cmp = st.op[3:] if kind == "LD" else st.op[2:]
        test = {
            "=": lambda a, b: a == b,
            "<>": lambda a, b: a != b,
            "<": lambda a, b: a < b,
            "<=": lambda a, b: a <= b,
            ">": lambda a, b: a > b,
            ">=": lambda a, b: a >= b,
        }[cmp]
        cpu = self
        real = t == "r"
        ftz = self.ftz

        def value():
            a, b = ga(), gb()
            if real:
                if a != a or b != b:
                    cpu._fatal(
                        st,
                        pou,
                        "NaN in a REAL compare: fatal error, the CPU goes to "
                        "STOP (S7-200 System Manual p.96)",
                    )
                if ftz:
                    a, b = _flush(a), _flush(b)
            return 1 if test(a, b) else 0

        if kind == "LD":

            def f():
                cpu.s = ((cpu.s << 1) | value()) & 0x1FF
        elif kind == "A":

            def f():
                cpu.s &= ~1 | value()
        else:

            def f():
                cpu.s |= value()

        return f

    def _b_move(self, st, classes, o, pou, idx):
        t = {"MOVB": "B", "MOVW": "W", "MOVD": "D", "MOVR": "D"}[st.op]
        if o[0].kind == "const" and st.op == "MOVR":
            v = _U32.unpack(_F32.pack(o[0].value))[0]
            g = lambda: v  # noqa: E731
        else:
            g = self.getter(o[0], t)
        s = self.setter(o[1], t)
        cpu = self

        def body():
            s(g())
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_blockmove(self, st, classes, o, pou, idx):
        w = _WIDTH_OF[classes[0]]
        size = _SIZE[w]
        src, dst, n = o
        gn = self.getter(n, "B")
        if src.kind not in ("mem",) or dst.kind not in ("mem",):
            raise StlError(
                f"{st.op}: IN and OUT are memory addresses",
                line=st.line,
                block=pou.block.label,
                network=st.network,
                text=st.text,
            )
        getsrc, soff = self._buf(src)
        getdst, doff = self._buf(dst)
        cpu = self

        def body():
            k = gn()
            if not 1 <= k <= 255:
                cpu._overflow()
                return
            sb, db = getsrc(), getdst()
            if soff + k * size > len(sb) or doff + k * size > len(db):
                cpu.eno = 0  # error 0091: operand out of range
                return
            db[doff : doff + k * size] = bytes(sb[soff : soff + k * size])
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_swap(self, st, classes, o, pou, idx):
        g, s = self.getter(o[0], "W"), self.setter(o[0], "W")
        cpu = self

        def body():
            v = g()
            s(((v & 0xFF) << 8) | (v >> 8))
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_math_r(self, st, classes, o, pou, idx):
        g_in, g_out = self.getter(o[0], "R"), self.getter(o[1], "R")
        s_out = self.setter(o[1], "R")
        op = st.op
        cpu = self
        ftz = self.ftz
        div = op == "/R"
        muldiv = op in ("*R", "/R")

        def body():
            a, b = g_out(), g_in()
            if ftz:
                a, b = _flush(a), _flush(b)
            if div and b == 0.0:
                cpu._divzero()
                return
            if not (math.isfinite(a) and math.isfinite(b)):
                cpu._overflow(muldiv)
                return
            r = a + b if op == "+R" else a - b if op == "-R" else a * b if op == "*R" else a / b
            cpu._store_real(s_out, r, muldiv, arith=True)

        return self._box(body, st, pou)

    def _store_real(self, s, r: float, clear_div: bool = False, arith: bool = False) -> None:
        try:
            r32 = _F32.unpack(_F32.pack(r))[0]
        except OverflowError:
            r32 = math.inf
        if not math.isfinite(r32):
            if arith:  # finite operands of + - * /, a result beyond the REAL range
                self.events["overflow"] += 1
            self._overflow(clear_div)
            return
        if r != 0.0 and abs(r) < _TINY:  # below the REAL range: denormal or 0 (IEEE)
            self.events["denormal"] += 1
            if self.ftz:
                r32 = 0.0
        s(r32)
        sm = self.mem["SM"]
        keep = 0x00 if clear_div else 0x08
        sm[1] = (sm[1] & keep) | (0x01 if r32 == 0.0 else 0) | (0x04 if r32 < 0.0 else 0)
        self.eno = 1

    def _b_func(self, st, classes, o, pou, idx):
        g, s = self.getter(o[0], "R"), self.setter(o[1], "R")
        fn = {
            "SQRT": math.sqrt,
            "LN": math.log,
            "EXP": math.exp,
            "SIN": math.sin,
            "COS": math.cos,
            "TAN": math.tan,
        }[st.op]
        cpu = self
        ftz = self.ftz
        op = st.op

        def body():
            x = g()
            if ftz:
                x = _flush(x)
            if not math.isfinite(x) or (op == "SQRT" and x < 0) or (op == "LN" and x <= 0):
                cpu._overflow(False)  # illegal input: SM1.1, output unaltered (S2M p.157)
                return
            try:
                r = fn(x)
            except (OverflowError, ValueError):
                cpu._overflow(False)
                return
            cpu._store_real(s, r)

        return self._box(body, st, pou)

    def _int_math(self, st, o, pou, t, bits):
        g_in, g_out = self.getter(o[0], t), self.getter(o[1], t)
        s_out = self.setter(o[1], t)
        lo, hi = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
        op = st.op[0]
        cpu = self

        def body():
            a, b = g_out(), g_in()
            if op == "/":
                if b == 0:
                    cpu._divzero()
                    return
                q = abs(a) // abs(b)
                r = -q if (a < 0) != (b < 0) else q
            else:
                r = a + b if op == "+" else a - b if op == "-" else a * b
            if not lo <= r <= hi:
                cpu._overflow(op in "*/")
                return
            s_out(r)
            cpu._status(r == 0, r < 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_math_i(self, st, classes, o, pou, idx):
        return self._int_math(st, o, pou, "I", 16)

    def _b_math_d(self, st, classes, o, pou, idx):
        return self._int_math(st, o, pou, "L", 32)

    def _b_mul(self, st, classes, o, pou, idx):
        g_in = self.getter(o[0], "I")
        g_out = self.getter(o[1], "L")
        s_out = self.setter(o[1], "L")
        cpu = self

        def body():
            low = g_out() & 0xFFFF
            low = low - 0x10000 if low & 0x8000 else low
            r = g_in() * low
            s_out(r)
            cpu._status(r == 0, r < 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_div(self, st, classes, o, pou, idx):
        g_in = self.getter(o[0], "I")
        g_out = self.getter(o[1], "L")
        s_out = self.setter(o[1], "L")
        cpu = self

        def body():
            a = g_out() & 0xFFFF
            a = a - 0x10000 if a & 0x8000 else a
            b = g_in()
            if b == 0:
                cpu._divzero()
                return
            q = abs(a) // abs(b)
            q = -q if (a < 0) != (b < 0) else q
            if not -32768 <= q <= 32767:
                cpu._overflow()
                return
            rem = a - q * b
            raw = ((rem & 0xFFFF) << 16) | (q & 0xFFFF)
            s_out(raw - (1 << 32) if raw & 0x80000000 else raw)
            cpu._status(q == 0, q < 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_incdec(self, st, classes, o, pou, idx):
        t = {"b": "B", "i": "I", "l": "L"}[classes[0][0]]
        g, s = self.getter(o[0], t), self.setter(o[0], t)
        step = 1 if st.op.startswith("INC") else -1
        lo, hi = {"B": (0, 255), "I": (-32768, 32767), "L": (-(2**31), 2**31 - 1)}[t]
        cpu = self

        def body():
            r = g() + step
            if not lo <= r <= hi:
                cpu._overflow(False)
                return
            s(r)
            cpu._status(r == 0, r < 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_logic(self, st, classes, o, pou, idx):
        t = _WIDTH_OF[classes[0][0]]
        g_in, g_out, s_out = self.getter(o[0], t), self.getter(o[1], t), self.setter(o[1], t)
        op = st.op[:-1]
        cpu = self

        def body():
            a, b = g_out(), g_in()
            r = a & b if op == "AND" else a | b if op == "OR" else a ^ b
            s_out(r)
            sm = cpu.mem["SM"]
            sm[1] = (sm[1] & ~0x01) | (0x01 if r == 0 else 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_invert(self, st, classes, o, pou, idx):
        t = _WIDTH_OF[classes[0][0]]
        g, s = self.getter(o[0], t), self.setter(o[0], t)
        mask = (1 << (8 * _SIZE[t])) - 1
        cpu = self

        def body():
            r = ~g() & mask
            s(r)
            sm = cpu.mem["SM"]
            sm[1] = (sm[1] & ~0x01) | (0x01 if r == 0 else 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_shift(self, st, classes, o, pou, idx):
        t = _WIDTH_OF[classes[0][0]]
        g, s = self.getter(o[0], t), self.setter(o[0], t)
        gn = self.getter(o[1], "B")
        nbits = 8 * _SIZE[t]
        mask = (1 << nbits) - 1
        kind = st.op[:2]
        cpu = self

        def body():
            v, n = g(), gn()
            last = 0
            if kind in ("SL", "SR"):
                n = min(n, nbits)  # manual: a shift count above the width shifts all bits out
                if n:
                    if kind == "SL":
                        last = (v >> (nbits - n)) & 1
                        v = (v << n) & mask
                    else:
                        last = (v >> (n - 1)) & 1
                        v >>= n
            else:
                n %= nbits
                if n:
                    if kind == "RL":
                        v = ((v << n) | (v >> (nbits - n))) & mask
                        last = v & 1
                    else:
                        v = ((v >> n) | (v << (nbits - n))) & mask
                        last = v >> (nbits - 1) & 1
            s(v)
            sm = cpu.mem["SM"]
            if n:
                sm[1] = (sm[1] & ~0x03) | (0x01 if v == 0 else 0) | (0x02 if last else 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_round(self, st, classes, o, pou, idx):
        g, s = self.getter(o[0], "R"), self.setter(o[1], "L")
        trunc = st.op == "TRUNC"
        cpu = self
        ftz = self.ftz

        def body():
            x = g()
            if ftz:
                x = _flush(x)
            if not math.isfinite(x):
                cpu._sm11()  # not a valid REAL: SM1.1, output not affected
                return
            if trunc:
                r = int(x)
            else:  # fraction >= 0.5 rounds up (S2M p.115), halves away from zero (assumed)
                r = math.floor(abs(x) + 0.5)
                r = -r if x < 0 else r
            if not -(2**31) <= r <= 2**31 - 1:
                cpu._sm11()
                return
            s(r)
            sm = cpu.mem["SM"]
            sm[1] &= ~0x02
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_convert(self, st, classes, o, pou, idx):
        src_t = _WIDTH_OF[classes[0][0]]
        dst_t = _WIDTH_OF[classes[1][0]]
        g, s = self.getter(o[0], src_t), self.setter(o[1], dst_t)
        op = st.op
        cpu = self

        def body():
            v = g()
            if op == "DTR":
                s(float(v))  # rounded to the nearest REAL
            elif op == "DTI" and not -32768 <= v <= 32767:
                cpu._sm11()
                return
            elif op == "ITB" and not 0 <= v <= 255:
                cpu._sm11()
                return
            else:
                s(v)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_jump(self, st, classes, o, pou, idx):
        target = pou.labels[o[0].value]
        cpu = self

        def f():
            return target if cpu.s & 1 else None

        return f

    def _b_label(self, st, classes, o, pou, idx):
        return lambda: None

    def _b_cret(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if cpu.s & 1:
                raise _Return

        return f

    def _b_end(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if cpu.s & 1:
                raise _EndScan

        return f

    def _b_stop(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if cpu.s & 1:
                cpu.stopped_by = f"STOP instruction at line {st.line} ({pou.block.label})"
                raise _Stop

        return f

    def _b_for(self, st, classes, o, pou, idx):
        s_idx = self.setter(o[0], "I")
        g_idx = self.getter(o[0], "I")
        g_init, g_final = self.getter(o[1], "I"), self.getter(o[2], "I")
        # the matching NEXT
        depth, end = 0, None
        for k in range(idx + 1, len(pou.code)):
            op = pou.code[k][0].op
            if op == "FOR":
                depth += 1
            elif op == "NEXT":
                if depth == 0:
                    end = k
                    break
                depth -= 1
        cpu = self

        def f():
            if not cpu.s & 1:
                cpu.eno = 0
                return end + 1
            init, final = g_init(), g_final()
            s_idx(init)
            cpu.eno = 1
            if init > final:
                return end + 1
            cpu._for.append((idx, g_idx, s_idx, g_final))
            return None

        return f

    def _b_next(self, st, classes, o, pou, idx):
        cpu = self

        def f():
            if not cpu._for:
                return None
            start, g_idx, s_idx, g_final = cpu._for[-1]
            v = g_idx() + 1
            if v > 32767 or v > g_final():
                cpu._for.pop()
                if v <= 32767:
                    s_idx(v)
                return None
            s_idx(v)
            return start + 1

        return f

    def _b_pls(self, st, classes, o, pou, idx):
        ch = o[0].value
        ctl, cnt, idle = 67 + 10 * ch, 72 + 10 * ch, 66 + 10 * ch
        sm = self.mem["SM"]
        p = self.pto[ch]
        cpu = self

        def body():
            c = sm[ctl]
            if not c & 0x80:  # enable bit cleared: abort the train
                if p.busy:
                    sm[idle] |= 0x20  # aborted by the user
                p.busy, p.queued = False, None
                sm[idle] |= 0x80
                cpu.eno = 1
                return
            if c & 0x40:
                cpu.eno = 1  # PWM is not modelled
                return
            n = _U32.unpack_from(sm, cnt)[0]
            if not p.busy:
                p.busy, p.scans = True, 0
                p.log.append(n)
                sm[idle] &= ~0x80
            elif p.queued is None:
                p.queued = n
            else:
                sm[idle] |= 0x40  # pipeline overflow
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_call(self, st, classes, o, pou, idx):
        key, target, params, ops = o
        cpu = self
        getters, setters = [], []
        for (section, _name, typ, off, bit), op in zip(params, ops, strict=True):
            t = {
                "BOOL": "x",
                "BYTE": "B",
                "WORD": "W",
                "INT": "I",
                "DWORD": "D",
                "DINT": "L",
                "REAL": "R",
            }[typ]
            if typ == "REAL" and op.kind == "const":
                v = op.value
                getters.append((section, off, bit, t, lambda v=v: v))
            else:
                getters.append((section, off, bit, t, self.getter(op, "x" if t == "x" else t)))
            setters.append(self.setter(op, "x" if t == "x" else t) if section != "IN" else None)
        if key is None:
            lib = self.loaded.libraries.get(target.upper()) or self.loaded.libraries[target]
            n_in = len(lib.inputs)

            def body():
                args = [g() for _, _, _, _, g in getters[:n_in]]
                outs = lib.fn(*args)
                outs = outs if isinstance(outs, tuple) else (outs,)
                for s, v in zip(setters[n_in:], outs, strict=True):
                    try:
                        s(_F32.unpack(_F32.pack(v))[0])
                    except OverflowError:
                        s(math.copysign(math.inf, v))
                cpu.eno = 1

            return self._box(body, st, pou)
        callee = self.loaded.pous[key]

        def body():
            if cpu.depth >= 8:
                cpu.eno = 0  # error 0008: maximum subroutine nesting exceeded
                cpu.events.setdefault("nesting", 0)
                cpu.events["nesting"] += 1
                return
            frame = cpu.frames[cpu.depth + 1]
            for (section, _off, _bit, t, g), (_, _, _, loff, lbit) in zip(
                getters, callee.params, strict=True
            ):
                if section == "OUT":
                    continue
                v = g()
                if t == "x":
                    frame[loff] = (
                        frame[loff] | (1 << lbit) if v else frame[loff] & ~(1 << lbit) & 0xFF
                    )
                else:
                    _FMT[t].pack_into(frame, loff, v)
            saved = cpu.s
            cpu.s = 1
            cpu.depth += 1
            try:
                cpu._run(key)
            except _Return:
                pass
            finally:
                cpu.depth -= 1
                cpu.s = saved
            for (section, _off, _bit, t, _), s, (_, _, _, loff, lbit) in zip(
                getters, setters, callee.params, strict=True
            ):
                if section == "IN":
                    continue
                if t == "x":
                    s(frame[loff] >> lbit & 1)
                else:
                    s(_FMT[t].unpack_from(frame, loff)[0])
            cpu.eno = 1

        return self._box(body, st, pou)


class _BadPointer(Exception):
    pass


_CONTACT = {
    "LD": "LD",
    "LDI": "LD",
    "A": "A",
    "AI": "A",
    "O": "O",
    "OI": "O",
    "LDN": "LDN",
    "LDNI": "LDN",
    "AN": "AN",
    "ANI": "AN",
    "ON": "ON",
    "ONI": "ON",
}


def _flush(x: float) -> float:
    return 0.0 if x != 0.0 and abs(x) < _TINY else x


_ADDR_EXAMPLE = {
    "BYTE": "VB0",
    "INT": "VW0",
    "WORD": "VW0",
    "DINT": "VD0",
    "DWORD": "VD0",
    "REAL": "VD0",
}

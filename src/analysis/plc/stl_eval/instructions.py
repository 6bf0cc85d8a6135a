"""The S7-200 instruction table: mnemonic -> (operand classes, builder, semantics source).

Each entry names the operand classes the loader checks (a letter for the data type: x bit,
b byte, w word, i INT, d double word, l DINT, r REAL, n a number; suffix ``>`` written,
``^`` read and written), the builder family that runs it (:mod:`.bit_logic`,
:mod:`.arithmetic`, :mod:`.program_control`, :mod:`.pulse_output`) and the page of the
manual that states its semantics. Sources: [S2M] the S7-200 Programmable Controller System
Manual (manualslib.com/manual/801761, its page numbers); [manualshelf] its older edition
C79000-G7076-C233-01 (manualshelf.com, page-NNN); [MWH] the STEP 7-Micro/WIN 32 help (its
file names); [SMART] the S7-200 SMART System Manual V2.3; "~" marks a rule assumed or taken
from a secondary source, not read in a manual page. :data:`REFUSED_OPS` are instructions
the CPU has and this evaluator does not model: refused with their line and the reason.
"""

from __future__ import annotations

__all__ = ["INSTRUCTIONS", "REFUSED_OPS", "instruction_table"]

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
_ins("WDR", (), "wdr", "MWH s7-27sz5.htm (Watchdog Reset retriggers the watchdog; cpu.spend)")
_ins("FOR", ("i>", "i", "i"), "for", "~ S7-200 FOR INDX, INIT, FINAL (page not retrieved)")
_ins("NEXT", (), "next", "~ S7-200 NEXT (page not retrieved)")
_ins(
    "PLS",
    ("n",),
    "pls",
    "MWH s7-24yeq.htm (PTO single segment, SMB67/SMB77, SMD72/SMD82, SM66.7/SM76.7)",
)

REFUSED_OPS = {
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

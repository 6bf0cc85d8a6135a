"""Translate S7-200 STL (STEP 7-Micro/WIN text) into S7-300 AWL for awlsim.

awlsim implements S7-300/400 semantics; the S7-200 is a different machine (a boolean logic
stack instead of an RLO, two-operand in-place math, V memory, SM bits, its own REAL error
rules). This translator maps a program instruction by instruction so that executing the
translation shows what the S7-200 text computes. The text is first read and checked by the
S7-200 evaluator's loader (:func:`analysis.plc.stl_eval.load_program`: one parser, one
operand check), so a program is refused with the same line, block, network and reason by
both; what the translation does not cover is refused the same way (:class:`StlError`).

Memory (:class:`Layout`, for the target CPU; CPU 224 by default)
    V n -> M n for the whole of the CPU's V memory (VB0-VB8191 on a CPU 224): a program's V
    addresses and the memory map's byte offsets are the same in both dialects. Everything
    else lives above it: SM, AC0-AC3, the process images I and Q, S, the S7-200 M area,
    then the translation's own bits and scratch (logic stacks, ENO, the first-scan and STOP
    bits, ROUND and CALL scratch, the PLS log). :func:`analysis.plc.runner.AwlRunner` sizes
    awlsim's M area to fit (its default is 2048 bytes).

=====================  ======================================================================
S7-200                 AWL
=====================  ======================================================================
SM0.0, "上电置1"        always on (the paper's symbol "power-on set 1" is read as SM0.0)
SM0.1, SM0.3           first scan (a bit set at the end of the first OB1 cycle)
logic stack            M bits per block (top of stack + 8 levels; LPS/LRD/LPP/ALD/OLD/LDS)
LD/A/O/N, =, S/R n     A/O on the TOS bit, = / S / R
EU / ED                FP / FN of the TOS bit, no edge in the first scan (as the S7-200)
LDB/LDW/LDD/LDR<op>    L a; L b; <op>I/D/R; = TOS; a NaN in a REAL compare stops an S7-200:
                       JUO sets the STOP bit and ends OB1
box instructions       run only with power flow: ``A TOS; JCN skip`` unless the TOS is known
                       to be SM0.0; an error (OV after the operation: NaN, infinity,
                       overflow, division by zero) skips the store, so the output keeps its
                       value as on the S7-200, and sets SM1.1 (SM1.3 for a division by
                       zero) when the program reads SM1 bits, ENO = 0 when it uses AENO
AENO                   TOS := TOS AND ENO (the ENO bit each box writes: not awlsim's OV)
MOVB/MOVW/MOVD/MOVR    L; T (REAL constants only into REAL operands: the loader refuses
                       ``MOVR 100, VD0``)
+R -R *R /R IN1, OUT   L OUT; L IN1; op; JO err; T OUT (OUT := OUT op IN1); /R tests the
                       divisor for 0 first (SM1.3)
+I -I *I /I, +D ..     the same with the INT/DINT instruction (awlsim sets OV on overflow)
SQRT/LN/EXP/SIN/COS/   L IN; op; JO err; T OUT
TAN IN, OUT
ROUND IN, OUT          exact S7-200 rule (TRUNC, then +-1 if |fraction| >= 0.5: halves away
                       from zero), not RND (ties to even); NaN, infinity or a value outside
                       DINT: SM1.1, OUT unchanged
TRUNC/DTR/ITD/DTI      TRUNC (JO err)/DTR/ITD/range-checked T
ANDx/ORx/XORx          AW/OW/XOW, AD/OD/XOD
INCW/DECW/INCD/DECD    +I/+D of 1 (overflow: unchanged)
JMP n / LBL n          JC Jn / Jn: (labels per block)
CALL SBRn|NAME, args   CALL FC n+1 (IN..., IN_OUT..., OUT... by position), by value: copied
                       through scratch memory (an AWL FC gets references)
CRET, END              A TOS; BEC (END: the first-scan bit is set first)
PLS n                  no PTO hardware in awlsim: logs SMB67, SMW68, SMD72, SMW168 (+10 for
                       PTO1) as they are when PLS runs (:meth:`Layout.pls_record`), and sets
                       the idle bit SM66.7 (enable bit off: SM66.5 if it was busy) or clears
                       it; :class:`analysis.plc.motion.engines.AwlsimEngine` runs the
                       System Manual's generator (:class:`~.stl_eval.PtoChannel`) on the log
                       after the scan and writes SMB66/76, SMB166/176 back
=====================  ======================================================================

Refused with the line (the evaluator runs them; awlsim has no counterpart here): indirect
addresses and pointers, direct L addresses (use the ``#names``), FOR/NEXT, STOP, BMx,
SWAP, MUL/DIV, shifts and rotates, INVx, INCB/DECB, BTI/ITB, SM0.2 and SM0.4-SM0.7 (clocks).

Known differences from the S7-200 that the translation cannot remove (awlsim's REAL unit,
observed on awlsim 0.77.1): a REAL overflow of finite operands saturates
to +-3.4028235E+38 without OV, so the store happens (the CPU sets SM1.1 and keeps OUT); a
denormal result is stored as 0 with OV, so the store is skipped (the CPU's handling is
unknown; the evaluator keeps IEEE's denormal); SIN/COS/TAN within 1e-7 of -1, 0 or 1 are
snapped. PLS: the runner's generator reads a profile table after the scan, the evaluator's
when PLS runs (a program that rewrites the table after its PLS in the same scan differs),
and the status a PLS leaves within its own scan is mirrored, not modelled (a PLS into a full
pipeline shows SM66.6 only from the next scan on). ``tests/plc/test_stl_machine.py``
compares the translation with the evaluator on
random programs outside those cases.

The AWL then goes through :func:`analysis.plc.peephole.optimize_awl` (``optimize=False``
keeps it literal): only the AWL that awlsim runs changes, not the S7-200 text, and nothing
observable does (that module's docstring says why).

The package: :mod:`.layout` (where each S7-200 area lives in M memory), :mod:`.emitter` (one
block's AWL: operands, the logic stack, box instructions), :mod:`.statements` (the table
mnemonic -> AWL); this module runs them over a loaded program.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from analysis.plc.peephole import optimize_awl
from analysis.plc.stl_eval.legacy import PAPER_SYMBOLS
from analysis.plc.stl_eval.loader import Loaded, load_program
from analysis.plc.stl_eval.syntax import StlError
from analysis.plc.translate.emitter import Emitter
from analysis.plc.translate.layout import (
    DEFAULT_LAYOUT,
    FIRST_SCAN_DONE,
    I_BASE,
    PLS_LOG,
    Q_BASE,
    SM_BASE,
    STOP_BIT,
    Layout,
)
from analysis.plc.translate.statements import emit_statement

__all__ = [
    "FIRST_SCAN_DONE",
    "I_BASE",
    "PLS_LOG",
    "Q_BASE",
    "SM_BASE",
    "STOP_BIT",
    "Layout",
    "Translation",
    "translate_s7200",
]


@dataclass(frozen=True)
class Translation:
    """AWL text, what the translation had to assume, and its memory layout."""

    awl: str
    notes: tuple[str, ...]
    layout: Layout = DEFAULT_LAYOUT


_AWL_TYPE = {
    "BOOL": "BOOL",
    "BYTE": "BYTE",
    "WORD": "WORD",
    "INT": "INT",
    "DWORD": "DWORD",
    "DINT": "DINT",
    "REAL": "REAL",
}


class _Translator:
    def __init__(self, loaded: Loaded, layout: Layout) -> None:
        self.loaded, self.layout = loaded, layout
        text = "\n".join(st.text for p in loaded.pous.values() for st in p.block.code)
        self.needs_sm1 = bool(re.search(r"\bSM1\.\d|\bSMB1\b|\bSMW0\b|\bSMD0\b", text.upper()))
        self._calls = {
            k: {o[0] for st, _, o, b in p.code if b == "call" and o[0]}
            for k, p in loaded.pous.items()
        }
        self.n_pous = len(loaded.pous)
        self.scratch_top = layout.logic + 4 * self.n_pous
        self._scratch: dict[str, int] = {}

    def calls_into(self, start: str, target: str) -> bool:
        seen, todo = set(), [start]
        while todo:
            k = todo.pop()
            if k == target:
                return True
            if k in seen:
                continue
            seen.add(k)
            todo += list(self._calls.get(k, ()))
        return False

    def call_scratch(self, key: str) -> int:
        if key not in self._scratch:
            self._scratch[key] = self.scratch_top
            self.scratch_top += 64
        return self._scratch[key]

    def note_scratch(self, end: int) -> None:
        pass


def translate_s7200(
    text: str, *, optimize: bool = True, cpu: str | None = None, symbols=None
) -> Translation:
    """Translate S7-200 STL text (Micro/WIN text form) into AWL for awlsim.

    Parameters
    ----------
    text : str
        ``ORGANIZATION_BLOCK ...:OB1`` and ``SUBROUTINE_BLOCK NAME:SBRn`` blocks.
    optimize : bool
        Remove reloads and overwritten stores (:func:`~.peephole.optimize_awl`).
    cpu : str, optional
        The S7-200 CPU (its V memory is translated whole; default CPU 224).
    symbols : dict, optional
        Global symbols (``上电置1`` is always read as SM0.0).

    Returns
    -------
    Translation
        ``awl`` source (FC n+1 per SBRn, OB1), notes and the memory :class:`Layout`.

    Raises
    ------
    StlError (a ValueError)
        Naming the line, block and network of an instruction or operand the S7-200 would
        not run or this translation does not cover.
    """
    loaded = load_program(text, symbols={**PAPER_SYMBOLS, **(symbols or {})}, cpu=cpu)
    layout = Layout.for_cpu(cpu)
    tr = _Translator(loaded, layout)
    notes: list[str] = []
    out: list[str] = [layout.header()]
    keys = [k for k in loaded.pous if k.startswith("SBR")] + ["OB1"]
    for k in loaded.pous:
        if k.startswith("INT"):
            raise StlError(
                "interrupt routines are not translated",
                line=loaded.pous[k].block.line,
                block=loaded.pous[k].block.label,
            )
    for idx, key in enumerate(keys):
        e = _block_body(tr, key, idx)
        b = loaded.pous[key].block
        out += _sbr_awl(b, e, layout) if b.kind == "SBR" else _ob1_awl(b, e, layout)
    awl = "\n".join(out)
    return Translation(optimize_awl(awl) if optimize else awl, tuple(notes), layout)


def _block_body(tr: _Translator, key: str, idx: int) -> Emitter:
    """The AWL of one block's statements (an :class:`Emitter` holding them)."""
    pou = tr.loaded.pous[key]
    e = Emitter(tr, key, idx)
    if pou.block.kind == "SBR":
        e.i("SET")
        e.i("=", e.tos)  # a called subroutine starts with the top of stack on
    for st, classes, o, builder in pou.code:
        try:
            emit_statement(e, st, classes, o, builder)
        except StlError:
            raise
        except ValueError as exc:
            raise StlError(
                str(exc), line=st.line, block=pou.block.label, network=st.network, text=st.text
            ) from None
    e.flush_labels()
    return e


def _sbr_awl(b, e: Emitter, layout: Layout) -> list[str]:
    """A subroutine SBRn as FC n+1 with its interface."""
    out = [
        f"FUNCTION FC {b.number + 1} : VOID",
        f"TITLE = {b.name} (S7-200 SBR{b.number})",
    ]
    for section, kw in (
        ("IN", "VAR_INPUT"),
        ("IN_OUT", "VAR_IN_OUT"),
        ("OUT", "VAR_OUTPUT"),
        ("TEMP", "VAR_TEMP"),
    ):
        names = [v for v in b.vars if v.section == section]
        if names:
            out += [kw, *(f"  {v.name} : {_AWL_TYPE[v.type]};" for v in names), "END_VAR"]
    out.append("BEGIN")
    out += e.out
    out += ["      BEU"]
    if e.nan_used:
        out += ["NAN:  SET", f"      S     {e.bit(layout.stop_bit)}", "      BEU"]
    out += ["END_FUNCTION", ""]
    return out


def _ob1_awl(b, e: Emitter, layout: Layout) -> list[str]:
    """The main program as OB1 (skipped once the STOP bit is set)."""
    if any(v.section == "TEMP" for v in b.vars):
        raise StlError("main program locals are not translated", line=b.line, block=b.label)
    out = [
        "ORGANIZATION_BLOCK OB 1",
        f"TITLE = {b.name} (translated from S7-200 STL)",
        "BEGIN",
        f"      A     {e.bit(layout.stop_bit)}",
        "      BEC",
    ]
    out += e.out
    out += [
        "MEND: SET",
        f"      S     {e.bit(layout.first_scan_done)}",
        "      BEU",
    ]
    out += ["NAN:  SET", f"      S     {e.bit(layout.stop_bit)}", "      BEU"]
    out += ["END_ORGANIZATION_BLOCK", ""]
    return out

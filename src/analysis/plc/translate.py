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
PLS n                  no PTO hardware: logs the pulse count SMD72/SMD82 and clears the idle
                       bit SM66.7/SM76.7 (a test sets it again to model "train done")
=====================  ======================================================================

Refused with the line (the evaluator runs them; awlsim has no counterpart here): indirect
addresses and pointers, direct L addresses (use the ``#names``), FOR/NEXT, STOP, BMx,
SWAP, MUL/DIV, shifts and rotates, INVx, INCB/DECB, BTI/ITB, SM0.2 and SM0.4-SM0.7 (clocks).

Known differences from the S7-200 that the translation cannot remove (awlsim's REAL unit,
observed on awlsim 0.77.1): a REAL overflow of finite operands saturates
to +-3.4028235E+38 without OV, so the store happens (the CPU sets SM1.1 and keeps OUT); a
denormal result is stored as 0 with OV, so the store is skipped (the CPU's handling is
unknown; the evaluator keeps IEEE's denormal); SIN/COS/TAN within 1e-7 of -1, 0 or 1 are
snapped. ``tests/plc/test_stl_machine.py`` compares the translation with the evaluator on
random programs outside those cases.

The AWL then goes through :func:`analysis.plc.peephole.optimize_awl` (``optimize=False``
keeps it literal): only the AWL that awlsim runs changes, not the S7-200 text, and nothing
observable does (that module's docstring says why).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from analysis.plc.memmap import CPUS, DEFAULT_CPU
from analysis.plc.peephole import optimize_awl
from analysis.plc.stl_eval.legacy import PAPER_SYMBOLS
from analysis.plc.stl_eval.machine import Loaded, _Opnd, load_program
from analysis.plc.stl_eval.syntax import StlError

__all__ = [
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
class Layout:
    """Where a translation keeps each S7-200 area in awlsim's M memory (module docstring).

    ``byte(area, n)`` is the M byte of S7-200 ``area`` byte ``n`` (``"V"``, ``"SM"``,
    ``"AC"`` (4 bytes per accumulator), ``"I"``, ``"Q"``, ``"S"``, ``"M"``).
    """

    cpu: str
    v: int
    sm: int
    ac: int
    i: int
    q: int
    s: int
    m: int
    first_scan_done: tuple[int, int]
    stop_bit: tuple[int, int]
    eno: tuple[int, int]
    cmp_scratch: tuple[int, int]
    round_scratch: int
    pls_log: int
    logic: int

    @classmethod
    def for_cpu(cls, cpu: str | None = None) -> Layout:
        c = CPUS[cpu or DEFAULT_CPU["s7-200"]]
        if c.dialect != "s7-200":
            raise ValueError(f"{c.name} is not an S7-200 CPU")
        v = c.areas["V"]
        sm = v
        ac = sm + c.areas["SM"]
        i = ac + 16
        q = i + c.areas["I"]
        s = q + c.areas["Q"]
        m = s + c.areas["S"]
        bits = m + c.areas["M"]  # one byte of the translation's own bits
        round_scratch = bits + 4  # 3 double words
        pls = round_scratch + 12  # MD pls: channel 0 count, +4 channel 1, MW +12/+14 counts
        logic = pls + 16  # 4 bytes per block
        return cls(
            c.name,
            v,
            sm,
            ac,
            i,
            q,
            s,
            m,
            (bits, 0),
            (bits, 1),
            (bits, 2),
            (bits, 7),
            round_scratch,
            pls,
            logic,
        )

    def byte(self, area: str, n: int) -> int:
        if area == "V":
            return n
        return {"SM": self.sm, "AC": self.ac, "I": self.i, "Q": self.q, "S": self.s, "M": self.m}[
            area
        ] + n

    def header(self) -> str:
        """The AWL comment the runner reads (M area size and STOP bit)."""
        return (
            f"// analysis.plc.translate: {self.cpu}; STOP bit M {self.stop_bit[0]}."
            f"{self.stop_bit[1]}"
        )


_DEFAULT = Layout.for_cpu()
SM_BASE = _DEFAULT.sm
"""M byte of SMB0 in a translation for the default CPU (CPU 224)."""
I_BASE = _DEFAULT.i
Q_BASE = _DEFAULT.q
PLS_LOG = _DEFAULT.pls_log
STOP_BIT = _DEFAULT.stop_bit
FIRST_SCAN_DONE = _DEFAULT.first_scan_done


@dataclass(frozen=True)
class Translation:
    """AWL text, what the translation had to assume, and its memory layout."""

    awl: str
    notes: tuple[str, ...]
    layout: Layout = _DEFAULT


_AWL_TYPE = {
    "BOOL": "BOOL",
    "BYTE": "BYTE",
    "WORD": "WORD",
    "INT": "INT",
    "DWORD": "DWORD",
    "DINT": "DINT",
    "REAL": "REAL",
}
_CMP = {"=": "==", "<>": "<>", "<": "<", "<=": "<=", ">": ">", ">=": ">="}
_MATH = {
    "+R": "+R",
    "-R": "-R",
    "*R": "*R",
    "/R": "/R",
    "+I": "+I",
    "-I": "-I",
    "*I": "*I",
    "/I": "/I",
    "+D": "+D",
    "-D": "-D",
    "*D": "*D",
    "/D": "/D",
}
_LOGIC = {
    "ANDB": "AW",
    "ORB": "OW",
    "XORB": "XOW",
    "ANDW": "AW",
    "ORW": "OW",
    "XORW": "XOW",
    "ANDD": "AD",
    "ORD": "OD",
    "XORD": "XOD",
}
_FUNC = {"SQRT": "SQRT", "LN": "LN", "EXP": "EXP", "SIN": "SIN", "COS": "COS", "TAN": "TAN"}
_NOT_TRANSLATED = {
    "FOR": "FOR/NEXT loops are not translated",
    "NEXT": "FOR/NEXT loops are not translated",
    "STOP": "STOP is not translated",
    "BMB": "block moves are not translated",
    "BMW": "block moves are not translated",
    "BMD": "block moves are not translated",
    "SWAP": "SWAP is not translated",
    "MUL": "MUL is not translated",
    "DIV": "DIV is not translated",
    "INVB": "INVB is not translated",
    "INVW": "INVW is not translated",
    "INVD": "INVD is not translated",
    "INCB": "INCB/DECB (unsigned byte arithmetic) are not translated",
    "DECB": "INCB/DECB (unsigned byte arithmetic) are not translated",
    "BTI": "BTI is not translated",
    "ITB": "ITB is not translated",
    "WDR": "WDR is not translated",
    **{
        k: "shifts and rotates are not translated"
        for k in ("SLB SRB RLB RRB SLW SRW RLW RRW SLD SRD RLD RRD".split())
    },
}


def _fmt_real(v: float) -> str:
    from analysis.plc.printer import fmt_real

    return fmt_real(v)


class _Emitter:
    """The AWL of one block."""

    def __init__(self, tr: _Translator, key: str, index: int) -> None:
        self.tr, self.key = tr, key
        self.pou = tr.loaded.pous[key]
        self.lay = tr.layout
        base = self.lay.logic + 4 * index
        self.tos = f"M {base}.0"
        self.stack = [f"M {base + (k + 1) // 8}.{(k + 1) % 8}" for k in range(8)]
        self.edge_base = base + 2
        self.n_edge = 0
        ops = [st.op for st, *_ in self.pou.code]
        self.uses_stack = any(op in ("LPS", "LRD", "LPP", "ALD", "OLD", "LDS") for op in ops)
        self.needs_eno = "AENO" in ops
        self.always = False
        self.always_stack = [False] * 8
        self.out: list[str] = []
        self.n_lab = 0
        self.pending: list[str] = []
        self.nan_used = False

    # --- output --------------------------------------------------------------------
    def i(self, op: str, arg: str = "") -> None:
        text = f"{op:<6}{arg}".rstrip()
        if self.pending:
            lab = self.pending.pop()
            for extra in self.pending:  # several labels at one place: chain with NOPs
                self.out.append(f"{extra}: NOP   0")
            self.pending = []
            self.out.append(f"{lab}: {text}")
        else:
            self.out.append(f"      {text}")

    def label(self) -> str:
        self.n_lab += 1
        return f"S{self.n_lab:03d}"

    def place(self, lab: str) -> None:
        """Attach ``lab`` to the next instruction (no NOP on the straight path)."""
        self.pending.append(lab)

    def flush_labels(self) -> None:
        for lab in self.pending:
            self.out.append(f"{lab}: NOP   0")
        self.pending = []

    def bit(self, b: tuple[int, int]) -> str:
        return f"M {b[0]}.{b[1]}"

    # --- operands --------------------------------------------------------------------
    def opnd(self, o: _Opnd, width: str | None = None) -> str:
        """AWL text of an operand read or written as ``width`` (B, W, D)."""
        if o.kind == "const":
            v = o.value
            if isinstance(v, float):
                return _fmt_real(v)
            if width == "B":
                return f"B#16#{v & 0xFF:02X}"
            if width == "W":
                return str(v) if -32768 <= v <= 32767 else f"W#16#{v & 0xFFFF:04X}"
            return f"L#{v}" if -(2**31) <= v < 2**31 else f"DW#16#{v & 0xFFFFFFFF:08X}"
        if o.kind in ("ptr", "addr"):
            raise ValueError(f"{o.text}: indirect addresses and pointers are not translated")
        if o.area == "L":
            if not o.text.startswith("#"):
                raise ValueError(
                    f"{o.text}: direct L addresses are not translated (use the #local names)"
                )
            return o.text
        if o.kind == "ac":
            base = self.lay.ac + o.off
            w = width or "D"
            return {"B": f"MB {base + 3}", "W": f"MW {base + 2}", "D": f"MD {base}"}[w]
        n = self.lay.byte(o.area, o.off)
        if o.kind == "bit":
            return f"M {n}.{o.bit}"
        w = {"B": "B", "W": "W", "I": "W", "D": "D", "L": "D", "R": "D"}[o.width]
        return f"M{w} {n}"

    def bit_src(self, o: _Opnd):
        """("always"|"first"|text) of a bit operand read by a contact."""
        if o.area == "SM" and o.off == 0:
            if o.bit == 0:
                return "always"
            if o.bit in (1, 3):
                return "first"
            raise ValueError(
                f"{o.text}: the SM0 clock and status bits are not translated (only SM0.0, "
                "SM0.1, SM0.3)"
            )
        return self.opnd(o)

    # --- logic stack -------------------------------------------------------------------
    def push(self) -> None:
        if self.uses_stack:
            for k in range(7, 0, -1):
                self.i("A", self.stack[k - 1])
                self.i("=", self.stack[k])
            self.i("A", self.tos)
            self.i("=", self.stack[0])
            self.always_stack = [self.always, *self.always_stack[:-1]]

    def pop(self) -> None:
        if self.uses_stack:
            for k in range(7):
                self.i("A", self.stack[k + 1])
                self.i("=", self.stack[k])
            self.i("CLR")
            self.i("=", self.stack[7])
            self.always_stack = [*self.always_stack[1:], False]

    def load_bit(self, o: _Opnd, negate: bool, combine: str | None) -> None:
        src = self.bit_src(o)
        first_done = self.bit(self.lay.first_scan_done)
        if src == "always":
            if combine is None:
                self.i("CLR" if negate else "SET")
                self.i("=", self.tos)
                self.always = not negate
                return
            if (combine == "A" and not negate) or (combine == "O" and negate):
                return  # A SM0.0 and O of its negation change nothing
            self.i("CLR" if combine == "A" else "SET")
            self.i("=", self.tos)
            self.always = combine == "O"
            return
        if combine is not None:
            self.i("A", self.tos)
        op = {None: "A", "A": "A", "O": "O"}[combine]
        if src == "first":
            self.i(op + ("" if negate else "N"), first_done)
        else:
            self.i(op + ("N" if negate else ""), src)
        self.i("=", self.tos)
        self.always = False

    def compare(self, kind: str, cmp: str, a: _Opnd, b: _Opnd, combine: str | None) -> None:
        w = {"B": "B", "W": "W", "D": "D", "R": "D"}[kind]
        self.i("L", self.opnd(a, w))
        self.i("L", self.opnd(b, w))
        self.i(_CMP[cmp] + {"R": "R", "D": "D", "B": "I", "W": "I"}[kind])
        scratch = self.tos if combine is None else self.bit(self.lay.cmp_scratch)
        self.i("=", scratch)
        if kind == "R":
            self.i("JUO", "NAN")
            self.nan_used = True
        if combine is not None:
            self.i("A", self.tos)
            self.i(combine, scratch)
            self.i("=", self.tos)
        self.always = False

    # --- box instructions ----------------------------------------------------------------
    def eno(self, value: bool) -> None:
        if self.needs_eno:
            self.i("SET" if value else "CLR")
            self.i("=", self.bit(self.lay.eno))

    def box(self, body) -> None:
        """Emit a box instruction. ``body(fail)`` emits its straight path; ``fail(bits)``
        returns a label to jump to on an error, whose path sets the SM1 ``bits`` (when the
        program reads SM1) and ENO = 0 (when it uses AENO); the output is not written."""
        skip = None
        if not self.always:
            skip = self.label()
            self.i("A", self.tos)
            self.i("JCN", skip)
        fails: list[tuple[str, dict]] = []

        def fail(bits: dict) -> str:
            lab = self.label()
            fails.append((lab, bits))
            return lab

        body(fail)
        self.eno(True)
        work = self.needs_eno or (self.tr.needs_sm1 and any(b for _, b in fails))
        if not work:
            for lab, _ in fails:
                self.place(lab)
            if skip:
                self.place(skip)
            return
        done, off = self.label(), self.label()
        self.i("JU", done)
        for lab, bits in fails:
            self.place(lab)
            if self.tr.needs_sm1 and bits:
                self.sm1(bits)
                self.i("JU", off)
        self.place(off)
        if skip:
            self.place(skip)
        self.eno(False)
        self.place(done)

    def sm1(self, bits: dict[int, object]) -> None:
        """Write SM1 bits (True/False, or "RLO" for the result of the compare just made)."""
        if not self.tr.needs_sm1:
            return
        for b, v in bits.items():
            dst = f"M {self.lay.sm + 1}.{b}"
            if v == "RLO":
                self.i("=", dst)
            else:
                self.i("SET")
                self.i("S" if v else "R", dst)

    def math_status(self, real: bool, dst: str, wide: bool, div: bool = False) -> None:
        """SM1.0 zero, SM1.2 negative of the value just stored at ``dst``; SM1.1 (and for
        a division SM1.3) off."""
        if not self.tr.needs_sm1:
            return
        zero = "0.0" if real else ("L#0" if wide else "0")
        cmp = "R" if real else ("D" if wide else "I")
        self.i("L", dst)
        self.i("L", zero)
        self.i("==" + cmp)
        self.sm1({0: "RLO"})
        self.i("L", dst)
        self.i("L", zero)
        self.i("<" + cmp)
        self.sm1({2: "RLO", 1: False, **({3: False} if div else {})})

    def math(self, st, o) -> None:
        op = st.op
        real = op.endswith("R")
        wide = op.endswith(("R", "D"))
        w = "D" if wide else "W"
        src, dst = self.opnd(o[0], w), self.opnd(o[1], w)
        div = op[0] == "/"
        muldiv = op[0] in "*/"
        overflow = {1: True, 0: False, 2: False, **({3: False} if muldiv else {})}

        def body(fail):
            if div:  # division by zero: SM1.3, nothing else changes (S2M p.154)
                self.i("L", src)
                if real:  # +-0.0 by its bits (awlsim's ==R also calls a denormal zero)
                    self.i("L", "DW#16#7FFFFFFF")
                    self.i("AD")
                    self.i("JZ", fail({3: True}))
                    # an infinite or NaN divisor is an illegal input (awlsim: x/inf = 0)
                    self.i("L", "DW#16#7F800000")
                    self.i(">=D")
                    self.i("JC", fail(overflow))
                else:
                    self.i("L", "L#0" if wide else "0")
                    self.i("==D" if wide else "==I")
                    self.i("JC", fail({3: True}))
            self.i("L", dst)
            self.i("L", src)
            self.i(_MATH[op])
            self.i("JO", fail(overflow))
            self.i("T", dst)
            self.math_status(real, dst, wide, muldiv)

        self.box(body)

    # --- one statement ---------------------------------------------------------------------
    def emit(self, st, classes, o, builder) -> None:
        op = st.op
        self.out.append(f"      // {st.text}")
        if op in _NOT_TRANSLATED:
            raise ValueError(_NOT_TRANSLATED[op])
        if builder == "contact":
            base = {"LDI": "LD", "LDNI": "LDN", "AI": "A", "ANI": "AN", "OI": "O", "ONI": "ON"}.get(
                op, op
            )
            if base in ("LD", "LDN"):
                self.push()
                self.load_bit(o[0], base == "LDN", None)
            else:
                self.load_bit(o[0], base.endswith("N"), base[0])
        elif builder == "compare":
            m = re.match(r"^(LD|A|O)([BWDR])(.+)$", op)
            if m.group(1) == "LD":
                self.push()
            self.compare(
                m.group(2), m.group(3), o[0], o[1], None if m.group(1) == "LD" else m.group(1)
            )
        elif op == "NOT":
            self.i("AN", self.tos)
            self.i("=", self.tos)
            self.always = False
        elif op == "AENO":
            self.i("A", self.tos)
            self.i("A", self.bit(self.lay.eno))
            self.i("=", self.tos)
            self.always = False
        elif op in ("EU", "ED"):
            edge = f"M {self.edge_base + self.n_edge // 8}.{self.n_edge % 8}"
            self.n_edge += 1
            if self.n_edge > 16:
                raise ValueError("more than 16 EU/ED in one block are not translated")
            self.i("A", self.tos)
            self.i("FP" if op == "EU" else "FN", edge)
            self.i("A", self.bit(self.lay.first_scan_done))  # no edge in the first scan
            self.i("=", self.tos)
            self.always = False
        elif op == "LPS":
            keep = self.always
            self.push()
            self.always = keep
        elif op in ("LRD", "LPP"):
            self.i("A", self.stack[0])
            self.i("=", self.tos)
            self.always = self.always_stack[0]
            if op == "LPP":
                self.pop()
        elif op in ("ALD", "OLD"):
            self.i("A", self.tos)
            self.i("A" if op == "ALD" else "O", self.stack[0])
            self.i("=", self.tos)
            self.always = False
            self.pop()
        elif op == "LDS":
            n = o[0].value
            known = self.always_stack[n - 1]  # level n's "known on" flag, before the push
            self.i("A", self.stack[n - 1])
            self.i("=", self.bit(self.lay.cmp_scratch))
            self.push()
            self.i("A", self.bit(self.lay.cmp_scratch))
            self.i("=", self.tos)
            self.always = known
        elif op == "NOP":
            pass
        elif builder == "coil":
            self.i("A", self.tos)
            self.i("=", self.opnd(o[0]))
        elif builder == "setreset":
            first, n = o[0], int(o[1].value)
            for k in range(n):
                b = first.bit + k
                bit = _Opnd("bit", first.area, first.off + b // 8, b % 8, text=first.text)
                self.i("A", self.tos)
                self.i("S" if op.startswith("S") else "R", self.opnd(bit))
        elif op == "JMP":
            lab = f"J{o[0].value:03d}"
            if self.always:
                self.i("JU", lab)
            else:
                self.i("A", self.tos)
                self.i("JC", lab)
        elif op == "LBL":
            self.place(f"J{o[0].value:03d}")
            self.always = False
        elif op == "CRET":
            self.i("A", self.tos)
            self.i("BEC")
        elif op == "END":
            self.i("A", self.tos)
            self.i("JC", "MEND")
        elif builder == "move":
            w = {"MOVB": "B", "MOVW": "W", "MOVD": "D", "MOVR": "D"}[op]

            def body(fail):
                self.i("L", self.opnd(o[0], w))
                self.i("T", self.opnd(o[1], w))

            self.box(body)
        elif builder in ("math_r", "math_i", "math_d"):
            self.math(st, o)
        elif builder == "func":
            src, dst = self.opnd(o[0], "D"), self.opnd(o[1], "D")

            def body(fail):
                err = fail({1: True, 0: False, 2: False})
                if op == "EXP":  # EXP(-inf) = 0 without OV on awlsim: an illegal input here
                    self.i("L", src)
                    self.i("L", "DW#16#7F800000")
                    self.i("AD")
                    self.i("L", "DW#16#7F800000")
                    self.i("==D")
                    self.i("JC", err)
                self.i("L", src)
                self.i(_FUNC[op])
                self.i("JO", err)
                self.i("T", dst)
                self.math_status(True, dst, True)

            self.box(body)
        elif builder == "logic":
            w = {"B": "B", "W": "W", "D": "D"}[op[-1]]
            src, dst = self.opnd(o[0], w), self.opnd(o[1], w)

            def body(fail):
                self.i("L", dst)
                self.i("L", src)
                self.i(_LOGIC[op])
                self.i("T", dst)
                if self.tr.needs_sm1:
                    self.i("L", dst)
                    self.i("L", "L#0" if w == "D" else "0")
                    self.i("==D" if w == "D" else "==I")
                    self.sm1({0: "RLO"})

            self.box(body)
        elif builder == "incdec":
            w = {"W": "W", "D": "D"}[op[-1]]
            dst = self.opnd(o[0], w)

            def body(fail):
                self.i("L", dst)
                self.i("L", "L#1" if w == "D" else "1")
                self.i(("+" if op.startswith("INC") else "-") + ("D" if w == "D" else "I"))
                self.i("JO", fail({1: True, 0: False, 2: False}))
                self.i("T", dst)
                self.math_status(False, dst, w == "D")

            self.box(body)
        elif op in ("ROUND", "TRUNC"):
            src, dst = self.opnd(o[0], "D"), self.opnd(o[1], "D")

            def body(fail):
                err = fail({1: True})  # not a valid REAL, or beyond DINT (S2M p.115)
                if op == "TRUNC":
                    self.i("L", src)
                    self.clear_ov()
                    self.i("TRUNC")
                    self.i("JO", err)
                    self.i("T", dst)
                else:
                    self.round(src, dst, err)
                self.sm1({1: False})

            self.box(body)
        elif op in ("DTR", "ITD"):
            src = self.opnd(o[0], "D" if op == "DTR" else "W")
            dst = self.opnd(o[1], "D")

            def body(fail):
                self.i("L", src)
                self.i(op)
                self.i("T", dst)

            self.box(body)
        elif op == "DTI":
            src, dst = self.opnd(o[0], "D"), self.opnd(o[1], "W")

            def body(fail):
                err = fail({1: True})
                self.i("L", src)
                self.i("L", "L#32767")
                self.i(">D")
                self.i("JC", err)
                self.i("L", src)
                self.i("L", "L#-32768")
                self.i("<D")
                self.i("JC", err)
                self.i("L", src)
                self.i("T", dst)

            self.box(body)
        elif op == "CALL":
            self.box(lambda fail: self.call(st, o))
        elif op == "PLS":
            ch = o[0].value
            lay = self.lay

            def body(fail):
                self.i("L", f"MD {lay.sm + 72 + 10 * ch}")
                self.i("T", f"MD {lay.pls_log + 4 * ch}")
                self.i("L", f"MW {lay.pls_log + 12 + 2 * ch}")
                self.i("+", "1")
                self.i("T", f"MW {lay.pls_log + 12 + 2 * ch}")
                self.i("SET")
                self.i("R", f"M {lay.sm + 66 + 10 * ch}.7")

            self.box(body)
        else:
            raise ValueError(f"{op} is not translated")

    def clear_ov(self) -> None:
        """OV := 0, ACCU1 unchanged (awlsim's TRUNC sets OV on an error but never clears
        it): ACCU1 + 0 as a DINT, which cannot overflow."""
        self.i("L", "L#0")
        self.i("+D")

    def round(self, src: str, dst: str, err: str) -> None:
        """S7-200 ROUND: TRUNC, then +-1 if |fraction| >= 0.5 (halves away from zero)."""
        r = self.lay.round_scratch
        d, t, f = f"MD {r}", f"MD {r + 4}", f"MD {r + 8}"
        l1, l2 = self.label(), self.label()
        self.i("L", src)
        self.clear_ov()
        for ins in (
            ("TRUNC",),
            ("JO", err),
            ("T", d),
            ("L", d),
            ("DTR",),
            ("T", t),
            ("L", src),
            ("L", t),
            ("-R",),
            ("T", f),
            ("L", f),
            ("L", "0.5"),
            (">=R",),
            ("JCN", l1),
            ("L", d),
            ("L", "L#1"),
            ("+D",),
            ("JO", err),
            ("T", d),
        ):
            self.i(*ins)
        self.place(l1)
        for ins in (
            ("L", f),
            ("L", "-0.5"),
            ("<=R",),
            ("JCN", l2),
            ("L", d),
            ("L", "L#1"),
            ("-D",),
            ("JO", err),
            ("T", d),
        ):
            self.i(*ins)
        self.place(l2)
        self.i("L", d)
        self.i("T", dst)

    def call(self, st, o) -> None:
        key, target, params, ops = o
        if key is None:
            raise ValueError(f"{target} is a library subroutine: not translated")
        callee = self.tr.loaded.pous[key]
        if self.tr.calls_into(key, self.key):
            raise ValueError("recursive calls are not translated")
        scratch = self.tr.call_scratch(self.key)
        binds = []
        copies_out = []
        byte = scratch
        bitpos = None
        for (section, name, typ, _, _), a in zip(params, ops, strict=True):
            if typ == "BOOL":
                if bitpos is None or bitpos == 8:
                    bitpos, bbyte = 0, byte
                    byte += 1
                slot = f"M {bbyte}.{bitpos}"
                bitpos += 1
            else:
                bitpos = None
                size = {"BYTE": 1, "WORD": 2, "INT": 2}.get(typ, 4)
                slot = f"M{'B' if size == 1 else 'W' if size == 2 else 'D'} {byte}"
                byte += size
            w = {"BYTE": "B", "WORD": "W", "INT": "W"}.get(typ, "D")
            if section != "OUT":
                if typ == "BOOL":
                    if a.kind == "const":
                        raise ValueError("a constant BOOL parameter is not translated")
                    self.i("A", self.opnd(a))
                    self.i("=", slot)
                else:
                    self.i("L", self.opnd(a, w))
                    self.i("T", slot)
            if section != "IN":
                copies_out.append((slot, a, typ, w))
            binds.append(f"{name} := {slot}")
        self.tr.note_scratch(byte)
        self.i("CALL", f"FC {callee.block.number + 1} ({', '.join(binds)})")
        for slot, a, typ, w in copies_out:
            if typ == "BOOL":
                self.i("A", slot)
                self.i("=", self.opnd(a))
            else:
                self.i("L", slot)
                self.i("T", self.opnd(a, w))
        self.i("A", self.bit(self.lay.stop_bit))  # the callee stopped the CPU
        self.i("BEC")


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
        pou = loaded.pous[key]
        e = _Emitter(tr, key, idx)
        if pou.block.kind == "SBR":
            e.i("SET")
            e.i("=", e.tos)  # a called subroutine starts with the top of stack on
        for st, classes, o, builder in pou.code:
            try:
                e.emit(st, classes, o, builder)
            except StlError:
                raise
            except ValueError as exc:
                raise StlError(
                    str(exc), line=st.line, block=pou.block.label, network=st.network, text=st.text
                ) from None
        e.flush_labels()
        b = pou.block
        if b.kind == "SBR":
            out += [
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
        else:
            if any(v.section == "TEMP" for v in b.vars):
                raise StlError("main program locals are not translated", line=b.line, block=b.label)
            out += [
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
    awl = "\n".join(out)
    return Translation(optimize_awl(awl) if optimize else awl, tuple(notes), layout)

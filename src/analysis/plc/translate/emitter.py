"""The AWL of one S7-200 block: its output, operands, logic stack and box instructions.

An :class:`Emitter` holds what the translation of one block needs besides the statement
table (:mod:`.statements`): the AWL lines and labels, the translation of operands into
awlsim's M memory (:mod:`.layout`), the S7-200 logic stack kept in M bits, the power-flow
rule of box instructions with their error paths (SM1 bits, ENO), the math, ROUND and CALL
sequences that several statements share.
"""

from __future__ import annotations

from analysis.plc.printer import fmt_real
from analysis.plc.stl_eval.operands import Operand

__all__ = ["Emitter"]

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


class Emitter:
    """The AWL of one block."""

    def __init__(self, tr, key: str, index: int) -> None:
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
    def opnd(self, o: Operand, width: str | None = None) -> str:
        """AWL text of an operand read or written as ``width`` (B, W, D)."""
        if o.kind == "const":
            v = o.value
            if isinstance(v, float):
                return fmt_real(v)
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

    def bit_src(self, o: Operand):
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

    def load_bit(self, o: Operand, negate: bool, combine: str | None) -> None:
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

    def compare(self, kind: str, cmp: str, a: Operand, b: Operand, combine: str | None) -> None:
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

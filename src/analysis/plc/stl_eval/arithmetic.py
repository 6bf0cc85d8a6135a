"""Move, math, numeric-function, conversion, logic and shift instructions of the S7-200
(mixed into :class:`~.cpu.S7200`).

REAL is IEEE-754 binary32; ``+R -R *R /R SQRT`` are correctly rounded (a float64 result
rounded once to binary32 is exact for these operations); SIN, COS, TAN, LN, EXP are computed
in float64 and rounded once (the CPU's library is not documented). Overflow, an illegal
input (NaN or infinity) or an illegal value (SQRT of a negative, LN of a non-positive) sets
SM1.1, clears SM1.0/SM1.2, ENO = 0 and leaves the output unchanged [S2M p.154, p.157; MWH
s7-29x9r.htm]; division by zero sets SM1.3, ENO = 0 and changes nothing else [same]. Integer
overflow likewise (the output is not written) [MWH s7-28hir.htm, s7-29u0i.htm]. ROUND/TRUNC
of a value outside DINT, a NaN or an infinity set SM1.1 and leave the output [S2M p.115].
Denormal REALs (outside the documented range, behaviour unknown) are kept as IEEE does;
``ftz=True`` flushes them to zero instead. Sources as named in :mod:`.instructions`.
"""

from __future__ import annotations

import math

from analysis.plc.stl_eval.operands import F32, SIZE, TINY, U32, WIDTH_OF, flush
from analysis.plc.stl_eval.syntax import StlError

__all__ = ["Arithmetic"]


class Arithmetic:
    """The builders of the move, math and conversion families."""

    def _b_move(self, st, classes, o, pou, idx):
        t = {"MOVB": "B", "MOVW": "W", "MOVD": "D", "MOVR": "D"}[st.op]
        if o[0].kind == "const" and st.op == "MOVR":
            v = U32.unpack(F32.pack(o[0].value))[0]
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
        w = WIDTH_OF[classes[0]]
        size = SIZE[w]
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
                a, b = flush(a), flush(b)
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
            r32 = F32.unpack(F32.pack(r))[0]
        except OverflowError:
            r32 = math.inf
        if not math.isfinite(r32):
            if arith:  # finite operands of + - * /, a result beyond the REAL range
                self.events["overflow"] += 1
            self._overflow(clear_div)
            return
        if r != 0.0 and abs(r) < TINY:  # below the REAL range: denormal or 0 (IEEE)
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
                x = flush(x)
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
        t = WIDTH_OF[classes[0][0]]
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
        t = WIDTH_OF[classes[0][0]]
        g, s = self.getter(o[0], t), self.setter(o[0], t)
        mask = (1 << (8 * SIZE[t])) - 1
        cpu = self

        def body():
            r = ~g() & mask
            s(r)
            sm = cpu.mem["SM"]
            sm[1] = (sm[1] & ~0x01) | (0x01 if r == 0 else 0)
            cpu.eno = 1

        return self._box(body, st, pou)

    def _b_shift(self, st, classes, o, pou, idx):
        t = WIDTH_OF[classes[0][0]]
        g, s = self.getter(o[0], t), self.setter(o[0], t)
        gn = self.getter(o[1], "B")
        nbits = 8 * SIZE[t]
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
                x = flush(x)
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
        src_t = WIDTH_OF[classes[0][0]]
        dst_t = WIDTH_OF[classes[1][0]]
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

"""Bit logic and compare instructions of the S7-200: contacts, coils, set/reset, the logic
stack, edges and compare contacts (mixed into :class:`~.cpu.S7200`).

The 9-level logic stack (LD pushes, A/O combine into the top, ALD/OLD/LPS/LRD/LPP/LDS; the
bottom is lost on a push, filled with 0 on a pop) [S2M p.83, manualshelf p.370]. Box
instructions run only with power flow (top of stack = 1); each sets ENO, which AENO ANDs
into the top [SMART 7.1]. EU/ED detect no edge in the first scan an instance runs (it
records the state) [SMART p.157, MWH s7-23wkr.htm]. Compare contacts are executed whatever
the power flow [manualshelf p.186]; a NaN in a REAL compare is a fatal error, the CPU goes
to STOP [S2M p.96]. Sources as named in :mod:`.instructions`.
"""

from __future__ import annotations

from analysis.plc.stl_eval.operands import Operand, Resolver, flush
from analysis.plc.stl_eval.syntax import StlError

__all__ = ["BitLogic"]

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


class BitLogic:
    """The builders of the bit logic family: each returns the closure one statement runs."""

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
            bits.append(Operand("bit", first.area, first.off + b // 8, b % 8, text=first.text))
        res = Resolver(self.loaded.cpu, pou.block, pou.frame)
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
        else:  # NOP

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
                    a, b = flush(a), flush(b)
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
